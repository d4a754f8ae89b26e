"""The kept thread pool of the batch paths (relief_cad._pool) and the packing of batch pairs."""

from __future__ import annotations

import multiprocessing

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect, intersect_many
from relief_cad._pool import run_ordered
from relief_cad.errors import BudgetExceededError


def _rows(lists: list) -> list:
    return [[(r.t, r.u, r.kind) for r in lst] for lst in lists]


def test_run_ordered_keeps_order_and_raises_the_first_failing_item() -> None:
    assert run_ordered(lambda k: 10 * k, list(range(50)), 2) == [10 * k for k in range(50)]

    def fail(k: int) -> int:
        if k in (7, 30):
            raise ValueError(f"item {k}")
        return k

    with pytest.raises(ValueError, match="item 7"):
        run_ordered(fail, list(range(50)), 2)


def _mixed_pairs(n: int) -> list[tuple[RationalBezier, RationalBezier]]:
    """Pairs of random curves of degrees 1 to 20: the packing's row buffer must grow."""
    rng = np.random.default_rng(11)
    out = []
    for _ in range(n):
        da, db = rng.integers(1, 21, size=2)
        out.append((RationalBezier(rng.random((da + 1, 2)), rng.random(da + 1) + 0.5),
                    RationalBezier(rng.random((db + 1, 2)))))
    return out


@pytest.mark.parametrize("workers", [1, 2])
def test_batches_of_high_degree_pairs_equal_the_pairs_one_by_one(workers: int) -> None:
    pairs = _mixed_pairs(300)
    assert _rows(intersect_many(pairs, workers=workers)) == _rows([intersect(a, b) for a, b in pairs])


def _child(queue: multiprocessing.Queue) -> None:  # type: ignore[type-arg]
    queue.put(_rows(intersect_many(_mixed_pairs(300), workers=2)))


def test_a_forked_child_gets_a_pool_of_its_own() -> None:
    """The parent's pool has no threads in a forked child: the child must make its own, not hang."""
    pairs = _mixed_pairs(300)
    want = _rows(intersect_many(pairs, workers=2))  # the parent's pool now exists
    ctx = multiprocessing.get_context("fork")
    queue = ctx.Queue()
    proc = ctx.Process(target=_child, args=(queue,))
    proc.start()
    try:
        got = queue.get(timeout=60)
    finally:
        proc.join(timeout=10)
        if proc.is_alive():
            proc.kill()
    assert got == want


def _first_error(pairs: list, workers: int, **kw: object) -> tuple[str, object]:
    with pytest.raises(Exception) as info:
        intersect_many(pairs, workers=workers, **kw)  # type: ignore[arg-type]
    return f"{type(info.value).__name__}: {info.value}", getattr(info.value, "unresolved", None)


def test_the_same_error_for_any_workers() -> None:
    """A bad item raises before any budget error; a budget error is that of the first pair, in order."""
    far = RationalBezier([[5.0, 5.0], [6.0, 6.0]])  # apart from the unit square: no step at all
    tight = [(a, far) for a, _ in _mixed_pairs(300)] + _mixed_pairs(300)  # budgets run out in later chunks
    bad = tight + ["not a pair"]
    for w in (1, 2, 3):
        assert _first_error(bad, w, budget=1) == (
            "InputTypeError: pairs[600] should be a tuple (a, b), not str", None)
    first: tuple[int, object] | None = None
    for k, (a, b) in enumerate(tight):  # the first pair, in order, whose budget of one step runs out
        try:
            intersect(a, b, budget=1)
        except BudgetExceededError as exc:
            first = (k, exc.unresolved)
            break
    assert first is not None and first[0] >= 300
    for w in (1, 2, 3):
        message, unresolved = _first_error(tight, w, budget=1)
        assert message.startswith("BudgetExceededError") and unresolved == first[1]


def test_a_task_of_the_pool_runs_its_own_batch_here_not_on_the_pool() -> None:
    """Two tasks on a 2-thread pool, each asking the pool for two more: on the pool, each would wait
    on tasks queued behind both of them, forever. Watched from a daemon thread."""
    import threading

    done: list[list[list[int]]] = []
    inner = lambda k: run_ordered(lambda j: 10 * k + j, [0, 1], 2)  # noqa: E731
    watcher = threading.Thread(target=lambda: done.append(run_ordered(inner, [1, 2], 2)), daemon=True)
    watcher.start()
    watcher.join(timeout=60)
    assert done == [[[10, 11], [20, 21]]]


@pytest.mark.parametrize("workers", [1, 2])
def test_no_pairs_give_no_lists(workers: int) -> None:
    assert intersect_many([], workers=workers) == []
    assert intersect_many(iter(()), workers=workers) == []

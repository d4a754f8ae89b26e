"""Kernel rows to result objects (relief_cad._kernels.rows): the one place, for planar and space rows."""

from __future__ import annotations

import dataclasses
import doctest

import numpy as np
import pytest

import relief_cad._kernels.batch as batch_module
import relief_cad._kernels.clip as clip_module
import relief_cad._kernels.rows as rows_module
from relief_cad import RationalBezier, intersect, intersect_many
from relief_cad.results import Intersection, IntersectionList, Overlap, ParameterBox


@pytest.mark.parametrize("module", [rows_module, batch_module, clip_module])
def test_the_compiled_modules_run_their_own_examples(module: object) -> None:
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE | doctest.ELLIPSIS)
    assert result.attempted >= 5 and result.failed == 0


def _fields(r: object) -> tuple[object, ...]:
    return tuple(np.asarray(v).tolist() if isinstance(v, np.ndarray) else v for v in dataclasses.astuple(r))


@pytest.mark.parametrize("dim", [2, 3])
def test_points_are_plain_floats_and_read_only_and_equal_hand_built_ones(dim: int) -> None:
    pad = [[0.0]] * 3 if dim == 3 else [[]] * 3
    a = RationalBezier(np.hstack([[[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], pad]))
    b = RationalBezier(np.hstack([[[0.0, 1.0], [1.0, 0.0], [2.0, 1.0]], pad]))
    res = intersect(a, b)
    assert isinstance(res, IntersectionList) and len(res) == 2 and res.complete
    for r in res:
        assert type(r) is Intersection
        assert type(r.t) is float and type(r.u) is float and type(r.distance) is float
        assert r.point.shape == (dim,) and not r.point.flags.writeable
        with pytest.raises(ValueError):
            r.point[0] = 1.0
        with pytest.raises(dataclasses.FrozenInstanceError):
            r.t = 0.0  # type: ignore[misc]
        hand = Intersection(r.t, r.u, np.array(r.point), r.kind, r.distance)
        assert _fields(hand) == _fields(r) and repr(hand) == repr(r)
        assert np.allclose(r.point, a(r.t), atol=1e-12) and np.allclose(r.point, b(r.u), atol=1e-12)
    assert [r.t for r in res] == sorted(r.t for r in res)


@pytest.mark.parametrize("dim", [2, 3])
def test_overlaps_equal_and_hash_as_hand_built_ones(dim: int) -> None:
    a = RationalBezier([[0.0, 0.0, 0.0][:dim], [4.0, 0.0, 0.0][:dim]])
    b = RationalBezier([[3.0, 0.0, 0.0][:dim], [1.0, 0.0, 0.0][:dim]])
    (ov,) = intersect(a, b)
    hand = Overlap(t=(0.25, 0.75), u=(1.0, 0.0))
    assert type(ov) is Overlap and ov == hand and hash(ov) == hash(hand) and repr(ov) == repr(hand)
    assert ov.reversed_direction


def test_batch_rows_go_to_their_own_pairs() -> None:
    rng = np.random.default_rng(7)
    pairs = [(RationalBezier(rng.random((4, 2))), RationalBezier(rng.random((4, 2)))) for _ in range(300)]
    many = intersect_many(pairs, workers=2)
    assert sum(len(r) for r in many) > 100  # random cubics in one square cross often
    for (a, b), got in zip(pairs, many, strict=True):
        one = intersect(a, b)
        assert [_fields(r) for r in got] == [_fields(r) for r in one]
        assert got.tol_used == one.tol_used and got.unresolved == one.unresolved == ()


def test_unresolved_rows_become_parameter_boxes() -> None:
    # nine crossings, one clipping step allowed: the budget leaves boxes open
    f9 = [-1.09375, 4.135416666666667, -3.1354166666666665, 2.09375]
    x3 = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    a = RationalBezier(np.column_stack([x3, f9]))
    b = RationalBezier(np.column_stack([f9, x3]))
    res = intersect(a, b, budget=1, on_budget="return")
    assert res.unresolved and all(type(bx) is ParameterBox for bx in res.unresolved)
    assert all(0.0 <= bx.t0 <= bx.t1 <= 1.0 and 0.0 <= bx.u0 <= bx.u1 <= 1.0 for bx in res.unresolved)
    assert len(intersect(a, b)) == 9


@pytest.mark.parametrize(("kind", "t", "u", "final"), [
    (0.0, 0.5, 0.25, True),   # an interior crossing is final as the kernel gives it
    (1.0, 0.5, 0.25, False),  # a tangent contact is refined
    (0.0, 0.0, 0.25, False),  # a crossing at an end of either curve may be at a singular end
    (0.0, 0.5, 1.0, False),
    (2.0, 0.5, 0.25, False),  # an overlap
    (3.0, 0.5, 0.25, False),  # an open box
])
def test_a_pair_is_final_only_when_every_row_is_an_interior_crossing(
        kind: float, t: float, u: float, final: bool) -> None:
    first = [0.0, 0.0, 0.1, 0.1, 0.1, 0.1, 0.0, 0.0, 0.0]  # an interior crossing before it
    rows = np.array([first, [0.0, kind, t, u, min(1.0, t + 0.1), min(1.0, u + 0.1), 1.0, 2.0, 0.0]])
    res, got = rows_module.rows_to_list(rows, 1e-9)
    assert got is final and len(res) + len(res.unresolved) == 2
    lists, looks = rows_module.batch_lists(np.vstack([rows, rows + np.eye(9)[0]]), np.array([1e-9, 2e-9]))
    assert looks == ([] if final else [0, 1]) and [x.tol_used for x in lists] == [1e-9, 2e-9]


def test_points_are_their_own_arrays_and_stay_put_when_the_kernel_scratch_is_reused() -> None:
    # a planar pair's result list is made on the kernel's scratch rows (reused by the next call):
    # each point must be its own array, not a view of rows the next pair writes over
    f9 = [-1.09375, 4.135416666666667, -3.1354166666666665, 2.09375]
    x3 = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    nine = (RationalBezier(np.column_stack([x3, f9])), RationalBezier(np.column_stack([f9, x3])))
    one = (RationalBezier([[0, 0], [1, 2], [2, 2], [3, 0]]), RationalBezier([[1.5, -0.5], [1.5, 2.5]]))
    first = intersect(*nine)
    kept = [r.point.copy() for r in first]
    assert len(first) == 9
    for _ in range(3):
        assert len(intersect(*one)) == 1 and len(intersect(*nine)) == 9
    for r, p in zip(first, kept, strict=True):
        assert r.point.flags.owndata and not r.point.flags.writeable
        assert r.point.tolist() == p.tolist()
        assert np.allclose(r.point, nine[0](r.t), atol=1e-12)

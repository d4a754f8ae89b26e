"""The shared frame of the property-based fuzz suite (``tests/*/test_fuzz_*.py``, issue 15).

A fuzz test is a body run by hypothesis on generated cases through :func:`fuzz`. Each case
is counted as *tried*, then as *refused* (the input was rejected with a ``ReliefCadError``
that the body checked: :meth:`Case.refuses`) or *answered* (the body checked the answer:
:meth:`Case.answered`); every property the body asserts is counted (:meth:`Case.check`).
After the hypothesis run the test FAILS when the answered fraction of its generator is below
its ``min_answered`` (a suite that passes because everything raises must fail) or above its
``max_answered`` (a generator of bad input that stopped producing bad input). The totals are
printed at the end of the run (``pytest_terminal_summary`` in ``tests/conftest.py``).

Reproducible: the hypothesis profile ``ci`` (``tests/conftest.py``) is derandomized, with no
deadline and no example database. ``FUZZ_EXAMPLES`` multiplies every example count (default 1;
``FUZZ_EXAMPLES=20`` for a long local run, ``HYPOTHESIS_PROFILE=dev`` for fresh random cases).
"""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from relief_cad.errors import BudgetExceededError, ReliefCadError

SCALE = float(os.environ.get("FUZZ_EXAMPLES", "1"))
"""Multiplier of every fuzz test's example count (environment variable ``FUZZ_EXAMPLES``)."""

# health checks about slow or large generation: timing-dependent, so flaky on a loaded machine
_QUIET = [HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much,
          HealthCheck.large_base_example]

# a message names what was expected ("x should be ...", "expected ...", "... needs ...")
_EXPECTED = re.compile(r"\b(should|expected|expects|needs|must)\b")


@dataclass
class Tally:
    """Outcome counts of one generator."""

    tried: int = 0
    refused: int = 0
    answered: int = 0
    properties: int = 0


TALLIES: dict[str, Tally] = {}
"""Generator name -> counts, over the whole pytest run (read by tests/conftest.py)."""


class Case:
    """One generated case: records its outcome and counts the properties checked."""

    def __init__(self, tally: Tally) -> None:
        self.tally = tally
        self.outcome: str | None = None

    def check(self, ok: object, *context: object) -> None:
        """Assert one property (counted); ``context`` is shown when it fails."""
        self.tally.properties += 1
        assert ok, context

    def answered(self) -> None:
        """The input was accepted and its answer checked."""
        self._set("answered")

    def refused(self) -> None:
        """The input was refused, and the body checked how (a command line's exit status and error line)."""
        self._set("refused")

    def refuses(self, call: Callable[[], Any], builtin: type[BaseException], *came: str,
                error: type[ReliefCadError] = ReliefCadError) -> ReliefCadError:
        """Run ``call``; it must raise ``error`` that is also ``builtin``, naming what was expected
        and ``came`` (what was received: each string must appear in the message)."""
        try:
            call()
        except ReliefCadError as exc:
            msg = str(exc)
            self.check(isinstance(exc, error) and isinstance(exc, builtin),
                       f"{type(exc).__name__} is not a {error.__name__} and a {builtin.__name__}", msg)
            self.check(_EXPECTED.search(msg), "the message does not say what was expected", msg)
            self.check(all(c in msg for c in came), f"the message does not name {came}", msg)
            self._set("refused")
            return exc
        raise AssertionError(f"expected a {error.__name__} ({builtin.__name__}); nothing was raised")

    def _set(self, outcome: str) -> None:
        assert self.outcome is None, f"a case is {self.outcome} and {outcome}"
        self.outcome = outcome


def _run_case(tally: Tally, body: Callable[..., None], args: tuple[Any, ...]) -> None:
    case = Case(tally)
    tally.tried += 1
    try:
        body(case, *args)
    except BudgetExceededError as exc:  # documented: a budget ran out, or no frame separated the curves
        case.check(isinstance(exc, RuntimeError) and str(exc), "a BudgetExceededError without a reason")
        case.outcome = "refused"
    if case.outcome == "refused":
        tally.refused += 1
    elif case.outcome == "answered":
        tally.answered += 1
    else:
        raise AssertionError("the fuzz body recorded no outcome (answered or refused)")


def check_fraction(name: str, tally: Tally, min_answered: float, max_answered: float) -> None:
    """Fail when the answered fraction of a generator is outside ``[min_answered, max_answered]``."""
    assert tally.tried > 0, f"{name}: no case was generated"
    frac = tally.answered / tally.tried
    assert min_answered <= frac <= max_answered, (
        f"{name}: {tally.answered} of {tally.tried} cases answered ({frac:.0%}); "
        f"this generator should answer {min_answered:.0%} to {max_answered:.0%}")


def fuzz(name: str, *strategies: Any, examples: int, min_answered: float = 0.5,
         max_answered: float = 1.0, explicit: Sequence[tuple[Any, ...]] = ()
         ) -> Callable[[Callable[..., None]], Callable[[], None]]:
    """Make a pytest test of ``body(case, *drawn)`` over ``examples`` (times FUZZ_EXAMPLES) cases.

    ``explicit`` cases (argument tuples) run first, as hypothesis ``@example``. The counts go to
    ``TALLIES[name]``; afterwards the answered fraction of the run must lie in
    ``[min_answered, max_answered]``.
    """
    def decorate(body: Callable[..., None]) -> Callable[[], None]:
        total = TALLIES.setdefault(name, Tally())
        current = [Tally()]

        def inner(drawn: tuple[Any, ...]) -> None:
            _run_case(current[0], body, drawn)

        hyp = given(st.tuples(*strategies))(inner)
        for args in explicit:
            hyp = example(tuple(args))(hyp)
        hyp = settings(max_examples=max(1, round(examples * SCALE)), deadline=None, database=None,
                       suppress_health_check=_QUIET)(hyp)

        def test() -> None:
            current[0] = run = Tally()
            try:
                hyp()
            finally:
                for key, value in vars(run).items():
                    setattr(total, key, getattr(total, key) + value)
            check_fraction(name, run, min_answered, max_answered)

        test.__name__ = body.__name__
        test.__qualname__ = body.__qualname__
        test.__doc__ = body.__doc__
        test.__module__ = body.__module__
        return test

    return decorate


def summary_lines() -> list[str]:
    """The totals table printed at the end of a run (empty when no fuzz test ran)."""
    if not TALLIES:
        return []
    rows = [(n, t) for n, t in sorted(TALLIES.items()) if t.tried]
    if not rows:
        return []
    total = Tally(*(sum(getattr(t, k) for _, t in rows) for k in vars(Tally())))
    width = max(len(n) for n, _ in rows + [("total", total)])
    head = f"{'generator':<{width}}  {'tried':>7}  {'refused':>7}  {'answered':>8}  {'properties':>10}"
    lines = [head]
    for n, t in rows + [("total", total)]:
        lines.append(f"{n:<{width}}  {t.tried:>7}  {t.refused:>7}  {t.answered:>8}  {t.properties:>10}")
    return lines

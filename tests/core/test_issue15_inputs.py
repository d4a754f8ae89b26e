"""Issues 15 and 16 (core part): every bad input listed there is refused with a ReliefCadError that
is also the matching built-in, and the hangs listed there answer at once."""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect, intersect_line, intersect_many
from relief_cad._checks import MAX_DEGREE, MAX_WEIGHT_RATIO
from relief_cad.errors import (
    DegreeError,
    InputTypeError,
    NonFiniteError,
    ReliefCadError,
    SpanError,
    WeightError,
)
from relief_cad.relief import central_projection
from relief_cad.space import intersect_space
from relief_cad.tolerances import default_tolerance

C = RationalBezier([[0, 0], [1, 2], [2, 0]])
S = RationalBezier([[0, 0, 0], [1, 2, 1], [2, 0, 0]])

CASES: list[tuple[str, Callable[[], Any], type[Exception]]] = [
    ("coordinate 10**400", lambda: RationalBezier([[10**400, 0], [1, 1]]), NonFiniteError),
    ("weight 10**400", lambda: RationalBezier([[0, 0], [1, 1]], [1, 10**400]), NonFiniteError),
    ("complex array", lambda: RationalBezier(np.array([[1j, 0], [1, 1]])), InputTypeError),
    ("numeric strings", lambda: RationalBezier([["1", "0"], ["1", "1"]]), InputTypeError),
    ("split(None)", lambda: C.split(None), InputTypeError),  # type: ignore[arg-type]
    ("split('a')", lambda: C.split("a"), InputTypeError),  # type: ignore[arg-type]
    ("split(10**400)", lambda: C.split(10**400), NonFiniteError),
    ("segment(None, 1)", lambda: C.segment(None, 1.0), InputTypeError),  # type: ignore[arg-type]
    ("central_projection('curve')", lambda: central_projection("curve"), InputTypeError),  # type: ignore[call-overload]
    ("intersect_line 'ab'", lambda: intersect_line(C, "ab", (1, 0)), InputTypeError),  # type: ignore[arg-type]
    ("intersect_many(5)", lambda: intersect_many(5), InputTypeError),  # type: ignore[arg-type]
    ("default_tolerance()", lambda: default_tolerance(), InputTypeError),
    ("default_tolerance('abc')", lambda: default_tolerance("abc"), InputTypeError),  # type: ignore[arg-type]
    ("default_tolerance(None)", lambda: default_tolerance(None), InputTypeError),  # type: ignore[arg-type]
    ("default_tolerance([])", lambda: default_tolerance(np.array([])), InputTypeError),
    ("k='2'", lambda: intersect_space(S, S, k="2"), InputTypeError),  # type: ignore[arg-type]
    ("k=1.0", lambda: intersect_space(S, S, k=1.0), SpanError),
    ("k=0.0", lambda: intersect_space(S, S, k=0.0), SpanError),
    ("budget=10**30 planar", lambda: intersect(C, C.reversed(), budget=10**30), ValueError),
    ("budget=10**30 many", lambda: intersect_many([(C, C)], budget=10**30), ValueError),
    ("elevate(5000)", lambda: C.elevate(5000), DegreeError),
    ("weights 1e300", lambda: RationalBezier([[0, 0], [0.5, 1], [1, 0]], [1, 1e300, 1]), WeightError),
]


@pytest.mark.parametrize(("what", "call", "error"), CASES, ids=[c[0] for c in CASES])
def test_bad_input_gets_a_relief_cad_error(what: str, call: Callable[[], Any],
                                           error: type[Exception]) -> None:
    with pytest.raises(error) as info:
        call()
    assert isinstance(info.value, ReliefCadError), what
    assert str(info.value), what


def test_degree_limit_is_exact() -> None:
    rng = np.random.default_rng(1)
    ok = RationalBezier(rng.random((MAX_DEGREE + 1, 2)))
    assert ok.degree == MAX_DEGREE
    with pytest.raises(DegreeError, match=str(MAX_DEGREE)):
        RationalBezier(rng.random((MAX_DEGREE + 2, 2)))
    with pytest.raises(DegreeError):
        ok.elevate(1)


def test_weight_ratio_limit_and_scaling() -> None:
    pts = [[0, 0], [0.5, 1], [1, 0]]
    inside = RationalBezier(pts, [1, MAX_WEIGHT_RATIO / 2, 1])
    assert inside.degree == 2
    scaled = RationalBezier(pts, [1e200, 3e200, 1e200])  # ratio 3: the same curve as [1, 3, 1]
    plain = RationalBezier(pts, [1, 3, 1])
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(scaled.evaluate(t), plain.evaluate(t), rtol=1e-14, atol=1e-14)


@pytest.mark.parametrize("pts", [[[1, 2, 3], [1, 2, 3]], [[1, 2, 3]] * 4,
                                 [[0.1 + 0.2, 0, 1], [0.3, 0, 1], [0.30000000000000004, 0, 1]]])
def test_point_like_space_curve_has_no_self_intersection(pts: list[list[float]]) -> None:
    start = time.perf_counter()
    result = intersect(RationalBezier(pts))
    assert len(result) == 0 and result.complete
    assert time.perf_counter() - start < 30.0  # a hang guard, not a speed claim


@pytest.mark.parametrize("big", [1e160, 1e170, 1e300])
def test_default_tolerance_does_not_overflow(big: float) -> None:
    a = RationalBezier([[-big, 0.0], [big, 0.0]])
    tol = default_tolerance(a)
    assert np.isfinite(tol)
    assert 1e-9 * 2 * big <= tol <= 1e-8 * 2 * big


def test_default_tolerance_at_max_degree_measures_the_curve() -> None:
    rng = np.random.default_rng(2)
    c = RationalBezier(rng.random((MAX_DEGREE + 1, 2)))
    samples = c.evaluate(np.linspace(0, 1, 1001))
    size = float(np.linalg.norm(samples.max(axis=0) - samples.min(axis=0)))
    assert default_tolerance(c) == pytest.approx(1e-9 * size, rel=0.05)


@pytest.mark.parametrize("tol", [1e-16, 1e-300, 5e-324])
@pytest.mark.parametrize("dim", [2, 3])
def test_tolerance_below_rounding_still_finds_the_crossing(tol: float, dim: int) -> None:
    a = RationalBezier([[-2, 0.3], [2, -0.2]]).embedded(dim)
    b = RationalBezier([[0.1, -2], [0.2, 2]]).embedded(dim)
    default = intersect(a, b)
    tiny = intersect(a, b, tol=tol)
    assert len(default) == 1
    assert len(tiny) == 1
    assert tiny[0].t == pytest.approx(default[0].t, abs=1e-12)

"""The tolerance rules of the core (issues 15 and 16): ``tol_used``, the floor, the cap, huge data.

- every result list reports ``tol_used``: the given ``tol`` raised to the rounding floor, or the
  default; every reported point has ``distance <= tol_used`` (property test, tolerances far below
  rounding included: 1e-300, 5e-324);
- no ``RuntimeWarning`` escapes a public call on finite data of magnitude 1e150 .. 1e300, and the
  crossings there are still found;
- a tolerance above ``MAX_TOLERANCE_FRACTION`` of the inputs' size is refused (``ToleranceError``,
  a ``ValueError``), and below it ``intersect(a, b)`` and ``intersect(b, a)`` agree;
- ``intersect_space(k=...)``: checked, deprecated, without effect (bit-identical rows).
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from relief_cad import RationalBezier, intersect, intersect_line, intersect_many, intersect_space
from relief_cad.errors import BudgetExceededError, InputTypeError, ReliefCadError, SpanError, ToleranceError
from relief_cad.space import relief_scheme
from relief_cad.tolerances import (
    MAX_TOLERANCE_FRACTION,
    ModelTolerance,
    default_tolerance,
    floor_of_magnitude,
    resolve_tolerance,
    rounding_floor,
    size_of,
)

from .strategies import curves

TINY = [None, 1e-300, 5e-324, 1e-16, 1e-12]


def _check_tol_used(res, given, *cs) -> None:
    floor = rounding_floor(*cs)
    if given is None:
        assert res.tol_used == default_tolerance(*cs)
    else:
        assert res.tol_used == max(given, floor)
    assert res.tol_used >= floor
    for r in res.points:
        assert r.distance <= res.tol_used, (r, res.tol_used)


_COORD = st.one_of(st.floats(-1e300, 1e300), st.sampled_from([0.0, -0.0, 5e-324, -5e-324, 1e-310]))


@settings(max_examples=200, deadline=None)
@given(st.lists(st.tuples(_COORD, _COORD, _COORD), min_size=1, max_size=6))
def test_floor_of_magnitude_is_the_rounding_floor_of_the_points(points) -> None:
    # the CAD layer takes the floor of two edges' boxes from their corners' largest magnitude
    expected = rounding_floor(np.array(points, dtype=float))
    assert floor_of_magnitude(max(abs(x) for p in points for x in p)) == expected
    assert expected >= 1e-300


@settings(max_examples=100, deadline=None)
@given(curves(dim=2, max_degree=6), curves(dim=3, max_degree=6),
       st.sampled_from([5e-324, 1e-300, 1e-12, 1e-7, 1.0, 1e300]))
def test_a_model_tolerance_is_raised_to_the_floor_only(a: RationalBezier, b: RationalBezier, tol) -> None:
    # a model's tolerance takes the compiled floor (largest |x|) and no cap; the same value as the
    # floor from the curves' full extent
    model = ModelTolerance(tol)
    assert resolve_tolerance(model, a) == max(tol, rounding_floor(a))
    assert resolve_tolerance(model, a, b) == max(tol, rounding_floor(a, b))
    assert resolve_tolerance(model, b, a.control_points) == max(tol, rounding_floor(b, a.control_points))


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(curves(dim=2, max_degree=4), curves(dim=2, max_degree=4), st.sampled_from(TINY))
def test_planar_tol_used_bounds_every_distance(a: RationalBezier, b: RationalBezier, tol) -> None:
    res = intersect(a, b, tol=tol, on_budget="return")
    _check_tol_used(res, tol, a, b)
    self_res = intersect(a, tol=tol, on_budget="return")
    _check_tol_used(self_res, tol, a)
    (many,) = intersect_many([(a, b)], tol=tol, on_budget="return")
    _check_tol_used(many, tol, a, b)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(curves(dim=3, max_degree=3), curves(dim=3, max_degree=3), st.sampled_from(TINY))
def test_space_tol_used_bounds_every_distance(a: RationalBezier, b: RationalBezier, tol) -> None:
    try:
        res = intersect(a, b, tol=tol, on_budget="return")
    except BudgetExceededError:  # no artefact-free frame (also on main: a point on a retraced line)
        assume(False)
    _check_tol_used(res, tol, a, b)


def test_tol_far_below_rounding_keeps_the_crossing() -> None:
    a = RationalBezier([[-2, 0.3], [2, -0.2]])
    b = RationalBezier([[0.1, -2], [0.2, 2]])
    for tol in (1e-300, 5e-324):
        res = intersect(a, b, tol=tol)
        assert len(res) == 1 and res[0].kind == "crossing"
        assert res.tol_used == rounding_floor(a, b) > tol
    line = intersect_line(a, (0.15, 0.0), (0.1, 4.0), tol=1e-300)
    assert len(line) == 1 and line[0].distance <= line.tol_used


# --------------------------------------------------------------------------- huge coordinates
SCALES = [1e150, 1e200, 1e250, 1e300]


@pytest.mark.parametrize("scale", SCALES)
def test_no_runtime_warning_on_huge_coordinates(scale: float) -> None:
    half = scale / 4
    arch = RationalBezier(np.array([[0, 0], [1, 2], [2, 0]]) * half)
    bar = RationalBezier(np.array([[0, 0.5], [2, 0.5]]) * half)
    arch3 = RationalBezier(np.array([[0, 0, 0], [1, 1, 1], [2, 0, 2]]) * half)
    cross3 = RationalBezier(np.array([[0, 0, 2], [1, 1, 1], [2, 0, 0]]) * half)
    loop = RationalBezier(np.array([[0, 0], [3, 3], [-1, 3], [2, 0]]) * half)
    loop3 = RationalBezier(np.array([[0, 0, 0], [3, 3, 1], [-1, 3, 1], [2, 0, 0]]) * half)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        planar = intersect(arch, bar)
        space = intersect(arch3, cross3)
        self_planar = intersect(loop)
        self_space = intersect(loop3)
        many = intersect_many([(arch, bar), (bar, arch)])
        line = intersect_line(arch, (0.0, 0.5 * half), (1.0, 0.0))
        default_tolerance(arch3, cross3)
        relief_scheme(arch3, cross3)
    # the answers, not only the silence: the same parameters as at unit scale
    unit = intersect(RationalBezier([[0, 0], [1, 2], [2, 0]]), RationalBezier([[0, 0.5], [2, 0.5]]))
    for got in (planar, many[0], line):
        assert [round(r.t, 9) for r in got] == [round(r.t, 9) for r in unit]
    assert [round(r.t, 9) for r in space] == [0.5]
    for got in (self_planar, self_space):  # z(t) = z(1 - t) on loop3: the same double point
        assert [(round(r.t, 6), round(r.u, 6)) for r in got] == [(0.172673, 0.827327)]
    for res in (planar, space, self_planar, many[0], many[1], line):
        assert math.isfinite(res.tol_used) and all(r.distance <= res.tol_used for r in res.points)


# --------------------------------------------------------------------------- huge tolerances
def _pairs(dim: int, n: int, seed: int) -> list[tuple[RationalBezier, RationalBezier]]:
    """Random cubic/quadratic pairs; every second one moved so that b(u0) = a(t0): they meet."""
    rng = np.random.default_rng(seed)
    out = []
    for i in range(n):
        a = RationalBezier(rng.normal(size=(4, dim)))
        pts = rng.normal(size=(3, dim))
        if i % 2:
            b0 = RationalBezier(pts)
            pts = pts + (a(rng.uniform(0.1, 0.9)) - b0(rng.uniform(0.1, 0.9)))
        out.append((a, RationalBezier(pts)))
    return out


@pytest.mark.parametrize("dim", [2, 3])
def test_tolerance_beyond_the_cap_is_refused(dim: int) -> None:
    a, b = _pairs(dim, 1, 3)[0]
    limit = MAX_TOLERANCE_FRACTION * size_of(a, b)
    calls = [lambda t: intersect(a, b, tol=t), lambda t: intersect(b, a, tol=t),
             lambda t: intersect_many([(a, b)], tol=t)]
    if dim == 2:
        calls.append(lambda t: intersect_line(a, (0.0, 0.0), (1.0, 1.0), tol=t))
    for call in calls:
        for tol in (1e300, 2 * limit):
            with pytest.raises(ToleranceError, match=r"at most 0\.01 of the inputs' size") as info:
                call(tol)
            assert isinstance(info.value, ValueError) and repr(tol) in str(info.value)
        assert call(0.5 * limit).tol_used == 0.5 * limit if call is not calls[2] else True
    with pytest.raises(ToleranceError):
        intersect(a, tol=1e300)


def _key(res, swap: bool = False) -> list[tuple]:
    """The answer (with the roles of a and b swapped back if ``swap``), rounded to what symmetry promises."""
    out = []
    for r in res:
        t, u = (r.u, r.t) if swap else (r.t, r.u)
        if r.kind == "overlap":
            out.append(("overlap", *sorted(round(x, 6) for x in (*t, *u))))
        else:
            out.append((r.kind, round(t, 6), round(u, 6)))
    return sorted(out)


@pytest.mark.parametrize("dim", [2, 3])
def test_accepted_tolerances_are_symmetric(dim: int) -> None:
    """At the cap (the largest accepted tolerance) swapping a and b swaps t and u, nothing else."""
    for a, b in _pairs(dim, 25, 11 + dim):
        tol = MAX_TOLERANCE_FRACTION * size_of(a, b)
        ab = intersect(a, b, tol=tol, on_budget="return")
        ba = intersect(b, a, tol=tol, on_budget="return")
        assert ab.tol_used == ba.tol_used == tol
        assert _key(ab) == _key(ba, swap=True), (a, b)


# --------------------------------------------------------------------------- the span k
def test_the_kernel_rows_do_not_depend_on_k() -> None:
    """psi o phi_k = psi: the space kernel finds the same rows whatever span it is given.

    Exact in real arithmetic; in binary64 the images pass through factors (1 + k), so a parameter
    may move by a few ulps (4e-16 measured on 40 pairs, 88 of 120 runs bit-identical). That is why
    intersect_space always runs the kernel with one k (then the public results are bit-identical).
    """
    from relief_cad._kernels import space_pair_kernel

    found = 0
    for a, b in _pairs(3, 20, 21):
        tol = default_tolerance(a, b)
        first, n0, status0 = space_pair_kernel(a.homogeneous, b.homogeneous, tol, 10**5, 2.0)
        found += n0
        for k in (0.1, 50.0, 7.3):
            rows, n, status = space_pair_kernel(a.homogeneous, b.homogeneous, tol, 10**5, k)
            assert (n, status) == (n0, status0)
            np.testing.assert_array_equal(rows[:n, 0], first[:n0, 0])  # the kinds
            np.testing.assert_allclose(rows[:n, 1:5], first[:n0, 1:5], rtol=0, atol=4e-15)
    assert found > 0  # some pairs meet, so rows were compared


def test_k_changes_nothing_and_is_deprecated() -> None:
    for a, b in _pairs(3, 6, 5):
        base = intersect_space(a, b)
        for k in (0.1, 2.0, 50.0, 0.5):
            with pytest.warns(DeprecationWarning, match="no effect"):
                got = intersect_space(a, b, k=k)
            assert [(r.t, r.u) if r.kind == "overlap" else (r.t, r.u, r.point.tobytes(), r.distance)
                    for r in got] == [(r.t, r.u) if r.kind == "overlap"
                                      else (r.t, r.u, r.point.tobytes(), r.distance) for r in base]


@pytest.mark.parametrize("k,error,builtin", [
    ("2", InputTypeError, TypeError), (True, InputTypeError, TypeError), (None, None, None),
    (float("nan"), SpanError, ValueError), (0.0, SpanError, ValueError), (1.0, SpanError, ValueError),
    (10**400, SpanError, ValueError),
])
def test_k_is_checked(k, error, builtin) -> None:
    a, b = _pairs(3, 1, 9)[0]
    if error is None:  # k=None: the default, no warning
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            intersect_space(a, b, k=k)
        return
    for call in (lambda: intersect_space(a, b, k=k), lambda: relief_scheme(a, b, k=k)):
        with pytest.raises(error) as info:
            call()
        assert isinstance(info.value, ReliefCadError) and isinstance(info.value, builtin)


def test_k_shapes_the_relief_scheme() -> None:
    a, b = _pairs(3, 1, 9)[0]
    s2, s5 = relief_scheme(a, b, k=2.0), relief_scheme(a, b, k=5.0)
    assert not np.allclose(s2.a_relief.control_points, s5.a_relief.control_points)
    np.testing.assert_allclose(s2.a_image.control_points, s5.a_image.control_points, rtol=1e-12, atol=1e-12)

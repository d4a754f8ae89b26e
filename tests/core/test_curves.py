"""Tests of RationalBezier: geometry preserved by every operation, against an mpmath reference."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from relief_cad import RationalBezier
from relief_cad.errors import (
    DegenerateCurveError,
    DegreeError,
    InputTypeError,
    NonFiniteError,
    ProjectionError,
    ReliefCadError,
    ShapeError,
    WeightError,
)
from tests.core.strategies import curves, params

SAMPLES = np.linspace(0.0, 1.0, 17)


def scale_of(c: RationalBezier) -> float:
    return float(np.max(np.abs(c.control_points))) + 1.0


def mp_eval(c: RationalBezier, t: float, dps: int = 50) -> list[mpmath.mpf]:
    """Reference: the defining formula sum w_i V_i B_i / sum w_i B_i in 50-digit arithmetic."""
    with mpmath.workdps(dps):
        n = c.degree
        tt = mpmath.mpf(t)
        num = [mpmath.mpf(0)] * c.dim
        den = mpmath.mpf(0)
        for i in range(n + 1):
            b = mpmath.binomial(n, i) * tt**i * (1 - tt) ** (n - i) * mpmath.mpf(float(c.weights[i]))
            den += b
            for j in range(c.dim):
                num[j] += b * mpmath.mpf(float(c.control_points[i, j]))
        return [x / den for x in num]


@settings(max_examples=60)
@given(curves(), params)
def test_de_casteljau_matches_mpmath_reference(c: RationalBezier, t: float) -> None:
    ref = np.array([float(x) for x in mp_eval(c, t)])
    got = c(t)
    assert got.shape == (c.dim,)
    np.testing.assert_allclose(got, ref, rtol=0, atol=1e-13 * scale_of(c) * max(c.weights) / min(c.weights))


@settings(max_examples=40)
@given(curves(), params)
def test_derivative_matches_mpmath_differentiation(c: RationalBezier, t: float) -> None:
    with mpmath.workdps(50):
        n, tt = c.degree, mpmath.mpf(t)
        w = [mpmath.mpf(float(x)) for x in c.weights]
        pts = [[mpmath.mpf(float(x)) for x in row] for row in c.control_points]
        b = [mpmath.binomial(n, i) * tt**i * (1 - tt) ** (n - i) for i in range(n + 1)]
        db = [mpmath.binomial(n, i) * (i * tt ** (i - 1) * (1 - tt) ** (n - i) if i else 0)
              - mpmath.binomial(n, i) * ((n - i) * tt**i * (1 - tt) ** (n - i - 1) if i < n else 0)
              for i in range(n + 1)]
        den = sum(w[i] * b[i] for i in range(n + 1))
        dden = sum(w[i] * db[i] for i in range(n + 1))
        ref = []
        for j in range(c.dim):
            num = sum(w[i] * pts[i][j] * b[i] for i in range(n + 1))
            dnum = sum(w[i] * pts[i][j] * db[i] for i in range(n + 1))
            ref.append(float((dnum * den - num * dden) / den**2))
    got = c.derivative(t)
    bound = 1e-9 * (np.max(np.abs(ref)) + scale_of(c)) * (max(c.weights) / min(c.weights)) ** 2
    np.testing.assert_allclose(got, ref, rtol=0, atol=bound)
    np.testing.assert_allclose(c.hodograph()(t), got, rtol=0, atol=bound)


@settings(max_examples=60)
@given(curves(), st.floats(0.01, 0.99))
def test_split_preserves_geometry(c: RationalBezier, t: float) -> None:
    left, right = c.split(t)
    tol = 1e-12 * scale_of(c) * max(c.weights) / min(c.weights)
    np.testing.assert_allclose(left(SAMPLES), c(SAMPLES * t), atol=tol, rtol=0)
    np.testing.assert_allclose(right(SAMPLES), c(t + SAMPLES * (1 - t)), atol=tol, rtol=0)
    assert np.array_equal(left.control_points[-1], right.control_points[0])


def _split_by_rounds(h: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray]:
    """De Casteljau's rounds on whole rows with numpy: the form the compiled split replaced."""
    n = h.shape[0] - 1
    left, right, b = np.empty_like(h), np.empty_like(h), h.copy()
    left[0], right[n] = b[0], b[n]
    for r in range(1, n + 1):
        b[: n + 1 - r] = (1.0 - t) * b[: n + 1 - r] + t * b[1 : n + 2 - r]
        left[r], right[n - r] = b[0], b[n - r]
    return left, right


@settings(max_examples=200)
@given(curves(), st.floats(1e-12, 1.0 - 1e-12))
def test_split_gives_the_bits_of_de_casteljau_rounds_on_whole_rows(c: RationalBezier, t: float) -> None:
    # the split is compiled (relief_cad._kernels.bezier.split_rows): the same operations in the same
    # order as the numpy rounds, so self-intersections cut their pieces exactly as before
    left, right = c.split(t)
    ref_left, ref_right = _split_by_rounds(c.homogeneous, t)
    assert np.array_equal(left.homogeneous, ref_left) and np.array_equal(right.homogeneous, ref_right)


@settings(max_examples=60)
@given(curves(), st.floats(0.0, 1.0), st.floats(0.0, 1.0))
def test_segment_any_interval_including_reversed(c: RationalBezier, t0: float, t1: float) -> None:
    if abs(t1 - t0) < 1e-3:
        with pytest.raises(DegenerateCurveError) if t0 == t1 else _null():
            c.segment(t0, t1)
        return
    s = c.segment(t0, t1)
    tol = 1e-11 * scale_of(c) * max(c.weights) / min(c.weights)
    np.testing.assert_allclose(s(SAMPLES), c(t0 + SAMPLES * (t1 - t0)), atol=tol, rtol=0)


@settings(max_examples=40)
@given(curves(rational=False), st.floats(-0.5, 0.0), st.floats(1.0, 1.5))
def test_segment_extrapolates_polynomial_curves(c: RationalBezier, t0: float, t1: float) -> None:
    s = c.segment(t0, t1)
    tol = 1e-10 * scale_of(c)
    np.testing.assert_allclose(s(SAMPLES), c(t0 + SAMPLES * (t1 - t0)), atol=tol * 50, rtol=0)


def test_segment_past_a_pole_is_an_error() -> None:
    c = RationalBezier([[0, 0], [1, 1], [2, 0]], [1.0, 10.0, 1.0])
    with pytest.raises(WeightError, match="non-positive weights"):
        c.segment(-3.0, 1.0)


@settings(max_examples=60)
@given(curves(), st.integers(1, 4))
def test_elevate_and_reversed_preserve_geometry(c: RationalBezier, r: int) -> None:
    e = c.elevate(r)
    assert e.degree == c.degree + r
    tol = 1e-12 * scale_of(c) * max(c.weights) / min(c.weights)
    np.testing.assert_allclose(e(SAMPLES), c(SAMPLES), atol=tol, rtol=0)
    np.testing.assert_allclose(c.reversed()(SAMPLES), c(1 - SAMPLES), atol=tol, rtol=0)
    assert c.reversed().reversed() == c


@settings(max_examples=60)
@given(curves())
def test_standard_form_is_a_moebius_reparametrisation(c: RationalBezier) -> None:
    s = c.standard_form()
    assert s.weights[0] == 1.0 and s.weights[-1] == 1.0
    np.testing.assert_array_equal(s.control_points, c.control_points)
    lam = (c.weights[0] / c.weights[-1]) ** (1.0 / c.degree)
    t = lam * SAMPLES / (1 - SAMPLES + lam * SAMPLES)
    tol = 1e-11 * scale_of(c) * max(c.weights) / min(c.weights)
    np.testing.assert_allclose(s(SAMPLES), c(t), atol=tol, rtol=0)


@settings(max_examples=40)
@given(curves())
def test_bounding_box_contains_curve_and_homogeneous_round_trip(c: RationalBezier) -> None:
    lo, hi = c.bounding_box()
    pts = c(np.linspace(0, 1, 101))
    assert np.all(pts >= lo - 1e-12 * scale_of(c)) and np.all(pts <= hi + 1e-12 * scale_of(c))
    back = RationalBezier.from_homogeneous(c.homogeneous)
    np.testing.assert_allclose(back.control_points, c.control_points, rtol=1e-15, atol=1e-15)
    np.testing.assert_array_equal(back.weights, c.weights)


@settings(max_examples=40)
@given(curves(dim=2), st.floats(-1, 1), st.floats(-1, 1), st.floats(0.0, 0.2))
def test_transformed_applies_collineation_exactly(c: RationalBezier, a: float, b: float, p: float) -> None:
    m = np.array([[1.0 + a, b, 3.0], [-b, 1.0 - a, -2.0], [p * 0.01, -p * 0.01, 1.0]])
    try:
        img = c.transformed(m)
    except ProjectionError:
        assert np.any(c.homogeneous @ m[2] <= 0)
        return
    h = np.column_stack([c(SAMPLES), np.ones(len(SAMPLES))]) @ m.T
    expected = h[:, :2] / h[:, 2:]
    np.testing.assert_allclose(img(SAMPLES), expected, atol=1e-10 * (scale_of(c) + 5) * max(c.weights) / min(c.weights))


def test_embedded_and_immutability() -> None:
    c = RationalBezier([[0, 0], [1, 2], [3, 1]], [1, 2, 1])
    e = c.embedded()
    assert e.dim == 3 and np.all(e.control_points[:, 2] == 0)
    np.testing.assert_allclose(e(0.3)[:2], c(0.3))
    with pytest.raises(ValueError):
        c.control_points[0, 0] = 5.0
    with pytest.raises(ValueError):
        c.weights[0] = 5.0
    assert not c.is_polynomial and RationalBezier([[0, 0], [1, 1]]).is_polynomial
    assert "weights" in repr(c)


class _null:
    def __enter__(self) -> None:
        return None

    def __exit__(self, *a: object) -> bool:
        return False


@pytest.mark.parametrize(
    ("points", "weights", "error", "builtin", "message"),
    [
        ([[0, 0], [1, float("nan")]], None, NonFiniteError, ValueError, "finite"),
        ([[0, 0], [float("inf"), 1]], None, NonFiniteError, ValueError, "finite"),
        ([[0, 0], [1, 1]], [1.0, float("nan")], NonFiniteError, ValueError, "finite"),
        ([[0, 0], [1, 1]], [1.0, 0.0], WeightError, ValueError, "> 0; weight 1 is 0.0"),
        ([[0, 0], [1, 1]], [1.0, -2.0], WeightError, ValueError, "weight 1 is -2.0"),
        ([[0, 0], [1, 1]], [1.0, 1.0, 1.0], ShapeError, ValueError, r"shape \(2,\)"),
        ([0, 0, 1], None, ShapeError, ValueError, r"\(n \+ 1, 2\)"),
        ([[0, 0, 0, 0], [1, 1, 1, 1]], None, ShapeError, ValueError, "not"),
        ([[1, 2]], None, DegreeError, ValueError, "at least 2 control points"),
        ("abc", None, InputTypeError, TypeError, "real numbers"),
        ([[1e308, 0], [1, 1]], [10.0, 1.0], NonFiniteError, ValueError, "weighted"),
    ],
)
def test_bad_input_gives_clear_errors(points, weights, error, builtin, message) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error, match=message) as info:
        RationalBezier(points, weights)
    assert isinstance(info.value, ReliefCadError) and isinstance(info.value, builtin)


def test_bad_parameters_and_operations() -> None:
    c = RationalBezier([[0, 0], [1, 2], [2, 0]], [1.0, 3.0, 1.0])
    with pytest.raises(NonFiniteError):
        c([0.5, math.inf])
    with pytest.raises(ShapeError):
        c(np.zeros((2, 2)))
    with pytest.raises(DegenerateCurveError):
        c.split(1.0)
    with pytest.raises(ShapeError):
        c.transformed(np.eye(4))
    with pytest.raises(ProjectionError):
        c.transformed(np.diag([1.0, 1.0, -1.0]))
    with pytest.raises(ProjectionError, match="weight should be > 0"):
        c(-2.0)
    with pytest.raises(NonFiniteError):
        c.segment(0.0, math.nan)
    with pytest.raises(InputTypeError):
        RationalBezier(c)  # type: ignore[arg-type]
    with pytest.raises(ShapeError):
        c.embedded(4)


def test_compiled_de_casteljau_gives_the_exact_values_on_dyadic_data() -> None:
    """The compiled float path of ``_decasteljau`` against its numpy form run on exact rationals.

    Dyadic control points and weights with small numerators, at parameters ``k / 8``: every
    float operation is exact, so the two must agree to the last bit (values and derivatives,
    degrees 1 to 8, planar and space rows).
    """
    from fractions import Fraction

    from relief_cad.curves import _decasteljau

    rng = np.random.default_rng(5)
    ts = np.arange(9) / 8
    exact_t = np.array([Fraction(int(k), 8) for k in range(9)], dtype=object)
    for degree in range(1, 9):
        for dim in (2, 3):
            h = np.hstack([rng.integers(-8, 9, size=(degree + 1, dim)) / 8,
                           rng.integers(1, 5, size=(degree + 1, 1)) / 4])
            value, deriv = _decasteljau(h, ts)
            exact_h = np.array([[Fraction(x) for x in row] for row in h.tolist()], dtype=object)
            exact_value, exact_deriv = _decasteljau(exact_h, exact_t)
            assert value.tolist() == exact_value.astype(float).tolist(), (degree, dim)
            assert deriv.tolist() == exact_deriv.astype(float).tolist(), (degree, dim)


@settings(max_examples=200, deadline=None)
@given(curves(dim=2))
def test_a_curve_rebuilt_from_its_own_arrays_is_the_constructors_to_the_bit(c: RationalBezier) -> None:
    """``_rebuilt`` (the self-intersection's copy of a curve) skips the checks, nothing else."""
    made = RationalBezier(c.control_points, c.weights)
    rebuilt = RationalBezier._rebuilt(c.control_points, c.weights)
    assert rebuilt.homogeneous.tobytes() == made.homogeneous.tobytes()
    assert rebuilt.control_points.tobytes() == made.control_points.tobytes()
    assert rebuilt.weights.tobytes() == made.weights.tobytes()
    assert not rebuilt.homogeneous.flags.writeable


def test_rebuilt_rows_that_overflow_go_through_the_constructors_check() -> None:
    pts = np.array([[0.0, 0.0], [1e300, 1.0]])
    with pytest.raises(NonFiniteError):
        RationalBezier._rebuilt(pts, np.array([1.0, 1e10]))


_SPECIAL = [0.0, -0.0, 1.0, -1.0, 1e-300, 1e300, 1.7e308, -1.7e308, 5e-324, math.inf, -math.inf, math.nan, 1e15, 1e-15]


def _built(pts: object, w: object) -> tuple[str, object]:
    """What the constructor gives: the rows' bits, or the error's class and message."""
    try:
        c = RationalBezier(pts, w)  # type: ignore[arg-type]
    except Exception as exc:  # noqa: BLE001 - compared below
        return "error", (type(exc).__name__, str(exc))
    return "rows", (c.homogeneous.tobytes(), c.control_points.tobytes(), c.weights.tobytes(),
                    c.is_polynomial)


@pytest.mark.parametrize("seed", range(4))
def test_the_compiled_rows_build_what_the_checked_rows_build(seed: int) -> None:
    """RationalBezier's one compiled pass against the checks and numpy products it replaced
    (relief_cad.curves._checked_rows, in the old order: points first, then weights), on points
    and weights with zeros, infinities, NaN, overflowing products and huge weight ratios."""
    from relief_cad.curves import _checked_rows

    rng = np.random.default_rng(seed)
    for _ in range(500):
        n, d = int(rng.integers(2, 6)), int(rng.integers(2, 4))
        pts = rng.normal(size=(n, d)) * 10.0 ** rng.integers(-5, 6)
        if rng.random() < 0.4:
            pts[rng.integers(n), rng.integers(d)] = rng.choice(_SPECIAL)
        w = None if rng.random() < 0.3 else rng.uniform(0.1, 3.0, n)
        if w is not None and rng.random() < 0.5:
            w[rng.integers(n)] = rng.choice(_SPECIAL)
        got = _built(pts, w)
        try:
            h = _checked_rows(np.array(pts), None if w is None else np.array(w))
            want_h = h.tobytes()
        except Exception as exc:  # noqa: BLE001 - compared below
            assert got == ("error", (type(exc).__name__, str(exc)))
            continue
        assert got[0] == "rows" and got[1][0] == want_h  # type: ignore[index]
        ones = np.ones(n) if w is None else np.asarray(w, dtype=float)
        assert got[1][2] == ones.tobytes() and got[1][1] == pts.astype(float).tobytes()  # type: ignore[index]


@pytest.mark.parametrize("weights", [[1.0, 2.0, 3.0], "ab", [1.0, -1.0]])
def test_bad_points_are_named_before_bad_weights(weights: object) -> None:
    with pytest.raises(NonFiniteError, match="control_points should be finite"):
        RationalBezier([[0.0, math.nan], [1.0, 1.0]], weights)  # type: ignore[arg-type]

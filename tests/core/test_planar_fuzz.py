"""Hypothesis fuzz of the planar intersector: robustness and metamorphic relations.

Random and adversarial pairs (coordinates from 1e-6 to 1e6, offsets up to 1e4,
repeated control points, point-like curves, nearly coincident curves, weights
from 1e-3 to 1e3). Checked: only ``ReliefCadError`` may escape and no hang
(budgets); swapping ``a`` and ``b`` swaps ``(t, u)``; reversing a curve maps
``t`` to ``1 - t``; an affine map keeps the parameters and maps the points;
splitting a curve and intersecting both halves gives the same points.

The metamorphic checks compare well-conditioned crossings only (angle between
the tangents above 1e-3, found in the reference run): tangent contacts and
near-misses sit on the tolerance boundary by construction.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from relief_cad.curves import RationalBezier
from relief_cad.errors import BudgetExceededError, ReliefCadError
from relief_cad.intersection import intersect
from relief_cad.results import Intersection, IntersectionList

unit = st.floats(min_value=-1.0, max_value=1.0, allow_nan=False, allow_infinity=False)


@st.composite
def planar_curve(draw: st.DrawFn, scale: float = 1.0, offset: tuple[float, float] = (0.0, 0.0),
                 adversarial: bool = True) -> RationalBezier:
    n = draw(st.integers(1, 5))
    pts = np.array(draw(st.lists(st.tuples(unit, unit), min_size=n + 1, max_size=n + 1)))
    if adversarial:
        mode = draw(st.sampled_from(["plain", "plain", "repeat", "point"]))
        if mode == "repeat":
            i = draw(st.integers(0, n))
            j = draw(st.integers(0, n))
            pts[i] = pts[j]
        elif mode == "point":
            pts[:] = pts[0]
    pts = pts * scale + np.array(offset)
    w = None
    if draw(st.booleans()):
        w = np.exp(np.array(draw(st.lists(st.floats(-math.log(1e3), math.log(1e3)),
                                          min_size=n + 1, max_size=n + 1))))
    return RationalBezier(pts, w)


@st.composite
def curve_pair(draw: st.DrawFn, adversarial: bool = True) -> tuple[RationalBezier, RationalBezier]:
    scale = 10.0 ** draw(st.integers(-6, 6))
    offset = (draw(st.floats(-1e4, 1e4)), draw(st.floats(-1e4, 1e4))) if draw(st.booleans()) else (0.0, 0.0)
    a = draw(planar_curve(scale, offset, adversarial))
    kind = draw(st.sampled_from(["independent", "independent", "near", "segment"])) if adversarial else "independent"
    if kind == "near":
        eps = scale * 10.0 ** draw(st.integers(-13, -6))
        b = RationalBezier(a.control_points + eps, a.weights)
    elif kind == "segment":
        t0 = draw(st.floats(0.0, 1.0))
        t1 = draw(st.floats(0.0, 1.0))
        b = a.segment(t0, t1) if abs(t1 - t0) > 1e-3 else a
    else:
        b = draw(planar_curve(scale, offset, adversarial))
    return a, b


def _dump(a: RationalBezier, b: RationalBezier) -> str:
    return repr([c.control_points.tolist() for c in (a, b)] + [c.weights.tolist() for c in (a, b)])


def _run(a: RationalBezier, b: RationalBezier) -> IntersectionList:
    return intersect(a, b, budget=4000, on_budget="return")


def _param_tol(a: RationalBezier, b: RationalBezier) -> float:
    """Parameter tolerance: 1e-7 widened by the rounding of coordinates far from the origin."""
    pts = np.vstack([a.control_points, b.control_points])
    size = float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))
    if size == 0.0:
        return 1.0
    return 1e-7 + 1e6 * np.finfo(float).eps * float(np.abs(pts).max()) / size


def _clean_crossings(a: RationalBezier, b: RationalBezier, res: IntersectionList) -> list[Intersection]:
    out = []
    for r in res.points:
        if r.kind != "crossing":
            continue
        da = a.derivative(r.t)
        db = b.derivative(r.u)
        na = float(np.hypot(*da))
        nb = float(np.hypot(*db))
        if not (na > 0.0 and nb > 0.0 and math.isfinite(na * nb)) or na * nb == 0.0:
            continue
        sin = abs(da[0] / na * db[1] / nb - da[1] / na * db[0] / nb)
        if sin > 1e-3 and 1e-6 < r.t < 1 - 1e-6 and 1e-6 < r.u < 1 - 1e-6:
            out.append(r)
    return out


def _has(res: IntersectionList, t: float, u: float, tol: float = 1e-7) -> bool:
    """``res`` has the contact ``(t, u)``: a point, an overlap over ``t``, or, where the budget ran
    out, an unresolved box holding it (reported, not dropped: ``res.complete`` is False then)."""
    for r in res:
        if isinstance(r, Intersection) and abs(r.t - t) <= tol and abs(r.u - u) <= tol:
            return True
        if not isinstance(r, Intersection):
            lo, hi = sorted(r.t)
            if lo - tol <= t <= hi + tol:
                return True
    return any(b.t0 - tol <= t <= b.t1 + tol and b.u0 - tol <= u <= b.u1 + tol for b in res.unresolved)


@settings(max_examples=1500)
@given(curve_pair())
def test_robust_only_relief_cad_errors(pair: tuple[RationalBezier, RationalBezier]) -> None:
    a, b = pair
    try:
        res = intersect(a, b, budget=4000)
    except BudgetExceededError as exc:
        assert exc.unresolved
        return
    except ReliefCadError:
        return
    assert [r.t if isinstance(r, Intersection) else r.t[0] for r in res] == sorted(
        r.t if isinstance(r, Intersection) else r.t[0] for r in res)
    for r in res.points:
        assert 0.0 <= r.t <= 1.0 and 0.0 <= r.u <= 1.0
        assert np.all(np.isfinite(r.point))


@settings(max_examples=250)
@given(curve_pair(adversarial=False))
def test_swap_swaps_parameters(pair: tuple[RationalBezier, RationalBezier]) -> None:
    a, b = pair
    ab = _run(a, b)
    ba = _run(b, a)
    for r in _clean_crossings(a, b, ab):
        assert _has(ba, r.u, r.t, _param_tol(a, b)), (r, list(ba), _dump(a, b))


# was a non-strict xfail: where a reversed curve osculates the other at a shared end (third-order
# contact) the clipping can spend this test's 4000-iteration budget in the tol band; the crossing
# then lies in an unresolved box, which _has accepts (the answer is honestly incomplete)
@settings(max_examples=250)
@given(curve_pair(adversarial=False))
def test_reverse_maps_t(pair: tuple[RationalBezier, RationalBezier]) -> None:
    a, b = pair
    ab = _run(a, b)
    rev = _run(a.reversed(), b)
    for r in _clean_crossings(a, b, ab):
        assert _has(rev, 1.0 - r.t, r.u, _param_tol(a, b)), (r, list(rev), _dump(a, b))


@settings(max_examples=250)
@given(curve_pair(adversarial=False), st.floats(-3.0, 3.0), st.floats(0.2, 5.0), st.floats(-100.0, 100.0))
def test_affine_map_keeps_parameters(pair: tuple[RationalBezier, RationalBezier], angle: float,
                                     stretch: float, shift: float) -> None:
    a, b = pair
    m = np.array([[stretch * math.cos(angle), -math.sin(angle), shift],
                  [stretch * math.sin(angle), math.cos(angle), -shift],
                  [0.0, 0.0, 1.0]])
    ab = _run(a, b)
    mapped = _run(a.transformed(m), b.transformed(m))
    for r in _clean_crossings(a, b, ab):
        assert _has(mapped, r.t, r.u, 10 * _param_tol(a, b)), (r, list(mapped), _dump(a, b))


@settings(max_examples=250)
@given(curve_pair(adversarial=False), st.floats(0.05, 0.95))
def test_split_gives_same_points(pair: tuple[RationalBezier, RationalBezier], s: float) -> None:
    a, b = pair
    ab = _run(a, b)
    left, right = a.split(s)
    lres = _run(left, b)
    rres = _run(right, b)
    merged = IntersectionList([Intersection(s * r.t, r.u, r.point, r.kind) for r in lres.points]
                              + [Intersection(s + (1 - s) * r.t, r.u, r.point, r.kind) for r in rres.points])
    for r in _clean_crossings(a, b, ab):
        assert _has(merged, r.t, r.u, _param_tol(a, b)), (r, list(merged), _dump(a, b), s)

"""The arbiter's exact curves (relief_cad.cad.exact.ExactCurve) on periodic B-spline edges.

An edge on a periodic B-spline may run past the curve's knot period (``[4.5, 7.5]`` on knots
``0..6``), start before it (``[-1, 1]``) or lie wholly in a later period (``[6, 8.5]``). Truth:
OCCT's own evaluation of the same edges (``BRepAdaptor_Curve``, which wraps the parameter into
the period), the curve's periodicity at 50 digits, and crossings built through OCCT's points.
"""

from __future__ import annotations

import math

import mpmath
import pytest
from OCP.BRep import BRep_Builder, BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeVertex
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Pnt, gp_Vec
from OCP.TopAbs import TopAbs_FORWARD, TopAbs_REVERSED
from OCP.TopoDS import TopoDS_Edge

from relief_cad import cad
from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal
from relief_cad.cad.compare import arbitrate_point, compare
from relief_cad.cad.exact import ARBITER_DIGITS, ExactCurve

PERIOD = 6.0
RANGES = [(4.5, 7.5), (0.5, 6.5), (-1.0, 1.0), (6.0, 8.5)]
WEIGHTS = [1.0, 3.0, 0.5, 2.0, 1.0, 0.25]


def periodic_curve(rational: bool) -> Geom_BSplineCurve:
    """A periodic cubic on knots 0..6 (the hunt's curve); rational with uneven weights."""
    poles = [
        (2 * math.cos(k * math.pi / 3), 1.3 * math.sin(k * math.pi / 3) + 0.2 * k, 0.0) for k in range(6)
    ]
    p = Array1OfPnt(1, 6)
    for i, q in enumerate(poles):
        p.SetValue(i + 1, gp_Pnt(*q))
    k = Array1OfReal(1, 7)
    m = Array1OfInteger(1, 7)
    for i in range(7):
        k.SetValue(i + 1, float(i))
        m.SetValue(i + 1, 1)
    if not rational:
        return Geom_BSplineCurve(p, k, m, 3, True)
    w = Array1OfReal(1, 6)
    for i, x in enumerate(WEIGHTS):
        w.SetValue(i + 1, x)
    return Geom_BSplineCurve(p, w, k, m, 3, True)


def edge_on(curve: Geom_BSplineCurve, a: float, b: float) -> TopoDS_Edge:
    """An edge on ``curve`` with range exactly ``[a, b]`` (BRepBuilderAPI_MakeEdge moves ``a`` into 0..6)."""
    builder = BRep_Builder()
    edge = TopoDS_Edge()
    builder.MakeEdge(edge, curve, 1e-7)
    for t, orientation in ((a, TopAbs_FORWARD), (b, TopAbs_REVERSED)):
        builder.Add(edge, BRepBuilderAPI_MakeVertex(curve.Value(t)).Vertex().Oriented(orientation))
    builder.Range(edge, a, b)
    assert BRep_Tool.Range_s(edge) == (a, b)
    return edge


def samples(a: float, b: float) -> list[float]:
    """Parameters over ``[a, b]``: 25 even ones, the knots and seams inside, and the ends."""
    even = [a + (b - a) * i / 24 for i in range(25)]
    knots = [float(k) for k in range(math.ceil(a), math.floor(b) + 1)]
    return sorted(set(even + knots))


def gap(p: list, q: tuple[float, float, float]) -> float:
    return max(abs(float(x) - y) for x, y in zip(p, q))


def crossing_line(curve: Geom_BSplineCurve, tc: float) -> TopoDS_Edge:
    """A segment across ``curve`` at ``tc`` (OCCT's point), along the normal; its parameter there is 0.3."""
    p, d = gp_Pnt(), gp_Vec()
    curve.D1(tc, p, d)
    n = (-d.Y() / d.Magnitude(), d.X() / d.Magnitude())
    a = gp_Pnt(p.X() - 0.3 * n[0], p.Y() - 0.3 * n[1], 0.0)
    b = gp_Pnt(p.X() + 0.3 * n[0], p.Y() + 0.3 * n[1], 0.0)
    return BRepBuilderAPI_MakeEdge(a, b).Edge()


@pytest.mark.parametrize("rational", [False, True], ids=["polynomial", "rational"])
@pytest.mark.parametrize("rng", RANGES, ids=[f"{a}..{b}" for a, b in RANGES])
def test_values_and_derivatives_match_occt_over_the_whole_edge_range(rational, rng):
    edge = edge_on(periodic_curve(rational), *rng)
    occ, ex = BRepAdaptor_Curve(edge), ExactCurve(edge)
    with mpmath.workdps(ARBITER_DIGITS):
        for t in samples(*rng):
            p, v1, v2 = gp_Pnt(), gp_Vec(), gp_Vec()
            occ.D2(t, p, v1, v2)
            q = p.Coord()
            assert gap(ex.value(t), q) <= 1e-12 * max(1.0, max(map(abs, q))), t
            _, d1, d2 = ex.jet(t)
            for mine, theirs in ((ex.derivative(t), v1), (d1, v1), (d2, v2)):
                q = theirs.Coord()
                assert gap(mine, q) <= 1e-10 * max(1.0, max(map(abs, q))), t


@pytest.mark.parametrize("rational", [False, True], ids=["polynomial", "rational"])
def test_value_is_periodic_and_continuous_at_50_digits(rational):
    ex = ExactCurve(edge_on(periodic_curve(rational), 4.5, 7.5))
    with mpmath.workdps(ARBITER_DIGITS):
        tiny = mpmath.mpf(2) ** -200  # far below a rounding of 6 at 50 digits
        start = ex.value(0)
        for t in (-tiny, tiny, PERIOD - tiny, PERIOD):  # either side of the seam: one point
            assert max(abs(x - y) for x, y in zip(ex.value(t), start)) <= mpmath.mpf(10) ** -40
        for t in (-tiny, tiny, PERIOD - tiny, mpmath.mpf("2.3"), mpmath.mpf("5.9")):
            here = ex.value(t)
            for k in (-2, -1, 1, 2, 3):
                there = ex.value(t + k * PERIOD)
                assert max(abs(x - y) for x, y in zip(here, there)) <= mpmath.mpf(10) ** -40, (t, k)


CROSSINGS = [(4.5, 7.5, 7.0), (0.5, 6.5, 6.25), (-1.0, 1.0, -0.5), (6.0, 8.5, 8.0)]


@pytest.mark.parametrize("rational", [False, True], ids=["polynomial", "rational"])
@pytest.mark.parametrize("a, b, tc", CROSSINGS, ids=[f"{a}..{b}@{tc}" for a, b, tc in CROSSINGS])
def test_the_arbiter_confirms_a_true_crossing(rational, a, b, tc):
    curve = periodic_curve(rational)
    edge, line = edge_on(curve, a, b), crossing_line(curve, tc)
    check = arbitrate_point(edge, line, tc + 1e-6, 0.3 - 1e-6, tol=1e-7)
    assert check.holds and check.kind == "crossing", check
    assert check.t == pytest.approx(tc, abs=1e-9) and check.u == pytest.approx(0.3, abs=1e-9)
    assert check.distance <= 1e-14 and check.exact


def test_compare_agrees_on_the_hunts_crossing_past_the_period():
    # the hunt's reproducer: relief_cad and OCCT both find the crossing at t ~ 6.9757 on [4.5, 7.5]
    edge = BRepBuilderAPI_MakeEdge(periodic_curve(False), 4.5, 7.5).Edge()
    line = BRepBuilderAPI_MakeEdge(gp_Pnt(-0.7, 1.25, 0), gp_Pnt(-0.9, 1.45, 0)).Edge()
    [r] = cad.intersections(edge, line)
    assert r.t == pytest.approx(6.975747217832237, abs=1e-9)
    check = arbitrate_point(edge, line, r.t, r.u, tol=1e-7)
    assert check.holds and check.kind == "crossing" and check.distance <= 1e-14
    c = compare(edge, line)
    assert c.errors == {} and c.disagreements == [] and c.agree
    [m] = c.agreed
    assert m.relief_error <= 1e-12 and m.occt_error <= 1e-12

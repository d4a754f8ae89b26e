"""Edge -> rational Bézier segment conversion, checked against OCCT's own evaluation.

OCCT (``BRepAdaptor_Curve.Value``) is the independent oracle: for every segment and
several ``s``, the segment point must equal the edge's point at ``edge_param(s)``.
"""

from __future__ import annotations

import math

import build123d as bd
import numpy as np
import pytest
from OCP.BRep import BRep_Builder, BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.Geom import (
    Geom_BezierCurve,
    Geom_BSplineCurve,
    Geom_Circle,
    Geom_Line,
    Geom_OffsetCurve,
    Geom_TrimmedCurve,
)
from OCP.gp import gp_Ax1, gp_Ax2, gp_Circ, gp_Dir, gp_Elips, gp_Hypr, gp_Parab, gp_Pnt, gp_Trsf, gp_Vec
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS_Edge

from relief_cad.cad import ocp
from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal, downcast_edge
from relief_cad.errors import (
    DegenerateCurveError,
    InputTypeError,
    ReliefCadError,
    UnsupportedCurveError,
)
from tests._env import cq, needs_cadquery

# ----------------------------------------------------------------------------- frames
FRAMES = {
    "xy": gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0)),
    "tilted": gp_Ax2(gp_Pnt(1.5, -2.0, 3.25), gp_Dir(1, 1, 1), gp_Dir(1, -1, 0)),
    "far": gp_Ax2(gp_Pnt(1000.0, 2000.0, -500.0), gp_Dir(0.2, -0.3, 0.9), gp_Dir(0, 0.9, 0.3)),
}


def _frame_pnt(ax: gp_Ax2, x: float, y: float, z: float = 0.0) -> gp_Pnt:
    o, xd, yd, zd = ax.Location(), ax.XDirection(), ax.YDirection(), ax.Direction()
    return gp_Pnt(
        o.X() + x * xd.X() + y * yd.X() + z * zd.X(),
        o.Y() + x * xd.Y() + y * yd.Y() + z * zd.Y(),
        o.Z() + x * xd.Z() + y * yd.Z() + z * zd.Z(),
    )


def _poles(ax: gp_Ax2, pts: list[tuple[float, ...]]) -> Array1OfPnt:
    arr = Array1OfPnt(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, _frame_pnt(ax, *p))
    return arr


def _reals(vals: list[float]) -> Array1OfReal:
    arr = Array1OfReal(1, len(vals))
    for i, v in enumerate(vals):
        arr.SetValue(i + 1, float(v))
    return arr


def _ints(vals: list[int]) -> Array1OfInteger:
    arr = Array1OfInteger(1, len(vals))
    for i, v in enumerate(vals):
        arr.SetValue(i + 1, int(v))
    return arr


def _edge(maker: BRepBuilderAPI_MakeEdge) -> TopoDS_Edge:
    assert maker.IsDone()
    return maker.Edge()


# ----------------------------------------------------------------------------- raw OCP curves
def line(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(_frame_pnt(ax, -1, 0.5), _frame_pnt(ax, 3, 2)))


def line_trimmed(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(Geom_Line(ax.Location(), ax.XDirection()), -2.5, 7.0))


def circle_full(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Circ(ax, 2.5)))


def circle_arc(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Circ(ax, 1.25), 0.3, 2.0))


def circle_arc_over_seam(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Circ(ax, 3.0), 5.0, 8.5))


def ellipse_full(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Elips(ax, 4.0, 1.5)))


def ellipse_arc(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Elips(ax, 4.0, 1.5), -1.0, 2.7))


def parabola(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Parab(ax, 0.75), -2.0, 3.0))


def hyperbola(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(gp_Hypr(ax, 2.0, 1.0), -1.5, 2.5))


def bezier_poly(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles(ax, [(0, 0), (1, 2), (3, -1), (4, 1)]))))


def bezier_rational_trimmed(ax: gp_Ax2) -> TopoDS_Edge:
    g = Geom_BezierCurve(_poles(ax, [(0, 0), (1, 2), (3, -1), (4, 1), (5, 0)]), _reals([1, 2, 0.5, 3, 1]))
    return _edge(BRepBuilderAPI_MakeEdge(g, 0.2, 0.85))


def bspline_multiplicities(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0), (1, 2), (2, -1), (3, 2), (4, 0), (5, 1), (6, -1), (7, 0.5), (8, 0)]
    knots = [0.0, 0.5, 1.25, 2.0, 3.0]
    mults = [4, 1, 3, 1, 4]  # 13 = 9 poles + degree 3 + 1
    g = Geom_BSplineCurve(_poles(ax, pts), _reals(knots), _ints(mults), 3)
    return _edge(BRepBuilderAPI_MakeEdge(g, 0.2, 2.9))


def bspline_single_span_trimmed(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0), (1, 2), (3, -1), (4, 1)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([1.5, 4.0]), _ints([4, 4]), 3)
    return _edge(BRepBuilderAPI_MakeEdge(g, 2.0, 3.75))


def bspline_single_span_rational(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0), (1, 2), (3, -1)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([1.0, 3.0, 0.5]), _reals([-1.0, 1.0]), _ints([3, 3]), 2)
    return _edge(BRepBuilderAPI_MakeEdge(g))


def bspline_c0_knot(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0), (1, 2), (2, 2), (3, 0), (4, -2), (5, -1), (6, 0)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([0, 1, 2]), _ints([4, 3, 4]), 3)
    return _edge(BRepBuilderAPI_MakeEdge(g))


def bspline_rational(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0), (1, 2), (2, -1), (3, 2), (4, 0), (5, 1)]
    g = Geom_BSplineCurve(
        _poles(ax, pts), _reals([1, 0.5, 2, 1.5, 0.7, 1]), _reals([0, 1, 2, 3]), _ints([3, 1, 2, 3]), 2
    )
    return _edge(BRepBuilderAPI_MakeEdge(g))


def bspline_periodic(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(2, 0), (1, 2), (-1, 2), (-2, 0), (-1, -2), (1, -2.5)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([0, 1, 2, 3, 4, 5, 6]), _ints([1] * 7), 3, True)
    return _edge(BRepBuilderAPI_MakeEdge(g))


def bspline_periodic_over_seam(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(2, 0), (1, 2), (-1, 2), (-2, 0), (-1, -2), (1, -2.5)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([0, 1, 2, 3, 4, 5, 6]), _ints([1] * 7), 3, True)
    return _edge(BRepBuilderAPI_MakeEdge(g, 4.5, 7.25))


def bspline_space(ax: gp_Ax2) -> TopoDS_Edge:
    pts = [(0, 0, 0), (1, 2, 1), (2, -1, -1), (3, 2, 2), (4, 0, -0.5), (5, 1, 1)]
    g = Geom_BSplineCurve(_poles(ax, pts), _reals([0, 1, 2, 3]), _ints([4, 1, 1, 4]), 3)
    return _edge(BRepBuilderAPI_MakeEdge(g))


def trimmed_circle(ax: gp_Ax2) -> TopoDS_Edge:
    return _edge(BRepBuilderAPI_MakeEdge(Geom_TrimmedCurve(Geom_Circle(ax, 2.0), 1.0, 4.0)))


OCP_BUILDERS = [
    line, line_trimmed, circle_full, circle_arc, circle_arc_over_seam, ellipse_full, ellipse_arc,
    parabola, hyperbola, bezier_poly, bezier_rational_trimmed, bspline_multiplicities, bspline_c0_knot,
    bspline_single_span_trimmed, bspline_single_span_rational,
    bspline_rational, bspline_periodic, bspline_periodic_over_seam, bspline_space, trimmed_circle,
]


def located(edge: TopoDS_Edge) -> TopoDS_Edge:
    trsf = gp_Trsf()
    trsf.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(0.3, -0.4, 0.8)), 0.7)
    move = gp_Trsf()
    move.SetTranslation(gp_Vec(5.0, -3.0, 2.0))
    return downcast_edge(edge.Moved(TopLoc_Location(move.Multiplied(trsf))))


def scaled(edge: TopoDS_Edge) -> TopoDS_Edge:
    trsf = gp_Trsf()
    trsf.SetScale(gp_Pnt(1, 1, 1), 2.5)
    return downcast_edge(edge.Located(TopLoc_Location(trsf)))


VARIANTS = {
    "plain": lambda e: e,
    "reversed": lambda e: downcast_edge(e.Reversed()),
    "located": located,
    "located_reversed": lambda e: downcast_edge(located(e).Reversed()),
    "scaled": scaled,
}


# ----------------------------------------------------------------------------- build123d / CadQuery
def _b3d_edges() -> dict[str, bd.Edge]:
    tilted = bd.Plane(origin=(1, 2, 3), z_dir=(1, 1, 1), x_dir=(1, -1, 0))
    return {
        "b3d_line": bd.Edge.make_line((0, 0, 0), (3, 4, 5)),
        "b3d_circle": bd.Edge.make_circle(2.0, plane=tilted),
        "b3d_arc": bd.Edge.make_circle(2.0, plane=tilted, start_angle=20, end_angle=250),
        "b3d_three_point_arc": bd.Edge.make_three_point_arc((0, 0, 0), (1, 1, 0), (2, 0, 0)),
        "b3d_ellipse": bd.Edge.make_ellipse(3.0, 1.0, plane=tilted, start_angle=-30, end_angle=200),
        "b3d_spline": bd.Edge.make_spline([(0, 0, 0), (1, 2, 0), (3, 1, 0), (4, 3, 1), (5, 0, 0)]),
        "b3d_spline_periodic": bd.Edge.make_spline(
            [(0, 0, 0), (2, 1, 0), (1, 3, 0), (-1, 2, 0)], periodic=True
        ),
        "b3d_bezier": bd.Edge.make_bezier((0, 0, 0), (1, 2, 1), (3, 1, -1), (4, 0, 0), weights=[1, 2, 3, 1]),
        "b3d_moved_arc": bd.Edge.make_circle(1.0, start_angle=0, end_angle=120).moved(
            bd.Location((1, 2, 3), (10, 20, 30))
        ),
        "b3d_line_in_sketch": _sketch_line(),
    }


def _sketch_line() -> bd.Edge:
    with bd.BuildLine(bd.Plane.XZ) as bl:
        bd.Line((0, 0), (2, 1))
    return bl.edges()[0]


def _cq_edges() -> dict[str, object]:
    """CadQuery edges (built when a test asks: CadQuery exists only in environment B)."""
    assert cq is not None
    return {
        "cq_line": cq.Edge.makeLine(cq.Vector(0, 0, 0), cq.Vector(1, 2, 3)),
        "cq_circle": cq.Edge.makeCircle(1.5, cq.Vector(1, 1, 1), cq.Vector(0, 1, 1), 10, 300),
        "cq_ellipse": cq.Edge.makeEllipse(3, 1, cq.Vector(0, 0, 0), cq.Vector(1, 0, 1), cq.Vector(0, 1, 0)),
        "cq_spline": cq.Edge.makeSpline([cq.Vector(0, 0, 0), cq.Vector(1, 1, 0), cq.Vector(2, 0, 1)]),
        "cq_spline_periodic": cq.Edge.makeSpline(
            [cq.Vector(0, 0, 0), cq.Vector(2, 1, 0), cq.Vector(1, 3, 0)], periodic=True
        ),
        "cq_bezier": cq.Edge.makeBezier([cq.Vector(0, 0, 0), cq.Vector(1, 2, 0), cq.Vector(3, 0, 0)]),
        "cq_workplane_arc": cq.Workplane("YZ").threePointArc((1, 1), (2, 0)).val(),
    }


NATIVE = _b3d_edges()
CQ_NAMES = ["cq_line", "cq_circle", "cq_ellipse", "cq_spline", "cq_spline_periodic", "cq_bezier",
            "cq_workplane_arc"]


# ----------------------------------------------------------------------------- round trips
S_VALUES = np.array([0.0, 1e-9, 0.1, 0.25, 1 / 3, 0.5, 0.77, 0.999, 1.0])


def check_round_trip(edge: object) -> list[ocp.Segment]:
    segs = ocp.edge_segments(edge)
    raw = edge if isinstance(edge, TopoDS_Edge) else edge.wrapped  # type: ignore[attr-defined]
    adaptor = BRepAdaptor_Curve(raw)
    first, last = adaptor.FirstParameter(), adaptor.LastParameter()
    # segments tile the edge's own range, in order, without gaps
    assert segs[0].t0 == first and segs[-1].t1 == last
    for a, b in zip(segs, segs[1:], strict=False):
        assert a.t1 == b.t0
        assert a.t0 < a.t1
    size = max(1.0, float(np.max(np.abs(np.vstack([s.curve.control_points for s in segs])))))
    for seg in segs:
        assert not seg.approximate
        ts = seg.edge_param(S_VALUES)
        assert np.all(np.diff(ts) >= 0)
        pts = seg.curve.evaluate(S_VALUES)
        for t, p in zip(ts, pts, strict=True):
            occt = np.array(adaptor.Value(float(t)).Coord())
            assert np.max(np.abs(occt - p)) <= 1e-12 * size, (t, occt, p)
        # the inverse map undoes the forward one
        np.testing.assert_allclose(seg.segment_param(ts), S_VALUES, rtol=0, atol=1e-13)
        assert seg.segment_param(seg.t0) == 0.0 and seg.segment_param(seg.t1) == 1.0
    return segs


@pytest.mark.parametrize("variant", list(VARIANTS))
@pytest.mark.parametrize("frame", list(FRAMES))
@pytest.mark.parametrize("builder", OCP_BUILDERS, ids=lambda f: f.__name__)
def test_ocp_round_trip(builder, frame, variant):
    check_round_trip(VARIANTS[variant](builder(FRAMES[frame])))


@pytest.mark.parametrize("name", list(NATIVE))
def test_native_round_trip(name):
    check_round_trip(NATIVE[name])


@needs_cadquery
@pytest.mark.parametrize("name", CQ_NAMES)
def test_cadquery_round_trip(name):
    edges = _cq_edges()
    assert sorted(edges) == sorted(CQ_NAMES)
    check_round_trip(edges[name])


@pytest.mark.parametrize(
    ("builder", "degree", "rational"),
    [
        (line, 1, False), (circle_arc, 2, True), (ellipse_full, 2, True), (parabola, 2, False),
        (hyperbola, 2, True), (bezier_poly, 3, False), (bspline_multiplicities, 3, False),
    ],
    ids=lambda v: getattr(v, "__name__", str(v)),
)
def test_segment_kind(builder, degree, rational):
    segs = ocp.edge_segments(builder(FRAMES["xy"]))
    assert all(s.curve.degree == degree for s in segs)
    assert all((not s.curve.is_polynomial) == rational for s in segs)


def test_span_counts():
    # a full circle: four 90 degree spans; knots of multiplicity 2 and 3 still split cleanly
    assert len(ocp.edge_segments(circle_full(FRAMES["xy"]))) == 4
    assert len(ocp.edge_segments(circle_arc(FRAMES["xy"]))) == 2
    segs = ocp.edge_segments(bspline_multiplicities(FRAMES["xy"]))
    assert [s.t0 for s in segs] == [0.2, 0.5, 1.25, 2.0]
    periodic = ocp.edge_segments(bspline_periodic_over_seam(FRAMES["xy"]))
    assert periodic[0].t0 == 4.5 and periodic[-1].t1 == 7.25


def test_circle_closed_form():
    # the arc's segments are the standard quarter arcs: |P(s) - C| = r for all s, weight cos(45 deg)
    segs = ocp.edge_segments(circle_full(FRAMES["xy"]))
    s = np.linspace(0, 1, 101)
    for seg in segs:
        assert np.allclose(np.hypot(*seg.curve.evaluate(s)[:, :2].T), 2.5, rtol=0, atol=1e-14)
        assert math.isclose(seg.curve.weights[1], math.sqrt(0.5), rel_tol=1e-15)
        # the map is the tan-half-angle relation, checked at the midpoint and a quarter
        assert math.isclose(seg.edge_param(0.5), 0.5 * (seg.t0 + seg.t1), rel_tol=1e-15)
        expected = 0.5 * (seg.t0 + seg.t1) - 2 * math.atan(0.5 * math.tan(math.pi / 8))
        assert math.isclose(seg.edge_param(0.25), expected, rel_tol=1e-15)


# ----------------------------------------------------------------------------- approximate / bad input
def test_offset_curve_is_approximated_and_flagged():
    base = Geom_Circle(FRAMES["xy"], 2.0)
    off = Geom_OffsetCurve(Geom_TrimmedCurve(base, 0.0, 2.0), 0.5, gp_Dir(0, 0, 1))
    edge = _edge(BRepBuilderAPI_MakeEdge(off))
    segs = ocp.edge_segments(edge)
    assert segs and all(s.approximate for s in segs)
    assert all(s.error <= ocp.APPROXIMATION_TOLERANCE for s in segs)
    adaptor = BRepAdaptor_Curve(edge)
    for seg in segs:
        for s in (0.0, 0.3, 1.0):
            occt = np.array(adaptor.Value(seg.edge_param(s)).Coord())
            assert np.linalg.norm(occt - seg.curve.evaluate(s)) <= 1e-6
    with pytest.raises(UnsupportedCurveError, match="OffsetCurve"):
        ocp.edge_segments(edge, approximate=False)


@pytest.mark.parametrize("basis, first, last", [("circle", 5.0, 7.0), ("circle", -1.0, 1.0), ("line", 0.0, 3.0)])
def test_offset_curve_is_approximated_over_the_edge_range(basis, first, last):
    """An offset of a whole circle over [5, 7] (past its period), or of an unbounded line (a hunt).

    The approximation covered the basis curve's own domain: past 2π the edge took an
    extrapolation (1.5e-5 off), and the line's offset failed as a "degenerate" segment.
    """
    curve = Geom_Circle(FRAMES["xy"], 1.0) if basis == "circle" else Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))
    edge = _edge(BRepBuilderAPI_MakeEdge(Geom_OffsetCurve(curve, 0.5, gp_Dir(0, 0, 1)), first, last))
    segs = ocp.edge_segments(edge)
    assert (segs[0].t0, segs[-1].t1) == BRep_Tool.Range_s(edge)  # OCCT keeps [-1, 1] as [2π - 1, 2π + 1]
    adaptor = BRepAdaptor_Curve(edge)
    for seg in segs:
        for s in np.linspace(0.0, 1.0, 9):
            occt = np.array(adaptor.Value(float(seg.edge_param(s))).Coord())
            assert np.linalg.norm(occt - seg.curve.evaluate(s)) <= 1e-7


def test_edge_without_3d_curve_is_approximated():
    # a helix from build123d lives on a cylinder: its edges carry curves on the surface
    helix = bd.Helix(pitch=1.0, height=2.0, radius=1.0)
    for edge in helix.edges():
        segs = ocp.edge_segments(edge)
        adaptor = BRepAdaptor_Curve(edge.wrapped)
        for seg in segs:
            for s in (0.0, 0.5, 1.0):
                occt = np.array(adaptor.Value(seg.edge_param(s)).Coord())
                assert np.linalg.norm(occt - seg.curve.evaluate(s)) <= 1e-5


def _zero_length_edge() -> TopoDS_Edge:
    builder = BRep_Builder()
    edge = TopoDS_Edge()
    builder.MakeEdge(edge, Geom_Line(gp_Pnt(1, 1, 1), gp_Dir(1, 0, 0)), 1e-7)
    builder.Range(edge, 2.0, 2.0)
    return edge


def _degenerated_edge() -> TopoDS_Edge:
    builder = BRep_Builder()
    edge = TopoDS_Edge()
    builder.MakeEdge(edge)
    builder.Degenerated(edge, True)
    return edge


@pytest.mark.parametrize(
    ("make", "error", "match"),
    [
        (_zero_length_edge, DegenerateCurveError, "zero length"),
        (_degenerated_edge, DegenerateCurveError, "degenerated"),
        (lambda: bd.Solid.make_box(1, 1, 1).wrapped, InputTypeError, "received a solid"),
        (lambda: bd.Face.make_rect(1, 1), InputTypeError, "received a face"),
        (lambda: bd.Vertex(1, 2, 3), InputTypeError, "received a vertex"),
        (lambda: ocp.make_compound([]), InputTypeError, "received a compound"),
        (lambda: "edge", InputTypeError, "received str"),
        (lambda: TopoDS_Edge(), InputTypeError, "null"),
    ],
)
def test_bad_input(make, error, match):
    with pytest.raises(error, match=match) as info:
        ocp.edge_segments(make())
    assert isinstance(info.value, ReliefCadError)


# ----------------------------------------------------------------------------- other conversions
def test_edges_of_unique_and_ordered():
    box = bd.Box(1, 2, 3)
    edges = ocp.edges_of(box)
    assert len(edges) == 12
    assert len(ocp.edges_of(box.wrapped)) == 12
    assert all(not a.IsSame(b) for i, a in enumerate(edges) for b in edges[i + 1 :])
    # a cylinder's seam edge appears twice in its face but once here
    assert len(ocp.edges_of(bd.Cylinder(1, 2))) == 3
    assert ocp.edges_of(bd.Edge.make_line((0, 0), (1, 1)))[0].IsSame(
        ocp.edges_of(bd.Edge.make_line((0, 0), (1, 1)))[0]
    ) is False


def test_geom_bezier_round_trip():
    from relief_cad.curves import RationalBezier

    curve = RationalBezier([[0, 0, 1], [1, 2, 0], [3, -1, 2], [4, 0, 0]], [1.0, 0.5, 2.0, 1.0])
    back = ocp.from_geom_bezier(ocp.to_geom_bezier(curve))
    np.testing.assert_array_equal(back.control_points, curve.control_points)
    np.testing.assert_array_equal(back.weights, curve.weights)
    planar = RationalBezier([[0, 0], [1, 2], [3, -1]], [1.0, 3.0, 1.0])
    back2 = ocp.from_geom_bezier(ocp.to_geom2d_bezier(planar))
    assert back2.dim == 2
    np.testing.assert_array_equal(back2.homogeneous, planar.homogeneous)
    edge = ocp.to_edge(curve)
    [seg] = ocp.edge_segments(edge)
    np.testing.assert_allclose(seg.curve.homogeneous, curve.homogeneous, rtol=1e-15)
    with pytest.raises(InputTypeError):
        ocp.from_geom_bezier(Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)))


def test_trim_edge_keeps_location_and_curve():
    edge = located(circle_arc(FRAMES["tilted"]))
    piece = ocp.trim_edge(edge, 0.5, 1.5)
    assert BRep_Tool.Range_s(piece) == (0.5, 1.5)
    for t in (0.5, 1.0, 1.5):
        np.testing.assert_allclose(ocp.edge_value(piece, t), ocp.edge_value(edge, t), atol=1e-14)
    with pytest.raises(DegenerateCurveError):
        ocp.trim_edge(edge, 1.0, 1.0)


@pytest.mark.parametrize("width", [5e-10, 3e-12])
def test_trim_edge_of_a_periodic_curve_below_occt_parameter_confusion_stays_short(width):
    """A piece of a circle narrower than ``PConfusion`` (1e-9): MakeEdge alone gives a whole circle."""
    edge = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1000.0)).Edge()
    piece = ocp.trim_edge(edge, 1.0, 1.0 + width)
    assert BRep_Tool.Range_s(piece) == (1.0, 1.0 + width)
    start, end = (ocp.edge_value(piece, t) for t in BRep_Tool.Range_s(piece))
    assert math.dist(start, end) == pytest.approx(1000.0 * width, rel=1e-3)
    assert BRepCheck_Analyzer(piece).IsValid()


def test_located_copies_each_get_their_own_placement() -> None:
    """Copies of one sketch placed by different locations (the edges of a copy share its location,
    whose matrix the conversion keeps): every converted segment lies on its own copy's edge."""
    sketch = bd.Circle(3) + bd.Rectangle(8, 2) + bd.Text("Relief", 4)
    copies = [sketch.moved(bd.Location((12 * k, 5 * k, 0), (0, 0, 1), 17 * k)) for k in range(4)]
    copies.append(sketch.moved(bd.Location((0, 0, 0), (0, 0, 1), 0)))  # the identity, after the others
    checked = 0
    for _ in range(2):  # the second pass meets every location again
        for copy in copies:
            for edge in copy.edges():
                adaptor = BRepAdaptor_Curve(edge.wrapped)
                for seg in ocp.edge_segments(edge.wrapped):
                    for t, s in ((seg.t0, 0.0), (0.5 * (seg.t0 + seg.t1), 0.5), (seg.t1, 1.0)):
                        p = adaptor.Value(t)
                        assert np.allclose(seg.curve(s), (p.X(), p.Y(), p.Z()), atol=1e-9)
                        checked += 1
    assert checked > 1000


# a periodic cubic B-spline of size 1e-4 (from a face read back from a BREP file) whose edge ends 3e-19
# below the curve's last knot: there OCCT 8.0's GeomConvert_BSplineCurveToBezierCurve sometimes
# returns arcs whose poles are uninitialised memory (found by an arrangement fuzz)
_PERIODIC_POLES = [(5.3657952229674233e-05, -2.8203958406125957e-05), (8.1744283514574836e-05, 3.9921248775447399e-05),
                   (6.935044460724103e-05, 8.9689937922855621e-05), (-3.507654704181075e-05, 8.6837118864465927e-05),
                   (-6.9185824147269075e-05, 2.0546917843323171e-05), (-0.00010870560455424085, -4.7739911889688697e-05),
                   (-2.626422689139772e-05, -0.00013714650224256125), (5.1077736391146336e-05, -5.5761344274738888e-05)]
_PERIODIC_KNOTS = [0.0, 6.3250874293420571e-05, 0.00015584514969939323, 0.00022040524574697265,
                   0.00028182662611769317, 0.00037817846896222806, 0.00045452773090633831, 0.00053051882923846327]


def _periodic_spline() -> Geom_BSplineCurve:
    poles, knots, mults = Array1OfPnt(1, 8), Array1OfReal(1, 8), Array1OfInteger(1, 8)
    for i, ((x, y), k) in enumerate(zip(_PERIODIC_POLES, _PERIODIC_KNOTS, strict=True)):
        poles.SetValue(i + 1, gp_Pnt(x, y, 0.0))
        knots.SetValue(i + 1, k)
        mults.SetValue(i + 1, 2 if i in (0, 7) else 1)
    return Geom_BSplineCurve(poles, knots, mults, 3, True)


def test_bspline_bound_a_few_ulps_off_a_knot_is_converted_on_the_curve() -> None:
    """The bound 3e-19 below the last knot is put on the knot before OCCT converts; every piece of
    50 conversions (the bad poles came with some heap states) lies on the curve, the edge's own
    range kept as the pieces' parameters."""
    curve = _periodic_spline()
    last = 0.000530518829238463  # the BREP file's rounding of the last knot
    assert 0.0 < _PERIODIC_KNOTS[-1] - last < 1e-18
    assert ocp._on_knot(_PERIODIC_KNOTS, last) == _PERIODIC_KNOTS[-1]
    assert ocp._on_knot(_PERIODIC_KNOTS, 0.5 * last) == 0.5 * last  # far from every knot: unchanged
    edge = BRepBuilderAPI_MakeEdge(curve, 0.0, last).Edge()
    adaptor = BRepAdaptor_Curve(edge)
    for _ in range(50):
        segs = ocp.edge_segments(edge)
        assert segs[0].t0 == 0.0 and segs[-1].t1 == last
        for seg in segs:
            assert np.all(seg.homogeneous[:, 2] == 0.0)  # in the plane z = 0, as the curve
            for t, s in ((seg.t0, 0.0), (0.5 * (seg.t0 + seg.t1), 0.5), (seg.t1, 1.0)):
                assert np.allclose(seg.curve(s), adaptor.Value(t).Coord(), rtol=0.0, atol=1e-15)


def test_periodic_spline_read_back_from_brep_text_is_converted() -> None:
    """A closed periodic spline of size 500 (workbench conic family) written as BREP text and read
    back: the text keeps the edge's range to 15 digits, 4.3e-12 above the last knot at 1646. That
    was not on the knot for ``_on_knot`` (within 1e-12), and OCCT 8.0 gave a middle arc 7 off the
    curve, so the edge could not be used. A bound within 1e-14 of a knot, relative, is on it."""
    import io

    from OCP.BRepTools import BRepTools
    from OCP.TopoDS import TopoDS_Shape

    pts = [bd.Vector(500.0 * math.cos(q), 400.0 * math.sin(q)) for q in (0.3, 1.4, 2.1, 3.3, 4.0, 5.2, 5.9)]
    written = io.BytesIO()
    BRepTools.Write_s(bd.Edge.make_spline(pts, periodic=True).wrapped, written)
    shape = TopoDS_Shape()
    BRepTools.Read_s(shape, io.BytesIO(written.getvalue()), BRep_Builder())
    edge = downcast_edge(shape)
    curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
    first, last = BRep_Tool.Range_s(edge)
    knot = curve.Knot(curve.NbKnots())
    assert abs(last - knot) <= 1e-14 * knot  # the text keeps 15 digits of the range (OCCT 8.0: 4.3e-12 off)
    adaptor = BRepAdaptor_Curve(edge)
    segs = ocp.edge_segments(edge)
    assert segs[0].t0 == first and segs[-1].t1 == last
    for seg in segs:
        for t, s in ((seg.t0, 0.0), (0.5 * (seg.t0 + seg.t1), 0.5), (seg.t1, 1.0)):
            assert np.allclose(seg.curve(s), adaptor.Value(t).Coord(), rtol=0.0, atol=1e-9)


def test_an_arc_off_its_curve_is_an_error_not_an_answer() -> None:
    """The guard on OCCT's Bézier arcs: an arc that does not run on the curve raises OcctError."""
    from OCP.GeomConvert import GeomConvert_BSplineCurveToBezierCurve

    from relief_cad.errors import OcctError

    curve = _periodic_spline()
    conv = GeomConvert_BSplineCurveToBezierCurve(curve)
    ks = _PERIODIC_KNOTS
    size = max(abs(c) for xy in _PERIODIC_POLES for c in xy)
    ocp._check_arc(curve, conv.Arc(2), ks[1], ks[2], size)  # the right arc: no error
    with pytest.raises(OcctError, match="off the curve"):
        ocp._check_arc(curve, conv.Arc(3), ks[1], ks[2], size)  # its neighbour


# --------------------------------------------------------------------------- bounds near knots, ranges past a period
@pytest.mark.parametrize("offset", [8e-10, 3e-10, -3e-10, -8e-10, 0.0])
def test_a_bound_within_pconfusion_of_a_knot_converts_exactly(offset):
    """A cubic B-spline 14,000 long, knots 0, 0.5, 1, cut at 0.5 + offset (found by a hunt).

    Given such a bound, OCCT's converter kept the whole span [0.5, 1] but started its arc at
    neither 0.5 nor the bound: the segment was 3.7e-6 off the edge at the reported parameters.
    """
    poles = [(0, 0, 0), (3000, 4000, 0), (7000, -3000, 0), (10000, 2000, 0), (14000, 0, 0)]
    curve = Geom_BSplineCurve(_poles(FRAMES["xy"], poles), _reals([0.0, 0.5, 1.0]), _ints([4, 1, 4]), 3, False)
    # the bound on the far side of the knot from the rest of the edge (no sliver of width 8e-10,
    # whose parameter map check_round_trip cannot check to 1e-13)
    first, last = (0.5 + offset, 1.0) if offset >= 0 else (0.0, 0.5 + offset)
    check_round_trip(BRepBuilderAPI_MakeEdge(curve, first, last).Edge())


@pytest.mark.parametrize("first, last", [(-1.0, 1.0), (4.0, 7.0), (1.0, 7.0), (4.5, 7.5), (6.0, 8.5),
                                         (-3.0, 2.999999999), (0.5, 6.5), (-7.5, -4.0)])
def test_periodic_bspline_ranges_past_the_first_period_convert(first, last):
    """Ranges of a periodic B-spline (knots 0..6) ending on a knot a period on: OCCT's converter
    took 7 for 1 and failed on [5, 7]; each is a valid edge, converted exactly now."""
    poles = [(2 * math.cos(k * math.pi / 3), 1.3 * math.sin(k * math.pi / 3) + 0.2 * k) for k in range(6)]
    curve = Geom_BSplineCurve(_poles(FRAMES["xy"], poles), _reals([float(k) for k in range(7)]), _ints([1] * 7), 3, True)
    edge = BRepBuilderAPI_MakeEdge(curve, first, last).Edge()
    assert BRepCheck_Analyzer(edge).IsValid()
    check_round_trip(edge)

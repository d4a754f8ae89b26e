"""relief_cad.cad.intersect / intersections / split on real OCCT edges.

Truth: closed forms where they exist; otherwise OCCT's own answer on the same edges
(relief_cad.cad.occt) and evaluating both edges at the reported parameters.
"""

from __future__ import annotations

import math
from typing import Any

import build123d as bd
import numpy as np
import pytest
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepAlgoAPI import BRepAlgoAPI_Splitter
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakePolygon
from OCP.GCPnts import GCPnts_AbscissaPoint
from OCP.Geom import Geom_BezierCurve, Geom_BSplineCurve
from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
from OCP.gp import gp_Ax1, gp_Ax2, gp_Circ, gp_Dir, gp_Elips, gp_Pnt, gp_Trsf, gp_Vec
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS_Edge, TopoDS_Vertex

from relief_cad.cad import api, ocp
from relief_cad.cad import build123d as rbd
from relief_cad.cad import split as cad_split
from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal, ListOfShape, downcast_edge
from relief_cad.cad.compare import compare
from relief_cad.cad.occt import occt_intersections
from relief_cad.cad.results import EdgeIntersection, EdgeOverlap
from relief_cad.errors import InputTypeError, InvalidInputError, ReliefCadError, ToleranceError
from tests._env import cq, needs_cadquery

TILTED = gp_Ax2(gp_Pnt(1.5, -2.0, 3.25), gp_Dir(1, 1, 1), gp_Dir(1, -1, 0))
XY = gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0))
FRAMES = {"xy": XY, "tilted": TILTED}


def fp(ax: gp_Ax2, x: float, y: float, z: float = 0.0) -> gp_Pnt:
    o, xd, yd, zd = ax.Location(), ax.XDirection(), ax.YDirection(), ax.Direction()
    return gp_Pnt(*(o.Coord(i) + x * xd.Coord(i) + y * yd.Coord(i) + z * zd.Coord(i) for i in (1, 2, 3)))


def seg(ax: gp_Ax2, p: tuple[float, ...], q: tuple[float, ...]) -> TopoDS_Edge:
    return BRepBuilderAPI_MakeEdge(fp(ax, *p), fp(ax, *q)).Edge()


def circle(ax: gp_Ax2, r: float) -> TopoDS_Edge:
    return BRepBuilderAPI_MakeEdge(gp_Circ(ax, r)).Edge()


def located(edge: TopoDS_Edge) -> TopoDS_Edge:
    trsf = gp_Trsf()
    trsf.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(0.3, -0.4, 0.8)), 0.7)
    move = gp_Trsf()
    move.SetTranslation(gp_Vec(5.0, -3.0, 2.0))
    return downcast_edge(edge.Moved(TopLoc_Location(move.Multiplied(trsf))))


def value(edge: object, t: float) -> np.ndarray:
    raw = edge if isinstance(edge, TopoDS_Edge) else edge.wrapped  # type: ignore[attr-defined]
    return np.array(BRepAdaptor_Curve(raw).Value(t).Coord())


def check_on_edges(results: list, tol: float = 1e-9) -> None:
    """Every reported point lies on both edges at the reported parameters (OCCT evaluation)."""
    for r in results:
        if isinstance(r, EdgeIntersection):
            np.testing.assert_allclose(value(r.edge_a, r.t), r.point, atol=tol)
            np.testing.assert_allclose(value(r.edge_b, r.u), r.point, atol=tol)
        else:
            for t, u in zip(r.t, r.u, strict=True):
                np.testing.assert_allclose(value(r.edge_a, t), value(r.edge_b, u), atol=tol)


def vertex_points(vertices: list) -> list[tuple[float, float, float]]:
    out = []
    for v in vertices:
        raw = v if isinstance(v, TopoDS_Vertex) else v.wrapped
        out.append(BRep_Tool.Pnt_s(raw).Coord())
    return sorted(out)


def matches(ours: list, occt: list, tol: float = 1e-7) -> None:
    """Same set of points as OCCT (each of ours near one of OCCT's and vice versa)."""
    pa = [np.array(r.point) for r in ours if isinstance(r, EdgeIntersection)]
    pb = [np.array(r.point) for r in occt if isinstance(r, EdgeIntersection)]
    # OCCT quirk (Geom2dInt_GInter): a transversal circle/circle crossing can come back as an
    # "overlap" of length ~1e-7; count it as the point it is
    pb += [value(r.edge_a, 0.5 * (r.t[0] + r.t[1])) for r in occt
           if isinstance(r, EdgeOverlap) and abs(r.t[1] - r.t[0]) < 1e-5]
    assert len(pa) == len(pb), (pa, pb)
    for p in pa:
        assert min(np.linalg.norm(p - q) for q in pb) <= tol
    for q in pb:
        assert min(np.linalg.norm(p - q) for p in pa) <= tol


# ----------------------------------------------------------------------------- closed forms
@pytest.mark.parametrize("frame", list(FRAMES))
@pytest.mark.parametrize("move", [False, True])
def test_line_line(frame, move):
    ax = FRAMES[frame]
    a, b = seg(ax, (0, 0), (4, 2)), seg(ax, (0, 3), (3, 0))
    if move:
        a, b = located(a), located(b)
    [hit] = api.intersections(a, b)
    # x/2 = 3 - x -> x = 2, y = 1; t on a is the distance from its start
    assert math.isclose(hit.t, math.hypot(2, 1), rel_tol=1e-14)
    assert math.isclose(hit.u, math.hypot(2, 2), rel_tol=1e-14)
    expected = value(a, hit.t)
    np.testing.assert_allclose(hit.point, expected, atol=1e-12)
    assert hit.kind == "crossing" and hit.route == "relief_cad" and not hit.approximate
    check_on_edges([hit])


@pytest.mark.parametrize("frame", list(FRAMES))
@pytest.mark.parametrize("reverse", [False, True])
def test_circle_line_angles(frame, reverse):
    ax = FRAMES[frame]
    c = circle(ax, 2.0)
    if reverse:
        c = downcast_edge(c.Reversed())
    line = seg(ax, (-3, 1), (3, 1))
    hits = api.intersections(c, line)
    # y = 1 on the circle of radius 2: angles pi/6 and 5pi/6 (the edge's own parameters)
    assert [round(h.t, 14) for h in hits] == [round(math.pi / 6, 14), round(5 * math.pi / 6, 14)]
    assert sorted(round(h.u, 13) for h in hits) == sorted(round(3 + s * math.sqrt(3), 13) for s in (-1, 1))
    check_on_edges(hits)


def test_ellipse_circle_closed_form():
    a_, b_, r = 3.0, 1.0, 2.0
    ell = BRepBuilderAPI_MakeEdge(gp_Elips(XY, a_, b_)).Edge()
    hits = api.intersections(ell, circle(XY, r))
    x = a_ * math.sqrt((r * r - b_ * b_) / (a_ * a_ - b_ * b_))
    y = math.sqrt(r * r - x * x)
    expected = sorted((sx * x, sy * y, 0.0) for sx in (-1, 1) for sy in (-1, 1))
    got = sorted(tuple(round(c, 12) for c in h.point) for h in hits)
    np.testing.assert_allclose(got, expected, atol=1e-13)
    for h in hits:  # the ellipse's own parameter: x = a cos t, y = b sin t
        assert math.isclose(math.cos(h.t) * a_, h.point[0], abs_tol=1e-13)
        assert math.isclose(math.sin(h.t) * b_, h.point[1], abs_tol=1e-13)
    check_on_edges(hits)


def test_space_crossing_of_a_twisted_spline():
    pts = [(0, 0, 0), (1, 2, 1), (2, -1, -1), (3, 2, 2), (4, 0, -0.5), (5, 1, 1)]
    spline = bd.Edge.make_spline(pts)
    p = np.array(tuple(spline.position_at(0.37)))
    d = np.array([0.3, -0.2, 1.0])
    line = bd.Edge.make_line(tuple(p - d), tuple(p + 2 * d))
    [hit] = api.intersections(spline, line)
    np.testing.assert_allclose(hit.point, p, atol=1e-9)
    assert math.isclose(hit.u, math.sqrt(d @ d), rel_tol=1e-9)
    check_on_edges([hit])


# ----------------------------------------------------------------------------- against OCCT
def _spline_xy() -> bd.Edge:
    return bd.Edge.make_spline([(-3, -1), (-1, 2), (0, -1.5), (1.5, 1.8), (3, -0.5)])


CASES = {
    "spline_arc": lambda: (_spline_xy(), bd.Edge.make_circle(1.2, start_angle=-30, end_angle=260)),
    "spline_line": lambda: (_spline_xy(), bd.Edge.make_line((-4, 0.2), (4, 0.3))),
    "spline_spline": lambda: (_spline_xy(), _spline_xy().rotate(bd.Axis.Z, 25)),
    "ellipse_circle_tilted": lambda: (
        bd.Edge.make_ellipse(3, 1, plane=bd.Plane((1, 2, 3), z_dir=(1, 1, 1))),
        bd.Edge.make_circle(2, plane=bd.Plane((1, 2, 3), z_dir=(1, 1, 1))),
    ),
    "arc_arc_located": lambda: (
        bd.Edge.make_circle(1, start_angle=0, end_angle=200).moved(bd.Location((0.5, 0, 0), (0, 0, 10))),
        bd.Edge.make_circle(1.2, start_angle=-90, end_angle=180),
    ),
}


@pytest.mark.parametrize("name", list(CASES))
def test_against_occt(name):
    a, b = CASES[name]()
    ours = api.intersections(a, b)
    assert ours
    check_on_edges(ours)
    matches(ours, occt_intersections(a, b))


def test_glyph_outlines_cross():
    t1 = bd.Text("A", 10)
    t2 = bd.Text("B", 10).rotate(bd.Axis.Z, 17).translate((1.2, 0.8, 0))
    ours = api.intersections(t1, t2)
    assert len(ours) >= 4
    check_on_edges(ours, tol=1e-7)
    matches(ours, occt_intersections(t1, t2), tol=1e-6)
    assert isinstance(ours[0].edge_a, bd.Edge)
    verts = api.intersect(t1, t2)
    assert isinstance(verts, bd.ShapeList) and all(isinstance(v, bd.Vertex) for v in verts)
    assert len(verts) == len(ours)


def test_two_filleted_sketch_wires():
    with bd.BuildSketch() as sk1:
        bd.Rectangle(4, 2)
        bd.fillet(sk1.vertices(), 0.5)
    with bd.BuildSketch() as sk2:
        bd.Rectangle(3, 3)
        bd.fillet(sk2.vertices(), 0.8)
    w1 = sk1.sketch.wires()[0]
    w2 = sk2.sketch.wires()[0].rotate(bd.Axis.Z, 30).translate((0.7, 0.3, 0))
    ours = api.intersections(w1, w2)
    assert ours
    check_on_edges(ours)
    matches(ours, occt_intersections(w1, w2))
    # indices refer to the unique-edge lists
    for r in ours:
        assert ocp.edges_of(w1)[r.index_a].IsSame(r.edge_a.wrapped)
        assert ocp.edges_of(w2)[r.index_b].IsSame(r.edge_b.wrapped)


def _busy_sketch() -> tuple[list[bd.Edge], list[bd.Edge]]:
    """Two sets of many planar edges: glyphs, filleted rectangles, a circle, a wavy spline, a Bézier
    crossing itself, a tangent line, a partly overlapping copy of a rectangle and a doubled edge."""
    glyphs = bd.Text("Re", font_size=6).edges()
    rect = bd.RectangleRounded(4.0, 2.5, 0.6).edges()
    moved = [e.translate((1.5, 0.0, 0.0)) for e in rect]  # shares stretches of the long sides
    circle = bd.Edge.make_circle(1.0).translate((1.0, 1.0, 0.0))
    tangent = bd.Edge.make_line((-3.0, 2.0, 0.0), (5.0, 2.0, 0.0))  # touches the circle's top
    wavy = bd.Edge.make_spline([bd.Vector(x, 0.8 * math.sin(x)) for x in np.linspace(-4.0, 6.0, 12)])
    loop = bd.Edge(BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([(0, 0), (3, 2), (-1, 2), (2, 0)]))).Edge())
    a = list(glyphs) + list(rect) + [circle, wavy, rect[0]]
    b = moved + [tangent, loop]
    return a, b


def _rows(results: list) -> list[tuple]:
    return [(type(r).__name__, r.index_a, r.index_b, r.t, r.u, getattr(r, "point", None)) for r in results]


@pytest.mark.parametrize("two_sets", [False, True])
def test_one_pass_over_all_segments_finds_what_edge_pairs_find(monkeypatch, two_sets):
    a, b = _busy_sketch()
    args = (a, b) if two_sets else (a + b,)
    assert len(args[0]) * len(args[-1]) > api._ONE_PASS_ABOVE  # the one pass runs
    swept = api.intersections(*args)
    monkeypatch.setattr(api, "_ONE_PASS_ABOVE", 10**9)  # edge pair by edge pair
    assert _rows(swept) == _rows(api.intersections(*args))
    kinds = {type(r).__name__ for r in swept} | {getattr(r, "kind", "") for r in swept}
    assert {"EdgeOverlap", "crossing", "tangent"} <= kinds  # the core's post-pass ran too
    check_on_edges(swept, tol=1e-7)


def test_end_meeting_test_is_the_same_on_floats_and_in_numpy():
    # a few pairs are tested on Python floats, many in one numpy pass: the same verdicts
    rng = np.random.default_rng(3)
    ends = np.round(rng.random((40, 6)) * 4, 1)
    ends[1:20:2] = ends[0:20:2][:, [3, 4, 5, 0, 1, 2]] + rng.choice([0.0, 0.05, 0.2], (10, 1))  # reversed
    ends[21:40:2] = ends[20:40:2] + rng.choice([0.0, 0.05, 0.2], (10, 1))
    pairs = np.array([(i, j) for i in range(40) for j in range(40)])
    tol = 0.1
    many = api._apart_pairs(ends.tolist(), pairs, tol)
    assert len(pairs) // 2 < len(many) <= len(pairs) - 20
    few = [k + i for k in range(0, len(pairs), 20) for i in api._apart_pairs(ends.tolist(), pairs[k:k + 20], tol)]
    assert few == many


# ----------------------------------------------------------------------------- once only
def test_shared_vertex_reported_once():
    a = seg(XY, (0, 0), (1, 1))
    b = seg(XY, (1, 1), (2, 0))
    [hit] = api.intersections(a, b)
    assert hit.point == pytest.approx((1.0, 1.0, 0.0), abs=1e-14)
    assert math.isclose(hit.t, math.sqrt(2), rel_tol=1e-15) and hit.u == 0.0


def _poles(pts: list[tuple[float, float]]) -> Array1OfPnt:
    arr = Array1OfPnt(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, gp_Pnt(p[0], p[1], 0.0))
    return arr


def test_crossing_at_bspline_knot_reported_once():
    knots = Array1OfReal(1, 3)
    for i, k in enumerate((0.0, 1.0, 2.0)):
        knots.SetValue(i + 1, k)
    mults = Array1OfInteger(1, 3)
    for i, m in enumerate((4, 1, 4)):
        mults.SetValue(i + 1, m)
    g = Geom_BSplineCurve(_poles([(0, 0), (1, 2), (2, -1), (3, 2), (4, 0)]), knots, mults, 3)
    spline = BRepBuilderAPI_MakeEdge(g).Edge()
    p = g.Value(1.0)
    line = BRepBuilderAPI_MakeEdge(gp_Pnt(p.X() - 0.5, p.Y() - 3, 0), gp_Pnt(p.X() + 0.5, p.Y() + 3, 0)).Edge()
    hits = api.intersections(spline, line)
    assert len(hits) == 1
    assert math.isclose(hits[0].t, 1.0, abs_tol=1e-12)
    assert len(api.intersect(spline, line)) == 1


def test_overlap_of_collinear_lines_and_arcs():
    a = seg(XY, (0, 0), (3, 0))
    b = seg(XY, (2, 0), (5, 0))
    [ov] = api.intersections(a, b)
    assert isinstance(ov, EdgeOverlap)
    assert ov.t == pytest.approx((2.0, 3.0), abs=1e-12) and ov.u == pytest.approx((0.0, 1.0), abs=1e-12)
    assert BRep_Tool.Range_s(ov.edge) == pytest.approx((2.0, 3.0), abs=1e-12)
    arc1 = BRepBuilderAPI_MakeEdge(gp_Circ(XY, 1.0), 0.0, 2.0).Edge()
    arc2 = BRepBuilderAPI_MakeEdge(gp_Circ(XY, 1.0), 1.0, 3.0).Edge()
    [ov2] = api.intersections(arc1, arc2)
    assert isinstance(ov2, EdgeOverlap)
    assert ov2.t == pytest.approx((1.0, 2.0), abs=1e-9) and ov2.u == pytest.approx((1.0, 2.0), abs=1e-9)
    check_on_edges([ov, ov2])


# ----------------------------------------------------------------------------- self-intersections
def test_bowtie_wire_self_intersection_without_shared_vertices():
    bowtie = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0), gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), True)
    hits = api.intersections(bowtie.Wire())
    assert len(hits) == 1
    assert hits[0].point == pytest.approx((1.0, 1.0, 0.0), abs=1e-14)
    assert hits[0].index_a < hits[0].index_b


def test_looping_bezier_crosses_itself_once():
    g = Geom_BezierCurve(_poles([(0, 0), (3, 2), (-1, 2), (2, 0)]))
    edge = BRepBuilderAPI_MakeEdge(g).Edge()
    [hit] = api.intersections(edge)
    assert hit.index_a == hit.index_b == 0 and hit.t < hit.u
    # symmetric loop: x(t) = x(1 - t) on the double point, so t + u = 1
    assert math.isclose(hit.t + hit.u, 1.0, abs_tol=1e-9)
    check_on_edges([hit])


@pytest.mark.parametrize(
    "shape",
    [
        lambda: circle(TILTED, 2.0),
        lambda: bd.Wire.make_rect(2, 1),
        lambda: bd.Edge.make_spline([(0, 0), (2, 1), (1, 3), (-1, 2)], periodic=True),
        lambda: bd.Face.make_rect(2, 1),
        lambda: bd.Solid.make_box(1, 2, 3),
        lambda: bd.Solid.make_cylinder(1, 2),
        lambda: bd.Solid.make_sphere(1),
        lambda: bd.Solid.make_cone(1, 0, 2),
        lambda: bd.fillet(bd.Box(2, 2, 2).edges(), 0.3),
        lambda: bd.Text("S", 10),
    ],
)
def test_simple_shapes_have_no_self_intersections(shape):
    assert api.intersections(shape()) == []


# ----------------------------------------------------------------------------- flavours
def test_flavours_of_vertices():
    a_b, b_b = bd.Edge.make_line((0, 0), (2, 2)), bd.Edge.make_line((0, 2), (2, 0))
    assert isinstance(api.intersect(a_b, b_b)[0], bd.Vertex)
    [raw] = api.intersect(a_b.wrapped, b_b.wrapped)
    assert isinstance(raw, TopoDS_Vertex)


@needs_cadquery
def test_flavours_of_cadquery_vertices():
    a_c = cq.Edge.makeLine(cq.Vector(0, 0, 0), cq.Vector(2, 2, 0))
    b_c = cq.Edge.makeLine(cq.Vector(0, 2, 0), cq.Vector(2, 0, 0))
    [v] = api.intersect(a_c, b_c)
    assert isinstance(v, cq.Vertex) and v.toTuple() == pytest.approx((1, 1, 0))
    [raw] = api.intersect(a_c.wrapped, b_c.wrapped)
    assert isinstance(raw, TopoDS_Vertex)


def test_build123d_contexts_and_algebra():
    with bd.BuildSketch() as sk:
        c = bd.Circle(1.0)
        bd.Rectangle(3, 0.5, mode=bd.Mode.PRIVATE)
        line = bd.Edge.make_line((-2, 0.25), (2, 0.25))
        pts = rbd.intersect(c.edges(), line)
        assert len(pts) == 2
        with bd.Locations(*pts):
            bd.Circle(0.1, mode=bd.Mode.SUBTRACT)
    assert len(sk.sketch.faces()) == 1
    # algebra mode: plain functions on shapes
    arc = bd.CenterArc((0, 0), 1, 0, 180)
    pieces = rbd.split(arc, bd.Line((-2, 0.5), (2, 0.5)))
    assert len(pieces) == 3 and isinstance(pieces, bd.ShapeList)


@needs_cadquery
def test_cadquery_plugin_invoke_and_register():
    from relief_cad.cad import cadquery as rcq

    line = cq.Workplane("XY").moveTo(-2, 0.5).lineTo(2, 0.5)
    circ = cq.Workplane("XY").circle(1.0)
    wp = line.invoke(rcq.intersection_points(circ))
    assert wp.size() == 2 and all(isinstance(v, cq.Vertex) for v in wp.vals())
    # the chain goes on: a circle at each point
    assert wp.circle(0.1).size() == 2
    posts = (
        cq.Workplane("XZ").rect(4, 2, forConstruction=True)
        .invoke(rcq.intersection_points(cq.Workplane("XZ").circle(1.5)))
        .circle(0.1).extrude(1)
    )
    assert posts.solids().size() == 4
    centres = sorted(tuple(round(c, 9) for c in s.Center().toTuple()) for s in posts.solids().vals())
    x = math.sqrt(1.5**2 - 1.0)
    assert [c[0] for c in centres] == pytest.approx([-x, -x, x, x], abs=1e-6)
    assert not hasattr(cq.Workplane, "relief_points")
    rcq.register("relief_points")
    try:
        assert line.relief_points(circ).size() == 2
        with pytest.raises(InvalidInputError):
            rcq.register("circle")
    finally:
        delattr(cq.Workplane, "relief_points")


# ----------------------------------------------------------------------------- split vs OCCT's splitter
def _occt_split(a: TopoDS_Edge, b: TopoDS_Edge) -> list[TopoDS_Edge]:
    splitter = BRepAlgoAPI_Splitter()
    args, tools = ListOfShape(), ListOfShape()
    args.Append(a)
    tools.Append(b)
    splitter.SetArguments(args)
    splitter.SetTools(tools)
    splitter.Build()
    assert splitter.IsDone()
    return ocp.edges_of(splitter.Shape())


def _length(edge: TopoDS_Edge) -> float:
    return float(GCPnts_AbscissaPoint.Length_s(BRepAdaptor_Curve(edge), 1e-13))


@pytest.mark.parametrize(
    "pair",
    [
        lambda: (seg(XY, (-3, 0.5), (3, 0.5)), circle(XY, 2.0)),
        lambda: (circle(TILTED, 2.0), seg(TILTED, (-3, 0.5), (3, 0.5))),
        lambda: (_spline_xy().wrapped, bd.Edge.make_line((-4, 0.2), (4, 0.3)).wrapped),
        lambda: (located(circle(XY, 1.0)), located(seg(XY, (0, -2), (0.3, 2)))),
    ],
)
def test_split_matches_occt_splitter(pair):
    a, b = pair()
    ours = cad_split(a, b)
    theirs = _occt_split(a, b)
    assert len(ours) == len(theirs)
    assert sorted(_length(e) for e in ours) == pytest.approx(sorted(_length(e) for e in theirs), abs=1e-7)
    assert sum(_length(e) for e in ours) == pytest.approx(_length(a), rel=1e-12)


def test_split_self_intersecting_wire():
    bowtie = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0), gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), True)
    pieces = cad_split(bowtie.Wire())
    assert len(pieces) == 6


# ----------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    ("args", "error"),
    [
        (lambda: (ocp.make_compound([]), seg(XY, (0, 0), (1, 0))), InvalidInputError),
        (lambda: (bd.Vertex(1, 2, 3), seg(XY, (0, 0), (1, 0))), InvalidInputError),
        (lambda: ("edge", seg(XY, (0, 0), (1, 0))), InputTypeError),
        (lambda: (seg(XY, (0, 0), (1, 0)), 3.0), InputTypeError),
    ],
)
def test_bad_shapes(args, error):
    a, b = args()
    with pytest.raises(error) as info:
        api.intersect(a, b)
    assert isinstance(info.value, ReliefCadError)


CAD_FUNCTIONS = {
    "intersections": api.intersections,
    "intersect": api.intersect,
    "split": cad_split,
    "occt_intersections": occt_intersections,
    "compare": compare,
}


@pytest.mark.parametrize("function", list(CAD_FUNCTIONS))
@pytest.mark.parametrize("tol", [0.0, -1.0, float("nan"), float("inf"), 10**400])
def test_bad_tolerance_value(function, tol):
    with pytest.raises(ToleranceError, match="finite distance > 0"):
        CAD_FUNCTIONS[function](seg(XY, (0, 0), (1, 0)), seg(XY, (0, 1), (1, 0)), tol=tol)


@pytest.mark.parametrize("function", list(CAD_FUNCTIONS))
@pytest.mark.parametrize("tol", ["abc", [1e-6], True, 1j])
def test_bad_tolerance_type(function, tol):
    with pytest.raises(InputTypeError, match=f"not {type(tol).__name__}"):
        CAD_FUNCTIONS[function](seg(XY, (0, 0), (1, 0)), seg(XY, (0, 1), (1, 0)), tol=tol)


# ----------------------------------------------------------------------------- more contacts
def test_tangent_line_and_circle():
    [hit] = api.intersections(circle(XY, 1.0), seg(XY, (-2, 1), (2, 1)))
    assert hit.kind == "tangent"
    assert hit.point == pytest.approx((0.0, 1.0, 0.0), abs=1e-7)
    assert math.isclose(hit.t, math.pi / 2, abs_tol=1e-7)


def test_identical_circles_give_one_overlap_over_the_whole_range():
    c1 = circle(TILTED, 1.5)
    c2 = circle(TILTED, 1.5)
    [ov] = api.intersections(c1, c2)
    assert isinstance(ov, EdgeOverlap)
    assert ov.t == pytest.approx((0.0, 2 * math.pi), abs=1e-9)
    assert ov.u == pytest.approx((0.0, 2 * math.pi), abs=1e-9)


def test_line_through_a_wire_vertex():
    wire = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 0), gp_Pnt(2, 0, 0)).Wire()
    line = seg(XY, (1, -1), (1, 3))
    hits = api.intersections(wire, line)
    # one result per wire edge (each touches the line at its end), one vertex overall
    assert len(hits) == 2
    assert all(h.point == pytest.approx((1.0, 1.0, 0.0), abs=1e-14) for h in hits)
    assert vertex_points(api.intersect(wire, line)) == [pytest.approx((1.0, 1.0, 0.0), abs=1e-14)]


def test_looping_spline_crosses_itself_across_spans():
    loop = bd.Edge.make_spline([(0, 0), (2, 1), (2, -1), (0, 1), (0, -1), (1, -2)])
    hits = api.intersections(loop)
    theirs = occt_intersections(loop)
    assert len(hits) == len([r for r in theirs if isinstance(r, EdgeIntersection)]) >= 1
    check_on_edges(hits)
    assert all(h.t < h.u and h.index_a == h.index_b == 0 for h in hits)


@pytest.mark.parametrize("count", [7, 9, 11])
def test_a_closed_spline_crossing_itself_at_its_seam_crosses_once(count: int) -> None:
    """A periodic figure-eight through ``count`` points of a lemniscate, one of them its double point,
    where the spline starts and ends (found by a hunt). Its first piece gives the crossing as
    ``(0, u)`` and its last as ``(u, period)``: that pair was counted as two crossings, a touch. The
    branches cross there at a clear angle (OCCT's own derivatives)."""
    th = np.linspace(0, 2 * np.pi, count, endpoint=False)
    eight = bd.Spline(*[(10 * np.sin(t), 10 * np.sin(t) * np.cos(t)) for t in th], periodic=True)
    found = api.intersections(eight)
    assert [r.kind for r in found] == ["crossing"], found
    assert math.dist(found[0].point, (0.0, 0.0, 0.0)) <= 1e-9
    curve = BRepAdaptor_Curve(eight.wrapped)
    dirs = []
    for t in (found[0].t, found[0].u):
        p, v = gp_Pnt(), gp_Vec()
        curve.D1(t, p, v)
        dirs.append(np.array(v.Coord()) / v.Magnitude())
    assert np.linalg.norm(np.cross(*dirs)) > 0.5


def test_near_miss_within_tolerance_is_tangent_and_outside_is_nothing():
    c = circle(XY, 1.0)
    near = seg(XY, (-2, 1 + 1e-9), (2, 1 + 1e-9))
    assert [h.kind for h in api.intersections(c, near, tol=1e-7)] == ["tangent"]
    assert api.intersections(c, seg(XY, (-2, 1.001), (2, 1.001)), tol=1e-7) == []


def _import_with_blocked(blocked: str, module: str) -> str:
    """Import ``module`` in a fresh interpreter where ``blocked`` cannot be imported; return the error."""
    import subprocess
    import sys

    code = (
        f"import sys; sys.modules[{blocked!r}] = None\n"
        "from relief_cad.errors import AdapterUnavailableError\n"
        "try:\n"
        f"    import {module}\n"
        "except AdapterUnavailableError as exc:\n"
        "    print('HINT', exc)\n"
    )
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout


@pytest.mark.parametrize(
    ("blocked", "module", "extra"),
    [("build123d", "relief_cad.cad.build123d", "relief-cad[build123d]"),
     ("cadquery", "relief_cad.cad.cadquery", "relief-cad[cadquery]")],
)
def test_missing_cad_package_gives_install_hint(blocked, module, extra):
    out = _import_with_blocked(blocked, module)
    assert out.startswith("HINT") and f'pip install "{extra}"' in out


def test_missing_ocp_is_told_apart_from_an_unsupported_one():
    out = _import_with_blocked("OCP", "relief_cad.cad")
    assert "none is installed" in out and "OCP 7.9, 8.0" in out
    assert "does not support" not in out


@pytest.mark.parametrize("version", ["7.7.2", "8.1.0.0", "6.9.1"])
def test_unsupported_ocp_version_is_named(version):
    from relief_cad.cad._compat import check_ocp_version
    from relief_cad.errors import AdapterUnavailableError

    with pytest.raises(AdapterUnavailableError, match=rf"OCP {version[:3]} found \({version}\).*supported: OCP 7.9, 8.0"):
        check_ocp_version(version)
    with pytest.raises(ImportError):  # AdapterUnavailableError is an ImportError too
        check_ocp_version(version)


def test_installed_ocp_is_supported_and_reported():
    import importlib.metadata

    import OCP

    from relief_cad.cad._compat import SUPPORTED_OCP, check_ocp_version, versions

    assert check_ocp_version(OCP.__version__) in SUPPORTED_OCP
    v = versions()
    assert v["ocp"] == OCP.__version__ and OCP.__version__.startswith(v["occt"])
    assert v["build123d"] == importlib.metadata.version("build123d")
    assert (v["cadquery"] is None) == (cq is None)


def test_planar_curves_keep_parameters_and_distances():
    ax = TILTED
    edges = [circle(ax, 2.0), seg(ax, (-3, 1), (3, 1.5)), located(circle(XY, 1.0))]
    segs = api.segments(edges[0]) + api.segments(edges[1])
    frame, curves = api.planar_curves(segs)
    assert frame.shape == (2, 4) and all(c.dim == 2 for c in curves)
    s = np.linspace(0, 1, 7)
    for sg, c in zip(segs, curves, strict=True):
        p3 = sg.curve.evaluate(s)
        p2 = c.evaluate(s)
        np.testing.assert_allclose(p2, p3 @ frame[:, :3].T + frame[:, 3], atol=1e-12)
        d3 = np.linalg.norm(np.diff(p3, axis=0), axis=1)
        d2 = np.linalg.norm(np.diff(p2, axis=0), axis=1)
        np.testing.assert_allclose(d2, d3, rtol=1e-12)
    with pytest.raises(InvalidInputError, match="one plane"):
        api.planar_curves(api.segments(edges[0]) + api.segments(edges[2]))


def test_results_on_approximated_edges_are_flagged():
    from OCP.Geom import Geom_Circle, Geom_OffsetCurve, Geom_TrimmedCurve

    off = Geom_OffsetCurve(Geom_TrimmedCurve(Geom_Circle(XY, 2.0), 0.0, 3.0), 0.5, gp_Dir(0, 0, 1))
    edge = BRepBuilderAPI_MakeEdge(off).Edge()
    [hit] = api.intersections(edge, seg(XY, (0, 0), (0, 4)))
    assert hit.approximate
    # the offset of a radius-2 circle by 0.5 is a circle of radius 2.5 (outward or inward)
    assert abs(hit.point[1]) == pytest.approx(2.5, abs=1e-6) or abs(hit.point[1]) == pytest.approx(1.5, abs=1e-6)
    check_on_edges([hit], tol=1e-6)


def test_circles_in_perpendicular_planes_meet_in_space():
    c1 = circle(XY, 1.0)
    c2 = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0.5, 0, 0), gp_Dir(0, 1, 0), gp_Dir(1, 0, 0)), 0.5)).Edge()
    [hit] = api.intersections(located(c1), located(c2))
    np.testing.assert_allclose(hit.point, value(located(c1), 0.0), atol=1e-9)
    assert hit.t in (0.0, pytest.approx(0.0, abs=1e-9), pytest.approx(2 * math.pi, abs=1e-9))
    check_on_edges([hit])
    matches([hit], occt_intersections(located(c1), located(c2)))


@pytest.mark.parametrize("pts", [[(0, 0), (1, 0), (1, 0.125), (0, -0.375), (0, 1)],  # the fuzz's case
                                 [(0, 0), (3, 1), (-2, 1), (1, 0)],  # a loop
                                 [(0, 0), (1, 0), (1, 0), (0, 0), (0, 1)],  # repeated points, a fold
                                 [(0, 0), (1.5, 0), (-0.5, 0.5), (0, 1)]])
def test_duplicate_bezier_edges_are_one_overlap_as_in_the_core(pts):
    # the CAD layer's batch kernel call had no post-pass: a duplicate looping edge came back as a
    # row of "tangent" points (found by tests/adapters/test_fuzz_cad.py)
    make = lambda: bd.Edge.make_bezier(*[(x, y, 0.0) for x, y in pts])  # noqa: E731
    a, b = make(), make()
    for res in (api.intersections(a, b), api.intersections(b, a), api.intersections(a, b.reversed())):
        assert len(res) == 1 and isinstance(res[0], EdgeOverlap), res
        assert sorted(res[0].t) == [0.0, 1.0] and sorted(res[0].u) == [0.0, 1.0]


def test_a_chord_and_its_arc_meet_at_their_two_ends():
    arc = bd.Edge.make_three_point_arc((0, 0, 0), (1, 1, 0), (2, 0, 0))
    chord = bd.Edge.make_line((0, 0, 0), (2, 0, 0))
    for res in (api.intersections(arc, chord), api.intersections(chord, arc)):
        assert [type(r) for r in res] == [EdgeIntersection, EdgeIntersection], res
        assert sorted(tuple(round(c, 12) for c in r.point) for r in res) == [(0, 0, 0), (2, 0, 0)]


def _circle(r: float, centre: tuple[float, float] = (0.0, 0.0), rot: float = 0.0) -> bd.Edge:
    return bd.Edge.make_circle(r).moved(bd.Location((centre[0], centre[1], 0.0), (0, 0, 1), rot))


TANGENT_CIRCLES = {  # (scale) -> two circles touching once; the contact at a joint of one's conic spans
    "inside, at the big circle's seam": lambda s: (_circle(s), _circle(0.5 * s, (0.5 * s, 0.0), 30.0)),
    "outside, at the big circle's seam": lambda s: (_circle(s), _circle(0.5 * s, (1.5 * s, 0.0), 30.0)),
    "inside, at the small circle's quarter point": lambda s: (_circle(s, rot=37.0), _circle(0.5 * s, (0.0, 0.5 * s))),
}


@pytest.mark.parametrize("scale", [0.01, 1.0, 100.0])
@pytest.mark.parametrize("name", list(TANGENT_CIRCLES))
def test_circles_touching_at_a_span_joint_are_one_tangent_contact(name: str, scale: float) -> None:
    """Exactly tangent circles: one tangent contact, whatever the scale. Where the contact lies on a
    joint of one circle's rational spans, the rounding of the spans split it into two crossings a
    few 1e-9 apart, one of them merged into the span's end contact: the pair came out as one
    'crossing' at 0.01 and 100 (6 of these 9 cases), which two closed curves cannot have."""
    a, b = TANGENT_CIRCLES[name](scale)
    found = [r for r in api.intersections(a, b) if isinstance(r, EdgeIntersection)]
    assert [r.kind for r in found] == ["tangent"], found
    contact = (scale, 0.0, 0.0) if "seam" in name else (0.0, scale, 0.0)
    assert math.dist(found[0].point, contact) <= 1e-6 * scale


@pytest.mark.parametrize("scale", [0.01, 1.0, 100.0])
@pytest.mark.parametrize("centre", [0.5, 1.5], ids=["inside", "outside"])
def test_two_crossings_within_tol_of_each_other_are_one_touch(scale: float, centre: float) -> None:
    """Tangent circles, the contact inside a span of each: the rounded spans cross twice close by.
    Crossings joined by a stretch within rounding are one contact, and an even number of crossings
    there is a touch (b crosses a and back), not one 'crossing':
    - at scale 100 the two lie 1e-6 apart, farther than tol (1e-7), with the circles within 1e-14
      between them (they came out as two crossings);
    - at scale 0.01 outside, they lie 8e-11 apart, which the rule for one point found twice (a
      segment joint, a seam) took for a copy, leaving one 'crossing': a copy has the same parameters.
    """
    a, b = _circle(scale, rot=37.0), _circle(0.5 * scale, (centre * scale, 0.0), 30.0)
    found = [r for r in api.intersections(a, b) if isinstance(r, EdgeIntersection)]
    assert [r.kind for r in found] == ["tangent"], found
    assert math.dist(found[0].point, (scale, 0.0, 0.0)) <= 1e-6 * scale


@pytest.mark.parametrize("scale", [10.0, 1e3, 1e5])
@pytest.mark.parametrize("excess", [0.0, 5e-15, 1e-13])
def test_circles_tol_into_each_other_at_their_seams_cross_twice_and_touch_nowhere(scale, excess) -> None:
    """Circles ``d`` = tol (+ ``excess``) into each other, the lens around both seams (a span joint).

    They cross at angles +-acos(1 - d / 2r) and part by at most ``d`` between. The spans' ends
    meet within tol at the seams, and that touch was reported beside both crossings: at radius
    1,000 with d = tol + 5e-15, 1.0000008e-7 off (beyond ``tol_used``). Found by a hunt; a sweep
    of 420 such pairs (radius 10 to 1e5, tol 1e-7 and 1e-6, d within 1e-6 of tol) is now clean.
    """
    tol = 1e-7
    d = tol + excess
    a, b = _circle(scale), _circle(scale, (2.0 * scale - d, 0.0))
    found = api.intersections(a, b, tol=tol)
    assert [r.kind for r in found] == ["crossing", "crossing"], found
    angle = math.acos(1.0 - d / (2.0 * scale))
    assert sorted(min(r.t, 2 * math.pi - r.t) for r in found) == pytest.approx([angle, angle], rel=1e-4)
    assert all(r.distance <= found.tol_used for r in found)


OSCULATING = {  # (scale) -> two curves with one common point, a contact of order four, and that point
    "ellipse and its osculating circle at the minor vertex": lambda s: (
        bd.Edge.make_ellipse(2 * s, s), _circle(4 * s, (0.0, -3 * s)), (0.0, s)),
    "ellipse and its osculating circle at the major vertex (the seam)": lambda s: (
        bd.Edge.make_ellipse(2 * s, s), _circle(0.5 * s, (1.5 * s, 0.0)), (2 * s, 0.0)),
    "two ellipses of one vertex curvature (the seam)": lambda s: (
        bd.Edge.make_ellipse(2 * s, s), bd.Edge.make_ellipse(3 * s, math.sqrt(1.5) * s).moved(
            bd.Location((-s, 0.0, 0.0))), (2 * s, 0.0)),
    "parabola and its osculating circle": lambda s: (
        BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([(-s, s), (0.0, -s), (s, s)]))).Edge(),
        _circle(0.5 * s, (0.0, 0.5 * s)), (0.0, 0.0)),
}


@pytest.mark.parametrize("scale", [0.01, 0.1, 1.0, 10.0, 1000.0])
@pytest.mark.parametrize("name", list(OSCULATING))
def test_a_contact_of_order_four_is_one_touch_at_every_scale(name: str, scale: float) -> None:
    """Curves with one common point where they osculate: eliminating y leaves a fourfold root.

    They stay within tol (1e-7) of each other 0.02 of a span either side, and came out as an
    overlap (or two, split at the seam) at scales 1 and 10, and at 0.01 as the touch with two
    crossings 2.5e-4 either side, where rounding makes them cross (found by a hunt; the arbiter and
    OCCT give one tangent point). The touch is one contact, at the common point.
    """
    a, b, point = OSCULATING[name](scale)
    found = api.intersections(a, b)
    assert [r.kind for r in found] == ["tangent"], found
    assert math.dist(found[0].point, (*point, 0.0)) <= 1e-9 * scale


def test_a_crossing_near_a_touch_stays_a_crossing_and_a_touch() -> None:
    """Quartics (workbench corpus, tangent family, seed 31) crossing at t 0.3014 and touching at 0.3081.

    The rounded touch is two crossings 3e-7 apart: one contact. The quartics stay within 7e-8
    (< tol 1e-7) from the crossing to the touch, 0.007 in parameter: farther than the 1e-3 within
    which contacts are one, so the crossing is its own contact (all three were joined into one
    'crossing', losing the touch; OCCT and the arbiter give the crossing and the touch).
    """
    a = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.18348910061215962, 0.82776756826476705), (0.78446703563155074, 0.9960598706652527),
        (0.026102035511390009, 0.76644510444985459), (0.071563082008245238, 0.83484135846277874),
        (0.20302951845847006, 0.44019535528065901)]))).Edge()
    b = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.19588657605912047, 0.79285253497977326), (0.7684224331510574, 1.0412463146350404),
        (0.035069984449493941, 0.7411886530850903), (0.11348462781258772, 0.71677763061923516),
        (-0.033367446455493832, 1.1059605696385408)]))).Edge()
    found = api.intersections(a, b)
    assert [(r.kind, round(r.t, 4)) for r in found] == [("crossing", 0.3014), ("tangent", 0.3081)], found
    c = compare(a, b)
    assert c.errors == {} and c.disagreements == [] and len(c.agreed) == 2


def test_a_near_miss_within_tol_that_crosses_twice_gives_both_crossings() -> None:
    """Quartics (workbench corpus, near-miss family, seed 505): b crosses a twice, 8e-4 apart in
    parameter, staying 7e-8 from it between (within tol 1e-7). Those are the data's own crossings,
    not the rounding of one touch (the edges stay within rounding, 1e-14, only between those):
    both are reported, as the exact arbiter says (they were joined into one 'tangent').
    """
    a = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.34357830669459066, 0.6780042687757678), (0.95794413676330192, 0.43240349609564954),
        (0.76522497532909028, 0.031079680127229947), (0.90896770547139039, 0.49155985526297363),
        (0.34838133060972343, 0.17777078804695989)]))).Edge()
    b = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.27479179544537796, -0.0098221460784857322), (0.9256271084926101, 0.10925139417206294),
        (0.81619903831512797, 0.54079163320498524), (0.86590583904996543, 0.060965416619736049),
        (0.37856129678612799, 0.47955347128743908)]))).Edge()
    found = api.intersections(a, b)
    assert [(r.kind, round(r.t, 4)) for r in found] == [
        ("crossing", 0.6183), ("crossing", 0.6862), ("crossing", 0.687)], found
    c = compare(a, b)
    assert c.errors == {} and all(d.verdict.winner == "relief_cad" for d in c.disagreements)


def _circle_and_spline_through_it(radius: float, bend: float, half: float, at: float) -> tuple[Any, Any]:
    """An arc of a circle (140 degrees about angle ``at``, in degrees) and a spline through its middle.

    The spline interpolates 7 points ``p + x t + (bend x^2 / 2 + bend^2 x^3 / 20) n`` (``x`` from
    ``-half`` to ``half``; ``p`` the arc's middle, ``t`` and ``n`` its tangent and normal there):
    its middle knot is ``p``, the arc's joint of two rational pieces. Its tangent there is not quite
    the circle's, so it crosses the circle at ``p`` and again close by.
    """
    th = math.radians(at)
    arc = bd.Edge.make_circle(radius, bd.Plane.XY, start_angle=at - 70, end_angle=at + 70)
    n = (math.cos(th), math.sin(th))
    t = (-n[1], n[0])
    p = (radius * n[0], radius * n[1])
    pts = []
    for x in [half * (i / 3 - 1) for i in range(7)]:
        y = 0.5 * bend * x * x + 0.05 * bend * bend * x**3
        pts.append(bd.Vector(p[0] + x * t[0] + y * n[0], p[1] + x * t[1] + y * n[1]))
    return arc, bd.Edge.make_spline(pts)


@pytest.mark.parametrize(("radius", "bend", "half", "at"), [
    (100.0, 0.004, 60.0, 90.0), (100.0, 0.004, 60.0, 37.0), (50.0, -0.005, 30.0, 200.0),
    (10.0, 0.05, 8.0, 90.0), (1.0, 0.3, 0.9, 10.0)])
def test_a_spline_crossing_a_circle_at_a_joint_and_again_close_by_gives_both_crossings(
        radius: float, bend: float, half: float, at: float) -> None:
    """The second crossing lies 1e-5 to 4e-5 of a piece away, the curves 1e-8 to 1e-11 apart between.

    The core took it for the rounding noise of the end meeting (within 1e-3 of a span and tol between
    them, unless 1e-4 apart in both parameters) and gave one crossing at any tolerance above the
    gap; OCCT and the exact arbiter give two. The edges part by far more than rounding between
    them: two contacts, at every tolerance.
    """
    arc, spline = _circle_and_spline_through_it(radius, bend, half, at)
    for tol in (1e-9, 1e-7, 1e-6):
        found = api.intersections(arc, spline, tol=tol)
        assert [r.kind for r in found] == ["crossing", "crossing"], (tol, found)
        assert 1e-6 < abs(found[1].t - found[0].t) < 1e-3 * (math.radians(70)), found
    c = compare(arc, spline)
    assert c.errors == {} and c.score()["occt_right"] == 0 and c.score()["neither"] == 0, c.disagreements


def test_a_circle_touching_an_ellipse_at_its_seam_is_one_touch() -> None:
    """An ellipse (size 320) and a circle touching it at its vertex, the seam (workbench fuzz).

    A rounded tangent root 1.2e-9 from the seam, 3e-7 away in space (> tol 1e-7), was kept next to the
    touch found at the end of the ellipse's piece: the curves are within tol all along between them,
    the rounding of one touch. It was reported twice; OCCT and the arbiter give one.
    """
    ra, rb, r2 = 321.6676685573217, 242.05423548918796, 148.10085373781246
    loc = bd.Location((2.8089138997659675, 9.775806030868567, 0), (0, 0, 1), 170.96184403929013)
    ellipse = bd.Edge.make_ellipse(ra, rb, bd.Plane.XY).moved(loc)
    circle = bd.Edge.make_circle(r2).moved(bd.Location((ra + r2, 0, 0))).moved(loc)
    found = api.intersections(ellipse, circle)
    assert [(r.kind, r.t) for r in found] == [("tangent", 0.0)], found
    c = compare(ellipse, circle)
    assert c.errors == {} and c.score()["occt_right"] == 0 and c.score()["neither"] == 0, c.disagreements


def test_a_curve_crossing_its_mirror_image_just_before_touching_it_gives_both() -> None:
    """Quartics (workbench corpus, tangent family, seed 6060): a curve and its mirror image in a plane
    tangent to it at t 0.69139 cross at 0.69071, 7e-4 before: within 1e-3, and within tol between.

    The touch was merged into the crossing; the curves part by far more than rounding between the
    two, so they are two contacts, as OCCT and the exact arbiter say.
    """
    a = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.22132417463217868, 0.94089899147737466), (0.82240931814185425, 0.48459761761653741),
        (0.64108822854342173, 0.24671568029724278), (0.17360103145910455, 0.54284616173057065),
        (0.37484967714882089, 0.32195014919176868)]))).Edge()
    b = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([
        (0.23714527487369813, -0.12526962798777785), (0.82442643356508549, 0.34866616321334698),
        (0.63612677511714422, 0.58106322056204118), (0.17763216614067445, 0.27119190047707481),
        (0.37223779914345645, 0.49796207786174346)]))).Edge()
    found = api.intersections(a, b)
    assert [(r.kind, round(r.t, 5)) for r in found] == [("crossing", 0.69071), ("tangent", 0.69139)], found
    c = compare(a, b)
    assert c.errors == {} and c.disagreements == [] and len(c.agreed) == 2


def test_a_spline_through_nine_points_of_a_circle_meets_it_at_each() -> None:
    """A cubic spline through 9 points of an arc of radius 200 (8 rational pieces against 2).

    The pieces' pairs run through the batch kernel in one call with 20 rows; it starts with room
    for 18 and, growing, dropped the rows of the pairs before: 3 of the points were found.
    """
    arc = bd.Edge.make_circle(200.0, bd.Plane.XY, start_angle=-40.0, end_angle=100.0)
    angles = [math.radians(30.0) + x for x in np.linspace(-0.5, 0.9, 9)]
    spline = bd.Edge.make_spline([bd.Vector(200.0 * math.cos(a), 200.0 * math.sin(a)) for a in angles])
    found = api.intersections(arc, spline)
    for a in angles:
        assert any(math.dist(r.point, (200.0 * math.cos(a), 200.0 * math.sin(a), 0.0)) <= 1e-7 for r in found), a
    c = compare(arc, spline)
    assert c.errors == {} and not [d for d in c.disagreements if d.claimant == "occt" and d.verdict.truth == "crossing"
                                   and d.verdict.winner == "occt"], c.disagreements


@pytest.mark.parametrize("radius", [1.0, 10.0, 200.0])
def test_a_spline_fitted_to_an_arc_crosses_it_at_small_angles_and_touches_it_once(radius: float) -> None:
    """A cubic spline through 9 evenly spaced points of an arc, off it by 4e-5 of the radius between.

    It crosses the arc at the 8 outer points and 4 times between them, at sin 1e-5 to 1e-3, and
    touches it at the middle point (the spline is symmetric about it): 12 crossings and 1 touch,
    as OCCT and the exact arbiter say. The kernel called crossings at span ends touches (a root
    found twice at an end, taken for a double root), and gave the flank of a crossing or of the
    touch, where the closest-approach iteration stalls 1e-8 to 1e-10 off, as touches, which the
    post-pass then chained into overlaps 3e-4 to 3e-3 of a span long.
    """
    th = 0.3
    arc = bd.Edge.make_circle(radius, bd.Plane.XY, start_angle=math.degrees(th) - 70,
                              end_angle=math.degrees(th) + 70)
    nodes = [th + x for x in np.linspace(-0.5, 0.9, 9)]
    spline = bd.Edge.make_spline([bd.Vector(radius * math.cos(a), radius * math.sin(a)) for a in nodes])
    found = api.intersections(arc, spline, tol=1e-7)
    assert [r.kind for r in found] == ["crossing"] * 6 + ["tangent"] + ["crossing"] * 6, found
    assert math.dist(found[6].point, (radius * math.cos(nodes[4]), radius * math.sin(nodes[4]), 0.0)) <= 1e-6 * radius
    c = compare(arc, spline, tol=1e-7)
    assert c.errors == {} and c.disagreements == [], c.disagreements


# (workbench fuzz of crossings at small angles) a nearly straight spline and a line; a spline and a
# copy of it moved across by 7e-7 of its size and turned by 1e-5
_NEARLY_STRAIGHT = [(-32.02930054679328, -181.913322548597), (-32.01319389570317, -181.92500603806556),
                    (-31.997093214861234, -181.9366977585871), (-31.980984831785005, -181.9483788602036),
                    (-31.964878568780556, -181.96006288471756), (-31.948779663571198, -181.97175705326555)]
_LINE = ((-32.037360785894556, -181.90749033543418), (-31.94071855257864, -181.9775880643706))
_SPLINE = [(-247.7569705472649, -95.74006665090563), (-247.7452579289973, -95.74845712725035),
           (-247.73354531072965, -95.7428309447995), (-247.72183269246204, -95.73152100308195),
           (-247.7101200741944, -95.72914401493445)]
_MOVED = [(-247.75696975646983, -95.74006730706594), (-247.7452570322639, -95.74845763552496),
          (-247.73354448503412, -95.74283130518954), (-247.72183200956823, -95.73152121558788),
          (-247.71011942131366, -95.72914407955555)]

# a nearly straight spline (wiggle 4e-6 of its length) and a line: it crosses 0.16 of a span past a
# knot, where it is 8.4e-8 off the line
_STRAIGHTER = [(0.09167337517639439, 0.1496076886667778), (0.08836051087167043, 0.1506178917044023),
               (0.0850478183400201, 0.1516286578921775), (0.08173480547730157, 0.15263837388922424),
               (0.07842237629939373, 0.15365000347017635), (0.07510936181310746, 0.15465971414443067),
               (0.07179655330218339, 0.15567010009947144), (0.0684836531228685, 0.1566801855238935)]
_ITS_LINE = ((0.09399226583321985, 0.14890017162795688), (0.06616489202788306, 0.15738812732526997))


@pytest.mark.parametrize("case", ["spline and line", "spline and moved copy", "knot a span from the crossing"])
def test_an_end_within_tol_on_the_flank_of_a_small_angle_crossing_is_that_crossing(case: str) -> None:
    """Crossings at a small angle have a long flank within tol: a span's end (4.5e-8 off the line
    at a knot 9e-3 of a span past the crossing) or the edge's end (5.7e-8 off, 8e-2 of a span past
    it) was reported as a second contact. The distance falls all the way from there to the
    crossing: one contact, as OCCT and the exact arbiter say.
    """
    if case == "spline and line":
        a = bd.Edge.make_spline([bd.Vector(*p) for p in _NEARLY_STRAIGHT])
        b = bd.Edge.make_line(*_LINE)
    elif case == "knot a span from the crossing":
        a = bd.Edge.make_spline([bd.Vector(*p) for p in _STRAIGHTER])
        b = bd.Edge.make_line(*_ITS_LINE)
    else:
        a, b = (bd.Edge.make_spline([bd.Vector(*p) for p in pts]) for pts in (_SPLINE, _MOVED))
    found = api.intersections(a, b, tol=1e-7)
    assert all(r.distance <= 1e-12 for r in found), found
    c = compare(a, b, tol=1e-7)
    assert c.errors == {} and not [d for d in c.disagreements if d.verdict.winner != "relief_cad"], c.disagreements


def test_a_space_spline_and_a_copy_turned_by_1e_7_about_one_of_its_points_are_separated() -> None:
    """The copy stays within tol (1e-7) of the spline for half its length around the point, and
    every projection frame showed the curves' images overlapping beyond where the curves do: the
    pair raised BudgetExceededError ("could not be separated"). Halves of the pieces separate it.
    """
    pts = [bd.Vector(0, 0, 0), bd.Vector(1, 0.2, -0.1), bd.Vector(2, -0.25, 0.2), bd.Vector(3, 0.1, 0.05),
           bd.Vector(4, 0.3, -0.2)]
    a = bd.Edge.make_spline(pts)
    p = a.position_at(0.37)
    b = bd.Edge.make_spline(pts).rotate(bd.Axis(p, (0.3, -0.5, 0.8)), math.degrees(1e-7))
    found = api.intersections(a, b, tol=1e-7)
    curve = BRep_Tool.Curve_s(a.wrapped, 0.0, 1.0)
    t_p = GeomAPI_ProjectPointOnCurve(gp_Pnt(p.X, p.Y, p.Z), curve).LowerDistanceParameter()
    assert [r.kind for r in found] == ["overlap"] and found[0].t[0] < t_p < found[0].t[1], found
    for t in np.linspace(found[0].t[0], found[0].t[1], 9)[1:-1]:  # a stretch within tol of b
        q = ocp.edge_value(a.wrapped, float(t))
        assert GeomAPI_ProjectPointOnCurve(gp_Pnt(*q), BRep_Tool.Curve_s(b.wrapped, 0.0, 1.0)).LowerDistance() <= 1e-7


# ----------------------------------------------------------------------------- overlaps with a fold or a return
def _polyline_spline(pts: list[tuple[float, float]]) -> TopoDS_Edge:
    """A degree-1 B-spline through ``pts``, parameter k at the k-th point."""
    n = len(pts)
    knots, mults = Array1OfReal(1, n), Array1OfInteger(1, n)
    for k in range(n):
        knots.SetValue(k + 1, float(k))
        mults.SetValue(k + 1, 2 if k in (0, n - 1) else 1)
    return BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(_poles(pts), knots, mults, 1)).Edge()


def test_a_crossing_with_t_inside_an_overlap_but_u_outside_it_is_kept():
    """b runs along a over x in [2, 5], goes up and comes back down across a at x = 3.5 (a hunt).

    The crossing's t lies inside the overlap's t range, but b is elsewhere (u = 3.5, the overlap
    has u in [0, 1]): it was dropped as the overlap again when a came first, kept the other way round.
    """
    a = seg(XY, (0, 0), (10, 0))
    b = _polyline_spline([(2, 0), (5, 0), (5, 2), (3.5, 2), (3.5, -2)])
    for first, second in ((a, b), (b, a)):
        got = api.intersections(first, second)
        overlaps = [r for r in got if isinstance(r, EdgeOverlap)]
        points = [r for r in got if isinstance(r, EdgeIntersection)]
        assert len(overlaps) == 1 and len(points) == 1, got
        assert points[0].kind == "crossing" and np.allclose(points[0].point, (3.5, 0, 0), atol=1e-12)
        check_on_edges(got)


def test_overlaps_meeting_where_b_folds_back_are_not_merged_across_the_fold():
    """A Bézier along a line out to x = 9.2531 (its fold) and back to x = 7: two overlaps, either order.

    The CAD layer merged the core's two overlaps into one, t = (2, 7) on the line, losing the
    stretch out to the fold. Truth in closed form (x_b'(u) = 0 at the fold).
    """
    u_fold = (66.0 + math.sqrt(66.0**2 + 4 * 88.5 * 1.5)) / (2 * 88.5)
    x_fold = 2 * (1 - u_fold) ** 3 + 7.5 * u_fold * (1 - u_fold) ** 2 + 42 * u_fold**2 * (1 - u_fold) + 7 * u_fold**3
    a = seg(XY, (0, 0), (10, 0))
    b = BRepBuilderAPI_MakeEdge(Geom_BezierCurve(_poles([(2, 0), (2.5, 0), (14, 0), (7, 0)]))).Edge()
    want = sorted([sorted([(2.0, 0.0), (x_fold, u_fold)]), sorted([(7.0, 1.0), (x_fold, u_fold)])])
    for first, second in ((a, b), (b, a)):
        got = api.intersections(first, second)
        assert all(isinstance(r, EdgeOverlap) for r in got), got
        ends = [sorted(zip(r.t, r.u, strict=True) if first is a else zip(r.u, r.t, strict=True)) for r in got]
        assert np.allclose(sorted(ends), want, atol=1e-9), got
        check_on_edges(got)


@pytest.mark.parametrize("dz", [0.0, 3e-8, 9e-8])
def test_an_arc_lifted_within_tol_off_its_circle_is_one_overlap_either_way(dz):
    """A circle of radius 5 and its own 20°-100° arc moved dz along z (found by a hunt).

    Lifted, the pair goes the space way, whose overlap ends are good to about 1e-9 rad: the two
    overlaps meeting at the circle's span joint (π/2) were not joined, one way round, and
    arrange cut the circle there too. Truth: the arc is dz from the circle all along (< tol).
    """
    circle = bd.Edge.make_circle(5)
    arc = bd.Edge.make_circle(5, start_angle=20, end_angle=100).moved(bd.Location((0, 0, dz)))
    for a, b in ((circle, arc), (arc, circle)):
        got = api.intersections(a, b, tol=1e-7)
        assert len(got) == 1 and isinstance(got[0], EdgeOverlap), got
        on_circle = got[0].t if a is circle else got[0].u
        assert np.allclose(sorted(on_circle), np.radians([20, 100]), atol=1e-8)
    assert len(rbd.arrange([circle, arc], tol=1e-7)) == 3  # the circle cut at the arc's ends, the arc shared

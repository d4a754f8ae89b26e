"""occt_intersections: OCCT's own answer, route choice and parameters on real OCP edges."""

from __future__ import annotations

import math

import pytest
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.gp import gp_Ax1, gp_Ax2, gp_Circ, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec
from OCP.TopLoc import TopLoc_Location

from relief_cad.cad._compat import downcast_edge
from relief_cad.cad.occt import occt_intersections
from relief_cad.cad.results import EdgeIntersection, EdgeOverlap
from relief_cad.errors import InputTypeError, ShapeError
from tests._env import needs_cadquery

from ._pairs import bezier, segment


def value(edge, t):
    p = BRepAdaptor_Curve(edge).Value(t)
    return (p.X(), p.Y(), p.Z())


def test_coplanar_crossing_uses_ginter_with_edge_parameters():
    a, b = segment((0, 0, 0), (2, 2, 0)), segment((0, 2, 0), (2, 0, 0))
    (hit,) = occt_intersections(a, b)
    assert isinstance(hit, EdgeIntersection) and hit.route == "Geom2dInt_GInter"
    assert hit.kind == "crossing"
    assert hit.t == pytest.approx(math.sqrt(2), abs=1e-12) and hit.u == pytest.approx(math.sqrt(2), abs=1e-12)


@pytest.mark.parametrize("tilt", [0.0, 0.7])
def test_circle_in_a_tilted_plane_against_a_chord(tilt):
    # circle of radius 2 in a tilted plane through the origin; chord along the local x axis at y = 1
    ax = gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, -math.sin(tilt), math.cos(tilt)), gp_Dir(1, 0, 0))
    circle = BRepBuilderAPI_MakeEdge(gp_Circ(ax, 2.0)).Edge()
    ydir = ax.YDirection()
    p = lambda x, y: (x, y * ydir.Y(), y * ydir.Z())  # noqa: E731
    chord = segment(p(-3, 1), p(3, 1))
    res = occt_intersections(circle, chord)
    assert [r.route for r in res] == ["Geom2dInt_GInter"] * 2
    # truth: angles pi/6 and 5 pi/6 on the circle, x = +-sqrt(3) on the chord (u = 3 +- sqrt 3)
    assert sorted(r.t for r in res) == pytest.approx([math.pi / 6, 5 * math.pi / 6], abs=1e-9)
    assert sorted(r.u for r in res) == pytest.approx([3 - math.sqrt(3), 3 + math.sqrt(3)], abs=1e-9)
    for r in res:
        assert math.dist(value(circle, r.t), r.point) < 1e-9


def test_located_and_reversed_edges_keep_their_own_parameters():
    base = segment((0, 0, 0), (4, 0, 0))
    tr = gp_Trsf()
    tr.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), math.pi / 2)
    tr2 = gp_Trsf()
    tr2.SetTranslation(gp_Vec(1, 1, 0))
    tr.PreMultiply(tr2)
    moved = downcast_edge(base.Moved(TopLoc_Location(tr)))  # x = 1, y from 1 to 5
    reversed_edge = downcast_edge(segment((0, 3, 0), (4, 3, 0)).Reversed())
    (hit,) = occt_intersections(moved, reversed_edge)
    assert hit.point == pytest.approx((1.0, 3.0, 0.0), abs=1e-12)
    assert hit.t == pytest.approx(2.0, abs=1e-12) and hit.u == pytest.approx(1.0, abs=1e-12)
    assert math.dist(value(moved, hit.t), hit.point) < 1e-12


def test_space_edges_use_inttools_and_shared_vertices_use_section():
    # two space cubics through (1.5, 0.5, 0.75) at t = u = 1/2 (dyadic data: exact truth)
    a = bezier([(0, 0, 0), (1, 2, 1), (2, -1, 1), (3, 1, 0)])
    b = bezier([(0, 1, 2.625), (1, -1, 0.625), (2, 2, 0.625), (3, 0, -0.375)])
    (hit,) = occt_intersections(a, b)
    assert hit.route == "IntTools_EdgeEdge" and hit.point == pytest.approx((1.5, 0.5, 0.75), abs=1e-9)
    assert hit.t == pytest.approx(0.5, abs=1e-9) and hit.u == pytest.approx(0.5, abs=1e-9)
    # two space cubics meeting at an end (not coplanar)
    c = bezier([(0, 0, 0), (1, 2, 1), (2, -1, 1), (3, 1, 0)])
    d = bezier([(3, 1, 0), (4, 0, 2), (5, 2, -1), (6, 0, 0)])
    res = occt_intersections(c, d)
    assert [r.route for r in res] == ["BRepAlgoAPI_Section"]
    assert res[0].t == pytest.approx(1.0, abs=1e-9) and res[0].u == pytest.approx(0.0, abs=1e-9)


def test_partial_overlap_is_a_segment_with_matching_ranges():
    a, b = segment((0, 0, 0), (2, 0, 0)), segment((3, 0, 0), (1, 0, 0))
    (ov,) = occt_intersections(a, b)
    assert isinstance(ov, EdgeOverlap)
    assert ov.t == pytest.approx((1.0, 2.0), abs=1e-9) and ov.u == pytest.approx((2.0, 1.0), abs=1e-9)
    assert ov.reversed_direction


def test_a_space_overlap_through_inttools_is_a_segment():
    # a twisted cubic and its piece on [1/4, 3/4], reversed (blossoms at dyadic parameters: exact);
    # the common part's range came as a tuple, which the route read as an IntTools_Range and failed
    a = bezier([(0, 0, 0), (1, 2, 1), (3, 2, 0), (4, 0, 2)])
    b = bezier([(3.09375, 1.125, 0.984375), (2.40625, 1.625, 0.578125), (1.59375, 1.625, 0.609375),
                (0.90625, 1.125, 0.453125)])
    (ov,) = occt_intersections(a, b)
    assert isinstance(ov, EdgeOverlap) and ov.route == "IntTools_EdgeEdge"
    assert ov.t == pytest.approx((0.25, 0.75), abs=1e-6) and ov.u == pytest.approx((1.0, 0.0), abs=1e-6)
    assert ov.reversed_direction


def test_self_intersection_of_a_looping_cubic_and_of_a_wire():
    loop = bezier([(0, 0, 0), (4, 3, 0), (-1, 3, 0), (3, 0, 0)])
    (hit,) = occt_intersections(loop)
    assert hit.index_a == hit.index_b == 0 and hit.t < hit.u
    # the double point is symmetric: t + u = 1 for this control polygon? check geometrically instead
    assert math.dist(value(loop, hit.t), value(loop, hit.u)) < 1e-7
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeWire

    w = BRepBuilderAPI_MakeWire(segment((0, 0, 0), (2, 0, 0)), segment((2, 0, 0), (2, 2, 0))).Wire()
    assert occt_intersections(w) == []  # the joint is not an intersection


def test_bad_input_is_named():
    with pytest.raises(InputTypeError, match="expected a TopoDS_Shape"):
        occt_intersections("edge", None)
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Compound

    empty = TopoDS_Compound()
    BRep_Builder().MakeCompound(empty)
    with pytest.raises(ShapeError, match="at least one edge with a curve"):
        occt_intersections(empty)


def test_build123d_inputs_get_their_own_edges_back():
    import build123d as bd

    arc = bd.Edge.make_circle(2.0)
    line = bd.Edge.make_line((-3, 1), (3, 1))
    res = occt_intersections(arc, line)
    assert len(res) == 2 and all(isinstance(r.edge_a, bd.Edge) and isinstance(r.edge_b, bd.Edge) for r in res)
    assert sorted(r.point[0] for r in res) == pytest.approx([-math.sqrt(3), math.sqrt(3)], abs=1e-9)


@needs_cadquery
def test_cadquery_inputs_get_their_own_edges_back():
    import cadquery as cq

    cq_res = occt_intersections(cq.Edge.makeCircle(2.0), cq.Edge.makeLine(cq.Vector(-3, 1, 0), cq.Vector(3, 1, 0)))
    assert len(cq_res) == 2 and isinstance(cq_res[0].edge_a, cq.Edge)


def test_trimmed_arc_reports_parameters_inside_its_range():
    ax = gp_Ax2(gp_Pnt(1, 1, 0), gp_Dir(0, 0, 1))
    arc = BRepBuilderAPI_MakeEdge(gp_Circ(ax, 2.0), 0.25, math.pi / 2).Edge()  # trimmed, off the origin
    chord = segment((-2, 2, 0), (4, 2, 0))  # y = 2: the circle at angles pi/6 and 5 pi/6
    (hit,) = occt_intersections(arc, chord)
    assert hit.t == pytest.approx(math.pi / 6, abs=1e-9) and hit.u == pytest.approx(3 + math.sqrt(3), abs=1e-9)
    assert math.dist(value(arc, hit.t), (1 + math.sqrt(3), 2.0, 0.0)) < 1e-9

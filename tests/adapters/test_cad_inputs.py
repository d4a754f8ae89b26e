"""Every public path of relief_cad.cad accepts the same inputs and refuses the same ones (issue 15, CAD layer).

The inputs are real OCCT shapes: a sphere and a cone (whose poles / apex are degenerated
edges), a 1e-12-long edge, an edge known only by a curve on a plane (no 3D curve), an edge on
a whole line (unbounded), an empty build123d ``Compound``, and lists of edges. Truth comes
from closed forms (a line through a sphere at height z meets its seam meridian once) and from
the edges' own evaluation.
"""

from __future__ import annotations

import math

import build123d as bd
import pytest
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.Geom import Geom_Line, Geom_Plane
from OCP.Geom2d import Geom2d_Line
from OCP.gp import gp_Dir, gp_Dir2d, gp_Lin, gp_Pln, gp_Pnt, gp_Pnt2d

from relief_cad.cad import api, compare, occt_intersections
from relief_cad.cad import split as cad_split
from relief_cad.cad.topology import edges_of
from relief_cad.errors import ShapeError

PUBLIC = {
    "intersections": api.intersections,
    "occt_intersections": occt_intersections,
    "compare": lambda a, b, **kw: compare(a, b, **kw),
}
CHORD = bd.Line((-2, 0, 0.5), (2, 0, 0.5))  # crosses the x > 0 seam meridian of the unit sphere once


def _points(results) -> list[tuple[float, ...]]:
    return sorted(tuple(round(c, 7) for c in r.point) for r in results)


@pytest.mark.parametrize("solid", ["sphere", "cone"])
def test_degenerated_edges_are_skipped_and_reported(solid):
    shape = bd.Sphere(1.0) if solid == "sphere" else bd.Cone(1.0, 0.0, 2.0)
    degenerated = [i for i, e in enumerate(edges_of(shape)) if BRep_Tool.Degenerated_s(e)]
    assert degenerated  # a pole / an apex: the case under test
    ours, theirs = api.intersections(shape, CHORD), occt_intersections(shape, CHORD)
    assert ours and _points(ours) == _points(theirs)
    assert all(r.index_a not in degenerated for r in ours + theirs)
    c = compare(shape, CHORD)
    assert c.agree and not c.errors
    assert [i for side, i, _ in c.skipped if side == "a"] == degenerated
    assert "skipped edge a[" in str(c)
    if solid == "sphere":  # x^2 + z^2 = 1 at z = 0.5
        [r] = ours
        assert r.point == pytest.approx((math.sqrt(0.75), 0.0, 0.5), abs=1e-9)


def test_sphere_edges_as_a_list_on_every_path():
    edges = edges_of(bd.Sphere(1.0))  # raw TopoDS_Edge list, the two poles included
    assert isinstance(edges, list) and len(edges) == 3
    answers = [_points(f(edges, CHORD)) for f in (api.intersections, occt_intersections)]
    assert answers[0] == answers[1] and len(answers[0]) == 1
    assert compare(list(edges), [CHORD]).agree


def test_lists_number_edges_like_intersections():
    a = [bd.Line((-2, -1), (2, 1)), bd.Line((-2, 1), (2, -1))]
    b = [bd.Line((0, -2), (0, 2)), bd.CenterArc((0, 0), 1.5, 0, 360)]
    ours, theirs = api.intersections(a, b), occt_intersections(a, b)
    key = [(r.index_a, r.index_b) for r in ours]
    assert key == [(r.index_a, r.index_b) for r in theirs] and len(key) == 6
    for r in theirs:  # the indices point at the edges that really hold the point
        ea, eb = edges_of(a)[r.index_a], edges_of(b)[r.index_b]
        assert BRepAdaptor_Curve(ea).Value(r.t).Distance(gp_Pnt(*r.point)) < 1e-7
        assert BRepAdaptor_Curve(eb).Value(r.u).Distance(gp_Pnt(*r.point)) < 1e-7
    assert compare(a, b).agree


def test_tiny_edge_is_compared_without_crashing():
    tiny = BRepBuilderAPI_MakeEdge(Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), 0.0, 1e-12).Edge()
    line = bd.Line((-1, -1), (1, 1))
    [r] = api.intersections(tiny, line)
    assert r.t == 0.0 and r.point == pytest.approx((0, 0, 0), abs=1e-12)
    c = compare(tiny, line)
    assert not c.errors and len(c.agreed) + len(c.disagreements) >= 1


def _pcurve_only_edge():
    edge = BRepBuilderAPI_MakeEdge(Geom2d_Line(gp_Pnt2d(-1, -1), gp_Dir2d(1, 1)), Geom_Plane(gp_Pln()), 0.0, 3.0).Edge()
    assert BRep_Tool.Curve_s(edge, 0.0, 0.0) is None  # the case under test: no 3D curve
    return edge


@pytest.mark.parametrize("function", list(PUBLIC))
def test_edge_without_3d_curve_on_every_path(function):
    result = PUBLIC[function](_pcurve_only_edge(), bd.Line((-1, 1), (1, -1)))
    results = result.agreed if function == "compare" else result
    assert len(results) == 1
    if function == "compare":
        assert result.agree and not result.errors
    else:  # the diagonal meets the anti-diagonal at the origin, sqrt(2) along the pcurve
        [r] = results
        assert r.t == pytest.approx(math.sqrt(2), abs=1e-7) and r.point == pytest.approx((0, 0, 0), abs=1e-7)


@pytest.mark.parametrize("function", [*PUBLIC, "split", "intersect"])
def test_edge_on_an_unbounded_line_is_refused(function):
    infinite = BRepBuilderAPI_MakeEdge(gp_Lin(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))).Edge()
    first, last = BRep_Tool.Range_s(infinite)
    assert last - first > 1e99  # OCCT's "infinite" range: the case under test
    fn = {**PUBLIC, "split": cad_split, "intersect": api.intersect}[function]
    with pytest.raises(ShapeError, match="bounded parameter range.*trim it"):
        fn(infinite, bd.Line((0, -1), (0, 1)))


@pytest.mark.parametrize("function", [*PUBLIC, "split", "intersect"])
def test_empty_build123d_compound_is_a_shape_without_edges(function):
    fn = {**PUBLIC, "split": cad_split, "intersect": api.intersect}[function]
    for args in ((bd.Compound(), CHORD), (CHORD, bd.Compound())):
        with pytest.raises(ShapeError, match="at least one edge with a curve"):
            fn(*args)

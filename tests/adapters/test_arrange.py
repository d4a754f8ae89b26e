"""relief_cad.cad.arrangement (split with shared topology, arrange, faces) on real OCCT shapes.

Oracles: OCCT itself -- IsSame on the pieces' vertices, BRepCheck_Analyzer, the faces of
BRepAlgoAPI_Common / BRepAlgoAPI_Cut and of General Fuse (BOPAlgo_Builder), and the
curve points at the pieces' ends measured against their vertices.
"""

from __future__ import annotations

import math
from pathlib import Path

import build123d as bd
import numpy as np
import pytest
from OCP.BOPAlgo import BOPAlgo_Builder
from OCP.BRep import BRep_Builder, BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepAlgoAPI import BRepAlgoAPI_Common, BRepAlgoAPI_Cut
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace, BRepBuilderAPI_MakeWire
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.BRepGProp import BRepGProp
from OCP.BRepTools import BRepTools
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt
from OCP.GProp import GProp_GProps
from OCP.TopAbs import TopAbs_EDGE, TopAbs_FACE, TopAbs_VERTEX
from OCP.TopExp import TopExp
from OCP.TopoDS import TopoDS_Shape

from relief_cad.cad import api, ocp
from relief_cad.cad import arrangement as arrange_module
from relief_cad.cad import build123d as rbd
from relief_cad.cad._compat import (
    Array1OfInteger,
    Array1OfPnt,
    Array1OfReal,
    IndexedMapOfShape,
    downcast_edge,
)
from relief_cad.errors import InputTypeError, InvalidInputError, ReliefCadError, ToleranceError
from tests._env import needs_cadquery

arrange = arrange_module.arrange
split_both = arrange_module.split_both
cad_split = arrange_module.split_connected


def raw(s):
    return s.wrapped if hasattr(s, "wrapped") else s


def sub_shapes(shape, kind):
    m = IndexedMapOfShape()
    TopExp.MapShapes_s(raw(shape), kind, m)
    return [m.FindKey(i) for i in range(1, m.Extent() + 1)]


def ends(edge):
    e = downcast_edge(raw(edge))
    return TopExp.FirstVertex_s(e), TopExp.LastVertex_s(e)


def assert_connected(pieces, tol=1e-9):
    """Piece ends at one point are one vertex (IsSame), and each end lies within its vertex tolerance."""
    vertices = []
    for p in pieces:
        e = downcast_edge(raw(p))
        t0, t1 = BRep_Tool.Range_s(e)
        curve = BRepAdaptor_Curve(e)
        for v, t in zip(ends(p), (t0, t1)):  # FirstVertex (no CumOri) is the one at t0
            at = np.array(BRep_Tool.Pnt_s(v).Coord())
            assert np.linalg.norm(np.array(curve.Value(t).Coord()) - at) <= BRep_Tool.Tolerance_s(v)
            vertices.append((at, v))
    for i, (p, v) in enumerate(vertices):
        for q, w in vertices[i + 1:]:
            if np.linalg.norm(p - q) <= tol:
                assert v.IsSame(w), f"two vertices at {p}"
    assert BRepCheck_Analyzer(ocp.make_compound([raw(p) for p in pieces])).IsValid()


def area(face):
    """Adaptive integration (eps 1e-10): OCCT's default Gauss rule is off by 2e-4 on spline faces."""
    props = GProp_GProps()
    BRepGProp.SurfaceProperties_s(raw(face), props, 1e-10)
    return props.Mass()


def line(p, q):
    return BRepBuilderAPI_MakeEdge(gp_Pnt(*p), gp_Pnt(*q)).Edge()


def general_fuse(shapes):
    """OCCT's General Fuse (BOPAlgo_Builder) of the shapes: its result shape."""
    builder = BOPAlgo_Builder()
    for s in shapes:
        builder.AddArgument(raw(s))
    builder.Perform()
    return builder.Shape()


def counts(shape):
    """(edges, vertices) of a shape or of a list of pieces, each counted once."""
    shape = shape if isinstance(shape, TopoDS_Shape) else ocp.make_compound([raw(p) for p in shape])
    return tuple(len(sub_shapes(shape, kind)) for kind in (TopAbs_EDGE, TopAbs_VERTEX))


def assert_one_vertex_at(pieces, point, n, within=None):
    """``n`` piece ends lie at ``point`` (``np.allclose``, or ``within`` a distance), and they are one TopoDS_Vertex."""
    def close(v):
        p = BRep_Tool.Pnt_s(v).Coord()
        return np.allclose(p, point) if within is None else math.dist(p, point) <= within

    at = [v for p in pieces for v in ends(p) if close(v)]
    assert len(at) == n and all(at[0].IsSame(v) for v in at)


# --------------------------------------------------------------------------- shared vertices
def test_crossing_lines_share_the_cut_vertex():
    pieces = arrange([line((0, 0, 0), (2, 2, 0)), line((0, 2, 0), (2, 0, 0))])
    assert len(pieces) == 4
    centre = [v for p in pieces for v in ends(p) if np.allclose(BRep_Tool.Pnt_s(v).Coord(), (1, 1, 0))]
    assert len(centre) == 4 and all(centre[0].IsSame(v) for v in centre)
    assert_connected(pieces)


def test_split_both_shares_vertices_and_keeps_orientation():
    circle = bd.Edge.make_circle(1.0)
    seg = bd.Edge.make_line((-2, 0.3), (2, 0.3)).reversed()
    pa, pb = split_both(seg, circle)
    assert len(pa) == 3 and len(pb) == 3  # the circle is cut twice and at its seam
    assert all(p.wrapped.Orientation() == seg.wrapped.Orientation() for p in pa)
    assert_connected(list(pa) + list(pb))
    cut_a = {v for p in pa for v in p.vertices() if abs(v.Y - 0.3) < 1e-9 and abs(abs(v.X) - math.sqrt(0.91)) < 1e-9}
    cut_b = [v for p in pb for v in p.vertices() if abs(abs(v.X) - math.sqrt(0.91)) < 1e-9]
    assert all(any(v.wrapped.IsSame(w.wrapped) for w in cut_a) for v in cut_b) and len(cut_b) == 4


def test_overlap_is_one_common_edge_of_both_inputs():
    a = line((0, 0, 0), (4, 0, 0))
    b = line((2, 0, 0), (6, 0, 0))
    pa, pb = split_both(a, b)
    assert [BRep_Tool.Range_s(e) for e in pa] == [(0.0, 2.0), (2.0, 4.0)]
    assert pa[1].IsSame(pb[0])
    assert len(arrange([a, b])) == 3
    assert_connected(pa + pb)


def test_reversed_overlap_shares_the_edge_with_its_own_direction():
    a = line((0, 0, 0), (4, 0, 0))
    b = line((6, 0, 0), (2, 0, 0))
    pa, pb = split_both(a, b)
    common = [e for e in pb if e.IsSame(pa[1])]
    assert len(common) == 1
    first = BRep_Tool.Pnt_s(TopExp.FirstVertex_s(common[0], True)).Coord()
    assert np.allclose(first, (4, 0, 0))  # b runs from x=6 to x=2, so its copy starts at x=4


def test_vertex_tolerance_is_the_measured_error_not_a_blanket_value():
    spline = bd.Edge.make_spline([(0, -1), (1, 1.3), (2, -0.7), (3, 1.1)])
    circle = bd.Edge.make_circle(1.4, bd.Plane.XY.offset(0)).moved(bd.Location((1.5, 0.2)))
    pieces = arrange([spline, circle])
    measured = {}
    for p in pieces:
        e = p.wrapped
        t0, t1 = BRep_Tool.Range_s(e)
        c = BRepAdaptor_Curve(e)
        for v, t in zip(ends(p), (t0, t1)):
            d = c.Value(t).Distance(BRep_Tool.Pnt_s(v))
            key = v.TShape().__hash__() if hasattr(v.TShape(), "__hash__") else id(v)
            measured.setdefault(key, (v, []))[1].append(d)
    assert len(measured) >= 4
    for v, ds in measured.values():
        tol = BRep_Tool.Tolerance_s(v)
        assert max(ds) <= tol <= max(1e-7, 1.001 * max(ds) + 1e-15)
    assert_connected(pieces)


# --------------------------------------------------------------------------- cuts closer than OCCT's resolution
def test_cuts_closer_than_occt_confusion_merge_instead_of_failing():
    """Two cutters 5e-8 apart with tol=1e-10: OCCT cannot make the 5e-8 piece between them.

    The cuts merge into one vertex (OCCT's ``Precision::Confusion``, 1e-7, is the shortest
    piece), as with the default tolerance, instead of an OcctError from the edge maker.
    """
    a = line((0, 0, 0), (10, 0, 0))
    cutters = [line((5, -1, 0), (5, 1, 0)), line((5 + 5e-8, -1, 0), (5 + 5e-8, 1, 0))]
    for tol in (None, 1e-10):
        pieces = cad_split(a, cutters, tol=tol)
        assert [BRep_Tool.Range_s(e) for e in pieces] == [(0.0, 5.0), (5.0, 10.0)]
        arranged = arrange([a, *cutters], tol=tol)
        assert len(arranged) == 4  # a in two, the cutters one edge (within 1e-7 of each other) in two
        assert_connected(arranged, tol=2e-7)
        pa, pb = split_both(a, cutters, tol=tol)
        assert len(pa) == 2 and len(pb) == 4
        assert_connected(list(pa) + list(pb), tol=2e-7)


@pytest.mark.parametrize("kind", ["line", "bezier"])
def test_part_of_size_1e_6_is_cut_where_occt_can_keep_pieces_apart(kind):
    """A crossing 8.6e-8 from a's start at scale 1e-6 (found by the CAD fuzz): no piece shorter than 1e-7."""
    first = bd.Edge.make_line((3.2533594812159234e-06, 1.90576690168536e-06), (2.321607934007233e-06, 1.224008628861211e-06))
    other = bd.Edge.make_bezier((3.3705919068602463e-06, 1.7833356278306984e-06), (1.9268476911488663e-06, 2.3607926826197946e-06),
                                (2.591793915056801e-06, 1.6290473687813069e-06), (1.7134838769253044e-06, 1.71540395780513e-06))
    a, b = (first, other) if kind == "line" else (other, first)
    crossings = api.intersections(a, b)
    assert len(crossings) == 1
    pieces = cad_split(a, b)
    for p in pieces:
        t0, t1 = BRep_Tool.Range_s(p.wrapped)
        assert math.dist(ocp.edge_value(p, t0), ocp.edge_value(p, t1)) > 1e-7
    assert len(pieces) == (1 if kind == "line" else 2)  # 8.6e-8 from the line's start; mid-Bézier
    pa, pb = split_both(a, b)
    assert_connected(list(pa) + list(pb), tol=1e-7)
    assert_connected(arrange([a, b]), tol=1e-7)


def length(shape):
    props = GProp_GProps()
    BRepGProp.LinearProperties_s(raw(shape), props)
    return props.Mass()


def test_cuts_close_in_parameter_but_apart_in_space_are_both_kept():
    """A line of parameter range 2e6 crossed at x = 1e6 and 1e6 + 1e-6 (found by a hunt).

    The cuts are 1e-12 of the range apart in parameter, but 10 tol apart in space: two vertices,
    a piece of 1e-6 between them, and both crossing lines joined to the long line.
    """
    long = line((0, 0, 0), (2e6, 0, 0))
    cutters = [line((x, -1, 0), (x, 1, 0)) for x in (1e6, 1e6 + 1e-6)]
    pieces = arrange([long, *cutters])
    assert counts(pieces) == counts(general_fuse([long, *cutters])) == (7, 8)
    on_long = sorted(BRep_Tool.Range_s(downcast_edge(raw(p))) for p in pieces if length(p) < 1e-5 or length(p) > 10)
    assert np.allclose(on_long, [(0.0, 1e6), (1e6, 1e6 + 1e-6), (1e6 + 1e-6, 2e6)], rtol=0, atol=1e-9)
    for x in (1e6, 1e6 + 1e-6):
        assert_one_vertex_at(pieces, (x, 0, 0), 4, within=1e-7)
    assert_connected(pieces, tol=1e-7)


@pytest.mark.parametrize("radius, gap", [(1e3, 5e-7), (1e5, 1e-6), (1e5, 3e-7)])
def test_a_piece_of_a_circle_below_occt_parameter_confusion_stays_short(radius, gap):
    """Cuts ``gap`` apart at the top of a circle: 5e-10 rad and less, below ``PConfusion`` (1e-9).

    ``BRepBuilderAPI_MakeEdge`` took the piece between them for a whole circle (twice the length,
    a face of twice the disk's area); at 3e-12 rad the cut was dropped. The piece keeps its
    length, the lines stay joined to the circle, and the faces are the disk.
    """
    circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), radius)).Edge()
    cutters = [line((x, radius - 1, 0), (x, radius + 1, 0)) for x in (0.0, gap)]
    pieces = arrange([circle, *cutters])
    assert len(pieces) == 7
    assert length(ocp.make_compound([raw(p) for p in pieces])) == pytest.approx(2 * math.pi * radius + 4, rel=1e-12)
    assert min(length(p) for p in pieces) == pytest.approx(gap, rel=1e-3)
    for x in (0.0, gap):
        assert_one_vertex_at(pieces, (x, radius, 0), 4, within=1e-7)
    assert_connected(pieces, tol=1e-7)
    cut = cad_split(circle, cutters)
    assert sorted(length(p) for p in cut)[0] == pytest.approx(gap, rel=1e-3)
    faces = arrange([circle, *cutters], faces=True)
    assert len(faces) == 1 and area(faces[0]) == pytest.approx(math.pi * radius**2, rel=1e-9)
    assert BRepCheck_Analyzer(raw(faces[0])).IsValid()


@pytest.mark.parametrize("depth", [1e-9, 1e-10])
def test_touch_hiding_two_crossings_gets_a_vertex_covering_them(depth):
    """A circle inside another, pushed ``depth`` through it: within tol (1e-7) one tangent contact,
    but the circles cross on either side of it (2.2e-5 away for 1e-9). The shared vertex's tolerance
    reaches those crossings, so the face with the hole is valid (it was not: intersecting wires)."""
    big = bd.Circle(1.0).face()
    small = bd.Circle(0.2).face().moved(bd.Location((0.8 + depth, 0, 0)))
    d = 0.8 + depth  # the circles' true crossings: x, +-y
    x = (d * d + 1.0 - 0.04) / (2 * d)
    reach = math.dist((x, math.sqrt(1.0 - x * x)), (1.0, 0.0))
    pieces = arrange([big, small])
    touch = [v for p in pieces for v in ends(p) if np.allclose(BRep_Tool.Pnt_s(v).Coord(), (1, 0, 0), atol=1e-6)]
    assert len(touch) >= 2 and all(touch[0].IsSame(v) for v in touch)  # one vertex, both circles' ends
    assert 0.999 * reach <= BRep_Tool.Tolerance_s(touch[0]) <= 1.1 * reach
    faces = arrange([big, small], faces=True)
    assert len(faces) == 2 and all(BRepCheck_Analyzer(raw(f)).IsValid() for f in faces)
    assert sorted(area(f) for f in faces) == pytest.approx(sorted([math.pi * 0.04, math.pi * 0.96]), rel=1e-9)


@pytest.mark.parametrize("scale", [0.01, 1.0, 100.0])
def test_exactly_tangent_circles_meet_at_one_vertex(scale):
    """Circles of radius ``scale`` and ``scale / 2`` touching inside at one point: each circle is cut
    there once, into 4 pieces in all, with 2 valid faces. At scale 100 the rounded spans cross
    twice 1e-6 apart, farther than tol: that was 2 vertices and a sliver edge of 1e-6 between them."""
    big = bd.Edge.make_circle(scale).moved(bd.Location((0, 0, 0), (0, 0, 1), 37.0))
    small = bd.Edge.make_circle(0.5 * scale).moved(bd.Location((0.5 * scale, 0, 0), (0, 0, 1), 30.0))
    pieces = arrange([big, small])
    assert len(pieces) == 4
    assert_connected(pieces, tol=1e-7)
    touch = [v for p in pieces for v in ends(p)
             if math.dist(BRep_Tool.Pnt_s(v).Coord(), (scale, 0, 0)) <= 1e-6 * scale]
    assert len(touch) == 4 and all(touch[0].IsSame(v) for v in touch)  # both circles' cut ends
    faces = arrange([big, small], faces=True)
    assert len(faces) == 2 and all(BRepCheck_Analyzer(raw(f)).IsValid() for f in faces)
    assert sorted(area(f) for f in faces) == pytest.approx(
        sorted([math.pi * 0.25 * scale**2, math.pi * 0.75 * scale**2]), rel=1e-9)


def test_self_intersection_of_one_edge_is_cut():
    eight = bd.Edge.make_spline([(0, 0), (1, 1), (2, 0), (1, -1), (0, 0.0001)][:4] + [(0, -0.5)])
    loop = bd.Edge.make_spline([(0, 0), (2, 1), (2, -1), (0, 1)])  # crosses itself once
    pieces = arrange(loop)
    assert len(pieces) == 3
    assert_connected(pieces)
    assert len(arrange(loop, faces=True)) == 1
    assert len(arrange(eight)) >= 1


def test_loops_among_many_arches_are_cut_and_the_arches_are_not():
    """Many edges take the one-pass path, which skips the self-intersection of every span running
    along its chord (the arches): the loops, whose crossing spans do not, are still cut there: a
    spline's between two spans, a Bezier curve's within its one span."""
    arches = [bd.Edge.make_spline([(3 * k, 5), (3 * k + 1, 6.5), (3 * k + 2, 6)]) for k in range(6)]
    loops = [bd.Edge.make_spline([(0, 0), (2, 1), (2, -1), (0, 1)]),
             bd.Edge.make_bezier((10, 0), (13, 1), (9, 1), (12, 0))]
    pieces = arrange(arches + loops)
    assert len(pieces) == len(arches) + 6  # each arch whole; each loop in three, through one vertex
    assert_connected(pieces)
    for k in range(2):
        loop_ends = [v for p in pieces[len(arches) + 3 * k:][:3] for v in ends(p)]
        assert sum(v.IsSame(loop_ends[1]) for v in loop_ends) == 4  # the crossing: 4 piece ends
    assert len(arrange(arches + loops, faces=True)) == 2


def test_inputs_are_not_modified():
    a, b = line((0, 0, 0), (2, 2, 0)), line((0, 2, 0), (2, 0, 0))
    before = [BRep_Tool.Tolerance_s(v) for v in ends(a)] + [BRep_Tool.Range_s(a)]
    arrange([a, b])
    assert [BRep_Tool.Tolerance_s(v) for v in ends(a)] + [BRep_Tool.Range_s(a)] == before


# --------------------------------------------------------------------------- against General Fuse
def glyphs_and_waves():
    text = bd.Text("Relief", font_size=10)
    waves = [bd.Edge.make_spline([(x, -4 + 1.3 * k + 0.8 * math.sin(0.7 * x + k)) for x in range(-20, 25, 5)])
             for k in range(6)]
    return [e.wrapped for e in text.edges()] + [w.wrapped for w in waves]


def test_glyphs_over_waves_match_general_fuse_counts():
    edges = glyphs_and_waves()
    pieces = arrange(edges)
    assert counts(pieces) == counts(general_fuse(edges))
    assert_connected(pieces)


def test_spokes_through_one_hub_meet_at_one_vertex_as_in_general_fuse():
    """40 lines through one point and a rim around it: 780 cuts at the hub, one vertex for the 80
    piece ends there (clustering their cut points pair by pair took 6 s and 1.8 GB at 50 lines)."""
    hub = (3.7, -1.2)
    spokes = [bd.Edge.make_line((hub[0] - 10 * math.cos(a), hub[1] - 10 * math.sin(a)),
                                (hub[0] + 10 * math.cos(a), hub[1] + 10 * math.sin(a)))
              for a in (k * math.pi / 40 + 0.1 for k in range(40))]
    edges = [e.wrapped for e in spokes] + [bd.Edge.make_circle(6).moved(bd.Location((*hub, 0))).wrapped]
    pieces = arrange(edges)
    assert_one_vertex_at(pieces, (*hub, 0), 80)
    assert counts(pieces) == counts(general_fuse(edges))
    assert_connected(pieces)


def test_a_pencil_of_circles_meets_at_two_vertices_as_in_general_fuse():
    """30 circles through (0, 1) and (0, -1): 435 pairs cut there, one vertex at each point."""
    circles = [bd.Edge.make_circle(math.hypot(1.0, c)).moved(bd.Location((c, 0, 0))).wrapped
               for c in (0.137 * (k - 15) for k in range(30))]
    pieces = arrange(circles)
    for y in (1.0, -1.0):
        assert_one_vertex_at(pieces, (0, y, 0), 60)
    assert counts(pieces) == counts(general_fuse(circles))
    assert_connected(pieces)


def test_copies_of_edges_give_the_arrangement_of_the_edges_once():
    """A drawing with some of its edges twice (copied, some reversed): the same pieces and vertices
    as the drawing once, and General Fuse's counts (the copies no longer meet each other pair by
    pair: 200 copies of one circle took 3 s)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Copy

    edges = glyphs_and_waves()
    copies = [BRepBuilderAPI_Copy(e).Shape() for e in edges[::3]]
    reversed_lines = [line((0, -6, 0), (4, 7, 0)), line((4, 7, 0), (0, -6, 0))]  # one curve both ways
    doubled = edges + copies + reversed_lines + [BRepBuilderAPI_Copy(e).Shape() for e in copies[:5]]
    infos = api._prepare(doubled, "a")
    assert len(infos) - len(api._mark_copies(infos)) == len(copies) + 1 + 5  # the reversed line too
    once = arrange(edges + reversed_lines[:1])
    twice = arrange(doubled)
    assert counts(twice) == counts(once) == counts(general_fuse(edges + copies + reversed_lines))
    assert_connected(twice)


def test_a_copy_with_a_larger_occt_tolerance_still_sets_the_model_tolerance():
    """The default tolerance is the largest OCCT tolerance of the edges, copies included: which of
    two copies is kept must not change it (a line ending 1e-4 short of another meets it at 1e-3)."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_Copy

    base = line((0, 0, 0), (10, 0, 0))
    loose = downcast_edge(BRepBuilderAPI_Copy(base).Shape())
    BRep_Builder().UpdateEdge(loose, 1e-3)
    short = line((5, 5, 0), (5, 1e-4, 0))
    counts = [len(sub_shapes(ocp.make_compound(arrange(edges)), TopAbs_EDGE))
              for edges in ([base, loose, short], [loose, base, short])]
    assert counts == [3, 3]  # the short line's end is on the long line, which is cut there


# --------------------------------------------------------------------------- faces against booleans
def shapes_overlapping():
    rect = bd.Rectangle(4, 2).face()
    circle = bd.Circle(1.3).face().moved(bd.Location((1.8, 0.6)))
    spline = bd.Face(bd.Wire([bd.Edge.make_spline([(-2.6, -0.4), (-1.0, 1.6), (0.4, -0.2), (-1.2, -1.7)],
                                                  periodic=True)]))
    return [rect, circle, spline]


@pytest.mark.parametrize("pair", [(0, 1), (0, 2), (1, 2)])
def test_face_areas_equal_occt_common_and_cuts(pair):
    shapes = shapes_overlapping()
    a, b = shapes[pair[0]], shapes[pair[1]]
    faces = arrange([a, b], faces=True)
    got = sorted(area(f) for f in faces)
    want = []
    for op in (BRepAlgoAPI_Common(a.wrapped, b.wrapped), BRepAlgoAPI_Cut(a.wrapped, b.wrapped),
               BRepAlgoAPI_Cut(b.wrapped, a.wrapped)):
        want += [area(f) for f in sub_shapes(op.Shape(), TopAbs_FACE)]
    assert len(got) == len(want)
    assert np.allclose(got, sorted(want), rtol=1e-7, atol=1e-9)
    for f in faces:
        assert BRepCheck_Analyzer(f.wrapped).IsValid()


def test_three_shapes_face_areas_equal_general_fuse_faces():
    shapes = shapes_overlapping()
    faces = arrange(shapes, faces=True)
    want = sorted(area(f) for f in sub_shapes(general_fuse(shapes), TopAbs_FACE))
    assert np.allclose(sorted(area(f) for f in faces), want, rtol=1e-7, atol=1e-9)


def test_ring_of_shapes_encloses_a_hole_face():
    # four overlapping bars around an empty middle: the middle is a bounded face of the arrangement
    bars = [bd.Rectangle(5, 1).face().moved(bd.Location((0, 2))), bd.Rectangle(5, 1).face().moved(bd.Location((0, -2))),
            bd.Rectangle(1, 5).face().moved(bd.Location((2, 0))), bd.Rectangle(1, 5).face().moved(bd.Location((-2, 0)))]
    faces = arrange(bars, faces=True)
    assert any(abs(area(f) - 9.0) < 1e-9 for f in faces)  # the 3 x 3 hole
    assert math.isclose(sum(area(f) for f in faces), 5 * 5 - 0 * 1, rel_tol=1e-9)


# --------------------------------------------------------------------------- library forms
def test_build123d_forms_inside_build_sketch():
    rect, circle = bd.Rectangle(2, 2), bd.Circle(1.2)
    faces = rbd.arrange([rect, circle], faces=True)
    assert isinstance(faces, bd.ShapeList) and all(isinstance(f, bd.Face) for f in faces)
    with bd.BuildSketch() as sketch:
        getattr(bd, "insert", bd.add)(faces)  # insert(): build123d 0.13 (add() deprecated); add(): 0.12
    assert math.isclose(sketch.sketch.area, (rect + circle).area, rel_tol=1e-9)
    edges = rbd.arrange([rect, circle])
    assert isinstance(edges, bd.ShapeList) and all(isinstance(e, bd.Edge) for e in edges)
    part = bd.extrude(faces[0], 1.0)
    assert BRepCheck_Analyzer(part.wrapped).IsValid()


@needs_cadquery
def test_cadquery_invoke_leaves_faces_and_edges_on_the_stack():
    import cadquery as cq

    from relief_cad.cad import cadquery as rcq

    wp = cq.Workplane("XY").rect(2, 2)
    faces = wp.invoke(rcq.arranged(cq.Workplane("XY").circle(1.2), faces=True))
    assert faces.size() == 9 and all(isinstance(f, cq.Face) for f in faces.vals())
    assert math.isclose(sum(f.Area() for f in faces.vals()),
                        cq.Workplane("XY").rect(2, 2).extrude(1).union(cq.Workplane("XY").circle(1.2).extrude(1))
                        .faces("<Z").val().Area(), rel_tol=1e-9)
    edges = wp.invoke(rcq.arranged(cq.Workplane("XY").circle(1.2)))
    assert all(isinstance(e, cq.Edge) for e in edges.vals())
    solid = faces.extrude(1.0)
    assert solid.val().isValid()


# --------------------------------------------------------------------------- errors
@pytest.mark.parametrize(
    ("call", "error", "builtin"),
    [
        (lambda: arrange(42), InputTypeError, TypeError),
        (lambda: arrange(ocp.make_compound([])), InvalidInputError, ValueError),
        (lambda: arrange([line((0, 0, 0), (1, 0, 0))], tol=-1.0), ToleranceError, ValueError),
        (lambda: arrange([line((0, 0, 0), (1, 0, 0)), line((0, 0, 0), (0, 0, 1)), line((0, 0, 0), (0, 1, 0))],
                         faces=True), InvalidInputError, ValueError),
    ],
)
def test_bad_input_is_named(call, error, builtin):
    with pytest.raises(error) as info:
        call()
    assert isinstance(info.value, ReliefCadError) and isinstance(info.value, builtin)
    assert "expected" in str(info.value) or "should be" in str(info.value)


def test_garbage_collector_state_is_restored():
    import gc

    a, b = line((0, 0, 0), (2, 2, 0)), line((0, 2, 0), (2, 0, 0))
    assert gc.isenabled()
    arrange([a, b])
    assert gc.isenabled()
    gc.disable()
    try:
        split_both(a, b)
        assert not gc.isenabled()  # a caller's choice is kept
    finally:
        gc.enable()
    with pytest.raises(InputTypeError):
        arrange([a, 42])
    assert gc.isenabled()


# --------------------------------------------------------------------------- degenerate inputs
def stalled_spline(n_stall=40, jitter=1e-12):
    """A closed cubic B-spline that stands still at one point over 40 of its 51 spans.

    Its poles repeat there up to ``jitter`` (build123d's periodic ``make_spline`` through some
    point sets gives such curves, standing still over a quarter of their range).
    """
    rng = np.random.default_rng(7)
    stop = (3.75, -3.11)
    pts = [(6.0, -2.6), (5.0, -2.85), (4.26, -3.0)]
    pts += [(stop[0] + jitter * a, stop[1] + jitter * b) for a, b in rng.uniform(-1.0, 1.0, (n_stall, 2))]
    pts += [(4.04, -3.53), (3.58, -5.33), (4.2, -8.44), (12.3, -0.93), (6.0, -2.6)]
    poles = Array1OfPnt(1, len(pts))
    for i, (x, y) in enumerate(pts, 1):
        poles.SetValue(i, gp_Pnt(x, y, 0.0))
    nk = len(pts) - 2
    knots, mults = Array1OfReal(1, nk), Array1OfInteger(1, nk)
    for i in range(nk):
        knots.SetValue(i + 1, float(i))
        mults.SetValue(i + 1, 4 if i in (0, nk - 1) else 1)
    return BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(poles, knots, mults, 3)).Edge(), stop


def test_a_spline_standing_still_does_not_meet_itself_there():
    """Its 40 spans at one point were 1,032 overlaps of the edge with itself (0.5 s), and arrange
    clustered their cuts for 4 s (40 to 70 s, and GBs, on the fuzz's splines); faces raised OCCT's
    gp_Dir2d error. It passes its stop once: no self-intersection, one piece, the face OCCT makes
    from its wire (OCCT's own check finds that face invalid too: the edge stands still).
    """
    edge, stop = stalled_spline()
    assert BRepCheck_Analyzer(edge).IsValid()
    assert len(api.intersections(edge)) == 0
    pieces = arrange([edge])
    assert len(pieces) == 1
    (face,) = arrange([edge], faces=True)
    own = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(edge).Wire()).Face()
    assert math.isclose(area(face), area(own), rel_tol=1e-9)


def test_a_line_through_a_spline_standing_still_is_cut_once_there():
    # the line meets every span of the stop; their cuts are one vertex, the slivers between them no pieces
    edge, stop = stalled_spline()
    across = line((stop[0] - 1.0, stop[1] - 1.0, 0.0), (stop[0] + 1.0, stop[1] + 1.0, 0.0))
    pieces = arrange([edge, across])
    assert_connected(pieces)
    near = [v for p in pieces for v in ends(p) if math.dist(BRep_Tool.Pnt_s(v).Coord(), (*stop, 0.0)) <= 1e-6]
    assert len(near) == 4 and all(v.IsSame(near[0]) for v in near)  # two pieces of each edge end there


def test_faces_of_holes_only_are_not_returned():
    """A circle and a parabola (a B-spline) that starts on it, touches it and ends on it again.

    OCCT's face builder gave two faces that fill the disk and a third, invalid, of area -pi r^2
    (the disk's outline as a hole only). It still leaves the lens between the start and the touch
    (area 0.0036) inside the larger face for this B-spline, as it does on General Fuse's edges
    (the same parabola as a Bezier curve gets the lens as a face of its own).
    """
    r = 2.536061679005639
    circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(-0.787344510806478, 2.6861346924223124, 0.0),
                                                    gp_Dir(0.0, 0.0, 1.0),
                                                    gp_Dir(0.8735037126914098, 0.4868174852183547, 0.0)), r)).Edge()
    pts = [(1.247807783673752, 4.1993313015887335), (-0.9845328402037407, 6.905852392030828),
           (-1.972150474879593, 0.4438493253876712)]
    poles, knots, mults = Array1OfPnt(1, 3), Array1OfReal(1, 2), Array1OfInteger(1, 2)
    for i, (x, y) in enumerate(pts, 1):
        poles.SetValue(i, gp_Pnt(x, y, 0.0))
    for i, k in enumerate((0.0, 5.921357256071988), 1):
        knots.SetValue(i, k)
        mults.SetValue(i, 3)
    parabola = BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(poles, knots, mults, 2)).Edge()
    faces = arrange([circle, parabola], faces=True)
    assert len(faces) >= 2
    assert all(BRepCheck_Analyzer(raw(f)).IsValid() and area(f) > 0.0 for f in faces)
    assert math.isclose(sum(area(f) for f in faces), math.pi * r * r, rel_tol=1e-9)


def test_vertex_tolerances_hold_for_occt_at_large_coordinates():
    """A closed spline of size 1,000 near (300, -4,600) from build123d (made by a periodic
    ``make_spline``, then scaled), whose ends are 4.9e-7 apart: the vertex that joins them had the
    measured error 2.47e-7 rounded up by 1e-9 of it, 2.5e-16, where OCCT evaluates the curve a few
    ulps (1e-12 there) away, and ``BRepBuilderAPI_MakeEdge`` refused the piece."""
    shape = TopoDS_Shape()
    assert BRepTools.Read_s(shape, str(Path(__file__).parent / "data" / "scaled_stalled_spline.brep"), BRep_Builder())
    pieces = arrange([shape])
    assert pieces
    assert_connected(pieces)

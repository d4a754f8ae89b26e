"""Property-based fuzz of relief_cad.cad with real shapes (issue 15): answers checked, refusals checked.

Shapes are built through build123d (lines, three-point arcs, Bézier edges; wires and faces;
spheres and cones with their degenerated poles / apex) at scales from 1e-6 to 1e6, located
(moved by a rotation and a translation) and reversed. Checked on every answer: the edges pass
through each reported point at the reported parameters (each edge's own OCCT parameter);
swapping a and b swaps them; a reversed edge keeps its parameters (orientation does not change
them); moving both shapes keeps the parameters and moves the points; a face or wire gives the
results of its edges; ``intersect`` returns the distinct points; ``split`` cuts at them;
OCCT's ``occt_intersections`` finds the same transversal crossings, or where it misses one the
50-digit arbiter confirms it; ``split`` makes no piece shorter than OCCT can; the same input twice gives
the same answer. Bad input must be a ReliefCadError that is also the matching built-in, naming
what was expected and what came. Counts: tests/_fuzz.py.
"""

from __future__ import annotations

import math

import build123d as bd
import pytest
from hypothesis import assume
from hypothesis import strategies as st
from OCP.BRep import BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.gp import gp_Dir, gp_Lin, gp_Pnt
from OCP.Precision import Precision

from relief_cad.cad import api, compare, edges_of, occt_intersections, ocp, split
from relief_cad.cad.arbiter import arbitrate_point
from relief_cad.cad.results import EdgeIntersection, EdgeOverlap
from relief_cad.errors import InputTypeError, ShapeError, ToleranceError
from tests._fuzz import Case, fuzz

coord = st.floats(-1.0, 1.0)
point = st.tuples(coord, coord)


@st.composite
def edges(draw: st.DrawFn, scale: float, offset: tuple[float, float]) -> bd.Edge:
    """A line, a three-point arc or a Bézier edge in the plane z = 0, of size about ``scale``."""
    kind = draw(st.sampled_from(["line", "arc", "bezier"]))
    n = {"line": 2, "arc": 3, "bezier": draw(st.integers(3, 5))}[kind]
    pts = [(x * scale + offset[0], y * scale + offset[1], 0.0) for x, y in draw(
        st.lists(point, min_size=n, max_size=n, unique_by=lambda p: (round(p[0], 2), round(p[1], 2))))]
    if kind == "arc":
        (x0, y0, _), (x1, y1, _), (x2, y2, _) = pts
        if abs((x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0)) < 0.05 * scale * scale:
            kind = "line"  # nearly collinear: no well-defined arc
    if kind == "line":
        # OCCT refuses a line between ends within Precision::Confusion (1e-7): no edge to test
        assume(math.dist(pts[0], pts[-1]) > 1e-7)
        return bd.Edge.make_line(pts[0], pts[-1])
    if kind == "arc":
        return bd.Edge.make_three_point_arc(*pts)
    return bd.Edge.make_bezier(*pts)


@st.composite
def edge_pairs(draw: st.DrawFn) -> tuple[bd.Edge, bd.Edge, float]:
    scale = 10.0 ** draw(st.integers(-6, 6))
    offset = (draw(st.floats(-3, 3)) * scale, draw(st.floats(-3, 3)) * scale)
    return draw(edges(scale, offset)), draw(edges(scale, offset)), scale


def value(edge: object, t: float) -> tuple[float, float, float]:
    raw = getattr(edge, "wrapped", edge)
    return BRepAdaptor_Curve(raw).Value(t).Coord()


def bound(scale: float) -> float:
    """How far an edge may pass from a reported point: 1e-7 of the size, 1e-7 at least (BRep)."""
    return 1e-6 * scale + 1e-7


def check_results(case: Case, results: list, ea: list, eb: list, scale: float) -> None:
    for r in results:
        if isinstance(r, EdgeIntersection):
            for edge, s in ((ea[r.index_a], r.t), (eb[r.index_b], r.u)):
                gap = math.dist(value(edge, s), r.point)
                case.check(gap <= bound(scale), f"the edge is {gap:.3g} from the point", r)
        else:
            case.check(isinstance(r, EdgeOverlap) and r.t[0] < r.t[1], r)


def clean(results: list, scale: float) -> list[EdgeIntersection]:
    """Transversal crossings away from the edges' ends (their parameters are well defined)."""
    out = []
    for r in results:
        if isinstance(r, EdgeIntersection) and r.kind == "crossing":
            ends = [value(e, x) for e, x in ((r.edge_a, BRep_Tool.Range_s(r.edge_a.wrapped)[0]),
                                             (r.edge_a, BRep_Tool.Range_s(r.edge_a.wrapped)[1]),
                                             (r.edge_b, BRep_Tool.Range_s(r.edge_b.wrapped)[0]),
                                             (r.edge_b, BRep_Tool.Range_s(r.edge_b.wrapped)[1]))]
            if min(math.dist(p, r.point) for p in ends) > 1e-3 * scale and not any(
                    q is not r and math.dist(q.point, r.point) < 1e-3 * scale
                    for q in results if isinstance(q, EdgeIntersection)):
                out.append(r)
    return out


def found(case: Case, r: EdgeIntersection, others: list, t: float, u: float, point, scale: float,
          what: str) -> None:
    ptol = 1e-6 * scale + 1e-9  # lines and arcs are parametrised by length, Bézier edges on [0, 1]
    case.check(any(isinstance(q, EdgeIntersection) and abs(q.t - t) <= ptol and abs(q.u - u) <= ptol
                   and math.dist(q.point, point) <= bound(scale) for q in others),
               f"{what}: {r} not found at {(t, u, point)}", others)


def shown(*shapes: object) -> list:
    """The edges as points along them (for failure messages)."""
    return [[tuple(round(c, 9) for c in value(e, x)) for x in _params(e)] for e in shapes]


def _params(e: object) -> list[float]:
    t0, t1 = BRep_Tool.Range_s(getattr(e, "wrapped", e))
    return [t0 + (t1 - t0) * i / 4 for i in range(5)]


def sees(theirs: list, r: EdgeIntersection, scale: float) -> bool:
    """OCCT has the crossing ``r``: a point there, or one of its tiny overlaps around it.

    OCCT's own points may be off by its resolution (``Precision::Confusion``, 1e-7) on top
    of the bound: at scale 1e-6 it puts a crossing 1.4e-7 from a line's start onto the start.
    """
    ptol = 1e-6 * scale + 1e-9
    near = bound(scale) + Precision.Confusion_s()
    return any(math.dist(q.point, r.point) <= near if isinstance(q, EdgeIntersection)
               else q.t[0] - ptol <= r.t <= q.t[1] + ptol for q in theirs if q.index_a == r.index_a)


def signature(results: list) -> list:
    return [(r.index_a, r.index_b, r.t, r.u, getattr(r, "point", None), r.kind) for r in results]


def degenerated(*shapes: bd.Edge) -> bool:
    """Whether OCCT made one of the edges a point (build123d's line between points < 1e-7 apart)."""
    return any(BRep_Tool.Degenerated_s(e.wrapped) for e in shapes)


def refused_degenerated(case: Case, call, a: bd.Edge, b: bd.Edge) -> bool:
    """When ``a`` or ``b`` is a point, check that ``call(a, b)`` refuses it by name; True if so."""
    if not degenerated(a, b):
        return False
    name = "a" if degenerated(a) else "b"
    case.refuses(lambda: call(a, b), ValueError, f"shape {name}", "degenerated", error=ShapeError)
    return True


# at scale 1e-6 a line between two drawn points < 1e-7 apart (OCCT's Precision::Confusion) is a
# degenerated edge, a point: that input must be refused by name (ShapeError), on either side
@fuzz("cad: edge pairs (swap, reversal, determinism)", edge_pairs(), examples=500, min_answered=0.9)
def test_fuzz_edge_pairs(case: Case, drawn: tuple[bd.Edge, bd.Edge, float]) -> None:
    a, b, scale = drawn
    if refused_degenerated(case, api.intersections, a, b):
        return
    ab = api.intersections(a, b)
    check_results(case, ab, [a], [b], scale)
    ba = api.intersections(b, a)
    rev = api.intersections(a.reversed(), b)
    for r in clean(ab, scale):
        found(case, r, ba, r.u, r.t, r.point, scale, "swap")
        found(case, r, rev, r.t, r.u, r.point, scale, "reversed edge")
    case.check(signature(api.intersections(a, b)) == signature(ab), "same input, another answer")
    vertices = api.intersect(a, b)
    points = [BRep_Tool.Pnt_s(v.wrapped).Coord() for v in vertices]
    case.check(all(any(math.dist(p, q.point) <= bound(scale) for q in ab if isinstance(q, EdgeIntersection))
                   or any(isinstance(q, EdgeOverlap) for q in ab) for p in points), "a vertex that is no result")
    case.check(len(points) >= min(1, len(ab)), "results but no vertex", ab)
    case.answered()


@fuzz("cad: moved, split and OCCT", edge_pairs(), st.tuples(st.floats(-5, 5), st.floats(-5, 5), st.floats(-5, 5)),
      st.tuples(st.floats(-180, 180), st.floats(-180, 180), st.floats(-180, 180)), examples=300, min_answered=1.0)
def test_fuzz_moved_split_occt(case: Case, drawn: tuple[bd.Edge, bd.Edge, float], shift: tuple,
                               angles: tuple) -> None:
    a, b, scale = drawn
    if refused_degenerated(case, split, a, b):
        return
    ab = api.intersections(a, b)
    loc = bd.Location(tuple(scale * s for s in shift), angles)
    moved = api.intersections(a.moved(loc), b.moved(loc))
    trsf = loc.wrapped.Transformation()
    for r in clean(ab, scale):
        p = gp_Pnt(*r.point).Transformed(trsf).Coord()
        found(case, r, moved, r.t, r.u, p, 6 * scale, "moved")
    theirs = occt_intersections(a, b)
    for r in clean(ab, scale):
        if not sees(theirs, r, scale):  # OCCT misses it: the 50-digit arbiter must confirm ours
            check = arbitrate_point(a, b, r.t, r.u, tol=bound(scale))
            case.check(check.kind == "crossing", "OCCT misses a crossing the arbiter does not confirm",
                       r, theirs, check)
    pieces = split(a, b)
    cuts = len(apart([value(a, r.t) for r in clean(ab, scale)], [value(a, x) for x in BRep_Tool.Range_s(a.wrapped)]))
    case.check(len(pieces) >= cuts + 1, "split gave fewer pieces than crossings + 1", len(pieces), cuts)
    ends = [[value(p, x) for x in BRep_Tool.Range_s(p.wrapped)] for p in pieces]
    t0, t1 = BRep_Tool.Range_s(a.wrapped)
    case.check(math.dist(ends[0][0], value(a, t0)) <= bound(scale) and
               math.dist(ends[-1][1], value(a, t1)) <= bound(scale), "the pieces do not span the edge", shown(a, b))
    case.check(all(math.dist(p[1], q[0]) <= bound(scale) for p, q in zip(ends, ends[1:])),
               "the pieces do not join", shown(a, b))
    case.answered()


def apart(points: list, ends: list) -> list:
    """The points farther than OCCT's shortest piece (1e-7 here) from the ends and from each other."""
    shortest = ocp.shortest_piece(0.0)
    kept: list = []
    for p in points:
        if all(math.dist(p, q) > shortest for q in ends + kept):
            kept.append(p)
    return kept


@st.composite
def polygons(draw: st.DrawFn) -> tuple[object, bd.Edge, float]:
    scale = 10.0 ** draw(st.integers(-4, 4))
    n = draw(st.integers(3, 6))
    angles = sorted(draw(st.lists(st.floats(0, 2 * math.pi), min_size=n, max_size=n,
                                  unique_by=lambda x: round(x, 1))))
    pts = [(scale * math.cos(t), scale * math.sin(t), 0.0) for t in angles]
    wire = bd.Wire.make_polygon(pts, close=True)
    shape = bd.Face(wire) if draw(st.booleans()) else wire
    line = bd.Edge.make_line(*[(scale * 2 * x, scale * 2 * y, 0.0) for x, y in draw(
        st.lists(point, min_size=2, max_size=2, unique_by=lambda p: (round(p[0], 1), round(p[1], 1))))])
    return shape, line, scale


@fuzz("cad: wires and faces", polygons(), examples=250, min_answered=1.0)
def test_fuzz_wires_and_faces(case: Case, drawn: tuple[object, bd.Edge, float]) -> None:
    shape, line, scale = drawn
    whole = api.intersections(shape, line)
    parts = edges_of(shape)
    check_results(case, whole, parts, [line], scale)
    for r in clean(whole, scale):
        alone = api.intersections(parts[r.index_a], line)
        found(case, r, alone, r.t, r.u, r.point, scale, "the face's edge on its own")
    case.answered()


@st.composite
def round_solids(draw: st.DrawFn) -> tuple[object, object, float]:
    r = 10.0 ** draw(st.integers(-3, 3))
    solid = bd.Sphere(r) if draw(st.booleans()) else bd.Cone(r, 0.0, 2 * r)
    z = draw(st.floats(0.1, 0.9)) * r
    other = (bd.Edge.make_line((-3 * r, draw(st.floats(-0.5, 0.5)) * r, z), (3 * r, 0.0, z))
             if draw(st.booleans()) else bd.Edge.make_circle(draw(st.floats(0.2, 2.0)) * r, bd.Plane.XY.offset(z)))
    return solid, other, r


@fuzz("cad: spheres and cones (degenerated edges)", round_solids(), st.integers(0, 9), examples=120,
      min_answered=1.0)
def test_fuzz_degenerated_edges(case: Case, drawn: tuple[object, object, float], which: int) -> None:
    solid, other, scale = drawn
    poles = [i for i, e in enumerate(edges_of(solid)) if BRep_Tool.Degenerated_s(e)]
    ours, theirs = api.intersections(solid, other), occt_intersections(solid, other)
    check_results(case, ours, edges_of(solid), [other], scale)
    case.check(all(r.index_a not in poles for r in ours + theirs), "a result on a degenerated edge")
    for r in clean(ours, scale):
        case.check(sees(theirs, r, scale), "OCCT misses the crossing", r, theirs)
    if which == 0:  # compare is slow (a 50-digit arbiter): one case in ten
        c = compare(solid, other)
        case.check(not c.errors and [i for side, i, _ in c.skipped if side == "a"] == poles, c)
    case.answered()


def _infinite() -> object:
    return BRepBuilderAPI_MakeEdge(gp_Lin(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))).Edge()


LINE = bd.Edge.make_line((-1, 0), (1, 0))
BAD_SHAPES = [  # (shape, error, built-in, words)
    (lambda: 5, InputTypeError, TypeError, ("expected a TopoDS_Shape", "received int")),
    (lambda: "edge", InputTypeError, TypeError, ("expected a TopoDS_Shape", "received str")),
    (lambda: 1.5, InputTypeError, TypeError, ("expected", "received float")),
    (lambda: {}, InputTypeError, TypeError, ("expected", "received dict")),
    (lambda: [LINE, 3], InputTypeError, TypeError, ("expected", "received int")),
    (lambda: bd.Compound(), ShapeError, ValueError, ("at least one edge with a curve", "no edges")),
    (lambda: [], ShapeError, ValueError, ("at least one edge", "no edges")),
    (lambda: bd.Vertex(1, 2, 3), ShapeError, ValueError, ("at least one edge", "no edges")),
    (lambda: [e for e in edges_of(bd.Sphere(1.0)) if BRep_Tool.Degenerated_s(e)], ShapeError, ValueError,
     ("at least one edge with a curve", "2 degenerated")),
    (_infinite, ShapeError, ValueError, ("bounded parameter range", "trim it")),
]
BAD_TOLS = [("abc", TypeError, "str"), ([1e-6], TypeError, "list"), (True, TypeError, "bool"),
            (10**400, ValueError, "digits"), (-1.0, ValueError, "-1.0"), (float("nan"), ValueError, "nan")]
FUNCTIONS = {"intersections": api.intersections, "intersect": api.intersect, "split": split,
             "occt_intersections": occt_intersections, "compare": compare}


@fuzz("cad: bad input", st.sampled_from(sorted(FUNCTIONS)), st.integers(0, len(BAD_SHAPES) + len(BAD_TOLS) - 1),
      st.booleans(), examples=300, min_answered=0.0, max_answered=0.0)
def test_fuzz_cad_bad_input(case: Case, function: str, i: int, first: bool) -> None:
    fn = FUNCTIONS[function]
    if i >= len(BAD_SHAPES):
        tol, builtin, came = BAD_TOLS[i - len(BAD_SHAPES)]
        case.refuses(lambda: fn(LINE, LINE, tol=tol), builtin, "tol should be", came, error=ToleranceError)
        return
    make, err, builtin, words = BAD_SHAPES[i]
    args = (make(), LINE) if first else (LINE, make())
    case.refuses(lambda: fn(*args), builtin, *words, error=err)


def test_sphere_and_circle_on_every_path() -> None:
    """Issue 15: intersections(sphere, circle) answered but occt_intersections raised ShapeError."""
    circle = bd.Edge.make_circle(math.sqrt(0.75), bd.Plane.XY.offset(0.5))  # on the sphere, across its seam
    ours, theirs = api.intersections(bd.Sphere(1.0), circle), occt_intersections(bd.Sphere(1.0), circle)
    assert len(ours) == len(theirs) == 1
    for r in ours + theirs:
        assert r.point == pytest.approx((math.sqrt(0.75), 0.0, 0.5), abs=1e-9)
    assert compare(bd.Sphere(1.0), circle).agree

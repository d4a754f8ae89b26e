"""Split and arrange with shared topology: edges cut at their intersections, connected by vertices.

:func:`arrange` takes all edges of all inputs, cuts them at all their mutual
intersections (self-intersections included) and returns the pieces as one
connected set: every cut point is one ``TopoDS_Vertex`` that all pieces through
it share (``IsSame`` on their ends), and a stretch where two edges overlap is
one edge, shared by both. With ``faces=True`` it returns the bounded faces of
the arrangement of planar edges, built by OCCT's own face builder
(``BOPAlgo_BuilderFace``) on the connected pieces. :func:`split_both` cuts two
shapes at their mutual intersections and returns both sets of pieces, sharing
vertices and overlap edges.

How: the intersections come from :func:`relief_cad.cad.api` (broad phase by
:mod:`relief_cad.broadphase`, every candidate segment pair through the core's
batch kernel in one call); the cut points and the edges' end vertices are
merged into vertices by :func:`relief_cad.broadphase.cluster_points` (points
within ``tol``, or within OCCT's ``Precision::Confusion`` where ``tol`` is smaller:
see :func:`relief_cad.cad.ocp.shortest_piece`; plus ends that already share a
vertex); each vertex is placed at the mean of the curve points it stands for,
and its tolerance is the largest distance from it to those curve points (the
real error of the intersection,
floored at OCCT's ``Precision::Confusion``), so ``BRepCheck_Analyzer`` accepts
every piece. Inputs are never modified.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> from OCP.TopExp import TopExp
>>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
>>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
>>> pieces = arrange([a, b])
>>> len(pieces), TopExp.LastVertex_s(pieces[0]).IsSame(TopExp.LastVertex_s(pieces[2]))
(4, True)
"""

from __future__ import annotations

import gc
import importlib
import math
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..broadphase import _cluster_points
from ..errors import InvalidInputError, OcctError, UnsupportedCurveError
from ..tolerances import _floor_of_magnitude
from . import api, flavour, ocp

try:
    from OCP.Bnd import Bnd_Box
    from OCP.BOPAlgo import BOPAlgo_BuilderFace
    from OCP.BRep import BRep_Builder, BRep_Tool
    from OCP.BRepAdaptor import BRepAdaptor_Curve
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace
    from OCP.BRepGProp import BRepGProp
    from OCP.GCPnts import GCPnts_AbscissaPoint
    from OCP.Geom import Geom_TrimmedCurve
    from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
    from OCP.gp import gp_Ax3, gp_Dir, gp_Pln, gp_Pnt
    from OCP.GProp import GProp_GProps
    from OCP.Precision import Precision
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_FORWARD
    from OCP.TopExp import TopExp
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS_Edge, TopoDS_Vertex
except ImportError as exc:  # pragma: no cover - api above raises first
    raise ImportError("relief_cad.cad.arrangement needs OCP") from exc
from ._compat import IndexedMapOfShape as TopTools_IndexedMapOfShape
from ._compat import ListOfShape as TopTools_ListOfShape
from ._compat import box_corners, downcast_edge, downcast_face

__all__ = ["arrange", "split_both", "split_connected"]


@dataclass
class _Cut:
    """A place on an edge where a vertex goes: edge index, edge parameter, a point near it."""

    edge: int
    t: float
    point: tuple[float, float, float]
    on_edge: bool = False  # the point is the edge's own at t (an end), not an intersection's


@dataclass
class _Graph:
    """The edges of an arrangement, the places they are cut, and which places are one vertex."""

    edges: list[Any]  # TopoDS_Edge, every input edge (degenerated ones included)
    skip: set[int]  # indices of edges that take no part (degenerated, or a copy of an earlier edge)
    cuts: list[_Cut] = field(default_factory=list)
    links: list[tuple[int, int]] = field(default_factory=list)  # cuts that are one vertex
    overlaps: int = 0
    # tangent contacts inside both edges: (cut on edge i, edge i, t, edge j, u); see _touch_spread
    touches: list[tuple[int, int, float, int, float]] = field(default_factory=list)
    tol: float = 0.0
    flavour: str = "ocp"
    frame: np.ndarray | None = None  # the common 2D frame of all edges (see api._common_frame), if any
    values: _Values = field(init=False)  # curve points of the edges (one adaptor per edge, for every use)

    def __post_init__(self) -> None:
        self.values = _Values(self.edges)


@contextmanager
def _no_gc_pauses() -> Iterator[None]:
    """Hold the cyclic garbage collector while an arrangement is built, and restore its state.

    Building one allocates hundreds of thousands of small objects that all stay alive
    (float lists, OCP handles, results), so every generation-0 collection rescans a growing
    heap for nothing: measured on 2,000 filleted-sketch edges, 25-30 % of the run. Nothing
    here makes reference cycles to collect; the collector runs again on exit.
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


# --------------------------------------------------------------------------- cut places
def _graph(a: Any, b: Any, tol: float | None) -> tuple[_Graph, int]:
    """Run the intersections and collect every cut and edge end; returns the graph and ``len(a's edges)``."""
    edges_a = ocp.edges_of(a)
    edges_b = [] if b is None else ocp.edges_of(b)
    _, raws, ftol, infos = api._run(edges_a, None if b is None else edges_b, tol, drop_copies=b is None)
    # cut points closer than OCCT can keep apart are one vertex (no piece between them); an
    # edge repeating an earlier one's curve has no pieces of its own (the earlier one's are its)
    copies = {info.index for info in infos if info.copy_of is not None}
    graph = _Graph(edges_a + edges_b, copies, tol=ocp.shortest_piece(ftol), flavour=flavour.flavour_of(a))
    graph.frame = infos[0].frame
    values = graph.values
    offset = len(edges_a)
    _add_ends(graph)
    for r in raws:
        i = r.ea.index
        j = r.eb.index + (0 if b is None else offset)
        if r.kind == "overlap":
            graph.overlaps += 1
            for t, u in zip(r.t, r.u, strict=True):
                _add_pair(graph, i, t, j, u, values(i, t))
        else:
            _add_pair(graph, i, r.t, j, r.u, r.point)
            if r.kind == "tangent" and _inside_edge(r.ea, r.t) and _inside_edge(r.eb, r.u):
                graph.touches.append((len(graph.cuts) - 2, i, float(r.t), j, float(r.u)))
    return graph, offset


def _inside_edge(info: Any, t: float) -> bool:
    """True when the edge goes on at both sides of ``t``: inside its range, or anywhere on a closed edge."""
    v0, v1 = TopExp.FirstVertex_s(info.edge), TopExp.LastVertex_s(info.edge)
    return bool(info.first < t < info.last or (not v0.IsNull() and v0.IsSame(v1)))


def _add_pair(graph: _Graph, i: int, t: float, j: int, u: float, p: tuple[float, float, float]) -> None:
    graph.cuts.append(_Cut(i, float(t), p))
    graph.cuts.append(_Cut(j, float(u), p))
    graph.links.append((len(graph.cuts) - 2, len(graph.cuts) - 1))


def _add_ends(graph: _Graph) -> None:
    """Both ends of every edge are cuts; ends sharing one ``TopoDS_Vertex`` are linked."""
    vmap = TopTools_IndexedMapOfShape()
    first_cut: dict[int, int] = {}  # vertex index in vmap -> first cut at it
    values = graph.values
    for k, edge in enumerate(graph.edges):
        if k in graph.skip or BRep_Tool.Degenerated_s(edge):
            graph.skip.add(k)
            continue
        t0, t1 = BRep_Tool.Range_s(edge)
        for t, v in ((t0, TopExp.FirstVertex_s(edge)), (t1, TopExp.LastVertex_s(edge))):
            graph.cuts.append(_Cut(k, t, values(k, t), True))
            if v.IsNull():
                continue
            index = vmap.Add(v)
            if index in first_cut:
                graph.links.append((first_cut[index], len(graph.cuts) - 1))
            else:
                first_cut[index] = len(graph.cuts) - 1


# --------------------------------------------------------------------------- vertices
class _Values:
    """Curve points of edges at their own parameters, one ``BRepAdaptor_Curve`` per edge."""

    def __init__(self, edges: list[Any]) -> None:
        self._edges = edges
        self._adaptors: dict[int, Any] = {}

    def __call__(self, k: int, t: float) -> tuple[float, float, float]:
        adaptor = self._adaptors.get(k)
        if adaptor is None:
            adaptor = self._adaptors[k] = BRepAdaptor_Curve(self._edges[k])
        return adaptor.Value(t).Coord()  # type: ignore[no-any-return]


def _vertices(graph: _Graph, values: _Values) -> tuple[np.ndarray, list[Any], np.ndarray]:
    """Merge the cuts into vertices: labels per cut, the vertices, their points (rows)."""
    points = np.array([c.point for c in graph.cuts], dtype=np.float64).reshape(-1, 3)
    labels = _cluster_points(points, graph.tol, links=graph.links)
    n = int(labels.max()) + 1 if labels.shape[0] else 0
    on_curve = np.array([c.point if c.on_edge else values(c.edge, c.t) for c in graph.cuts],
                        dtype=np.float64).reshape(-1, 3)
    sums = np.zeros((n, 3))
    np.add.at(sums, labels, on_curve)
    centres = sums / np.bincount(labels, minlength=n)[:, None]
    errors = np.zeros(n)
    np.maximum.at(errors, labels, np.linalg.norm(on_curve - centres[labels], axis=1))
    for cut, i, t, j, u in graph.touches:
        label = labels[cut]
        for q in _touch_spread(graph, i, t, j, u):
            errors[label] = max(errors[label], math.dist(q, centres[label]))
    floor = Precision.Confusion_s()
    builder = BRep_Builder()
    vertices = []
    for centre, error in zip(centres.tolist(), errors.tolist(), strict=True):
        v = TopoDS_Vertex()
        # the measured error, rounded up by a relative 1e-9 and the rounding floor of the coordinates,
        # so that OCCT's own re-measuring passes: it evaluates the curves its way, ulps apart (an error
        # of 2.5e-7 at coordinates of 4,600 was 2.5e-16 over OCCT's distance, 1e-12 an ulp there)
        rounding = _floor_of_magnitude(max(abs(centre[0]), abs(centre[1]), abs(centre[2])))
        builder.MakeVertex(v, gp_Pnt(*centre), max(floor, error * (1.0 + 1e-9) + rounding))
        vertices.append(v)
    return labels, vertices, centres


def _touch_spread(graph: _Graph, i: int, t: float, j: int, u: float) -> list[tuple[float, float, float]]:
    """The points where edges ``i`` and ``j`` really meet around their tangent contact at ``(t, u)``.

    A touch within tol may hide two crossings: circles 1e-9 into each other cross 2.2e-5 from
    the contact on either side, and a vertex of tolerance 1e-7 there leaves the wires crossing
    outside it (``BRepCheck_Analyzer``: intersecting wires). The pair is intersected again at a
    thousandth of the tolerance; its points joined to the contact by a stretch where the edges stay
    within tol are the contact's own, and the vertex's tolerance is measured to them as well.
    """
    values = graph.values
    fine = api.intersections(graph.edges[i], graph.edges[j], tol=1e-3 * graph.tol)
    curve_j, _ = _global_curve(graph.edges[j])
    out = []
    for r in fine:
        if r.kind != "overlap" and _joined(graph, i, t, r.t, curve_j, u, r.u):
            out.append(values(i, r.t))
            out.append(values(j, r.u))
    return out


def _joined(graph: _Graph, i: int, t0: float, t1: float, curve: Any, u0: float, u1: float) -> bool:
    """True when edge ``i`` over ``[t0, t1]`` stays within tol of ``curve`` near ``[u0, u1]``.

    ``curve`` is the other edge's global curve; 7 samples of edge ``i``, projected on it.
    """
    for k in range(1, 8):
        f = k / 8.0
        proj = GeomAPI_ProjectPointOnCurve(gp_Pnt(*graph.values(i, t0 + f * (t1 - t0))), curve,
                                           min(u0, u1) - abs(u1 - u0), max(u0, u1) + abs(u1 - u0))
        if proj.NbPoints() == 0 or proj.LowerDistance() > graph.tol:
            return False
    return True


# --------------------------------------------------------------------------- pieces
def _global_curve(edge: Any) -> tuple[Any, Any]:
    """The edge's 3D curve in global coordinates and the map of its parameters (location applied)."""
    loc = TopLoc_Location()
    curve = BRep_Tool.Curve_s(edge, loc, 0.0, 0.0)
    if curve is None:
        raise UnsupportedCurveError("expected edges with a 3D curve; received one without")
    if loc.IsIdentity():
        return curve, None
    trsf = loc.Transformation()
    return curve.Transformed(trsf), trsf


def _make_piece(curve: Any, trsf: Any, v1: Any, v2: Any, t1: float, t2: float) -> TopoDS_Edge:
    if trsf is not None:
        t1, t2 = curve.TransformedParameter(t1, trsf), curve.TransformedParameter(t2, trsf)
    return ocp.edge_on_curve(curve, t1, t2, v1, v2)


@dataclass
class _Piece:
    edge: TopoDS_Edge
    nodes: tuple[int, int]
    mid_at: tuple[int, float]  # (input edge, its parameter) of the piece's middle: a point for _same_piece
    curve: Any
    t: tuple[float, float]
    twin: bool = False  # the edge of an earlier piece (an overlap), reused


def _edge_pieces(k: int, graph: _Graph, places: list[tuple[float, int]], vertices: list[Any],
                 centres: np.ndarray, values: _Values) -> list[_Piece]:
    """Cut edge ``k`` at its places ``(t, vertex)``: pieces in increasing parameter."""
    edge = graph.edges[k]
    curve, trsf = _global_curve(edge)
    t0, t1 = BRep_Tool.Range_s(edge)
    eps = 1e-12 * max(1.0, abs(t1 - t0))
    places = sorted(places)
    pieces: list[_Piece] = []
    start_t, start_n = places[0]
    for t, node in places[1:]:
        mid = 0.5 * (start_t + t)
        if node == start_n and (t - start_t <= eps or math.dist(values(k, mid), centres[node]) <= graph.tol):
            continue  # one place twice, or a sliver from a vertex back to itself: no piece
        if t <= start_t:
            continue  # two vertices at one parameter (their points off the curve): no piece can join them
        piece = _make_piece(curve, trsf, vertices[start_n], vertices[node], start_t, t)
        pieces.append(_Piece(piece, (start_n, node), (k, mid), curve, (start_t, t)))
        start_t, start_n = t, node
    return pieces


def _same_piece(p: _Piece, q: _Piece, tol: float, values: _Values) -> bool:
    """True when two pieces between the same vertices lie on each other (an overlap).

    Each piece's middle point is found here, when a piece between the same vertices came
    before: most pieces never need it. Pieces whose middles lie on each other must also be
    as long as each other (within ``4 tol`` and 1e-6 of the length): an edge standing still
    (a spline with repeated poles) has its parameter middle at its stop, on any piece through it.
    """
    for piece, other in ((p, q), (q, p)):
        edge = other.edge
        loc_curve = BRep_Tool.Curve_s(edge, TopLoc_Location(), 0.0, 0.0)
        lo, hi = BRep_Tool.Range_s(edge)
        proj = GeomAPI_ProjectPointOnCurve(gp_Pnt(*values(*piece.mid_at)), loc_curve, lo, hi)
        if proj.NbPoints() == 0 or proj.LowerDistance() > tol:
            return False
    lp, lq = (float(GCPnts_AbscissaPoint.Length_s(BRepAdaptor_Curve(x.edge))) for x in (p, q))
    return abs(lp - lq) <= max(4.0 * tol, 1e-6 * max(lp, lq))


def _pieces(graph: _Graph) -> tuple[list[list[_Piece]], list[Any], np.ndarray]:
    """Every edge's pieces, an overlap's second copy replaced by the first one (same TopoDS_Edge)."""
    values = graph.values
    labels, vertices, centres = _vertices(graph, values)
    places: dict[int, list[tuple[float, int]]] = {}
    for cut, label in zip(graph.cuts, labels.tolist(), strict=True):
        places.setdefault(cut.edge, []).append((cut.t, label))
    by_nodes: dict[tuple[int, int], list[_Piece]] = {}
    out: list[list[_Piece]] = []
    for k in range(len(graph.edges)):
        pieces = [] if k in graph.skip else _edge_pieces(k, graph, places[k], vertices, centres, values)
        for n, piece in enumerate(pieces):
            a, b = piece.nodes
            key = (a, b) if a <= b else (b, a)
            earlier = by_nodes.get(key)
            if earlier is None:  # most pieces: the first between their vertices
                by_nodes[key] = [piece]
                continue
            twin = next((q for q in earlier if _same_piece(piece, q, graph.tol, values)), None)
            if twin is None:
                earlier.append(piece)
            else:
                closed = twin.nodes[0] == twin.nodes[1]
                reverse = twin.nodes != piece.nodes or (closed and not _same_way(twin, piece))
                shared = downcast_edge(twin.edge.Reversed()) if reverse else twin.edge
                pieces[n] = _Piece(shared, piece.nodes, piece.mid_at, twin.curve, twin.t, twin=True)
        out.append(pieces)
    return out, vertices, centres


def _same_way(p: _Piece, q: _Piece) -> bool:
    """For closed twin pieces: do they run the same way? (compare the tangents at their mids)."""
    dp = p.curve.DN(0.5 * sum(p.t), 1)
    dq = q.curve.DN(0.5 * sum(q.t), 1)
    return bool(dp.Dot(dq) >= 0.0)


def _oriented(piece: TopoDS_Edge, original: Any) -> TopoDS_Edge:
    if original.Orientation() == TopAbs_FORWARD:
        return piece
    return downcast_edge(piece.Reversed())


# --------------------------------------------------------------------------- faces
def _plane(graph: _Graph, centres: np.ndarray) -> gp_Pln:
    """The plane of a planar arrangement (through the mean vertex, normal from the common frame)."""
    frame = graph.frame
    if frame is None:
        raise InvalidInputError("expected edges lying in one plane for faces=True; they do not")
    normal = np.cross(frame[0, :3], frame[1, :3])
    origin = centres.mean(axis=0)
    return gp_Pln(gp_Ax3(gp_Pnt(*origin.tolist()), gp_Dir(*normal.tolist()), gp_Dir(*frame[0, :3].tolist())))


def _bounded_faces(edges: list[TopoDS_Edge], plane: gp_Pln) -> list[Any]:
    """The bounded faces of connected planar edges, by ``BOPAlgo_BuilderFace`` inside a large frame.

    The edges go in both orientations, with the four edges of a rectangle around
    them; OCCT's builder splits the rectangle into faces, and the face holding
    the rectangle's edges (the unbounded outside) is dropped. So is a face of holes
    only (negative area): the builder sometimes leaves the outside's inner boundary
    apart from the rectangle, as a face of its own (a circle and a spline through three
    of its points: two faces that fill the disk, and the disk's outline as a hole
    only, an invalid face of area -pi r^2). An exception OCCT raises is an OcctError.
    """
    box = Bnd_Box()
    for e in edges:
        BRepBndLib.Add_s(e, box)
    corners = np.array(box_corners(box)).reshape(2, 3)
    pts = np.array([[x, y, z] for x in corners[:, 0] for y in corners[:, 1] for z in corners[:, 2]])
    pos = plane.Position()
    o = np.array(pos.Location().Coord())
    u, v = np.array(pos.XDirection().Coord()), np.array(pos.YDirection().Coord())
    us, vs = (pts - o) @ u, (pts - o) @ v
    margin = 0.1 * max(float(np.ptp(us)), float(np.ptp(vs)), 1.0)
    frame = BRepBuilderAPI_MakeFace(
        plane, float(us.min()) - margin, float(us.max()) + margin, float(vs.min()) - margin,
        float(vs.max()) + margin,
    ).Face()
    frame_edges = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(frame, TopAbs_EDGE, frame_edges)
    shapes = TopTools_ListOfShape()
    for i in range(1, frame_edges.Extent() + 1):
        shapes.Append(frame_edges.FindKey(i))
    for e in map(_face_edge, edges):
        forward = downcast_edge(e.Oriented(TopAbs_FORWARD))
        shapes.Append(forward)
        shapes.Append(forward.Reversed())
    builder = BOPAlgo_BuilderFace()
    builder.SetFace(downcast_face(frame.Oriented(TopAbs_FORWARD)))
    builder.SetShapes(shapes)
    builder.SetAvoidInternalShapes(True)
    try:
        builder.Perform()
    except Exception as exc:  # noqa: BLE001 - OCCT raises Standard_Failure subclasses
        raise OcctError(f"BOPAlgo_BuilderFace failed on the arranged edges: {exc}") from exc
    if builder.HasErrors():
        raise OcctError("BOPAlgo_BuilderFace failed on the arranged edges")
    return [f for f in builder.Areas() if not _touches(f, frame_edges) and _signed_area(f) > 0.0]


def _face_edge(edge: TopoDS_Edge) -> TopoDS_Edge:
    """The edge for ``BOPAlgo_BuilderFace``: a chord for a piece of a periodic curve too short for OCCT.

    A piece shorter in parameter than ``PConfusion`` (:func:`.ocp.edge_on_curve`) is valid, but
    the face builder does not close a loop through it: a circle of radius 1,000 cut 5e-7 apart gave
    no disk. Its chord between the same vertices is within ``Precision::Confusion`` of it
    (checked at its middle), and the faces are built with that.
    """
    curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
    t1, t2 = BRep_Tool.Range_s(edge)
    if curve is None or not isinstance(curve, Geom_TrimmedCurve) or t2 - t1 > Precision.PConfusion_s():
        return edge
    v1, v2 = TopExp.FirstVertex_s(edge), TopExp.LastVertex_s(edge)
    p1, p2 = BRep_Tool.Pnt_s(v1), BRep_Tool.Pnt_s(v2)
    chord_mid = [0.5 * (a + b) for a, b in zip(p1.Coord(), p2.Coord(), strict=True)]
    if math.dist(chord_mid, BRepAdaptor_Curve(edge).Value(0.5 * (t1 + t2)).Coord()) > Precision.Confusion_s():
        return edge
    maker = BRepBuilderAPI_MakeEdge(v1, v2)
    return maker.Edge() if maker.IsDone() else edge


def _signed_area(face: Any) -> float:
    """The area of a face, negative for a face bounded by holes only (its wires run clockwise)."""
    props = GProp_GProps()
    BRepGProp.SurfaceProperties_s(face, props)
    return float(props.Mass())


def _touches(face: Any, frame_edges: Any) -> bool:
    fmap = TopTools_IndexedMapOfShape()
    TopExp.MapShapes_s(face, TopAbs_EDGE, fmap)
    return any(fmap.Contains(frame_edges.FindKey(i)) for i in range(1, frame_edges.Extent() + 1))


# --------------------------------------------------------------------------- public API
def _unique(pieces: list[list[_Piece]]) -> list[TopoDS_Edge]:
    """Every piece once (a twin is an earlier piece's edge), as made: forward."""
    return [p.edge for edge_pieces in pieces for p in edge_pieces if not p.twin]


def arrange(shapes: Any, *, tol: float | None = None, faces: bool = False) -> Any:
    """Cut all edges of all shapes at all their intersections: connected edges, or the faces they bound.

    Parameters
    ----------
    shapes : shape or list of shapes
        Edges, wires, faces, sketches, compounds (build123d, CadQuery or raw OCP),
        or a list of them. Every edge takes part once (an edge shared by two
        faces is one edge); degenerated edges are left out.
    tol : float, optional
        Distance (model units) within which curves meet and cut points are one
        vertex; default as for :func:`relief_cad.cad.api.intersections` (the
        largest OCCT tolerance of the edges when meaningful, else
        :func:`relief_cad.tolerances.default_tolerance` of their control points).
    faces : bool, keyword-only
        False: return the edges. True: return the bounded faces of the
        arrangement (every region enclosed by the edges, holes cut out), built
        with ``BOPAlgo_BuilderFace``; the edges must lie in one plane, and
        dangling edges bound nothing.

    Returns
    -------
    list of edges, or of faces
        In the flavour of the first input (build123d ``ShapeList[Edge]`` /
        ``ShapeList[Face]``, CadQuery ``Edge`` / ``Face`` lists, or raw
        ``TopoDS_Edge`` / ``TopoDS_Face``). Edges: every piece once, forward,
        grouped by input edge in increasing parameter; pieces meeting at a point
        share one ``TopoDS_Vertex``; an overlap is one edge. Faces: in
        ``BOPAlgo_BuilderFace`` order.

    Raises
    ------
    InputTypeError
        If an input is not a shape.
    InvalidInputError
        If the shapes have no edge with a curve, or, with ``faces=True``, the
        edges do not lie in one plane.
    ToleranceError
        If ``tol`` is not a finite distance > 0.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakePolygon
    >>> from OCP.gp import gp_Pnt
    >>> square = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0), gp_Pnt(2, 2, 0),
    ...                                     gp_Pnt(0, 2, 0), True).Wire()
    >>> cross = BRepBuilderAPI_MakeEdge(gp_Pnt(1, -1, 0), gp_Pnt(1, 3, 0)).Edge()
    >>> len(arrange([square, cross])), len(arrange([square, cross], faces=True))
    (9, 2)
    >>> len(arrange(square))  # nothing to cut: the same four edges, rebuilt
    4
    """
    with _no_gc_pauses():
        graph, _ = _graph(shapes, None, tol)
        pieces, _, centres = _pieces(graph)
        edges = _unique(pieces)
    if not faces:
        return flavour.wrap_edges(edges, graph.flavour)
    return _wrap_faces(_bounded_faces(edges, _plane(graph, centres)), graph.flavour)


def split_both(a: Any, b: Any, *, tol: float | None = None) -> tuple[Any, Any]:
    """Cut the edges of ``a`` and of ``b`` where they meet each other: both sets of pieces, connected.

    Parameters
    ----------
    a, b : shape
        As for :func:`relief_cad.cad.api.intersections` (the edges of one shape
        are not cut where they cross each other; :func:`arrange` does that).
    tol : float, optional
        As for :func:`arrange`.

    Returns
    -------
    pieces_a, pieces_b : lists of edges
        In the flavour of ``a``: for every edge of ``a`` (then ``b``), in
        :func:`~relief_cad.cad.ocp.edges_of` order, its pieces in increasing
        parameter, keeping the edge's orientation. A cut point is one vertex
        shared by the pieces of both shapes; where the shapes overlap, both
        lists hold the same edge (``IsSame``).

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(2, 0, 0), gp_Pnt(6, 0, 0)).Edge()
    >>> pa, pb = split_both(a, b)
    >>> len(pa), len(pb), pa[1].IsSame(pb[0])
    (2, 2, True)
    """
    with _no_gc_pauses():
        graph, offset = _graph(a, b, tol)
        pieces, _, _ = _pieces(graph)
    sides = (range(offset), range(offset, len(graph.edges)))
    out = tuple(
        flavour.wrap_edges(
            [_oriented(p.edge, graph.edges[k]) for k in side for p in pieces[k]], graph.flavour
        )
        for side in sides
    )
    return out[0], out[1]


def split_connected(a: Any, b: Any = None, *, tol: float | None = None) -> Any:
    """Cut the edges of ``a`` where they meet ``b`` (or each other): ``a``'s pieces, sharing vertices.

    Consecutive pieces of an edge, and pieces of different edges meeting at a
    point, share one ``TopoDS_Vertex``: the pieces form connected wires.

    Parameters
    ----------
    a : shape
        The shape whose edges are cut.
    b : shape, optional
        The cutting shape. ``None``: ``a``'s edges are cut where they cross each
        other or themselves.
    tol : float, optional
        As for :func:`arrange`.

    Returns
    -------
    list of edges
        In the flavour of ``a``: for every edge of ``a``, its pieces in
        increasing parameter, keeping its orientation.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(1, -1, 0), gp_Pnt(1, 1, 0)).Edge()
    >>> [BRep_Tool.Range_s(e) for e in split_connected(a, b)]
    [(0.0, 1.0), (1.0, 4.0)]
    """
    if b is not None:
        return split_both(a, b, tol=tol)[0]
    with _no_gc_pauses():
        graph, _ = _graph(a, None, tol)
        pieces, _, _ = _pieces(graph)
    return flavour.wrap_edges(
        [_oriented(p.edge, graph.edges[k]) for k, ps in enumerate(pieces) for p in ps], graph.flavour
    )


def _wrap_faces(faces: list[Any], flavour: str) -> Any:
    if flavour in ("build123d", "cadquery"):
        return importlib.import_module(f"relief_cad.cad.{flavour}").wrap_faces(faces)
    return faces

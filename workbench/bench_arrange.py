"""Benchmark of ``arrange``: relief_cad against OCCT's General Fuse (``BOPAlgo_Builder``), same edges.

Families (each at several sizes, default 50, 500 and 5,000 edges; ``RELIEF_BENCH_ARRANGE_SIZES=50,200``
overrides):

* ``glyphs``: build123d ``Text`` outlines (lines of "Relief perspective 2026") with wavy splines across;
* ``fillets``: a staggered grid of overlapping filleted rectangles and circles;
* ``step``: the edges of the parts in ``workbench/data/step/*.step`` projected onto a plane
  (oblique view), copies shifted so that they overlap.

For every case: ``relief_s`` (:func:`relief_cad.cad.arrangement.arrange`, OCCT conversion and native
edges with shared vertices included; best of a few runs), ``occt_s`` (``BOPAlgo_Builder`` on the same
edges), ``speedup = occt_s / relief_s``, the edge and vertex counts of both results, whether every
piece shares its vertices (``connected``) and ``BRepCheck_Analyzer`` on relief_cad's result. Where
the counts differ, the vertices found by one side only are judged by the 50-digit arbiter
(:func:`relief_cad.cad.compare` on the input edges around each such point): ``verdict`` says who is
right. ``growth`` rows give the exponent of the cost with size (log-log slope between sizes).
``ocp_floor_s`` is what the OCP calls alone cost that any arrangement returning OCCT edges must
make, with General Fuse's counts (read the input curves, make the vertices and the edges;
``_floor_calls``), and ``speedup_bound = occt_s / ocp_floor_s`` the most such an arrangement can
reach: issue 13 asked for 10x at every size.

Run ``python -m workbench bench arrange`` or ``python -m workbench.bench_arrange``.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from relief_cad.cad._compat import box_corners

__all__ = ["run", "cases"]

STEP_DIR = Path(__file__).resolve().parent / "data" / "step"
DEFAULT_SIZES = (50, 500, 5000)


# --------------------------------------------------------------------------- inputs
def _glyphs(n: int) -> list[Any]:
    import build123d as bd

    text = "Relief perspective 2026"
    edges: list[Any] = []
    line = 0
    while len(edges) < n:
        y0 = -14.0 * line
        glyphs = bd.Text(text, font_size=10).moved(bd.Location((0, y0, 0)))
        # build123d lists a glyph's contours in an order that varies from run to run (the dot and
        # the stem of "i"): sorted by place, the first n edges are the same in every run
        for face in sorted(glyphs.faces(), key=_place):
            edges.extend(e.wrapped for e in face.edges())
        for k in range(20):
            pts: list[bd.VectorLike] = [bd.Vector(x, y0 - 6 + 0.6 * k + 0.8 * math.sin(0.7 * x + k))
                                        for x in range(-60, 65, 5)]
            edges.append(bd.Edge.make_spline(pts).wrapped)
        line += 1
    return edges[:n]


def _place(shape: Any) -> tuple[float, float]:
    centre = shape.bounding_box().center()
    return (round(centre.X, 6), round(centre.Y, 6))


def _fillets(n: int) -> list[Any]:
    import build123d as bd

    edges: list[Any] = []
    k = 0
    while len(edges) < n:
        i, j = divmod(k, 25)
        x, y = 3.0 * j + 1.5 * (i % 2), 2.2 * i
        rect = bd.RectangleRounded(4.0, 2.5, 0.6).moved(bd.Location((x, y, 0)))
        edges.extend(e.wrapped for e in rect.edges())
        edges.append(bd.Edge.make_circle(1.0).moved(bd.Location((x + 2.0, y + 1.2, 0))).wrapped)
        k += 1
    return edges[:n]


def _step_edges() -> list[Any]:
    """The STEP parts' edges, projected along an oblique direction onto the XY plane."""
    import build123d as bd
    from OCP.BRep import BRep_Tool
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.Geom import Geom_Line, Geom_Plane
    from OCP.GeomProjLib import GeomProjLib
    from OCP.gp import gp_Dir, gp_Pln, gp_Pnt

    from relief_cad.cad import ocp

    plane = Geom_Plane(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)))
    view = gp_Dir(0.3, 0.2, 1.0)
    out = []
    for path in sorted(STEP_DIR.glob("*.step")):
        for edge in ocp.edges_of(bd.import_step(str(path))):
            if BRep_Tool.Degenerated_s(edge):
                continue
            curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
            t0, t1 = BRep_Tool.Range_s(edge)
            if isinstance(curve, Geom_Line):  # GeomProjLib gives a B-spline on knots +-2e100 for a line
                ends = [_flatten(curve.Value(t).Coord(), view) for t in (t0, t1)]
                maker = BRepBuilderAPI_MakeEdge(gp_Pnt(*ends[0]), gp_Pnt(*ends[1]))
            else:
                flat = GeomProjLib.ProjectOnPlane_s(curve, plane, view, True)
                maker = BRepBuilderAPI_MakeEdge(flat, t0, t1)
            if maker.IsDone() and _length(maker.Edge()) > 1e-3 and _converts(maker.Edge()):
                out.append(maker.Edge())
    return out


def _converts(edge: Any) -> bool:
    """False for the few projected edges relief_cad's conversion refuses (reported in the notes)."""
    from relief_cad.cad import segments

    try:
        segments(edge)
    except Exception:  # noqa: BLE001 - such an edge is left out of both sides of the benchmark
        return False
    return True


def _flatten(p: tuple[float, float, float], view: Any) -> tuple[float, float, float]:
    d = view.Coord()
    s = p[2] / d[2]
    return (p[0] - s * d[0], p[1] - s * d[1], 0.0)


def _length(edge: Any) -> float:
    from OCP.BRepGProp import BRepGProp
    from OCP.GProp import GProp_GProps

    props = GProp_GProps()
    BRepGProp.LinearProperties_s(edge, props)
    return float(props.Mass())


def _step(n: int) -> list[Any]:
    from OCP.gp import gp_Trsf, gp_Vec
    from OCP.TopLoc import TopLoc_Location

    from relief_cad.cad._compat import downcast_edge

    base = _step_edges()
    span = _extent(base)
    edges: list[Any] = []
    k = 0
    while len(edges) < n:
        trsf = gp_Trsf()
        trsf.SetTranslation(gp_Vec(0.37 * span * (k % 6), 0.41 * span * (k // 6), 0.0))
        edges.extend(downcast_edge(e.Moved(TopLoc_Location(trsf))) for e in base)
        k += 1
    return edges[:n]


def _extent(edges: list[Any]) -> float:
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    box = Bnd_Box()
    for e in edges:
        BRepBndLib.Add_s(e, box)
    lo_hi = np.array(box_corners(box)).reshape(2, 3)
    return float(np.max(lo_hi[1] - lo_hi[0]))


def cases(sizes: tuple[int, ...] = DEFAULT_SIZES) -> list[tuple[str, int, Callable[[], list[Any]]]]:
    """``(family, size, make_edges)`` for every benchmark case."""
    families: dict[str, Callable[[int], list[Any]]] = {"glyphs": _glyphs, "fillets": _fillets, "step": _step}
    return [(name, n, partial(f, n)) for name, f in families.items() for n in sizes]


# --------------------------------------------------------------------------- the two sides
def _general_fuse(edges: list[Any]) -> Any:
    from OCP.BOPAlgo import BOPAlgo_Builder

    builder = BOPAlgo_Builder()
    for e in edges:
        builder.AddArgument(e)
    builder.Perform()
    return builder.Shape()


def _counts(shape: Any) -> tuple[int, int]:
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_VERTEX
    from OCP.TopExp import TopExp

    from relief_cad.cad._compat import IndexedMapOfShape

    out = []
    for kind in (TopAbs_EDGE, TopAbs_VERTEX):
        m = IndexedMapOfShape()
        TopExp.MapShapes_s(shape, kind, m)
        out.append(m.Extent())
    return out[0], out[1]


def _vertex_points(shape: Any) -> np.ndarray:
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_VERTEX
    from OCP.TopExp import TopExp

    from relief_cad.cad._compat import IndexedMapOfShape, downcast_vertex

    m = IndexedMapOfShape()
    TopExp.MapShapes_s(shape, TopAbs_VERTEX, m)
    pts = [BRep_Tool.Pnt_s(downcast_vertex(m.FindKey(i))).Coord() for i in range(1, m.Extent() + 1)]
    return np.array(pts, dtype=np.float64).reshape(-1, 3)


def _connected(pieces: list[Any]) -> bool:
    """No two distinct vertices of the result at one point: pieces meeting there share one vertex."""
    from relief_cad.broadphase import cluster_points
    from relief_cad.cad import ocp

    pts = _vertex_points(ocp.make_compound(pieces))
    labels = cluster_points(pts, 1e-9)
    return bool(np.unique(labels).shape[0] == pts.shape[0])  # no two distinct vertices at one point


def _only_one_side(p_relief: np.ndarray, p_occt: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray]:
    from relief_cad.broadphase import cluster_points

    pts = np.vstack([p_relief, p_occt])
    labels = cluster_points(pts, tol)
    r_labels, o_labels = set(labels[: len(p_relief)].tolist()), set(labels[len(p_relief):].tolist())
    only_r = [i for i, lab in enumerate(labels[: len(p_relief)].tolist()) if lab not in o_labels]
    only_o = [i for i, lab in enumerate(labels[len(p_relief):].tolist()) if lab not in r_labels]
    return p_relief[only_r], p_occt[only_o]


def _verdict(edges: list[Any], only_r: np.ndarray, only_o: np.ndarray, tol: float, limit: int = 12) -> str:
    """Judge the vertices found by one side only with the 50-digit arbiter: ``limit`` of each side at most.

    Past ``limit`` (each judgment takes about a second), the judged ones are spread evenly over
    that side's list (:func:`_spread`), not its first ones, which lie close together.

    A vertex is *real* when it is an end of an input edge, or when two input edges near it
    (or one edge with itself) meet there: :func:`relief_cad.cad.arbitrate_point`, started
    from the point's projections, finds a contact within ``tol`` whose point lies within
    ``tol`` of the vertex. A real vertex that the other side lacks means the other side
    merged two distinct points (or missed one); an unreal one is the claimant's error.
    """
    if len(only_r) == 0 and len(only_o) == 0:
        return "same"
    boxes = _edge_boxes(edges)
    tally = {"relief-only real": 0, "relief-only wrong": 0, "occt-only real": 0, "occt-only wrong": 0}
    for side, points in (("relief", _spread(only_r, limit)), ("occt", _spread(only_o, limit))):
        for p in points:
            tally[f"{side}-only {'real' if _real_vertex(edges, boxes, p, tol) else 'wrong'}"] += 1
    judged = ", ".join(f"{k}: {v}" for k, v in tally.items() if v)
    return f"{judged} (of {len(only_r)}+{len(only_o)} one-sided vertices)"


def _spread(points: np.ndarray, limit: int) -> np.ndarray:
    """At most ``limit`` rows of ``points``, evenly spaced over them (all of them when they are few).

    >>> _spread(np.arange(10.0).reshape(-1, 1), 4)[:, 0].tolist()
    [0.0, 3.0, 6.0, 9.0]
    """
    if len(points) <= limit:
        return points
    out: np.ndarray = points[np.unique(np.linspace(0, len(points) - 1, limit).round().astype(int))]
    return out


def _edge_boxes(edges: list[Any]) -> tuple[np.ndarray, np.ndarray]:
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    corners = []
    for e in edges:
        box = Bnd_Box()
        BRepBndLib.Add_s(e, box)
        corners.append(box_corners(box))
    c = np.array(corners, dtype=np.float64).reshape(-1, 6)
    return c[:, :3], c[:, 3:]


def _real_vertex(edges: list[Any], boxes: tuple[np.ndarray, np.ndarray], p: np.ndarray, tol: float) -> bool:
    from OCP.BRep import BRep_Tool
    from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
    from OCP.gp import gp_Pnt

    from relief_cad.broadphase import box_pairs_between
    from relief_cad.cad import arbitrate_point

    near = [edges[j] for _, j in box_pairs_between([p], [p], *boxes, pad=tol).tolist()]
    params: list[tuple[Any, float]] = []
    for e in near:
        t0, t1 = BRep_Tool.Range_s(e)
        ends = [np.array(BRep_Tool.Pnt_s(v).Coord()) for v in _end_vertices(e)]
        if any(np.linalg.norm(q - p) <= tol for q in ends):
            return True
        proj = GeomAPI_ProjectPointOnCurve(gp_Pnt(*p.tolist()), BRep_Tool.Curve_s(e, 0.0, 0.0), t0, t1)
        params.extend((e, proj.Parameter(k)) for k in range(1, proj.NbPoints() + 1))
    for i, (ea, t) in enumerate(params):
        for eb, u in params[i + 1:]:
            check = arbitrate_point(ea, eb, t, u, tol=tol)
            if check.holds and np.linalg.norm(_point(ea, check.t) - p) <= tol:
                return True
    return False


def _end_vertices(edge: Any) -> list[Any]:
    from OCP.TopExp import TopExp

    return [v for v in (TopExp.FirstVertex_s(edge), TopExp.LastVertex_s(edge)) if not v.IsNull()]


def _point(edge: Any, t: float) -> np.ndarray:
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    return np.array(BRepAdaptor_Curve(edge).Value(float(t)).Coord())


def _best(f: Callable[[], Any], repeat: int) -> tuple[Any, float]:
    best = math.inf
    out = None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f()
        best = min(best, time.perf_counter() - t0)
    return out, best


def _ocp_floor(edges: list[Any], n_edges: int, n_vertices: int, repeat: int) -> float:
    """Seconds of the OCP calls any ``arrange`` returning OCCT edges makes, at the least (best of ``repeat``).

    Those of :func:`_floor_calls`; ``occt_s / floor_s`` bounds the speedup any arrangement built
    through OCP can reach on the case.
    """
    return _best(_floor_calls(edges, n_edges, n_vertices), repeat)[1]


def _floor_calls(edges: list[Any], n_edges: int,
                 n_vertices: int) -> Callable[[], tuple[list[Any], list[Any]]]:
    """The least OCP work of an arrangement with ``n_edges`` edges and ``n_vertices`` vertices, as a call.

    The call reads each input edge's curve and range (``BRep_Tool``), then makes ``n_vertices``
    vertices and ``n_edges`` edges on the input curves, each between two of those vertices, the
    cheapest way (``BRep_Builder``: ``MakeVertex``; ``MakeEdge``, ``Range`` and two ``Add``), and
    returns ``(vertices, edges)``. The points and parameters are found before: no intersection,
    no checks.
    """
    from OCP.BRep import BRep_Builder, BRep_Tool
    from OCP.gp import gp_Pnt
    from OCP.TopAbs import TopAbs_FORWARD, TopAbs_REVERSED
    from OCP.TopLoc import TopLoc_Location
    from OCP.TopoDS import TopoDS_Edge, TopoDS_Vertex

    per = -(-n_edges // len(edges))  # pieces cut from each input edge, evenly in its parameter
    spans = []
    for e in edges:
        curve = BRep_Tool.Curve_s(e, TopLoc_Location(), 0.0, 0.0)
        a, b = BRep_Tool.Range_s(e)
        spans += [(curve, a + (b - a) * k / per, a + (b - a) * (k + 1) / per) for k in range(per)]
    spans = spans[:n_edges]
    points = [spans[k % n_edges][0].Value(spans[k % n_edges][1]).Coord() for k in range(n_vertices)]
    builder = BRep_Builder()

    def calls() -> tuple[list[Any], list[Any]]:
        for e in edges:
            BRep_Tool.Curve_s(e, TopLoc_Location(), 0.0, 0.0)
            BRep_Tool.Range_s(e)
        vertices = [TopoDS_Vertex() for _ in points]
        for v, p in zip(vertices, points, strict=True):
            builder.MakeVertex(v, gp_Pnt(*p), 1e-7)
        made = []
        for k, (curve, t0, t1) in enumerate(spans):
            e = TopoDS_Edge()
            builder.MakeEdge(e, curve, 1e-7)
            builder.Range(e, t0, t1)
            builder.Add(e, vertices[k % n_vertices].Oriented(TopAbs_FORWARD))
            builder.Add(e, vertices[(k + 1) % n_vertices].Oriented(TopAbs_REVERSED))
            made.append(e)
        return vertices, made

    return calls


def _case(name: str, n: int, make: Callable[[], list[Any]]) -> dict[str, Any]:
    from OCP.BRepCheck import BRepCheck_Analyzer

    from relief_cad.cad import ocp
    from relief_cad.cad.arrangement import arrange

    edges = make()
    repeat = 3 if len(edges) <= 1000 else 1
    pieces, relief_s = _best(lambda: arrange(edges), repeat)
    fused, occt_s = _best(lambda: _general_fuse(edges), 1 if len(edges) > 500 else 2)
    comp = ocp.make_compound(pieces)
    r_edges, r_vertices = _counts(comp)
    o_edges, o_vertices = _counts(fused)
    tol = 1e-7
    row: dict[str, Any] = {
        "family": name, "edges": len(edges), "relief_s": relief_s, "occt_s": occt_s,
        "speedup": occt_s / relief_s, "relief_E": r_edges, "occt_E": o_edges,
        "relief_V": r_vertices, "occt_V": o_vertices,
        "valid": bool(BRepCheck_Analyzer(comp).IsValid()), "connected": _connected(pieces),
    }
    row["ocp_floor_s"] = _ocp_floor(edges, o_edges, o_vertices, repeat)
    row["speedup_bound"] = occt_s / row["ocp_floor_s"]  # the most any arrange through OCP can reach
    if (r_edges, r_vertices) == (o_edges, o_vertices):
        row["verdict"] = "same"
    else:
        only_r, only_o = _only_one_side(_vertex_points(comp), _vertex_points(fused), tol)
        row["verdict"] = _verdict(edges, only_r, only_o, tol)
    return row


def _growth(rows: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for family in dict.fromkeys(r["family"] for r in rows):
        rs = [r for r in rows if r["family"] == family]
        for a, b in zip(rs, rs[1:], strict=False):
            scale = math.log(b["edges"] / a["edges"])
            out.append({
                "family": family, "from": a["edges"], "to": b["edges"],
                "relief_exponent": math.log(b["relief_s"] / a["relief_s"]) / scale,
                "occt_exponent": math.log(b["occt_s"] / a["occt_s"]) / scale,
            })
    return out


def _sizes() -> tuple[int, ...]:
    env = os.environ.get("RELIEF_BENCH_ARRANGE_SIZES")
    if not env:
        return DEFAULT_SIZES
    return tuple(int(s) for s in env.split(",") if s.strip())


def run() -> dict[str, Any]:
    """Run every case: ``{"rows": [...], "growth": [...], "worst_speedup": x, "median_speedup": y}``."""
    from relief_cad.cad.arrangement import arrange

    arrange(_fillets(20) + _glyphs(60))  # warm up: compiled kernels (self-intersections too), OCCT, fonts
    rows = []
    for name, n, make in cases(_sizes()):
        try:
            rows.append(_case(name, n, make))
        except Exception as exc:  # noqa: BLE001 - a failing case is reported, the others still run
            rows.append({"family": name, "edges": n, "error": f"{type(exc).__name__}: {exc}"})
    timed = [r for r in rows if "speedup" in r]
    speedups = sorted(r["speedup"] for r in timed)
    return {
        "rows": rows,
        "growth": _growth(timed),
        "worst_speedup": speedups[0] if speedups else None,
        "median_speedup": speedups[len(speedups) // 2] if speedups else None,
    }


if __name__ == "__main__":
    from .bench import format_result

    print(format_result(run()))

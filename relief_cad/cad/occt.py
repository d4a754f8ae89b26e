"""OpenCASCADE's own answer to an edge/edge intersection, in relief_cad's rich result types.

:func:`occt_intersections` takes the same inputs as :func:`relief_cad.cad.intersections`
(edges, wires, faces or any shapes of build123d, CadQuery or raw OCP) and returns what
OCCT finds on the same edges, as :class:`~relief_cad.cad.results.EdgeIntersection` and
:class:`~relief_cad.cad.results.EdgeOverlap` objects whose ``route`` names the OCCT
algorithm that answered:

``"Geom2dInt_GInter"``
    Both edges lie in one plane (checked on the poles of their exact B-spline form, within
    ``tol``). The 3D curves are mapped exactly into the plane's 2D frame
    (``GeomAPI.To2d``, which keeps the parameterisation) and intersected by
    ``Geom2dInt_GInter`` with ``SetMinNbSamples`` raised to twice the number of poles
    (at least OCCT's default, at most 400): points with their transition (``Touch`` ->
    ``"tangent"``), and segments (overlaps).
``"IntTools_EdgeEdge"``
    Space edges (not coplanar): the common parts of ``IntTools_EdgeEdge`` with
    ``SetFuzzyValue(tol)``: ``VERTEX`` parts are points, ``EDGE`` parts overlaps.
``"BRepAlgoAPI_Section"``
    Where the two routes above are known to fail: space edges that share a topological
    vertex or whose ends meet within ``tol`` (``IntTools_EdgeEdge`` misses such end
    contacts), a failed
    ``IntTools_EdgeEdge``, or a curve type ``GeomAPI.To2d`` cannot map. The section's
    vertices and edges are projected back onto both edges for their parameters
    (``GeomAPI_ProjectPointOnCurve``); point kinds come from the tangents there.

Parameters are the edges' own OCCT parameters (those of ``BRep_Tool.Curve``, which the
edge's location does not change: the routes work on located copies of the same curves).
The edge orientation does not change them either.

For ``b=None`` the self-intersections of ``a``'s edges are reported (every pair of
distinct edges, and each edge with itself), without the shared vertices that join
consecutive edges, as :func:`relief_cad.cad.intersections` does.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
>>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
>>> [(r.route, round(r.t, 6), round(r.u, 6), r.kind) for r in occt_intersections(a, b)]
[('Geom2dInt_GInter', 1.414214, 1.414214, 'crossing')]
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np

from ..errors import InvalidInputError, OcctError, ShapeError
from ._checks import check_model_tol, check_tol
from ._compat import ListOfShape, downcast_edge, downcast_vertex
from .curvetypes import basis_curve, curve_kind
from .flavour import flavour_of, wrap_edge
from .ocp import edge_with_3d_curve
from .results import EdgeIntersection, EdgeOverlap, EdgeResult
from .topology import edges_of, usable_edges

__all__ = [
    "ROUTES",
    "occt_intersections",
    "edge_plane",
    "unique_edges",
    "default_occt_tolerance",
]

ROUTES = ("auto", "Geom2dInt_GInter", "IntTools_EdgeEdge", "BRepAlgoAPI_Section")
"""Route names accepted by :func:`occt_intersections` (``"auto"`` chooses as documented)."""

RouteName = Literal["auto", "Geom2dInt_GInter", "IntTools_EdgeEdge", "BRepAlgoAPI_Section"]

_TANGENT_SINE = 1e-7
"""Sine of the angle between tangents below which a Section point is called tangent."""


# --------------------------------------------------------------------------- shapes in


unique_edges = edges_of
"""The unique edges of a shape: :func:`relief_cad.cad.topology.edges_of` (the same list, by construction)."""


def default_occt_tolerance(*edges: Any) -> float:
    """Return the default tolerance: the largest ``BRep_Tool.Tolerance`` of the edges.

    Parameters
    ----------
    *edges : TopoDS_Edge
        The edges taking part.

    Returns
    -------
    float
        The tolerance in model units (``1e-7`` for freshly made edges).

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> default_occt_tolerance(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge())
    1e-07
    """
    from OCP.BRep import BRep_Tool

    return float(max([BRep_Tool.Tolerance_s(e) for e in edges] + [1e-7]))


# --------------------------------------------------------------------------- geometry helpers


@dataclass
class _EdgeData:
    edge: Any  # TopoDS_Edge
    curve: Any  # located Geom_Curve (a copy when the edge has a location)
    first: float
    last: float
    poles: np.ndarray  # (m, 3) poles of the exact B-spline form, located


def _fast_hull(curve: Any, first: float, last: float) -> np.ndarray | None:
    """Points whose hull holds the curve and whose plane is the curve's, without conversion.

    Lines: the two ends; circles and ellipses: the corners of the axis-aligned square/rectangle
    around them in their plane; Bézier and B-spline curves: their poles (of the whole curve, a
    superset for a trimmed edge). ``None`` for other types (converted by OCCT instead).
    """
    def xyz(p: Any) -> list[float]:
        return [p.X(), p.Y(), p.Z()]

    kind, curve = curve_kind(curve), basis_curve(curve)
    if kind == "line":
        return np.array([xyz(curve.Value(first)), xyz(curve.Value(last))])
    if kind in ("bezier", "bspline"):
        return np.array([xyz(curve.Pole(i)) for i in range(1, curve.NbPoles() + 1)])
    if kind in ("circle", "ellipse"):
        ax = curve.Position()
        c = np.array(xyz(ax.Location()))
        x, y = np.array(xyz(ax.XDirection())), np.array(xyz(ax.YDirection()))
        ra = curve.Radius() if kind == "circle" else curve.MajorRadius()
        rb = curve.Radius() if kind == "circle" else curve.MinorRadius()
        return np.array([c + sx * ra * x + sy * rb * y for sx in (-1, 1) for sy in (-1, 1)])
    return None


def _edge_data(edge: Any) -> _EdgeData:
    from OCP.BRep import BRep_Tool
    from OCP.Geom import Geom_TrimmedCurve
    from OCP.GeomConvert import GeomConvert

    edge = edge_with_3d_curve(edge)  # an edge known only on surfaces gets OCCT's approximated 3D curve
    curve = BRep_Tool.Curve_s(edge, 0.0, 0.0)
    first, last = BRep_Tool.Range_s(edge)
    if not (math.isfinite(first) and math.isfinite(last)) or last <= first:
        raise ShapeError(f"expected a bounded edge parameter range, received ({first}, {last})")
    try:
        poles = _fast_hull(curve, first, last)
        if poles is None:
            bs = GeomConvert.CurveToBSplineCurve_s(Geom_TrimmedCurve(curve, first, last))
            pts = (bs.Pole(i) for i in range(1, bs.NbPoles() + 1))
            poles = np.array([[p.X(), p.Y(), p.Z()] for p in pts])
    except Exception:  # noqa: BLE001 - offset and other curves: sample instead
        ts = np.linspace(first, last, 65)
        poles = np.array([[p.X(), p.Y(), p.Z()] for p in (curve.Value(float(t)) for t in ts)])
    return _EdgeData(edge, curve, first, last, poles)


def edge_plane(points: np.ndarray, tol: float) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """Return ``(origin, x_dir, normal)`` of a plane holding all ``points`` within ``tol``, else None.

    Parameters
    ----------
    points : ndarray, shape (m, 3)
        Points (poles of the edges' exact B-spline forms).
    tol : float
        Largest allowed distance from the plane.

    Returns
    -------
    tuple of ndarray or None
        Origin, unit x direction and unit normal of the plane; ``None`` when the points
        are not coplanar. Collinear or coincident points get a plane through them.

    Examples
    --------
    >>> o, x, n = edge_plane(np.array([[0, 0, 1.0], [1, 0, 1], [0, 1, 1]]), 1e-9)
    >>> np.round(np.abs(n), 12).tolist()
    [0.0, 0.0, 1.0]
    >>> edge_plane(np.array([[0, 0, 0.0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]), 1e-9) is None
    True
    """
    pts = np.asarray(points, dtype=np.float64)
    origin = pts.mean(axis=0)
    centred = pts - origin
    padded = np.vstack([centred, np.zeros((max(0, 3 - centred.shape[0]), 3))])
    _, s, vt = np.linalg.svd(padded, full_matrices=False)  # thin: the full SVD is N x N
    normal = vt[2]
    if float(np.max(np.abs(centred @ normal))) > tol:
        return None
    x_dir = vt[0]
    scale = float(s[0]) if s.size else 0.0
    if scale <= tol or (s.size > 1 and float(s[1]) <= 1e-12 * scale):
        # collinear points: prefer the global plane that contains the line (z = const first)
        for cand in (np.array([0.0, 0.0, 1.0]), np.array([0.0, 1.0, 0.0]), np.array([1.0, 0.0, 0.0])):
            if scale <= tol or abs(float(cand @ x_dir)) < 0.9:
                normal = cand - (cand @ x_dir) * x_dir if scale > tol else cand
                normal /= np.linalg.norm(normal)
                x_dir = np.cross(normal, np.array([0.0, 0.0, 1.0]) if abs(normal[2]) < 0.9 else [1.0, 0, 0])
                x_dir = np.cross(x_dir, normal)
                x_dir /= np.linalg.norm(x_dir)
                break
    # orient the frame canonically (z-up plane keeps the global x axis when possible)
    if normal[2] < 0 or (normal[2] == 0 and normal[1] < 0):
        normal = -normal
    if abs(normal[2]) > 1 - 1e-12:
        x_dir = np.array([1.0, 0.0, 0.0])
    return origin, x_dir / np.linalg.norm(x_dir), normal / np.linalg.norm(normal)


def _to2d(data: _EdgeData, plane: Any) -> Any:
    """Map the edge's 3D curve into the plane's 2D frame, same parameters; None if impossible."""
    from OCP.Geom import Geom_TrimmedCurve
    from OCP.GeomAPI import GeomAPI

    curve = data.curve
    while isinstance(curve, Geom_TrimmedCurve):
        curve = curve.BasisCurve()
    try:
        return GeomAPI.To2d_s(curve, plane)
    except Exception:  # noqa: BLE001 - offset curves etc.
        return None


def _pnt(p: Any) -> tuple[float, float, float]:
    return (float(p.X()), float(p.Y()), float(p.Z()))


def _project_param(data: _EdgeData, point: Any) -> float:
    """Edge parameter of the point of the edge closest to ``point`` (a gp_Pnt)."""
    from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve

    proj = GeomAPI_ProjectPointOnCurve(point, data.curve, data.first, data.last)
    best_t, best_d = None, math.inf
    if proj.NbPoints() > 0:
        best_t, best_d = proj.LowerDistanceParameter(), proj.LowerDistance()
    for t in (data.first, data.last):  # the ends, which the projector may skip
        d = data.curve.Value(t).Distance(point)
        if d < best_d:
            best_t, best_d = t, d
    if best_t is None:  # pragma: no cover - the ends always give a candidate
        raise OcctError("GeomAPI_ProjectPointOnCurve found no parameter")
    return float(best_t)


def _tangent_sine(da: _EdgeData, t: float, db: _EdgeData, u: float) -> float:
    from OCP.gp import gp_Pnt, gp_Vec

    pa, va, pb, vb = gp_Pnt(), gp_Vec(), gp_Pnt(), gp_Vec()
    da.curve.D1(t, pa, va)
    db.curve.D1(u, pb, vb)
    na, nb = va.Magnitude(), vb.Magnitude()
    if na == 0.0 or nb == 0.0:
        return 0.0
    return float(va.Crossed(vb).Magnitude() / (na * nb))


# --------------------------------------------------------------------------- raw routes
# Each route returns a list of ("point", t, u, (x, y, z), kind) and ("overlap", (t0, t1), (u0, u1)).

_Raw = tuple[Any, ...]


def _min_samples(*datas: _EdgeData) -> int:
    n = max(len(d.poles) for d in datas)
    return int(min(400, max(20, 2 * n)))


def _route_ginter(da: _EdgeData, db: _EdgeData | None, plane: Any, tol: float) -> list[_Raw] | None:
    from OCP.Geom2dAdaptor import Geom2dAdaptor_Curve
    from OCP.Geom2dInt import Geom2dInt_GInter
    from OCP.IntRes2d import IntRes2d_TypeTrans

    ca = _to2d(da, plane)
    cb = _to2d(db, plane) if db is not None else None
    if ca is None or (db is not None and cb is None):
        return None
    aa = Geom2dAdaptor_Curve(ca, da.first, da.last)
    inter = Geom2dInt_GInter()
    inter.SetMinNbSamples(_min_samples(da) if db is None else _min_samples(da, db))
    if db is None:
        inter.Perform(aa, tol, tol)
    else:
        ab = Geom2dAdaptor_Curve(cb, db.first, db.last)
        inter.Perform(aa, ab, tol, tol)
    if not inter.IsDone():
        raise OcctError("Geom2dInt_GInter did not finish (IsDone() is False)")
    dbb = da if db is None else db
    out: list[_Raw] = []
    for i in range(1, inter.NbPoints() + 1):
        ip = inter.Point(i)
        t, u = float(ip.ParamOnFirst()), float(ip.ParamOnSecond())
        touch = ip.TransitionOfFirst().TransitionType() == IntRes2d_TypeTrans.IntRes2d_Touch
        pa, pb = da.curve.Value(t), dbb.curve.Value(u)
        mid = ((pa.X() + pb.X()) / 2, (pa.Y() + pb.Y()) / 2, (pa.Z() + pb.Z()) / 2)
        out.append(("point", t, u, mid, "tangent" if touch else "crossing", pa.Distance(pb)))
    for i in range(1, inter.NbSegments() + 1):
        seg = inter.Segment(i)
        if not (seg.HasFirstPoint() and seg.HasLastPoint()):
            raise OcctError("Geom2dInt_GInter returned an unbounded segment on bounded edges")
        p0, p1 = seg.FirstPoint(), seg.LastPoint()
        t0, u0, t1, u1 = p0.ParamOnFirst(), p0.ParamOnSecond(), p1.ParamOnFirst(), p1.ParamOnSecond()
        out.append(("overlap", (float(t0), float(t1)), (float(u0), float(u1))))
    return out


def _route_edgeedge(da: _EdgeData, db: _EdgeData, tol: float) -> list[_Raw] | None:
    from OCP.IntTools import IntTools_EdgeEdge
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_VERTEX

    ee = IntTools_EdgeEdge(da.edge, db.edge)
    ee.SetFuzzyValue(tol)
    try:
        ee.Perform()
    except Exception:  # noqa: BLE001 - OCCT Standard_Failure
        return None
    if not ee.IsDone():
        return None
    out: list[_Raw] = []
    parts = ee.CommonParts()
    for i in range(1, parts.Length() + 1):
        cp = parts.Value(i)
        if cp.Type() == TopAbs_VERTEX:
            t, u = float(cp.VertexParameter1()), float(cp.VertexParameter2())
            pa, pb = da.curve.Value(t), db.curve.Value(u)
            mid = ((pa.X() + pb.X()) / 2, (pa.Y() + pb.Y()) / 2, (pa.Z() + pb.Z()) / 2)
            kind = "tangent" if _tangent_sine(da, t, db, u) < _TANGENT_SINE else "crossing"
            out.append(("point", t, u, mid, kind, pa.Distance(pb)))
        elif cp.Type() == TopAbs_EDGE:
            t0, t1 = _bounds(cp.Range1())
            ranges2 = cp.Ranges2()
            for j in range(1, ranges2.Length() + 1):
                r2 = ranges2.Value(j)
                u0 = _project_param(db, da.curve.Value(t0))
                u1 = _project_param(db, da.curve.Value(t1))
                lo, hi = sorted(_bounds(r2))
                u0, u1 = min(max(u0, lo), hi), min(max(u1, lo), hi)
                out.append(("overlap", (t0, t1), (u0, u1)))
    return out


def _bounds(r: Any) -> tuple[float, float]:
    """``(first, last)`` of an ``IntTools_Range``, or of the tuple OCP gives for one.

    ``IntTools_CommonPrt.Range1`` has two overloads in OCP 7.9 and 8.0, and the one taken returns
    a ``(first, last)`` tuple; the elements of ``Ranges2`` are ``IntTools_Range`` objects.
    """
    if isinstance(r, tuple):
        return float(r[0]), float(r[1])
    return float(r.First()), float(r.Last())


def _route_section(da: _EdgeData, db: _EdgeData, tol: float) -> list[_Raw]:
    from OCP.BRep import BRep_Tool
    from OCP.BRepAlgoAPI import BRepAlgoAPI_Section
    from OCP.TopAbs import TopAbs_EDGE, TopAbs_VERTEX
    from OCP.TopExp import TopExp_Explorer

    section = BRepAlgoAPI_Section()
    args, tools = ListOfShape(), ListOfShape()
    args.Append(da.edge)
    tools.Append(db.edge)
    section.SetArguments(args)
    section.SetTools(tools)
    section.SetFuzzyValue(tol)
    section.Build()
    if not section.IsDone():
        raise OcctError("BRepAlgoAPI_Section failed (IsDone() is False)")
    result = section.Shape()
    out: list[_Raw] = []
    covered: list[tuple[float, float]] = []
    ex = TopExp_Explorer(result, TopAbs_EDGE)
    while ex.More():
        e = downcast_edge(ex.Current())
        f, l_ = BRep_Tool.Range_s(e)
        c = BRep_Tool.Curve_s(e, 0.0, 0.0)
        p0, p1 = c.Value(f), c.Value(l_)
        t0, t1 = _project_param(da, p0), _project_param(da, p1)
        u0, u1 = _project_param(db, p0), _project_param(db, p1)
        if t1 < t0:
            t0, t1, u0, u1 = t1, t0, u1, u0
        covered.append((t0, t1))
        out.append(("overlap", (t0, t1), (u0, u1)))
        ex.Next()
    ex = TopExp_Explorer(result, TopAbs_VERTEX, TopAbs_EDGE)
    while ex.More():
        v = downcast_vertex(ex.Current())
        p = BRep_Tool.Pnt_s(v)
        t, u = _project_param(da, p), _project_param(db, p)
        if not any(lo - 1e-12 <= t <= hi + 1e-12 for lo, hi in covered):
            pa, pb = da.curve.Value(t), db.curve.Value(u)
            kind = "tangent" if _tangent_sine(da, t, db, u) < _TANGENT_SINE else "crossing"
            out.append(("point", t, u, _pnt(p), kind, pa.Distance(pb)))
        ex.Next()
    return out


def _shares_vertex(ea: Any, eb: Any) -> bool:
    from OCP.TopExp import TopExp
    from OCP.TopoDS import TopoDS_Vertex

    return bool(TopExp.CommonVertex_s(ea, eb, TopoDS_Vertex()))


def _ends_meet(da: _EdgeData, db: _EdgeData, tol: float) -> bool:
    """True when an end of one edge lies within ``tol`` of an end of the other."""
    ends_a = [da.curve.Value(da.first), da.curve.Value(da.last)]
    ends_b = [db.curve.Value(db.first), db.curve.Value(db.last)]
    return any(p.Distance(q) <= tol for p in ends_a for q in ends_b)


def _shared_vertex_points(ea: Any, eb: Any) -> list[tuple[float, float, float]]:
    from OCP.BRep import BRep_Tool
    from OCP.TopAbs import TopAbs_VERTEX
    from OCP.TopExp import TopExp_Explorer

    def verts(e: Any) -> list[Any]:
        ex = TopExp_Explorer(e, TopAbs_VERTEX)
        vs = []
        while ex.More():
            vs.append(downcast_vertex(ex.Current()))
            ex.Next()
        return vs

    vb = verts(eb)
    return [_pnt(BRep_Tool.Pnt_s(v)) for v in verts(ea) if any(v.IsSame(w) for w in vb)]


def _pair(
    da: _EdgeData, db: _EdgeData | None, tol: float, route: RouteName
) -> tuple[str, list[_Raw]]:
    """Run one edge pair (or one edge with itself) through the chosen OCCT route."""
    from OCP.gp import gp_Ax3, gp_Dir, gp_Pln, gp_Pnt

    pts = da.poles if db is None else np.vstack([da.poles, db.poles])
    plane_data = edge_plane(pts, tol) if route in ("auto", "Geom2dInt_GInter") else None
    if route == "Geom2dInt_GInter" and plane_data is None:
        raise InvalidInputError("expected coplanar edges for route 'Geom2dInt_GInter', received space edges")
    if plane_data is not None:
        o, x, n = plane_data
        plane = gp_Pln(gp_Ax3(gp_Pnt(*o), gp_Dir(*n), gp_Dir(*x)))
        raw = _route_ginter(da, db, plane, tol)
        if raw is not None:
            return "Geom2dInt_GInter", raw
        if route == "Geom2dInt_GInter":
            raise OcctError("GeomAPI.To2d cannot map this curve type into the plane")
    if db is None:
        # a single space edge: its two halves through IntTools_EdgeEdge
        return _self_space(da, tol)
    if route == "BRepAlgoAPI_Section" or (
        route == "auto" and (_shares_vertex(da.edge, db.edge) or _ends_meet(da, db, tol))
    ):
        return "BRepAlgoAPI_Section", _route_section(da, db, tol)
    raw = _route_edgeedge(da, db, tol)
    if raw is None:
        if route == "IntTools_EdgeEdge":
            raise OcctError("IntTools_EdgeEdge failed on this pair")
        return "BRepAlgoAPI_Section", _route_section(da, db, tol)
    return "IntTools_EdgeEdge", raw


def _self_space(da: _EdgeData, tol: float) -> tuple[str, list[_Raw]]:
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge

    mid = 0.5 * (da.first + da.last)
    h1 = _edge_data(BRepBuilderAPI_MakeEdge(da.curve, da.first, mid).Edge())
    h2 = _edge_data(BRepBuilderAPI_MakeEdge(da.curve, mid, da.last).Edge())
    raw = _route_edgeedge(h1, h2, tol) or []
    ptol = 1e-9 * max(1.0, abs(da.last - da.first))
    return "IntTools_EdgeEdge", [
        r for r in raw if not (r[0] == "point" and abs(r[1] - mid) <= ptol and abs(r[2] - mid) <= ptol)
    ]


# --------------------------------------------------------------------------- public entry


def _bbox(data: _EdgeData, tol: float) -> tuple[np.ndarray, np.ndarray]:
    return data.poles.min(axis=0) - tol, data.poles.max(axis=0) + tol


def occt_intersections(
    a: Any,
    b: Any = None,
    *,
    tol: float | None = None,
    route: RouteName = "auto",
) -> list[EdgeResult]:
    """Return OCCT's own intersections of the edges of ``a`` and ``b`` (or of ``a`` with itself).

    Parameters
    ----------
    a : TopoDS_Shape, build123d Shape or CadQuery Shape
        Edges, wires, faces or any shapes; their unique edges take part.
    b : same types, optional
        The second shape; ``None`` for the self-intersections of ``a``'s edges.
    tol : float, optional
        Distance tolerance in model units; default: the largest ``BRep_Tool.Tolerance``
        of the edges (see :func:`default_occt_tolerance`).
    route : {"auto", "Geom2dInt_GInter", "IntTools_EdgeEdge", "BRepAlgoAPI_Section"}
        Force one route (``"auto"``: as described in the module docstring).

    Returns
    -------
    list of EdgeIntersection and EdgeOverlap
        Sorted by ``(index_a, index_b, t)``; ``route`` of every result names the OCCT
        algorithm that answered. Edges are returned in the input's flavour.

    Raises
    ------
    InputTypeError
        Not a shape.
    ShapeError
        A shape with no edges, or an edge without a bounded 3D curve.
    ToleranceError
        A non-positive or non-finite ``tol``.
    OcctError
        An OCCT algorithm failed on a forced route.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 1)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(1, 0, 0), gp_Pnt(0, 1, 1)).Edge()
    >>> [(r.route, round(r.point[2], 9)) for r in occt_intersections(a, b, route="IntTools_EdgeEdge")]
    [('IntTools_EdgeEdge', 0.5)]
    """
    if route not in ROUTES:
        raise InvalidInputError(f"expected route in {ROUTES}, received {route!r}")
    if tol is not None:
        check_tol(tol)  # the type and sign first, before the shapes are read
    flavour_a = flavour_of(a)
    indexed_a, _ = usable_edges(a, "a")  # degenerated edges skipped, unbounded ones refused
    if b is None:
        indexed_b, flavour_b = indexed_a, flavour_a
    else:
        flavour_b = flavour_of(b)
        indexed_b, _ = usable_edges(b, "b")
    tol = default_occt_tolerance(*(e for _, e in indexed_a), *(e for _, e in indexed_b)) if tol is None \
        else float(check_model_tol(tol, [e for _, e in indexed_a] + [e for _, e in indexed_b]))
    data_a = [_edge_data(e) for _, e in indexed_a]
    data_b = data_a if b is None else [_edge_data(e) for _, e in indexed_b]
    boxes_a = [_bbox(d, tol) for d in data_a]
    boxes_b = boxes_a if b is None else [_bbox(d, tol) for d in data_b]

    results: list[EdgeResult] = []
    for i, da in enumerate(data_a):
        for j, db in enumerate(data_b):
            if b is None and j < i:
                continue
            if b is None and i == j:
                name, raw = _pair(da, None, tol, route)
            else:
                (la, ha), (lb, hb) = boxes_a[i], boxes_b[j]
                if np.any(la > hb) or np.any(lb > ha):
                    continue
                name, raw = _pair(da, db, tol, route)
            skip = _shared_vertex_points(da.edge, db.edge) if b is None and i != j else []
            index_a, index_b = indexed_a[i][0], indexed_b[j][0]
            results.extend(
                _make_results(
                    raw, name, index_a, index_b, da, db, flavour_a, flavour_b, tol, skip,
                    self_edge=i == j and b is None,
                )
            )
    results.sort(key=lambda r: (r.index_a, r.index_b, r.t if isinstance(r, EdgeIntersection) else r.t[0]))
    return results


def _make_results(
    raw: Sequence[_Raw],
    name: str,
    i: int,
    j: int,
    da: _EdgeData,
    db: _EdgeData,
    flavour_a: str,
    flavour_b: str,
    tol: float,
    skip_points: Sequence[tuple[float, float, float]],
    *,
    self_edge: bool,
) -> list[EdgeResult]:
    na, nb = wrap_edge(da.edge, flavour_a), wrap_edge(db.edge, flavour_b)
    out: list[EdgeResult] = []
    seen: list[tuple[float, float, float]] = []
    ptol = 1e-9 * max(1.0, abs(da.last - da.first))
    spans = [sorted(r[1]) for r in raw if r[0] == "overlap"]
    for r in raw:
        if r[0] == "point":
            _, t, u, point, kind, dist = r
            if any(lo - ptol <= t <= hi + ptol for lo, hi in spans):
                continue  # GInter repeats a segment's ends as points
            if self_edge:
                if abs(t - u) <= 1e-9 * max(1.0, abs(da.last - da.first)):
                    continue
                if u < t:
                    t, u = u, t
            if any(math.dist(point, s) <= tol for s in skip_points):
                continue
            if any(math.dist(point, s) <= tol for s in seen):
                continue  # a shared vertex reported twice (once per end)
            seen.append(point)
            out.append(EdgeIntersection(i, j, na, nb, t, u, point, kind, float(dist), False, name))
        else:
            _, (t0, t1), (u0, u1) = r
            if t1 < t0:
                t0, t1, u0, u1 = t1, t0, u1, u0
            if self_edge and t0 == u0 and t1 == u1:
                continue
            common = _trimmed(da, t0, t1, flavour_a)
            out.append(EdgeOverlap(i, j, na, nb, (t0, t1), (u0, u1), common, "overlap", False, name))
    return out


def _trimmed(data: _EdgeData, t0: float, t1: float, flavour: str) -> Any:
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge

    try:
        edge = BRepBuilderAPI_MakeEdge(data.curve, t0, t1).Edge()
    except Exception:  # noqa: BLE001 - degenerate range
        return None
    return wrap_edge(edge, flavour)

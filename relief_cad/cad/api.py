"""Intersect CAD shapes: edges in, native vertices and rich results out.

The adapters convert; they do not compute. Every edge is converted exactly to
rational Bézier segments (:func:`relief_cad.cad.ocp.edge_segments`), segment
pairs whose boxes overlap go to the core intersector, and the answers are
mapped back to the edges' own OCCT parameters and to native geometry. Planar
pairs in the common frame go, all in one call, straight to the compiled batch
kernel that :func:`relief_cad.intersect_many` runs (same kernel, same
tolerance and budget, hence the same answers as :func:`relief_cad.intersect`,
without building a ``RationalBezier`` per segment); the others (space pairs,
a segment against itself) go through :func:`relief_cad.intersect`.

Inputs ``a`` and ``b`` may be edges, wires, faces, solids, compounds or lists of
them, as build123d shapes, CadQuery shapes / ``Workplane`` objects or raw
``TopoDS_Shape``; the results come back in the flavour of ``a``.

Planar or space: when the control points of every edge taking part lie in one
plane (within ``tol / 1000``), the segments are mapped into a 2D frame of that
plane (an exact isometry for planes parallel to XY, an orthonormal frame
otherwise; affine, so parameters are unchanged) and intersected by the planar
intersector; otherwise each pair is checked for a common plane and, failing
that, intersected in space.

Default tolerance (``tol=None``): the largest OCCT tolerance
(``BRep_Tool.Tolerance``) of the edges taking part, when that is meaningful,
i.e. at most ``1e-3`` of the diagonal of their joint bounding box; otherwise
:func:`relief_cad.tolerances.default_tolerance` of all their control points.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
>>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
>>> [(round(r.t, 12), r.point, r.kind) for r in intersections(a, b)]
[(1.414213562373, (1.0, 1.0, 0.0), 'crossing')]
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from OCP.BRep import BRep_Tool
from OCP.TopExp import TopExp

from .._kernels import KIND_CROSSING, KIND_TANGENT, KIND_UNRESOLVED
from .._kernels.bezier import affine_rows
from ..broadphase import _box_pairs, _box_pairs_between
from ..clipping import _batch_rows
from ..curves import RationalBezier
from ..errors import InvalidInputError
from ..intersection import DEFAULT_BUDGET
from ..pieces import _along_chord
from ..results import Intersection, Overlap
from ..tolerances import ModelTolerance, _floor_of_magnitude, default_tolerance
from . import ocp
from ._checks import check_model_tol, check_tol
from .flavour import flavour_of, wrap_edge, wrap_vertices
from .results import EdgeIntersection, EdgeOverlap, EdgeResultList
from .topology import usable_edges

__all__ = ["intersect", "intersections", "planar_curves", "segments"]

_PLANE_FRACTION = 1e-3  # control points within tol * this of a plane count as coplanar
_MEANINGFUL_FRACTION = 1e-3  # an OCCT tolerance above this fraction of the size is not used


def segments(edge: Any, *, approximate: bool = True) -> list[ocp.Segment]:
    """Convert an edge to rational Bézier segments with exact maps to its own parameter.

    Parameters
    ----------
    edge : build123d Edge, CadQuery Edge or TopoDS_Edge
        The edge (its location applied; its orientation does not change parameters).
    approximate : bool, keyword-only
        Allow OCCT approximation of curve types without an exact conversion
        (flagged ``approximate=True``); if False they raise ``UnsupportedCurveError``.

    Returns
    -------
    list of Segment
        See :class:`relief_cad.cad.ocp.Segment` (``curve``, ``t0``, ``t1``,
        ``edge_param(s)``, ``segment_param(t)``, ``approximate``).

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt
    >>> circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.0)).Edge()
    >>> [(s.curve.degree, round(s.t1, 6)) for s in segments(circle)]
    [(2, 1.570796), (2, 3.141593), (2, 4.712389), (2, 6.283185)]
    """
    return ocp.edge_segments(edge, approximate=approximate)


def planar_curves(
    segs: list[ocp.Segment], *, tol: float | None = None
) -> tuple[np.ndarray, list[RationalBezier]]:
    """Map space segments lying in one plane to planar curves (dim 2) in a frame of that plane.

    Parameters
    ----------
    segs : list of Segment
        Segments (of one or several edges), e.g. from :func:`segments`.
    tol : float, optional
        How far (model units) a control point may lie off the plane; default
        ``1e-3`` of :func:`relief_cad.tolerances.default_tolerance` of the points.

    Returns
    -------
    frame : ndarray, shape (2, 4)
        The affine isometry ``(x, y, z, 1) -> (u, v)`` used (see
        :func:`relief_cad.cad.ocp.planar_frame`): parameters and distances are kept,
        so ``edge_param`` of each segment applies to its planar curve unchanged.
    curves : list of RationalBezier
        One planar curve per segment.

    Raises
    ------
    InvalidInputError
        If the control points are not coplanar within ``tol``.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> edge = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 5), gp_Pnt(3, 4, 5)).Edge()
    >>> frame, [line] = planar_curves(segments(edge))
    >>> line.dim, line.control_points.tolist()
    (2, [[0.0, 0.0], [3.0, 4.0]])
    """
    pts = np.vstack([s.control_points for s in segs])
    limit = default_tolerance(pts) * _PLANE_FRACTION if tol is None else check_tol(tol)
    if float(pts[:, 2].max() - pts[:, 2].min()) <= limit:
        frame = _XY_FRAME
    else:
        found = ocp.planar_frame(pts, limit)
        if found is None:
            raise InvalidInputError(
                f"expected segments whose control points lie in one plane (within {limit:.3g}); they do not"
            )
        frame = found
    return frame.copy(), [_to_plane(s, frame) for s in segs]


# --------------------------------------------------------------------------- preparation
@dataclass
class _EdgeInfo:
    index: int
    edge: Any  # TopoDS_Edge
    segs: list[ocp.Segment]
    rows: list[list[list[float]]]  # every segment's homogeneous rows as Python floats
    lows: list[tuple[float, float, float]]  # lower corner of every segment's control-point box
    highs: list[tuple[float, float, float]]  # upper corners
    xy: list[list[float]]  # every segment's control points (x, y), back to back
    ws: list[float]  # and their weights
    lo: tuple[float, float, float]  # the edge's box
    hi: tuple[float, float, float]
    tolerance: float
    approximate: bool
    first: float
    last: float
    frame: np.ndarray | None = None  # the common 2D frame of all edges, when there is one
    _curves2d: dict[int, RationalBezier] | None = None
    _packed: _Packed | None = None  # see _planar_arrays
    _vertices: tuple[Any, Any] | None = None
    _marks: list[tuple[Any, tuple[float, float, float]]] | None = None
    _vertex_tols: list[float] | None = None
    _adaptor: Any = None  # BRepAdaptor_Curve, see adaptor
    _stalls: tuple[float, list[bool], list[tuple[float, float]]] | None = None  # see _stalls
    copy_of: int | None = None  # the index of an earlier edge of the same curve (see _mark_copies)

    @property
    def vertices(self) -> tuple[Any, Any]:
        """First and last ``TopoDS_Vertex`` of the edge (may be null), looked up on demand."""
        if self._vertices is None:
            self._vertices = (TopExp.FirstVertex_s(self.edge), TopExp.LastVertex_s(self.edge))
        return self._vertices

    @property
    def adaptor(self) -> Any:
        """The edge's ``BRepAdaptor_Curve`` (global coordinates), made on first use (``ocp.curve_*``)."""
        if self._adaptor is None:
            self._adaptor = ocp.edge_adaptor(self.edge)
        return self._adaptor

    @property
    def vertex_marks(self) -> list[tuple[Any, tuple[float, float, float]]]:
        """``(vertex, point)`` of the first and last vertex (null ones left out), on demand."""
        if self._marks is None:
            self._marks = [(v, BRep_Tool.Pnt_s(v).Coord()) for v in self.vertices if not v.IsNull()]
        return self._marks

    @property
    def vertex_tolerances(self) -> list[float]:
        """The tolerances of the vertices of :attr:`vertex_marks`, in their order, on demand.

        Apart from the points: a contact at a shared vertex is nearly always within the model
        tolerance of its point, and OCCT's ``BRep_Tool.Tolerance_s`` of a vertex costs more than
        the point.
        """
        if self._vertex_tols is None:
            self._vertex_tols = [BRep_Tool.Tolerance_s(v) for v, _ in self.vertex_marks]
        return self._vertex_tols


def _prepare(shape: Any, name: str) -> list[_EdgeInfo]:
    infos = []
    edges, _skipped = usable_edges(shape, name)  # degenerated edges skipped, unbounded ones refused
    for index, edge in edges:
        segs = ocp._bounded_segments(edge, *BRep_Tool.Range_s(edge))  # usable: checked once, above
        rows = [s.homogeneous.tolist() for s in segs]
        lows, highs, xy, ws = _boxes(segs, rows)
        if len(segs) == 1:
            lo, hi = lows[0], highs[0]
        else:
            lo = tuple(map(min, zip(*lows, strict=True)))  # type: ignore[assignment]
            hi = tuple(map(max, zip(*highs, strict=True)))  # type: ignore[assignment]
        infos.append(
            _EdgeInfo(
                index=index,
                edge=edge,
                segs=segs,
                rows=rows,
                lows=lows,
                highs=highs,
                xy=xy,
                ws=ws,
                lo=lo,
                hi=hi,
                tolerance=BRep_Tool.Tolerance_s(edge),
                approximate=segs[0].approximate,
                first=segs[0].t0,
                last=segs[-1].t1,
            )
        )
    return infos


_Point3 = tuple[float, float, float]


def _boxes(
    segs: list[ocp.Segment], rows: list[list[list[float]]],
) -> tuple[list[_Point3], list[_Point3], list[list[float]], list[float]]:
    """Corners of the segments' control-point boxes, and their points ``[x, y]`` and weights, packed.

    The ``[x, y]`` rows are the planar control points in the XY frame, as
    :func:`_curve2d` computes them (the same divisions). A few segments: Python
    floats (the arrays are tiny); many: one numpy pass over all of them.
    """
    if len(rows) <= 8:
        lows: list[_Point3] = []
        highs: list[_Point3] = []
        xy: list[list[float]] = []
        ws: list[float] = []
        for seg in rows:
            cart = [(x / w, y / w, z / w) for x, y, z, w in seg]
            xs, ys, zs = zip(*cart, strict=True)
            lows.append((min(xs), min(ys), min(zs)))
            highs.append((max(xs), max(ys), max(zs)))
            xy.extend([c[0], c[1]] for c in cart)
            ws.extend([r[3] for r in seg])
        return lows, highs, xy, ws
    h = np.concatenate([s.homogeneous for s in segs])
    points = h[:, :3] / h[:, 3:]
    starts = np.cumsum([0] + [len(r) for r in rows[:-1]])
    lows = [tuple(c) for c in np.minimum.reduceat(points, starts, axis=0).tolist()]
    highs = [tuple(c) for c in np.maximum.reduceat(points, starts, axis=0).tolist()]
    return lows, highs, points[:, :2].tolist(), h[:, 3].tolist()


def _all_points(infos: list[_EdgeInfo]) -> np.ndarray:
    return np.vstack([s.control_points for e in infos for s in e.segs])


def _joint_box(infos: list[_EdgeInfo]) -> tuple[_Point3, _Point3]:
    """The two corners of the joint bounding box of the edges' control points."""
    if len(infos) == 1:
        return infos[0].lo, infos[0].hi
    if len(infos) == 2:
        (a0, a1, a2), (b0, b1, b2) = infos[0].lo, infos[1].lo
        (c0, c1, c2), (d0, d1, d2) = infos[0].hi, infos[1].hi
        return ((min(a0, b0), min(a1, b1), min(a2, b2)), (max(c0, d0), max(c1, d1), max(c2, d2)))
    los = [e.lo for e in infos]
    his = [e.hi for e in infos]
    return (
        (min(p[0] for p in los), min(p[1] for p in los), min(p[2] for p in los)),
        (max(p[0] for p in his), max(p[1] for p in his), max(p[2] for p in his)),
    )


def _default_tol(infos: list[_EdgeInfo], box: tuple[_Point3, _Point3] | None = None) -> float:
    box = _joint_box(infos) if box is None else box
    size = math.dist(box[0], box[1])
    occt = max(e.tolerance for e in infos)
    if math.isfinite(occt) and 0.0 < occt <= _MEANINGFUL_FRACTION * size:
        return occt
    # the bounding box corners carry the size and the largest coordinate of all control points
    return default_tolerance(np.array(box))


def _common_frame(
    infos: list[_EdgeInfo], tol: float, box: tuple[_Point3, _Point3] | None = None
) -> np.ndarray | None:
    """A 2D frame of a plane holding every control point, or None (XY-parallel checked on boxes)."""
    box = _joint_box(infos) if box is None else box
    if box[1][2] - box[0][2] <= tol * _PLANE_FRACTION:
        return _XY_FRAME
    return ocp.planar_frame(_all_points(infos), tol * _PLANE_FRACTION)


_XY_FRAME = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]])


def _to_plane(segment: ocp.Segment, frame: np.ndarray) -> RationalBezier:
    h = segment.homogeneous
    if frame is _XY_FRAME:
        return ocp._make_curve(h[:, (0, 1, 3)])
    h2 = np.empty((h.shape[0], 3))
    affine_rows(h, frame, h2)  # the plane's (u, v) of the rows, the same bits on every machine
    h2[:, 2] = h[:, 3]
    return ocp._make_curve(h2)


def _set_plane(infos: list[_EdgeInfo], frame: np.ndarray | None) -> None:
    for e in infos:
        e.frame = frame
        e._curves2d = {}
        e._packed = None


def _curve2d(e: _EdgeInfo, i: int) -> RationalBezier:
    """Segment ``i`` of an edge in the common frame (built on first use)."""
    cache = e._curves2d
    if cache is None or e.frame is None:
        raise InvalidInputError("internal: no common frame set")  # pragma: no cover
    if i not in cache:
        cache[i] = _to_plane(e.segs[i], e.frame)
    return cache[i]


# --------------------------------------------------------------------------- the core loop
@dataclass
class _Raw:
    ea: _EdgeInfo
    eb: _EdgeInfo
    t: Any  # float or (t0, t1)
    u: Any
    point: tuple[float, float, float]
    kind: str
    distance: float


def _core() -> tuple[Any, Any]:
    """``relief_cad.intersect`` and, when the core offers it, the batched ``intersect_many``."""
    import relief_cad

    core: Any = getattr(relief_cad, "intersect", None)
    many: Any = getattr(relief_cad, "intersect_many", None)
    if core is None or many is None:  # pragma: no cover - the package exports both today
        from .. import intersection

        core = core or intersection.intersect
        many = many or getattr(intersection, "intersect_many", None)
    return core, many


@dataclass
class _Job:
    ea: _EdgeInfo
    eb: _EdgeInfo
    i: int
    j: int
    ca: RationalBezier | None  # None: a planar pair in the common frame (packed for the kernel)
    cb: RationalBezier | None  # None: self-intersection of one segment (or a packed planar pair)
    packed: bool = False


# one core result: (kind, t, u, t1, u1, distance); t1, u1 are the far ends of an overlap
_Found = tuple[str, float, float, float, float, float]


def _pair_jobs(
    ea: _EdgeInfo, eb: _EdgeInfo, same: bool, tol: float, planar: bool, all_edges: bool = False
) -> list[_Job]:
    """The segment pairs of one edge pair whose boxes (widened by ``tol``) overlap.

    ``all_edges``: the pair holds every edge taking part, so when there is no common
    plane (``planar`` False) the pair has none either (the same points were tested).
    """
    frame = None
    if not planar and not all_edges:
        frame = ocp.planar_frame(
            np.vstack([s.control_points for s in (ea.segs + ([] if same else eb.segs))]),
            tol * _PLANE_FRACTION,
        )
    jobs: list[_Job] = []
    if len(ea.lows) == 1 and len(eb.lows) == 1:
        candidates: Any = [(0, 0)]  # the edge boxes already overlap
    elif len(ea.lows) * len(eb.lows) <= 64:
        candidates = [
            (i, j)
            for i, (la, ha) in enumerate(zip(ea.lows, ea.highs, strict=True))
            for j, (lb, hb) in enumerate(zip(eb.lows, eb.highs, strict=True))
            if la[0] - tol <= hb[0] and lb[0] <= ha[0] + tol
            and la[1] - tol <= hb[1] and lb[1] <= ha[1] + tol
            and la[2] - tol <= hb[2] and lb[2] <= ha[2] + tol
        ]
    else:
        candidates = _box_pairs_between(ea.lows, ea.highs, eb.lows, eb.highs, pad=tol).tolist()
    still_a, still_b = _stalls(ea, tol)[0], _stalls(eb, tol)[0]
    for ii, jj in candidates:
        i, j = int(ii), int(jj)
        if (same and j < i) or (still_a[i] and still_b[j]):
            continue  # two spans that are each one point within tol: see _stalls
        if same and i == j and _no_self_job(ea, i, planar, tol):
            continue
        if planar and not (same and i == j):
            jobs.append(_Job(ea, eb, i, j, None, None, True))
            continue
        sa, sb = ea.segs[i], eb.segs[j]
        if planar:
            ca = _curve2d(ea, i)
            cb = _curve2d(eb, j)
        elif frame is not None:
            ca, cb = _to_plane(sa, frame), _to_plane(sb, frame)
        else:
            ca, cb = sa.curve, sb.curve
        jobs.append(_Job(ea, eb, i, j, ca, None if (same and i == j) else cb))
    return jobs


def _stalls(e: _EdgeInfo, tol: float) -> tuple[list[bool], list[tuple[float, float]]]:
    """Where edge ``e`` stands still within ``tol``: per segment, whether it is one point; the stalls.

    A segment is one point when the diagonal of its control points' box is at most ``tol`` (model
    units). A stall is a run of such consecutive segments whose joint box stays within ``tol``,
    as the edge parameters ``(first, last)`` it covers. B-splines have them where poles repeat
    (up to rounding): build123d's periodic ``make_spline`` through some point sets gives a curve
    standing still over a quarter of its range, in 50 spans or more.

    Two segments that are each one point are never intersected with each other (one point within
    tol of another is met from the segments that move on at the stall's ends; an edge with no
    segment that moves, a sliver shorter than tol, has no stall), and a contact of an
    edge with itself inside one stall is no self-intersection (:func:`_clean_pair`): it is the
    edge's one passage there. Intersected, every pair of such spans was an overlap of the edge with
    itself, 1,000s of them from one spline, and ``arrange`` clustered their cuts for minutes.
    Computed once per edge and tolerance; most edges have no such segment.
    """
    cached = e._stalls
    if cached is not None and cached[0] == tol:
        return cached[1], cached[2]
    flags = [math.dist(lo, hi) <= tol for lo, hi in zip(e.lows, e.highs, strict=True)]
    if all(flags):  # an edge within tol of a point in all (a sliver): no segment that moves on
        flags = [False] * len(flags)
    runs: list[tuple[float, float]] = []
    i, n = 0, len(flags)
    while i < n:
        if not flags[i]:
            i += 1
            continue
        lo: tuple[float, ...] = e.lows[i]
        hi: tuple[float, ...] = e.highs[i]
        j = i
        while j + 1 < n and flags[j + 1]:
            wider_lo, wider_hi = tuple(map(min, lo, e.lows[j + 1])), tuple(map(max, hi, e.highs[j + 1]))
            if math.dist(wider_lo, wider_hi) > tol:
                break
            lo, hi, j = wider_lo, wider_hi, j + 1
        runs.append((e.segs[i].t0, e.segs[j].t1))
        i = j + 1
    e._stalls = (tol, flags, runs)
    return flags, runs


def _in_one_stall(e: _EdgeInfo, t: float, u: float, tol: float) -> bool:
    """True when parameters ``t`` and ``u`` of edge ``e`` lie in one of its stalls (:func:`_stalls`)."""
    lo, hi = min(t, u), max(t, u)
    return any(a <= lo and hi <= b for a, b in _stalls(e, tol)[1])


def _stall_passage(e: _EdgeInfo, t: float, u: float, point: _Point3, tol: float) -> bool:
    """True when edge ``e`` meets itself at ``(t, u)`` only by standing still there (:func:`_stalls`).

    ``[t, u]`` reaches into a stall, and the edge stays within ``tol`` of the contact ``point``
    from ``t`` and from ``u`` to the stall: it slows down into the stall and leaves it as one
    passage (a spline 1.7e-4 of a span before its stall is 1e-8 from it). Five samples of each
    stretch outside the stall, as :func:`_stretch_within` proves a stretch by samples.
    """
    lo, hi = min(t, u), max(t, u)
    for a, b in _stalls(e, tol)[1]:
        if hi < a or lo > b:
            continue
        outside = [(s0, s1) for s0, s1 in ((lo, a), (b, hi)) if s0 < s1]
        if all(math.dist(ocp.curve_value(e.adaptor, s0 + f * (s1 - s0)), point) <= tol
               for s0, s1 in outside for f in (0.0, 0.25, 0.5, 0.75, 1.0)):
            return True
    return False


def _cannot_cross_itself(rows: list[list[float]]) -> bool:
    """True for a segment that has no self-intersection: a line, or a conic arc that does not fold back.

    A rational quadratic with positive weights is a conic arc inside its control
    triangle; it meets itself only when its control points are collinear with the
    middle one outside (the curve runs out and back over itself).
    """
    if len(rows) == 2:
        return True
    if len(rows) != 3:
        return False
    (x0, y0, z0, w0), (x1, y1, z1, w1), (x2, y2, z2, w2) = rows
    a = (x1 / w1 - x0 / w0, y1 / w1 - y0 / w0, z1 / w1 - z0 / w0)
    b = (x2 / w2 - x1 / w1, y2 / w2 - y1 / w1, z2 / w2 - z1 / w1)
    dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    cross = math.hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
    return dot >= 0.0 or cross > 1e-9 * math.hypot(*a) * math.hypot(*b)


def _no_self_job(e: _EdgeInfo, i: int, planar: bool, tol: float) -> bool:
    """True when segment ``i`` of edge ``e`` cannot cross itself, so that its self job would find nothing.

    :func:`_cannot_cross_itself` on its rows, or, in the common frame (``planar``), its planar
    control points running along their chord (:func:`relief_cad.pieces.along_chord`: the core's
    test of a piece that cannot meet itself then passes on the whole segment, which is then one
    piece with no pair to intersect). Most free-form spans of glyphs and sketches pass the second
    in about 1.3 us, where the self job takes about 28 us (the planar curve built, the tolerance
    resolved, the pieces cut) to answer nothing; it took 50 us, a quarter of the time of
    ``arrange`` on 5,000 glyph edges, before the core's self-intersection stopped checking its
    curve again.
    """
    if _cannot_cross_itself(e.rows[i]) or _stalls(e, tol)[0][i]:
        return True
    if not planar:
        return False
    pts, _, offsets, _ = _planar_arrays(e)
    return _along_chord(pts[offsets[i]:offsets[i + 1]])


_Packed = tuple[list[list[float]], list[float], list[int], list[list[float]]]


def _planar_arrays(e: _EdgeInfo) -> _Packed:
    """An edge's segments in the common frame, packed: points ``[x, y]``, weights, offsets, ends.

    The values are those of the segments' planar :class:`RationalBezier` curves
    (:func:`_curve2d`): the same homogeneous rows divided by the same weights. ``ends``
    holds per segment its first and last points in space, ``[x0, y0, z0, x1, y1, z1]``
    (the rows divided by their weights, for :func:`_apart_pairs`).
    """
    if e._packed is None:
        frame = e.frame
        if frame is None:
            raise InvalidInputError("internal: no common frame set")  # pragma: no cover
        offsets = [0]
        for seg in e.rows:
            offsets.append(offsets[-1] + len(seg))
        pts: list[list[float]] = []
        ws: list[float] = []
        if frame is _XY_FRAME:
            pts, ws = e.xy, e.ws
        else:
            for s in e.segs:
                for x, y, w in _to_plane(s, frame).homogeneous.tolist():
                    pts.append([x / w, y / w])
                    ws.append(w)
        ends = [[c / r[-1] for r in (seg[0], seg[-1]) for c in r[:-1]] for seg in e.rows]
        e._packed = (pts, ws, offsets, ends)
    return e._packed


def _pack_edges(
    infos: list[_EdgeInfo],
) -> tuple[np.ndarray, np.ndarray, np.ndarray, list[list[float]], list[int]]:
    """The segments of the edges packed for the batch kernel: ``P, W, offsets, ends, starts``.

    ``ends`` holds the space end points of every packed curve (lists of 6), ``starts[k]`` the
    index of edge ``k``'s first segment among the packed curves.
    """
    pts: list[list[float]] = []
    ws: list[float] = []
    ends: list[list[float]] = []
    offsets = [0]
    starts: list[int] = []
    for e in infos:
        e_pts, e_ws, e_offsets, e_ends = _planar_arrays(e)
        starts.append(len(offsets) - 1)
        shift = len(ws)
        pts.extend(e_pts)
        ws.extend(e_ws)
        ends.extend(e_ends)
        offsets.extend([shift + o for o in e_offsets[1:]])
    P = np.array(pts)
    W = np.array(ws)
    P.flags.writeable = False
    W.flags.writeable = False
    return P, W, np.array(offsets, dtype=np.int64), ends, starts


def _pack(jobs: list[_Job]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list[list[float]]]:
    """The jobs' edges packed (every edge once, in order of first use): ``P, W, offsets, pairs, ends``.

    ``pairs`` are the jobs' segment pairs as indices of packed curves.
    """
    order: dict[int, int] = {}  # id(edge info) -> its place among the packed edges
    edges: list[_EdgeInfo] = []
    for job in jobs:
        for e in (job.ea, job.eb):
            if id(e) not in order:
                order[id(e)] = len(edges)
                edges.append(e)
    P, W, offsets, ends, starts = _pack_edges(edges)
    pairs = [(starts[order[id(j.ea)]] + j.i, starts[order[id(j.eb)]] + j.j) for j in jobs]
    return P, W, offsets, np.array(pairs, dtype=np.int64).reshape(-1, 2), ends


def _apart_pairs(ends: list[list[float]], pairs: np.ndarray, tol: float) -> list[int]:
    """The indices of the packed pairs whose segments' ends do not meet (both within ``tol`` of the other's).

    Nearness is the largest coordinate difference. Pairs whose ends meet may coincide (a
    duplicate edge), the clipping's slowest case: they go through ``relief_cad.intersect``, which
    answers coincident curves before clipping. A few pairs are tested on Python floats
    (numpy's cost per call is more than theirs), many in one numpy pass: the same subtractions
    and comparisons.
    """
    if pairs.shape[0] <= 32:
        return [k for k, (i, j) in enumerate(pairs.tolist()) if not _ends_meet(ends[i], ends[j], tol)]
    rows = np.array(ends).reshape(-1, 6)
    a, b = rows[pairs[:, 0]], rows[pairs[:, 1]]

    def near(p: np.ndarray, q: np.ndarray) -> np.ndarray:
        return np.abs(p - q).max(axis=1) <= tol  # type: ignore[no-any-return]

    a0, a1, b0, b1 = a[:, :3], a[:, 3:], b[:, :3], b[:, 3:]
    meet = (near(a0, b0) & near(a1, b1)) | (near(a0, b1) & near(a1, b0))
    return np.flatnonzero(~meet).tolist()  # type: ignore[no-any-return]


def _ends_meet(a: list[float], b: list[float], tol: float) -> bool:
    """True when two segments' ends meet (:func:`_apart_pairs`); end points ``[x0, y0, z0, x1, y1, z1]``."""
    d00 = max(abs(a[0] - b[0]), abs(a[1] - b[1]), abs(a[2] - b[2])) <= tol
    d11 = max(abs(a[3] - b[3]), abs(a[4] - b[4]), abs(a[5] - b[5])) <= tol
    d01 = max(abs(a[0] - b[3]), abs(a[1] - b[4]), abs(a[2] - b[5])) <= tol
    d10 = max(abs(a[3] - b[0]), abs(a[4] - b[1]), abs(a[5] - b[2])) <= tol
    return (d00 and d11) or (d01 and d10)


def _solve_packed(jobs: list[_Job], tol: float) -> list[list[_Found] | None]:
    """Planar jobs in the common frame: one call of the batch kernel on packed control points.

    A job whose segments' ends meet (see :func:`_apart_pairs`) is left to the caller: None.
    """
    P, W, offsets, pairs, ends = _pack(jobs)
    return _batch_found(
        P, W, offsets, pairs, ends, tol, lambda k: (jobs[k].ea, jobs[k].i, jobs[k].eb, jobs[k].j)
    )


def _batch_found(
    P: np.ndarray, W: np.ndarray, offsets: np.ndarray, pairs: np.ndarray, ends: list[list[float]], tol: float,
    pair_of: Callable[[int], tuple[_EdgeInfo, int, _EdgeInfo, int]],
) -> list[list[_Found] | None]:
    """The batch kernel on packed segment pairs: every pair's results by ``t``, None where the ends meet.

    The kernel gives each pair's rows in the order of ``t`` (an overlap by its first ``t``), so
    they are kept as they come. ``pair_of(k)`` names pair ``k``'s edges and segments, for the
    budget error of an unresolved pair.
    """
    which = _apart_pairs(ends, pairs, tol)
    rows: list[list[float]] = []
    if which:
        run = pairs if len(which) == pairs.shape[0] else pairs[which]
        rows = _batch_rows(P, W, offsets, run, np.full(len(which), tol), DEFAULT_BUDGET).tolist()  # all cores
    out: list[list[_Found] | None] = [None] * pairs.shape[0]
    for k in which:
        out[k] = []
    for r in rows:
        kind = int(r[1])
        k = which[int(r[0])]
        if kind == KIND_UNRESOLVED:
            # let the public intersector raise its BudgetExceededError with the partial results
            ea, i, eb, j = pair_of(k)
            _core()[0](_curve2d(ea, i), _curve2d(eb, j), tol=tol)
            raise InvalidInputError("internal: unresolved box without a budget error")  # pragma: no cover
        name = "crossing" if kind == KIND_CROSSING else "tangent" if kind == KIND_TANGENT else "overlap"
        out[k].append((name, r[2], r[3], r[4], r[5], r[8]))  # type: ignore[union-attr]
    return out  # each pair's rows come by t from the batch kernel (clipping.intersect_packed)


def _solve(
    jobs: list[_Job], tol: float, self_mode: bool = False, known: list[list[_Found] | None] | None = None
) -> list[list[_Found]]:
    """Run the core intersector on every job; planar two-curve jobs in one batched call.

    ``self_mode``: the self-intersections of one shape, whose end-to-end contacts (a vertex shared by
    two edges, a joint of two segments) are dropped later, so the batch kernel's answer stands there.
    ``known``: the batch kernel's answers when they are known already (:func:`_model_jobs`).
    """
    if known is None:  # the packed jobs through the batch kernel
        known = [None] * len(jobs)
        packed = [k for k, job in enumerate(jobs) if job.packed]
        if packed:
            for k, found in zip(packed, _solve_packed([jobs[k] for k in packed], tol), strict=True):
                known[k] = found
    answers: list[list[_Found] | None] = [
        found if found is not None and _final(job, found, self_mode) else None
        for job, found in zip(jobs, known, strict=True)
    ]
    if all(a is not None for a in answers):
        return answers  # type: ignore[return-value]
    core, many = _core()
    batch = [
        k for k, job in enumerate(jobs)
        if answers[k] is None and job.ca is not None and job.cb is not None
        and job.ca.dim == 2 and job.cb.dim == 2
    ]
    if many is not None and len(batch) > 1:
        for k, res in zip(batch, many([(jobs[k].ca, jobs[k].cb) for k in batch], tol=tol), strict=True):
            answers[k] = _as_found(res)
    for k, job in enumerate(jobs):
        if answers[k] is None:
            if job.packed:  # a pair the batch kernel did not settle (see _final), or whose ends meet
                job.ca, job.cb = _curve2d(job.ea, job.i), _curve2d(job.eb, job.j)
            answers[k] = _as_found(core(job.ca, job.cb, tol=tol))
    return [a if a is not None else [] for a in answers]


def _final(job: _Job, found: list[_Found], self_mode: bool = False) -> bool:
    """True when the batch kernel's answer needs no post-pass (the rule of the core's ``needs_refining``).

    Overlaps, tangent contacts and meetings at an end whose derivative vanishes (a repeated end
    control point) go through ``relief_cad.intersect``, whose post-pass decides them by geometry.
    The joint of two consecutive segments of one edge, and in ``self_mode`` any point contact at an
    end of both segments, are final: the results drop them (a joint, a vertex two edges share).
    """
    joint = job.ea is job.eb and job.j == job.i + 1
    for kind, t, u, *_ in found:
        if (joint and t == 1.0 and u == 0.0) or (
                self_mode and kind != "overlap" and t in (0.0, 1.0) and u in (0.0, 1.0)):
            continue
        if kind != "crossing" or _singular(job.ea.rows[job.i], t) or _singular(job.eb.rows[job.j], u):
            return False
    return True


def _singular(rows: list[list[float]], s: float) -> bool:
    """True when ``s`` is an end of the segment with homogeneous ``rows`` where its derivative vanishes."""
    if s != 0.0 and s != 1.0:
        return False
    p, q = (rows[0], rows[1]) if s == 0.0 else (rows[-1], rows[-2])
    return all(x / p[-1] == y / q[-1] for x, y in zip(p[:-1], q[:-1], strict=True))


def _as_found(results: Any) -> list[_Found]:
    out: list[_Found] = []
    for r in results:
        if isinstance(r, Overlap):
            out.append(("overlap", r.t[0], r.u[0], r.t[1], r.u[1], 0.0))
        elif isinstance(r, Intersection):
            out.append((r.kind, r.t, r.u, 0.0, 0.0, r.distance))
    return out


def _raw_results(job: _Job, found: list[_Found]) -> list[_Raw]:
    """Map one segment pair's results to the edges' own parameters and 3D points."""
    ea, eb = job.ea, job.eb
    sa, sb = ea.segs[job.i], eb.segs[job.j]
    ra, rb = ea.rows[job.i], eb.rows[job.j]
    out: list[_Raw] = []
    for kind, t, u, t1, u1, _distance in found:
        if kind == "overlap":
            tt = (sa.edge_param(t), sa.edge_param(t1))
            uu = (sb.edge_param(u), sb.edge_param(u1))
            out.append(_Raw(ea, eb, tt, uu, _point3(ra, t), "overlap", 0.0))
        else:
            pa = _point3(ra, t)
            pb = _point3(rb, u)
            point = (0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2]))
            out.append(_Raw(ea, eb, sa.edge_param(t), sb.edge_param(u), point, kind, math.dist(pa, pb)))
    return out


def _point3(rows: list[list[float]], s: float) -> tuple[float, float, float]:
    """The point at ``s`` of a space segment given by its homogeneous rows (Bernstein sum; ends exact)."""
    n = len(rows) - 1
    if s <= 0.0 or s >= 1.0:
        x, y, z, w = rows[0] if s <= 0.0 else rows[n]
    else:
        r = 1.0 - s
        x = y = z = w = 0.0
        for i, (hx, hy, hz, hw) in enumerate(rows):
            b = math.comb(n, i) * s**i * r ** (n - i)
            x += b * hx
            y += b * hy
            z += b * hz
            w += b * hw
    return (x / w, y / w, z / w)


def _is_same_vertex(v: Any, w: Any) -> bool:
    return bool(not v.IsNull() and not w.IsNull() and v.IsSame(w))


def _at_end(e: _EdgeInfo, t: float, which: int, ptol: float) -> bool:
    return abs(t - (e.first if which == 0 else e.last)) <= ptol * max(1.0, abs(e.last - e.first))


def _clean_pair(raws: list[_Raw], same: bool, self_mode: bool, tol: float) -> list[_Raw]:
    """Merge overlaps, drop points inside overlaps, duplicates and trivial contacts of one edge pair."""
    if not raws:
        return raws
    if len(raws) == 1 and not same and not self_mode and raws[0].kind != "overlap":
        return raws  # a single point of two distinct edges: nothing to merge or drop
    ea, eb = raws[0].ea, raws[0].eb
    ptol = 1e-9
    overlaps = sorted((r for r in raws if r.kind == "overlap"), key=lambda r: r.t[0])
    merged: list[_Raw] = []
    for r in overlaps:
        t0, t1 = r.t
        u0, u1 = r.u
        if t0 > t1:
            t0, t1, u0, u1 = t1, t0, u1, u0
        if same and _in_one_stall(ea, min(t0, u0, u1), max(t1, u0, u1), tol):
            continue  # the edge standing still within tol: no overlap with itself (_stalls)
        r = _Raw(ea, eb, (t0, t1), (u0, u1), r.point, "overlap", 0.0)
        if merged and _continues(merged[-1], r, tol, ptol):
            prev = merged[-1]
            merged[-1] = _Raw(ea, eb, (prev.t[0], max(prev.t[1], r.t[1])), (prev.u[0], r.u[1]),
                              prev.point, "overlap", 0.0)
            continue
        merged.append(r)
    points: list[_Raw] = []
    crossings: list[int] = []  # per kept point: the distinct crossings it stands for
    floor: float | None = None  # the rounding floor of both edges, found on first use
    found = [r for r in raws if r.kind != "overlap"]
    for r in sorted(found if same else _joint_meetings(found, tol), key=lambda r: r.distance):
        t, u = r.t, r.u
        if same:
            # the same point of one edge (a segment joint), or the closing point of a closed edge
            span = max(1.0, abs(ea.last - ea.first))
            if abs(t - u) <= ptol * span or _stall_passage(ea, t, u, r.point, tol):
                continue
            if _is_same_vertex(ea.vertices[0], ea.vertices[1]) and (
                (_at_end(ea, t, 0, ptol) and _at_end(ea, u, 1, ptol))
                or (_at_end(ea, t, 1, ptol) and _at_end(ea, u, 0, ptol))
            ):
                continue
            if t > u:
                r = _Raw(ea, eb, u, t, r.point, r.kind, r.distance)
        elif self_mode and _shared_vertex_contact(r, tol):
            continue
        if any(_inside(o, r, tol) for o in merged):
            continue
        if points and r.distance > 0.0:
            floor = floor if floor is not None else _pair_floor(r)
            if _on_flank(r, points, floor):
                continue
        k = next((k for k, p in enumerate(points) if _near(p.point, r.point, tol)), -1)
        if k < 0:
            points.append(r)
            crossings.append(1 if r.kind == "crossing" else 0)
        elif r.kind == "crossing" and points[k].kind == "crossing" and not _same_place(points[k], r, tol):
            crossings[k] += 1  # another crossing within tol of this one (not a copy from a segment joint)
    if len(points) > 1:
        points, crossings = _join_stretches(points, crossings)
    # an even number of crossings within tol of each other is a touch: b crosses a and back
    return merged + [_Raw(p.ea, p.eb, p.t, p.u, p.point, "tangent", p.distance) if n % 2 == 0 and n else p
                     for p, n in zip(points, crossings, strict=True)]


def _continues(prev: _Raw, r: _Raw, tol: float, ptol: float) -> bool:
    """True when the overlap ``r`` (later in ``t``) continues ``prev``: one overlap, cut at a span joint.

    They meet on both edges, in parameter (within ``ptol`` of the ranges) or in space (within
    ``tol``: a space pair's overlap ends are good to about 1e-9 rad), and ``b`` runs on the same
    way (where it turns back they are two overlaps).
    """
    ea, eb = prev.ea, prev.eb
    if (prev.u[1] - prev.u[0]) * (r.u[1] - r.u[0]) < 0.0:
        return False
    if r.t[0] - prev.t[1] <= ptol * max(1.0, abs(ea.last - ea.first)) and _close_params(
        prev.u[1], r.u[0], eb, ptol
    ):
        return True
    return _near(ocp.curve_value(ea.adaptor, prev.t[1]), ocp.curve_value(ea.adaptor, r.t[0]), tol) and _near(
        ocp.curve_value(eb.adaptor, prev.u[1]), ocp.curve_value(eb.adaptor, r.u[0]), tol)


def _join_stretches(points: list[_Raw], crossings: list[int]) -> tuple[list[_Raw], list[int]]:
    """Crossings the edges join by a stretch within rounding are one contact, with all their crossings.

    Tangent circles of radius 100 cross twice 1e-6 apart where their rational spans are rounded,
    farther apart than tol (1e-7), though the circles stay within 1e-14 between the two: the
    rounding of one tangent meeting. Consecutive crossings (by ``t``) are joined when they are
    within 1e-2 of a span in both parameters (:func:`_near_params`; the rounding of a contact of
    order four, an ellipse and its osculating circle at a vertex in a plane tilted at coordinates
    of 2,000, crosses 1.2e-3 of a span apart) and the edges stay within the rounding floor of
    their control points between them (:func:`_stretch_within`). A chain keeps its point nearest
    to the other edge, but a touch (an even count) spread over more than 1e-6 of a span is placed
    midway (:func:`_midway`). Rounding spreads the crossings of a touch by about the square root of
    the rounding for a contact of order two (a touch in space rounded to crossings 3e-8 apart lay
    at one of them), by its fourth root for one of order four (6e-4 either side of it, at
    coordinates of 2,000). A wider gap is
    the data's own: a curve crossing another twice 8e-4 apart, 7e-8 from it between (a near-miss
    within tol 1e-7), crosses it twice, as the exact arbiter says; so does a crossing 0.007 before
    a touch.
    """
    order = sorted((k for k, n in enumerate(crossings) if n), key=lambda k: points[k].t)
    if len(order) < 2:
        return points, crossings
    chains: list[list[int]] = [[order[0]]]
    for k in order[1:]:
        last = points[chains[-1][-1]]
        if _near_params(last, points[k], 1e-2) and _stretch_within(last, points[k], _pair_floor(last)):
            chains[-1].append(k)
        else:
            chains.append([k])
    if len(chains) == len(order):
        return points, crossings
    count = dict(enumerate(crossings))
    out = list(points)
    for chain in chains:
        best = min(chain, key=lambda k: (points[k].distance, points[k].t))
        count[best] = sum(crossings[k] for k in chain)
        if count[best] % 2 == 0 and not _near_params(points[chain[0]], points[chain[-1]], 1e-6):
            out[best] = _midway(points[chain[0]], points[chain[-1]])
        for k in chain:
            if k != best:
                del count[k]
    return [out[k] for k in count], list(count.values())


def _midway(p: _Raw, q: _Raw) -> _Raw:
    """The contact halfway in ``t`` between crossings ``p`` and ``q`` that rounding made of one touch."""
    return _touch_at(p, 0.5 * (p.t + q.t), 0.5 * (p.u + q.u))


def _touch_at(r: _Raw, t: float, u: float) -> _Raw:
    """A touch of ``r``'s edges at ``t`` on ``a``: its ``u`` the foot on ``b`` near ``u``, its point halfway.

    The foot is :func:`~relief_cad.cad.ocp.curve_foot`; the distance is the one to it.
    """
    a = ocp.curve_value(r.ea.adaptor, t)
    u, dist = ocp.curve_foot(r.eb.adaptor, a, u)
    b = ocp.curve_value(r.eb.adaptor, u)
    point = (0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]))
    return _Raw(r.ea, r.eb, t, u, point, "tangent", dist)


def _near_params(p: _Raw, q: _Raw, frac: float = 1e-3) -> bool:
    """True when contacts ``p`` and ``q`` of one edge pair are within ``frac`` of a span in both parameters.

    The span is that of the rational piece holding ``p`` on each edge (the core's parameter
    on a piece runs over [0, 1], and its rule for one contact is 1e-3 there; for a point on the
    flank of another, 1e-1).
    """
    dt, du = abs(float(q.t) - float(p.t)), abs(float(q.u) - float(p.u))
    return dt <= frac * _span_at(p.ea, p.t) and du <= frac * _span_at(p.eb, p.u)


def _on_flank(r: _Raw, points: list[_Raw], floor: float) -> bool:
    """True when contact ``r`` lies on the flank of a closer contact in ``points`` (the core's rule).

    ``r`` more than ``floor`` apart, 1e-3 to 1e-1 of a span from it (the core's reach for an end
    meeting; a whole span at a joint of spans, :func:`_at_joint`; nearer than 1e-3, the core's rule
    of one contact has kept the end), with the edges between them
    no farther apart than ``max(4 d, floor)`` (``d`` its distance): it is within tol only because
    the edges stay close up to that contact. The core drops such points within a span pair;
    across spans, the end of the next span is one: a nearly straight spline crossing a line at a
    small angle near a knot is 4.5e-8 off the line at the knot, and the crossing was reported twice.

    A touch nearer a crossing than 1e-3 is on its flank too: within one span pair the core's rule
    of one contact would have joined them, but across a joint each span gave its own. Two circles
    tol + 5e-15 into each other at their seams gave both crossings and a touch between them,
    1.0000008e-7 apart (beyond tol).
    """
    if r.distance <= floor:
        return False
    lim = max(4.0 * r.distance, floor)
    reach = 1.0 if _at_joint(r.ea, r.t) or _at_joint(r.eb, r.u) else 1e-1
    touch = r.kind != "crossing"
    return any(p.distance < r.distance and _near_params(p, r, reach)
               and (not _near_params(p, r) or (touch and p.kind == "crossing"))
               and _stretch_within(p, r, lim) for p in points)


def _joint_meetings(found: list[_Raw], tol: float) -> list[_Raw]:
    """Point contacts of two distinct edges, each meeting at an inner joint of spans decided once.

    Every span pair at a joint reports the meeting there by the core's rule for a span's end, which
    sees one span only: one pair may call it a crossing, another a touch. The copies (one place and
    the same parameters, :func:`_same_place`) are one meeting. The one nearest the other edge is
    decided by the edges on both sides (:func:`_joint_sides`) and, when it is a touch, placed where
    it is (:func:`_joint_touch`); the rest are dropped. Where the sides do not decide
    (:func:`_joint_sides` gives None) and no touch lies nearby, the nearest copy stands as the
    core gave it, and copies that are all crossings stand. A cubic B-spline touching a line 2e-7
    of its range after a knot was a crossing at the knot; a line touching a circle 2e-7 before the
    joint of two of its spans, where the core saw sine 2e-7, was a crossing at the joint. A
    meeting farther apart than the rounding floor is no meeting at the joint: the contact it
    stands for lies nearby (:func:`_off_joint`).
    """
    joints = [r for r in found if _inner_joint(r)]
    if not joints:
        return found
    floor = _pair_floor(joints[0])
    out = [r for r in found if not any(r is q for q in joints)]
    while joints:
        group = [q for q in joints if _same_place(joints[0], q, tol)]
        joints = [q for q in joints if not any(q is g for g in group)]
        best = min(group, key=lambda q: q.distance)
        if best.distance > floor:  # no meeting at the joint: a contact next to it, or the core's copies
            near = _off_joint(best, tol, floor)
            if near is not None:
                out.append(near)
            elif all(q.kind == "crossing" for q in group):
                out.extend(group)
            else:
                out.append(best)  # _off_joint found no touch to place: the nearest copy as the core gave it
            continue
        cross = _joint_sides(best, floor)
        if cross is not False and all(q.kind == "crossing" for q in group):
            out.extend(group)  # the later merge counts copies once (_same_place)
            continue
        kind = "crossing" if cross else "tangent"
        decided = _Raw(best.ea, best.eb, best.t, best.u, best.point, kind, best.distance)
        if not cross:
            moved = _joint_touch(decided, tol)
            # undecided and no touch nearby: the core's nearest copy stands as it gave it
            decided = moved if moved is not decided or cross is False else best
        out.append(decided)
    return out


def _off_joint(r: _Raw, tol: float, floor: float) -> _Raw | None:
    """The contact that a meeting at an inner joint, apart by more than ``floor``, stands for; or None.

    The core puts a contact within tol of a span's end on that end (its parameter exactly 0 or
    1), but at an inner joint the edge goes on: the contact itself lies inside the next span. A
    touch is placed where the tangents are parallel (:func:`_joint_touch`); failing that, a
    crossing where the edges come closest (:func:`_joint_nearest`), labelled by the edges on both
    sides of it (:func:`_joint_sides`; a near-miss, undecided there, is a touch by the rule of
    tol). A line crossing a B-spline at 17 degrees 2e-7 of its range after a knot came back as a
    touch at the knot, 1.5e-7 from the crossing (tol 1e-7); in space, a line touching a
    B-spline 4e-7 of its range after a knot came back as a crossing at the knot. None when
    neither moves: the meeting keeps the core's copies.
    """
    tangent = _Raw(r.ea, r.eb, r.t, r.u, r.point, "tangent", r.distance)
    touch = _joint_touch(tangent, tol)
    if touch is not tangent:
        return touch
    near = _joint_nearest(r, tol)
    if near is r:
        return None
    kind = "crossing" if _joint_sides(near, floor) else "tangent"
    return _Raw(near.ea, near.eb, near.t, near.u, near.point, kind, near.distance)


def _joint_nearest(r: _Raw, tol: float) -> _Raw:
    """The meeting ``r`` at a joint moved to the nearest place next to it where the edges meet, or ``r``.

    Planar pairs: where ``a`` crosses to the other side of ``b`` (the sign of ``(a - b) x b' . n``,
    ``n`` the plane's normal). Space pairs: where the edges come closest (the sign of the slope
    ``(a - b) . a'`` of their squared distance, which shows a shallow crossing less sharply: at
    1e-3 rad, to about 1e-10 of the range). ``b`` is taken at the foot of ``a``. The change
    nearest the joint on either side (:func:`_nearest_change`) is taken when the edges are less
    than a quarter as far apart there as at the joint; its kind is left to the caller.
    """
    if r.distance > tol:
        return r
    frame = r.ea.frame
    normal = np.cross(frame[0, :3], frame[1, :3]) if frame is not None else None

    def negative(t: float) -> bool:
        pa = ocp.curve_value(r.ea.adaptor, t)
        u = ocp.curve_foot(r.eb.adaptor, pa, r.u)[0]
        gap = np.subtract(pa, ocp.curve_value(r.eb.adaptor, u))
        if normal is None:
            return float(gap @ ocp.curve_tangent(r.ea.adaptor, t)) < 0.0
        return float(np.cross(gap, ocp.curve_tangent(r.eb.adaptor, u)) @ normal) < 0.0

    return _nearest_change(negative, r)


def _nearest_change(negative: Callable[[float], bool], r: _Raw) -> _Raw:
    """``r`` moved to where ``negative`` first changes on either side of ``r.t`` along ``a``, or ``r``.

    Each side's first change (:func:`_first_change`) is a candidate where the edges are less than a
    quarter as far apart as at ``r`` (:func:`_moved_touch`). One candidate is the contact that
    the core put on the joint. Candidates on both sides leave ``r`` as it is: the joint lies in a
    stretch where the edges stay within tol between two contacts, which the core made one touch
    (two circles of radius 317 that cut into each other by 3e-8 cross 7e-3 apart, on either side
    of the joint at the seam of one).
    """
    moved = []
    for sense in (-1.0, 1.0):
        t = _first_change(negative, r, sense)
        candidate = r if t is None else _moved_touch(r, t)
        if candidate is not r:
            moved.append(candidate)
    return moved[0] if len(moved) == 1 else r


def _first_change(negative: Callable[[float], bool], r: _Raw, sense: float) -> float | None:
    """Where ``negative`` first differs from its value at ``r.t``, walking out along ``a`` one way.

    The walk runs from 1e-9 to :data:`_JOINT_REACH` of the span in the direction ``sense``
    (+1.0 or -1.0), doubling the step; the first step where ``negative`` has changed is bisected
    (:func:`_bisect_sign`). None when it does not change within reach or before ``a`` ends.
    """
    span = _span_at(r.ea, r.t)
    here, prev, h = negative(r.t), r.t, 1e-9 * span
    while h <= _JOINT_REACH * span:
        t = min(r.ea.last, max(r.ea.first, r.t + sense * h))
        if negative(t) != here:
            return _bisect_sign(negative, prev, t)
        if t in (r.ea.first, r.ea.last):
            return None
        prev, h = t, 2.0 * h
    return None


def _bisect_sign(negative: Callable[[float], bool], lo: float, hi: float) -> float:
    """A place in ``[lo, hi]`` (either order) where ``negative`` changes, to adjacent doubles (midpoint).

    ``negative(lo) != negative(hi)`` is the caller's to ensure.
    """
    below = negative(lo)
    for _ in range(80):  # halving 1e-3 of a span to adjacent doubles takes at most about 60 steps
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        lo, hi = (mid, hi) if negative(mid) == below else (lo, mid)
    return 0.5 * (lo + hi)


def _moved_touch(r: _Raw, t: float) -> _Raw:
    """``r`` moved to ``t`` (:func:`_touch_at`) if the edges are less than a quarter as far apart there.

    Not clearly closer than at the joint: the joint meets ``b`` (within rounding), ``r`` stands.
    """
    touch = _touch_at(r, t, r.u)
    if not touch.distance < 0.25 * r.distance or not r.eb.first < touch.u < r.eb.last:
        return r
    return touch


def _joint_sides(r: _Raw, floor: float) -> bool | None:
    """Whether the edges cross at the meeting ``r`` at a joint of spans: True, False (a touch) or None.

    The core labels a meeting at an end of a span by its angle alone (an end meeting at sine below
    1e-7 is a touch): it sees one span at a time. Across a joint, the edges show which it is. On
    each side of the meeting, walking out along ``a`` from 1e-9 to 1e-3 of its span, the first
    offset of ``a`` from its foot on ``b`` longer than ``floor`` is taken (64 ulps of the
    coordinates: far above the rounding of the evaluation, and short of another crossing nearby
    whenever the edges part by more than rounding between): offsets in opposite directions are a
    crossing, in one direction a touch. A spline through 17 points of a circle crosses the circle
    at sine 1e-8 at one of its knots (4e-5 after crossing it the other way); that was a touch.
    None (undecided) when the meeting is farther apart than ``floor``, when a side stays within
    ``floor`` up to 1e-3 of the span, or when an edge ends first.
    """
    if r.distance > floor:
        return None
    span, sides = _span_at(r.ea, r.t), []
    for sense in (-1.0, 1.0):
        h, off = 1e-9 * span, None
        while off is None and h <= _JOINT_REACH * span:
            t = r.t + sense * h
            if not r.ea.first <= t <= r.ea.last:
                return None
            pa = ocp.curve_value(r.ea.adaptor, t)
            fu = ocp.curve_foot(r.eb.adaptor, pa, r.u)[0]
            if not r.eb.first < fu < r.eb.last:
                return None  # b ends there: no foot across from a
            a, foot = np.array(pa), np.array(ocp.curve_value(r.eb.adaptor, fu))
            off = a - foot if math.dist(pa, foot) > floor else None
            h *= 2.0
        if off is None:
            return None
        sides.append(off)
    return float(sides[0] @ sides[1]) < 0.0


def _inner_joint(r: _Raw) -> bool:
    """True when contact ``r`` lies at a joint of spans of either edge and at no end of either edge.

    An end meeting keeps the core's end rule: the edge does not go on past it.
    """
    if not (_at_joint(r.ea, r.t) or _at_joint(r.eb, r.u)):
        return False
    return not any(_at_end(e, x, k, 1e-9) for e, x in ((r.ea, r.t), (r.eb, r.u)) for k in (0, 1))


# below this sine the tangents at a joint are parallel (measured: B-splines touching a line 5e-8 to
# 2e-5 of their range past a knot, 1e-7 to 4e-5; the rounded tangents of contacts of order four at
# a joint, below 1e-15)
_JOINT_TOUCH_SIN = 1e-8

# how far from a joint, in its span, the contact a meeting there stands for is looked for: the core's
# reach for a meeting at a span's end (its rule of one contact, 1e-3 of a span)
_JOINT_REACH = 1e-3


def _joint_touch(r: _Raw, tol: float) -> _Raw:
    """A touch at an inner joint of spans, moved to where the edges' tangents are parallel.

    The core places a meeting at a span's end on that end, while the touch itself may lie just
    inside the next span: a quintic B-spline touches a line 7.5e-8 of its range after a knot,
    1.2e-7 along the line, beyond tol 1e-7. Walking out on both sides, the first change of sign
    of ``(a' x b') . n`` (``b`` at the foot of ``a``; ``n`` the normal of the edges' common
    plane, or for space pairs the direction of ``a' x b'`` at the joint) is found and bisected
    down to adjacent doubles (:func:`_nearest_change`). The touch moves there when the edges are
    less than a quarter as far apart there as at the joint (:func:`_moved_touch`): a joint that
    meets ``b`` (two crossings within rounding either side of a touch, one at the joint: the
    exact arbiter's point is that one) keeps it. So does a touch whose tangents are parallel at
    the joint to :data:`_JOINT_TOUCH_SIN`: near a contact of order four (an ellipse and its
    osculating circle at a vertex, a joint of the ellipse's spans) the sine stays within rounding
    for 1e-5 of the range, and its first sign change there is rounding's.
    """
    if r.distance > tol:
        return r

    def cross(t: float) -> np.ndarray:  # b's tangent (at the foot of a(t)) times a's, over their lengths
        u = ocp.curve_foot(r.eb.adaptor, ocp.curve_value(r.ea.adaptor, t), r.u)[0]
        da, db = np.array(ocp.curve_tangent(r.ea.adaptor, t)), np.array(ocp.curve_tangent(r.eb.adaptor, u))
        size = float(np.linalg.norm(da) * np.linalg.norm(db))
        return np.cross(da, db) / size if size > 0.0 else np.zeros(3)

    here = cross(r.t)
    sine = float(np.linalg.norm(here))
    if sine < _JOINT_TOUCH_SIN:
        return r  # the tangents are parallel at the joint, within their rounding: the touch is there
    frame = r.ea.frame
    normal = np.cross(frame[0, :3], frame[1, :3]) if frame is not None else here / sine
    return _nearest_change(lambda x: float(cross(x) @ normal) < 0.0, r)


def _at_joint(e: _EdgeInfo, t: float) -> bool:
    """True when ``t`` is a joint of two of edge ``e``'s spans (not an end of the edge).

    A meeting there is no end meeting of the edge, only of the spans the core saw one at a time:
    on the flank of a crossing a span away (a nearly straight spline 8e-8 off a line at a knot,
    0.16 of a span from where it crosses at sin 1e-7) it is no contact.
    """
    if len(e.segs) < 2:
        return False  # one span: no joint (most edges of a sketch: lines and arcs)
    span = max(1.0, abs(e.last - e.first))
    return any(abs(t - s.t0) <= 1e-12 * span for s in e.segs[1:])


def _span_at(e: _EdgeInfo, t: float) -> float:
    """The parameter length of the piece of edge ``e`` that holds ``t`` (the last one at its end)."""
    k = max(0, bisect.bisect_right([s.t0 for s in e.segs], t) - 1)
    return e.segs[k].t1 - e.segs[k].t0


def _pair_floor(p: _Raw) -> float:
    """The rounding floor of the control points of both edges of contact ``p`` (from their boxes)."""
    return _box_floor(p.ea.lo, p.ea.hi, p.eb.lo, p.eb.hi)


def _box_floor(*corners: _Point3) -> float:
    """The rounding floor of control points within boxes with these corners: ``rounding_floor`` of them.

    The largest magnitude is that of a corner's coordinate, so the floor is found on the floats
    (numpy's reductions cost more than this on a few corners).
    """
    return _floor_of_magnitude(max(abs(c) for corner in corners for c in corner))


def _stretch_within(p: _Raw, q: _Raw, tol: float) -> bool:
    """True when the edges stay within ``tol`` between contacts ``p`` and ``q`` of one edge pair.

    Seven samples of ``a`` evenly between them, the middle first (most pairs of crossings are far
    apart, and fail there), each against its foot on ``b`` near the matching fraction of ``b``'s
    step (:func:`~relief_cad.cad.ocp.curve_foot`). Matching fractions alone are off by the
    difference of the parameterisations: over the 1.1e-3 between the two crossings that rounding
    makes of an ellipse touching its osculating circle, 1e-6, far above the 1e-13 of rounding.
    """
    for f in (0.5, 0.25, 0.75, 0.125, 0.375, 0.625, 0.875):
        a = ocp.curve_value(p.ea.adaptor, p.t + f * (q.t - p.t))
        if ocp.curve_foot(p.eb.adaptor, a, p.u + f * (q.u - p.u))[1] > tol:
            return False
    return True


def _same_place(p: _Raw, r: _Raw, tol: float) -> bool:
    """True when two points of one edge pair are one point found twice.

    Within 1e-3 tol of each other, at the same parameter of each edge (a point found at the joint
    of two segments maps to the knot from both) or, on a closed edge, at both of its ends (a
    crossing at the seam). Place alone is not enough: at 1/100 scale the rounded spans of tangent
    circles cross twice 8e-11 apart, within 1e-3 of the 1e-7 floor of tol. On one edge the pair may
    come either way round: a double point at the seam of a closed spline is ``(0, u)`` from the
    first piece and ``(u, period)`` from the last, once its parameters are put in order (it was
    counted as two crossings there, a touch).
    """
    if math.dist(p.point, r.point) > 1e-3 * tol:
        return False
    if _same_param(p.ea, p.t, r.t) and _same_param(p.eb, p.u, r.u):
        return True
    return p.ea is p.eb and _same_param(p.ea, p.t, r.u) and _same_param(p.ea, p.u, r.t)


def _same_param(e: _EdgeInfo, t: float, s: float) -> bool:
    """True when ``t`` and ``s`` are one point of edge ``e``: equal within 1e-12 of its range, or its ends.

    Its two ends are one point only on a closed edge (a seam).
    """
    span = max(1.0, abs(e.last - e.first))
    if abs(t - s) <= 1e-12 * span:
        return True
    ends = [(_at_end(e, x, 0, 1e-9), _at_end(e, x, 1, 1e-9)) for x in (t, s)]
    return _is_same_vertex(e.vertices[0], e.vertices[1]) and (
        (ends[0][0] and ends[1][1]) or (ends[0][1] and ends[1][0]))


def _close_params(u_prev: float, u_next: float, eb: _EdgeInfo, ptol: float) -> bool:
    return abs(u_prev - u_next) <= ptol * max(1.0, abs(eb.last - eb.first))


def _near(p: tuple[float, float, float], q: tuple[float, float, float], tol: float) -> bool:
    return math.dist(p, q) <= tol


def _inside(o: _Raw, r: _Raw, tol: float) -> bool:
    """True when the point ``r`` is the overlap ``o`` (or one of its ends) again.

    Both parameters must lie in the overlap's ranges: ``a`` may run on along ``b`` while ``b``
    comes back across ``a`` elsewhere, a crossing at a ``t`` inside the overlap but ``u`` outside.
    On one edge the pair may come either way round.
    """
    if _in_ranges(o, r.t, r.u) or (o.ea is o.eb and _in_ranges(o, r.u, r.t)):
        return True
    ends = [ocp.curve_value(o.ea.adaptor, o.t[0]), ocp.curve_value(o.ea.adaptor, o.t[1])]
    return any(_near(e, r.point, tol) for e in ends)


def _in_ranges(o: _Raw, t: float, u: float) -> bool:
    slack_t = 1e-9 * max(1.0, abs(o.ea.last - o.ea.first))
    slack_u = 1e-9 * max(1.0, abs(o.eb.last - o.eb.first))
    in_t = bool(min(o.t) - slack_t <= t <= max(o.t) + slack_t)
    return in_t and bool(min(o.u) - slack_u <= u <= max(o.u) + slack_u)


def _shared_vertex_contact(r: _Raw, tol: float) -> bool:
    """True for the contact at a vertex joining two distinct edges (self-intersection mode).

    The contact must lie within tol (or the vertex's own tolerance) of a vertex of ``a`` that is
    also one of ``b``'s. The distances, on cached floats, come first, and the vertices within tol
    are tried first: a contact at the vertex two edges share nearly always lies within tol of its
    point, and is told so without reading any vertex's tolerance (the dearest OCCT call). The
    other vertices' tolerances are read (once per edge) only when none of those is shared.
    """
    marks = [(k, va, math.dist(p, r.point)) for k, (va, p) in enumerate(r.ea.vertex_marks)]
    for k, va, d in sorted(marks, key=lambda m: m[2] > tol):  # within tol first, in order
        if (d <= tol or d <= r.ea.vertex_tolerances[k]) and any(va.IsSame(vb) for vb, _ in r.eb.vertex_marks):
            return True
    return False


def _close_edge_pairs(infos_a: list[_EdgeInfo], infos_b: list[_EdgeInfo], tol: float) -> Any:
    """Index pairs of edges whose boxes, widened by ``tol``, overlap (vectorised for many edges)."""
    if len(infos_a) * len(infos_b) <= 16:
        out = []
        for ia, ea in enumerate(infos_a):
            lo_a, hi_a = ea.lo, ea.hi
            for ib, eb in enumerate(infos_b):
                lo_b, hi_b = eb.lo, eb.hi
                if all(lo_a[k] - tol <= hi_b[k] and lo_b[k] - tol <= hi_a[k] for k in range(3)):
                    out.append((ia, ib))
        return out
    # a grid of the boxes (relief_cad.broadphase): cost grows with the nearby pairs, not with all pairs
    return _box_pairs_between(
        [e.lo for e in infos_a], [e.hi for e in infos_a], [e.lo for e in infos_b], [e.hi for e in infos_b],
        pad=tol,
    ).tolist()


def _segment_boxes(infos: list[_EdgeInfo]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every segment of the edges, edge after edge: box corners (rows), its edge's index and its own."""
    counts = [len(e.lows) for e in infos]
    lows = np.array([c for e in infos for c in e.lows]).reshape(-1, 3)
    highs = np.array([c for e in infos for c in e.highs]).reshape(-1, 3)
    edge = np.repeat(np.arange(len(infos), dtype=np.int64), counts)
    seg = np.arange(lows.shape[0], dtype=np.int64) - np.repeat(np.cumsum([0] + counts[:-1]), counts)
    return lows, highs, edge, seg


def _model_jobs(
    infos_a: list[_EdgeInfo], infos_b: list[_EdgeInfo], self_mode: bool, tol: float
) -> tuple[list[_Job], list[list[_Found] | None]]:
    """The planar jobs of many edges, from one broad phase over all segment boxes, with the kernel's answers.

    The same jobs in the same order as the edge-pair path of :func:`_run` (edge pairs in order,
    then segment pairs; a box pair tested with the lower index first), but a pair gets a
    :class:`_Job` only when it has results or goes to ``relief_cad.intersect``: a segment
    against itself, segments whose ends meet. The answers: the kernel's, None for the core.
    """
    everyone = infos_a if self_mode else infos_a + infos_b
    P, W, offsets, ends, _ = _pack_edges(everyone)  # packed curve g is segment g of the boxes below
    lo, hi, edge, seg = _segment_boxes(everyone)
    if self_mode:
        pairs = _box_pairs(lo, hi, pad=tol)
        selves = [(k, i) for k, e in enumerate(infos_a) for i in range(len(e.rows))
                  if not _no_self_job(e, i, True, tol)]
    else:
        na = sum(len(e.lows) for e in infos_a)
        pairs = _box_pairs_between(lo[:na], hi[:na], lo[na:], hi[na:], pad=tol)
        pairs[:, 1] += na
        selves = []
    point = np.array([f for e in everyone for f in _stalls(e, tol)[0]], dtype=bool).reshape(-1)
    pairs = pairs[~(point[pairs[:, 0]] & point[pairs[:, 1]])]  # never two one-point spans (_stalls)
    ga, gb = pairs[:, 0], pairs[:, 1]
    order = np.lexsort((seg[gb], seg[ga], edge[gb], edge[ga]))
    pairs = pairs[order]
    ga, gb = pairs[:, 0].tolist(), pairs[:, 1].tolist()
    edge_l, seg_l = edge.tolist(), seg.tolist()
    found = _batch_found(
        P, W, offsets, pairs, ends, tol,
        lambda k: (everyone[edge_l[ga[k]]], seg_l[ga[k]], everyone[edge_l[gb[k]]], seg_l[gb[k]]),
    )
    keys = [
        (edge_l[ga[k]], edge_l[gb[k]], seg_l[ga[k]], seg_l[gb[k]], k) for k, f in enumerate(found) if f != []
    ]
    keys += [(k, k, i, i, -1) for k, i in selves]
    jobs: list[_Job] = []
    answers: list[list[_Found] | None] = []
    for ia, ib, i, j, k in sorted(keys):
        ea, eb = everyone[ia], everyone[ib]
        if k < 0:
            jobs.append(_Job(ea, eb, i, j, _curve2d(ea, i), None))
            answers.append(None)
        else:
            jobs.append(_Job(ea, eb, i, j, None, None, True))
            answers.append(found[k])
    return jobs, answers


# above this many edge pairs, planar jobs come from one broad phase over all segments (:func:`_model_jobs`);
# below, edge pair by edge pair (:func:`_close_edge_pairs`, :func:`_pair_jobs`): the same jobs
_ONE_PASS_ABOVE = 16


def _mark_copies(infos: list[_EdgeInfo]) -> list[_EdgeInfo]:
    """Mark every edge whose curve is an earlier edge's, bit for bit (either way round): the others.

    Copies of one edge (a drawing imported with its lines twice, a shape added to itself) all
    overlap each other: ``n`` copies are ``n (n - 1) / 2`` whole overlaps through the core, and
    every other edge meets each copy at the same points. An arrangement keeps one of them.
    """
    boxes: dict[tuple[Any, ...], list[_EdgeInfo]] = {}  # copies share their box: only those are keyed
    for info in infos:
        boxes.setdefault((len(info.rows), info.lo, info.hi), []).append(info)
    for group in boxes.values():
        if len(group) < 2:
            continue
        first: dict[tuple[Any, ...], int] = {}
        for info in group:  # in input order: the first edge of a curve stays
            key = tuple(tuple(map(tuple, rows)) for rows in info.rows)
            back = tuple(tuple(map(tuple, rows[::-1])) for rows in info.rows[::-1])
            index = first.get(key, first.get(back))
            if index is None:
                first[key] = info.index
            else:
                info.copy_of = index
    return [info for info in infos if info.copy_of is None]


def _run(a: Any, b: Any, tol: float | None, *,
         drop_copies: bool = False) -> tuple[str, list[_Raw], float, list[_EdgeInfo]]:
    """The intersections of the edges of ``a`` and ``b`` (None: of ``a`` with itself), cleaned.

    Returns the flavour of ``a``, the results, the model tolerance and the edge infos of ``a``.
    ``drop_copies`` (``b`` None): an edge that repeats an earlier one's curve takes no part
    (its info's ``copy_of`` names the earlier edge; see :func:`_mark_copies`).
    """
    if tol is not None:
        check_tol(tol)  # the type and sign first, before the shapes are read
    flavour = flavour_of(a)
    all_a = _prepare(a, "a")
    infos_a = _mark_copies(all_a) if drop_copies and b is None else all_a
    infos_b = infos_a if b is None else _prepare(b, "b")
    everyone = infos_a if b is None else infos_a + infos_b
    model = all_a if b is None else all_a + infos_b  # copies too: the tolerance and plane of every edge
    box = _joint_box(model)
    # one tolerance for the whole model: the default or the given tol checked against the edges' size,
    # raised to the rounding floor of their control points; not capped again per segment pair
    ftol = ModelTolerance(max(_default_tol(model, box), _box_floor(*box))) if tol is None \
        else check_model_tol(tol, [e.edge for e in model])
    frame = _common_frame(model, ftol, box)
    _set_plane(model, frame)
    if frame is not None and len(infos_a) * len(infos_b) > _ONE_PASS_ABOVE:  # many planar edges: one pass
        jobs, known = _model_jobs(infos_a, infos_b, b is None, ftol)
        answers = _solve(jobs, ftol, b is None, known)
    else:
        jobs = []
        for ia, ib in _close_edge_pairs(infos_a, infos_b, ftol):
            if b is None and ib < ia:
                continue
            ea, eb = infos_a[ia], infos_b[ib]
            same = b is None and ia == ib
            alone = len(everyone) == (1 if same else 2)  # the pair holds every edge
            jobs.extend(_pair_jobs(ea, eb, same, ftol, frame is not None, alone))
        answers = _solve(jobs, ftol, b is None)
    raws: list[_Raw] = []
    pair: list[_Raw] = []  # the results of one edge pair (its jobs are consecutive)
    for k, (job, found) in enumerate(zip(jobs, answers, strict=True)):
        pair.extend(_raw_results(job, found) if found else [])
        if pair and (k + 1 == len(jobs) or jobs[k + 1].ea is not job.ea or jobs[k + 1].eb is not job.eb):
            raws.extend(_clean_pair(pair, b is None and job.ea is job.eb, b is None, ftol))
            pair = []
    return flavour, raws, ftol, all_a


# --------------------------------------------------------------------------- public API
def intersections(a: Any, b: Any = None, *, tol: float | None = None) -> EdgeResultList:
    """Intersect the edges of two shapes (or of one shape with itself): the rich results.

    Parameters
    ----------
    a : shape
        Edges, wires, faces or any shapes (build123d, CadQuery or raw OCP), or a
        list of them. Degenerated edges (poles) are skipped.
    b : shape, optional
        The other shape. ``None``: the self-intersections of ``a``'s edges (an edge
        crossing itself, distinct edges crossing each other), without the shared
        vertices that join consecutive edges.
    tol : float, optional
        Distance tolerance in model units (see the module docstring for the default).

    Returns
    -------
    EdgeResultList
        A list of EdgeIntersection and EdgeOverlap, sorted by ``(index_a, index_b, t)``.
        Parameters are the edges' own; a contact found by two segment pairs (a B-spline
        knot, a shared end) is reported once per edge pair; points inside an overlap are
        absorbed by it. Its ``tol_used`` is the tolerance applied (every ``distance`` is at
        most that).

    Raises
    ------
    ToleranceError
        If ``tol`` is not a finite distance > 0 or exceeds
        :data:`~relief_cad.tolerances.MAX_TOLERANCE_FRACTION` of the edges' joint size.
    InputTypeError
        If an input is not a shape.
    InvalidInputError
        If a shape has no edge with a curve (an empty compound, a vertex).
    DegenerateCurveError
        If an edge has zero length.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakePolygon
    >>> from OCP.gp import gp_Pnt
    >>> square = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0), gp_Pnt(1, 1, 0),
    ...                                     gp_Pnt(0, 1, 0), True).Wire()
    >>> intersections(square)
    []
    """
    flavour, raws, ftol, _ = _run(a, b, tol)
    out = EdgeResultList(tol_used=float(ftol))
    natives: dict[int, Any] = {}

    def native(info: _EdgeInfo) -> Any:
        if id(info) not in natives:
            natives[id(info)] = wrap_edge(info.edge, flavour)
        return natives[id(info)]

    for r in raws:
        ea, eb = r.ea, r.eb
        native_a = native(ea)
        native_b = native(eb)
        approx = ea.approximate or eb.approximate
        if r.kind == "overlap":
            common = wrap_edge(ocp.trim_edge(ea.edge, r.t[0], r.t[1]), flavour)
            out.append(EdgeOverlap(ea.index, eb.index, native_a, native_b, r.t, r.u, common,
                                   approximate=approx))
        else:
            out.append(EdgeIntersection(ea.index, eb.index, native_a, native_b, r.t, r.u, r.point,
                                        r.kind, r.distance, approx))  # type: ignore[arg-type]
    out.sort(key=lambda r: (r.index_a, r.index_b, r.t if isinstance(r, EdgeIntersection) else r.t[0]))
    return out


def intersect(a: Any, b: Any = None, *, tol: float | None = None) -> Any:
    """Intersect the edges of two shapes (or one shape with itself) and return native vertices.

    Parameters
    ----------
    a, b, tol
        As for :func:`intersections`.

    Returns
    -------
    build123d ShapeList[Vertex], list of CadQuery Vertex, or list of TopoDS_Vertex
        In the flavour of ``a``: one vertex per distinct intersection point
        (points closer than ``tol`` merged); an overlap contributes its two end
        points.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.BRep import BRep_Tool
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
    >>> [BRep_Tool.Pnt_s(v).Coord() for v in intersect(a, b)]
    [(1.0, 1.0, 0.0)]
    >>> c = BRepBuilderAPI_MakeEdge(gp_Pnt(5, 5, 0), gp_Pnt(6, 5, 0)).Edge()
    >>> intersect(a, c)
    []
    """
    flavour, raws, ftol, _ = _run(a, b, tol)
    points: list[tuple[float, float, float]] = []
    for r in sorted(raws, key=lambda r: (r.ea.index, r.eb.index, r.t if r.kind != "overlap" else r.t[0])):
        if r.kind == "overlap":
            cands = [ocp.curve_value(r.ea.adaptor, r.t[0]), ocp.curve_value(r.ea.adaptor, r.t[1])]
        else:
            cands = [r.point]
        for p in cands:
            if not any(math.dist(p, q) <= ftol for q in points):
                points.append(p)
    return wrap_vertices([ocp.make_vertex(p) for p in points], flavour)


"""Curve/curve intersection: the public entry points.

:func:`intersect` intersects two rational Bézier curves (planar curves by
Bézier clipping here; space curves are handed to :mod:`relief_cad.space`),
:func:`intersect_line` intersects a planar curve with an infinite line, and
:func:`intersect_many` runs many planar pairs in one compiled call.

The planar solver (one compiled kernel, :mod:`relief_cad._kernels.planar`):

1. moves both curves into a common frame by an exact translation and an exact
   power-of-two scaling (so parameters and exactness are unaffected);
2. projects the four end points on the other curve: end point contacts come out
   with ``t`` or ``u`` exactly ``0.0``/``1.0``; pairs of end point contacts are
   tested for coincidence in between (dense sampling within ``tol``), giving
   :class:`~relief_cad.Overlap` intervals whose ends are exact;
3. Bézier clipping (Sederberg & Nishita) with the fat lines widened by ``tol``,
   alternating roles, a perpendicular fat line when a clip stalls, a split of the
   larger sub-curve when that stalls too, and a "flat band" stop when both
   sub-curves lie within ``tol`` of a line (tangent contacts); a candidate box
   is one where both sub-polygons span at most 1e-7 of the curves' own extent
   (sampled on the curves: a Chebyshev-like polygon can be 1e9 times larger),
   or ``tol``;
4. candidate boxes are clustered; Newton's method on ``a(t) - b(u) = 0`` polishes
   every root, finished with a double-double residual when the root is
   ill-conditioned (high degree, small crossing angle); a root is *certified*
   when that iteration reaches a fixed point in double parameters. Neighbouring
   roots with no measurable gap between them merge into one tangent contact
   (a double root split by rounding) unless both are certified (genuine
   crossings as close as 1e-8 stay two); at an angle no rounded touch shows they
   are one crossing found twice. A cluster without a root is a near-miss: one tangent contact
   at the closest approach when the gap is within ``tol`` and no root or end meeting
   lies down the valley from it (a stalled iteration on a small-angle crossing's flank);
5. the kind is ``"crossing"`` for a certified (simple) root unless the tangents
   are parallel to ``|sin| < 1e-12``; an uncertified root (a double or triple
   root as far as double-double can tell) is ``"tangent"`` when ``|sin| < 1e-7``
   (isolated) or ``< 1e-10`` (in a cluster of several roots); so an osculating
   contact that crosses (``y = x**3`` against ``y = 0``) is ``"tangent"``. End
   point contacts are ``"tangent"`` when ``|sin| < 1e-7``;
6. a post-pass (:mod:`relief_cad.contacts`, plain Python on the candidates only;
   skipped when every result is an interior crossing) decides by geometry:
   consecutive contacts joined by a stretch within ``tol`` both ways are one
   :class:`~relief_cad.Overlap` (whatever the parameterisations: doubled control
   points, elevated or reversed copies, retracing curves); two contacts closer than
   1e-6 in both parameters are one double root ("tangent") when the exact sign of the
   signed distance (the binary64 data taken as exact rationals) does not change
   between them, else two simple roots ("crossing"); end meetings where a derivative
   vanishes are classified by the first non-vanishing derivatives (tangent when
   ``|sin| < 1e-7``, so a fold-back at 180 degrees is tangent); interior tangent
   contacts are placed at the simple root of the lowest derivative of the tangency
   function that has one (osculating contacts to 1e-9 on exact data).

Accuracy: transversal crossings to a few ulps of the parameters (1e-13 on the
certified corpora, including Chebyshev-like curves of degree 20 to 40 and crossings 1e-8
apart); tangent contacts to about 1e-9, including osculating ones.

>>> from relief_cad.curves import RationalBezier
>>> loop = RationalBezier([[0, 0], [3, 3], [-1, 3], [2, 0]])
>>> [(round(r.t, 6), round(r.u, 6), r.kind) for r in intersect(loop)]   # its double point, t < u
[(0.172673, 0.827327, 'crossing')]
"""

from __future__ import annotations

import functools
import gc
import math
from collections.abc import Iterable, Sequence

import numpy as np
from numpy.typing import NDArray

from ._checks import (
    DEFAULT_BUDGET,
    OnBudget,
    as_real_array,
    check_budget,
    check_curve,
    check_on_budget,
    check_tol,
    check_workers,
)
from ._kernels import (
    intersect_batch_kernel,
    intersect_one_kernel,
    pack_pairs,
    planar_pair,
)
from ._kernels.rows import batch_lists, rows_to_list
from ._pool import run_ordered
from ._types import FloatArray
from .contacts import _needs_refining, _refine_contacts, _refine_self, _self_overlaps, _whole_overlap
from .curves import RationalBezier
from .errors import (
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ShapeError,
)
from .pieces import _along_chord, _monotone_pieces, _one_place
from .results import Intersection, IntersectionList, Overlap, ParameterBox, Result, _finish
from .space import intersect_space, space_pair
from .tolerances import (
    _pairs_default_tolerances,
    _resolve_tolerance,
    _rounding_floor,
    _sampled_tolerance,
    default_tolerance,
)

__all__ = [
    "DEFAULT_BUDGET",
    "intersect",
    "intersect_line",
    "intersect_many",
]



def _ro(arr: FloatArray) -> FloatArray:
    """A read-only C-contiguous float64 array (the one array type the kernels are compiled for)."""
    if arr.flags.writeable or not arr.flags.c_contiguous or arr.dtype != np.float64:
        arr = np.array(arr, dtype=np.float64, order="C")
        arr.flags.writeable = False
    return arr


def _planar(pa: FloatArray, wa: FloatArray, pb: FloatArray, wb: FloatArray, tol: float,
            budget: int) -> IntersectionList:
    """Run the pair kernel on arrays made read-only C float64 first."""
    rows = intersect_one_kernel(_ro(pa), _ro(wa), _ro(pb), _ro(wb), tol, budget)
    res: IntersectionList = rows_to_list(rows, tol)[0]
    return res


def _refined(a: RationalBezier, b: RationalBezier, res: IntersectionList, tol: float) -> IntersectionList:
    """The kernel's result decided by :func:`relief_cad.contacts.refine_contacts`."""
    if not _needs_refining(a, b, res):
        return res
    return IntersectionList(_refine_contacts(a, b, res, tol), res.unresolved)


def _split_homogeneous(h: FloatArray, name: str) -> tuple[FloatArray, FloatArray]:
    h = np.ascontiguousarray(h, dtype=np.float64)
    if h.ndim != 2 or h.shape[1] != 3 or h.shape[0] < 2:
        raise ShapeError(f"{name} should have shape (n + 1, 3) with n >= 1, not {h.shape}")
    w = np.ascontiguousarray(h[:, 2])
    if not np.all(np.isfinite(h)):
        raise NonFiniteError(f"{name} should be finite")
    if not np.all(w > 0.0):
        raise InvalidInputError(f"{name} weights (last column) should all be > 0")
    return np.ascontiguousarray(h[:, :2] / w[:, None]), w


def _intersect_planar(hA: FloatArray, hB: FloatArray | None, tol: float,
                      budget: int = DEFAULT_BUDGET) -> IntersectionList:
    """Planar intersection on homogeneous control points (internal; used by ``space.py``).

    Contract
    --------
    ``hA`` and ``hB`` are ``(n + 1, 3)`` arrays of rows ``(w x, w y, w)`` with
    finite entries and ``w > 0``; ``hB=None`` asks for the self-intersections of
    ``hA``. ``tol`` is a finite distance > 0 in the units of ``x, y``. Returns an
    :class:`~relief_cad.IntersectionList` sorted by ``t``, with parameters of the
    given curves (``t`` on ``hA``, ``u`` on ``hB``) and points of shape ``(2,)``;
    it never raises on a budget: the unresolved parameter boxes are in
    ``.unresolved``. Raises :class:`~relief_cad.errors.ShapeError` /
    :class:`~relief_cad.errors.InvalidInputError` on malformed arrays.

    Examples
    --------
    >>> ha = np.array([[0.0, 0.0, 1.0], [2.0, 2.0, 1.0]])
    >>> hb = np.array([[0.0, 2.0, 1.0], [2.0, 0.0, 1.0]])
    >>> [(r.t, r.u, r.kind) for r in _intersect_planar(ha, hb, 1e-9)]
    [(0.5, 0.5, 'crossing')]
    """
    pa, wa = _split_homogeneous(hA, "hA")
    if hB is None:
        return _self_planar(RationalBezier(pa, wa), tol, budget)
    pb, wb = _split_homogeneous(hB, "hB")
    return _planar(pa, wa, pb, wb, tol, budget)


@functools.cache
def _chord_pairs(n: int) -> tuple[NDArray[np.intp], NDArray[np.intp]]:
    """Row indices ``(i, j)``, ``i < j``, of the chords of ``n`` control points (``triu_indices``)."""
    i, j = np.triu_indices(n, 1)
    return i, j


def _simple_piece(p: FloatArray) -> bool:
    """True when every chord ``p_j - p_i`` (i < j) lies in one open half-plane.

    Then the (rational) curve is monotone along some direction and cannot cross itself.
    :func:`relief_cad.pieces.along_chord` decides most pieces first (its half-plane is the chord's).
    """
    if _along_chord(p.tolist()):
        return True
    i, j = _chord_pairs(p.shape[0])
    v = p[j] - p[i]
    v = v[np.hypot(v[:, 0], v[:, 1]) > 0.0]
    if v.shape[0] == 0:
        return True
    ang = np.arctan2(v[:, 1], v[:, 0])
    ang.sort()
    widest = max(float(np.diff(ang).max(initial=-np.inf)), float(ang[0] + 2 * np.pi - ang[-1]))
    return widest > np.pi + 1e-12


def _self_planar(curve: RationalBezier, tol: float, budget: int) -> IntersectionList:
    """Self-intersections: split into monotone pieces, intersect pairs of pieces."""
    pieces = _monotone_pieces(curve, tol, _simple_piece, 10)
    items: list[Result] = []
    boxes: list[ParameterBox] = []
    overlaps: list[tuple[Overlap, bool]] = []
    for i in range(len(pieces)):
        for j in range(i + 1, len(pieces)):
            s0, s1, ci = pieces[i]
            r0, r1, cj = pieces[j]
            sub = _refined(ci, cj, _planar(ci.control_points, ci.weights, cj.control_points,
                                           cj.weights, tol, budget), tol)
            for r in sub:
                if isinstance(r, Overlap):  # a stretch the curve runs along twice
                    overlaps.append((_global_overlap(r, s0, s1, r0, r1), True))
                    continue
                t = s0 + r.t * (s1 - s0) if r.t not in (0.0, 1.0) else (s0 if r.t == 0.0 else s1)
                u = r0 + r.u * (r1 - r0) if r.u not in (0.0, 1.0) else (r0 if r.u == 0.0 else r1)
                if abs(t - u) <= 1e-7 or _one_place(curve, t, u, tol):
                    continue  # the joint of adjacent pieces, or both sides of a sharp tip
                if any(isinstance(q, Intersection) and abs(q.t - t) <= 1e-9 and abs(q.u - u) <= 1e-9
                       for q in items):
                    continue
                items.append(Intersection(t, u, r.point, r.kind, r.distance))
            for bx in sub.unresolved:
                boxes.append(ParameterBox(s0 + bx.t0 * (s1 - s0), s0 + bx.t1 * (s1 - s0),
                                          r0 + bx.u0 * (r1 - r0), r0 + bx.u1 * (r1 - r0)))
    return IntersectionList(_refine_self(curve, [*items, *_self_overlaps(overlaps, curve)], tol), boxes)


def _global_overlap(r: Overlap, s0: float, s1: float, r0: float, r1: float) -> Overlap:
    """A piece pair's overlap in the whole curve's parameters (piece ends mapped exactly)."""
    def on(x: float, lo: float, hi: float) -> float:
        return lo if x == 0.0 else hi if x == 1.0 else lo + x * (hi - lo)

    return Overlap(t=(on(r.t[0], s0, s1), on(r.t[1], s0, s1)), u=(on(r.u[0], r0, r1), on(r.u[1], r0, r1)))


def intersect(a: RationalBezier, b: RationalBezier | None = None, *, tol: float | None = None,
              budget: int | None = None, on_budget: OnBudget = "raise") -> IntersectionList:
    """Intersect two rational Bézier curves (or find the self-intersections of one).

    Parameters
    ----------
    a, b : RationalBezier
        The curves. ``b=None`` gives the self-intersections of ``a`` (each double
        point once, with ``t < u``). Planar curves are intersected by Bézier
        clipping; when either curve is a space curve the pair goes to the relief
        perspective intersector (:mod:`relief_cad.space`).
    tol : float, optional
        Distance tolerance in model units: a near-miss closer than ``tol`` is a
        tangent contact at the closest approach, a wider gap is no intersection.
        Default :func:`relief_cad.tolerances.default_tolerance` of both curves'
        control points (``1e-9`` of their size plus rounding). A given ``tol`` is
        raised to the rounding floor of the data and may be at most
        :data:`~relief_cad.tolerances.MAX_TOLERANCE_FRACTION` (1e-2) of the curves'
        size: within that cap the answer does not depend on the order of ``a``
        and ``b`` (see :func:`relief_cad.tolerances.resolve_tolerance`).
    budget : int, optional
        Cap on clipping iterations (default :data:`DEFAULT_BUDGET`).
    on_budget : {"raise", "return"}
        What to do when the budget runs out: raise
        :class:`~relief_cad.errors.BudgetExceededError` (with ``.partial`` and
        ``.unresolved``) or return the partial list with ``.unresolved`` filled.

    Returns
    -------
    IntersectionList
        :class:`~relief_cad.Intersection` and :class:`~relief_cad.Overlap`
        objects sorted by ``t``. End point contacts have ``t``/``u`` exactly
        ``0.0`` or ``1.0``. ``tol_used`` is the tolerance applied; every
        point has ``distance <= tol_used``.

    Raises
    ------
    InputTypeError
        If ``a`` or ``b`` is not a :class:`~relief_cad.RationalBezier`.
    ToleranceError
        If ``tol`` is not a finite distance > 0, or exceeds the cap.
    BudgetExceededError
        If the budget runs out and ``on_budget="raise"``.

    Examples
    --------
    >>> from relief_cad.curves import RationalBezier
    >>> a = RationalBezier([[0, 0], [1, 2], [2, 0]])
    >>> b = RationalBezier([[0, 0.5], [2, 0.5]])
    >>> [(round(r.t, 12), round(r.u, 12), r.kind) for r in intersect(a, b)]
    [(0.146446609407, 0.146446609407, 'crossing'), (0.853553390593, 0.853553390593, 'crossing')]
    >>> c = RationalBezier([[0, 0], [1, 1], [2, 0]])
    >>> intersect(c, RationalBezier([[0, 0.5], [2, 0.5]]))[0].kind
    'tangent'
    """
    if type(a) is not RationalBezier:  # the exact class needs no further look (hot path)
        check_curve(a, "a")
    if b is not None and type(b) is not RationalBezier:
        check_curve(b, "b")
    if type(on_budget) is not str or on_budget != "raise":  # the default needs no further check
        check_on_budget(on_budget)
    nbudget = DEFAULT_BUDGET if budget is None else check_budget(budget)
    if b is None:
        if a.control_points.shape[1] == 3:
            result: IntersectionList = intersect_space(a, b, tol=tol, budget=budget, on_budget=on_budget)
            return result
        ftol = _resolve_tolerance(check_tol(tol), a)
        # the curve of a's own points and weights, as built from them (the same rows for every a)
        curve = RationalBezier._rebuilt(a.control_points, a.weights)
        return _finish(_with_tol(_self_planar(curve, ftol, nbudget), ftol), on_budget)
    # the default, or the given tol raised to the data's rounding level (one rule: resolve_tolerance;
    # _sampled_tolerance is its compiled default for two curves)
    ftol = (_sampled_tolerance((a, b)) if tol is None else None) or _resolve_tolerance(check_tol(tol), a, b)
    # planar pairs in one compiled call (planar_pair: the curves' kernel views, the kernel, the
    # result list). Curves whose end points match within 2 tol (a margin for the exact rescaling of
    # huge coordinates there) may coincide all along, the clipping's slowest case: whole_overlap
    # decides them by geometry first
    got = planar_pair(a, b, ftol, nbudget)
    if got is None:  # a space curve: the relief scheme, with the tolerance resolved above
        return space_pair(a, b, check_tol(tol), nbudget, on_budget, ftol)
    if got is False:
        whole = _whole_overlap(a, b, ftol)
        if whole is not None:
            return IntersectionList([whole], tol_used=ftol)
        got = planar_pair(a, b, ftol, nbudget, False)
    res: IntersectionList
    res, final = got
    if not final and (res.unresolved or _needs_refining(a, b, res)):
        res = _finish(_with_tol(_refined(a, b, res, ftol), ftol), on_budget)
    return res


def _with_tol(res: IntersectionList, tol: float) -> IntersectionList:
    """``res`` with :attr:`~relief_cad.IntersectionList.tol_used` set to ``tol``."""
    res.tol_used = tol
    return res


def intersect_line(curve: RationalBezier, point: Sequence[float] | FloatArray,
                   direction: Sequence[float] | FloatArray, *, tol: float | None = None,
                   budget: int | None = None, on_budget: OnBudget = "raise") -> IntersectionList:
    """Intersect a planar curve with the infinite line ``point + s * direction``.

    Parameters
    ----------
    curve : RationalBezier
        A planar curve.
    point, direction : array_like, shape (2,)
        A point of the line and its (nonzero) direction.
    tol : float, optional
        Distance tolerance (default from the curve's control points and the point of the line
        nearest their middle: where along the line ``point`` lies does not matter);
        raised to the rounding floor, capped by the curve's size as in :func:`intersect`.
    budget, on_budget
        As for :func:`intersect`.

    Returns
    -------
    IntersectionList
        Results with ``t`` on the curve and ``u`` the line parameter ``s``
        (any real number), sorted by ``t``: :class:`Intersection` points, and an
        :class:`Overlap` for a stretch of the curve lying on the line (within
        ``tol``), with ``u`` the line's parameters at its ends.

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier.
    ShapeError
        If ``point`` or ``direction`` is not a 2-vector, or the curve is not planar.
    InvalidInputError
        If ``direction`` is zero or not finite.

    Examples
    --------
    >>> from relief_cad.curves import RationalBezier
    >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]])
    >>> [(r.t, r.u) for r in intersect_line(c, (0, 0.75), (1, 0))]
    [(0.25, 0.5), (0.75, 1.5)]
    >>> intersect_line(RationalBezier([[1, 0], [3, 0]]), (0, 0), (2, 0))
    [Overlap(t=(0.0, 1.0), u=(0.5, 1.5), kind='overlap')]
    """
    check_curve(curve, "curve")
    if curve.dim != 2:
        raise ShapeError(f"intersect_line needs a planar curve (dim 2), not dim {curve.dim}")
    p = as_real_array(point, "point")
    d = as_real_array(direction, "direction")
    if p.shape != (2,) or d.shape != (2,):
        raise ShapeError(f"point and direction should have shape (2,), not {p.shape} and {d.shape}")
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(d))):
        raise NonFiniteError("point and direction should be finite")
    length = math.hypot(float(d[0]), float(d[1]))
    if length == 0.0:
        raise InvalidInputError(f"direction should be nonzero, not ({float(d[0]):g}, {float(d[1]):g})")
    check_on_budget(on_budget)
    nbudget = check_budget(budget)
    given = check_tol(tol)
    pts = curve.control_points
    # the line through the foot of the curve's middle, by a unit direction: the curve and its
    # line segment stay in the curve's own scale, however far the given point lies along the line
    # (at 1e12 along, the tolerance grew to 1e3 and the crossing came out 0.5 off) and however
    # long the direction (|d|^2 overflowed at 1e160 and was subnormal at 1e-160)
    e = np.array([float(d[0]) / length, float(d[1]) / length])
    shift = float((0.5 * (pts.min(axis=0) + pts.max(axis=0)) - p) @ e)
    foot = p + shift * e
    res, ftol = _line_results(curve, foot, e, given, nbudget)
    items: list[Result] = []
    for r in res:
        if isinstance(r, Intersection):
            pt = curve.evaluate(r.t) if r.kind == "crossing" else r.point
            su = (float((np.asarray(pt) - foot) @ e) + shift) / length
            items.append(Intersection(r.t, su, r.point, r.kind, r.distance))
        else:  # a stretch of the curve along the line: u is the line's parameter at its ends
            u0, u1 = ((float((curve.evaluate(t) - foot) @ e) + shift) / length for t in r.t)
            items.append(Overlap(t=r.t, u=(u0, u1)))
    return _finish(IntersectionList(items, res.unresolved, ftol), on_budget)


def _line_results(curve: RationalBezier, foot: FloatArray, e: FloatArray, given: float | None,
                  budget: int) -> tuple[IntersectionList, float]:
    """The planar results of ``curve`` against the line ``foot + s e`` (``e`` a unit vector), and the tol."""
    pts = curve.control_points
    s = (pts - foot) @ e
    lo = float(min(s.min(), 0.0))
    hi = float(max(s.max(), 0.0))
    # the default (curve and foot), or the given tol checked against the curve
    base = default_tolerance(curve, foot[None, :]) if given is None else _resolve_tolerance(given, curve)
    # 1 % beyond the curve's extent along the line, in the curve's own scale (a fixed pad of one
    # direction length made the segment, and its rounding floor, huge beside a tiny curve), and
    # longer than the tolerance: a curve shorter than the rounding of its coordinates (one ulp at
    # x = 1) made both ends of the segment round to one point, and its crossing was lost
    ext = max(hi - lo, float(np.ptp(pts, axis=0).max()))
    pad = max(0.01 * ext, 4.0 * base)
    seg = np.array([foot + (lo - pad) * e, foot + (hi + pad) * e])
    # raised to the rounding floor of the segment that stands for the line
    ftol = max(base, _rounding_floor(curve, RationalBezier(seg)))
    return _planar(pts, curve.weights, seg, np.ones(2), ftol, budget), ftol


def _batch_job(out: list[IntersectionList], start: int, part: list[tuple[RationalBezier, RationalBezier]],
               lim: float, tol: float | None, budget: int,
               on_budget: OnBudget) -> tuple[list[int], Exception | None]:
    """One chunk of :func:`intersect_many`'s pairs, ``part`` (from pair ``start``): ``(rest, error)``.

    The planar pairs that cannot coincide all along (``lim``: see
    :func:`relief_cad._kernels.batch.pack_pairs`) are packed, and their result lists are put in
    ``out`` at their places; ``rest`` lists the indices (in ``part``) of the others. ``error`` is
    that of the first taken pair that raised, or None (the caller raises it in its turn, after
    any error of the ``rest``). Each pair's tolerance is resolved (``tol`` None: each pair's
    default), the batch kernel runs without the GIL and the result objects are made with it:
    on a thread, one chunk is packed and its objects made while another chunk's kernel runs.
    """
    taken, rest, pts, wts, offsets = pack_pairs(part, RationalBezier, lim)
    pairs = [part[k] for k in taken]
    try:
        tols = (_pairs_default_tolerances(pairs) if tol is None
                else np.array([_resolve_tolerance(tol, *pr) for pr in pairs]))
        idx = np.arange(2 * len(pairs), dtype=np.int64).reshape(-1, 2)
        rows = intersect_batch_kernel(pts, wts, offsets, idx, tols, budget)
        lists, looks = batch_lists(rows, tols)  # by pair, each by t (the kernel's order)
        for j in looks:  # the pairs whose rows a budget left open or that refining may change
            listed, (a, b) = lists[j], pairs[j]
            if listed.unresolved or _needs_refining(a, b, listed):
                lists[j] = _finish(_with_tol(_refined(a, b, listed, listed.tol_used), listed.tol_used),
                                   on_budget)
    except Exception as exc:  # noqa: BLE001 - raised by the caller, in order
        return rest, exc
    for k, listed in zip(taken, lists, strict=True):
        out[start + k] = listed
    return rest, None


def _rest_pair(plist: Sequence[object], k: int, tol: float | None, budget: int,
               on_budget: OnBudget) -> IntersectionList:
    """Item ``k`` of :func:`intersect_many`'s pairs that the batch kernel does not take, checked first."""
    pr = plist[k]
    if not isinstance(pr, tuple) or len(pr) != 2:
        raise InputTypeError(f"pairs[{k}] should be a tuple (a, b), not {type(pr).__name__}")
    a, b = pr
    if not isinstance(a, RationalBezier):
        check_curve(a, f"pairs[{k}][0]")
    if not isinstance(b, RationalBezier):
        check_curve(b, f"pairs[{k}][1]")
    return intersect(a, b, tol=tol, budget=budget, on_budget=on_budget)


_EMPTY = IntersectionList()  # a place of intersect_many's output before its list is put there
_MIN_CHUNK = 64  # pairs per thread task, at least: below that the pool costs more than it gains


def intersect_many(pairs: Iterable[tuple[RationalBezier, RationalBezier]], *,
                   tol: float | None = None, budget: int | None = None,
                   on_budget: OnBudget = "raise", workers: int | None = None) -> list[IntersectionList]:
    """Intersect many curve pairs; planar pairs run in compiled calls on a thread pool.

    Parameters
    ----------
    pairs : iterable of (RationalBezier, RationalBezier)
        The pairs.
    tol : float, optional
        One tolerance for every pair; default: each pair's own default tolerance.
        Resolved per pair as in :func:`intersect` (floor and cap; each list's ``tol_used``).
    budget, on_budget
        As for :func:`intersect` (the budget is per pair).
    workers : int, optional
        Threads for the planar pairs (default ``os.cpu_count()``); the results are the same,
        in the same order, for any value.

    Returns
    -------
    list of IntersectionList
        One result list per pair, in order.

    Raises
    ------
    InputTypeError
        If ``pairs`` is not an iterable of ``(a, b)`` tuples of curves, or ``workers`` not an int.
    InvalidInputError
        If ``workers < 1``.

    Examples
    --------
    >>> from relief_cad.curves import RationalBezier
    >>> a = RationalBezier([[0, 0], [2, 2]])
    >>> b = RationalBezier([[0, 2], [2, 0]])
    >>> [[r.t for r in lst] for lst in intersect_many([(a, b), (b, a)], workers=2)]
    [[0.5], [0.5]]
    """
    if not isinstance(pairs, Iterable):
        raise InputTypeError(f"pairs should be an iterable of (a, b) tuples, not {type(pairs).__name__}")
    plist = list(pairs)
    check_on_budget(on_budget)
    nbudget = check_budget(budget)
    ftol = check_tol(tol)
    nworkers = check_workers(workers)
    n = len(plist)
    out: list[IntersectionList] = [_EMPTY] * n  # every place is filled below, or an error raised
    lim = -1.0 if ftol is None else 2.0 * ftol
    size = max(1, n) if nworkers <= 1 or n < 2 * _MIN_CHUNK else max(_MIN_CHUNK, -(-n // (4 * nworkers)))
    # many small objects at once: keep the cyclic GC from rescanning them repeatedly
    gc_enabled = gc.isenabled()
    gc.disable()
    try:
        # each chunk is packed, run and made into result lists by one task of the pool (one
        # task packs while another's kernel runs); the pairs it does not take (and any bad
        # item, which raises first) go through intersect one by one, then a chunk's error is
        # raised in its turn
        starts = range(0, n, size)
        chunks = run_ordered(lambda s: _batch_job(out, s, plist[s:s + size], lim, ftol, nbudget, on_budget),
                             starts, nworkers)
        for start, (rest, _) in zip(starts, chunks, strict=True):
            for k in rest:
                out[start + k] = _rest_pair(plist, start + k, ftol, nbudget, on_budget)
        for _, error in chunks:
            if error is not None:
                raise error
    finally:
        if gc_enabled:
            gc.enable()
    return out

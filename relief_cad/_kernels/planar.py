"""The planar pair driver.

End points, overlaps, the clipping loop, clusters of candidates, their polish and
classification, merging and the result rows.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import hypot, sqrt

from .bezier import _cartesian, _curve_box_update, _eval, _frame, _grow, _homog_into, _segment
from .certify import _polish_dd, _side_dd
from .clip import clip_range_kernel, cones_apart, fat_line_kernel
from .constants import (
    _EPS,
    _ROUND,
    _SPLIT_RATIO,
    KIND_CROSSING,
    KIND_OVERLAP,
    KIND_TANGENT,
    KIND_UNRESOLVED,
    RES_COLS,
)
from .polish import _angle_sin, _closest, _coincide, _local_dist, _local_proj, _newton, _point_on

_INF = cython.declare(cython.double, math.inf)  # a C constant (``math.inf`` is a Python lookup)
# constants.py is plain Python (its names are Python objects): C copies for the loops
_C_EPS = cython.declare(cython.double, _EPS)
_C_ROUND = cython.declare(cython.double, _ROUND)
_C_SPLIT_RATIO = cython.declare(cython.double, _SPLIT_RATIO)
_K_CROSSING = cython.declare(cython.double, KIND_CROSSING)
_K_TANGENT = cython.declare(cython.double, KIND_TANGENT)
_K_OVERLAP = cython.declare(cython.double, KIND_OVERLAP)
_K_UNRESOLVED = cython.declare(cython.double, KIND_UNRESOLVED)
_NSMALL = cython.declare(cython.Py_ssize_t, 24)  # candidates and points held in the scratch buffer
_NRES = cython.declare(cython.Py_ssize_t, 64)  # result rows made with the scratch when res is None
_ROUNDING_ROOT = cython.declare(cython.double, 0.5)  # column 5 of a point: a root only rounding makes


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _in_overlap(
    ov: cython.double[:, :],
    nov: cython.Py_ssize_t,
    t0: cython.double,
    t1: cython.double,
    u0: cython.double,
    u1: cython.double,
    margin: cython.double,
) -> cython.bint:
    """True when the box lies inside one overlap's parameter rectangle (plus margin)."""
    k: cython.Py_ssize_t
    for k in range(nov):
        a0 = ov[k, 0] - margin
        a1 = ov[k, 1] + margin
        b0 = min(ov[k, 2], ov[k, 3]) - margin
        b1 = max(ov[k, 2], ov[k, 3]) + margin
        if t0 >= a0 and t1 <= a1 and u0 >= b0 and u1 <= b1:
            return True
    return False


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
@cython.inline
def _one_contact(gap: cython.double, d: cython.double, floor: cython.double) -> cython.bint:
    """True when a contact ``d`` apart and another, the curves at most ``gap`` apart between, are one.

    The rounding noise of a contact parts the curves by no more than its own distance; between
    two contacts the curves must part by more than the data's rounding (``floor``) and 4 times
    that for them to be two.
    """
    return gap <= max(4.0 * d, floor)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _two_roots(pts: cython.double[:, :], i: cython.Py_ssize_t, j: cython.Py_ssize_t, rnd: cython.double,
               gap: cython.double, floor: cython.double, k_tangent: cython.double,
               k_crossing: cython.double) -> cython.bint:
    """True when points ``i`` and ``j`` are a contact (an end meeting, a touch) and a crossing root: two.

    Within 1e-3 in parameter, with the curves within tol all along between them (at most ``gap``
    apart), such a contact and a root are otherwise one contact. But the root is another contact
    when between them the curves part by more than the data's rounding (``floor``) and 4 times the
    contact's own distance: a spline through a circle's point that crosses it again 1e-4 of a span
    away, 1e-10 off it between; a curve crossing its mirror image 7e-4 before it touches it. The
    rounding noise of a touch parts by no more than the touch's own distance. An end meeting closer
    than rounding (``<= rnd``) is also another root than a crossing more than 1e-4 away in both
    parameters, the curves parting by more than ``floor`` between (the crossing of a loop thinner
    than tol next to the end: a self-intersection's pieces meeting near a cusp). Within ``floor``
    all along, the crossing is the rounding of the end's own contact: ellipses of size 0.02 in
    contact of order four at their seam (one common point) crossed 2.5e-4 either side of it.
    """
    e: cython.Py_ssize_t = i if pts[i, 4] == 2.0 or pts[i, 3] == k_tangent else j
    r: cython.Py_ssize_t = j if e == i else i
    if not ((pts[e, 4] == 2.0 or pts[e, 3] == k_tangent) and pts[r, 4] == 1.0 and pts[r, 3] == k_crossing):
        return False
    if (pts[e, 4] == 2.0 and pts[e, 2] <= rnd and abs(pts[i, 0] - pts[j, 0]) > 1e-4
            and abs(pts[i, 1] - pts[j, 1]) > 1e-4 and gap > floor):
        return True
    return not _one_contact(gap, pts[e, 2], floor)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _root_resolution(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                     t: cython.double, u: cython.double, rnd: cython.double, wa: cython.double[:, :],
                     wb: cython.double[:, :]) -> cython.double:
    """How far apart the curves at a root may come out at ``(t, u)``, in the frame.

    16 ``rnd``, and 4 ulps of each parameter times the curve's speed there: a curve running fast,
    pinched by its weights, moves by more than rounding between neighbouring parameters.
    """
    _ax, _ay, adx, ady, _a2, _a3 = _eval(HA, t, wa)
    _bx, _by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
    ulp: cython.double = _C_EPS
    return 16.0 * rnd + 4.0 * ulp * (hypot(adx, ady) * max(abs(t), ulp) + hypot(bdx, bdy) * max(abs(u), ulp))


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _gap_between(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                 t0: cython.double, u0: cython.double, t1: cython.double, u1: cython.double,
                 wa: cython.double[:, :], wb: cython.double[:, :]) -> cython.double:
    """The largest distance from ``a`` to ``b`` at 7 points evenly spaced from (t0, u0) to (t1, u1)."""
    q: cython.Py_ssize_t
    gap: cython.double = 0.0
    for q in range(1, 8):
        f = q / 8.0
        x, y, _a, _b, _c, _d = _eval(HA, t0 + f * (t1 - t0), wa)
        gap = max(gap, _local_dist(HB, x, y, u0 + f * (u1 - u0), wb))
    return gap


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flank_root(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                t: cython.double, u: cython.double, d: cython.double, rnd: cython.double,
                floor: cython.double, wa: cython.double[:, :], wb: cython.double[:, :]
                ) -> tuple[cython.double, cython.double, cython.double]:
    """The crossing on whose flank a cluster's closest approach ``(t, u)``, ``d`` apart, lies.

    Along a crossing at a small angle the distance has a long narrow valley, where the damped
    iteration of :func:`_closest` stalls: a spline fitted to an arc, crossing it at sin 1.4e-5,
    gave 6 "touches" 1e-8 to 2e-8 off it, up to 2e-3 from the crossing (which a pass that chains
    touches then made an overlap). A root that Newton reaches from there, the curves between them
    no farther apart than ``max(4 d, floor)`` (one contact, as in :func:`_two_roots`), is the
    cluster's contact: returned with distance ``-1`` (else ``(t, u, d)`` as given). So is the
    closest approach itself when it is a root (``d <= rnd``): one at an end of a span, where
    Newton's iterates left the unit square, is no touch unless its angle says so.
    """
    if d <= rnd:
        return t, u, -1.0
    t2, u2, r2 = _newton(HA, HB, t, u, wa, wb, 60)
    if r2 > rnd or not _one_contact(_gap_between(HA, HB, t, u, t2, u2, wa, wb), d, floor):
        return t, u, d
    return t2, u2, -1.0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _crosses(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :], t: cython.double,
             u: cython.double, rnd: cython.double, wa: cython.double[:, :],
             wb: cython.double[:, :]) -> cython.bint:
    """True when curves meeting at ``(t, u)`` (a root up to rounding) cross at an angle no touch shows.

    A touch found to within rounding (``|a - b| <= rnd``) may lie ``s = sqrt(rnd / c)`` along from
    the true touch (``c`` half the relative curvature), where the tangents make ``sin ~ 2 c s =
    2 sqrt(c rnd)``: 2.4e-7 at curvature 1 in the frame. A crossing's angle is its own. So the
    meeting crosses when ``sin >= max(1e-7, 8 sqrt(rnd (ka + kb)))`` (``ka``, ``kb`` the
    curvatures); never where a first derivative vanishes (a cusp: the post-pass decides).
    """
    _ax, _ay, adx, ady, addx, addy = _eval(HA, t, wa)
    _bx, _by, bdx, bdy, bddx, bddy = _eval(HB, u, wb)
    la = hypot(adx, ady)
    lb = hypot(bdx, bdy)
    if la == 0.0 or lb == 0.0:
        return False
    ka = abs(adx * addy - ady * addx) / (la * la * la)
    kb = abs(bdx * bddy - bdy * bddx) / (lb * lb * lb)
    return abs(adx * bdy - ady * bdx) / (la * lb) >= max(1e-7, 8.0 * sqrt(rnd * (ka + kb)))


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _unmeasured_crossing(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                         t: cython.double, u: cython.double, level: cython.double, wa: cython.double[:, :],
                         wb: cython.double[:, :], da: cython.double[:, :],
                         db: cython.double[:, :]) -> cython.bint:
    """True when ``a`` keeps to one side of ``b`` across a root ``(t, u)``, once apart by ``level``.

    Walking out from the root on each side of ``t`` (steps growing by 1.5 from 1e-10 to 0.05), the
    first signed distance of ``a`` from ``b`` (:func:`_side_dd`: double-double, the data taken
    exactly) above ``level`` has the same sign on both sides. False when a side runs off the curve
    first, or stays within ``level`` up to 0.05.
    """
    e: cython.int
    sides: cython.int = 0
    d: cython.double
    g: cython.double
    for e in range(-1, 2, 2):
        d = 1e-10
        uu: cython.double = u
        g = 0.0
        while d < 0.05 and abs(g) <= level:
            tt: cython.double = t + e * d
            if tt < 0.0 or tt > 1.0:
                return False
            x, y, _a, _b, _c, _d = _eval(HA, tt, wa)
            uu = _local_proj(HB, x, y, uu, wb)
            g = _side_dd(HA, HB, tt, uu, wb, da, db)
            d *= 1.5
        if abs(g) <= level:
            return False
        sides += 1 if g > 0.0 else -1
    return sides != 0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _rounding_root(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                   t: cython.double, u: cython.double, alone: cython.bint, floor: cython.double,
                   wa: cython.double[:, :], wb: cython.double[:, :], da: cython.double[:, :],
                   db: cython.double[:, :]) -> cython.bint:
    """True when a certified root at ``(t, u)`` at a tiny angle is no crossing of the data: a touch.

    - The exact data do not cross there (the first gap above double-double's rounding, 1e-28,
      has one sign both ways): a Bezier arc of an ellipse and a circle osculating it at its vertex
      (contact of order four) met in double evaluation at roots 4.7e-5 either side of the
      vertex, where the data are 1e-16 apart, the tangents at sin 4e-12.
    - Or ``alone`` (the cluster's only root, or one at sin below 1e-12, a touch's by the angle
      alone) and the curves part to one side both ways by more than rounding (``4 floor``): a
      touch crosses an even number of times, and the clusters missed the other crossing (the same
      contact with the circle turned by 0.3), or rounding made two (a parabola and its osculating
      circle at the vertex, both spans converted from OCCT, cross 3.7e-4 apart at sin 1e-13).

    Two roots of a cluster however close stay crossings where the data cross: a parabola
    crossing a line at exact roots 7e-9 apart is 1e-17 below it between them.
    """
    if _unmeasured_crossing(HA, HB, t, u, 1e-28, wa, wb, da, db):
        return True
    return alone and _unmeasured_crossing(HA, HB, t, u, 4.0 * floor, wa, wb, da, db)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flank_of(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
              pts: cython.double[:, :], i: cython.Py_ssize_t, j: cython.Py_ssize_t, rnd: cython.double,
              floor: cython.double, wa: cython.double[:, :], wb: cython.double[:, :]) -> cython.Py_ssize_t:
    """Which of points ``i``, ``j`` lies on the flank of the other contact: its index, else -1.

    Such a point is within tol of the other curve only because the curves stay close up to a
    contact next to it; it is no contact of its own:

    - a cluster's closest approach (a touch found by no root, column 4 ``0``) next to a root or an
      end meeting: the damped iteration of :func:`_closest` stalled on the way down. A spline
      fitted to an arc touches it at a span's end; the closest approach came out 1e-10 off, 3e-4
      in t and 2e-3 in u before it, and a pass that chains touches made an overlap of the two;
    - an end meeting more than ``floor`` apart (column 4 ``2``) next to a certified root: a nearly
      straight spline crossing a line at a small angle 9e-3 of a span before the span's end is
      4.5e-8 off the line there, within tol, and was reported twice (a spline and a copy moved
      across and turned by 1e-4: 8e-2 of a span before its end).

    Next means within 1e-1 in both parameters (a crossing at a small angle has a long flank, and
    so has a contact of high order: an ellipse and its osculating circle at a vertex, 2.4e-8 apart
    0.02 of a span from it, where a closest approach 1.6e-2 away made an overlap with the contact),
    the curves between them no farther apart than ``max(4 d, floor)`` (``d`` the flank point's
    distance; one contact, as in :func:`_two_roots`). An end meeting within 1e-3 of
    the root in both is left to the rule of one contact there, which keeps the end: a circle pushed
    1e-9 through another at its seam is one touch there, not crossings on either side of it.
    """
    e: cython.Py_ssize_t = -1
    end: cython.bint = False  # an end meeting next to a root (else a closest approach)
    if pts[i, 4] == 0.0 and pts[j, 4] != 0.0 and pts[i, 2] > rnd:
        e = i
    elif pts[j, 4] == 0.0 and pts[i, 4] != 0.0 and pts[j, 2] > rnd:
        e = j
    elif pts[i, 4] == 2.0 and pts[j, 4] == 1.0 and pts[j, 5] == 1.0 and pts[i, 2] > floor:
        e = i
        end = True
    elif pts[j, 4] == 2.0 and pts[i, 4] == 1.0 and pts[i, 5] == 1.0 and pts[j, 2] > floor:
        e = j
        end = True
    near: cython.double = 1e-1
    dt = abs(pts[i, 0] - pts[j, 0])
    du = abs(pts[i, 1] - pts[j, 1])
    if e < 0 or dt > near or du > near or (end and dt <= 1e-3 and du <= 1e-3):
        return -1
    r: cython.Py_ssize_t = j if e == i else i
    gap = _gap_between(HA, HB, pts[e, 0], pts[e, 1], pts[r, 0], pts[r, 1], wa, wb)
    return e if _one_contact(gap, pts[e, 2], floor) else -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _point_like(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                pts: cython.double[:, :], i: cython.Py_ssize_t, j: cython.Py_ssize_t, tl: cython.double,
                wa: cython.double[:, :], wb: cython.double[:, :]) -> cython.bint:
    """True when each curve stays within ``tl`` of its point ``i`` up to its point ``j`` (4 samples)."""
    q: cython.Py_ssize_t
    x0, y0, _a, _b, _c, _d = _eval(HA, pts[i, 0], wa)
    x1, y1, _a, _b, _c, _d = _eval(HB, pts[i, 1], wb)
    for q in range(1, 5):
        f = q / 4.0
        x, y, _a, _b, _c, _d = _eval(HA, pts[i, 0] + f * (pts[j, 0] - pts[i, 0]), wa)
        x2, y2, _a, _b, _c, _d = _eval(HB, pts[i, 1] + f * (pts[j, 1] - pts[i, 1]), wb)
        if hypot(x - x0, y - y0) > tl or hypot(x2 - x1, y2 - y1) > tl:
            return False
    return True


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _data_floor(PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :],
                scale: cython.double, rnd: cython.double) -> cython.double:
    """The rounding level of the control points in the frame: ``rnd`` times their largest coordinate.

    The frame's unit is ``1 / scale`` model units; ``rnd`` (64 eps) of the largest coordinate is
    :func:`relief_cad.tolerances.rounding_floor` of both curves, and never below ``rnd``.
    """
    i: cython.Py_ssize_t
    big: cython.double = 0.0
    for i in range(PA.shape[0]):
        big = max(big, abs(PA[i, 0]), abs(PA[i, 1]))
    for i in range(PB.shape[0]):
        big = max(big, abs(PB[i, 0]), abs(PB[i, 1]))
    return rnd * max(1.0, big * scale)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _drop_near_roots(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
                     roots: cython.double[:, :], nroots: cython.Py_ssize_t, gap: cython.double,
                     wa: cython.double[:, :], wb: cython.double[:, :]) -> cython.Py_ssize_t:
    """Drop the uncertified roots (column 2 not 1) that a certified one explains; the new count.

    One is explained when it lies between two certified roots in ``t`` (the near-roots of triple
    crossings at an inflection), or when the curves at the middle of it and a certified root are
    within ``gap`` (rounding): the same root found again. Others stay: a touch (a double root,
    never certified) 0.004 from a crossing in one wide cluster is a contact of its own.
    """
    k: cython.Py_ssize_t
    c: cython.Py_ssize_t
    k2: cython.Py_ssize_t = 0
    keep: cython.bint
    lo: cython.double = _INF
    hi: cython.double = -_INF
    for c in range(nroots):
        if roots[c, 2] == 1.0:
            lo = min(lo, roots[c, 0])
            hi = max(hi, roots[c, 0])
    for k in range(nroots):
        keep = roots[k, 2] == 1.0 or not (lo <= hi)
        if not keep and not (lo < roots[k, 0] < hi):
            keep = True
            for c in range(nroots):
                if roots[c, 2] == 1.0 and _mid_gap(HA, HB, roots[k, 0], roots[k, 1], roots[c, 0], roots[c, 1],
                                                   wa, wb) <= gap:
                    keep = False
                    break
        if keep:
            roots[k2, 0] = roots[k, 0]
            roots[k2, 1] = roots[k, 1]
            roots[k2, 2] = roots[k, 2]
            k2 += 1
    return k2


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _sole_root(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :],
               roots: cython.double[:, :], t0: cython.double, t1: cython.double, u0: cython.double,
               u1: cython.double, SA: cython.double[:, :], SB: cython.double[:, :], CA: cython.double[:, :],
               CB: cython.double[:, :], VA: cython.double[:], VB: cython.double[:]) -> cython.bint:
    """True when the certified root ``roots[0]`` is the only one of the cluster ``[t0, t1] x [u0, u1]``.

    It lies in the cluster's box, and the two curves' pieces over it meet at most once: their
    tangent cones are apart (:func:`.clip.cones_apart`), with each piece's control points known
    to :func:`_piece_error`. A wide cluster of a crossing at a low angle (or of two boxes meeting
    at a subdivision's split) then needs no Newton runs from seeds along its diagonals: each
    would end at this root. ``SA``, ``SB``, ``CA``, ``CB``, ``VA``, ``VB`` are scratch (the
    clipping's, free once it has ended).
    """
    if roots[0, 2] != 1.0 or not (t0 <= roots[0, 0] <= t1 and u0 <= roots[0, 1] <= u1):
        return False
    _segment(HA, t0, t1, SA)
    _segment(HB, u0, u1, SB)
    _cartesian(SA, CA, VA)
    _cartesian(SB, CB, VB)
    return cones_apart(CA, CB, _piece_error(HA, SA), _piece_error(HB, SB))


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _piece_error(H: cython.const[cython.double][:, :], S: cython.const[cython.double][:, :]) -> cython.double:
    """A bound of the error of the Cartesian control points of ``S``, :func:`.bezier._segment` of ``H``.

    de Casteljau's rounding in the homogeneous rows, ``2 m`` rounds of ``2 eps`` at most each
    times their largest entry, over the piece's least weight (the division by it), doubled.
    """
    i: cython.Py_ssize_t
    m: cython.Py_ssize_t = H.shape[0]
    big: cython.double = 0.0
    wmin: cython.double = _INF
    for i in range(m):
        big = max(big, abs(H[i, 0]), abs(H[i, 1]), abs(H[i, 2]))
        wmin = min(wmin, S[i, 2])
    return 8.0 * m * _C_EPS * big / wmin


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _mid_gap(HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :], t0: cython.double,
             u0: cython.double, t1: cython.double, u1: cython.double, wa: cython.double[:, :],
             wb: cython.double[:, :]) -> cython.double:
    """Distance from ``a`` at the middle of ``t0, t1`` to ``b`` near the middle of ``u0, u1``."""
    x: cython.double
    y: cython.double
    x, y, _a, _b, _c, _d = _eval(HA, 0.5 * (t0 + t1), wa)
    return _local_dist(HB, x, y, 0.5 * (u0 + u1), wb)


@cython.cfunc
@cython.nogil
def _room(a: cython.double[:, :], n: cython.Py_ssize_t) -> cython.double[:, :]:
    """``a`` itself when it has at least ``n`` rows, else a larger copy (:func:`._grow`, with the GIL).

    The callers test ``n > a.shape[0]`` first: ``a = _room(a, n)`` takes the view again (two
    atomic updates of its acquisition count) even when nothing grows, on every row or split.
    """
    if n <= a.shape[0]:
        return a
    with cython.gil:
        return _grow(np.asarray(a), n)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _put(
    res: cython.double[:, :],
    nres: cython.Py_ssize_t,
    pair: cython.double,
    kind: cython.double,
    t: cython.double,
    u: cython.double,
    t1: cython.double,
    u1: cython.double,
    x: cython.double,
    y: cython.double,
    dist: cython.double,
) -> cython.void:
    """Write result row ``nres`` (``res`` has room for it)."""
    res[nres, 0] = pair
    res[nres, 1] = kind
    res[nres, 2] = t
    res[nres, 3] = u
    res[nres, 4] = t1
    res[nres, 5] = u1
    res[nres, 6] = x
    res[nres, 7] = y
    res[nres, 8] = dist


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
@cython.inline
def _hypot_le(dx: cython.double, dy: cython.double, e: cython.double) -> cython.bint:
    """``hypot(dx, dy) <= e``, the same answer, without ``hypot`` when the squares decide it.

    ``q = dx² + dy²`` is within 3e-16 of the exact sum relative (plus 2e-308 where the squares
    underflow), and ``hypot`` within an ulp of its root: outside a band of 1e-14 around ``e²``, ``q``
    decides as ``hypot`` would (for ``e`` from 1e-140 to 1e140; else, and for NaN, ``hypot``
    decides). ``hypot`` is a tenth of the clipping's time; this test runs twice a step.
    """
    q: cython.double
    e2: cython.double
    if 1e-140 < e < 1e140:
        q = dx * dx + dy * dy
        e2 = e * e
        if q < e2 * (1.0 - 1e-14):
            return True
        if q > e2 * (1.0 + 1e-14):
            return False
    return hypot(dx, dy) <= e


def _box(
    P: cython.const[cython.double][:, :]
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """The control-point box ``(xlo, xhi, ylo, yhi)`` of planar points ``P``."""
    i: cython.Py_ssize_t
    xl = xh = P[0, 0]
    yl = yh = P[0, 1]
    for i in range(1, P.shape[0]):
        xl = min(xl, P[i, 0])
        xh = max(xh, P[i, 0])
        yl = min(yl, P[i, 1])
        yh = max(yh, P[i, 1])
    return xl, xh, yl, yh


def _apart(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], tol: cython.double
) -> cython.bint:
    """True when the control-point boxes of two planar curves are more than ``tol`` apart."""
    axl, axh, ayl, ayh = _box(PA)
    bxl, bxh, byl, byh = _box(PB)
    return axl > bxh + tol or bxl > axh + tol or ayl > byh + tol or byl > ayh + tol


def scratch_rows(ma: cython.Py_ssize_t, mb: cython.Py_ssize_t) -> cython.Py_ssize_t:
    """Rows of the scratch buffer of :func:`_pair_core` for curves of ``ma`` and ``mb`` control points.

    Its blocks are laid out there; the count grows with ``ma + mb`` (a buffer made for the
    largest pair of a batch serves every pair).
    """
    m: cython.Py_ssize_t = ma + mb
    return m + (3 * m + 8) + (2 * m + 16) + 3 * m + 88 + m + (8 + 2 * _NSMALL + 4) + _NSMALL


def _pair_core(
    PA: cython.const[cython.double][:, :],
    WA: cython.const[cython.double][:],
    PB: cython.const[cython.double][:, :],
    WB: cython.const[cython.double][:],
    tol: cython.double,
    budget: cython.longlong,
    pair: cython.double,
    scratch: cython.double[:, :],
    rv: cython.double[:, :],
    nres: cython.Py_ssize_t,
) -> cython.Py_ssize_t:
    """The pair driver, without the GIL: rows appended to ``rv`` from row ``nres``; the new row count.

    ``scratch`` has at least :func:`scratch_rows` rows of ``RES_COLS`` columns (its contents are
    overwritten). When ``rv`` has no room for the rows, nothing is written and ``-2 - n`` is
    returned, ``n`` the rows ``rv`` needs: the caller grows it and runs the pair again (the same
    bits). -1 signals a Python exception (an allocation that failed).

    Not one screen: the paper's clipping loop and the root classification share the scratch
    views and their counters; split, each part would take a dozen of them as arguments.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    k: cython.Py_ssize_t
    q: cython.Py_ssize_t
    ma: cython.Py_ssize_t = PA.shape[0]
    mb: cython.Py_ssize_t = PB.shape[0]
    na: cython.Py_ssize_t = ma - 1
    nb: cython.Py_ssize_t = mb - 1
    eps: cython.double = _C_EPS
    split_ratio: cython.double = _C_SPLIT_RATIO
    k_crossing: cython.double = _K_CROSSING
    k_tangent: cython.double = _K_TANGENT
    k_overlap: cython.double = _K_OVERLAP
    k_unresolved: cython.double = _K_UNRESOLVED
    # scratch views (slices of three buffers) and locals that type inference leaves as objects
    CA: cython.double[:, :]
    CB: cython.double[:, :]
    CPA: cython.double[:, :]
    CPB: cython.double[:, :]
    SA: cython.double[:, :]
    SB: cython.double[:, :]
    VA: cython.double[:]
    VB: cython.double[:]
    VPA: cython.double[:]
    VPB: cython.double[:]
    ea: cython.double[:]
    eb: cython.double[:]
    d0: cython.double
    d1: cython.double
    px: cython.double
    py: cython.double
    qx: cython.double
    qy: cython.double
    t0: cython.double
    t1: cython.double
    u0: cython.double
    u1: cython.double
    nt0: cython.double
    nt1: cython.double
    nu0: cython.double
    nu1: cython.double
    tm: cython.double
    um: cython.double
    w: cython.double
    wt: cython.double
    wu: cython.double
    perp: cython.bint
    wide: cython.bint
    fresh: cython.bint
    distinct: cython.bint
    padt: cython.double
    padu: cython.double
    gap: cython.double
    same: cython.bint
    nunc: cython.Py_ssize_t
    if _apart(PA, PB, tol):  # disjoint bounding boxes (widened by tol): nothing to do
        return nres
    # the curves in the frame and all scratch arrays are blocks of rows of ``scratch`` (one
    # allocation by the caller; each costs about half a microsecond), viewed as arrays of 1 to
    # RES_COLS columns; an array that must grow is replaced by a larger copy (see _room). After
    # the curves (HA, HB): a block of 3 columns from row o3, of 2 from o2, of 1 from o1, of 4 from
    # o4 (overlaps, stack, candidates, boxes), the derivative rows (r6), the points and roots of up
    # to _NSMALL candidates (r5), and _NSMALL rows of small vectors (rv5: cluster labels, kept
    # flags, used ends, a box: one column each). Each view is sliced straight from ``scratch``,
    # where and when it is first needed: taking a view costs two atomic updates of the buffer's
    # acquisition count (on entry and on return), a tenth of a small pair's time for 30 views
    r0 = ma + mb
    o3 = r0
    o2 = o3 + 3 * ma + 3 * mb + 8
    o1 = o2 + 2 * ma + 2 * mb + 16
    o4 = o1 + 3 * ma + 3 * mb
    r6 = o4 + 88  # ma + mb rows
    r5 = r6 + ma + mb  # 8 + 2 * _NSMALL + 4 rows
    rv5 = r5 + 8 + 2 * _NSMALL + 4  # _NSMALL rows, the last of scratch_rows(ma, mb)
    HA: cython.double[:, :] = scratch[0:ma, 0:3]
    HB: cython.double[:, :] = scratch[ma:r0, 0:3]
    cx, cy, scale = _frame(PA, PB)
    _homog_into(PA, WA, cx, cy, scale, HA)
    _homog_into(PB, WB, cx, cy, scale, HB)
    tl = tol * scale
    if not tl > 0.0:
        tl = 1e-300
    inv = 1.0 / scale
    wa: cython.double[:, :] = scratch[o3 : o3 + ma, 0:3]
    wb: cython.double[:, :] = scratch[o3 + ma : o3 + ma + mb, 0:3]
    rnd: cython.double = _C_ROUND * max(1.0, 1.0)  # frame is normalised to |x| < 1

    # no Python object below: the rare allocations take the GIL back (``with cython.gil``, _room)
    # ---------------------------------------------------------------- end points
    # candidates (t, u, dist) from each end point's projection on the other curve;
    # an end point outside the other curve's two fat lines (widened by tol) is skipped
    CA = scratch[o2 : o2 + ma, 0:2]
    CB = scratch[o2 + ma : o2 + ma + mb, 0:2]
    VA = scratch[o1 : o1 + ma, 0]
    VB = scratch[o1 + ma : o1 + ma + mb, 0]
    # the whole curves' Cartesian points and boxes: the clipping's first step starts from them
    axl0, axh0, ayl0, ayh0 = _cartesian(HA, CA, VA)
    bxl0, bxh0, byl0, byh0 = _cartesian(HB, CB, VB)
    SA = scratch[o3 + ma + mb : o3 + 2 * ma + mb, 0:3]
    SB = scratch[o3 + 2 * ma + mb : o3 + 2 * ma + 2 * mb, 0:3]
    ea = scratch[o1 + ma + mb : o1 + 2 * ma + mb, 0]
    eb = scratch[o1 + 2 * ma + mb : o1 + 2 * ma + 2 * mb, 0]
    ends: cython.double[:, :] = scratch[o3 + 3 * ma + 3 * mb : o3 + 3 * ma + 3 * mb + 8, 0:3]
    nend = 0
    # cheap rejection: an end point farther than tol outside the other curve's two fat lines
    fa0 = fat_line_kernel(CA, False)
    fa1 = fat_line_kernel(CA, True)
    fb0 = fat_line_kernel(CB, False)
    fb1 = fat_line_kernel(CB, True)
    for which in range(4):
        if which < 2:
            qx = CA[na * which, 0]
            qy = CA[na * which, 1]
            d0 = fb0[0] * qx + fb0[1] * qy + fb0[2]
            d1 = fb1[0] * qx + fb1[1] * qy + fb1[2]
            if d0 < fb0[3] - tl or d0 > fb0[4] + tl or d1 < fb1[3] - tl or d1 > fb1[4] + tl:
                continue
        else:
            qx = CB[nb * (which - 2), 0]
            qy = CB[nb * (which - 2), 1]
            d0 = fa0[0] * qx + fa0[1] * qy + fa0[2]
            d1 = fa1[0] * qx + fa1[1] * qy + fa1[2]
            if d0 < fa0[3] - tl or d0 > fa0[4] + tl or d1 < fa1[3] - tl or d1 > fa1[4] + tl:
                continue
        if which < 2:
            te = float(which)
            px = CA[na * which, 0]
            py = CA[na * which, 1]
            CPB = scratch[o2 + 2 * ma + mb : o2 + 2 * ma + 2 * mb, 0:2]
            VPB = scratch[o1 + 3 * ma + 2 * mb : o1 + 3 * ma + 3 * mb, 0]
            uu, dd = _point_on(HB, px, py, tl, SB, CPB, VPB, eb, wb)
            # snap to an end point of b when that end also is within tol
            for iend in range(2):
                ue = float(iend)
                qx = CB[iend * nb, 0]
                qy = CB[iend * nb, 1]
                de = hypot(qx - px, qy - py)
                if de <= tl and (abs(uu - ue) < 1e-6 or de <= dd):
                    uu = ue
                    dd = de
            tt = te
        else:
            ue = float(which - 2)
            px = CB[nb * (which - 2), 0]
            py = CB[nb * (which - 2), 1]
            CPA = scratch[o2 + ma + mb : o2 + 2 * ma + mb, 0:2]
            VPA = scratch[o1 + 2 * ma + 2 * mb : o1 + 3 * ma + 2 * mb, 0]
            tt, dd = _point_on(HA, px, py, tl, SA, CPA, VPA, ea, wa)
            for iend in range(2):
                te = float(iend)
                qx = CA[iend * na, 0]
                qy = CA[iend * na, 1]
                de = hypot(qx - px, qy - py)
                if de <= tl and (abs(tt - te) < 1e-6 or de <= dd):
                    tt = te
                    dd = de
            uu = ue
        if dd <= tl:
            dup = False
            for k in range(nend):
                if abs(ends[k, 0] - tt) <= 1e-9 and abs(ends[k, 1] - uu) <= 1e-9:
                    dup = True
                    # prefer exact end values
                    if tt == 0.0 or tt == 1.0:
                        ends[k, 0] = tt
                    if uu == 0.0 or uu == 1.0:
                        ends[k, 1] = uu
            if not dup:
                ends[nend, 0] = tt
                ends[nend, 1] = uu
                ends[nend, 2] = dd
                nend += 1

    # ---------------------------------------------------------------- overlaps
    ov: cython.double[:, :] = scratch[o4 : o4 + 4, 0:4]
    nov: cython.Py_ssize_t = 0
    if nend >= 2:  # an overlap runs between two end contacts
        used: cython.double[:] = scratch[rv5 : rv5 + 8, 2]  # 1.0 for an end used by an overlap
        for i in range(8):
            used[i] = 0.0
        nsamp = max(24, na * nb + 4)
        for i in range(nend):
            for j in range(i + 1, nend):
                if used[i] and used[j]:
                    continue
                if abs(ends[i, 0] - ends[j, 0]) <= 1e-9 or abs(ends[i, 1] - ends[j, 1]) <= 1e-9:
                    continue
                if ends[i, 0] < ends[j, 0]:
                    p, q = i, j
                else:
                    p, q = j, i
                with cython.gil:  # it allocates
                    same = _coincide(HA, HB, ends[p, 0], ends[p, 1], ends[q, 0], ends[q, 1], tl, wa, wb,
                                     nsamp)
                if same:
                    ov[nov, 0] = ends[p, 0]
                    ov[nov, 1] = ends[q, 0]
                    ov[nov, 2] = ends[p, 1]
                    ov[nov, 3] = ends[q, 1]
                    nov += 1
                    used[i] = 1.0
                    used[j] = 1.0
                    if nov == 4:
                        break
            if nov == 4:
                break

    # ---------------------------------------------------------------- clipping
    stack: cython.double[:, :] = scratch[o4 + 4 : o4 + 68, 0:4]
    stack[0, 0] = 0.0
    stack[0, 1] = 1.0
    stack[0, 2] = 0.0
    stack[0, 3] = 1.0
    nstack = 1
    cands: cython.double[:, :] = scratch[o4 + 68 : o4 + 84, 0:4]
    ncand: cython.Py_ssize_t = 0
    unres: cython.double[:, :] = scratch[o4 + 84 : o4 + 88, 0:4]
    nunres: cython.Py_ssize_t = 0
    # candidate boxes: 1e-7 of the curves' own extent, which for an ill-conditioned curve
    # (Chebyshev-like, polygon 1e9 times its curve) is far below the frame's size; a box of
    # 1e-7 frame units could then hold the whole curve and all its crossings (issue 12)
    epsb = 1e-7
    ext = scale * hypot(
        max(PA[0, 0], PA[na, 0], PB[0, 0], PB[nb, 0]) - min(PA[0, 0], PA[na, 0], PB[0, 0], PB[nb, 0]),
        max(PA[0, 1], PA[na, 1], PB[0, 1], PB[nb, 1]) - min(PA[0, 1], PA[na, 1], PB[0, 1], PB[nb, 1]),
    )
    if ext < 0.25:  # the end points span less than a quarter of the frame: sample the curves
        box: cython.double[:] = scratch[rv5 : rv5 + 4, 3]
        box[0] = _INF
        box[1] = -_INF
        box[2] = _INF
        box[3] = -_INF
        _curve_box_update(PA, WA, box, wa)
        _curve_box_update(PB, WB, box, wb)
        ext = scale * hypot(box[1] - box[0], box[3] - box[2])
        if ext < 0.25:
            epsb = 4e-7 * ext
    epsb = max(tl, epsb)
    iters: cython.longlong = 0
    margin = 1e-9
    while nstack > 0:
        nstack -= 1
        t0 = stack[nstack, 0]
        t1 = stack[nstack, 1]
        u0 = stack[nstack, 2]
        u1 = stack[nstack, 3]
        # the first step (both whole curves) takes CA, CB and their boxes as made above (the end
        # points and overlaps leave them alone); every other one makes its own
        fresh = iters == 0
        axl, axh, ayl, ayh = axl0, axh0, ayl0, ayh0
        bxl, bxh, byl, byh = bxl0, bxh0, byl0, byh0
        while True:
            iters += 1
            if iters > budget:
                if nunres + 1 > unres.shape[0]:
                    unres = _room(unres, nunres + 1)
                unres[nunres, 0] = t0
                unres[nunres, 1] = t1
                unres[nunres, 2] = u0
                unres[nunres, 3] = u1
                nunres += 1
                break
            if nov > 0 and _in_overlap(ov, nov, t0, t1, u0, u1, margin):
                break
            if not fresh:
                _segment(HA, t0, t1, SA)
                _segment(HB, u0, u1, SB)
                axl, axh, ayl, ayh = _cartesian(SA, CA, VA)
                bxl, bxh, byl, byh = _cartesian(SB, CB, VB)
            fresh = False
            if axl > bxh + tl or bxl > axh + tl or ayl > byh + tl or byl > ayh + tl:
                break
            # the sub-curves' extents at the start of this step (hypot only where a test needs it)
            dxa = axh - axl
            dya = ayh - ayl
            dxb = bxh - bxl
            dyb = byh - byl
            if (_hypot_le(dxa, dya, epsb) and _hypot_le(dxb, dyb, epsb)) or (
                    t1 - t0 <= 1e-15 and u1 - u0 <= 1e-15):
                if ncand + 1 > cands.shape[0]:
                    cands = _room(cands, ncand + 1)
                cands[ncand, 0] = t0
                cands[ncand, 1] = t1
                cands[ncand, 2] = u0
                cands[ncand, 3] = u1
                ncand += 1
                break
            wt = t1 - t0
            wu = u1 - u0
            empty = False
            wida = 0.0
            widb = 0.0
            for iperp in range(2):
                perp = iperp == 1  # the fat lines along the chords, then across them
                # clip b against a's fat line
                nx, ny, c, dmin, dmax = fat_line_kernel(CA, perp)
                if not perp:
                    wida = dmax - dmin
                lo, hi = clip_range_kernel(CB, VB, nx, ny, c, dmin - tl, dmax + tl, eb)
                if lo > hi:
                    empty = True
                    break
                if lo > 0.0 or hi < 1.0:
                    w = u1 - u0
                    nu0 = u0 + lo * w
                    nu1 = u0 + hi * w
                    u0 = nu0
                    u1 = max(nu0, nu1)
                    _segment(HB, u0, u1, SB)
                    bxl, bxh, byl, byh = _cartesian(SB, CB, VB)
                # clip a against b's fat line
                nx, ny, c, dmin, dmax = fat_line_kernel(CB, perp)
                if not perp:
                    widb = dmax - dmin
                lo, hi = clip_range_kernel(CA, VA, nx, ny, c, dmin - tl, dmax + tl, ea)
                if lo > hi:
                    empty = True
                    break
                if lo > 0.0 or hi < 1.0:
                    w = t1 - t0
                    nt0 = t0 + lo * w
                    nt1 = t0 + hi * w
                    t0 = nt0
                    t1 = max(nt0, nt1)
                    _segment(HA, t0, t1, SA)
                    axl, axh, ayl, ayh = _cartesian(SA, CA, VA)
                if (t1 - t0) <= split_ratio * wt or (u1 - u0) <= split_ratio * wu:
                    break
            if empty:
                break
            if (t1 - t0) <= split_ratio * wt or (u1 - u0) <= split_ratio * wu:
                fresh = True
                continue
            # stalled: a flat band contact, or split the larger sub-curve
            exa = hypot(dxa, dya)
            exb = hypot(dxb, dyb)
            if wida <= tl and widb <= tl and exa <= 4.0 * exb + tl and exb <= 4.0 * exa + tl:
                if ncand + 1 > cands.shape[0]:
                    cands = _room(cands, ncand + 1)
                cands[ncand, 0] = t0
                cands[ncand, 1] = t1
                cands[ncand, 2] = u0
                cands[ncand, 3] = u1
                ncand += 1
                break
            if nstack + 2 > stack.shape[0]:
                stack = _room(stack, nstack + 2)
            if (exa >= exb and t1 - t0 > 1e-15) or u1 - u0 <= 1e-15:
                tm = 0.5 * (t0 + t1)
                stack[nstack, 0] = tm
                stack[nstack, 1] = t1
                stack[nstack, 2] = u0
                stack[nstack, 3] = u1
                nstack += 1
                t1 = tm
            else:
                um = 0.5 * (u0 + u1)
                stack[nstack, 0] = t0
                stack[nstack, 1] = t1
                stack[nstack, 2] = um
                stack[nstack, 3] = u1
                nstack += 1
                u1 = um
        if iters > budget:
            while nstack > 0:
                nstack -= 1
                if nunres + 1 > unres.shape[0]:
                    unres = _room(unres, nunres + 1)
                unres[nunres, :] = stack[nstack, :]
                nunres += 1

    if ncand == 0 and nend == 0 and nunres == 0:
        return nres  # nothing found (no ends, hence no overlaps): no cluster arrays to make
    floor: cython.double = _data_floor(PA, PB, scale, rnd)  # the rounding of the data, in the frame

    # ---------------------------------------------------------------- clusters
    # union-find labels, held as doubles (exact integers) in the scratch buffer
    label: cython.double[:]
    if ncand <= _NSMALL:
        label = scratch[rv5 : rv5 + ncand, 0]
    else:
        with cython.gil:
            label = np.empty(ncand)
    li: cython.Py_ssize_t
    lj: cython.Py_ssize_t
    for i in range(ncand):
        label[i] = i
    for i in range(ncand):
        for j in range(i + 1, ncand):
            gt = max(cands[i, 0], cands[j, 0]) - min(cands[i, 1], cands[j, 1])
            gu = max(cands[i, 2], cands[j, 2]) - min(cands[i, 3], cands[j, 3])
            if gt <= 1e-7 and gu <= 1e-7:
                li = cython.cast(cython.Py_ssize_t, label[i])
                while label[li] != li:
                    li = cython.cast(cython.Py_ssize_t, label[li])
                lj = cython.cast(cython.Py_ssize_t, label[j])
                while label[lj] != lj:
                    lj = cython.cast(cython.Py_ssize_t, label[lj])
                if li != lj:
                    label[max(li, lj)] = min(li, lj)
    for i in range(ncand):
        li = cython.cast(cython.Py_ssize_t, label[i])
        while label[li] != li:
            li = cython.cast(cython.Py_ssize_t, label[li])
        label[i] = li

    # points found: (t, u, dist, kind, priority)
    b5: cython.double[:, :]  # pts (column 5: 1.0 for a certified root), then roots (3 columns)
    if ncand <= _NSMALL:
        b5 = scratch[r5 : r5 + 8 + ncand + ncand + 4, 0:6]
    else:
        with cython.gil:
            b5 = np.empty((8 + ncand + ncand + 4, 6))
    pts: cython.double[:, :] = b5[0 : 8 + ncand]
    npts = 0
    for k in range(nend):
        if npts + 1 > pts.shape[0]:
            pts = _room(pts, npts + 1)
        pts[npts, 0] = ends[k, 0]
        pts[npts, 1] = ends[k, 1]
        pts[npts, 2] = ends[k, 2]
        pts[npts, 3] = -1.0  # kind decided below
        pts[npts, 4] = 2.0  # end points win merges
        pts[npts, 5] = 0.0
        npts += 1
    roots: cython.double[:, :] = b5[8 + ncand : 8 + ncand + ncand + 4, 0:3]
    da: cython.double[:, :] = scratch[r6 : r6 + ma, 0:6]
    db: cython.double[:, :] = scratch[r6 + ma : r6 + ma + mb, 0:6]
    # Newton seeds, grown per cluster if needed
    seeds: cython.double[:, :] = scratch[o2 + 2 * ma + 2 * mb : o2 + 2 * ma + 2 * mb + 16, 0:2]
    for root_label in range(ncand):
        if label[root_label] != root_label:
            continue
        # members of this cluster
        nmem = 0
        for i in range(ncand):
            if label[i] == root_label:
                nmem += 1
        stride = max(1, nmem // 24)
        nroots = 0
        bestres = _INF
        bt = 0.0
        bu = 0.0
        ct0 = _INF
        ct1 = -_INF
        cu0 = _INF
        cu1 = -_INF
        for i in range(ncand):
            if label[i] == root_label:
                ct0 = min(ct0, cands[i, 0])
                ct1 = max(ct1, cands[i, 1])
                cu0 = min(cu0, cands[i, 2])
                cu1 = max(cu1, cands[i, 3])
        # Newton seeds: member box centres, and for a wide cluster (a band of
        # near-tangency that may hold several roots) points along both diagonals
        wide = nmem >= 2 or ct1 - ct0 > 1e-6 or cu1 - cu0 > 1e-6
        nseed = (nmem + stride - 1) // stride + (10 if wide else 0)
        if nseed > seeds.shape[0]:
            seeds = _room(seeds, nseed)
        ks = 0
        cnt = 0
        for i in range(ncand):
            if label[i] != root_label:
                continue
            cnt += 1
            if (cnt - 1) % stride != 0 or ks >= nseed:
                continue
            seeds[ks, 0] = 0.5 * (cands[i, 0] + cands[i, 1])
            seeds[ks, 1] = 0.5 * (cands[i, 2] + cands[i, 3])
            ks += 1
        kmem = ks  # the member seeds; the diagonal ones follow
        if wide:
            for q in range(5):
                f = (q + 0.5) / 5.0
                seeds[ks, 0] = ct0 + f * (ct1 - ct0)
                seeds[ks, 1] = cu0 + f * (cu1 - cu0)
                seeds[ks + 1, 0] = ct0 + f * (ct1 - ct0)
                seeds[ks + 1, 1] = cu1 - f * (cu1 - cu0)
                ks += 2
        # a root belongs to the cluster within a box width of its box: Newton from a diagonal seed
        # of a wide tangent cluster ran 0.09 away to a crossing, whose certificate then dropped the
        # cluster's own uncertified touch (the other cluster finds that crossing itself)
        padt = max(1e-6, ct1 - ct0)
        padu = max(1e-6, cu1 - cu0)
        for q in range(ks):
            if q == kmem and nroots == 1 and _sole_root(HA, HB, roots, ct0, ct1, cu0, cu1, SA, SB, CA, CB,
                                                        VA, VB):
                break  # the diagonal seeds could find no other root
            t, u, r = _newton(HA, HB, seeds[q, 0], seeds[q, 1], wa, wb, 60)
            if t < ct0 - padt or t > ct1 + padt or u < cu0 - padu or u > cu1 + padu:
                continue
            if r < bestres:
                bestres = r
                bt = t
                bu = u
            if r <= rnd:
                seen = False
                for k in range(nroots):
                    if roots[k, 2] == 1.0 and abs(roots[k, 0] - t) <= 1e-12 and abs(roots[k, 1] - u) <= 1e-12:
                        seen = True
                        break
                if seen:
                    continue
                # ill-conditioned root (high degree, near-tangent): double-double polish
                _x, _y, adx, ady, _a2, _a3 = _eval(HA, t, wa)
                _x, _y, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
                sig = abs(adx * bdy - ady * bdx) / max(hypot(adx, ady), hypot(bdx, bdy), 1e-300)
                cert = 1.0  # a well-conditioned root is trusted as is
                if (na + nb) * eps > 1e-14 * sig:
                    cert = 0.0
                    t2, u2, ok = _polish_dd(HA, HB, t, u, wa, wb, da, db, 10)
                    if ok:
                        t = t2
                        u = u2
                        cert = 1.0
                dup = False
                for k in range(nroots):
                    if abs(roots[k, 0] - t) <= 1e-11 and abs(roots[k, 1] - u) <= 1e-11:
                        dup = True
                        if cert > roots[k, 2]:  # keep the certified copy
                            roots[k, 0] = t
                            roots[k, 1] = u
                            roots[k, 2] = cert
                        break
                if not dup:
                    if nroots + 1 > roots.shape[0]:
                        roots = _room(roots, nroots + 1)
                    roots[nroots, 0] = t
                    roots[nroots, 1] = u
                    roots[nroots, 2] = cert
                    nroots += 1
        if nroots == 0:
            t, u, d = _closest(HA, HB, bt, bu, wa, wb, 60)
            if d <= tl:
                t, u, d = _flank_root(HA, HB, t, u, d, rnd, floor, wa, wb)
                if npts + 1 > pts.shape[0]:
                    pts = _room(pts, npts + 1)
                cert = 0.0
                if 0.0 <= d <= _root_resolution(HA, HB, t, u, rnd, wa, wb):
                    # a root that the rounding of strongly weighted data hides: a degree-9 curve of
                    # weights 0.02 to 8.5 crossing a line at sin 0.995, 2.3e-4 before its pinched
                    # end, came out a touch 1.16 rnd off; an arc of end weight 1e-5 crossing a line
                    # where it moves 1e5 times faster than elsewhere, 44 rnd off. Certified simple
                    # there (double-double Newton at a fixed point), it is a root as any certified one
                    t2, u2, ok = _polish_dd(HA, HB, t, u, wa, wb, da, db, 10)
                    if ok and abs(t2 - t) <= 1e-9 and abs(u2 - u) <= 1e-9:
                        t = t2
                        u = u2
                        d = -1.0
                        cert = 1.0
                kind = k_tangent
                if cert == 1.0:
                    kind = k_crossing if _angle_sin(HA, HB, t, u, wa, wb) >= 1e-12 else k_tangent
                elif d < 0.0 and _crosses(HA, HB, t, u, rnd, wa, wb):
                    kind = k_crossing
                pts[npts, 0] = t
                pts[npts, 1] = u
                pts[npts, 2] = max(d, 0.0)
                pts[npts, 3] = kind
                pts[npts, 4] = 1.0 if d < 0.0 else 0.0
                pts[npts, 5] = cert
                npts += 1
            continue
        # certified roots explain the cluster: drop the uncertified near-roots that are theirs
        nroots = _drop_near_roots(HA, HB, roots, nroots, 4.0 * rnd, wa, wb)
        nunc = 0
        for k in range(nroots):
            if roots[k, 2] != 1.0:
                nunc += 1
        # sort roots by t (insertion sort)
        for i in range(1, nroots):
            j = i
            while j > 0 and roots[j - 1, 0] > roots[j, 0]:
                for c3 in range(3):
                    tmp = roots[j - 1, c3]
                    roots[j - 1, c3] = roots[j, c3]
                    roots[j, c3] = tmp
                j -= 1
        # merge neighbours with no measurable gap between them (a split double root)
        i = 0
        while i < nroots:
            j = i
            while j + 1 < nroots:
                tm = 0.5 * (roots[j, 0] + roots[j + 1, 0])
                um = 0.5 * (roots[j, 1] + roots[j + 1, 1])
                mx, my, _a, _b, _c, _d = _eval(HA, tm, wa)
                uq = um
                # distance from a(tm) to b near um (a few Newton steps)
                for _ in range(8):
                    x, y, dx, dy, ddx, ddy = _eval(HB, uq, wb)
                    fx = x - mx
                    fy = y - my
                    h = dx * dx + dy * dy + fx * ddx + fy * ddy
                    if h <= 0.0:
                        break
                    uq = min(1.0, max(0.0, uq - (fx * dx + fy * dy) / h))
                x, y, _a, _b, _c, _d = _eval(HB, uq, wb)
                dq = hypot(x - mx, y - my)
                distinct = (
                    roots[j, 2] == 1.0
                    and roots[j + 1, 2] == 1.0
                    and (
                        abs(roots[j + 1, 0] - roots[j, 0]) > 1e-13
                        or abs(roots[j + 1, 1] - roots[j, 1]) > 1e-13
                    )
                )
                if dq <= 4.0 * rnd and not distinct:
                    j += 1
                else:
                    break
            if j == i:
                sn = _angle_sin(HA, HB, roots[i, 0], roots[i, 1], wa, wb)
                kind = k_crossing
                cert = roots[i, 2]
                if roots[i, 2] == 1.0:
                    # a certified (simple) root crosses, however small the angle, unless rounding
                    # alone makes it one (the curves part to one side both ways): then it is a
                    # touch, one contact with the cluster's other such roots (the dedupe's rule)
                    if sn < 1e-7 and _rounding_root(HA, HB, roots[i, 0], roots[i, 1],
                                                    nroots == 1 or sn < 1e-12, floor, wa, wb, da, db):
                        kind = k_tangent
                        cert = _ROUNDING_ROOT
                    elif sn < 1e-12:
                        kind = k_tangent
                elif nunc == 1 and sn < 1e-7:  # the cluster's one uncertified root: a touch
                    kind = k_tangent
                elif sn < 1e-10:
                    kind = k_tangent
                if npts + 1 > pts.shape[0]:
                    pts = _room(pts, npts + 1)
                pts[npts, 0] = roots[i, 0]
                pts[npts, 1] = roots[i, 1]
                pts[npts, 2] = 0.0
                pts[npts, 3] = kind
                pts[npts, 4] = 1.0
                pts[npts, 5] = cert
                npts += 1
            else:
                t, u, d = _closest(
                    HA, HB, 0.5 * (roots[i, 0] + roots[j, 0]), 0.5 * (roots[i, 1] + roots[j, 1]), wa, wb, 60
                )
                if npts + 1 > pts.shape[0]:
                    pts = _room(pts, npts + 1)
                pts[npts, 0] = t
                pts[npts, 1] = u
                pts[npts, 2] = d
                # a double root split by rounding touches; roots of a crossing at an angle no touch
                # shows, with no gap between them, are one crossing found twice: at an end of a
                # spline's span, crossing an arc at sin 3.6e-4
                pts[npts, 3] = k_crossing if _crosses(HA, HB, t, u, rnd, wa, wb) else k_tangent
                pts[npts, 4] = 1.0
                pts[npts, 5] = 0.0
                npts += 1
            i = j + 1

    # ---------------------------------------------------------------- dedupe + emit
    keep: cython.double[:]  # 1.0: kept
    if npts <= _NSMALL:
        keep = scratch[rv5 : rv5 + npts, 1]
    else:
        with cython.gil:
            keep = np.empty(npts)
    for i in range(npts):
        keep[i] = 1.0
    for i in range(npts):
        if not keep[i]:
            continue
        for j in range(i + 1, npts):
            if not keep[j]:
                continue
            noise = False  # a crossing root merged into an end contact away from it
            dt = abs(pts[i, 0] - pts[j, 0])
            du = abs(pts[i, 1] - pts[j, 1])
            if pts[i, 5] == _ROUNDING_ROOT and pts[j, 5] == _ROUNDING_ROOT and dt <= 0.05 and du <= 0.05 and (
                    _gap_between(HA, HB, pts[i, 0], pts[i, 1], pts[j, 0], pts[j, 1], wa, wb) <= 4.0 * floor):
                # roots of one touch that rounding made (_rounding_root), no gap between them: the
                # touch lies between them (a contact of order four, split symmetrically)
                pts[i, 0] = 0.5 * (pts[i, 0] + pts[j, 0])
                pts[i, 1] = 0.5 * (pts[i, 1] + pts[j, 1])
                same = True
            elif pts[i, 5] == 1.0 and pts[j, 5] == 1.0 and (dt > 1e-13 or du > 1e-13):
                # certified roots found distinct (a touch that rounding split into two crossings
                # 8e-10 apart): two roots however close, as the clusters decided
                same = False
            elif dt <= 1e-9 and du <= 1e-9:
                same = True
            else:
                flank = _flank_of(HA, HB, pts, i, j, rnd, floor, wa, wb)
                if flank >= 0:  # no contact of its own: dropped, whatever the priorities
                    keep[flank] = 0.0
                    if flank == i:
                        break
                    continue
                # one parameter shared: the same point if the curves are point-like between
                same = (dt <= 1e-9 or du <= 1e-9) and _point_like(HA, HB, pts, i, j, tl, wa, wb)
                if not same and (
                    dt <= 1e-3
                    and du <= 1e-3
                    and (
                        pts[i, 3] == k_tangent
                        or pts[j, 3] == k_tangent
                        or pts[i, 4] == 2.0
                        or pts[j, 4] == 2.0
                    )
                ):
                    # else one contact if the curves stay within tol all along between them (a
                    # touch's tangent root 1e-9 from the end where it touches, 3e-7 apart on an
                    # ellipse of size 240)
                    gap = _gap_between(HA, HB, pts[i, 0], pts[i, 1], pts[j, 0], pts[j, 1], wa, wb)
                    same = gap <= tl and not _two_roots(pts, i, j, rnd, gap, floor, k_tangent, k_crossing)
                    noise = True
            if same:
                # the kept point takes the other's kind if it has none, but a crossing root near an
                # end contact is the rounding noise of a tangent meeting there (see _two_roots): the
                # end's own angle decides its kind
                if pts[j, 4] > pts[i, 4]:
                    if pts[j, 3] < 0.0 and pts[i, 3] >= 0.0 and not (noise and pts[i, 3] == k_crossing):
                        pts[j, 3] = pts[i, 3]
                    keep[i] = 0.0
                    break
                else:
                    if pts[i, 3] < 0.0 and pts[j, 3] >= 0.0 and not (noise and pts[j, 3] == k_crossing):
                        pts[i, 3] = pts[j, 3]
                    keep[j] = 0.0
    if nres + npts + nov + nunres > rv.shape[0]:
        return -2 - (nres + npts + nov + nunres)  # no room: the caller grows rv, runs again
    for i in range(npts):
        if not keep[i]:
            continue
        t = pts[i, 0]
        u = pts[i, 1]
        # drop points on an overlap
        on = False
        for k in range(nov):
            ub0 = min(ov[k, 2], ov[k, 3])
            ub1 = max(ov[k, 2], ov[k, 3])
            if ov[k, 0] - 1e-6 <= t <= ov[k, 1] + 1e-6 and ub0 - 1e-6 <= u <= ub1 + 1e-6:
                on = True
        if on:
            continue
        kf = pts[i, 3]
        if kf < 0.0:
            sn = _angle_sin(HA, HB, t, u, wa, wb)
            kf = k_tangent if sn < 1e-7 else k_crossing
        ax, ay, _a, _b, _c, _d = _eval(HA, t, wa)
        bx, by, _a, _b, _c, _d = _eval(HB, u, wb)
        dist = hypot(ax - bx, ay - by) * inv
        px = 0.5 * (ax + bx) * inv + cx
        py = 0.5 * (ay + by) * inv + cy
        _put(rv, nres, pair, kf, t, u, t, u, px, py, dist)
        nres += 1
    for k in range(nov):
        _put(rv, nres, pair, k_overlap, ov[k, 0], ov[k, 2], ov[k, 1], ov[k, 3], 0.0, 0.0, 0.0)
        nres += 1
    for k in range(nunres):
        _put(rv, nres, pair, k_unresolved, unres[k, 0], unres[k, 2], unres[k, 1], unres[k, 3], 0.0, 0.0, 0.0)
        nres += 1
    return nres


def intersect_pair_kernel(
    PA: cython.const[cython.double][:, :],
    WA: cython.const[cython.double][:],
    PB: cython.const[cython.double][:, :],
    WB: cython.const[cython.double][:],
    tol: cython.double,
    budget: cython.longlong,
    pair: cython.double,
    res,
    nres: cython.Py_ssize_t,
):
    """Intersect two planar rational Bézier curves; append result rows to ``res``.

    Parameters are the Cartesian control points and weights of each curve, the distance
    tolerance (model units, > 0, resolved by the caller), the iteration budget, the pair index
    written in column 0, and the result array (or None: made here) with its row count. Returns
    ``(res, nres)``. The work runs without the GIL (:func:`_pair_core`).
    """
    if _apart(PA, PB, tol):
        return res, nres
    rows = scratch_rows(PA.shape[0], PB.shape[0])
    # one allocation (about half a microsecond each): the scratch rows, and the result rows
    # when the caller has none
    buf = np.empty((rows + (_NRES if res is None else 0), RES_COLS))
    if res is None:
        res = buf[rows:]
    scratch: cython.double[:, :] = buf
    rv: cython.double[:, :] = res
    n: cython.Py_ssize_t
    while True:
        with cython.nogil:
            n = _pair_core(PA, WA, PB, WB, tol, budget, pair, scratch, rv, nres)
        if n >= 0:
            return res, n
        res = _grow(res, -2 - n)  # no room for the rows: grow and run again (the same bits)
        rv = res

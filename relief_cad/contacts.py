r"""Contact post-pass: overlaps found by geometry, certified tangency, directions at singular points.

The clipping kernels return candidate contacts fast; this module decides, on those candidates
only (so it is never hot), what they are:

- **Overlaps by geometry.** Two consecutive contacts ``p``, ``q`` (sorted by ``t``) bound a
  coincident stretch when every sample of ``a`` on ``[p.t, q.t]`` lies within ``tol`` of the piece
  of ``b`` between ``p.u`` and ``q.u``, *and* every sample of that piece of ``b`` lies within
  ``tol`` of ``a`` on ``[p.t, q.t]`` (distance both ways). A chain of such stretches is one
  :class:`~relief_cad.Overlap` whose ends are the chain's end contacts (exact ``0.0``/``1.0`` where
  the kernel's end-point projection put them). This does not depend on the speed of either
  parameterisation: a cubic with doubled end control points traces the same segment as a line.
  Self-overlaps of curves that retrace themselves come out of the same test on pairs of pieces.
- **Double root or two simple roots.** Two contacts closer than :data:`CLUSTER_GAP` in both
  parameters are one double root when the signed distance of ``a`` from ``b`` has the same sign
  between them as on both sides, and two simple roots when it changes sign. The binary64 control
  points and weights are taken as the exact data (every double is a dyadic rational), and the
  signed distance is evaluated exactly in rationals at the foot point, so the decision is
  certified, whatever the gap (1e-9 in parameter, 1e-18 in distance).
- **Directions from the first non-vanishing derivative.** At a point where the derivative
  vanishes (a repeated control point at an end, a cusp) the direction of the curve is that of
  its first non-vanishing derivative: after splitting the curve there, the first control point
  that differs from the point. End meetings are classified by these directions.
- **Higher-order contacts** (tangencies, osculations) are located on the derivative system: the
  root of the tangency function ``a'(t) × b'(u(t))`` (``u(t)`` the foot point), or of the
  curvature difference when the tangency function has a double root (an osculating contact).

>>> from relief_cad import RationalBezier, intersect
>>> straight = RationalBezier([[0, 0], [0, 0], [1, 1], [1, 1]])   # a segment stored as a cubic
>>> intersect(straight, straight.reversed())
[Overlap(t=(0.0, 1.0), u=(1.0, 0.0), kind='overlap')]
"""

from __future__ import annotations

import functools
import math
import numbers
from collections.abc import Sequence
from fractions import Fraction
from typing import Literal

import numpy as np
from numpy.polynomial import polynomial as P

from ._checks import check_curve, check_flag, check_given_tol, check_unit
from ._kernels.batch import ends_match
from ._kernels.bezier import max_abs
from ._kernels.certify import fold_bisect
from ._kernels.constants import SAFE_EXPONENT as _SAFE_EXPONENT
from ._kernels.polish import _end_ratio, foot_newton, foot_seeds, surely_far
from ._kernels.polish import _spread as _spread_one
from ._types import FloatArray
from .curves import RationalBezier, _decasteljau
from .errors import InputTypeError, InvalidInputError, ShapeError
from .results import Intersection, Overlap, Result
from .tolerances import _rounding_floor

__all__ = [
    "CLUSTER_GAP",
    "END_TANGENT_SIN",
    "curve_direction",
    "needs_refining",
    "whole_overlap",
    "refine_contacts",
    "refine_self",
    "self_overlaps",
]

CLUSTER_GAP: float = 1e-6
"""Parameter distance below which two contacts are tested as one double root (dimensionless)."""

END_TANGENT_SIN: float = 1e-7
"""``|sin|`` of the angle between the directions below which an end meeting is ``"tangent"``."""

_SAMPLES_PER_DEGREE = 3
_NEWTON_STEPS = 40  # linear convergence (ratio 2/3) at a fold tip needs ~35 steps
_SINGULAR = 1e-9  # |derivative| / size below which the first non-vanishing derivative is used


# ---------------------------------------------------------------------------- input checks
# Only the public functions check (through relief_cad._checks); relief_cad's own calls take the
# private ``_f`` of each, unchecked.
def _check_side(side: object) -> Literal[1, -1]:
    """``side`` when it is the int ``1`` or ``-1`` (not a bool, not a float)."""
    if isinstance(side, bool) or not isinstance(side, numbers.Integral):
        raise InputTypeError(f"side should be 1 or -1 (an int), not {type(side).__name__}")
    if side not in (1, -1):
        raise InvalidInputError(f"side should be 1 or -1, not {int(side)}")
    return 1 if side == 1 else -1


def _check_pair(a: object, b: object) -> tuple[RationalBezier, RationalBezier]:
    """``a`` and ``b`` when they are curves of one dimension (2 or 3)."""
    ca, cb = check_curve(a, "a"), check_curve(b, "b")
    if ca.dim != cb.dim:
        raise ShapeError(f"a and b should be curves of one dimension, not {ca.dim}-D and {cb.dim}-D")
    return ca, cb


def _check_results(items: object) -> Sequence[Result]:
    """``items`` when it is a sequence (a list, a tuple, an IntersectionList) of Intersection and Overlap."""
    if isinstance(items, (str, bytes)) or not isinstance(items, Sequence):
        raise InputTypeError("items should be a sequence of Intersection and Overlap, "
                             f"not {type(items).__name__}")
    for i, r in enumerate(items):
        if not isinstance(r, (Intersection, Overlap)):
            raise InputTypeError(f"items[{i}] should be an Intersection or an Overlap, "
                                 f"not {type(r).__name__}")
    return items


def _check_pieces(pieces: object) -> Sequence[tuple[Overlap, bool]]:
    """``pieces`` when it is a sequence of ``(Overlap, bool)`` pairs (tuples or lists)."""
    if isinstance(pieces, (str, bytes)) or not isinstance(pieces, Sequence):
        raise InputTypeError("pieces should be a sequence of (Overlap, bool) pairs, "
                             f"not {type(pieces).__name__}")
    for i, p in enumerate(pieces):
        pair = isinstance(p, (tuple, list))
        if not (pair and len(p) == 2 and isinstance(p[0], Overlap)):
            what = f"({', '.join(type(x).__name__ for x in p)})" if pair else type(p).__name__
            raise InputTypeError(f"pieces[{i}] should be an (Overlap, bool) pair, not {what}")
        check_flag(p[1], f"pieces[{i}][1]")
    return pieces


# ---------------------------------------------------------------------------- distance to a curve
def _foot(b: RationalBezier, pts: FloatArray, enough: float = 0.0, each: bool = False,
          dense: int = 1) -> tuple[FloatArray, FloatArray]:
    """Closest parameters on ``b`` (shape (m,)) and distances (m,) for points ``pts`` (m, d).

    Safeguarded Newton from the nearest of a grid; it stops once every distance is ``<= enough``:
    that of every seed, or with ``each``, that of the best seed of each point. ``each`` is for
    callers that only test the distances against a bound ``>= enough`` (the answer is the same:
    the iteration only ever lowers a distance), where the other seeds, on other branches, never
    get that close and kept the loop running to its step limit (5 ms at degree 8). ``dense``
    multiplies the number of grid points (for a second look where the first grid was too coarse).
    """
    n = max(8, _SAMPLES_PER_DEGREE * 4 * (b.degree + 1)) * dense
    # Newton from the three nearest local minima of the grid distance, keeping the best: near a
    # double point, or on a thin loop whose branches pass closer than the grid spacing, the nearest
    # grid points may all lie on the other branch, while each branch has a local minimum of its own
    # (compiled: the grid, its distances and the seeds in one call, the bits of the numpy form)
    k = 3
    m = pts.shape[0]
    grid = np.linspace(0.0, 1.0, n + 1)
    u, dist = foot_seeds(b.homogeneous, grid, np.ascontiguousarray(pts, dtype=np.float64), k)
    # the safeguarded Newton loop, compiled (the same operations and order as the numpy form it
    # replaced: the same bits): from the same u, the Newton step, damped (halved, quartered: next
    # to a double point the full step lands on the other branch and is refused), and two shrinking
    # probes that leave stationary points (a fold tip); a trial is kept only where it brings b
    # closer; stop once every distance is <= enough, or when three steps in a row gain nothing
    # (every point at its local minimum)
    _newton(b, np.repeat(pts, k, axis=0), u, dist, enough, n, k if each else 1)
    best = np.argmin(dist.reshape(m, k), axis=1)
    return u.reshape(m, k)[np.arange(m), best], dist.reshape(m, k)[np.arange(m), best]


def _newton(b: RationalBezier, pts: FloatArray, u: FloatArray, dist: FloatArray, enough: float,
            n: int, group: int = 1) -> None:
    """The compiled Newton loop of :func:`_foot` on ``u`` and ``dist`` (m,) in place, ``n`` the grid's size.

    ``group``: the rows come in groups of that many seeds of one point (see ``foot_newton``).

    A NaN trial (overflowed data) raises :meth:`~relief_cad.RationalBezier.evaluate`'s
    :class:`~relief_cad.errors.NonFiniteError`, as the numpy form of the loop did.
    """
    if not foot_newton(b.homogeneous, b.hodograph().homogeneous, np.ascontiguousarray(pts, dtype=np.float64),
                       u, dist, enough, 0.5 / n, _NEWTON_STEPS, 1.0 - 1e-6, group):
        b.evaluate(np.array([np.nan]))


def _surely_far(b: RationalBezier, pts: FloatArray, tol: float) -> bool:
    """True when some point of ``pts`` (m, d) is certainly farther than ``tol`` from ``b``.

    Grid test only (no Newton): a point of ``b`` lies within one grid chord of a grid point, so
    a grid distance above ``tol`` plus the longest chord is a certain miss. Compiled
    (:func:`relief_cad._kernels.polish.surely_far`).
    """
    grid = np.linspace(0.0, 1.0, 8 * (b.degree + 1) + 1)
    return bool(surely_far(b.homogeneous, grid, np.ascontiguousarray(pts, dtype=np.float64), tol))


def _piece(c: RationalBezier, s0: float, s1: float) -> RationalBezier:
    return c if (s0, s1) == (0.0, 1.0) else c.segment(s0, s1)


def _coincide(a: RationalBezier, b: RationalBezier, t0: float, t1: float, u0: float, u1: float,
              tol: float) -> bool:
    """True when ``a[t0, t1]`` and ``b[u0 .. u1]`` are within ``tol`` of each other, both ways."""
    if t0 == t1 or u0 == u1:
        return False
    pa = _piece(a, t0, t1)
    pb = _piece(b, min(u0, u1), max(u0, u1))
    quick = np.array([0.25, 0.5, 0.75])
    if _surely_far(pb, pa.evaluate(_spread(pa, quick)), tol) or _surely_far(
        pa, pb.evaluate(_spread(pb, quick)), tol
    ):
        return False
    m = _SAMPLES_PER_DEGREE * (a.degree + b.degree) + 5
    s = (np.arange(1, m + 1) - 0.5) / m
    for src, dst in ((pa, pb), (pb, pa)):
        pts = src.evaluate(_spread(src, s))
        far = _foot(dst, pts, 0.25 * tol, each=True)[1] > tol
        # a second look, on a grid 8 times finer, at the points that seemed far: on a small loop
        # the true foot can lie between two grid points that are both farther than a false local
        # minimum next to them (a rational loop against its own reverse came out as four contacts)
        if far.any() and not np.all(_foot(dst, pts[far], 0.25 * tol, each=True, dense=8)[1] <= tol):
            return False
    span = float(np.ptp(pa.evaluate(np.linspace(0.0, 1.0, m)), axis=0).max())
    return span > 4.0 * tol


def _spread(c: RationalBezier, s: FloatArray) -> FloatArray:
    """Parameters of ``c`` for the samples ``s`` in [0, 1], spread along it as on its standard form.

    Samples even in the parameter of a curve of unequal end weights see only one end of it (the
    kernel's ``_spread``, whose ``λ`` comes from ``_end_ratio``).
    """
    lam = _end_ratio(c.homogeneous, 0.0, 1.0, np.empty_like(c.homogeneous))
    return s if lam == 1.0 else np.array([_spread_one(float(f), lam) for f in s])


# ---------------------------------------------------------------------------- overlaps
def _end_nodes(a: RationalBezier, b: RationalBezier, tol: float) -> set[tuple[float, float]]:
    """Contacts at the curves' end points (exact where the end points are the same point).

    An end point through which the other curve passes more than once (a fold back through it, a
    double point on it) gives one contact per passage: a curve that starts at a point, leaves
    it and comes back along the other curve overlaps from where it comes back, not from its start.
    """
    out: set[tuple[float, float]] = set()
    ends_b = (b.control_points[0], b.control_points[-1])
    for t, pt in ((0.0, a.control_points[0]), (1.0, a.control_points[-1])):
        exact = [u for u, q in zip((0.0, 1.0), ends_b, strict=True) if np.array_equal(pt, q)]
        out.update((t, u) for u in _passages(b, pt, tol, exact))
    for u, pt in ((0.0, ends_b[0]), (1.0, ends_b[1])):
        out.update((t, u) for t in _passages(a, pt, tol, [q[0] for q in out if q[1] == u]))
    return out


def _passages(c: RationalBezier, pt: FloatArray, tol: float, found: list[float]) -> list[float]:
    """Parameters where ``c`` passes within ``tol`` of ``pt``: ``found``, else the foot; then the rest."""
    if not found:
        if _surely_far(c, pt[None, :], tol):
            return []
        fu, fd = _foot(c, pt[None, :], 0.25 * tol)
        found = [float(fu[0])] if fd[0] <= tol else []
    return found + _other_feet(c, pt, tol, found)


def _other_feet(b: RationalBezier, pt: FloatArray, tol: float, known: list[float]) -> list[float]:
    """Parameters of ``b`` apart from ``known`` (by over 1e-6) where ``b`` passes within ``tol`` of ``pt``.

    The local minima of the grid distance that may lie within ``tol`` (grid distance up to ``tol``
    plus the longest chord), each polished by the Newton iteration of :func:`_foot`; a passage
    already known (or found twice) counts once. Most end points have one passage: then no Newton.
    """
    n = max(8, _SAMPLES_PER_DEGREE * 4 * (b.degree + 1))
    grid = np.linspace(0.0, 1.0, n + 1)
    vals = b.evaluate(grid)
    d = np.sqrt(((vals - pt) ** 2).sum(axis=1))
    chord = float(np.sqrt((np.diff(vals, axis=0) ** 2).sum(axis=1)).max())
    left = np.concatenate([[np.inf], d[:-1]])
    right = np.concatenate([d[1:], [np.inf]])
    seeds = grid[(d <= left) & (d <= right) & (d <= tol + chord)]
    seeds = [float(s) for s in seeds if all(abs(s - k) > 1.0 / n for k in known)]
    out: list[float] = []
    for s in seeds:
        u = np.array([s])
        dist = np.sqrt(((b.evaluate(u) - pt) ** 2).sum(axis=1))
        _newton(b, pt[None, :], u, dist, 0.25 * tol, n)
        if dist[0] <= tol and all(abs(u[0] - k) > 1e-6 for k in known + out):
            out.append(float(u[0]))
    return out


def _chains(a: RationalBezier, b: RationalBezier, pts: list[Intersection], ovs: list[Overlap],
            tol: float, ends: bool = True) -> list[Overlap]:
    """Chains of contacts with coincident stretches between them, as overlaps.

    From each contact, the next one (in ``t``) joined to it by a coincident stretch extends the
    chain; contacts in between that lie on another branch (a loop's double point) are passed over.
    """
    # a transversal crossing cannot end a coincident stretch: only tangent and end contacts
    # (and overlap ends) are nodes; crossings inside a stretch (a loop's double point) are covered
    nodes = sorted({(p.t, p.u) for p in pts if p.kind == "tangent" or p.t in (0.0, 1.0) or p.u in (0.0, 1.0)}
                   | {(o.t[0], o.u[0]) for o in ovs} | {(o.t[1], o.u[1]) for o in ovs}
                   | (_end_nodes(a, b, tol) | _fold_nodes(a, b, tol) if ends else set()))
    linked = {((o.t[0], o.u[0]), (o.t[1], o.u[1])) for o in ovs}
    out: list[Overlap] = []
    i = 0
    while i < len(nodes):
        start = cur = nodes[i]
        sense = 0.0  # u runs one way along a chain: a fold of either curve ends it
        while True:
            nxt = next((q for q in nodes if q[0] > cur[0] and (q[1] - cur[1]) * sense >= 0.0
                        and ((cur, q) in linked or _coincide(a, b, cur[0], q[0], cur[1], q[1], tol))), None)
            if nxt is None:
                break
            sense = sense or math.copysign(1.0, nxt[1] - cur[1])
            cur = nxt
            if _turns(a, cur[0]) or _turns(b, cur[1]):
                break  # an overlap ends where either curve turns back (a line run four times)
        if cur != start:
            out.append(Overlap(t=(start[0], cur[0]), u=(start[1], cur[1])))
        i += 1
        # the nodes a chain passed through (or a copy of its start) start none; its end node may (a
        # fold), and so may one inside its t range but not its u range: b folded back over a's stretch
        while i < len(nodes) and any(_passed(nodes[i], o) for o in out):
            i += 1
    return out


def _passed(node: tuple[float, float], o: Overlap, slack: float = 1e-9) -> bool:
    """True for a node on the overlap ``o`` (parameters within its ranges) other than its end node."""
    if abs(node[0] - o.t[1]) <= slack and abs(node[1] - o.u[1]) <= slack:
        return False
    in_t = min(o.t) - slack <= node[0] <= max(o.t) + slack
    return in_t and min(o.u) - slack <= node[1] <= max(o.u) + slack


def _fold_nodes(a: RationalBezier, b: RationalBezier, tol: float) -> set[tuple[float, float]]:
    """Contacts at the folds of either curve (where it turns back) that lie within ``tol`` of the other.

    A curve that runs along the other, turns back and runs along it again covers one stretch twice:
    two overlaps that meet at the fold, where ``u`` (or ``t``) turns. Without a node there, the
    chain ran from where the curve arrived to where it left, at the same point of the other curve.
    """
    out: set[tuple[float, float]] = set()
    for c, other, swap in ((a, b, False), (b, a, True)):
        for f in _folds(c):
            p = c.evaluate(np.array([f]))
            if _surely_far(other, p, tol):
                continue
            fu, fd = _foot(other, p, 0.25 * tol)
            if fd[0] <= tol:
                out.add((float(fu[0]), f) if swap else (f, float(fu[0])))
    return out


def _folds(c: RationalBezier) -> list[float]:
    """Parameters in (0, 1) where ``c`` turns back on its own path.

    The derivative reverses between grid points, and vanishes (below :data:`_SINGULAR` of the
    size) where it reverses: a curve retraces itself only through a zero derivative. The sharp
    tip of a loop next to a cusp turns without retracing and is no fold.
    """
    s = np.linspace(0.0, 1.0, 8 * (c.degree + 1) + 1)
    d = c.derivative(s)
    size = float(np.ptp(c.control_points, axis=0).max())
    out = []
    for k in np.flatnonzero((d[:-1] * d[1:]).sum(axis=1) < 0.0).tolist():
        m = fold_bisect(c.homogeneous, d[k], float(s[k]), float(s[k + 1]))
        # a fold found within rounding of an end is that end (the end nodes stand for it)
        if 1e-14 < m < 1.0 - 1e-14 and float(np.hypot.reduce(c.derivative(m))) <= _SINGULAR * size:
            out.append(m)
    return out


def _covered(p: Intersection, ovs: Sequence[Overlap], slack: float = 1e-12) -> bool:
    return any(o.t[0] - slack <= p.t <= o.t[1] + slack
               and min(o.u) - slack <= p.u <= max(o.u) + slack for o in ovs)


def _overlaps(a: RationalBezier, b: RationalBezier, items: list[Result], tol: float) -> list[Result]:
    pts = [r for r in items if isinstance(r, Intersection)]
    ovs = [r for r in items if isinstance(r, Overlap)]
    # a meeting at a repeated end control point may be tangent whatever the kernel's label (its
    # direction is that of a higher derivative: _end_kind), so it may bound a coincident stretch
    maybe_tangent = any(p.kind == "tangent" or _singular_end(a, p.t) or _singular_end(b, p.u) for p in pts)
    if not ((len(pts) >= 2 and maybe_tangent) or (ovs and pts)):
        return items
    found = _chains(a, b, pts, ovs, tol)
    if not found:
        return items
    kept: list[Result] = [p for p in pts if not _covered(p, found)]
    return kept + list(found)


def self_overlaps(pieces: Sequence[tuple[Overlap, bool]],
                  curve: RationalBezier | None = None) -> list[Overlap]:
    """Merge self-overlaps of pieces that continue each other into one (ends exact).

    Parameters
    ----------
    pieces : sequence of (Overlap, bool)
        Overlaps in the curve's own parameters with ``t`` before ``u``; the flag is ignored
        (kept for callers that track where each came from).
    curve : RationalBezier, optional
        The curve: two overlaps meeting where it turns back (at ``t`` or at ``u``) stay two.
        A line run four times (x = T4(2s - 1)) turns back at ``t`` and ``u`` at once where two
        of its runs meet, and ``u`` kept its way there: one overlap ran through two folds.

    Returns
    -------
    list of Overlap
        Sorted by ``t``, chained overlaps (one's end is the next one's start, ``u`` running the
        same way) merged.

    Raises
    ------
    InputTypeError
        If ``pieces`` is not a sequence of ``(Overlap, bool)`` pairs (the message names the first
        bad one), or ``curve`` is neither None nor a RationalBezier.

    Examples
    --------
    >>> parts = [(Overlap(t=(0.0, 0.25), u=(1.0, 0.75)), True), (Overlap(t=(0.25, 0.5), u=(0.75, 0.5)), True)]
    >>> self_overlaps(parts)
    [Overlap(t=(0.0, 0.5), u=(1.0, 0.5), kind='overlap')]
    >>> self_overlaps([Overlap(t=(0.0, 0.25), u=(1.0, 0.75))])
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: pieces[0] should be an (Overlap, bool) pair, not Overlap
    """
    checked = _check_pieces(pieces)
    return _self_overlaps(checked, None if curve is None else check_curve(curve, "curve"))


def _self_overlaps(pieces: Sequence[tuple[Overlap, bool]],
                   curve: RationalBezier | None = None) -> list[Overlap]:
    """:func:`self_overlaps` of valid input (relief_cad's own calls: no checks)."""
    out: list[Overlap] = []
    for o in sorted((o for o, _ in pieces), key=lambda o: o.t):
        k = next((k for k, q in enumerate(out) if _continues(q, o) and not _turns_at(curve, q)), None)
        if k is None:
            out.append(o)
        else:
            out[k] = Overlap(t=(out[k].t[0], o.t[1]), u=(out[k].u[0], o.u[1]))
    return sorted(out, key=lambda o: o.t)


def _continues(q: Overlap, o: Overlap) -> bool:
    """``o`` starts where ``q`` ends (within 1e-12 on both curves) and runs ``u`` the same way.

    Across a fold ``u`` turns back: the two stretches are then two overlaps, never one.
    """
    return (abs(q.t[1] - o.t[0]) <= 1e-12 and abs(q.u[1] - o.u[0]) <= 1e-12
            and (q.u[1] > q.u[0]) == (o.u[1] > o.u[0]))


def _turns_at(curve: RationalBezier | None, q: Overlap) -> bool:
    """True when ``curve`` turns back at ``q``'s end, in ``t`` or ``u`` (:func:`_turns`)."""
    return curve is not None and (_turns(curve, q.t[1]) or _turns(curve, q.u[1]))


def _turns(c: RationalBezier, x: float) -> bool:
    """True when ``c`` turns back at ``x`` inside its range: it leaves ``c(x)`` the way it came."""
    return 0.0 < x < 1.0 and float(np.dot(_curve_direction(c, x, -1), _curve_direction(c, x, 1))) > 0.0


def _fold(c: RationalBezier, t: float, u: float) -> float | None:
    """The fold parameter between ``t`` and ``u`` where ``c`` turns back (derivative reverses).

    Bisection on the sign of ``c'(x) . c'(t)`` (compiled: :func:`relief_cad._kernels.certify.fold_bisect`).
    """
    m = fold_bisect(c.homogeneous, c.derivative(t), t, u)
    return None if math.isnan(m) else m


# ---------------------------------------------------------------------------- range
SAFE_EXPONENT = _SAFE_EXPONENT
"""Coordinates of magnitude 2**-100 .. 2**100 are used as they are; others are scaled first.

The geometry here (and the space kernel's Gauss-Newton step) forms squared distances and products
of squared derivatives, which overflow beyond about 1e77 (or underflow below 1e-77). An exact
power-of-two scaling into range changes no parameter and no digit of the points and distances
brought back."""


def range_exponent(big: float) -> int:
    """0 when ``big`` (the largest |coordinate|) is in the safe range, else its binary exponent.

    >>> range_exponent(1e10), range_exponent(1e300)
    (0, 997)
    """
    exp = math.frexp(big)[1] if big > 0.0 else 0
    return 0 if abs(exp) <= SAFE_EXPONENT else exp


def _exponent_of(*curves: RationalBezier) -> int:
    return range_exponent(max(max_abs(c.control_points, 3) for c in curves))


def _scaled(c: RationalBezier, exp: int) -> RationalBezier:
    return RationalBezier(np.ldexp(c.control_points, -exp), c.weights)


def _rescaled(items: Sequence[Result], exp: int) -> list[Result]:
    """Points and distances multiplied by ``2**exp`` (exact); overlaps carry parameters only."""
    return [Intersection(r.t, r.u, np.ldexp(r.point, exp), r.kind, math.ldexp(r.distance, exp))
            if isinstance(r, Intersection) else r for r in items]


def _to_fold(c: RationalBezier, o: Overlap, tol: float) -> Overlap:
    """``o`` ending exactly at the fold where ``c`` turns back, when ``o`` is a stretch run out and back.

    A gap between the outward end ``t1`` and the return end ``u1`` (``t1 < u1``) is closed when
    the curve retraces itself up to the fold; an overrun (``t1 >= u1`` with ``u`` running back:
    both stretches claim the same parameters, as the pieces of a split curve can at the fold) is
    cut back to the fold. Otherwise ``o`` is returned as it is.
    """
    (t0, t1), (u0, u1) = o.t, o.u
    if u0 > u1 > t1 and not _turns(c, t1):  # u runs back towards t: a retrace (never a stretch run
        # twice the same way); ending at a fold already, it is a stretch of its own (a line run 4 times)
        m = _fold(c, t1, u1)
        if m is not None and m > t1 and _coincide(c, c, t1, m, u1, m, tol):
            return Overlap(t=(t0, m), u=(u0, m))
    elif u0 > u1 and u0 > t0 and t1 >= u1:
        m = _fold(c, t0, u0)
        if m is not None and t0 < m < u0 and _coincide(c, c, t0, m, u0, m, tol):
            return Overlap(t=(t0, m), u=(u0, m))
    return o


def refine_self(c: RationalBezier, items: Sequence[Result], tol: float) -> list[Result]:
    """Return the self-intersections of ``c`` with retraced stretches as one overlap each.

    Parameters
    ----------
    c : RationalBezier
    items : sequence of Intersection and Overlap
        Self-intersection candidates, ``t < u``, in ``c``'s own parameter.
    tol : float
        Distance tolerance (model units).

    Returns
    -------
    list of Intersection and Overlap
        Sorted by ``t``; a stretch run twice (out and back) is one :class:`Overlap` with
        ``t < u``, reaching the fold point where the curve turns back.

    Raises
    ------
    InputTypeError
        If ``c`` is not a RationalBezier, or ``items`` not a sequence of Intersection and
        Overlap (the message names the first bad item).
    ToleranceError
        If ``tol`` is not a finite distance > 0 (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> c = RationalBezier([[0, 0, 0], [1, 1, 1], [1, 1, 1], [0, 0, 0]])
    >>> pts = [Intersection(x, 1.0 - x, c(x), "tangent") for x in (0.0, 0.25, 0.375)]
    >>> refine_self(c, pts, 1e-9)
    [Overlap(t=(0.0, 0.5), u=(1.0, 0.5), kind='overlap')]
    >>> refine_self(c, pts, -1e-9)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not -1e-09
    """
    return _refine_self(check_curve(c, "c"), _check_results(items), check_given_tol(tol))


def _refine_self(c: RationalBezier, items: Sequence[Result], tol: float) -> list[Result]:
    """:func:`refine_self` of valid input (relief_cad's own calls: no checks)."""
    exp = _exponent_of(c)
    if exp:
        return _rescaled(_refine_self(_scaled(c, exp), _rescaled(items, -exp), math.ldexp(tol, -exp)), exp)
    pts = [r for r in items if isinstance(r, Intersection)]
    ovs = [r for r in items if isinstance(r, Overlap)]
    chained = (len(pts) >= 2 and any(p.kind == "tangent" for p in pts)) or (ovs and pts)
    if not (chained or ovs):
        return _by_t(list(items))
    cands = (_chains(c, c, pts, ovs, tol, ends=False) if chained else []) + ovs
    # o.t == o.u: the curve against itself, not a retraced stretch
    found = [(_to_fold(c, o, tol), True) for o in cands if o.t != o.u]
    merged = _drop_nested(_self_overlaps(found, c))
    res: list[Result] = [p for p in pts if not _covered(p, merged)]
    res += merged
    return _by_t(res)


def _by_t(res: list[Result]) -> list[Result]:
    """``res`` sorted by ``t`` (an overlap by its first ``t``; stable), in place."""
    res.sort(key=lambda r: r.t[0] if isinstance(r, Overlap) else r.t)
    return res


def _drop_nested(ovs: list[Overlap]) -> list[Overlap]:
    """``ovs`` without the overlaps that lie inside another, the first of two that lie inside each other.

    Ends are compared within 1e-9: the same fold end, reached by two chains, differs by roundings.
    """
    ovs = list(dict.fromkeys(ovs))
    return [o for i, o in enumerate(ovs)
            if not any(j != i and _inside(o, q) and (j < i or not _inside(q, o)) for j, q in enumerate(ovs))]


def _inside(o: Overlap, q: Overlap, slack: float = 1e-9) -> bool:
    """True when ``o`` lies within ``q`` on both curves, up to ``slack`` in parameter."""
    return (q.t[0] - slack <= o.t[0] and o.t[1] <= q.t[1] + slack
            and min(q.u) - slack <= min(o.u) and max(o.u) <= max(q.u) + slack)


# ---------------------------------------------------------------------------- directions
def curve_direction(c: RationalBezier, t: float, side: Literal[1, -1] = 1) -> FloatArray:
    """Return the unit direction in which ``c`` leaves ``c(t)`` towards ``t + side·dt``.

    It is the direction of the first non-vanishing derivative: after splitting ``c`` at ``t``,
    the first control point of the piece on that side that differs from ``c(t)``. At a regular
    point this is ``±c'(t) / |c'(t)|``; at an end with repeated control points, or a cusp, it
    is still defined.

    Parameters
    ----------
    c : RationalBezier
    t : float
        Parameter in ``[0, 1]``.
    side : {1, -1}
        ``1`` for the direction of increasing ``t``, ``-1`` for decreasing ``t``.

    Returns
    -------
    ndarray, shape (d,)
        A unit vector (zeros for a curve that is one point on that side, or at an end with
        ``side`` pointing off the curve).

    Raises
    ------
    InputTypeError
        If ``c`` is not a RationalBezier, ``t`` not a real number or ``side`` not an int.
    NonFiniteError, InvalidInputError
        If ``t`` is NaN or infinite, or outside ``[0, 1]``; if ``side`` is neither 1 nor -1.

    Examples
    --------
    >>> c = RationalBezier([[0, 0], [0, 0], [1, 0], [1, 1]])   # c'(0) = 0
    >>> curve_direction(c, 0.0).tolist()
    [1.0, 0.0]
    >>> curve_direction(c, 1.0, side=-1).tolist()
    [0.0, -1.0]
    >>> curve_direction(c, 0.5, side=0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: side should be 1 or -1, not 0
    """
    return _curve_direction(check_curve(c, "c"), check_unit(t, "t"), _check_side(side))


def _curve_direction(c: RationalBezier, t: float, side: Literal[1, -1] = 1) -> FloatArray:
    """:func:`curve_direction` of valid input (relief_cad's own calls: no checks)."""
    if (t >= 1.0 and side == 1) or (t <= 0.0 and side == -1):
        return np.zeros(c.dim)
    if 0.0 < t < 1.0:
        left, right = c.split(t)
        piece = right if side == 1 else left.reversed()
    else:
        piece = c if side == 1 else c.reversed()
    pts = piece.control_points
    scale = float(np.abs(pts).max()) or 1.0
    for q in pts[1:]:
        d = q - pts[0]
        norm = float(np.hypot.reduce(d))
        if norm > 4e-16 * scale:
            unit: FloatArray = d / norm
            return unit
    return np.zeros(c.dim)


def _is_singular(c: RationalBezier, t: float, kind: str) -> bool:
    if t == 0.0 or t == 1.0:  # an end: singular when its control point is repeated
        return _singular_end(c, t)
    pts = c.control_points
    if kind != "tangent":
        return False
    size = float(np.ptp(pts, axis=0).max()) or 1.0
    return float(np.hypot.reduce(c.derivative(t))) <= _SINGULAR * size


def _end_kind(a: RationalBezier, b: RationalBezier, p: Intersection) -> Intersection:
    """Reclassify a contact at a singular point (zero derivative) by its true directions."""
    if not (_is_singular(a, p.t, p.kind) or _is_singular(b, p.u, p.kind)):
        return p
    sides_a: tuple[Literal[1, -1], ...] = (1,) if p.t <= 0.0 else (-1,) if p.t >= 1.0 else (1, -1)
    sides_b: tuple[Literal[1, -1], ...] = (1,) if p.u <= 0.0 else (-1,) if p.u >= 1.0 else (1, -1)
    sines = []
    for sa in sides_a:
        da = _curve_direction(a, p.t, sa)
        for sb in sides_b:
            db = _curve_direction(b, p.u, sb)
            sines.append(float(np.hypot.reduce(np.cross(da, db))) if a.dim == 3
                         else abs(float(da[0] * db[1] - da[1] * db[0])))
    kind: Literal["crossing", "tangent"] = "tangent" if min(sines) < END_TANGENT_SIN else "crossing"
    if kind == p.kind:
        return p
    return Intersection(p.t, p.u, p.point, kind, p.distance)


# ---------------------------------------------------------------------------- double roots
def _exact(c: RationalBezier, t: float) -> tuple[list[Fraction], list[Fraction]]:
    """Exact point and derivative of ``c`` at the double ``t`` (the doubles are exact data)."""
    h = np.array([[Fraction(float(v)) for v in row] for row in c.homogeneous], dtype=object)
    val, dval = _decasteljau(h, np.array([Fraction(t)], dtype=object))
    w = val[0, -1]
    dw = dval[0, -1]
    pt = [x / w for x in val[0, :-1]]
    der = [(dx - x * dw) / w for dx, x in zip(dval[0, :-1], pt, strict=True)]
    return pt, der


def _side(a: RationalBezier, b: RationalBezier, t: float, u_guess: float) -> int:
    """Exact sign of the signed distance of ``a(t)`` from ``b`` at its (float) foot point."""
    u, _ = _foot(b, a.evaluate(np.array([t])))
    u0 = float(u[0]) if abs(float(u[0]) - u_guess) < 1e-3 else u_guess
    pa, _ = _exact(a, t)
    pb, db = _exact(b, u0)
    s = db[0] * (pa[1] - pb[1]) - db[1] * (pa[0] - pb[0])
    return (s > 0) - (s < 0)


def _double_root(a: RationalBezier, b: RationalBezier, p: Intersection, q: Intersection) -> bool:
    """True when two close contacts are one double root (no sign change of the distance).

    The signed distance is taken exactly at 1/4, 1/2 and 3/4 of the way from ``p`` to ``q`` and one
    gap beyond each; one double root leaves every nonzero sign the same, two simple roots flip
    the sign between them.
    """
    gap = q.t - p.t
    if gap <= 0.0:
        return True
    inner = {_side(a, b, p.t + f * gap, p.u + f * (q.u - p.u)) for f in (0.25, 0.5, 0.75)} - {0}
    outer = {_side(a, b, t, u) for t, u in ((p.t - gap, p.u), (q.t + gap, q.u)) if 0.0 <= t <= 1.0} - {0}
    return not inner or not outer or inner == outer


def _merge_clusters(a: RationalBezier, b: RationalBezier, pts: list[Intersection]) -> list[Intersection]:
    out: list[Intersection] = []
    for p in sorted(pts, key=lambda r: r.t):
        last = out[-1] if out else None
        if (last is not None and abs(p.t - last.t) < CLUSTER_GAP and abs(p.u - last.u) < CLUSTER_GAP
                and 0.0 < last.t and p.t < 1.0 and _double_root(a, b, last, p)):
            out[-1] = Intersection(0.5 * (last.t + p.t), 0.5 * (last.u + p.u),
                                   0.5 * (np.asarray(last.point) + np.asarray(p.point)), "tangent",
                                   max(last.distance, p.distance))
            continue
        if (last is not None and abs(p.t - last.t) < CLUSTER_GAP and abs(p.u - last.u) < CLUSTER_GAP
                and last.kind == "tangent" and p.kind == "tangent" and not _double_root(a, b, last, p)):
            out[-1] = Intersection(last.t, last.u, last.point, "crossing", last.distance)
            p = Intersection(p.t, p.u, p.point, "crossing", p.distance)
        out.append(p)
    return out


# ---------------------------------------------------------------------------- tangent location
def _tangency(a: RationalBezier, b: RationalBezier, ts: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Tangency function ``a'(t) × b'(u(t)) / (|a'| |b'|)`` at ``ts`` (m,), and the foot points."""
    u, _ = _foot(b, a.evaluate(ts))
    da, db = a.derivative(ts), b.derivative(u)
    h = (da[:, 0] * db[:, 1] - da[:, 1] * db[:, 0]) / np.maximum(
        np.hypot(da[:, 0], da[:, 1]) * np.hypot(db[:, 0], db[:, 1]), 1e-300)
    return h, u


def _contact_root(coef: FloatArray) -> float | None:
    """The root near 0 of the lowest derivative of the power series ``coef`` that has a simple root there.

    A contact of order ``m`` makes the tangency function vanish to order ``m - 1``; its
    ``(m - 2)``-th derivative has a simple root there, well conditioned even where the function
    itself is below rounding (deflation by differentiation). Near 0 is within a quarter of the
    window: the estimate of a contact of order four in data rounded at coordinates of 2,000 (an
    ellipse and its osculating circle at a vertex) lies 0.06 of the window off it.
    """
    grid = np.linspace(-1.0, 1.0, 41)
    for j in range(4):
        q = P.polyder(coef, j) if j else coef
        dq = P.polyder(q)
        scale = float(np.abs(P.polyval(grid, dq)).max())
        roots = [float(r.real) for r in P.polyroots(q) if abs(r.imag) < 1e-9 and abs(r.real) < 0.25]
        roots.sort(key=abs)
        if roots and scale > 0.0 and abs(float(P.polyval(roots[0], dq))) >= 1e-3 * scale:
            return roots[0]
    return None


@functools.cache
def _design(s: tuple[float, ...], deg: int) -> tuple[FloatArray, FloatArray, float]:
    """Least-squares set-up of :func:`_fit` on the nodes ``s`` (made once).

    The Vandermonde matrix with its columns scaled to unit norm, the column norms and ``rcond``.
    """
    van = P.polyvander(np.array(s), deg)
    scl = np.sqrt(np.square(van.T).sum(1))
    scl[scl == 0] = 1
    return van / scl, scl, len(s) * float(np.finfo(np.float64).eps)


def _fit(s: FloatArray, h: FloatArray, deg: int) -> FloatArray:
    """Power-series coefficients (deg + 1,) of the least-squares fit of ``h`` at the nodes ``s``.

    The computation of ``np.polynomial.Polynomial.fit(s, h, deg, domain=[-1, 1]).coef`` (the
    same bits), with its Vandermonde matrix made once for the fixed nodes.
    """
    a, scl, rcond = _design(tuple(s.tolist()), deg)
    coef: FloatArray = np.linalg.lstsq(a, h, rcond)[0] / scl
    return coef


def _locate(a: RationalBezier, b: RationalBezier, p: Intersection, tol: float) -> Intersection:
    """Place an interior tangent contact on the root of the derivative system.

    The tangency function is sampled on a window of half-width 1e-2 around the kernel's estimate
    (where it is far above rounding), fitted by a degree-10 polynomial, and the contact is the
    simple root of its lowest derivative that has one (see :func:`_contact_root`).
    """
    w = 1e-2
    if a.dim != 2 or not (w < p.t < 1.0 - w and 0.0 < p.u < 1.0):
        return p
    s = np.cos(np.pi * (np.arange(21) + 0.5) / 21)
    h, _ = _tangency(a, b, p.t + w * s)
    root = _contact_root(_fit(s, h, 10))
    if root is None:
        return p
    t = p.t + w * root
    u = float(_foot(b, a.evaluate(np.array([t])))[0][0])
    gap = float(np.hypot.reduce(a.evaluate(t) - b.evaluate(u)))
    # the contact is the closest meeting: a root of the fit farther apart than the estimate (by more
    # than rounding, 1e3 floors: curves mapped from a plane tilted at coordinates of 2,000 carry
    # its rounding, 1e-13 at coordinates of 1) is the fit's error (a curve touching its mirror
    # image, 1e-16 apart at the kernel's point, was moved 8e-5 along to where they are 3.8e-8
    # apart); within the window in ``u`` as in ``t``: the rounding of a contact of order four (an
    # ellipse and its osculating circle at a vertex) puts the kernel's estimate 1e-4 of ``t`` and
    # 2e-4 of ``u`` off it
    if gap > min(tol, p.distance + 1e3 * _rounding_floor(a, b)) or abs(u - p.u) > w:
        return p
    return Intersection(t, u, 0.5 * (a.evaluate(t) + b.evaluate(u)), p.kind, gap)


# ---------------------------------------------------------------------------- entry point
def _singular_end(c: RationalBezier, t: float) -> bool:
    """True at an end of ``c`` whose first control leg vanishes, or is below :data:`_SINGULAR` of the size.

    The second case is an end made by cutting a curve where its derivative vanishes (a piece of
    a self-intersection cut at a fold): the repeated control point is then repeated only up to
    rounding.
    """
    if t != 0.0 and t != 1.0:
        return False
    rows = c.control_points.tolist()  # Python floats: the same differences and maxima as numpy's, faster
    p, q = (rows[0], rows[1]) if t == 0.0 else (rows[-1], rows[-2])
    if p == q:
        return True
    lead: float = max(abs(y - x) for x, y in zip(p, q, strict=True))
    spread: float = max(abs(y - x) for row in rows for x, y in zip(p, row, strict=True))
    return lead <= _SINGULAR * spread


def whole_overlap(a: RationalBezier, b: RationalBezier, tol: float) -> Overlap | None:
    """The overlap of two curves with the same end points that coincide all along, else None.

    Checked before clipping (coincident curves are the clipping's slowest case): the end points
    must match within ``tol`` (a degree-elevated or rescaled copy may move them by a rounding), so
    the test costs two comparisons for every other pair. Closed curves match at both ends either
    way round; the sense is taken from where interior points of ``a`` fall on ``b``. Curves of
    different dimensions never match.

    Raises
    ------
    InputTypeError
        If ``a`` or ``b`` is not a RationalBezier.
    ToleranceError
        If ``tol`` is not a finite distance > 0 (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]])
    >>> whole_overlap(c, c.elevate(2), 1e-9)
    Overlap(t=(0.0, 1.0), u=(0.0, 1.0), kind='overlap')
    >>> whole_overlap(c, c.control_points, 1e-9)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: b should be a RationalBezier, not ndarray
    """
    return _whole_overlap(check_curve(a, "a"), check_curve(b, "b"), check_given_tol(tol))


def _whole_overlap(a: RationalBezier, b: RationalBezier, tol: float) -> Overlap | None:
    """:func:`whole_overlap` of valid input (relief_cad's own calls: no checks)."""
    if not _ends_may_match(a.control_points, b.control_points, 2.0 * tol):
        return None  # the answer for almost every pair, from eight to twelve scalar reads
    copy = _exact_copy(a, b, tol)
    if copy is not None:
        return copy
    exp = _exponent_of(a, b)
    if exp:
        return _whole_overlap(_scaled(a, exp), _scaled(b, exp), math.ldexp(tol, -exp))
    pa, pb = a.control_points, b.control_points
    if pa.shape[1] != pb.shape[1]:
        return None
    closed = _near(pa[0], pa[-1], tol)
    senses = [(u0, u1) for u0, u1, i0, i1 in ((0.0, 1.0, 0, -1), (1.0, 0.0, -1, 0))
              if _near(pa[0], pb[i0], tol) and _near(pa[-1], pb[i1], tol)]
    # closed curves run along each other in the sense the feet of a's interior points show; when
    # they show none (a curve running out and back along itself, its first and last control points
    # one, where a(1/4) and a(3/4) may be one point), each sense whose ends match is tried
    along = [(u0, u1) for u0, u1 in senses if _runs_along(a, b, u1 - u0, tol)] if closed else senses
    for u0, u1 in along or senses:
        if _coincide(a, b, 0.0, 1.0, u0, u1, tol):
            return Overlap(t=(0.0, 1.0), u=(u0, u1))
    return None


def _ends_may_match(pa: FloatArray, pb: FloatArray, lim: float) -> bool:
    """True when the ends of ``pa`` are within ``lim`` of those of ``pb`` (per coordinate), either way round.

    The cheap gate of :func:`whole_overlap` (called with ``lim = 2 tol``: a margin for its exact
    rescaling of huge coordinates); curves of different dimensions never match. Compiled
    (:func:`relief_cad._kernels.batch.ends_match`, the test the planar kernel runs itself).
    """
    return bool(ends_match(pa, pb, lim))


def _exact_copy(a: RationalBezier, b: RationalBezier, tol: float) -> Overlap | None:
    """The overlap of an open curve with an exact copy of itself or of its reverse, else None.

    No sampling: the duplicate edge of a sketch is answered at once at any degree (the sampled test
    costs O(n^3), minutes at the largest degree). A curve whose ends are within ``4 tol`` (closed,
    or too small to tell) goes the sampled way.
    """
    ha, hb = a.homogeneous, b.homogeneous
    if ha.shape != hb.shape or not float(np.max(np.abs(ha[0] / ha[0, -1] - ha[-1] / ha[-1, -1]))) > 4.0 * tol:
        return None
    if np.array_equal(ha, hb):
        return Overlap(t=(0.0, 1.0), u=(0.0, 1.0))
    if np.array_equal(ha, hb[::-1]):
        return Overlap(t=(0.0, 1.0), u=(1.0, 0.0))
    return None


def _near(p: FloatArray, q: FloatArray, tol: float) -> bool:
    """True when the points ``p`` and ``q`` are within ``tol`` in every coordinate."""
    return bool(np.max(np.abs(p - q)) <= tol)


def _runs_along(a: RationalBezier, b: RationalBezier, sense: float, tol: float) -> bool:
    """True when ``b`` runs through ``a(1/4), a(1/2), a(3/4)`` (within ``tol``) in the sense of ``sense``.

    Two closed curves from one point match both ways at their ends; the feet of interior points
    tell whether ``b`` goes round the same way (``sense > 0``) or the other way (``sense < 0``).
    """
    fu, fd = _foot(b, a.evaluate(np.array([0.25, 0.5, 0.75])), 0.25 * tol)
    steps = np.diff(fu) * sense
    return bool(np.all(fd <= tol) and np.all(steps > 0.0))


def needs_refining(a: RationalBezier, b: RationalBezier, items: Sequence[Result]) -> bool:
    """True when :func:`refine_contacts` can change ``items`` (a cheap test, run on every pair).

    Interior crossings, and end meetings where both derivatives are nonzero, are final as the
    kernel gives them; overlaps, tangent contacts and end meetings at a repeated end control
    point are not.

    Raises
    ------
    InputTypeError
        If ``a`` or ``b`` is not a RationalBezier, or ``items`` not a sequence of Intersection
        and Overlap (the message names the first bad item).
    ShapeError
        If ``a`` and ``b`` are of different dimensions.

    Examples
    --------
    >>> line = RationalBezier([[0, 0], [1, 1]])
    >>> needs_refining(line, line, [Intersection(0.5, 0.5, line(0.5), "crossing")])
    False
    >>> needs_refining(line, line, [(0.5, 0.5)])
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: items[0] should be an Intersection or an Overlap, not tuple
    """
    ca, cb = _check_pair(a, b)
    return _needs_refining(ca, cb, _check_results(items))


def _needs_refining(a: RationalBezier, b: RationalBezier, items: Sequence[Result]) -> bool:
    """:func:`needs_refining` of valid input (relief_cad's own calls: no checks)."""
    for r in items:  # a plain loop: this runs on every pair with results (the kind of an Overlap
        # is "overlap"), and an end test only where a parameter is exactly 0 or 1
        if r.kind != "crossing":
            return True
        t = r.t
        if (t == 0.0 or t == 1.0) and _singular_end(a, t):
            return True
        u = r.u
        if (u == 0.0 or u == 1.0) and _singular_end(b, u):
            return True
    return False


def refine_contacts(a: RationalBezier, b: RationalBezier, items: Sequence[Result],
                    tol: float) -> list[Result]:
    """Return the kernel's candidate contacts of ``a`` and ``b``, decided by geometry.

    Parameters
    ----------
    a, b : RationalBezier
        The two curves (same dimension, 2 or 3).
    items : sequence of Intersection and Overlap
        The kernel's results for the pair, in the curves' own parameters.
    tol : float
        The distance tolerance used (model units).

    Returns
    -------
    list of Intersection and Overlap
        Sorted by ``t``: coincident stretches as one :class:`Overlap` each, close contacts
        decided as one double root or two simple roots by the exact sign of the distance, end
        meetings at singular points classified by their first non-vanishing derivatives, and
        interior tangent contacts located on the derivative system.

    Raises
    ------
    InputTypeError
        If ``a`` or ``b`` is not a RationalBezier, or ``items`` not a sequence of Intersection
        and Overlap (the message names the first bad item).
    ShapeError
        If ``a`` and ``b`` are of different dimensions.
    ToleranceError
        If ``tol`` is not a finite distance > 0 (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> line = RationalBezier([[0, 0], [1, 1]])
    >>> cubic = RationalBezier([[0, 0], [0, 0], [1, 1], [1, 1]])
    >>> from relief_cad import intersect
    >>> refine_contacts(line, cubic, intersect(line, cubic), 1e-9)
    [Overlap(t=(0.0, 1.0), u=(0.0, 1.0), kind='overlap')]
    >>> refine_contacts(line, cubic, intersect(line, cubic), float("nan"))
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not nan
    """
    ca, cb = _check_pair(a, b)
    return _refine_contacts(ca, cb, _check_results(items), check_given_tol(tol))


def _refine_contacts(a: RationalBezier, b: RationalBezier, items: Sequence[Result],
                     tol: float) -> list[Result]:
    """:func:`refine_contacts` of valid input (relief_cad's own calls: no checks)."""
    exp = _exponent_of(a, b)
    if exp:
        out = _refine_contacts(_scaled(a, exp), _scaled(b, exp), _rescaled(items, -exp),
                               math.ldexp(tol, -exp))
        return _rescaled(out, exp)
    out = _overlaps(a, b, list(items), tol)
    pts = [r for r in out if isinstance(r, Intersection)]
    ovs = [r for r in out if isinstance(r, Overlap)]
    if pts and a.dim == 2:
        pts = _merge_clusters(a, b, pts)
        pts = [_locate(a, b, p, tol) if p.kind == "tangent" else p for p in pts]
    pts = [_end_kind(a, b, p) for p in pts]
    res: list[Result] = [*pts, *ovs]
    res.sort(key=lambda r: r.t[0] if isinstance(r, Overlap) else r.t)
    return res

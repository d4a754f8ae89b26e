"""The arbiter: who is right when relief_cad and OCCT disagree (50-digit arithmetic on exact data).

A point candidate is refined by Gauss-Newton on ``a(t) - b(u) = 0`` (which converges to the
local minimum of the distance for a near miss) and judged by its true distance against
``tol``. A stationary point of the distance that is no local minimum is no contact: between two
crossings of a thin lens (two circles or a circle and a line that cut each other ``d`` deep), the
point of ``a`` halfway between them and the point of ``b`` opposite it, ``d`` apart, are a saddle
of ``|a(t) - b(u)|**2``; there the refinement goes on downhill on both sides, to the crossings.
An overlap claim is checked by sampling the claimed range of ``a`` and finding the
closest point of ``b`` to each sample in high precision. The curves are
:class:`~relief_cad.cad.exact.ExactCurve` objects.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
>>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
>>> v = arbitrate_point(a, b, 1.4, 1.4, tol=1e-7)
>>> v.holds, v.kind, round(v.t, 12), v.distance < 1e-40
(True, 'crossing', 1.414213562373, True)
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any, NamedTuple

from ..errors import InvalidInputError
from .exact import ARBITER_DIGITS, ExactCurve

__all__ = ["OverlapCheck", "PointCheck", "arbitrate_overlap", "arbitrate_point"]


@dataclass(frozen=True)
class PointCheck:
    """The arbiter's finding near a point candidate.

    >>> import build123d as bd
    >>> check = arbitrate_point(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)), 1.4, 1.4, tol=1e-7)
    >>> check.kind, check.holds, round(check.t, 12)
    ('crossing', True, 1.414213562373)

    Attributes
    ----------
    t, u : float
        Refined edge parameters (local minimum of the distance, inside both ranges).
    point : tuple of float
        The refined common point (mean of ``a(t)`` and ``b(u)``).
    distance : float
        The true distance ``|a(t) - b(u)|`` there, computed with 50 digits.
    sine : float
        Sine of the angle between the two tangents (0 for a tangent contact).
    kind : {"crossing", "tangent", "miss"}
        ``"miss"`` when the distance exceeds the tolerance.
    holds : bool
        True when the refined distance is within the tolerance.
    exact : bool
        False when a curve had no exact data (evaluated by OCCT in binary64).
    sides : tuple of PointCheck
        Set when the refinement first reached a saddle of the distance, no contact (the apex of a
        thin lens): the local minima downhill on both sides of it (the lens's two crossings),
        ordered by ``t``. The check itself is the one of them nearest to the candidate.
    """

    t: float
    u: float
    point: tuple[float, float, float]
    distance: float
    sine: float
    kind: str
    holds: bool
    exact: bool = True
    sides: tuple[PointCheck, ...] = ()


@dataclass(frozen=True)
class OverlapCheck:
    """The arbiter's finding on an overlap claim ``a[t0, t1] == b[u0, u1]``.

    >>> import build123d as bd
    >>> a, b = bd.Line((0, 0), (4, 0)), bd.Line((1, 0), (3, 0))
    >>> check = arbitrate_overlap(a, b, (1.0, 3.0), (0.0, 2.0), tol=1e-7)
    >>> check.status, check.holds
    ('coincident', True)

    Attributes
    ----------
    status : {"coincident", "within_tolerance", "tangent", "crossing", "none"}
        ``"coincident"``: the curves coincide along the range up to rounding of their
        data; ``"within_tolerance"``: they stay closer than ``tol`` without touching at
        an isolated point (a genuine near-coincident stretch); ``"tangent"`` /
        ``"crossing"``: the true answer in the range is isolated point(s) (the first one's
        kind); ``"none"``: nothing within tolerance.
    max_distance : float
        The largest sampled distance from ``a`` to ``b`` over the range.
    points : tuple of PointCheck
        The isolated true points found in the range (for the non-overlap statuses).
    min_distance : float
        The smallest sampled distance (set for ``"none"``).
    """

    status: str
    max_distance: float
    points: tuple[PointCheck, ...] = ()
    min_distance: float = 0.0

    @property
    def holds(self) -> bool:
        """True when the overlap claim is right (coincident or within tolerance).

        >>> OverlapCheck(status="none", max_distance=1.0).holds
        False
        """
        return self.status in ("coincident", "within_tolerance")


def _exact(edge: Any, cache: dict[int, ExactCurve] | None = None) -> ExactCurve:
    if isinstance(edge, ExactCurve):
        return edge
    return ExactCurve(edge)


class _Local(NamedTuple):
    """``|a(t) - b(u)|**2 / 2`` to second order at ``(t, u)``.

    Its gradient ``g1, g2``, Gauss-Newton matrix ``a11, a12, a22`` and Hessian
    ``[[h11, a12], [a12, h22]]`` (the curvature terms ``r . a''`` and ``-r . b''`` on its diagonal).
    """

    g1: Any
    g2: Any
    a11: Any
    a12: Any
    a22: Any
    h11: Any
    h22: Any


def _local(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any) -> _Local:
    """The gradient, Gauss-Newton matrix and Hessian of ``|a(t) - b(u)|**2 / 2`` at ``(t, u)``.

    >>> import build123d as bd, mpmath
    >>> a, b = ExactCurve(bd.Line((0, 0), (2, 0))), ExactCurve(bd.Line((1, 1), (1, -1)))
    >>> [round(float(x), 9) + 0.0 for x in _local(a, b, mpmath.mpf(0.5), mpmath.mpf(1))]
    [-0.5, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0]
    """
    pa, da, dda = ca.jet(t)
    pb, db, ddb = cb.jet(u)
    r = [pa[k] - pb[k] for k in range(3)]
    a11 = sum(x * x for x in da)
    a22 = sum(x * x for x in db)
    return _Local(
        g1=sum(da[k] * r[k] for k in range(3)),
        g2=-sum(db[k] * r[k] for k in range(3)),
        a11=a11,
        a12=-sum(da[k] * db[k] for k in range(3)),
        a22=a22,
        h11=a11 + sum(dda[k] * r[k] for k in range(3)),
        h22=a22 - sum(ddb[k] * r[k] for k in range(3)),
    )


def _d2(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any) -> Any:
    """``|a(t) - b(u)|**2``."""
    qa, qb = ca.value(t), cb.value(u)
    return sum((qa[k] - qb[k]) ** 2 for k in range(3))


def _refine(ca: ExactCurve, cb: ExactCurve, t0: Any, u0: Any) -> tuple[Any, Any, Any]:
    """Newton on the gradient of ``|a(t) - b(u)|**2 / 2``: a stationary point of the distance.

    The full Hessian (with the curvature terms ``r . a''``) makes near misses converge
    quadratically; where it is not positive definite the Gauss-Newton matrix is used. Each
    iteration also tries the doubled step, which restores fast convergence at tangent
    contacts (a double root), and backtracks when the distance would grow. Parameters are
    clamped to the edges' ranges. The point reached is a local minimum, or, from a start on or
    next to a saddle (the apex of a thin lens), that saddle: :func:`_downhill` goes on from there.
    """
    mp = ca.mp
    t, u = ca.clamp(mp.mpf(t0)), cb.clamp(mp.mpf(u0))
    size = max(ca.size, cb.size)
    eps2 = (mp.mpf(10) ** (-(mp.dps - 8)) * size) ** 2
    rel = mp.mpf(10) ** (-(mp.dps // 2))

    cur = _d2(ca, cb, t, u)
    for _ in range(150):
        if cur < eps2:
            break
        g1, g2, a11, a12, a22, h11, h22 = _local(ca, cb, t, u)
        if h11 > 0 and h22 > 0 and h11 * h22 - a12 * a12 > 0:
            a11, a22 = h11, h22
        lam = (a11 + a22) * mp.mpf(10) ** (-(mp.dps - 10))
        det = (a11 + lam) * (a22 + lam) - a12 * a12
        if det == 0:
            break
        dt = -((a22 + lam) * g1 - a12 * g2) / det
        du = -((a11 + lam) * g2 - a12 * g1) / det
        nt, nu = ca.clamp(t + dt), cb.clamp(u + du)
        best: tuple[Any, Any, Any] = (_d2(ca, cb, nt, nu), nt, nu)
        nt, nu = ca.clamp(t + 2 * dt), cb.clamp(u + 2 * du)
        val = _d2(ca, cb, nt, nu)
        if val < best[0]:
            best = (val, nt, nu)
        step = mp.mpf(1)
        while best[0] > cur and step > mp.mpf(2) ** -40:  # backtrack
            step /= 2
            nt, nu = ca.clamp(t + step * dt), cb.clamp(u + step * du)
            best = (_d2(ca, cb, nt, nu), nt, nu)
        if best[0] > cur:
            break
        val, nt, nu = best
        small = abs(nt - t) <= (abs(t) + 1) * rel and abs(nu - u) <= (abs(u) + 1) * rel
        t, u, cur = nt, nu, val
        if small:
            break
    return t, u, mp.sqrt(cur)


def _into_range(c: ExactCurve, t: Any) -> Any:
    """``t`` on edge ``c``: round the seam of a closed periodic edge, else clamped to its range.

    >>> import build123d as bd, mpmath
    >>> circle, line = ExactCurve(bd.Edge.make_circle(1.0)), ExactCurve(bd.Line((0, 0), (3, 4)))
    >>> round(float(_into_range(circle, mpmath.mpf(-1e-3))), 12), float(_into_range(line, mpmath.mpf(-1)))
    (6.28218530718, 0.0)
    """
    if c.period is None or c.first <= t <= c.last:
        return c.clamp(t)
    return c.first + (t - c.first) % c.period


def _downhill_direction(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any) -> tuple[Any, Any, Any] | None:
    """The unit direction ``(dt, du)`` along which ``|a(t) - b(u)|**2 / 2`` curves down, and its curvature.

    The curvature is the Hessian's negative eigenvalue; None where the Hessian is positive
    semi-definite to ``10**(-dps/2)`` of its size (its entries are good to about ``10**-30``).

    The parabola ``y = x**2`` and the line ``y = 1/4`` at the apex of their lens, ``(0, 0)`` and
    ``(0, 1/4)``: the Hessian ``[[2, -2], [-2, 1]]`` has the eigenvalue ``3/2 - sqrt(17)/2``.

    >>> import build123d as bd, mpmath
    >>> a, b = ExactCurve(bd.Bezier((-1, 1), (0, -1), (1, 1))), ExactCurve(bd.Line((-1, 0.25), (1, 0.25)))
    >>> with mpmath.workdps(50):  # the arbiter's precision
    ...     dt, du, low = _downhill_direction(a, b, mpmath.mpf(0.5), 1)
    ...     there = _downhill_direction(a, b, 0.75, 1.5)
    >>> round(float(low), 12), round(float(1.5 - math.sqrt(17) / 2), 12), there  # at a crossing: a minimum
    (-0.561552812809, -0.561552812809, None)
    """
    mp = ca.mp
    h11, h12, h22 = (_local(ca, cb, t, u)[k] for k in (5, 3, 6))
    half = mp.sqrt(((h11 - h22) / 2) ** 2 + h12**2)
    low = (h11 + h22) / 2 - half
    if low >= -(abs(h11) + abs(h22)) * mp.mpf(10) ** (-(mp.dps // 2)):
        return None
    # the eigenvector of ``low``: (h12, low - h11) or (low - h22, h12), the better conditioned
    vt, vu = (h12, low - h11) if abs(low - h11) >= abs(low - h22) else (low - h22, h12)
    norm = mp.sqrt(vt**2 + vu**2)
    return vt / norm, vu / norm, low


def _downhill(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any, dist: Any) -> list[tuple[Any, Any, Any]]:
    """The local minima downhill on both sides of ``(t, u)`` where the Hessian is indefinite, or ``[]``.

    At the apex of a lens ``dist`` deep the distance falls as ``dist - k s**2`` along the
    direction of negative curvature ``low`` (``|a - b|**2 / 2`` as ``dist**2 / 2 + low s**2 / 2``),
    to 0 at ``s = sqrt(2) dist / sqrt(-low)``. Each side is refined from there, or, where that
    does not end below ``dist``, from the first point at half, a quarter... of that step whose
    distance is below ``dist``. Empty at a local minimum or a root.
    """
    mp = ca.mp
    if dist <= mp.mpf(10) ** (-(mp.dps - 8)) * max(ca.size, cb.size):
        return []
    way = _downhill_direction(ca, cb, t, u)
    if way is None:
        return []
    vt, vu, low = way
    found: list[tuple[Any, Any, Any]] = []
    for sign in (-1, 1):
        s = mp.sqrt(2) * dist / mp.sqrt(-low)
        for k in range(80):
            nt, nu = _into_range(ca, t + sign * s * vt), _into_range(cb, u + sign * s * vu)
            if k == 0 or _d2(ca, cb, nt, nu) < dist**2:
                side = _refine(ca, cb, nt, nu)
                if side[2] < dist:
                    found.append(side)
                    break
                if k:
                    break
            s /= 2
    return found


def _minima(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any, tol: float) -> list[PointCheck]:
    """The checks of the local minima of the distance the refinement reaches from ``(t, u)``.

    One, or, from a saddle (:func:`_downhill`), those on both sides of it (one at a curve's end),
    each with ``sides`` set to all of them.
    """
    rt, ru, dist = _refine(ca, cb, t, u)
    sides: list[PointCheck] = []
    for st, su, sd in _downhill(ca, cb, rt, ru, dist):
        check = _point_check(ca, cb, st, su, sd, tol)
        if not any(abs(check.t - c.t) <= 1e-9 * (1 + abs(c.t)) for c in sides):
            sides.append(check)
    if not sides:
        return [_point_check(ca, cb, rt, ru, dist, tol)]
    sides.sort(key=lambda c: c.t)
    return [dataclasses.replace(c, sides=tuple(sides)) for c in sides]


def _point_check(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any, dist: Any, tol: float) -> PointCheck:
    mp = ca.mp
    pa, pb = ca.value(t), cb.value(u)
    da, db = ca.derivative(t), cb.derivative(u)
    cross = [da[1] * db[2] - da[2] * db[1], da[2] * db[0] - da[0] * db[2], da[0] * db[1] - da[1] * db[0]]
    na, nb = mp.sqrt(sum(x * x for x in da)), mp.sqrt(sum(x * x for x in db))
    sine = float(mp.sqrt(sum(x * x for x in cross)) / (na * nb)) if na * nb != 0 else 0.0
    holds = float(dist) <= tol
    # tangent: the curves stay within tol over a stretch much longer than tol (sine small)
    tangent = sine < math.sqrt(tol / max(ca.size, cb.size, 1e-300)) * 1e-1 or sine < 1e-12
    kind = ("tangent" if tangent else "crossing") if holds else "miss"
    point = tuple(float((pa[k] + pb[k]) / 2) for k in range(3))
    return PointCheck(float(t), float(u), point, float(dist), sine, kind, holds, ca.exact and cb.exact)  # type: ignore[arg-type]


def arbitrate_point(
    a: Any, b: Any, t: float, u: float, *, tol: float, digits: int = ARBITER_DIGITS
) -> PointCheck:
    """Refine a point candidate ``a(t) ~ b(u)`` in high precision and judge it against ``tol``.

    Parameters
    ----------
    a, b : TopoDS_Edge, build123d Edge, CadQuery Edge or ExactCurve
        The two edges (the same edge twice for a double point).
    t, u : float
        The candidate's edge parameters.
    tol : float
        The distance tolerance in model units.
    digits : int
        Decimal digits of the arithmetic.

    Returns
    -------
    PointCheck
        The refined parameters, true distance, tangent sine and verdict. The refinement ends at a
        local minimum of the distance: from a saddle (a stationary point that is no minimum, as
        at the apex of a thin lens between two crossings, of any depth) it goes on downhill on
        both sides; the check is then the point reached nearest to the candidate (holding ones
        first), with all of them in ``sides``.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0.5, 1e-3, 0), gp_Pnt(0.5, 1, 0)).Edge()
    >>> c = arbitrate_point(a, b, 0.5, 0.0, tol=1e-7)
    >>> c.holds, c.kind, round(c.distance, 12)
    (False, 'miss', 0.001)

    A circle of radius 1 and the line ``x = 3/4`` cross at ``(3/4, +-sqrt(7)/4)``. The candidate at
    the apex of their lens, the circle's point ``(1, 0)`` and the line's ``(3/4, 0)``, is a saddle
    of the distance, no contact (it was judged a miss, 1/4 away): the check is the crossing
    nearest to it (a tie here: the first in ``t``), and ``sides`` holds both.

    >>> import build123d as bd
    >>> c = arbitrate_point(bd.Edge.make_circle(1.0), bd.Line((0.75, -1), (0.75, 1)), 0.0, 1.0, tol=1e-7)
    >>> c.kind, c.distance < 1e-40, [tuple(round(x, 12) + 0.0 for x in s.point[:2]) for s in c.sides]
    ('crossing', True, [(0.75, 0.661437827766), (0.75, -0.661437827766)])
    >>> round(math.sqrt(7) / 4, 12)
    0.661437827766
    """
    import mpmath

    with mpmath.workdps(digits):
        ca, cb = _exact(a), _exact(b)
        checks = _minima(ca, cb, t, u, tol)
        if len(checks) == 1:
            return checks[0]
        start = [float((p + q) / 2) for p, q in zip(ca.value(t), cb.value(u), strict=True)]
        return min(checks, key=lambda c: (not c.holds, math.dist(c.point, start)))


def _minima_near(ca: ExactCurve, cb: ExactCurve, t: Any, u: Any, tol: float) -> list[PointCheck]:
    """:func:`_minima` from a sample ``(t, u)`` of an overlap claim, each point's parameters next to it.

    On a closed edge a point has its parameter at either end of the range; a lens round the seam
    has one crossing next to each end, and both are next to a sample at the seam.
    """
    return [dataclasses.replace(c, t=ca.near(c.t, float(t)), u=cb.near(c.u, float(u)))
            for c in _minima(ca, cb, t, u, tol)]


def _closest_u(ca: ExactCurve, cb: ExactCurve, t: Any, u0: Any) -> tuple[Any, Any]:
    mp = ca.mp
    pa = ca.value(t)
    u = cb.clamp(mp.mpf(u0))
    for _ in range(200):
        pb, db = cb.value(u), cb.derivative(u)
        r = [pa[k] - pb[k] for k in range(3)]
        den = sum(x * x for x in db)
        if den == 0:
            break
        du = sum(r[k] * db[k] for k in range(3)) / den
        nu = cb.clamp(u + du)
        if abs(nu - u) <= (abs(u) + 1) * mp.mpf(10) ** (-(mp.dps // 2)):
            u = nu
            break
        u = nu
    pb = cb.value(u)
    return u, mp.sqrt(sum((pa[k] - pb[k]) ** 2 for k in range(3)))


def _one_point_of(c: ExactCurve, t: float, u: float, tol: float) -> bool:
    """True when parameters ``t`` and ``u`` of one edge are one point of it, not a double point.

    The same parameter (to 1e-9 of the range), or the closing point of a closed edge: ``u`` one
    period from ``t`` on a periodic one, or ``t`` and ``u`` at its two ends where they meet
    within ``tol``.

    >>> import build123d as bd
    >>> circle = ExactCurve(bd.Edge.make_circle(1.0))
    >>> _one_point_of(circle, 1e-14, 2 * math.pi, 1e-7), _one_point_of(circle, 0.0, math.pi, 1e-7)
    (True, False)
    """
    span = c.last - c.first
    if abs(c.near(u, t) - t) <= 1e-9 * span:
        return True
    ends = sorted((t, u))
    if abs(ends[0] - c.first) > 1e-9 * span or abs(ends[1] - c.last) > 1e-9 * span:
        return False
    return math.dist([float(x) for x in c.value(c.first)], [float(x) for x in c.value(c.last)]) <= tol


def _sampled(ca: ExactCurve, cb: ExactCurve, ts: list[Any],
             guesses: list[Any]) -> tuple[list[Any], list[Any]]:
    """The closest parameters of ``b`` to ``a`` at ``ts`` (from ``guesses``) and their distances.

    On one edge (a self-overlap claim) the search may slide from the other stretch onto the point
    itself: a distance 0 that says nothing. Such a sample, whose guess was away from ``t``, is
    given an infinite distance (the claim does not hold there).
    """
    span = ca.last - ca.first
    us, dists = [], []
    for ti, guess in zip(ts, guesses, strict=True):
        ui, di = _closest_u(ca, cb, ti, guess)
        if ca is cb and abs(ui - ti) <= 1e-6 * span < abs(guess - ti):
            di = ca.mp.inf
        us.append(ui)
        dists.append(di)
    return us, dists


def _rounding(ca: ExactCurve, cb: ExactCurve, tol: float) -> float:
    """The rounding level of the data: ``1e-3 tol`` or ``1e-13`` of the curves' size, the larger."""
    return max(1e-3 * tol, 1e-13 * max(ca.size, cb.size))


def _one_place(ts: list[float], ca: ExactCurve) -> bool:
    """True when contacts at ``a``'s parameters ``ts`` are one contact: within 1e-3 of its range.

    The library's rule (``relief_cad.contacts``): contacts bounding a stretch along which the curves
    stay within tol are one overlap, unless they are within 1e-3 in parameter. A tangent that a
    tolerance stretched into a segment has one deep minimum there; a curve and a copy of it rounded
    by 1e-9 meet at several places far apart, and between them stay within tol: an overlap.
    """
    return max(ts) - min(ts) <= 1e-3 * max(1.0, abs(ca.last - ca.first))


def _end_contacts(ca: ExactCurve, cb: ExactCurve, ts: list[Any], us: list[Any]) -> list[float]:
    """The ends of a sampled range (``a`` at ``ts``, closest ``b`` at ``us``) where either curve ends.

    Within tol of the other curve, the end of a curve is a contact (an end meeting); a copy of a
    curve rounded by 1e-9 whose one end meets the other exactly has a single deep minimum there, yet
    its other end bounds the stretch within tol with it.
    """
    def at_end(x: Any, c: ExactCurve) -> bool:
        slack = 1e-9 * max(1.0, abs(c.last - c.first))
        return bool(abs(x - c.first) <= slack or abs(x - c.last) <= slack)

    return [float(ts[i]) for i in (0, len(ts) - 1) if at_end(ts[i], ca) or at_end(us[i], cb)]


def arbitrate_overlap(
    a: Any,
    b: Any,
    t: tuple[float, float],
    u: tuple[float, float],
    *,
    tol: float,
    samples: int = 33,
    digits: int = ARBITER_DIGITS,
) -> OverlapCheck:
    """Check an overlap claim ``a[t0, t1] == b[u0, u1]`` by sampling both curves in high precision.

    For ``samples`` parameters evenly spread over ``[t0, t1]`` the closest point of ``b``
    is found by Newton's method in 50-digit arithmetic. The claim holds when every
    distance is within ``tol``; it is then ``"coincident"`` when the distances are at the
    rounding level of the data (``1e-3 tol`` or ``1e-13`` of the curves' size, the
    larger), and otherwise ``"within_tolerance"`` unless the distance has an isolated
    minimum far below the rest, or the range lies within 1e-3 of both curves' ranges (a
    tangent contact or a near-miss that a tolerance stretched into a segment: the verdict is
    then ``"tangent"``, the library's rule; deep minima farther apart than 1e-3 of ``a``'s
    range are contacts bounding a stretch within tol, an overlap). A claim that fails is
    resolved into the true isolated points in the range.

    Parameters
    ----------
    a, b : TopoDS_Edge, build123d Edge, CadQuery Edge or ExactCurve
        The two edges.
    t, u : tuple of float
        The claimed ranges, ``a(t[0]) = b(u[0])`` and ``a(t[1]) = b(u[1])``.
    tol : float
        The distance tolerance.
    samples : int
        Number of samples along ``[t0, t1]``.
    digits : int
        Decimal digits of the arithmetic.

    Returns
    -------
    OverlapCheck

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(1, 0, 0), gp_Pnt(3, 0, 0)).Edge()
    >>> arbitrate_overlap(a, b, (1.0, 2.0), (0.0, 1.0), tol=1e-7).status
    'coincident'
    """
    import mpmath

    if samples < 3:
        raise InvalidInputError(f"expected at least 3 samples, received {samples}")
    with mpmath.workdps(digits):
        ca, cb = _exact(a), _exact(b)
        mp = ca.mp
        t0, t1 = mp.mpf(t[0]), mp.mpf(t[1])
        u0, u1 = mp.mpf(u[0]), mp.mpf(u[1])
        ts = [t0 + (t1 - t0) * mp.mpf(i) / (samples - 1) for i in range(samples)]
        us, dists = _sampled(ca, cb, ts, [u0 + (u1 - u0) * mp.mpf(i) / (samples - 1) for i in range(samples)])
        dmax = float(max(dists))
        rounding = _rounding(ca, cb, tol)
        if dmax <= rounding:
            return OverlapCheck("coincident", dmax)
        # isolated minima in the range
        found: list[PointCheck] = []
        minima = [
            i
            for i in range(samples)
            if dists[i] <= (dists[i - 1] if i > 0 else mp.inf)
            and dists[i] <= (dists[i + 1] if i < samples - 1 else mp.inf)
        ]
        # the deepest few (a flat, noisy distance profile has many shallow ones)
        for i in sorted(minima, key=lambda j: dists[j])[:6]:
            for check in _minima_near(ca, cb, ts[i], us[i], tol):
                if ca is cb and _one_point_of(ca, check.t, check.u, tol):
                    continue  # one edge at one point (one parameter, or its closing point): no double point
                if check.holds and not any(abs(check.t - f.t) <= 1e-9 * (1 + abs(f.t)) for f in found):
                    found.append(check)
        if dmax <= tol:
            dmin = min(f.distance for f in found) if found else float(min(dists))
            deep = dmin * 10 < dmax and (dmin <= rounding or dmin * 1e3 < tol)
            # a near-miss within tol: the whole range within 1e-3 of both curves' ranges
            short = _one_place([float(t0), float(t1)], ca) and _one_place([float(u0), float(u1)], cb)
            ends = _end_contacts(ca, cb, ts, us)
            if found and (deep or short) and _one_place([f.t for f in found] + ends, ca):
                return OverlapCheck("tangent", dmax, tuple(found))
            return OverlapCheck("within_tolerance", dmax)
        if not found:
            return OverlapCheck("none", dmax, (), float(min(dists)))
        return OverlapCheck(found[0].kind, dmax, tuple(found))

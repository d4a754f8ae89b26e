"""Exact curve data for the arbiter: an edge's 3D curve in 50-digit arithmetic.

:class:`ExactCurve` reads OCCT's own definition of an edge's curve (poles, weights and knots
of Bézier and B-spline curves, axis placements and radii of lines and conics, the edge
location's matrix), each binary64 number taken exactly, and evaluates it with mpmath (a periodic
B-spline at any parameter: it is moved by whole periods into the knot period). It
shares no conversion code with relief_cad's :mod:`.ocp` (only the curve-type dispatch,
:func:`.curvetypes.curve_kind`). Curve types without exact data (offset curves, edges known
only on surfaces) are evaluated by OCCT in binary64 and flagged ``exact=False``.

>>> import build123d as bd
>>> c = ExactCurve(bd.Line((0, 0), (3, 4)))
>>> c.exact, [float(x) for x in c.value(5.0)]
(True, [3.0, 4.0, 0.0])
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .curvetypes import basis_curve, curve_kind

__all__ = ["ARBITER_DIGITS", "ExactCurve"]

ARBITER_DIGITS = 50
"""Decimal digits of the arbiter's arithmetic."""


def _mp() -> Any:
    import mpmath

    return mpmath.mp.clone() if hasattr(mpmath.mp, "clone") else mpmath.mp


# --------------------------------------------------------------------------- exact curves


class ExactCurve:
    """An edge's 3D curve evaluated in high precision from OCCT's exact definition.

    Parameters
    ----------
    edge : TopoDS_Edge, build123d Edge or CadQuery Edge
        The edge; its location is applied, its own parameter is used.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt
    >>> circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2.0)).Edge()
    >>> c = ExactCurve(circle)
    >>> c.exact, [round(float(x), 12) + 0.0 for x in c.value(c.mp.pi / 2)]
    (True, [0.0, 2.0, 0.0])
    """

    def __init__(self, edge: Any) -> None:
        import mpmath
        from OCP.BRep import BRep_Tool
        from OCP.TopLoc import TopLoc_Location

        self.mp = mpmath.mp
        raw = getattr(edge, "wrapped", edge)
        loc = TopLoc_Location()
        curve = BRep_Tool.Curve_s(raw, loc, 0.0, 0.0)
        self.first, self.last = (float(x) for x in BRep_Tool.Range_s(raw))
        trsf = loc.Transformation()
        self._matrix = [[self._f(trsf.Value(i, j)) for j in range(1, 5)] for i in range(1, 4)]
        self._identity = loc.IsIdentity()
        self._occt_curve = BRep_Tool.Curve_s(raw, 0.0, 0.0)
        self.exact = True
        if curve is None:  # only curves on surfaces: OCCT's binary64 evaluation, global coordinates
            from OCP.BRepAdaptor import BRepAdaptor_Curve

            self._occt_curve = curve = BRepAdaptor_Curve(raw)
            self._identity = True
        self._eval = self._build(curve)
        self.period = _full_period(self._occt_curve, self.first, self.last)
        pts = [self._occt_curve.Value(float(t)) for t in np.linspace(self.first, self.last, 9)]
        arr = np.array([[p.X(), p.Y(), p.Z()] for p in pts])
        self.size = float(np.linalg.norm(arr.max(axis=0) - arr.min(axis=0))) or 1.0

    def _f(self, x: float) -> Any:
        return self.mp.mpf(float(x))

    def _build(self, curve: Any) -> Any:
        mp, f = self.mp, self._f
        kind, curve = curve_kind(curve), basis_curve(curve)

        def vec(v: Any) -> list[Any]:
            return [f(v.X()), f(v.Y()), f(v.Z())]

        if kind == "line":
            ax = curve.Position()
            p, d = vec(ax.Location()), vec(ax.Direction())
            return lambda t: [p[k] + t * d[k] for k in range(3)]  # noqa: B023
        if kind in ("circle", "ellipse", "hyperbola", "parabola"):
            ax = curve.Position()
            c, x, y = vec(ax.Location()), vec(ax.XDirection()), vec(ax.YDirection())
            if kind == "circle":
                r = f(curve.Radius())
                return lambda t: [c[k] + r * (mp.cos(t) * x[k] + mp.sin(t) * y[k]) for k in range(3)]
            if kind == "ellipse":
                ra, rb = f(curve.MajorRadius()), f(curve.MinorRadius())
                return lambda t: [c[k] + ra * mp.cos(t) * x[k] + rb * mp.sin(t) * y[k] for k in range(3)]
            if kind == "hyperbola":
                ra, rb = f(curve.MajorRadius()), f(curve.MinorRadius())
                return lambda t: [c[k] + ra * mp.cosh(t) * x[k] + rb * mp.sinh(t) * y[k] for k in range(3)]
            foc = f(curve.Focal())
            return lambda t: [c[k] + t * t / (4 * foc) * x[k] + t * y[k] for k in range(3)]
        if kind == "bezier":
            n = curve.NbPoles()
            hom = [[*vec(curve.Pole(i)), f(curve.Weight(i))] for i in range(1, n + 1)]
            hom = [[h[0] * h[3], h[1] * h[3], h[2] * h[3], h[3]] for h in hom]

            binom = [mp.mpf(math.comb(n - 1, i)) for i in range(n)]

            def bezier(t: Any) -> list[Any]:
                # Bernstein sum (all terms positive on [0, 1]; exact data, 50 digits)
                s_ = 1 - t
                tp = [mp.mpf(1)]
                sp = [mp.mpf(1)]
                for _ in range(n - 1):
                    tp.append(tp[-1] * t)
                    sp.append(sp[-1] * s_)
                acc = [mp.mpf(0)] * 4
                for i in range(n):
                    c = binom[i] * tp[i] * sp[n - 1 - i]
                    h = hom[i]
                    for k in range(4):
                        acc[k] += c * h[k]
                return [acc[k] / acc[3] for k in range(3)]

            return bezier
        if kind == "bspline":
            bs, period = curve, None
            if bs.IsPeriodic():  # the same curve over its knot period [first knot, last knot]
                period = f(bs.FirstParameter()), f(bs.LastParameter())  # exact: not OCCT's Period()
                bs = bs.Copy()  # OCP hands back the most derived type
                bs.SetNotPeriodic()
            p = bs.Degree()
            knots = [f(bs.Knot(i)) for i in range(1, bs.NbKnots() + 1)]
            flat: list[Any] = []
            for i in range(1, bs.NbKnots() + 1):
                flat.extend([knots[i - 1]] * bs.Multiplicity(i))
            hom = [[*vec(bs.Pole(i)), f(bs.Weight(i))] for i in range(1, bs.NbPoles() + 1)]
            hom = [[h[0] * h[3], h[1] * h[3], h[2] * h[3], h[3]] for h in hom]
            # OCCT's flat knots have (poles + degree + 1) entries for non-periodic curves
            lo_i, hi_i = p, len(hom) - 1

            def bspline(t: Any) -> list[Any]:
                if period is not None:
                    t = _into_period(t, *period)
                span = lo_i
                for s in range(lo_i, hi_i + 1):
                    if flat[s] <= t:
                        span = s
                span = min(span, hi_i)
                d = [list(hom[j + span - p]) for j in range(p + 1)]
                for r in range(1, p + 1):
                    for j in range(p, r - 1, -1):
                        den = flat[j + 1 + span - r] - flat[j + span - p]
                        alpha = (t - flat[j + span - p]) / den if den != 0 else mp.mpf(0)
                        d[j] = [(1 - alpha) * d[j - 1][k] + alpha * d[j][k] for k in range(4)]
                w = d[p][3]
                return [d[p][k] / w for k in range(3)]

            return bspline
        # anything else: OCCT's binary64 evaluation (flagged)
        self.exact = False
        occ = curve

        def fallback(t: Any) -> list[Any]:
            q = occ.Value(float(t))
            return [f(q.X()), f(q.Y()), f(q.Z())]

        return fallback

    def value(self, t: Any) -> list[Any]:
        """Return the point at edge parameter ``t`` (global coordinates) as 3 mpf numbers.

        >>> import build123d as bd
        >>> [float(x) for x in ExactCurve(bd.Line((0, 0), (3, 4))).value(2.5)]
        [1.5, 2.0, 0.0]
        """
        # no wrapping round a closed edge's seam: conics are periodic in mpmath's cos and sin, and
        # periodic B-splines are moved into their exact knot period; a wrap by the binary64 period
        # (2π is 2.4e-16 short) threw the finite differences across the seam 20% off
        p: list[Any] = self._eval(self.mp.mpf(t))
        if self._identity:
            return p
        m = self._matrix
        return [m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3] for i in range(3)]

    def derivative(self, t: Any) -> list[Any]:
        """Return ``dP/dt`` at ``t`` (central difference at high precision).

        >>> import build123d as bd
        >>> [round(float(x), 12) for x in ExactCurve(bd.Line((0, 0), (3, 4))).derivative(1.0)]
        [0.6, 0.8, 0.0]
        """
        mp = self.mp
        h = mp.mpf(10) ** (-(mp.dps // 2 - 2)) * max(mp.mpf(1), abs(mp.mpf(self.last - self.first)))
        t = mp.mpf(t)
        lo, hi = max(t - h, mp.mpf(self.first) - h), t + h
        p1, p0 = self.value(hi), self.value(lo)
        return [(p1[k] - p0[k]) / (hi - lo) for k in range(3)]

    def jet(self, t: Any) -> tuple[list[Any], list[Any], list[Any]]:
        """Return ``P(t)``, ``P'(t)`` and ``P''(t)`` (central differences, step ``10**(-dps/3)``).

        >>> import build123d as bd
        >>> p, d1, d2 = ExactCurve(bd.Line((0, 0), (3, 4))).jet(1.0)  # at mpmath's working precision
        >>> [round(float(x), 6) + 0.0 for x in d1 + d2]
        [0.6, 0.8, 0.0, 0.0, 0.0, 0.0]
        """
        mp = self.mp
        h = mp.mpf(10) ** (-(mp.dps // 3)) * max(mp.mpf(1), abs(mp.mpf(self.last - self.first)))
        t = mp.mpf(t)
        p0, pm, pp = self.value(t), self.value(t - h), self.value(t + h)
        d1 = [(pp[k] - pm[k]) / (2 * h) for k in range(3)]
        d2 = [(pp[k] - 2 * p0[k] + pm[k]) / (h * h) for k in range(3)]
        return p0, d1, d2

    def near(self, t: float, ref: float) -> float:
        """``t``, or on a closed periodic edge the parameter of its point nearest to ``ref`` in parameter.

        A contact at a closed edge's seam is found at either end of its range: ``2 pi - 1e-8`` is
        ``-1e-8`` next to a contact at 0 on a full ellipse.

        >>> import build123d as bd
        >>> c = ExactCurve(bd.Edge.make_circle(1.0))
        >>> round(c.near(2 * math.pi - 1e-8, 0.0), 12), ExactCurve(bd.Line((0, 0), (3, 4))).near(4.9, 0.0)
        (-1e-08, 4.9)
        """
        if self.period is None:
            return t
        return t + self.period * round((ref - t) / self.period)

    def clamp(self, t: Any) -> Any:
        """Clamp ``t`` into the edge's parameter range.

        >>> import build123d as bd
        >>> float(ExactCurve(bd.Line((0, 0), (3, 4))).clamp(7.0))
        5.0
        """
        return min(max(t, self.mp.mpf(self.first)), self.mp.mpf(self.last))


def _into_period(t: Any, lo: Any, hi: Any) -> Any:
    """``t`` moved by whole periods ``hi - lo`` into a periodic curve's knot period ``[lo, hi]``.

    The period's ends are the first and last knots, so a periodic B-spline is evaluated at any
    parameter, on any edge range (past the last knot, before the first, in a later period), by
    its polynomial spans over one period. A parameter already in the period, both ends included,
    is kept as it is. Any other one becomes ``lo + (t - lo) mod (hi - lo)``, in ``[lo, hi)``
    before rounding; a ``t`` a rounding below a period boundary can round up to ``hi``, where the
    last knot span's end is the curve's start point, so the value stays continuous either way.

    >>> from mpmath import mpf
    >>> [float(_into_period(mpf(t), mpf(0), mpf(6))) for t in (7.5, -1, 6, 12, -(2.0**-200))]
    [1.5, 5.0, 6.0, 0.0, 6.0]
    """
    if lo <= t <= hi:
        return t
    return lo + (t - lo) % (hi - lo)


def _full_period(curve: Any, first: float, last: float) -> float | None:
    """The period of a periodic ``curve`` whose edge runs once round it (``last - first``), else None."""
    if curve is None or not curve.IsPeriodic():
        return None
    period = float(curve.Period())
    return period if abs((last - first) - period) <= 1e-12 * max(1.0, period) else None

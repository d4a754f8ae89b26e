"""Exact evaluation of non-rational OCCT B-spline curves for the tests: de Boor in mpmath.

The poles and knots are taken exactly (every double is a rational number); the working
precision is the caller's ``mp.mp.dps``.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import mpmath as mp

Point = list[mp.mpf]


def de_boor(poles: Sequence[Sequence[float]], knots: Sequence[float], degree: int) -> Callable[[Any], Point]:
    """``s -> S(s)``: the B-spline of ``poles`` (rows), flat ``knots`` (multiplicities repeated) and ``degree``."""
    ps = [[mp.mpf(c) for c in p] for p in poles]
    ks = [mp.mpf(k) for k in knots]
    dim = len(ps[0])

    def point(s: Any) -> Point:
        s = mp.mpf(s)
        k = max(i for i in range(degree, len(ps)) if ks[i] <= s)
        d = [list(ps[j]) for j in range(k - degree, k + 1)]
        for r in range(1, degree + 1):
            for j in range(degree, r - 1, -1):
                a = (s - ks[j + k - degree]) / (ks[j + 1 + k - r] - ks[j + k - degree])
                d[j] = [(1 - a) * d[j - 1][q] + a * d[j][q] for q in range(dim)]
        return d[degree]

    return point


def of_curve(curve: Any, dim: int = 3) -> Callable[[Any], Point]:
    """:func:`de_boor` of an OCCT ``Geom_BSplineCurve`` (not rational): its first ``dim`` coordinates."""
    poles = [curve.Pole(i).Coord()[:dim] for i in range(1, curve.NbPoles() + 1)]
    knots = [curve.Knot(i) for i in range(1, curve.NbKnots() + 1) for _ in range(curve.Multiplicity(i))]
    return de_boor(poles, knots, curve.Degree())

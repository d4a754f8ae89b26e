"""Known edge pairs with independently computed truth (sympy/closed forms), raw OCP edges."""

from __future__ import annotations

import math
from fractions import Fraction

import sympy as sp
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.Geom import Geom_BezierCurve
from OCP.gp import gp_Pnt

from relief_cad.cad._compat import Array1OfPnt


def segment(p, q):
    return BRepBuilderAPI_MakeEdge(gp_Pnt(*map(float, p)), gp_Pnt(*map(float, q))).Edge()


def bezier(points):
    arr = Array1OfPnt(1, len(points))
    for i, p in enumerate(points):
        arr.SetValue(i + 1, gp_Pnt(*(float(c) for c in p)))
    return BRepBuilderAPI_MakeEdge(Geom_BezierCurve(arr)).Edge()


def bernstein_of(poly_in_x, n):
    """Exact Bernstein coefficients of poly(2t - 1), degree n."""
    t = sp.symbols("t")
    p = sp.Poly(sp.expand(poly_in_x(2 * t - 1)), t)
    a = [p.coeff_monomial(t**k) for k in range(n + 1)]
    return [sum(sp.Rational(sp.binomial(i, k), sp.binomial(n, k)) * a[k] for k in range(i + 1)) for i in range(n + 1)]


def graph_curve(coeffs):
    """Bézier (x, y) = (2t - 1, sum b_i B_i(t)) with the given y coefficients (floats)."""
    n = len(coeffs) - 1
    return bezier([(-1 + Fraction(2 * i, n), float(c), 0.0) for i, c in enumerate(coeffs)])


def flat_contact(n):
    """y = x^n on [-1, 1] against the x axis: one tangent point at x = 0 (t = 1/2, u = 1)."""
    return graph_curve(bernstein_of(lambda x: x**n, n)), segment((-1, 0, 0), (1, 0, 0))


def chebyshev_pair(n):
    """y = T_n(x) (Bernstein data rounded to binary64) against the x axis, and the exact roots.

    The truth is computed on the rounded data itself: the roots of the exact rational
    polynomial sum(b_i B_i(t)) with b_i the binary64 coefficients, isolated by sympy.
    """
    coeffs = [float(c) for c in bernstein_of(lambda x: sp.chebyshevt(n, x), n)]
    t = sp.symbols("t")
    y = sum(sp.Rational(c) * sp.binomial(n, i) * t**i * (1 - t) ** (n - i) for i, c in enumerate(coeffs))
    roots = [float(r.evalf(30)) for r in sp.Poly(sp.expand(y), t).real_roots() if 0 <= r <= 1]
    return graph_curve(coeffs), segment((-1, 0, 0), (1, 0, 0)), sorted(roots)


def near(x, y, tol):
    return math.dist(tuple(x), tuple(y)) <= tol

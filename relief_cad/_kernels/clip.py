"""Fat lines and convex-hull clipping of a parameter range.

Bézier clipping (the paper's §4): the fat line of a curve and the explicit Bézier functions of
the signed distance, bounded by their convex hull.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
from cython.cimports.libc.math import atan2, hypot, sqrt

from .constants import _EPS

_INF = cython.declare(cython.double, math.inf)  # a C constant (``math.inf`` is a Python lookup)
_PI = cython.declare(cython.double, math.pi)
_C_EPS = cython.declare(cython.double, _EPS)  # a C copy of the machine epsilon


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _norm(x: cython.double, y: cython.double) -> cython.double:
    """``|(x, y)|``: ``sqrt(x² + y²)`` (within an ulp), ``hypot`` where the squares could over- or underflow.

    glibc's ``hypot`` (correctly rounded since 2.35) costs about as much as the rest of a fat
    line; the square root of the sum of squares is within an ulp of it for squares between
    1e-290 and 1e290, which is where every fat line of the normalised frame lies but a point-like one.
    """
    q: cython.double = x * x + y * y
    if 1e-290 < q < 1e290:
        return sqrt(q)
    return hypot(x, y)


def fat_line_kernel(P: cython.const[cython.double][:, :], perpendicular: cython.bint):
    """Fat line ``(nx, ny, c, dmin, dmax)`` of control points ``P`` (not widened).

    The signed distance is ``d(x, y) = nx x + ny y + c`` (unit normal); every
    control point, hence the curve, has ``dmin <= d <= dmax``. The line runs
    through the end points; when they (nearly) coincide it runs from the first
    point to the farthest control point; for a point-like polygon it is the x axis
    direction. ``perpendicular`` swaps in the perpendicular direction (the fat line
    bounding the curve *along* its chord).
    """
    i: cython.Py_ssize_t
    m: cython.Py_ssize_t = P.shape[0]
    n: cython.Py_ssize_t = m - 1
    nx: cython.double
    ny: cython.double
    d: cython.double
    x0 = P[0, 0]
    y0 = P[0, 1]
    ex = P[n, 0] - x0
    ey = P[n, 1] - y0
    chord = _norm(ex, ey)
    far: cython.double = 0.0
    fx: cython.double = 0.0
    fy: cython.double = 0.0
    for i in range(1, m):
        ddx = P[i, 0] - x0
        ddy = P[i, 1] - y0
        dd = ddx * ddx + ddy * ddy
        if dd > far:
            far = dd
            fx = ddx
            fy = ddy
    if chord * chord <= 1e-6 * far:
        ex = fx
        ey = fy
        chord = sqrt(far)
    if chord == 0.0:
        ex = 1.0
        ey = 0.0
        chord = 1.0
    if perpendicular:
        nx = ex / chord
        ny = ey / chord
    else:
        nx = -ey / chord
        ny = ex / chord
    c = -(nx * x0 + ny * y0)
    dmin: cython.double = _INF
    dmax: cython.double = -_INF
    for i in range(m):
        d = nx * P[i, 0] + ny * P[i, 1] + c
        dmin = min(dmin, d)
        dmax = max(dmax, d)
    return nx, ny, c, dmin, dmax


def hull_range_kernel(e: cython.double[:]):
    """Parameter range where the convex hull of ``(j / m, e[j])`` reaches ``e >= 0``.

    Returns ``(lo, hi)``; ``lo > hi`` means the hull lies entirely below zero.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    ei: cython.double
    ej: cython.double
    si: cython.double
    sj: cython.double
    s: cython.double
    m: cython.Py_ssize_t = e.shape[0] - 1
    h: cython.double = 1.0 / cython.cast(cython.double, m)
    lo: cython.double = _INF
    hi: cython.double = -_INF
    for j in range(m + 1):
        if e[j] >= 0.0:
            sj = j * h
            lo = min(lo, sj)
            hi = max(hi, sj)
    if lo == 0.0 and hi == 1.0:
        return lo, hi
    # hull edges crossing zero: segments from a point below to a point above
    for i in range(m + 1):
        ei = e[i]
        if ei >= 0.0:
            continue
        si = i * h
        for j in range(m + 1):
            ej = e[j]
            if ej <= 0.0:
                continue
            sj = j * h
            if lo <= min(si, sj) and max(si, sj) <= hi:
                continue  # this crossing cannot widen [lo, hi]
            s = si + (sj - si) * (ei / (ei - ej))
            lo = min(lo, s)
            hi = max(hi, s)
    if lo < 0.0:
        lo = 0.0
    if hi > 1.0:
        hi = 1.0
    return lo, hi


def clip_range_kernel(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    nx: cython.double,
    ny: cython.double,
    c: cython.double,
    dmin: cython.double,
    dmax: cython.double,
    e: cython.double[:],
):
    """Range ``(lo, hi)`` of a rational curve's parameter where ``dmin <= d <= dmax`` is possible.

    ``d`` is the signed distance ``nx x + ny y + c`` of the curve ``(P, W)``;
    ``dmin <= d(s)`` is ``sum W_j (d_j - dmin) B_j(s) >= 0`` and ``d(s) <= dmax`` is
    ``sum W_j (dmax - d_j) B_j(s) >= 0`` (the weights' sum is positive), and each is
    bounded by the convex hull of its Bézier function. ``e`` is scratch of length
    ``n + 1``. Returns ``lo > hi`` when the curve cannot meet the strip.
    """
    j: cython.Py_ssize_t
    lo1: cython.double
    hi1: cython.double
    lo2: cython.double
    hi2: cython.double
    m: cython.Py_ssize_t = P.shape[0]
    for j in range(m):
        e[j] = W[j] * (nx * P[j, 0] + ny * P[j, 1] + c - dmin)
    lo1, hi1 = hull_range_kernel(e)
    if lo1 > hi1:
        return 1.0, 0.0
    for j in range(m):
        e[j] = W[j] * (dmax - (nx * P[j, 0] + ny * P[j, 1] + c))
    lo2, hi2 = hull_range_kernel(e)
    return max(lo1, lo2), min(hi1, hi2)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _cone(P: cython.const[cython.double][:, :], err: cython.double) -> tuple[cython.double, cython.double]:
    """The angles ``(lo, hi)`` (radians) of a cone holding every tangent direction of the curve ``P``.

    ``P``: Cartesian control points of a rational Bézier curve of positive weights, each within
    ``err`` of the exact one. Its derivative is a combination with non-negative coefficients of
    the differences ``P_j - P_i``, ``i < j`` (``w_i w_j B_i B_j (j - i) / (t (1 - t) W^2)``), each a
    sum of legs ``P_k+1 - P_k`` of the control polygon: each tangent direction lies in the cone of
    the legs. Each leg's angle is widened by the error of its ends and its rounding (``2 err + 4
    eps`` times the largest coordinate, over its length). ``lo > hi`` when the cone is not known
    to be narrower than a right angle (a leg too short to tell its direction, or directions too
    far apart).
    """
    i: cython.Py_ssize_t
    m: cython.Py_ssize_t = P.shape[0]
    big: cython.double = 0.0
    for i in range(m):
        big = max(big, abs(P[i, 0]), abs(P[i, 1]))
    rx: cython.double = P[m - 1, 0] - P[0, 0]  # the chord: a sum of the legs
    ry: cython.double = P[m - 1, 1] - P[0, 1]
    if rx == 0.0 and ry == 0.0:
        return 1.0, 0.0
    off: cython.double = 2.0 * err + 4.0 * _C_EPS * big  # a leg's end points' error (> 0 here)
    lo: cython.double = 0.0
    hi: cython.double = 0.0
    for i in range(m - 1):
        vx = P[i + 1, 0] - P[i, 0]
        vy = P[i + 1, 1] - P[i, 1]
        n = hypot(vx, vy)
        if not off <= 1e-3 * n:  # a repeated point too: no direction to tell
            return 1.0, 0.0
        a = atan2(rx * vy - ry * vx, rx * vx + ry * vy)  # from the chord's direction
        lo = min(lo, a - 2.0 * off / n)  # asin(off / n) < 2 off / n for off / n <= 1e-3
        hi = max(hi, a + 2.0 * off / n)
    if hi - lo >= 0.5 * _PI:
        return 1.0, 0.0
    base = atan2(ry, rx)
    return base + lo, base + hi


def cones_apart(P: cython.const[cython.double][:, :], Q: cython.const[cython.double][:, :],
                ep: cython.double = 0.0, eq: cython.double = 0.0) -> cython.bint:
    """True when no tangent of the curve ``P`` can be parallel to one of ``Q``: they meet at most once.

    ``P``, ``Q``: Cartesian control points of planar rational Bézier curves of positive weights,
    each point within ``ep`` (``eq``) of the exact one (model units; 0 for exact data). The cones
    of their tangent directions (:func:`_cone`) are compared as lines (directions modulo pi).
    Two meetings would give both curves the chord between them, and a chord of a curve is an
    integral of its derivative, so it lies in the curve's cone: in both. (The tangent-cone test
    of Sederberg and Meyers; not part of the paper.)

    >>> import numpy as np
    >>> steep = np.array([[0.0, -1.0], [0.1, 0.0], [0.0, 1.0]])
    >>> flat = np.array([[-1.0, 0.0], [0.0, 0.1], [1.0, 0.0]])
    >>> bool(cones_apart(steep, flat)), bool(cones_apart(flat, flat[::-1].copy()))
    (True, False)
    >>> bool(cones_apart(steep, flat, 0.01, 0.01))  # points known to 0.01 only: cones too wide
    False
    """
    alo, ahi = _cone(P, ep)
    if not alo <= ahi:
        return False
    blo, bhi = _cone(Q, eq)
    if not blo <= bhi:
        return False
    k: cython.int
    for k in range(-3, 4):
        if blo + k * _PI <= ahi + 1e-15 and alo <= bhi + k * _PI + 1e-15:
            return False
    return True

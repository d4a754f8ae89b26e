"""Newton polishing, closest points, projections on planar curves and coincidence tests.

The post-processing of the clipping candidates (the paper's §4) and the overlap test.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import hypot, sqrt

from .bezier import _cartesian, _eval, _segment
from .clip import clip_range_kernel, fat_line_kernel

_INF = cython.declare(cython.double, math.inf)  # a C constant (``math.inf`` is a Python lookup)


def _newton(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wa: cython.double[:, :],
    wb: cython.double[:, :],
    iters: cython.Py_ssize_t,
):
    """Newton on ``a(t) - b(u) = 0`` from ``(t, u)``, clamped to the unit square.

    Returns ``(t, u, residual)`` of the best iterate.
    """
    bt = t
    bu = u
    bres = _INF
    stall = 0
    for _ in range(iters):
        ax, ay, adx, ady, _a2, _a3 = _eval(HA, t, wa)
        bx, by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
        fx = ax - bx
        fy = ay - by
        res = hypot(fx, fy)
        if res < bres:
            bres = res
            bt = t
            bu = u
            stall = 0
        else:
            stall += 1
            if stall >= 3:
                break
        if res == 0.0:
            break
        det = -adx * bdy + ady * bdx
        scale = hypot(adx, ady) * hypot(bdx, bdy)
        if scale == 0.0 or abs(det) <= 1e-300:
            break
        # J = [[adx, -bdx], [ady, -bdy]]; J d = -F
        dt = (-fx * (-bdy) + bdx * (-fy)) / det
        du = (adx * (-fy) - ady * (-fx)) / det
        nt = min(1.0, max(0.0, t + dt))
        nu = min(1.0, max(0.0, u + du))
        if nt == t and nu == u:
            break
        t = nt
        u = nu
        if abs(dt) <= 1e-15 and abs(du) <= 1e-15:
            # converged to rounding: one last evaluation decides
            ax, ay, adx, ady, _a2, _a3 = _eval(HA, t, wa)
            bx, by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
            res = hypot(ax - bx, ay - by)
            if res < bres:
                bres = res
                bt = t
                bu = u
            break
    return bt, bu, bres


def _closest(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wa: cython.double[:, :],
    wb: cython.double[:, :],
    iters: cython.Py_ssize_t,
):
    """Local minimum of ``|a(t) - b(u)|`` from ``(t, u)`` (damped Newton, clamped).

    Returns ``(t, u, distance)``.
    """
    ax, ay, adx, ady, addx, addy = _eval(HA, t, wa)
    bx, by, bdx, bdy, bddx, bddy = _eval(HB, u, wb)
    fx = ax - bx
    fy = ay - by
    f2 = fx * fx + fy * fy
    lam: cython.double = 0.0  # declared: inference gives up on ``lam = max(2.0 * lam, ...)``
    nt: cython.double
    nu: cython.double
    dt: cython.double
    du: cython.double
    det: cython.double
    a11: cython.double
    a22: cython.double
    for _ in range(iters):
        g1 = fx * adx + fy * ady
        g2 = -(fx * bdx + fy * bdy)
        h11 = adx * adx + ady * ady + fx * addx + fy * addy
        h22 = bdx * bdx + bdy * bdy - (fx * bddx + fy * bddy)
        h12 = -(adx * bdx + ady * bdy)
        improved = False
        for _k in range(30):
            a11 = h11 + lam
            a22 = h22 + lam
            det = a11 * a22 - h12 * h12
            if a11 <= 0.0 or det <= 0.0:
                lam = max(2.0 * lam, 1e-12 * (abs(h11) + abs(h22)) + 1e-300)
                continue
            dt = -(a22 * g1 - h12 * g2) / det
            du = -(a11 * g2 - h12 * g1) / det
            nt = min(1.0, max(0.0, t + dt))
            nu = min(1.0, max(0.0, u + du))
            if nt == t and nu == u:
                break
            nax, nay, nadx, nady, naddx, naddy = _eval(HA, nt, wa)
            nbx, nby, nbdx, nbdy, nbddx, nbddy = _eval(HB, nu, wb)
            nfx = nax - nbx
            nfy = nay - nby
            nf2 = nfx * nfx + nfy * nfy
            if nf2 <= f2:
                t = nt
                u = nu
                ax, ay, adx, ady, addx, addy = nax, nay, nadx, nady, naddx, naddy
                bx, by, bdx, bdy, bddx, bddy = nbx, nby, nbdx, nbdy, nbddx, nbddy
                fx = nfx
                fy = nfy
                f2 = nf2
                lam *= 0.1
                improved = True
                break
            lam = max(4.0 * lam, 1e-12 * (abs(h11) + abs(h22)) + 1e-300)
        if not improved:
            break
    return t, u, sqrt(f2)


def _point_on(
    H: cython.const[cython.double][:, :],
    px: cython.double,
    py: cython.double,
    tol: cython.double,
    S: cython.double[:, :],
    C: cython.double[:, :],
    V: cython.double[:],
    e: cython.double[:],
    wk: cython.double[:, :],
):
    """Closest point of curve ``H`` to ``(px, py)`` if it may be within ``tol``.

    Clips the parameter range against two perpendicular strips of half-width
    ``tol`` around the point (cheap rejection), then projects by Newton.
    Returns ``(u, distance)`` with ``distance = inf`` when rejected.
    """
    perp: cython.bint
    u0 = 0.0
    u1 = 1.0
    for _ in range(30):
        _segment(H, u0, u1, S)
        xl, xh, yl, yh = _cartesian(S, C, V)
        if px < xl - tol or px > xh + tol or py < yl - tol or py > yh + tol:
            return 0.0, _INF
        if hypot(xh - xl, yh - yl) <= tol:
            break
        w0 = u1 - u0
        for iperp in range(2):
            perp = iperp == 1  # the fat line along the chord, then across it
            nx, ny, c, _dmin, _dmax = fat_line_kernel(C, perp)
            dp = nx * px + ny * py + c
            lo, hi = clip_range_kernel(C, V, nx, ny, c, dp - tol, dp + tol, e)
            if lo > hi:
                return 0.0, _INF
            w = u1 - u0
            nu0 = u0 + lo * w
            u1 = max(nu0, u0 + hi * w)
            u0 = nu0
            if not perp:
                _segment(H, u0, u1, S)
                _cartesian(S, C, V)
        if u1 - u0 > 0.8 * w0:
            # stalled (several candidate stretches): sample the remaining range
            best = _INF
            bu = u0
            for k in range(17):
                uu = u0 + (u1 - u0) * (k / 16.0)
                x, y, _dx, _dy, _ddx, _ddy = _eval(H, uu, wk)
                d = hypot(x - px, y - py)
                if d < best:
                    best = d
                    bu = uu
            u0 = bu
            u1 = bu
            break
    u = 0.5 * (u0 + u1)
    x, y, _dx, _dy, _ddx, _ddy = _eval(H, u, wk)
    best = hypot(x - px, y - py)
    bu = u
    for _ in range(40):
        x, y, dx, dy, ddx, ddy = _eval(H, u, wk)
        fx = x - px
        fy = y - py
        g = fx * dx + fy * dy
        h = dx * dx + dy * dy + fx * ddx + fy * ddy
        if h <= 0.0:
            h = dx * dx + dy * dy
            if h == 0.0:
                break
        nu = min(1.0, max(0.0, u - g / h))
        if nu == u:
            break
        x, y, _dx, _dy, _ddx, _ddy = _eval(H, nu, wk)
        d = hypot(x - px, y - py)
        if d > best:
            break
        best = d
        bu = nu
        u = nu
    return bu, best


def _local_dist(
    H: cython.const[cython.double][:, :],
    px: cython.double,
    py: cython.double,
    u: cython.double,
    wk: cython.double[:, :],
):
    """Distance from ``(px, py)`` to curve ``H`` near ``u`` (a few projection Newton steps)."""
    for _ in range(8):
        x, y, dx, dy, ddx, ddy = _eval(H, u, wk)
        fx = x - px
        fy = y - py
        h = dx * dx + dy * dy + fx * ddx + fy * ddy
        if h <= 0.0:
            h = dx * dx + dy * dy
            if h == 0.0:
                break
        nu = min(1.0, max(0.0, u - (fx * dx + fy * dy) / h))
        if nu == u:
            break
        u = nu
    x, y, _dx, _dy, _ddx, _ddy = _eval(H, u, wk)
    return hypot(x - px, y - py)


def _angle_sin(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wa: cython.double[:, :],
    wb: cython.double[:, :],
):
    """``|sin|`` of the angle between the curves' tangents at ``a(t)``, ``b(u)``.

    A zero first derivative falls back on the second one; ``1.0`` when undefined.
    """
    _ax, _ay, adx, ady, addx, addy = _eval(HA, t, wa)
    _bx, _by, bdx, bdy, bddx, bddy = _eval(HB, u, wb)
    la = hypot(adx, ady)
    if la == 0.0:
        adx, ady = addx, addy
        la = hypot(adx, ady)
    lb = hypot(bdx, bdy)
    if lb == 0.0:
        bdx, bdy = bddx, bddy
        lb = hypot(bdx, bdy)
    if la == 0.0 or lb == 0.0:
        return 1.0
    return abs(adx * bdy - ady * bdx) / (la * lb)


def _local_proj(
    H: cython.const[cython.double][:, :],
    px: cython.double,
    py: cython.double,
    u: cython.double,
    wk: cython.double[:, :],
):
    """Parameter of the point of ``H`` nearest ``(px, py)`` close to ``u`` (safeguarded Newton)."""
    x, y, dx, dy, ddx, ddy = _eval(H, u, wk)
    best = hypot(x - px, y - py)
    bu = u
    for _ in range(30):
        fx = x - px
        fy = y - py
        g = fx * dx + fy * dy
        h = dx * dx + dy * dy + fx * ddx + fy * ddy
        if h <= 0.0:
            h = dx * dx + dy * dy
        if not h > 0.0:
            # zero speed (repeated control points): nudge inwards
            nu = min(1.0, max(0.0, u + (1e-6 if u < 0.5 else -1e-6)))
        else:
            nu = min(1.0, max(0.0, u - g / h))
        if abs(nu - u) <= 1e-16:
            break
        u = nu
        x, y, dx, dy, ddx, ddy = _eval(H, u, wk)
        d = hypot(x - px, y - py)
        if d < best:
            best = d
            bu = u
    return bu


def _coincide(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    ta: cython.double,
    ua: cython.double,
    tb: cython.double,
    ub: cython.double,
    tol: cython.double,
    wa: cython.double[:, :],
    wb: cython.double[:, :],
    nsamp: cython.Py_ssize_t,
):
    """True when a on ``[ta, tb]`` and b on ``[ua, ub]`` coincide (within ``tol``).

    Marches along ``a`` projecting onto ``b`` (and back), requiring monotone ``u``.
    """
    u = ua
    direction = 1.0 if ub > ua else -1.0
    k: cython.Py_ssize_t
    j: cython.Py_ssize_t
    fwd: cython.double[:] = np.empty(nsamp + 1)
    fwd[0] = ua
    fwd[nsamp] = ub
    for k in range(1, nsamp):
        s = ta + (tb - ta) * (cython.cast(cython.double, k) / nsamp)  # true division (k, nsamp: C ints)
        px, py, _a, _b, _c, _d = _eval(HA, s, wa)
        uu = _local_proj(HB, px, py, u, wb)
        x, y, _a, _b, _c, _d = _eval(HB, uu, wb)
        if hypot(x - px, y - py) > tol:
            return False
        if (uu - u) * direction < -1e-12:
            return False
        u = uu
        fwd[k] = uu
    if (ub - u) * direction < -1e-12:
        return False
    # and back: b's stretch lies on a (seeded from the forward correspondence)
    for k in range(1, nsamp):
        s = ua + (ub - ua) * (cython.cast(cython.double, k) / nsamp)
        j = 0
        while j < nsamp - 1 and (fwd[j + 1] - s) * direction < 0.0:
            j += 1
        seed = ta + (tb - ta) * (cython.cast(cython.double, j) / nsamp)
        px, py, _a, _b, _c, _d = _eval(HB, s, wb)
        tt = _local_proj(HA, px, py, seed, wa)
        x, y, _a, _b, _c, _d = _eval(HA, tt, wa)
        if hypot(x - px, y - py) > tol:
            return False
    return True

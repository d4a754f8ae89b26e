"""Numba kernels of the planar Bézier-clipping intersector and of the space relief scheme (hot loops only).

Every function here is ``@njit(cache=True, error_model="numpy")`` and also runs as plain Python when
``NUMBA_DISABLE_JIT=1``. The public, documented API lives in
:mod:`relief_cad.intersection` and :mod:`relief_cad.clipping`; these kernels have
no stability promise.

Data layout
-----------
A planar rational curve is passed as Cartesian control points ``P`` of shape
``(n + 1, 2)`` and weights ``W`` of shape ``(n + 1,)``. Inside a pair solve both
curves are moved by an *exact* translation (Sterbenz) and an exact power-of-two
scaling into a frame of size about 1, and converted to homogeneous rows
``(w x, w y, w)``; the clipping and the Newton polish work in that frame.

Result rows (``RES_COLS`` columns)
    ``[pair, kind, t, u, t1, u1, x, y, distance]`` with ``kind`` one of
    :data:`KIND_CROSSING`, :data:`KIND_TANGENT`, :data:`KIND_OVERLAP`,
    :data:`KIND_UNRESOLVED` (then ``t, t1, u, u1`` hold the box ``t0, t1, u0, u1``
    in the ``t, t1, u, u1`` columns).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = [
    "KIND_CROSSING",
    "KIND_OVERLAP",
    "KIND_TANGENT",
    "KIND_UNRESOLVED",
    "RES_COLS",
    "clip_range_kernel",
    "fat_line_kernel",
    "hull_range_kernel",
    "intersect_batch_kernel",
    "intersect_one_kernel",
    "intersect_pair_kernel",
    "SPACE_COLS",
    "STATUS_ARTEFACT",
    "STATUS_OK",
    "space_pair_kernel",
]

KIND_CROSSING = 0
KIND_TANGENT = 1
KIND_OVERLAP = 2
KIND_UNRESOLVED = 3
RES_COLS = 9

_EPS = 2.220446049250313e-16
_SPLIT_RATIO = 0.8  # a clip keeping more than 80 % of an interval counts as a stall
_ROUND = 64.0 * _EPS  # rounding level of a residual, relative to the frame size (~1)


# --------------------------------------------------------------------------- helpers


@njit(cache=True, error_model="numpy")
def _grow(arr, n):  # type: ignore[no-untyped-def]
    """Return ``arr`` with room for at least ``n`` rows (copying when it must grow)."""
    if n <= arr.shape[0]:
        return arr
    cap = max(n, 2 * arr.shape[0])
    out = np.empty((cap, arr.shape[1]))
    out[: arr.shape[0], :] = arr
    return out


@njit(cache=True, error_model="numpy")
def _segment(H, t0, t1, out):  # type: ignore[no-untyped-def]
    """Homogeneous control points of the sub-curve on ``[t0, t1]`` into ``out``."""
    m = H.shape[0]
    n = m - 1
    for i in range(m):
        out[i, 0] = H[i, 0]
        out[i, 1] = H[i, 1]
        out[i, 2] = H[i, 2]
    if t1 < 1.0:
        s = 1.0 - t1
        for r in range(1, n + 1):
            for i in range(n, r - 1, -1):
                out[i, 0] = s * out[i - 1, 0] + t1 * out[i, 0]
                out[i, 1] = s * out[i - 1, 1] + t1 * out[i, 1]
                out[i, 2] = s * out[i - 1, 2] + t1 * out[i, 2]
    if t0 > 0.0:
        tt = t0 / t1 if t1 < 1.0 else t0
        s = 1.0 - tt
        for r in range(1, n + 1):
            for i in range(0, n - r + 1):
                out[i, 0] = s * out[i, 0] + tt * out[i + 1, 0]
                out[i, 1] = s * out[i, 1] + tt * out[i + 1, 1]
                out[i, 2] = s * out[i, 2] + tt * out[i + 1, 2]


@njit(cache=True, error_model="numpy")
def _cartesian(S, P, W):  # type: ignore[no-untyped-def]
    """Cartesian points and weights (weights scaled to max 1) of homogeneous rows ``S``.

    Returns the bounding box ``(xlo, xhi, ylo, yhi)`` of the points.
    """
    m = S.shape[0]
    wmax = 0.0
    for i in range(m):
        if S[i, 2] > wmax:
            wmax = S[i, 2]
    xlo = math.inf
    xhi = -math.inf
    ylo = math.inf
    yhi = -math.inf
    iwmax = 1.0 / wmax
    for i in range(m):
        w = S[i, 2]
        iw = 1.0 / w
        x = S[i, 0] * iw
        y = S[i, 1] * iw
        P[i, 0] = x
        P[i, 1] = y
        W[i] = w * iwmax
        xlo = min(xlo, x)
        xhi = max(xhi, x)
        ylo = min(ylo, y)
        yhi = max(yhi, y)
    return xlo, xhi, ylo, yhi


@njit(cache=True, error_model="numpy")
def _eval(H, t, wk):  # type: ignore[no-untyped-def]
    """Point, first and second derivative of the rational curve ``H`` at ``t``.

    Returns ``(x, y, dx, dy, ddx, ddy)``; ``wk`` is scratch of ``H``'s shape.
    """
    m = H.shape[0]
    n = m - 1
    s = 1.0 - t
    if n == 1:
        vx = s * H[0, 0] + t * H[1, 0]
        vy = s * H[0, 1] + t * H[1, 1]
        vw = s * H[0, 2] + t * H[1, 2]
        d1x = H[1, 0] - H[0, 0]
        d1y = H[1, 1] - H[0, 1]
        d1w = H[1, 2] - H[0, 2]
        d2x = 0.0
        d2y = 0.0
        d2w = 0.0
    else:
        for i in range(m):
            wk[i, 0] = H[i, 0]
            wk[i, 1] = H[i, 1]
            wk[i, 2] = H[i, 2]
        for r in range(1, n - 1):
            for i in range(0, m - r):
                wk[i, 0] = s * wk[i, 0] + t * wk[i + 1, 0]
                wk[i, 1] = s * wk[i, 1] + t * wk[i + 1, 1]
                wk[i, 2] = s * wk[i, 2] + t * wk[i + 1, 2]
        r0x = s * wk[0, 0] + t * wk[1, 0]
        r0y = s * wk[0, 1] + t * wk[1, 1]
        r0w = s * wk[0, 2] + t * wk[1, 2]
        r1x = s * wk[1, 0] + t * wk[2, 0]
        r1y = s * wk[1, 1] + t * wk[2, 1]
        r1w = s * wk[1, 2] + t * wk[2, 2]
        vx = s * r0x + t * r1x
        vy = s * r0y + t * r1y
        vw = s * r0w + t * r1w
        d1x = n * (r1x - r0x)
        d1y = n * (r1y - r0y)
        d1w = n * (r1w - r0w)
        c = n * (n - 1)
        d2x = c * (wk[2, 0] - 2.0 * wk[1, 0] + wk[0, 0])
        d2y = c * (wk[2, 1] - 2.0 * wk[1, 1] + wk[0, 1])
        d2w = c * (wk[2, 2] - 2.0 * wk[1, 2] + wk[0, 2])
    x = vx / vw
    y = vy / vw
    dx = (d1x - x * d1w) / vw
    dy = (d1y - y * d1w) / vw
    ddx = (d2x - 2.0 * dx * d1w - x * d2w) / vw
    ddy = (d2y - 2.0 * dy * d1w - y * d2w) / vw
    return x, y, dx, dy, ddx, ddy


# --------------------------------------------------------------------------- clipping


@njit(cache=True, error_model="numpy")
def fat_line_kernel(P, perpendicular):  # type: ignore[no-untyped-def]
    """Fat line ``(nx, ny, c, dmin, dmax)`` of control points ``P`` (not widened).

    The signed distance is ``d(x, y) = nx x + ny y + c`` (unit normal); every
    control point, hence the curve, has ``dmin <= d <= dmax``. The line runs
    through the end points; when they (nearly) coincide it runs from the first
    point to the farthest control point; for a point-like polygon it is the x axis
    direction. ``perpendicular`` swaps in the perpendicular direction (the fat line
    bounding the curve *along* its chord).
    """
    m = P.shape[0]
    n = m - 1
    x0 = P[0, 0]
    y0 = P[0, 1]
    ex = P[n, 0] - x0
    ey = P[n, 1] - y0
    chord = math.hypot(ex, ey)
    far = 0.0
    fx = 0.0
    fy = 0.0
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
        chord = math.sqrt(far)
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
    dmin = math.inf
    dmax = -math.inf
    for i in range(m):
        d = nx * P[i, 0] + ny * P[i, 1] + c
        dmin = min(dmin, d)
        dmax = max(dmax, d)
    return nx, ny, c, dmin, dmax


@njit(cache=True, error_model="numpy")
def hull_range_kernel(e):  # type: ignore[no-untyped-def]
    """Parameter range where the convex hull of ``(j / m, e[j])`` reaches ``e >= 0``.

    Returns ``(lo, hi)``; ``lo > hi`` means the hull lies entirely below zero.
    """
    m = e.shape[0] - 1
    h = 1.0 / m
    lo = math.inf
    hi = -math.inf
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


@njit(cache=True, error_model="numpy")
def clip_range_kernel(P, W, nx, ny, c, dmin, dmax, e):  # type: ignore[no-untyped-def]
    """Range ``(lo, hi)`` of a rational curve's parameter where ``dmin <= d <= dmax`` is possible.

    ``d`` is the signed distance ``nx x + ny y + c`` of the curve ``(P, W)``;
    ``dmin <= d(s)`` is ``sum W_j (d_j - dmin) B_j(s) >= 0`` and ``d(s) <= dmax`` is
    ``sum W_j (dmax - d_j) B_j(s) >= 0`` (the weights' sum is positive), and each is
    bounded by the convex hull of its Bézier function. ``e`` is scratch of length
    ``n + 1``. Returns ``lo > hi`` when the curve cannot meet the strip.
    """
    m = P.shape[0]
    for j in range(m):
        e[j] = W[j] * (nx * P[j, 0] + ny * P[j, 1] + c - dmin)
    lo1, hi1 = hull_range_kernel(e)
    if lo1 > hi1:
        return 1.0, 0.0
    for j in range(m):
        e[j] = W[j] * (dmax - (nx * P[j, 0] + ny * P[j, 1] + c))
    lo2, hi2 = hull_range_kernel(e)
    return max(lo1, lo2), min(hi1, hi2)


# --------------------------------------------------------------------------- polish


@njit(cache=True, error_model="numpy")
def _newton(HA, HB, t, u, wa, wb, iters):  # type: ignore[no-untyped-def]
    """Newton on ``a(t) - b(u) = 0`` from ``(t, u)``, clamped to the unit square.

    Returns ``(t, u, residual)`` of the best iterate.
    """
    bt = t
    bu = u
    bres = math.inf
    stall = 0
    for _ in range(iters):
        ax, ay, adx, ady, _a2, _a3 = _eval(HA, t, wa)
        bx, by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
        fx = ax - bx
        fy = ay - by
        res = math.hypot(fx, fy)
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
        scale = math.hypot(adx, ady) * math.hypot(bdx, bdy)
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
            res = math.hypot(ax - bx, ay - by)
            if res < bres:
                bres = res
                bt = t
                bu = u
            break
    return bt, bu, bres


@njit(cache=True, error_model="numpy")
def _closest(HA, HB, t, u, wa, wb, iters):  # type: ignore[no-untyped-def]
    """Local minimum of ``|a(t) - b(u)|`` from ``(t, u)`` (damped Newton, clamped).

    Returns ``(t, u, distance)``.
    """
    ax, ay, adx, ady, addx, addy = _eval(HA, t, wa)
    bx, by, bdx, bdy, bddx, bddy = _eval(HB, u, wb)
    fx = ax - bx
    fy = ay - by
    f2 = fx * fx + fy * fy
    lam = 0.0
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
    return t, u, math.sqrt(f2)


@njit(cache=True, error_model="numpy")
def _point_on(H, px, py, tol, S, C, V, e, wk):  # type: ignore[no-untyped-def]
    """Closest point of curve ``H`` to ``(px, py)`` if it may be within ``tol``.

    Clips the parameter range against two perpendicular strips of half-width
    ``tol`` around the point (cheap rejection), then projects by Newton.
    Returns ``(u, distance)`` with ``distance = inf`` when rejected.
    """
    u0 = 0.0
    u1 = 1.0
    for _ in range(30):
        _segment(H, u0, u1, S)
        xl, xh, yl, yh = _cartesian(S, C, V)
        if px < xl - tol or px > xh + tol or py < yl - tol or py > yh + tol:
            return 0.0, math.inf
        if math.hypot(xh - xl, yh - yl) <= tol:
            break
        w0 = u1 - u0
        for perp in (False, True):
            nx, ny, c, _dmin, _dmax = fat_line_kernel(C, perp)
            dp = nx * px + ny * py + c
            lo, hi = clip_range_kernel(C, V, nx, ny, c, dp - tol, dp + tol, e)
            if lo > hi:
                return 0.0, math.inf
            w = u1 - u0
            nu0 = u0 + lo * w
            u1 = max(nu0, u0 + hi * w)
            u0 = nu0
            if perp is False:
                _segment(H, u0, u1, S)
                _cartesian(S, C, V)
        if u1 - u0 > 0.8 * w0:
            # stalled (several candidate stretches): sample the remaining range
            best = math.inf
            bu = u0
            for k in range(17):
                uu = u0 + (u1 - u0) * (k / 16.0)
                x, y, _dx, _dy, _ddx, _ddy = _eval(H, uu, wk)
                d = math.hypot(x - px, y - py)
                if d < best:
                    best = d
                    bu = uu
            u0 = bu
            u1 = bu
            break
    u = 0.5 * (u0 + u1)
    x, y, _dx, _dy, _ddx, _ddy = _eval(H, u, wk)
    best = math.hypot(x - px, y - py)
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
        d = math.hypot(x - px, y - py)
        if d > best:
            break
        best = d
        bu = nu
        u = nu
    return bu, best


@njit(cache=True, error_model="numpy")
def _local_dist(H, px, py, u, wk):  # type: ignore[no-untyped-def]
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
    return math.hypot(x - px, y - py)


@njit(cache=True, error_model="numpy")
def _angle_sin(HA, HB, t, u, wa, wb):  # type: ignore[no-untyped-def]
    """``|sin|`` of the angle between the curves' tangents at ``a(t)``, ``b(u)``.

    A zero first derivative falls back on the second one; ``1.0`` when undefined.
    """
    _ax, _ay, adx, ady, addx, addy = _eval(HA, t, wa)
    _bx, _by, bdx, bdy, bddx, bddy = _eval(HB, u, wb)
    la = math.hypot(adx, ady)
    if la == 0.0:
        adx, ady = addx, addy
        la = math.hypot(adx, ady)
    lb = math.hypot(bdx, bdy)
    if lb == 0.0:
        bdx, bdy = bddx, bddy
        lb = math.hypot(bdx, bdy)
    if la == 0.0 or lb == 0.0:
        return 1.0
    return abs(adx * bdy - ady * bdx) / (la * lb)


# --------------------------------------------------------------------------- double-double


@njit(cache=True, error_model="numpy")
def _two_sum(a, b):  # type: ignore[no-untyped-def]
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@njit(cache=True, error_model="numpy")
def _two_prod(a, b):  # type: ignore[no-untyped-def]
    p = a * b
    c = 134217729.0 * a
    ah = c - (c - a)
    al = a - ah
    c = 134217729.0 * b
    bh = c - (c - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


@njit(cache=True, error_model="numpy")
def _dd_add(ah, al, bh, bl):  # type: ignore[no-untyped-def]
    s, e = _two_sum(ah, bh)
    e += al + bl
    return _two_sum(s, e)


@njit(cache=True, error_model="numpy")
def _dd_mul(ah, al, bh, bl):  # type: ignore[no-untyped-def]
    p, e = _two_prod(ah, bh)
    e += ah * bl + al * bh
    return _two_sum(p, e)


@njit(cache=True, error_model="numpy")
def _dd_div(ah, al, bh, bl):  # type: ignore[no-untyped-def]
    q1 = ah / bh
    ph, pl = _dd_mul(q1, 0.0, bh, bl)
    rh, rl = _dd_add(ah, al, -ph, -pl)
    q2 = rh / bh
    return _two_sum(q1, q2)


@njit(cache=True, error_model="numpy")
def _eval_dd(H, t, wk):  # type: ignore[no-untyped-def]
    """Point of the rational curve ``H`` at ``t`` in double-double ``(xh, xl, yh, yl)``.

    de Casteljau with every operation error-free-transformed (``wk``: scratch of
    shape ``(m, 6)``), so the result is accurate to about ``eps**2 * cond``.
    """
    m = H.shape[0]
    sh, sl = _two_sum(1.0, -t)
    for i in range(m):
        for k in range(3):
            wk[i, 2 * k] = H[i, k]
            wk[i, 2 * k + 1] = 0.0
    for r in range(1, m):
        for i in range(0, m - r):
            for k in range(3):
                ph, pl = _dd_mul(sh, sl, wk[i, 2 * k], wk[i, 2 * k + 1])
                qh, ql = _dd_mul(t, 0.0, wk[i + 1, 2 * k], wk[i + 1, 2 * k + 1])
                vh, vl = _dd_add(ph, pl, qh, ql)
                wk[i, 2 * k] = vh
                wk[i, 2 * k + 1] = vl
    xh, xl = _dd_div(wk[0, 0], wk[0, 1], wk[0, 4], wk[0, 5])
    yh, yl = _dd_div(wk[0, 2], wk[0, 3], wk[0, 4], wk[0, 5])
    return xh, xl, yh, yl


@njit(cache=True, error_model="numpy")
def _polish_dd(HA, HB, t, u, wa, wb, da, db, steps):  # type: ignore[no-untyped-def]
    """Newton steps on ``a(t) - b(u)`` with a double-double residual.

    Returns ``(t, u, certified)``: ``certified`` when the iteration reached a fixed
    point in double precision parameters (last step below 4e-16), i.e. an exact
    root lies within an ulp or two; a spurious root of a rounded double root
    keeps moving and is not certified.
    """
    for _ in range(steps):
        axh, axl, ayh, ayl = _eval_dd(HA, t, da)
        bxh, bxl, byh, byl = _eval_dd(HB, u, db)
        fx, _fxl = _dd_add(axh, axl, -bxh, -bxl)
        fy, _fyl = _dd_add(ayh, ayl, -byh, -byl)
        if fx == 0.0 and fy == 0.0:
            return t, u, True
        _ax, _ay, adx, ady, _a2, _a3 = _eval(HA, t, wa)
        _bx, _by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
        det = -adx * bdy + ady * bdx
        if det == 0.0:
            return t, u, False
        dt = (-fx * (-bdy) + bdx * (-fy)) / det
        du = (adx * (-fy) - ady * (-fx)) / det
        if abs(dt) > 0.25 or abs(du) > 0.25:
            return t, u, False
        nt = min(1.0, max(0.0, t + dt))
        nu = min(1.0, max(0.0, u + du))
        small = abs(dt) <= 4e-16 and abs(du) <= 4e-16
        t = nt
        u = nu
        if small:
            return t, u, True
    return t, u, False


# --------------------------------------------------------------------------- pair solve


@njit(cache=True, error_model="numpy")
def _frame(PA, PB):  # type: ignore[no-untyped-def]
    """Exact translation ``(cx, cy)`` and power-of-two scale of the joint frame."""
    cx = 0.0
    cy = 0.0
    for k in range(2):
        lo = math.inf
        hi = -math.inf
        for i in range(PA.shape[0]):
            lo = min(lo, PA[i, k])
            hi = max(hi, PA[i, k])
        for i in range(PB.shape[0]):
            lo = min(lo, PB[i, k])
            hi = max(hi, PB[i, k])
        c = 0.0
        # Sterbenz: x - c is exact when c / 2 <= x <= 2 c (same sign).
        if lo > 0.0 and hi <= 2.0 * lo:
            c = lo
        elif hi < 0.0 and lo >= 2.0 * hi:
            c = hi
        if k == 0:
            cx = c
        else:
            cy = c
    big = 0.0
    for i in range(PA.shape[0]):
        big = max(big, abs(PA[i, 0] - cx), abs(PA[i, 1] - cy))
    for i in range(PB.shape[0]):
        big = max(big, abs(PB[i, 0] - cx), abs(PB[i, 1] - cy))
    scale = 1.0
    if big > 0.0:
        e = max(math.frexp(big)[1], -1000)  # keep the scale finite for subnormal inputs
        scale = math.ldexp(1.0, -e)
    return cx, cy, scale


@njit(cache=True, error_model="numpy")
def _bbox_update(P, box):  # type: ignore[no-untyped-def]
    """Grow ``box = [xlo, xhi, ylo, yhi, max|coord|]`` by the points ``P``."""
    for i in range(P.shape[0]):
        x = P[i, 0]
        y = P[i, 1]
        box[0] = min(box[0], x)
        box[1] = max(box[1], x)
        box[2] = min(box[2], y)
        box[3] = max(box[3], y)
        box[4] = max(box[4], abs(x), abs(y))


@njit(cache=True, error_model="numpy")
def _curve_box_update(P, W, box):  # type: ignore[no-untyped-def]
    """Grow ``box`` (per coordinate ``[lo, hi]`` pairs) by samples of the curve itself.

    The curve is sampled at ``2 (n + 1) + 1`` uniform parameters by homogeneous de
    Casteljau: the curve's own extent, not its control polygon's (which can be far
    larger for ill-conditioned curves).
    """
    m = P.shape[0]
    d = P.shape[1]
    ns = 2 * m + 1
    wk = np.empty((m, d + 1))
    for k in range(ns):
        t = k / (ns - 1.0)
        s = 1.0 - t
        for i in range(m):
            for j in range(d):
                wk[i, j] = W[i] * P[i, j]
            wk[i, d] = W[i]
        for r in range(1, m):
            for i in range(m - r):
                for j in range(d + 1):
                    wk[i, j] = s * wk[i, j] + t * wk[i + 1, j]
        for j in range(d):
            x = wk[0, j] / wk[0, d]
            box[2 * j] = min(box[2 * j], x)
            box[2 * j + 1] = max(box[2 * j + 1], x)


@njit(cache=True, error_model="numpy")
def _default_tol(PA, WA, PB, WB):  # type: ignore[no-untyped-def]
    """:func:`relief_cad.tolerances.default_tolerance` of both curves (2-D or 3-D).

    ``1e-9`` times the diagonal of the curves' joint extent (sampled) plus ``64 eps``
    times the largest control-point coordinate (the rounding level of the data).
    """
    d = PA.shape[1]
    box = np.empty(2 * d)
    for j in range(d):
        box[2 * j] = math.inf
        box[2 * j + 1] = -math.inf
    _curve_box_update(PA, WA, box)
    _curve_box_update(PB, WB, box)
    big = 0.0
    for i in range(PA.shape[0]):
        for j in range(d):
            big = max(big, abs(PA[i, j]))
    for i in range(PB.shape[0]):
        for j in range(d):
            big = max(big, abs(PB[i, j]))
    diag = 0.0
    for j in range(d):
        diag += (box[2 * j + 1] - box[2 * j]) ** 2
    tol = 1e-9 * math.sqrt(diag) + 64.0 * _EPS * big
    if not (tol > 0.0 and tol < math.inf):
        return 1e-300
    return tol


@njit(cache=True, error_model="numpy")
def _homog(P, W, cx, cy, scale):  # type: ignore[no-untyped-def]
    """Homogeneous rows of the curve in the frame, weights scaled to max 1."""
    m = P.shape[0]
    wmax = 0.0
    for i in range(m):
        wmax = max(wmax, W[i])
    H = np.empty((m, 3))
    for i in range(m):
        w = W[i] / wmax
        H[i, 0] = w * ((P[i, 0] - cx) * scale)
        H[i, 1] = w * ((P[i, 1] - cy) * scale)
        H[i, 2] = w
    return H


@njit(cache=True, error_model="numpy")
def _in_overlap(ov, nov, t0, t1, u0, u1, margin):  # type: ignore[no-untyped-def]
    """True when the box lies inside one overlap's parameter rectangle (plus margin)."""
    for k in range(nov):
        a0 = ov[k, 0] - margin
        a1 = ov[k, 1] + margin
        b0 = min(ov[k, 2], ov[k, 3]) - margin
        b1 = max(ov[k, 2], ov[k, 3]) + margin
        if t0 >= a0 and t1 <= a1 and u0 >= b0 and u1 <= b1:
            return True
    return False


@njit(cache=True, error_model="numpy")
def _coincide(HA, HB, ta, ua, tb, ub, tol, wa, wb, nsamp):  # type: ignore[no-untyped-def]
    """True when a on ``[ta, tb]`` and b on ``[ua, ub]`` coincide (within ``tol``).

    Marches along ``a`` projecting onto ``b`` (and back), requiring monotone ``u``.
    """
    u = ua
    direction = 1.0 if ub > ua else -1.0
    fwd = np.empty(nsamp + 1)
    fwd[0] = ua
    fwd[nsamp] = ub
    for k in range(1, nsamp):
        s = ta + (tb - ta) * (k / nsamp)
        px, py, _a, _b, _c, _d = _eval(HA, s, wa)
        uu = _local_proj(HB, px, py, u, wb)
        x, y, _a, _b, _c, _d = _eval(HB, uu, wb)
        if math.hypot(x - px, y - py) > tol:
            return False
        if (uu - u) * direction < -1e-12:
            return False
        u = uu
        fwd[k] = uu
    if (ub - u) * direction < -1e-12:
        return False
    # and back: b's stretch lies on a (seeded from the forward correspondence)
    for k in range(1, nsamp):
        s = ua + (ub - ua) * (k / nsamp)
        j = 0
        while j < nsamp - 1 and (fwd[j + 1] - s) * direction < 0.0:
            j += 1
        seed = ta + (tb - ta) * (j / nsamp)
        px, py, _a, _b, _c, _d = _eval(HB, s, wb)
        tt = _local_proj(HA, px, py, seed, wa)
        x, y, _a, _b, _c, _d = _eval(HA, tt, wa)
        if math.hypot(x - px, y - py) > tol:
            return False
    return True


@njit(cache=True, error_model="numpy")
def _local_proj(H, px, py, u, wk):  # type: ignore[no-untyped-def]
    """Parameter of the point of ``H`` nearest ``(px, py)`` close to ``u`` (safeguarded Newton)."""
    x, y, dx, dy, ddx, ddy = _eval(H, u, wk)
    best = math.hypot(x - px, y - py)
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
        d = math.hypot(x - px, y - py)
        if d < best:
            best = d
            bu = u
    return bu


@njit(cache=True, error_model="numpy")
def _add(res, nres, pair, kind, t, u, t1, u1, x, y, dist):  # type: ignore[no-untyped-def]
    res = _grow(res, nres + 1)
    res[nres, 0] = pair
    res[nres, 1] = kind
    res[nres, 2] = t
    res[nres, 3] = u
    res[nres, 4] = t1
    res[nres, 5] = u1
    res[nres, 6] = x
    res[nres, 7] = y
    res[nres, 8] = dist
    return res, nres + 1


@njit(cache=True, error_model="numpy")
def intersect_pair_kernel(PA, WA, PB, WB, tol, budget, pair, res, nres):  # type: ignore[no-untyped-def]
    """Intersect two planar rational Bézier curves; append result rows to ``res``.

    Parameters are the Cartesian control points and weights of each curve, the
    distance tolerance (model units), the iteration budget, the pair index written
    in column 0, and the result array with its row count. Returns ``(res, nres)``.
    """
    ma = PA.shape[0]
    mb = PB.shape[0]
    na = ma - 1
    nb = mb - 1
    if not tol > 0.0:
        tol = _default_tol(PA, WA, PB, WB)
    # disjoint bounding boxes (widened by tol): nothing to do
    xla = xha = PA[0, 0]
    yla = yha = PA[0, 1]
    for i in range(1, ma):
        xla = min(xla, PA[i, 0])
        xha = max(xha, PA[i, 0])
        yla = min(yla, PA[i, 1])
        yha = max(yha, PA[i, 1])
    xlb = xhb = PB[0, 0]
    ylb = yhb = PB[0, 1]
    for i in range(1, mb):
        xlb = min(xlb, PB[i, 0])
        xhb = max(xhb, PB[i, 0])
        ylb = min(ylb, PB[i, 1])
        yhb = max(yhb, PB[i, 1])
    if xla > xhb + tol or xlb > xha + tol or yla > yhb + tol or ylb > yha + tol:
        return res, nres
    cx, cy, scale = _frame(PA, PB)
    HA = _homog(PA, WA, cx, cy, scale)
    HB = _homog(PB, WB, cx, cy, scale)
    tl = tol * scale
    if not tl > 0.0:
        tl = 1e-300
    inv = 1.0 / scale
    # one allocation per column count for all scratch arrays (leading-axis slices stay C-contiguous)
    b3 = np.empty((3 * ma + 3 * mb, 3))
    b2 = np.empty((2 * ma + 2 * mb, 2))
    b1 = np.empty(3 * ma + 3 * mb)
    wa = b3[0:ma]
    wb = b3[ma:ma + mb]
    rnd = _ROUND * max(1.0, 1.0)  # frame is normalised to |x| < 1

    # ---------------------------------------------------------------- end points
    # candidates (t, u, dist) from each end point's projection on the other curve;
    # an end point outside the other curve's two fat lines (widened by tol) is skipped
    CA = b2[0:ma]
    CB = b2[ma:ma + mb]
    VA = b1[0:ma]
    VB = b1[ma:ma + mb]
    _cartesian(HA, CA, VA)
    _cartesian(HB, CB, VB)
    SA = b3[ma + mb:2 * ma + mb]
    SB = b3[2 * ma + mb:2 * ma + 2 * mb]
    ea = b1[ma + mb:2 * ma + mb]
    eb = b1[2 * ma + mb:2 * ma + 2 * mb]
    CPA = b2[ma + mb:2 * ma + mb]
    CPB = b2[2 * ma + mb:2 * ma + 2 * mb]
    VPA = b1[2 * ma + 2 * mb:3 * ma + 2 * mb]
    VPB = b1[3 * ma + 2 * mb:3 * ma + 3 * mb]
    ends = np.empty((8, 3))
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
            uu, dd = _point_on(HB, px, py, tl, SB, CPB, VPB, eb, wb)
            # snap to an end point of b when that end also is within tol
            for ue in (0.0, 1.0):
                qx = CB[int(ue) * nb, 0]
                qy = CB[int(ue) * nb, 1]
                de = math.hypot(qx - px, qy - py)
                if de <= tl and (abs(uu - ue) < 1e-6 or de <= dd):
                    uu = ue
                    dd = de
            tt = te
        else:
            ue = float(which - 2)
            px = CB[nb * (which - 2), 0]
            py = CB[nb * (which - 2), 1]
            tt, dd = _point_on(HA, px, py, tl, SA, CPA, VPA, ea, wa)
            for te in (0.0, 1.0):
                qx = CA[int(te) * na, 0]
                qy = CA[int(te) * na, 1]
                de = math.hypot(qx - px, qy - py)
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
    ov = np.empty((4, 4))
    nov = 0
    used = np.zeros(8, dtype=np.bool_)
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
            if _coincide(HA, HB, ends[p, 0], ends[p, 1], ends[q, 0], ends[q, 1], tl, wa, wb, nsamp):
                ov[nov, 0] = ends[p, 0]
                ov[nov, 1] = ends[q, 0]
                ov[nov, 2] = ends[p, 1]
                ov[nov, 3] = ends[q, 1]
                nov += 1
                used[i] = True
                used[j] = True
                if nov == 4:
                    break
        if nov == 4:
            break

    # ---------------------------------------------------------------- clipping
    stack = np.empty((64, 4))
    stack[0, 0] = 0.0
    stack[0, 1] = 1.0
    stack[0, 2] = 0.0
    stack[0, 3] = 1.0
    nstack = 1
    cands = np.empty((16, 4))
    ncand = 0
    unres = np.empty((4, 4))
    nunres = 0
    epsb = max(tl, 1e-7)
    iters = 0
    margin = 1e-9
    while nstack > 0:
        nstack -= 1
        t0 = stack[nstack, 0]
        t1 = stack[nstack, 1]
        u0 = stack[nstack, 2]
        u1 = stack[nstack, 3]
        fresh = False
        axl = axh = ayl = ayh = bxl = bxh = byl = byh = 0.0
        while True:
            iters += 1
            if iters > budget:
                unres = _grow(unres, nunres + 1)
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
            exa = math.hypot(axh - axl, ayh - ayl)
            exb = math.hypot(bxh - bxl, byh - byl)
            if (exa <= epsb and exb <= epsb) or (t1 - t0 <= 1e-15 and u1 - u0 <= 1e-15):
                cands = _grow(cands, ncand + 1)
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
            for perp in (False, True):
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
                if (t1 - t0) <= _SPLIT_RATIO * wt or (u1 - u0) <= _SPLIT_RATIO * wu:
                    break
            if empty:
                break
            if (t1 - t0) <= _SPLIT_RATIO * wt or (u1 - u0) <= _SPLIT_RATIO * wu:
                fresh = True
                continue
            # stalled: a flat band contact, or split the larger sub-curve
            if wida <= tl and widb <= tl and exa <= 4.0 * exb + tl and exb <= 4.0 * exa + tl:
                cands = _grow(cands, ncand + 1)
                cands[ncand, 0] = t0
                cands[ncand, 1] = t1
                cands[ncand, 2] = u0
                cands[ncand, 3] = u1
                ncand += 1
                break
            stack = _grow(stack, nstack + 2)
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
                unres = _grow(unres, nunres + 1)
                unres[nunres, :] = stack[nstack, :]
                nunres += 1

    # ---------------------------------------------------------------- clusters
    label = np.arange(ncand)
    for i in range(ncand):
        for j in range(i + 1, ncand):
            gt = max(cands[i, 0], cands[j, 0]) - min(cands[i, 1], cands[j, 1])
            gu = max(cands[i, 2], cands[j, 2]) - min(cands[i, 3], cands[j, 3])
            if gt <= 1e-7 and gu <= 1e-7:
                li = label[i]
                while label[li] != li:
                    li = label[li]
                lj = label[j]
                while label[lj] != lj:
                    lj = label[lj]
                if li != lj:
                    label[max(li, lj)] = min(li, lj)
    for i in range(ncand):
        li = label[i]
        while label[li] != li:
            li = label[li]
        label[i] = li

    # points found: (t, u, dist, kind, priority)
    pts = np.empty((8 + ncand, 5))
    npts = 0
    for k in range(nend):
        pts = _grow(pts, npts + 1)
        pts[npts, 0] = ends[k, 0]
        pts[npts, 1] = ends[k, 1]
        pts[npts, 2] = ends[k, 2]
        pts[npts, 3] = -1.0  # kind decided below
        pts[npts, 4] = 2.0  # end points win merges
        npts += 1
    roots = np.empty((ncand + 4, 3))
    da = np.empty((ma, 6))
    db = np.empty((mb, 6))
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
        bestres = math.inf
        bt = 0.0
        bu = 0.0
        ct0 = math.inf
        ct1 = -math.inf
        cu0 = math.inf
        cu1 = -math.inf
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
        seeds = np.empty((nseed, 2))
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
        if wide:
            for q in range(5):
                f = (q + 0.5) / 5.0
                seeds[ks, 0] = ct0 + f * (ct1 - ct0)
                seeds[ks, 1] = cu0 + f * (cu1 - cu0)
                seeds[ks + 1, 0] = ct0 + f * (ct1 - ct0)
                seeds[ks + 1, 1] = cu1 - f * (cu1 - cu0)
                ks += 2
        for q in range(ks):
            t, u, r = _newton(HA, HB, seeds[q, 0], seeds[q, 1], wa, wb, 60)
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
                sig = abs(adx * bdy - ady * bdx) / max(math.hypot(adx, ady), math.hypot(bdx, bdy), 1e-300)
                cert = 1.0  # a well-conditioned root is trusted as is
                if (na + nb) * _EPS > 1e-14 * sig:
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
                    roots = _grow(roots, nroots + 1)
                    roots[nroots, 0] = t
                    roots[nroots, 1] = u
                    roots[nroots, 2] = cert
                    nroots += 1
        if nroots == 0:
            t, u, d = _closest(HA, HB, bt, bu, wa, wb, 60)
            if d <= tl:
                pts = _grow(pts, npts + 1)
                pts[npts, 0] = t
                pts[npts, 1] = u
                pts[npts, 2] = d
                pts[npts, 3] = float(KIND_TANGENT)
                pts[npts, 4] = 0.0
                npts += 1
            continue
        # certified roots explain the cluster: drop uncertified near-roots between them
        ncert = 0
        for k in range(nroots):
            if roots[k, 2] == 1.0:
                ncert += 1
        if 0 < ncert < nroots:
            k2 = 0
            for k in range(nroots):
                if roots[k, 2] == 1.0:
                    roots[k2, 0] = roots[k, 0]
                    roots[k2, 1] = roots[k, 1]
                    roots[k2, 2] = roots[k, 2]
                    k2 += 1
            nroots = k2
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
                dq = math.hypot(x - mx, y - my)
                distinct = roots[j, 2] == 1.0 and roots[j + 1, 2] == 1.0 and (
                    abs(roots[j + 1, 0] - roots[j, 0]) > 1e-13 or abs(roots[j + 1, 1] - roots[j, 1]) > 1e-13)
                if dq <= 4.0 * rnd and not distinct:
                    j += 1
                else:
                    break
            if j == i:
                sn = _angle_sin(HA, HB, roots[i, 0], roots[i, 1], wa, wb)
                kind = KIND_CROSSING
                if roots[i, 2] == 1.0:
                    # a certified (simple) root crosses, however small the angle
                    if sn < 1e-12:
                        kind = KIND_TANGENT
                elif nroots == 1 and sn < 1e-7:
                    kind = KIND_TANGENT
                elif sn < 1e-10:
                    kind = KIND_TANGENT
                pts = _grow(pts, npts + 1)
                pts[npts, 0] = roots[i, 0]
                pts[npts, 1] = roots[i, 1]
                pts[npts, 2] = 0.0
                pts[npts, 3] = float(kind)
                pts[npts, 4] = 1.0
                npts += 1
            else:
                t, u, d = _closest(HA, HB, 0.5 * (roots[i, 0] + roots[j, 0]),
                                   0.5 * (roots[i, 1] + roots[j, 1]), wa, wb, 60)
                pts = _grow(pts, npts + 1)
                pts[npts, 0] = t
                pts[npts, 1] = u
                pts[npts, 2] = d
                pts[npts, 3] = float(KIND_TANGENT)
                pts[npts, 4] = 1.0
                npts += 1
            i = j + 1

    # ---------------------------------------------------------------- dedupe + emit
    keep = np.ones(npts, dtype=np.bool_)
    for i in range(npts):
        if not keep[i]:
            continue
        for j in range(i + 1, npts):
            if not keep[j]:
                continue
            dt = abs(pts[i, 0] - pts[j, 0])
            du = abs(pts[i, 1] - pts[j, 1])
            if dt <= 1e-9 and du <= 1e-9:
                same = True
            elif dt <= 1e-9 or du <= 1e-9:
                # one parameter shared: the same point only if the curve is point-like between
                same = True
                x0, y0, _a, _b, _c, _d = _eval(HA, pts[i, 0], wa)
                x1, y1, _a, _b, _c, _d = _eval(HB, pts[i, 1], wb)
                for q in range(5):
                    f = q / 4.0
                    x, y, _a, _b, _c, _d = _eval(HA, pts[i, 0] + f * (pts[j, 0] - pts[i, 0]), wa)
                    x2, y2, _a, _b, _c, _d = _eval(HB, pts[i, 1] + f * (pts[j, 1] - pts[i, 1]), wb)
                    if math.hypot(x - x0, y - y0) > tl or math.hypot(x2 - x1, y2 - y1) > tl:
                        same = False
                        break
            elif dt <= 1e-3 and du <= 1e-3 and (
                    pts[i, 3] == KIND_TANGENT or pts[j, 3] == KIND_TANGENT
                    or pts[i, 4] == 2.0 or pts[j, 4] == 2.0):
                # one contact if the curves stay within tol all along between them
                same = True
                for q in range(1, 8):
                    f = q / 8.0
                    tm = pts[i, 0] + f * (pts[j, 0] - pts[i, 0])
                    um = pts[i, 1] + f * (pts[j, 1] - pts[i, 1])
                    x, y, _a, _b, _c, _d = _eval(HA, tm, wa)
                    if _local_dist(HB, x, y, um, wb) > tl:
                        same = False
                        break
            else:
                same = False
            if same:
                if pts[j, 4] > pts[i, 4]:
                    if pts[j, 3] < 0.0 and pts[i, 3] >= 0.0:
                        pts[j, 3] = pts[i, 3]
                    keep[i] = False
                    break
                else:
                    if pts[i, 3] < 0.0 and pts[j, 3] >= 0.0:
                        pts[i, 3] = pts[j, 3]
                    keep[j] = False
    for i in range(npts):
        if not keep[i]:
            continue
        t = pts[i, 0]
        u = pts[i, 1]
        # drop points on an overlap
        on = False
        for k in range(nov):
            b0 = min(ov[k, 2], ov[k, 3])
            b1 = max(ov[k, 2], ov[k, 3])
            if ov[k, 0] - 1e-6 <= t <= ov[k, 1] + 1e-6 and b0 - 1e-6 <= u <= b1 + 1e-6:
                on = True
        if on:
            continue
        kf = pts[i, 3]
        if kf < 0.0:
            sn = _angle_sin(HA, HB, t, u, wa, wb)
            kf = float(KIND_TANGENT) if sn < 1e-7 else float(KIND_CROSSING)
        ax, ay, _a, _b, _c, _d = _eval(HA, t, wa)
        bx, by, _a, _b, _c, _d = _eval(HB, u, wb)
        dist = math.hypot(ax - bx, ay - by) * inv
        px = 0.5 * (ax + bx) * inv + cx
        py = 0.5 * (ay + by) * inv + cy
        res, nres = _add(res, nres, pair, kf, t, u, t, u, px, py, dist)
    for k in range(nov):
        res, nres = _add(res, nres, pair, float(KIND_OVERLAP), ov[k, 0], ov[k, 2], ov[k, 1], ov[k, 3],
                         0.0, 0.0, 0.0)
    for k in range(nunres):
        res, nres = _add(res, nres, pair, float(KIND_UNRESOLVED), unres[k, 0], unres[k, 2],
                         unres[k, 1], unres[k, 3], 0.0, 0.0, 0.0)
    return res, nres


@njit(cache=True, error_model="numpy")
def intersect_batch_kernel(P, W, offsets, pairs, tol, budget):  # type: ignore[no-untyped-def]
    """Intersect many pairs in one call.

    ``P`` (N, 2) and ``W`` (N,) hold every curve's control points back to back;
    curve ``k`` is rows ``offsets[k]:offsets[k + 1]``. ``pairs`` (p, 2) indexes
    curves; ``tol`` (p,) holds each pair's tolerance. Returns the result rows.
    """
    res = np.empty((max(16, 2 * pairs.shape[0]), RES_COLS))
    nres = 0
    for k in range(pairs.shape[0]):
        ia = pairs[k, 0]
        ib = pairs[k, 1]
        # contiguous copies: the pair kernel is compiled for C-contiguous arrays only
        PA = np.ascontiguousarray(P[offsets[ia]:offsets[ia + 1]])
        WA = np.ascontiguousarray(W[offsets[ia]:offsets[ia + 1]])
        PB = np.ascontiguousarray(P[offsets[ib]:offsets[ib + 1]])
        WB = np.ascontiguousarray(W[offsets[ib]:offsets[ib + 1]])
        res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol[k], budget, k, res, nres)
    return res[:nres]


@njit(cache=True, error_model="numpy")
def intersect_one_kernel(PA, WA, PB, WB, tol, budget):  # type: ignore[no-untyped-def]
    """One pair: the result rows (a single array return is cheaper to box than a tuple)."""
    res = np.empty((8, RES_COLS))
    res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol, budget, 0, res, 0)
    return res[:nres]


# =========================================================================== space (relief scheme)
# The space intersector's hot path lives here too, beside the planar kernel it calls, so that an
# edit to either invalidates numba's cache of both (numba keys a cache on its own source file).
# A space curve is passed as homogeneous rows (w x, w y, w z, w), shape (n + 1, 4), in model
# coordinates. Result rows (SPACE_COLS columns): [kind, t, u, t1, u1, x, y, z, distance] with kind
# one of the KIND_* codes (an overlap or an unresolved box holds t0, u0, t1, u1 in t, u, t1, u1).

SPACE_COLS = 9
STATUS_OK = 0
STATUS_ARTEFACT = 1
_SPACE_TANGENT_SIN = 1e-6
_SPACE_OVERLAP_SAMPLES = 17
_SPACE_N_FRAMES = 4


@njit(cache=True)
def _space_eval(H, t, wk, p, d):  # type: ignore[no-untyped-def]
    """Point ``p`` and derivative ``d`` of homogeneous curve ``H`` at ``t`` (de Casteljau)."""
    n = H.shape[0] - 1
    for i in range(n + 1):
        for j in range(4):
            wk[i, j] = H[i, j]
    s = 1.0 - t
    for r in range(1, n):
        for i in range(n + 1 - r):
            for j in range(4):
                wk[i, j] = s * wk[i, j] + t * wk[i + 1, j]
    w = s * wk[0, 3] + t * wk[1, 3]
    dw = n * (wk[1, 3] - wk[0, 3])
    for j in range(3):
        p[j] = (s * wk[0, j] + t * wk[1, j]) / w
        d[j] = (n * (wk[1, j] - wk[0, j]) - p[j] * dw) / w


@njit(cache=True)
def _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db):  # type: ignore[no-untyped-def]
    _space_eval(HA, t, wka, pa, da)
    _space_eval(HB, u, wkb, pb, db)
    f = 0.0
    for j in range(3):
        f += (pa[j] - pb[j]) ** 2
    return f


@njit(cache=True)
def _space_polish(HA, HB, t, u, fix_t, fix_u, wka, wkb):  # type: ignore[no-untyped-def]
    """Minimise |a(t) - b(u)| locally: Gauss-Newton with Levenberg damping, in [0, 1]^2."""
    pa = np.empty(3)
    da = np.empty(3)
    pb = np.empty(3)
    db = np.empty(3)
    qa = np.empty(3)
    qda = np.empty(3)
    qb = np.empty(3)
    qdb = np.empty(3)
    f = _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
    if fix_t and fix_u:
        return t, u, math.sqrt(f)
    lam = 0.0
    for _ in range(80):
        a11 = 0.0
        a12 = 0.0
        a22 = 0.0
        g1 = 0.0
        g2 = 0.0
        for j in range(3):
            r = pa[j] - pb[j]
            a11 += da[j] * da[j]
            a12 -= da[j] * db[j]
            a22 += db[j] * db[j]
            g1 += da[j] * r
            g2 -= db[j] * r
        accepted = False
        moved = 0.0
        for _attempt in range(16):
            dt = 0.0
            du = 0.0
            if not fix_t and not fix_u:
                m11 = a11 * (1.0 + lam) + 1e-300
                m22 = a22 * (1.0 + lam) + 1e-300
                det = m11 * m22 - a12 * a12
                if det > 0.0:
                    dt = -(m22 * g1 - a12 * g2) / det
                    du = -(-a12 * g1 + m11 * g2) / det
            elif fix_u:
                if a11 > 0.0:
                    dt = -g1 / (a11 * (1.0 + lam))
            else:
                if a22 > 0.0:
                    du = -g2 / (a22 * (1.0 + lam))
            nt = min(max(t + dt, 0.0), 1.0)
            nu = min(max(u + du, 0.0), 1.0)
            nf = _space_dist2(HA, HB, nt, nu, wka, wkb, qa, qda, qb, qdb)
            if nf <= f:
                moved = abs(nt - t) + abs(nu - u)
                t = nt
                u = nu
                f = nf
                for j in range(3):
                    pa[j] = qa[j]
                    da[j] = qda[j]
                    pb[j] = qb[j]
                    db[j] = qdb[j]
                lam = 0.0 if lam <= 1e-10 else lam * 0.1
                accepted = True
                break
            lam = max(lam * 10.0, 1e-10)
        if not accepted or f == 0.0 or moved <= 2.0 * _EPS:
            break
    return t, u, math.sqrt(f)


@njit(cache=True)
def _space_sin_angle(HA, HB, t, u, wka, wkb):  # type: ignore[no-untyped-def]
    pa = np.empty(3)
    da = np.empty(3)
    pb = np.empty(3)
    db = np.empty(3)
    _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
    cx = da[1] * db[2] - da[2] * db[1]
    cy = da[2] * db[0] - da[0] * db[2]
    cz = da[0] * db[1] - da[1] * db[0]
    na = math.sqrt(da[0] ** 2 + da[1] ** 2 + da[2] ** 2)
    nb = math.sqrt(db[0] ** 2 + db[1] ** 2 + db[2] ** 2)
    if na == 0.0 or nb == 0.0:
        return 0.0
    return math.sqrt(cx * cx + cy * cy + cz * cz) / (na * nb)


@njit(cache=True)
def _space_closest_on(HB, p, u, lo, hi, wkb):  # type: ignore[no-untyped-def]
    """Gap from ``p`` to ``b`` near ``u`` (Gauss-Newton in ``u``, kept in [lo, hi])."""
    q = np.empty(3)
    dq = np.empty(3)
    for _ in range(40):
        _space_eval(HB, u, wkb, q, dq)
        g = 0.0
        hh = 0.0
        for j in range(3):
            g += (q[j] - p[j]) * dq[j]
            hh += dq[j] * dq[j]
        if hh == 0.0:
            break
        nu = min(max(u - g / hh, lo), hi)
        if abs(nu - u) <= 1e-16:
            u = nu
            break
        u = nu
    _space_eval(HB, u, wkb, q, dq)
    return math.sqrt((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 + (q[2] - p[2]) ** 2)


@njit(cache=True)
def _space_overlap_real(HA, HB, t0, u0, t1, u1, tol, wka, wkb):  # type: ignore[no-untyped-def]
    pa = np.empty(3)
    da = np.empty(3)
    pb = np.empty(3)
    db = np.empty(3)
    if math.sqrt(_space_dist2(HA, HB, t0, u0, wka, wkb, pa, da, pb, db)) > tol:
        return False
    if math.sqrt(_space_dist2(HA, HB, t1, u1, wka, wkb, pa, da, pb, db)) > tol:
        return False
    lo = min(u0, u1)
    hi = max(u0, u1)
    for i in range(1, _SPACE_OVERLAP_SAMPLES - 1):
        s = i / (_SPACE_OVERLAP_SAMPLES - 1.0)
        _space_eval(HA, t0 + s * (t1 - t0), wka, pa, da)
        if _space_closest_on(HB, pa, u0 + s * (u1 - u0), lo, hi, wkb) > tol:
            return False
    return True


@njit(cache=True)
def _jacobi_eigen3(c):  # type: ignore[no-untyped-def]
    """Eigenvectors (columns, ascending eigenvalues) of a symmetric 3x3 matrix (Jacobi rotations)."""
    a = c.copy()
    v = np.eye(3)
    for _ in range(50):
        off = abs(a[0, 1]) + abs(a[0, 2]) + abs(a[1, 2])
        if off <= 1e-300 or off <= 1e-15 * (abs(a[0, 0]) + abs(a[1, 1]) + abs(a[2, 2])):
            break
        for p in range(2):
            for q in range(p + 1, 3):
                if a[p, q] == 0.0:
                    continue
                theta = (a[q, q] - a[p, p]) / (2.0 * a[p, q])
                t = (1.0 if theta >= 0.0 else -1.0) / (abs(theta) + math.sqrt(theta * theta + 1.0))
                cs = 1.0 / math.sqrt(t * t + 1.0)
                sn = t * cs
                for k in range(3):
                    akp = a[k, p]
                    akq = a[k, q]
                    a[k, p] = cs * akp - sn * akq
                    a[k, q] = sn * akp + cs * akq
                for k in range(3):
                    apk = a[p, k]
                    aqk = a[q, k]
                    a[p, k] = cs * apk - sn * aqk
                    a[q, k] = sn * apk + cs * aqk
                for k in range(3):
                    vkp = v[k, p]
                    vkq = v[k, q]
                    v[k, p] = cs * vkp - sn * vkq
                    v[k, q] = sn * vkp + cs * vkq
    order = np.argsort(np.array([a[0, 0], a[1, 1], a[2, 2]]))
    out = np.empty((3, 3))
    for j in range(3):
        for k in range(3):
            out[k, j] = v[k, order[j]]
    return out


@njit(cache=True)
def _space_direction_frame(P, d, M):  # type: ignore[no-untyped-def]
    """Frame looking along ``d`` from a centre placed so every point of ``P`` is well in front."""
    nd = math.sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
    dd = d / nd
    lo = np.empty(3)
    hi = np.empty(3)
    for j in range(3):
        lo[j] = P[:, j].min()
        hi[j] = P[:, j].max()
    centre = 0.5 * (lo + hi)
    radius = 0.0
    spread = 0.0
    for i in range(P.shape[0]):
        r2 = 0.0
        dep = 0.0
        for j in range(3):
            r2 += (P[i, j] - centre[j]) ** 2
            dep += (P[i, j] - centre[j]) * dd[j]
        radius = max(radius, math.sqrt(r2))
        spread = max(spread, abs(dep))
    if radius == 0.0:
        radius = 1.0
    dist = spread + 2.0 * radius
    origin = centre - dist * dd
    helper = np.array([1.0, 0.0, 0.0]) if abs(dd[0]) < 0.8 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(helper, dd)
    e1 = e1 / math.sqrt(e1[0] ** 2 + e1[1] ** 2 + e1[2] ** 2)
    e2 = np.cross(dd, e1)
    for j in range(3):
        M[0, j] = e1[j] / radius
        M[1, j] = e2[j] / radius
        M[2, j] = dd[j] / radius
        M[3, j] = 0.0
    for i in range(3):
        M[i, 3] = -(M[i, 0] * origin[0] + M[i, 1] * origin[1] + M[i, 2] * origin[2])
    M[3, 3] = 1.0
    return radius


@njit(cache=True)
def _space_frame(mode, P, ref, M):  # type: ignore[no-untyped-def]
    """Fill ``M`` (local -> frame coordinates) for frame ``mode``; return its scale, or 0 if unusable.

    Mode 0 is the model's own frame (centre at the model origin), usable when every control
    point lies in front of it (z > 0) with moderate depth ratio: the paper's frame for its
    curves. Modes 1-3 look along the least-variance axis, a tilted axis, a fixed oblique axis.
    """
    m = P.shape[0]
    if mode == 0:
        zmin = np.inf
        zmax = -np.inf
        big = 0.0
        for i in range(m):
            z = P[i, 2] + ref[2]
            zmin = min(zmin, z)
            zmax = max(zmax, z)
            for j in range(3):
                big = max(big, abs(P[i, j] + ref[j]))
        if not (zmin > 1e-3 * big and zmax < 100.0 * zmin):
            return 0.0
        for i in range(4):
            for j in range(4):
                M[i, j] = 1.0 if i == j else 0.0
        for j in range(3):
            M[j, 3] = ref[j]
        return 1.0
    mean = np.zeros(3)
    for i in range(m):
        mean += P[i]
    mean /= m
    cov = np.zeros((3, 3))
    for i in range(m):
        for j in range(3):
            for k in range(3):
                cov[j, k] += (P[i, j] - mean[j]) * (P[i, k] - mean[k])
    vecs = _jacobi_eigen3(cov)
    if mode == 1:
        d = vecs[:, 0].copy()
    elif mode == 2:
        d = vecs[:, 0] + 0.6 * vecs[:, 1]
    else:
        d = np.array([0.3, -0.5, 0.81])
    return _space_direction_frame(P, d, M)


@njit(cache=True)
def _space_project(H, M, k, P2, W2):  # type: ignore[no-untyped-def]
    """psi(phi(M H)): the planar image of a curve, as Cartesian points and weights. False if behind O."""
    n = H.shape[0]
    for i in range(n):
        x = 0.0
        y = 0.0
        z = 0.0
        w = 0.0
        for j in range(4):
            x += M[0, j] * H[i, j]
            y += M[1, j] * H[i, j]
            z += M[2, j] * H[i, j]
            w += M[3, j] * H[i, j]
        # relief phi_k: (x, y, z, w) -> ((1+k)x, (1+k)y, (1+k)z, z + k w); then psi: drop to (X, Y, Z)
        rx = (1.0 + k) * x
        ry = (1.0 + k) * y
        rz = (1.0 + k) * z
        if not (rz > 0.0) or not (z + k * w > 0.0):
            return False
        P2[i, 0] = rx / rz
        P2[i, 1] = ry / rz
        W2[i] = rz
    return True


@njit(cache=True)
def _space_lipschitz(P2a, W2a, P2b, W2b, HA, HB, M):  # type: ignore[no-untyped-def]
    """Bound of |D psi| over the hull of both curves' control points in frame coordinates."""
    zmin = np.inf
    r2 = 0.0
    for H, P2 in ((HA, P2a), (HB, P2b)):
        for i in range(H.shape[0]):
            w = H[i, 3]
            z = 0.0
            for j in range(4):
                z += M[2, j] * H[i, j]
            zmin = min(zmin, z / w)
            r2 = max(r2, P2[i, 0] ** 2 + P2[i, 1] ** 2)
    return math.sqrt(1.0 + r2) / zmin


@njit(cache=True)
def _space_add(out, n, kind, t, u, t1, u1, x, y, z, dist):  # type: ignore[no-untyped-def]
    if n >= out.shape[0]:
        bigger = np.empty((2 * out.shape[0] + 4, SPACE_COLS))
        bigger[:n] = out[:n]
        out = bigger
    out[n, 0] = kind
    out[n, 1] = t
    out[n, 2] = u
    out[n, 3] = t1
    out[n, 4] = u1
    out[n, 5] = x
    out[n, 6] = y
    out[n, 7] = z
    out[n, 8] = dist
    return out, n + 1


@njit(cache=True, error_model="numpy")
def _space_half(H, L, R):  # type: ignore[no-untyped-def]
    """Split homogeneous rows ``H`` at t = 1/2 into ``L`` and ``R`` (de Casteljau)."""
    n = H.shape[0] - 1
    wk = H.copy()
    for j in range(4):
        L[0, j] = wk[0, j]
        R[n, j] = wk[n, j]
    for r in range(1, n + 1):
        for i in range(n + 1 - r):
            for j in range(4):
                wk[i, j] = 0.5 * (wk[i, j] + wk[i + 1, j])
        for j in range(4):
            L[r, j] = wk[0, j]
            R[n - r, j] = wk[n - r, j]


@njit(cache=True, error_model="numpy")
def _space_box(H, box):  # type: ignore[no-untyped-def]
    """Box ``[lo x, lo y, lo z, hi x, hi y, hi z]`` of the control points (contains the curve)."""
    for j in range(3):
        box[j] = math.inf
        box[3 + j] = -math.inf
    for i in range(H.shape[0]):
        for j in range(3):
            x = H[i, j] / H[i, 3]
            box[j] = min(box[j], x)
            box[3 + j] = max(box[3 + j], x)


@njit(cache=True, error_model="numpy")
def _space_separated(HA, HB, tol, max_depth):  # type: ignore[no-untyped-def]
    """True when boxes of sub-curves (halving both, depth <= max_depth) prove a gap wider than tol.

    A cheap pre-pass before the relief scheme: two space curves that stay apart need no
    projection at all (their projections may well cross). False means "not proven apart".
    """
    na = HA.shape[0]
    nb = HB.shape[0]
    size = 4 * max_depth + 8
    stack_a = np.empty((size, na, 4))
    stack_b = np.empty((size, nb, 4))
    depth = np.empty(size, dtype=np.int64)
    stack_a[0] = HA
    stack_b[0] = HB
    depth[0] = 0
    top = 1
    ca = np.empty((na, 4))
    cb = np.empty((nb, 4))
    la = np.empty((na, 4))
    ra = np.empty((na, 4))
    lb = np.empty((nb, 4))
    rb = np.empty((nb, 4))
    ba = np.empty(6)
    bb = np.empty(6)
    while top > 0:
        top -= 1
        ca[:, :] = stack_a[top]
        cb[:, :] = stack_b[top]
        d = depth[top]
        _space_box(ca, ba)
        _space_box(cb, bb)
        apart = False
        for j in range(3):
            if ba[j] > bb[3 + j] + tol or bb[j] > ba[3 + j] + tol:
                apart = True
        if apart:
            continue
        if d >= max_depth or top + 4 > size:
            return False
        _space_half(ca, la, ra)
        _space_half(cb, lb, rb)
        stack_a[top] = la
        stack_b[top] = lb
        stack_a[top + 1] = la
        stack_b[top + 1] = rb
        stack_a[top + 2] = ra
        stack_b[top + 2] = lb
        stack_a[top + 3] = ra
        stack_b[top + 3] = rb
        for q in range(4):
            depth[top + q] = d + 1
        top += 4
    return True


@njit(cache=True)
def space_pair_kernel(HA0, HB0, tol, budget, k):  # type: ignore[no-untyped-def]
    """Intersect two space rational curves by the relief scheme.

    ``HA0``, ``HB0``: homogeneous rows ``(w x, w y, w z, w)`` in model coordinates; ``tol`` a
    distance in model units (``<= 0`` asks for the default tolerance of both curves); ``budget``
    the planar clipping budget; ``k`` the span of the relief perspective. Returns ``(rows, nrows, status)``.
    """
    na = HA0.shape[0]
    nb = HB0.shape[0]
    PA = np.empty((na, 3))
    PB = np.empty((nb, 3))
    for i in range(na):
        for j in range(3):
            PA[i, j] = HA0[i, j] / HA0[i, 3]
    for i in range(nb):
        for j in range(3):
            PB[i, j] = HB0[i, j] / HB0[i, 3]
    big0 = max(np.abs(PA).max(), np.abs(PB).max())
    PA0 = PA.copy()
    PB0 = PB.copy()
    ref = PA[0].copy()
    # local coordinates: an exact shift for nearby values (Sterbenz), parameters unchanged
    HA = np.empty((na, 4))
    HB = np.empty((nb, 4))
    for i in range(na):
        for j in range(3):
            PA[i, j] -= ref[j]
            HA[i, j] = PA[i, j] * HA0[i, 3]
        HA[i, 3] = HA0[i, 3]
    for i in range(nb):
        for j in range(3):
            PB[i, j] -= ref[j]
            HB[i, j] = PB[i, j] * HB0[i, 3]
        HB[i, 3] = HB0[i, 3]
    allp = np.empty((na + nb, 3))
    allp[:na] = PA
    allp[na:] = PB
    big = np.abs(allp).max()
    if not (tol > 0.0):
        # relief_cad.tolerances.default_tolerance of both curves (their own sampled extent)
        tol = _default_tol(PA0, HA0[:, 3].copy(), PB0, HB0[:, 3].copy())
    meet = max(1e3 * _EPS * big, 16.0 * _EPS * big0, 1e-3 * tol)
    out = np.empty((8, SPACE_COLS))
    if _space_separated(HA, HB, tol, 5):
        return out, 0, STATUS_OK
    wka = np.empty((na, 4))
    wkb = np.empty((nb, 4))
    M = np.empty((4, 4))
    P2a = np.empty((na, 2))
    W2a = np.empty(na)
    P2b = np.empty((nb, 2))
    W2b = np.empty(nb)
    nout = 0
    for mode in range(_SPACE_N_FRAMES):
        scale = _space_frame(mode, allp, ref, M)
        if scale == 0.0:
            continue
        if not _space_project(HA, M, k, P2a, W2a) or not _space_project(HB, M, k, P2b, W2b):
            continue
        ptol = _space_lipschitz(P2a, W2a, P2b, W2b, HA, HB, M) * (tol / scale) * (1.0 + 1e-6)
        res = np.empty((16, RES_COLS))
        res, nres = intersect_pair_kernel(P2a, W2a, P2b, W2b, ptol, budget, 0, res, 0)
        artefact = False
        nout = 0
        for r in range(nres):
            kind = int(res[r, 1])
            if kind == KIND_OVERLAP:
                if _space_overlap_real(HA, HB, res[r, 2], res[r, 3], res[r, 4], res[r, 5], tol, wka, wkb):
                    out, nout = _space_add(out, nout, KIND_OVERLAP, res[r, 2], res[r, 3], res[r, 4],
                                           res[r, 5], 0.0, 0.0, 0.0, 0.0)
                else:
                    artefact = True
                    break
            elif kind == KIND_UNRESOLVED:
                out, nout = _space_add(out, nout, KIND_UNRESOLVED, res[r, 2], res[r, 3], res[r, 4], res[r, 5],
                                 0.0, 0.0, 0.0, 0.0)
        if artefact:
            continue
        pa = np.empty(3)
        da = np.empty(3)
        pb = np.empty(3)
        db = np.empty(3)
        qe = np.empty(3)
        dqe = np.empty(3)
        for r in range(nres):
            kind = int(res[r, 1])
            if kind != KIND_CROSSING and kind != KIND_TANGENT:
                continue
            t = res[r, 2]
            u = res[r, 3]
            fix_t = False
            fix_u = False
            for end in (0.0, 1.0):
                if t == end or abs(t - end) < 1e-9:
                    if math.sqrt(_space_dist2(HA, HB, end, u, wka, wkb, pa, da, pb, db)) <= tol:
                        t = end
                        fix_t = True
                if u == end or abs(u - end) < 1e-9:
                    if math.sqrt(_space_dist2(HA, HB, t, end, wka, wkb, pa, da, pb, db)) <= tol:
                        u = end
                        fix_u = True
            t, u, gap = _space_polish(HA, HB, t, u, fix_t, fix_u, wka, wkb)
            if gap > tol:
                continue
            # a point inside an overlap, or at the place where one ends (a closed curve returns to
            # it with another parameter), is part of that overlap
            inside = False
            _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
            for q in range(nout):
                if out[q, 0] == KIND_OVERLAP:
                    lo_u = min(out[q, 2], out[q, 4])
                    hi_u = max(out[q, 2], out[q, 4])
                    if out[q, 1] - 1e-9 <= t <= out[q, 3] + 1e-9 and lo_u - 1e-9 <= u <= hi_u + 1e-9:
                        inside = True
                    for te in (out[q, 1], out[q, 3]):
                        _space_eval(HA, te, wka, qe, dqe)
                        gap_e = 0.0
                        for j in range(3):
                            gap_e += (qe[j] - pa[j]) ** 2
                        if math.sqrt(gap_e) <= tol:
                            inside = True
            if inside:
                continue
            ckind = KIND_TANGENT
            if gap <= meet and _space_sin_angle(HA, HB, t, u, wka, wkb) > _SPACE_TANGENT_SIN:
                ckind = KIND_CROSSING
            # merge repeated finds of one contact (tangent finds agree only to ~sqrt(eps))
            dup = -1
            for q in range(nout):
                if out[q, 0] == KIND_CROSSING or out[q, 0] == KIND_TANGENT:
                    near = 1e-10
                    if ckind == KIND_TANGENT and out[q, 0] == KIND_TANGENT:
                        near = 1e-6
                    if abs(out[q, 1] - t) <= near and abs(out[q, 2] - u) <= near:
                        dup = q
            _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
            if dup >= 0:
                if gap < out[dup, 8]:
                    out[dup, 1] = t
                    out[dup, 2] = u
                    for j in range(3):
                        out[dup, 5 + j] = 0.5 * (pa[j] + pb[j]) + ref[j]
                    out[dup, 8] = gap
                continue
            out, nout = _space_add(out, nout, ckind, t, u, t, u, 0.5 * (pa[0] + pb[0]) + ref[0],
                             0.5 * (pa[1] + pb[1]) + ref[1], 0.5 * (pa[2] + pb[2]) + ref[2], gap)
        return out, nout, STATUS_OK
    return out, 0, STATUS_ARTEFACT

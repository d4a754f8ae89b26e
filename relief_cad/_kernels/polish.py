"""Newton polishing, closest points, projections on planar curves and coincidence tests.

The post-processing of the clipping candidates (the paper's §4) and the overlap test.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import exp, hypot, log, sqrt

from .bezier import _cartesian, _eval, _rounds, _segment
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


def _end_ratio(H: cython.const[cython.double][:, :], t0: cython.double, t1: cython.double,
               wk: cython.double[:, :]) -> cython.double:
    """``λ = (w(t1) / w(t0))^(1/n)`` of the stretch ``[t0, t1]`` of ``H`` (1.0 where undefined).

    The stretch's end weights are the curve's weights there; the Möbius map of :func:`_spread`
    with this ``λ`` gives it equal end weights (Farin's standard form).
    """
    n: cython.Py_ssize_t = H.shape[0] - 1
    k: cython.Py_ssize_t = H.shape[1] - 1
    if n < 1:
        return 1.0
    _rounds(H, t0, wk)
    w0 = (1.0 - t0) * wk[0, k] + t0 * wk[1, k]
    _rounds(H, t1, wk)
    w1 = (1.0 - t1) * wk[0, k] + t1 * wk[1, k]
    if not (w0 > 0.0 and w1 > 0.0):
        return 1.0
    lam: cython.double = exp(log(w1 / w0) / n)
    return lam if lam > 0.0 and lam < 1e300 else 1.0


def _spread(f: cython.double, lam: cython.double) -> cython.double:
    """The parameter in [0, 1] of the sample ``f`` on the standard form: ``f / (f + λ (1 - f))``.

    Unequal end weights crowd a stretch's points towards one end (weights 1, 1e4, 1e8 put all
    but 1e-4 of its parameter range near one end): samples even in the parameter would see
    only that end, and two curves 25 tol apart in the middle came out as one overlap.
    """
    if lam == 1.0:
        return f
    return f / (f + lam * (1.0 - f))


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

    Marches along ``a`` projecting onto ``b`` (and back), requiring monotone ``u``. The samples
    are spread along each stretch as on its standard form (:func:`_spread`).
    """
    u = ua
    direction = 1.0 if ub > ua else -1.0
    k: cython.Py_ssize_t
    j: cython.Py_ssize_t
    lam_a = _end_ratio(HA, ta, tb, wa)
    lam_b = _end_ratio(HB, ua, ub, wb)
    fwd: cython.double[:] = np.empty(nsamp + 1)
    fwd[0] = ua
    fwd[nsamp] = ub
    for k in range(1, nsamp):
        s = ta + (tb - ta) * _spread(cython.cast(cython.double, k) / nsamp, lam_a)  # k, nsamp: C ints
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
    # and back: b's stretch lies on a's stretch (seeded from the forward correspondence; a foot
    # beyond [ta, tb] is taken at its end: b may run on along a past the stretch, and fold back)
    lo = min(ta, tb)
    hi = max(ta, tb)
    for k in range(1, nsamp):
        s = ua + (ub - ua) * _spread(cython.cast(cython.double, k) / nsamp, lam_b)
        j = 0
        while j < nsamp - 1 and (fwd[j + 1] - s) * direction < 0.0:
            j += 1
        seed = ta + (tb - ta) * _spread(cython.cast(cython.double, j) / nsamp, lam_a)
        px, py, _a, _b, _c, _d = _eval(HB, s, wb)
        tt = min(hi, max(lo, _local_proj(HA, px, py, seed, wa)))
        x, y, _a, _b, _c, _d = _eval(HA, tt, wa)
        if hypot(x - px, y - py) > tol:
            return False
    return True


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _clip01(x: cython.double) -> cython.double:
    """``np.clip(x, 0.0, 1.0)`` for one float: NaN stays NaN, and its max-then-min order."""
    if x != x:
        return x
    r = x if x > 0.0 else 0.0
    return r if r < 1.0 else 1.0


@cython.cfunc
@cython.exceptval(check=False)
def _at(H: cython.const[cython.double][:, :], t: cython.double, B: cython.double[:, :],
        X: cython.double[:]) -> cython.void:
    """The point of the rational curve ``H`` ((n + 1, d + 1), weights last) at ``t`` into ``X`` (d,).

    The operations of :meth:`relief_cad.RationalBezier.evaluate` in their order (homogeneous de
    Casteljau, then the division by the weight), so the bits are the same; ``B`` is scratch of
    ``H``'s shape.
    """
    c: cython.Py_ssize_t
    k: cython.Py_ssize_t = H.shape[1]
    s: cython.double = 1.0 - t
    _rounds(H, t, B)
    w: cython.double = s * B[0, k - 1] + t * B[1, k - 1]
    for c in range(k - 1):
        X[c] = (s * B[0, c] + t * B[1, c]) / w


@cython.cfunc
@cython.exceptval(check=False)
def _gap(H: cython.const[cython.double][:, :], t: cython.double, P: cython.const[cython.double][:, :],
         i: cython.Py_ssize_t, B: cython.double[:, :], X: cython.double[:]) -> cython.double:
    """Distance from the point ``P[i]`` to the curve ``H`` at ``t`` (numpy's sum order)."""
    c: cython.Py_ssize_t
    _at(H, t, B, X)
    acc: cython.double = (X[0] - P[i, 0]) * (X[0] - P[i, 0])
    for c in range(1, P.shape[1]):
        acc = acc + (X[c] - P[i, c]) * (X[c] - P[i, c])
    return sqrt(acc)


def foot_newton(
    H: cython.const[cython.double][:, :],
    HD: cython.const[cython.double][:, :],
    P: cython.const[cython.double][:, :],
    u: cython.double[:],
    dist: cython.double[:],
    enough: cython.double,
    delta: cython.double,
    steps: cython.Py_ssize_t,
    stall: cython.double,
    group: cython.Py_ssize_t,
) -> cython.bint:
    """The safeguarded Newton iteration of :func:`relief_cad.contacts._foot`, in place on ``u``, ``dist``.

    ``H`` is the curve and ``HD`` its hodograph (homogeneous rows, weights last), ``P`` (m, d)
    the points, ``u`` (m,) and ``dist`` (m,) the seeds and their distances. Each step tries, from
    the same ``u``, the Newton step, its half and quarter, and the probes ``u +- delta``, keeping
    each trial that brings a point closer; ``delta`` halves per step. Rows come in consecutive
    groups of ``group`` seeds of one point. It stops after ``steps`` steps, once every group has a
    distance ``<= enough`` (``group`` 1: every row), or after three steps in a row where no
    distance fell below ``stall`` times its value before the step. The numpy form's operations in their
    order: the same bits. Returns False when a trial parameter is NaN (overflowed data), where the
    numpy form raised in :meth:`~relief_cad.RationalBezier.evaluate`.
    """
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t
    j: cython.Py_ssize_t
    _step: cython.Py_ssize_t
    m: cython.Py_ssize_t = P.shape[0]
    d: cython.Py_ssize_t = P.shape[1]
    B: cython.double[:, :] = np.empty((max(H.shape[0], HD.shape[0]), max(H.shape[1], HD.shape[1])))
    X: cython.double[:] = np.empty(d)
    Y: cython.double[:] = np.empty(d)
    trial: cython.double[:] = np.empty(5)
    XU: cython.double[:, :] = np.empty((m, d))  # the point of the curve at u[i], once computed
    known: cython.uchar[:] = np.zeros(m, dtype=np.uint8)
    done: cython.bint
    still: cython.bint
    before: cython.double
    ui: cython.double
    num: cython.double
    den: cython.double
    step: cython.double
    td: cython.double
    best: cython.double = 0.0
    stalled: cython.Py_ssize_t = 0
    for _step in range(steps):
        done = True
        still = True
        for i in range(m):
            before = dist[i]
            ui = u[i]
            if known[i]:  # the same bits as evaluating again at the same u
                for c in range(d):
                    X[c] = XU[i, c]
            else:
                _at(H, ui, B, X)
                for c in range(d):
                    XU[i, c] = X[c]
                known[i] = True
            _at(HD, ui, B, Y)
            num = (X[0] - P[i, 0]) * Y[0]
            den = Y[0] * Y[0]
            for c in range(1, d):
                num = num + (X[c] - P[i, c]) * Y[c]
                den = den + Y[c] * Y[c]
            if not (den >= 1e-300 or den != den):  # np.maximum(den, 1e-300), NaN kept
                den = 1e-300
            step = num / den
            trial[0] = _clip01(ui - step)
            trial[1] = _clip01(ui - 0.5 * step)
            trial[2] = _clip01(ui - 0.25 * step)
            trial[3] = _clip01(ui + delta)
            trial[4] = _clip01(ui - delta)
            for j in range(5):
                if trial[j] != trial[j]:
                    return False
                td = _gap(H, trial[j], P, i, B, X)
                if td < dist[i]:
                    u[i] = trial[j]
                    dist[i] = td
                    for c in range(d):
                        XU[i, c] = X[c]
            best = dist[i] if i % group == 0 else min(best, dist[i])
            if i % group == group - 1:
                done = done and best <= enough
            still = still and dist[i] >= before * stall
        delta *= 0.5
        if done:
            break
        stalled = stalled + 1 if still else 0
        if stalled >= 3:
            break
    return True


@cython.cfunc
def _grid_points(H: cython.const[cython.double][:, :], grid: cython.const[cython.double][:],
                 d: cython.Py_ssize_t):
    """The curve ``H`` at ``grid`` (g,): (g, d), the bits of :meth:`~relief_cad.RationalBezier.evaluate`."""
    g: cython.Py_ssize_t
    B: cython.double[:, :] = np.empty((H.shape[0], H.shape[1]))
    X: cython.double[:, :] = np.empty((grid.shape[0], d))
    for g in range(grid.shape[0]):
        _at(H, grid[g], B, X[g])
    return X


@cython.cfunc
@cython.exceptval(check=False)
def _sq(P: cython.const[cython.double][:, :], i: cython.Py_ssize_t, X: cython.double[:, :],
        g: cython.Py_ssize_t) -> cython.double:
    """``((P[i] - X[g]) ** 2).sum()`` in numpy's order (coordinate by coordinate)."""
    c: cython.Py_ssize_t
    acc: cython.double = (P[i, 0] - X[g, 0]) * (P[i, 0] - X[g, 0])
    for c in range(1, P.shape[1]):
        acc = acc + (P[i, c] - X[g, c]) * (P[i, c] - X[g, c])
    return acc


def foot_seeds(
    H: cython.const[cython.double][:, :],
    grid: cython.const[cython.double][:],
    P: cython.const[cython.double][:, :],
    k: cython.Py_ssize_t,
):
    """Seeds of :func:`relief_cad.contacts._foot`: for each point, the ``k`` nearest local minima.

    ``H`` is the curve (homogeneous rows, weights last), ``grid`` (g,) its sampled parameters with
    ``g >= k``, ``P`` (m, d) the points. The squared grid distances are those of the numpy form
    (``((P[:, None] - X[None]) ** 2).sum(axis=2)``, ``X`` the curve at the grid, evaluated with the
    bits of :meth:`~relief_cad.RationalBezier.evaluate`); a grid point is a local minimum when its
    distance is ``<=`` both neighbours' (none past the ends). The seeds of a point are its ``k``
    smallest minima, then, if there are fewer, its first non-minima in grid order: the order of a
    stable ``argsort`` that counts non-minima as infinite. Returns ``u`` (m k,), the seeds'
    parameters, and ``dist`` (m k,), their distances, the seeds of one point consecutive.
    """
    i: cython.Py_ssize_t
    g: cython.Py_ssize_t
    j: cython.Py_ssize_t
    ng: cython.Py_ssize_t = grid.shape[0]
    m: cython.Py_ssize_t = P.shape[0]
    X: cython.double[:, :] = _grid_points(H, grid, P.shape[1])
    D: cython.double[:] = np.empty(ng)
    key: cython.double[:] = np.empty(ng)
    pick: cython.Py_ssize_t[:] = np.empty(k, dtype=np.intp)
    u_out = np.empty(m * k)
    d_out = np.empty(m * k)
    uo: cython.double[:] = u_out
    do: cython.double[:] = d_out
    lo: cython.double
    hi: cython.double
    for i in range(m):
        for g in range(ng):
            D[g] = _sq(P, i, X, g)
        for g in range(ng):  # no neighbour past an end: an infinite one (NaN is no minimum)
            lo = D[g - 1] if g > 0 else _INF
            hi = D[g + 1] if g < ng - 1 else _INF
            key[g] = D[g] if D[g] <= lo and D[g] <= hi else _INF
        _smallest(key, k, pick)
        for j in range(k):
            uo[i * k + j] = grid[pick[j]]
            do[i * k + j] = sqrt(D[pick[j]])
    return u_out, d_out


@cython.cfunc
@cython.exceptval(check=False)
def _smallest(key: cython.double[:], k: cython.Py_ssize_t, pick: cython.Py_ssize_t[:]) -> cython.void:
    """Indexes of the ``k`` smallest ``key`` (no NaN) into ``pick``, ties by index.

    The first ``k`` of a stable ``argsort``.
    """
    g: cython.Py_ssize_t
    j: cython.Py_ssize_t
    n: cython.Py_ssize_t = 0
    for g in range(key.shape[0]):
        if n == k and not key[g] < key[pick[k - 1]]:
            continue
        j = n if n < k else k - 1  # full: the last pick drops out; insert after every key <= key[g]
        while j > 0 and key[g] < key[pick[j - 1]]:
            pick[j] = pick[j - 1]
            j -= 1
        pick[j] = g
        if n < k:
            n += 1


def surely_far(
    H: cython.const[cython.double][:, :],
    grid: cython.const[cython.double][:],
    P: cython.const[cython.double][:, :],
    tol: cython.double,
) -> cython.bint:
    """True when some point of ``P`` (m, d) is certainly farther than ``tol`` from the curve ``H``.

    The test of :func:`relief_cad.contacts._surely_far` with its numpy form's bits: the curve at
    ``grid`` (g,) (the bits of :meth:`~relief_cad.RationalBezier.evaluate`), the longest chord
    between consecutive grid points, and for each point its nearest grid distance; far when that
    distance exceeds ``tol`` plus the longest chord.
    """
    g: cython.Py_ssize_t
    i: cython.Py_ssize_t
    X: cython.double[:, :] = _grid_points(H, grid, P.shape[1])
    acc: cython.double
    near: cython.double
    chord: cython.double = -_INF
    for g in range(grid.shape[0] - 1):  # np.max propagates NaN
        acc = sqrt(_sq(X, g + 1, X, g))
        if acc > chord or acc != acc or chord != chord:
            chord = acc if chord == chord else chord
    for i in range(P.shape[0]):
        near = _INF
        for g in range(grid.shape[0]):  # np.min propagates NaN
            acc = _sq(P, i, X, g)
            if acc < near or acc != acc or near != near:
                near = acc if near == near else near
        if sqrt(near) > tol + chord:
            return True
    return False

"""Double-double arithmetic and the certified Newton polish of ill-conditioned roots.

Error-free transformations (two-sum, Dekker's two-product) and a double-double de Casteljau.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import sqrt

from .bezier import _eval, _rounds


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _two_sum(a: cython.double, b: cython.double) -> tuple[cython.double, cython.double]:
    s = a + b
    bb = s - a
    return s, (a - (s - bb)) + (b - bb)


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _two_prod(a: cython.double, b: cython.double) -> tuple[cython.double, cython.double]:
    p = a * b
    c = 134217729.0 * a
    ah = c - (c - a)
    al = a - ah
    c = 134217729.0 * b
    bh = c - (c - b)
    bl = b - bh
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _dd_add(
    ah: cython.double, al: cython.double, bh: cython.double, bl: cython.double
) -> tuple[cython.double, cython.double]:
    s, e = _two_sum(ah, bh)
    e += al + bl
    return _two_sum(s, e)


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _dd_mul(
    ah: cython.double, al: cython.double, bh: cython.double, bl: cython.double
) -> tuple[cython.double, cython.double]:
    p, e = _two_prod(ah, bh)
    e += ah * bl + al * bh
    return _two_sum(p, e)


@cython.cfunc
@cython.nogil
@cython.inline
@cython.exceptval(check=False)
def _dd_div(
    ah: cython.double, al: cython.double, bh: cython.double, bl: cython.double
) -> tuple[cython.double, cython.double]:
    q1 = ah / bh
    ph, pl = _dd_mul(q1, 0.0, bh, bl)
    rh, rl = _dd_add(ah, al, -ph, -pl)
    q2 = rh / bh
    return _two_sum(q1, q2)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _eval_dd(
    H: cython.const[cython.double][:, :], t: cython.double, wk: cython.double[:, :]
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """Point of the rational curve ``H`` at ``t`` in double-double ``(xh, xl, yh, yl)``.

    de Casteljau with every operation error-free-transformed (``wk``: scratch of
    shape ``(m, 6)``), so the result is accurate to about ``eps**2 * cond``.

    A polynomial curve (every weight exactly 1) skips its weights: their double-double de
    Casteljau stays exactly ``(1, 0)`` (``(sh, sl)`` is ``1 - t`` exactly, so ``sh + sl + t`` is 1
    and every round's error-free sum returns it), and the quotient by ``(1, 0)`` is then
    ``two_sum(xh, xl)``: the same bits for a third less work.
    """
    i: cython.Py_ssize_t
    m = H.shape[0]
    sh, sl = _two_sum(1.0, -t)
    ncols: cython.Py_ssize_t = 2
    for i in range(m):
        if H[i, 2] != 1.0:
            ncols = 3
            break
    for i in range(m):
        for k in range(ncols):
            wk[i, 2 * k] = H[i, k]
            wk[i, 2 * k + 1] = 0.0
    for r in range(1, m):
        for i in range(0, m - r):
            for k in range(ncols):
                ph, pl = _dd_mul(sh, sl, wk[i, 2 * k], wk[i, 2 * k + 1])
                qh, ql = _dd_mul(t, 0.0, wk[i + 1, 2 * k], wk[i + 1, 2 * k + 1])
                vh, vl = _dd_add(ph, pl, qh, ql)
                wk[i, 2 * k] = vh
                wk[i, 2 * k + 1] = vl
    if ncols == 2:
        xh, xl = _two_sum(wk[0, 0], wk[0, 1])
        yh, yl = _two_sum(wk[0, 2], wk[0, 3])
        return xh, xl, yh, yl
    xh, xl = _dd_div(wk[0, 0], wk[0, 1], wk[0, 4], wk[0, 5])
    yh, yl = _dd_div(wk[0, 2], wk[0, 3], wk[0, 4], wk[0, 5])
    return xh, xl, yh, yl


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _gap_dd(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    da: cython.double[:, :],
    db: cython.double[:, :],
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """``a(t) - b(u)`` in double-double ``(xh, xl, yh, yl)``: :func:`_eval_dd` of both points.

    ``da``, ``db``: scratch. The one home of the certified residual: :func:`_polish_dd` steps
    on it, :func:`_side_dd` takes its side.
    """
    axh, axl, ayh, ayl = _eval_dd(HA, t, da)
    bxh, bxl, byh, byl = _eval_dd(HB, u, db)
    fx, fxl = _dd_add(axh, axl, -bxh, -bxl)
    fy, fyl = _dd_add(ayh, ayl, -byh, -byl)
    return fx, fxl, fy, fyl


def _side_dd(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wb: cython.double[:, :],
    da: cython.double[:, :],
    db: cython.double[:, :],
) -> cython.double:
    """Signed distance of ``a(t)`` from ``b`` at ``b(u)`` (its foot), ``a - b`` in double-double.

    Positive on the left of ``b``'s direction. The difference of the points is exact to about
    ``eps**2`` (:func:`_eval_dd`), so a gap of 1e-20 between exact data keeps its sign, where the
    double evaluation's rounding (1e-16) decides it at random. ``wb``, ``da``, ``db``: scratch.
    """
    fx, fxl, fy, fyl = _gap_dd(HA, HB, t, u, da, db)
    _bx, _by, bdx, bdy, _b2, _b3 = _eval(HB, u, wb)
    speed = sqrt(bdx * bdx + bdy * bdy)
    if speed == 0.0:
        return 0.0
    return (bdx * (fy + fyl) - bdy * (fx + fxl)) / speed


def _polish_dd(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wa: cython.double[:, :],
    wb: cython.double[:, :],
    da: cython.double[:, :],
    db: cython.double[:, :],
    steps: cython.Py_ssize_t,
):
    """Newton steps on ``a(t) - b(u)`` with a double-double residual.

    Returns ``(t, u, certified)``: ``certified`` when the iteration reached a fixed
    point in double precision parameters (last step below 4e-16), i.e. an exact
    root lies within an ulp or two; a spurious root of a rounded double root
    keeps moving and is not certified.
    """
    for _ in range(steps):
        fx, _fxl, fy, _fyl = _gap_dd(HA, HB, t, u, da, db)
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
        small: cython.bint = abs(dt) <= 4e-16 and abs(du) <= 4e-16
        t = nt
        u = nu
        if small:
            return t, u, True
    return t, u, False


@cython.cfunc
@cython.exceptval(check=False)
def _along(H: cython.const[cython.double][:, :], x: cython.double, ref: cython.const[cython.double][:],
           B: cython.double[:, :]) -> cython.double:
    """``c'(x) . ref`` for the rational curve ``H`` ((n + 1, d + 1), weights last), sign-faithful.

    The derivative has the bits of :meth:`relief_cad.RationalBezier.derivative` (the same de
    Casteljau rounds, then the quotient rule in its order); the dot product is summed in
    double-double from exact products, so its sign is right unless it is below about 2**-100 of
    its terms (numpy's dot rounds, and where OpenBLAS fuses, differs from machine to machine).
    """
    c: cython.Py_ssize_t
    k: cython.Py_ssize_t = H.shape[1]
    nd: cython.double = H.shape[0] - 1
    s: cython.double = 1.0 - x
    _rounds(H, x, B)
    w: cython.double = s * B[0, k - 1] + x * B[1, k - 1]
    dw: cython.double = nd * (B[1, k - 1] - B[0, k - 1])
    hi: cython.double = 0.0
    lo: cython.double = 0.0
    for c in range(k - 1):
        pt = (s * B[0, c] + x * B[1, c]) / w
        der = (nd * (B[1, c] - B[0, c]) - pt * dw) / w
        ph, pl = _two_prod(der, ref[c])
        hi, lo = _dd_add(hi, lo, ph, pl)
    return hi


def fold_bisect(H: cython.const[cython.double][:, :], ref: cython.const[cython.double][:],
                t: cython.double, u: cython.double) -> cython.double:
    """The parameter in ``(t, u)`` where the curve ``H`` turns back against ``ref``, or NaN.

    ``H``: (n + 1, d + 1) homogeneous control points (weights last); ``ref`` (d,): the derivative
    at ``t``. NaN when ``c'(u) . ref >= 0`` (no reversal); otherwise bisection keeps
    ``c'(lo) . ref > 0 >= c'(hi) . ref`` down to adjacent doubles (at most 200 halvings) and
    returns the midpoint. See :func:`relief_cad.contacts._fold`.
    """
    B: cython.double[:, :] = np.empty((H.shape[0], H.shape[1]))
    lo: cython.double = t
    hi: cython.double = u
    mid: cython.double
    if _along(H, hi, ref, B) >= 0.0:
        return math.nan
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid == lo or mid == hi:
            break
        if _along(H, mid, ref, B) > 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)

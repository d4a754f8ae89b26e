"""Homogeneous Bézier curves: de Casteljau evaluation and subdivision, boxes, frame.

Rational Bézier curves in homogeneous form (the paper's §2) and the exact joint frame of a pair.
The tolerance is always given by the caller (:func:`relief_cad.tolerances.resolve_tolerance`).

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math
from fractions import Fraction

import cython
import numpy as np
from cython.cimports.libc.math import sqrt

if cython.compiled:
    from cython.cimports.libc.math import fma
else:  # uncompiled (Python < 3.13 has no math.fma): the same correctly rounded a * b + c, exactly

    def fma(a, b, c):
        return float(Fraction(a) * Fraction(b) + Fraction(c))

_INF = cython.declare(cython.double, math.inf)  # a C constant (``math.inf`` is a Python lookup)
_NAN = cython.declare(cython.double, math.nan)


def _grow(arr, n):
    """Return ``arr`` with room for at least ``n`` rows (copying when it must grow)."""
    if n <= arr.shape[0]:
        return arr
    cap = max(n, 2 * arr.shape[0])
    out = np.empty((cap, arr.shape[1]))
    out[: arr.shape[0], :] = arr
    return out


def _segment(
    H: cython.const[cython.double][:, :], t0: cython.double, t1: cython.double, out: cython.double[:, :]
):
    """Homogeneous control points of the sub-curve on ``[t0, t1]`` into ``out``."""
    i: cython.Py_ssize_t
    r: cython.Py_ssize_t
    s: cython.double
    tt: cython.double
    m: cython.Py_ssize_t = H.shape[0]
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


def _cartesian(S: cython.double[:, :], P: cython.double[:, :], W: cython.double[:]):
    """Cartesian points and weights (weights scaled to max 1) of homogeneous rows ``S``.

    Returns the bounding box ``(xlo, xhi, ylo, yhi)`` of the points.
    """
    i: cython.Py_ssize_t
    w: cython.double
    iw: cython.double
    x: cython.double
    y: cython.double
    m: cython.Py_ssize_t = S.shape[0]
    wmax: cython.double = 0.0
    for i in range(m):
        if S[i, 2] > wmax:
            wmax = S[i, 2]
    xlo: cython.double = _INF
    xhi: cython.double = -_INF
    ylo: cython.double = _INF
    yhi: cython.double = -_INF
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


def _rounds(H: cython.const[cython.double][:, :], t: cython.double, B: cython.double[:, :]):
    """Homogeneous de Casteljau at ``t``: ``H`` ((n + 1, k), n >= 1) copied into ``B``, rounds ``1 .. n - 1``.

    The value is then ``(1 - t) B[0] + t B[1]`` and the derivative ``n (B[1] - B[0])``. Row ``i``
    becomes ``s B[i] + t B[i + 1]`` per round, the operations and order of the numpy form of
    :func:`relief_cad.curves._decasteljau`, so every caller gets the same bits.
    """
    i: cython.Py_ssize_t
    r: cython.Py_ssize_t
    c: cython.Py_ssize_t
    n: cython.Py_ssize_t = H.shape[0] - 1
    k: cython.Py_ssize_t = H.shape[1]
    s: cython.double = 1.0 - t
    for i in range(n + 1):
        for c in range(k):
            B[i, c] = H[i, c]
    if k == 3:  # planar rows (w x, w y, w), written out: the same operations, a third of the time
        for r in range(1, n):
            for i in range(n + 1 - r):
                B[i, 0] = s * B[i, 0] + t * B[i + 1, 0]
                B[i, 1] = s * B[i, 1] + t * B[i + 1, 1]
                B[i, 2] = s * B[i, 2] + t * B[i + 1, 2]
        return
    for r in range(1, n):
        for i in range(n + 1 - r):
            for c in range(k):
                B[i, c] = s * B[i, c] + t * B[i + 1, c]


def decasteljau_rows(H: cython.const[cython.double][:, :], T: cython.const[cython.double][:]):
    """Homogeneous values ``H(t)`` and derivatives ``H'(t)``, each ``(m, k)``, at parameters ``T`` (m,).

    ``H`` is ``(n + 1, k)`` with ``n >= 1``: homogeneous control points (weights last, any ``k``).
    The float path of :func:`relief_cad.curves._decasteljau` (see :func:`_rounds`: the same bits),
    without the numpy calls per round that made a scalar evaluation cost 30 us at degree 6.
    """
    c: cython.Py_ssize_t
    q: cython.Py_ssize_t
    t: cython.double
    s: cython.double
    n: cython.Py_ssize_t = H.shape[0] - 1
    k: cython.Py_ssize_t = H.shape[1]
    m: cython.Py_ssize_t = T.shape[0]
    nd: cython.double = n
    value = np.empty((m, k))
    deriv = np.empty((m, k))
    V: cython.double[:, :] = value
    D: cython.double[:, :] = deriv
    B: cython.double[:, :] = np.empty((n + 1, k))
    for q in range(m):
        t = T[q]
        s = 1.0 - t
        _rounds(H, t, B)
        for c in range(k):
            V[q, c] = s * B[0, c] + t * B[1, c]
            D[q, c] = nd * (B[1, c] - B[0, c])
    return value, deriv


def split_rows(H: cython.const[cython.double][:, :], t: cython.double):
    """Homogeneous rows ``(left, right)``, each ``(n + 1, k)``: the pieces of ``H`` on ``[0, t]``, ``[t, 1]``.

    ``H`` is ``(n + 1, k)`` with ``n >= 1`` and ``0 < t < 1``. Round ``r`` of de Casteljau's
    scheme makes row ``i`` ``(1 - t) B[i] + t B[i + 1]`` (``i <= n - r``), the operations and order
    of the numpy form it replaced in :meth:`relief_cad.curves.RationalBezier.split` (the same bits);
    ``left[r]`` is then ``B[0]`` and ``right[n - r]`` is ``B[n - r]``. That form made a split of a
    degree-13 span cost 40 us, a numpy call per round.
    """
    n: cython.Py_ssize_t = H.shape[0] - 1
    k: cython.Py_ssize_t = H.shape[1]
    s: cython.double = 1.0 - t
    left = np.empty((n + 1, k))
    right = np.empty((n + 1, k))
    L: cython.double[:, :] = left
    R: cython.double[:, :] = right
    B: cython.double[:, :] = np.array(H, dtype=np.float64)  # the working rows: a copy of H
    i: cython.Py_ssize_t
    r: cython.Py_ssize_t
    c: cython.Py_ssize_t
    for c in range(k):
        L[0, c] = B[0, c]
        R[n, c] = B[n, c]
    for r in range(1, n + 1):
        for i in range(n + 1 - r):
            for c in range(k):
                B[i, c] = s * B[i, c] + t * B[i + 1, c]
        for c in range(k):
            L[r, c] = B[0, c]
            R[n - r, c] = B[n - r, c]
    return left, right


def bernstein_product(F: cython.const[cython.double][:, :], G: cython.const[cython.double][:, :],
                      fac: cython.const[cython.double][:, :], den: cython.const[cython.double][:]):
    """Bernstein coefficients ``(p + q + 1, k)`` of the product of ``F`` (p + 1, kf) and ``G`` (q + 1, kg).

    ``kf`` and ``kg`` are ``k`` or 1 (a column broadcast over the other's ``k``); ``fac[i, j]`` is
    ``C(p, i) C(q, j)`` rounded once and ``den[r]`` is ``C(p + q, r)``. Term ``(i, j)`` is
    ``(fac[i, j] F[i]) G[j]``, added to row ``i + j`` in order of ``i``, then each row is divided by
    ``den``: the operations and order of :func:`relief_cad.curves._product_bernstein`'s numpy form
    (the same bits), without its numpy calls per row (56 us for a rational cubic's hodograph).
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    c: cython.Py_ssize_t
    p: cython.Py_ssize_t = F.shape[0] - 1
    q: cython.Py_ssize_t = G.shape[0] - 1
    k: cython.Py_ssize_t = max(F.shape[1], G.shape[1])
    sf: cython.Py_ssize_t = 1 if F.shape[1] > 1 else 0  # column step: 0 broadcasts a column
    sg: cython.Py_ssize_t = 1 if G.shape[1] > 1 else 0
    out = np.zeros((p + q + 1, k))
    o: cython.double[:, :] = out
    for i in range(p + 1):
        for j in range(q + 1):
            for c in range(k):
                o[i + j, c] = o[i + j, c] + (fac[i, j] * F[i, c * sf]) * G[j, c * sg]
    for i in range(p + q + 1):
        for c in range(k):
            o[i, c] = o[i, c] / den[i]
    return out


def _eval(H: cython.const[cython.double][:, :], t: cython.double, wk: cython.double[:, :]):
    """Point, first and second derivative of the rational curve ``H`` at ``t``.

    Returns ``(x, y, dx, dy, ddx, ddy)``; ``wk`` is scratch of ``H``'s shape.
    """
    i: cython.Py_ssize_t
    r: cython.Py_ssize_t
    m: cython.Py_ssize_t = H.shape[0]
    n: cython.Py_ssize_t = m - 1
    c: cython.Py_ssize_t
    s: cython.double = 1.0 - t
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


def _frame(PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :]):
    """Exact translation ``(cx, cy)`` and power-of-two scale of the joint frame."""
    i: cython.Py_ssize_t
    k: cython.Py_ssize_t
    lo: cython.double
    hi: cython.double
    c: cython.double
    cx: cython.double = 0.0
    cy: cython.double = 0.0
    for k in range(2):
        lo = _INF
        hi = -_INF
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
    big: cython.double = 0.0
    for i in range(PA.shape[0]):
        big = max(big, abs(PA[i, 0] - cx), abs(PA[i, 1] - cy))
    for i in range(PB.shape[0]):
        big = max(big, abs(PB[i, 0] - cx), abs(PB[i, 1] - cy))
    return cx, cy, _pow2_scale(big)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _pow2_scale(big: cython.double) -> cython.double:
    """``2**-e`` with ``e = max(frexp(big)[1], -1000)`` (``2**(e - 1) <= big < 2**e``); else 1.0.

    By exact doublings and halvings (libc's ``frexp`` needs a pointer, which pure-Python mode
    has not): ``e`` stays above -1000 so that the scale is finite for subnormal inputs.
    """
    if not 0.0 < big < _INF:  # as frexp: e = 0 for 0, inf and nan
        return 1.0
    e: cython.int = 0
    p: cython.double = 1.0  # 2**e
    scale: cython.double = 1.0  # 2**-e
    if big >= 1.0:
        while big >= p:  # p = inf past 2**1023 ends it
            p *= 2.0
            scale *= 0.5
            e += 1
        return scale
    while e > -1000 and big < 0.5 * p:
        p *= 0.5
        scale *= 2.0
        e -= 1
    return scale


def homogeneous_rows(P: cython.const[cython.double][:, :], W: object, max_ratio: cython.double):
    """The rows ``[w_i P_i, w_i]`` of a curve's points ``P`` (n + 1, d) and weights ``W``, or None.

    ``W`` is a float64 array (n + 1,) or None (every weight 1). None is returned when a point,
    a weight or a product is not finite, a weight is not > 0, or the weights' max / min exceeds
    ``max_ratio``: the checks of :class:`~relief_cad.RationalBezier` then name the fault. The
    products are numpy's ``P * W[:, None]`` (one rounding each), so the rows are those numpy
    makes; a new (n + 1, d + 1) array.

    >>> import numpy as np
    >>> homogeneous_rows(np.array([[1.0, 2.0], [3.0, 4.0]]), np.array([2.0, 0.5]), 1e15).tolist()
    [[2.0, 4.0, 2.0], [1.5, 2.0, 0.5]]
    >>> homogeneous_rows(np.array([[1.0, 2.0]]), np.array([0.0]), 1e15) is None
    True
    """
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t
    n: cython.Py_ssize_t = P.shape[0]
    d: cython.Py_ssize_t = P.shape[1]
    w: cython.double = 1.0
    lo: cython.double = _INF
    hi: cython.double = 0.0
    WV: cython.const[cython.double][:]
    weighted: cython.bint = W is not None
    if weighted:
        WV = W
    out = np.empty((n, d + 1))
    H: cython.double[:, :] = out
    for i in range(n):  # (float(): Python floats when run uncompiled, as compiled: no numpy warnings)
        if weighted:
            w = float(WV[i])
            if not (0.0 < w < _INF):  # also NaN
                return None
            lo = min(lo, w)
            hi = max(hi, w)
        for c in range(d):
            H[i, c] = float(P[i, c]) * w
            if not (abs(P[i, c]) < _INF and abs(H[i, c]) < _INF):  # also NaN
                return None
        H[i, d] = w
    if weighted and not hi / lo <= max_ratio:
        return None
    return out


def max_abs(P: cython.const[cython.double][:, :], ncols: cython.Py_ssize_t) -> cython.double:
    """The largest ``|P[i, c]|`` over the rows and the first ``ncols`` columns of ``P`` (0.0 if empty).

    >>> import numpy as np
    >>> max_abs(np.array([[1.0, -3.0, 9.0], [2.0, 0.5, 1.0]]), 2)
    3.0
    """
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t
    big: cython.double = 0.0
    for i in range(P.shape[0]):
        for c in range(min(ncols, P.shape[1])):
            big = max(big, abs(P[i, c]))
    return big


def affine_rows(H: cython.const[cython.double][:, :], M: cython.const[cython.double][:, :],
                out: cython.double[:, :]):
    """Write ``H @ M.T`` (rows ``H`` (n, k), a map ``M`` (m, k), k <= 4) into ``out[:, :m]`` (may be ``H``).

    Each entry is the chain ``fma(M[j, k-1], H[i, k-1], ... fma(M[j, 1], H[i, 1], M[j, 0] H[i, 0]))``,
    every step rounded once (C99 ``fma``; exact fractions when uncompiled), so the result does not
    depend on the machine's BLAS: numpy's ``H @ M.T`` is this chain where OpenBLAS uses FMA (x86-64
    with AVX2) and differs in the last bit where it does not. The columns of ``out`` from ``m`` on
    are left as they are (the weights, when ``out`` is ``H``).

    >>> import numpy as np
    >>> h = np.array([[1.0, 2.0, 3.0, 1.0]])
    >>> affine_rows(h, np.array([[0.0, 1.0, 0.0, 5.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 2.0, 0.0]]), h)
    >>> h.tolist()
    [[7.0, 1.0, 6.0, 1.0]]
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    c: cython.Py_ssize_t
    k: cython.Py_ssize_t = H.shape[1]
    acc: cython.double
    row = cython.declare(cython.double[4])
    if M.shape[1] != k or k > 4 or k < 1 or out.shape[0] != H.shape[0] or out.shape[1] < M.shape[0]:
        raise ValueError(f"expected rows (n, k), a map (m, k) with k <= 4 and out (n, >= m); received "
                         f"{H.shape[0]}x{k}, {M.shape[0]}x{M.shape[1]} and {out.shape[0]}x{out.shape[1]}")
    for i in range(H.shape[0]):
        for c in range(k):
            row[c] = H[i, c]  # the whole row first: out may be H
        for j in range(M.shape[0]):
            acc = M[j, 0] * row[0]
            for c in range(1, k):
                acc = fma(M[j, c], row[c], acc)
            out[i, j] = acc


def _bbox_update(P: cython.const[cython.double][:, :], box: cython.double[:]):
    """Grow ``box = [xlo, xhi, ylo, yhi, max|coord|]`` by the points ``P``."""
    for i in range(P.shape[0]):
        x = P[i, 0]
        y = P[i, 1]
        box[0] = min(box[0], x)
        box[1] = max(box[1], x)
        box[2] = min(box[2], y)
        box[3] = max(box[3], y)
        box[4] = max(box[4], abs(x), abs(y))


def _curve_box_update(
    P: cython.const[cython.double][:, :], W: cython.const[cython.double][:], box: cython.double[:],
    wk: cython.double[:, :],
):
    """Grow ``box`` (``[xlo, xhi, ylo, yhi]``) by samples of the planar curve itself.

    The curve (``P`` (n + 1, 2), weights ``W``) is sampled at ``2 (n + 1) + 1`` uniform
    parameters by homogeneous de Casteljau: the curve's own extent, not its control polygon's
    (which can be far larger for ill-conditioned curves). ``wk`` is work space of at least
    ``n + 1`` rows and 3 columns (overwritten). The three coordinates are written out, not
    looped over: a tenth of the time of a degree-7 pair goes here.
    """
    i: cython.Py_ssize_t
    k: cython.Py_ssize_t
    r: cython.Py_ssize_t
    t: cython.double
    s: cython.double
    x: cython.double
    m: cython.Py_ssize_t = P.shape[0]
    ns: cython.Py_ssize_t = 2 * m + 1
    for k in range(ns):
        t = k / (ns - 1.0)
        s = 1.0 - t
        for i in range(m):
            wk[i, 0] = W[i] * P[i, 0]
            wk[i, 1] = W[i] * P[i, 1]
            wk[i, 2] = W[i]
        for r in range(1, m):
            for i in range(m - r):
                wk[i, 0] = s * wk[i, 0] + t * wk[i + 1, 0]
                wk[i, 1] = s * wk[i, 1] + t * wk[i + 1, 1]
                wk[i, 2] = s * wk[i, 2] + t * wk[i + 1, 2]
        x = wk[0, 0] / wk[0, 2]
        box[0] = min(box[0], x)
        box[1] = max(box[1], x)
        x = wk[0, 1] / wk[0, 2]
        box[2] = min(box[2], x)
        box[3] = max(box[3], x)


def _homog(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    cx: cython.double,
    cy: cython.double,
    scale: cython.double,
):
    """Homogeneous rows of the curve in the frame, weights scaled to max 1."""
    H = np.empty((P.shape[0], 3))
    _homog_into(P, W, cx, cy, scale, H)
    return H


def _homog_into(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    cx: cython.double,
    cy: cython.double,
    scale: cython.double,
    H: cython.double[:, :],
):
    """:func:`_homog` into ``H`` (``m`` rows, 3 columns)."""
    i: cython.Py_ssize_t
    w: cython.double
    m: cython.Py_ssize_t = P.shape[0]
    wmax: cython.double = 0.0
    for i in range(m):
        wmax = max(wmax, W[i])
    for i in range(m):
        w = W[i] / wmax
        H[i, 0] = w * ((P[i, 0] - cx) * scale)
        H[i, 1] = w * ((P[i, 1] - cy) * scale)
        H[i, 2] = w


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _sample_into(H: cython.const[cython.double][:, :], P: cython.const[cython.double][:, :],
                 T: cython.const[cython.double][:], wk: cython.double[:, :], lo: cython.Py_ssize_t,
                 big: cython.double) -> cython.double:
    """Fold the samples of the curve ``H`` at ``T`` into the box in rows ``lo``, ``lo + 1`` of ``wk``.

    Row ``lo`` holds the per-coordinate minima, row ``lo + 1`` the maxima. Returns ``big`` raised
    to the largest ``|x|`` of the control points ``P``, or -1.0 when a sampled weight is not > 0
    or a sample is not finite. The samples are the bits of
    :meth:`~relief_cad.RationalBezier.evaluate` (:func:`_rounds`, then the division by the weight,
    as ``RationalBezier._eval``).
    """
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t
    q: cython.Py_ssize_t
    d: cython.Py_ssize_t = H.shape[1] - 1
    t: cython.double
    s: cython.double
    w: cython.double
    x: cython.double
    for i in range(P.shape[0]):
        for c in range(P.shape[1]):
            if abs(P[i, c]) > big:
                big = abs(P[i, c])
    for q in range(T.shape[0]):
        t = T[q]
        s = 1 - t
        _rounds(H, t, wk)
        w = s * wk[0, d] + t * wk[1, d]
        if not w > 0.0:
            return -1.0
        for c in range(d):
            x = (s * wk[0, c] + t * wk[1, c]) / w
            if not (-_INF < x < _INF):
                return -1.0
            if x < wk[lo, c]:
                wk[lo, c] = x
            if x > wk[lo + 1, c]:
                wk[lo + 1, c] = x
    return big


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _rule(wk: cython.double[:, :], lo: cython.Py_ssize_t, dim: cython.Py_ssize_t, big: cython.double,
          rel: cython.double, ulps: cython.double) -> cython.double:
    """:func:`_rule3` of the samples' box in rows ``lo`` (minima), ``lo + 1`` (maxima) of ``wk``."""
    return _rule3(wk[lo, 0], wk[lo, 1], wk[lo, 2] if dim > 2 else 0.0, wk[lo + 1, 0], wk[lo + 1, 1],
                  wk[lo + 1, 2] if dim > 2 else 0.0, dim, big, rel, ulps)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _rule3(lo0: cython.double, lo1: cython.double, lo2: cython.double, hi0: cython.double,
           hi1: cython.double, hi2: cython.double, dim: cython.Py_ssize_t, big: cython.double,
           rel: cython.double, ulps: cython.double) -> cython.double:
    """The default tolerance from the samples' box ``[lo, hi]`` (``dim``: 2 or 3); -1.0 if all is 0.

    :func:`relief_cad.tolerances._tolerance_at`'s rule and order of operations: the box diagonal
    scaled by ``scale = max(big, max |sample|)``, its squares summed coordinate by coordinate,
    ``rel * size + ulps * big``, never below the floor ``max(ulps * big, 1e-300)``.
    """
    scale: cython.double = max(big, abs(lo0), abs(hi0))
    scale = max(scale, abs(lo1), abs(hi1))
    if dim > 2:
        scale = max(scale, abs(lo2), abs(hi2))
    if scale == 0.0:
        return -1.0
    dc: cython.double = (hi0 - lo0) / scale
    ss: cython.double = 0.0 + dc * dc
    dc = (hi1 - lo1) / scale
    ss = ss + dc * dc
    if dim > 2:
        dc = (hi2 - lo2) / scale
        ss = ss + dc * dc
    size: cython.double = sqrt(ss) * scale
    tol: cython.double = rel * size + ulps * big
    floor: cython.double = max(ulps * big, 1e-300)
    if not (-_INF < tol < _INF):
        return floor
    return max(tol, floor)


def _sample_box(curve, params: list, samples: cython.Py_ssize_t):
    """The box of one curve's samples and its largest ``|x|``: ``(lo0, lo1, lo2, hi0, hi1, hi2, big, dim)``.

    A planar curve has ``lo2 = hi2 = 0.0`` (it lies in ``x_2 = 0``). ``False`` when a sampled
    weight is not positive or a sample is not finite (see :func:`_sample_into`).
    """
    H: cython.const[cython.double][:, :] = curve.homogeneous
    rows: cython.Py_ssize_t = H.shape[0]
    dim: cython.Py_ssize_t = H.shape[1] - 1
    c: cython.Py_ssize_t
    if rows < 2:
        return False
    wk: cython.double[:, :] = np.zeros((rows + 2, 4))  # de Casteljau rows, the minima, the maxima
    for c in range(dim):
        wk[rows, c] = _INF
        wk[rows + 1, c] = -_INF
    big = _sample_into(H, curve.control_points, params[min(2 * rows + 1, samples)], wk, rows, 0.0)
    if big < 0.0:
        return False
    return (wk[rows, 0], wk[rows, 1], wk[rows, 2], wk[rows + 1, 0], wk[rows + 1, 1], wk[rows + 1, 2],
            big, dim)


def sampled_tolerance(curves: tuple, params: list, samples: cython.Py_ssize_t, rel: cython.double,
                      ulps: cython.double):
    """Default tolerance of rational curves sampled along themselves (model units), or None.

    ``curves`` are :class:`~relief_cad.curves.RationalBezier` (their ``homogeneous`` rows and their
    ``control_points`` are read); a curve of degree ``n`` is sampled at ``params[min(2 n + 3,
    samples)]`` (``params[m]`` is ``np.linspace(0.0, 1.0, m)``), with the bits of
    ``RationalBezier.evaluate``. With the box of all samples, ``big`` the largest ``|x|`` of the
    control points and ``rel``, ``ulps`` the rule's factors, returns
    :func:`relief_cad.tolerances._tolerance_at`'s value (the same operations in the same order). A
    curve of fewer coordinates than the others counts as lying in ``x_d = 0``. None when a sampled
    weight is not positive or a sample is not finite (the general path then raises or handles
    them), or when every coordinate is 0.

    Each curve's box (:func:`_sample_box`) is kept in its ``_sbox`` slot (the curve is immutable):
    a second call on the same curve does not sample it again. The boxes' union is exact (minima
    and maxima), so the value does not depend on that cache.
    """
    tol = _cached_tolerance(curves, params, samples, rel, ulps)
    return None if tol < 0.0 else tol


def pairs_tolerances(pairs: list, params: list, samples: cython.Py_ssize_t, rel: cython.double,
                     ulps: cython.double):
    """:func:`sampled_tolerance` of each ``(a, b)`` tuple of ``pairs``: an array, NaN where None.

    One call for a batch (the per-curve boxes are cached as in :func:`sampled_tolerance`).
    """
    k: cython.Py_ssize_t
    out = np.empty(len(pairs))
    o: cython.double[:] = out
    for k in range(len(pairs)):
        o[k] = _cached_tolerance(pairs[k], params, samples, rel, ulps)
        if o[k] < 0.0:
            o[k] = math.nan
    return out


@cython.cfunc
def _cached_tolerance(curves: tuple, params: list, samples: cython.Py_ssize_t, rel: cython.double,
                      ulps: cython.double) -> cython.double:
    """:func:`sampled_tolerance`'s value, or -1.0 for None."""
    lo0: cython.double = _INF
    lo1: cython.double = _INF
    lo2: cython.double = _INF
    hi0: cython.double = -_INF
    hi1: cython.double = -_INF
    hi2: cython.double = -_INF
    big: cython.double = 0.0
    dim: cython.Py_ssize_t = 0
    x0: cython.double
    x1: cython.double
    x2: cython.double
    y0: cython.double
    y1: cython.double
    y2: cython.double
    b: cython.double
    d: cython.Py_ssize_t
    for curve in curves:
        box = curve._sbox
        if box is None:
            box = _sample_box(curve, params, samples)
            curve._sbox = box
        if box is False:
            return -1.0
        x0, x1, x2, y0, y1, y2, b, d = box
        lo0, lo1, lo2 = min(lo0, x0), min(lo1, x1), min(lo2, x2)
        hi0, hi1, hi2 = max(hi0, y0), max(hi1, y1), max(hi2, y2)
        big = max(big, b)
        dim = max(dim, d)
    return _rule3(lo0, lo1, lo2, hi0, hi1, hi2, dim, big, rel, ulps)


def pair_tolerances(
    H: cython.const[cython.double][:, :],
    P: cython.const[cython.double][:, :],
    offsets: cython.const[cython.longlong][:],
    pairs: cython.const[cython.longlong][:, :],
    table: cython.const[cython.double][:, :],
    samples: cython.Py_ssize_t,
    rel: cython.double,
    ulps: cython.double,
):
    """:func:`sampled_tolerance` of every pair of packed curves of one dimension: an array, NaN where None.

    Curve ``k`` has the homogeneous rows ``H[offsets[k]:offsets[k + 1]]`` and the control points
    ``P[offsets[k]:offsets[k + 1]]``; ``pairs`` (p, 2) indexes curves; ``table[m, :m]`` is
    ``np.linspace(0.0, 1.0, m)``. No Python per pair (the batch's hot path), and the pairs run
    without the GIL, so threads compute chunks of a batch at once.
    """
    k: cython.Py_ssize_t
    j: cython.Py_ssize_t
    c: cython.Py_ssize_t
    n: cython.Py_ssize_t
    m: cython.Py_ssize_t
    lo: cython.Py_ssize_t
    hi: cython.Py_ssize_t
    rows: cython.Py_ssize_t = 0
    dim: cython.Py_ssize_t = H.shape[1] - 1
    big: cython.double
    for k in range(offsets.shape[0] - 1):
        rows = max(rows, offsets[k + 1] - offsets[k])
    out = np.empty(pairs.shape[0])
    o: cython.double[:] = out
    wk: cython.double[:, :] = np.empty((rows + 2, dim + 1))
    with cython.nogil:  # threads compute the tolerances of their chunks at once
        for k in range(pairs.shape[0]):
            for c in range(dim):
                wk[rows, c] = _INF
                wk[rows + 1, c] = -_INF
            big = 0.0
            for j in range(2):
                lo = offsets[pairs[k, j]]
                hi = offsets[pairs[k, j] + 1]
                n = hi - lo - 1
                m = min(2 * n + 3, samples)
                if n < 1 or big < 0.0:
                    big = -1.0
                    break
                big = _sample_into(H[lo:hi], P[lo:hi], table[m, :m], wk, rows, big)
            o[k] = _NAN if big < 0.0 else _rule(wk, rows, dim, big, rel, ulps)
            if o[k] < 0.0:
                o[k] = _NAN
    return out

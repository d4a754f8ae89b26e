"""The relief scheme for space curves.

The paper's §3: the frame, the relief perspective φ_k, the projection ψ, the planar solve of
the images and the check back in space (depth check).

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
The helpers are C functions on typed memoryviews; their scratch arrays are allocated once per
kernel call. Squares that the numpy version took as ``x ** 2`` on numpy scalars go through
:func:`_sq` (libm ``pow``, which is not always ``x * x`` in the last bit): results stay bit-identical.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import pow as c_pow
from cython.cimports.libc.math import sqrt

from .batch import _ends_match
from .constants import (
    _EPS,
    _SPACE_N_FRAMES,
    _SPACE_OVERLAP_SAMPLES,
    _SPACE_TANGENT_SIN,
    KIND_CROSSING,
    KIND_OVERLAP,
    KIND_TANGENT,
    KIND_UNRESOLVED,
    RES_COLS,
    SAFE_EXPONENT,
    SPACE_COLS,
    STATUS_ARTEFACT,
    STATUS_ENDS_MATCH,
    STATUS_OK,
)
from .planar import intersect_pair_kernel

_NO_SPACE_ROWS = np.empty((0, SPACE_COLS))  # the rows of a pair without result (shared, read-only)
_NO_SPACE_ROWS.flags.writeable = False
# C copies of the constants used in the loops
_C_EPS = cython.declare(cython.double, _EPS)
_C_TANGENT_SIN = cython.declare(cython.double, _SPACE_TANGENT_SIN)
_C_SAMPLES = cython.declare(cython.Py_ssize_t, _SPACE_OVERLAP_SAMPLES)
_C_CROSSING = cython.declare(cython.int, KIND_CROSSING)
_C_TANGENT = cython.declare(cython.int, KIND_TANGENT)
_C_OVERLAP = cython.declare(cython.int, KIND_OVERLAP)
_C_UNRESOLVED = cython.declare(cython.int, KIND_UNRESOLVED)
_INF = cython.declare(cython.double, math.inf)
# the exponent of _sq: a variable, so that the C compiler cannot turn pow(x, 2) into x * x
_TWO = cython.declare(cython.double, 2.0)
# numpy's min / max of up to this many values let a later equal value win (seen on -0.0 / 0.0)
_NP_MINMAX_SCALAR = cython.declare(cython.Py_ssize_t, 16)
# the model's own frame is taken only when its projection is this well conditioned (see _frame0)
_FRAME0_KAPPA = cython.declare(cython.double, 32.0)


@cython.cfunc
@cython.inline
@cython.exceptval(check=False)
def _sq(x: cython.double) -> cython.double:
    """``x ** 2`` as numpy computes it on a scalar: libm ``pow(x, 2.0)``."""
    return c_pow(x, _TWO)


@cython.cfunc
@cython.exceptval(check=False)
def _space_eval(
    H: cython.const[cython.double][:, :],
    t: cython.double,
    wk: cython.double[:, ::1],
    p: cython.double[:],
    d: cython.double[:],
) -> cython.void:
    """Point ``p`` and derivative ``d`` of homogeneous curve ``H`` at ``t`` (de Casteljau)."""
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    r: cython.Py_ssize_t
    n: cython.Py_ssize_t = H.shape[0] - 1
    for i in range(n + 1):
        for j in range(4):
            wk[i, j] = H[i, j]
    s: cython.double = 1.0 - t
    for r in range(1, n):
        for i in range(n + 1 - r):
            for j in range(4):
                wk[i, j] = s * wk[i, j] + t * wk[i + 1, j]
    w: cython.double = s * wk[0, 3] + t * wk[1, 3]
    dw: cython.double = n * (wk[1, 3] - wk[0, 3])
    for j in range(3):
        p[j] = (s * wk[0, j] + t * wk[1, j]) / w
        d[j] = (n * (wk[1, j] - wk[0, j]) - p[j] * dw) / w


@cython.cfunc
@cython.exceptval(check=False)
def _space_dist2(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wka: cython.double[:, ::1],
    wkb: cython.double[:, ::1],
    pa: cython.double[:],
    da: cython.double[:],
    pb: cython.double[:],
    db: cython.double[:],
) -> cython.double:
    j: cython.Py_ssize_t
    _space_eval(HA, t, wka, pa, da)
    _space_eval(HB, u, wkb, pb, db)
    f: cython.double = 0.0
    for j in range(3):
        f += (pa[j] - pb[j]) ** 2  # C doubles: as compiled before (not _sq)
    return f


@cython.cfunc
@cython.exceptval(check=False)
def _space_polish(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    fix_t: cython.bint,
    fix_u: cython.bint,
    wka: cython.double[:, ::1],
    wkb: cython.double[:, ::1],
    vec: cython.double[:, ::1],
) -> tuple[cython.double, cython.double, cython.double]:
    """Minimise |a(t) - b(u)| locally: Gauss-Newton with Levenberg damping, in [0, 1]^2.

    ``vec``: scratch, 8 rows of 3.
    """
    j: cython.Py_ssize_t
    _it: cython.int
    _attempt: cython.int
    pa: cython.double[:] = vec[0]
    da: cython.double[:] = vec[1]
    pb: cython.double[:] = vec[2]
    db: cython.double[:] = vec[3]
    qa: cython.double[:] = vec[4]
    qda: cython.double[:] = vec[5]
    qb: cython.double[:] = vec[6]
    qdb: cython.double[:] = vec[7]
    a11: cython.double
    a12: cython.double
    a22: cython.double
    g1: cython.double
    g2: cython.double
    r: cython.double
    dt: cython.double
    du: cython.double
    m11: cython.double
    m22: cython.double
    det: cython.double
    nt: cython.double
    nu: cython.double
    nf: cython.double
    moved: cython.double
    accepted: cython.bint
    f: cython.double = _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
    if fix_t and fix_u:
        return t, u, sqrt(f)
    lam: cython.double = 0.0
    for _it in range(80):
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
        if not accepted or f == 0.0 or moved <= 2.0 * _C_EPS:
            break
    return t, u, sqrt(f)


@cython.cfunc
@cython.exceptval(check=False)
def _space_sin_angle(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wka: cython.double[:, ::1],
    wkb: cython.double[:, ::1],
    vec: cython.double[:, ::1],
) -> cython.double:
    """Sine of the angle between the tangents at ``a(t)`` and ``b(u)``; ``vec``: scratch, 4 rows of 3."""
    da: cython.double[:] = vec[1]
    db: cython.double[:] = vec[3]
    _space_dist2(HA, HB, t, u, wka, wkb, vec[0], da, vec[2], db)
    cx: cython.double = da[1] * db[2] - da[2] * db[1]
    cy: cython.double = da[2] * db[0] - da[0] * db[2]
    cz: cython.double = da[0] * db[1] - da[1] * db[0]
    na: cython.double = sqrt(_sq(da[0]) + _sq(da[1]) + _sq(da[2]))
    nb: cython.double = sqrt(_sq(db[0]) + _sq(db[1]) + _sq(db[2]))
    if na == 0.0 or nb == 0.0:
        return 0.0
    return sqrt(cx * cx + cy * cy + cz * cz) / (na * nb)


@cython.cfunc
@cython.exceptval(check=False)
def _space_closest_on(
    HB: cython.const[cython.double][:, :],
    p: cython.double[:],
    u: cython.double,
    lo: cython.double,
    hi: cython.double,
    wkb: cython.double[:, ::1],
    q: cython.double[:],
    dq: cython.double[:],
) -> cython.double:
    """Gap from ``p`` to ``b`` near ``u`` (Gauss-Newton in ``u``, kept in [lo, hi]).

    ``q``, ``dq``: scratch.
    """
    j: cython.Py_ssize_t
    _it: cython.int
    g: cython.double
    hh: cython.double
    nu: cython.double
    for _it in range(40):
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
    return sqrt(_sq(q[0] - p[0]) + _sq(q[1] - p[1]) + _sq(q[2] - p[2]))


@cython.cfunc
@cython.exceptval(check=False)
def _space_overlap_real(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t0: cython.double,
    u0: cython.double,
    t1: cython.double,
    u1: cython.double,
    tol: cython.double,
    wka: cython.double[:, ::1],
    wkb: cython.double[:, ::1],
    vec: cython.double[:, ::1],
) -> cython.bint:
    """True when the curves stay within ``tol`` from ``(t0, u0)`` to ``(t1, u1)``.

    Both ends, and ``a``'s samples between from ``b`` between ``u0`` and ``u1``. A planar overlap
    that is one in space too; two tangent finds that are one touch. ``vec``: scratch, 6 rows of 3.
    """
    i: cython.Py_ssize_t
    s: cython.double
    pa: cython.double[:] = vec[0]
    da: cython.double[:] = vec[1]
    pb: cython.double[:] = vec[2]
    db: cython.double[:] = vec[3]
    if sqrt(_space_dist2(HA, HB, t0, u0, wka, wkb, pa, da, pb, db)) > tol:
        return False
    if sqrt(_space_dist2(HA, HB, t1, u1, wka, wkb, pa, da, pb, db)) > tol:
        return False
    lo: cython.double = min(u0, u1)
    hi: cython.double = max(u0, u1)
    for i in range(1, _C_SAMPLES - 1):
        s = cython.cast(cython.double, i) / (_C_SAMPLES - 1.0)
        _space_eval(HA, t0 + s * (t1 - t0), wka, pa, da)
        if _space_closest_on(HB, pa, u0 + s * (u1 - u0), lo, hi, wkb, vec[4], vec[5]) > tol:
            return False
    return True


@cython.cfunc
@cython.exceptval(check=False)
def _jacobi_eigen3(a: cython.double[:, ::1], v: cython.double[:, ::1]) -> cython.void:
    """Eigenvectors (columns of ``v``) of the symmetric 3x3 ``a`` (Jacobi rotations).

    ``a`` is diagonalised in place.
    """
    i: cython.Py_ssize_t
    p: cython.Py_ssize_t
    q: cython.Py_ssize_t
    k: cython.Py_ssize_t
    _it: cython.int
    off: cython.double
    theta: cython.double
    t: cython.double
    cs: cython.double
    sn: cython.double
    akp: cython.double
    akq: cython.double
    for i in range(3):
        for k in range(3):
            v[i, k] = 1.0 if i == k else 0.0
    for _it in range(50):
        off = abs(a[0, 1]) + abs(a[0, 2]) + abs(a[1, 2])
        if off <= 1e-300 or off <= 1e-15 * (abs(a[0, 0]) + abs(a[1, 1]) + abs(a[2, 2])):
            break
        for p in range(2):
            for q in range(p + 1, 3):
                if a[p, q] == 0.0:
                    continue
                theta = (a[q, q] - a[p, p]) / (2.0 * a[p, q])
                t = (1.0 if theta >= 0.0 else -1.0) / (abs(theta) + sqrt(theta * theta + 1.0))
                cs = 1.0 / sqrt(t * t + 1.0)
                sn = t * cs
                for k in range(3):
                    akp = a[k, p]
                    akq = a[k, q]
                    a[k, p] = cs * akp - sn * akq
                    a[k, q] = sn * akp + cs * akq
                for k in range(3):
                    akp = a[p, k]  # a[p, k], a[q, k]
                    akq = a[q, k]
                    a[p, k] = cs * akp - sn * akq
                    a[q, k] = sn * akp + cs * akq
                for k in range(3):
                    akp = v[k, p]  # v[k, p], v[k, q]
                    akq = v[k, q]
                    v[k, p] = cs * akp - sn * akq
                    v[k, q] = sn * akp + cs * akq


@cython.cfunc
def _eigen_order(a: cython.double[:, ::1]) -> tuple[cython.Py_ssize_t, cython.Py_ssize_t]:
    """Indices of the smallest and the second-smallest diagonal entry of ``a`` (np.argsort's order)."""
    x0: cython.double = a[0, 0]
    x1: cython.double = a[1, 1]
    x2: cython.double = a[2, 2]
    i0: cython.Py_ssize_t
    i2: cython.Py_ssize_t
    if x0 != x1 and x0 != x2 and x1 != x2 and x0 == x0 and x1 == x1 and x2 == x2:
        # distinct numbers: one order only
        i0 = 0 if x0 < x1 and x0 < x2 else (1 if x1 < x2 else 2)
        i2 = 0 if x0 > x1 and x0 > x2 else (1 if x1 > x2 else 2)
        return i0, 3 - i0 - i2
    order = np.argsort(np.array([x0, x1, x2]))  # ties: numpy's own order
    return int(order[0]), int(order[1])


@cython.cfunc
def _space_direction_frame(
    P: cython.const[cython.double][:, :],
    d0: cython.double,
    d1: cython.double,
    d2: cython.double,
    M: cython.double[:, :],
    fw: cython.double[:, ::1],
) -> cython.double:
    """Frame looking along ``d`` from a centre placed so every point of ``P`` is well in front.

    ``fw``: scratch, 7 rows of 3.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    m: cython.Py_ssize_t = P.shape[0]
    dd: cython.double[:] = fw[0]
    centre: cython.double[:] = fw[1]
    origin: cython.double[:] = fw[2]
    helper: cython.double[:] = fw[3]
    e1: cython.double[:] = fw[4]
    e2: cython.double[:] = fw[5]
    lo: cython.double
    hi: cython.double
    r2: cython.double
    dep: cython.double
    nd: cython.double = sqrt(_sq(d0) + _sq(d1) + _sq(d2))
    dd[0] = d0 / nd
    dd[1] = d1 / nd
    dd[2] = d2 / nd
    for j in range(3):
        # numpy's P[:, j].min() / .max(), including which of -0.0 / 0.0 it returns
        if m <= _NP_MINMAX_SCALAR:
            lo = P[0, j]
            hi = P[0, j]
            for i in range(1, m):
                if P[i, j] <= lo:
                    lo = P[i, j]
                if P[i, j] >= hi:
                    hi = P[i, j]
        else:
            lo = np.asarray(P)[:, j].min()
            hi = np.asarray(P)[:, j].max()
        centre[j] = 0.5 * (lo + hi)
    radius: cython.double = 0.0
    spread: cython.double = 0.0
    for i in range(m):
        r2 = 0.0
        dep = 0.0
        for j in range(3):
            r2 += _sq(P[i, j] - centre[j])
            dep += (P[i, j] - centre[j]) * dd[j]
        radius = max(radius, sqrt(r2))
        spread = max(spread, abs(dep))
    if radius == 0.0:
        radius = 1.0
    dist: cython.double = spread + 2.0 * radius
    for j in range(3):
        origin[j] = centre[j] - dist * dd[j]
        helper[j] = 0.0
    helper[0 if abs(dd[0]) < 0.8 else 1] = 1.0
    _cross(helper, dd, e1)
    ne1: cython.double = sqrt(_sq(e1[0]) + _sq(e1[1]) + _sq(e1[2]))
    for j in range(3):
        e1[j] = e1[j] / ne1
    _cross(dd, e1, e2)
    for j in range(3):
        M[0, j] = e1[j] / radius
        M[1, j] = e2[j] / radius
        M[2, j] = dd[j] / radius
        M[3, j] = 0.0
    for i in range(3):
        M[i, 3] = -(M[i, 0] * origin[0] + M[i, 1] * origin[1] + M[i, 2] * origin[2])
    M[3, 3] = 1.0
    return radius


@cython.cfunc
@cython.exceptval(check=False)
def _cross(a: cython.double[:], b: cython.double[:], out: cython.double[:]) -> cython.void:
    """``out = a x b`` with np.cross's operations."""
    out[0] = a[1] * b[2] - a[2] * b[1]
    out[1] = a[2] * b[0] - a[0] * b[2]
    out[2] = a[0] * b[1] - a[1] * b[0]


@cython.cfunc
@cython.exceptval(check=False)
def _frame0(P: cython.const[cython.double][:, :], ref: cython.const[cython.double][:]) -> cython.bint:
    """True when the model's own frame (eye at the origin, looking along z) suits the points ``P + ref``.

    Every point in front (z > 1e-3 of the largest coordinate), and the projection well conditioned:
    ``sqrt(1 + r^2) zmax / zmin <= 32``, ``r`` the largest ``|(x, y)| / z``, bounds the ratio of its
    largest to its least magnification over the points. The planar tolerance is the 3D one times the
    largest (the Lipschitz bound), while the curves' planar distances shrink by the least: an
    ill-conditioned frame (ratio 1,500: points at depths 0.025 to 0.97, 37 times off axis) made the
    planar tolerance so wide that a crossing and a touch 0.036 apart became one contact and the touch
    was lost. The paper's curves give 6 to 25; modes 1-3 about 2 to 4.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    x: cython.double
    y: cython.double
    z: cython.double
    zmin: cython.double = _INF
    zmax: cython.double = -_INF
    big: cython.double = 0.0
    r2: cython.double = 0.0
    for i in range(P.shape[0]):
        x = P[i, 0] + ref[0]
        y = P[i, 1] + ref[1]
        z = P[i, 2] + ref[2]
        zmin = min(zmin, z)
        zmax = max(zmax, z)
        for j in range(3):
            big = max(big, abs(P[i, j] + ref[j]))
        if z > 0.0:
            r2 = max(r2, (_sq(x) + _sq(y)) / _sq(z))
    if not (zmin > 1e-3 * big and zmax < 100.0 * zmin):
        return False
    return sqrt(1.0 + r2) * zmax <= _FRAME0_KAPPA * zmin


@cython.cfunc
def _space_frame_work(
    mode: cython.int,
    P: cython.const[cython.double][:, :],
    ref: cython.const[cython.double][:],
    M: cython.double[:, :],
    fw: cython.double[:, ::1],
) -> cython.double:
    """:func:`_space_frame` with scratch ``fw`` (16 rows of 3)."""
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    k: cython.Py_ssize_t
    m: cython.Py_ssize_t = P.shape[0]
    if mode == 0:
        if not _frame0(P, ref):
            return 0.0
        for i in range(4):
            for j in range(4):
                M[i, j] = 1.0 if i == j else 0.0
        for j in range(3):
            M[j, 3] = ref[j]
        return 1.0
    cov: cython.double[:, ::1] = fw[0:3]
    vecs: cython.double[:, ::1] = fw[3:6]
    mean: cython.double[:] = fw[6]
    for j in range(3):
        mean[j] = 0.0
    for i in range(m):
        for j in range(3):
            mean[j] += P[i, j]
    for j in range(3):
        mean[j] /= cython.cast(cython.double, m)
    for j in range(3):
        for k in range(3):
            cov[j, k] = 0.0
    for i in range(m):
        for j in range(3):
            for k in range(3):
                cov[j, k] += (P[i, j] - mean[j]) * (P[i, k] - mean[k])
    _jacobi_eigen3(cov, vecs)
    o0: cython.Py_ssize_t
    o1: cython.Py_ssize_t
    o0, o1 = _eigen_order(cov)
    if mode == 1:
        return _space_direction_frame(P, vecs[0, o0], vecs[1, o0], vecs[2, o0], M, fw[7:])
    if mode == 2:
        return _space_direction_frame(
            P,
            vecs[0, o0] + 0.6 * vecs[0, o1],
            vecs[1, o0] + 0.6 * vecs[1, o1],
            vecs[2, o0] + 0.6 * vecs[2, o1],
            M,
            fw[7:],
        )
    return _space_direction_frame(P, 0.3, -0.5, 0.81, M, fw[7:])


@cython.ccall
def _space_frame(
    mode: cython.int,
    P: cython.const[cython.double][:, :],
    ref: cython.const[cython.double][:],
    M: cython.double[:, :],
) -> cython.double:
    """Fill ``M`` (local -> frame coordinates) for frame ``mode``; return its scale, or 0 if unusable.

    Mode 0 is the model's own frame (centre at the model origin), usable when every control
    point lies in front of it (z > 0) with moderate depth ratio: the paper's frame for its
    curves. Modes 1-3 look along the least-variance axis, a tilted axis, a fixed oblique axis.
    """
    return _space_frame_work(mode, P, ref, M, np.empty((16, 3)))


@cython.ccall
@cython.exceptval(check=False)
def _space_project(
    H: cython.const[cython.double][:, :],
    M: cython.double[:, :],
    k: cython.double,
    P2: cython.double[:, :],
    W2: cython.double[:],
) -> cython.bint:
    """psi(phi(M H)): the planar image of a curve, as Cartesian points and weights. False if behind O."""
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    n: cython.Py_ssize_t = H.shape[0]
    x: cython.double
    y: cython.double
    z: cython.double
    w: cython.double
    rx: cython.double
    ry: cython.double
    rz: cython.double
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


@cython.cfunc
@cython.exceptval(check=False)
def _lipschitz_scan(
    H: cython.const[cython.double][:, :],
    P2: cython.double[:, :],
    M: cython.double[:, :],
    zmin: cython.double,
    r2: cython.double,
) -> tuple[cython.double, cython.double]:
    """Update the least depth ``zmin`` and the largest squared image radius ``r2`` with one curve."""
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    w: cython.double
    z: cython.double
    for i in range(H.shape[0]):
        w = H[i, 3]
        z = 0.0
        for j in range(4):
            z += M[2, j] * H[i, j]
        zmin = min(zmin, z / w)
        r2 = max(r2, _sq(P2[i, 0]) + _sq(P2[i, 1]))
    return zmin, r2


@cython.cfunc
@cython.exceptval(check=False)
def _space_lipschitz(
    P2a: cython.double[:, :],
    P2b: cython.double[:, :],
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    M: cython.double[:, :],
) -> cython.double:
    """Bound of |D psi| over the hull of both curves' control points in frame coordinates."""
    zmin: cython.double = _INF
    r2: cython.double = 0.0
    zmin, r2 = _lipschitz_scan(HA, P2a, M, zmin, r2)
    zmin, r2 = _lipschitz_scan(HB, P2b, M, zmin, r2)
    return sqrt(1.0 + r2) / zmin


@cython.cfunc
def _space_add(
    out: object,
    n: cython.Py_ssize_t,
    kind: cython.double,
    t: cython.double,
    u: cython.double,
    t1: cython.double,
    u1: cython.double,
    x: cython.double,
    y: cython.double,
    z: cython.double,
    dist: cython.double,
) -> object:
    """Write row ``n`` of ``out`` (grown when full); return ``out``."""
    if n >= out.shape[0]:
        bigger = np.empty((2 * out.shape[0] + 4, SPACE_COLS))
        bigger[:n] = out[:n]
        out = bigger
    ov: cython.double[:, ::1] = out
    ov[n, 0] = kind
    ov[n, 1] = t
    ov[n, 2] = u
    ov[n, 3] = t1
    ov[n, 4] = u1
    ov[n, 5] = x
    ov[n, 6] = y
    ov[n, 7] = z
    ov[n, 8] = dist
    return out


@cython.cfunc
@cython.exceptval(check=False)
def _half_into(
    S: cython.double[:, :, ::1],
    src: cython.Py_ssize_t,
    r0: cython.Py_ssize_t,
    n: cython.Py_ssize_t,
    left: cython.Py_ssize_t,
    right: cython.Py_ssize_t,
    wk: cython.double[:, ::1],
) -> cython.void:
    """Halve the curve in rows ``r0 : r0 + n`` of slot ``src`` into those rows of slots ``left``, ``right``.

    de Casteljau at t = 1/2 on homogeneous rows (``wk``: n rows of scratch); ``src`` may be
    ``left`` or ``right`` (its rows are read into ``wk`` first). Indices, not slices: a slice of a
    typed view costs two atomic updates of its buffer count.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    r: cython.Py_ssize_t
    m: cython.Py_ssize_t = n - 1
    for i in range(n):
        for j in range(4):
            wk[i, j] = S[src, r0 + i, j]
    for j in range(4):
        S[left, r0, j] = wk[0, j]
        S[right, r0 + m, j] = wk[m, j]
    for r in range(1, m + 1):
        for i in range(m + 1 - r):
            for j in range(4):
                wk[i, j] = 0.5 * (wk[i, j] + wk[i + 1, j])
        for j in range(4):
            S[left, r0 + r, j] = wk[0, j]
            S[right, r0 + m - r, j] = wk[m - r, j]


@cython.cfunc
@cython.exceptval(check=False)
def _hulls_apart(
    S: cython.double[:, :, ::1],
    s: cython.Py_ssize_t,
    na: cython.Py_ssize_t,
    nb: cython.Py_ssize_t,
    tol: cython.double,
    P: cython.double[:, ::1],
) -> cython.bint:
    """True when slot ``s``'s control polygons (a: rows ``:na``, b: the next ``nb``) are over ``tol`` apart.

    By the convex hull property the curves then do too. Two tests: the boxes (apart by more than
    ``tol`` along x, y or z), then the extents along the line through the two polygons' centroids
    (apart by more than ``tol`` times its length ``|d|``), which separates curves that pass each
    other obliquely long before their boxes do. ``P``: na + nb + 1 rows of scratch (the Cartesian
    points, then d).
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    lo_a: cython.double
    hi_a: cython.double
    lo_b: cython.double
    hi_b: cython.double
    m: cython.Py_ssize_t = na + nb  # row m of P: the direction d from a's centroid to b's
    dd: cython.double = 0.0
    for i in range(m):
        for j in range(3):
            P[i, j] = S[s, i, j] / S[s, i, 3]
    for j in range(3):
        lo_a = _INF
        hi_a = -_INF
        lo_b = _INF
        hi_b = -_INF
        P[m, j] = 0.0
        for i in range(na):
            lo_a = min(lo_a, P[i, j])
            hi_a = max(hi_a, P[i, j])
            P[m, j] -= P[i, j] / na
        for i in range(na, m):
            lo_b = min(lo_b, P[i, j])
            hi_b = max(hi_b, P[i, j])
            P[m, j] += P[i, j] / nb
        if lo_a > hi_b + tol or lo_b > hi_a + tol:
            return True
        dd += P[m, j] * P[m, j]
    if not dd > 0.0:
        return False
    hi_a = -_INF
    lo_b = _INF
    for i in range(na):
        hi_a = max(hi_a, P[i, 0] * P[m, 0] + P[i, 1] * P[m, 1] + P[i, 2] * P[m, 2])
    for i in range(na, m):
        lo_b = min(lo_b, P[i, 0] * P[m, 0] + P[i, 1] * P[m, 1] + P[i, 2] * P[m, 2])
    return lo_b - hi_a > tol * sqrt(dd)


@cython.cfunc
@cython.exceptval(check=False)
def _space_separated(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    tol: cython.double,
    max_depth: cython.int,
    stack: cython.double[:, :, ::1],
    depth: cython.int[::1],
    work: cython.double[:, ::1],
) -> cython.bint:
    """True when the hulls of sub-curves (halving both, depth <= max_depth) prove a gap wider than tol.

    A cheap pre-pass before the relief scheme: two space curves that stay apart need no
    projection at all (their projections may well cross). False means "not proven apart".
    Depth first: a pair that meets reaches the depth limit after a few dozen tests.
    Scratch: ``stack`` (4 max_depth + 8, na + nb, 4), a pair of sub-curves per slot;
    ``depth`` (4 max_depth + 8); ``work`` (na + nb + 1 + max(na, nb) rows of at least 4).
    """
    na: cython.Py_ssize_t = HA.shape[0]
    nb: cython.Py_ssize_t = HB.shape[0]
    size: cython.Py_ssize_t = 4 * max_depth + 8
    pts: cython.double[:, ::1] = work[0 : na + nb + 1]
    wk: cython.double[:, ::1] = work[na + nb + 1 :]
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    q: cython.Py_ssize_t
    d: cython.int
    # slot 0: both curves in local coordinates, a's first point at the origin (as _space_pair
    # makes them), so that the boxes and the products along d are not rounded at the size of an
    # offset far larger than the curves
    for j in range(3):
        pts[na + nb, j] = HA[0, j] / HA[0, 3]
    for i in range(na):
        for j in range(3):
            stack[0, i, j] = (HA[i, j] / HA[i, 3] - pts[na + nb, j]) * HA[i, 3]
        stack[0, i, 3] = HA[i, 3]
    for i in range(nb):
        for j in range(3):
            stack[0, na + i, j] = (HB[i, j] / HB[i, 3] - pts[na + nb, j]) * HB[i, 3]
        stack[0, na + i, 3] = HB[i, 3]
    depth[0] = 0
    top: cython.Py_ssize_t = 1
    while top > 0:
        top -= 1
        d = depth[top]
        if _hulls_apart(stack, top, na, nb, tol, pts):
            continue
        if d >= max_depth or top + 4 > size:
            return False
        # slots top .. top + 3 get (a left, b left), (a left, b right), (a right, b left), (a right, b right)
        _half_into(stack, top, 0, na, top, top + 2, wk)
        _half_into(stack, top, na, nb, top, top + 1, wk)
        for i in range(na):
            for j in range(4):
                stack[top + 1, i, j] = stack[top, i, j]
                stack[top + 3, i, j] = stack[top + 2, i, j]
        for i in range(na, na + nb):
            for j in range(4):
                stack[top + 2, i, j] = stack[top, i, j]
                stack[top + 3, i, j] = stack[top + 1, i, j]
        for q in range(4):
            depth[top + q] = d + 1
        top += 4
    return True


@cython.cfunc
@cython.exceptval(check=False)
def _abs_max(P: cython.double[:, ::1]) -> cython.double:
    """``np.abs(P).max()`` (finite data)."""
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    big: cython.double = abs(P[0, 0])
    for i in range(P.shape[0]):
        for j in range(P.shape[1]):
            big = max(big, abs(P[i, j]))
    return big


# the scratch arrays of one call of the space kernel for curves of (na, nb) control points, as this
# module's typed views (a numpy array passed to a typed view is converted on every call), kept for
# the next call of that size (allocating them cost about a microsecond); a call takes them out
# while it runs, so a call made meanwhile (another thread: the planar driver runs without the GIL)
# makes its own. At most _SPARE_SIZES sizes are kept.
_spare: dict = {}
_SPARE_SIZES = 32
_SEP_DEPTH = cython.declare(cython.int, 6)  # the separation pre-pass halves both curves this often
# the safe range of relief_cad.contacts.range_exponent: largest |w x| in [2**-101, 2**100), or 0
_SAFE_LO = cython.declare(cython.double, math.ldexp(1.0, -SAFE_EXPONENT - 1))
_SAFE_HI = cython.declare(cython.double, math.ldexp(1.0, SAFE_EXPONENT))


def _views(allp: cython.double[:, ::1], ws: cython.double[:, ::1], stack: cython.double[:, :, ::1],
           depth: cython.int[::1]):
    """The scratch arrays as this module's own typed views (compiled; as given uncompiled)."""
    return allp, ws, stack, depth


@cython.cfunc
def _run(HA0: cython.const[cython.double][:, :], HB0: cython.const[cython.double][:, :], tol: cython.double,
         budget, k: cython.double, ends_lim: cython.double):
    """:func:`_space_pair` in the kept scratch arrays of this size (see ``_spare``)."""
    na: cython.Py_ssize_t = HA0.shape[0]
    nb: cython.Py_ssize_t = HB0.shape[0]
    bufs = _spare.pop((na, nb), None)
    if bufs is None:
        slots: cython.Py_ssize_t = 4 * _SEP_DEPTH + 8
        bufs = _views(np.empty((na + nb, 3)), np.empty((2 * na + 2 * nb + 37, 4)),
                      np.empty((slots, na + nb, 4)), np.empty(slots, dtype=np.intc))
    try:
        return _space_pair(HA0, HB0, tol, budget, k, ends_lim, bufs[0], bufs[1], bufs[2], bufs[3])
    finally:
        if len(_spare) < _SPARE_SIZES:
            _spare[(na, nb)] = bufs


def space_pair_kernel(
    HA0: cython.const[cython.double][:, :],
    HB0: cython.const[cython.double][:, :],
    tol: cython.double,
    budget,
    k: cython.double,
):
    """Intersect two space rational curves by the relief scheme.

    ``HA0``, ``HB0``: homogeneous rows ``(w x, w y, w z, w)`` in model coordinates; ``tol`` a
    distance in model units (> 0: resolved by the caller, relief_cad.tolerances); ``budget``
    the planar clipping budget; ``k`` the span of the relief perspective. Returns ``(rows, nrows, status)``.
    """
    return _run(HA0, HB0, tol, budget, k, -1.0)


def space_pair_rows(
    HA0: cython.const[cython.double][:, :],
    HB0: cython.const[cython.double][:, :],
    tol: cython.double,
    budget,
    ends_lim: cython.double,
):
    """The rows of :func:`space_pair_kernel` (k = 2) for a pair that needs nothing else, or None.

    The common case in one call. None when the pair needs the caller's general path: it is not
    proven apart and its end points match within ``ends_lim`` per coordinate either way round
    (curves that may coincide all along: relief_cad.contacts.whole_overlap decides first; a pair
    proven apart cannot coincide), its coordinates lie outside the safe range (the caller scales
    them by a power of two), or every frame showed an artefact.
    """
    if not _in_safe_range(HA0, HB0):
        return None
    rows, n, status = _run(HA0, HB0, tol, budget, 2.0, ends_lim)
    if status != STATUS_OK:
        return None
    return rows[:n] if n else _NO_SPACE_ROWS


@cython.cfunc
@cython.exceptval(check=False)
def _in_safe_range(
    HA: cython.const[cython.double][:, :], HB: cython.const[cython.double][:, :]
) -> cython.bint:
    """True when relief_cad.contacts.range_exponent of the largest |w x|, |w y|, |w z| is 0."""
    i: cython.Py_ssize_t
    c: cython.Py_ssize_t
    big: cython.double = 0.0
    for i in range(HA.shape[0]):
        for c in range(3):
            big = max(big, abs(HA[i, c]))
    for i in range(HB.shape[0]):
        for c in range(3):
            big = max(big, abs(HB[i, c]))
    return big == 0.0 or _SAFE_LO <= big < _SAFE_HI


@cython.cfunc
def _space_pair(
    HA0: cython.const[cython.double][:, :],
    HB0: cython.const[cython.double][:, :],
    tol: cython.double,
    budget,
    k: cython.double,
    ends_lim: cython.double,
    allp: cython.double[:, ::1],
    ws: cython.double[:, ::1],
    stack: cython.double[:, :, ::1],
    depth: cython.int[::1],
):
    """:func:`space_pair_kernel` in the given scratch arrays (their contents are overwritten).

    ``allp`` (na + nb, 3): the local Cartesian points; ``ws`` (2 na + 2 nb + 37, 4):
    the work of the pre-pass, then the curves, de Casteljau's rows and the frame; ``stack`` and
    ``depth`` the pre-pass's slots (:func:`_space_separated`).

    Not one screen: the frames, the planar driver's rows and their classification in space share
    the scratch views and counters.
    """
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    q: cython.Py_ssize_t
    r: cython.Py_ssize_t
    e: cython.Py_ssize_t
    mode: cython.int
    kind: cython.int
    ckind: cython.int
    na: cython.Py_ssize_t = HA0.shape[0]
    nb: cython.Py_ssize_t = HB0.shape[0]
    # most pairs whose boxes overlap stay apart: proven first, before any other work
    if _space_separated(HA0, HB0, tol, _SEP_DEPTH, stack, depth, ws):
        return _NO_SPACE_ROWS, 0, STATUS_OK
    # allp holds the local Cartesian points of a (rows :na) and of b (rows na:)
    PA: cython.double[:, ::1] = allp[:na]
    PB: cython.double[:, ::1] = allp[na:]
    for i in range(na):
        for j in range(3):
            PA[i, j] = HA0[i, j] / HA0[i, 3]
    for i in range(nb):
        for j in range(3):
            PB[i, j] = HB0[i, j] / HB0[i, 3]
    if ends_lim >= 0.0 and _ends_match(PA, PB, ends_lim):
        return _NO_SPACE_ROWS, 0, STATUS_ENDS_MATCH
    big0: cython.double = max(_abs_max(PA), _abs_max(PB))
    # one scratch array of 4 columns for the rest of the call, cut into blocks of rows: the local
    # curves, de Casteljau's rows, the frame, 3-vectors, the frame's work
    HA: cython.double[:, ::1] = ws[0:na]
    HB: cython.double[:, ::1] = ws[na : na + nb]
    o: cython.Py_ssize_t = na + nb
    wka: cython.double[:, ::1] = ws[o : o + na]
    wkb: cython.double[:, ::1] = ws[o + na : o + na + nb]
    o += na + nb
    M: cython.double[:, ::1] = ws[o : o + 4]
    ref: cython.double[:] = ws[o + 4, 0:3]
    vec: cython.double[:, ::1] = ws[o + 5 : o + 21]
    fw: cython.double[:, ::1] = ws[o + 21 : o + 37]
    for j in range(3):
        ref[j] = PA[0, j]
    # local coordinates: an exact shift for nearby values (Sterbenz), parameters unchanged
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
    big: cython.double = _abs_max(allp)
    meet: cython.double = max(1e3 * _C_EPS * big, 16.0 * _C_EPS * big0, 1e-3 * tol)
    out = np.empty((8, SPACE_COLS))
    ov: cython.double[:, ::1] = out
    # points and derivatives on the curves (rows of vec), then the planar images, which the planar
    # driver takes as they are
    pa: cython.double[:] = vec[8]
    da: cython.double[:] = vec[9]
    pb: cython.double[:] = vec[10]
    db: cython.double[:] = vec[11]
    qe: cython.double[:] = vec[12]
    dqe: cython.double[:] = vec[13]
    P2a_arr = np.empty((na, 2))
    W2a_arr = np.empty(na)
    P2b_arr = np.empty((nb, 2))
    W2b_arr = np.empty(nb)
    P2a: cython.double[:, ::1] = P2a_arr
    W2a: cython.double[::1] = W2a_arr
    P2b: cython.double[:, ::1] = P2b_arr
    W2b: cython.double[::1] = W2b_arr
    rv: cython.double[:, :]
    nres: cython.Py_ssize_t
    nout: cython.Py_ssize_t = 0
    scale: cython.double
    ptol: cython.double
    artefact: cython.bint
    fix_t: cython.bint
    fix_u: cython.bint
    inside: cython.bint
    t: cython.double
    u: cython.double
    gap: cython.double
    end: cython.double
    te: cython.double
    gap_e: cython.double
    lo_u: cython.double
    hi_u: cython.double
    near: cython.double
    dup: cython.Py_ssize_t
    for mode in range(_SPACE_N_FRAMES):
        scale = _space_frame_work(mode, allp, ref, M, fw)
        if scale == 0.0:
            continue
        if not _space_project(HA, M, k, P2a, W2a) or not _space_project(HB, M, k, P2b, W2b):
            continue
        ptol = _space_lipschitz(P2a, P2b, HA, HB, M) * (tol / scale) * (1.0 + 1e-6)
        res = np.empty((16, RES_COLS))
        res, nres = intersect_pair_kernel(P2a, W2a, P2b, W2b, ptol, budget, 0, res, 0)
        rv = res
        artefact = False
        nout = 0
        for r in range(nres):
            kind = cython.cast(cython.int, rv[r, 1])
            if kind == _C_OVERLAP:
                if _space_overlap_real(HA, HB, rv[r, 2], rv[r, 3], rv[r, 4], rv[r, 5], tol, wka, wkb, vec):
                    out = _space_add(
                        out, nout, _C_OVERLAP, rv[r, 2], rv[r, 3], rv[r, 4], rv[r, 5], 0.0, 0.0, 0.0, 0.0
                    )
                    nout += 1
                else:
                    artefact = True
                    break
            elif kind == _C_UNRESOLVED:
                out = _space_add(
                    out, nout, _C_UNRESOLVED, rv[r, 2], rv[r, 3], rv[r, 4], rv[r, 5], 0.0, 0.0, 0.0, 0.0
                )
                nout += 1
        if artefact:
            continue
        ov = out
        for r in range(nres):
            kind = cython.cast(cython.int, rv[r, 1])
            if kind != _C_CROSSING and kind != _C_TANGENT:
                continue
            t = rv[r, 2]
            u = rv[r, 3]
            fix_t = False
            fix_u = False
            for e in range(2):
                end = cython.cast(cython.double, e)  # 0.0, then 1.0
                if t == end or abs(t - end) < 1e-9:
                    if sqrt(_space_dist2(HA, HB, end, u, wka, wkb, pa, da, pb, db)) <= tol:
                        t = end
                        fix_t = True
                if u == end or abs(u - end) < 1e-9:
                    if sqrt(_space_dist2(HA, HB, t, end, wka, wkb, pa, da, pb, db)) <= tol:
                        u = end
                        fix_u = True
            t, u, gap = _space_polish(HA, HB, t, u, fix_t, fix_u, wka, wkb, vec)
            if gap > tol:
                continue
            # a point inside an overlap, or at the place where one ends (a closed curve returns to
            # it with another parameter), is part of that overlap
            inside = False
            _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
            for q in range(nout):
                if ov[q, 0] == _C_OVERLAP:
                    lo_u = min(ov[q, 2], ov[q, 4])
                    hi_u = max(ov[q, 2], ov[q, 4])
                    if ov[q, 1] - 1e-9 <= t <= ov[q, 3] + 1e-9 and lo_u - 1e-9 <= u <= hi_u + 1e-9:
                        inside = True
                    for e in range(2):
                        te = ov[q, 1 + 2 * e]  # t0, then t1
                        _space_eval(HA, te, wka, qe, dqe)
                        gap_e = 0.0
                        for j in range(3):
                            gap_e += _sq(qe[j] - pa[j])
                        if sqrt(gap_e) <= tol:
                            inside = True
            if inside:
                continue
            ckind = _C_TANGENT
            if gap <= meet and _space_sin_angle(HA, HB, t, u, wka, wkb, vec) > _C_TANGENT_SIN:
                ckind = _C_CROSSING
            # merge repeated finds of one contact (tangent finds agree only to ~sqrt(eps), and a
            # touch's finds polished from far-apart planar rows spread over 3e-6): tangent finds
            # within 1e-3 with the curves within tol all along between them (the planar rule);
            # other finds within 1e-10, or within 1e-6 with no gap above `meet` between them (a
            # crossing at 1e-6 rad is found twice 1e-10 apart, both at 1e-15 from the other curve)
            dup = -1
            for q in range(nout):
                if ov[q, 0] == _C_CROSSING or ov[q, 0] == _C_TANGENT:
                    near = 1e-6
                    reach = meet
                    if ckind == _C_TANGENT and ov[q, 0] == _C_TANGENT:
                        near = 1e-3
                        reach = tol
                    if abs(ov[q, 1] - t) <= near and abs(ov[q, 2] - u) <= near and (
                            (abs(ov[q, 1] - t) <= 1e-10 and abs(ov[q, 2] - u) <= 1e-10)
                            or _space_overlap_real(HA, HB, ov[q, 1], ov[q, 2], t, u, reach, wka, wkb, vec)):
                        dup = q
            _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
            if dup >= 0:
                if gap < ov[dup, 8]:
                    ov[dup, 1] = t
                    ov[dup, 2] = u
                    for j in range(3):
                        ov[dup, 5 + j] = 0.5 * (pa[j] + pb[j]) + ref[j]
                    ov[dup, 8] = gap
                continue
            out = _space_add(
                out,
                nout,
                ckind,
                t,
                u,
                t,
                u,
                0.5 * (pa[0] + pb[0]) + ref[0],
                0.5 * (pa[1] + pb[1]) + ref[1],
                0.5 * (pa[2] + pb[2]) + ref[2],
                gap,
            )
            nout += 1
            ov = out
        return out, nout, STATUS_OK
    return out, 0, STATUS_ARTEFACT

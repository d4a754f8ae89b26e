"""The relief scheme for space curves.

The paper's §3: the frame, the relief perspective φ_k, the projection ψ, the planar solve of
the images and the check back in space (depth check).

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import math

import cython
import numpy as np
from cython.cimports.libc.math import sqrt

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
    SPACE_COLS,
    STATUS_ARTEFACT,
    STATUS_OK,
)
from .planar import intersect_pair_kernel


def _space_eval(
    H: cython.const[cython.double][:, :],
    t: cython.double,
    wk: cython.double[:, :],
    p: cython.double[:],
    d: cython.double[:],
):
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


def _space_dist2(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wka: cython.double[:, :],
    wkb: cython.double[:, :],
    pa: cython.double[:],
    da: cython.double[:],
    pb: cython.double[:],
    db: cython.double[:],
):
    _space_eval(HA, t, wka, pa, da)
    _space_eval(HB, u, wkb, pb, db)
    f = 0.0
    for j in range(3):
        f += (pa[j] - pb[j]) ** 2
    return f


def _space_polish(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    fix_t: cython.bint,
    fix_u: cython.bint,
    wka: cython.double[:, :],
    wkb: cython.double[:, :],
):
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
        return t, u, sqrt(f)
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
    return t, u, sqrt(f)


def _space_sin_angle(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t: cython.double,
    u: cython.double,
    wka: cython.double[:, :],
    wkb: cython.double[:, :],
):
    pa = np.empty(3)
    da = np.empty(3)
    pb = np.empty(3)
    db = np.empty(3)
    _space_dist2(HA, HB, t, u, wka, wkb, pa, da, pb, db)
    cx = da[1] * db[2] - da[2] * db[1]
    cy = da[2] * db[0] - da[0] * db[2]
    cz = da[0] * db[1] - da[1] * db[0]
    na = sqrt(da[0] ** 2 + da[1] ** 2 + da[2] ** 2)
    nb = sqrt(db[0] ** 2 + db[1] ** 2 + db[2] ** 2)
    if na == 0.0 or nb == 0.0:
        return 0.0
    return sqrt(cx * cx + cy * cy + cz * cz) / (na * nb)


def _space_closest_on(
    HB: cython.const[cython.double][:, :],
    p: cython.double[:],
    u: cython.double,
    lo: cython.double,
    hi: cython.double,
    wkb: cython.double[:, :],
):
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
    return sqrt((q[0] - p[0]) ** 2 + (q[1] - p[1]) ** 2 + (q[2] - p[2]) ** 2)


def _space_overlap_real(
    HA: cython.const[cython.double][:, :],
    HB: cython.const[cython.double][:, :],
    t0: cython.double,
    u0: cython.double,
    t1: cython.double,
    u1: cython.double,
    tol: cython.double,
    wka: cython.double[:, :],
    wkb: cython.double[:, :],
):
    pa = np.empty(3)
    da = np.empty(3)
    pb = np.empty(3)
    db = np.empty(3)
    if sqrt(_space_dist2(HA, HB, t0, u0, wka, wkb, pa, da, pb, db)) > tol:
        return False
    if sqrt(_space_dist2(HA, HB, t1, u1, wka, wkb, pa, da, pb, db)) > tol:
        return False
    lo = min(u0, u1)
    hi = max(u0, u1)
    for i in range(1, _SPACE_OVERLAP_SAMPLES - 1):
        s = i / (_SPACE_OVERLAP_SAMPLES - 1.0)
        _space_eval(HA, t0 + s * (t1 - t0), wka, pa, da)
        if _space_closest_on(HB, pa, u0 + s * (u1 - u0), lo, hi, wkb) > tol:
            return False
    return True


def _jacobi_eigen3(c):
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
                t = (1.0 if theta >= 0.0 else -1.0) / (abs(theta) + sqrt(theta * theta + 1.0))
                cs = 1.0 / sqrt(t * t + 1.0)
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


def _space_direction_frame(P, d, M):
    """Frame looking along ``d`` from a centre placed so every point of ``P`` is well in front."""
    nd = sqrt(d[0] ** 2 + d[1] ** 2 + d[2] ** 2)
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
        radius = max(radius, sqrt(r2))
        spread = max(spread, abs(dep))
    if radius == 0.0:
        radius = 1.0
    dist = spread + 2.0 * radius
    origin = centre - dist * dd
    helper = np.array([1.0, 0.0, 0.0]) if abs(dd[0]) < 0.8 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(helper, dd)
    e1 = e1 / sqrt(e1[0] ** 2 + e1[1] ** 2 + e1[2] ** 2)
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


def _space_frame(mode, P, ref, M):
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


def _space_project(
    H: cython.const[cython.double][:, :],
    M: cython.double[:, :],
    k: cython.double,
    P2: cython.double[:, :],
    W2: cython.double[:],
):
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


def _space_lipschitz(P2a, W2a, P2b, W2b, HA, HB, M):
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
    return sqrt(1.0 + r2) / zmin


def _space_add(out, n, kind, t, u, t1, u1, x, y, z, dist):
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


def _space_half(H: cython.const[cython.double][:, :], L: cython.double[:, :], R: cython.double[:, :]):
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


def _space_box(H: cython.const[cython.double][:, :], box: cython.double[:]):
    """Box ``[lo x, lo y, lo z, hi x, hi y, hi z]`` of the control points (contains the curve)."""
    for j in range(3):
        box[j] = math.inf
        box[3 + j] = -math.inf
    for i in range(H.shape[0]):
        for j in range(3):
            x = H[i, j] / H[i, 3]
            box[j] = min(box[j], x)
            box[3 + j] = max(box[3 + j], x)


def _space_separated(HA, HB, tol, max_depth):
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


def space_pair_kernel(HA0, HB0, tol, budget, k):
    """Intersect two space rational curves by the relief scheme.

    ``HA0``, ``HB0``: homogeneous rows ``(w x, w y, w z, w)`` in model coordinates; ``tol`` a
    distance in model units (> 0: resolved by the caller, relief_cad.tolerances); ``budget``
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
                    out, nout = _space_add(
                        out,
                        nout,
                        KIND_OVERLAP,
                        res[r, 2],
                        res[r, 3],
                        res[r, 4],
                        res[r, 5],
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    )
                else:
                    artefact = True
                    break
            elif kind == KIND_UNRESOLVED:
                out, nout = _space_add(
                    out, nout, KIND_UNRESOLVED, res[r, 2], res[r, 3], res[r, 4], res[r, 5], 0.0, 0.0, 0.0, 0.0
                )
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
                    if sqrt(_space_dist2(HA, HB, end, u, wka, wkb, pa, da, pb, db)) <= tol:
                        t = end
                        fix_t = True
                if u == end or abs(u - end) < 1e-9:
                    if sqrt(_space_dist2(HA, HB, t, end, wka, wkb, pa, da, pb, db)) <= tol:
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
                        if sqrt(gap_e) <= tol:
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
            out, nout = _space_add(
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
        return out, nout, STATUS_OK
    return out, 0, STATUS_ARTEFACT

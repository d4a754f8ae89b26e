"""Batches: many planar pairs in one call on packed control points.

Both entry points first test the control-point boxes of a pair, without the GIL and before any
allocation (:func:`_boxes_apart`): a pair whose boxes lie farther apart than its tolerance (or
than an upper bound of its default tolerance) has no result rows, as the pair kernel would find.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import cython
import numpy as np
from cython.cimports.libc.math import fabs, sqrt

from .bezier import _grow
from .constants import _ROUND, KIND_UNRESOLVED, RES_COLS
from .planar import _apart, _box, _pair_core, scratch_rows
from .rows import rows_to_list

_K_UNRESOLVED = cython.declare(cython.double, KIND_UNRESOLVED)  # a C copy for the loops
_C_ROUND = cython.declare(cython.double, _ROUND)  # 64 eps
_NO_ROWS = np.empty((0, RES_COLS))
_NO_ROWS.flags.writeable = False
_NO_ROWS_VIEW = cython.declare(cython.const[cython.double][:, :], _NO_ROWS)  # a typed view kept for C calls


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _boxes_apart(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], tol: cython.double
) -> cython.bint:
    """True when the control-point boxes of two planar curves are more than ``tol`` apart.

    ``tol <= 0`` stands for the pair's default tolerance (:func:`.bezier._default_tol`), which is
    bounded here by twice ``1e-9`` times the diagonal of the control points' joint box plus
    ``64 eps`` times their largest coordinate: the curves lie in their control polygons' hull, so
    their sampled extent is within that box (up to rounding, far below the factor 2). Only a pair
    that the pair kernel's own box test rejects can give True.
    """
    bound: cython.double = tol
    if not tol > 0.0:
        axl, axh, ayl, ayh = _box(PA)
        bxl, bxh, byl, byh = _box(PB)
        xl = min(axl, bxl)
        xh = max(axh, bxh)
        yl = min(ayl, byl)
        yh = max(ayh, byh)
        big = max(max(fabs(xl), fabs(xh)), max(fabs(yl), fabs(yh)))
        diag = sqrt((xh - xl) * (xh - xl) + (yh - yl) * (yh - yl))
        bound = 2.0 * (1e-9 * diag + _C_ROUND * big)
    return _apart(PA, PB, bound)


def intersect_batch_kernel(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    offsets: cython.const[cython.longlong][:],
    pairs: cython.const[cython.longlong][:, :],
    tol: cython.const[cython.double][:],
    budget: cython.longlong,
):
    """Intersect many pairs in one call, without the GIL (other threads run meanwhile).

    ``P`` (N, 2) and ``W`` (N,) hold every curve's control points back to back;
    curve ``k`` is rows ``offsets[k]:offsets[k + 1]``. ``pairs`` (p, 2) indexes
    curves; ``tol`` (p,) holds each pair's tolerance. Returns the result rows.
    One scratch buffer, made for the largest pair, serves every pair.
    """
    k: cython.Py_ssize_t
    m: cython.Py_ssize_t = 1
    n: cython.Py_ssize_t = 0
    nres: cython.Py_ssize_t = 0
    npairs: cython.Py_ssize_t = pairs.shape[0]
    for k in range(offsets.shape[0] - 1):
        m = max(m, offsets[k + 1] - offsets[k])
    scratch: cython.double[:, :] = np.empty((scratch_rows(m, m), RES_COLS))
    res = np.empty((max(16, 2 * npairs), RES_COLS))
    rv: cython.double[:, :] = res
    k = 0
    while k < npairs:
        with cython.nogil:
            k, nres, n = _batch_run(P, W, offsets, pairs, tol, budget, scratch, rv, k, nres)
        if n < 0:  # no room for pair k's rows after those of the pairs before: grow, and run it again
            res = _grow(res, max(-2 - n, 2 * rv.shape[0]))
            rv = res
    return res[:nres]


@cython.cfunc
@cython.nogil
@cython.exceptval(check=True)  # an exception of a pair propagates (checked once per call, not per pair)
def _batch_run(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    offsets: cython.const[cython.longlong][:],
    pairs: cython.const[cython.longlong][:, :],
    tol: cython.const[cython.double][:],
    budget: cython.longlong,
    scratch: cython.double[:, :],
    rv: cython.double[:, :],
    k: cython.Py_ssize_t,
    nres: cython.Py_ssize_t,
) -> tuple[cython.Py_ssize_t, cython.Py_ssize_t, cython.Py_ssize_t]:
    """Run pairs ``k, k + 1, ...`` into ``rv`` from row ``nres``, without the GIL: ``(k, nres, 0)`` when done.

    It stops early at the first pair whose rows do not fit: ``(k, nres, m)``, the rows of the pairs
    before it kept (``nres`` of them), ``m`` :func:`_pair_core`'s ``-2 - n`` for pair ``k``; or at
    one that raised (the exception propagates).
    """
    n: cython.Py_ssize_t
    PA: cython.const[cython.double][:, :]
    PB: cython.const[cython.double][:, :]
    while k < pairs.shape[0]:
        ia = pairs[k, 0]
        ib = pairs[k, 1]
        PA = P[offsets[ia] : offsets[ia + 1]]
        PB = P[offsets[ib] : offsets[ib + 1]]
        if not _boxes_apart(PA, PB, tol[k]):
            n = _pair_core(PA, W[offsets[ia] : offsets[ia + 1]], PB, W[offsets[ib] : offsets[ib + 1]],
                           tol[k], budget, k, scratch, rv, nres)
            if n < 0:
                return k, nres, n
            _sort_by_t(rv, nres, n)
            nres = n
        k += 1
    return k, nres, 0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _sort_by_t(rv: cython.double[:, :], first: cython.Py_ssize_t, last: cython.Py_ssize_t) -> cython.void:
    """Order one pair's rows ``first .. last - 1`` by ``t`` (column 2), stably, unresolved boxes last.

    The pair driver writes its points, then its overlaps, then its unresolved boxes: the points
    and overlaps are sorted (an insertion sort: a pair has few rows), and the boxes stay after them
    in the order they were found. That is the order of the result lists (a point by its ``t``, an
    overlap by its first ``t``), so the Python side builds them without sorting.
    """
    while last > first and rv[last - 1, 1] == _K_UNRESOLVED:
        last -= 1
    i: cython.Py_ssize_t
    j: cython.Py_ssize_t
    c: cython.Py_ssize_t
    x: cython.double
    for i in range(first + 1, last):
        j = i
        while j > first and rv[j - 1, 2] > rv[j, 2]:  # strict: equal t keep their order
            for c in range(rv.shape[1]):
                x = rv[j, c]
                rv[j, c] = rv[j - 1, c]
                rv[j - 1, c] = x
            j -= 1


def _ends_match(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], lim: cython.double
) -> cython.bint:
    """True when both end points of ``PA`` lie within ``lim`` (per coordinate) of those of ``PB``.

    Either way round: ``PA``'s first point near ``PB``'s first and its last near ``PB``'s last,
    or first near last and last near first. Points of different dimensions never match.
    """
    if PA.shape[1] != PB.shape[1]:
        return False
    na: cython.Py_ssize_t = PA.shape[0] - 1
    nb: cython.Py_ssize_t = PB.shape[0] - 1
    return (_near(PA, 0, PB, 0, lim) and _near(PA, na, PB, nb, lim)) or (
        _near(PA, 0, PB, nb, lim) and _near(PA, na, PB, 0, lim))


@cython.cfunc
@cython.exceptval(check=False)
def _near(P: cython.const[cython.double][:, :], i: cython.Py_ssize_t, Q: cython.const[cython.double][:, :],
          j: cython.Py_ssize_t, lim: cython.double) -> cython.bint:
    """True when row ``i`` of ``P`` and row ``j`` of ``Q`` differ by at most ``lim`` in every coordinate."""
    c: cython.Py_ssize_t
    for c in range(P.shape[1]):
        if not abs(P[i, c] - Q[j, c]) <= lim:
            return False
    return True


def ends_match(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], lim: cython.double
) -> bool:
    """:func:`_ends_match` for Python callers (control points of any one dimension)."""
    return _ends_match(PA, PB, lim)


# the scratch buffer of intersect_one_kernel and its typed view, kept between calls (an allocation
# and its view cost about half a microsecond, a quarter of a small pair's kernel time); None while
# a call uses them, so that a call made meanwhile (another thread: the kernel runs without the
# GIL) makes its own
_spare = cython.declare(object, None)
_SPARE_ROWS = cython.declare(cython.Py_ssize_t, 256)


def kernel_views(P: cython.const[cython.double][:, :], W: cython.const[cython.double][:]):
    """``(P, W)`` as this module's own typed views (compiled), or as given (uncompiled).

    A numpy array passed to :func:`intersect_one_kernel` is converted on every call (the buffer
    protocol, a format check and a new view object: about 0.1 us per array, a quarter of a
    small pair's call); a view this module made is taken as it is. A curve keeps its pair for
    its next call (:meth:`relief_cad.RationalBezier._kernel_views`).
    """
    return P, W


def _view(a: cython.double[:, :]):
    """``a`` as this module's own typed view (compiled; as given uncompiled): see :func:`kernel_views`."""
    return a


def intersect_one_kernel(
    PA: cython.const[cython.double][:, :],
    WA: cython.const[cython.double][:],
    PB: cython.const[cython.double][:, :],
    WB: cython.const[cython.double][:],
    tol: cython.double,
    budget: cython.longlong,
    ends_lim: cython.double = -1.0,
    listed: cython.bint = False,
):
    """One pair: its result rows, a new array (a single array return is cheaper to box than a tuple).

    A pair with no result (boxes apart, or nothing found) returns one shared read-only empty array.
    With ``ends_lim >= 0``, a pair whose end points match within ``ends_lim`` (:func:`_ends_match`:
    curves that may coincide all along, which the caller tests first) returns None, unsolved.
    The pair kernel runs without the GIL in a scratch buffer kept for the next call: its first
    rows, then room for result rows; rows that do not fit there go to a larger array, and the pair
    runs again (the same bits). With ``listed``, the return is ``rows_to_list(rows, tol)``
    instead (:func:`planar_pair`'s path), made from the rows where the kernel wrote them: no copy
    of them, no new view.
    """
    global _spare
    if ends_lim >= 0.0 and _ends_match(PA, PB, ends_lim):
        return None
    if _apart(PA, PB, tol):
        return rows_to_list(_NO_ROWS_VIEW, tol) if listed else _NO_ROWS
    rows: cython.Py_ssize_t = scratch_rows(PA.shape[0], PB.shape[0])
    spare = _spare
    _spare = None
    if spare is None or spare[0].shape[0] < rows + _SPARE_ROWS:
        buf = np.empty((rows + _SPARE_ROWS, RES_COLS))
        spare = (buf, _view(buf))
    buf = spare[0]
    res = None
    n: cython.Py_ssize_t
    try:
        scratch: cython.double[:, :] = spare[1]  # this module's own view: taken as it is
        rv: cython.double[:, :] = scratch[rows:]
        while True:
            with cython.nogil:
                n = _pair_core(PA, WA, PB, WB, tol, budget, 0.0, scratch, rv, 0)
            if n >= 0:
                _sort_by_t(rv, 0, n)
                break
            res = np.empty((-2 - n, RES_COLS))
            rv = res
        if listed:
            return rows_to_list(rv[:n], tol)
        if n == 0:
            return _NO_ROWS
        return np.array(buf[rows : rows + n]) if res is None else res[:n]
    finally:
        _spare = spare


def planar_pair(a, b, tol: cython.double, budget: cython.longlong, ends: cython.bint = True):
    """The results of two curves if both are planar: ``(IntersectionList, final)``, or None, or False.

    ``a``, ``b``: :class:`~relief_cad.RationalBezier` (their kernel views are read, made once per
    curve); ``tol`` their resolved tolerance (model units), ``budget`` the clipping budget. None
    when either curve is a space curve (the caller's space path); False when ``ends`` is set and
    their end points match within ``2 tol`` (curves that may coincide all along: the caller asks
    :func:`relief_cad.contacts.whole_overlap` first, then calls again with ``ends`` False). Else
    :func:`relief_cad._kernels.rows.rows_to_list` of the pair kernel's rows. The one-call path of
    :func:`relief_cad.intersect`, without Python between the curves and the result list.

    >>> from relief_cad import RationalBezier as R
    >>> res, final = planar_pair(R([[0, 0], [2, 2]]), R([[0, 2], [2, 0]]), 1e-9, 1000)
    >>> [(r.t, r.u, r.kind) for r in res], final
    ([(0.5, 0.5, 'crossing')], True)
    >>> planar_pair(R([[0, 0], [2, 2]]), R([[2, 2], [0, 0]]), 1e-9, 1000)  # the same segment
    False
    >>> planar_pair(R([[0, 0], [2, 2]]), R([[0, 2, 1], [2, 0, 1]]), 1e-9, 1000) is None  # a space curve
    True
    """
    ka = a._kv or a._kernel_views()
    kb = b._kv or b._kernel_views()
    PA: cython.const[cython.double][:, :] = ka[0]
    PB: cython.const[cython.double][:, :] = kb[0]
    if PA.shape[1] != 2 or PB.shape[1] != 2:
        return None
    got = intersect_one_kernel(PA, ka[1], PB, kb[1], tol, budget, 2.0 * tol if ends else -1.0, True)
    return False if got is None else got


def pack_pairs(pairs: list, cls: type, lim: cython.double):
    """Sort out the pairs that the batch kernel takes and pack their curves: ``(taken, rest, P, W, offsets)``.

    A pair is taken when it is a tuple of two curves of exactly the class ``cls`` (a
    :class:`~relief_cad.RationalBezier`), both planar, whose end points do not match. They match
    within ``lim`` per coordinate either way round (:func:`_ends_match`), or, for ``lim < 0``
    (per-pair default tolerances, not yet known), when the first x of ``a`` equals an end x of
    ``b``: such curves may coincide all along, which :func:`relief_cad.intersect` answers first.
    ``taken`` and ``rest`` list the indices of the taken pairs and of all others, in order. The
    taken curves are packed as :func:`intersect_batch_kernel` takes them: curve ``2 i`` is ``a``
    of pair ``taken[i]`` and ``2 i + 1`` its ``b``, rows ``offsets[c]:offsets[c + 1]`` of ``P``
    (N, 2) and ``W`` (N,), both read-only. The curves' own kernel views are read (made once per
    curve), so there is no Python per row.

    >>> from relief_cad import RationalBezier as R
    >>> line, arc = R([[0, 0], [2, 2]]), R([[0.5, 2], [1, 0], [2, 2]], [1.0, 0.5, 1.0])
    >>> taken, rest, P, W, offsets = pack_pairs([(line, arc), (line, line), "x"], R, -1.0)
    >>> taken, rest, offsets.tolist(), W.tolist()
    ([0], [1, 2], [0, 2, 5], [1.0, 1.0, 1.0, 0.5, 1.0])
    """
    k: cython.Py_ssize_t
    c: cython.Py_ssize_t = 0  # curves packed
    row: cython.Py_ssize_t = 0  # rows packed
    PA: cython.const[cython.double][:, :]
    PB: cython.const[cython.double][:, :]
    taken: list = []
    rest: list = []
    cap: cython.Py_ssize_t = 8 * len(pairs) + 8  # rows: two cubics a pair, grown when short
    P = np.empty((cap, 2))
    W = np.empty(cap)
    offsets = np.empty(2 * len(pairs) + 1, dtype=np.int64)
    Pv: cython.double[:, :] = P  # typed once (and again when grown): no buffer look-up per curve
    Wv: cython.double[:] = W
    Ov: cython.longlong[:] = offsets
    Ov[0] = 0
    for k in range(len(pairs)):
        pr = pairs[k]
        if type(pr) is not tuple or len(pr) != 2 or type(pr[0]) is not cls or type(pr[1]) is not cls:
            rest.append(k)
            continue
        ka = pr[0]._kv or pr[0]._kernel_views()
        kb = pr[1]._kv or pr[1]._kernel_views()
        PA = ka[0]
        PB = kb[0]
        if PA.shape[1] != 2 or PB.shape[1] != 2 or (_ends_match(PA, PB, lim) if lim >= 0.0 else (
                PA[0, 0] == PB[0, 0] or PA[0, 0] == PB[PB.shape[0] - 1, 0])):
            rest.append(k)
            continue
        taken.append(k)
        if row + PA.shape[0] + PB.shape[0] > cap:
            cap = 2 * cap + PA.shape[0] + PB.shape[0]
            P = np.concatenate((P[:row], np.empty((cap - row, 2))))
            W = np.concatenate((W[:row], np.empty(cap - row)))
            Pv = P
            Wv = W
        row = _pack_curve(PA, ka[1], Pv, Wv, row)
        row = _pack_curve(PB, kb[1], Pv, Wv, row)
        Ov[c + 1] = row - PB.shape[0]
        Ov[c + 2] = row
        c += 2
    P = P[:row]
    W = W[:row]
    P.flags.writeable = False
    W.flags.writeable = False
    return taken, rest, P, W, offsets[: c + 1]


@cython.cfunc
def _pack_curve(Q: cython.const[cython.double][:, :], V: cython.const[cython.double][:],
                P: cython.double[:, :], W: cython.double[:], row: cython.Py_ssize_t) -> cython.Py_ssize_t:
    """Copy one curve's points ``Q`` and weights ``V`` into ``P``, ``W`` from ``row``: the next free row."""
    i: cython.Py_ssize_t
    for i in range(Q.shape[0]):
        P[row + i, 0] = Q[i, 0]
        P[row + i, 1] = Q[i, 1]
        W[row + i] = V[i]
    return row + Q.shape[0]

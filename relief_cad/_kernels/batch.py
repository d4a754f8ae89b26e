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

from .constants import RES_COLS
from .planar import intersect_pair_kernel

_NO_ROWS = np.empty((0, RES_COLS))
_NO_ROWS.flags.writeable = False


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _box(
    P: cython.const[cython.double][:, :]
) -> tuple[cython.double, cython.double, cython.double, cython.double]:
    """The control-point box ``(xlo, xhi, ylo, yhi)`` of planar points ``P``."""
    i: cython.Py_ssize_t
    xl = xh = P[0, 0]
    yl = yh = P[0, 1]
    for i in range(1, P.shape[0]):
        xl = min(xl, P[i, 0])
        xh = max(xh, P[i, 0])
        yl = min(yl, P[i, 1])
        yh = max(yh, P[i, 1])
    return xl, xh, yl, yh


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
    axl, axh, ayl, ayh = _box(PA)
    bxl, bxh, byl, byh = _box(PB)
    bound: cython.double = tol
    if not tol > 0.0:
        xl = min(axl, bxl)
        xh = max(axh, bxh)
        yl = min(ayl, byl)
        yh = max(ayh, byh)
        big = max(max(fabs(xl), fabs(xh)), max(fabs(yl), fabs(yh)))
        diag = sqrt((xh - xl) * (xh - xl) + (yh - yl) * (yh - yl))
        bound = 2.0 * (1e-9 * diag + 64.0 * 2.220446049250313e-16 * big)
    return axl > bxh + bound or bxl > axh + bound or ayl > byh + bound or byl > ayh + bound


def intersect_batch_kernel(
    P: cython.const[cython.double][:, :],
    W: cython.const[cython.double][:],
    offsets: cython.const[cython.longlong][:],
    pairs: cython.const[cython.longlong][:, :],
    tol: cython.const[cython.double][:],
    budget,
):
    """Intersect many pairs in one call.

    ``P`` (N, 2) and ``W`` (N,) hold every curve's control points back to back;
    curve ``k`` is rows ``offsets[k]:offsets[k + 1]``. ``pairs`` (p, 2) indexes
    curves; ``tol`` (p,) holds each pair's tolerance. Returns the result rows.
    """
    res = np.empty((max(16, 2 * pairs.shape[0]), RES_COLS))
    nres: cython.Py_ssize_t = 0
    k: cython.Py_ssize_t
    PA: cython.const[cython.double][:, :]
    PB: cython.const[cython.double][:, :]
    WA: cython.const[cython.double][:]
    WB: cython.const[cython.double][:]
    for k in range(pairs.shape[0]):
        ia = pairs[k, 0]
        ib = pairs[k, 1]
        PA = P[offsets[ia] : offsets[ia + 1]]
        PB = P[offsets[ib] : offsets[ib + 1]]
        if _boxes_apart(PA, PB, tol[k]):
            continue
        WA = W[offsets[ia] : offsets[ia + 1]]
        WB = W[offsets[ib] : offsets[ib + 1]]
        res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol[k], budget, k, res, nres)
    return res[:nres]


@cython.cfunc
@cython.exceptval(check=False)
def _ends_match(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], lim: cython.double
) -> cython.bint:
    """True when both end points of ``PA`` lie within ``lim`` (per coordinate) of those of ``PB``.

    Either way round: ``PA``'s first point near ``PB``'s first and its last near ``PB``'s last,
    or first near last and last near first.
    """
    na: cython.Py_ssize_t = PA.shape[0] - 1
    nb: cython.Py_ssize_t = PB.shape[0] - 1
    ax0, ay0, ax1, ay1 = PA[0, 0], PA[0, 1], PA[na, 0], PA[na, 1]
    bx0, by0, bx1, by1 = PB[0, 0], PB[0, 1], PB[nb, 0], PB[nb, 1]
    if abs(ax0 - bx0) <= lim and abs(ay0 - by0) <= lim and abs(ax1 - bx1) <= lim and abs(ay1 - by1) <= lim:
        return True
    return abs(ax0 - bx1) <= lim and abs(ay0 - by1) <= lim and abs(ax1 - bx0) <= lim and abs(ay1 - by0) <= lim


def ends_match(
    PA: cython.const[cython.double][:, :], PB: cython.const[cython.double][:, :], lim: cython.double
) -> bool:
    """:func:`_ends_match` for Python callers."""
    return _ends_match(PA, PB, lim)


def intersect_one_kernel(
    PA: cython.const[cython.double][:, :],
    WA: cython.const[cython.double][:],
    PB: cython.const[cython.double][:, :],
    WB: cython.const[cython.double][:],
    tol: cython.double,
    budget,
    ends_lim: cython.double = -1.0,
):
    """One pair: the result rows (a single array return is cheaper to box than a tuple).

    A pair with no result (boxes apart, or nothing found) returns one shared read-only empty array.
    With ``ends_lim >= 0``, a pair whose end points match within ``ends_lim`` (:func:`_ends_match`:
    curves that may coincide all along, which the caller tests first) returns None, unsolved.
    """
    if ends_lim >= 0.0 and _ends_match(PA, PB, ends_lim):
        return None
    if _boxes_apart(PA, PB, tol):
        return _NO_ROWS
    # no ``res``: the pair kernel makes its result rows in its own scratch buffer (one allocation)
    res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol, budget, 0, None, 0)
    return res[:nres] if nres else _NO_ROWS

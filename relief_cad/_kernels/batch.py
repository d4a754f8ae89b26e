"""Batches: many planar pairs in one call on packed control points.

Compiled by Cython (pure-Python mode) when the package is built; see :mod:`relief_cad._kernels`.
"""

from __future__ import annotations

import numpy as np

from .constants import RES_COLS
from .planar import intersect_pair_kernel


def intersect_batch_kernel(P, W, offsets, pairs, tol, budget):
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
        PA = np.ascontiguousarray(P[offsets[ia] : offsets[ia + 1]])
        WA = np.ascontiguousarray(W[offsets[ia] : offsets[ia + 1]])
        PB = np.ascontiguousarray(P[offsets[ib] : offsets[ib + 1]])
        WB = np.ascontiguousarray(W[offsets[ib] : offsets[ib + 1]])
        res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol[k], budget, k, res, nres)
    return res[:nres]


def intersect_one_kernel(PA, WA, PB, WB, tol, budget):
    """One pair: the result rows (a single array return is cheaper to box than a tuple)."""
    res = np.empty((8, RES_COLS))
    res, nres = intersect_pair_kernel(PA, WA, PB, WB, tol, budget, 0, res, 0)
    return res[:nres]

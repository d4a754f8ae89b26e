"""Broad phase: which boxes may touch, and which points are one point (numpy only, no OCP).

Sort-and-sweep over axis-aligned boxes: the boxes are sorted by their lower
corner along the axis where the fewest of them overlap, and each box is paired only with
the boxes whose lower corner falls inside its own extent along that axis; the
other axes filter those candidates. The cost is ``O(n log n + k)``, ``k`` the
number of pairs overlapping along the sweep axis, instead of the ``n^2`` of
testing all pairs.

:func:`cluster_points` merges points closer than a tolerance (the cut points
that become one vertex) with a grid instead: a sweep along one axis degenerates
when many points share that coordinate (copies of a part side by side, an
axis-aligned pattern), while grid cells hold only the points that are truly near.

>>> import numpy as np
>>> lows = np.array([[0.0, 0.0], [0.5, 0.5], [3.0, 0.0]])
>>> highs = lows + 1.0
>>> box_pairs(lows, highs).tolist()
[[0, 1]]
"""

from __future__ import annotations

import functools
import itertools
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from .errors import InvalidInputError, ShapeError, ToleranceError

__all__ = ["box_pairs", "box_pairs_between", "cluster_points"]

IntArray = NDArray[np.int64]
FloatArray = NDArray[np.float64]


def _boxes(lows: object, highs: object, name: str) -> tuple[FloatArray, FloatArray]:
    """Check a set of boxes: two finite arrays of shape ``(n, dim)`` with ``lows <= highs``."""
    lo = np.asarray(lows, dtype=np.float64)
    hi = np.asarray(highs, dtype=np.float64)
    if lo.ndim != 2 or lo.shape != hi.shape:
        raise ShapeError(
            f"expected {name} lows and highs of one shape (n, dim); received {lo.shape} and {hi.shape}"
        )
    if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
        raise InvalidInputError(f"expected finite box corners for {name}; received NaN or inf")
    if np.any(lo > hi):
        raise InvalidInputError(f"expected lows <= highs for every box of {name}; some are inverted")
    return lo, hi


def _pad(pad: float) -> float:
    value = float(pad)
    if not (np.isfinite(value) and value >= 0.0):
        raise ToleranceError(f"expected a finite pad >= 0 (model units); received {pad!r}")
    return value


def _sweep_axis(lo: FloatArray, hi: FloatArray, pad: float) -> int:
    """The axis along which a sweep meets the fewest candidate pairs.

    Boxes sharing a coordinate range (shapes side by side in a row) make a poor sweep
    axis: counting each axis's candidates costs a sort per axis, far less than testing
    many times more candidates.
    """
    if lo.shape[0] == 0:
        return 0
    counts = []
    for axis in range(lo.shape[1]):
        keys = np.sort(lo[:, axis])
        stops = np.searchsorted(keys, hi[:, axis] + pad, side="right")
        counts.append(int(np.sum(stops - np.searchsorted(keys, lo[:, axis], side="left"))))
    return int(np.argmin(counts))


def _ranges(starts: IntArray, stops: IntArray) -> tuple[IntArray, IntArray]:
    """All ``(k, m)`` with ``starts[k] <= m < stops[k]``, as two flat arrays (no Python loop)."""
    counts = np.maximum(stops - starts, 0)
    total = int(counts.sum())
    owners = np.repeat(np.arange(starts.shape[0], dtype=np.int64), counts)
    firsts = np.repeat(starts - np.cumsum(counts) + counts, counts)
    return owners, firsts + np.arange(total, dtype=np.int64)


def _sweep(
    lo_a: FloatArray, hi_a: FloatArray, lo_b: FloatArray, axis: int, pad: float, strict: bool
) -> tuple[IntArray, IntArray]:
    """Pairs ``(i, j)``: box ``j`` of b starts inside box ``i`` of a along ``axis`` (after ``i``'s start).

    ``strict``: the start of ``j`` must be strictly after that of ``i`` (ties go to the
    other direction of the sweep, so that no pair is found twice).
    """
    order = np.argsort(lo_b[:, axis], kind="stable")
    keys = lo_b[order, axis]
    starts = np.searchsorted(keys, lo_a[:, axis], side="right" if strict else "left")
    stops = np.searchsorted(keys, hi_a[:, axis] + pad, side="right")
    owners, positions = _ranges(starts.astype(np.int64), stops.astype(np.int64))
    return owners, order[positions].astype(np.int64)


def _touch(lo_a: FloatArray, hi_a: FloatArray, lo_b: FloatArray, hi_b: FloatArray,
           i: IntArray, j: IntArray, pad: float) -> NDArray[np.bool_]:
    return np.all((lo_a[i] - pad <= hi_b[j]) & (lo_b[j] <= hi_a[i] + pad), axis=1)  # type: ignore[no-any-return]


def box_pairs(lows: object, highs: object, *, pad: float = 0.0) -> IntArray:
    """Return the pairs ``i < j`` of boxes of one set that overlap once widened by ``pad``.

    Parameters
    ----------
    lows, highs : array_like, shape (n, dim)
        Lower and upper corners of ``n`` axis-aligned boxes (any dimension).
    pad : float, keyword-only
        Distance (model units) by which boxes may miss each other and still count
        as overlapping (the intersection tolerance); default 0 (touching counts).

    Returns
    -------
    ndarray of int64, shape (k, 2)
        Every overlapping pair once, ``i < j``, sorted.

    Raises
    ------
    ShapeError
        If ``lows`` and ``highs`` are not two arrays of one shape ``(n, dim)``.
    InvalidInputError
        If a corner is not finite or a box is inverted.
    ToleranceError
        If ``pad`` is negative or not finite.

    Examples
    --------
    >>> box_pairs([[0.0, 0.0], [2.0, 0.0]], [[1.0, 1.0], [3.0, 1.0]], pad=1.0).tolist()
    [[0, 1]]
    >>> box_pairs(np.empty((0, 3)), np.empty((0, 3))).shape
    (0, 2)
    """
    lo, hi = _boxes(lows, highs, "the boxes")
    p = _pad(pad)
    axis = _sweep_axis(lo, hi, p)
    i, j = _sweep(lo, hi, lo, axis, p, strict=False)
    a, b = np.minimum(i, j), np.maximum(i, j)
    keep = (a != b) & _touch(lo, hi, lo, hi, a, b, p)  # the lower index as ``a`` (one rounding)
    return _unique_pairs(a[keep], b[keep])


def box_pairs_between(lows_a: object, highs_a: object, lows_b: object, highs_b: object, *,
                      pad: float = 0.0) -> IntArray:
    """Return the pairs ``(i, j)``, box ``i`` of a and box ``j`` of b, that overlap once widened by ``pad``.

    Parameters
    ----------
    lows_a, highs_a : array_like, shape (n, dim)
        Corners of the first set of boxes.
    lows_b, highs_b : array_like, shape (m, dim)
        Corners of the second set (same ``dim``).
    pad : float, keyword-only
        As for :func:`box_pairs`.

    Returns
    -------
    ndarray of int64, shape (k, 2)
        Every overlapping pair once, sorted.

    Raises
    ------
    ShapeError, InvalidInputError, ToleranceError
        As for :func:`box_pairs`; ``ShapeError`` also if the dimensions differ.

    Examples
    --------
    >>> lows_b, highs_b = [[0.5, 0.5], [5.0, 5.0]], [[2.0, 2.0], [6.0, 6.0]]
    >>> box_pairs_between([[0.0, 0.0]], [[1.0, 1.0]], lows_b, highs_b).tolist()
    [[0, 0]]
    """
    lo_a, hi_a = _boxes(lows_a, highs_a, "set a")
    lo_b, hi_b = _boxes(lows_b, highs_b, "set b")
    if lo_a.shape[1] != lo_b.shape[1] and lo_a.shape[0] and lo_b.shape[0]:
        raise ShapeError(f"expected boxes of one dimension; received {lo_a.shape[1]} and {lo_b.shape[1]}")
    p = _pad(pad)
    if lo_a.shape[0] == 0 or lo_b.shape[0] == 0:
        return np.empty((0, 2), dtype=np.int64)
    axis = _sweep_axis(np.vstack([lo_a, lo_b]), np.vstack([hi_a, hi_b]), p)
    i1, j1 = _sweep(lo_a, hi_a, lo_b, axis, p, strict=False)  # b starts at or after a
    j2, i2 = _sweep(lo_b, hi_b, lo_a, axis, p, strict=True)  # a starts strictly after b
    i, j = np.concatenate([i1, i2]), np.concatenate([j1, j2])
    keep = _touch(lo_a, hi_a, lo_b, hi_b, i, j, p)
    return _unique_pairs(i[keep], j[keep])


def _unique_pairs(a: IntArray, b: IntArray) -> IntArray:
    """The distinct pairs ``(a, b)``, sorted (one key per pair: far faster than rows)."""
    if a.shape[0] == 0:
        return np.empty((0, 2), dtype=np.int64)
    m = int(b.max()) + 1
    keys = np.unique(a.astype(np.int64) * m + b)
    return np.stack([keys // m, keys % m], axis=1).astype(np.int64)


def cluster_points(
    points: object, tol: float, *, links: Sequence[tuple[int, int]] | IntArray = ()
) -> IntArray:
    """Label points so that points closer than ``tol`` (and linked points) share a label.

    Clusters are the connected components of the graph "closer than ``tol``"
    (Euclidean) plus the extra ``links``: a chain of close points is one
    cluster even if its ends are further apart than ``tol``.

    Parameters
    ----------
    points : array_like, shape (n, dim)
        The points (rows), finite.
    tol : float
        Merge distance, model units, ``>= 0``.
    links : sequence of (int, int), keyword-only
        Pairs of point indices that are one point whatever their distance (e.g.
        two ends of edges sharing one ``TopoDS_Vertex``).

    Returns
    -------
    ndarray of int64, shape (n,)
        Labels ``0 .. m-1``, numbered in order of each cluster's first point.

    Raises
    ------
    ShapeError
        If ``points`` is not 2D, or a link is not a pair of valid indices.
    InvalidInputError, ToleranceError
        If a point is not finite, or ``tol`` is negative or not finite.

    Examples
    --------
    >>> cluster_points([[0.0, 0.0], [5.0, 0.0], [0.0, 1e-9]], 1e-6).tolist()
    [0, 1, 0]
    >>> cluster_points([[0.0, 0.0], [5.0, 0.0]], 1e-6, links=[(0, 1)]).tolist()
    [0, 0]
    >>> cluster_points(np.empty((0, 3)), 1.0).tolist()
    []
    """
    pts = np.asarray(points, dtype=np.float64)
    if pts.ndim != 2:
        raise ShapeError(f"expected points of shape (n, dim); received an array of shape {pts.shape}")
    if not np.all(np.isfinite(pts)):
        raise InvalidInputError("expected finite points; received NaN or inf")
    p = _pad(tol)
    # a few points: every pair (a grid has a fixed cost of some 0.2 ms, more than their distances)
    close = np.stack(np.triu_indices(pts.shape[0], 1), axis=1) if pts.shape[0] <= 64 else _grid_pairs(pts, p)
    if close.shape[0]:
        diff = pts[close[:, 0]] - pts[close[:, 1]]
        near = np.flatnonzero(np.abs(diff).max(axis=1) <= p)  # no coordinate apart by more than tol
        close = close[near[np.linalg.norm(diff[near], axis=1) <= tol]]
    extra = np.asarray(links, dtype=np.int64).reshape(-1, 2)
    if extra.shape[0] and (extra.min() < 0 or extra.max() >= pts.shape[0]):
        raise ShapeError(
            f"expected links between point indices 0..{pts.shape[0] - 1}; received {extra.tolist()}"
        )
    return _components(pts.shape[0], np.vstack([close, extra]))


def _grid_pairs(pts: FloatArray, tol: float) -> IntArray:
    """Candidate pairs ``(i, j)`` of points that may lie within ``tol``: those in neighbouring grid cells.

    The cells are cubes of side ``h >= 2 tol`` (at most about a million of them along
    each axis), so two points within ``tol`` lie in cells at most one apart on every axis,
    whatever the rounding of ``(p - lo) / h``. Each point is paired with the later points of
    its own cell and with every point of half of its neighbouring cells (the other half
    pairs from the other side). Unlike a sweep along one axis, points sharing a
    coordinate (copies of a part on a row, an axis-aligned grid) cost nothing extra: the
    candidates grow with the points per cell, not per column.
    """
    n, dim = pts.shape
    if n < 2 or dim == 0:
        return np.empty((0, 2), dtype=np.int64)
    lo = pts.min(axis=0)
    span = float(np.max(pts.max(axis=0) - lo))
    per_axis = float(2 ** min(20, 60 // dim))  # cells per axis: the keys below fit in int64
    h = 2.0 * max(tol, span / per_axis)
    if not h > 0.0:  # one point repeated, tol 0: one cell
        h = 1.0
    cells = np.floor((pts - lo) / h).astype(np.int64) + 1  # >= 1: a neighbour's index is never < 0
    sizes = cells.max(axis=0) + 2
    strides = np.concatenate([np.cumprod(sizes[::-1])[::-1][1:], [1]]).astype(np.int64)
    key = cells @ strides
    order = np.argsort(key, kind="stable")
    sk = key[order]
    position = np.arange(n, dtype=np.int64)
    own_i, own_j = _ranges(position + 1, np.searchsorted(sk, sk, side="right").astype(np.int64))
    found_i, found_j = [own_i], [own_j]
    for step in _half_neighbours(dim):
        target = sk + int(np.dot(step, strides))
        starts = np.searchsorted(sk, target, side="left").astype(np.int64)
        stops = np.searchsorted(sk, target, side="right").astype(np.int64)
        i, j = _ranges(starts, stops)
        found_i.append(i)
        found_j.append(j)
    return np.stack([order[np.concatenate(found_i)], order[np.concatenate(found_j)]], axis=1)


@functools.cache
def _half_neighbours(dim: int) -> tuple[tuple[int, ...], ...]:
    """The offsets in ``{-1, 0, 1}^dim`` whose first non-zero entry is +1 (half of the neighbours)."""
    return tuple(
        step for step in itertools.product((-1, 0, 1), repeat=dim)
        if any(step) and next(c for c in step if c) == 1
    )


def _components(n: int, edges: IntArray) -> IntArray:
    """Connected components of a graph on ``n`` nodes by label propagation with pointer jumping.

    The smallest index of a component reaches one more of its nodes every round
    (labels only decrease), so after at most ``n`` rounds every component carries
    one label and the next round changes nothing: the budget of ``n + 2`` rounds
    is never exhausted (it would be a bug, reported as such).
    """
    labels = np.arange(n, dtype=np.int64)
    if edges.shape[0]:
        a, b = edges[:, 0], edges[:, 1]
        for _ in range(n + 2):
            low = np.minimum(labels[a], labels[b])
            new = labels.copy()
            np.minimum.at(new, a, low)
            np.minimum.at(new, b, low)
            new = new[new]  # pointer jumping
            if np.array_equal(new, labels):
                break
            labels = new
        else:  # pragma: no cover - the propagation always converges within the budget
            raise RuntimeError("internal: cluster_points did not converge")
    _, first, inverse = np.unique(labels, return_index=True, return_inverse=True)
    rank = np.empty(first.shape[0], dtype=np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(first.shape[0], dtype=np.int64)
    return rank[inverse.reshape(-1)]

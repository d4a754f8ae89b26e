"""Broad phase: which boxes may touch, and which points are one point (numpy only, no OCP).

Boxes go into the cells of a uniform grid about as large as the typical box; only
boxes sharing a cell are tested against each other, so the cost grows with the
boxes that are near each other, not with all pairs. Unlike a sweep along one
axis, it does not degenerate when many boxes share a coordinate range (copies of
a part side by side, an axis-aligned pattern of shapes).

:func:`cluster_points` merges points closer than a tolerance (the cut points
that become one vertex): points in one cell of a fine grid (side ``tol / (2 sqrt(dim))``) are
one group at once, and only groups are paired, through the same grid as boxes. So the cost
grows with the number of places, not with the square of the points at one place.

>>> import numpy as np
>>> lows = np.array([[0.0, 0.0], [0.5, 0.5], [3.0, 0.0]])
>>> highs = lows + 1.0
>>> box_pairs(lows, highs).tolist()
[[0, 1]]
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Sequence

import numpy as np
from numpy.typing import NDArray

from ._checks import as_index_array, as_points, as_real_array, check_distance, check_finite
from .errors import InputTypeError, InvalidInputError, ShapeError

__all__ = ["box_pairs", "box_pairs_between", "cluster_points"]

IntArray = NDArray[np.int64]
FloatArray = NDArray[np.float64]


def _boxes(lows: object, highs: object, names: tuple[str, str]) -> tuple[FloatArray, FloatArray]:
    """Check a set of boxes: two finite arrays of one shape ``(n, dim)`` with ``lows <= highs``."""
    lo_name, hi_name = names
    lo, hi = as_real_array(lows, lo_name), as_real_array(highs, hi_name)
    if lo.ndim != 2 or lo.shape != hi.shape:
        raise ShapeError(f"{lo_name} and {hi_name} should be arrays of one shape (n, dim), "
                         f"not {lo.shape} and {hi.shape}")
    check_finite(lo, lo_name)
    check_finite(hi, hi_name)
    inverted = np.flatnonzero(np.any(lo > hi, axis=1))
    if inverted.shape[0]:
        k = int(inverted[0])
        raise InvalidInputError(f"{lo_name} should be <= {hi_name} in every coordinate; box {k} has "
                                f"{lo_name} {lo[k].tolist()} and {hi_name} {hi[k].tolist()}")
    return lo, hi


def _points(points: object) -> FloatArray:
    """Check the points of :func:`cluster_points`: a finite array of shape ``(n, dim)``, ``dim >= 1``."""
    return as_points(points, "points")


def _links(links: object, n: int) -> IntArray:
    """Check the links of :func:`cluster_points`: pairs ``(i, j)`` of indices of the ``n`` points."""
    if links is None or isinstance(links, (str, bytes, numbers.Number)):
        raise InputTypeError(f"links should be a sequence of (int, int) pairs, not {type(links).__name__}")
    extra = as_index_array(links, "links")
    if extra.shape != (0,) and (extra.ndim != 2 or extra.shape[1] != 2):
        raise ShapeError(f"links should be (int, int) pairs, shape (k, 2), not shape {extra.shape}")
    if extra.size and (extra.min() < 0 or extra.max() >= n):
        raise ShapeError(f"links should be indices of the {n} points (0 to {n - 1}), "
                         f"not from {int(extra.min())} to {int(extra.max())}")
    return extra


def _ranges(starts: IntArray, stops: IntArray) -> tuple[IntArray, IntArray]:
    """All ``(k, m)`` with ``starts[k] <= m < stops[k]``, as two flat arrays (no Python loop)."""
    counts = np.maximum(stops - starts, 0)
    total = int(counts.sum())
    owners = np.repeat(np.arange(starts.shape[0], dtype=np.int64), counts)
    firsts = np.repeat(starts - np.cumsum(counts) + counts, counts)
    return owners, firsts + np.arange(total, dtype=np.int64)


def _cell_pairs(lo: FloatArray, hi: FloatArray, pad: float) -> tuple[IntArray, IntArray]:
    """Candidate pairs ``(i, j)``, ``i != j``, of boxes that may overlap once widened by ``pad``.

    A few boxes: every pair. Many: the pairs sharing a cell of a uniform grid, each box in
    every cell that its corners, moved out by ``pad``, reach (``floor((x - o) / h)``: each
    step rounds monotonically, so two boxes that pass :func:`_touch` share a cell). The
    cells are about as large as the typical box, doubled while the boxes would fill more
    than 8 cells each on average (a few long boxes among many small ones). A pair sharing
    several cells comes several times.
    """
    n, dim = lo.shape
    if n <= 64 or dim == 0:
        i, j = np.triu_indices(n, 1)
        return i.astype(np.int64), j.astype(np.int64)
    low, high = lo - pad, hi + pad
    origin = low.min(axis=0)
    span = float(np.max(high.max(axis=0) - origin))
    h = max(float(np.median(np.max(high - low, axis=1))), span / 2.0 ** min(19, 60 // dim))
    if not h > 0.0:  # every box one and the same point
        h = 1.0
    for _ in range(64):  # h doubles: within 64 rounds one cell holds everything
        c0 = np.floor((low - origin) / h).astype(np.int64)
        c1 = np.floor((high - origin) / h).astype(np.int64)
        counts = c1 - c0 + 1
        per_box = np.prod(counts, axis=1)
        if int(per_box.sum()) <= 8 * n + 64:
            break
        h *= 2.0
    owner = np.repeat(np.arange(n, dtype=np.int64), per_box)
    local = np.arange(owner.shape[0], dtype=np.int64) - np.repeat(np.cumsum(per_box) - per_box, per_box)
    sizes = c1.max(axis=0) + 1
    strides = np.concatenate([np.cumprod(sizes[::-1])[::-1][1:], [1]]).astype(np.int64)
    key = np.zeros(owner.shape[0], dtype=np.int64)
    for axis in range(dim - 1, -1, -1):  # the cell of each incidence, axis by axis (mixed radix)
        width = counts[owner, axis]
        key += (c0[owner, axis] + local % width) * strides[axis]
        local //= width
    order = np.argsort(key, kind="stable")
    sk = key[order]
    first, second = _ranges(np.arange(1, sk.shape[0] + 1, dtype=np.int64),
                            np.searchsorted(sk, sk, side="right").astype(np.int64))
    return owner[order[first]], owner[order[second]]


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
    InputTypeError
        If ``lows`` or ``highs`` is not an array of real numbers (strings, a ragged list ...).
    ShapeError
        If ``lows`` and ``highs`` are not two arrays of one shape ``(n, dim)``.
    NonFiniteError
        If a corner is not finite.
    InvalidInputError
        If a box is inverted (a low above its high).
    ToleranceError
        If ``pad`` is negative or not finite (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> box_pairs([[0.0, 0.0], [2.0, 0.0]], [[1.0, 1.0], [3.0, 1.0]], pad=1.0).tolist()
    [[0, 1]]
    >>> box_pairs(np.empty((0, 3)), np.empty((0, 3))).shape
    (0, 2)
    >>> box_pairs([[0.0, 0.0]], [[1.0, 1.0]], pad=-1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: pad should be a finite distance >= 0 in model units, not -1.0
    """
    lo, hi = _boxes(lows, highs, ("lows", "highs"))
    return _box_pairs(lo, hi, check_distance(pad, "pad"))


def _box_pairs(lows: object, highs: object, pad: float) -> IntArray:
    """:func:`box_pairs` of boxes known to be valid (the CAD layer's calls: no checks)."""
    p, (lo, hi) = _within_range(float(pad), np.asarray(lows, dtype=np.float64),
                                np.asarray(highs, dtype=np.float64))
    i, j = _cell_pairs(lo, hi, p)
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
    InputTypeError, ShapeError, NonFiniteError, InvalidInputError, ToleranceError
        As for :func:`box_pairs`; ``ShapeError`` also if the dimensions differ.

    Examples
    --------
    >>> lows_b, highs_b = [[0.5, 0.5], [5.0, 5.0]], [[2.0, 2.0], [6.0, 6.0]]
    >>> box_pairs_between([[0.0, 0.0]], [[1.0, 1.0]], lows_b, highs_b).tolist()
    [[0, 0]]
    >>> box_pairs_between([[0.0, 0.0]], [[1.0, 1.0]], [[0.0, 0.0, 0.0]], [[1.0, 1.0, 1.0]])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: lows_a and lows_b should have one dim (columns), not 2 and 3
    """
    lo_a, hi_a = _boxes(lows_a, highs_a, ("lows_a", "highs_a"))
    lo_b, hi_b = _boxes(lows_b, highs_b, ("lows_b", "highs_b"))
    if lo_a.shape[1] != lo_b.shape[1] and lo_a.shape[0] and lo_b.shape[0]:
        raise ShapeError(f"lows_a and lows_b should have one dim (columns), not {lo_a.shape[1]} and "
                         f"{lo_b.shape[1]}")
    return _box_pairs_between(lo_a, hi_a, lo_b, hi_b, check_distance(pad, "pad"))


def _box_pairs_between(lows_a: object, highs_a: object, lows_b: object, highs_b: object,
                       pad: float) -> IntArray:
    """:func:`box_pairs_between` of boxes known to be valid (the CAD layer's calls: no checks)."""
    p, (lo_a, hi_a, lo_b, hi_b) = _within_range(float(pad), *(np.asarray(x, dtype=np.float64)
                                                               for x in (lows_a, highs_a, lows_b, highs_b)))
    if lo_a.shape[0] == 0 or lo_b.shape[0] == 0:
        return np.empty((0, 2), dtype=np.int64)
    na = lo_a.shape[0]
    if na * lo_b.shape[0] <= 2016:  # a few boxes: every pair
        i, j = np.divmod(np.arange(na * lo_b.shape[0], dtype=np.int64), lo_b.shape[0])
    else:  # both sets in one grid; a pair across the sets in either order
        x, y = _cell_pairs(np.vstack([lo_a, lo_b]), np.vstack([hi_a, hi_b]), p)
        across = (x < na) != (y < na)
        x, y = x[across], y[across]
        i, j = np.minimum(x, y), np.maximum(x, y) - na
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
    InputTypeError
        If ``points`` is not an array of real numbers, or ``links`` not integer pairs.
    ShapeError
        If ``points`` is not of shape ``(n, dim)`` (``dim >= 1``), or a link is not a pair of
        valid indices.
    NonFiniteError
        If a point is not finite.
    ToleranceError
        If ``tol`` is negative or not finite (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> cluster_points([[0.0, 0.0], [5.0, 0.0], [0.0, 1e-9]], 1e-6).tolist()
    [0, 1, 0]
    >>> cluster_points([[0.0, 0.0], [5.0, 0.0]], 1e-6, links=[(0, 1)]).tolist()
    [0, 0]
    >>> cluster_points(np.empty((0, 3)), 1.0).tolist()
    []
    >>> cluster_points([[0.0, 0.0], [5.0, 0.0]], 1e-6, links=[(0, 2)])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: links should be indices of the 2 points (0 to 1), not from 0 to 2
    """
    pts = _points(points)
    return _cluster_points(pts, check_distance(tol, "tol"), _links(links, pts.shape[0]))


def _cluster_points(points: object, tol: float, links: object) -> IntArray:
    """:func:`cluster_points` of points and links known to be valid (the CAD layer's call: no checks)."""
    p, (pts,) = _within_range(float(tol), np.asarray(points, dtype=np.float64))
    extra = np.asarray(links, dtype=np.int64).reshape(-1, 2)
    node, lo, hi = _tight_groups(pts, p)
    edges = [node[extra]] if extra.shape[0] else []
    if lo.shape[0] > 1:
        edges.append(_close_groups(pts, node, lo, hi, p))
    return _components(lo.shape[0], np.vstack(edges) if edges else np.empty((0, 2), dtype=np.int64))[node]


_HUGE = 2.0**500  # coordinates beyond this may overflow when squared in a norm


def _within_range(tol: float, *arrays: FloatArray) -> tuple[float, list[FloatArray]]:
    """``tol`` and the ``arrays``, scaled by one power of two (exact) when they are huge; else as they are.

    The norms of point differences square them, and box corners minus their origin may
    overflow: beyond about 1e154 every point would stand apart, and grid cells would be
    computed from inf. Scaled by ``2**-e`` (``e`` the exponent of the largest coordinate or
    ``tol``) every difference and ``tol`` keep their bits, so every comparison its answer.

    >>> tol, (pts,) = _within_range(1e290, np.array([[1e300, 0.0], [-1e300, 1e299]]))
    >>> float(np.max(np.abs(pts))) <= 1.0, tol == 1e290 * float(np.max(np.abs(pts))) / 1e300
    (True, True)
    """
    big = max([abs(tol)] + [float(np.max(np.abs(a), initial=0.0)) for a in arrays])
    if not big > _HUGE:
        return tol, list(arrays)
    e = math.frexp(big)[1]
    return math.ldexp(tol, -e), [np.ldexp(a, -e) for a in arrays]


def _tight_groups(pts: FloatArray, tol: float) -> tuple[IntArray, FloatArray, FloatArray]:
    """Group points that are all within ``tol`` of each other: ``(node, lo, hi)``.

    Points sharing a cell of a grid of side ``tol / (2 sqrt(dim))`` form one group when the
    box of the group's points has a diagonal of at most ``tol`` (so every two of them are
    within ``tol``: one component whatever else); a point of a group that fails that (a
    ``tol`` below the rounding of the coordinates) is a group of its own. ``node[i]`` is
    point ``i``'s group, the groups numbered in order of their first point; ``lo``, ``hi``
    (groups, dim) are the groups' boxes. Many points at one place (the cut points of a
    hundred lines through one point) thus become one group in ``O(n log n)``, where testing
    their pairs took ``O(n^2)`` time and memory.
    """
    n, dim = pts.shape
    if n == 0:
        return np.empty(0, dtype=np.int64), pts, pts
    if tol > 0.0:
        side = tol / (2.0 * np.sqrt(max(dim, 1)))
        with np.errstate(over="ignore"):  # inf for a tol below the coordinates' rounding (split below)
            cells = np.floor((pts - pts.min(axis=0)) / side)
    else:
        cells = pts  # tol 0: only equal points are one
    cell, lo, hi = _groups(pts, cells)
    loose = np.linalg.norm(hi - lo, axis=1) > tol
    if loose.any():  # every point of a loose group apart
        keys = np.where(loose[cell], cell.max() + 1 + np.arange(n, dtype=np.int64), cell)
        cell, lo, hi = _groups(pts, keys.astype(np.float64).reshape(-1, 1))
    return cell, lo, hi


def _groups(pts: FloatArray, keys: FloatArray) -> tuple[IntArray, FloatArray, FloatArray]:
    """Points with equal rows of ``keys`` (n, k) are one group: ``(group of each point, lo, hi)``.

    The groups are numbered in order of their first point; ``lo``, ``hi`` are the boxes of
    their points. One sort of the rows (``lexsort``), then runs of equal rows.
    """
    n = pts.shape[0]
    order = np.lexsort(keys.T[::-1])
    sk = keys[order]
    new = np.ones(n, dtype=bool)
    new[1:] = np.any(sk[1:] != sk[:-1], axis=1)
    starts = np.flatnonzero(new)
    first = np.minimum.reduceat(order, starts)  # each run's first point
    rank = np.empty(starts.shape[0], dtype=np.int64)
    rank[np.argsort(first, kind="stable")] = np.arange(starts.shape[0], dtype=np.int64)
    group = np.empty(n, dtype=np.int64)
    group[order] = rank[np.cumsum(new) - 1]
    sp = pts[order]
    lo = np.empty((starts.shape[0], pts.shape[1]))
    hi = np.empty((starts.shape[0], pts.shape[1]))
    lo[rank] = np.minimum.reduceat(sp, starts, axis=0)
    hi[rank] = np.maximum.reduceat(sp, starts, axis=0)
    return group, lo, hi


def _close_groups(pts: FloatArray, node: IntArray, lo: FloatArray, hi: FloatArray, tol: float) -> IntArray:
    """The pairs of groups with two points within ``tol`` of each other, as rows ``(a, b)``.

    Candidates come from the grid (boxes within ``tol``); a pair whose boxes are more than
    ``tol`` apart has no such points, one whose boxes are within ``tol`` corner to far corner
    has only such points (the norms of the coordinate differences are monotone in them, as
    computed); only the pairs in between compare their points.
    """
    i, j = _cell_pairs(lo, hi, tol)
    a, b = np.minimum(i, j), np.maximum(i, j)
    keep = (a != b) & _touch(lo, hi, lo, hi, a, b, tol)
    pairs = _unique_pairs(a[keep], b[keep])
    a, b = pairs[:, 0], pairs[:, 1]
    gap = np.maximum(np.maximum(lo[b] - hi[a], lo[a] - hi[b]), 0.0)
    reach = np.maximum(hi[a] - lo[b], hi[b] - lo[a])
    near = np.linalg.norm(gap, axis=1) <= tol
    sure = near & (np.linalg.norm(reach, axis=1) <= tol)
    unsure = np.flatnonzero(near & ~sure)
    if unsure.shape[0]:
        order = np.argsort(node, kind="stable")  # each group's points, as one run of ``order``
        starts = np.searchsorted(node[order], np.arange(lo.shape[0] + 1))
        for k in unsure.tolist():
            sure[k] = _any_within(pts[order[starts[a[k]]:starts[a[k] + 1]]],
                                  pts[order[starts[b[k]]:starts[b[k] + 1]]], tol)
    close: IntArray = pairs[sure]
    return close


def _any_within(pa: FloatArray, pb: FloatArray, tol: float) -> bool:
    """True when a point of ``pa`` and one of ``pb`` are within ``tol`` (blocks of about 2**20 pairs)."""
    rows = max(1, (1 << 20) // pb.shape[0])
    for s in range(0, pa.shape[0], rows):  # stops at the first block with such a pair
        if bool((np.linalg.norm(pa[s:s + rows, None, :] - pb[None, :, :], axis=2) <= tol).any()):
            return True
    return False


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

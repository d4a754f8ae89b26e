r"""Low-level ("hazmat") Bézier clipping functions, documented, no stability promise.

These are thin Python faces of the compiled kernels in :mod:`relief_cad._kernels`
that the planar intersector runs; they let you inspect one clipping step.

A *fat line* of a curve is a strip ``dmin <= nx x + ny y + c <= dmax`` (unit
normal ``(nx, ny)``) containing the curve; it runs along the chord through the
end points (or, for a closed or point-like control polygon, from the first
point to the farthest one). For a rational curve with control points ``P_j``
and weights ``w_j > 0`` the signed distance to the line is

.. math::

    d(s) = \frac{\sum_j w_j d_j B_j^m(s)}{\sum_j w_j B_j^m(s)}, \qquad d_j = n \cdot P_j + c,

so ``dmin <= d(s)`` is ``sum_j w_j (d_j - dmin) B_j(s) >= 0`` and ``d(s) <= dmax``
is ``sum_j w_j (dmax - d_j) B_j(s) >= 0``: two *explicit* Bézier functions whose
control points ``(j/m, w_j (d_j - dmin))`` bound them by their convex hull. The
clip range is where both hulls reach ``>= 0``.

>>> import numpy as np
>>> nodes = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, -2.0], [3.0, 0.0]])
>>> compute_fat_line(nodes)
(0.0, 1.0, 0.0, -2.0, 2.0)
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from ._checks import (
    DEFAULT_BUDGET,
    MAX_WEIGHT_RATIO,
    as_index_array,
    as_points,
    as_real_array,
    check_budget,
    check_distance,
    check_finite,
    check_flag,
    check_tol,
    check_weights,
    check_workers,
)
from ._kernels import (
    clip_range_kernel,
    fat_line_kernel,
    hull_range_kernel,
    intersect_batch_kernel,
)
from ._pool import run_ordered
from ._types import FloatArray
from .contacts import range_exponent
from .curves import RationalBezier
from .errors import ShapeError, ToleranceError, WeightError
from .tolerances import _default_tolerances, _resolve_tolerance

__all__ = [
    "RESULT_COLUMNS",
    "batch_rows",
    "clip_range",
    "compute_fat_line",
    "distance_coefficients",
    "hull_range",
    "intersect_packed",
]

RESULT_COLUMNS: tuple[str, ...] = ("pair", "kind", "t", "u", "t1", "u1", "x", "y", "distance")
"""Columns of :func:`intersect_packed` rows; ``kind`` 0 crossing, 1 tangent, 2 overlap
(``t..t1``, ``u..u1``), 3 unresolved box (``t..t1`` x ``u..u1``)."""


def _points(nodes: object, name: str = "nodes") -> FloatArray:
    """``nodes`` as a new float64 array of shape (m + 1, 2), m >= 1, of finite numbers (checked)."""
    return as_points(nodes, name, dim=2, least=2)


def _weights(weights: object, n: int, name: str = "weights") -> FloatArray:
    """The weights of ``n`` control points: ``None`` gives ones; else (n,) finite, > 0 (checked)."""
    if weights is None:
        return np.ones(n)
    w = as_real_array(weights, name)
    if w.shape != (n,):
        raise ShapeError(f"{name} should have shape ({n},), one per control point, not {w.shape}")
    check_finite(w, name)
    check_weights(w, name)
    return w


def _line(line: object) -> tuple[float, float, float, float, float]:
    """A fat line ``(nx, ny, c, dmin, dmax)`` of five finite numbers (checked)."""
    arr = as_real_array(line, "line")
    if arr.shape != (5,):
        raise ShapeError(f"line should be the five numbers (nx, ny, c, dmin, dmax) of compute_fat_line, "
                         f"not shape {arr.shape}")
    check_finite(arr, "line")
    nx, ny, c, dmin, dmax = (float(v) for v in arr)
    return nx, ny, c, dmin, dmax


def compute_fat_line(nodes: FloatArray, *, perpendicular: bool = False
                     ) -> tuple[float, float, float, float, float]:
    """Fat line ``(nx, ny, c, dmin, dmax)`` of a control polygon (not widened by a tolerance).

    Parameters
    ----------
    nodes : ndarray, shape (m + 1, 2)
        Cartesian control points.
    perpendicular : bool
        Return the perpendicular fat line (bounds along the chord) instead.

    Returns
    -------
    tuple of float
        Unit normal ``(nx, ny)``, offset ``c`` and the distance bounds of the nodes.

    Examples
    --------
    >>> compute_fat_line(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]))
    (0.0, 1.0, 0.0, 0.0, 1.0)
    >>> compute_fat_line(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]), perpendicular=True)
    (1.0, 0.0, 0.0, 0.0, 2.0)
    >>> compute_fat_line(np.array([[1.0, 1.0], [1.0, 1.0]]))  # point-like: defined, no error
    (0.0, 1.0, -1.0, 0.0, 0.0)
    """
    pts = _points(nodes)
    perp = check_flag(perpendicular, "perpendicular")
    # the kernel squares distances (its own callers pass a normalised frame): coordinates out of
    # the safe range are scaled by a power of two first (exact), the offsets scaled back
    exp = range_exponent(float(np.max(np.abs(pts))))
    nx, ny, c, dmin, dmax = fat_line_kernel(np.ldexp(pts, -exp) if exp else pts, perp)
    c, dmin, dmax = math.ldexp(c, exp), math.ldexp(dmin, exp), math.ldexp(dmax, exp)
    # (+ 0.0 turns a -0.0 into 0.0)
    return float(nx) + 0.0, float(ny) + 0.0, float(c) + 0.0, float(dmin) + 0.0, float(dmax) + 0.0


def distance_coefficients(nodes: FloatArray, weights: FloatArray | None,
                          line: tuple[float, float, float, float, float], tol: float = 0.0
                          ) -> tuple[FloatArray, FloatArray]:
    """Bézier coefficients of ``w (d - dmin + tol)`` and ``w (dmax + tol - d)`` of a curve.

    Parameters
    ----------
    nodes : ndarray, shape (m + 1, 2)
        The clipped curve's control points.
    weights : ndarray, shape (m + 1,) or None
        Its weights (``None`` for a polynomial curve).
    line : tuple
        A fat line ``(nx, ny, c, dmin, dmax)`` from :func:`compute_fat_line`.
    tol : float
        Widening of the strip on both sides.

    Returns
    -------
    (ndarray, ndarray)
        ``lower`` and ``upper``: the curve can be inside the strip only where both
        Bézier functions are ``>= 0``.

    Examples
    --------
    >>> lower, upper = distance_coefficients(np.array([[0.0, 3.0], [1.0, -1.0], [2.0, 3.0]]),
    ...                                      np.array([1.0, 2.0, 1.0]), (0.0, 1.0, 0.0, 0.0, 1.0))
    >>> lower.tolist(), upper.tolist()
    ([3.0, -2.0, 3.0], [-2.0, 4.0, -2.0])
    """
    p = _points(nodes)
    w = _weights(weights, p.shape[0])
    nx, ny, c, dmin, dmax = _line(line)
    widen = check_distance(tol, "tol")
    d = p @ np.array([nx, ny]) + c
    return w * (d - (dmin - widen)), w * ((dmax + widen) - d)


def hull_range(coefficients: FloatArray) -> tuple[float, float]:
    """Range of ``s`` where the convex hull of ``(j / m, e_j)`` reaches ``e >= 0``.

    Returns ``(lo, hi)``; ``lo > hi`` when the whole hull is below zero.

    Examples
    --------
    >>> hull_range(np.array([-1.0, 1.0]))
    (0.5, 1.0)
    >>> hull_range(np.array([-1.0, -2.0, -1.0]))
    (inf, -inf)
    """
    e = as_real_array(coefficients, "coefficients")
    if e.ndim != 1 or e.shape[0] < 2:
        raise ShapeError(f"coefficients should have shape (m + 1,) with m >= 1, not {e.shape}")
    check_finite(e, "coefficients")
    lo, hi = hull_range_kernel(e)
    return float(lo), float(hi)


def clip_range(nodes: FloatArray, weights: FloatArray | None,
               line: tuple[float, float, float, float, float], tol: float = 0.0
               ) -> tuple[float, float]:
    """Parameter range of a curve that can lie in a fat line widened by ``tol``.

    Parameters
    ----------
    nodes, weights
        The clipped curve (weights ``None`` for a polynomial curve).
    line : tuple
        ``(nx, ny, c, dmin, dmax)`` of the other curve.
    tol : float
        Widening of the strip on both sides.

    Returns
    -------
    (float, float)
        ``(lo, hi)`` in ``[0, 1]``; ``lo > hi`` means the curve misses the strip.

    Examples
    --------
    >>> line = compute_fat_line(np.array([[0.0, 0.0], [2.0, 0.0]]))
    >>> clip_range(np.array([[0.0, -1.0], [1.0, 1.0]]), None, line)
    (0.5, 0.5)
    >>> lo, hi = clip_range(np.array([[0.0, 1.0], [1.0, 2.0]]), None, line)
    >>> lo > hi
    True
    """
    p = _points(nodes)
    w = _weights(weights, p.shape[0])
    nx, ny, c, dmin, dmax = _line(line)
    widen = check_distance(tol, "tol")
    lo, hi = clip_range_kernel(p, w, nx, ny, c, dmin - widen, dmax + widen, np.empty(p.shape[0]))
    return float(lo), float(hi)


def intersect_packed(points: FloatArray, weights: FloatArray, offsets: NDArray[np.int64],
                     pairs: NDArray[np.int64], tol: float | None = None, budget: int = DEFAULT_BUDGET, *,
                     workers: int | None = None) -> FloatArray:
    """Intersect many planar curve pairs given as packed arrays; return raw result rows.

    The fastest entry point (no Python objects per pair): one compiled call.

    Parameters
    ----------
    points : ndarray, shape (N, 2)
        Control points of every curve, back to back.
    weights : ndarray, shape (N,)
        Their weights (> 0).
    offsets : ndarray of int, shape (c + 1,)
        Curve ``k`` is rows ``offsets[k]:offsets[k + 1]`` (at least 2 rows each); an integer
        array (a float array is refused, not truncated).
    pairs : ndarray of int, shape (p, 2)
        Curve indices of each pair (integers, as ``offsets``).
    tol : float, optional
        Distance tolerance for every pair (default: each pair's default tolerance); raised to
        each pair's rounding floor (:func:`relief_cad.tolerances.resolve_tolerance`).
    budget : int
        Iteration budget per pair (default 500 000, as for :func:`relief_cad.intersect`).
    workers : int, keyword-only
        Threads the pairs run on (:func:`batch_rows`); default: every core. The rows are
        the same for any number.

    Returns
    -------
    ndarray, shape (r, 9)
        Rows with :data:`RESULT_COLUMNS`, grouped by pair in pair order; within a
        pair, points and overlaps by ``t`` (an overlap by its first ``t``), then the
        unresolved boxes.

    Raises
    ------
    InputTypeError
        If an array holds anything but real numbers (``offsets`` and ``pairs``: integers), or
        ``budget`` or ``workers`` is not an int.
    ShapeError
        If the arrays' shapes do not fit, ``offsets`` does not run from 0 to N giving each curve
        at least 2 rows, or ``pairs`` names a curve that is not there.
    NonFiniteError, WeightError, ToleranceError, InvalidInputError
        For a point or weight that is not finite, a weight <= 0 (or a curve's weights' max /
        min above :data:`~relief_cad._checks.MAX_WEIGHT_RATIO`), a bad ``tol``, a budget < 1.

    Examples
    --------
    >>> pts = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]])
    >>> rows = intersect_packed(pts, np.ones(4), np.array([0, 2, 4]), np.array([[0, 1]]))
    >>> rows[:, :4].tolist()
    [[0.0, 0.0, 0.5, 0.5]]
    >>> intersect_packed(pts, np.ones(4), np.array([0.0, 2.0, 4.0]), np.array([[0, 1]]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: offsets should be an array of integers (indices), not of float64
    """
    p, w, off, pr = _packed(points, weights, offsets, pairs)
    given = check_tol(tol)
    nbudget = check_budget(budget)
    nworkers = check_workers(workers)
    # each chunk's tolerances are computed on its own thread (without the GIL for the default)
    return _batch_rows(p, w, off, pr, _pair_tolerances(p, w, off, pr, given), nbudget, nworkers)


def _packed(points: object, weights: object, offsets: object, pairs: object
            ) -> tuple[FloatArray, FloatArray, NDArray[np.int64], NDArray[np.int64]]:
    """The packed arrays of :func:`intersect_packed`, checked: ``(P, W, offsets, pairs)``.

    ``P`` and ``W`` are new read-only float64 arrays, ``offsets`` and ``pairs`` C-ordered int64
    (an empty ``pairs`` of any shape is ``(0, 2)``). Every index the kernels read is checked
    here: they do no bounds checks.
    """
    p = as_real_array(points, "points")
    w = as_real_array(weights, "weights")
    if p.ndim != 2 or p.shape[1] != 2 or w.shape != (p.shape[0],):
        raise ShapeError(f"points should be (N, 2) and weights (N,), not {p.shape} and {w.shape}")
    check_finite(p, "points")
    check_finite(w, "weights")
    off = as_index_array(offsets, "offsets")
    if off.ndim != 1 or off.shape[0] < 2 or off[0] != 0 or off[-1] != p.shape[0] or np.any(np.diff(off) < 2):
        raise ShapeError("offsets should start at 0, end at N and give every curve >= 2 control points")
    _check_curve_weights(w, off)
    pr = as_index_array(pairs, "pairs")
    if pr.size == 0:
        pr = pr.reshape(0, 2)
    if pr.ndim != 2 or pr.shape[1] != 2 or (pr.size and (pr.min() < 0 or pr.max() >= off.shape[0] - 1)):
        raise ShapeError(f"pairs should be (p, 2) indices of the {off.shape[0] - 1} curves, "
                         f"not shape {pr.shape} from {pr.min(initial=0)} to {pr.max(initial=0)}")
    p.flags.writeable = False  # new arrays (the caller's stay as they are): the kernels read them
    w.flags.writeable = False
    return p, w, off, pr


def _check_curve_weights(w: FloatArray, off: NDArray[np.int64]) -> None:
    """Refuse a weight <= 0, or a curve whose weights' max / min exceeds the ratio a curve may have."""
    if not np.all(w > 0.0):
        i = int(np.argmin(w > 0.0))
        raise WeightError(f"weights should all be > 0; weight {i} is {float(w[i])!r}")
    if float(np.max(w, initial=1.0)) <= MAX_WEIGHT_RATIO * float(np.min(w, initial=1.0)):
        return  # no curve's ratio exceeds that of all weights together
    ratio = np.maximum.reduceat(w, off[:-1]) / np.minimum.reduceat(w, off[:-1])
    worst = int(np.argmax(ratio))
    check_weights(w[off[worst]:off[worst + 1]], f"the weights of curve {worst}")


def _checked_tols(tols: object, n: int) -> FloatArray:
    """``n`` pair tolerances (model units, finite, > 0) as a float64 array (checked)."""
    t = as_real_array(tols, "tols")
    if t.shape != (n,):
        raise ShapeError(f"tols should have shape ({n},), one per pair, not {t.shape}")
    good = np.isfinite(t) & (t > 0.0)
    if not np.all(good):
        k = int(np.argmin(good))
        raise ToleranceError(f"tols should be finite distances > 0 in model units; tols[{k}] is "
                             f"{float(t[k])!r}")
    return t


_MIN_CHUNK = 256  # pairs per thread, at least: below that a thread costs more than it gains


def batch_rows(points: FloatArray, weights: FloatArray, offsets: NDArray[np.int64], pairs: NDArray[np.int64],
               tols: FloatArray | Callable[[int, int], FloatArray], budget: int,
               workers: int | None = None) -> FloatArray:
    """Run the batch kernel on packed pairs, split into chunks over ``workers`` threads: all rows.

    The arrays are those of :func:`intersect_packed` (checked as there); ``tols`` holds each
    pair's tolerance (model units, finite, > 0), or is a function giving those of pairs ``lo`` to
    ``hi - 1`` as ``tols(lo, hi)``, called once per chunk on the chunk's thread (its answers are
    checked too); ``workers`` None is every core. The kernel runs without the GIL, so the
    chunks run at once; their rows are joined in pair order (column 0 indexes ``pairs``), the
    same rows for any ``workers``. An exception is that of the first chunk, in order, that raised.

    >>> pts = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]])
    >>> pts.flags.writeable = False
    >>> w = np.ones(4)
    >>> w.flags.writeable = False
    >>> pairs = np.array([[0, 1]] * 600)
    >>> rows = batch_rows(pts, w, np.array([0, 2, 4]), pairs, np.full(600, 1e-9), 1000, workers=2)
    >>> rows.shape, rows[-1, :4].tolist()
    ((600, 9), [599.0, 0.0, 0.5, 0.5])
    """
    p, w, off, pr = _packed(points, weights, offsets, pairs)
    nbudget = check_budget(budget)
    nworkers = check_workers(workers)
    if callable(tols):
        given = tols
        return _batch_rows(p, w, off, pr, lambda lo, hi: _checked_tols(given(lo, hi), hi - lo), nbudget,
                           nworkers)
    return _batch_rows(p, w, off, pr, _checked_tols(tols, pr.shape[0]), nbudget, nworkers)


def _batch_rows(points: FloatArray, weights: FloatArray, offsets: NDArray[np.int64], pairs: NDArray[np.int64],
                tols: FloatArray | Callable[[int, int], FloatArray], budget: int,
                workers: int | None = None) -> FloatArray:
    """:func:`batch_rows` on arrays already checked (relief_cad's own callers): no check of them."""
    n = pairs.shape[0]
    threads = 1 if n < 2 * _MIN_CHUNK else check_workers(workers)  # a few pairs: no pool
    size = n if threads <= 1 else max(_MIN_CHUNK, -(-n // threads))

    def chunk(start: int) -> FloatArray:
        stop = min(n, start + size)
        part_tols = tols(start, stop) if callable(tols) else tols[start:stop]
        part: FloatArray = intersect_batch_kernel(points, weights, offsets, pairs[start:stop], part_tols,
                                                  budget)
        if start:
            part[:, 0] += start
        return part

    if size >= n:
        return chunk(0)
    return np.concatenate(run_ordered(chunk, range(0, n, size), threads))


def _pair_tolerances(p: FloatArray, w: FloatArray, off: NDArray[np.int64], pairs: NDArray[np.int64],
                     tol: float | None) -> Callable[[int, int], FloatArray]:
    """Each pair's :func:`~relief_cad.tolerances.resolve_tolerance` by chunk: ``f(lo, hi)``, pairs lo to hi-1.

    The default (``tol`` None) is computed on the packed arrays in one compiled call per chunk,
    without the GIL (so chunks on threads compute theirs at once); its homogeneous rows are
    those a :class:`~relief_cad.RationalBezier` makes (``p * w``, then ``w``). Curves are built
    once each, when needed (a given ``tol``, or a pair whose sample is degenerate).
    """
    curves: dict[int, RationalBezier] = {}

    def curve(k: int) -> RationalBezier:
        if k not in curves:
            curves[k] = RationalBezier(p[off[k]:off[k + 1]], w[off[k]:off[k + 1]])
        return curves[k]

    if tol is None:
        H = np.empty((p.shape[0], 3))
        with np.errstate(over="ignore", invalid="ignore"):  # an overflow: that pair's curve raises
            H[:, :2] = p * w[:, None]
        H[:, 2] = w
        return lambda lo, hi: _default_tolerances(curve, H, p, off, pairs[lo:hi])
    return lambda lo, hi: np.array([_resolve_tolerance(tol, curve(i), curve(j))
                                    for i, j in pairs[lo:hi].tolist()])

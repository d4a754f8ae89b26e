"""A curve cut into pieces that cannot cross themselves: the first step of every self-intersection.

Planar (:mod:`relief_cad.intersection`) and space (:mod:`relief_cad.space`) self-intersections both
cut the curve here and then intersect every pair of pieces; each brings its own test of a piece
that cannot meet itself. A piece that fails the test is halved, at most ``max_depth`` times, except
a straight piece (within ``tol`` of a line) that turns back along it: no halving ever makes such a
piece pass (every piece holding the fold tip turns back), so it is cut at the fold instead, and its
halves are kept once they run one way along the line.

>>> from relief_cad import RationalBezier
>>> folded = RationalBezier([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]])   # x = 4t - 3t^2 turns at t = 2/3
>>> [(round(s0, 12), round(s1, 12)) for s0, s1, _ in monotone_pieces(folded, 1e-9, lambda p: False, 10)]
[(0.0, 0.666666666667), (0.666666666667, 1.0)]
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from ._checks import as_points, check_count, check_curve, check_flag, check_given_tol, check_unit
from ._kernels.certify import fold_bisect
from ._types import FloatArray, PointsLike
from .curves import RationalBezier
from .errors import DegenerateCurveError, InputTypeError, InvalidInputError

__all__ = ["along_chord", "monotone_pieces", "one_place"]

# how far inside 90 degrees of the chord every chord must turn (as a cosine): far above rounding,
# so that the angle test of a simple piece (widest gap of the chord angles above pi) passes too
_ALONG_MARGIN = 1e-6


def along_chord(points: PointsLike) -> bool:
    """True when every chord ``p_j - p_i`` (``i < j``) of the planar ``points`` runs along ``p_n - p_0``.

    "Along" is a positive dot product with the end-to-end chord beyond ``1e-6`` of the lengths'
    product (within 90 degrees of it, less a margin); chords of length zero are left out, and a
    closed polygon (``p_n == p_0``) is never along. Such a (rational, positive weights) curve is
    monotone along its chord, so it cannot cross itself: a cheap sufficient test, on Python floats,
    for the chords-in-a-half-plane test of the planar self-intersection (which then holds too, with
    the chord's half-plane), where most of a sketch's spans are decided in microseconds.
    ``points`` is a list of ``[x, y]`` (m >= 2), or an array of shape ``(m, 2)``.

    Raises
    ------
    InputTypeError
        If ``points`` is not an array of real numbers (a curve, strings, a ragged list ...).
    ShapeError
        If ``points`` is not of shape ``(m, 2)`` with ``m >= 2``.
    NonFiniteError
        If a coordinate is NaN or infinite.

    Examples
    --------
    >>> along_chord([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])      # an arch
    True
    >>> along_chord([[0.0, 0.0], [3.0, 1.0], [-1.0, 1.0], [2.0, 0.0]])     # a loop: it crosses itself
    False
    >>> along_chord([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: points should have shape (n, 2) with n >= 2, not (2, 3)
    """
    return _along_chord(as_points(points, "points", dim=2, least=2).tolist())


def _along_chord(points: list[list[float]]) -> bool:
    """:func:`along_chord` of valid input, a list of ``[x, y]`` floats (relief_cad's own calls)."""
    x0, y0 = points[0]
    dx = points[-1][0] - x0
    dy = points[-1][1] - y0
    dlen = math.hypot(dx, dy)
    if not dlen > 0.0:
        return False
    for i, (xi, yi) in enumerate(points):
        for xj, yj in points[i + 1:]:
            vx = xj - xi
            vy = yj - yi
            if vx == 0.0 and vy == 0.0:
                continue
            if not vx * dx + vy * dy > _ALONG_MARGIN * math.hypot(vx, vy) * dlen:
                return False
    return True


def _line_of(p: FloatArray, tol: float) -> FloatArray | None:
    """Unit direction of a line through ``p[0]`` that all of ``p`` (m, d) is within ``tol`` of, or None.

    The line runs to the control point farthest from ``p[0]``; the curve lies in the hull of ``p``.
    """
    legs = p - p[0]
    far = np.hypot.reduce(legs, axis=1)  # hypot: no overflow for coordinates up to 1e308
    k = int(np.argmax(far))
    if not far[k] > 0.0:
        return None
    d = legs[k] / far[k]
    off = legs - np.outer(legs @ d, d)
    return d if float(np.hypot.reduce(off, axis=1).max()) <= tol else None


def _fold_split(c: RationalBezier, tol: float) -> float | None:
    """Where a piece lying within ``tol`` of a line turns back along it, in (0, 1); else None.

    Halving such a piece ten times was the cost of a retracing curve (2.6 ms for a quadratic).
    The sense of the line is that of the first control leg that moves along it (a piece cut at a
    fold starts with a vanishing derivative); a fold within 1e-6 of an end is left to halving.
    """
    p = c.control_points
    d = _line_of(p, tol)
    if d is None:
        return None
    along = np.diff(p, axis=0) @ d
    moves = np.flatnonzero(np.abs(along) > 1e-12 * float(np.abs(along).max(initial=0.0)))
    if moves.size == 0:
        return None
    m = fold_bisect(c.homogeneous, d * np.sign(along[moves[0]]), 0.0, 1.0)
    return m if 1e-6 < m < 1.0 - 1e-6 else None


def _runs_one_way(p: FloatArray, tol: float) -> bool:
    """True when ``p`` lies within ``tol`` of a line and no leg runs back along it by more than ``tol``.

    Such a piece meets itself nowhere farther than ``tol`` from its own point (the halves of a fold).
    """
    d = _line_of(p, tol)
    return d is not None and bool((np.diff(p, axis=0) @ d >= -tol).all())


_MOST_CUTS = 48  # cuts per piece at most: a piece of width 2**-48 is a point of the parameter line


def _settled(p: FloatArray, tol: float, depth: int) -> bool:
    """True when a piece cut ``depth`` times may stay whole: no wider than ``tol``, or cut the most."""
    return depth >= _MOST_CUTS or float(np.ptp(p, axis=0).max()) <= tol


def one_place(curve: RationalBezier, t: float, u: float, tol: float) -> bool:
    """True when ``curve`` between ``t`` and ``u`` spans at most ``tol``: a place, not a double point.

    The control points of that arc span at most ``tol`` in every coordinate, so the arc lies in
    a box that small. Pieces cut deep around the sharp tip of a near-cusp meet within tol on both
    sides of it (1.5e-6 apart in parameter, the arc between them 1e-12 long).

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier, or ``t`` or ``u`` not a real number.
    NonFiniteError, InvalidInputError
        If ``t`` or ``u`` is NaN or infinite, or outside ``[0, 1]``.
    DegenerateCurveError
        If ``t == u`` (no arc between them).
    ToleranceError
        If ``tol`` is not a finite distance > 0 (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> c = RationalBezier([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0000001], [2.0, 0.0]])
    >>> one_place(c, 0.4999985, 0.5000015, 1e-9), one_place(c, 0.2, 0.8, 1e-9)
    (True, False)
    >>> one_place(c, 0.2, 1.5, 1e-9)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: u should be a parameter in [0, 1], not 1.5
    """
    checked = check_curve(curve, "curve")
    tv, uv = check_unit(t, "t"), check_unit(u, "u")
    if tv == uv:
        raise DegenerateCurveError("t and u should be two different parameters (the ends of an arc), "
                                   f"not both {tv!r}")
    return _one_place(checked, tv, uv, check_given_tol(tol))


def _one_place(curve: RationalBezier, t: float, u: float, tol: float) -> bool:
    """:func:`one_place` of valid input (relief_cad's own calls: no checks)."""
    arc = curve.segment(min(t, u), max(t, u)).control_points
    return float(np.ptp(arc, axis=0).max()) <= tol


def monotone_pieces(curve: RationalBezier, tol: float, simple: Callable[[FloatArray], bool],
                    max_depth: int) -> list[tuple[float, float, RationalBezier]]:
    """``curve`` cut into pieces that cannot cross themselves: ``(s0, s1, piece)`` sorted by ``s0``.

    Parameters
    ----------
    curve : RationalBezier
    tol : float
        Distance tolerance (model units): how far from a line a straight piece may stray.
    simple : callable
        ``simple(control_points)`` is True for a piece that cannot meet itself.
    max_depth : int
        Cuts per piece (0 to :data:`_MOST_CUTS`) before it may be kept as it is: once its control
        points span at most ``tol`` (a loop in it is below the tolerance), or after
        :data:`_MOST_CUTS` cuts. A piece still larger is cut on: a cubic with a loop of size 1,
        reparameterised by weights ``1e4 ** i``, holds the whole loop within 3e-4 of its start,
        and a piece of width 2**-10 kept whole lost the double point.

    Returns
    -------
    list of (float, float, RationalBezier)
        Each piece with its parameter range ``[s0, s1]`` on ``curve``; the ranges tile ``[0, 1]``.

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier, ``simple`` not callable (or it answers other than
        True or False), or ``max_depth`` not an int.
    DegreeError, InvalidInputError
        If ``max_depth`` is negative, or above :data:`_MOST_CUTS` (48: a piece cut more is a point
        of the parameter line, and the cap of :data:`_MOST_CUTS` cuts would no longer hold).
    ToleranceError
        If ``tol`` is not a finite distance > 0 (:class:`~relief_cad.errors.ToleranceTypeError`
        if it is not a real number).

    Examples
    --------
    >>> line = RationalBezier([[0.0, 0.0], [1.0, 1.0]])
    >>> [(s0, s1) for s0, s1, _ in monotone_pieces(line, 1e-9, lambda p: True, 10)]
    [(0.0, 1.0)]
    >>> monotone_pieces(line, 1e-9, lambda p: True, 10.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: max_depth should be an int >= 0, not float
    """
    checked, tol_v = check_curve(curve, "curve"), check_given_tol(tol)
    if not callable(simple):
        raise InputTypeError("simple should be a callable (control points -> bool), "
                             f"not {type(simple).__name__}")
    depth = check_count(max_depth, "max_depth")
    if depth > _MOST_CUTS:
        raise InvalidInputError(f"max_depth should be an int from 0 to {_MOST_CUTS} (cuts per piece), "
                                f"not {depth}")
    return _monotone_pieces(checked, tol_v, lambda p: check_flag(simple(p), "simple(control_points)"), depth)


def _monotone_pieces(curve: RationalBezier, tol: float, simple: Callable[[FloatArray], bool],
                     max_depth: int) -> list[tuple[float, float, RationalBezier]]:
    """:func:`monotone_pieces` of valid input (relief_cad's own calls: no checks)."""
    pieces: list[tuple[float, float, RationalBezier]] = []
    todo = [(0.0, 1.0, curve, 0, False)]
    while todo:
        s0, s1, c, depth, folded = todo.pop()
        p = c.control_points
        settled = depth >= max_depth and _settled(p, tol, depth)
        if settled or simple(p) or (folded and _runs_one_way(p, tol)):
            pieces.append((s0, s1, c))
            continue
        m = _fold_split(c, tol)
        at = 0.5 if m is None else m
        left, right = c.split(at)
        sm = s0 + at * (s1 - s0) if m is not None else 0.5 * (s0 + s1)
        todo.append((sm, s1, right, depth + 1, folded or m is not None))
        todo.append((s0, sm, left, depth + 1, folded or m is not None))
    pieces.sort(key=lambda x: x[0])
    return pieces

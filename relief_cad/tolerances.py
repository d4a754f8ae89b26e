r"""Named default tolerances (all documented, all overridable per call).

Distances are in model units. When a caller passes ``tol=None`` the
intersectors use :func:`default_tolerance` of the input curves:

.. math::

    \mathrm{tol} = \mathrm{RELATIVE\_TOLERANCE} \cdot \mathrm{size}
        + \mathrm{ROUNDING\_ULPS} \cdot \varepsilon \cdot \max |x|

where ``size`` is the diagonal of the joint bounding box of the *curves themselves*
(sampled at ``min(2 n + 3, 65)`` parameters each, so the cost is O(n^2) in the degree; the
control polygon of an ill-conditioned curve can be a million times larger than the curve) and
``max |x|`` the largest absolute
control-point coordinate (the second term keeps the tolerance above the rounding noise of
the data: curves far from the origin, or evaluated from huge control points). The diagonal is
computed on data scaled by ``max |x|``, so coordinates up to the float range (1e300) do not
overflow it.

>>> import numpy as np
>>> round(default_tolerance(np.array([[0.0, 0.0], [3.0, 4.0]])), 12)
5e-09
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Union, cast

import numpy as np
from numpy.typing import NDArray

from ._kernels.bezier import max_abs, pair_tolerances, pairs_tolerances, sampled_tolerance
from ._types import FloatArray

if TYPE_CHECKING:
    from .curves import RationalBezier

__all__ = [
    "MAX_TOLERANCE_FRACTION",
    "ModelTolerance",
    "PARAMETER_TOLERANCE",
    "RELATIVE_TOLERANCE",
    "ROUNDING_ULPS",
    "default_tolerance",
    "floor_of_magnitude",
    "is_point_like",
    "resolve_tolerance",
    "rounding_floor",
    "size_of",
]

RELATIVE_TOLERANCE: float = 1e-9
"""Default distance tolerance as a fraction of the inputs' size (bounding-box diagonal)."""

ROUNDING_ULPS: float = 64.0
"""Multiple of machine epsilon times the largest coordinate added to the default tolerance."""

PARAMETER_TOLERANCE: float = 1e-15
"""Parameter-space resolution below which two parameters are the same (dimensionless)."""

MAX_TOLERANCE_FRACTION: float = 1e-2
"""Largest accepted tolerance as a fraction of the inputs' size (:func:`size_of`).

A tolerance is the distance below which two points are the same point. Once it is a sizeable
fraction of the curves, whole stretches of them lie within it of each other, the contacts it
defines are no longer isolated, and which ones come out depends on the order of the arguments
(measured on 150 random cubic/quadratic pairs: asymmetric answers for ``intersect(a, b)`` and
``intersect(b, a)`` from 5 % of the size in the plane and in space, none up to 2 %). So a larger
tolerance is refused with :class:`~relief_cad.errors.ToleranceError` instead of answered.
"""

_EPS = float(np.finfo(np.float64).eps)

_SAMPLES = 65
"""Most parameters sampled per curve for its size (keeps the cost O(n^2) in the degree)."""

_PARAMS: list[FloatArray] = []
"""``_PARAMS[m]`` is ``np.linspace(0.0, 1.0, m)`` (read-only): the parameters sampled on a curve."""


def _params() -> list[FloatArray]:
    """:data:`_PARAMS`, made at the first call (in one assignment: another thread sees it empty or whole)."""
    if not _PARAMS:
        _PARAMS[:] = [_linspace(m) for m in range(_SAMPLES + 1)]
    return _PARAMS


def _linspace(m: int) -> FloatArray:
    t = np.linspace(0.0, 1.0, m)
    t.flags.writeable = False
    return t


CurveOrPoints = Union["RationalBezier", FloatArray, Iterable[FloatArray]]


def default_tolerance(*inputs: CurveOrPoints) -> float:
    """Return the default distance tolerance for these curves (or point sets).

    Parameters
    ----------
    *inputs : RationalBezier or ndarray of shape (m, d)
        Every curve taking part; a plain array counts as points (its extent and its
        coordinates both enter as they are).

    Returns
    -------
    float
        A positive distance in model units (see the module docstring), never below
        :func:`rounding_floor` of the inputs (at least ``1e-300``): coincident points at the
        origin, or subnormal coordinates, get ``1e-300``.

    Raises
    ------
    InputTypeError
        If no input is given, or one is neither a curve nor a non-empty array of real numbers.
    ShapeError
        If an array of points is not of shape ``(m, d)``.
    NonFiniteError
        If a point is not finite.

    Examples
    --------
    >>> default_tolerance(np.zeros((2, 2)))
    1e-300
    >>> from relief_cad import RationalBezier
    >>> steep = RationalBezier([[0, 0], [1, 1e6], [2, -1e6], [3, 0]])  # control polygon >> curve
    >>> default_tolerance(steep) < 1e-9 * 1e6
    True
    >>> default_tolerance(steep, np.array([0.0, 1.0]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: inputs[1] should be a RationalBezier or an (m, d) array of points, not an...
    """
    from .curves import RationalBezier

    if inputs and all(isinstance(item, RationalBezier) for item in inputs):
        fast = _sampled_tolerance(cast(tuple[RationalBezier, ...], inputs))
        if fast is not None:
            return fast
    return _general_tolerance(_checked_inputs(inputs, "inputs", "default_tolerance"))


def _general_tolerance(items: tuple[RationalBezier | FloatArray, ...]) -> float:
    """:func:`default_tolerance` of checked inputs, each curve sampled here (the general path)."""
    extents: list[FloatArray] = []
    coords: list[FloatArray] = []
    for item in items:
        if isinstance(item, np.ndarray):
            extents.append(item)
            coords.append(item)
        else:
            extents.append(item.evaluate(np.linspace(0.0, 1.0, min(2 * item.degree + 3, _SAMPLES))))
            coords.append(item.control_points)
    return _tolerance_of(extents, coords)


def _checked_inputs(items: tuple[object, ...], name: str,
                    func: str) -> tuple[RationalBezier | FloatArray, ...]:
    """The curves or arrays of points given to ``func`` as ``*name``, checked (its only check).

    Curves stay as they are; anything else becomes a finite float array of shape ``(m, d)``.
    """
    from .curves import RationalBezier
    from .errors import InputTypeError

    if not items:
        raise InputTypeError(f"{func} needs at least one curve or array of points ({name}), none given")
    return tuple(item if isinstance(item, RationalBezier) else _point_array(item, f"{name}[{k}]")
                 for k, item in enumerate(items))


def _point_array(item: object, name: str) -> FloatArray:
    """``item`` as a finite float array of points of shape ``(m, d)``, ``m, d >= 1``; else the error."""
    from ._checks import as_real_array, check_finite
    from .errors import InputTypeError, ShapeError

    arr = as_real_array(item, name)
    if arr.ndim == 0 or arr.size == 0:
        what = type(item).__name__ if arr.ndim == 0 else f"an empty array of shape {arr.shape}"
        raise InputTypeError(f"{name} should be a RationalBezier or a non-empty (m, d) array of points, "
                             f"not {what}")
    if arr.ndim != 2:
        raise ShapeError(f"{name} should be a RationalBezier or an (m, d) array of points, "
                         f"not an array of shape {arr.shape}")
    check_finite(arr, name)
    return arr


def _sampled_tolerance(curves: tuple[RationalBezier, ...]) -> float | None:
    """:func:`default_tolerance` of curves known to be :class:`~relief_cad.RationalBezier` (hot path).

    Compiled (:func:`relief_cad._kernels.bezier.sampled_tolerance`: the samples, the rule of
    :func:`_tolerance_at` and its order of operations, so the same bits as the general path),
    without :func:`default_tolerance`'s checks of the inputs' types. None when a sample is
    degenerate: then the general path raises or handles it.
    """
    tol: float | None = sampled_tolerance(curves, _params(), _SAMPLES, RELATIVE_TOLERANCE,
                                          ROUNDING_ULPS * _EPS)
    return tol


def _pairs_default_tolerances(pairs: list[tuple[RationalBezier, RationalBezier]]) -> FloatArray:
    """:func:`default_tolerance` of each pair of curves, in one compiled call.

    The values of :func:`_sampled_tolerance`, each curve sampled once and its box cached; a pair
    with a degenerate sample gets the general path.
    """
    tols: FloatArray = pairs_tolerances(pairs, _params(), _SAMPLES, RELATIVE_TOLERANCE, ROUNDING_ULPS * _EPS)
    for k in np.flatnonzero(np.isnan(tols)).tolist():
        tols[k] = default_tolerance(*pairs[k])
    return tols


def _default_tolerances(curve: Callable[[int], RationalBezier], H: FloatArray, P: FloatArray,
                        offsets: NDArray[np.int64], pairs: NDArray[np.int64]) -> FloatArray:
    """:func:`default_tolerance` of each pair of packed planar curves (``pairs``: (p, 2) indexes), at once.

    ``H`` (homogeneous rows), ``P`` (control points) and ``offsets`` hold the curves packed as the
    batch kernel takes them (curve ``k`` is rows ``offsets[k]:offsets[k + 1]``). The same values as
    :func:`_sampled_tolerance` pair by pair (the batch's hot path: no Python per pair); a pair with
    a degenerate sample gets the general path, on the curves ``curve(k)`` gives.
    """
    tols: FloatArray = pair_tolerances(H, P, offsets, pairs, _table(), _SAMPLES, RELATIVE_TOLERANCE,
                                       ROUNDING_ULPS * _EPS)
    for k in np.flatnonzero(np.isnan(tols)).tolist():
        tols[k] = default_tolerance(curve(int(pairs[k, 0])), curve(int(pairs[k, 1])))
    return tols


def _table() -> FloatArray:
    """``_table()[m, :m]`` is ``_params()[m]``: the sampled parameters as one array (made once)."""
    if not _TABLE:
        table = np.zeros((_SAMPLES + 1, _SAMPLES + 1))
        for m, t in enumerate(_params()):
            table[m, :m] = t
        table.flags.writeable = False
        _TABLE[:] = [table]
    return _TABLE[0]


_TABLE: list[FloatArray] = []


def _tolerance_of(extents: list[FloatArray], coords: list[FloatArray]) -> float:
    """The rule of the module docstring, computed on scaled data so that no norm overflows."""
    dim = max(a.shape[1] for a in extents)
    pad = [np.hstack([a, np.zeros((a.shape[0], dim - a.shape[1]))]) for a in extents]
    stacked = np.vstack(pad)
    big = max(float(np.max(np.abs(c))) for c in coords)
    scale = max(big, float(np.max(np.abs(stacked))))
    if scale == 0.0:
        return 1e-300
    return _tolerance_at((stacked.max(axis=0) - stacked.min(axis=0)) / scale, scale, big)


def _tolerance_at(diag: FloatArray, scale: float, big: float) -> float:
    """The rule of the module docstring from the scaled bounding-box diagonal ``diag`` (``scale > 0``).

    The squares of the diagonal's coordinates are summed in coordinate order, as the compiled
    :func:`relief_cad._kernels.bezier.sampled_tolerance` does: the same bits on every machine (a
    BLAS dot product's summation, or fused multiply-adds, depend on the CPU it dispatches to).
    """
    squares = 0.0
    for x in diag.tolist():
        squares = squares + x * x
    size = math.sqrt(squares) * scale
    tol = RELATIVE_TOLERANCE * size + ROUNDING_ULPS * _EPS * big
    if not math.isfinite(tol):
        return _floor_of_magnitude(big)
    # never below the floor (subnormal data: 64 eps * 2e-308 < 1e-300)
    return max(tol, _floor_of_magnitude(big))


def size_of(*curves: RationalBezier | FloatArray) -> float:
    """The diagonal of the joint bounding box of the curves' control points (model units).

    A plain ``(m, d)`` array counts as its points (as in :func:`default_tolerance`).

    Computed on coordinates scaled by the largest one, so it does not overflow up to the float
    range.

    Raises
    ------
    InputTypeError, ShapeError, NonFiniteError
        As for :func:`default_tolerance`.

    Examples
    --------
    >>> from relief_cad import RationalBezier
    >>> size_of(RationalBezier([[0.0, 0.0], [3.0, 4.0]]), RationalBezier([[1e300, 0.0], [0.0, 0.0]]))
    1e+300
    >>> size_of(np.array([[0.0, 0.0], [3.0, np.nan]]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.NonFiniteError: curves[0] should be finite numbers; entry (1, 1) is nan
    """
    return _extent(_checked_inputs(curves, "curves", "size_of"))[0]


def _extent(items: tuple[RationalBezier | FloatArray, ...]) -> tuple[float, float]:
    """``(size, max |x|)`` of the control points: one min and one max per input (cheap: hot path).

    Inputs of fewer dimensions count as lying in ``x_d = 0`` (as :meth:`RationalBezier.embedded`).
    """
    los: list[list[float]] = []
    his: list[list[float]] = []
    for item in items:
        pts = _points_of(item)
        los.append(pts.min(axis=0).tolist())
        his.append(pts.max(axis=0).tolist())
    dim = max(len(lo) for lo in los)
    lo = [min(v[j] if j < len(v) else 0.0 for v in los) for j in range(dim)]
    hi = [max(v[j] if j < len(v) else 0.0 for v in his) for j in range(dim)]
    big = max(max(-x for x in lo), max(hi))
    if big == 0.0:
        return 0.0, 0.0
    return math.hypot(*((h - low) / big for h, low in zip(hi, lo, strict=True))) * big, big


def _points_of(item: RationalBezier | FloatArray) -> FloatArray:
    """The control points of a curve, or an array of points as it is (checked by :func:`_point_array`)."""
    if isinstance(item, np.ndarray):
        return item
    return item.control_points


class ModelTolerance(float):
    """A tolerance already resolved, and capped, for a whole model (the CAD layer's edges together).

    The CAD layer checks its ``tol`` against the size of all the edges taking part, then intersects
    their Bézier segments pair by pair; a sliver segment may be far smaller than that tolerance
    without making it meaningless for the model. Passed as ``tol``, a ``ModelTolerance`` is
    therefore not capped again per pair by :func:`resolve_tolerance` (it is still raised to the
    rounding floor).

    >>> from relief_cad import RationalBezier
    >>> resolve_tolerance(ModelTolerance(1e-7), RationalBezier([[0.0, 0.0], [1e-8, 0.0]]))
    1e-07
    """


def resolve_tolerance(tol: float | None, *curves: RationalBezier | FloatArray) -> float:
    """The tolerance actually used for these curves (model units): what results report as ``tol_used``.

    ``None`` gives :func:`default_tolerance` of the curves; a given ``tol`` (already checked by
    :func:`relief_cad._checks.check_tol`) is raised to :func:`rounding_floor`. A ``tol`` above
    :data:`MAX_TOLERANCE_FRACTION` of :func:`size_of` the curves (and above the rounding floor) is
    refused, unless the curves are a single point, where there is nothing to confuse, or ``tol`` is a
    :class:`ModelTolerance`.

    Raises
    ------
    ToleranceTypeError
        If ``tol`` is neither None nor a real number.
    ToleranceError
        If ``tol`` is not a finite distance > 0, or exceeds ``MAX_TOLERANCE_FRACTION * size_of(*curves)``.
    InputTypeError, ShapeError, NonFiniteError
        For ``curves`` as for :func:`default_tolerance`.

    Examples
    --------
    >>> from relief_cad import RationalBezier
    >>> line = RationalBezier([[0.0, 0.0], [3.0, 4.0]])
    >>> resolve_tolerance(1e-300, line) == rounding_floor(line)
    True
    >>> resolve_tolerance(1.0, line)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be at most 0.01 of the inputs' size (that is 0.05), not 1.0
    >>> resolve_tolerance(float("nan"), line)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not nan
    """
    from ._checks import check_tol

    given = check_tol(tol)
    return _resolve_tolerance(given, *_checked_inputs(curves, "curves", "resolve_tolerance"))


def _resolve_tolerance(tol: float | None, *curves: RationalBezier | FloatArray) -> float:
    """:func:`resolve_tolerance` of a checked ``tol`` and checked curves (relief_cad's own calls)."""
    if tol is None:
        return default_tolerance(*curves)
    if isinstance(tol, ModelTolerance) and not any(isinstance(c, np.ndarray) for c in curves):
        # a model's tolerance is never capped, so only the floor is needed: the largest |x|, compiled
        return max(tol, _floor_of_magnitude(max(max_abs(_points_of(c), 3) for c in curves)))
    size, big = _extent(curves)
    floor = _floor_of_magnitude(big)
    limit = MAX_TOLERANCE_FRACTION * size
    if tol > max(limit, floor) and size > 0.0 and not isinstance(tol, ModelTolerance):
        from .errors import ToleranceError

        raise ToleranceError(f"tol should be at most {MAX_TOLERANCE_FRACTION:g} of the inputs' size "
                             f"(that is {limit:.6g}), not {tol!r}")
    return max(tol, floor)


def is_point_like(curve: RationalBezier, tol: float) -> bool:
    """True when every control point lies within ``tol`` of the first one (model units).

    A rational Bézier curve with positive weights lies in the convex hull of its control points,
    so such a curve is a single point up to ``tol``: it has no self-intersection, and the
    self-intersection paths answer at once instead of subdividing it to their depth limit.

    ``tol`` may be 0 (every control point the same). A curve that is not a
    :class:`~relief_cad.RationalBezier` raises :class:`~relief_cad.errors.InputTypeError`; a ``tol``
    that is not a real number :class:`~relief_cad.errors.ToleranceTypeError`, and one that is not a
    finite distance >= 0 :class:`~relief_cad.errors.ToleranceError`.

    >>> from relief_cad import RationalBezier
    >>> is_point_like(RationalBezier([[1.0, 2.0, 3.0], [1.0, 2.0, 3.0 + 1e-17]]), 1e-12)
    True
    >>> is_point_like(RationalBezier([[1.0, 2.0], [1.0, 2.0]]), -1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance >= 0 in model units, not -1.0
    """
    from ._checks import check_curve, check_distance

    return _is_point_like(check_curve(curve, "curve"), check_distance(tol, "tol"))


def _is_point_like(curve: RationalBezier, tol: float) -> bool:
    """:func:`is_point_like` of a checked curve and ``tol`` (relief_cad's own calls)."""
    pts = curve.control_points
    return bool(np.max(np.abs(pts - pts[0])) <= tol)


def rounding_floor(*curves: RationalBezier | FloatArray) -> float:
    """The rounding level of the data: ``ROUNDING_ULPS * eps * max |x|`` over all control points.

    Every tolerance (given or default) is raised to at least this distance, because points
    computed from such coordinates are only known to about that accuracy: two lines crossing at
    1e-16 apart in rounding are still a crossing. No product is formed, so nothing overflows.

    Raises
    ------
    InputTypeError, ShapeError, NonFiniteError
        As for :func:`default_tolerance`.

    Examples
    --------
    >>> from relief_cad import RationalBezier
    >>> rounding_floor(RationalBezier([[0.0, 0.0], [1.0, 2.0]])) == ROUNDING_ULPS * _EPS * 2.0
    True
    >>> rounding_floor("curve")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: curves[0] should be an array of real numbers, not of str
    """
    return _rounding_floor(*_checked_inputs(curves, "curves", "rounding_floor"))


def _rounding_floor(*curves: RationalBezier | FloatArray) -> float:
    """:func:`rounding_floor` of checked curves (relief_cad's own calls)."""
    return _floor_of_magnitude(_extent(curves)[1])


def floor_of_magnitude(big: float) -> float:
    """The rounding floor of data whose largest coordinate magnitude is ``big`` (model units).

    :func:`rounding_floor` from the magnitude alone, for callers that keep box corners as
    floats: ``rounding_floor(points) == floor_of_magnitude(max |x|)`` to the bit.

    ``big`` should be a finite real number >= 0: else :class:`~relief_cad.errors.InputTypeError`,
    :class:`~relief_cad.errors.NonFiniteError` or :class:`~relief_cad.errors.InvalidInputError`.

    >>> floor_of_magnitude(2.0) == ROUNDING_ULPS * _EPS * 2.0
    True
    >>> floor_of_magnitude(0.0)  # never zero
    1e-300
    >>> floor_of_magnitude(float("inf"))
    Traceback (most recent call last):
    ...
    relief_cad.errors.NonFiniteError: big should be a finite number, not inf
    """
    return _floor_of_magnitude(_magnitude(big))


def _magnitude(big: object) -> float:
    """``big`` as a float, when it is a finite real number >= 0 (a largest coordinate magnitude)."""
    from ._checks import check_param
    from .errors import InvalidInputError

    value = check_param(big, "big")
    if value < 0.0:
        raise InvalidInputError(f"big should be a magnitude >= 0 in model units, not {value!r}")
    return value


def _floor_of_magnitude(big: float) -> float:
    """:func:`floor_of_magnitude` of a checked ``big`` (relief_cad's own calls)."""
    return max(ROUNDING_ULPS * _EPS * big, 1e-300)

"""The one input check of the core's public functions (tolerance, budget, ``on_budget``, curves).

Every public entry point (planar and space alike) checks its arguments here, so the same mistake
gives the same error class and message everywhere:

- a value of the wrong Python type: :class:`~relief_cad.errors.InputTypeError` (a ``TypeError``);
  for ``tol`` that is :class:`~relief_cad.errors.ToleranceTypeError`, also a ``ToleranceError``;
- a tolerance that is not a finite distance > 0: :class:`~relief_cad.errors.ToleranceError`;
- any other value out of range: :class:`~relief_cad.errors.InvalidInputError` (a ``ValueError``).

>>> check_tol(1e-6)
1e-06
>>> check_tol(None) is None
True
>>> check_budget(None) == DEFAULT_BUDGET
True
"""

from __future__ import annotations

import math
import numbers
import os
from typing import TYPE_CHECKING, Any, Literal

import numpy as np
from numpy.typing import NDArray

from ._types import FloatArray
from .errors import (
    DegreeError,
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ShapeError,
    SpanError,
    ToleranceError,
    ToleranceTypeError,
    WeightError,
)
from .tolerances import ModelTolerance

if TYPE_CHECKING:
    from .curves import RationalBezier

__all__ = [
    "DEFAULT_BUDGET",
    "MAX_DEGREE",
    "MAX_WEIGHT_RATIO",
    "OnBudget",
    "as_index_array",
    "as_points",
    "as_real_array",
    "check_degree",
    "check_distance",
    "check_flag",
    "check_finite",
    "check_given_tol",
    "check_param",
    "check_span",
    "check_weights",
    "check_budget",
    "check_count",
    "check_curve",
    "check_on_budget",
    "check_tol",
    "check_unit",
    "check_workers",
]

# Near-tangent crossings (angles down to 1e-8 at the default tolerance) keep the curves within tol
# over a stretch that clipping can only subdivide: measured, 300 000 iterations (0.4 s at worst)
# resolve every such case of a random family; the default leaves headroom and still bounds the work.
DEFAULT_BUDGET: int = 500_000
"""Default cap on clipping iterations per curve pair (each clip or split is one)."""

MAX_BUDGET: int = 2**62
"""Largest accepted budget (it is held in a 64-bit integer by the kernels)."""

OnBudget = Literal["raise", "return"]

MAX_DEGREE: int = 256
"""Largest supported curve degree (constructors, :meth:`~relief_cad.RationalBezier.elevate`,
hodographs). Beyond it evaluation is O(n^2) per point and clipping a pair O(n^3) per step, and the
Bernstein coefficients of binary64 lose all digits (C(n, n/2) > 1e75 at n = 256); measured figures
are in ``workbench/bench_degree.py``. A higher degree raises :class:`~relief_cad.errors.DegreeError`.
"""

MAX_WEIGHT_RATIO: float = 1e15
"""Largest accepted ratio max(w) / min(w) of a curve's weights (dimensionless).

A weight ratio ``r`` moves the curve across a parameter interval of about ``1 / r``; beyond
``1 / PARAMETER_TOLERANCE`` = 1e15 such a feature is below the parameter resolution, so no answer
could honestly be called complete. Scaling all weights by one factor changes nothing, so only the
ratio counts; larger ratios raise :class:`~relief_cad.errors.WeightError`.
"""


def _is_real(value: Any) -> bool:
    """True for ints and floats (Python or numpy), False for bool, str, complex, arrays, None."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def check_curve(c: Any, name: str) -> RationalBezier:
    """Return ``c`` when it is a :class:`~relief_cad.RationalBezier`, else raise ``InputTypeError``.

    >>> check_curve("x", "a")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: a should be a RationalBezier, not str
    """
    if not isinstance(c, _curve_class()):
        raise InputTypeError(f"{name} should be a RationalBezier, not {type(c).__name__}")
    return c


_CURVE_CLASS: list[type[RationalBezier]] = []


def _curve_class() -> type[RationalBezier]:
    """:class:`~relief_cad.RationalBezier`, looked up on first use (curves imports this module)."""
    if not _CURVE_CLASS:
        from .curves import RationalBezier

        _CURVE_CLASS.append(RationalBezier)
    return _CURVE_CLASS[0]


def check_tol(tol: Any, name: str = "tol") -> float | None:
    """Return ``tol`` as a float distance in model units, or ``None`` when it is ``None`` (default).

    Raises
    ------
    ToleranceTypeError
        If ``tol`` is not a real number (``bool``, ``str``, a list, ``complex`` ...).
    ToleranceError
        If ``tol`` is not finite and > 0 (including integers too large for a float).

    Examples
    --------
    >>> check_tol("abc")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceTypeError: tol should be a distance > 0 in model units (a float), not str
    >>> check_tol(0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not 0.0
    """
    return None if tol is None else check_given_tol(tol, name)


def check_given_tol(tol: Any, name: str = "tol") -> float:
    """:func:`check_tol` where there is no default: ``None`` is refused too (a resolved tolerance).

    >>> check_given_tol(None)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceTypeError: tol should be a distance > 0 in model units (a float), not NoneType
    """
    value = _distance(tol, name, False)
    return tol if isinstance(tol, ModelTolerance) else value  # a model's tolerance keeps its type


def _distance(value: Any, name: str, zero_ok: bool) -> float:
    """``value`` as a float distance in model units, finite and > 0 (``>= 0`` with ``zero_ok``)."""
    least = ">= 0" if zero_ok else "> 0"
    if not _is_real(value):
        raise ToleranceTypeError(
            f"{name} should be a distance {least} in model units (a float), not {type(value).__name__}")
    try:
        out = float(value)
    except OverflowError as exc:
        raise ToleranceError(f"{name} should be a finite distance {least} in model units, "
                             f"not an integer of {len(str(abs(int(value))))} digits") from exc
    if not (math.isfinite(out) and (out >= 0.0 if zero_ok else out > 0.0)):
        raise ToleranceError(f"{name} should be a finite distance {least} in model units, not {out!r}")
    return out


def check_distance(value: Any, name: str) -> float:
    """Return a distance that may be zero (a widening, a padding) as a float in model units.

    Raises
    ------
    ToleranceTypeError
        If ``value`` is not a real number (``None``, ``bool``, ``str``, an array ...).
    ToleranceError
        If ``value`` is negative, NaN, infinite or an integer too large for a float.

    Examples
    --------
    >>> check_distance(0, "pad")
    0.0
    >>> check_distance(-1e-3, "pad")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: pad should be a finite distance >= 0 in model units, not -0.001
    """
    return _distance(value, name, True) + 0.0  # -0.0 becomes 0.0


def check_flag(value: Any, name: str) -> bool:
    """Return a yes/no option as a bool; refuse anything but ``True``, ``False`` (or numpy's bools).

    >>> check_flag("no", "perpendicular")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: perpendicular should be True or False, not str
    """
    if not isinstance(value, (bool, np.bool_)):
        raise InputTypeError(f"{name} should be True or False, not {type(value).__name__}")
    return bool(value)


def check_budget(budget: Any) -> int:
    """Return the iteration budget (``None`` gives :data:`DEFAULT_BUDGET`).

    >>> check_budget(0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: budget should be an int from 1 to 2**62, not 0
    """
    if budget is None:
        return DEFAULT_BUDGET
    if isinstance(budget, bool) or not isinstance(budget, numbers.Integral):
        raise InputTypeError(f"budget should be an int from 1 to 2**62, not {type(budget).__name__}")
    value = int(budget)
    if not 1 <= value <= MAX_BUDGET:
        raise InvalidInputError(f"budget should be an int from 1 to 2**62, not {value}")
    return value


def check_workers(workers: Any) -> int:
    """Return the number of worker threads (``None`` gives ``os.cpu_count()``, at least 1).

    >>> check_workers(0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: workers should be an int >= 1 or None, not 0
    """
    if workers is None:
        return max(1, os.cpu_count() or 1)
    if isinstance(workers, bool) or not isinstance(workers, numbers.Integral):
        raise InputTypeError(f"workers should be an int >= 1 or None, not {type(workers).__name__}")
    if workers < 1:
        raise InvalidInputError(f"workers should be an int >= 1 or None, not {int(workers)}")
    return int(workers)


def check_on_budget(on_budget: Any) -> OnBudget:
    """Return ``on_budget`` when it is ``"raise"`` or ``"return"``.

    >>> check_on_budget("ignore")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: on_budget should be 'raise' or 'return', not 'ignore'
    """
    if isinstance(on_budget, str) and on_budget in ("raise", "return"):
        return "raise" if on_budget == "raise" else "return"
    raise InvalidInputError(f"on_budget should be 'raise' or 'return', not {on_budget!r}")


_KIND_NAMES = {"U": "str", "S": "bytes", "c": "complex", "b": "bool", "O": "object"}  # numpy kinds, named


def _array_kind_error(arr: np.ndarray[Any, Any], name: str) -> InputTypeError | None:
    """The error for an array of strings, complex numbers, booleans or other objects, else None."""
    kind = arr.dtype.kind
    if kind in "iuf":
        return None
    if kind == "O":
        bad = [x for x in arr.ravel().tolist() if not _is_real(x)]
        if not bad:
            return None
        what = type(bad[0]).__name__
    else:
        what = _KIND_NAMES.get(kind, str(arr.dtype))
    return InputTypeError(f"{name} should be an array of real numbers, not of {what}")


def as_real_array(value: Any, name: str) -> FloatArray:
    """Return ``value`` as a new C-ordered float64 array; refuse strings, complex numbers, booleans.

    Raises
    ------
    InputTypeError
        For a curve, a ragged list, strings (even numeric ones), complex or boolean entries.
    NonFiniteError
        For integers too large for a float (such as ``10**400``).

    Examples
    --------
    >>> as_real_array([[1, 2.5]], "p").tolist()
    [[1.0, 2.5]]
    >>> as_real_array(["1", "2"], "p")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: p should be an array of real numbers, not of str
    >>> as_real_array([1j, 2], "p")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: p should be an array of real numbers, not of complex
    """
    from .curves import RationalBezier

    if isinstance(value, RationalBezier):
        raise InputTypeError(f"{name} should be an array of numbers, not a {type(value).__name__}")
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError) as exc:
        raise InputTypeError(f"{name} should be an array of real numbers, not a ragged or "
                             f"non-numeric {type(value).__name__}") from exc
    if type(value) in (list, tuple) and raw.dtype == np.float64:
        return raw  # a list of floats: numpy made a new C-ordered array, the one to return
    err = _array_kind_error(raw, name)
    if err is not None:
        raise err
    try:
        return np.array(raw, dtype=np.float64, order="C")
    except OverflowError as exc:
        raise NonFiniteError(f"{name} should be finite numbers; an integer is too large "
                             "for a float") from exc


def as_index_array(value: Any, name: str) -> NDArray[np.int64]:
    """Return ``value`` as a C-ordered int64 array of indices; refuse floats, bools, strings, objects.

    An index is an integer, as numpy's own indexing asks: a float array (even of whole numbers)
    is refused rather than truncated. An empty sequence is taken whatever its dtype.

    Raises
    ------
    InputTypeError
        For a ragged or non-numeric value, or entries that are not integers.

    Examples
    --------
    >>> as_index_array([0, 2, 4], "offsets").tolist()
    [0, 2, 4]
    >>> as_index_array([0.5, 2.0], "offsets")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: offsets should be an array of integers (indices), not of float64
    """
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError) as exc:
        raise InputTypeError(f"{name} should be an array of integers (indices), not a ragged or "
                             f"non-numeric {type(value).__name__}") from exc
    if raw.size and raw.dtype.kind not in "iu":
        what = _KIND_NAMES.get(raw.dtype.kind, str(raw.dtype))
        raise InputTypeError(f"{name} should be an array of integers (indices), not of {what}")
    if raw.dtype.kind == "u" and raw.size and int(raw.max()) > np.iinfo(np.int64).max:
        raise InvalidInputError(f"{name} should be indices below 2**63, not {int(raw.max())}")
    return np.ascontiguousarray(raw, dtype=np.int64)


def as_points(value: Any, name: str, dim: int | None = None, least: int = 0) -> FloatArray:
    """Return points as a new float64 array of shape ``(n, dim)`` (``n >= least``), finite.

    ``dim`` None takes any dimension >= 1. The one check of arrays of points (:func:`as_real_array`,
    the shape, :func:`check_finite`).

    >>> as_points([[0.0, 1.0, 2.0]], "nodes", dim=2, least=2)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: nodes should have shape (n, 2) with n >= 2, not (1, 3)
    """
    arr = as_real_array(value, name)
    if arr.ndim != 2 or arr.shape[0] < least or (arr.shape[1] != dim if dim else arr.shape[1] < 1):
        rules = ([f"n >= {least}"] if least else []) + ([] if dim else ["dim >= 1"])
        raise ShapeError(f"{name} should have shape (n, {dim or 'dim'})"
                         f"{' with ' + ' and '.join(rules) if rules else ''}, not {arr.shape}")
    check_finite(arr, name)
    return arr


def check_finite(arr: FloatArray, name: str) -> None:
    """Raise :class:`~relief_cad.errors.NonFiniteError` naming the first NaN or infinite entry.

    >>> check_finite(np.array([1.0, np.inf]), "t")
    Traceback (most recent call last):
    ...
    relief_cad.errors.NonFiniteError: t should be finite numbers; entry (1,) is inf
    """
    if not np.isfinite(arr).all():
        if arr.ndim == 0:
            raise NonFiniteError(f"{name} should be a finite number, not {float(arr)!r}")
        bad = tuple(int(i) for i in np.argwhere(~np.isfinite(arr))[0])
        raise NonFiniteError(f"{name} should be finite numbers; entry {bad} is {float(arr[bad])!r}")


def check_weights(w: FloatArray, name: str = "weights") -> None:
    """Refuse weights that are not all > 0, or whose ratio exceeds :data:`MAX_WEIGHT_RATIO`.

    >>> check_weights(np.array([1.0, 1e300, 1.0]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.WeightError: weights should have max / min <= 1e+15 (binary64 resolution), not 1e+300
    """
    if not np.all(w > 0.0):
        i = int(np.argmin(w > 0.0))
        raise WeightError(f"{name} should all be > 0; weight {i} is {float(w[i])!r}")
    ratio = float(np.max(w)) / float(np.min(w))
    if not ratio <= MAX_WEIGHT_RATIO:
        raise WeightError(f"{name} should have max / min <= {MAX_WEIGHT_RATIO:g} "
                          f"(binary64 resolution), not {ratio:g}")


def check_degree(degree: int, what: str = "a curve") -> None:
    """Raise :class:`~relief_cad.errors.DegreeError` when ``degree`` exceeds :data:`MAX_DEGREE`.

    >>> check_degree(5000, "elevate")
    Traceback (most recent call last):
    ...
    relief_cad.errors.DegreeError: elevate would give degree 5000; the degree should be at most 256...
    """
    if degree > MAX_DEGREE:
        raise DegreeError(f"{what} would give degree {degree}; the degree should be at most {MAX_DEGREE} "
                          "(the largest supported degree)")


def check_count(value: Any, name: str) -> int:
    """Return a count (an int >= 0, not a bool): a degree increase, a number of pieces.

    Raises
    ------
    InputTypeError
        If ``value`` is not an int (a float, a str, ``None``, a bool).
    DegreeError
        If ``value`` is negative.

    Examples
    --------
    >>> check_count(2.0, "r")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: r should be an int >= 0, not float
    >>> check_count(-1, "r")
    Traceback (most recent call last):
    ...
    relief_cad.errors.DegreeError: r should be an int >= 0, not -1
    """
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise InputTypeError(f"{name} should be an int >= 0, not {type(value).__name__}")
    if value < 0:
        raise DegreeError(f"{name} should be an int >= 0, not {int(value)}")
    return int(value)


def check_param(t: Any, name: str) -> float:
    """Return a curve parameter as a finite float; refuse ``None``, strings, bools, NaN, 10**400.

    >>> check_param("a", "t")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: t should be a real number, not str
    """
    if not _is_real(t):
        raise InputTypeError(f"{name} should be a real number, not {type(t).__name__}")
    try:
        value = float(t)
    except OverflowError as exc:
        raise NonFiniteError(f"{name} should be a finite number, not an integer too large "
                             "for a float") from exc
    if not math.isfinite(value):
        raise NonFiniteError(f"{name} should be a finite number, not {value!r}")
    return value


def check_unit(t: Any, name: str) -> float:
    """Return a curve parameter in ``[0, 1]`` as a float (:func:`check_param`, then the range).

    >>> check_unit(1.5, "t")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: t should be a parameter in [0, 1], not 1.5
    """
    value = check_param(t, name)
    if not 0.0 <= value <= 1.0:
        raise InvalidInputError(f"{name} should be a parameter in [0, 1], not {value!r}")
    return value


def check_span(k: Any) -> float:
    """Return the relief span ``k`` (a real number > 0 and != 1, as the relief perspective needs).

    >>> check_span(1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.SpanError: the span k should be > 0 and != 1, not 1.0
    """
    if not _is_real(k):
        raise InputTypeError(f"the span k should be a real number, not {type(k).__name__}")
    try:
        kv = float(k)
    except OverflowError as exc:
        raise SpanError("the span k should be finite, not an integer too large for a float") from exc
    if not math.isfinite(kv):
        raise SpanError(f"the span k should be finite, not {kv!r}")
    if kv <= 0.0 or kv == 1.0:
        raise SpanError(f"the span k should be > 0 and != 1, not {kv!r}")
    return kv

"""Exceptions raised by relief_cad.

Every error relief_cad raises on purpose derives from :class:`ReliefCadError`
*and* from the matching built-in exception, so callers can catch either
``ReliefCadError`` or, say, ``ValueError``.

>>> from relief_cad.errors import WeightError, ReliefCadError
>>> issubclass(WeightError, ValueError) and issubclass(WeightError, ReliefCadError)
True
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "AdapterUnavailableError",
    "BudgetExceededError",
    "DegenerateCurveError",
    "DegreeError",
    "InputTypeError",
    "InvalidInputError",
    "NoNeutralPlaneError",
    "NonFiniteError",
    "OcctError",
    "ProjectionError",
    "ReliefCadError",
    "ShapeError",
    "SpanError",
    "ToleranceError",
    "ToleranceTypeError",
    "UnsupportedCurveError",
    "WeightError",
]


class ReliefCadError(Exception):
    """Root of every error relief_cad raises on purpose.

    >>> from relief_cad import RationalBezier
    >>> try:
    ...     RationalBezier([[0, 0]])
    ... except ReliefCadError as exc:
    ...     print(type(exc).__name__)
    DegreeError
    """


class InvalidInputError(ReliefCadError, ValueError):
    """A value is outside what the function accepts.

    >>> issubclass(InvalidInputError, ValueError)
    True
    """


class NonFiniteError(InvalidInputError):
    """A coordinate, weight or parameter is NaN or infinite.

    >>> from relief_cad import RationalBezier
    >>> RationalBezier([[0, 0], [1, float('nan')]])
    Traceback (most recent call last):
    ...
    relief_cad.errors.NonFiniteError: control_points should be finite numbers; entry (1, 1) is nan
    """


class ShapeError(InvalidInputError):
    """An array has the wrong number of dimensions or the wrong length.

    >>> from relief_cad import RationalBezier
    >>> RationalBezier([[0, 0, 0, 0], [1, 1, 1, 1]])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: control_points should have shape (n + 1, 2) or (n + 1, 3), not (2, 4)
    """


class WeightError(InvalidInputError):
    """A rational weight is zero or negative (weights must be > 0).

    >>> from relief_cad import RationalBezier
    >>> RationalBezier([[0, 0], [1, 1]], [1.0, -1.0])
    Traceback (most recent call last):
    ...
    relief_cad.errors.WeightError: weights should all be > 0; weight 1 is -1.0
    """


class DegreeError(InvalidInputError):
    """A curve's degree is not allowed here (e.g. degree 0 where a curve is needed).

    >>> issubclass(DegreeError, ValueError)
    True
    """


class DegenerateCurveError(InvalidInputError):
    """A curve or edge is degenerate (zero length, point-like) where that is not allowed.

    >>> from relief_cad import RationalBezier
    >>> RationalBezier([[0, 0], [1, 1]]).segment(0.5, 0.5)
    Traceback (most recent call last):
    ...
    relief_cad.errors.DegenerateCurveError: segment needs t0 != t1, got t0 = t1 = 0.5
    """


class ToleranceError(InvalidInputError):
    """A tolerance is not a finite positive distance.

    >>> from relief_cad import RationalBezier, intersect
    >>> line = RationalBezier([[0, 0], [1, 1]])
    >>> intersect(line, line, tol=-1.0)  # doctest: +IGNORE_EXCEPTION_DETAIL
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0
    """


class SpanError(InvalidInputError):
    """The span ``k`` of a relief perspective is not > 0 and != 1.

    >>> from relief_cad import ReliefPerspective
    >>> ReliefPerspective(-1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.SpanError: the span k should be > 0 and != 1, not -1.0
    """


class ProjectionError(InvalidInputError):
    """A point or control point lies behind (or on) a projection centre or on a singular plane.

    >>> from relief_cad import central_projection
    >>> central_projection([0.0, 0.0, -1.0])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ProjectionError: points should lie in front of the centre (z > 0); point 0 has z = -1.0
    """


class NoNeutralPlaneError(InvalidInputError):
    """A space curve has no neutral plane: it is not of the paper's form in any frame.

    >>> issubclass(NoNeutralPlaneError, ValueError)
    True
    """


class InputTypeError(ReliefCadError, TypeError):
    """An argument has a Python type the function does not accept.

    >>> from relief_cad import lift
    >>> lift('curve')
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: the curve to lift should be a RationalBezier, not str
    """


class ToleranceTypeError(ToleranceError, InputTypeError):
    """A tolerance of the wrong Python type (not a real number): both a ``ValueError`` and a ``TypeError``.

    >>> from relief_cad import RationalBezier, intersect
    >>> line = RationalBezier([[0, 0], [1, 1]])
    >>> intersect(line, line, tol="1e-9")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceTypeError: tol should be a distance > 0 in model units (a float), not str
    """


class UnsupportedCurveError(ReliefCadError, TypeError):
    """A CAD curve type relief_cad cannot convert exactly (and no approximation was allowed).

    >>> issubclass(UnsupportedCurveError, TypeError)
    True
    """


class AdapterUnavailableError(ReliefCadError, ImportError):
    """A CAD package needed by an adapter is not installed.

    >>> issubclass(AdapterUnavailableError, ImportError)
    True
    """


class OcctError(ReliefCadError, RuntimeError):
    """OpenCASCADE failed on an operation relief_cad asked of it.

    >>> issubclass(OcctError, RuntimeError)
    True
    """


class BudgetExceededError(ReliefCadError, RuntimeError):
    """An iteration or subdivision budget ran out before every parameter box was resolved.

    >>> err = BudgetExceededError("budget", unresolved=[(0.0, 0.5, 0.0, 1.0)])
    >>> isinstance(err, RuntimeError), err.unresolved
    (True, [(0.0, 0.5, 0.0, 1.0)])

    Attributes
    ----------
    partial : list
        The results found before the budget ran out (already validated).
    unresolved : list of tuple
        The parameter boxes ``(t0, t1, u0, u1)`` that were not resolved, in
        each input's own parameterisation.
    """

    def __init__(self, message: str, *, partial: Any = None, unresolved: Any = None) -> None:
        super().__init__(message)
        self.partial = [] if partial is None else partial
        self.unresolved = [] if unresolved is None else unresolved

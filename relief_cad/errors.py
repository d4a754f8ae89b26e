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
    "UnsupportedCurveError",
    "WeightError",
]


class ReliefCadError(Exception):
    """Root of every error relief_cad raises on purpose."""


class InvalidInputError(ReliefCadError, ValueError):
    """A value is outside what the function accepts."""


class NonFiniteError(InvalidInputError):
    """A coordinate, weight or parameter is NaN or infinite."""


class ShapeError(InvalidInputError):
    """An array has the wrong number of dimensions or the wrong length."""


class WeightError(InvalidInputError):
    """A rational weight is zero or negative (weights must be > 0)."""


class DegreeError(InvalidInputError):
    """A curve's degree is not allowed here (e.g. degree 0 where a curve is needed)."""


class DegenerateCurveError(InvalidInputError):
    """A curve or edge is degenerate (zero length, point-like) where that is not allowed."""


class ToleranceError(InvalidInputError):
    """A tolerance is not a finite positive distance."""


class SpanError(InvalidInputError):
    """The span ``k`` of a relief perspective is not > 0 and != 1."""


class ProjectionError(InvalidInputError):
    """A point or control point lies behind (or on) a projection centre or on a singular plane."""


class NoNeutralPlaneError(InvalidInputError):
    """A space curve has no neutral plane: it is not of the paper's form in any frame."""


class InputTypeError(ReliefCadError, TypeError):
    """An argument has a Python type the function does not accept."""


class UnsupportedCurveError(ReliefCadError, TypeError):
    """A CAD curve type relief_cad cannot convert exactly (and no approximation was allowed)."""


class AdapterUnavailableError(ReliefCadError, ImportError):
    """A CAD package needed by an adapter is not installed."""


class OcctError(ReliefCadError, RuntimeError):
    """OpenCASCADE failed on an operation relief_cad asked of it."""


class BudgetExceededError(ReliefCadError, RuntimeError):
    """An iteration or subdivision budget ran out before every parameter box was resolved.

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

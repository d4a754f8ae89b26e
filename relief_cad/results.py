"""Result types of the intersectors.

Parameters are always reported in each input's own parameterisation: for a
:class:`~relief_cad.RationalBezier` that is its ``t`` in ``[0, 1]``; the CAD
adapters map them to the edge's own OCCT parameter.

>>> import numpy as np
>>> hit = Intersection(t=0.5, u=0.25, point=np.array([1.0, 2.0]), kind="crossing")
>>> hit.kind, hit.t, hit.u
('crossing', 0.5, 0.25)
>>> Overlap(t=(0.0, 0.5), u=(1.0, 0.5)).reversed_direction
True
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Literal, Union

import numpy as np

from ._types import FloatArray
from .errors import BudgetExceededError, InputTypeError

__all__ = [
    "Intersection",
    "IntersectionList",
    "Overlap",
    "ParameterBox",
    "Result",
    "finish",
]

ContactKind = Literal["crossing", "tangent"]


@dataclass(frozen=True)
class Intersection:
    """An isolated common point of two curves (or a double point of one).

    >>> from relief_cad import RationalBezier, intersect
    >>> hit = intersect(RationalBezier([[0, 0], [2, 2]]), RationalBezier([[0, 2], [2, 0]]))[0]
    >>> hit.t, hit.u, hit.point.tolist(), hit.kind
    (0.5, 0.5, [1.0, 1.0], 'crossing')

    Attributes
    ----------
    t : float
        Parameter on the first curve.
    u : float
        Parameter on the second curve (for self-intersections, ``t < u``).
    point : ndarray, shape (d,)
        The intersection point in model units (the mean of ``a(t)`` and ``b(u)``); read-only
        in the results of the intersectors (each point its own array).
    kind : {"crossing", "tangent"}
        ``"crossing"`` for a transversal meeting, ``"tangent"`` for a tangent
        contact or a near-miss closer than the tolerance.
    distance : float
        ``|a(t) - b(u)|`` in model units (0 up to rounding for true meetings;
        the gap for a near-miss contact).
    """

    t: float
    u: float
    point: FloatArray
    kind: ContactKind
    distance: float = 0.0

    def __repr__(self) -> str:
        pt = ", ".join(f"{float(c):.17g}" for c in np.asarray(self.point))
        return (
            f"Intersection(t={self.t!r}, u={self.u!r}, point=({pt}), kind={self.kind!r}"
            + (f", distance={self.distance:.3g}" if self.distance else "")
            + ")"
        )


@dataclass(frozen=True)
class Overlap:
    """A stretch along which two curves coincide.

    >>> from relief_cad import RationalBezier, intersect
    >>> line = RationalBezier([[0, 0], [4, 0]])
    >>> intersect(line, RationalBezier([[3, 0], [1, 0]]))
    [Overlap(t=(0.25, 0.75), u=(1.0, 0.0), kind='overlap')]

    ``a(t[0]) == b(u[0])`` and ``a(t[1]) == b(u[1])`` with ``t[0] < t[1]``; so
    ``u[0] > u[1]`` when ``b`` runs against ``a``.

    Attributes
    ----------
    t : tuple of float
        Parameter interval ``(t0, t1)`` on the first curve, ``t0 < t1``.
    u : tuple of float
        Matching parameters ``(u0, u1)`` on the second curve.
    kind : "overlap"
        Always ``"overlap"``.
    """

    t: tuple[float, float]
    u: tuple[float, float]
    kind: Literal["overlap"] = field(default="overlap")

    @property
    def reversed_direction(self) -> bool:
        """True when the second curve runs against the first along the overlap.

        >>> Overlap(t=(0.25, 0.75), u=(0.0, 1.0)).reversed_direction
        False
        """
        return self.u[1] < self.u[0]


Result = Union[Intersection, Overlap]


@dataclass(frozen=True)
class ParameterBox:
    """A parameter rectangle ``[t0, t1] x [u0, u1]`` left unresolved by a budget.

    >>> ParameterBox(0.0, 0.5, 0.25, 1.0).t1
    0.5
    """

    t0: float
    t1: float
    u0: float
    u1: float


class IntersectionList(list[Result]):
    """The results of an intersection, sorted by ``t``, plus what was left unresolved.

    A plain ``list`` of :class:`Intersection` and :class:`Overlap` objects with two
    extra attributes: :attr:`unresolved`, the parameter boxes a budget left open
    (empty when the answer is complete), and :attr:`tol_used`, the distance tolerance
    (model units) the intersector actually used: the given ``tol`` raised to the
    rounding floor of the data, or the default (:func:`relief_cad.tolerances.resolve_tolerance`).
    Every :class:`Intersection` in the list has ``distance <= tol_used``; ``nan`` for a
    list built by hand.

    >>> IntersectionList([]).complete
    True
    >>> from relief_cad import RationalBezier, intersect
    >>> res = intersect(RationalBezier([[-2, 0.3], [2, -0.2]]), RationalBezier([[0.1, -2], [0.2, 2]]),
    ...                 tol=1e-300)   # far below the rounding of the data: raised to it
    >>> len(res), res.tol_used > 1e-300, res[0].distance <= res.tol_used
    (1, True, True)
    """

    __slots__ = ("unresolved", "tol_used")
    unresolved: tuple[ParameterBox, ...]
    tol_used: float

    def __init__(self, items: Iterable[Result] = (), unresolved: Iterable[ParameterBox] = (),
                 tol_used: float = math.nan) -> None:
        list.__init__(self, items)
        self.unresolved = unresolved if type(unresolved) is tuple else tuple(unresolved)
        self.tol_used = tol_used

    @property
    def complete(self) -> bool:
        """True when no budget ran out (every parameter box was resolved).

        >>> IntersectionList([], unresolved=[ParameterBox(0.0, 1.0, 0.0, 1.0)]).complete
        False
        """
        return not self.unresolved

    @property
    def points(self) -> list[Intersection]:
        """The isolated points only.

        >>> IntersectionList([Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]).points
        []
        """
        return [r for r in self if isinstance(r, Intersection)]

    @property
    def overlaps(self) -> list[Overlap]:
        """The overlaps only.

        >>> len(IntersectionList([Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]).overlaps)
        1
        """
        return [r for r in self if isinstance(r, Overlap)]


def finish(result: IntersectionList, on_budget: str) -> IntersectionList:
    """Return ``result``, or raise when a budget left boxes open and ``on_budget == "raise"``.

    Raises
    ------
    BudgetExceededError
        Carrying the results found (``.partial``) and the open boxes (``.unresolved``).
    InputTypeError
        If ``result`` is not an :class:`IntersectionList`.
    InvalidInputError
        If ``on_budget`` is neither ``"raise"`` nor ``"return"``.

    Examples
    --------
    >>> finish(IntersectionList([]), "raise").complete
    True
    >>> finish(IntersectionList([]), "ignore")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: on_budget should be 'raise' or 'return', not 'ignore'
    """
    from ._checks import check_on_budget  # here, not above: _checks imports (through _kernels) this module

    if not isinstance(result, IntersectionList):
        raise InputTypeError(f"result should be an IntersectionList, not {type(result).__name__}")
    return _finish(result, check_on_budget(on_budget))


def _finish(result: IntersectionList, on_budget: str) -> IntersectionList:
    """:func:`finish` of valid input (relief_cad's own calls: no checks)."""
    if result.unresolved and on_budget == "raise":
        raise BudgetExceededError(
            f"the iteration budget ran out with {len(result.unresolved)} parameter box(es) "
            "unresolved; pass a larger budget= or on_budget='return'",
            partial=list(result),
            unresolved=list(result.unresolved),
        )
    return result

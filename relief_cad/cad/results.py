"""Rich result types of the CAD adapters: which edges met, where, on their own parameters.

:func:`relief_cad.cad.intersections` returns a list of :class:`EdgeIntersection`
(isolated common points) and :class:`EdgeOverlap` (stretches where two edges
coincide). Every parameter is the edge's own OCCT parameter (what
``BRepAdaptor_Curve(edge).Value(t)`` takes), never a Bézier segment's ``[0, 1]``
parameter, and the edges are returned in the caller's flavour (build123d
``Edge``, CadQuery ``Edge`` or raw ``TopoDS_Edge``).

Edge indices count the *unique* edges of each input shape in ``TopExp_Explorer``
order, with repeated occurrences of the same edge (``IsSame``) removed: that is
the list :func:`relief_cad.cad.ocp.edges_of` returns.

>>> hit = EdgeIntersection(index_a=0, index_b=1, edge_a=None, edge_b=None,
...                        t=0.5, u=2.0, point=(1.0, 0.0, 0.0), kind="crossing")
>>> hit.kind, hit.route, hit.approximate
('crossing', 'relief_cad', False)
>>> EdgeOverlap(index_a=0, index_b=0, edge_a=None, edge_b=None,
...             t=(0.0, 1.0), u=(3.0, 2.0), edge=None).reversed_direction
True
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any, Literal, Union

__all__ = ["EdgeIntersection", "EdgeOverlap", "EdgeResult", "EdgeResultList"]


@dataclass(frozen=True)
class EdgeIntersection:
    """An isolated common point of two edges (or a double point of one edge).

    >>> import build123d as bd
    >>> from relief_cad.cad import intersections
    >>> hit = intersections(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))[0]
    >>> hit.kind, round(hit.t, 12), tuple(round(c, 12) for c in hit.point)
    ('crossing', 1.414213562373, (1.0, 1.0, 0.0))

    Attributes
    ----------
    index_a : int
        Index of the first edge in the unique-edge list of shape ``a``
        (``TopExp_Explorer`` order, duplicates removed with ``IsSame``).
    index_b : int
        Index of the second edge in the unique-edge list of shape ``b``; for
        self-intersections (``b=None``) an index in ``a``'s list, with
        ``index_a <= index_b``.
    edge_a, edge_b : Any
        The two native edges, in the flavour of the input (build123d ``Edge``,
        CadQuery ``Edge`` or ``TopoDS_Edge``).
    t : float
        The edge's own OCCT parameter on ``edge_a`` (inside its parameter range;
        the edge's orientation does not change it).
    u : float
        The edge's own OCCT parameter on ``edge_b``. For an edge crossing itself
        (``index_a == index_b``), ``t < u``.
    point : tuple of float
        The common point ``(x, y, z)`` in model units (global coordinates, the
        edges' locations applied).
    kind : {"crossing", "tangent"}
        ``"crossing"`` for a transversal meeting, ``"tangent"`` for a tangent
        contact or a near miss closer than the tolerance.
    distance : float
        The gap ``|a(t) - b(u)|`` in model units (0 up to rounding for true
        meetings).
    approximate : bool
        True when one of the edges was converted by approximation (offset
        curves, curves on surfaces...); the point is then only as good as the
        stated approximation tolerance.
    route : str
        Who computed the result: ``"relief_cad"`` or the name of an OCCT route.
    """

    index_a: int
    index_b: int
    edge_a: Any
    edge_b: Any
    t: float
    u: float
    point: tuple[float, float, float]
    kind: Literal["crossing", "tangent"]
    distance: float = 0.0
    approximate: bool = False
    route: str = "relief_cad"


@dataclass(frozen=True)
class EdgeOverlap:
    """A stretch along which two edges coincide.

    >>> import build123d as bd
    >>> from relief_cad.cad import intersections
    >>> ov = intersections(bd.Line((0, 0), (4, 0)), bd.Line((3, 0), (1, 0)))[0]
    >>> ov.kind, ov.t, ov.u, round(ov.edge.length, 12)
    ('overlap', (1.0, 3.0), (2.0, 0.0), 2.0)

    Attributes
    ----------
    index_a, index_b : int
        Edge indices, as in :class:`EdgeIntersection`.
    edge_a, edge_b : Any
        The two native edges.
    t : tuple of float
        Edge parameters ``(t0, t1)`` on ``edge_a``, ``t0 < t1``.
    u : tuple of float
        Matching edge parameters ``(u0, u1)`` on ``edge_b``: ``a(t0) = b(u0)`` and
        ``a(t1) = b(u1)`` (so ``u0 > u1`` when ``b`` runs against ``a``).
    edge : Any
        The common part as a native edge (``edge_a`` trimmed to ``[t0, t1]``).
    kind : "overlap"
        Always ``"overlap"``.
    approximate : bool
        True when one of the edges was converted by approximation.
    route : str
        Who computed the result.
    """

    index_a: int
    index_b: int
    edge_a: Any
    edge_b: Any
    t: tuple[float, float]
    u: tuple[float, float]
    edge: Any
    kind: Literal["overlap"] = field(default="overlap")
    approximate: bool = False
    route: str = "relief_cad"

    @property
    def reversed_direction(self) -> bool:
        """True when ``edge_b`` runs against ``edge_a`` along the overlap.

        >>> import build123d as bd
        >>> from relief_cad.cad import intersections
        >>> intersections(bd.Line((0, 0), (4, 0)), bd.Line((3, 0), (1, 0)))[0].reversed_direction
        True
        """
        return self.u[1] < self.u[0]


EdgeResult = Union[EdgeIntersection, EdgeOverlap]
"""One result of :func:`relief_cad.cad.intersections`."""


class EdgeResultList(list[EdgeResult]):
    """The results of :func:`relief_cad.cad.intersections`: a plain list plus ``tol_used``.

    ``tol_used`` is the distance tolerance (model units) actually applied to the whole model:
    the given ``tol`` (checked against the edges' size and raised to the rounding floor of their
    coordinates) or the CAD default. Every :class:`EdgeIntersection` has ``distance <= tol_used``.

    >>> import build123d as bd
    >>> from relief_cad.cad import intersections
    >>> res = intersections(bd.Line((-2, 0.3), (2, -0.2)), bd.Line((0.1, -2), (0.2, 2)), tol=1e-300)
    >>> len(res), res.tol_used > 1e-300
    (1, True)
    """

    tol_used: float

    def __init__(self, items: Iterable[EdgeResult] = (), tol_used: float = math.nan) -> None:
        super().__init__(items)
        self.tol_used = tol_used

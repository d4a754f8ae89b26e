"""Shapes in: the one path from a build123d / CadQuery / OCP shape to its edges.

Every public function of :mod:`relief_cad.cad` (the intersector, the OCCT cross-check and
the comparison) reads its inputs through :func:`edges_of`, so all of them accept the same
inputs (an edge, a wire, a face, a solid, a compound, a CadQuery ``Workplane``, or a list of
any of these) and number the edges the same way: ``index_a`` / ``index_b`` of every result
is a position in ``edges_of(shape)``.

Edges that cannot take part are recognised here, once:

* degenerated edges (a sphere's poles, a cone's apex) are points, not curves:
  :func:`usable_edges` leaves them out and says which ones it left out;
* edges on an unbounded curve (an infinite parameter range, e.g. ``BRepBuilderAPI_MakeEdge``
  of a whole ``gp_Lin``) are refused with :class:`~relief_cad.errors.ShapeError`: relief_cad
  does not guess a finite piece of them. Trim the edge first.

>>> from OCP.BRepPrimAPI import BRepPrimAPI_MakeSphere
>>> edges, skipped = usable_edges(BRepPrimAPI_MakeSphere(1.0).Shape(), "a")
>>> len(edges_of(BRepPrimAPI_MakeSphere(1.0).Shape())), [i for i, _ in edges], [i for i, _ in skipped]
(3, [1], [0, 2])
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from typing import Any

from OCP.BRep import BRep_Builder, BRep_Tool
from OCP.Precision import Precision
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp
from OCP.TopoDS import TopoDS_Compound, TopoDS_Edge, TopoDS_Shape

from ..errors import InputTypeError, ShapeError
from ._compat import IndexedMapOfShape, downcast_edge

__all__ = ["Skipped", "as_edge", "check_bounded", "edges_of", "make_compound", "unwrap", "usable_edges"]

Skipped = tuple[int, str]
"""``(index, reason)`` of an edge left out (its position in :func:`edges_of` and why)."""


def _wrapped(obj: Any) -> Any:
    """``obj.wrapped`` without touching an empty build123d shape's wrapper (it asserts)."""
    if "_wrapped" in getattr(obj, "__dict__", {}) and obj.__dict__["_wrapped"] is None:
        return make_compound([])  # an empty build123d shape (e.g. ``Compound()``) has no edges
    return getattr(obj, "wrapped", None)


def unwrap(obj: Any) -> TopoDS_Shape:
    """Return the raw ``TopoDS_Shape`` of a build123d / CadQuery shape (or the shape itself).

    Lists and tuples of shapes become one compound; a CadQuery ``Workplane``
    contributes the shapes on its stack; an empty build123d shape (``Compound()``)
    becomes an empty compound.

    Raises
    ------
    InputTypeError
        If ``obj`` is not a shape (or a sequence of shapes), or is a null shape.

    Examples
    --------
    >>> unwrap(42)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: expected a TopoDS_Shape, a build123d or CadQuery shape, ...
    """
    if isinstance(obj, TopoDS_Shape):
        shape = obj
    elif isinstance(wrapped := _wrapped(obj), TopoDS_Shape):
        shape = wrapped
    elif hasattr(obj, "vals") and callable(obj.vals) and type(obj).__name__ == "Workplane":
        shape = make_compound([unwrap(v) for v in obj.vals() if hasattr(v, "wrapped")])
    elif isinstance(obj, (list, tuple)):
        shape = make_compound([unwrap(v) for v in obj])
    else:
        raise InputTypeError(
            "expected a TopoDS_Shape, a build123d or CadQuery shape, or a list of them; "
            f"received {type(obj).__name__}"
        )
    if shape.IsNull():
        raise InputTypeError("expected a non-null shape; received a null TopoDS_Shape")
    return shape


def make_compound(shapes: Iterable[TopoDS_Shape]) -> TopoDS_Compound:
    """Return a compound holding ``shapes`` (raw OCP shapes).

    Examples
    --------
    >>> make_compound([]).NbChildren()
    0
    """
    builder = BRep_Builder()
    comp = TopoDS_Compound()
    builder.MakeCompound(comp)
    for s in shapes:
        builder.Add(comp, s)
    return comp


def edges_of(shape: Any) -> list[TopoDS_Edge]:
    """Return the unique edges of a shape, in ``TopExp_Explorer`` order.

    Repeated occurrences of one edge (``IsSame``: same TShape and location,
    any orientation, e.g. a seam or an edge shared by two faces) appear once, at
    their first position. Degenerated edges (poles of spheres...) are kept here;
    :func:`usable_edges` leaves them out.

    Parameters
    ----------
    shape : TopoDS_Shape, build123d / CadQuery shape, Workplane, or a list of them
        Any shape; an edge gives a one-element list.

    Returns
    -------
    list of TopoDS_Edge

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakePolygon
    >>> from OCP.gp import gp_Pnt
    >>> poly = BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0), gp_Pnt(1, 1, 0), True)
    >>> len(edges_of(poly.Wire())), len(edges_of(make_compound([])))
    (3, 0)
    """
    raw = unwrap(shape)
    if isinstance(raw, TopoDS_Edge):
        return [raw]
    emap = IndexedMapOfShape()
    TopExp.MapShapes_s(raw, TopAbs_EDGE, emap)
    return [downcast_edge(emap.FindKey(i)) for i in range(1, emap.Extent() + 1)]


def check_bounded(edge: TopoDS_Edge, what: str = "an edge") -> tuple[float, float]:
    """Return the edge's parameter range, refusing an unbounded one.

    Raises
    ------
    ShapeError
        If either end of the range is infinite (an edge on a whole line or parabola).

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Dir, gp_Lin, gp_Pnt
    >>> check_bounded(BRepBuilderAPI_MakeEdge(gp_Lin(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))).Edge())
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: expected an edge with a bounded parameter range; received ...
    """
    first, last = BRep_Tool.Range_s(edge)
    if not (math.isfinite(first) and math.isfinite(last)) or Precision.IsInfinite_s(first) or \
            Precision.IsInfinite_s(last):  # OCCT's "infinite" is Precision::Infinite() = 2e100
        raise ShapeError(
            f"expected {what} with a bounded parameter range; received [{first}, {last}] (an edge on an "
            "unbounded curve, e.g. a whole line): trim it to the part you need first"
        )
    return float(first), float(last)


def usable_edges(shape: Any, name: str) -> tuple[list[tuple[int, TopoDS_Edge]], list[Skipped]]:
    """Return the edges of ``shape`` that take part, with their indices, and those left out.

    Parameters
    ----------
    shape : any input :func:`edges_of` accepts
    name : str
        The argument's name (``"a"`` or ``"b"``), for messages.

    Returns
    -------
    edges : list of (int, TopoDS_Edge)
        Index in :func:`edges_of` order and the edge, for every non-degenerated edge.
    skipped : list of (int, str)
        Index and reason of every degenerated edge (a point: a sphere's pole, a cone's apex).

    Raises
    ------
    ShapeError
        If no edge with a curve is left, or an edge is unbounded (see :func:`check_bounded`).

    Examples
    --------
    >>> usable_edges(make_compound([]), "a")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: expected shape a to have at least one edge with a curve; it has no edges
    """
    edges: list[tuple[int, TopoDS_Edge]] = []
    skipped: list[Skipped] = []
    for index, edge in enumerate(edges_of(shape)):
        if BRep_Tool.Degenerated_s(edge):
            skipped.append((index, "degenerated edge (a point, e.g. a pole or an apex)"))
            continue
        check_bounded(edge, f"every edge of shape {name}")
        edges.append((index, edge))
    if not edges:
        detail = f"none ({len(skipped)} degenerated)" if skipped else "no edges"
        raise ShapeError(f"expected shape {name} to have at least one edge with a curve; it has {detail}")
    return edges, skipped


def as_edge(edge: Any) -> TopoDS_Edge:
    """Return the raw ``TopoDS_Edge`` of one edge (OCP, build123d or CadQuery).

    Raises
    ------
    InputTypeError
        If ``edge`` is not an edge (a wire, a face... or not a shape).

    Examples
    --------
    >>> as_edge(make_compound([]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: expected an edge; received a compound shape ...
    """
    raw = edge if isinstance(edge, TopoDS_Shape) else _wrapped(edge)
    if not isinstance(raw, TopoDS_Shape):
        raise InputTypeError(
            f"expected an edge (TopoDS_Edge or a build123d / CadQuery Edge); received {type(edge).__name__}"
        )
    if raw.IsNull():
        raise InputTypeError("expected an edge; received a null shape")
    if not isinstance(raw, TopoDS_Edge):
        if raw.ShapeType() == TopAbs_EDGE:
            return downcast_edge(raw)  # type: ignore[no-any-return]
        raise InputTypeError(
            f"expected an edge; received a {raw.ShapeType().name.replace('TopAbs_', '').lower()} shape "
            "(use edges_of() or the intersection functions for wires, faces and solids)"
        )
    return raw

"""Results out: native build123d / CadQuery / OCP objects, matching the input's library.

Every public function of :mod:`relief_cad.cad` returns vertices and edges in the flavour of
its input: :func:`flavour_of` tells which library an input comes from, and
:func:`wrap_vertices`, :func:`wrap_edge` and :func:`wrap_edges` turn raw ``TopoDS_*``
objects into that library's objects. This module imports build123d or CadQuery only when a
result of that flavour is wrapped, and never imports :mod:`.api` (nor the flavour faces
:mod:`.build123d` and :mod:`.cadquery`, which are built on :mod:`.api`): no import cycle.

>>> flavour_of([]), wrap_vertices([], "ocp")
('ocp', [])
"""

from __future__ import annotations

import importlib
from typing import Any, Literal

__all__ = ["Flavour", "flavour_of", "native_library", "wrap_edge", "wrap_edges", "wrap_vertices"]

Flavour = Literal["build123d", "cadquery", "ocp"]


def flavour_of(obj: Any) -> Flavour:
    """Return ``"build123d"``, ``"cadquery"`` or ``"ocp"``: the library an input comes from.

    A list takes the flavour of its first element; an empty list is ``"ocp"``.

    Examples
    --------
    >>> flavour_of([])
    'ocp'
    """
    if isinstance(obj, (list, tuple)):
        return flavour_of(obj[0]) if obj else "ocp"
    mod = type(obj).__module__
    if mod.startswith("build123d"):
        return "build123d"
    if mod.startswith("cadquery"):
        return "cadquery"
    return "ocp"


def native_library(flavour: str) -> Any:
    """Return the library module of a flavour (``None`` for ``"ocp"``), importing it on first use.

    >>> native_library("ocp") is None
    True
    """
    if flavour in ("build123d", "cadquery"):
        return importlib.import_module(flavour)
    return None


def wrap_vertices(vertices: list[Any], flavour: str) -> Any:
    """Return ``TopoDS_Vertex`` objects in a flavour.

    build123d: a ``ShapeList[Vertex]``; CadQuery: a list of ``Vertex``; OCP: the list itself.

    >>> wrap_vertices([], "build123d")
    []
    """
    lib = native_library(flavour)
    if lib is None:
        return vertices
    if flavour == "build123d":
        return lib.ShapeList([lib.Vertex(v) for v in vertices])
    return [lib.Vertex(v) for v in vertices]


def wrap_edge(edge: Any, flavour: str) -> Any:
    """Return a ``TopoDS_Edge`` in a flavour (build123d / CadQuery ``Edge``, or the edge itself).

    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> wrap_edge(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge(), "build123d").length
    1.0
    """
    lib = native_library(flavour)
    return edge if lib is None else lib.Edge(edge)


def wrap_edges(edges: list[Any], flavour: str) -> Any:
    """Return ``TopoDS_Edge`` objects in a flavour (build123d: a ``ShapeList[Edge]``).

    >>> wrap_edges([], "build123d")
    []
    """
    lib = native_library(flavour)  # once, not per edge: arrangements return tens of thousands
    if lib is None:
        return list(edges)
    out = [lib.Edge(e) for e in edges]
    return lib.ShapeList(out) if flavour == "build123d" else out

"""build123d face of the adapters: unwrap ``.wrapped``, call :mod:`relief_cad.cad.api`, rewrap.

Plain functions on shapes, so they work in algebra mode and inside
``BuildLine`` / ``BuildSketch`` / ``BuildPart`` contexts alike (they do not add
anything to the active builder; pass the vertices to ``Locations`` to place
objects at them).

>>> import build123d as bd
>>> a = bd.Edge.make_line((0, 0), (2, 2))
>>> b = bd.Edge.make_line((0, 2), (2, 0))
>>> [tuple(v) for v in intersect(a, b)]
[(1.0, 1.0, 0.0)]
"""

from __future__ import annotations

from typing import Any

from ..errors import AdapterUnavailableError

try:
    import build123d as _bd
except ImportError as exc:  # pragma: no cover - exercised only without build123d
    raise AdapterUnavailableError(
        'relief_cad.cad.build123d needs build123d; install it with: pip install "relief-cad[build123d]"'
    ) from exc

from . import api, flavour
from .arrangement import arrange as _arrange
from .arrangement import split_both as _split_both
from .arrangement import split_connected as _split_connected
from .results import EdgeResult

__all__ = [
    "arrange",
    "intersect",
    "intersections",
    "split",
    "split_both",
    "wrap_edge",
    "wrap_edges",
    "wrap_faces",
    "wrap_vertices",
]


def wrap_vertices(vertices: list[Any]) -> Any:
    """Return ``TopoDS_Vertex`` objects as a build123d ``ShapeList[Vertex]``.

    Examples
    --------
    >>> wrap_vertices([])
    []
    """
    return flavour.wrap_vertices(vertices, "build123d")


def wrap_edge(edge: Any) -> Any:
    """Return a ``TopoDS_Edge`` as a build123d ``Edge``.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> wrap_edge(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge()).length
    1.0
    """
    return flavour.wrap_edge(edge, "build123d")


def wrap_edges(edges: list[Any]) -> Any:
    """Return ``TopoDS_Edge`` objects as a build123d ``ShapeList[Edge]``.

    Examples
    --------
    >>> wrap_edges([])
    []
    """
    return flavour.wrap_edges(edges, "build123d")


def intersect(a: Any, b: Any = None, *, tol: float | None = None) -> Any:
    """Return the intersection points of build123d shapes as a ``ShapeList[Vertex]``.

    See :func:`relief_cad.cad.api.intersect` (the result is always build123d,
    whatever the input flavour).

    Examples
    --------
    >>> import build123d as bd
    >>> intersect(bd.Edge.make_circle(1.0), bd.Edge.make_line((5, 5), (6, 6)))
    []
    """
    found = api.intersect(a, b, tol=tol)
    if isinstance(found, _bd.ShapeList) and all(isinstance(v, _bd.Vertex) for v in found):
        return found  # build123d input: already a ShapeList[Vertex]
    return wrap_vertices([v.wrapped for v in _as_list(found)])


def intersections(a: Any, b: Any = None, *, tol: float | None = None) -> list[EdgeResult]:
    """Return the rich results (:class:`~relief_cad.cad.results.EdgeIntersection`...) of build123d shapes.

    Examples
    --------
    >>> import build123d as bd
    >>> [r.kind for r in intersections(bd.Edge.make_line((0, 0), (2, 0)), bd.Edge.make_circle(1.0))]
    ['crossing']
    """
    return api.intersections(a, b, tol=tol)


def split(a: Any, b: Any = None, *, tol: float | None = None) -> Any:
    """Split the edges of ``a`` at ``b`` (or at each other) and return a ``ShapeList[Edge]``.

    Examples
    --------
    >>> import build123d as bd
    >>> len(split(bd.Edge.make_line((-2, 0), (2, 0)), bd.Edge.make_circle(1.0)))
    3
    """
    return _as_shapelist(_split_connected(a, b, tol=tol), wrap_edges)


# --------------------------------------------------------------------------- arrange (issue 13)
def arrange(shapes: Any, *, tol: float | None = None, faces: bool = False) -> Any:
    """Cut all edges of ``shapes`` at all their intersections: a ``ShapeList[Edge]`` or ``ShapeList[Face]``.

    See :func:`relief_cad.cad.arrangement.arrange`. The pieces share vertices, so
    they make wires and faces directly; inside ``BuildSketch``, ``add(arrange(...,
    faces=True))`` adds the bounded regions.

    Examples
    --------
    >>> import build123d as bd
    >>> faces = arrange([bd.Rectangle(2, 2), bd.Circle(1.2)], faces=True)
    >>> union = bd.Rectangle(2, 2) + bd.Circle(1.2)
    >>> len(faces), round(sum(f.area for f in faces), 6) == round(union.area, 6)
    (9, True)
    """
    return _as_shapelist(_arrange(shapes, tol=tol, faces=faces),
                         wrap_faces if faces else wrap_edges)


def split_both(a: Any, b: Any, *, tol: float | None = None) -> tuple[Any, Any]:
    """Cut ``a`` and ``b`` where they meet: two ``ShapeList[Edge]`` sharing vertices and overlap edges.

    See :func:`relief_cad.cad.arrangement.split_both`.

    Examples
    --------
    >>> import build123d as bd
    >>> pa, pb = split_both(bd.Edge.make_line((-2, 0), (2, 0)), bd.Edge.make_circle(1.0))
    >>> shared = [any(v.wrapped.IsSame(w.wrapped) for w in pa[1].vertices()) for v in pb[0].vertices()]
    >>> len(pa), len(pb), shared
    (3, 2, [True, True])
    """
    pa, pb = _split_both(a, b, tol=tol)
    return _as_shapelist(pa, wrap_edges), _as_shapelist(pb, wrap_edges)


def _as_shapelist(shapes: Any, wrap: Any) -> Any:
    if isinstance(shapes, _bd.ShapeList) and all(hasattr(s, "wrapped") for s in shapes):
        return shapes  # build123d input: already native
    return wrap([s.wrapped if hasattr(s, "wrapped") else s for s in shapes])


def _as_list(vertices: Any) -> list[Any]:
    return [v if hasattr(v, "wrapped") else _bd.Vertex(v) for v in vertices]


def wrap_faces(faces: list[Any]) -> Any:
    """Return ``TopoDS_Face`` objects as a build123d ``ShapeList[Face]``.

    Examples
    --------
    >>> wrap_faces([])
    []
    """
    return _bd.ShapeList([_bd.Face(f) for f in faces])

"""CadQuery face of the adapters and a ``Workplane`` plugin in CadQuery's documented style.

Nothing is patched at import. Two ways to use the plugin:

* ``Workplane.invoke``: ``wp.invoke(intersection_points(other))`` replaces the
  stack by the intersection vertices of the objects on it with ``other`` (or
  with each other when ``other`` is None), so the chain goes on
  (``.circle(0.1)`` at every point, ``.vertices()``...);
* :func:`register` adds the same as a ``Workplane`` method (opt-in, named
  ``intersection_points`` unless told otherwise).

>>> import cadquery as cq
>>> a = cq.Workplane("XY").moveTo(-2, 0).lineTo(2, 0)
>>> b = cq.Workplane("XY").circle(1.0)
>>> [tuple(round(c, 12) for c in v.toTuple()) for v in a.invoke(intersection_points(b)).vals()]
[(-1.0, 0.0, 0.0), (1.0, 0.0, 0.0)]
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..errors import AdapterUnavailableError, InputTypeError, InvalidInputError

try:
    import cadquery as _cq
except ImportError as exc:  # pragma: no cover - exercised only without CadQuery
    raise AdapterUnavailableError(
        'relief_cad.cad.cadquery needs CadQuery; install it with: pip install "relief-cad[cadquery]"'
    ) from exc

from . import api, flavour
from .arrangement import arrange as _arrange
from .arrangement import split_connected as _split_connected
from .results import EdgeResult

__all__ = [
    "arrange",
    "arranged",
    "intersect",
    "intersection_points",
    "intersections",
    "register",
    "split",
    "wrap_edge",
    "wrap_faces",
    "wrap_vertices",
]


def wrap_vertices(vertices: list[Any]) -> list[Any]:
    """Return ``TopoDS_Vertex`` objects as CadQuery ``Vertex`` objects.

    Examples
    --------
    >>> wrap_vertices([])
    []
    """
    return flavour.wrap_vertices(vertices, "cadquery")  # type: ignore[no-any-return]


def wrap_edge(edge: Any) -> Any:
    """Return a ``TopoDS_Edge`` as a CadQuery ``Edge``.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> wrap_edge(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge()).Length()
    1.0
    """
    return flavour.wrap_edge(edge, "cadquery")


def _shapes(obj: Any) -> Any:
    """The shapes of a Workplane's stack (or the object itself)."""
    if isinstance(obj, _cq.Workplane):
        vals = [v for v in obj.vals() if isinstance(v, _cq.Shape)]
        if not vals:
            raise InvalidInputError("expected a Workplane with shapes on its stack; it holds none")
        return vals if len(vals) > 1 else vals[0]
    return obj


def intersect(a: Any, b: Any = None, *, tol: float | None = None) -> list[Any]:
    """Return the intersection points of CadQuery shapes or Workplanes as ``Vertex`` objects.

    See :func:`relief_cad.cad.api.intersect`.

    Examples
    --------
    >>> import cadquery as cq
    >>> intersect(cq.Edge.makeCircle(1.0), cq.Edge.makeLine(cq.Vector(5, 5, 0), cq.Vector(6, 6, 0)))
    []
    """
    return [_cq.Vertex(v) if not isinstance(v, _cq.Shape) else v
            for v in api.intersect(_shapes(a), None if b is None else _shapes(b), tol=tol)]


def intersections(a: Any, b: Any = None, *, tol: float | None = None) -> list[EdgeResult]:
    """Return the rich results for CadQuery shapes or Workplanes.

    Examples
    --------
    >>> import cadquery as cq
    >>> line = cq.Edge.makeLine(cq.Vector(0, 0, 0), cq.Vector(2, 0, 0))
    >>> [r.kind for r in intersections(line, cq.Edge.makeCircle(1.0))]
    ['crossing']
    """
    return api.intersections(_shapes(a), None if b is None else _shapes(b), tol=tol)


def split(a: Any, b: Any = None, *, tol: float | None = None) -> list[Any]:
    """Split the edges of ``a`` at ``b`` (or at each other); CadQuery ``Edge`` pieces.

    Examples
    --------
    >>> import cadquery as cq
    >>> line = cq.Edge.makeLine(cq.Vector(-2, 0, 0), cq.Vector(2, 0, 0))
    >>> len(split(line, cq.Edge.makeCircle(1.0)))
    3
    """
    return _native(_split_connected(_shapes(a), None if b is None else _shapes(b), tol=tol),
                   _cq.Edge)


def _native(shapes: Any, kind: Any) -> list[Any]:
    return [s if isinstance(s, _cq.Shape) else kind(s) for s in shapes]


# --------------------------------------------------------------------------- arrange (issue 13)
def arrange(shapes: Any, *, tol: float | None = None, faces: bool = False) -> list[Any]:
    """Cut all edges of CadQuery shapes / Workplanes at all their intersections: ``Edge`` or ``Face`` list.

    See :func:`relief_cad.cad.arrangement.arrange`.

    Examples
    --------
    >>> import cadquery as cq
    >>> len(arrange([cq.Workplane("XY").rect(2, 2), cq.Workplane("XY").circle(1.2)], faces=True))
    9
    """
    items = [_shapes(s) for s in shapes] if isinstance(shapes, (list, tuple)) else _shapes(shapes)
    return _native(_arrange(items, tol=tol, faces=faces), _cq.Face if faces else _cq.Edge)


def arranged(other: Any = None, *, tol: float | None = None, faces: bool = False) -> Callable[[Any], Any]:
    """Return a callable for ``Workplane.invoke`` leaving the arranged edges (or faces) on the stack.

    Parameters
    ----------
    other : Workplane, CadQuery shape or list of them, optional
        More shapes to arrange with the stack's objects.
    tol : float, optional
        As for :func:`relief_cad.cad.arrangement.arrange`.
    faces : bool, keyword-only
        True: the bounded faces of the arrangement instead of its edges.

    Returns
    -------
    callable
        ``f(workplane) -> Workplane`` whose stack holds the pieces (``Edge``) or
        the faces (``Face``), on the workplane's plane, so ``.extrude()``,
        ``.edges()``... go on from there.

    Examples
    --------
    >>> import cadquery as cq
    >>> wp = cq.Workplane("XY").rect(2, 2)
    >>> wp.invoke(arranged(cq.Workplane("XY").circle(1.2), faces=True)).size()
    9
    """

    def _apply(wp: Any) -> Any:
        if not isinstance(wp, _cq.Workplane):
            raise InputTypeError(f"expected a cadquery Workplane; received {type(wp).__name__}")
        extra = [] if other is None else list(other) if isinstance(other, (list, tuple)) else [other]
        return wp.newObject(arrange([wp, *extra], tol=tol, faces=faces))

    return _apply


def intersection_points(other: Any = None, *, tol: float | None = None) -> Callable[[Any], Any]:
    """Return a callable for ``Workplane.invoke`` putting intersection vertices on the stack.

    Parameters
    ----------
    other : Workplane or CadQuery shape, optional
        What to intersect the stack's objects with; ``None``: the stack's objects
        with each other (self-intersections, shared vertices excluded).
    tol : float, optional
        Distance tolerance (model units); see :func:`relief_cad.cad.api.intersections`.

    Returns
    -------
    callable
        ``f(workplane) -> Workplane`` whose stack holds one ``Vertex`` per point
        (the workplane's plane is kept, so ``.circle(r)`` draws at every point).

    Examples
    --------
    >>> import cadquery as cq
    >>> wp = cq.Workplane("XY").moveTo(0, -2).lineTo(0, 2)
    >>> wp.invoke(intersection_points(cq.Workplane("XY").rect(1, 1))).size()
    2
    """

    def _apply(wp: Any) -> Any:
        if not isinstance(wp, _cq.Workplane):
            raise InputTypeError(f"expected a cadquery Workplane; received {type(wp).__name__}")
        return wp.newObject(intersect(wp, other, tol=tol))

    return _apply


def register(name: str = "intersection_points") -> None:
    """Add ``Workplane.<name>(other=None, *, tol=None)`` (opt-in; nothing is patched at import).

    Raises
    ------
    InvalidInputError
        If ``Workplane`` already has an attribute of that name not added by relief_cad.

    Examples
    --------
    >>> import cadquery as cq
    >>> register()
    >>> cq.Workplane("XY").moveTo(-2, 0).lineTo(2, 0).intersection_points(
    ...     cq.Workplane("XY").circle(1.0)).size()
    2
    >>> del cq.Workplane.intersection_points  # undo the opt-in
    """
    existing = getattr(_cq.Workplane, name, None)
    if existing is not None and not getattr(existing, "_relief_cad_plugin", False):
        raise InvalidInputError(
            f"cadquery.Workplane already has an attribute {name!r}; choose another name for register()"
        )

    def method(self: Any, other: Any = None, *, tol: float | None = None) -> Any:
        return intersection_points(other, tol=tol)(self)

    method.__doc__ = intersection_points.__doc__
    method._relief_cad_plugin = True  # type: ignore[attr-defined]
    setattr(_cq.Workplane, name, method)


def wrap_faces(faces: list[Any]) -> list[Any]:
    """Return ``TopoDS_Face`` objects as CadQuery ``Face`` objects.

    Examples
    --------
    >>> wrap_faces([])
    []
    """
    return [_cq.Face(f) for f in faces]

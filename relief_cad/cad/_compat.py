"""Everything that differs between the supported OCP releases (7.9 and 8.0), in one place.

OCP 8.0 (OCCT 8.0, brought by build123d 0.13) moved the NCollection container
instances out of their toolkit modules into ``OCP.collections``; OCP 7.9
(OCCT 7.9, CadQuery 2.8 and build123d 0.12) still has them where OCCT's
``typedef`` names put them:

===============================  ========================================  ================================
relief_cad name                  OCP 7.9                                   OCP 8.0
===============================  ========================================  ================================
``Array1OfPnt``                  ``OCP.TColgp.TColgp_Array1OfPnt``          ``OCP.collections.Array1_gp_Pnt``
``Array1OfPnt2d``                ``OCP.TColgp.TColgp_Array1OfPnt2d``        ``Array1_gp_Pnt2d``
``Array1OfReal``                 ``OCP.TColStd.TColStd_Array1OfReal``       ``Array1_double``
``Array1OfInteger``              ``OCP.TColStd.TColStd_Array1OfInteger``    ``Array1_int``
``IndexedMapOfShape``            ``OCP.TopTools.TopTools_IndexedMapOfShape`` ``IndexedMap_TopoDS_Shape_...``
``ListOfShape``                  ``OCP.TopTools.TopTools_ListOfShape``      ``List_TopoDS_Shape``
===============================  ========================================  ================================

Every other OCP name relief_cad uses is spelled the same in both. The rest of
relief_cad (and the workbench) imports these names from here and never asks
for a version.

Importing this module imports OCP and checks its version; it raises
:class:`~relief_cad.errors.AdapterUnavailableError` (an ``ImportError``) that
says either that OCP is missing or which OCP was found and which ones are
supported.

>>> arr = Array1OfReal(1, 2)
>>> arr.SetValue(1, 0.5); arr.Value(1), arr.Length()
(0.5, 2)
>>> sorted(versions())
['build123d', 'cadquery', 'occt', 'ocp', 'relief_cad']
"""

from __future__ import annotations

import importlib.metadata
from typing import Any

from ..errors import AdapterUnavailableError

__all__ = [
    "SUPPORTED_OCP",
    "Array1OfInteger",
    "Array1OfPnt",
    "Array1OfPnt2d",
    "Array1OfReal",
    "IndexedMapOfShape",
    "ListOfShape",
    "box_corners",
    "check_ocp_version",
    "downcast_edge",
    "downcast_face",
    "downcast_vertex",
    "install_hint",
    "ocp_version",
    "versions",
]

SUPPORTED_OCP: tuple[tuple[int, int], ...] = ((7, 9), (8, 0))
"""The OCP (= OCCT) major.minor releases this release of relief_cad supports."""

_EXTRAS_HINT = 'pip install "relief-cad[build123d]" (OCP 8.0) or "relief-cad[cadquery]" (OCP 7.9)'


def install_hint() -> str:
    """Return the install hint the CAD-layer import errors give.

    >>> "relief-cad[build123d]" in install_hint()
    True
    """
    return _EXTRAS_HINT


def _supported_text() -> str:
    return ", ".join(f"{a}.{b}" for a, b in SUPPORTED_OCP)


def check_ocp_version(version: str) -> tuple[int, int]:
    """Return ``(major, minor)`` of an OCP version string, refusing unsupported releases.

    Parameters
    ----------
    version : str
        ``OCP.__version__``, e.g. ``"7.9.3.1"`` or ``"8.0.1.1"`` (OCP's first
        three numbers are the OCCT version it binds).

    Returns
    -------
    tuple of int
        ``(major, minor)``, one of :data:`SUPPORTED_OCP`.

    Raises
    ------
    AdapterUnavailableError
        If the string is not a version or names a release not in :data:`SUPPORTED_OCP`;
        the message names the version found and the supported ones.

    Examples
    --------
    >>> check_ocp_version("8.0.1.1")
    (8, 0)
    >>> check_ocp_version("7.7.2")
    Traceback (most recent call last):
    ...
    relief_cad.errors.AdapterUnavailableError: OCP 7.7 found (7.7.2), which this release of relief_cad ...
    """
    parts = str(version).split(".")
    try:
        major, minor = int(parts[0]), int(parts[1])
    except (IndexError, ValueError):
        raise AdapterUnavailableError(
            f"expected an OCP version such as '8.0.1'; found OCP reporting version {version!r}; "
            f"relief_cad supports OCP {_supported_text()}"
        ) from None
    if (major, minor) not in SUPPORTED_OCP:
        raise AdapterUnavailableError(
            f"OCP {major}.{minor} found ({version}), which this release of relief_cad does not support; "
            f"supported: OCP {_supported_text()}; install a supported one with: {_EXTRAS_HINT}"
        )
    return major, minor


def _import_ocp() -> Any:
    try:
        import OCP
    except ImportError as exc:
        raise AdapterUnavailableError(
            f"relief_cad.cad needs OCP (the OCCT bindings, OCP {_supported_text()}) and none is "
            f"installed ({exc}); install it with: {_EXTRAS_HINT}"
        ) from exc
    return OCP


OCP_MODULE = _import_ocp()
_OCP_VERSION = str(getattr(OCP_MODULE, "__version__", "unknown"))
_MAJOR_MINOR = check_ocp_version(_OCP_VERSION)


def ocp_version() -> tuple[int, int]:
    """Return the installed OCP's ``(major, minor)``.

    >>> ocp_version() in SUPPORTED_OCP
    True
    """
    return _MAJOR_MINOR


if _MAJOR_MINOR >= (8, 0):
    from OCP.collections import Array1_double as Array1OfReal
    from OCP.collections import Array1_gp_Pnt as Array1OfPnt
    from OCP.collections import Array1_gp_Pnt2d as Array1OfPnt2d
    from OCP.collections import Array1_int as Array1OfInteger
    from OCP.collections import IndexedMap_TopoDS_Shape_TopTools_ShapeMapHasher as IndexedMapOfShape
    from OCP.collections import List_TopoDS_Shape as ListOfShape
else:
    from OCP.TColgp import TColgp_Array1OfPnt as Array1OfPnt
    from OCP.TColgp import TColgp_Array1OfPnt2d as Array1OfPnt2d
    from OCP.TColStd import TColStd_Array1OfInteger as Array1OfInteger
    from OCP.TColStd import TColStd_Array1OfReal as Array1OfReal
    from OCP.TopTools import TopTools_IndexedMapOfShape as IndexedMapOfShape
    from OCP.TopTools import TopTools_ListOfShape as ListOfShape


def _distribution_version(*names: str) -> str | None:
    for name in names:
        try:
            return importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            continue
    return None


def versions() -> dict[str, str | None]:
    """Return the versions of the CAD stack relief_cad runs on, for results files and reports.

    Nothing is imported to find them (build123d and CadQuery versions come from
    the installed distributions' metadata).

    Returns
    -------
    dict of str to str or None
        Keys ``"occt"`` (the OCCT release OCP binds: the first three numbers of
        OCP's version, e.g. ``"8.0.1"``), ``"ocp"`` (``OCP.__version__``),
        ``"build123d"``, ``"cadquery"`` (None when not installed) and
        ``"relief_cad"`` (None when run from a source tree that is not installed).

    Examples
    --------
    >>> v = versions()
    >>> v["ocp"].startswith(v["occt"])
    True
    """
    return {
        "occt": ".".join(_OCP_VERSION.split(".")[:3]),
        "ocp": _OCP_VERSION,
        "build123d": _distribution_version("build123d"),
        "cadquery": _distribution_version("cadquery"),
        "relief_cad": _distribution_version("relief-cad", "relief_cad"),
    }


# OCCT 8 made TopoDS::Edge / TopoDS::Vertex free functions of a namespace: OCP 8.0 binds them
# only as ``TopoDS.Edge``; OCP 7.9 binds both ``TopoDS.Edge`` and the static spelling ``Edge_s``.
from OCP.TopoDS import TopoDS as _TopoDS  # noqa: E402

downcast_edge: Any = _TopoDS.Edge
"""Downcast a ``TopoDS_Shape`` of type edge to ``TopoDS_Edge`` (``TopoDS::Edge``)."""

downcast_vertex: Any = _TopoDS.Vertex
"""Downcast a ``TopoDS_Shape`` of type vertex to ``TopoDS_Vertex`` (``TopoDS::Vertex``)."""

downcast_face: Any = _TopoDS.Face
"""Downcast a ``TopoDS_Shape`` of type face to ``TopoDS_Face`` (``TopoDS::Face``)."""


def box_corners(box: Any) -> tuple[float, float, float, float, float, float]:
    """Return ``(xmin, ymin, zmin, xmax, ymax, zmax)`` of a ``Bnd_Box``.

    OCP 8.0 cannot convert the return value of ``Bnd_Box.Get``; ``CornerMin``/``CornerMax`` work in both.

    >>> from OCP.Bnd import Bnd_Box
    >>> from OCP.gp import gp_Pnt
    >>> box = Bnd_Box(gp_Pnt(0, 0, 0), gp_Pnt(1, 2, 3))
    >>> box_corners(box)
    (0.0, 0.0, 0.0, 1.0, 2.0, 3.0)
    """
    lo, hi = box.CornerMin(), box.CornerMax()
    return (lo.X(), lo.Y(), lo.Z(), hi.X(), hi.Y(), hi.Z())

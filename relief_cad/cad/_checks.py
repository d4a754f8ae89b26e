"""Input checks of the CAD layer: the core's checks (:mod:`relief_cad._checks`), one rule everywhere.

A tolerance that is not a real number (``str``, a list, ``bool``, ``complex``) is a
:class:`~relief_cad.errors.ToleranceTypeError` (both a ``ToleranceError`` and an
``InputTypeError``); a real number that is not a finite distance > 0 (including integers
too large for a float) is a :class:`~relief_cad.errors.ToleranceError`, exactly as in
:func:`relief_cad.intersect`.

>>> check_tol(1e-6)
1e-06
"""

from __future__ import annotations

from typing import Any

from .._checks import check_tol as _core_check_tol
from ..tolerances import ModelTolerance, _resolve_tolerance

__all__ = ["check_model_tol", "check_tol"]


def check_tol(tol: Any, name: str = "tol") -> float:
    """Return a given ``tol`` (not None) as a float distance in model units.

    Raises
    ------
    ToleranceTypeError
        If ``tol`` is not a real number (``bool``, ``str``, a list, ``complex``...).
    ToleranceError
        If ``tol`` is not finite and > 0 (``0``, ``-1``, ``nan``, ``inf``, ``10**400``).

    Examples
    --------
    >>> check_tol("abc")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceTypeError: tol should be a distance > 0 in model units (a float), not str
    >>> check_tol(10**400)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not an integer ...
    """
    value = _core_check_tol(tol, name)
    if value is None:
        raise _not_none(name)
    return value


def _not_none(name: str) -> Exception:
    from ..errors import ToleranceTypeError

    return ToleranceTypeError(f"{name} should be a distance > 0 in model units (a float), not NoneType")


def check_model_tol(tol: Any, edges: list[Any]) -> ModelTolerance:
    """Return a given ``tol`` checked against the size of these edges, as a :class:`ModelTolerance`.

    One rule for :func:`~relief_cad.cad.intersect`, :func:`~relief_cad.cad.split`,
    :func:`~relief_cad.cad.occt_intersections` and :func:`~relief_cad.cad.compare`: ``tol``
    is refused above :data:`relief_cad.tolerances.MAX_TOLERANCE_FRACTION` of the diagonal of the
    edges' joint OCCT bounding box, and raised to the rounding floor of its corners (as in the
    core, :func:`relief_cad.tolerances.resolve_tolerance`).

    Raises
    ------
    ToleranceError
        If ``tol`` is not a finite distance > 0, or exceeds that fraction of the edges' size.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> edge = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge()
    >>> check_model_tol(1e-7, [edge])
    1e-07
    >>> check_model_tol(1e300, [edge])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be at most 0.01 of the inputs' size (...), not 1e+300
    """
    import numpy as np
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    from ._compat import box_corners

    value = check_tol(tol)
    box = Bnd_Box()
    for edge in edges:
        BRepBndLib.Add_s(edge, box, False)
    corners = np.array(box_corners(box), dtype=float).reshape(2, 3)
    return ModelTolerance(_resolve_tolerance(value, corners))

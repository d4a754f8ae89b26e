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

__all__ = ["check_tol"]


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

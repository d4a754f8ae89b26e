"""Input checks of the CAD layer that the core's checks do not cover yet.

``check_tol`` follows the core's rule (``relief_cad._checks.check_tol``, being written in
parallel): a tolerance that is not a real number (``str``, a list, ``bool``, ``complex``)
is an :class:`~relief_cad.errors.InputTypeError`; a real number that is not a finite
distance > 0 (including integers too large for a float) is a
:class:`~relief_cad.errors.ToleranceError`. When the core's function lands, this one
becomes a re-export of it.

>>> check_tol(1e-6)
1e-06
"""

from __future__ import annotations

import math
import numbers
from typing import Any

from ..errors import InputTypeError, ToleranceError

__all__ = ["check_tol"]


def check_tol(tol: Any, name: str = "tol") -> float:
    """Return ``tol`` as a float distance in model units.

    Raises
    ------
    InputTypeError
        If ``tol`` is not a real number (``bool``, ``str``, a list, ``complex``...).
    ToleranceError
        If ``tol`` is not finite and > 0 (``0``, ``-1``, ``nan``, ``inf``, ``10**400``).

    Examples
    --------
    >>> check_tol("abc")
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: tol should be a distance > 0 in model units (a float), not str
    >>> check_tol(10**400)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: tol should be a finite distance > 0 in model units, not an integer ...
    """
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real):
        raise InputTypeError(
            f"{name} should be a distance > 0 in model units (a float), not {type(tol).__name__}"
        )
    try:
        value = float(tol)
    except OverflowError as exc:
        raise ToleranceError(
            f"{name} should be a finite distance > 0 in model units, "
            f"not an integer of {len(str(abs(int(tol))))} digits"  # type: ignore[call-overload]
        ) from exc
    if not (math.isfinite(value) and value > 0.0):
        raise ToleranceError(f"{name} should be a finite distance > 0 in model units, not {value!r}")
    return value

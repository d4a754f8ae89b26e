r"""Named default tolerances (all documented, all overridable per call).

Distances are in model units. When a caller passes ``tol=None`` the
intersectors use :func:`default_tolerance` of the inputs' control points:

.. math::

    \mathrm{tol} = \mathrm{RELATIVE\_TOLERANCE} \cdot \mathrm{size}
        + \mathrm{ROUNDING\_ULPS} \cdot \varepsilon \cdot \max |x|

where ``size`` is the diagonal of the joint bounding box of the control
points and ``max |x|`` their largest absolute coordinate (the second term keeps
the tolerance above the rounding noise of curves far from the origin).

>>> import numpy as np
>>> round(default_tolerance(np.array([[0.0, 0.0], [3.0, 4.0]])), 12)
5e-09
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from ._types import FloatArray

__all__ = [
    "RELATIVE_TOLERANCE",
    "ROUNDING_ULPS",
    "PARAMETER_TOLERANCE",
    "default_tolerance",
]

RELATIVE_TOLERANCE: float = 1e-9
"""Default distance tolerance as a fraction of the inputs' size (bounding-box diagonal)."""

ROUNDING_ULPS: float = 64.0
"""Multiple of machine epsilon times the largest coordinate added to the default tolerance."""

PARAMETER_TOLERANCE: float = 1e-15
"""Parameter-space resolution below which two parameters are the same (dimensionless)."""

_EPS = float(np.finfo(np.float64).eps)


def default_tolerance(*point_sets: FloatArray | Iterable[FloatArray]) -> float:
    """Return the default distance tolerance for curves with these control points.

    Parameters
    ----------
    *point_sets : ndarray, shape (m, d)
        Control points (Cartesian) of every curve taking part.

    Returns
    -------
    float
        A positive distance in model units (see the module docstring). A set of
        coincident points gets the rounding term alone, or ``1e-300`` at the origin.

    Examples
    --------
    >>> default_tolerance(np.zeros((2, 2)))
    1e-300
    """
    arrays = [np.asarray(p, dtype=np.float64).reshape(-1, np.asarray(p).shape[-1]) for p in point_sets]
    stacked = np.vstack(arrays)
    lo = stacked.min(axis=0)
    hi = stacked.max(axis=0)
    size = float(np.linalg.norm(hi - lo))
    big = float(np.max(np.abs(stacked)))
    tol = RELATIVE_TOLERANCE * size + ROUNDING_ULPS * _EPS * big
    if not math.isfinite(tol) or tol <= 0.0:
        return 1e-300
    return tol

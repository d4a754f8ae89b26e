"""relief_cad: curve/curve intersection by relief perspective and Bézier clipping.

The core (this package) imports numpy only (its kernels are compiled by Cython at install);
the CAD adapters live in
:mod:`relief_cad.cad` and are never imported from here.

>>> from relief_cad import RationalBezier, intersect
>>> a = RationalBezier([[0, 0], [1, 2], [2, 0]])
>>> b = RationalBezier([[0, 1], [2, 1]])
>>> [(round(r.t, 6), round(r.u, 6), r.kind) for r in intersect(a, b)]
[(0.5, 0.5, 'tangent')]
"""

from __future__ import annotations

from .curves import RationalBezier
from .errors import ReliefCadError
from .intersection import DEFAULT_BUDGET, intersect, intersect_line, intersect_many
from .relief import (
    NeutralPlaneFrame,
    ReliefPerspective,
    central_projection,
    find_neutral_plane,
    lift,
    preimage_of_lift,
    relief_of_lift,
)
from .results import Intersection, IntersectionList, Overlap, ParameterBox
from .space import ReliefFrame, ReliefScheme, intersect_space, relief_scheme
from .tolerances import RELATIVE_TOLERANCE, default_tolerance

__all__ = [
    "DEFAULT_BUDGET",
    "RELATIVE_TOLERANCE",
    "Intersection",
    "IntersectionList",
    "NeutralPlaneFrame",
    "Overlap",
    "ParameterBox",
    "RationalBezier",
    "ReliefCadError",
    "ReliefFrame",
    "ReliefPerspective",
    "ReliefScheme",
    "central_projection",
    "default_tolerance",
    "find_neutral_plane",
    "intersect",
    "intersect_line",
    "intersect_many",
    "intersect_space",
    "lift",
    "preimage_of_lift",
    "relief_of_lift",
    "relief_scheme",
]
__version__ = "0.1.0"

"""relief_cad: curve/curve intersection by relief perspective and Bézier clipping."""

from __future__ import annotations

from .curves import RationalBezier
from .errors import ReliefCadError
from .relief import (
    NeutralPlaneFrame,
    ReliefPerspective,
    central_projection,
    find_neutral_plane,
    lift,
    preimage_of_lift,
    relief_of_lift,
)
from .results import Intersection, IntersectionList, Overlap

__all__ = [
    "Intersection",
    "IntersectionList",
    "NeutralPlaneFrame",
    "Overlap",
    "RationalBezier",
    "ReliefCadError",
    "ReliefPerspective",
    "central_projection",
    "find_neutral_plane",
    "lift",
    "preimage_of_lift",
    "relief_of_lift",
]
__version__ = "0.1.0"

"""relief_cad: curve/curve intersection by relief perspective and Bézier clipping."""

from __future__ import annotations

from .curves import RationalBezier
from .errors import ReliefCadError
from .results import Intersection, IntersectionList, Overlap

__all__ = [
    "Intersection",
    "IntersectionList",
    "Overlap",
    "RationalBezier",
    "ReliefCadError",
]
__version__ = "0.1.0"

"""Type aliases shared by the public API."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Union

import numpy as np
from numpy.typing import NDArray

__all__ = ["FloatArray", "PointsLike", "ParamsLike"]

FloatArray = NDArray[np.float64]
"""A float64 numpy array."""

PointsLike = Union[FloatArray, Sequence[Sequence[float]]]
"""Rows of points, shape ``(m, d)``: a numpy array or nested sequences."""

ParamsLike = Union[float, FloatArray, Sequence[float]]
"""A scalar parameter or a 1-D array of parameters."""

"""Constants shared by the kernels: result-row layout, kinds and numerical thresholds."""

from __future__ import annotations

KIND_CROSSING = 0
KIND_TANGENT = 1
KIND_OVERLAP = 2
KIND_UNRESOLVED = 3
RES_COLS = 9

_EPS = 2.220446049250313e-16
_SPLIT_RATIO = 0.8  # a clip keeping more than 80 % of an interval counts as a stall
_ROUND = 64.0 * _EPS  # rounding level of a residual, relative to the frame size (~1)

# A space curve is passed as homogeneous rows (w x, w y, w z, w), shape (n + 1, 4), in model
# coordinates. Result rows (SPACE_COLS columns): [kind, t, u, t1, u1, x, y, z, distance] with kind
# one of the KIND_* codes (an overlap or an unresolved box holds t0, u0, t1, u1 in t, u, t1, u1).
SPACE_COLS = 9
STATUS_OK = 0
STATUS_ARTEFACT = 1
STATUS_ENDS_MATCH = 2  # the end points match: the caller tests coincidence first
_SPACE_TANGENT_SIN = 1e-6
_SPACE_OVERLAP_SAMPLES = 17
_SPACE_N_FRAMES = 4
# coordinates of magnitude 2**-100 .. 2**100 are used as they are, others scaled first
# (relief_cad.contacts.range_exponent)
SAFE_EXPONENT = 100

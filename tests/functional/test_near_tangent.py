"""Near-tangent crossings (angles 1e-4..1e-8): exactly one crossing, at the certified root of the stored data.

The curves are y = x^2 and y = x^2 + theta x on x = 2t - 1 (quadratic Béziers). Their y control
values 1 -+ theta round to doubles, so the crossing of the *stored* data is at
t* = 1 / (1 + sqrt(dplus / dminus)) with dplus = fl(1 + theta) - 1 and dminus = 1 - fl(1 - theta)
(exact in binary64), and u* = t* (both x(t) = 2t - 1). Exact similarity maps (quarter turns,
power-of-two scales) keep the data exact and the parameters unchanged; after a shift by 1e4 the
data are rounded, and the truth is the crossing of the stored data, found in 50-digit arithmetic.
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from relief_cad import RationalBezier, intersect
from relief_cad.results import Intersection

ANGLES = [10.0 ** -e for e in (4, 5, 6, 7, 8)] + [3.1e-5, 4.7e-7, 2.2e-8]
TRANSFORMS = [(1, 0, 0.0), (2.0**-13, 1, 0.0), (2.0**17, 2, 0.0), (1.0, 3, 1e4), (2.0**5, 1, -1e4)]


def truth(theta: float) -> float:
    dplus = (1.0 + theta) - 1.0
    dminus = 1.0 - (1.0 - theta)
    with mpmath.workdps(40):
        return float(1 / (1 + mpmath.sqrt(mpmath.mpf(dplus) / mpmath.mpf(dminus))))


def truth_on_data(a: RationalBezier, b: RationalBezier, t0: float) -> tuple[float, float]:
    """The crossing of the actual stored (possibly rounded) data: 2-D Newton in 50 digits."""
    with mpmath.workdps(50):
        def point(c: RationalBezier, s: mpmath.mpf) -> list[mpmath.mpf]:
            h = [[mpmath.mpf(float(x)) for x in row] for row in c.homogeneous]
            b0 = [(1 - s) ** 2, 2 * s * (1 - s), s**2]
            v = [sum(b0[i] * h[i][j] for i in range(3)) for j in range(3)]
            return [v[0] / v[2], v[1] / v[2]]
        f = lambda t, u: [pa - pb for pa, pb in zip(point(a, t), point(b, u))]  # noqa: E731
        root = mpmath.findroot(f, (mpmath.mpf(t0), mpmath.mpf(t0)))
        return float(root[0]), float(root[1])


@pytest.mark.parametrize("theta", ANGLES)
@pytest.mark.parametrize(("scale", "quarter_turns", "shift"), TRANSFORMS)
def test_near_tangent_crossing_found_once(theta: float, scale: float, quarter_turns: int, shift: float) -> None:
    a = RationalBezier([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]])
    b = RationalBezier([[-1.0, 1.0 - theta], [0.0, -1.0], [1.0, 1.0 + theta]])
    c, s = [(1, 0), (0, 1), (-1, 0), (0, -1)][quarter_turns]
    m = np.array([[scale * c, -scale * s, shift], [scale * s, scale * c, shift], [0.0, 0.0, 1.0]])
    a, b = a.transformed(m), b.transformed(m)
    res = intersect(a, b)
    ts = us = truth(theta)
    if shift:  # shifting by 1e4 rounds the data: the truth is the crossing of what is stored
        ts, us = truth_on_data(a, b, ts)
    assert len(res) == 1, res
    r = res[0]
    assert isinstance(r, Intersection) and r.kind == "crossing"
    assert abs(r.t - ts) <= 1e-13 and abs(r.u - us) <= 1e-13, (r.t - ts, r.u - us)

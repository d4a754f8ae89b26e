"""A B-spline touching a line just past one of its knots: the touch, not the knot.

The spline has poles ``(x_i, -x_i**2)`` (x symmetric in [-1, 1]) and one interior knot at
``0.5 - delta``; the horizontal line through its highest point touches it there. The core sees
one span at a time and places a meeting at a span's end on that end, so a touch ``delta`` from
the knot came back at the knot: 7.5e-8 of the range away, 1.2e-7 along the line (tol 1e-7).

Truth: de Boor in 40 digits on the exact poles and knots; the apex is the root of ``y'(s)``
(mpmath ``findroot`` on ``mp.diff``), its ``x`` gives the line's parameter (the line runs from
``x = -2`` at unit speed). The pair is also placed in a plane turned about (1, 2, 3) and moved
(parameters do not change). Asserted: one tangent, ``t`` within 1e-9 of the apex and ``u``
within 1e-8 (measured: 1e-16 and 1e-15 in XY).
"""

from __future__ import annotations

import math

import build123d as bd
import mpmath as mp
import pytest
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Pnt

from relief_cad.cad import intersections
from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal
from tests._exact_bspline import de_boor

TOL = 1e-7


def _spline(degree: int, knot: float) -> tuple[bd.Edge, list[tuple[float, float]]]:
    n = degree + 2
    xs = [-1 + 2 * i / (n - 1) for i in range(n)]
    poles = [(x, -(x * x)) for x in xs]
    pts, knots, mults = Array1OfPnt(1, n), Array1OfReal(1, 3), Array1OfInteger(1, 3)
    for i, (x, y) in enumerate(poles):
        pts.SetValue(i + 1, gp_Pnt(x, y, 0))
    for i, (k, m) in enumerate(((0.0, degree + 1), (knot, 1), (1.0, degree + 1))):
        knots.SetValue(i + 1, k)
        mults.SetValue(i + 1, m)
    return bd.Edge(BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(pts, knots, mults, degree)).Edge()), poles


def _apex(degree: int, knot: float, poles: list[tuple[float, float]]) -> tuple[mp.mpf, mp.mpf, mp.mpf]:
    """``(s, x, y)`` of the spline's highest point, 40 digits."""
    mp.mp.dps = 40
    ev = de_boor(poles, [0.0] * (degree + 1) + [knot] + [1.0] * (degree + 1), degree)

    s = mp.findroot(lambda q: mp.diff(lambda v: ev(v)[1], q), mp.mpf(0.5))
    x, y = ev(s)
    return s, x, y


@pytest.mark.parametrize("degree", [3, 5])
@pytest.mark.parametrize("knot", [0.4999999, 0.49999, 0.5000004, 0.49998])
@pytest.mark.parametrize("tilted", [False, True])
def test_a_touch_next_to_a_knot_is_placed_on_the_touch(degree: int, knot: float, tilted: bool) -> None:
    spline, poles = _spline(degree, knot)
    s, x, y = _apex(degree, knot, poles)
    assert abs(s - knot) > 1e-9  # the touch is no knot (the case the test is about)
    line = bd.Edge.make_line((-2, float(y)), (2, float(y)))
    if tilted:
        place = bd.Location((-7.5, 3.25, 1.0), (1, 2, 3), 37)
        spline, line = spline.moved(place), line.moved(place)
    [hit] = intersections(spline, line, tol=TOL)
    assert hit.kind == "tangent"
    assert abs(hit.t - float(s)) <= 1e-9, (hit.t, float(s))
    assert abs(hit.u - float(x + 2)) <= 1e-8, (hit.u, float(x + 2))
    assert math.isfinite(hit.distance) and hit.distance <= TOL

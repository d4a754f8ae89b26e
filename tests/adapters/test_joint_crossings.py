"""A spline through points of a circle, against the circle: meetings at the spline's knots.

``build123d.Edge.make_spline`` through points of the unit circle gives a cubic B-spline that
passes through each point only to rounding: it crosses the circle at tiny angles (sine 1e-8)
a few 1e-9 of its range from a knot, and again 4e-5 away. The core sees each span alone, and
labels a meeting at a span's end by its angle (a touch below sine 1e-7); across the knot, the
spline is on opposite sides of the circle, so the meeting is a crossing.

Truth: the B-spline's poles and knots, taken exactly, in 40-digit de Boor evaluation. On each
side of a point contact the signed gap ``|S(s) - c| - R`` is sampled out from 1e-9 to 1e-3 of
the range (doubling) until it exceeds the rounding floor of the data (``64 eps R``, four times
over); its sign is taken from the first gap above a sixteenth of that (the reported contact is
itself a few 1e-9 off the exact root, where the gap is 1e-17). Opposite signs there make a crossing, equal signs a touch. A contact whose gap changes sign
on a side before that is left out: the data cross again within rounding (a cluster of roots that
the rule makes one contact by parity), as at most knots in the middle of a long arc.
"""

from __future__ import annotations

import math

import build123d as bd
import mpmath as mp
import pytest
from OCP.BRep import BRep_Tool

from relief_cad.cad import intersections
from tests._exact_bspline import of_curve

TOL = 1e-7


def _gap(curve, radius: float, centre: tuple[float, float]):
    """``s -> |S(s) - centre| - radius`` for the B-spline ``curve`` (OCCT), in mpmath (40 digits)."""
    point = of_curve(curve, 2)

    def gap(s: mp.mpf) -> mp.mpf:
        x, y = point(s)
        return mp.hypot(x - centre[0], y - centre[1]) - radius

    return gap


CASES = [(17, 0.2, 1.5, 1.0, (0.0, 0.0), False), (17, 0.2, 1.5, 1.0, (0.0, 0.0), True),
         (17, 0.2, 1.5, 10.0, (3.0, -2.0), False), (17, 2.2, 3.5, 1.0, (0.0, 0.0), False),
         (33, 0.1, 2.9, 1.0, (0.0, 0.0), False), (9, 0.3, 1.1, 5.0, (1.0, 1.0), True)]


@pytest.mark.parametrize(("n", "a0", "a1", "radius", "centre", "reverse"), CASES)
def test_spline_through_circle_points_crosses_at_its_knots(
        n: int, a0: float, a1: float, radius: float, centre: tuple[float, float], reverse: bool) -> None:
    angles = [a0 + (a1 - a0) * i / (n - 1) for i in range(n)]
    angles = angles[::-1] if reverse else angles
    pts = [bd.Vector(centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a), 0) for a in angles]
    circle = bd.Edge.make_circle(radius).moved(bd.Location((centre[0], centre[1], 0)))
    assert _checked(bd.Edge.make_spline(pts), circle, radius, centre) >= 2


@pytest.mark.parametrize(("radius", "bend", "half"), [(1.0, 0.3, 0.5), (200.0, 0.6, 0.9), (0.05, -0.4, 1.2),
                                                      (30.0, 0.75, 0.4), (500.0, -0.2, 1.4)])
def test_spline_through_an_arc_joint_crosses_there(radius: float, bend: float, half: float) -> None:
    """A spline through the top of a half circle, where both have a joint: it crosses there and close by."""
    bend, half = bend / radius, radius * half
    pts = [bd.Vector(x, radius + 0.5 * bend * x * x + 0.05 * bend * bend * x**3, 0)
           for x in (-half + 2 * half * i / 6 for i in range(7))]
    arc = bd.Edge.make_circle(radius, bd.Plane.XY, start_angle=20, end_angle=160)
    assert _checked(bd.Edge.make_spline(pts), arc, radius, (0.0, 0.0)) >= 1


def _checked(spline: bd.Edge, circle: bd.Edge, radius: float, centre: tuple[float, float]) -> int:
    """Check the kind of every point contact of ``spline`` with ``circle`` that the truth decides; their number."""
    mp.mp.dps = 40
    curve = BRep_Tool.Curve_s(spline.wrapped, 0.0, 1.0)
    gap = _gap(curve, radius, centre)
    first, last = curve.FirstParameter(), curve.LastParameter()
    span, level = last - first, 4.0 * 64 * 2.0**-52 * (radius + max(map(abs, centre)))
    checked = 0
    for r in intersections(spline, circle, tol=TOL * max(1.0, radius)):
        if isinstance(r.t, tuple) or r.distance > 1e-12 * radius:
            continue
        sides = [_side(gap, r.t, sense * span, level, (first, last)) for sense in (-1, 1)]
        if None in sides:
            continue
        want = "crossing" if sides[0] != sides[1] else "tangent"
        assert r.kind == want, (r.t, r.kind, sides)
        checked += 1
    return checked


def _side(gap, t: float, span: float, level: float, limits: tuple[float, float]) -> int | None:
    """The sign of ``gap`` where it first exceeds ``level`` out from ``t`` (None: it flips first)."""
    h, sign = 1e-9, 0
    while h <= 1e-3:
        s = mp.mpf(t) + h * span
        if not limits[0] <= s <= limits[1]:
            return None
        g = gap(s)
        if sign and g * sign < 0:
            return None
        sign = sign or (int(mp.sign(g)) if abs(g) > level / 16 else 0)  # past the contact's own offset
        if abs(g) > level:
            return sign
        h *= 2.0
    return None

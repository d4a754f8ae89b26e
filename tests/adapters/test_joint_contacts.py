"""A line touching or crossing a cubic B-spline a little way from its knot: the contact, not the knot.

The spline has poles ``(x_i, -x_i**2, z_i)`` (x evenly in [-1, 1]; ``z_i = 0.4 x_i**3`` in space,
0 in the plane) and one interior knot at 0.5. The line meets it at ``s* = 0.5 + delta``: along the
tangent there (a touch) or turned from it by ``theta`` towards the principal normal (a crossing).
The core sees one span at a time and puts a contact within tol of a span's end on that end: it
came back at the knot, up to 2.4e-7 from the contact (tol 1e-7); in space a touch was a crossing
there, and in the plane a crossing was a touch.

Truth: de Boor in 40 digits on the exact poles and knots, and mpmath derivatives. The line's
ends ``S(s*) - 1.5 d`` and ``S(s*) + 1.2 d`` (``d`` the unit direction) are rounded to doubles, so
``u = 1.5`` on the line to rounding. Each case checks that it is the case the test is about: the
knot is within tol of the line, and farther than tol from the contact. Asserted: one result, its
kind, ``t`` within 1e-9 of ``s*`` and ``u`` within 1e-8 of 1.5.
"""

from __future__ import annotations

import math

import build123d as bd
import mpmath as mp
import pytest
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
from OCP.Geom import Geom_BSplineCurve
from OCP.gp import gp_Pnt

from relief_cad.cad import intersections, segments
from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal
from tests._exact_bspline import de_boor

TOL = 1e-7
KNOT = 0.5


def _spline(space: bool) -> tuple[bd.Edge, list[tuple[float, float, float]]]:
    xs = [-1 + 2 * i / 4 for i in range(5)]
    poles = [(x, -(x * x), 0.4 * x**3 if space else 0.0) for x in xs]
    pts, knots, mults = Array1OfPnt(1, 5), Array1OfReal(1, 3), Array1OfInteger(1, 3)
    for i, p in enumerate(poles):
        pts.SetValue(i + 1, gp_Pnt(*p))
    for i, (k, m) in enumerate(((0.0, 4), (KNOT, 1), (1.0, 4))):
        knots.SetValue(i + 1, k)
        mults.SetValue(i + 1, m)
    return bd.Edge(BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(pts, knots, mults, 3)).Edge()), poles


def _unit(v: list[mp.mpf]) -> list[mp.mpf]:
    n = mp.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def _line_distance(p: list[mp.mpf], o: list[mp.mpf], d: list[mp.mpf]) -> mp.mpf:
    w = [a - b for a, b in zip(p, o, strict=True)]
    along = sum(a * b for a, b in zip(w, d, strict=True))
    return mp.sqrt(max(mp.mpf(0), sum(c * c for c in w) - along * along))


def _case(space: bool, delta: float, theta: float) -> tuple[bd.Edge, bd.Edge, float]:
    """The spline, the line meeting it at ``s* = KNOT + delta`` (turned by ``theta``), and ``s*``."""
    mp.mp.dps = 40
    spline, poles = _spline(space)
    curve = de_boor(poles, [0.0] * 4 + [KNOT] + [1.0] * 4, 3)
    s = mp.mpf(KNOT + delta)
    p = curve(s)
    d1 = [mp.diff(lambda v, q=q: curve(v)[q], s) for q in range(3)]
    d2 = [mp.diff(lambda v, q=q: curve(v)[q], s, 2) for q in range(3)]
    t = _unit(d1)
    n = _unit([b - sum(x * y for x, y in zip(d2, t, strict=True)) * a for a, b in zip(t, d2, strict=True)])
    d = _unit([mp.cos(theta) * a + mp.sin(theta) * b for a, b in zip(t, n, strict=True)])
    start = [float(a - 1.5 * b) for a, b in zip(p, d, strict=True)]
    end = [float(a + 1.2 * b) for a, b in zip(p, d, strict=True)]
    knot_point = curve(mp.mpf(KNOT))
    # the case the test is about: the core's end rule takes the knot, which is not the contact
    assert _line_distance(knot_point, p, d) <= TOL
    assert mp.sqrt(sum((a - b) ** 2 for a, b in zip(knot_point, p, strict=True))) > TOL
    return spline, bd.Edge.make_line(start, end), float(s)


@pytest.mark.parametrize("space", [False, True])
@pytest.mark.parametrize("delta", [4e-7, -3e-5, 2e-4])
def test_a_touch_near_a_knot_is_placed_on_the_touch(space: bool, delta: float) -> None:
    spline, line, s = _case(space, delta, 0.0)
    [hit] = intersections(spline, line, tol=TOL)
    assert hit.kind == "tangent"
    assert abs(hit.t - s) <= 1e-9, (hit.t, s)
    assert abs(hit.u - 1.5) <= 1e-8, hit.u
    assert math.isfinite(hit.distance) and hit.distance <= TOL


@pytest.mark.parametrize("space", [False, True])
@pytest.mark.parametrize(("delta", "theta"), [(1.5e-7, 0.3), (-1.2e-7, 0.3), (1e-7, 0.6)])
def test_a_crossing_near_a_knot_is_placed_on_the_crossing(space: bool, delta: float, theta: float) -> None:
    spline, line, s = _case(space, delta, theta)
    # in the plane the line crosses the spline again, 0.2 to 0.4 of its range on: one contact here
    [hit] = [r for r in intersections(spline, line, tol=TOL) if abs(r.t - s) < 1e-2]
    assert hit.kind == "crossing"
    assert abs(hit.t - s) <= 1e-9, (hit.t, s)
    assert abs(hit.u - 1.5) <= 1e-8, hit.u
    assert math.isfinite(hit.distance) and hit.distance <= TOL


def _circle_case(radius: float, arc: float, theta: float, lift: float) -> tuple[bd.Edge, bd.Edge, float]:
    """A circle, a line meeting it ``arc`` (along the circle) after the joint of its first two spans,
    and the angle there.

    The line runs along the tangent turned by ``theta`` towards the centre and by ``lift`` out of
    the circle's plane (a space pair when ``lift`` is not 0); its start is ``1.5 radius`` back.
    """
    mp.mp.dps = 40
    circle = bd.Edge.make_circle(radius)
    joint = segments(circle)[1].t0
    a = mp.mpf(joint) + mp.mpf(arc) / radius
    p = [radius * mp.cos(a), radius * mp.sin(a), mp.mpf(0)]
    t, n, z = [-mp.sin(a), mp.cos(a), 0], [-mp.cos(a), -mp.sin(a), 0], [0, 0, 1]
    d = _unit([mp.cos(lift) * (mp.cos(theta) * x + mp.sin(theta) * y) + mp.sin(lift) * w
               for x, y, w in zip(t, n, z, strict=True)])
    start = [float(c - 1.5 * radius * e) for c, e in zip(p, d, strict=True)]
    end = [float(c + 1.2 * radius * e) for c, e in zip(p, d, strict=True)]
    knot_point = [radius * mp.cos(joint), radius * mp.sin(joint), mp.mpf(0)]
    assert _line_distance(knot_point, p, d) <= TOL  # the case the test is about, as above
    assert mp.sqrt(sum((x - y) ** 2 for x, y in zip(knot_point, p, strict=True))) > TOL
    return circle, bd.Edge.make_line(start, end), float(a)


@pytest.mark.parametrize(("radius", "arc", "theta", "lift", "kind"), [
    (1.0, -2e-7, 0.0, 0.0, "tangent"), (1.0, -1.3e-7, 0.0, 0.0, "tangent"), (4.0, 3e-7, 0.0, 0.0, "tangent"),
    (1.0, 2e-7, 0.3, 0.0, "crossing"),
    (40.0, -2e-7, 0.3, 0.0, "crossing"), (1.0, -2e-7, 0.0, 0.4, "crossing"), (1.0, 1.5e-7, 0.3, 0.5, "crossing")])
def test_a_contact_near_a_circle_joint_is_placed_on_it(radius: float, arc: float, theta: float, lift: float,
                                                       kind: str) -> None:
    """A line along the tangent lifted out of the circle's plane meets it at the lift's angle: a crossing."""
    circle, line, a = _circle_case(radius, arc, theta, lift)
    [hit] = [r for r in intersections(circle, line, tol=TOL) if abs(r.t - a) < 1e-2]
    assert hit.kind == kind
    assert abs(hit.t - a) * radius <= 1e-9, (hit.t, a)
    assert abs(hit.u - 1.5 * radius) <= 1e-8 * radius, hit.u
    assert math.isfinite(hit.distance) and hit.distance <= TOL


@pytest.mark.parametrize("tilted", [False, True])
def test_a_touch_the_core_calls_a_crossing_at_a_circle_joint(tilted: bool) -> None:
    """A line touching a unit circle 2e-7 before the joint at 90 degrees, its ends computed in doubles.

    The joint is 2e-14 from the line, within the rounding floor: the core saw sine 2e-7 there and
    called both copies crossings; the edges on both sides of the joint show a touch.
    """
    a = math.pi / 2 - 2e-7
    p = (math.cos(a), math.sin(a), 0.0)
    d = (-math.sin(a), math.cos(a), 0.0)
    line = bd.Edge.make_line(tuple(c - 1.5 * e for c, e in zip(p, d, strict=True)),
                             tuple(c + 1.2 * e for c, e in zip(p, d, strict=True)))
    circle = bd.Edge.make_circle(1.0)
    if tilted:
        place = bd.Location((3.0, -2.0, 1.5), (1, 2, 3), 37)
        circle, line = circle.moved(place), line.moved(place)
    [hit] = [r for r in intersections(circle, line, tol=TOL) if abs(r.t - a) < 1e-2]
    assert hit.kind == "tangent"
    assert abs(hit.t - a) <= 1e-9, (hit.t, a)
    assert abs(hit.u - 1.5) <= 1e-8, hit.u

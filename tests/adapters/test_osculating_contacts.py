"""A conic and its circle of curvature at a vertex: one touch (contact of order four) at the vertex.

The ellipse ``x²/a² + y²/b² = 1`` at its vertex ``(a, 0)``, the parabola ``y² = 4 f x`` at ``(0, 0)``
and the hyperbola ``x²/a² - y²/b² = 1`` at ``(a, 0)`` have curvature radius ``R = b²/a`` (``2 f``
for the parabola), centre on the axis: the circle there meets the conic at the vertex only, the gap
growing as the fourth power of the distance along. The rounding of the converted spans (1e-16)
made such a pair cross twice 1e-4 to 6e-4 either side of the vertex, or once, or come out as an
overlap 4e-4 long: the answer changed with nothing but the circle's start angle and the trim.
The truth here is the closed form, in real OCCT edges (``Geom_Ellipse``, ``Geom_Parabola``,
``Geom_Hyperbola`` trimmed, ``Geom_Circle``), in the XY plane and in a tilted plane off the origin.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_Transform
from OCP.Geom import Geom_Circle, Geom_Ellipse, Geom_Hyperbola, Geom_Parabola, Geom_TrimmedCurve
from OCP.gp import gp_Ax1, gp_Ax2, gp_Dir, gp_Pnt, gp_Trsf, gp_Vec

from relief_cad import RationalBezier, intersect
from relief_cad.cad import intersections

TOL = 1e-7
FAMILIES = {  # the conic, its vertex on the x axis, and the centre and radius of its circle there
    "ellipse": (lambda ax: Geom_Ellipse(ax, 2.0, 1.0), 2.0, 1.5, 0.5),
    "parabola": (lambda ax: Geom_Parabola(ax, 0.75), 0.0, 1.5, 1.5),
    "hyperbola": (lambda ax: Geom_Hyperbola(ax, 1.0, 1.5), 1.0, 3.25, 2.25),
}


def _placed(shape, tilted: bool, origin: tuple[float, float, float]):
    move = gp_Trsf()
    move.SetTranslation(gp_Vec(*origin))
    if tilted:
        turn = gp_Trsf()
        turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 0.9)
        move = move.Multiplied(turn)
    return BRepBuilderAPI_Transform(shape, move, True).Shape(), move


def _pair(family: str, turn: float, trim: tuple[float, float], tilted: bool, origin: tuple[float, float, float]):
    """The trimmed conic, its circle of curvature at the vertex (start turned by ``turn``), the vertex."""
    make, vx, cx, radius = FAMILIES[family]
    conic = make(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0)))
    conic_edge = BRepBuilderAPI_MakeEdge(Geom_TrimmedCurve(conic, *trim)).Edge()
    ax = gp_Ax2(gp_Pnt(cx, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0))
    ax.Rotate(gp_Ax1(ax.Location(), ax.Direction()), turn)
    circle_edge = BRepBuilderAPI_MakeEdge(Geom_Circle(ax, radius)).Edge()
    a, move = _placed(conic_edge, tilted, origin)
    b, _ = _placed(circle_edge, tilted, origin)
    return a, b, gp_Pnt(vx, 0, 0).Transformed(move).Coord()


CASES = [
    (family, turn, trim, tilted, origin)
    for family, turn, tilted, origin in itertools.product(
        FAMILIES, (0.0, 0.3, 0.77, 2.0, -0.5, 3.0), (False, True), ((0.0, 0.0, 0.0), (-7.5, 3.25, 1.0)))
    for trim in ((-0.37, 2.9), (-1.1, 0.83), (-0.5, 0.6))
    if not (family == "ellipse" and trim == (-0.5, 0.6))
]


@pytest.mark.parametrize(("family", "turn", "trim", "tilted", "origin"), CASES)
def test_a_conic_touches_its_circle_of_curvature_once_at_the_vertex(family, turn, trim, tilted, origin) -> None:
    a, b, vertex = _pair(family, turn, trim, tilted, origin)
    res = list(intersections(a, b, tol=TOL))
    assert [r.kind for r in res] == ["tangent"], res
    assert math.dist(res[0].point, vertex) <= TOL, (res[0].point, vertex)
    assert abs(res[0].t) <= 1e-7 or abs(res[0].t - 2 * math.pi) <= 1e-7  # the conic's vertex parameter
    angle = 0.0 if family == "ellipse" else math.pi  # where the vertex lies on the circle
    assert abs(math.remainder(res[0].u + turn - angle, 2 * math.pi)) <= 1e-6  # the circle starts at -turn


def _arc(centre: np.ndarray, radius: float, mid: float, half: float) -> RationalBezier:
    """The circular arc ``mid ± half`` as a rational quadratic (weights 1, cos half, 1)."""
    def at(angle: float) -> np.ndarray:
        return centre + radius * np.array([math.cos(angle), math.sin(angle)])

    tip = centre + radius / math.cos(half) * np.array([math.cos(mid), math.sin(mid)])
    return RationalBezier([at(mid - half), tip, at(mid + half)], [1.0, math.cos(half), 1.0])


@pytest.mark.parametrize("turn", [-0.77, -0.5, 0.0, 0.1, 0.3, 0.5, 0.77])
def test_a_bezier_ellipse_arc_touches_its_circle_of_curvature_once(turn: float) -> None:
    """The core alone: rational quadratic arcs, the ellipse's over -60..60 degrees (vertex at t = 1/2).

    With the circle turned by 0.3 the core gave one crossing 1e-4 from the vertex. (Moved to
    coordinates of 2,000, the rounded data cross twice there, exactly: the core keeps the data's
    crossings, and the CAD layer, which knows the data were rounded, joins them into the touch.)
    """
    s = np.zeros(2)
    c60 = math.cos(math.pi / 3)
    ellipse = RationalBezier([s + (2 * c60, -math.sin(math.pi / 3)), s + (2 / c60, 0.0),
                              s + (2 * c60, math.sin(math.pi / 3))], [1.0, c60, 1.0])
    circle = _arc(s + (1.5, 0.0), 0.5, turn, 1.0)  # angle 0 at u = 1/2 - tan(turn / 2) / (2 tan(1/2))
    res = intersect(ellipse, circle, tol=TOL)
    assert [r.kind for r in res] == ["tangent"], res
    assert abs(res[0].t - 0.5) <= 1e-7
    assert abs(res[0].u - (0.5 - math.tan(turn / 2) / (2 * math.tan(0.5)))) <= 1e-6
    assert math.dist(res[0].point, s + (2.0, 0.0)) <= TOL

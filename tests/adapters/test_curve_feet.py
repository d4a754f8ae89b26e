"""Feet of points on edges (``ocp.curve_foot``): OCCT's projection, and one answer on either entry.

``curve_foot`` runs a few Newton steps on Python floats from a parameter near the foot. Its
answer is checked against OCCT's own ``GeomAPI_ProjectPointOnCurve`` on real build123d edges (a
line, an arc, an ellipse arc and a space B-spline), for points 1e-9 to 1e-2 off the curve near a
known parameter; ``edge_foot`` (an adaptor made per call) must give the same bits as
``curve_foot`` on an adaptor made once, which the CAD layer keeps per edge.
"""

from __future__ import annotations

import math

import build123d as bd
import pytest
from OCP.BRep import BRep_Tool
from OCP.GeomAPI import GeomAPI_ProjectPointOnCurve
from OCP.gp import gp_Pnt

from relief_cad.cad import ocp

EDGES = {
    "line": lambda: bd.Edge.make_line((0, 0, 0), (3, 1, 0.5)),
    "arc": lambda: bd.Edge.make_circle(2.0, start_angle=10, end_angle=250),
    "ellipse": lambda: bd.Edge.make_ellipse(3.0, 1.0, start_angle=0, end_angle=200),
    "spline": lambda: bd.Edge.make_spline([(0, 0, 0), (1, 2, 1), (2, -1, -1), (3, 2, 2), (4, 0, -0.5)]),
}


def _offset_point(edge: bd.Edge, t: float, off: float) -> tuple[float, float, float]:
    """The point ``off`` model units from the edge at ``t``, across its tangent (in the XY plane or out of it)."""
    p = ocp.edge_value(edge.wrapped, t)
    d = ocp.edge_tangent(edge.wrapped, t)
    n = (-d[1], d[0], 0.0) if abs(d[0]) + abs(d[1]) > 1e-12 else (1.0, 0.0, 0.0)
    scale = off / math.hypot(*n)
    return (p[0] + n[0] * scale, p[1] + n[1] * scale, p[2] + n[2] * scale)


@pytest.mark.parametrize("name", sorted(EDGES))
@pytest.mark.parametrize("off", [1e-9, 1e-6, 1e-2])
def test_curve_foot_is_occts_projection(name: str, off: float) -> None:
    edge = EDGES[name]()
    t0, t1 = BRep_Tool.Range_s(edge.wrapped)
    curve = BRep_Tool.Curve_s(edge.wrapped, 0.0, 0.0)
    adaptor = ocp.edge_adaptor(edge.wrapped)
    for f in (0.2, 0.5, 0.8):
        t = t0 + f * (t1 - t0)
        point = _offset_point(edge, t, off)
        start = t + 1e-3 * (t1 - t0)  # near the foot, not on it
        u, dist = ocp.curve_foot(adaptor, point, start)
        proj = GeomAPI_ProjectPointOnCurve(gp_Pnt(*point), curve, t0, t1)
        assert proj.NbPoints() >= 1
        assert abs(u - proj.LowerDistanceParameter()) <= 1e-9 * (t1 - t0)
        assert abs(dist - proj.LowerDistance()) <= 1e-12 * max(1.0, off)
        assert ocp.edge_foot(edge.wrapped, point, start) == (u, dist)  # the same bits either way


def test_curve_foot_stays_in_the_range() -> None:
    """A point beyond an end of the edge has its foot at that end, not past it."""
    edge = EDGES["line"]()
    t0, t1 = BRep_Tool.Range_s(edge.wrapped)
    u, dist = ocp.curve_foot(ocp.edge_adaptor(edge.wrapped), (4.0, 1.0, 0.5), 0.5 * (t0 + t1))
    assert u == t1
    assert dist == pytest.approx(math.dist((4.0, 1.0, 0.5), ocp.edge_value(edge.wrapped, t1)), rel=1e-15)

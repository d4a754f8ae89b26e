"""The one OCCT curve-type dispatch: what kind of ``Geom_Curve`` an edge lies on.

Conversion (:mod:`.ocp`), the OCCT routes (:mod:`.occt`) and the arbiter's exact data
(:mod:`.exact`) all ask :func:`curve_kind` and branch on its answer, so a curve type is
recognised the same way everywhere. Trimmed curves are looked through
(:func:`basis_curve`): an edge's parameters are those of the basis curve.

>>> from OCP.GC import GC_MakeArcOfCircle
>>> from OCP.gp import gp_Pnt
>>> arc = GC_MakeArcOfCircle(gp_Pnt(1, 0, 0), gp_Pnt(0, 1, 0), gp_Pnt(-1, 0, 0)).Value()
>>> type(arc).__name__, curve_kind(arc)
('Geom_TrimmedCurve', 'circle')
"""

from __future__ import annotations

from typing import Any, Literal

from OCP.Geom import (
    Geom_BezierCurve,
    Geom_BSplineCurve,
    Geom_Circle,
    Geom_Ellipse,
    Geom_Hyperbola,
    Geom_Line,
    Geom_Parabola,
    Geom_TrimmedCurve,
)

__all__ = ["CurveKind", "EXACT_KINDS", "basis_curve", "curve_kind"]

CurveKind = Literal["line", "circle", "ellipse", "hyperbola", "parabola", "bezier", "bspline", "other"]

EXACT_KINDS: tuple[CurveKind, ...] = (
    "line", "circle", "ellipse", "hyperbola", "parabola", "bezier", "bspline",
)
"""The kinds relief_cad converts exactly (``"other"``: offset curves... are approximated)."""

_KINDS: tuple[tuple[type, CurveKind], ...] = (
    (Geom_Line, "line"),
    (Geom_Circle, "circle"),
    (Geom_Ellipse, "ellipse"),
    (Geom_BSplineCurve, "bspline"),
    (Geom_BezierCurve, "bezier"),
    (Geom_Parabola, "parabola"),
    (Geom_Hyperbola, "hyperbola"),
)


def basis_curve(curve: Any) -> Any:
    """Return the curve under any ``Geom_TrimmedCurve`` layers (the curve itself otherwise).

    >>> from OCP.gp import gp_Dir, gp_Pnt
    >>> line = Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))
    >>> basis_curve(Geom_TrimmedCurve(line, 0.0, 1.0)) is not None
    True
    """
    while isinstance(curve, Geom_TrimmedCurve):
        curve = curve.BasisCurve()
    return curve


def curve_kind(curve: Any) -> CurveKind:
    """Return the kind of a ``Geom_Curve`` (trimmed curves: the kind of their basis curve).

    Examples
    --------
    >>> from OCP.gp import gp_Dir, gp_Pnt
    >>> curve_kind(Geom_Line(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0))), curve_kind(None)
    ('line', 'other')
    """
    curve = basis_curve(curve)
    for cls, kind in _KINDS:
        if isinstance(curve, cls):
            return kind
    return "other"

r"""OCP conversion: OCCT edges to rational Bézier segments and back.

Every OCP call of relief_cad lives here (1-based arrays, handles, locations);
the build123d and CadQuery modules only unwrap ``.wrapped`` and rewrap results.

Conversion is exact (up to rounding) for lines, circles, ellipses, parabolas,
hyperbolas, Bézier curves, B-splines (rational or not, clamped or periodic,
any knot multiplicities) and trimmed curves of those. Each edge becomes a list
of :class:`Segment`: a :class:`~relief_cad.curves.RationalBezier` (in global
coordinates: the edge's ``TopLoc_Location`` is applied) plus the exact map
between the segment parameter ``s`` in ``[0, 1]`` and the edge's own OCCT
parameter ``t``:

* lines, parabolas, Bézier and B-spline spans: ``t = t0 + s (t1 - t0)``;
* circle and ellipse arcs (the parameter is an angle; each span of at most 90°
  with half-angle :math:`\alpha` and middle :math:`\theta_m` is the standard
  rational quadratic with weights :math:`1, \cos\alpha, 1`):

  .. math:: t = \theta_m + 2 \arctan\bigl(\tan(\alpha/2)\,(2s - 1)\bigr)

* hyperbola arcs (weights :math:`1, \cosh\beta, 1`):

  .. math:: t = U_m + 2 \operatorname{artanh}\bigl(\tanh(\beta/2)\,(2s - 1)\bigr)

Other curves (offset curves, edges known only on a surface...) are
approximated by OCCT (``GeomConvert_ApproxCurve``) and flagged
``approximate=True`` with the achieved error, or refused with
:class:`~relief_cad.errors.UnsupportedCurveError` when approximation is off.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> edge = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()
>>> [seg] = edge_segments(edge)
>>> seg.curve.control_points.tolist(), seg.t_range
([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]], (0.0, 2.0))
"""

from __future__ import annotations

import bisect
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from OCP.BRep import BRep_Builder, BRep_Tool
from OCP.BRepAdaptor import BRepAdaptor_Curve
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeVertex
from OCP.Geom import Geom_BezierCurve, Geom_Curve, Geom_TrimmedCurve
from OCP.Geom2d import Geom2d_BezierCurve
from OCP.GeomAbs import GeomAbs_Shape
from OCP.GeomConvert import GeomConvert_ApproxCurve, GeomConvert_BSplineCurveToBezierCurve
from OCP.gp import gp_Pnt, gp_Pnt2d, gp_Vec
from OCP.Precision import Precision
from OCP.TopAbs import TopAbs_FORWARD, TopAbs_REVERSED
from OCP.TopLoc import TopLoc_Location
from OCP.TopoDS import TopoDS_Edge, TopoDS_Vertex

from .._kernels.bezier import affine_rows
from ..curves import RationalBezier
from ..errors import (
    DegenerateCurveError,
    InputTypeError,
    InvalidInputError,
    OcctError,
    UnsupportedCurveError,
)
from ._compat import Array1OfPnt, Array1OfPnt2d, Array1OfReal, downcast_edge
from .curvetypes import basis_curve, curve_kind
from .topology import as_edge, check_bounded, edges_of, make_compound, unwrap

__all__ = [
    "APPROXIMATION_TOLERANCE",
    "MAX_CONIC_SPAN",
    "Segment",
    "edge_on_curve",
    "edge_segments",
    "edges_of",
    "edge_tolerance",
    "edge_value",
    "edge_with_3d_curve",
    "from_geom_bezier",
    "make_compound",
    "make_vertex",
    "planar_frame",
    "shortest_piece",
    "to_edge",
    "to_geom2d_bezier",
    "to_geom_bezier",
    "trim_edge",
    "unwrap",
]

MAX_CONIC_SPAN: float = math.pi / 2
"""Largest angle (radians) one rational quadratic span of a circle or ellipse covers."""

MAX_HYPERBOLA_SPAN: float = 1.0
"""Largest hyperbolic-parameter width one rational quadratic hyperbola span covers."""

APPROXIMATION_TOLERANCE: float = 1e-7
"""Default 3D tolerance (model units) for curves OCCT has to approximate (offset curves...)."""

_MAX_BEZIER_DEGREE = 25  # OCCT's Geom_BezierCurve limit


# --------------------------------------------------------------------------- segments
@dataclass(frozen=True, eq=False)
class Segment:
    """One rational Bézier piece of an edge and its exact parameter map.

    Attributes
    ----------
    homogeneous : ndarray, shape (n + 1, 4)
        The piece's homogeneous control points ``[w x, w y, w z, w]`` in global
        coordinates (read-only).
    curve : RationalBezier
        The piece as a curve, control points shape ``(n + 1, 3)`` (built on first
        access from :attr:`homogeneous`; see :meth:`from_curve`).
    t0, t1 : float
        The edge parameters at ``s = 0`` and ``s = 1`` (``t0 < t1``).
    mapping : {"linear", "circular", "hyperbolic"}
        How ``s`` maps to ``t`` (see the module docstring).
    centre : float
        ``θ_m`` / ``U_m`` of a conic span (unused for ``"linear"``).
    scale : float
        ``tan(α/2)`` / ``tanh(β/2)`` of a conic span (unused for ``"linear"``).
    approximate : bool
        True when the piece comes from an OCCT approximation.
    error : float
        The approximation error OCCT reports (model units); 0 for exact pieces.

    Examples
    --------
    >>> seg = Segment.from_curve(RationalBezier([[0, 0, 0], [1, 0, 0]]), 2.0, 4.0)
    >>> seg.edge_param(0.25), seg.segment_param(3.0)
    (2.5, 0.5)
    """

    homogeneous: np.ndarray
    t0: float
    t1: float
    mapping: str = "linear"
    centre: float = 0.0
    scale: float = 1.0
    approximate: bool = False
    error: float = 0.0

    @classmethod
    def from_curve(cls, curve: RationalBezier, t0: float, t1: float, **kwargs: Any) -> Segment:
        """Build a segment from a space curve (keyword arguments as the attributes).

        Examples
        --------
        >>> Segment.from_curve(RationalBezier([[0, 0, 0], [1, 0, 0]]), 0.0, 1.0).curve.degree
        1
        """
        seg = cls(curve.homogeneous, float(t0), float(t1), **kwargs)
        seg.__dict__["curve"] = curve
        return seg

    @functools.cached_property
    def curve(self) -> RationalBezier:
        """The piece as a :class:`~relief_cad.curves.RationalBezier` (space, dim 3)."""
        return _make_curve(self.homogeneous)

    @functools.cached_property
    def control_points(self) -> np.ndarray:
        """Cartesian control points, shape ``(n + 1, 3)``."""
        h = self.homogeneous
        return h[:, :3] / h[:, 3:]  # type: ignore[no-any-return]

    @property
    def t_range(self) -> tuple[float, float]:
        """The edge-parameter range ``(t0, t1)`` the segment covers.

        >>> import build123d as bd
        >>> from relief_cad.cad import segments
        >>> segments(bd.Line((0, 0), (3, 4)))[0].t_range
        (0.0, 5.0)
        """
        return (self.t0, self.t1)

    def edge_param(self, s: Any) -> Any:
        """Map segment parameters ``s`` in ``[0, 1]`` to the edge's OCCT parameters (exactly).

        Parameters
        ----------
        s : float or ndarray
            Segment parameter(s); 0 and 1 map exactly to ``t0`` and ``t1``.

        Returns
        -------
        float or ndarray
            Edge parameter(s), same shape as ``s``.

        Examples
        --------
        >>> Segment.from_curve(RationalBezier([[0, 0, 0], [1, 0, 0]]), 0.0, 2.0).edge_param(1.0)
        2.0
        """
        if isinstance(s, (float, int)):
            x = float(s)
            if x == 0.0:
                return self.t0
            if x == 1.0:
                return self.t1
            if self.mapping == "linear":
                return self.t0 + x * (self.t1 - self.t0)
            if self.mapping == "circular":
                return self.centre + 2.0 * math.atan(self.scale * (2.0 * x - 1.0))
            return self.centre + 2.0 * math.atanh(self.scale * (2.0 * x - 1.0))
        scalar = np.ndim(s) == 0
        sa = np.asarray(s, dtype=np.float64)
        if self.mapping == "linear":
            t = self.t0 + sa * (self.t1 - self.t0)
        elif self.mapping == "circular":
            t = self.centre + 2.0 * np.arctan(self.scale * (2.0 * sa - 1.0))
        else:
            t = self.centre + 2.0 * np.arctanh(self.scale * (2.0 * sa - 1.0))
        t = np.where(sa == 0.0, self.t0, np.where(sa == 1.0, self.t1, t))
        return float(t) if scalar else t

    def segment_param(self, t: Any) -> Any:
        """Map edge parameters ``t`` in ``[t0, t1]`` to segment parameters (exact inverse).

        Parameters
        ----------
        t : float or ndarray
            Edge parameter(s).

        Returns
        -------
        float or ndarray
            Segment parameter(s) ``s``; ``t0`` and ``t1`` map exactly to 0 and 1.

        Examples
        --------
        >>> Segment.from_curve(RationalBezier([[0, 0, 0], [1, 0, 0]]), 0.0, 2.0).segment_param(2.0)
        1.0
        """
        if isinstance(t, (float, int)):
            x = float(t)
            if x == self.t0:
                return 0.0
            if x == self.t1:
                return 1.0
            if self.mapping == "linear":
                return (x - self.t0) / (self.t1 - self.t0)
            if self.mapping == "circular":
                return 0.5 * (math.tan(0.5 * (x - self.centre)) / self.scale + 1.0)
            return 0.5 * (math.tanh(0.5 * (x - self.centre)) / self.scale + 1.0)
        scalar = np.ndim(t) == 0
        ta = np.asarray(t, dtype=np.float64)
        if self.mapping == "linear":
            s = (ta - self.t0) / (self.t1 - self.t0)
        elif self.mapping == "circular":
            s = 0.5 * (np.tan(0.5 * (ta - self.centre)) / self.scale + 1.0)
        else:
            s = 0.5 * (np.tanh(0.5 * (ta - self.centre)) / self.scale + 1.0)
        s = np.where(ta == self.t0, 0.0, np.where(ta == self.t1, 1.0, s))
        return float(s) if scalar else s


def _segment(h: np.ndarray, t0: float, t1: float, mapping: str = "linear", centre: float = 0.0,
             scale: float = 1.0) -> Segment:
    """A :class:`Segment` of an exact conversion, without the frozen-dataclass ``__init__`` (hot path)."""
    seg = object.__new__(Segment)
    seg.__dict__.update(homogeneous=h, t0=t0, t1=t1, mapping=mapping, centre=centre, scale=scale,
                        approximate=False, error=0.0)
    return seg


def _make_curve(h: np.ndarray) -> RationalBezier:
    """Build a curve from homogeneous rows OCCT guarantees finite with positive weights."""
    trusted = getattr(RationalBezier, "_trusted", None)
    if trusted is not None:
        return trusted(h)  # type: ignore[no-any-return]
    return RationalBezier.from_homogeneous(h)  # pragma: no cover


# --------------------------------------------------------------------------- shapes in
def edge_tolerance(edge: Any) -> float:
    """Return OCCT's tolerance of an edge (``BRep_Tool.Tolerance``, model units).

    Examples
    --------
    >>> edge_tolerance(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)).Edge())
    1e-07
    """
    return float(BRep_Tool.Tolerance_s(as_edge(edge)))


# --------------------------------------------------------------------------- conversion
# the matrices of the locations met last, by OCCT's hash of the location: the edges of one sketch,
# glyph or placed part share one location, whose twelve values cost twelve calls into OCCT (7 us)
_MATRICES: dict[int, tuple[TopLoc_Location, np.ndarray]] = {}
_MATRICES_KEPT = 256


def _location_matrix(loc: TopLoc_Location) -> np.ndarray | None:
    """Return the 3x4 matrix of a location (``None`` for the identity), read-only.

    A location equal to one met before (``IsEqual``: the same chain of transformations, hence
    the same values) gets the matrix read then.
    """
    if loc.IsIdentity():
        return None
    key = loc.HashCode()
    hit = _MATRICES.get(key)
    if hit is not None and hit[0].IsEqual(loc):
        return hit[1]
    value = loc.Transformation().Value
    mat = np.array([[value(r, c) for c in (1, 2, 3, 4)] for r in (1, 2, 3)])
    mat.flags.writeable = False
    if len(_MATRICES) >= _MATRICES_KEPT:
        _MATRICES.clear()
    _MATRICES[key] = (loc, mat)
    return mat


def _apply(h: np.ndarray, m: np.ndarray | None) -> np.ndarray:
    """Apply a 3x4 affine matrix to homogeneous rows ``[w x, w y, w z, w]`` (n, 4), in place.

    The products are summed by :func:`~relief_cad._kernels.bezier.affine_rows` (one FMA chain per
    entry), the same bits on every machine whatever its BLAS.
    """
    if m is not None:
        affine_rows(h, m, h)
    return h


def _conic_frame(curve: Any) -> tuple[tuple[float, float, float], ...]:
    pos = curve.Position()
    return pos.Location().Coord(), pos.XDirection().Coord(), pos.YDirection().Coord()


def _rows(
    frame: tuple[tuple[float, float, float], ...], coords: list[tuple[float, float, float]]
) -> np.ndarray:
    """Homogeneous rows ``[w (O + x X + y Y), w]`` from local ``(x w, y w, w)`` triples."""
    (ox, oy, oz), (xx, xy, xz), (yx, yy, yz) = frame
    return np.array(
        [
            (ox * w + x * xx + y * yx, oy * w + x * xy + y * yy, oz * w + x * xz + y * yz, w)
            for x, y, w in coords
        ]
    )


def _quadratic_spans(
    curve: Any,
    first: float,
    last: float,
    m: np.ndarray | None,
    kind: str,
) -> list[Segment]:
    """Rational quadratic spans of an ellipse (circle) or hyperbola arc, in closed form.

    Ellipse: ``P(θ) = O + a cos θ X + b sin θ Y``; a span of half-angle ``α`` around
    ``θm`` has weights ``1, cos α, 1`` and middle point ``O + (a cos θm X + b sin θm Y) / cos α``.
    Hyperbola: the same with ``cosh`` / ``sinh``. ``kind`` is the curve's :func:`curve_kind`:
    ``"circle"``, ``"ellipse"`` or ``"hyperbola"``.
    """
    frame = _conic_frame(curve)
    fx: Any
    fy: Any
    fs: Any
    if kind == "hyperbola":
        a, b = curve.MajorRadius(), curve.MinorRadius()
        fx, fy, fs = math.cosh, math.sinh, math.tanh
        max_span, mapping = MAX_HYPERBOLA_SPAN, "hyperbolic"
    else:
        if kind == "circle":
            a = b = curve.Radius()
        else:
            a, b = curve.MajorRadius(), curve.MinorRadius()
        fx, fy, fs = math.cos, math.sin, math.tan
        max_span, mapping = MAX_CONIC_SPAN, "circular"
    if not (a > 0.0 and b > 0.0):
        raise DegenerateCurveError(f"expected a conic with radii > 0; received radii {a} and {b}")
    span = last - first
    n = max(1, math.ceil(span / max_span - 1e-9))
    knots = [first + span * i / n for i in range(n)] + [last]
    (ox, oy, oz), (xx, xy, xz), (yx, yy, yz) = frame
    rows = []
    params = []
    # the middle control point is stored times its weight cos(half) / cosh(half)
    x0, y0 = a * fx(first), b * fy(first)
    for i in range(n):
        k0, k1 = knots[i], knots[i + 1]
        half = 0.5 * (k1 - k0)
        mid = k0 + half
        x1, y1 = a * fx(k1), b * fy(k1)
        # as _rows(frame, [(x0, y0, 1), (a fx(mid), b fy(mid), fx(half)), (x1, y1, 1)])
        rows.append(
            [
                (ox * w + x * xx + y * yx, oy * w + x * xy + y * yy, oz * w + x * xz + y * yz, w)
                for x, y, w in ((x0, y0, 1.0), (a * fx(mid), b * fy(mid), fx(half)), (x1, y1, 1.0))
            ]
        )
        params.append((k0, k1, mid, fs(0.5 * half)))
        x0, y0 = x1, y1
    hs = np.array(rows)
    return [
        _segment(_apply(hs[i], m), k0, k1, mapping, mid, scale)
        for i, (k0, k1, mid, scale) in enumerate(params)
    ]


def _parabola_segment(curve: Any, first: float, last: float, m: np.ndarray | None) -> list[Segment]:
    f4 = 4.0 * curve.Focal()
    # P(U) = O + U^2/(4F) X + U Y; middle control point P(U0) + (U1 - U0)/2 P'(U0)
    coords = [
        (first * first / f4, first, 1.0),
        (first * last / f4, 0.5 * (first + last), 1.0),
        (last * last / f4, last, 1.0),
    ]
    return [Segment(_apply(_rows(_conic_frame(curve), coords), m), first, last)]


def _line_segment(curve: Any, first: float, last: float, m: np.ndarray | None) -> list[Segment]:
    lin = curve.Lin()
    ox, oy, oz = lin.Location().Coord()
    dx, dy, dz = lin.Direction().Coord()
    h = np.array(
        [
            (ox + first * dx, oy + first * dy, oz + first * dz, 1.0),
            (ox + last * dx, oy + last * dy, oz + last * dz, 1.0),
        ]
    )
    return [_segment(_apply(h, m), first, last)]


def _bezier_rows(bez: Any) -> np.ndarray:
    """Homogeneous rows of a Geom_BezierCurve (1-based OCCT access)."""
    n = bez.NbPoles()
    pole = bez.Pole
    if bez.IsRational():
        weight = bez.Weight
        rows = []
        for i in range(1, n + 1):
            x, y, z = pole(i).Coord()
            w = weight(i)
            rows.append((x * w, y * w, z * w, w))
        return np.array(rows)
    return np.array([(*pole(i).Coord(), 1.0) for i in range(1, n + 1)])


def _bezier_segment(curve: Any, first: float, last: float, m: np.ndarray | None) -> list[Segment]:
    h = _apply(_bezier_rows(curve), m)
    if first == 0.0 and last == 1.0:
        return [Segment(h, first, last)]
    return [Segment.from_curve(_make_curve(h).segment(first, last), first, last)]


def _bspline_segments(curve: Any, first: float, last: float, m: np.ndarray | None) -> list[Segment]:
    degree = curve.Degree()
    if (
        curve.NbKnots() == 2
        and not curve.IsPeriodic()
        and curve.Multiplicity(1) == curve.Multiplicity(2) == degree + 1
    ):
        # a single clamped span is a Bézier curve already: its poles are the control points
        h = _apply(_bezier_rows(curve), m)
        k0, k1 = curve.Knot(1), curve.Knot(2)
        if first == k0 and last == k1:
            return [Segment(h, first, last)]
        piece = _make_curve(h).segment((first - k0) / (k1 - k0), (last - k0) / (k1 - k0))
        return [Segment.from_curve(piece, first, last)]
    knots = [curve.Knot(i) for i in range(1, curve.NbKnots() + 1)]
    out: list[Segment] = []
    for r0, r1, shift in _conversion_ranges(curve, knots, first, last):
        out.extend(_knot_arcs(curve, knots, r0, r1, shift, m))
    if not out:
        raise OcctError(f"GeomConvert_BSplineCurveToBezierCurve gave no arc on [{first}, {last}]")
    # the labels of the edge's own bounds, exactly (the conversion ranges may have snapped them)
    out[0] = _segment(out[0].homogeneous, first, out[0].t1)
    out[-1] = _segment(out[-1].homogeneous, out[-1].t0, last)
    return out


def _conversion_ranges(curve: Any, knots: list[float], first: float,
                       last: float) -> list[tuple[float, float, float]]:
    """``[first, last]`` as ranges within the knot domain: ``(r0, r1, shift)``, edge parameter = r + shift.

    A periodic curve's range is moved by whole periods to start in the knot domain, and cut at
    its seam: OCCT reduces a bound past the domain to the knot a period before (``LocateU``), and
    then fails on ``[5, 7]`` of knots 0..6 (7 taken as 1).
    """
    if not curve.IsPeriodic():
        return [(first, last, 0.0)]
    k0, k1 = knots[0], knots[-1]
    period = k1 - k0
    shift = math.floor((first - k0) / period) * period
    r0, r1 = _on_knot(knots, first - shift), last - shift
    if r0 >= k1:  # first a rounding below a period's start: start at k0
        r0, r1, shift = k0, r1 - period, shift + period
    if _on_knot(knots, r1) <= k1:
        return [(r0, min(r1, k1), shift)]
    return [(r0, k1, shift), (k0, r1 - period, shift + period)]


def _knot_arcs(curve: Any, knots: list[float], r0: float, r1: float, shift: float,
               m: np.ndarray | None) -> list[Segment]:
    """The Bézier arcs of ``curve`` over ``[r0, r1]`` (in its knot domain), labelled ``+ shift``.

    OCCT converts whole knot spans only (``[r0, r1]`` widened to the knots around it), where its
    arcs are exact; the end arcs are then cut at ``r0`` and ``r1`` here, by de Casteljau. Given a
    bound within ``PConfusion`` of a knot, OCCT kept the whole span but took its first pole at
    neither (a curve 14,000 long: points 3.7e-6 off the reported parameters).
    """
    r0, r1 = _on_knot(knots, r0), _on_knot(knots, r1)
    if not r1 > r0:
        return []
    lo = knots[max(0, bisect.bisect_right(knots, r0) - 1)]
    hi = knots[min(len(knots) - 1, bisect.bisect_left(knots, r1))]
    try:
        conv = GeomConvert_BSplineCurveToBezierCurve(curve, lo, hi, _KNOT_TOL)
    except Exception as exc:  # noqa: BLE001 - OCCT raises Standard_Failure subclasses
        raise OcctError(f"GeomConvert_BSplineCurveToBezierCurve failed on [{lo}, {hi}]: {exc}") from exc
    n = conv.NbArcs()
    arr = Array1OfReal(1, n + 1)
    conv.Knots(arr)
    ks = [arr.Value(i) for i in range(1, n + 2)]
    size = 0.0  # the largest coordinate of the curve's poles (for _check_arc)
    if curve.IsPeriodic():
        size = max(abs(c) for i in range(1, curve.NbPoles() + 1) for c in curve.Pole(i).Coord())
    out = []
    for i in range(n):
        a0, a1 = max(ks[i], r0), min(ks[i + 1], r1)
        if not a1 > a0:
            continue
        arc = conv.Arc(i + 1)
        if size:
            _check_arc(curve, arc, ks[i], ks[i + 1], size)
        h = _apply(_bezier_rows(arc), m)
        if (a0, a1) != (ks[i], ks[i + 1]):
            w = ks[i + 1] - ks[i]
            h = _make_curve(h).segment((a0 - ks[i]) / w, (a1 - ks[i]) / w).homogeneous
        out.append(_segment(h, a0 + shift, a1 + shift))
    return out


_KNOT_TOL = 1e-12  # the parametric tolerance given to GeomConvert_BSplineCurveToBezierCurve
_KNOT_RTOL = 1e-14  # a bound this close to a knot, relative to it, is on it (BREP text keeps 15 digits)


def _on_knot(knots: Sequence[float], x: float) -> float:
    """``x``, or the knot in ``knots`` (increasing) within :data:`_KNOT_TOL` (or :data:`_KNOT_RTOL` of it).

    A bound a few ulps off a knot (an edge range read back from a BREP file, 3e-19 below the last
    knot, or 4.3e-12 above the last knot at 1646: BREP text keeps 15 digits) is put on the knot,
    so that no arc a rounding long is cut off the span beside it. (OCCT 8.0's converter, given
    such a bound on a periodic curve, returned arcs of uninitialised poles; it is now given knots
    only, and :func:`_check_arc` still guards the arcs of periodic curves.)
    """
    i = bisect.bisect_left(knots, x)
    for k in knots[max(0, i - 1): i + 1]:
        if abs(x - k) <= max(_KNOT_TOL, _KNOT_RTOL * abs(k)):
            return float(k)
    return x


def _check_arc(curve: Any, arc: Any, k0: float, k1: float, size: float) -> None:
    """Raise :class:`OcctError` unless the Bézier ``arc`` runs on ``curve`` over ``[k0, k1]``.

    Its ends and its middle are compared with the curve's points there, to 1e-7 of ``size``
    (the largest coordinate of the curve's poles): a guard against poles OCCT left unset (see
    :func:`_on_knot`), which would be taken for the curve and give wrong intersections instead
    of an error.
    """
    for s, k in ((0.0, k0), (0.5, 0.5 * (k0 + k1)), (1.0, k1)):
        gap = arc.Value(s).Distance(curve.Value(k))
        if not gap <= 1e-7 * size:
            raise OcctError(f"GeomConvert_BSplineCurveToBezierCurve gave an arc off the curve over "
                            f"[{k0}, {k1}] (expected its point at {s} on the curve; it is {gap:.3g} away)")


def _approx_segments(
    curve_or_adaptor: Any, first: float, last: float, m: np.ndarray | None, tol: float
) -> list[Segment]:
    """Approximate any curve by a B-spline with OCCT over ``[first, last]``, keeping its parameterisation.

    A curve is trimmed to the edge's range first: OCCT approximates a curve over its own domain,
    so past a periodic curve's period the edge took an extrapolation (1.5e-5 off an offset circle),
    and an offset of an unbounded line had no usable domain at all.
    """
    if isinstance(curve_or_adaptor, Geom_Curve):
        curve_or_adaptor = Geom_TrimmedCurve(curve_or_adaptor, first, last)
    try:
        approx = GeomConvert_ApproxCurve(curve_or_adaptor, tol, GeomAbs_Shape.GeomAbs_C2, 1000, 14)
    except Exception as exc:  # noqa: BLE001
        raise OcctError(f"GeomConvert_ApproxCurve failed: {exc}") from exc
    if not approx.HasResult():
        raise UnsupportedCurveError(
            f"OCCT could not approximate this curve within {tol} (no result); it cannot be converted"
        )
    err = float(approx.MaxError())
    bs = approx.Curve()
    shift = bs.FirstParameter() - first  # a periodic curve's trimmed range may start a period on
    segs = _bspline_segments(bs, first + shift, last + shift, m)
    out = [Segment(s.homogeneous, s.t0 - shift, s.t1 - shift, approximate=True, error=err) for s in segs]
    out[0] = Segment(out[0].homogeneous, first, out[0].t1, approximate=True, error=err)
    out[-1] = Segment(out[-1].homogeneous, out[-1].t0, last, approximate=True, error=err)
    return out


def edge_segments(
    edge: Any, *, approximate: bool = True, approximation_tolerance: float = APPROXIMATION_TOLERANCE
) -> list[Segment]:
    """Convert an edge to rational Bézier segments with exact parameter maps.

    Parameters
    ----------
    edge : TopoDS_Edge or build123d / CadQuery Edge
        The edge; its location is applied, its orientation ignored (parameters
        stay the edge's own).
    approximate : bool, keyword-only
        Allow OCCT approximation for curve types without an exact conversion
        (offset curves, curves on surfaces, other curves); the segments are then
        flagged ``approximate=True``. If False such edges raise
        :class:`UnsupportedCurveError`.
    approximation_tolerance : float, keyword-only
        The 3D tolerance asked of the approximation (model units).

    Returns
    -------
    list of Segment
        In increasing edge parameter, covering the edge's range without gaps.

    Raises
    ------
    InputTypeError
        If ``edge`` is not an edge.
    DegenerateCurveError
        If the edge is degenerated or has zero length.
    UnsupportedCurveError
        If the curve needs approximation and ``approximate`` is False (or fails).

    Examples
    --------
    >>> from OCP.GC import GC_MakeArcOfCircle
    >>> arc = GC_MakeArcOfCircle(gp_Pnt(1, 0, 0), gp_Pnt(0, 1, 0), gp_Pnt(-1, 0, 0)).Value()
    >>> segs = edge_segments(BRepBuilderAPI_MakeEdge(arc).Edge())
    >>> len(segs), segs[0].curve.degree, round(segs[-1].t1, 12)
    (2, 2, 3.14159265359)
    >>> edge_segments(make_compound([]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: expected an edge; received a compound shape ...
    """
    e = as_edge(edge)
    if BRep_Tool.Degenerated_s(e):
        raise DegenerateCurveError("expected an edge with a curve; received a degenerated edge (a point)")
    first, last = check_bounded(e)
    return _bounded_segments(e, first, last, approximate, approximation_tolerance)


def _bounded_segments(
    e: TopoDS_Edge, first: float, last: float, approximate: bool = True,
    approximation_tolerance: float = APPROXIMATION_TOLERANCE,
) -> list[Segment]:
    """:func:`edge_segments` of a raw edge already checked: not degenerated, range ``[first, last]`` bounded.

    The path of callers that have checked their edges once (:func:`~relief_cad.cad.topology.usable_edges`).

    Raises
    ------
    DegenerateCurveError
        If ``first >= last``, or the edge has zero length.
    UnsupportedCurveError
        As :func:`edge_segments`.
    """
    loc = TopLoc_Location()
    curve = BRep_Tool.Curve_s(e, loc, 0.0, 0.0)
    if not last > first:
        raise DegenerateCurveError(
            f"expected an edge with a parameter range t0 < t1; received [{first}, {last}] (zero length)"
        )
    m = _location_matrix(loc)
    if curve is None or (hasattr(curve, "IsNull") and curve.IsNull()):
        # only a curve on a surface: approximate the 3D curve from the adaptor
        if not approximate:
            raise UnsupportedCurveError("the edge has no 3D curve (only a curve on a surface)")
        return _check_length(_approx_segments(BRepAdaptor_Curve(e), first, last, None,
                                              approximation_tolerance))
    return _curve_segments(curve, first, last, m, approximate, approximation_tolerance)


def _curve_segments(
    curve: Any, first: float, last: float, m: np.ndarray | None, approximate: bool, tol: float
) -> list[Segment]:
    kind = curve_kind(curve)
    curve = basis_curve(curve)
    if kind == "line":
        return _line_segment(curve, first, last, m)
    if kind in ("circle", "ellipse", "hyperbola"):
        return _quadratic_spans(curve, first, last, m, kind)
    if kind == "bspline":
        return _check_length(_bspline_segments(curve, first, last, m))
    if kind == "bezier":
        return _check_length(_bezier_segment(curve, first, last, m))
    if kind == "parabola":
        return _parabola_segment(curve, first, last, m)
    name = type(curve).__name__
    if not approximate:
        raise UnsupportedCurveError(
            f"expected a line, conic, Bézier or B-spline curve for exact conversion; received {name} "
            "(pass approximate=True to convert it by OCCT approximation)"
        )
    return _approx_segments(curve, first, last, m, tol)


def _check_length(segs: list[Segment]) -> list[Segment]:
    """Refuse free-form edges whose control points all coincide (lines and conics cannot)."""
    x0, y0, z0, w0 = segs[0].homogeneous[0].tolist()
    p0 = (x0 / w0, y0 / w0, z0 / w0)
    px, py, pz = p0
    for seg in segs:  # usually decided by the first segment
        for x, y, z, w in seg.homogeneous.tolist():
            if x != w * px or y != w * py or z != w * pz:
                return segs
    raise DegenerateCurveError(
        f"expected an edge of non-zero length; received one whose every control point is {list(p0)}"
    )


def edge_with_3d_curve(edge: Any, tol: float = APPROXIMATION_TOLERANCE) -> TopoDS_Edge:
    """Return the edge itself, or for an edge known only by curves on surfaces a new edge on a 3D curve.

    The new edge lies on OCCT's B-spline approximation (``GeomConvert_ApproxCurve`` of the
    edge's ``BRepAdaptor_Curve``, within ``tol`` model units) over the same parameter
    range, so parameters keep their meaning.

    Examples
    --------
    >>> from OCP.Geom import Geom_Plane
    >>> from OCP.Geom2d import Geom2d_Line
    >>> from OCP.gp import gp_Dir2d, gp_Pln
    >>> line2d = Geom2d_Line(gp_Pnt2d(0, 0), gp_Dir2d(1, 0))
    >>> e = BRepBuilderAPI_MakeEdge(line2d, Geom_Plane(gp_Pln()), 0.0, 2.0).Edge()
    >>> BRep_Tool.Curve_s(e, 0.0, 0.0) is None, BRep_Tool.Range_s(edge_with_3d_curve(e))
    (True, (0.0, 2.0))
    """
    e = as_edge(edge)
    if BRep_Tool.Curve_s(e, 0.0, 0.0) is not None:
        return e
    first, last = check_bounded(e)
    try:
        approx = GeomConvert_ApproxCurve(BRepAdaptor_Curve(e), tol, GeomAbs_Shape.GeomAbs_C2, 1000, 14)
    except Exception as exc:  # noqa: BLE001 - OCCT raises Standard_Failure subclasses
        raise OcctError(f"GeomConvert_ApproxCurve failed on an edge without a 3D curve: {exc}") from exc
    if not approx.HasResult():
        raise UnsupportedCurveError(
            "OCCT could not approximate the 3D curve of an edge known only on surfaces"
        )
    maker = BRepBuilderAPI_MakeEdge(approx.Curve(), first, last)
    if not maker.IsDone():
        raise OcctError(f"BRepBuilderAPI_MakeEdge failed on [{first}, {last}] (error {maker.Error()})")
    return maker.Edge()


def edge_value(edge: Any, t: float) -> tuple[float, float, float]:
    """Return the point of an edge at its own parameter ``t`` (``BRepAdaptor_Curve``, global coordinates).

    Examples
    --------
    >>> edge_value(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge(), 0.5)
    (0.5, 0.0, 0.0)
    """
    return curve_value(edge_adaptor(edge), t)


def edge_adaptor(edge: Any) -> BRepAdaptor_Curve:
    """The edge's ``BRepAdaptor_Curve`` (global coordinates), made once for many ``curve_*`` calls.

    For :func:`curve_value`, :func:`curve_tangent` and :func:`curve_foot` at many parameters of
    one edge.

    Examples
    --------
    >>> edge_adaptor(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()).LastParameter()
    2.0
    """
    return BRepAdaptor_Curve(as_edge(edge))


def curve_value(curve: BRepAdaptor_Curve, t: float) -> tuple[float, float, float]:
    """:func:`edge_value` on an edge's ``BRepAdaptor_Curve`` made once (for many parameters of one edge).

    Examples
    --------
    >>> curve_value(edge_adaptor(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()), 0.5)
    (0.5, 0.0, 0.0)
    """
    return curve.Value(float(t)).Coord()  # type: ignore[no-any-return]


def edge_tangent(edge: Any, t: float) -> tuple[float, float, float]:
    """Return an edge's first derivative at its own parameter ``t`` (``BRepAdaptor_Curve``, global).

    Examples
    --------
    >>> edge_tangent(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge(), 0.5)
    (1.0, 0.0, 0.0)
    """
    return curve_tangent(edge_adaptor(edge), t)


def curve_tangent(curve: BRepAdaptor_Curve, t: float) -> tuple[float, float, float]:
    """:func:`edge_tangent` on an edge's ``BRepAdaptor_Curve`` made once.

    Examples
    --------
    >>> curve_tangent(edge_adaptor(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()), 0.5)
    (1.0, 0.0, 0.0)
    """
    p, d1 = gp_Pnt(), gp_Vec()
    curve.D1(float(t), p, d1)
    return d1.Coord()  # type: ignore[no-any-return]


def edge_foot(edge: Any, point: Sequence[float], u: float, steps: int = 8) -> tuple[float, float]:
    """The foot on an edge of ``point`` near the edge's parameter ``u``, and the distance to it.

    :func:`curve_foot` on the edge's ``BRepAdaptor_Curve`` (global coordinates).

    Examples
    --------
    >>> line = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge()
    >>> edge_foot(line, (0.5, 0.25, 0.0), 1.5)
    (0.5, 0.25)
    """
    return curve_foot(edge_adaptor(edge), point, u, steps)


def curve_foot(
    curve: BRepAdaptor_Curve, point: Sequence[float], u: float, steps: int = 8
) -> tuple[float, float]:
    """The foot on an edge's curve adaptor of ``point`` near its parameter ``u``, and the distance to it.

    A few Newton steps on the squared distance, kept in the edge's range; a local foot, for
    points close to the edge near ``u``. The steps are on Python floats, the dot products summed
    in coordinate order: the same bits as numpy's on this data, without a BLAS (whose kernels
    may sum in another order) and at a fifth of the cost.

    Examples
    --------
    >>> line = edge_adaptor(BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 0, 0)).Edge())
    >>> curve_foot(line, (0.5, 0.25, 0.0), 1.5)
    (0.5, 0.25)
    """
    lo, hi = curve.FirstParameter(), curve.LastParameter()
    p, d1, d2 = gp_Pnt(), gp_Vec(), gp_Vec()
    x0, x1, x2 = (float(c) for c in point)
    for _ in range(steps):
        curve.D2(u, p, d1, d2)
        px, py, pz = p.Coord()
        f0, f1, f2 = px - x0, py - x1, pz - x2
        a0, a1, a2 = d1.Coord()
        b0, b1, b2 = d2.Coord()
        speed2 = a0 * a0 + a1 * a1 + a2 * a2
        h = speed2 + (f0 * b0 + f1 * b1 + f2 * b2)
        h = h if h > 0.0 else speed2
        if h == 0.0:
            break
        nu = min(hi, max(lo, u - (f0 * a0 + f1 * a1 + f2 * a2) / h))
        if nu == u:
            break
        u = nu
    return u, math.dist(curve.Value(u).Coord(), (x0, x1, x2))


# --------------------------------------------------------------------------- planar frame
def planar_frame(points: np.ndarray, tol: float) -> np.ndarray | None:
    """Return a 2x4 affine map to a plane containing ``points`` (rows), or None if not coplanar.

    The rows of the result are ``(u, -u·o)`` and ``(v, -v·o)`` for an orthonormal
    in-plane basis ``u, v`` and a point ``o`` of the plane, so ``M @ (x, y, z, 1)``
    gives 2D coordinates. The map is affine and isometric, so curve parameters
    and distances are unchanged. Points count as coplanar when every one lies
    within ``tol`` of the plane.

    Examples
    --------
    >>> frame = planar_frame(np.array([[0, 0, 1.0], [1, 0, 1], [0, 1, 1]]), 1e-12)
    >>> (frame @ [1.0, 2.0, 1.0, 1.0]).tolist()
    [1.0, 2.0]
    >>> planar_frame(np.array([[0, 0, 0.0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]), 1e-12) is None
    True
    """
    pts = np.asarray(points, dtype=np.float64)
    z = pts[:, 2]
    if float(z.max() - z.min()) <= tol:
        # parallel to XY (the common sketch case): drop z, keeping x and y bit-exact
        return np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]])
    o = pts.mean(axis=0)
    # thin SVD (zero rows pad to 3 without changing the right singular vectors): the full
    # one builds an N x N matrix and dominated intersections() on edges with many poles
    centred = np.vstack([pts - o, np.zeros((max(0, 3 - pts.shape[0]), 3))])
    _, sv, vt = np.linalg.svd(centred, full_matrices=False)
    normal = vt[2]
    if float(np.max(np.abs((pts - o) @ normal))) > tol:
        return None
    u, v = vt[0], vt[1]
    frame = np.empty((2, 4))
    frame[0, :3] = u
    frame[1, :3] = v
    frame[0, 3] = -float(u @ o)
    frame[1, 3] = -float(v @ o)
    return frame


# --------------------------------------------------------------------------- shapes out
def make_vertex(point: Sequence[float]) -> TopoDS_Vertex:
    """Return a ``TopoDS_Vertex`` at ``point`` (x, y, z).

    Examples
    --------
    >>> BRep_Tool.Pnt_s(make_vertex((1.0, 2.0, 3.0))).Coord()
    (1.0, 2.0, 3.0)
    """
    return BRepBuilderAPI_MakeVertex(gp_Pnt(float(point[0]), float(point[1]), float(point[2]))).Vertex()


def shortest_piece(tol: float) -> float:
    """The least distance (model units) between the end points of a piece of an edge cut by relief_cad.

    OCCT's edge maker takes two ends within ``Precision::Confusion()`` (1e-7) of each
    other for one point, and refuses two different vertices there
    (``BRepBuilderAPI_DifferentPointsOnClosedCurve``): no cut is made closer than
    that to another cut or to an edge's end, nor closer than the model tolerance
    ``tol``. So on parts not much larger than 1e-7, cuts that close merge.

    >>> shortest_piece(1e-9), shortest_piece(0.01)
    (1e-07, 0.01)
    """
    return max(float(tol), float(Precision.Confusion_s()))


def trim_edge(edge: Any, t0: float, t1: float) -> TopoDS_Edge:
    """Return the part of ``edge`` over the edge parameters ``[t0, t1]`` as a new edge.

    The new edge lies on the same curve, keeps the edge's location and
    orientation.

    Raises
    ------
    DegenerateCurveError
        If ``t0 == t1``.

    Examples
    --------
    >>> e = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(4, 0, 0)).Edge()
    >>> BRep_Tool.Range_s(trim_edge(e, 1.0, 3.0))
    (1.0, 3.0)
    """
    e = as_edge(edge)
    lo, hi = (float(t0), float(t1)) if t0 <= t1 else (float(t1), float(t0))
    if lo == hi:
        raise DegenerateCurveError(f"expected t0 != t1 to trim an edge; received t0 = t1 = {lo}")
    loc = TopLoc_Location()
    curve = BRep_Tool.Curve_s(e, loc, 0.0, 0.0)
    if curve is None:
        raise UnsupportedCurveError("cannot trim an edge without a 3D curve")
    new = edge_on_curve(curve, lo, hi)
    if not loc.IsIdentity():
        new = downcast_edge(new.Located(loc))
    return downcast_edge(new.Oriented(e.Orientation()))


_PCONFUSION = float(Precision.PConfusion_s())  # OCCT's parametric confusion, a constant (1e-9)


def edge_on_curve(curve: Any, t0: float, t1: float, v0: Any = None, v1: Any = None) -> TopoDS_Edge:
    """An edge on ``curve`` over ``[t0, t1]`` (``t0 < t1``), between vertices ``v0`` and ``v1`` or new ones.

    As ``BRepBuilderAPI_MakeEdge``, but a range of a periodic curve shorter than
    ``Precision::PConfusion`` (1e-9) stays that range: ``MakeEdge`` takes it for a whole period
    (cuts 5e-7 apart on a circle of radius 1,000, 5e-10 rad, gave a full circle between them).
    Such an edge is put together as ``MakeEdge`` does it, on a trimmed curve around the range:
    the same parameters, not periodic (``MakeEdge`` would take the trimmed curve's basis again).

    Raises
    ------
    OcctError
        If OCCT cannot make the edge.

    Examples
    --------
    >>> from OCP.Geom import Geom_Circle
    >>> from OCP.gp import gp_Ax2, gp_Dir
    >>> circle = Geom_Circle(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1000.0)
    >>> t0, t1 = BRep_Tool.Range_s(edge_on_curve(circle, 1.0, 1.0 + 5e-10))
    >>> t1 - t0 < 1e-9
    True
    """
    if t1 - t0 <= _PCONFUSION and basis_curve(curve).IsPeriodic():
        return _short_periodic_edge(basis_curve(curve), t0, t1, v0, v1)
    if v0 is None:
        maker = BRepBuilderAPI_MakeEdge(curve, t0, t1)
    else:
        maker = BRepBuilderAPI_MakeEdge(curve, v0, v1, t0, t1)
    if not maker.IsDone():
        raise OcctError(f"BRepBuilderAPI_MakeEdge failed on [{t0}, {t1}] (error {maker.Error()})")
    return maker.Edge()


def _short_periodic_edge(basis: Any, t0: float, t1: float, v0: Any, v1: Any) -> TopoDS_Edge:
    if v0 is None:
        v0, v1 = (make_vertex(basis.Value(t).Coord()) for t in (t0, t1))
    width = 0.1 * basis.Period()
    builder = BRep_Builder()
    edge = TopoDS_Edge()
    builder.MakeEdge(edge, Geom_TrimmedCurve(basis, t0 - width, t1 + width), Precision.Confusion_s())
    builder.Add(edge, v0.Oriented(TopAbs_FORWARD))
    builder.Add(edge, v1.Oriented(TopAbs_REVERSED))
    builder.Range(edge, t0, t1)
    builder.UpdateVertex(v0, t0, edge, 0.0)
    builder.UpdateVertex(v1, t1, edge, 0.0)
    return edge


def to_geom_bezier(curve: RationalBezier) -> Geom_BezierCurve:
    """Return a ``Geom_BezierCurve`` (planar curves placed in z = 0).

    Raises
    ------
    InvalidInputError
        If the degree exceeds OCCT's limit of 25.

    Examples
    --------
    >>> g = to_geom_bezier(RationalBezier([[0, 0], [1, 1], [2, 0]], [1, 2, 1]))
    >>> g.NbPoles(), g.Weight(2), g.IsRational()
    (3, 2.0, True)
    """
    _check_degree(curve)
    pts = curve.control_points
    arr = Array1OfPnt(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, gp_Pnt(float(p[0]), float(p[1]), float(p[2]) if curve.dim == 3 else 0.0))
    if curve.is_polynomial:
        return Geom_BezierCurve(arr)
    return Geom_BezierCurve(arr, _weights_array(curve))


def to_geom2d_bezier(curve: RationalBezier) -> Geom2d_BezierCurve:
    """Return a ``Geom2d_BezierCurve`` of a planar curve.

    Raises
    ------
    InvalidInputError
        If the curve is not planar (dim 2) or its degree exceeds 25.

    Examples
    --------
    >>> to_geom2d_bezier(RationalBezier([[0, 0], [1, 1]])).NbPoles()
    2
    """
    if curve.dim != 2:
        raise InvalidInputError(f"expected a planar curve (dim 2) for Geom2d; received dim {curve.dim}")
    _check_degree(curve)
    pts = curve.control_points
    arr = Array1OfPnt2d(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, gp_Pnt2d(float(p[0]), float(p[1])))
    if curve.is_polynomial:
        return Geom2d_BezierCurve(arr)
    return Geom2d_BezierCurve(arr, _weights_array(curve))


def _check_degree(curve: RationalBezier) -> None:
    if curve.degree > _MAX_BEZIER_DEGREE:
        raise InvalidInputError(
            f"OCCT Bézier curves have degree <= {_MAX_BEZIER_DEGREE}; received degree {curve.degree}"
        )


def _weights_array(curve: RationalBezier) -> Array1OfReal:
    w = Array1OfReal(1, curve.degree + 1)
    for i, wi in enumerate(curve.weights):
        w.SetValue(i + 1, float(wi))
    return w


def from_geom_bezier(geom: Any) -> RationalBezier:
    """Return the ``RationalBezier`` of a ``Geom_BezierCurve`` (dim 3) or ``Geom2d_BezierCurve`` (dim 2).

    Raises
    ------
    InputTypeError
        If ``geom`` is neither.

    Examples
    --------
    >>> from_geom_bezier(to_geom2d_bezier(RationalBezier([[0, 0], [1, 1]]))).control_points.tolist()
    [[0.0, 0.0], [1.0, 1.0]]
    """
    if isinstance(geom, Geom_BezierCurve):
        return _make_curve(_bezier_rows(geom))
    if isinstance(geom, Geom2d_BezierCurve):
        n = geom.NbPoles()
        h = np.empty((n, 3))
        for i in range(n):
            h[i, :2] = geom.Pole(i + 1).Coord()
            h[i, 2] = geom.Weight(i + 1)
        h[:, :2] *= h[:, 2:]
        return _make_curve(h)
    raise InputTypeError(
        f"expected a Geom_BezierCurve or Geom2d_BezierCurve; received {type(geom).__name__}"
    )


def to_edge(curve: RationalBezier) -> TopoDS_Edge:
    """Return a ``TopoDS_Edge`` on the curve (parameter range ``[0, 1]``; planar curves in z = 0).

    Examples
    --------
    >>> e = to_edge(RationalBezier([[0, 0, 0], [3, 4, 0]]))
    >>> edge_value(e, 1.0)
    (3.0, 4.0, 0.0)
    """
    maker = BRepBuilderAPI_MakeEdge(to_geom_bezier(curve))
    if not maker.IsDone():
        raise OcctError(f"BRepBuilderAPI_MakeEdge failed on a Bézier curve (error {maker.Error()})")
    return maker.Edge()


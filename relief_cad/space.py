r"""Space-curve intersection by the paper's relief-perspective scheme.

For space rational curves ``a(t)``, ``b(u)`` (Hlúšek, "Bezier curves intersection using relief
perspective"):

.. math::

    a \xrightarrow{φ} a^r \xrightarrow{ψ} a^s, \qquad
    b \xrightarrow{φ} b^r \xrightarrow{ψ} b^s,

Bézier clipping intersects the planar curves ``a^s``, ``b^s``; a candidate ``(t, u)`` is real only
where the reliefs agree, ``a^r(t) = b^r(u)`` (central projection forgets depth), and the point is
``φ^{-1}`` of the common relief point.

Why this works for *any* space rational curves, not only the paper's form: the relief ``φ`` fixes
every line through the centre O, so ``ψ ∘ φ = ψ``. All that is needed is a frame (centre O and
image plane ``z = 1``) in which every control point of both curves lies in front of O (so the
projected weights are positive) and the projection is not degenerate. When both curves already
lie in front of O in the model's own coordinates (as the paper's curves ``Q`` do), that frame is
the model's; otherwise one is chosen from the control points. Since ``φ`` is a bijection off its
neutral plane, "the reliefs agree" is the same as "the curves meet", which is checked (and
polished, by Gauss-Newton on ``|a(t) - b(u)|^2``) in model units so that ``tol`` keeps its meaning.

Tolerance: a space gap ``g`` between points at depth ``z >= z_min`` projects to a planar gap of
at most ``g · sqrt(1 + r_max^2) / z_min`` (the largest singular value of ``Dψ`` over the convex
hull of the control points, ``r_max`` the largest projected radius there), so the planar clipping
runs with that widened tolerance and no space near-miss closer than ``tol`` is lost.

>>> import numpy as np
>>> from relief_cad import RationalBezier
>>> a = RationalBezier([[0, 0, 0], [1, 1, 1], [2, 0, 2]])
>>> b = RationalBezier([[0, 0, 2], [1, 1, 1], [2, 0, 0]])
>>> [round(r.t, 12) for r in intersect_space(a, b)]
[0.5]
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import NDArray

from ._checks import (
    OnBudget,
    as_real_array,
    check_budget,
    check_curve,
    check_finite,
    check_on_budget,
    check_param,
    check_span,
    check_tol,
)
from ._kernels import (
    KIND_OVERLAP,
    KIND_UNRESOLVED,
    SPACE_COLS,
    STATUS_ARTEFACT,
    _space_frame,
    intersect_one_kernel,
    space_pair_kernel,
    space_pair_rows,
)
from ._kernels.bezier import max_abs
from ._kernels.rows import space_results
from ._types import FloatArray
from .contacts import _needs_refining, _refine_contacts, _refine_self, _whole_overlap, range_exponent
from .curves import RationalBezier
from .errors import BudgetExceededError, InputTypeError, InvalidInputError, ProjectionError, ShapeError
from .pieces import _monotone_pieces, _one_place
from .relief import ReliefPerspective, central_projection
from .results import Intersection, IntersectionList, ParameterBox, Result, _finish
from .tolerances import _is_point_like, _resolve_tolerance, _sampled_tolerance

__all__ = ["ReliefFrame", "ReliefScheme", "intersect_space", "relief_scheme"]



@dataclass(frozen=True)
class ReliefFrame:
    """A projection frame: model coordinates -> frame coordinates (centre O at the origin).

    >>> from relief_cad import RationalBezier
    >>> curve = RationalBezier([[0, 0, 1], [1, 1, 2]])   # already in front of O: the model's frame
    >>> relief_scheme(curve, curve.reversed()).frame.name
    'model'

    Attributes
    ----------
    matrix : ndarray, shape (4, 4)
        Homogeneous similarity (rotation, translation, uniform scale) to frame coordinates.
    scale : float
        Model units per frame unit.
    name : str
        ``"model"`` for the model's own frame (the paper's), else how it was chosen.
    """

    matrix: FloatArray
    scale: float
    name: str


@dataclass(frozen=True)
class ReliefScheme:
    """The intermediate curves of the scheme for one frame (for figures, teaching and debugging).

    >>> from relief_cad import RationalBezier
    >>> s = relief_scheme(RationalBezier([[0, 0, 1], [1, 1, 2]]), RationalBezier([[1, 0, 1], [0, 1, 2]]))
    >>> s.a_relief.dim, s.a_image.dim, s.perspective.k
    (3, 2, 2.0)

    Attributes
    ----------
    frame : ReliefFrame
    perspective : ReliefPerspective
        The relief map ``φ`` used.
    a_frame, b_frame : RationalBezier
        The curves in frame coordinates.
    a_relief, b_relief : RationalBezier
        Their reliefs ``φ(a)``, ``φ(b)``.
    a_image, b_image : RationalBezier
        The planar images ``ψ(φ(a))``, ``ψ(φ(b))`` in the image plane ``z = 1``.
    planar_tolerance : float
        The widened tolerance used for the planar clipping (image-plane units).
    """

    frame: ReliefFrame
    perspective: ReliefPerspective
    a_frame: RationalBezier
    b_frame: RationalBezier
    a_relief: RationalBezier
    b_relief: RationalBezier
    a_image: RationalBezier
    b_image: RationalBezier
    planar_tolerance: float


_FRAME_NAMES = ("model", "least-variance axis", "tilted view", "fixed oblique view")


def _first_frame(points: FloatArray) -> ReliefFrame:
    """The frame the kernel tries first for these control points (model coordinates).

    Out of the safe range (:func:`relief_cad.contacts.range_exponent`) the points are scaled by a
    power of two first, exactly as :func:`_pair` scales them for the kernel.
    """
    exp = range_exponent(max_abs(points, 3))
    ref = np.ldexp(points[0], -exp)
    local = np.ascontiguousarray(np.ldexp(points, -exp) - ref)
    m = np.empty((4, 4))
    for mode, name in enumerate(_FRAME_NAMES):
        scale = float(_space_frame(mode, local, ref, m))
        if scale > 0.0:
            shift = np.eye(4)
            shift[:3, 3] = -ref
            shrink = np.diag([math.ldexp(1.0, -exp)] * 3 + [1.0])
            return ReliefFrame(matrix=m @ shift @ shrink, scale=math.ldexp(scale, exp), name=name)
    raise AssertionError("unreachable: the oblique frames always exist")  # pragma: no cover


def _check_frame(frame: object) -> ReliefFrame:
    """``frame`` when it is a :class:`ReliefFrame` whose matrix is a similarity of scale ``1 / frame.scale``.

    The planar tolerance is the space one divided by ``frame.scale``: any other matrix (a shear, a
    projective map, a scale that does not match) would give the scheme a meaningless tolerance.

    >>> _check_frame(ReliefFrame(np.eye(4), -1.0, "mine"))
    Traceback (most recent call last):
    ...
    relief_cad.errors.InvalidInputError: frame.scale should be > 0 (model units per frame unit), not -1.0
    """
    if not isinstance(frame, ReliefFrame):
        raise InputTypeError(f"frame should be a ReliefFrame or None, not {type(frame).__name__}")
    m = as_real_array(frame.matrix, "frame.matrix")
    if m.shape != (4, 4):
        raise ShapeError(f"frame.matrix should have shape (4, 4), not {m.shape}")
    check_finite(m, "frame.matrix")
    scale = check_param(frame.scale, "frame.scale")
    if scale <= 0.0:
        raise InvalidInputError(f"frame.scale should be > 0 (model units per frame unit), not {scale!r}")
    rot = m[:3, :3] * scale
    with np.errstate(over="ignore", invalid="ignore"):  # an overflow fails the test
        off = float(np.max(np.abs(rot @ rot.T - np.eye(3))))
    if not (off <= 1e-9 and m[3].tolist() == [0.0, 0.0, 0.0, 1.0]):
        raise InvalidInputError(
            "frame.matrix should be a similarity (frame.scale * its 3x3 block orthogonal, last row "
            f"(0, 0, 0, 1)), not one whose last row is {m[3].tolist()} and whose scaled block is off "
            f"orthogonal by {off:.3g}")
    return frame


def _framed(curve: RationalBezier, frame: ReliefFrame, name: str) -> RationalBezier:
    """``curve`` in frame coordinates, every control point in front of the centre (``z > 0``)."""
    out = curve.transformed(frame.matrix)
    z = out.homogeneous[:, 2]
    if not np.all(z > 0.0):
        i = int(np.argmin(z > 0.0))
        raise ProjectionError(
            f"frame should put every control point of {name} in front of the centre (z > 0 in frame "
            f"coordinates); control point {i} has z = {float(out.control_points[i, 2])!r}")
    return out


def _planar_tolerance(a_f: RationalBezier, b_f: RationalBezier, tol_frame: float) -> float:
    pts = np.vstack([a_f.control_points, b_f.control_points])
    zmin = float(pts[:, 2].min())
    r2 = float(np.max((pts[:, 0] ** 2 + pts[:, 1] ** 2) / pts[:, 2] ** 2))
    return math.sqrt(1.0 + r2) / zmin * tol_frame * (1.0 + 1e-6)


def relief_scheme(
    a: RationalBezier, b: RationalBezier, *, frame: ReliefFrame | None = None, k: float = 2.0,
    tol: float | None = None,
) -> ReliefScheme:
    """Return the curves of the relief scheme for ``a`` and ``b`` in one frame.

    Parameters
    ----------
    a, b : RationalBezier
        Space curves (planar ones are taken in ``z = 0``).
    frame : ReliefFrame, optional
        The frame; by default the first admissible one (the model's own when every control point
        has ``z > 0``, as for the paper's curves).
    k : float, default 2.0
        Span of the relief perspective ``φ`` (a real number > 0 and != 1: else
        :class:`~relief_cad.errors.SpanError` / :class:`~relief_cad.errors.InputTypeError`). It shapes
        the reliefs ``a_relief``, ``b_relief``; the images ``ψ(φ(a))`` are the same for every ``k``.
    tol : float, optional
        Space tolerance (model units) from which the planar one is derived; resolved as in
        :func:`intersect_space` (:func:`relief_cad.tolerances.resolve_tolerance`).

    Returns
    -------
    ReliefScheme

    Raises
    ------
    InputTypeError
        If ``a`` or ``b`` is not a RationalBezier, ``frame`` not a ReliefFrame (or None), or ``k``
        not a real number.
    SpanError, ToleranceError
        For a span ``k`` that is not > 0 and != 1, or a ``tol`` as in :func:`intersect_space`.
    InvalidInputError, ShapeError, NonFiniteError
        For a given ``frame`` whose matrix is not a finite 4x4 similarity of scale ``1 / frame.scale``.
    ProjectionError
        For a given ``frame`` that puts a control point on or behind the centre (``z <= 0``).

    Examples
    --------
    >>> from relief_cad import RationalBezier, preimage_of_lift
    >>> P = RationalBezier([[0, 0], [1, 2], [2, 0]], [1.0, 0.5, 1.0])
    >>> s = relief_scheme(preimage_of_lift(P, 2.0), preimage_of_lift(P.reversed(), 2.0))
    >>> s.frame.name, bool(np.allclose(s.a_image(0.3), P(0.3)))
    ('model', True)
    >>> relief_scheme("x", P)
    Traceback (most recent call last):
    ...
    relief_cad.errors.InputTypeError: a should be a RationalBezier, not str
    """
    a3 = check_curve(a, "a").embedded(3)
    b3 = check_curve(b, "b").embedded(3)
    phi = ReliefPerspective(k)  # checks the span k
    t = _resolve_tolerance(check_tol(tol), a3, b3)
    if frame is None:
        frame = _first_frame(np.vstack([a3.control_points, b3.control_points]))
    else:
        frame = _check_frame(frame)
    a_f = _framed(a3, frame, "a")
    b_f = _framed(b3, frame, "b")
    a_r = phi.apply(a_f)
    b_r = phi.apply(b_f)
    return ReliefScheme(
        frame=frame,
        perspective=phi,
        a_frame=a_f,
        b_frame=b_f,
        a_relief=a_r,
        b_relief=b_r,
        a_image=central_projection(a_r),
        b_image=central_projection(b_r),
        planar_tolerance=_planar_tolerance(a_f, b_f, t / frame.scale),
    )


# ---------------------------------------------------------------------------- driver
def _pair(ha: FloatArray, hb: FloatArray, tol: float, budget: int) -> FloatArray:
    """The space kernel on one pair (homogeneous rows), scaled by a power of two when needed.

    Out of the safe range of :data:`relief_cad.contacts.SAFE_EXPONENT` the kernel's Gauss-Newton
    step (products of squared derivatives) would overflow.
    """
    exp = range_exponent(max(max_abs(ha, 3), max_abs(hb, 3)))
    if not exp:
        return _pair_in_range(ha, hb, tol, budget)
    ha = ha.copy()
    hb = hb.copy()
    ha[:, :3] = np.ldexp(ha[:, :3], -exp)
    hb[:, :3] = np.ldexp(hb[:, :3], -exp)
    rows: FloatArray = _pair_in_range(ha, hb, math.ldexp(tol, -exp), budget).copy()
    rows[:, 5:9] = np.ldexp(rows[:, 5:9], exp)  # the point and the distance, back in model units
    return rows


def _pair_in_range(ha: FloatArray, hb: FloatArray, tol: float, budget: int) -> FloatArray:
    rows = _separated(ha, hb, tol, budget, 0)
    if rows is None:
        raise BudgetExceededError(
            "every projection frame showed an overlap of the projected curves that is not an overlap "
            f"in space (both curves on one cone through each centre tried), in halves of the curves "
            f"too, {_SPLIT_DEPTH} times over; they could not be separated",
            partial=IntersectionList([]), unresolved=[ParameterBox(0.0, 1.0, 0.0, 1.0)],
        )
    return rows


_SPLIT_DEPTH = 6  # halvings of both curves, at most, of a pair that every frame shows as an artefact


def _separated(ha: FloatArray, hb: FloatArray, tol: float, budget: int, depth: int) -> FloatArray | None:
    """The space rows of a pair, from the halves of both curves where every frame shows an artefact.

    Curves that stay within tol of each other along part of their length only (a space curve and
    a copy turned by 1e-6 about a line through one of its points) project, in every frame, to
    images overlapping beyond where the curves do. Halving both curves (up to
    :data:`_SPLIT_DEPTH` times) separates the stretch within tol from the rest; the rows of the
    halves are mapped back to the pair's parameters. None when a part still cannot be separated.
    """
    # ψ∘φ = ψ: the span of the relief changes nothing (see intersect_space); the kernel takes 2
    rows, n, status = space_pair_kernel(ha, hb, tol, budget, 2.0)
    if status != STATUS_ARTEFACT:
        out: FloatArray = rows[:n]
        return out
    flat = _coplanar_rows(ha, hb, tol, budget)
    if flat is not None or depth >= _SPLIT_DEPTH:
        return flat
    parts = []
    halves_b = [h.homogeneous for h in RationalBezier._trusted(hb).split(0.5)]
    for ka, part_a in enumerate(RationalBezier._trusted(ha).split(0.5)):
        for kb, part_b in enumerate(halves_b):
            sub = _separated(part_a.homogeneous, part_b, tol, budget, depth + 1)
            if sub is None:
                return None
            sub = sub.copy()
            sub[:, [1, 3]] = 0.5 * (ka + sub[:, [1, 3]])  # t, t1 (an overlap's or a box's)
            sub[:, [2, 4]] = 0.5 * (kb + sub[:, [2, 4]])  # u, u1
            parts.append(sub)
    return _joined_halves(np.vstack(parts))


def _joined_halves(rows: FloatArray) -> FloatArray:
    """Rows of the halves of a pair as one: a point found by two halves once, abutting overlaps joined."""
    points = [r for r in rows.tolist() if r[0] != KIND_OVERLAP]
    overlaps = sorted((r for r in rows.tolist() if r[0] == KIND_OVERLAP), key=lambda r: r[1])
    kept: list[list[float]] = []
    for r in points:
        if r[0] == KIND_UNRESOLVED or not any(q[0] != KIND_UNRESOLVED and q[1] == r[1] and q[2] == r[2]
                                                for q in kept):
            kept.append(r)
    joined: list[list[float]] = []
    for r in overlaps:
        if joined and joined[-1][3] == r[1] and joined[-1][4] == r[2]:
            joined[-1][3:5] = r[3:5]
        else:
            joined.append(r)
    out = [r for r in kept if not any(o[1] <= r[1] <= o[3] and min(o[2], o[4]) <= r[2] <= max(o[2], o[4])
                                      for o in joined)]
    return np.array(out + joined, dtype=np.float64).reshape(-1, SPACE_COLS)


def _coplanar_rows(ha: FloatArray, hb: FloatArray, tol: float, budget: int) -> FloatArray | None:
    """Space rows of two curves lying in one plane (within ``tol``), intersected in that plane.

    Curves on a common cone through every centre tried (collinear segments, a segment and a curve
    running out and back along it) have images that overlap in every frame; when all their control
    points lie within ``tol`` of one plane, the convex hull puts the curves there too, and the planar
    clipping in that plane's coordinates answers them. ``None`` when they are not coplanar.
    """
    pa = ha[:, :3] / ha[:, 3:]
    pb = hb[:, :3] / hb[:, 3:]
    both = np.vstack([pa, pb])
    centre = both.mean(axis=0)
    axes = np.linalg.svd(both - centre)[2]  # rows: in-plane, in-plane, normal
    if float(np.max(np.abs((both - centre) @ axes[2]))) > tol:
        return None
    flat = intersect_one_kernel((pa - centre) @ axes[:2].T, ha[:, 3].copy(), (pb - centre) @ axes[:2].T,
                                hb[:, 3].copy(), tol, budget)
    rows = np.zeros((flat.shape[0], SPACE_COLS))
    rows[:, 0:5] = flat[:, 1:6]  # kind, t, u, t1, u1 (boxes: t0, u0, t1, u1)
    rows[:, 5:8] = centre + flat[:, 6:7] * axes[0] + flat[:, 7:8] * axes[1]
    rows[:, 8] = flat[:, 8]
    return rows


def _monotone(points: FloatArray) -> bool:
    """True when every leg of the control polygon advances along the chord: no self-intersection.

    A leg of length zero (a repeated control point: where the curve's derivative vanishes, such as
    each piece ending at the tip of a curve that runs out and back) advances nothing and is
    allowed. The curve's projection on the chord is then still strictly increasing (positive
    weights keep the variation diminishing), so it cannot meet itself; before, such a piece was
    never monotone and was halved twelve times.
    """
    big = float(np.max(np.abs(points)))
    unit = points / big if big > 0.0 else points  # scaled: no overflow for coordinates up to 1e308
    legs = np.diff(unit, axis=0)
    chord = unit[-1] - unit[0]
    return bool(np.all((legs @ chord > 0.0) | ~legs.any(axis=1)))


def _boxes_near(points: list[FloatArray], tol: float) -> NDArray[np.bool_]:
    """``near[i, j]``: the control-point boxes of pieces ``i`` and ``j`` are within ``tol`` on every axis.

    A curve lies in the hull of its control points, so pieces whose boxes are farther apart than
    ``tol`` have no contact: the pair is not sent to the kernel (a retracing curve splits into
    dozens of pieces near its fold, and most pairs of them lie apart).
    """
    lo = np.array([p.min(axis=0) for p in points])
    hi = np.array([p.max(axis=0) for p in points])
    apart = (lo[:, None, :] > hi[None, :, :] + tol) | (lo[None, :, :] > hi[:, None, :] + tol)
    near: NDArray[np.bool_] = np.logical_not(apart.any(axis=2))
    return near


def _self_rows(curve: RationalBezier, tol: float, budget: int) -> FloatArray:
    """Self-intersections: split into monotone pieces, intersect every pair of pieces."""
    if _is_point_like(curve, tol):
        return np.empty((0, SPACE_COLS))  # a point has no self-intersection
    pieces = _monotone_pieces(curve, tol, _monotone, 12)
    near = _boxes_near([p.control_points for _, _, p in pieces], tol)
    rows: list[FloatArray] = []
    for i, (a0, a1, pa) in enumerate(pieces):
        for j in range(i + 1, len(pieces)):
            if not near[i, j]:
                continue
            b0, b1, pb = pieces[j]
            found = _pair(pa.homogeneous, pb.homogeneous, tol, budget)
            for r in found:
                r = r.copy()
                if j == i + 1 and r[1] == 1.0 and r[2] == 0.0:
                    continue  # the joint shared by consecutive pieces
                r[1] = a0 + r[1] * (a1 - a0)
                r[3] = a0 + r[3] * (a1 - a0)
                r[2] = b0 + r[2] * (b1 - b0)
                r[4] = b0 + r[4] * (b1 - b0)
                if abs(r[2] - r[1]) <= 1e-9 or _one_place(curve, r[1], r[2], tol):
                    continue  # one place of the curve (both sides of a sharp tip)
                rows.append(r)
    if not rows:
        return np.empty((0, SPACE_COLS))
    table = np.array(sorted(rows, key=lambda r: (r[1], r[2])))
    keep = [table[0]]
    for r in table[1:]:
        if abs(r[1] - keep[-1][1]) <= 1e-9 and abs(r[2] - keep[-1][2]) <= 1e-9:
            continue
        keep.append(r)
    return np.array(keep)


def intersect_space(
    a: RationalBezier,
    b: RationalBezier | None = None,
    *,
    tol: float | None = None,
    budget: int | None = None,
    on_budget: Literal["raise", "return"] = "raise",
    k: float | None = None,
) -> IntersectionList:
    """Intersect space rational Bézier curves by the relief-perspective scheme.

    Parameters
    ----------
    a : RationalBezier
        A space curve (a planar one is taken in the plane ``z = 0``).
    b : RationalBezier, optional
        The other curve; ``None`` gives the self-intersections of ``a`` (each once, ``t < u``).
    tol : float, optional
        Distance tolerance in model units: meetings closer than ``tol`` are reported (a near-miss
        as one ``"tangent"`` contact at the closest approach, its gap in ``distance``); wider gaps
        give nothing. Default :func:`relief_cad.tolerances.default_tolerance` of both curves.
    budget : int, optional
        Iteration budget passed to the planar clipping.
    on_budget : {"raise", "return"}
        What to do when a budget runs out: raise :class:`BudgetExceededError`, or return the
        results with :attr:`IntersectionList.unresolved` filled.
    k : float, optional
        Deprecated, and without effect on the result: accepted for compatibility, checked like
        every span (a real number > 0 and != 1; else :class:`~relief_cad.errors.SpanError` or
        :class:`~relief_cad.errors.InputTypeError`) and answered with a ``DeprecationWarning``.
        The relief ``φ_k`` fixes every line through the centre, so ``ψ ∘ φ_k = ψ`` for every
        ``k``: the planar images that are clipped, hence the intersections, are the same for
        every span (in binary64 the factors ``1 + k`` moved parameters by a few ulps, 4e-16
        measured, so the kernel always runs with one span and the results are bit-identical
        whatever ``k`` is passed). The span shapes only the reliefs themselves; see
        :func:`relief_scheme`, where ``k`` is a real parameter.

    Returns
    -------
    IntersectionList
        Sorted by ``t``: :class:`Intersection` (``kind`` from the angle of the space tangents)
        and :class:`Overlap` results, parameters in ``[0, 1]`` of each curve; ``tol_used`` is
        the tolerance applied (:func:`relief_cad.tolerances.resolve_tolerance`).

    Raises
    ------
    InputTypeError, ToleranceError
        For inputs of the wrong type, a tolerance that is not a positive distance, or one above
        :data:`relief_cad.tolerances.MAX_TOLERANCE_FRACTION` of the curves' size.
    BudgetExceededError
        If a budget runs out (``on_budget="raise"``), or no frame gives a projection free of
        artefacts, for the curves nor for their halves (:data:`_SPLIT_DEPTH` times over).

    Examples
    --------
    >>> from relief_cad import RationalBezier
    >>> skew_a = RationalBezier([[0, 0, 0], [100, 0, 0]])
    >>> skew_b = RationalBezier([[50, -100, 1], [50, 100, 1]])
    >>> len(intersect_space(skew_a, skew_b))   # their projections along z cross; they do not meet
    0
    >>> near = intersect_space(skew_a, skew_b, tol=1.01)   # a near-miss within tol is a contact
    >>> near[0].kind, near[0].distance <= near.tol_used == 1.01
    ('tangent', True)
    """
    if not isinstance(a, RationalBezier) or not (b is None or isinstance(b, RationalBezier)):
        raise InputTypeError(
            "intersect_space expects RationalBezier curves, not "
            f"{type(a).__name__} and {type(b).__name__}"
        )
    a3 = a if a.dim == 3 else a.embedded(3)
    if k is not None:
        _deprecated_span(k)
    check_on_budget(on_budget)
    nbudget = check_budget(budget)
    given = check_tol(tol)
    if b is None:
        tol_s = _resolve_tolerance(given, a3)
        items, boxes = space_results(_self_rows(a3, tol_s, nbudget))
        return _finished(_refine_self(a3, items, tol_s), boxes, tol_s, on_budget)
    return space_pair(a3, b, given, nbudget, on_budget)


def space_pair(a: RationalBezier, b: RationalBezier, tol: float | None, budget: int,
               on_budget: OnBudget, resolved: float | None = None) -> IntersectionList:
    """:func:`intersect_space` of two curves, ``tol``, ``budget`` and ``on_budget`` already checked.

    The one path of a pair of space curves (a planar one is placed in z = 0), for
    :func:`intersect_space` and :func:`relief_cad.intersect`. ``tol`` None: the default tolerance.
    ``resolved``: the tolerance the caller already resolved from ``tol`` for these curves (the
    same value, a planar curve counting as lying in z = 0), used as it is.
    Most pairs take one kernel call (:func:`relief_cad._kernels.space.space_pair_rows`); curves whose
    end points match (they may coincide all along: :func:`~relief_cad.contacts.whole_overlap`),
    coordinates out of the kernel's safe range, and pairs whose every frame shows an artefact take
    the general path (:func:`_pair`).
    """
    ha, hb = a.homogeneous, b.homogeneous
    if ha.shape[1] != 4 or hb.shape[1] != 4:  # a planar curve goes in z = 0 (a space curve as it is)
        return space_pair(a.embedded(3), b.embedded(3), tol, budget, on_budget, resolved)
    tol_s = resolved or (_sampled_tolerance((a, b)) if tol is None else None) or _resolve_tolerance(tol, a, b)
    rows = space_pair_rows(ha, hb, tol_s, budget, 2.0 * tol_s)
    if rows is None:
        whole = _whole_overlap(a, b, tol_s)  # coincident curves (closed ones too) by geometry
        if whole is not None:
            return IntersectionList([whole], tol_used=tol_s)
        rows = _pair(ha, hb, tol_s, budget)
    if rows.shape[0] == 0:  # most pairs: nothing to build, sort or check
        return IntersectionList((), (), tol_s)
    items, boxes = space_results(rows)
    if _needs_refining(a, b, items):
        items = _refine_contacts(a, b, items, tol_s)
    return _finished(items, boxes, tol_s, on_budget)


def _finished(items: list[Result], boxes: list[ParameterBox], tol: float,
              on_budget: OnBudget) -> IntersectionList:
    """The results sorted by ``t`` (an overlap by its first ``t``), then :func:`relief_cad.results.finish`.

    A point's parameter within :data:`_AT_END` of a curve's end is that end, exactly, as the
    documentation of :func:`relief_cad.intersect` says of end point contacts (a T-junction in
    space came out at ``u = 7.5e-16``: the polish moved it off the end by rounding).
    """
    items = [_ends_exact(r) for r in items]
    items.sort(key=lambda r: r.t if isinstance(r, Intersection) else r.t[0])
    return _finish(IntersectionList(items, boxes, tol), on_budget)


_AT_END = 8.0 * 2.0**-52  # a parameter this close to 0 or 1 is the end: the point moves by a rounding


def _ends_exact(r: Result) -> Result:
    """``r``, or the point ``r`` with a parameter within :data:`_AT_END` of an end put on it."""
    if not isinstance(r, Intersection):
        return r
    t, u = _at_end(r.t), _at_end(r.u)
    return r if (t, u) == (r.t, r.u) else Intersection(t, u, r.point, r.kind, r.distance)


def _at_end(x: float) -> float:
    """``x``, or the end ``0.0`` / ``1.0`` within :data:`_AT_END` of it."""
    if 0.0 < x <= _AT_END:
        return 0.0
    if 1.0 - _AT_END <= x < 1.0:
        return 1.0
    return x


def _deprecated_span(k: object) -> None:
    """Check a ``k`` given to :func:`intersect_space` and warn that it has no effect."""
    check_span(k)
    warnings.warn(
        "intersect_space(k=...) has no effect and is deprecated: the relief fixes every line through "
        "the centre (psi o phi_k = psi), so the intersections are the same for every span k; "
        "k shapes only the reliefs of relief_scheme()",
        DeprecationWarning,
        stacklevel=3,
    )

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
>>> b = RationalBezier([[0, 0, 2], [1, 0.5, 1], [2, 0, 0]])
>>> [round(r.t, 12) for r in intersect_space(a, b)]
[0.5]
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass
from typing import Literal

import numpy as np

from ._types import FloatArray
from .curves import RationalBezier
from .errors import BudgetExceededError, InputTypeError, ToleranceError
from .relief import ReliefPerspective, central_projection
from .results import Intersection, IntersectionList, Overlap, ParameterBox, Result
from .tolerances import default_tolerance

__all__ = ["ReliefFrame", "ReliefScheme", "intersect_space", "relief_scheme"]

_EPS = float(np.finfo(np.float64).eps)
_MAX_FRAMES = 4
_OVERLAP_SAMPLES = 17
_TANGENT_SIN = 1e-6


@dataclass(frozen=True)
class ReliefFrame:
    """A projection frame: model coordinates -> frame coordinates (centre O at the origin).

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


def _frame_from_direction(points: FloatArray, direction: FloatArray, name: str) -> ReliefFrame:
    d = direction / np.linalg.norm(direction)
    centre = 0.5 * (points.min(axis=0) + points.max(axis=0))
    rel = points - centre
    radius = float(np.max(np.linalg.norm(rel, axis=1)))
    if radius == 0.0:
        radius = 1.0
    depth_spread = float(np.max(np.abs(rel @ d)))
    distance = depth_spread + 2.0 * radius
    origin = centre - distance * d
    helper = np.array([1.0, 0.0, 0.0]) if abs(d[0]) < 0.8 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(helper, d)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(d, e1)
    rot = np.vstack([e1, e2, d])
    m = np.eye(4)
    m[:3, :3] = rot / radius
    m[:3, 3] = -(rot @ origin) / radius
    return ReliefFrame(matrix=m, scale=radius, name=name)


def _frames(points: FloatArray) -> Iterator[ReliefFrame]:
    """Yield projection frames, best first: the model's own, then views along principal axes."""
    z = points[:, 2]
    big = float(np.max(np.abs(points)))
    if float(z.min()) > 1e-3 * big and float(z.max()) < 100.0 * float(z.min()):
        yield ReliefFrame(matrix=np.eye(4), scale=1.0, name="model")
    centred = points - points.mean(axis=0)
    if points.shape[0] >= 2 and float(np.max(np.abs(centred))) > 0.0:
        _, _, vt = np.linalg.svd(centred)
        axes = [vt[2], vt[1], vt[0]] if vt.shape[0] == 3 else [np.array([0.0, 0.0, 1.0])]
    else:
        axes = [np.array([0.0, 0.0, 1.0])]
    yield _frame_from_direction(points, axes[0], "least-variance axis")
    tilt = axes[0] + 0.6 * (axes[1] if len(axes) > 1 else np.array([1.0, 0.0, 0.0]))
    yield _frame_from_direction(points, tilt, "tilted view")
    yield _frame_from_direction(points, np.array([0.3, -0.5, 0.81]), "fixed oblique view")


def _planar_tolerance(a_f: RationalBezier, b_f: RationalBezier, tol_frame: float) -> float:
    pts = np.vstack([a_f.control_points, b_f.control_points])
    zmin = float(pts[:, 2].min())
    r2 = float(np.max((pts[:, 0] ** 2 + pts[:, 1] ** 2) / pts[:, 2] ** 2))
    lipschitz = math.sqrt(1.0 + r2) / zmin
    return lipschitz * tol_frame * (1.0 + 1e-6)


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
        Span of the relief perspective ``φ``.
    tol : float, optional
        Space tolerance (model units) from which the planar one is derived.

    Returns
    -------
    ReliefScheme

    Examples
    --------
    >>> from relief_cad import RationalBezier, preimage_of_lift
    >>> P = RationalBezier([[0, 0], [1, 2], [2, 0]], [1.0, 0.5, 1.0])
    >>> s = relief_scheme(preimage_of_lift(P, 2.0), preimage_of_lift(P.reversed(), 2.0))
    >>> s.frame.name, bool(np.allclose(s.a_image(0.3), P(0.3)))
    ('model', True)
    """
    a3 = a.embedded(3)
    b3 = b.embedded(3)
    pts = np.vstack([a3.control_points, b3.control_points])
    if frame is None:
        frame = next(_frames(pts))
    t = default_tolerance(pts) if tol is None else float(tol)
    a_f = a3.transformed(frame.matrix)
    b_f = b3.transformed(frame.matrix)
    phi = ReliefPerspective(k)
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


# ---------------------------------------------------------------------------- space polish
def _eval_h(h: FloatArray, t: float) -> tuple[FloatArray, FloatArray]:
    """Point and derivative of a homogeneous curve at one parameter (de Casteljau)."""
    n = h.shape[0] - 1
    b = h.copy()
    s = 1.0 - t
    for r in range(1, n):
        b[: n + 1 - r] = s * b[: n + 1 - r] + t * b[1 : n + 2 - r]
    value = s * b[0] + t * b[1]
    dvalue = n * (b[1] - b[0])
    w = value[-1]
    p = value[:-1] / w
    dp = (dvalue[:-1] - p * dvalue[-1]) / w
    return p, dp


def _polish(
    ha: FloatArray, hb: FloatArray, t: float, u: float, fix_t: bool, fix_u: bool
) -> tuple[float, float, float]:
    """Minimise |a(t) - b(u)| locally: Gauss-Newton with Levenberg damping, parameters in [0, 1].

    A fixed parameter (an exact end point) is not moved. Returns ``(t, u, gap)``.
    """
    pa, da = _eval_h(ha, t)
    pb, db = _eval_h(hb, u)
    r = pa - pb
    f = float(r @ r)
    if fix_t and fix_u:
        return t, u, math.sqrt(f)
    lam = 0.0
    for _ in range(80):
        cols = ([] if fix_t else [da]) + ([] if fix_u else [-db])
        jac = np.column_stack(cols)
        jtj = jac.T @ jac
        g = jac.T @ r
        accepted = False
        moved = 0.0
        for _attempt in range(16):
            a_mat = jtj + lam * np.diag(np.diag(jtj)) + 1e-300 * np.eye(jtj.shape[0])
            step = -np.linalg.lstsq(a_mat, g, rcond=None)[0]
            i = 0
            nt, nu = t, u
            if not fix_t:
                nt = min(max(t + float(step[0]), 0.0), 1.0)
                i = 1
            if not fix_u:
                nu = min(max(u + float(step[i]), 0.0), 1.0)
            npa, nda = _eval_h(ha, nt)
            npb, ndb = _eval_h(hb, nu)
            nr = npa - npb
            nf = float(nr @ nr)
            if nf <= f:
                moved = abs(nt - t) + abs(nu - u)
                t, u, pa, da, pb, db, r, f = nt, nu, npa, nda, npb, ndb, nr, nf
                lam = 0.0 if lam <= 1e-10 else lam * 0.1
                accepted = True
                break
            lam = max(lam * 10.0, 1e-10)
        if not accepted or f == 0.0 or moved <= 2.0 * _EPS:
            break
    return t, u, math.sqrt(f)


def _snap_ends(
    ha: FloatArray, hb: FloatArray, t: float, u: float, tol: float
) -> tuple[float, float, bool, bool]:
    """Snap parameters to exact end points when an end point of one curve lies on the other there."""
    fix_t = fix_u = False
    for end in (0.0, 1.0):
        if abs(t - end) < 1e-9:
            p, _ = _eval_h(ha, end)
            q, _ = _eval_h(hb, u)
            if float(np.linalg.norm(p - q)) <= tol:
                t, fix_t = end, True
        if abs(u - end) < 1e-9:
            p, _ = _eval_h(ha, t)
            q, _ = _eval_h(hb, end)
            if float(np.linalg.norm(p - q)) <= tol:
                u, fix_u = end, True
    return t, u, fix_t, fix_u


def _kind(ha: FloatArray, hb: FloatArray, t: float, u: float, gap: float, meet: float) -> str:
    if gap > meet:
        return "tangent"
    _, da = _eval_h(ha, t)
    _, db = _eval_h(hb, u)
    na = float(np.linalg.norm(da))
    nb = float(np.linalg.norm(db))
    if na == 0.0 or nb == 0.0:
        return "tangent"
    sin = float(np.linalg.norm(np.cross(da, db))) / (na * nb)
    return "crossing" if sin > _TANGENT_SIN else "tangent"


def _project_onto(hb: FloatArray, p: FloatArray, u: float, lo: float, hi: float) -> tuple[float, float]:
    """Closest point of b to p near u, within [lo, hi] (Newton on (b(u) - p) . b'(u) = 0)."""
    for _ in range(40):
        q, dq = _eval_h(hb, u)
        r = q - p
        # second derivative by a finite difference of the first (sufficient for the check)
        h = 1e-7
        _, dq2 = _eval_h(hb, min(u + h, 1.0))
        ddq = (dq2 - dq) / h
        g = float(r @ dq)
        hess = float(dq @ dq + r @ ddq)
        if hess <= 0.0:
            hess = float(dq @ dq) or 1.0
        nu = min(max(u - g / hess, lo), hi)
        if abs(nu - u) < 1e-15:
            u = nu
            break
        u = nu
    q, _ = _eval_h(hb, u)
    return u, float(np.linalg.norm(q - p))


def _overlap_is_real(ha: FloatArray, hb: FloatArray, ov: Overlap, tol: float) -> bool:
    t0, t1 = ov.t
    u0, u1 = ov.u
    for end_t, end_u in ((t0, u0), (t1, u1)):
        p, _ = _eval_h(ha, end_t)
        q, _ = _eval_h(hb, end_u)
        if float(np.linalg.norm(p - q)) > tol:
            return False
    lo, hi = min(u0, u1), max(u0, u1)
    for s in np.linspace(0.0, 1.0, _OVERLAP_SAMPLES)[1:-1]:
        t = t0 + s * (t1 - t0)
        p, _ = _eval_h(ha, t)
        _, gap = _project_onto(hb, p, u0 + s * (u1 - u0), lo, hi)
        if gap > tol:
            return False
    return True


def _inside_overlap(t: float, u: float, overlaps: list[Overlap], slack: float) -> bool:
    for ov in overlaps:
        ulo, uhi = min(ov.u), max(ov.u)
        if ov.t[0] - slack <= t <= ov.t[1] + slack and ulo - slack <= u <= uhi + slack:
            return True
    return False


def _dedupe(points: list[Intersection], ptol: float) -> list[Intersection]:
    """Merge repeated finds of one contact.

    Crossings polish to a few ulps, so two within ``ptol`` are one. Tangent contacts converge only
    to about the square root of the precision, so two tangent finds within ``1e-6`` are one.
    """
    points = sorted(points, key=lambda r: (r.t, r.u))
    out: list[Intersection] = []
    for p in points:
        near = ptol
        if out and p.kind == "tangent" and out[-1].kind == "tangent":
            near = 1e-6
        if out and abs(p.t - out[-1].t) <= near and abs(p.u - out[-1].u) <= near:
            keep = out[-1]
            if (p.distance, p.t not in (0.0, 1.0)) < (keep.distance, keep.t not in (0.0, 1.0)):
                out[-1] = p
            continue
        out.append(p)
    return out


def _check_tol(tol: float | None, pts: FloatArray) -> float:
    if tol is None:
        return default_tolerance(pts)
    try:
        value = float(tol)
    except (TypeError, ValueError) as exc:
        raise InputTypeError(f"tol should be a distance (a real number), not {type(tol).__name__}") from exc
    if not math.isfinite(value) or value <= 0.0:
        raise ToleranceError(f"tol should be a finite distance > 0 in model units, not {tol!r}")
    return value


def intersect_space(
    a: RationalBezier,
    b: RationalBezier | None = None,
    *,
    tol: float | None = None,
    budget: int | None = None,
    on_budget: Literal["raise", "return"] = "raise",
    k: float = 2.0,
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
    k : float, default 2.0
        Span of the relief perspective used.

    Returns
    -------
    IntersectionList
        Sorted by ``t``: :class:`Intersection` (``kind`` from the angle of the space tangents)
        and :class:`Overlap` results, parameters in ``[0, 1]`` of each curve.

    Raises
    ------
    InputTypeError, ToleranceError
        For inputs of the wrong type or a tolerance that is not a positive distance.
    BudgetExceededError
        If a budget runs out (``on_budget="raise"``), or no frame gives a projection free of
        artefacts.

    Examples
    --------
    >>> from relief_cad import RationalBezier
    >>> skew_a = RationalBezier([[0, 0, 0], [1, 0, 0]])
    >>> skew_b = RationalBezier([[0.5, -1, 1], [0.5, 1, 1]])
    >>> len(intersect_space(skew_a, skew_b))   # their projections along z cross; they do not meet
    0
    >>> intersect_space(skew_a, skew_b, tol=1.5)[0].kind   # a near-miss within tol is a contact
    'tangent'
    """
    from .intersection import intersect as planar_intersect

    if not isinstance(a, RationalBezier) or not (b is None or isinstance(b, RationalBezier)):
        raise InputTypeError(
            "intersect_space expects RationalBezier curves, not "
            f"{type(a).__name__} and {type(b).__name__}"
        )
    self_mode = b is None
    a3 = a.embedded(3)
    b3 = a3 if b is None else b.embedded(3)
    pts = a3.control_points if self_mode else np.vstack([a3.control_points, b3.control_points])
    tol_v = _check_tol(tol, pts)
    input_noise = 16.0 * _EPS * float(np.max(np.abs(pts)))
    # Work about a local origin: subtracting a nearby reference is exact (Sterbenz), and keeps the
    # full relative precision of curves far from the model origin. Parameters are unchanged.
    ref = a3.control_points[0].copy()
    a3 = RationalBezier(a3.control_points - ref, a3.weights)
    b3 = a3 if self_mode else RationalBezier(b3.control_points - ref, b3.weights)
    pts = a3.control_points if self_mode else np.vstack([a3.control_points, b3.control_points])
    ha = a3.homogeneous
    hb = b3.homogeneous
    big = float(np.max(np.abs(pts)))
    # A gap below this is a meeting (rounding of the input data or of the evaluation), not a near-miss.
    meet = max(1e3 * _EPS * big, input_noise, 1e-3 * tol_v)
    unresolved: list[ParameterBox] = []
    phi = ReliefPerspective(k)
    last_frame = ""
    for frame in _frames(pts):
        last_frame = frame.name
        a_f = a3.transformed(frame.matrix)
        b_f = a_f if self_mode else b3.transformed(frame.matrix)
        a_s = central_projection(phi.apply(a_f))
        b_s = a_s if self_mode else central_projection(phi.apply(b_f))
        ptol = _planar_tolerance(a_f, b_f, tol_v / frame.scale)
        try:
            planar = planar_intersect(a_s, None if self_mode else b_s, tol=ptol, budget=budget,
                                      on_budget="return")
        except BudgetExceededError:  # pragma: no cover - on_budget="return" should not raise
            raise
        unresolved = list(getattr(planar, "unresolved", ()))
        overlaps: list[Overlap] = []
        artefact = False
        for res in planar:
            if isinstance(res, Overlap):
                if not self_mode and _overlap_is_real(ha, hb, res, tol_v):
                    overlaps.append(res)
                else:
                    artefact = True
                    break
        if artefact:
            continue
        points: list[Intersection] = []
        for res in planar:
            if isinstance(res, Overlap):
                continue
            t, u = float(res.t), float(res.u)
            t, u, fix_t, fix_u = _snap_ends(ha, hb, t, u, tol_v)
            t, u, gap = _polish(ha, hb, t, u, fix_t, fix_u)
            if gap > tol_v:
                continue
            if self_mode and abs(t - u) <= 1e-9:
                continue
            if self_mode and t > u:
                t, u = u, t
            if _inside_overlap(t, u, overlaps, 1e-9):
                continue
            pa, _ = _eval_h(ha, t)
            pb, _ = _eval_h(hb, u)
            points.append(
                Intersection(t=t, u=u, point=0.5 * (pa + pb) + ref, kind=_kind(ha, hb, t, u, gap, meet),  # type: ignore[arg-type]
                             distance=gap)
            )
        results: list[Result] = [*_dedupe(points, 1e-10), *overlaps]
        results.sort(key=lambda r: r.t if isinstance(r, Intersection) else r.t[0])
        out = IntersectionList(results, unresolved)
        if unresolved and on_budget == "raise":
            raise BudgetExceededError(
                f"the planar clipping budget ran out with {len(unresolved)} parameter boxes unresolved",
                partial=out, unresolved=unresolved,
            )
        return out
    raise BudgetExceededError(
        f"every one of {_MAX_FRAMES} projection frames (last: {last_frame}) showed an overlap of the "
        "projected curves that is not an overlap in space; the curves could not be separated",
        partial=IntersectionList([], unresolved), unresolved=unresolved,
    )

"""Space intersection by the relief scheme, checked against truth built by construction.

Certified truth here does not come from the intersector: meetings are built exactly (dyadic
control points and parameters, so the translated curve passes through the point exactly in
floating point), the paper-form pairs come from mirror-symmetric planar arcs whose crossing has a
closed form, overlaps are sub-segments with exact ends, skew pairs have a known constant gap.
"""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect, preimage_of_lift
from relief_cad.errors import InputTypeError, ReliefCadError, ToleranceError
from relief_cad.results import Intersection, Overlap
from relief_cad.space import intersect_space, relief_scheme

RNG_SEEDS = range(12)
TRANSFORMS = [
    (1.0, np.zeros(3)),
    (1e-4, np.zeros(3)),
    (1e5, np.zeros(3)),
    (1.0, np.array([1e4, -1e4, 1e4])),
    (1e-4, np.array([1e4, 0.0, 0.0])),
]


def bern(n: int, i: int, t: Fraction) -> Fraction:
    return math.comb(n, i) * t**i * (1 - t) ** (n - i)


def exact_point(pts: np.ndarray, t: Fraction) -> list[Fraction]:
    n = len(pts) - 1
    return [sum(Fraction(float(pts[i, j])) * bern(n, i, t) for i in range(n + 1)) for j in range(pts.shape[1])]


def dyadic_cubic(rng: np.random.Generator) -> np.ndarray:
    return rng.integers(-64, 65, size=(4, 3)) / 8.0


def mp_closest(a: RationalBezier, b: RationalBezier, t: float, u: float) -> tuple[float, float]:
    """Certified truth on the actual floating-point data: Newton on grad |a(t) - b(u)|^2 in 60 digits."""
    import mpmath

    with mpmath.workdps(60):
        def ev(c: RationalBezier, s: mpmath.mpf) -> tuple[list, list, list]:  # point, 1st, 2nd derivative
            h = [[mpmath.mpf(float(x)) for x in row] for row in c.homogeneous]
            n = len(h) - 1
            def poly(s: mpmath.mpf, d: int) -> list:
                out = []
                for j in range(len(h[0])):
                    out.append(mpmath.diff(lambda x, j=j: sum(h[i][j] * mpmath.binomial(n, i) * x**i * (1 - x) ** (n - i) for i in range(n + 1)), s, d))
                return out
            H, H1, H2 = poly(s, 0), poly(s, 1), poly(s, 2)
            w, w1, w2 = H[-1], H1[-1], H2[-1]
            p = [x / w for x in H[:-1]]
            p1 = [(H1[j] - p[j] * w1) / w for j in range(3)]
            p2 = [(H2[j] - 2 * p1[j] * w1 - p[j] * w2) / w for j in range(3)]
            return p, p1, p2
        tt, uu = mpmath.mpf(t), mpmath.mpf(u)
        for _ in range(30):
            pa, da, dda = ev(a, tt)
            pb, db, ddb = ev(b, uu)
            r = [pa[j] - pb[j] for j in range(3)]
            g = mpmath.matrix([sum(r[j] * da[j] for j in range(3)), -sum(r[j] * db[j] for j in range(3))])
            hm = mpmath.matrix([[sum(da[j] ** 2 + r[j] * dda[j] for j in range(3)), -sum(da[j] * db[j] for j in range(3))],
                                [-sum(da[j] * db[j] for j in range(3)), sum(db[j] ** 2 - r[j] * ddb[j] for j in range(3))]])
            step = mpmath.lu_solve(hm, g)
            tt, uu = tt - step[0], uu - step[1]
            if abs(step[0]) + abs(step[1]) < mpmath.mpf(10) ** -40:
                break
        return float(tt), float(uu)


def transform(curve: RationalBezier, scale: float, shift: np.ndarray) -> RationalBezier:
    m = np.eye(4)
    m[:3, :3] *= scale
    m[:3, 3] = shift
    return curve.transformed(m)


def meeting_pair(seed: int) -> tuple[RationalBezier, RationalBezier, float, float]:
    """Two space cubics that meet exactly at a(t*) = b(u*) (exact in binary floating point)."""
    rng = np.random.default_rng(seed)
    pa = dyadic_cubic(rng)
    pb = dyadic_cubic(rng)
    ts = Fraction(int(rng.integers(1, 16)), 16)
    us = Fraction(int(rng.integers(1, 16)), 16)
    x = exact_point(pa, ts)
    y = exact_point(pb, us)
    shift = np.array([float(xi - yi) for xi, yi in zip(x, y)])
    assert all(Fraction(float(xi - yi)) == xi - yi for xi, yi in zip(x, y))
    pb = pb + shift
    return RationalBezier(pa), RationalBezier(pb), float(ts), float(us)


@pytest.mark.parametrize("seed", RNG_SEEDS)
@pytest.mark.parametrize(("scale", "shift"), TRANSFORMS)
def test_random_space_cubics_meeting_at_a_known_point(seed: int, scale: float, shift: np.ndarray) -> None:
    a, b, ts, us = meeting_pair(seed)
    a, b = transform(a, scale, shift), transform(b, scale, shift)
    if scale != 1.0:  # the rounded data need not meet exactly any more: truth on the actual data
        ts, us = mp_closest(a, b, ts, us)
    res = intersect_space(a, b)
    assert len(res) == 1, res
    r = res[0]
    assert isinstance(r, Intersection) and r.kind == "crossing"
    assert abs(r.t - ts) <= 1e-12 and abs(r.u - us) <= 1e-12
    np.testing.assert_allclose(r.point, a(ts), atol=1e-12 * scale * 100 + 1e-12 * np.abs(shift).max())
    swapped = intersect_space(b, a)
    assert len(swapped) == 1 and abs(swapped[0].t - us) <= 1e-12 and abs(swapped[0].u - ts) <= 1e-12


@pytest.mark.parametrize("seed", RNG_SEEDS)
def test_tangential_touch_in_space(seed: int) -> None:
    """b(u) = a(u) + (u - t*)^2 v touches a at (t*, t*) with a common tangent, nowhere else."""
    rng = np.random.default_rng(100 + seed)
    pa = dyadic_cubic(rng)
    ts = Fraction(int(rng.integers(3, 14)), 16)
    v = rng.integers(-8, 9, size=3) / 4.0 + np.array([0.0, 0.0, 3.0])
    # Bernstein coefficients of (u - t*)^2 on degree 3: elevate [t*^2, -t*(1-t*), (1-t*)^2]
    q = [ts**2, -ts * (1 - ts), (1 - ts) ** 2]
    c3 = [q[0], (q[0] + 2 * q[1]) / 3, (2 * q[1] + q[2]) / 3, q[2]]
    pb = pa + np.array([float(c) for c in c3])[:, None] * v[None, :]
    a, b = RationalBezier(pa), RationalBezier(pb)
    np.testing.assert_allclose(a(float(ts)), b(float(ts)), atol=1e-13)
    res = intersect_space(a, b)
    pts = [r for r in res if isinstance(r, Intersection)]
    assert len(pts) == 1, res
    assert pts[0].kind == "tangent"
    assert abs(pts[0].t - float(ts)) <= 1e-7 and abs(pts[0].u - float(ts)) <= 1e-7


def mirror_arcs(w0: float, wm: float, w2: float) -> tuple[RationalBezier, RationalBezier, float]:
    """A rational quadratic arc and its mirror image in x = 0: exactly one crossing, at t = u = t*."""
    p1 = RationalBezier([[-1.0, -1.0], [0.0, 1.0], [1.0, 2.0]], [w0, wm, w2])
    p2 = RationalBezier([[1.0, -1.0], [0.0, 1.0], [-1.0, 2.0]], [w0, wm, w2])
    ts = 1.0 / (1.0 + math.sqrt(w2 / w0))
    return p1, p2, ts


@pytest.mark.parametrize("weights", [(1.0, 0.5, 1.0), (1.0, 2.0, 0.5), (0.5, 1.5, 0.5), (1.0, 1.0, 1.0)])
@pytest.mark.parametrize(("k1", "k2"), [(2.0, 2.0), (0.5, 0.5), (2.0, 3.0), (0.5, 4.0)])
def test_paper_form_pairs_meet_only_where_the_reliefs_agree(weights: tuple[float, float, float], k1: float, k2: float) -> None:
    p1, p2, ts = mirror_arcs(*weights)
    k1 = max(k1, max(weights) - 0.25)
    k2 = max(k2, max(weights) - 0.25) if k2 != k1 else k1
    q1, q2 = preimage_of_lift(p1, k1), preimage_of_lift(p2, k2)
    w_at = float(p1.homogeneous[:, 2] @ np.array([(1 - ts) ** 2, 2 * ts * (1 - ts), ts**2]))
    meets = k1 == k2 or abs(w_at - 1.0) < 1e-15
    # their projections always cross at (t*, t*)
    scheme = relief_scheme(q1, q2)
    assert scheme.frame.name == "model"
    np.testing.assert_allclose(scheme.a_image(ts), scheme.b_image(ts), atol=1e-14)
    res = intersect_space(q1, q2)
    if meets:
        assert len(res) == 1 and res[0].kind == "crossing"
        assert abs(res[0].t - ts) <= 1e-12 and abs(res[0].u - ts) <= 1e-12
    else:
        assert len(res) == 0, res


def line_param(t: float) -> float:
    """Parameter on the line x = 4u of the point of a with parameter t (x(t) = 3t + 3t^2 - 2t^3)."""
    return (3 * t + 3 * t**2 - 2 * t**3) / 4


@pytest.mark.parametrize(("scale", "shift"), TRANSFORMS)
@pytest.mark.parametrize("gap_factor", [1e-6, 1e-10, 1.0])
def test_skew_curves_and_near_misses(scale: float, shift: np.ndarray, gap_factor: float) -> None:
    """a in z = 0, b = a line at height g above it; projections along z cross at a known point."""
    a = RationalBezier([[0, 0, 0], [1, 2, 0], [3, 2, 0], [4, 0, 0]])  # y(t) = 6 t (1 - t)
    # line y = 1 crosses a at y(t) = 6t(1-t) = 1, i.e. t = (3 -+ sqrt(3)) / 6, where x(t) = 3t + 3t^2 - 2t^3
    size = 4.0
    g = gap_factor * size
    b = RationalBezier([[0.0, 1.0, g], [4.0, 1.0, g]])
    a, b = transform(a, scale, shift), transform(b, scale, shift)
    res = intersect_space(a, b)
    tol_default = 1e-9 * np.linalg.norm(np.ptp(np.vstack([a.control_points, b.control_points]), axis=0))
    roots = [(3 - math.sqrt(3)) / 6, (3 + math.sqrt(3)) / 6]
    if g * scale < tol_default:
        assert len(res) == 2, res
        # a gap below the rounding of the coordinates themselves is indistinguishable from a meeting
        resolvable = g * scale > 16 * np.finfo(float).eps * np.abs(a.control_points).max()
        for r, t in zip(res, roots):
            assert abs(r.t - t) <= 1e-7 and abs(r.u - line_param(t)) <= 1e-7
            if resolvable:
                assert r.kind == "tangent"
                assert r.distance == pytest.approx(g * scale, rel=1e-3, abs=1e-3 * tol_default)
    else:
        assert len(res) == 0, res
    if gap_factor == 1e-6:
        wide = intersect_space(a, b, tol=2 * g * scale)
        assert len(wide) == 2 and all(r.kind == "tangent" for r in wide)


def overlap_cases() -> list[tuple[str, RationalBezier, RationalBezier, tuple[float, float], tuple[float, float]]]:
    rng = np.random.default_rng(7)
    cubic = RationalBezier(dyadic_cubic(rng) + np.array([0, 0, 9.0]), [1.0, 0.75, 1.5, 1.0])
    sub = cubic.segment(0.25, 0.75)
    lam = 1.7
    moebius = RationalBezier(sub.control_points, sub.weights * lam ** np.arange(4))
    line_a = RationalBezier([[0, 0, 0], [2, 2, 2]])
    line_b = RationalBezier([[1, 1, 1], [3, 3, 3]])
    c = math.cos(math.pi / 4)
    arc = RationalBezier([[1, 0, 0], [1, 1, 0.0], [0, 1, 0]], [1, c, 1]).transformed(
        np.array([[1, 0, 0, 0], [0, 0.6, -0.8, 1.0], [0, 0.8, 0.6, 2.0], [0, 0, 0, 1.0]])
    )
    arc2 = arc.segment(0.5, 1.5)
    return [
        ("sub-segment", cubic, sub, (0.25, 0.75), (0.0, 1.0)),
        ("reversed", cubic, sub.reversed(), (0.25, 0.75), (1.0, 0.0)),
        ("moebius", cubic, moebius, (0.25, 0.75), (0.0, 1.0)),
        ("lines", line_a, line_b, (0.5, 1.0), (0.0, 0.5)),
        ("coincident arcs", arc, arc2, (0.5, 1.0), (0.0, 0.5)),
    ]


@pytest.mark.parametrize("case", overlap_cases(), ids=lambda c: c[0])
def test_overlaps_in_space(case: tuple) -> None:  # type: ignore[type-arg]
    _, a, b, t, u = case
    res = intersect_space(a, b)
    overlaps = [r for r in res if isinstance(r, Overlap)]
    assert len(overlaps) == 1 and len(res) == 1, res
    ov = overlaps[0]
    assert ov.t == pytest.approx(t, abs=1e-12) and ov.u == pytest.approx(u, abs=1e-12)


@pytest.mark.parametrize("entry", ["intersect", "intersect_space"])
@pytest.mark.parametrize("other", ["same", "elevated", "reversed", "reweighted"])
def test_closed_space_curve_on_itself_is_one_overlap(entry: str, other: str) -> None:
    """A closed space loop against a copy of itself: one overlap, through either entry point.

    The clipping alone sees the loop's shared end point as crossings and its coinciding images as
    a string of tangent contacts; the end points matching must send the pair to the geometric
    test of coincidence first (the kernel's gate, then whole_overlap): no clipping, so a budget of
    one iteration is enough.
    """
    loop = RationalBezier([[0, 0, 0], [2, 2, 1], [-2, 2, -1], [0, 0, 0]])
    b = {"same": loop, "elevated": loop.elevate(1), "reversed": loop.reversed(),
         "reweighted": RationalBezier(loop.control_points, [1.0, 2.0, 0.5, 1.0]).elevate(1)}[other]
    a = loop if other != "reweighted" else RationalBezier(loop.control_points, [1.0, 2.0, 0.5, 1.0])
    res = (intersect if entry == "intersect" else intersect_space)(a, b, budget=1)
    u = (1.0, 0.0) if other == "reversed" else (0.0, 1.0)
    assert list(res) == [Overlap(t=(0.0, 1.0), u=u)], res


def test_coplanar_pair_in_a_tilted_plane() -> None:
    """A parabola arc y = 6t(1-t), x = 4t and the line y = 1 in a tilted plane: two crossings."""
    rot = np.array([[0.36, 0.48, -0.8], [-0.8, 0.6, 0.0], [0.48, 0.64, 0.6]])
    m = np.eye(4)
    m[:3, :3] = rot
    m[:3, 3] = [5.0, -3.0, 2.0]
    a = RationalBezier([[0, 0, 0], [1, 2, 0], [3, 2, 0], [4, 0, 0]]).transformed(m)
    b = RationalBezier([[0.0, 1.0, 0.0], [4.0, 1.0, 0.0]]).transformed(m)
    res = intersect_space(a, b)
    roots = [(3 - math.sqrt(3)) / 6, (3 + math.sqrt(3)) / 6]
    assert [r.kind for r in res] == ["crossing", "crossing"]
    for r, t in zip(res, roots):
        assert abs(r.t - t) <= 1e-12 and abs(r.u - line_param(t)) <= 1e-12


def test_mixed_planar_and_space_inputs() -> None:
    planar = RationalBezier([[0, 0], [4, 0]])
    space = RationalBezier([[1, -1, -1], [1, 1, 1]])
    res = intersect_space(planar, space)
    assert len(res) == 1 and abs(res[0].t - 0.25) <= 1e-14 and abs(res[0].u - 0.5) <= 1e-14


def test_shared_end_points_are_exact() -> None:
    a = RationalBezier([[0, 0, 0], [1, 2, 1], [2, 0, 3]])
    b = RationalBezier([[2, 0, 3], [3, -1, 0], [5, 1, 1]])
    res = intersect_space(a, b)
    assert len(res) == 1 and res[0].t == 1.0 and res[0].u == 0.0


def test_self_intersection_of_a_space_loop() -> None:
    # a planar loop (x = t - t^3 style) lifted with z = 0 at the double point
    a = RationalBezier([[0, 0, 0], [3, 3, 1], [-1, 3, 1], [2, 0, 0]])
    res = intersect_space(a)
    assert len(res) == 1
    r = res[0]
    assert r.t < r.u
    np.testing.assert_allclose(a(r.t), a(r.u), atol=1e-12)


@pytest.mark.parametrize("tip", [[1.0, 1.0, 1.0], [3.0, -2.0, 0.5]])
@pytest.mark.parametrize("scale", [1.0, 2.0**-40, 2.0**60])
def test_a_space_curve_running_out_and_back_is_one_self_overlap(tip: list[float], scale: float) -> None:
    # the derivative vanishes at the tip, so every piece that ends there has a repeated control
    # point: such a piece is still monotone along its chord (it used to be halved twelve times, and
    # the pieces' pairs made this 12 ms); the answer is the stretch out against the stretch back
    p = np.array([[0.0, 0.0, 0.0], tip, tip, [0.0, 0.0, 0.0]]) * scale
    res = intersect_space(RationalBezier(p))
    assert res.complete
    assert list(res) == [Overlap(t=(0.0, 0.5), u=(1.0, 0.5))]


def test_monotone_pieces_allow_repeated_control_points_but_not_a_turn() -> None:
    from relief_cad.space import _monotone

    leg = np.array([1.0, 2.0, 0.5])
    assert _monotone(np.array([0 * leg, leg, 2 * leg, 2 * leg]))   # ends at a zero derivative
    assert _monotone(np.array([0 * leg, 0 * leg, leg, 3 * leg]))   # starts at one
    assert not _monotone(np.array([0 * leg, 2 * leg, leg, 3 * leg]))   # a leg runs back
    assert not _monotone(np.array([0 * leg, leg, leg, 0 * leg]))   # closed: no chord to advance on


def test_bad_input() -> None:
    a = RationalBezier([[0, 0, 0], [1, 1, 1]])
    with pytest.raises(ToleranceError):
        intersect_space(a, a, tol=-1.0)
    with pytest.raises(ToleranceError):
        intersect_space(a, a, tol=float("nan"))
    with pytest.raises(InputTypeError) as info:
        intersect_space(a, "b")  # type: ignore[arg-type]
    assert isinstance(info.value, ReliefCadError) and isinstance(info.value, TypeError)


def test_curves_in_a_plane_through_the_projection_centre() -> None:
    """Both curves lie in the plane x = 0 through O, in front of it: the model frame's projection
    flattens them onto one line (an image overlap that is not a space overlap), so another frame is
    taken and the real crossing is found."""
    a = RationalBezier([[0.0, -1.0, 1.0], [0.0, 0.0, 3.0], [0.0, 1.0, 1.0]])  # z = 1 + 4t(1-t), y = 2t - 1
    b = RationalBezier([[0.0, -1.0, 1.5], [0.0, 1.0, 1.5]])  # z = 1.5
    res = intersect_space(a, b)
    # 1 + 4t(1-t) = 1.5  ->  t = (2 -+ sqrt(2)) / 4 ; y = 2t - 1 = 2u - 1  ->  u = t
    roots = [(2 - math.sqrt(2)) / 4, (2 + math.sqrt(2)) / 4]
    assert [r.kind for r in res] == ["crossing", "crossing"], res
    for r, t in zip(res, roots):
        assert abs(r.t - t) <= 1e-12 and abs(r.u - t) <= 1e-12
    assert relief_scheme(a, b).frame.name == "model"  # the frame that first sees the artefact
    top = intersect_space(a, RationalBezier([[0.0, -1.0, 2.0], [0.0, 1.0, 2.0]]))  # z = 2 touches at t = 1/2
    assert len(top) == 1 and top[0].kind == "tangent" and abs(top[0].t - 0.5) <= 1e-7


@pytest.mark.parametrize(("scale", "shift"), TRANSFORMS)
def test_overlaps_survive_scaling_and_translation(scale: float, shift: np.ndarray) -> None:
    # rounding the transformed data moves the truth by about eps * |shift| / scale in parameter
    ptol = 1e-9 + 10 * np.finfo(float).eps * float(np.abs(shift).max()) / scale
    for _, a, b, t, u in overlap_cases():
        res = intersect_space(transform(a, scale, shift), transform(b, scale, shift))
        overlaps = [r for r in res if isinstance(r, Overlap)]
        assert len(overlaps) == 1 and len(res) == 1, res
        assert overlaps[0].t == pytest.approx(t, abs=ptol) and overlaps[0].u == pytest.approx(u, abs=ptol)


def test_kernel_projection_is_psi_of_phi_from_the_foundation_objects() -> None:
    """The compiled hot path projects exactly as the paper's explicit maps do."""
    from relief_cad import ReliefPerspective, central_projection
    from relief_cad._kernels import _space_project as _project

    rng = np.random.default_rng(3)
    for k in (0.5, 2.0, 7.0):
        a = RationalBezier(rng.random((5, 3)) + [0, 0, 1.0], rng.random(5) + 0.5)
        b = RationalBezier(rng.random((4, 3)) + [0, 0, 1.0])
        scheme = relief_scheme(a, b, k=k)
        p2 = np.empty((5, 2))
        w2 = np.empty(5)
        assert _project(a.homogeneous, scheme.frame.matrix, k, p2, w2)
        image = central_projection(ReliefPerspective(k).apply(a.transformed(scheme.frame.matrix)))
        np.testing.assert_allclose(p2, image.control_points, rtol=1e-14, atol=1e-14)
        np.testing.assert_allclose(w2, image.weights, rtol=1e-14)
        np.testing.assert_allclose(scheme.a_image.control_points, image.control_points, rtol=1e-14, atol=1e-14)
        np.testing.assert_allclose(scheme.a_relief(SAMPLES), ReliefPerspective(k).apply(scheme.a_frame(SAMPLES)), atol=1e-13)


SAMPLES = np.linspace(0.0, 1.0, 11)


def test_budget_exhaustion_is_reported_never_silent() -> None:
    from relief_cad.errors import BudgetExceededError

    a, b, _, _ = meeting_pair(3)
    with pytest.raises(BudgetExceededError) as info:
        intersect_space(a, b, budget=1)
    assert info.value.unresolved and isinstance(info.value, RuntimeError)
    partial = intersect_space(a, b, budget=1, on_budget="return")
    assert not partial.complete and partial.unresolved
    for box in partial.unresolved:
        assert 0.0 <= box.t0 <= box.t1 <= 1.0 and 0.0 <= box.u0 <= box.u1 <= 1.0


def test_public_intersect_forwards_on_budget_to_the_space_path() -> None:
    from relief_cad import intersect

    a, b, _, _ = meeting_pair(5)
    partial = intersect(a, b, budget=1, on_budget="return")
    assert not partial.complete
    assert len(intersect(a, b)) == 1


def test_an_end_point_contact_in_space_has_its_end_parameter_exactly() -> None:
    """A line's end on a degree-5 rational curve in space, a T-junction 1.8e-15 off (a hunt).

    The contact came out at ``u = 7.5e-16`` (and ``6.1e-16`` swapped), where the documentation of
    ``intersect`` says end point contacts have ``t``/``u`` exactly 0.0 or 1.0.
    """
    a = RationalBezier(
        [[4.873451855244321, -9.518026563068497, 14.929081273409023],
         [-4.798824471806243, 1.2101221898532137, 2.670699169609954],
         [-8.128164856292084, -10.834582804626454, 12.434717003414264],
         [0.7602776022389622, 10.035152943924516, 24.543447635481552],
         [-6.869756769496002, 0.9037258211890074, 1.7637590159555674],
         [-16.120828697415185, -7.9151075161370805, 20.376087003367743]],
        [1.6974764580168227, 2.5256472461455544, 2.6714872000651972, 3.504618324304794,
         2.9758282135497294, 4.01918052934404])
    b = RationalBezier([[-5.039409409555223, 1.2374655038376177, 14.682793292826998],
                        [-0.6108178161033901, -0.4573353370881814, -10.336569705505854]],
                       [4.553185733302792, 1.8273739663222324])
    (hit,) = intersect(a, b)
    (back,) = intersect(b, a)
    assert hit.u == 0.0 and back.t == 0.0
    assert hit.t == pytest.approx(0.6147648065779625, abs=1e-12) and back.u == pytest.approx(hit.t, abs=1e-12)


SHALLOW_A = ([[0.5565896092577248, -13.682864208178732, 10.376982028002251],
              [1.9432288577906958, -11.029078829842012, 3.6140230834075937],
              [4.330821069314403, 18.65730609338056, -8.602581155350567],
              [8.611261288591832, -0.8875591413070163, 6.2328212717157445]],
             [0.9893199506900721, 0.5045334674845968, 0.8824393911673138, 1.290154309823515])


@pytest.mark.parametrize("angle", [3e-5, 1e-5, 3e-6, 1e-6, 3e-7])
@pytest.mark.parametrize("seed", range(6))
def test_a_shallow_crossing_in_space_is_reported_once(angle: float, seed: int) -> None:
    """A line through a point of a rational space cubic at a tiny angle to it: one crossing.

    At 1e-6 rad the crossing was found twice, 1.1e-10 apart in ``t`` and both 1e-15 from the other
    curve (the merge wanted 1e-10 in both parameters). The line is made through ``a(t0)``, turned
    from the tangent by ``angle`` towards the binormal: it stays in the rectifying plane, which
    the curve leaves along its normal at once, so the truth is ``t0`` alone (to about
    ``eps / angle``) at the point ``a(t0)``. (Turned towards the normal, the line meets the curve
    again ``2 angle / curvature`` along.)
    """
    rng = np.random.default_rng(seed)
    a = RationalBezier(*SHALLOW_A)
    t0 = 0.7250085964727272 if seed == 0 else float(rng.uniform(0.2, 0.8))
    p, d = a.evaluate(np.array([t0]))[0], a.derivative(np.array([t0]))[0]
    dd = a.derivative(np.array([t0 + 1e-4]))[0] - a.derivative(np.array([t0 - 1e-4]))[0]  # along a''
    d /= np.linalg.norm(d)
    n = np.cross(d, dd) * rng.choice([-1.0, 1.0])  # the binormal, either way
    n /= np.linalg.norm(n)
    e = math.cos(angle) * d + math.sin(angle) * n
    s0, s1 = rng.uniform(4.0, 12.0, 2)
    b = RationalBezier([p - s0 * e, p + s1 * e])
    res = [r for r in intersect(a, b) if isinstance(r, Intersection)]
    assert len(res) == 1, res
    (r,) = res
    assert abs(r.t - t0) < 1e-13 / angle and abs(r.u - s0 / (s0 + s1)) < 1e-13 / angle
    assert np.linalg.norm(np.asarray(r.point) - p) <= intersect(a, b).tol_used

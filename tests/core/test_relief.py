"""The paper's mathematics: relief perspective properties, Lemma, Theorem, projections, neutral planes."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from relief_cad import RationalBezier
from relief_cad.errors import (
    InputTypeError,
    NoNeutralPlaneError,
    ProjectionError,
    ReliefCadError,
    ShapeError,
    SpanError,
    WeightError,
)
from relief_cad.relief import (
    ReliefPerspective,
    central_projection,
    find_neutral_plane,
    lift,
    preimage_of_lift,
    relief_of_lift,
)
from tests.core.strategies import curves, spans

SAMPLES = np.linspace(0.0, 1.0, 13)
point3 = st.lists(st.floats(-50, 50), min_size=3, max_size=3).map(np.array)


def close(a: np.ndarray, b: np.ndarray, rel: float = 1e-11) -> None:
    scale = 1.0 + float(np.max(np.abs(b)))
    np.testing.assert_allclose(a, b, rtol=0, atol=rel * scale)


def admissible_k(p: RationalBezier, k: float) -> float:
    """A span with 1 + k > every weight, and k != 1."""
    k = max(k, float(np.max(p.weights)) - 1.0 + 0.5)
    return 1.25 if abs(k - 1.0) < 1e-3 else k


@settings(max_examples=80)
@given(point3, spans)
def test_lemma_inverse_and_explicit_preimage(x: np.ndarray, k: float) -> None:
    phi = ReliefPerspective(k)
    if abs(x[2] - (1 + k)) < 1e-6 or abs(x[2] + k) < 1e-6:
        return
    close(phi.apply(phi.inverse(x)), x, 1e-9)
    # Lemma: (x, y, z) is the relief of (kx, ky, kz) / (1 + k - z)
    pre = k * x / (1 + k - x[2])
    close(phi.inverse(x), pre, 1e-11)
    close(phi.apply(pre), x, 1e-9)


@settings(max_examples=60)
@given(curves(dim=2), spans)
def test_theorem_relief_of_q_is_the_lift_of_p(p: RationalBezier, k: float) -> None:
    k = admissible_k(p, k)
    q = preimage_of_lift(p, k)
    rq = ReliefPerspective(k).apply(q)
    bar = lift(p)
    close(rq.control_points, bar.control_points)
    assert np.allclose(rq.weights, rq.weights[0], rtol=1e-13)  # constant weights: a polynomial curve
    close(rq(SAMPLES), bar(SAMPLES))
    # the paper's closed form of the relief of the lift
    close(relief_of_lift(p, k).homogeneous, ReliefPerspective(k).apply(bar).homogeneous)


@settings(max_examples=60)
@given(curves(dim=2), spans)
def test_central_projection_of_q_and_lift_is_p(p: RationalBezier, k: float) -> None:
    k = admissible_k(p, k)
    q = preimage_of_lift(p, k)
    for space in (q, lift(p)):
        img = central_projection(space)
        assert img.dim == 2 and img.degree == p.degree
        close(img(SAMPLES), p(SAMPLES))
        close(central_projection(space(SAMPLES)), p(SAMPLES))


@settings(max_examples=60)
@given(curves(dim=3), spans, st.floats(0.5, 20))
def test_psi_after_phi_equals_psi(c: RationalBezier, k: float, shift: float) -> None:
    pts = c.control_points
    lift_z = float(shift - pts[:, 2].min())
    moved = c.transformed(np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, lift_z], [0, 0, 0, 1.0]]))
    phi = ReliefPerspective(k)
    close(central_projection(phi.apply(moved))(SAMPLES), central_projection(moved)(SAMPLES))
    x = moved(SAMPLES)
    close(central_projection(phi.apply(x)), central_projection(x))


@settings(max_examples=100)
@given(point3, spans, st.floats(-40, 40))
def test_section_4_properties(x: np.ndarray, k: float, c: float) -> None:
    phi = ReliefPerspective(k)
    assert phi.vanishing_plane_z == 1 + k and phi.neutral_plane_z == -k
    if abs(c + k) > 1e-3:
        # a plane z = c maps to the plane z = (1 + k) c / (c + k)
        img = phi.apply(np.array([[x[0], x[1], c], [x[1], -x[0], c]]))
        close(img[:, 2], np.full(2, (1 + k) * c / (c + k)))
    if abs(x[2] + k) > 1e-3:
        r = phi.apply(x)
        # orthographic projection of the relief onto z = 1 equals central projection from S = (0, 0, -k)
        s = phi.viewpoint
        lam = (1.0 - s[2]) / (x[2] - s[2])
        close(r[:2], (s + lam * (x - s))[:2], 1e-10)
        # points with z > 1 land in the slab 1 < z < 1 + k
        if x[2] > 1.0 + 1e-9:
            assert 1.0 < r[2] < 1.0 + k
        # phi fixes every line through O: the image of x is a multiple of x
        close(np.cross(r, x), np.zeros(3), 1e-9)
    # phi fixes the image plane pointwise
    on_sigma = np.array([x[0], x[1], 1.0])
    close(phi.apply(on_sigma), on_sigma, 1e-13)
    # the vanishing plane is the image of infinity: far points approach z = 1 + k
    far = phi.apply(np.array([x[0], x[1], 1e12]))
    assert abs(far[2] - (1 + k)) < 1e-9 * (1 + k)


def test_neutral_plane_goes_to_infinity() -> None:
    phi = ReliefPerspective(2.0)
    with pytest.raises(ProjectionError, match="neutral plane"):
        phi.apply([1.0, 1.0, -2.0])
    with pytest.raises(ProjectionError, match="vanishing plane"):
        phi.inverse([1.0, 1.0, 3.0])
    near = phi.apply(np.array([0.1, 0.0, -2.0 + 1e-9]))
    assert abs(near[0]) > 1e7


@settings(max_examples=40)
@given(curves(dim=2), spans, st.floats(0.2, 5.0), st.floats(-3, 3), st.floats(-1, 1), st.floats(0.1, 10))
def test_neutral_plane_found_for_paper_form_in_any_frame(
    p: RationalBezier, k: float, weight_scale: float, angle: float, tilt: float, scale: float
) -> None:
    k = admissible_k(p, k)
    q = preimage_of_lift(p, k)
    # put Q in a random similarity frame and rescale its weights
    ca, sa, ct, st_ = np.cos(angle), np.sin(angle), np.cos(tilt), np.sin(tilt)
    rot = np.array([[ca, -sa, 0], [sa, ca, 0], [0, 0, 1.0]]) @ np.array([[1, 0, 0], [0, ct, -st_], [0, st_, ct]])
    m = np.eye(4)
    m[:3, :3] = scale * rot
    m[:3, 3] = [3.0, -7.0, 11.0]
    model = RationalBezier.from_homogeneous(q.transformed(m).homogeneous * weight_scale)
    frame = find_neutral_plane(model, k=1.5)
    # in the frame the curve has the paper's form: Q = preimage_of_lift(P, k)
    close(preimage_of_lift(frame.planar, frame.k).homogeneous, frame.curve.homogeneous, 1e-9)
    close(frame.curve(SAMPLES), (np.column_stack([model(SAMPLES), np.ones(13)]) @ frame.matrix.T)[:, :3], 1e-9)
    close(frame.matrix @ frame.inverse_matrix, np.eye(4), 1e-12)
    # the neutral plane is z = -k in the frame, and every control point is in front of O
    pp = frame.matrix @ np.append(frame.plane_point, 1.0)
    assert abs(pp[2] + frame.k) < 1e-9 * (1 + frame.k)
    assert np.all(frame.curve.control_points[:, 2] > 0)
    # weights times distance to the neutral plane are constant: that is what makes it neutral
    dist = model.control_points @ frame.plane_normal - frame.plane_normal @ frame.plane_point
    prod = dist * model.weights
    assert np.allclose(prod, prod[0], rtol=1e-8)


@settings(max_examples=20)
@given(curves(dim=3, min_degree=4, max_degree=8, rational=False))
def test_generic_curves_have_no_neutral_plane(c: RationalBezier) -> None:
    w = np.linspace(1.0, 2.0, c.degree + 1) ** 2  # weights no plane can balance for generic points
    curve = RationalBezier(c.control_points, w)
    pts = curve.control_points
    centred = pts - pts.mean(axis=0)
    if np.linalg.svd(centred, compute_uv=False)[-1] < 1e-3 * (1 + np.abs(pts).max()):
        return  # (nearly) coplanar control points may have one
    with pytest.raises(NoNeutralPlaneError, match="not of the paper's form"):
        find_neutral_plane(curve)


@pytest.mark.parametrize(
    ("call", "error", "builtin"),
    [
        (lambda: ReliefPerspective(0.0), SpanError, ValueError),
        (lambda: ReliefPerspective(-1.0), SpanError, ValueError),
        (lambda: ReliefPerspective(1.0), SpanError, ValueError),
        (lambda: ReliefPerspective(float("nan")), SpanError, ValueError),
        (lambda: ReliefPerspective("two"), InputTypeError, TypeError),  # type: ignore[arg-type]
        (lambda: central_projection([1.0, 2.0, -1.0]), ProjectionError, ValueError),
        (lambda: central_projection(RationalBezier([[0, 0, 1], [1, 1, -1]])), ProjectionError, ValueError),
        (lambda: central_projection([1.0, 2.0]), ShapeError, ValueError),
        (lambda: central_projection([1.0, float("nan"), 1.0]), ReliefCadError, ValueError),
        (lambda: lift(RationalBezier([[0, 0, 0], [1, 1, 1]])), ShapeError, ValueError),
        (lambda: lift([[0, 0], [1, 1]]), InputTypeError, TypeError),  # type: ignore[arg-type]
        (lambda: preimage_of_lift(RationalBezier([[0, 0], [1, 1]], [1, 5]), 2.0), WeightError, ValueError),
        (lambda: ReliefPerspective(2.0).apply(RationalBezier([[0, 0], [1, 1]])), ShapeError, ValueError),
        (lambda: ReliefPerspective(2.0).apply(RationalBezier([[0, 0, -5], [1, 1, 1]])), ProjectionError, ValueError),
        (lambda: find_neutral_plane("curve"), InputTypeError, TypeError),  # type: ignore[arg-type]
    ],
)
def test_bad_input(call, error, builtin) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(error) as info:
        call()
    assert isinstance(info.value, ReliefCadError) and isinstance(info.value, builtin)


def test_weight_error_names_smallest_admissible_span() -> None:
    with pytest.raises(WeightError, match=r"weight 2 is 4.5 and k = 2.0; any k > 3.5"):
        preimage_of_lift(RationalBezier([[0, 0], [1, 1], [2, 0]], [1, 2, 4.5]), 2.0)

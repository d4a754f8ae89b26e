"""Bad input to the public functions of relief_cad.relief and relief_cad.space (relief_scheme).

Every bad value gets its own ReliefCadError class, which is also the matching built-in, with a
message that names the parameter and what came; good input gives the same result as the math.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from relief_cad import RationalBezier
from relief_cad.errors import (
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ProjectionError,
    ReliefCadError,
    ShapeError,
    SpanError,
    ToleranceError,
    ToleranceTypeError,
)
from relief_cad.relief import (
    ReliefPerspective,
    central_projection,
    find_neutral_plane,
    lift,
    preimage_of_lift,
    relief_of_lift,
)
from relief_cad.space import ReliefFrame, relief_scheme

NAN, INF = float("nan"), float("inf")
P2 = RationalBezier([[0, 0], [1, 2], [2, 0]], [1.0, 0.5, 1.5])  # planar, weights < 1 + k for k = 2
A3 = RationalBezier([[0, 0, 1], [1, 2, 2], [2, 0, 3]])  # space, in front of the centre
B3 = RationalBezier([[0, 2, 1], [1, 0, 2], [2, 2, 1]])
Q3 = preimage_of_lift(P2, 2.0)  # of the paper's form: it has a neutral plane
SAMPLES = np.linspace(0.0, 1.0, 7)

Case = tuple[str, Callable[[], Any], type[Exception], type[Exception], tuple[str, ...]]

# a value that is not a curve: (id, value, type name in the message)
NOT_CURVES = [
    ("str", "x", "str"),
    ("None", None, "NoneType"),
    ("bool", True, "bool"),
    ("nan", NAN, "float"),
    ("int", 3, "int"),
    ("list of points", [[0.0, 0.0, 1.0], [1.0, 1.0, 2.0]], "list"),
    ("array of points", np.array([[0.0, 0.0], [1.0, 1.0]]), "ndarray"),
]
# a bad span k: (id, value, error, built-in, what came)
BAD_SPANS = [
    ("str", "2", InputTypeError, TypeError, "str"),
    ("None", None, InputTypeError, TypeError, "NoneType"),
    ("bool", True, InputTypeError, TypeError, "bool"),
    ("complex", 2j, InputTypeError, TypeError, "complex"),
    ("nan", NAN, SpanError, ValueError, "nan"),
    ("inf", INF, SpanError, ValueError, "inf"),
    ("zero", 0, SpanError, ValueError, "0.0"),
    ("negative", -1.0, SpanError, ValueError, "-1.0"),
    ("one", 1, SpanError, ValueError, "1.0"),
    ("10**400", 10**400, SpanError, ValueError, "too large"),
]
# a bad rtol of find_neutral_plane: a relative tolerance > 0 and < 1
BAD_RTOLS = [
    ("str", "1e-10", InputTypeError, TypeError, "str"),
    ("None", None, InputTypeError, TypeError, "NoneType"),
    ("bool", True, InputTypeError, TypeError, "bool"),
    ("complex", 1j, InputTypeError, TypeError, "complex"),
    ("list", [1e-10], InputTypeError, TypeError, "list"),
    ("nan", NAN, NonFiniteError, ValueError, "nan"),
    ("inf", INF, NonFiniteError, ValueError, "inf"),
    ("10**400", 10**400, NonFiniteError, ValueError, "too large"),
    ("zero", 0, ToleranceError, ValueError, "0.0"),
    ("negative", -1e-10, ToleranceError, ValueError, "-1e-10"),
    ("one", 1.0, ToleranceError, ValueError, "1.0"),
    ("above one", 5.0, ToleranceError, ValueError, "5.0"),
]
# a bad space tolerance of relief_scheme (the rules of intersect_space)
BAD_TOLS = [
    ("str", "1e-9", ToleranceTypeError, TypeError, "str"),
    ("bool", True, ToleranceTypeError, TypeError, "bool"),
    ("list", [1e-9], ToleranceTypeError, TypeError, "list"),
    ("nan", NAN, ToleranceError, ValueError, "nan"),
    ("inf", INF, ToleranceError, ValueError, "inf"),
    ("zero", 0, ToleranceError, ValueError, "0.0"),
    ("negative", -1e-6, ToleranceError, ValueError, "-1e-06"),
    ("10**400", 10**400, ToleranceError, ValueError, "digits"),
    ("above the cap", 1.0, ToleranceError, ValueError, "at most"),
]


def _shear() -> np.ndarray:
    m = np.eye(4)
    m[0, 1] = 0.5
    return m


# a bad frame of relief_scheme: (id, value, error, built-in, (parameter, what came))
BAD_FRAMES = [
    ("str", "model", InputTypeError, TypeError, ("frame should", "str")),
    ("bare matrix", np.eye(4), InputTypeError, TypeError, ("frame should", "ndarray")),
    ("scale str", ReliefFrame(np.eye(4), "1", "f"), InputTypeError, TypeError, ("frame.scale", "str")),  # type: ignore[arg-type]
    ("scale None", ReliefFrame(np.eye(4), None, "f"), InputTypeError, TypeError, ("frame.scale", "NoneType")),  # type: ignore[arg-type]
    ("scale nan", ReliefFrame(np.eye(4), NAN, "f"), NonFiniteError, ValueError, ("frame.scale", "nan")),
    ("scale zero", ReliefFrame(np.eye(4), 0.0, "f"), InvalidInputError, ValueError, ("frame.scale", "0.0")),
    ("scale negative", ReliefFrame(np.eye(4), -1.0, "f"), InvalidInputError, ValueError, ("frame.scale", "-1.0")),
    ("matrix str", ReliefFrame("eye", 1.0, "f"), InputTypeError, TypeError, ("frame.matrix", "str")),  # type: ignore[arg-type]
    ("matrix 3x3", ReliefFrame(np.eye(3), 1.0, "f"), ShapeError, ValueError, ("frame.matrix", "(3, 3)")),
    ("matrix nan", ReliefFrame(np.full((4, 4), NAN), 1.0, "f"), NonFiniteError, ValueError, ("frame.matrix", "nan")),
    ("matrix shear", ReliefFrame(_shear(), 1.0, "f"), InvalidInputError, ValueError, ("frame.matrix", "0.5")),
    ("scale not the matrix's", ReliefFrame(np.eye(4), 2.0, "f"), InvalidInputError, ValueError,
     ("frame.matrix", "by 3")),
    ("projective matrix", ReliefFrame(np.diag([1.0, 1.0, 1.0, 2.0]), 1.0, "f"), InvalidInputError, ValueError,
     ("frame.matrix", "2.0]")),
    ("curves behind the centre", ReliefFrame(np.diag([1.0, 1.0, -1.0, 1.0]), 1.0, "f"), ProjectionError,
     ValueError, ("frame should", "z = -1.0")),
]
# bad points or curve x of central_projection and ReliefPerspective.apply / inverse
BAD_X = [
    ("str", "abc", InputTypeError, TypeError, "str"),
    ("None", None, InputTypeError, TypeError, "NoneType"),
    ("bool", True, InputTypeError, TypeError, "bool"),
    ("complex", [1j, 0, 1], InputTypeError, TypeError, "complex"),
    ("ragged", [[0, 0, 1], [1, 1]], InputTypeError, TypeError, "ragged"),
    ("scalar", 1.5, ShapeError, ValueError, "shape ()"),
    ("planar point", [1.0, 2.0], ShapeError, ValueError, "shape (2,)"),
    ("planar points", [[1.0, 2.0], [3.0, 4.0]], ShapeError, ValueError, "shape (2, 2)"),
    ("nan", [1.0, NAN, 1.0], NonFiniteError, ValueError, "nan"),
    ("inf", [[1.0, 1.0, 1.0], [1.0, 1.0, INF]], NonFiniteError, ValueError, "inf"),
    ("planar curve", P2, ShapeError, ValueError, "2-D one"),
]


def _cases() -> list[Case]:
    cases: list[Case] = []

    def add(cid: str, call: Callable[[], Any], err: type[Exception], builtin: type[Exception],
            *words: str) -> None:
        cases.append((cid, call, err, builtin, words))

    for cid, v, came in NOT_CURVES:
        add(f"relief_scheme-a-{cid}", lambda v=v: relief_scheme(v, B3), InputTypeError, TypeError, "a should", came)
        add(f"relief_scheme-b-{cid}", lambda v=v: relief_scheme(A3, v), InputTypeError, TypeError, "b should", came)
        add(f"find_neutral_plane-curve-{cid}", lambda v=v: find_neutral_plane(v), InputTypeError, TypeError,
            "curve should", came)
        add(f"lift-curve-{cid}", lambda v=v: lift(v), InputTypeError, TypeError, "curve to lift should", came)
        add(f"preimage_of_lift-curve-{cid}", lambda v=v: preimage_of_lift(v, 2.0), InputTypeError, TypeError,
            "curve should", came)
        add(f"relief_of_lift-curve-{cid}", lambda v=v: relief_of_lift(v, 2.0), InputTypeError, TypeError,
            "curve should", came)
    for cid, k, err, builtin, came in BAD_SPANS:
        add(f"relief_scheme-k-{cid}", lambda k=k: relief_scheme(A3, B3, k=k), err, builtin, "span k", came)
        add(f"find_neutral_plane-k-{cid}", lambda k=k: find_neutral_plane(Q3, k=k), err, builtin, "span k", came)
        add(f"preimage_of_lift-k-{cid}", lambda k=k: preimage_of_lift(P2, k), err, builtin, "span k", came)
        add(f"relief_of_lift-k-{cid}", lambda k=k: relief_of_lift(P2, k), err, builtin, "span k", came)
        add(f"ReliefPerspective-k-{cid}", lambda k=k: ReliefPerspective(k), err, builtin, "span k", came)
    for cid, r, err, builtin, came in BAD_RTOLS:
        add(f"find_neutral_plane-rtol-{cid}", lambda r=r: find_neutral_plane(Q3, rtol=r), err, builtin,
            "rtol should", came)
    for cid, t, err, builtin, came in BAD_TOLS:
        add(f"relief_scheme-tol-{cid}", lambda t=t: relief_scheme(A3, B3, tol=t), err, builtin, "tol should", came)
    for cid, f, err, builtin, words in BAD_FRAMES:
        add(f"relief_scheme-frame-{cid}", lambda f=f: relief_scheme(A3, B3, frame=f), err, builtin, *words)
    phi = ReliefPerspective(2.0)
    for cid, x, err, builtin, came in BAD_X:
        add(f"central_projection-x-{cid}", lambda x=x: central_projection(x), err, builtin, "x should", came)
        add(f"apply-x-{cid}", lambda x=x: phi.apply(x), err, builtin, "x should", came)
        add(f"inverse-x-{cid}", lambda x=x: phi.inverse(x), err, builtin, "x should", came)
    for name, fn in (("lift", lift), ("preimage_of_lift", lambda c: preimage_of_lift(c, 2.0)),
                     ("relief_of_lift", lambda c: relief_of_lift(c, 2.0))):
        add(f"{name}-curve-space curve", lambda fn=fn: fn(A3), ShapeError, ValueError, "curve", "3-D one")
    add("central_projection-x-overflow", lambda: central_projection([1e300, 1e300, 1e-300]), NonFiniteError,
        ValueError, "image of x", "inf")
    add("apply-x-overflow", lambda: ReliefPerspective(1e300).apply([1e300, 1e300, 1e300]), NonFiniteError,
        ValueError, "image of x", "inf")
    return cases


CASES = _cases()


@pytest.mark.parametrize(("cid", "call", "error", "builtin", "words"), CASES, ids=[c[0] for c in CASES])
def test_bad_input_is_refused(cid: str, call: Callable[[], Any], error: type[Exception],
                              builtin: type[Exception], words: tuple[str, ...]) -> None:
    with pytest.raises(Exception) as info:  # noqa: B017  the exact class is asserted below
        call()
    exc = info.value
    assert type(exc) is error, (cid, type(exc).__name__, str(exc))
    assert isinstance(exc, ReliefCadError) and isinstance(exc, builtin), cid
    for word in words:  # the parameter, then what came
        assert word in str(exc), (cid, word, str(exc))


def test_every_public_function_is_covered() -> None:
    names = {c[0].split("-")[0] for c in CASES}
    assert names == {"relief_scheme", "find_neutral_plane", "central_projection", "lift", "preimage_of_lift",
                     "relief_of_lift", "ReliefPerspective", "apply", "inverse"}


# ---------------------------------------------------------------------------- good input, same result
def _phi_matrix(k: float) -> np.ndarray:
    """φ_k as a 4x4 homogeneous matrix, from the paper's formula (x, y, z) -> (1 + k)(x, y, z) / (z + k)."""
    m = np.diag([1.0 + k, 1.0 + k, 1.0 + k, k])
    m[3, 2] = 1.0
    return m


def test_relief_scheme_good_input_unchanged() -> None:
    s = relief_scheme(A3, B3, k=3, tol=1e-7)
    assert s.frame.name == "model" and s.frame.scale == 1.0
    np.testing.assert_array_equal(s.frame.matrix, np.eye(4))  # every control point has z > 0
    rel = A3.homogeneous @ _phi_matrix(3.0).T
    np.testing.assert_array_equal(s.a_frame.homogeneous, A3.homogeneous)
    np.testing.assert_array_equal(s.a_relief.homogeneous, rel)
    np.testing.assert_array_equal(s.a_image.homogeneous, rel[:, :3])  # ψ: drop W
    pts = np.vstack([A3.control_points, B3.control_points])
    r2 = float(np.max((pts[:, 0] ** 2 + pts[:, 1] ** 2) / pts[:, 2] ** 2))
    assert s.planar_tolerance == math.sqrt(1.0 + r2) / float(pts[:, 2].min()) * 1e-7 * (1.0 + 1e-6)
    again = relief_scheme(A3, B3, k=3.0, tol=1e-7, frame=s.frame)  # its own frame passes the check
    np.testing.assert_array_equal(again.b_image.homogeneous, s.b_image.homogeneous)
    assert again.planar_tolerance == s.planar_tolerance


def test_relief_scheme_takes_planar_curves_in_z0() -> None:
    flat_a, flat_b = RationalBezier([[0, 0], [1, 2], [2, 0]]), RationalBezier([[0, 1], [2, 1]])
    s = relief_scheme(flat_a, flat_b)
    t = relief_scheme(flat_a.embedded(3), flat_b.embedded(3))
    np.testing.assert_array_equal(s.a_image.homogeneous, t.a_image.homogeneous)
    np.testing.assert_array_equal(s.frame.matrix, t.frame.matrix)


def test_find_neutral_plane_good_input_unchanged() -> None:
    k = 2.0  # five control points in general position: the neutral plane is unique
    p = RationalBezier([[0, 0], [1, 2], [2, -1], [3, 3], [4, 0]], [1.0, 0.5, 1.5, 0.8, 1.2])
    h = p.homogeneous  # Q = preimage_of_lift(P, k) by the paper's formula: its neutral plane is z = -k
    q = RationalBezier.from_homogeneous(np.column_stack([k * h, 1.0 + k - p.weights]))
    frame = find_neutral_plane(q, k=3, rtol=np.float64(1e-10))
    np.testing.assert_allclose(frame.plane_normal, [0.0, 0.0, 1.0], atol=1e-12)
    assert abs(float(frame.plane_point @ frame.plane_normal) + k) < 1e-12
    assert frame.k == 3.0
    np.testing.assert_allclose(preimage_of_lift(frame.planar, 3.0).homogeneous, frame.curve.homogeneous,
                               rtol=1e-12, atol=1e-12)
    default = find_neutral_plane(q, 3.0)
    np.testing.assert_array_equal(default.matrix, frame.matrix)  # the same rtol, given as a numpy float


def test_central_projection_good_input_unchanged() -> None:
    pts = np.array([[1.0, 2.0, 4.0], [-3.0, 0.5, 0.25]])
    np.testing.assert_array_equal(central_projection(pts), pts[:, :2] / pts[:, 2:])
    np.testing.assert_array_equal(central_projection(pts[0].tolist()), pts[0, :2] / pts[0, 2])
    np.testing.assert_array_equal(central_projection(A3).homogeneous, A3.homogeneous[:, :3])


def test_relief_perspective_good_input_unchanged() -> None:
    phi, pts = ReliefPerspective(3), np.array([[1.0, 2.0, 4.0], [-3.0, 0.5, 0.25]])
    hom = np.column_stack([pts, np.ones(2)]) @ _phi_matrix(3.0).T
    np.testing.assert_array_equal(phi.apply(pts), hom[:, :3] / hom[:, 3:])
    np.testing.assert_array_equal(phi.apply(A3).homogeneous, A3.homogeneous @ _phi_matrix(3.0).T)
    np.testing.assert_allclose(phi.inverse(phi.apply(pts)), pts, rtol=1e-14)


def test_lift_good_input_unchanged() -> None:
    lifted = lift(P2)
    np.testing.assert_array_equal(lifted.control_points, P2.homogeneous)
    assert lifted.is_polynomial


def test_preimage_of_lift_good_input_unchanged() -> None:
    k, h, w = 2.5, P2.homogeneous, P2.weights
    expected = np.column_stack([k * h, 1.0 + k - w])  # W_i = k (x w, y w, w), Ω_i = 1 + k - w_i
    np.testing.assert_array_equal(preimage_of_lift(P2, np.float64(k)).homogeneous, expected)


def test_relief_of_lift_good_input_unchanged() -> None:
    k, h, w = 2.5, P2.homogeneous, P2.weights
    expected = np.column_stack([(1.0 + k) * h, w + k])  # (1 + k)(x w, y w, w) / (w + k), weight w + k
    np.testing.assert_array_equal(relief_of_lift(P2, k).homogeneous, expected)
    np.testing.assert_allclose(relief_of_lift(P2, k)(SAMPLES), ReliefPerspective(k).apply(lift(P2)(SAMPLES)),
                               rtol=1e-13, atol=1e-13)

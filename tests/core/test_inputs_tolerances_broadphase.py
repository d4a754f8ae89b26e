"""Bad input to the public functions of relief_cad.broadphase and relief_cad.tolerances.

Every bad value gets its own ReliefCadError class, which is also the matching built-in, with a
message that names the parameter and what came; good input gives the same answers as before
(and as the private functions relief_cad calls internally).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from relief_cad import RationalBezier
from relief_cad.broadphase import (
    _box_pairs,
    _box_pairs_between,
    _cluster_points,
    box_pairs,
    box_pairs_between,
    cluster_points,
)
from relief_cad.errors import (
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ShapeError,
    ToleranceError,
    ToleranceTypeError,
)
from relief_cad.tolerances import (
    _EPS,
    ROUNDING_ULPS,
    ModelTolerance,
    _floor_of_magnitude,
    _is_point_like,
    _resolve_tolerance,
    _rounding_floor,
    default_tolerance,
    floor_of_magnitude,
    is_point_like,
    resolve_tolerance,
    rounding_floor,
    size_of,
)
from tests.core._refused import refused

NAN, INF = float("nan"), float("inf")
A = RationalBezier([[0, 0], [1, 2], [2, 0]])
B = RationalBezier([[0, 0.5], [2, 0.5]])
S = RationalBezier([[0, 0, 0], [1, 2, 1], [2, 0, 3]])
LO = np.array([[0.0, 0.0], [0.5, 0.5], [3.0, 0.0]])
HI = LO + 1.0
PTS = np.array([[0.0, 0.0], [5.0, 0.0], [0.0, 1e-9]])




# ----------------------------------------------------------------------------- bad values
# an array of real numbers that is not one: (id, value, error, what came)
NOT_REAL_ARRAYS = [
    ("str", "x", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("bool array", np.array([[True, False]]), InputTypeError, "bool"),
    ("complex", np.array([[1j, 0.0]]), InputTypeError, "complex"),
    ("numeric str", [["1", "2"]], InputTypeError, "str"),
    ("ragged", [[0.0, 0.0], [1.0]], InputTypeError, "ragged"),
    ("object array of str", np.array([[0.0, "a"]], dtype=object), InputTypeError, "str"),
    ("object array of None", np.array([[0.0, None]], dtype=object), InputTypeError, "NoneType"),
    ("curve", A, InputTypeError, "RationalBezier"),
    ("nan entry", [[0.0, NAN]], NonFiniteError, "nan"),
    ("inf entry", np.array([[-INF, 0.0]]), NonFiniteError, "inf"),
    ("10**400 entry", [[10**400, 0.0]], NonFiniteError, "integer"),
]
# a distance that may be zero, badly given: (id, value, error, what came)
BAD_DISTANCES = [
    ("str", "x", ToleranceTypeError, "str"),
    ("None", None, ToleranceTypeError, "NoneType"),
    ("bool", True, ToleranceTypeError, "bool"),
    ("list", [], ToleranceTypeError, "list"),
    ("array", np.array([0.1]), ToleranceTypeError, "ndarray"),
    ("complex", 1j, ToleranceTypeError, "complex"),
    ("nan", NAN, ToleranceError, "nan"),
    ("inf", INF, ToleranceError, "inf"),
    ("negative", -1.0, ToleranceError, "-1.0"),
    ("tiny negative", -5e-324, ToleranceError, "-5e-324"),
    ("10**400", 10**400, ToleranceError, "integer"),
]


# ----------------------------------------------------------------------------- broadphase
@pytest.mark.parametrize("param", ["lows", "highs"])
@pytest.mark.parametrize(("what", "value", "error", "came"), NOT_REAL_ARRAYS, ids=[c[0] for c in NOT_REAL_ARRAYS])
def test_box_pairs_refuses_bad_corners(param, what, value, error, came) -> None:
    args = {"lows": LO[:1], "highs": HI[:1], param: value}
    refused(lambda: box_pairs(**args), error, param, came)


@pytest.mark.parametrize(("lows", "highs", "came"), [
    ([0.0, 0.0], [1.0, 1.0], "(2,)"),  # one box as a vector
    (np.zeros((2, 2, 2)), np.ones((2, 2, 2)), "(2, 2, 2)"),
    (LO, HI[:2], "(2, 2)"),  # a high missing
    (LO, HI[:, :1], "(3, 1)"),  # a coordinate missing
    (NAN, HI, "()"),  # a scalar
])
def test_box_pairs_refuses_bad_shapes(lows, highs, came) -> None:
    refused(lambda: box_pairs(lows, highs), ShapeError, "lows", "highs", "(n, dim)", came)


def test_box_pairs_refuses_an_inverted_box() -> None:
    refused(lambda: box_pairs(LO, np.vstack([HI[:2], [[2.0, 1.0]]])), InvalidInputError,
            "lows should be <= highs", "box 2", "[3.0, 0.0]", "[2.0, 1.0]")


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_DISTANCES, ids=[c[0] for c in BAD_DISTANCES])
def test_box_pairs_refuses_a_bad_pad(what, value, error, came) -> None:
    refused(lambda: box_pairs(LO, HI, pad=value), error, "pad", came)
    refused(lambda: box_pairs_between(LO, HI, LO, HI, pad=value), error, "pad", came)


@pytest.mark.parametrize("param", ["lows_a", "highs_a", "lows_b", "highs_b"])
@pytest.mark.parametrize(("what", "value", "error", "came"), NOT_REAL_ARRAYS, ids=[c[0] for c in NOT_REAL_ARRAYS])
def test_box_pairs_between_refuses_bad_corners(param, what, value, error, came) -> None:
    args = {"lows_a": LO[:1], "highs_a": HI[:1], "lows_b": LO[:1], "highs_b": HI[:1], param: value}
    refused(lambda: box_pairs_between(**args), error, param, came)


@pytest.mark.parametrize("side", ["a", "b"])
def test_box_pairs_between_refuses_bad_shapes_and_inverted_boxes(side: str) -> None:
    good = {"lows_a": LO, "highs_a": HI, "lows_b": LO, "highs_b": HI}
    refused(lambda: box_pairs_between(**{**good, f"highs_{side}": HI[:2]}), ShapeError,
            f"lows_{side} and highs_{side}", "(3, 2) and (2, 2)")
    refused(lambda: box_pairs_between(**{**good, f"lows_{side}": HI + 1.0}), InvalidInputError,
            f"lows_{side} should be <= highs_{side}", "box 0")


def test_box_pairs_between_refuses_sets_of_two_dimensions() -> None:
    refused(lambda: box_pairs_between(LO, HI, np.zeros((1, 3)), np.ones((1, 3))), ShapeError,
            "lows_a and lows_b", "2 and 3")


@pytest.mark.parametrize(("what", "value", "error", "came"), NOT_REAL_ARRAYS, ids=[c[0] for c in NOT_REAL_ARRAYS])
def test_cluster_points_refuses_bad_points(what, value, error, came) -> None:
    refused(lambda: cluster_points(value, 0.1), error, "points", came)


@pytest.mark.parametrize(("value", "came"), [
    ([0.0, 1.0], "(2,)"), (np.zeros((2, 2, 2)), "(2, 2, 2)"), (np.zeros((3, 0)), "(3, 0)"), (NAN, "()"),
])
def test_cluster_points_refuses_points_of_a_bad_shape(value, came) -> None:
    refused(lambda: cluster_points(value, 0.1), ShapeError, "points", "(n, dim)", came)


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_DISTANCES, ids=[c[0] for c in BAD_DISTANCES])
def test_cluster_points_refuses_a_bad_tol(what, value, error, came) -> None:
    refused(lambda: cluster_points(PTS, value), error, "tol", came)


BAD_LINKS = [
    ("str", "x", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("int", 0, InputTypeError, "int"),
    ("nan", NAN, InputTypeError, "float"),
    ("float pairs", [(0, 1.5)], InputTypeError, "float64"),
    ("whole floats", np.array([[0.0, 1.0]]), InputTypeError, "float64"),
    ("bool pairs", [[True, False]], InputTypeError, "bool"),
    ("object array", np.array([[0, 1]], dtype=object), InputTypeError, "object"),
    ("ragged", [(0, 1), (2,)], InputTypeError, "ragged"),
    ("one flat pair", (0, 1), ShapeError, "(2,)"),
    ("triples", [(0, 1, 2)], ShapeError, "(1, 3)"),
    ("3d", np.zeros((1, 1, 2), dtype=np.int64), ShapeError, "(1, 1, 2)"),
    ("index too large", [(0, 3)], ShapeError, "from 0 to 3"),
    ("negative index", [(-1, 0)], ShapeError, "from -1 to 0"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_LINKS, ids=[c[0] for c in BAD_LINKS])
def test_cluster_points_refuses_bad_links(what, value, error, came) -> None:
    refused(lambda: cluster_points(PTS, 1e-6, links=value), error, "links", came)


# ----------------------------------------------------------------------------- tolerances
CURVE_FUNCS: list[tuple[str, Callable[..., Any], str]] = [
    ("default_tolerance", default_tolerance, "inputs"),
    ("size_of", size_of, "curves"),
    ("rounding_floor", rounding_floor, "curves"),
    ("resolve_tolerance", lambda *c: resolve_tolerance(None, *c), "curves"),
    ("resolve_tolerance(1e-9)", lambda *c: resolve_tolerance(1e-9, *c), "curves"),
]
# not a curve nor an array of points: (id, value, error, what came)
NOT_POINTS = [
    *NOT_REAL_ARRAYS[:-4],  # all but the curve (a curve is good here) and the non-finite entries
    ("nan", NAN, InputTypeError, "float"),
    ("int", 3, InputTypeError, "int"),
    ("empty", np.empty((0, 2)), InputTypeError, "empty"),
    ("empty list", [], InputTypeError, "empty"),
    ("vector", np.array([0.0, 1.0]), ShapeError, "(2,)"),
    ("3d array", np.zeros((2, 2, 2)), ShapeError, "(2, 2, 2)"),
    ("nan entry", np.array([[0.0, 1.0], [NAN, 0.0]]), NonFiniteError, "nan"),
    ("inf entry", [[INF, 0.0]], NonFiniteError, "inf"),
    ("10**400 entry", [[10**400, 0.0]], NonFiniteError, "integer"),
]


@pytest.mark.parametrize(("func", "param"), [(f, p) for _, f, p in CURVE_FUNCS], ids=[c[0] for c in CURVE_FUNCS])
@pytest.mark.parametrize(("what", "value", "error", "came"), NOT_POINTS, ids=[c[0] for c in NOT_POINTS])
def test_curves_or_points_are_checked(func, param, what, value, error, came) -> None:
    refused(lambda: func(A, value), error, f"{param}[1]", came)


@pytest.mark.parametrize(("func", "param"), [(f, p) for _, f, p in CURVE_FUNCS], ids=[c[0] for c in CURVE_FUNCS])
def test_at_least_one_curve_is_needed(func, param) -> None:
    refused(lambda: func(), InputTypeError, "needs at least one", param)


BAD_TOLS = [
    *[c for c in BAD_DISTANCES if c[0] not in ("None", "negative", "tiny negative")],
    ("zero", 0.0, ToleranceError, "0.0"),
    ("int zero", 0, ToleranceError, "0.0"),
    ("negative", -1e-9, ToleranceError, "-1e-09"),
    ("model nan", ModelTolerance(NAN), ToleranceError, "nan"),
    ("above the cap", 1.0, ToleranceError, "at most 0.01"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_TOLS, ids=[c[0] for c in BAD_TOLS])
def test_resolve_tolerance_refuses_a_bad_tol(what, value, error, came) -> None:
    refused(lambda: resolve_tolerance(value, A, B), error, "tol", came)


@pytest.mark.parametrize(("what", "value", "came"), [
    ("str", "x", "str"), ("None", None, "NoneType"), ("array", A.control_points, "ndarray"), ("float", 1.5, "float"),
])
def test_is_point_like_refuses_a_bad_curve(what, value, came) -> None:
    refused(lambda: is_point_like(value, 1e-9), InputTypeError, "curve", came)


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_DISTANCES, ids=[c[0] for c in BAD_DISTANCES])
def test_is_point_like_refuses_a_bad_tol(what, value, error, came) -> None:
    refused(lambda: is_point_like(A, value), error, "tol", came)


BAD_MAGNITUDES = [
    ("str", "x", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("list", [], InputTypeError, "list"),
    ("array", np.array([1.0, 2.0]), InputTypeError, "ndarray"),
    ("complex", 1j, InputTypeError, "complex"),
    ("nan", NAN, NonFiniteError, "nan"),
    ("inf", INF, NonFiniteError, "inf"),
    ("-inf", -INF, NonFiniteError, "-inf"),
    ("10**400", 10**400, NonFiniteError, "integer"),
    ("negative", -1.0, InvalidInputError, "-1.0"),
    ("tiny negative", -5e-324, InvalidInputError, "-5e-324"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_MAGNITUDES, ids=[c[0] for c in BAD_MAGNITUDES])
def test_floor_of_magnitude_refuses_a_bad_magnitude(what, value, error, came) -> None:
    refused(lambda: floor_of_magnitude(value), error, "big", came)


# ----------------------------------------------------------------------------- good input
def test_box_pairs_good_input_answers_as_before() -> None:
    assert box_pairs(LO, HI).tolist() == [[0, 1]]
    assert box_pairs(LO.tolist(), HI.tolist(), pad=0).tolist() == [[0, 1]]  # lists, an int pad of 0
    assert box_pairs(LO, HI, pad=np.float64(2.0)).tolist() == [[0, 1], [0, 2], [1, 2]]
    assert box_pairs(LO, HI, pad=ModelTolerance(2.0)).tolist() == [[0, 1], [0, 2], [1, 2]]
    assert box_pairs(np.array([[0, 0], [1, 1], [3, 0]], dtype=np.int32), np.array([[1, 1], [2, 2], [4, 1]],
                     dtype=np.int32)).tolist() == [[0, 1]]
    assert box_pairs(np.zeros((2, 0)), np.zeros((2, 0))).tolist() == [[0, 1]]  # no axis: one point
    assert box_pairs_between(LO, HI, LO[2:], HI[2:], pad=0.0).tolist() == [[2, 0]]
    assert box_pairs_between(LO, HI, np.empty((0, 3)), np.empty((0, 3))).shape == (0, 2)


@pytest.mark.parametrize("seed", range(4))
def test_public_and_internal_broadphase_agree(seed: int) -> None:
    rng = np.random.default_rng(seed)
    lo = rng.random((150, 2)) * 10
    hi = lo + rng.random((150, 2))
    pad = float(rng.choice([0.0, 0.05]))
    assert np.array_equal(box_pairs(lo, hi, pad=pad), _box_pairs(lo, hi, pad))
    assert np.array_equal(box_pairs_between(lo[:70], hi[:70], lo[70:], hi[70:], pad=pad),
                          _box_pairs_between(lo[:70].tolist(), hi[:70].tolist(), lo[70:], hi[70:], pad))
    pts = np.round(lo, 1)
    links = rng.integers(0, 150, (5, 2))
    assert np.array_equal(cluster_points(pts, 0.05, links=links), _cluster_points(pts, 0.05, links.tolist()))


def test_cluster_points_good_input_answers_as_before() -> None:
    assert cluster_points(PTS, 1e-6).tolist() == [0, 1, 0]
    assert cluster_points(PTS, 0).tolist() == [0, 1, 2]  # tol 0: only equal points are one
    assert cluster_points(PTS.tolist(), 1e-6, links=[(0, 1)]).tolist() == [0, 0, 0]
    for none in ((), [], np.empty((0, 2), dtype=np.int64), np.array([], dtype=np.uint8)):
        assert cluster_points(PTS, 1e-6, links=none).tolist() == [0, 1, 0]
    assert cluster_points(PTS, 1e-6, links=np.array([[1, 2]], dtype=np.uint16)).tolist() == [0, 0, 0]
    assert cluster_points(np.empty((0, 3)), 1.0, links=[]).tolist() == []


def test_tolerances_good_input_answers_as_before() -> None:
    floor2 = ROUNDING_ULPS * _EPS * 2.0
    assert size_of(A, B) == math.hypot(2.0, 2.0)
    assert size_of(A, [[0, 0], [3, 4]]) == 5.0  # a list of int points
    assert size_of(S, np.array([[0.0, 0.0]])) == math.hypot(2.0, 2.0, 3.0)
    assert rounding_floor(A, B) == floor2 == floor_of_magnitude(2) == floor_of_magnitude(np.float64(2.0))
    assert floor_of_magnitude(0) == floor_of_magnitude(-0.0) == 1e-300
    assert default_tolerance([[0, 0], [3, 4]]) == default_tolerance(np.array([[0.0, 0.0], [3.0, 4.0]]))
    assert default_tolerance(A, B.control_points) > 0.0
    assert resolve_tolerance(None, A, B) == default_tolerance(A, B)
    assert resolve_tolerance(1e-9, A, B) == 1e-9
    assert resolve_tolerance(1e-300, A) == floor2
    assert resolve_tolerance(np.float64(1e-6), A, B.control_points) == 1e-6
    assert resolve_tolerance(ModelTolerance(1.0), A) == 1.0  # a model's tolerance is not capped
    assert is_point_like(RationalBezier([[1.0, 1.0], [1.0, 1.0]]), 0)  # tol 0: all one point
    assert not is_point_like(A, 1.99) and is_point_like(A, 2.0) and is_point_like(A, 2)


@pytest.mark.parametrize("tol", [None, 1e-300, 1e-9, 1e-3, ModelTolerance(1e-7)])
def test_public_and_internal_tolerances_agree(tol: float | None) -> None:
    for curves in ((A, B), (S, A), (A, B.control_points), (S,)):
        assert resolve_tolerance(tol, *curves) == _resolve_tolerance(tol, *curves)
        assert rounding_floor(*curves) == _rounding_floor(*curves)
    for big in (0.0, 1.0, 1e-310, 1e300):
        assert floor_of_magnitude(big) == _floor_of_magnitude(big)
    for t in (0.0, 1e-9, 2.0):
        assert is_point_like(A, t) == _is_point_like(A, t)

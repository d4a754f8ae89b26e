"""Bad input to the public functions of relief_cad.contacts, relief_cad.pieces and results.finish.

Every bad value gets its own ReliefCadError class, which is also the matching built-in, with a
message that names the parameter and what came. Before these checks a string or None in place of a
curve raised a raw AttributeError, a NaN or negative tol and a parameter outside [0, 1] were taken
(answering None, [] or a direction at the wrong place), and ``finish`` took any ``on_budget``.
Good input gives the same answers as before, and as the private functions relief_cad calls itself.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from relief_cad import (
    RationalBezier,
    contacts,
    intersect,
    intersect_many,
    intersect_space,
    intersection,
    pieces,
    results,
    space,
)
from relief_cad.contacts import (
    _curve_direction,
    _needs_refining,
    _refine_contacts,
    _refine_self,
    _self_overlaps,
    _whole_overlap,
    curve_direction,
    needs_refining,
    refine_contacts,
    refine_self,
    self_overlaps,
    whole_overlap,
)
from relief_cad.errors import (
    BudgetExceededError,
    DegenerateCurveError,
    DegreeError,
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ShapeError,
    ToleranceError,
    ToleranceTypeError,
)
from relief_cad.pieces import (
    _along_chord,
    _monotone_pieces,
    _one_place,
    along_chord,
    monotone_pieces,
    one_place,
)
from relief_cad.results import Intersection, IntersectionList, Overlap, ParameterBox, _finish, finish
from relief_cad.tolerances import ModelTolerance
from tests.core._refused import refused

NAN, INF = float("nan"), float("inf")
A = RationalBezier([[0, 0], [1, 2], [2, 0]])
B = RationalBezier([[0, 0.5], [2, 0.5]])
ITEMS = list(intersect(A, B))
ARCH = RationalBezier([[0, 0], [1, 1], [2, 0]])  # touches the line y = 0.5 at t = 0.5
LINE = RationalBezier([[0, 0.5], [2, 0.5]])
S3 = RationalBezier([[0, 0, 0], [1, 2, 1], [2, 0, 3]])
RETRACE = RationalBezier([[0, 0, 0], [1, 1, 1], [1, 1, 1], [0, 0, 0]])  # runs out and back
RETRACE_ITEMS = [Intersection(x, 1.0 - x, RETRACE(x), "tangent") for x in (0.0, 0.25, 0.375)]
OV = Overlap(t=(0.0, 0.25), u=(1.0, 0.75))
PARTS = [(OV, True), (Overlap(t=(0.25, 0.5), u=(0.75, 0.5)), True)]
LOOP = RationalBezier([[0.0, 0.0], [3.0, 1.0], [-1.0, 1.0], [2.0, 0.0]])  # crosses itself once
ARCH_POINTS = [[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]]


def _open() -> IntersectionList:
    return IntersectionList(ITEMS, [ParameterBox(0.0, 0.5, 0.0, 1.0)], 1e-9)


def _simple(p: Any) -> bool:
    return bool(np.ptp(p, axis=0).max() < 0.5)


# the good arguments of each public function; each case below changes one of them
GOOD: dict[Callable[..., Any], dict[str, Any]] = {
    curve_direction: {"c": A, "t": 0.5, "side": 1},
    needs_refining: {"a": A, "b": B, "items": ITEMS},
    whole_overlap: {"a": A, "b": B, "tol": 1e-9},
    refine_contacts: {"a": A, "b": B, "items": ITEMS, "tol": 1e-9},
    refine_self: {"c": RETRACE, "items": RETRACE_ITEMS, "tol": 1e-9},
    self_overlaps: {"pieces": PARTS, "curve": LOOP},
    along_chord: {"points": ARCH_POINTS},
    monotone_pieces: {"curve": LOOP, "tol": 1e-9, "simple": _simple, "max_depth": 10},
    one_place: {"curve": A, "t": 0.2, "u": 0.3, "tol": 1e-9},
    finish: {"result": _open(), "on_budget": "return"},
}


def call(fn: Callable[..., Any], **bad: Any) -> Any:
    """``fn`` on its good arguments with ``bad`` put in."""
    return fn(**{**GOOD[fn], **bad})




def _ids(cases: list[tuple[Any, ...]]) -> list[str]:
    return [c[0] for c in cases]


def test_every_public_function_is_covered() -> None:
    names = {f.__name__ for f in GOOD}
    public = {n for n in contacts.__all__ + pieces.__all__ if callable(getattr(contacts, n, None))
              or callable(getattr(pieces, n, None))}
    assert public | {"finish"} == names


@pytest.mark.parametrize("fn", list(GOOD), ids=[f.__name__ for f in GOOD])
def test_good_arguments_are_taken(fn: Callable[..., Any]) -> None:
    call(fn)


# ----------------------------------------------------------------------------- curves
# not a curve: (id, value, what came)
NOT_CURVES = [
    ("str", "x", "str"),
    ("None", None, "NoneType"),
    ("bool", True, "bool"),
    ("nan", NAN, "float"),
    ("int", 3, "int"),
    ("list of points", [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]], "list"),
    ("array of points", np.array([[0.0, 0.0], [1.0, 2.0]]), "ndarray"),
    ("a result", Overlap(t=(0.0, 1.0), u=(0.0, 1.0)), "Overlap"),
]
CURVE_PARAMS = [
    (curve_direction, "c"), (needs_refining, "a"), (needs_refining, "b"), (whole_overlap, "a"),
    (whole_overlap, "b"), (refine_contacts, "a"), (refine_contacts, "b"), (refine_self, "c"),
    (self_overlaps, "curve"), (monotone_pieces, "curve"), (one_place, "curve"),
]


@pytest.mark.parametrize(("fn", "param"), CURVE_PARAMS, ids=[f"{f.__name__}-{p}" for f, p in CURVE_PARAMS])
@pytest.mark.parametrize(("what", "value", "came"), [c for c in NOT_CURVES if c[1] is not None],
                         ids=_ids([c for c in NOT_CURVES if c[1] is not None]))
def test_a_curve_is_checked(fn, param, what, value, came) -> None:
    refused(lambda: call(fn, **{param: value}), InputTypeError, f"{param} should be a RationalBezier", came)


NEEDED_CURVES = [c for c in CURVE_PARAMS if c[0] is not self_overlaps]  # its curve may be None


@pytest.mark.parametrize(("fn", "param"), NEEDED_CURVES, ids=[f"{f.__name__}-{p}" for f, p in NEEDED_CURVES])
def test_none_is_no_curve(fn, param) -> None:
    refused(lambda: call(fn, **{param: None}), InputTypeError, param, "NoneType")


@pytest.mark.parametrize("fn", [needs_refining, refine_contacts])
def test_the_two_curves_of_a_pair_have_one_dimension(fn) -> None:
    refused(lambda: call(fn, b=S3), ShapeError, "a and b should be curves of one dimension", "2-D and 3-D")
    refused(lambda: call(fn, a=S3, items=[]), ShapeError, "a and b", "3-D and 2-D")


# ----------------------------------------------------------------------------- tolerances
BAD_TOLS = [
    ("str", "1e-9", ToleranceTypeError, "str"),
    ("None", None, ToleranceTypeError, "NoneType"),
    ("bool", True, ToleranceTypeError, "bool"),
    ("list", [1e-9], ToleranceTypeError, "list"),
    ("array", np.array([1e-9]), ToleranceTypeError, "ndarray"),
    ("complex", 1j, ToleranceTypeError, "complex"),
    ("nan", NAN, ToleranceError, "nan"),
    ("inf", INF, ToleranceError, "inf"),
    ("zero", 0, ToleranceError, "0.0"),
    ("negative", -1e-9, ToleranceError, "-1e-09"),
    ("tiny negative", -5e-324, ToleranceError, "-5e-324"),
    ("10**400", 10**400, ToleranceError, "integer"),
    ("model nan", ModelTolerance(NAN), ToleranceError, "nan"),
]
TOL_FUNCS = [whole_overlap, refine_contacts, refine_self, monotone_pieces, one_place]


@pytest.mark.parametrize("fn", TOL_FUNCS, ids=[f.__name__ for f in TOL_FUNCS])
@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_TOLS, ids=_ids(BAD_TOLS))
def test_tol_is_checked(fn, what, value, error, came) -> None:
    refused(lambda: call(fn, tol=value), error, "tol should be", came)


# ----------------------------------------------------------------------------- results
BAD_ITEMS = [
    ("str", "x", "items should be a sequence", "str"),
    ("None", None, "items should be a sequence", "NoneType"),
    ("bool", True, "items should be a sequence", "bool"),
    ("nan", NAN, "items should be a sequence", "float"),
    ("one result", ITEMS[0], "items should be a sequence", "Intersection"),
    ("array", np.array(ITEMS), "items should be a sequence", "ndarray"),
    ("generator", (r for r in ITEMS), "items should be a sequence", "generator"),
    ("set", {OV}, "items should be a sequence", "set"),
    ("a tuple item", [*ITEMS, (0.5, 0.5)], f"items[{len(ITEMS)}] should be an Intersection", "tuple"),
    ("a curve item", [A], "items[0] should be an Intersection or an Overlap", "RationalBezier"),
    ("a float item", [0.5], "items[0]", "float"),
    ("a None item", (None,), "items[0]", "NoneType"),
    ("a box item", [ParameterBox(0.0, 1.0, 0.0, 1.0)], "items[0]", "ParameterBox"),
    ("a nested list", [ITEMS], "items[0]", "list"),
    ("a string list", ["crossing"], "items[0]", "str"),
]
ITEM_FUNCS = [needs_refining, refine_contacts, refine_self]


@pytest.mark.parametrize("fn", ITEM_FUNCS, ids=[f.__name__ for f in ITEM_FUNCS])
@pytest.mark.parametrize(("what", "value", "words", "came"), BAD_ITEMS, ids=_ids(BAD_ITEMS))
def test_items_are_checked(fn, what, value, words, came) -> None:
    refused(lambda: call(fn, items=value), InputTypeError, words, came)


BAD_PIECES = [
    ("str", "x", "pieces should be a sequence of (Overlap, bool) pairs", "str"),
    ("None", None, "pieces should be a sequence", "NoneType"),
    ("one pair", (OV, True), "pieces[0] should be an (Overlap, bool) pair", "Overlap"),
    ("array", np.array([1.0]), "pieces should be a sequence", "ndarray"),
    ("dict", {OV: True}, "pieces should be a sequence", "dict"),
    ("bare overlaps", [OV], "pieces[0] should be an (Overlap, bool) pair", "not Overlap"),
    ("no flag", [(OV,)], "pieces[0]", "(Overlap)"),
    ("three", [*PARTS, (OV, True, 1)], "pieces[2]", "(Overlap, bool, int)"),
    ("a point", [(ITEMS[0], True)], "pieces[0]", "(Intersection, bool)"),
    ("flag first", [(True, OV)], "pieces[0]", "(bool, Overlap)"),
    ("an int flag", [(OV, 1)], "pieces[0][1] should be True or False", "int"),
    ("a None flag", [*PARTS, (OV, None)], "pieces[2][1]", "NoneType"),
    ("a str flag", [[OV, "yes"]], "pieces[0][1]", "str"),
]


@pytest.mark.parametrize(("what", "value", "words", "came"), BAD_PIECES, ids=_ids(BAD_PIECES))
def test_self_overlaps_pieces_are_checked(what, value, words, came) -> None:
    refused(lambda: self_overlaps(value), InputTypeError, words, came)


BAD_RESULTS = [
    ("str", "x", "str"),
    ("None", None, "NoneType"),
    ("a plain list", list(ITEMS), "list"),
    ("a tuple", tuple(ITEMS), "tuple"),
    ("one result", ITEMS[0], "Intersection"),
    ("an array", np.array([1.0]), "ndarray"),
]


@pytest.mark.parametrize(("what", "value", "came"), BAD_RESULTS, ids=_ids(BAD_RESULTS))
def test_finish_result_is_checked(what, value, came) -> None:
    refused(lambda: finish(value, "raise"), InputTypeError, "result should be an IntersectionList", came)


@pytest.mark.parametrize(("value", "came"), [
    ("ignore", "'ignore'"), ("Raise", "'Raise'"), ("", "''"), (None, "None"), (True, "True"), (1, "1"),
])
def test_finish_on_budget_is_checked(value, came) -> None:
    """A misspelt "raise" used to return the open result as if "return" had been asked for."""
    refused(lambda: finish(_open(), value), InvalidInputError, "on_budget should be 'raise' or 'return'", came)


# ----------------------------------------------------------------------------- parameters
BAD_PARAMS = [
    ("str", "0.5", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("complex", 0.5j, InputTypeError, "complex"),
    ("list", [0.5], InputTypeError, "list"),
    ("array", np.array([0.5, 0.6]), InputTypeError, "ndarray"),
    ("nan", NAN, NonFiniteError, "nan"),
    ("inf", INF, NonFiniteError, "inf"),
    ("-inf", -INF, NonFiniteError, "-inf"),
    ("10**400", 10**400, NonFiniteError, "too large"),
    ("negative", -0.5, InvalidInputError, "parameter in [0, 1], not -0.5"),
    ("above one", 1.5, InvalidInputError, "parameter in [0, 1], not 1.5"),
    ("int above one", 2, InvalidInputError, "not 2.0"),
]
PARAMS = [(curve_direction, "t"), (one_place, "t"), (one_place, "u")]


@pytest.mark.parametrize(("fn", "param"), PARAMS, ids=[f"{f.__name__}-{p}" for f, p in PARAMS])
@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_PARAMS, ids=_ids(BAD_PARAMS))
def test_a_parameter_is_checked(fn, param, what, value, error, came) -> None:
    refused(lambda: call(fn, **{param: value}), error, param, came)


BAD_SIDES = [
    ("zero", 0, InvalidInputError, "not 0"),
    ("two", 2, InvalidInputError, "not 2"),
    ("minus two", np.int64(-2), InvalidInputError, "not -2"),
    ("float", 1.0, InputTypeError, "float"),
    ("bool", True, InputTypeError, "bool"),
    ("str", "1", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("nan", NAN, InputTypeError, "float"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_SIDES, ids=_ids(BAD_SIDES))
def test_curve_direction_side_is_checked(what, value, error, came) -> None:
    refused(lambda: curve_direction(A, 0.5, value), error, "side should be 1 or -1", came)


def test_one_place_needs_an_arc() -> None:
    refused(lambda: one_place(A, 0.3, 0.3, 1e-9), DegenerateCurveError, "t and u", "not both 0.3")
    refused(lambda: one_place(A, 0, 0.0, 1e-9), DegenerateCurveError, "t and u", "0.0")


# ----------------------------------------------------------------------------- pieces
BAD_POINTS = [
    ("str", "x", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("curve", A, InputTypeError, "RationalBezier"),
    ("numeric str", [["0", "0"], ["1", "1"]], InputTypeError, "str"),
    ("complex", [[0j, 0.0], [1.0, 1.0]], InputTypeError, "complex"),
    ("ragged", [[0.0, 0.0], [1.0]], InputTypeError, "ragged"),
    ("one point", [[0.0, 0.0]], ShapeError, "(1, 2)"),
    ("no point", np.zeros((0, 2)), ShapeError, "(0, 2)"),
    ("a vector", [0.0, 1.0], ShapeError, "(2,)"),
    ("space points", [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], ShapeError, "(2, 3)"),
    ("3d array", np.zeros((2, 2, 2)), ShapeError, "(2, 2, 2)"),
    ("nan", [[0.0, 0.0], [NAN, 1.0]], NonFiniteError, "nan"),
    ("inf", [[0.0, 0.0], [1.0, -INF]], NonFiniteError, "inf"),
    ("10**400", [[0, 0], [10**400, 1]], NonFiniteError, "integer"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_POINTS, ids=_ids(BAD_POINTS))
def test_along_chord_points_are_checked(what, value, error, came) -> None:
    refused(lambda: along_chord(value), error, "points", came)


BAD_SIMPLES = [
    ("str", "x", "simple should be a callable", "str"),
    ("None", None, "simple should be a callable", "NoneType"),
    ("bool", True, "simple should be a callable", "bool"),
    ("float", 1.0, "simple should be a callable", "float"),
    ("answers None", lambda p: None, "simple(control_points) should be True or False", "NoneType"),
    ("answers an int", lambda p: 1, "simple(control_points)", "int"),
    ("answers a str", lambda p: "yes", "simple(control_points)", "str"),
    ("answers an array", lambda p: np.ptp(p, axis=0) < 1.0, "simple(control_points)", "ndarray"),
]


@pytest.mark.parametrize(("what", "value", "words", "came"), BAD_SIMPLES, ids=_ids(BAD_SIMPLES))
def test_monotone_pieces_simple_is_checked(what, value, words, came) -> None:
    refused(lambda: call(monotone_pieces, simple=value), InputTypeError, words, came)


BAD_DEPTHS = [
    ("float", 10.0, InputTypeError, "float"),
    ("str", "10", InputTypeError, "str"),
    ("None", None, InputTypeError, "NoneType"),
    ("bool", True, InputTypeError, "bool"),
    ("nan", NAN, InputTypeError, "float"),
    ("negative", -1, DegreeError, "not -1"),
    ("too deep", 49, InvalidInputError, "from 0 to 48"),
    ("10**400", 10**400, InvalidInputError, "from 0 to 48"),
]


@pytest.mark.parametrize(("what", "value", "error", "came"), BAD_DEPTHS, ids=_ids(BAD_DEPTHS))
def test_monotone_pieces_max_depth_is_checked(what, value, error, came) -> None:
    refused(lambda: call(monotone_pieces, max_depth=value), error, "max_depth should be an int", came)


# ----------------------------------------------------------------------------- good input
def _same(x: Any, y: Any) -> bool:
    """The same results, bit for bit (reprs carry every digit; arrays compared exactly)."""
    if isinstance(x, np.ndarray):
        return bool(np.array_equal(x, y)) and x.dtype == y.dtype
    return repr(x) == repr(y)


PAIRS = [
    (A, B), (ARCH, LINE), (RationalBezier([[0, 0], [1, 1]]), RationalBezier([[0, 0], [0, 0], [1, 1], [1, 1]])),
    (LOOP, LOOP.reversed()), (S3, RationalBezier([[0, 1, 1], [2, 0, 1]])), (S3, S3.segment(0.25, 0.75)),
    (RationalBezier(A.control_points * 1e200), RationalBezier(B.control_points * 1e200)),  # scaled first
]


@pytest.mark.parametrize(("a", "b"), PAIRS)
def test_contacts_of_a_pair_answer_as_before(a: RationalBezier, b: RationalBezier) -> None:
    found = intersect(a, b)
    tol = found.tol_used
    for items in (found, list(found), tuple(found), []):
        assert needs_refining(a, b, items) == _needs_refining(a, b, items)
        assert _same(refine_contacts(a, b, items, tol), _refine_contacts(a, b, items, tol))
    assert _same(refine_contacts(a, b, found, np.float64(tol)), _refine_contacts(a, b, found, tol))
    assert _same(refine_contacts(a, b, found, ModelTolerance(tol)), _refine_contacts(a, b, found, tol))
    for other in (b, a.elevate(1), a.reversed()):
        assert _same(whole_overlap(a, other, tol), _whole_overlap(a, other, tol))


def test_contacts_answer_as_documented() -> None:
    line = RationalBezier([[0, 0], [1, 1]])
    cubic = RationalBezier([[0, 0], [0, 0], [1, 1], [1, 1]])
    assert refine_contacts(line, cubic, intersect(line, cubic), 1e-9) == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]
    assert not needs_refining(line, line, [Intersection(0.5, 0.5, line(0.5), "crossing")])
    assert needs_refining(ARCH, LINE, intersect(ARCH, LINE))  # a tangent contact
    assert whole_overlap(A, A.elevate(2), 1e-9) == Overlap(t=(0.0, 1.0), u=(0.0, 1.0))
    big = RationalBezier(A.control_points * 100)
    assert whole_overlap(big, big.reversed(), 1) == Overlap(t=(0.0, 1.0), u=(1.0, 0.0))  # an int tol
    assert whole_overlap(A, S3, 1e-9) is None  # curves of different dimensions never match


@pytest.mark.parametrize("c", [A, LOOP, S3, RationalBezier([[0, 0], [0, 0], [1, 0], [1, 1]])])
def test_curve_direction_answers_as_before(c: RationalBezier) -> None:
    for t in (0, 0.0, 0.25, np.float64(0.5), 0.75, 1, 1.0):
        for side in (1, -1, np.int64(1), np.int64(-1)):
            assert _same(curve_direction(c, t, side), _curve_direction(c, float(t), 1 if side == 1 else -1))
    cusped = RationalBezier([[0, 0], [0, 0], [1, 0], [1, 1]])
    assert curve_direction(cusped, 0.0).tolist() == [1.0, 0.0]
    assert curve_direction(cusped, 1.0, side=-1).tolist() == [0.0, -1.0]
    assert curve_direction(cusped, 0.0, side=-1).tolist() == [0.0, 0.0]  # off the curve: zeros


@pytest.mark.parametrize("c", [LOOP, RETRACE, A, RationalBezier([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]])])
def test_self_intersection_steps_answer_as_before(c: RationalBezier) -> None:
    found = intersect(c)
    for items in (found, list(found), tuple(found), RETRACE_ITEMS if c is RETRACE else []):
        for tol in (found.tol_used, 1e-6):
            assert _same(refine_self(c, items, tol), _refine_self(c, items, tol))
    parts = [(o, True) for o in found if isinstance(o, Overlap)]
    assert _same(self_overlaps(parts, c), _self_overlaps(parts, c))
    for simple in (_simple, lambda p: np.bool_(_simple(p))):
        for depth in (0, 10, np.int64(12), 48):
            assert _same(monotone_pieces(c, 1e-9, simple, depth), _monotone_pieces(c, 1e-9, _simple, int(depth)))


def test_self_steps_answer_as_documented() -> None:
    assert refine_self(RETRACE, RETRACE_ITEMS, 1e-9) == [Overlap(t=(0.0, 0.5), u=(1.0, 0.5))]
    merged = [Overlap(t=(0.0, 0.5), u=(1.0, 0.5))]
    assert self_overlaps(PARTS) == self_overlaps(PARTS, None) == merged
    assert self_overlaps([[o, np.bool_(f)] for o, f in PARTS]) == merged  # lists, numpy's bools
    assert self_overlaps(()) == self_overlaps([], LOOP) == []
    folded = RationalBezier([[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]])
    cuts = [(round(s0, 12), round(s1, 12)) for s0, s1, _ in monotone_pieces(folded, 1e-9, lambda p: False, 10)]
    assert cuts == [(0.0, 0.666666666667), (0.666666666667, 1.0)]


def test_pieces_answer_as_before() -> None:
    rng = np.random.default_rng(7)
    for _ in range(40):
        pts = rng.random((int(rng.integers(2, 7)), 2))
        assert along_chord(pts) == along_chord(pts.tolist()) == _along_chord(pts.tolist())
        c = RationalBezier(pts)
        t, u = (float(x) for x in rng.random(2))
        for tol in (1e-9, 0.1, 1.0):
            assert one_place(c, t, u, tol) == one_place(c, u, t, tol) == _one_place(c, t, u, tol)
    assert along_chord(ARCH_POINTS) and along_chord(tuple(map(tuple, ARCH_POINTS)))
    assert along_chord(np.array(ARCH_POINTS, dtype=np.int32))
    assert not along_chord([[0.0, 0.0], [3.0, 1.0], [-1.0, 1.0], [2.0, 0.0]])  # a loop
    assert along_chord((np.array(ARCH_POINTS) * 1e200).tolist()) is False  # overflow declines
    near_cusp = RationalBezier([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0000001], [2.0, 0.0]])
    assert one_place(near_cusp, 0.4999985, 0.5000015, 1e-9) and not one_place(near_cusp, 0.2, 0.8, 1e-9)
    assert one_place(A, 0, 1, 2) and one_place(A, np.float64(1.0), 0, 2.0)  # ints, numpy floats


def test_finish_answers_as_before() -> None:
    done = IntersectionList(ITEMS, (), 1e-9)
    for on_budget in ("raise", "return"):
        assert finish(done, on_budget) is done is _finish(done, on_budget)
    opened = _open()
    assert finish(opened, "return") is opened
    with pytest.raises(BudgetExceededError) as info:
        finish(opened, "raise")
    assert info.value.partial == ITEMS and info.value.unresolved == list(opened.unresolved)
    assert finish(intersect(A, B, budget=3, on_budget="return"), "return").unresolved


# ----------------------------------------------------------------------------- internal calls
PUBLIC = [(contacts, f.__name__) for f in GOOD if f.__module__ == contacts.__name__]
PUBLIC += [(pieces, f.__name__) for f in GOOD if f.__module__ == pieces.__name__] + [(results, "finish")]


def test_relief_cad_calls_the_private_functions(monkeypatch: pytest.MonkeyPatch) -> None:
    """The checks cost the intersectors nothing: their calls go to the unchecked ``_f``."""
    def trap(*args: Any, **kwargs: Any) -> Any:
        raise AssertionError("a public function was called from inside relief_cad")

    for module, name in PUBLIC:
        monkeypatch.setattr(module, name, trap)
        assert not hasattr(intersection, name) and not hasattr(space, name), name
    assert intersect(ARCH, LINE)[0].kind == "tangent"  # refine_contacts, finish
    assert intersect(LINE, RationalBezier([[0, 0.5], [0, 0.5], [2, 0.5], [2, 0.5]])) == [
        Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]  # whole_overlap
    assert len(intersect(LOOP)) == 1 and intersect(RETRACE) == [Overlap(t=(0.0, 0.5), u=(1.0, 0.5))]
    assert len(intersect_many([(ARCH, LINE), (A, B)], workers=1)[1]) == 2
    assert intersect_space(S3, S3.segment(0.25, 0.75)) == [Overlap(t=(0.25, 0.75), u=(0.0, 1.0))]
    assert math.isfinite(intersect(A, B, budget=3, on_budget="return").tol_used)

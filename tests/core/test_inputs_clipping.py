"""Bad input to the public functions of :mod:`relief_cad.clipping` gets a ReliefCadError that names it.

Each case gives one bad argument to a function whose other arguments are good, and asserts the
error class (a ReliefCadError that is also the matching built-in) and that the message names the
parameter. Before these checks, these inputs raised raw numpy errors, or gave NaN answers, or (an
index out of range given to ``batch_rows``) crashed the interpreter.
"""

from __future__ import annotations

import math
import subprocess
import sys
from collections.abc import Callable
from typing import Any

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect
from relief_cad.clipping import (
    batch_rows,
    clip_range,
    compute_fat_line,
    distance_coefficients,
    hull_range,
    intersect_packed,
)
from relief_cad.errors import (
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ReliefCadError,
    ShapeError,
    ToleranceError,
    ToleranceTypeError,
    WeightError,
)

NODES = np.array([[0.0, -1.0], [1.0, 2.0], [2.0, 1.0]])
LINE = (0.0, 1.0, 0.0, 0.0, 1.0)
PTS = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]])
OFFSETS = np.array([0, 2, 4])
PAIRS = np.array([[0, 1]])

BUILTIN = {InputTypeError: TypeError, ToleranceTypeError: TypeError}


def _fat(**kw: Any) -> object:
    return compute_fat_line(kw.get("nodes", NODES), perpendicular=kw.get("perpendicular", False))


def _coeffs(**kw: Any) -> object:
    return distance_coefficients(kw.get("nodes", NODES), kw.get("weights", None), kw.get("line", LINE),
                                 kw.get("tol", 0.0))


def _clip(**kw: Any) -> object:
    return clip_range(kw.get("nodes", NODES), kw.get("weights", None), kw.get("line", LINE), kw.get("tol", 0.0))


def _hull(**kw: Any) -> object:
    return hull_range(kw.get("coefficients", np.array([-1.0, 1.0])))


def _packed(**kw: Any) -> object:
    return intersect_packed(kw.get("points", PTS), kw.get("weights", np.ones(4)), kw.get("offsets", OFFSETS),
                            kw.get("pairs", PAIRS), kw.get("tol", None), kw.get("budget", 1000), workers=1)


def _batch(**kw: Any) -> object:
    return batch_rows(kw.get("points", PTS), kw.get("weights", np.ones(4)), kw.get("offsets", OFFSETS),
                      kw.get("pairs", PAIRS), kw.get("tols", np.full(1, 1e-9)), kw.get("budget", 1000),
                      workers=1)


NODE_CASES = [
    ("nodes", "abc", InputTypeError),
    ("nodes", [[True, False], [False, True]], InputTypeError),
    ("nodes", [[0.0, 0.0], [1.0, 2.0, 3.0]], InputTypeError),  # ragged
    ("nodes", np.array([[0.0, 0.0], [math.nan, 1.0]]), NonFiniteError),
    ("nodes", np.array([[0.0, 0.0], [math.inf, 1.0]]), NonFiniteError),
    ("nodes", np.zeros((1, 2)), ShapeError),
    ("nodes", np.zeros((3, 3)), ShapeError),
]
WEIGHT_CASES = [
    ("weights", "ab", InputTypeError),
    ("weights", [1.0, 2.0], ShapeError),
    ("weights", [1.0, -1.0, 1.0], WeightError),
    ("weights", [1.0, 0.0, 1.0], WeightError),
    ("weights", [1.0, math.nan, 1.0], NonFiniteError),
    ("weights", [1.0, 1e300, 1.0], WeightError),
]
LINE_CASES = [
    ("line", (1.0, 2.0), ShapeError),
    ("line", "abcde", InputTypeError),
    ("line", (0.0, 1.0, 0.0, math.nan, 1.0), NonFiniteError),
    ("tol", "x", ToleranceTypeError),
    ("tol", -1e-3, ToleranceError),
    ("tol", math.inf, ToleranceError),
    ("tol", None, ToleranceTypeError),
]
PACKED_CASES = [
    ("points", "x", InputTypeError),
    ("points", np.zeros((4, 3)), ShapeError),
    ("points", np.where(PTS == 2.0, math.nan, PTS), NonFiniteError),
    ("weights", np.ones(3), ShapeError),
    ("weights", np.array([1.0, -1.0, 1.0, 1.0]), WeightError),
    ("weights", np.array([1.0, 1e300, 1.0, 1.0]), WeightError),  # one curve's ratio above 1e15
    ("offsets", np.array([0.0, 2.0, 4.0]), InputTypeError),  # not truncated to ints
    ("offsets", np.array([0.5, 2.0, 4.0]), InputTypeError),
    ("offsets", np.array([0, 1, 4]), ShapeError),  # a curve of one point
    ("offsets", np.array([0, 2, 5]), ShapeError),  # past the points
    ("offsets", "ab", InputTypeError),
    ("pairs", np.array([[0.7, 1.0]]), InputTypeError),
    ("pairs", np.array([[0, 2]]), ShapeError),  # curve 2 is not there
    ("pairs", np.array([[-1, 1]]), ShapeError),
    ("pairs", np.array([0, 1]), ShapeError),
    ("pairs", "ab", InputTypeError),
    ("budget", "x", InputTypeError),
    ("budget", 2.5, InputTypeError),
    ("budget", True, InputTypeError),
    ("budget", 0, InvalidInputError),
]

CASES: list[tuple[Callable[..., object], str, object, type[Exception]]] = [
    *[(_fat, p, v, e) for p, v, e in NODE_CASES],
    (_fat, "perpendicular", "yes", InputTypeError),
    (_fat, "perpendicular", 1, InputTypeError),
    *[(f, p, v, e) for f in (_coeffs, _clip) for p, v, e in NODE_CASES + WEIGHT_CASES + LINE_CASES],
    (_hull, "coefficients", ["a", "b"], InputTypeError),
    (_hull, "coefficients", [math.nan, 1.0], NonFiniteError),
    (_hull, "coefficients", [1.0], ShapeError),
    (_hull, "coefficients", [[1.0, 2.0]], ShapeError),
    *[(f, p, v, e) for f in (_packed, _batch) for p, v, e in PACKED_CASES],
    (_packed, "tol", "a", ToleranceTypeError),
    (_packed, "tol", -1.0, ToleranceError),
    (_batch, "tols", np.full(2, 1e-9), ShapeError),
    (_batch, "tols", np.array([math.nan]), ToleranceError),
    (_batch, "tols", np.array([0.0]), ToleranceError),
    (_batch, "tols", lambda lo, hi: np.full(hi - lo + 1, 1e-9), ShapeError),  # a chunk's answer
    (_batch, "tols", lambda lo, hi: np.full(hi - lo, -1.0), ToleranceError),
]


@pytest.mark.parametrize(("fn", "param", "value", "error"), CASES,
                         ids=[f"{c[0].__name__[1:]}-{c[1]}-{i}" for i, c in enumerate(CASES)])
def test_bad_input_gets_a_relief_cad_error_naming_it(fn: Callable[..., object], param: str, value: object,
                                                     error: type[Exception]) -> None:
    with pytest.raises(error) as info:
        fn(**{param: value})
    assert type(info.value) is error
    assert isinstance(info.value, ReliefCadError)
    assert isinstance(info.value, BUILTIN.get(error, ValueError))
    assert param in str(info.value) or (param == "pairs" and "curves" in str(info.value))


def test_good_input_still_gives_the_same_clipping() -> None:
    """The checks change no answer: the pair's rows are those of intersect, the primitives as before."""
    a = RationalBezier(PTS[:2])
    b = RationalBezier(PTS[2:])
    expected = intersect(a, b)
    for rows in (_packed(), _batch(), _packed(pairs=[[0, 1]], offsets=[0, 2, 4], points=PTS.tolist())):
        assert rows.shape == (1, 9)  # type: ignore[attr-defined]
        assert rows[0, 2] == expected[0].t and rows[0, 3] == expected[0].u  # type: ignore[index]
    assert _packed(pairs=np.empty((0, 2), dtype=np.int64)).shape == (0, 9)  # type: ignore[attr-defined]
    assert _packed(pairs=[]).shape == (0, 9)  # type: ignore[attr-defined]
    assert compute_fat_line(NODES, perpendicular=np.bool_(True)) == compute_fat_line(NODES, perpendicular=True)
    lower, upper = distance_coefficients(NODES, None, LINE, 0.5)
    assert lower.tolist() == [-0.5, 2.5, 1.5] and upper.tolist() == [2.5, -0.5, 0.5]
    assert clip_range(NODES, [1.0, 1.0, 1.0], LINE, 0) == clip_range(NODES, None, LINE)
    assert hull_range([-1, 1]) == (0.5, 1.0)  # integers are numbers


def test_packed_inputs_are_left_as_the_caller_gave_them() -> None:
    pts = PTS.copy()
    w = np.ones(4)
    intersect_packed(pts, w, OFFSETS, PAIRS, workers=1)
    assert pts.flags.writeable and w.flags.writeable and np.array_equal(pts, PTS)


_OUT_OF_RANGE = """
import numpy as np
from relief_cad.clipping import batch_rows
from relief_cad.errors import ShapeError
pts = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]])
for pairs in ([[0, 5000000]], [[0, 2]], [[3, 0]]):
    try:
        batch_rows(pts, np.ones(4), np.array([0, 2, 4]), np.array(pairs), np.full(1, 1e-9), 1000)
    except ShapeError:
        print("refused")
"""


def test_an_index_out_of_range_is_refused_not_read() -> None:
    """The batch kernel does no bounds checks: an index past the curves crashed the interpreter."""
    out = subprocess.run([sys.executable, "-c", _OUT_OF_RANGE], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr[-2000:]
    assert out.stdout.split() == ["refused"] * 3

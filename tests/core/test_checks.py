"""One input check: planar and space curves get the same error for the same bad argument."""

from __future__ import annotations

import pytest

from relief_cad import RationalBezier, intersect
from relief_cad.errors import InputTypeError, InvalidInputError, ToleranceError, ToleranceTypeError

PLANAR = (RationalBezier([[0, 0], [2, 2]]), RationalBezier([[0, 2], [2, 0]]))
SPACE = (RationalBezier([[0, 0, 0], [2, 2, 2]]), RationalBezier([[0, 2, 1], [2, 0, 1]]))


@pytest.mark.parametrize("pair", [PLANAR, SPACE], ids=["planar", "space"])
@pytest.mark.parametrize(
    ("tol", "error"),
    [
        (True, ToleranceTypeError),
        ("abc", ToleranceTypeError),
        ("1e-3", ToleranceTypeError),
        ([1e-6], ToleranceTypeError),
        (1j, ToleranceTypeError),
        (0, ToleranceError),
        (-1e-9, ToleranceError),
        (float("nan"), ToleranceError),
        (float("inf"), ToleranceError),
        (10**400, ToleranceError),
    ],
)
def test_tol_errors_are_the_same_for_planar_and_space(pair: tuple[RationalBezier, RationalBezier],
                                                      tol: object, error: type[Exception]) -> None:
    with pytest.raises(error) as info:
        intersect(*pair, tol=tol)  # type: ignore[arg-type]
    assert "tol should be" in str(info.value)
    if error is ToleranceTypeError:
        assert isinstance(info.value, TypeError) and isinstance(info.value, ToleranceError)


@pytest.mark.parametrize("pair", [PLANAR, SPACE], ids=["planar", "space"])
@pytest.mark.parametrize(
    ("budget", "error"),
    [(0, InvalidInputError), (-5, InvalidInputError), (10**30, InvalidInputError),
     (2.5, InputTypeError), ("7", InputTypeError), (True, InputTypeError)],
)
def test_budget_errors_are_the_same_for_planar_and_space(pair: tuple[RationalBezier, RationalBezier],
                                                         budget: object, error: type[Exception]) -> None:
    with pytest.raises(error, match="budget should be an int from 1 to 2\\*\\*62"):
        intersect(*pair, budget=budget)  # type: ignore[arg-type]


@pytest.mark.parametrize("pair", [PLANAR, SPACE], ids=["planar", "space"])
@pytest.mark.parametrize("on_budget", ["ignore", None, 1])
def test_on_budget_errors_are_the_same_for_planar_and_space(pair: tuple[RationalBezier, RationalBezier],
                                                            on_budget: object) -> None:
    with pytest.raises(InvalidInputError, match="on_budget should be 'raise' or 'return'"):
        intersect(*pair, on_budget=on_budget)  # type: ignore[arg-type]


@pytest.mark.parametrize("pair", [PLANAR, SPACE], ids=["planar", "space"])
def test_good_arguments_give_the_crossing(pair: tuple[RationalBezier, RationalBezier]) -> None:
    result = intersect(*pair, tol=1e-9, budget=10_000, on_budget="return")
    assert [(r.t, r.u) for r in result.points] == [(0.5, 0.5)]

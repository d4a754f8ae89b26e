"""The CAD layer's tolerance rules (issues 15 and 16), on real build123d / OCP edges.

- one tolerance for the whole model, raised to the rounding floor: two lines of size 1e10 that
  cross give their vertex with the default (OCCT's 1e-7 is below their rounding, about 1e-6);
- ``intersections(...).tol_used`` bounds every reported distance;
- a tolerance above 1e-2 of the edges' joint size is refused by every public function
  (``intersect``, ``split``, ``intersections``, ``occt_intersections``, ``compare``) with one error;
- a sliver edge smaller than the model's tolerance is not refused (the cap is per model).
"""

from __future__ import annotations

import math

import build123d as bd
import pytest

from relief_cad.cad import api, compare, intersect, intersections, occt_intersections, split
from relief_cad.errors import ToleranceError
from relief_cad.tolerances import MAX_TOLERANCE_FRACTION, rounding_floor

A = bd.Line((0, 0, 0), (2, 2, 0))
B = bd.Line((0, 2, 0), (2, 0, 0))
SIZE = math.hypot(2, 2)  # the joint box of A and B: 2 x 2 (and OCCT's box adds its tiny gap)

PUBLIC = {
    "intersect": intersect,
    "split": split,
    "intersections": intersections,
    "occt_intersections": occt_intersections,
    "compare": compare,
}


@pytest.mark.parametrize("name", sorted(PUBLIC))
@pytest.mark.parametrize("tol", [1e300, 0.05 * SIZE])
def test_a_tolerance_beyond_the_cap_is_refused_everywhere(name: str, tol: float) -> None:
    for a, b in ((A, B), (B, A)):
        with pytest.raises(ToleranceError, match=r"at most 0\.01 of the inputs' size") as info:
            PUBLIC[name](a, b, tol=tol)
        assert isinstance(info.value, ValueError) and repr(tol) in str(info.value)


def test_below_the_cap_both_orders_agree() -> None:
    tol = 0.9 * MAX_TOLERANCE_FRACTION * SIZE
    ab, ba = intersections(A, B, tol=tol), intersections(B, A, tol=tol)
    assert [(round(r.t, 12), round(r.u, 12)) for r in ab] == [(round(r.u, 12), round(r.t, 12)) for r in ba]
    assert ab.tol_used == ba.tol_used == tol
    assert len(intersect(A, B, tol=tol)) == len(intersect(B, A, tol=tol)) == 1


def test_huge_lines_cross_with_the_default_tolerance() -> None:
    s = 1e10
    a = bd.Line((0, 0, 0), (2 * s, 2 * s, 0))
    b = bd.Line((0, 2 * s, 0), (2 * s, 0, 0))
    res = intersections(a, b)
    assert len(res) == 1 and res[0].kind == "crossing"
    assert math.dist(res[0].point, (s, s, 0.0)) <= res.tol_used
    assert res.tol_used >= rounding_floor(api.segments(a)[0].curve) > 1e-7  # the OCCT default, raised
    assert len(intersect(a, b)) == 1
    assert len(compare(a, b).agreed) == 1


def test_tol_used_bounds_the_distances_and_tiny_tolerances_are_raised() -> None:
    near = bd.Line((0, 1e-9, 0), (2, 1e-9, 0))  # 1e-9 above the x axis
    axis = bd.Line((1, -1, 0), (1, 1, 0))
    for tol in (1e-300, 1e-12, 1e-7, None):
        res = intersections(near, axis, tol=tol)
        assert math.isfinite(res.tol_used) and (tol is None or res.tol_used >= tol)
        assert len(res) == 1 and all(r.distance <= res.tol_used for r in res)


def test_sliver_edges_below_the_model_tolerance_are_accepted() -> None:
    """Two 1e-6 crossing slivers in a model of size 4: tol 1e-5 is 10 times their size, but tiny
    against the model; the cap applies to the model, once, not to each segment pair."""
    sliver = bd.Line((1, 0.5, 0), (1 + 1e-6, 0.5, 0))
    other = bd.Line((1 + 5e-7, 0.5 - 5e-7, 0), (1 + 5e-7, 0.5 + 5e-7, 0))
    far = bd.Line((0, 3, 0), (4, 3, 0))
    res = intersections([sliver, far], [other, far], tol=1e-5)
    assert res.tol_used == 1e-5
    hits = [r for r in res if r.index_a == 0 and r.index_b == 0]
    assert hits and all(r.distance <= 1e-5 for r in hits if hasattr(r, "distance"))
    with pytest.raises(ToleranceError):  # the same slivers alone: 1e-5 is beyond their size
        intersections(sliver, other, tol=1e-5)

"""Hazmat clipping functions: fat lines, distance coefficients, hull ranges, clip ranges."""

from __future__ import annotations

import numpy as np
import pytest

from relief_cad.clipping import clip_range, compute_fat_line, distance_coefficients, hull_range
from relief_cad.curves import RationalBezier
from relief_cad.errors import InvalidInputError, ShapeError
from relief_cad.intersection import intersect_many


def _dist(line: tuple[float, float, float, float, float], pts: np.ndarray) -> np.ndarray:
    nx, ny, c, _lo, _hi = line
    return pts @ np.array([nx, ny]) + c


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("perpendicular", [False, True])
def test_fat_line_contains_the_curve(seed: int, perpendicular: bool) -> None:
    rng = np.random.default_rng(seed)
    n = 1 + seed % 5
    curve = RationalBezier(rng.normal(size=(n + 1, 2)), rng.uniform(0.1, 5.0, n + 1))
    line = compute_fat_line(curve.control_points, perpendicular=perpendicular)
    assert line[0] ** 2 + line[1] ** 2 == pytest.approx(1.0)
    d = _dist(line, curve.evaluate(np.linspace(0, 1, 201)))
    assert d.min() >= line[3] - 1e-12 and d.max() <= line[4] + 1e-12


@pytest.mark.parametrize("scale", [1e-200, 1e-160, 1e-150, 1e-5, 1.0, 1e5, 1e150, 1e160, 1e200])
def test_fat_line_normal_is_a_unit_vector_at_every_scale(scale: float) -> None:
    # the chord's length is sqrt(x² + y²) where the squares neither over- nor underflow, hypot
    # elsewhere: a unit normal within an ulp or two at every size of chord
    rng = np.random.default_rng(int(np.log10(scale)) + 300)
    for _ in range(50):
        pts = scale * rng.normal(size=(4, 2))
        nx, ny, c, dmin, dmax = compute_fat_line(pts)
        assert abs(np.hypot(nx, ny) - 1.0) <= 4e-16
        chord = pts[-1] - pts[0]
        assert abs(nx * chord[0] + ny * chord[1]) <= 1e-15 * np.hypot(*chord)
        d = _dist((nx, ny, c, dmin, dmax), pts)
        assert d.min() >= dmin - 1e-14 * scale and d.max() <= dmax + 1e-14 * scale


@pytest.mark.parametrize("nodes", [
    [[1.0, 1.0], [1.0, 1.0], [1.0, 1.0]],              # point-like
    [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [0.0, 0.0]],  # closed
    [[0.0, 0.0], [0.0, 0.0], [3.0, 1.0]],              # repeated start
])
def test_degenerate_fat_lines_are_defined(nodes: list[list[float]]) -> None:
    pts = np.array(nodes)
    line = compute_fat_line(pts)
    assert all(np.isfinite(line))
    d = _dist(line, pts)
    assert d.min() >= line[3] - 1e-15 and d.max() <= line[4] + 1e-15


def test_distance_coefficients_by_hand() -> None:
    lower, upper = distance_coefficients(np.array([[0.0, 3.0], [1.0, -1.0], [2.0, 3.0]]),
                                         np.array([1.0, 2.0, 1.0]), (0.0, 1.0, 0.0, 0.0, 1.0), tol=0.5)
    assert lower.tolist() == [3.5, -1.0, 3.5]
    assert upper.tolist() == [-1.5, 5.0, -1.5]


@pytest.mark.parametrize("coeffs,expected", [
    ([-1.0, 1.0], (0.5, 1.0)),
    ([1.0, -1.0], (0.0, 0.5)),
    ([-1.0, 3.0, -1.0], (0.125, 0.875)),
    ([2.0, 2.0], (0.0, 1.0)),
])
def test_hull_range_by_hand(coeffs: list[float], expected: tuple[float, float]) -> None:
    assert hull_range(np.array(coeffs)) == pytest.approx(expected)


def test_hull_range_empty() -> None:
    lo, hi = hull_range(np.array([-1.0, -0.5, -2.0]))
    assert lo > hi


@pytest.mark.parametrize("seed", range(10))
def test_clip_range_keeps_every_point_inside_the_strip(seed: int) -> None:
    rng = np.random.default_rng(100 + seed)
    a = RationalBezier(rng.random((4, 2)))
    b = RationalBezier(rng.random((4, 2)), rng.uniform(0.2, 3.0, 4))
    line = compute_fat_line(a.control_points)
    lo, hi = clip_range(b.control_points, b.weights, line, tol=1e-3)
    s = np.linspace(0, 1, 2001)
    d = _dist(line, b.evaluate(s))
    inside = s[(d >= line[3] - 1e-3) & (d <= line[4] + 1e-3)]
    if lo > hi:
        assert inside.size == 0
    else:
        assert inside.size == 0 or (inside.min() >= lo - 1e-12 and inside.max() <= hi + 1e-12)


def test_shape_errors() -> None:
    with pytest.raises(ShapeError):
        compute_fat_line(np.zeros((3, 3)))
    with pytest.raises(ShapeError):
        hull_range(np.zeros(1))
    with pytest.raises(ShapeError):
        clip_range(np.zeros((3, 2)), np.ones(2), (0.0, 1.0, 0.0, 0.0, 1.0))


def test_intersect_packed_matches_intersect() -> None:
    from relief_cad.clipping import intersect_packed
    from relief_cad.intersection import intersect

    rng = np.random.default_rng(5)
    curves = [RationalBezier(rng.random((4, 2))) for _ in range(20)]
    pts = np.concatenate([c.control_points for c in curves])
    offsets = np.arange(0, 4 * 21, 4)
    pairs = np.array([[i, i + 1] for i in range(19)])
    rows = intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs)
    assert pts.flags.writeable
    for k, (i, j) in enumerate(pairs):
        mine = sorted((r[2], r[3]) for r in rows if r[0] == k)
        ref = [(x.t, x.u) for x in intersect(curves[i], curves[j])]
        assert mine == ref


def _wavy_pairs(n: int) -> list[tuple[RationalBezier, RationalBezier]]:
    """``n`` pairs of the graph of the Chebyshev polynomial T_7(2x - 1) and a line across it: 7 crossings each."""
    t7 = [-1.0, 13.0, -47.666666666666664, 85.8, -85.8, 47.666666666666664, -13.0, 1.0]  # Bernstein ordinates
    xs = np.linspace(0.0, 1.0, 8)
    return [(RationalBezier(np.column_stack([xs, t7])), RationalBezier([[0.0, 0.01 * k], [1.0, 0.02 * k]]))
            for k in range(n)]


def test_intersect_packed_keeps_the_rows_of_earlier_pairs_when_the_output_grows() -> None:
    # 9 pairs of 7 crossings: 63 rows, more than the 18 the batch kernel starts with. When pair k's
    # rows did not fit, the rows grew and pair k ran again, but from row 0: the rows of the pairs
    # before it in the same call were overwritten (the CAD layer lost 10 of 13 crossings of a spline
    # through 9 points of a circle)
    from relief_cad.clipping import intersect_packed
    from relief_cad.intersection import intersect

    pairs = _wavy_pairs(9)
    curves = [c for pr in pairs for c in pr]
    pts = np.concatenate([c.control_points for c in curves])
    offsets = np.cumsum([0] + [len(c.control_points) for c in curves])
    rows = intersect_packed(pts, np.ones(pts.shape[0]), offsets, np.arange(18).reshape(9, 2), workers=1)
    assert rows.shape[0] == 63
    for k, (a, b) in enumerate(pairs):
        mine = [(r[2], r[3]) for r in rows if r[0] == k]
        assert mine == [(x.t, x.u) for x in intersect(a, b)]
    for k, listed in enumerate(intersect_many(pairs, workers=1)):
        assert [(x.t, x.u, x.kind) for x in listed] == [(x.t, x.u, x.kind) for x in intersect(*pairs[k])]


def test_intersect_packed_rows_are_the_same_on_any_number_of_threads() -> None:
    from relief_cad.clipping import intersect_packed

    rng = np.random.default_rng(11)
    pts = rng.random((4 * 300, 2))
    offsets = np.arange(0, 4 * 301, 4)
    pairs = rng.integers(0, 300, (2000, 2))  # enough for several chunks of pairs
    one = intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, workers=1)
    assert one.shape[0] > 1000 and set(one[:, 0].astype(int)) <= set(range(2000))
    assert np.all(np.diff(one[:, 0]) >= 0)  # grouped by pair, in pair order
    for workers in (2, 3, 8):
        assert np.array_equal(intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, workers=workers), one)
    given = intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, 1e-6, workers=1)
    assert given.shape[0] >= one.shape[0]  # a wider tolerance finds as much, or more
    assert np.array_equal(intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, 1e-6, workers=2), given)
    with pytest.raises(InvalidInputError):
        intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, workers=0)


def test_batch_rows_computes_each_chunks_tolerances_on_its_own_thread() -> None:
    # the default tolerances of a batch took a fifth of its time on one thread, before the chunks
    # ran: computed per chunk, on the chunk's thread, they run at once on two cores
    import threading

    from relief_cad.clipping import batch_rows

    rng = np.random.default_rng(12)
    pts = rng.random((4 * 100, 2))
    pts.flags.writeable = False
    w = np.ones(pts.shape[0])
    w.flags.writeable = False
    offsets = np.arange(0, 4 * 101, 4)
    pairs = rng.integers(0, 100, (1000, 2))
    calls: list[tuple[int, int, str]] = []

    def tols(lo: int, hi: int) -> np.ndarray:
        calls.append((lo, hi, threading.current_thread().name))
        return np.full(hi - lo, 1e-9)

    rows = batch_rows(pts, w, offsets, pairs, tols, 1000, workers=2)
    assert sorted(c[:2] for c in calls) == [(0, 500), (500, 1000)]
    assert all(name.startswith("relief_cad-pool") for _, _, name in calls)
    assert np.array_equal(rows, batch_rows(pts, w, offsets, pairs, np.full(1000, 1e-9), 1000, workers=1))


def test_intersect_packed_rejects_bad_offsets() -> None:
    from relief_cad.clipping import intersect_packed

    with pytest.raises(ShapeError):
        intersect_packed(np.zeros((4, 2)), np.ones(4), np.array([0, 1, 4]), np.array([[0, 1]]))


def test_intersect_packed_rows_of_a_pair_come_by_t_then_boxes() -> None:
    """The order the result lists take without sorting: points and overlaps by ``t``, boxes last."""
    from relief_cad._kernels import KIND_UNRESOLVED
    from relief_cad.clipping import intersect_packed

    rng = np.random.default_rng(29)
    curves = [RationalBezier(rng.random((int(rng.integers(3, 9)), 2)) * 4.0) for _ in range(120)]
    pts = np.concatenate([c.control_points for c in curves])
    offsets = np.concatenate([[0], np.cumsum([c.control_points.shape[0] for c in curves])])
    pairs = rng.integers(0, 120, (600, 2))
    for budget, boxes_expected in ((100_000, False), (6, True)):
        rows = intersect_packed(pts, np.ones(pts.shape[0]), offsets, pairs, budget=budget)
        boxes = 0
        several = 0
        for k in np.unique(rows[:, 0]):
            mine = rows[rows[:, 0] == k]
            is_box = mine[:, 1] == KIND_UNRESOLVED
            assert not np.any(is_box[:-1] & ~is_box[1:])  # no point after a box
            ts = mine[~is_box, 2]
            assert np.all(np.diff(ts) >= 0.0)
            boxes += int(is_box.sum())
            several += int(ts.size > 1)
        assert (boxes > 0) == boxes_expected and (several > 20 or boxes_expected)


_HYPOT_LE_CHECK = """
import math, random
from relief_cad._kernels.planar import _hypot_le
random.seed(7)
cases = [(3.0, 4.0, 5.0), (3.0, 4.0, math.nextafter(5.0, 0.0)), (0.0, 0.0, 0.0), (-0.0, 0.0, 1e-300),
         (math.nan, 1.0, 2.0), (math.inf, 1.0, 1e300), (1e-160, 1e-160, 1e-150), (1e-200, 0.0, 1e-139),
         (1e200, 1e200, 1e139), (2.0, 2.0, math.hypot(2.0, 2.0))]
for _ in range(200000):
    e = 10.0 ** random.uniform(-300, 300)
    dx, dy = (e * random.uniform(-1.0, 1.0) * 10.0 ** random.uniform(-3, 1) for _ in range(2))
    cases.append((dx, dy, e))
    h = math.hypot(dx, dy)  # and e at an ulp or two around the root: the band where q cannot decide
    cases += [(dx, dy, h), (dx, dy, math.nextafter(h, 0.0)), (dx, dy, math.nextafter(h, math.inf))]
bad = [c for c in cases if _hypot_le(*c) != (math.hypot(c[0], c[1]) <= c[2])]
print(len(cases), bad[:5])
raise SystemExit(1 if bad else 0)
"""


def test_hypot_le_decides_as_hypot() -> None:
    """The pair driver's size test ``hypot(dx, dy) <= e`` decided from the squares gives hypot's answer.

    Run on the uncompiled kernels (the helper is a C function once compiled), in a subprocess.
    """
    import os
    import subprocess
    import sys

    out = subprocess.run([sys.executable, "-c", _HYPOT_LE_CHECK], env=dict(os.environ, RELIEF_CAD_PURE="1"),
                         capture_output=True, text=True, timeout=600, check=False)
    assert out.returncode == 0, out.stdout[-2000:] + out.stderr[-2000:]


def _random_rational(rng: np.random.Generator) -> RationalBezier:
    n = int(rng.integers(2, 8))
    return RationalBezier(rng.random((n, 2)), 10.0 ** rng.uniform(-1.5, 1.5, n))


def test_a_chord_of_a_curve_lies_in_its_tangent_cone() -> None:
    # the cone of a rational curve's control polygon legs holds every chord of the curve (a chord is
    # an integral of the derivative), at any weights: a line along a chord is never apart from it
    from relief_cad._kernels.clip import cones_apart

    rng = np.random.default_rng(21)
    for _ in range(400):
        a = _random_rational(rng)
        s0, s1 = sorted(rng.uniform(0.0, 1.0, 2))
        piece = a.segment(s0, s0 + (s1 - s0) * 10.0 ** rng.uniform(-4, 0))
        t1, t2 = sorted(rng.uniform(0.0, 1.0, 2))
        chord = np.array([piece.evaluate(t1), piece.evaluate(t2)])
        rounding = 1e-13 * np.abs(piece.control_points).max()  # of the evaluated ends, generously
        assert not cones_apart(piece.control_points, chord, 0.0, rounding)
        assert not cones_apart(chord, piece.control_points, rounding, 0.0)


def test_curves_whose_tangent_cones_are_apart_meet_at_most_once() -> None:
    from relief_cad._kernels.clip import cones_apart
    from relief_cad.intersection import intersect

    rng = np.random.default_rng(22)
    apart = 0
    for _ in range(400):
        a = _random_rational(rng)
        t = rng.uniform(0.2, 0.8)
        piece = a.segment(t - 0.1, t + 0.1)
        centre = piece.evaluate(0.5)
        turn = rng.uniform(0.01, 1.5)
        rot = np.array([[np.cos(turn), np.sin(turn)], [-np.sin(turn), np.cos(turn)]])
        other = RationalBezier((piece.control_points - centre) @ rot + centre + rng.normal(0, 0.01, 2),
                               piece.weights[::-1].copy())
        if cones_apart(piece.control_points, other.control_points):
            apart += 1
            assert len(intersect(piece, other)) <= 1
    assert apart > 100  # the test sees many pairs whose cones are apart

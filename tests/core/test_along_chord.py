"""relief_cad.pieces.along_chord: a cheap sufficient test that a planar curve cannot cross itself.

The CAD layer skips the self-intersection of every span it passes, and the core's test of a simple
piece takes its answer first, so a wrong True would lose a self-crossing. Oracles, none of them
relief_cad's: the angles of the chords (a curve whose chords all lie in one open half-plane is
monotone along a direction), and the rational curve itself, sampled by Bernstein sums, whose
projection on the end-to-end chord must then rise all along.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect
from relief_cad.pieces import along_chord


def _widest_gap(points: np.ndarray) -> float:
    """The widest angular gap between the directions of the nonzero chords (2 pi when none)."""
    angles = sorted(math.atan2(q[1] - p[1], q[0] - p[0])
                    for i, p in enumerate(points) for q in points[i + 1:] if (q != p).any())
    if not angles:
        return 2 * math.pi
    gaps = [b - a for a, b in zip(angles, angles[1:])] + [angles[0] + 2 * math.pi - angles[-1]]
    return max(gaps)


def _samples(points: np.ndarray, weights: np.ndarray, n: int = 801) -> np.ndarray:
    """The rational curve at ``n`` uniform parameters, by Bernstein sums (rows)."""
    deg = points.shape[0] - 1
    t = np.linspace(0.0, 1.0, n)[:, None]
    basis = np.hstack([math.comb(deg, i) * t**i * (1 - t) ** (deg - i) for i in range(deg + 1)]) * weights
    return (basis @ points) / basis.sum(axis=1, keepdims=True)


def _polygon(rng: np.random.Generator, arch: bool) -> np.ndarray:
    """Random control points: an arch-like polygon running mostly one way, or any polygon."""
    m = int(rng.integers(2, 9))
    scale = 10.0 ** rng.uniform(-6, 6)
    if arch:
        steps = np.column_stack([rng.uniform(0.0, 1.0, m - 1), rng.uniform(-1.2, 1.2, m - 1)])
        pts = np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)])
        if rng.random() < 0.2:  # a repeated control point: a chord of length zero
            k = int(rng.integers(0, m))
            pts = np.insert(pts, k, pts[k], axis=0)
        turn = rng.uniform(0, 2 * math.pi)
        rot = np.array([[math.cos(turn), -math.sin(turn)], [math.sin(turn), math.cos(turn)]])
        pts = pts @ rot.T
    else:
        pts = rng.uniform(-1.0, 1.0, (m, 2))
    return pts * scale + rng.uniform(-1, 1, 2) * scale


@pytest.mark.parametrize("seed", range(4))
def test_along_means_chords_in_a_half_plane_and_a_curve_running_one_way(seed: int) -> None:
    rng = np.random.default_rng(seed)
    verdicts = []
    for k in range(600):
        pts = _polygon(rng, arch=k % 2 == 0)
        along = along_chord(pts.tolist())
        verdicts.append(along)
        if not along:
            continue
        assert _widest_gap(pts) > math.pi + 1e-12, pts.tolist()
        weights = rng.uniform(0.2, 5.0, pts.shape[0])
        chord = pts[-1] - pts[0]
        rise = np.diff(_samples(pts, weights) @ chord)
        size = float(np.abs(pts).max()) * float(np.hypot(*chord))
        assert rise.min() > -1e-12 * size, (pts.tolist(), weights.tolist())
    # both answers come up often: the checks above are not vacuous, nor is the test refusing all
    assert 100 < sum(verdicts) < 500


def test_a_loop_is_not_along_and_its_crossing_is_found() -> None:
    loop = [[0.0, 0.0], [3.0, 1.0], [-1.0, 1.0], [2.0, 0.0]]
    assert not along_chord(loop)
    res = intersect(RationalBezier(loop))
    assert len(res) == 1 and res[0].kind == "crossing" and res[0].t < res[0].u
    c = RationalBezier(loop)
    assert np.allclose(c.evaluate(res[0].t), c.evaluate(res[0].u), atol=1e-12)


@pytest.mark.parametrize(
    "points",
    [
        [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [0.0, 0.0]],  # closed: no chord to run along
        [[0.0, 0.0], [0.0, 0.0]],  # a point
        [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]],  # straight, folding back at t = 2/3
        [[0.0, 0.0], [1.0, 5.0], [2.0, -5.0], [1.5, 0.0], [3.0, 0.0]],  # a chord turned 90 degrees and more
        [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]],  # a leg at exactly 90 degrees: no margin
    ],
)
def test_not_along(points: list[list[float]]) -> None:
    assert not along_chord(points)


def test_repeated_control_points_are_left_out() -> None:
    assert along_chord([[0.0, 0.0], [0.0, 0.0], [1.0, 0.5], [2.0, 0.0], [2.0, 0.0]])


@pytest.mark.parametrize("scale", [1e-200, 1e200])
def test_extreme_scales_answer_no_rather_than_a_wrong_yes(scale: float) -> None:
    """Products that under- or overflow make the test decline (the core's own test decides)."""
    arch = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]]) * scale
    assert along_chord(arch.tolist()) is False
    assert along_chord((arch / scale).tolist()) is True

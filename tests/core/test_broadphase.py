"""relief_cad.broadphase: grid pairs against all-pairs testing, point clusters against brute force."""

from __future__ import annotations

import numpy as np
import pytest

from relief_cad.broadphase import box_pairs, box_pairs_between, cluster_points
from relief_cad.errors import InvalidInputError, ReliefCadError, ShapeError, ToleranceError


def brute_pairs(lo, hi, pad):
    n = len(lo)
    return [[i, j] for i in range(n) for j in range(i + 1, n)
            if np.all((lo[i] - pad <= hi[j]) & (lo[j] <= hi[i] + pad))]


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("dim", [1, 2, 3])
def test_box_pairs_equal_all_pairs(seed, dim):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(0, 120))
    lo = rng.random((n, dim)) * 10
    hi = lo + rng.random((n, dim)) * rng.choice([0.0, 1.0, 3.0])
    pad = float(rng.choice([0.0, 0.05, 0.5]))
    assert box_pairs(lo, hi, pad=pad).tolist() == brute_pairs(lo, hi, pad)


@pytest.mark.parametrize("seed", range(6))
def test_box_pairs_between_equal_all_pairs(seed):
    rng = np.random.default_rng(100 + seed)
    lo_a = rng.random((int(rng.integers(1, 80)), 3)) * 10
    hi_a = lo_a + rng.random(lo_a.shape)
    lo_b = rng.random((int(rng.integers(1, 80)), 3)) * 10
    k = min(3, len(lo_a), len(lo_b))
    lo_b[:k] = lo_a[:k]  # equal corners: each pair found once
    hi_b = lo_b + rng.random(lo_b.shape)
    want = [[i, j] for i in range(len(lo_a)) for j in range(len(lo_b))
            if np.all((lo_a[i] - 0.1 <= hi_b[j]) & (lo_b[j] <= hi_a[i] + 0.1))]
    assert box_pairs_between(lo_a, hi_a, lo_b, hi_b, pad=0.1).tolist() == want


def test_rows_of_boxes_sharing_a_coordinate_range_give_few_candidates():
    # 100 rows of 100 unit boxes, side by side: every column shares its x range with 100 boxes
    # (a sweep along x or y meets 5,000 candidates per column); grid cells hold a box and its
    # neighbours
    from relief_cad.broadphase import _cell_pairs

    x, y = np.meshgrid(np.arange(100.0) * 1.5, np.arange(100.0) * 1.5)
    lo = np.column_stack([x.ravel(), y.ravel()])
    candidates, _ = _cell_pairs(lo, lo + 1.0, 0.0)
    assert candidates.shape[0] <= 20 * lo.shape[0]
    assert box_pairs(lo, lo + 1.0).shape == (0, 2)  # 0.5 apart: none touch
    assert box_pairs(lo, lo + 1.0, pad=0.5).shape == (2 * 100 * 99 + 2 * 99 * 99, 2)  # sides and corners


def test_grid_work_grows_with_nearby_pairs_not_all_pairs():
    # 20,000 unit boxes along a line: ~2 neighbours each; an all-pairs test would need 2e8 checks
    n = 20000
    lo = np.stack([np.arange(n, dtype=float) * 0.9, np.zeros(n)], axis=1)
    pairs = box_pairs(lo, lo + 1.0)
    assert pairs.shape == (n - 1, 2)
    assert np.all(pairs[:, 1] == pairs[:, 0] + 1)


def test_cluster_candidates_grow_with_nearby_points_not_shared_coordinates():
    # 40,000 points on a 200 x 200 grid: a sweep along x pairs the 200 points of each column
    # (4 million candidates); grid cells give each point its few real neighbours
    from relief_cad.broadphase import _cell_pairs

    x, y = np.meshgrid(np.arange(200.0), np.arange(200.0))
    pts = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    pts = np.vstack([pts, pts[:100] + 1e-9])  # 100 near duplicates
    candidates, _ = _cell_pairs(pts, pts, 1e-6)
    assert candidates.shape[0] <= 2 * pts.shape[0]
    labels = cluster_points(pts, 1e-6)
    assert labels.max() + 1 == 40000
    assert np.array_equal(labels[40000:], labels[:100])


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("n", [60, 400])  # all pairs tested, then grid cells
def test_cluster_points_are_the_components_of_the_closeness_graph(seed, n):
    rng = np.random.default_rng(seed)
    pts = np.round(rng.random((n, 2)) * 5, 1)  # many exact and near duplicates
    tol = 0.15
    labels = cluster_points(pts, tol)
    root = list(range(n))  # union-find over every pair within tol

    def find(i):
        while root[i] != i:
            i = root[i]
        return i

    for i, j in zip(*np.nonzero(np.linalg.norm(pts[:, None] - pts[None, :], axis=2) <= tol)):
        root[find(int(i))] = find(int(j))
    reach = np.array([[find(i) == find(j) for j in range(n)] for i in range(n)])
    assert np.array_equal(labels[:, None] == labels[None, :], reach)
    first = [int(np.flatnonzero(labels == k)[0]) for k in range(labels.max() + 1)]
    assert first == sorted(first)  # numbered by first appearance


def test_links_join_far_points_and_chains_join():
    labels = cluster_points([[0.0, 0], [1.0, 0], [2.0, 0], [9.0, 9]], 1.0, links=[(0, 3)])
    assert labels.tolist() == [0, 0, 0, 0]


@pytest.mark.parametrize(
    ("call", "error", "builtin"),
    [
        (lambda: box_pairs([[0.0, 0.0]], [[1.0]]), ShapeError, ValueError),
        (lambda: box_pairs([[0.0, float("nan")]], [[1.0, 1.0]]), InvalidInputError, ValueError),
        (lambda: box_pairs([[2.0, 0.0]], [[1.0, 1.0]]), InvalidInputError, ValueError),
        (lambda: box_pairs([[0.0, 0.0]], [[1.0, 1.0]], pad=-1.0), ToleranceError, ValueError),
        (lambda: box_pairs_between([[0.0]], [[1.0]], [[0.0, 0.0]], [[1.0, 1.0]]), ShapeError, ValueError),
        (lambda: cluster_points([0.0, 1.0], 0.1), ShapeError, ValueError),
        (lambda: cluster_points([[0.0], [1.0]], float("inf")), ToleranceError, ValueError),
        (lambda: cluster_points([[0.0], [1.0]], 0.1, links=[(0, 2)]), ShapeError, ValueError),
    ],
)
def test_bad_input_is_named(call, error, builtin):
    with pytest.raises(error) as info:
        call()
    assert isinstance(info.value, ReliefCadError) and isinstance(info.value, builtin)
    assert "should " in str(info.value)  # what was expected (and then what came)


def _closeness_components(pts: np.ndarray, tol: float) -> np.ndarray:
    """Brute force: ``same[i, j]`` when points i and j are joined by a chain of steps within ``tol``."""
    n = pts.shape[0]
    reach = np.linalg.norm(pts[:, None] - pts[None, :], axis=2) <= tol
    for k in range(n):  # transitive closure (Warshall)
        reach |= reach[:, k:k + 1] & reach[k:k + 1, :]
    return reach


@pytest.mark.parametrize("seed", range(6))
def test_jittered_clusters_about_tol_apart_are_the_closeness_components(seed):
    """Clusters of points spread over a third of tol, their centres about tol apart: the groups'
    boxes are neither surely apart nor surely within tol, so their points are compared."""
    rng = np.random.default_rng(seed)
    tol = 1e-3
    centres = np.cumsum(rng.uniform(0.8, 1.3, size=(6, 2)) * tol / np.sqrt(2), axis=0)
    pts = (centres[rng.integers(0, 6, 150)] + rng.uniform(-tol / 6, tol / 6, (150, 2)))
    labels = cluster_points(pts, tol)
    assert np.array_equal(labels[:, None] == labels[None, :], _closeness_components(pts, tol))


def test_thousands_of_points_at_one_place_are_one_vertex_without_pairing_them():
    """The cut points of many lines through one point: 20,000 points within 1e-12 of the origin
    (on both sides of 0, so in several grid cells) and 20,000 near (1, 0). Testing every pair took
    two times 2e8 candidate pairs (gigabytes); they are one group per grid cell now."""
    rng = np.random.default_rng(3)
    near_0 = rng.uniform(-1e-12, 1e-12, (20000, 2))
    near_1 = near_0[::-1] + [1.0, 0.0]
    labels = cluster_points(np.vstack([near_0, near_1]), 1e-9)
    assert labels[:20000].tolist() == [0] * 20000 and labels[20000:].tolist() == [1] * 20000


def test_a_tol_below_the_rounding_of_the_coordinates_joins_no_distinct_points():
    """tol 1e-310: the grid's cell coordinates overflow to inf, and one cell holds points 1 apart;
    a group whose points are not all within tol is split into its points."""
    labels = cluster_points([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 0.0]], 1e-310)
    assert labels.tolist() == [0, 1, 2, 2]


@pytest.mark.parametrize("scale", [1e150, 1e200, 1e300])
def test_clusters_do_not_depend_on_the_scale_up_to_the_float_range(scale):
    """The points' norms square their differences: beyond 1e154 they overflowed and every point stood apart."""
    rng = np.random.default_rng(4)
    pts = np.repeat(rng.random((25, 2)) * 100.0, 4, axis=0) + rng.random((100, 2)) * 1e-3
    base = cluster_points(pts, 1e-2)
    assert len(set(base.tolist())) == 25
    assert cluster_points(pts * scale, 1e-2 * scale).tolist() == base.tolist()


def test_box_pairs_near_the_float_range_are_those_of_the_scaled_boxes():
    """Corners minus their origin overflowed to inf: the grid cells were cast from NaN (a warning, and garbage)."""
    import warnings

    rng = np.random.default_rng(1)
    lo = (rng.random((300, 2)) * 2.0 - 1.0) * 1.7e308
    hi = lo + rng.random((300, 2)) * 1e307
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pairs = box_pairs(lo, hi)
        between = box_pairs_between(lo[:150], hi[:150], lo[150:], hi[150:])
    assert pairs.tolist() == box_pairs(lo * 2.0**-1000, hi * 2.0**-1000).tolist()
    assert between.tolist() == box_pairs_between(lo[:150] * 2.0**-1000, hi[:150] * 2.0**-1000,
                                                  lo[150:] * 2.0**-1000, hi[150:] * 2.0**-1000).tolist()
    assert len(pairs) > 0

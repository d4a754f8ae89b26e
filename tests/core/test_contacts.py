"""The contact post-pass (relief_cad.contacts) on real curves, against answers known exactly."""

from __future__ import annotations

import math

import numpy as np
import pytest

from relief_cad import RationalBezier, intersect, intersect_many
from relief_cad.contacts import _SINGULAR, _double_root, _foot, _singular_end, curve_direction, refine_self
from relief_cad.results import Intersection, Overlap


def _parabola(r1: float, r2: float) -> RationalBezier:
    """y = (t - r1)(t - r2) over x = t, exact Bernstein coefficients for dyadic roots."""
    return RationalBezier([[0.0, r1 * r2], [0.5, r1 * r2 - 0.5 * (r1 + r2)], [1.0, (1 - r1) * (1 - r2)]])


AXIS = RationalBezier([[-1.0, 0.0], [2.0, 0.0]])


def test_two_simple_roots_7e_9_apart_stay_two_crossings() -> None:
    r2 = 0.5 + 2.0**-27
    res = intersect(_parabola(0.5, r2), AXIS)
    assert [r.kind for r in res] == ["crossing", "crossing"]
    assert abs(res[0].t - 0.5) <= 1e-13 and abs(res[1].t - r2) <= 1e-13


def test_exact_double_root_is_one_tangent() -> None:
    res = intersect(_parabola(0.5, 0.5), AXIS)
    assert len(res) == 1 and res[0].kind == "tangent" and abs(res[0].t - 0.5) <= 1e-7


@pytest.mark.parametrize("gap", [2.0**-26, 2.0**-20, 2.0**-14])  # (0.5 - g)(0.5 + g) exact in binary64
def test_sign_test_decides_exactly(gap: float) -> None:
    a = _parabola(0.5, 0.5)
    p = Intersection(0.5 - gap, (1.5 - gap) / 3, a(0.5 - gap), "tangent")
    q = Intersection(0.5 + gap, (1.5 + gap) / 3, a(0.5 + gap), "tangent")
    assert _double_root(a, AXIS, p, q)              # the same sign between and outside
    b = _parabola(0.5 - gap, 0.5 + gap)
    assert not _double_root(b, AXIS, p, q)          # the sign changes between: two roots


def test_direction_from_first_nonvanishing_derivative() -> None:
    c = RationalBezier([[0, 0], [0, 0], [0, 0], [3, 4]])
    assert np.allclose(curve_direction(c, 0.0), [0.6, 0.8])
    assert np.allclose(curve_direction(c, 1.0, side=-1), [-0.6, -0.8])
    assert np.allclose(curve_direction(c, 1.0), [0.0, 0.0])       # nothing beyond the end
    cusp = RationalBezier([[0, 0], [2, 2], [0, 2], [2, 0]])       # c'(1/2) = 0: a cusp
    assert np.linalg.norm(cusp.derivative(0.5)) < 1e-12
    left, right = curve_direction(cusp, 0.5, -1), curve_direction(cusp, 0.5, 1)
    assert np.allclose(left, right, atol=1e-6)  # both branches leave the tip along one tangent


@pytest.mark.parametrize("deg", [15, 45, 90, 135, 175])
def test_end_meeting_with_zero_derivative_is_a_crossing(deg: int) -> None:
    th = math.radians(deg)
    a = RationalBezier([[0, 0], [0, 0], [1, 0], [1, 0]])
    b = RationalBezier([[0, 0], [0, 0], [math.cos(th), math.sin(th)], [math.cos(th), math.sin(th)]])
    res = intersect(a, b)
    assert [(r.t, r.u, r.kind) for r in res] == [(0.0, 0.0, "crossing")]


def test_fold_back_at_end_is_tangent() -> None:
    a = RationalBezier([[0, 0], [1, 0], [1, 0]])
    b = RationalBezier([[1, 0], [1, 0], [1, 1], [0, 1]])   # leaves a(1) at 90 degrees
    assert [r.kind for r in intersect(a, b)] == ["crossing"]
    c = RationalBezier([[1, 0], [1, 0], [0.5, 0], [0, -1]])  # leaves a(1) going back: a fold-back
    assert [r.kind for r in intersect(a, c)] == ["tangent"]


@pytest.mark.parametrize("dim", [2, 3])
def test_retracing_curve_self_overlap(dim: int) -> None:
    pts = np.array([[0, 0, 0], [1, 1, 1], [1, 1, 1], [0, 0, 0]], dtype=float)[:, :dim]
    assert intersect(RationalBezier(pts)) == [Overlap(t=(0.0, 0.5), u=(1.0, 0.5))]


def test_refine_self_keeps_an_isolated_double_point() -> None:
    loop = RationalBezier([[0, 0], [3, 3], [-1, 3], [2, 0]])
    res = intersect(loop)
    assert len(res) == 1 and isinstance(res[0], Intersection)
    assert refine_self(loop, res, 1e-9) == list(res)


def test_doubled_straight_cubic_against_sub_segment_and_line() -> None:
    c = RationalBezier([[0, 0], [0, 0], [1, 1], [1, 1]])
    assert intersect(c, RationalBezier([[0, 0], [1, 1]])) == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]
    res = intersect(c, c.segment(0.5, 1.0))
    assert len(res) == 1 and isinstance(res[0], Overlap)
    assert res[0].t[1] == 1.0 and abs(res[0].t[0] - 0.5) <= 1e-12 and res[0].u == (0.0, 1.0)


def test_curve_against_itself_elevated_and_reversed() -> None:
    rng = np.random.default_rng(7)
    for _ in range(5):
        c = RationalBezier(rng.random((6, 2)))
        assert intersect(c, c) == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]
        assert intersect(c, c.reversed()) == [Overlap(t=(0.0, 1.0), u=(1.0, 0.0))]
        res = intersect(c, c.elevate(1))
        assert len(res) == 1 and isinstance(res[0], Overlap)


def test_crossing_curves_stay_points() -> None:
    a = RationalBezier([[0, 0], [1, 2], [2, 0]])
    b = RationalBezier([[0, 0.5], [2, 0.5]])
    assert [r.kind for r in intersect(a, b)] == ["crossing", "crossing"]


def test_foot_leaves_a_fold_tip() -> None:
    fold = RationalBezier([[0, 0], [2, 0], [1, 0]])  # x(t) = 4t - 3t^2, turns back at t = 2/3
    piece = fold.segment(0.5, 0.7)                   # holds the tip, at s = 5/6
    pts = piece.evaluate(np.array([0.853, 0.95]))    # nearest grid point: the tip, a stationary point
    _u, dist = _foot(piece, pts)
    assert np.all(dist <= 1e-12)


# the two closed cubics (first control point = last) of the space fuzz's swap and determinism
# tests, against themselves: every frame's images overlapped where the kernel's end contacts
# paired a(0) with b(1), so the space path gave up (BudgetExceededError), and the planar path
# answered the wrong orientation, u = (1, 0), for a curve against itself
CLOSED = [
    RationalBezier([[3.294797e-106, 0.55, 5.822546], [3.526472, -2.225074e-308, -2.314974],
                    [-4.729646, 4.6777e-29, 9.788799], [3.294797e-106, 0.55, 5.822546]]),
    RationalBezier([[5.947891e-294, -2.121377e-159, 2.695167], [-6.340934, -6.794267, -3.463299],
                    [5.911397e-2, -2.710342e-127, -5.736203], [5.947891e-294, -2.121377e-159, 2.695167]],
                   weights=[0.2, 0.2, 0.2, 0.2]),
]


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("which", [0, 1])
def test_closed_curve_against_itself_is_one_overlap_in_its_own_sense(dim: int, which: int) -> None:
    c = CLOSED[which]
    c = RationalBezier(c.control_points[:, :dim], c.weights)
    assert list(intersect(c, c)) == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]
    assert list(intersect(c, c.elevate(1))) == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))]
    assert list(intersect(c, c.reversed())) == [Overlap(t=(0.0, 1.0), u=(1.0, 0.0))]
    assert list(intersect(c.reversed(), c)) == [Overlap(t=(0.0, 1.0), u=(1.0, 0.0))]


def test_curves_sharing_only_their_end_points_are_two_crossings_not_an_overlap() -> None:
    # compiled, the kernel's coincidence test of two end contacts sampled only its first point
    # (k / nsamp of two C integers): a chord and its arc, or two quarter circles between the same
    # points, came back as one Overlap
    chord, arc = RationalBezier([[0, 0], [1, 0]]), RationalBezier([[0, 0], [0.5, 1], [1, 0]])
    r = 2**-0.5
    q1 = RationalBezier([[1, 0], [1, 1], [0, 1]], weights=[1, r, 1])
    q2 = RationalBezier([[1, 0], [0, 0], [0, 1]], weights=[1, r, 1])
    for a, b in ((chord, arc), (arc, chord), (q1, q2), (q1, q2.reversed())):
        res = intersect(a, b)
        assert not res.overlaps and len(res) == 2, res
        assert {(r.t, r.u) for r in res} <= {(0.0, 0.0), (0.0, 1.0), (1.0, 0.0), (1.0, 1.0)}, res


def test_intersect_many_answers_a_looping_curve_against_itself_as_intersect_does() -> None:
    # the batch path had no post-pass: 30 "tangent" points and the loop's crossing, not one Overlap
    c = RationalBezier([[0, 0], [1, 0], [1, 0.125], [0, -0.375], [0, 1]])
    for b in (c, RationalBezier(c.control_points.copy()), c.reversed()):
        assert intersect_many([(c, b)])[0] == intersect(c, b)
        assert len(intersect(c, b)) == 1 and isinstance(intersect(c, b)[0], Overlap)


def test_foot_is_the_closest_point_of_the_curve() -> None:
    """``_foot`` (compiled Newton from grid seeds) against dense sampling of the curve.

    Its distance is that of a real point of the curve, so it can never be below the true
    minimum; it must not be above the best of 2**14 + 1 samples either, beyond the iteration's
    stopping rule (three steps in a row that gain less than 1e-6 of the distance): random rational
    cubics and quintics, planar and space, points near and far.
    """
    rng = np.random.default_rng(11)
    dense = np.linspace(0.0, 1.0, 2**14 + 1)
    for k in range(40):
        dim = 2 + k % 2
        degree = 3 + 2 * (k % 3 == 0)
        curve = RationalBezier(rng.random((degree + 1, dim)), 0.5 + rng.random(degree + 1))
        pts = rng.random((5, dim)) * 3 - 1
        u, dist = _foot(curve, pts)
        samples = curve.evaluate(dense)
        best = np.sqrt(((pts[:, None, :] - samples[None, :, :]) ** 2).sum(axis=2)).min(axis=1)
        assert np.all((u >= 0.0) & (u <= 1.0))
        assert np.allclose(np.linalg.norm(curve.evaluate(u) - pts, axis=1), dist, rtol=0, atol=1e-15)
        assert np.all(dist <= best * (1 + 1e-6) + 1e-12), (k, dist - best)


def test_a_rational_loop_against_its_reverse_is_one_overlap_in_a_batch() -> None:
    """A rational quartic with a small loop (double point at t = 0.107 / 0.322) against its reverse.

    ``intersect`` answers it before clipping (whole_overlap); ``intersect_many`` sends it to the
    batch kernel (the reversed copy's control points differ by a rounding), whose post-pass found
    four contacts: a sample on the loop had its closest point between two grid points of the other
    curve, both farther than a false local minimum next to them. The coincidence test now takes a
    second look on a finer grid. Also at the scale 2**498 (the range-scaled path).
    """
    rows = [["0x1.9c4b40857003ap-2", "0x1.173a217f4f81ep-2"], ["0x1.87ad5557c561cp-6", "0x1.2ba4f6d3a7a2fp-4"],
            ["0x1.357aa7d8dae06p-1", "0x1.24cbe9e157589p-2"], ["0x1.9d274a05c0997p-2", "0x1.583be67662eeap-1"],
            ["0x1.9fe779cac709fp-2", "0x1.6013b151deb12p-3"]]
    w = ["0x1.9a2f809584dd8p-1", "0x1.747029f97c71dp+0", "0x1.d2c3c33b69a8ap-1", "0x1.2a7597573af18p-1",
         "0x1.393936725c924p-1"]
    pts = np.array([[float.fromhex(x) for x in r] for r in rows])
    weights = np.array([float.fromhex(x) for x in w])
    for exp in (0, 498):
        loop = RationalBezier(np.ldexp(pts, exp), weights)
        back = loop.reversed()
        assert not np.array_equal(back.control_points[::-1], loop.control_points)  # a rounding apart
        whole = [Overlap(t=(0.0, 1.0), u=(1.0, 0.0))]
        assert list(intersect(loop, back)) == whole
        assert [list(r) for r in intersect_many([(loop, back), (back, loop)])] == [whole, whole]
        assert [(round(r.t, 9), round(r.u, 9)) for r in intersect(loop)] == [(0.107127077, 0.321738207)]


@pytest.mark.parametrize(("p0", "p1", "w", "q1"), [
    ([7590.615937723392, 7590.7555862141835, 7590.622298778737],
     [7590.615937476653, 7590.755587224401, 7590.622299616646],
     [4.591419424199418, 2.221377866582616, 3.7073208671091176],
     [7590.615937476654, 7590.755587224401, 7590.622299616641]),
    ([2576.190208146096, 2575.4051932557427, 2576.3641251334943],
     [2576.1902089237587, 2575.405193069251, 2576.364124569507],
     [4.758906237500452, 0.33937340298159346, 3.4162977374985934],
     [2576.190208923758, 2575.40519306925, 2576.3641245695085]),
    ([3947.8638821813765, 3948.770058819687, 3947.609723871362],
     [3947.8638811107453, 3948.7700588201733, 3947.6097247470702],
     [4.542990583237281, 1.2536061775975924, 1.1577827598617723],
     [3947.8638811107467, 3948.770058820173, 3947.609724747071]),
])
def test_a_curve_running_out_and_back_and_its_rounded_copy_coincide_either_way(
        p0: list[float], p1: list[float], w: list[float], q1: list[float]) -> None:
    # a quadratic whose first and last control points are one runs out and back along itself; a copy
    # with the middle point rounded differently (1e-12 of 1e4) is the same curve. Its interior
    # points' feet on the copy tell no sense (a(1/4) and a(3/4) may be one point), and the closed
    # curves' coincidence was not tested at all: crossings at the ends, or an overlap one way only
    # (3 of 300 such pairs; the space fuzz found one)
    a = RationalBezier([p0, p1, p0], w)
    b = RationalBezier([p0, q1, p0], w)
    for x, y in ((a, b), (b, a)):
        found = intersect(x, y)
        assert [type(r).__name__ for r in found] == ["Overlap"], found
        assert found[0].t == (0.0, 1.0)


def _singular_end_by_numpy(c: RationalBezier, t: float) -> bool:
    """The rule of a singular end on whole numpy rows (the form the Python-float test replaced)."""
    pts = c.control_points
    i, j = (0, 1) if t == 0.0 else (-1, -2)
    if np.all(pts[i] == pts[j]):
        return True
    return bool(np.abs(pts[j] - pts[i]).max() <= _SINGULAR * np.abs(pts - pts[i]).max())


def test_a_singular_end_is_decided_as_on_numpy_rows() -> None:
    """Repeated end points, legs around 1e-9 of the size (either side of the rule), and plain ends.

    The test runs on Python floats (it decides every end meeting of the CAD layer's core calls);
    the differences and maxima are exact, so every answer must be numpy's.
    """
    rng = np.random.default_rng(20261205)
    answers = []
    for _ in range(4000):
        n, d = int(rng.integers(1, 8)), int(rng.integers(2, 4))
        p = rng.normal(size=(n + 1, d)) * 10.0 ** rng.uniform(-6, 6)
        end, leg = (0, 1) if rng.random() < 0.5 else (-1, -2)
        kind = rng.integers(0, 3)
        if kind == 1:
            p[leg] = p[end]
        elif kind == 2:
            p[leg] = p[end] + rng.normal(size=d) * 1e-9 * np.abs(p - p[end]).max() * rng.uniform(0.0, 2.0)
        c = RationalBezier(p, rng.uniform(0.2, 5.0, n + 1))
        for t in (0.0, 1.0):
            assert _singular_end(c, t) == _singular_end_by_numpy(c, t), (p.tolist(), t)
            answers.append(_singular_end(c, t))
    assert 1000 < sum(answers) < len(answers) - 1000  # both answers, many times
    assert not _singular_end(RationalBezier([[0.0, 0.0], [0.0, 0.0], [1.0, 1.0]]), 0.5)


@pytest.mark.parametrize("r", [1.0, 100.0, 1e4])
def test_curves_apart_in_the_middle_are_no_overlap_whatever_their_weights(r: float) -> None:
    """A segment and a parabola with the same ends, weights 1, r, r² on both (found by a hunt).

    Geometric weights only reparameterise the curves (a Möbius map), but they put all but 1/r of
    the parameter range near one end: samples even in the parameter saw only that end, and a
    parabola peaking 25 tol above the segment came out as an overlap at r = 1e4. Truth in closed
    form: the peak is h / 2 above the segment. At 0.5 tol they do overlap.
    """
    tol = 1e-6
    weights = [1.0, r, r * r]
    a = RationalBezier([[0, 0], [5, 0], [10, 0]], weights=weights)
    for peak, overlap in ((25 * tol, False), (1.5 * tol, False), (0.5 * tol, True)):
        b = RationalBezier([[0, 0], [5, 2 * peak], [10, 0]], weights=weights)
        got = intersect(a, b, tol=tol)
        if overlap:
            assert got == [Overlap(t=(0.0, 1.0), u=(0.0, 1.0))], got
        else:
            assert [(p.t, p.u) for p in got if isinstance(p, Intersection)] == [(0.0, 0.0), (1.0, 1.0)], got
            assert not any(isinstance(p, Overlap) for p in got), got

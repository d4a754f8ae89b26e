"""The arbiter on thin lenses: curves crossing twice close together, with a saddle of the distance between.

Between the two crossings of a circle and a line ``depth`` below its top (or of two circles whose
centres are ``2 R - depth`` apart), the point of ``a`` halfway between them and the point of
``b`` opposite it, ``depth`` apart, are a saddle of ``|a(t) - b(u)|**2``: its gradient vanishes,
and a refinement started there stayed there. The arbiter judged such a candidate a miss when the
lens was deeper than tol, and a true tangent, at distance ``depth``, when it was thinner; the
truth is the two crossings, whose places are closed forms of the binary64 data. The lenses sit at
a circle's seam (parameter 0, where ``cos`` and ``sin`` are exact), so the candidate is the
saddle itself, or at its top (parameter pi / 2), the candidate OCCT and relief_cad report there.
"""

from __future__ import annotations

import math

import build123d as bd
import mpmath
import pytest

from relief_cad.cad.compare import arbitrate_overlap, arbitrate_point, compare
from relief_cad.cad.results import EdgeIntersection

R = 10.0
TOL = 1e-7


def circle(centre: tuple[float, float] = (0.0, 0.0)) -> bd.Edge:
    return bd.Edge.make_circle(R).moved(bd.Location((centre[0], centre[1], 0.0)))


def crossings_with_vertical_line(x: float) -> list[tuple[float, float]]:
    """The circle ``|p| = R`` and the line through ``(x, 0)`` along y cross at ``(x, +-sqrt(R^2 - x^2))``."""
    with mpmath.workdps(60):
        y = mpmath.sqrt(mpmath.mpf(R) ** 2 - mpmath.mpf(x) ** 2)
        return [(x, float(y)), (x, float(-y))]


def crossings_of_circles(dx: float) -> list[tuple[float, float]]:
    """Circles of radius R about ``(0, 0)`` and ``(dx, 0)`` cross at ``(dx / 2, +-sqrt(R^2 - dx^2 / 4))``."""
    with mpmath.workdps(60):
        y = mpmath.sqrt(mpmath.mpf(R) ** 2 - (mpmath.mpf(dx) / 2) ** 2)
        return [(dx / 2, float(y)), (dx / 2, float(-y))]


def assert_is_one_of(point: tuple[float, ...], truth: list[tuple[float, float]]) -> None:
    assert min(math.dist(point[:2], p) for p in truth) <= 1e-12, (point, truth)
    assert point[2] == 0.0


def assert_both_crossings(check, truth: list[tuple[float, float]]) -> None:
    """``check`` is one true crossing; its ``sides``, when the refinement stopped on the saddle, both.

    (Where the derivatives show the saddle's slope, as at a circle's seam, the refinement goes
    straight to one crossing, and ``sides`` is empty.)
    """
    assert check.holds and check.kind == "crossing" and check.distance < 1e-30, check
    assert_is_one_of(check.point, truth)
    assert len(check.sides) in (0, 2), check.sides
    for side, p in [] if not check.sides else zip(sorted(check.sides, key=lambda s: s.point[1]), sorted(truth, key=lambda p: p[1]),
                       strict=True):
        assert side.holds and side.distance < 1e-30 and math.dist(side.point[:2], p) <= 1e-12, (side, p)


# depths: 1e-3, 10 tol, half tol, 1e-2 tol (the lens thinner than tol: still two exact crossings)
DEPTHS = [1e-3, 1e-6, 5e-8, 1e-9]


@pytest.mark.parametrize("depth", DEPTHS)
def test_a_candidate_on_the_saddle_of_a_circle_and_a_line_refines_to_the_crossings(depth: float) -> None:
    x = R - depth  # the line x = R - depth cuts the circle's seam point (R, 0) off
    a, b = circle(), bd.Edge.make_line((x, -20.0), (x, 20.0))
    truth = crossings_with_vertical_line(x)
    # the candidate: the circle's point (R, 0) and the line's (x, 0), the saddle itself
    chk = arbitrate_point(a, b, 0.0, 20.0, tol=TOL)
    # was: a miss at distance `depth` (depth > tol) or a tangent at distance `depth` (depth <= tol)
    assert_both_crossings(chk, truth)
    # the same verdict from a candidate next to the saddle: the arbiter needs no luck
    near = arbitrate_point(a, b, 1e-9, 20.0, tol=TOL)
    assert near.kind == chk.kind and near.distance < 1e-30
    assert_is_one_of(near.point, truth)


@pytest.mark.parametrize("depth", DEPTHS)
def test_a_candidate_on_the_saddle_of_two_circles_refines_to_the_crossings(depth: float) -> None:
    dx = 2 * R - depth  # the lens round a's seam (R, 0) and b's point at pi, (dx - R, 0)
    a, b = circle(), circle((dx, 0.0))
    chk = arbitrate_point(a, b, 0.0, math.pi, tol=TOL)
    assert_both_crossings(chk, crossings_of_circles(dx))


@pytest.mark.parametrize("depth", [1e-3, 1e-6])
def test_the_top_of_a_circle_against_a_line_below_it_is_no_miss(depth: float) -> None:
    # the candidate OCCT and relief_cad give for a touch there: t = pi / 2 (its cosine 6e-17, a
    # saddle to 6e-16), the line's middle; it was judged a miss, `depth` away
    y = R - depth
    a, b = circle(), bd.Edge.make_line((-20.0, y), (20.0, y))
    with mpmath.workdps(60):
        x = float(mpmath.sqrt(mpmath.mpf(R) ** 2 - mpmath.mpf(y) ** 2))
    truth = [(x, y), (-x, y)]
    for t in (math.pi / 2, math.pi / 2 + 1e-9, math.pi / 2 - 1e-9):
        chk = arbitrate_point(a, b, t, 20.0, tol=TOL)
        assert chk.holds and chk.kind == "crossing" and chk.distance < 1e-30, (t, chk)
        assert_is_one_of(chk.point, truth)


@pytest.mark.parametrize("depth", [1e-6, 5e-8, 1e-9])
def test_an_overlap_claim_sampled_too_coarsely_for_the_lens_gives_its_crossings(depth: float) -> None:
    # samples 0.01 apart in t along the circle from its seam, where the line cuts a lens 2e-4 to
    # 9e-4 wide: the sample at the seam is the closest, and its refinement stopped on the saddle
    # (a tangent `depth` away, or nothing when depth > tol)
    x = R - depth
    a, b = circle(), bd.Edge.make_line((x, -20.0), (x, 20.0))
    truth = crossings_with_vertical_line(x)
    chk = arbitrate_overlap(a, b, (0.0, 0.32), (20.0, 23.2), tol=TOL)
    assert not chk.holds and chk.status == "crossing", chk
    assert len(chk.points) == 2, chk.points
    for p in chk.points:
        assert p.kind == "crossing" and p.distance < 1e-30
        assert_is_one_of(p.point, truth)
    # the crossing in the claimed range is among them, and the one round the seam, next to it
    assert sorted(round(p.t, 9) for p in chk.points) == pytest.approx(
        sorted(math.atan2(y, x) for _, y in truth), abs=1e-9)


def test_compare_judges_a_touch_claimed_at_the_apex_of_circles_half_tol_into_each_other() -> None:
    # a touch reported at a's seam, the apex of the lens of circles 5e-8 into each other (the rule
    # for tol gives one touch there); the arbiter refined it to the saddle and said "a true tangent
    # point (refined distance 5e-08 <= tol)": its exact truth is the crossings, 7e-4 either side
    dx = 2 * R - 5e-8
    a, b = circle(), circle((dx, 0.0))
    claim = EdgeIntersection(0, 0, None, None, 0.0, math.pi, (R - 2.5e-8, 0.0, 0.0), "tangent")
    c = compare(a, b, relief=[claim])
    assert c.errors == {}
    mine = [d for d in c.disagreements if d.claimant == "relief_cad" and d.claim is claim]
    assert len(mine) == 1, c.disagreements
    verdict = mine[0].verdict
    assert verdict.truth == "crossing" and verdict.distance < 1e-30, verdict
    for d in c.disagreements:  # no point claim is judged by the saddle's tangent
        if isinstance(d.claim, EdgeIntersection):
            assert not (d.verdict.truth == "tangent" and d.verdict.distance >= 1e-30), d

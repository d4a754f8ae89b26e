"""Curves that turn back: straight folds, small loops at a cusp, a fold over the end of another curve.

Straight curves that fold back: each pair of runs along the line is one self-overlap.

A curve whose control points lie on one line traces that line back and forth: it turns back
where the derivative of its coordinate along the line changes sign (a fold). Between two folds it
runs one way (a run); two runs cover a common stretch, which is one :class:`Overlap` of the
curve with itself. The truth here comes from the line coordinate alone, ``x(t) = N(t) / D(t)``
with numpy power-series polynomials: the folds are the roots of ``N' D - N D'`` in (0, 1), and an
overlap's ends are where one run reaches the other's end value. Nothing of relief_cad is used.
"""

from __future__ import annotations

import math
from math import comb

import numpy as np
import pytest
from numpy.polynomial import polynomial as P

from relief_cad import Overlap, RationalBezier, intersect
from relief_cad.contacts import self_overlaps


def _power(coef: list[float]) -> np.ndarray:
    """Power-series coefficients of the Bernstein polynomial with coefficients ``coef``."""
    n = len(coef) - 1
    out = np.zeros(n + 1)
    for i, c in enumerate(coef):
        out += c * comb(n, i) * P.polymul(P.polypow([0.0, 1.0], i), P.polypow([1.0, -1.0], n - i))[: n + 1]
    return out


def _roots_in(poly: np.ndarray, lo: float, hi: float) -> list[float]:
    """Real roots of ``poly`` in ``(lo, hi)``: the companion matrix's, then Newton-polished (simple roots).

    Several eigenvalues may polish onto one root (numpy 1.26's LAPACK gave a double root as a
    complex pair 4e-8 off the axis, and Newton took both from there to a simple root already
    found): a root within 1e-9 of one already taken is that one.
    """
    der = P.polyder(poly)
    out: list[float] = []
    for r in P.polyroots(poly):
        if abs(r.imag) < 1e-6:
            x = float(r.real)
            for _ in range(8):
                slope = float(P.polyval(x, der))
                if slope == 0.0:
                    break
                x -= float(P.polyval(x, poly)) / slope
            if lo < x < hi and all(abs(x - y) > 1e-9 for y in out):
                out.append(x)
    return sorted(out)


def _truth(xs: list[float], ws: list[float]) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The self-overlaps ``((t0, t1), (u0, u1))`` of the straight curve with line coordinates ``xs``."""
    num, den = _power([w * x for w, x in zip(ws, xs, strict=True)]), _power(ws)
    x = lambda t: float(P.polyval(t, num) / P.polyval(t, den))  # noqa: E731
    folds = _roots_in(P.polysub(P.polymul(P.polyder(num), den), P.polymul(num, P.polyder(den))), 1e-9, 1 - 1e-9)
    ends = [0.0, *folds, 1.0]
    runs = list(zip(ends[:-1], ends[1:], strict=True))

    def at(run: tuple[float, float], v: float) -> float:  # the parameter of the run where x = v
        if abs(x(run[0]) - v) < 1e-12:
            return run[0]
        if abs(x(run[1]) - v) < 1e-12:
            return run[1]
        (root,) = _roots_in(P.polysub(num, v * den), run[0] - 1e-12, run[1] + 1e-12)
        return root

    out = []
    for i, ra in enumerate(runs):
        for rb in runs[i + 1:]:
            lo = max(min(x(ra[0]), x(ra[1])), min(x(rb[0]), x(rb[1])))
            hi = min(max(x(ra[0]), x(ra[1])), max(x(rb[0]), x(rb[1])))
            if hi - lo > 1e-6:
                t0, t1 = sorted((at(ra, lo), at(ra, hi)))
                out.append(((t0, t1), (at(rb, x(t0)), at(rb, x(t1)))))
    return out


def _straight(xs: list[float], ws: list[float], angle: float, dim: int = 2) -> RationalBezier:
    """The line coordinates ``xs`` placed on a line at ``angle`` (tilted out of the plane in space)."""
    d = np.array([np.cos(angle), np.sin(angle), 0.375])[:dim]
    d /= np.linalg.norm(d)
    return RationalBezier(np.array(xs)[:, None] * d + np.array([0.25, -0.5, 0.125])[:dim], np.array(ws))


def _check(c: RationalBezier, truth: list[tuple[tuple[float, float], tuple[float, float]]]) -> None:
    res = intersect(c)
    assert res.complete
    assert all(isinstance(r, Overlap) for r in res), res
    assert len(res) == len(truth), (res, truth)
    for (t, u) in truth:
        assert any(np.allclose(o.t, t, atol=1e-9, rtol=0) and np.allclose(o.u, u, atol=1e-9, rtol=0)
                   for o in res), (res, t, u)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("seed", range(24))
def test_a_straight_curve_folding_back_once_overlaps_itself_once(seed: int, dim: int) -> None:
    """Planar and space self-intersections (each cuts its pieces in :mod:`relief_cad.pieces`)."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 6))
    ws = (rng.random(n + 1) + 0.5).tolist() if seed % 2 else [1.0] * (n + 1)
    while True:  # a curve with exactly one fold, not within 1e-3 of an end
        xs = rng.standard_normal(n + 1).tolist()
        truth = _truth(xs, ws)
        if len(truth) == 1 and 1e-3 < truth[0][0][1] < 1 - 1e-3:
            break
    _check(_straight(xs, ws, rng.random() * np.pi, dim), truth)


@pytest.mark.parametrize("xs", [[0.0, 3.0, -2.5, 1.2], [0.3, 2.0, -1.0, 1.7], [-1.0, 2.5, -2.0, 0.5]])
def test_a_straight_cubic_folding_back_twice_overlaps_itself_three_times(xs: list[float]) -> None:
    """Out, back past the start, out again: three runs, each pair one overlap.

    The pieces cut at the folds start and end where the derivative vanishes (their end control
    points repeat up to rounding); two such pieces along one line were two crossings, not an
    overlap, and an overlap of runs going the same way was once closed up to a fold.
    """
    truth = _truth(xs, [1.0] * 4)
    assert len(truth) == 3
    _check(_straight(xs, [1.0] * 4, 0.927295218), truth)


def test_pieces_cut_at_folds_overlap_where_they_run_along_each_other() -> None:
    """The first and last runs of a twice-folding cubic, as curves of their own: one overlap."""
    xs = [-1.0, 2.5, -2.0, 0.5]
    c = _straight(xs, [1.0] * 4, 0.3)
    f1, f2 = _roots_in(P.polyder(_power(xs)), 0.0, 1.0)
    a, b = c.segment(0.0, f1), c.segment(f2, 1.0)   # each ends at a fold: a vanishing derivative
    (o,) = intersect(a, b)
    assert isinstance(o, Overlap)
    assert o.t[1] == 1.0 and o.u[0] == 0.0
    assert np.allclose(a(o.t[0]), b(0.0), atol=1e-12) and np.allclose(b(o.u[1]), a(1.0), atol=1e-12)


def test_self_overlaps_never_chain_across_a_fold() -> None:
    """Two stretches meeting end to start, the second running back in ``u``, stay two overlaps."""
    out_and_on = Overlap(t=(0.3, 0.45), u=(0.7, 0.84))
    back = Overlap(t=(0.45, 0.7), u=(0.84, 0.7))
    assert self_overlaps([(out_and_on, True), (back, True)]) == [out_and_on, back]
    on = Overlap(t=(0.45, 0.6), u=(0.84, 0.9))
    assert self_overlaps([(out_and_on, True), (on, True)]) == [Overlap(t=(0.3, 0.6), u=(0.7, 0.9))]


def _double_point(xs: list[float], ys: list[float], guess: tuple[float, float]) -> tuple[float, float]:
    """The double point ``c(t) = c(u)``, ``t < u``, of a polynomial cubic, to 50 digits (mpmath).

    On the divided differences ``(c(t) - c(u)) / (t - u)``, written out in the power basis (no
    division), so the trivial solution ``t = u`` is not a root.
    """
    import mpmath as mp

    mp.mp.dps = 50
    power = [[mp.mpf(0)] * 4 for _ in range(2)]
    for k, coord in enumerate((xs, ys)):
        for i, v in enumerate(coord):  # Bernstein to power basis, exactly in mpmath
            for j in range(i, 4):
                power[k][j] += mp.mpf(v) * comb(3, i) * comb(3 - i, j - i) * (-1) ** (j - i)

    def divided(t: object, u: object) -> list[object]:
        return [sum(a[j] * sum(t ** q * u ** (j - 1 - q) for q in range(j)) for j in range(1, 4)) for a in power]

    t, u = mp.findroot(divided, (mp.mpf(guess[0]), mp.mpf(guess[1])))
    return float(t), float(u)


@pytest.mark.parametrize("gap", [1e-3, 1e-4, 1e-5, 1e-6, 1e-7])
def test_a_small_loop_next_to_a_cusp_is_found(gap: float) -> None:
    """(0,0), (1,1), (0,1), (1 - gap, 0): a cusp at t = 1/2 for gap 0, a loop for gap > 0.

    The loop is split between the two halves of the curve, whose joint lies inside it; for gap
    1e-6 the loop is 5.6e-7 long and 2.5e-10 wide, thinner than the tolerance (1.25e-9), and its
    crossing (4.3e-4 from the joint in parameter) was lost in the joint's own contact.
    """
    xs, ys = [0.0, 1.0, 0.0, 1.0 - gap], [0.0, 1.0, 1.0, 0.0]
    d = 0.433 * gap ** 0.5
    t, u = _double_point(xs, ys, (0.5 - d, 0.5 + d))
    assert 0.0 < t < 0.5 < u < 1.0 and u - t > 1e-4
    (hit,) = intersect(RationalBezier(np.array([xs, ys]).T))
    assert abs(hit.t - t) < 1e-9 and abs(hit.u - u) < 1e-9


@pytest.mark.parametrize("gap", [1e-3, 1e-5, 1e-7, 1e-9])
def test_no_loop_on_the_other_side_of_the_cusp(gap: float) -> None:
    xs, ys = [0.0, 1.0, 0.0, 1.0 + gap], [0.0, 1.0, 1.0, 0.0]
    res = intersect(RationalBezier(np.array([xs, ys]).T))
    assert res.complete and len(res) == 0


@pytest.mark.parametrize("dim", [2, 3])
def test_a_curve_folding_back_over_the_end_of_another_overlaps_it_on_both_runs(dim: int) -> None:
    """A straight cubic runs past the start of a segment on its line, turns back, and later runs
    along it again: three overlaps, two of them meeting at the fold (x = 0.50381 > 0.5).

    There was no contact at the fold, so the stretch out and back was one chain from where the
    cubic arrives at the segment's start to where it leaves it (the same point of the segment):
    it came out as a tangent point (planar) or an overlap stopping short of the fold (space).
    """
    xs, (b0, b1) = [0.0, 1.2, -0.3, 1.0], (0.5, 2.0)
    num = _power(xs)
    x = lambda t: float(P.polyval(t, num))  # noqa: E731
    f1, f2 = _roots_in(P.polyder(num), 0.0, 1.0)
    (ta,) = _roots_in(P.polysub(num, [b0]), 0.0, f1)
    (tb,) = _roots_in(P.polysub(num, [b0]), f1, f2)
    (tc,) = _roots_in(P.polysub(num, [b0]), f2, 1.0)
    tip = (x(f1) - b0) / (b1 - b0)
    truth = [((ta, f1), (0.0, tip)), ((f1, tb), (tip, 0.0)), ((tc, 1.0), (0.0, (x(1.0) - b0) / (b1 - b0)))]
    d = np.array([0.48, 0.64, 0.6])[:dim] / np.linalg.norm([0.48, 0.64, 0.6][:dim])
    res = intersect(RationalBezier(np.array(xs)[:, None] * d), RationalBezier(np.array([b0, b1])[:, None] * d))
    assert all(isinstance(r, Overlap) for r in res) and len(res) == 3, res
    for t, u in truth:
        assert any(np.allclose(o.t, t, atol=1e-9, rtol=0) and np.allclose(o.u, u, atol=1e-9, rtol=0)
                   for o in res), (res, t, u)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("lam", [1.0, 1e3, 1e4, 1e5])
def test_a_loop_squeezed_near_the_start_by_its_weights_is_found(dim: int, lam: float) -> None:
    """The nodal cubic x = T^2 - c, y = T (T^2 - c) (T = 2s - 1; z = T^2 in space), weighted by
    ``lam ** i``: the same curve, its loop within 3e-4 of the start at lam 1e4 (found by a hunt).
    Pieces were cut 10 (12) times at most, so the piece holding the whole loop was kept whole, and
    the double point was lost with ``complete=True``. Truth: T = -+sqrt(c), mapped by the weights
    (s = t / (lam (1 - t) + t), t the unweighted parameter)."""
    c = 0.25 if dim == 2 else 0.01
    n = 3
    ts = np.linspace(0.0, 1.0, n + 1)
    T = 2.0 * ts - 1.0
    samples = np.c_[T * T - c, T * (T * T - c)] if dim == 2 else np.c_[T * T - c, T * (T * T - c), T * T]
    basis = np.array([[math.comb(n, i) * s**i * (1 - s) ** (n - i) for i in range(n + 1)] for s in ts])
    poles = np.linalg.solve(basis, samples)
    curve = RationalBezier(poles, [lam**i for i in range(n + 1)])
    found = intersect(curve)
    truth = [t / (lam * (1.0 - t) + t) for t in ((1 - math.sqrt(c)) / 2, (1 + math.sqrt(c)) / 2)]
    assert found.complete and [r.kind for r in found] == ["crossing"], found
    assert (found[0].t, found[0].u) == pytest.approx(truth, rel=1e-9)


@pytest.mark.parametrize("dim", [2, 3])
@pytest.mark.parametrize("lift", [1e-7, 1e-6])
def test_the_sharp_tip_of_a_near_cusp_is_no_double_point(dim: int, lift: float) -> None:
    """A cubic whose cusp is lifted into a sharp smooth tip: no loop (Newton on a(s) = a(t), s < t,
    from either side of the tip runs to s = t). Cut deep around the tip, its pieces meet within tol
    on both sides of it, 1.5e-6 apart in parameter: that is one place of the curve, not a touch."""
    pts = [[0.0, 0.0], [2.0, 2.0], [0.0, 2.0 + lift], [2.0, 0.0]]
    curve = RationalBezier([p + [0.0] for p in pts] if dim == 3 else pts)
    assert list(intersect(curve)) == []


@pytest.mark.parametrize("n", [4, 5, 6])
def test_a_line_run_n_times_overlaps_itself_once_per_pair_of_runs(n: int) -> None:
    """x = T_n(2s - 1) (Chebyshev) along a line: n runs over the same stretch, n (n - 1) / 2 overlaps.

    Where two runs meet, the curve turns back in ``t`` and in ``u`` at once, and ``u`` keeps its
    way there: overlaps were chained through those folds, and one ending at a fold was extended
    to the next (3 overlaps for n = 4 and 5; found by a hunt). In the plane only: in space such a
    line loses overlaps between its piece pairs, from n = 3 on (a known weakness).
    """
    dim = 2
    s = (1 - np.cos(np.pi * (np.arange(n + 1) + 0.5) / (n + 1))) / 2
    basis = np.array([[comb(n, i) * x**i * (1 - x) ** (n - i) for i in range(n + 1)] for x in s])
    xs = np.linalg.solve(basis, np.cos(n * np.arccos(2 * s - 1))).tolist()
    truth = _truth(xs, [1.0] * (n + 1))
    assert len(truth) == n * (n - 1) // 2
    _check(_straight(xs, [1.0] * (n + 1), 0.4636476, dim), truth)


# --------------------------------------------------------------------------- a curve folding back along another
_FOLD_U = (66.0 + math.sqrt(66.0**2 + 4 * 88.5 * 1.5)) / (2 * 88.5)  # x_b'(u) = 0: -88.5 u² + 66 u + 1.5 = 0


def _fold_x(u: float) -> float:
    return 2 * (1 - u) ** 3 + 7.5 * u * (1 - u) ** 2 + 42 * u**2 * (1 - u) + 7 * u**3


@pytest.mark.parametrize("dim", [2, 3])
def test_a_curve_overshooting_along_a_line_and_folding_back_gives_two_overlaps_either_way(dim: int) -> None:
    """b runs along a from x = 2 out to x = 9.2531 (its fold), and back to x = 7 (found by a hunt).

    The line a was matched end to end with b, (0.2, 0) to (0.7, 1): the check of b's stretch on a
    took feet anywhere on a, not on its stretch. Truth in closed form: the fold is the root of
    x_b'(u); a is covered on [0.2, x_f / 10] twice, by two overlaps meeting at the fold.
    """
    d = np.array([1.0, 0.5, 0.3])[:dim] if dim == 3 else np.array([1.0, 0.0])
    o = np.array([0.2, -1.0, 0.5])[:dim] if dim == 3 else np.zeros(2)
    a = RationalBezier([o, o + 10 * d])
    b = RationalBezier([o + x * d for x in (2.0, 2.5, 14.0, 7.0)])
    t_fold = _fold_x(_FOLD_U) / 10
    want = [[(0.2, 0.0), (t_fold, _FOLD_U)], [(0.7, 1.0), (t_fold, _FOLD_U)]]  # each overlap's end nodes
    for first, second in ((a, b), (b, a)):
        got = intersect(first, second)
        assert all(isinstance(r, Overlap) for r in got), got
        ends = [sorted(zip(r.t, r.u, strict=True) if first is a else zip(r.u, r.t, strict=True)) for r in got]
        assert np.allclose(sorted(ends), want, atol=1e-9), got

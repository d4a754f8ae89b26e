"""Generate ``planar_corpus.json``: planar curve pairs with certified intersections.

The truth is built independently of relief_cad: every control point and weight
is a double, converted EXACTLY to a sympy ``Rational``; then

* curve/curve: ``N_A(t) W_B(u) - N_B(u) W_A(t) = 0`` (x and y), the resultant in
  ``u`` gives a polynomial in ``t`` whose real roots (sympy ``real_roots``,
  exact) are refined to 40 digits; each ``u`` is a common root of the two
  equations found with mpmath ``polyroots`` at 50 digits;
* curve/line: the cross product ``(A(t) - P) x D`` is one exact polynomial in ``t``;
* designed families (tangent contacts, end points, overlaps, near-misses) carry
  their closed-form answer, checked here against the resultant where it exists.

Run ``python tests/functional/make_planar_corpus.py`` to rewrite the JSON file.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import mpmath
import numpy as np
import sympy as sp

__all__ = ["build", "main"]

OUT = Path(__file__).with_name("planar_corpus.json")
T, U = sp.symbols("t u")
mpmath.mp.dps = 50


def _bern(n: int, i: int, x: sp.Symbol) -> sp.Expr:
    return sp.binomial(n, i) * x**i * (1 - x) ** (n - i)


def _exact(pts: np.ndarray, w: np.ndarray | None, x: sp.Symbol) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    n = pts.shape[0] - 1
    ww = np.ones(n + 1) if w is None else w
    nx = sum(sp.Rational(float(ww[i])) * sp.Rational(float(pts[i, 0])) * _bern(n, i, x) for i in range(n + 1))
    ny = sum(sp.Rational(float(ww[i])) * sp.Rational(float(pts[i, 1])) * _bern(n, i, x) for i in range(n + 1))
    wd = sum(sp.Rational(float(ww[i])) * _bern(n, i, x) for i in range(n + 1))
    return sp.expand(nx), sp.expand(ny), sp.expand(wd)


def _tangent_sin(a: tuple[sp.Expr, ...], b: tuple[sp.Expr, ...], t: Any, u: Any) -> float:
    def deriv(c: tuple[sp.Expr, ...], x: sp.Symbol, v: Any) -> tuple[Any, Any]:
        nx, ny, wd = c
        f = [sp.lambdify(x, e, "mpmath") for e in (nx, ny, wd, sp.diff(nx, x), sp.diff(ny, x), sp.diff(wd, x))]
        vals = [g(v) for g in f]
        px, py, w, dx, dy, dw = vals
        return (dx * w - px * dw) / w**2, (dy * w - py * dw) / w**2

    ax, ay = deriv(a, T, t)
    bx, by = deriv(b, U, u)
    la = mpmath.sqrt(ax**2 + ay**2)
    lb = mpmath.sqrt(bx**2 + by**2)
    if la == 0 or lb == 0:
        return 1.0
    return float(abs(ax * by - ay * bx) / (la * lb))


def curve_curve_truth(pa: np.ndarray, wa: np.ndarray | None, pb: np.ndarray, wb: np.ndarray | None
                      ) -> list[dict[str, Any]]:
    """Certified ``(t, u, kind)`` of every intersection (isolated points only)."""
    a = _exact(pa, wa, T)
    b = _exact(pb, wb, U)
    e1 = sp.expand(a[0] * b[2] - b[0] * a[2])
    e2 = sp.expand(a[1] * b[2] - b[1] * a[2])
    res = sp.Poly(sp.resultant(sp.Poly(e1, U), sp.Poly(e2, U)).as_expr(), T)
    if res.is_zero:
        raise ValueError("resultant vanishes (common component)")
    out: list[dict[str, Any]] = []
    troots = []
    for r in res.real_roots():
        v = mpmath.mpf(str(sp.N(r, 45)))
        if -1e-30 <= v <= 1 + 1e-30 and all(abs(v - q) > 1e-30 for q in troots):
            troots.append(v)
    for tv in troots:
        p1 = sp.Poly(e1.subs(T, sp.Float(str(tv), 50)), U)
        p2 = sp.lambdify(U, e2.subs(T, sp.Float(str(tv), 50)), "mpmath")
        coeffs = [mpmath.mpf(str(c)) for c in p1.all_coeffs()]
        while coeffs and coeffs[0] == 0:
            coeffs.pop(0)
        if len(coeffs) < 2:
            continue
        cand = mpmath.polyroots(coeffs, maxsteps=400, extraprec=400)
        seen: list[Any] = []
        for c in cand:
            if abs(mpmath.im(c)) > 1e-12:
                continue
            uv = mpmath.re(c)
            if not -1e-20 <= uv <= 1 + 1e-20:
                continue
            scale = 1 + max(abs(x) for x in coeffs)
            if abs(p2(uv)) > 1e-20 * scale:
                continue
            if any(abs(uv - s) < 1e-20 for s in seen):
                continue
            seen.append(uv)
            sn = _tangent_sin(a, b, tv, uv)
            out.append({"t": float(tv), "u": float(uv), "kind": "tangent" if sn < 1e-7 else "crossing"})
    out.sort(key=lambda r: r["t"])
    return out


def curve_line_truth(pa: np.ndarray, wa: np.ndarray | None, p: np.ndarray, d: np.ndarray
                     ) -> list[dict[str, Any]]:
    """Certified ``t`` (curve) and ``u`` (line ``p + u d``) of a curve/line pair."""
    nx, ny, wd = _exact(pa, wa, T)
    px, py = (sp.Rational(float(v)) for v in p)
    dx, dy = (sp.Rational(float(v)) for v in d)
    poly = sp.Poly(sp.expand((nx - px * wd) * dy - (ny - py * wd) * dx), T)
    out = []
    for r in poly.real_roots():
        v = sp.N(r, 45)
        if 0 <= v <= 1 and all(abs(float(v) - q["t"]) > 0 for q in out):
            x = (nx / wd).subs(T, v)
            y = (ny / wd).subs(T, v)
            u = ((x - px) * dx + (y - py) * dy) / (dx**2 + dy**2)
            out.append({"t": float(v), "u": float(sp.N(u, 30)), "kind": "crossing"})
    out.sort(key=lambda r: r["t"])
    return out


def _hex(a: np.ndarray | None) -> Any:
    return None if a is None else [[float(v).hex() for v in row] for row in np.atleast_2d(a)]


def _case(family: str, name: str, pa: np.ndarray, wa: np.ndarray | None, pb: np.ndarray,
          wb: np.ndarray | None, expected: list[dict[str, Any]], **extra: Any) -> dict[str, Any]:
    return {"family": family, "name": name, "a": _hex(pa), "wa": None if wa is None else _hex(wa)[0],
            "b": _hex(pb), "wb": None if wb is None else _hex(wb)[0], "expected": expected, **extra}


def _bernstein_of_power(coeffs: list[sp.Rational], n: int) -> list[sp.Rational]:
    """Bernstein coefficients (degree n) of ``sum coeffs[k] x^k``."""
    x = sp.symbols("x")
    poly = sum(c * x**k for k, c in enumerate(coeffs))
    out = []
    # b_i = sum_{k<=i} C(i,k)/C(n,k) a_k
    for i in range(n + 1):
        out.append(sum(sp.binomial(i, k) / sp.binomial(n, k) * sp.Poly(poly, x).coeff_monomial(x**k)
                       for k in range(i + 1)))
    return out


def build() -> list[dict[str, Any]]:
    """All corpus cases."""
    cases: list[dict[str, Any]] = []
    rng = np.random.default_rng(2024)

    # random dyadic cubic pairs
    for k in range(14):
        pa = rng.integers(0, 17, (4, 2)) / 16.0
        pb = rng.integers(0, 17, (4, 2)) / 16.0
        cases.append(_case("random cubic", f"cubic {k}", pa, None, pb, None,
                           curve_curve_truth(pa, None, pb, None)))
    # nine crossings: y = f(x) against x = f(y), f(x) = 1/2 + 25 (x - 3/20)(x - 1/2)(x - 17/20)
    xx = sp.symbols("xx")
    fx = _bernstein_of_power(sp.Poly(sp.Rational(1, 2) + 25 * (xx - sp.Rational(3, 20)) * (xx - sp.Rational(1, 2))
                                     * (xx - sp.Rational(17, 20)), xx).all_coeffs()[::-1], 3)
    x = np.arange(4) / 3.0
    pa = np.column_stack([x, [float(v) for v in fx]])
    pb = np.column_stack([[float(v) for v in fx], x])
    nine = curve_curve_truth(pa, None, pb, None)
    assert len(nine) == 9, nine
    cases.append(_case("random cubic", "nine crossings", pa, None, pb, None, nine))
    # rational pairs up to degree 4 (dyadic weights)
    for k in range(8):
        na = 2 + k % 3
        nb = 2 + (k // 2) % 3
        pa = rng.integers(0, 17, (na + 1, 2)) / 16.0
        pb = rng.integers(0, 17, (nb + 1, 2)) / 16.0
        wa = rng.integers(2, 17, na + 1) / 8.0
        wb = rng.integers(2, 17, nb + 1) / 8.0
        cases.append(_case("rational", f"rational {na}x{nb} #{k}", pa, wa, pb, wb,
                           curve_curve_truth(pa, wa, pb, wb)))
    # circle arcs (weights cos(h), rounded: the truth is for the stored doubles)
    def arc(cx: float, cy: float, r: float, a0: float, a1: float) -> tuple[np.ndarray, np.ndarray]:
        h = 0.5 * (a1 - a0)
        m = 0.5 * (a0 + a1)
        p = np.array([[cx + r * math.cos(a0), cy + r * math.sin(a0)],
                      [cx + r * math.cos(m) / math.cos(h), cy + r * math.sin(m) / math.cos(h)],
                      [cx + r * math.cos(a1), cy + r * math.sin(a1)]])
        return p, np.array([1.0, math.cos(h), 1.0])
    for k, (c2, r2, lo2, hi2) in enumerate([((0.8, 0.3), 1.1, 0.6, 3.0), ((1.2, -0.4), 0.9, 1.0, 3.5),
                                            ((-0.5, 1.5), 1.3, -1.5, 0.5)]):
        pa, wa = arc(0.0, 0.0, 1.0, 0.2, 2.6)
        pb, wb = arc(c2[0], c2[1], r2, lo2, hi2)
        cases.append(_case("arcs", f"arc-arc {k}", pa, wa, pb, wb, curve_curve_truth(pa, wa, pb, wb)))
        pl = np.array([[-1.5, -0.7 + 0.4 * k], [1.6, 1.1 - 0.3 * k]])
        cases.append(_case("arcs", f"arc-line {k}", pa, wa, pl, None, curve_curve_truth(pa, wa, pl, None)))
    # line against degree 5..20 (Chebyshev-like: y = T_n(2x - 1) in Bernstein form)
    for n in (5, 8, 12, 16, 20):
        xx = sp.symbols("xx")
        cheb = sp.Poly(sp.chebyshevt(n, 2 * xx - 1), xx)
        coeffs = [cheb.coeff_monomial(xx**k) for k in range(n + 1)]
        ys = _bernstein_of_power(coeffs, n)
        pa = np.column_stack([np.arange(n + 1) / n, [float(v) for v in ys]])
        for yl in (0.3, -0.7):
            line = np.array([[0.0, yl], [1.0, yl + 1.0 / 64]])
            # the control polygon is huge (|y| up to 7e5): pass a tolerance of the curve's size
            cases.append(_case("line vs high degree", f"chebyshev {n} line {yl}", pa, None, line, None,
                               curve_curve_truth(pa, None, line, None), tol=1e-10))
    # degree 10..15 pairs: exact degree elevation of a cubic pair (truth of the cubic pair
    # moved by the rounding of the elevated control points: compare at 1e-12)
    for deg in (10, 15):
        pa = rng.integers(0, 17, (4, 2)) / 16.0
        pb = rng.integers(0, 17, (4, 2)) / 16.0
        truth = curve_curve_truth(pa, None, pb, None)

        def elevate(p: np.ndarray, to: int) -> np.ndarray:
            q = [[sp.Rational(float(v)) for v in row] for row in p]
            while len(q) - 1 < to:
                n = len(q) - 1
                q = [q[0]] + [[sp.Rational(i, n + 1) * q[i - 1][c] + (1 - sp.Rational(i, n + 1)) * q[i][c]
                               for c in range(2)] for i in range(1, n + 1)] + [q[-1]]
            return np.array([[float(v) for v in row] for row in q])
        cases.append(_case("high degree", f"elevated cubic pair to {deg}", elevate(pa, deg), None,
                           elevate(pb, deg), None, truth, param_tol=1e-12))
    # scaled / translated copies of the first random cubic pairs
    for k in range(4):
        base = cases[k]
        pa = np.array([[float.fromhex(v) for v in r] for r in base["a"]])
        pb = np.array([[float.fromhex(v) for v in r] for r in base["b"]])
        for label, fa in (("scaled 1e-4", lambda p: p * 1e-4), ("scaled 1e5", lambda p: p * 1e5),
                          ("translated 1e4", lambda p: p + 1e4)):
            qa, qb = fa(pa), fa(pb)
            cases.append(_case("scale", f"{base['name']} {label}", qa, None, qb, None,
                               curve_curve_truth(qa, None, qb, None)))
    # designed tangent contacts (closed forms)
    par = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])   # y = 2 t (1 - t) peak 0.5 at t = 1/2
    cases.append(_case("tangent", "parabola touches line", par, None, np.array([[0.0, 0.5], [2.0, 0.5]]), None,
                       [{"t": 0.5, "u": 0.5, "kind": "tangent"}], tangent_tol=1e-7))
    cases.append(_case("tangent", "mirror parabolas", par, None, np.array([[0.0, 1.0], [1.0, 0.0], [2.0, 1.0]]),
                       None, [{"t": 0.5, "u": 0.5, "kind": "tangent"}], tangent_tol=1e-7))
    q = np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    wq = np.array([1.0, math.sqrt(0.5), 1.0])
    s2 = math.sqrt(0.5)
    cases.append(_case("tangent", "quarter circle touches line", q, wq,
                       np.array([[2 * s2 - 0.5, 0.5], [0.5, 2 * s2 - 0.5]]), None,
                       [{"t": 0.5, "u": 0.5, "kind": "tangent"}], tangent_tol=1e-7))
    cases.append(_case("tangent", "circle arcs touching outside", q, wq,
                       np.array([[2 * s2, 2 * s2 - 1.0], [2 * s2 - 1.0, 2 * s2 - 1.0], [2 * s2 - 1.0, 2 * s2]]),
                       wq, [{"t": 0.5, "u": 0.5, "kind": "tangent"}], tangent_tol=1e-7))
    cub = np.array([[-1.0, -1.0], [-1.0 / 3.0, 1.0], [1.0 / 3.0, -1.0], [1.0, 1.0]])  # y = x^3
    cases.append(_case("tangent", "osculating x^3 vs y=0", cub, None, np.array([[-1.0, 0.0], [1.0, 0.0]]), None,
                       [{"t": 0.5, "u": 0.5, "kind": "tangent"}], tangent_tol=1e-5))
    # near-tangent crossing pairs: parabola y = (2t-1)^2 against y = c (roots t = 1/2 +- sqrt(c)/2)
    pp = np.array([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]])
    for c in (2.0**-8, 2.0**-26, 2.0**-34, 2.0**-40, 2.0**-46, 2.0**-50, 2.0**-54):
        s = math.sqrt(c) / 2
        cases.append(_case("close crossings", f"two crossings c={c}", pp, None,
                           np.array([[-1.0, c], [1.0, c]]), None,
                           [{"t": 0.5 - s, "u": 0.5 - s, "kind": "crossing"},
                            {"t": 0.5 + s, "u": 0.5 + s, "kind": "crossing"}]))
    # near-tangent crossings through an inflection: y = x^3 against y = e x (x = 0, +-sqrt(e));
    # the middle crossing has angle e (down to 1e-9)
    cub3 = np.array([[-1.0, -1.0], [-1.0 / 3.0, 1.0], [1.0 / 3.0, -1.0], [1.0, 1.0]])
    for e in (2.0**-14, 2.0**-26, 2.0**-30):
        r = math.sqrt(e)
        cases.append(_case("close crossings", f"inflection crossings e={e}", cub3, None,
                           np.array([[-1.0, -e], [1.0, e]]), None,
                           [{"t": (1 - r) / 2, "u": (1 - r) / 2, "kind": "crossing"},
                            {"t": 0.5, "u": 0.5, "kind": "crossing"},
                            {"t": (1 + r) / 2, "u": (1 + r) / 2, "kind": "crossing"}]))
    # near misses
    for gap, expect in ((1e-6, []), (1e-10, [{"t": 0.5, "u": 0.5, "kind": "tangent"}])):
        cases.append(_case("near miss", f"parabola vs line gap {gap}", par, None,
                           np.array([[0.0, 0.5 + gap], [2.0, 0.5 + gap]]), None, expect, tangent_tol=1e-4))
    # shared end points
    c3 = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 1.0]])
    cases.append(_case("end points", "end to end", c3, None, np.array([[3.0, 1.0], [4.0, 0.0], [5.0, 2.0]]), None,
                       [{"t": 1.0, "u": 0.0, "kind": "crossing"}], exact_ends=True))
    cases.append(_case("end points", "T-junction", np.array([[0.0, 0.0], [2.0, 2.0]]), None,
                       np.array([[1.0, 1.0], [2.0, 0.0]]), None, [{"t": 0.5, "u": 0.0, "kind": "crossing"}],
                       exact_ends=True))
    cases.append(_case("end points", "G1 continuation", np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]]), None,
                       np.array([[2.0, 1.0], [3.0, 1.0], [4.0, 0.0]]), None,
                       [{"t": 1.0, "u": 0.0, "kind": "tangent"}], exact_ends=True))
    cases.append(_case("end points", "fold-back", np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0]]), None,
                       np.array([[2.0, 1.0], [1.0, 1.0], [0.5, 0.0]]), None,
                       [{"t": 1.0, "u": 0.0, "kind": "tangent"}], exact_ends=True))
    s2s = np.array([[0.0, 0.0], [1.0, -1.0], [2.0, 1.0]])
    cases.append(_case("end points", "start to start", c3, None, s2s, None,
                       curve_curve_truth(c3, None, s2s, None), exact_ends=True))
    cases.append(_case("end points", "T-junction cubic on line", np.array([[0.0, 3.0], [1.0, 2.0], [1.5, 2.5], [2.0, 1.0]]),
                       None, np.array([[0.0, 0.0], [4.0, 2.0]]), None,
                       curve_curve_truth(np.array([[0.0, 3.0], [1.0, 2.0], [1.5, 2.5], [2.0, 1.0]]), None,
                                         np.array([[0.0, 0.0], [4.0, 2.0]]), None), exact_ends=True))
    g1a = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 1.0]])
    g1b = np.array([[3.0, 1.0], [4.0, 0.0], [5.0, 1.0], [6.0, 0.0]])
    cases.append(_case("end points", "G1 cubics", g1a, None, g1b, None,
                       [{"t": 1.0, "u": 0.0, "kind": "tangent"}], exact_ends=True))
    # more random rational pairs (non-dyadic weights)
    for k in range(6):
        na = 2 + k % 3
        nb = 4 - k % 3
        pa = rng.random((na + 1, 2))
        pb = rng.random((nb + 1, 2))
        wa = rng.uniform(0.3, 3.0, na + 1)
        wb = rng.uniform(0.3, 3.0, nb + 1)
        cases.append(_case("rational", f"rational random {na}x{nb} #{k}", pa, wa, pb, wb,
                           curve_curve_truth(pa, wa, pb, wb)))
    # overlaps (dyadic sub-segments are exact)
    cub4 = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, -1.0], [4.0, 2.0]])

    def seg(p: np.ndarray, t0: float, t1: float) -> np.ndarray:
        q = [[sp.Rational(float(v)) for v in row] for row in p]
        n = len(q) - 1
        out = []
        for i in range(n + 1):
            # blossom with i copies of t1 and n - i copies of t0
            args = [sp.Rational(t1)] * i + [sp.Rational(t0)] * (n - i)
            pts = [list(r) for r in q]
            for r, a in enumerate(args, start=1):
                pts = [[(1 - a) * pts[j][c] + a * pts[j + 1][c] for c in range(2)] for j in range(n + 1 - r)]
            out.append([float(v) for v in pts[0]])
        return np.array(out)
    cases.append(_case("overlap", "sub-segment", cub4, None, seg(cub4, 0.25, 0.75), None,
                       [{"overlap": [[0.25, 0.75], [0.0, 1.0]]}]))
    cases.append(_case("overlap", "reversed sub-segment", cub4, None, seg(cub4, 0.75, 0.25), None,
                       [{"overlap": [[0.25, 0.75], [1.0, 0.0]]}]))
    cases.append(_case("overlap", "partial", seg(cub4, 0.0, 0.5), None, seg(cub4, 0.25, 1.0), None,
                       [{"overlap": [[0.5, 1.0], [0.0, 1.0 / 3.0]]}]))
    cases.append(_case("overlap", "collinear lines", np.array([[0.0, 0.0], [2.0, 1.0]]), None,
                       np.array([[1.0, 0.5], [4.0, 2.0]]), None, [{"overlap": [[0.5, 1.0], [0.0, 1.0 / 3.0]]}]))
    cases.append(_case("overlap", "coincident arcs (Möbius)", q, wq,
                       np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]), np.array([1.0, 2 * s2, 4.0]),
                       [{"overlap": [[0.0, 1.0], [0.0, 1.0]]}]))
    # overlap plus crossing: two pieces of one loop cubic c, a = c[0, 5/8], b = c[3/8, 1]
    loop = np.array([[0.0, 0.0], [5.0, 4.0], [-1.0, 4.0], [4.0, 0.0]])
    s1, s2_ = sp.symbols("s1 s2")
    cx, cy, _w = _exact(loop, None, T)
    gx = sp.cancel((cx.subs(T, s1) - cx.subs(T, s2_)) / (s1 - s2_))
    gy = sp.cancel((cy.subs(T, s1) - cy.subs(T, s2_)) / (s1 - s2_))
    sols = [sol for sol in sp.solve([gx, gy], [s1, s2_], dict=True)
            if all(v.is_real for v in sol.values())]
    dp = sorted(float(sp.N(v, 30)) for v in sols[0].values())
    cases.append(_case("overlap", "overlap plus crossing", seg(loop, 0.0, 0.625), None, seg(loop, 0.375, 1.0),
                       None, [{"overlap": [[0.6, 1.0], [0.0, 0.4]]},
                              {"t": dp[0] / 0.625, "u": (dp[1] - 0.375) / 0.625, "kind": "crossing"}],
                       double_point=dp))
    return cases


def main() -> None:
    cases = build()
    OUT.write_text(json.dumps(cases, indent=1))
    print(f"wrote {len(cases)} cases to {OUT}")


if __name__ == "__main__":
    main()

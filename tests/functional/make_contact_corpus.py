"""Generate ``contact_corpus.json``: contact families with truth certified by construction.

Every case is built so that its answer is known exactly, independently of relief_cad:

* **mirror tangencies** (dyadic data): ``a`` has ``y(t) - c = K (t - t0)^2 q(t)`` with dyadic
  roots, ``b`` is its mirror image about ``y = c`` with the same weights; ``x`` is monotone, so
  they meet exactly at the roots (``u = t``): ``t0`` a tangency, the roots of ``q`` crossings;
* **osculating contacts**: ``(t - t0)^3`` and ``(t - t0)^4`` factors against the line ``y = c``
  and against the mirror image;
* **circle arcs** touching at the rational point ``(5, 0)`` (weights ``5, 4, 5``: exact);
* **G1 fold-backs**: ``b`` starts at ``a(1)`` with the opposite tangent, on the other side;
* **doubled end control points**: straight and curved cubics against themselves, reversed
  copies, lines and sub-segments (one ``Overlap`` with exact ends);
* **end meetings at every angle** of curves with zero end derivatives (rays in disjoint cones);
* **end tangencies** (the slow family): curves leaving one point in one direction, one on each
  side of the common tangent, or nested parabolas;
* **curves against themselves** (200 seeded random curves, degree 2-7, dyadic control points),
  reversed and degree-elevated: one ``Overlap``;
* **retracing curves**: self-overlaps (``b`` is ``null``: the self-intersection of ``a``);
* **Chebyshev-like curves** of degree 25-40 against lines: the exact polynomial of the stored
  doubles, real roots isolated by sympy to 40 digits.

Run ``python tests/functional/make_contact_corpus.py`` to rewrite the JSON file.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np
import sympy as sp

OUT = Path(__file__).with_name("contact_corpus.json")
T = sp.symbols("t")


def _hex(rows: Any) -> list[list[str]] | list[str]:
    arr = np.asarray(rows, dtype=float)
    if arr.ndim == 1:
        return [float(v).hex() for v in arr]
    return [[float(v).hex() for v in r] for r in arr]


def _case(family: str, name: str, a: Any, b: Any, expected: list[dict[str, Any]], wa: Any = None,
          wb: Any = None, **extra: Any) -> dict[str, Any]:
    case = {"family": family, "name": name, "a": _hex(a), "wa": None if wa is None else _hex(wa),
            "b": None if b is None else _hex(b), "wb": None if wb is None else _hex(wb),
            "expected": expected, "exact_ends": True}
    case.update(extra)
    return case


def _pt(t: Any, u: Any, kind: str) -> dict[str, Any]:
    return {"t": float(t), "u": float(u), "kind": kind, "exact": [str(t), str(u)]}


def _ov(t: tuple[Any, Any], u: tuple[Any, Any]) -> dict[str, Any]:
    return {"overlap": [[float(t[0]), float(t[1])], [float(u[0]), float(u[1])]]}


def _bernstein(poly: sp.Expr, n: int) -> list[Fraction]:
    """Exact Bernstein coefficients of degree ``n`` of a polynomial in ``T``."""
    p = sp.Poly(sp.expand(poly), T)
    pw = [sp.Rational(p.coeff_monomial(T**k)) for k in range(n + 1)]
    out = []
    for i in range(n + 1):
        s = sum(sp.Rational(math.comb(i, k), math.comb(n, k)) * pw[k] for k in range(i + 1))
        out.append(Fraction(int(s.p), int(s.q)))
    return out


def _dyadic(values: list[Fraction]) -> bool:
    return all(v.denominator & (v.denominator - 1) == 0 for v in values)


def _lcm_scale(values: list[Fraction]) -> int:
    m = 1
    for v in values:
        d = v.denominator
        while d % 2 == 0:
            d //= 2
        m = m * d // math.gcd(m, d)
    return m


# ---------------------------------------------------------------------------- families
def mirror_family() -> list[dict[str, Any]]:
    rng = np.random.default_rng(12)
    cases = []
    specs = [  # (double root t0, simple roots, degree, contact power)
        (Fraction(1, 2), [], 3, 2), (Fraction(3, 8), [Fraction(3, 4)], 3, 2),
        (Fraction(5, 8), [Fraction(1, 8), Fraction(7, 8)], 4, 2),
        (Fraction(1, 2), [Fraction(1, 8), Fraction(3, 16), Fraction(7, 8)], 5, 2),
        (Fraction(9, 16), [Fraction(1, 4), Fraction(13, 16), Fraction(15, 16)], 6, 2),
        (Fraction(1, 4), [Fraction(1, 2), Fraction(3, 4), Fraction(7, 8)], 5, 2),
        (Fraction(1, 2), [], 3, 3), (Fraction(3, 8), [Fraction(7, 8)], 4, 3),
        (Fraction(1, 2), [], 4, 4), (Fraction(5, 8), [Fraction(1, 4)], 5, 4),
    ]
    for k, (t0, roots, n, power) in enumerate(specs):
        poly = (T - sp.Rational(t0.numerator, t0.denominator)) ** power
        for r in roots:
            poly *= T - sp.Rational(r.numerator, r.denominator)
        coeffs = _bernstein(poly, n)
        scale = Fraction(_lcm_scale(coeffs), 1) * 4
        coeffs = [c * scale for c in coeffs]
        assert _dyadic(coeffs)
        mx = max(abs(c) for c in coeffs)
        coeffs = [c / (2 ** math.ceil(math.log2(mx))) for c in coeffs]  # exact: a power of two
        xs = np.sort(rng.integers(0, 64, n + 1)) / 64.0
        xs[-1] = xs[-1] + 1.0
        xs = np.cumsum(np.diff(np.concatenate([[0.0], xs])) + 1 / 16)  # strictly increasing, dyadic
        rational = k % 2 == 1
        w = np.array([2.0 ** int(e) for e in rng.integers(-1, 2, n + 1)]) if rational else None
        for variant, (sc, dx, dy) in enumerate([(1.0, 0.0, 0.25), (2.0**-6, 3.5, -1.0), (2.0**7, -96.0, 40.0)]):
            c = Fraction(dy)
            ya = [float(c + (cf / Fraction(float(w[i])) if w is not None else cf)) for i, cf in enumerate(coeffs)]
            yb = [float(c - (cf / Fraction(float(w[i])) if w is not None else cf)) for i, cf in enumerate(coeffs)]
            pa = np.column_stack([xs * sc + dx, np.array(ya) * sc])
            pb = np.column_stack([xs * sc + dx, np.array(yb) * sc])
            assert all(Fraction(v) - c == (cf / Fraction(float(w[i])) if w is not None else cf)
                       for i, (v, cf) in enumerate(zip(ya, coeffs)))
            kind0 = "tangent"
            exp = [_pt(t0, t0, kind0)] + [_pt(r, r, "crossing") for r in roots]
            exp.sort(key=lambda e: e["t"])
            fam = "mirror tangency" if power == 2 else "osculating mirror"
            cases.append(_case(fam, f"{fam} {k}.{variant} (deg {n}, contact order {power})", pa, pb,
                               exp, w, w))
        if power >= 3:  # the same curve against the line y = c
            line = np.array([[xs[0] - 0.5, 0.25], [xs[-1] + 0.5, 0.25]])
            ya = [float(Fraction(0.25) + (cf / Fraction(float(w[i])) if w is not None else cf))
                  for i, cf in enumerate(coeffs)]
            pa = np.column_stack([xs, ya])
            exp = []
            for r in sorted([t0, *roots]):
                x = _x_exact(xs, w, r)
                u = (x - Fraction(line[0, 0])) / (Fraction(line[1, 0]) - Fraction(line[0, 0]))
                exp.append(_pt(r, u, "tangent" if r == t0 else "crossing"))
            cases.append(_case("osculating line", f"osculating line {k} (deg {n}, order {power})", pa, line,
                               exp, w, None))
    return cases


def _x_exact(xs: np.ndarray, w: np.ndarray | None, t: Fraction) -> Fraction:
    n = len(xs) - 1
    ww = [Fraction(1)] * (n + 1) if w is None else [Fraction(float(v)) for v in w]
    num = sum(ww[i] * Fraction(float(xs[i])) * math.comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))
    den = sum(ww[i] * math.comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1))
    return num / den


def circle_family() -> list[dict[str, Any]]:
    w = [5.0, 4.0, 5.0]  # cos(alpha) = 4/5 scaled by 5: exact
    big = np.array([[4.0, -3.0], [6.25, 0.0], [4.0, 3.0]])          # circle r = 5 about (0, 0)
    outer = np.array([[6.0, -3.0], [3.75, 0.0], [6.0, 3.0]])        # circle r = 5 about (10, 0)
    inner = np.array([[4.5, -1.5], [5.625, 0.0], [4.5, 1.5]])       # circle r = 5/2 about (5/2, 0)
    cases = []
    for name, other in (("external", outer), ("internal", inner)):
        for v, (sc, dx, dy, rot) in enumerate([(1.0, 0.0, 0.0, False), (2.0**-10, 0.5, 0.25, False),
                                               (2.0**12, 1024.0, -4096.0, False), (1.0, 0.0, 0.0, True)]):
            def tr(p: np.ndarray, sc: float = sc, dx: float = dx, dy: float = dy, rot: bool = rot) -> np.ndarray:
                q = p[:, ::-1] * np.array([-1.0, 1.0]) if rot else p  # a quarter turn: exact
                return q * sc + np.array([dx, dy])
            cases.append(_case("circle tangency", f"circle {name} {v}", tr(big), tr(other),
                               [_pt(Fraction(1, 2), Fraction(1, 2), "tangent")], w, w))
    return cases


def foldback_family() -> list[dict[str, Any]]:
    cases = []
    pairs = [
        ([[0, 0], [1, 1], [2, 1]], [[2, 1], [1, 1], [1, 2]], None, None),
        ([[0, 0], [1, 1], [2, 1], [2, 1]], [[2, 1], [2, 1], [1, 1], [1, 2]], None, None),
        ([[0, 0], [0.5, 1], [1.5, 1], [2, 1]], [[2, 1], [1, 1], [0.5, 1.5], [0, 3]], None, None),
        ([[0, 0], [1, 1], [2, 1]], [[2, 1], [1, 1], [1, 2]], [1, 2, 1], [1, 0.5, 1]),
    ]
    for k, (a, b, wa, wb) in enumerate(pairs):
        for v, sc in enumerate((1.0, 2.0**-20, 2.0**30)):
            cases.append(_case("G1 fold-back", f"fold-back {k}.{v}", np.array(a) * sc, np.array(b) * sc,
                               [_pt(1, 0, "tangent")], wa, wb))
    return cases


def doubled_family() -> list[dict[str, Any]]:
    straight = np.array([[0, 0], [0, 0], [1, 1], [1, 1]], dtype=float)
    curved = np.array([[0, 0], [0, 0], [1, 2], [2, 0]], dtype=float)
    both = np.array([[0, 0], [0, 0], [1, 2], [2, 0], [2, 0]], dtype=float)
    cases = []
    for name, c in (("straight", straight), ("curved", curved), ("curved both ends", both)):
        for v, (sc, off) in enumerate(((1.0, 0.0), (2.0**-16, 3.0), (2.0**20, -2.0**22))):
            p = c * sc + off
            cases.append(_case("doubled end points", f"{name} {v} vs itself", p, p, [_ov((0, 1), (0, 1))]))
            cases.append(_case("doubled end points", f"{name} {v} vs reversed", p, p[::-1], [_ov((0, 1), (1, 0))]))
    line = np.array([[0, 0], [1, 1]], dtype=float)
    even = np.array([[0, 0], [1 / 4, 1 / 4], [1 / 2, 1 / 2], [3 / 4, 3 / 4], [1, 1]])
    cases.append(_case("doubled end points", "straight vs line", straight, line, [_ov((0, 1), (0, 1))]))
    cases.append(_case("doubled end points", "straight vs evenly spaced quartic", straight, even,
                       [_ov((0, 1), (0, 1))]))
    cases.append(_case("doubled end points", "straight 3D vs itself", np.column_stack([straight, straight[:, 0]]),
                       np.column_stack([straight, straight[:, 0]]), [_ov((0, 1), (0, 1))]))
    # sub-segments: the straight cubic is x(t) = 3t^2 - 2t^3; its piece over [1/2, 1] by blossoming
    sub = _segment_exact(straight, Fraction(1, 2), Fraction(1))
    cases.append(_case("doubled end points", "straight vs its half", straight, sub, [_ov((0.5, 1), (0, 1))]))
    csub = _segment_exact(curved, Fraction(1, 4), Fraction(3, 4))
    cases.append(_case("doubled end points", "curved vs its middle", curved, csub, [_ov((0.25, 0.75), (0, 1))]))
    cases.append(_case("doubled end points", "curved vs its middle reversed", curved, csub[::-1],
                       [_ov((0.25, 0.75), (1, 0))]))
    return cases


def _segment_exact(p: np.ndarray, a: Fraction, b: Fraction) -> np.ndarray:
    """Polynomial piece over ``[a, b]`` by exact blossoming (asserts the result is dyadic)."""
    n = p.shape[0] - 1
    rows = []
    for i in range(n + 1):
        args = [a] * (n - i) + [b] * i
        pts = [[Fraction(float(v)) for v in r] for r in p]
        for level, s in enumerate(args):
            pts = [[(1 - s) * pts[j][d] + s * pts[j + 1][d] for d in range(p.shape[1])]
                   for j in range(n - level)]
        rows.append(pts[0])
    assert _dyadic([v for r in rows for v in r])
    return np.array([[float(v) for v in r] for r in rows])


def end_angle_family() -> list[dict[str, Any]]:
    cases = []
    ray = np.array([[0, 0], [0, 0], [1, 0], [1, 0]], dtype=float)
    for deg in range(5, 181, 5):
        th = math.radians(deg)
        rot = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
        b = ray @ rot.T
        b[:2] = 0.0
        kind = "tangent" if deg == 180 else "crossing"
        cases.append(_case("end angle", f"rays at {deg} deg", ray, b, [_pt(0, 0, kind)]))
        cases.append(_case("end angle", f"rays at {deg} deg, b reversed", ray, b[::-1], [_pt(0, 1, kind)]))
    cone = np.array([[0, 0], [0, 0], [1, 0], [1, 0.125]])  # within polar angles [0, 7.2] deg
    for deg in range(20, 181, 10):
        th = math.radians(deg)
        rot = np.array([[math.cos(th), -math.sin(th)], [math.sin(th), math.cos(th)]])
        b = (cone * np.array([1.0, -1.0])) @ rot.T  # within [deg - 7.2, deg]
        b[:2] = 0.0
        kind = "tangent" if deg == 180 else "crossing"  # at 180 deg: a fold-back
        cases.append(_case("end angle", f"curved at {deg} deg", cone, b, [_pt(0, 0, kind)]))
    return cases


def end_tangent_family() -> list[dict[str, Any]]:
    cases = []
    pairs = [([[0, 0], [1, 0], [2, 1], [3, 3]], [[0, 0], [1, 0], [2, -1], [3, -2]]),
             ([[0, 0], [1, 0], [2, 1]], [[0, 0], [1, 0], [2, 2]]),
             ([[0, 0], [1, 0], [2, 1], [3, 1]], [[0, 0], [2, 0], [3, -1], [3, -3]]),
             ([[0, 0], [1, 0], [2, 0.5], [3, 2]], [[0, 0], [0.5, 0], [1, -0.5], [3, -1]])]
    for k, (a, b) in enumerate(pairs):
        for v, sc in enumerate((1.0, 2.0**-12, 2.0**14)):
            cases.append(_case("end tangency", f"end tangency {k}.{v}", np.array(a) * sc,
                               np.array(b) * sc, [_pt(0, 0, "tangent")]))
    return cases


def self_family() -> list[dict[str, Any]]:
    rng = np.random.default_rng(2026)
    cases = []
    for k in range(200):
        n = int(rng.integers(2, 8))
        p = rng.integers(0, 65, size=(n + 1, 2)) / 64.0
        if np.ptp(p, axis=0).max() == 0.0:
            continue
        cases.append(_case("self overlap", f"random {k} (deg {n}) vs itself", p, p, [_ov((0, 1), (0, 1))]))
        if k % 2 == 0:
            cases.append(_case("self overlap", f"random {k} vs reversed", p, p[::-1], [_ov((0, 1), (1, 0))]))
        else:
            el = _elevate_exact(p)
            cases.append(_case("self overlap", f"random {k} vs elevated", p, el, [_ov((0, 1), (0, 1))],
                               elevated_exact=_dyadic([Fraction(v) for v in el.ravel()])))
    specials = {"loop": [[0, 0], [3, 3], [-1, 3], [2, 0]], "cusp": [[0, 0], [1, 1], [0, 1], [1, 0]],
                "near cusp": [[0, 0], [1, 1], [0.015625, 1], [1, 0]]}
    for name, pts in specials.items():
        p = np.array(pts, dtype=float)
        cases.append(_case("self overlap", f"{name} vs itself", p, p, [_ov((0, 1), (0, 1))]))
        cases.append(_case("self overlap", f"{name} vs reversed", p, p[::-1], [_ov((0, 1), (1, 0))]))
    return cases


def _elevate_exact(p: np.ndarray) -> np.ndarray:
    n = p.shape[0] - 1
    q = [p[0]] + [(i / (n + 1)) * p[i - 1] + (1 - i / (n + 1)) * p[i] for i in range(1, n + 1)] + [p[n]]
    return np.array(q)


def retrace_family() -> list[dict[str, Any]]:
    third = Fraction(1, 3)
    return [
        _case("retrace", "out and back (2D)", [[0, 0], [1, 1], [1, 1], [0, 0]], None,
              [_ov((0, 0.5), (1, 0.5))]),
        _case("retrace", "out and back (3D)", [[0, 0, 0], [1, 1, 1], [1, 1, 1], [0, 0, 0]], None,
              [_ov((0, 0.5), (1, 0.5))]),
        _case("retrace", "fold vs itself", [[0, 0], [2, 0], [1, 0]], [[0, 0], [2, 0], [1, 0]],
              [_ov((0, 1), (0, 1))]),
        # x(t) = 4t - 3t^2: x(t) = x(u) for t + u = 4/3; the fold is at t = 2/3
        _case("retrace", "fold self-overlap", [[0, 0], [2, 0], [1, 0]], None,
              [_ov((float(third), 2 / 3), (1, 2 / 3))], overlap_tol=1e-12),
    ]


def chebyshev_family() -> list[dict[str, Any]]:
    cases = []
    for n, scale, level in ((25, 1.0, 0.1), (32, 0.00428, -0.000188), (32, 1.0, 0.3), (40, 1.0, -0.05),
                            (36, 0.5, 0.01)):
        poly = sp.chebyshevt(n, 2 * T - 1)
        coeffs = [float(c) * scale for c in _bernstein(poly, n)]
        xs = np.array([-1.0 + 2.0 * i / n for i in range(n + 1)])
        pa = np.column_stack([xs, coeffs])
        line = np.array([[-1.5, level], [1.5, level]])
        ypoly = sum(sp.Rational(coeffs[i]) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1))
        xpoly = sum(sp.Rational(float(xs[i])) * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i in range(n + 1))
        p = sp.Poly(sp.expand(ypoly - sp.Rational(level)), T)
        exp = []
        for (lo, hi), _mult in p.intervals(eps=sp.Rational(1, 10**40), inf=0, sup=1):
            t = (lo + hi) / 2
            x = xpoly.subs(T, t)
            u = (x + sp.Rational(3, 2)) / 3
            exp.append({"t": float(t), "u": float(u), "kind": "crossing"})
        cases.append(_case("chebyshev", f"T{n} x {scale} vs y = {level}", pa, line, exp,
                           exact_ends=False, crossings=len(exp)))
    return cases


def build() -> list[dict[str, Any]]:
    """Every case of the corpus."""
    return (mirror_family() + circle_family() + foldback_family() + doubled_family() + end_angle_family()
            + end_tangent_family() + self_family() + retrace_family() + chebyshev_family())


def main() -> None:
    """Rewrite ``contact_corpus.json``."""
    cases = build()
    OUT.write_text(json.dumps(cases, indent=0) + "\n")
    print(f"{len(cases)} cases -> {OUT}")


if __name__ == "__main__":
    main()

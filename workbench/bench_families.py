"""Benchmark: worst time per contact family (the corner cases of issue 12), relief_cad vs OCCT.

The families are those of ``tests/functional/contact_corpus.json`` (mirror and circle
tangencies, osculations, fold-backs, doubled end control points, end meetings at every angle,
end tangencies, curves against themselves, retracing curves, Chebyshev-like curves). For every
pair both relief_cad's :func:`~relief_cad.intersect` and OCCT's ``Geom2dInt_GInter`` run on the
same curves in the same process (best of ``repeat`` runs each); the table gives per family the
median and the WORST relief_cad time, the case that was worst, the worst time among the family's
cubic cases (every curve of degree at most 3: issue 12's goal is under 1 ms), and the median and
worst ratio relief/OCCT (below 1 = relief_cad faster). Self-intersection cases have no OCCT figure.

Run ``python -m workbench.bench_families``; :func:`run` returns the table as a dict.
"""

from __future__ import annotations

import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from relief_cad.curves import RationalBezier
from relief_cad.intersection import intersect

from .bench_planar import occt_curve, occt_intersect

__all__ = ["CORPUS", "run"]

OCCT_MAX_DEGREE = 25  # Geom2d_BezierCurve refuses higher degrees (Standard_OutOfRange)

CORPUS = Path(__file__).resolve().parents[1] / "tests" / "functional" / "contact_corpus.json"


def _curve(rows: list[list[str]], w: list[str] | None) -> RationalBezier:
    pts = np.array([[float.fromhex(v) for v in r] for r in rows])
    return RationalBezier(pts, None if w is None else np.array([float.fromhex(v) for v in w]))


def _best(fn: Callable[[], Any], repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def _fresh_best(case: dict[str, Any], repeat: int) -> float:
    """Best of ``repeat`` relief_cad runs, each on curves built anew.

    What a curve caches (its hodograph) is then paid in every timed run, as in a first call.
    """
    best = float("inf")
    for _ in range(repeat):
        a = _curve(case["a"], case["wa"])
        b = None if case["b"] is None else _curve(case["b"], case["wb"])
        t0 = time.perf_counter()
        intersect(a, b, on_budget="return")
        best = min(best, time.perf_counter() - t0)
    return best


def _is_cubic(case: dict[str, Any]) -> bool:
    """Every curve of the case of degree at most 3."""
    return len(case["a"]) <= 4 and (case["b"] is None or len(case["b"]) <= 4)


def _time_case(case: dict[str, Any], repeat: int) -> tuple[float, float | None]:
    ours = _fresh_best(case, repeat)
    a = _curve(case["a"], case["wa"])
    if case["b"] is None:
        return ours, None
    b = _curve(case["b"], case["wb"])
    if a.dim != 2 or max(a.degree, b.degree) > OCCT_MAX_DEGREE:
        return ours, None
    ca, cb = occt_curve(a), occt_curve(b)
    return ours, _best(lambda: occt_intersect(ca, cb), repeat)


def run(repeat: int = 3) -> dict[str, Any]:
    """Time every corpus case; returns ``{family: {n, median_us, worst_us, worst_case, ...}}``."""
    if not CORPUS.exists():
        raise FileNotFoundError(f"the contact corpus should be at {CORPUS}; it is missing")
    cases = json.loads(CORPUS.read_text())
    rows: dict[str, list[tuple[str, float, float | None, bool]]] = {}
    for case in cases:
        ours, occt = _time_case(case, repeat)
        rows.setdefault(case["family"], []).append((case["name"], ours, occt, _is_cubic(case)))
    table: dict[str, Any] = {}
    for fam, items in rows.items():
        times = np.array([t for _, t, _, _ in items])
        worst = int(np.argmax(times))
        ratios = np.array([t / o for _, t, o, _ in items if o])
        cubic = [t for _, t, _, c in items if c]
        table[fam] = {
            "n": len(items),
            "median_us": float(np.median(times) * 1e6),
            "worst_us": float(times[worst] * 1e6),
            "worst_case": items[worst][0],
            "worst_cubic_us": max(cubic) * 1e6 if cubic else None,
            "median_ratio": float(np.median(ratios)) if ratios.size else None,
            "worst_ratio": float(ratios.max()) if ratios.size else None,
        }
    return table


def _main() -> None:
    table = run()
    head = (f"{'family':22} {'n':>4} {'median us':>10} {'worst us':>10} {'cubic max':>10} "
            f"{'ratio med':>9} {'ratio max':>9}")
    print(head + "  worst case")
    for fam, r in table.items():
        med = "-" if r["median_ratio"] is None else f"{r['median_ratio']:.2f}"
        mx = "-" if r["worst_ratio"] is None else f"{r['worst_ratio']:.2f}"
        cub = "-" if r["worst_cubic_us"] is None else f"{r['worst_cubic_us']:.1f}"
        print(f"{fam:22} {r['n']:4d} {r['median_us']:10.1f} {r['worst_us']:10.1f} {cub:>10} {med:>9} "
              f"{mx:>9}  {r['worst_case']}")


if __name__ == "__main__":
    _main()

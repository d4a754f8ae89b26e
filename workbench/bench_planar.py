"""Benchmark: relief_cad's planar intersector against OCCT's ``Geom2dInt_GInter``.

Both run on the SAME curves in one process; OCCT curves are built directly with
OCP (``Geom2d_BezierCurve`` from ``TColgp_Array1OfPnt2d`` poles and
``TColStd_Array1OfReal`` weights, wrapped in ``Geom2dAdaptor_Curve``). The OCCT
timing includes building the intersector and reading every point (what a caller
pays); the relief_cad timing includes building the result objects.

Run ``python -m workbench.bench_planar`` for the table; :func:`run` returns it as a
dict.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Callable
from functools import partial
from typing import Any

import numpy as np

from relief_cad.clipping import intersect_packed
from relief_cad.curves import RationalBezier
from relief_cad.intersection import intersect, intersect_many

__all__ = ["cases", "occt_curve", "occt_intersect", "run"]

OCCT_TOL = 1e-9


def occt_curve(c: RationalBezier) -> Any:
    """The OCCT 2D adaptor of a planar :class:`RationalBezier`."""
    from OCP.Geom2d import Geom2d_BezierCurve
    from OCP.Geom2dAdaptor import Geom2dAdaptor_Curve
    from OCP.gp import gp_Pnt2d

    from relief_cad.cad._compat import Array1OfPnt2d, Array1OfReal

    pts = c.control_points
    poles = Array1OfPnt2d(1, pts.shape[0])
    for i, (x, y) in enumerate(pts.tolist()):
        poles.SetValue(i + 1, gp_Pnt2d(x, y))
    if c.is_polynomial:
        geom = Geom2d_BezierCurve(poles)
    else:
        w = Array1OfReal(1, pts.shape[0])
        for i, wi in enumerate(c.weights.tolist()):
            w.SetValue(i + 1, wi)
        geom = Geom2d_BezierCurve(poles, w)
    return Geom2dAdaptor_Curve(geom)


def occt_intersect(
    ca: Any, cb: Any, tol: float = OCCT_TOL, min_samples: int | None = None
) -> list[tuple[float, float]]:
    """``(t, u)`` of every point OCCT's ``Geom2dInt_GInter`` finds (segments give their ends)."""
    from OCP.Geom2dInt import Geom2dInt_GInter

    inter = Geom2dInt_GInter()
    if min_samples is not None:
        inter.SetMinNbSamples(min_samples)
    inter.Perform(ca, cb, tol, tol)
    out = []
    for i in range(1, inter.NbPoints() + 1):
        p = inter.Point(i)
        out.append((p.ParamOnFirst(), p.ParamOnSecond()))
    for i in range(1, inter.NbSegments() + 1):
        s = inter.Segment(i)
        if s.HasFirstPoint():
            out.append((s.FirstPoint().ParamOnFirst(), s.FirstPoint().ParamOnSecond()))
        if s.HasLastPoint():
            out.append((s.LastPoint().ParamOnFirst(), s.LastPoint().ParamOnSecond()))
    return out


def _random_cubic_pairs(n: int, seed: int = 1) -> list[tuple[RationalBezier, RationalBezier]]:
    rng = np.random.default_rng(seed)
    return [(RationalBezier(rng.random((4, 2))), RationalBezier(rng.random((4, 2)))) for _ in range(n)]


def _arc(cx: float, cy: float, r: float, a0: float, a1: float) -> RationalBezier:
    """A circle arc (opening < pi) as a rational quadratic."""
    h = 0.5 * (a1 - a0)
    m = 0.5 * (a0 + a1)
    p0 = (cx + r * np.cos(a0), cy + r * np.sin(a0))
    p2 = (cx + r * np.cos(a1), cy + r * np.sin(a1))
    p1 = (cx + r * np.cos(m) / np.cos(h), cy + r * np.sin(m) / np.cos(h))
    return RationalBezier([p0, p1, p2], [1.0, float(np.cos(h)), 1.0])


def cases() -> dict[str, list[tuple[RationalBezier, RationalBezier]]]:
    """The benchmark cases: name -> list of pairs."""
    out: dict[str, list[tuple[RationalBezier, RationalBezier]]] = {}
    out["cubic x1"] = [(RationalBezier([[0, 0], [1, 2], [2, 2], [3, 0]]),
                        RationalBezier([[1.5, -0.5], [1.2, 0.5], [1.8, 1.5], [1.5, 2.5]]))]
    # y = f(x) against x = f(y), f(x) = 1/2 + 25 (x - 0.15)(x - 0.5)(x - 0.85): nine crossings
    f9 = [-1.09375, 4.135416666666667, -3.1354166666666665, 2.09375]
    x3 = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    out["cubic x9"] = [(RationalBezier(np.column_stack([x3, f9])), RationalBezier(np.column_stack([f9, x3])))]
    out["arcs x2"] = [(_arc(0, 0, 1, 0.2, 2.6), _arc(0.3, 1.3, 1, np.pi + 0.3, 2 * np.pi - 0.3))]
    # graph of T_7(2x - 1) (Bernstein ordinates) against a straight degree-7 curve: seven crossings
    t7 = [-1.0, 13.0, -47.666666666666664, 85.8, -85.8, 47.666666666666664, -13.0, 1.0]
    xs = np.linspace(0, 1, 8)
    out["degree 7 x7"] = [(RationalBezier(np.column_stack([xs, t7])),
                           RationalBezier(np.column_stack([xs, 0.05 + 0.1 * xs])))]
    out["disjoint, boxes overlap"] = [
        (
            RationalBezier([[0, 0], [1, 2], [2, 2], [3, 0]]),
            RationalBezier([[0.5, 0.2], [1.2, 1.2], [1.8, 1.2], [2.5, 0.2]]),
        )
    ]
    out["near-tangent"] = [
        (RationalBezier([[0, 0], [1, 1], [2, 0]]), RationalBezier([[0, 0.5 - 1e-7], [2, 0.5 - 1e-7 + 1e-9]]))
    ]
    out["1000 random cubics"] = _random_cubic_pairs(1000)
    return out


def _each(fn: Callable[[Any, Any], Any], pairs: list[tuple[Any, Any]]) -> list[Any]:
    """``fn(a, b)`` for every pair, in order."""
    return [fn(a, b) for a, b in pairs]


def _time(fn: Callable[[], Any], repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


_FRESH_CODE = """
import time
t0 = time.perf_counter()
import relief_cad
from relief_cad import RationalBezier as R, intersect
t1 = time.perf_counter()
intersect(R([[0, 0], [1, 2], [2, 0]]), R([[0, 1], [2, 0]]))
t2 = time.perf_counter()
intersect(R([[0, 0, 0], [1, 2, 1], [2, 0, 0]]), R([[0, 1, 0.5], [2, 0, 0.5]]))
t3 = time.perf_counter()
print(t1 - t0, t2 - t1, t3 - t2)
"""


def _startup() -> dict[str, float]:
    """Import, first planar and first space call in a fresh interpreter (nothing warmed first)."""
    out = subprocess.run([sys.executable, "-c", _FRESH_CODE], check=True, capture_output=True, text=True)
    imp, planar, space = (float(v) for v in out.stdout.split())
    return {"import_s": imp, "first_planar_s": planar, "first_space_s": space,
            "fresh_total_s": imp + planar + space}


def _per_pair_ratios(pairs: list[tuple[RationalBezier, RationalBezier]], occ: list[Any]) -> list[float]:
    """relief / OCCT time ratio of every pair on its own (best of 3 each)."""
    out = []
    for (a, b), (ca, cb) in zip(pairs, occ, strict=True):
        t_rel = _time(partial(intersect, a, b), 3)
        t_occ = _time(partial(occt_intersect, ca, cb), 3)
        out.append(t_rel / t_occ)
    return out


def _batch_rates(n: int, repeat: int) -> dict[str, float]:
    """Pairs/s of ``intersect_many`` on 1 thread and on all threads, and of the packed entry point."""
    batch = _random_cubic_pairs(n, seed=3)
    # the best of many short runs, each path run first: the first runs on a second thread are
    # slow (the pool starts, the other core wakes), and 5 runs gave 1.08x where 40 give 1.26x
    repeat = max(repeat, 40)
    intersect_many(batch, workers=1)
    intersect_many(batch)
    t1 = _time(lambda: intersect_many(batch, workers=1), repeat)
    tall = _time(lambda: intersect_many(batch), repeat)
    # the same pairs through the packed-array entry point (no Python objects per pair)
    pts = np.concatenate([c.control_points for pr in batch for c in pr])
    offsets = np.arange(0, 4 * 2 * len(batch) + 1, 4)
    idx = np.arange(2 * len(batch)).reshape(-1, 2)
    wts = np.ones(pts.shape[0])
    intersect_packed(pts, wts, offsets, idx)
    t_packed = _time(lambda: intersect_packed(pts, wts, offsets, idx, workers=1), repeat)
    t_packed_all = _time(lambda: intersect_packed(pts, wts, offsets, idx), repeat)
    return {"batch_pairs": n, "threads_all": os.cpu_count() or 1,
            "batch_pairs_per_s_1_thread": n / t1, "batch_pairs_per_s_all_threads": n / tall,
            "thread_speedup": t1 / tall, "packed_pairs_per_s_1_thread": n / t_packed,
            "packed_pairs_per_s_all_threads": n / t_packed_all}


def run(repeat: int = 5, batch: int = 2000) -> dict[str, Any]:
    """Time relief_cad and OCCT on every case; return ``{"cases": [...], ...}``.

    Each case row holds ``us_relief``, ``us_occt`` (µs per pair, best of
    ``repeat``), ``ratio`` (relief / OCCT), and the number of points each found;
    ``worst_ratio`` is the largest case ratio, ``random_pair_ratios`` the median, 90 %
    and worst ratio of the random cubics timed pair by pair. Batch rates are on ``batch``
    random cubic pairs; the start-up figures come from a fresh interpreter.
    """
    rows: list[dict[str, Any]] = []
    random_ratios: list[float] = []
    for name, pairs in cases().items():
        occ = [(occt_curve(a), occt_curve(b)) for a, b in pairs]
        n_rel = sum(len(intersect(a, b)) for a, b in pairs)
        n_occ = sum(len(occt_intersect(ca, cb)) for ca, cb in occ)
        reps = repeat if len(pairs) > 10 else repeat * 50
        t_rel = _time(partial(_each, intersect, pairs), reps) / len(pairs)
        t_occ = _time(partial(_each, occt_intersect, occ), reps) / len(pairs)
        if len(pairs) > 10:
            random_ratios = _per_pair_ratios(pairs, occ)
        rows.append(
            {
                "case": name,
                "pairs": len(pairs),
                "us_relief": 1e6 * t_rel,
                "us_occt": 1e6 * t_occ,
                "ratio": t_rel / t_occ,
                "points_relief": n_rel,
                "points_occt": n_occ,
            }
        )
    out: dict[str, Any] = {"cases": rows, "worst_ratio": max(r["ratio"] for r in rows), "target_ratio": 0.25}
    if random_ratios:
        q = np.quantile(random_ratios, [0.5, 0.9, 1.0])
        out["random_pair_ratios"] = {"median": float(q[0]), "p90": float(q[1]), "worst": float(q[2])}
    out.update(_batch_rates(batch, max(1, repeat // 2)))
    out.update(_startup())
    return out


def _main() -> None:
    r = run()
    print(
        f"{'case':28s} {'pairs':>6s} {'relief µs':>10s} {'OCCT µs':>10s} {'ratio':>7s} {'pts rc/occt':>12s}"
    )
    for row in r["cases"]:
        print(
            f"{row['case']:28s} {row['pairs']:6d} {row['us_relief']:10.2f} {row['us_occt']:10.2f} "
            f"{row['ratio']:7.3f} {row['points_relief']:>6d}/{row['points_occt']:<6d}"
        )
    print(f"worst case ratio {r['worst_ratio']:.3f} (target <= {r['target_ratio']}); "
          "random cubics pair by pair: "
          + ", ".join(f"{k} {v:.3f}" for k, v in r.get("random_pair_ratios", {}).items()))
    print(f"batch of {r['batch_pairs']:,} random cubic pairs: {r['batch_pairs_per_s_1_thread']:,.0f} pairs/s "
          f"on 1 thread, {r['batch_pairs_per_s_all_threads']:,.0f} on {r['threads_all']} "
          f"({r['thread_speedup']:.2f}x); packed rows {r['packed_pairs_per_s_1_thread']:,.0f} pairs/s "
          f"(all threads {r['packed_pairs_per_s_all_threads']:,.0f})")
    print(f"fresh process: import {r['import_s'] * 1e3:.0f} ms, "
          f"first planar {r['first_planar_s'] * 1e3:.0f} ms, first space {r['first_space_s'] * 1e3:.0f} ms, "
          f"total {r['fresh_total_s'] * 1e3:.0f} ms")


if __name__ == "__main__":
    _main()

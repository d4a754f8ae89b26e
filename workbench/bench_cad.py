"""Benchmark of the CAD adapters: relief_cad on build123d edge pairs vs build123d's and CadQuery's routes.

Same edges, one run. For each pair:

* ``relief_us``: :func:`relief_cad.cad.intersect` on the build123d edges, conversion to
  rational Bézier segments and native ``Vertex`` output included;
* ``b3d_find_us``: build123d ``Edge.find_intersection_points``;
* ``b3d_intersect_us``: build123d ``Edge.intersect`` (boolean route, vertices out);
* ``cq_split_us``: CadQuery's route, ``cadquery.Edge.split`` (``BRepAlgoAPI_Splitter``;
  CadQuery has no edge/edge point query, and ``Edge.intersect`` -- a boolean common --
  returns nothing for crossing edges); its point count is the number of new vertices;
* ``speedup_find``: ``b3d_find_us / relief_us``.

Times are the best of 5 batches (``timeit`` style), so they resist other load on the machine.

Conversion rows: ``relief_cad.cad.segments`` alone, µs per edge, for a cubic Bézier, a
single-span cubic B-spline, a 70° arc, a full circle and a 3-span interpolated spline.

Run ``python -m workbench.bench_cad`` (prints the table) or ``python -m workbench bench cad``.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from functools import partial
from typing import Any

__all__ = ["run", "pairs", "conversion_edges"]


def _time(f: Callable[[], Any], repeat: int, budget_s: float = 0.5) -> float:
    """µs per call: the best of 5 batches of ``repeat // 5`` calls (``timeit``-style, robust to load).

    Fewer calls per batch when a single call is slow enough to exceed ``budget_s`` overall.
    """
    t0 = time.perf_counter()
    f()  # warm up (OCCT caches, first allocations)
    one = time.perf_counter() - t0
    number = max(1, min(repeat // 5, int(budget_s / 5 / max(one, 1e-9))))
    best = float("inf")
    for _ in range(5):
        t0 = time.perf_counter()
        for _ in range(number):
            f()
        best = min(best, (time.perf_counter() - t0) / number)
    return best * 1e6


def _vertex_count(shape: Any) -> int:
    """The vertices of build123d's ``Edge.intersect`` answer (0 for None)."""
    return 0 if shape is None else len(shape.vertices())


def _count_and_time(f: Callable[[], Any], count: Callable[[Any], int], repeat: int) -> tuple[Any, Any]:
    """``(number of points, µs per call)``, or ``("error: ...", None)`` when the route raises."""
    try:
        n = count(f())
    except Exception as exc:  # noqa: BLE001 - a failing route is a result of the benchmark
        return f"error: {type(exc).__name__}", None
    return n, _time(f, repeat)


def _ratio(num: float | None, den: float | None) -> float | None:
    return None if num is None or den is None else num / den


def pairs() -> dict[str, tuple[Any, Any]]:
    """The build123d edge pairs of the benchmark (names -> (edge_a, edge_b))."""
    import build123d as bd

    spline = bd.Edge.make_spline([(-3, -1), (-1, 2), (0, -1.5), (1.5, 1.8), (3, -0.5)])
    glyph = bd.Text("S", 10).edges()
    glyph_a = max(glyph, key=lambda e: e.length)
    glyph_b = glyph_a.rotate(bd.Axis(tuple(glyph_a.center()), (0, 0, 1)), 60)
    return {
        "line_line": (bd.Edge.make_line((0, 0), (4, 2)), bd.Edge.make_line((0, 3), (3, 0))),
        "arc_line": (
            bd.Edge.make_circle(2, start_angle=10, end_angle=300),
            bd.Edge.make_line((-3, 1), (3, 1)),
        ),
        "ellipse_circle": (bd.Edge.make_ellipse(3, 1), bd.Edge.make_circle(2)),
        "spline_arc": (spline, bd.Edge.make_circle(1.2, start_angle=-30, end_angle=260)),
        "spline_line": (spline, bd.Edge.make_line((-4, 0.2), (4, 0.3))),
        "spline_spline": (spline, spline.rotate(bd.Axis.Z, 25)),
        "glyph_glyph": (glyph_a, glyph_b),
        "space_spline_line": _space_pair(),
    }


def _space_pair() -> tuple[Any, Any]:
    import build123d as bd

    spline = bd.Edge.make_spline([(0, 0, 0), (1, 2, 1), (2, -1, -1), (3, 2, 2), (4, 0, -0.5), (5, 1, 1)])
    p = spline.position_at(0.37)
    d = bd.Vector(0.3, -0.2, 1.0)
    return spline, bd.Edge.make_line(p - d, p + d * 2)


def conversion_edges() -> dict[str, Any]:
    """Single edges whose conversion to segments is timed."""
    import build123d as bd
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.Geom import Geom_BSplineCurve
    from OCP.gp import gp_Pnt

    from relief_cad.cad._compat import Array1OfInteger, Array1OfPnt, Array1OfReal

    poles = Array1OfPnt(1, 4)
    for i, (x, y) in enumerate([(0, 0), (1, 2), (3, 1), (4, 0)]):
        poles.SetValue(i + 1, gp_Pnt(x, y, 0))
    knots = Array1OfReal(1, 2)
    knots.SetValue(1, 0.0)
    knots.SetValue(2, 1.0)
    mults = Array1OfInteger(1, 2)
    mults.SetValue(1, 4)
    mults.SetValue(2, 4)
    cubic_bspline = bd.Edge(BRepBuilderAPI_MakeEdge(Geom_BSplineCurve(poles, knots, mults, 3)).Edge())
    return {
        "cubic_bezier": bd.Edge.make_bezier((0, 0), (1, 2), (3, 1), (4, 0)),
        "cubic_bspline_1span": cubic_bspline,
        "arc_70deg": bd.Edge.make_circle(2, start_angle=10, end_angle=80),
        "circle_full": bd.Edge.make_circle(2),
        "spline_3span": bd.Edge.make_spline([(0, 0), (1, 2), (3, 1), (4, 3)]),
    }


def _cadquery() -> Any:
    """The ``cadquery`` module, or None where it is not installed (build123d 0.13 on OCP 8.0)."""
    try:
        import cadquery
    except ImportError:
        return None
    return cadquery


def _cq_split(cq: Any, a: Any, b: Any, repeat: int) -> tuple[Any, Any]:
    """CadQuery's split of ``a`` by ``b``: (new vertices, µs), or (None, None) without CadQuery."""
    if cq is None:
        return None, None
    ca, cb = cq.Edge(a.wrapped), cq.Edge(b.wrapped)
    return _count_and_time(lambda: ca.split(cb), lambda r: max(0, len(r.Edges()) - 1), repeat)


def run(repeat: int = 200, occt_repeat: int = 20) -> dict[str, Any]:
    """Run the benchmark; returns ``{"rows": [...], "cadquery": ...}`` (µs per call).

    CadQuery's column needs CadQuery (OCP 7.9), which cannot share an environment with
    build123d 0.13 (OCP 8.0): without it the column is empty and ``cadquery`` says why.
    """
    import relief_cad.cad as rc

    cq = _cadquery()
    rows: list[dict[str, Any]] = []
    for name, (a, b) in pairs().items():
        relief_pts, relief_us = _count_and_time(partial(rc.intersect, a, b), len, repeat)
        find_pts, find_us = _count_and_time(partial(a.find_intersection_points, b), len, occt_repeat)
        inter_pts, inter_us = _count_and_time(partial(a.intersect, b), _vertex_count, occt_repeat)
        cq_pts, cq_us = _cq_split(cq, a, b, occt_repeat)
        rows.append(
            {
                "pair": name,
                "relief_pts": relief_pts,
                "b3d_find_pts": find_pts,
                "b3d_inter_pts": inter_pts,
                "cq_split_pts": cq_pts,
                "relief_us": relief_us,
                "b3d_find_us": find_us,
                "b3d_intersect_us": inter_us,
                "cq_split_us": cq_us,
                "speedup_find": _ratio(find_us, relief_us),
                "speedup_intersect": _ratio(inter_us, relief_us),
            }
        )
    conversion: list[dict[str, Any]] = []
    for name, edge in conversion_edges().items():
        raw = edge.wrapped
        conversion.append(
            {
                "pair": f"convert:{name}",
                "segments": len(rc.segments(raw)),
                "relief_us": _time(partial(rc.segments, raw), 20 * repeat),
            }
        )
    note = "measured" if cq is not None else "not measured: CadQuery is not installed here (it needs OCP 7.9)"
    return {"rows": rows + conversion, "cadquery": note}


def main() -> None:
    """Print the benchmark table."""
    res = run()
    try:
        from .bench import format_rows
    except ImportError:  # pragma: no cover
        for r in res["rows"]:
            print(r)
        return
    print(format_rows(res["rows"]))
    print(f"CadQuery: {res['cadquery']}")


if __name__ == "__main__":
    main()

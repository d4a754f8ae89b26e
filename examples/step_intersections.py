"""Intersect the edges of two STEP files with relief_cad, cross-check with OCCT, write a report.

Every edge of the first file is intersected with every edge of the second
(``relief_cad.cad.intersections``: edges pruned by bounding boxes, converted exactly to
rational Bézier segments). The script prints a table of the points (edge indices and
types, kind, point, both edges' own parameters), then runs OCCT on the same edges
(``relief_cad.cad.compare.compare``: Geom2dInt_GInter / IntTools_EdgeEdge /
BRepAlgoAPI_Section, with a 50-digit arbiter on every disagreement) and writes:

* ``report.html``: the comparison table and a picture of both answers (self-contained);
* ``comparison.json``: the same, machine-readable.

Run::

    python examples/step_intersections.py [A.step B.step] [--out OUT_DIR] [--tol TOL]

Without files it uses the two small parts bundled with the workbench
(``workbench/data/step/bracket.step`` and ``knob.step``), or, when those are not there,
two parts it makes itself with build123d (``--demo`` forces that).
"""

from __future__ import annotations

import argparse
import base64
import html
import json
import sys
import time
from pathlib import Path
from typing import Any

BUNDLED = Path(__file__).resolve().parent.parent / "workbench" / "data" / "step"


def make_demo_parts(folder: Path) -> tuple[Path, Path]:
    """Write two small STEP parts whose edges cross: a splined plate and a ring standing on it."""
    import build123d as bd

    folder.mkdir(parents=True, exist_ok=True)
    with bd.BuildPart() as plate:
        with bd.BuildSketch():
            with bd.BuildLine():
                bd.Spline((-30, 0), (-10, 14), (10, 6), (30, 0))
                bd.ThreePointArc((30, 0), (0, -16), (-30, 0))
            bd.make_face()
        bd.extrude(amount=4)
    with bd.BuildPart() as ring:
        with bd.Locations((4, 4, 4)):
            bd.Cylinder(12, 6, align=(bd.Align.CENTER, bd.Align.CENTER, bd.Align.MIN))
            bd.Box(30, 6, 6, align=(bd.Align.CENTER, bd.Align.CENTER, bd.Align.MIN))
    a, b = folder / "demo_plate.step", folder / "demo_ring.step"
    bd.export_step(plate.part, str(a))
    bd.export_step(ring.part, str(b))
    return a, b


def read_step(path: Path) -> Any:
    """Read a STEP file into one OCCT shape (``STEPControl_Reader``); clear error if unreadable."""
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPControl import STEPControl_Reader

    reader = STEPControl_Reader()
    if not path.is_file() or reader.ReadFile(str(path)) != IFSelect_RetDone:
        raise SystemExit(f"error: cannot read STEP file {path}")
    reader.TransferRoots()
    return reader.OneShape()


def _geom(edge: Any) -> str:
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    name = str(BRepAdaptor_Curve(edge).GetType()).split(".")[-1]
    return name.removeprefix("GeomAbs_").lower()


def picture(comparison: Any, max_edges: int = 16) -> bytes:
    """PNG of the edges and both answers; only the edges that meet something when there are many.

    (Drawing every edge of a large part would be slow: ``plot_pair_png`` samples 200 points per
    edge and fits a plane to all of them.)
    """
    from dataclasses import replace

    from relief_cad.cad.compare import plot_pair_png

    everyone = list(comparison.relief) + list(comparison.occt)
    flagged = [d.claim for d in comparison.disagreements]
    edges_a, edges_b = comparison.edges_a, comparison.edges_b
    if len(edges_a) + len(edges_b) <= max_edges or not everyone:
        return bytes(plot_pair_png(edges_a, edges_b, everyone[: len(comparison.relief)],
                                   comparison.occt, flagged))
    keep_a = sorted({r.index_a for r in everyone})
    keep_b = sorted({r.index_b for r in everyone})
    new_a = {old: new for new, old in enumerate(keep_a)}
    new_b = {old: new for new, old in enumerate(keep_b)}

    def moved(rs: list[Any]) -> list[Any]:
        return [replace(r, index_a=new_a[r.index_a], index_b=new_b[r.index_b]) for r in rs]

    return bytes(plot_pair_png([edges_a[i] for i in keep_a], [edges_b[i] for i in keep_b],
                               moved(list(comparison.relief)), moved(list(comparison.occt)), moved(flagged),
                               title=f"the {len(keep_a) + len(keep_b)} edges that meet: relief_cad (blue o), "
                                     "OCCT (red x), disagreements ringed"))


def _warm_up() -> None:
    """Load relief_cad's compiled kernels on a tiny planar and space pair, so the timing below is fair."""
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.gp import gp_Ax2, gp_Circ, gp_Dir, gp_Pnt

    from relief_cad.cad import intersections

    circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 1.0)).Edge()
    intersections(circle, BRepBuilderAPI_MakeEdge(gp_Pnt(-2, 0.5, 0), gp_Pnt(2, 0.5, 0)).Edge())
    intersections(circle, BRepBuilderAPI_MakeEdge(gp_Pnt(1, 0, -1), gp_Pnt(1, 0, 1)).Edge())


def _html_page(title: str, table: str, body: str) -> str:
    css = ("body{font-family:sans-serif;margin:2em;max-width:70em} table{border-collapse:collapse}"
           "td,th{border:1px solid #bbb;padding:2px 6px;font-size:90%} th{background:#eee}")
    return (f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{html.escape(title)}</title>"
            f"<style>{css}</style></head><body><h1>{html.escape(title)}</h1>{table}{body}</body></html>")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Intersect the edges of two STEP files; compare with OCCT.")
    parser.add_argument("files", nargs="*", type=Path, help="two STEP files (default: bundled parts)")
    parser.add_argument("--out", type=Path, default=Path("out_step"), help="output folder")
    parser.add_argument("--tol", type=float, default=None, help="tolerance in model units "
                        "(default: the largest OCCT edge tolerance)")
    parser.add_argument("--demo", action="store_true", help="use two parts made here with build123d")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)

    if args.files and len(args.files) != 2:
        parser.error(f"expected two STEP files, got {len(args.files)}")
    if args.files:
        path_a, path_b = args.files
    elif not args.demo and (BUNDLED / "bracket.step").is_file() and (BUNDLED / "knob.step").is_file():
        path_a, path_b = BUNDLED / "bracket.step", BUNDLED / "knob.step"
    else:
        path_a, path_b = make_demo_parts(args.out)

    from relief_cad.cad import intersections
    from relief_cad.cad.compare import compare
    from relief_cad.cad.occt import default_occt_tolerance, unique_edges

    a, b = read_step(path_a), read_step(path_b)
    edges_a, edges_b = unique_edges(a), unique_edges(b)
    tol = args.tol if args.tol is not None else default_occt_tolerance(*edges_a, *edges_b)
    print(f"{path_a.name}: {len(edges_a)} edges; {path_b.name}: {len(edges_b)} edges; tol = {tol:.3g}")

    _warm_up()
    t0 = time.perf_counter()
    results = intersections(a, b, tol=tol)
    elapsed = time.perf_counter() - t0
    print(f"relief_cad: {len(results)} result(s) in {elapsed * 1e3:.1f} ms")
    print(f"{'#':>3} {'edge a':<16}{'edge b':<16}{'kind':<9}{'x':>12}{'y':>12}{'z':>12}{'t':>14}{'u':>14}")
    for i, r in enumerate(results):
        ea = f"{r.index_a}:{_geom(edges_a[r.index_a])}"
        eb = f"{r.index_b}:{_geom(edges_b[r.index_b])}"
        if r.kind == "overlap":
            print(f"{i:>3} {ea:<16}{eb:<16}overlap  t=[{r.t[0]:.9f}, {r.t[1]:.9f}] "
                  f"u=[{r.u[0]:.9f}, {r.u[1]:.9f}]")
            continue
        x, y, z = r.point
        print(f"{i:>3} {ea:<16}{eb:<16}{r.kind:<9}{x:>12.6f}{y:>12.6f}{z:>12.6f}{r.t:>14.9f}{r.u:>14.9f}")

    comparison: Any = None
    try:
        comparison = compare(a, b, tol=tol, relief=results)
    except Exception as exc:  # noqa: BLE001 - the table above stands; say why there is no comparison
        note = f"{type(exc).__name__}: {exc}"
        print(f"OCCT comparison failed: {note}", file=sys.stderr)
    title = f"relief_cad vs OCCT: {path_a.name} x {path_b.name}"
    if comparison is not None:
        print(f"OCCT on the same edges: {comparison.times['occt'] * 1e3:.1f} ms "
              f"(routes: {', '.join(comparison.routes) or '-'})")
        print(comparison)
        png = base64.b64encode(picture(comparison)).decode()
        body = (comparison.to_html(plot=False)
                + f'<img alt="edges and both answers" src="data:image/png;base64,{png}"/>')
        data = comparison.to_dict()
    else:
        body = f"<p><b>The OCCT comparison failed</b>: {html.escape(note)}</p>"
        data = {"error": note}
    data.update(file_a=str(path_a), file_b=str(path_b), tol=tol,
                relief_cad=[{"index_a": r.index_a, "index_b": r.index_b, "kind": r.kind,
                             "t": r.t, "u": r.u, "point": getattr(r, "point", None)} for r in results])
    report = args.out / "report.html"
    occt_ms = f"; OCCT took {comparison.times['occt'] * 1e3:.1f} ms" if comparison is not None else ""
    table = (f"<p>{len(edges_a)} edges x {len(edges_b)} edges, tolerance {tol:.3g}; relief_cad found "
             f"{len(results)} result(s) in {elapsed * 1e3:.1f} ms{occt_ms}.</p>")
    report.write_text(_html_page(title, table, body), encoding="utf-8")
    (args.out / "comparison.json").write_text(json.dumps(data, indent=1, default=str), encoding="utf-8")
    print(f"wrote {report} and {args.out / 'comparison.json'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

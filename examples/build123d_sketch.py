"""A build123d part drilled where the curves of its sketch cross (found by relief_cad).

The plate's outline mixes lines and an arc; three construction curves drawn on it (a
spline, an arc and a line) cross each other. ``relief_cad.cad.build123d.intersections``
finds every crossing (edge parameters, point, kind), and the script drills a hole at each
point (``Locations(*vertices)`` + ``Hole``), then writes:

* ``plate.step``: the drilled part;
* ``sketch_intersections.png``: the sketch with the crossings marked and numbered;

and prints a table of the points. Run::

    python examples/build123d_sketch.py [OUT_DIR]      # default ./out_build123d/
"""

from __future__ import annotations

import argparse
import math
import os
from pathlib import Path
from typing import Any

import build123d as bd
import numpy as np

from relief_cad.cad import build123d as rb

PLATE_THICKNESS = 6.0
HOLE_DIAMETER = 3.0


def outline() -> Any:
    """The plate's outline: three lines and an arc, as a closed build123d ``Wire``."""
    with bd.BuildLine() as line:
        bd.Polyline((-50, 20), (-50, -30), (50, -30), (50, 20))
        bd.ThreePointArc((50, 20), (0, 38), (-50, 20))
    return line.wire()


def construction_curves() -> dict[str, Any]:
    """The construction curves drawn on the plate: a spline, an arc and a line (build123d edges)."""
    return {
        "spline": bd.Spline((-42, -20), (-15, 25), (10, -22), (42, 18)),
        "arc": bd.CenterArc((0, -5), 26, -25, 230),
        "line": bd.Line((-45, 8), (45, -12)),
    }


def find_points(curves: dict[str, Any]) -> list[Any]:
    """Every crossing of the construction curves with each other (rich results)."""
    # b=None: the curves against each other (and each against itself).
    return rb.intersections(list(curves.values()))


def build_part(points: list[tuple[float, float, float]]) -> Any:
    """The plate with one through hole at every point."""
    with bd.BuildPart() as part:
        with bd.BuildSketch():
            bd.make_face(outline().edges())
        bd.extrude(amount=PLATE_THICKNESS)
        with bd.Locations(*[bd.Location((x, y, PLATE_THICKNESS)) for x, y, _ in points]):
            bd.Hole(radius=HOLE_DIAMETER / 2)
    return part.part


def _polyline(edge: Any, n: int = 300) -> np.ndarray:
    return np.array([tuple(edge.position_at(s)) for s in np.linspace(0.0, 1.0, n)])


def draw(curves: dict[str, Any], points: list[tuple[float, float, float]], path: Path) -> None:
    """Picture of the sketch: outline, construction curves, crossings numbered."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7.0, 4.4), dpi=100)
    for edge in outline().edges():
        q = _polyline(edge)
        ax.plot(q[:, 0], q[:, 1], color="0.35", lw=1.6)
    colors = {"spline": "tab:blue", "arc": "tab:green", "line": "tab:purple"}
    for name, edge in curves.items():
        q = _polyline(edge)
        ax.plot(q[:, 0], q[:, 1], color=colors[name], lw=1.8, label=name)
    for i, (x, y, _) in enumerate(points):
        ax.add_patch(plt.Circle((x, y), HOLE_DIAMETER / 2, fill=False, color="tab:red", lw=1.2))
        ax.plot([x], [y], "o", color="tab:red", ms=3)
        ax.annotate(str(i), (x, y), xytext=(5, 5), textcoords="offset points", fontsize=9, color="tab:red")
    ax.set_aspect("equal")
    ax.set_title("relief_cad: crossings of a spline, an arc and a line (holes drilled there)", fontsize=10)
    ax.legend(loc="lower right", fontsize=8)
    ax.tick_params(labelsize=8)
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", nargs="?", default="out_build123d", help="output folder")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    curves = construction_curves()
    names = list(curves)
    results = find_points(curves)
    points = [r.point for r in results]

    print(f"{len(results)} crossing(s) of the construction curves:")
    print(f"{'#':>2}  {'edge a':<7}{'edge b':<7}{'kind':<9}{'x':>12}{'y':>12}"
          f"{'t (edge a)':>14}{'u (edge b)':>14}")
    for i, r in enumerate(results):
        x, y, _ = r.point
        print(f"{i:>2}  {names[r.index_a]:<7}{names[r.index_b]:<7}{r.kind:<9}{x:>12.6f}{y:>12.6f}"
              f"{r.t:>14.9f}{r.u:>14.9f}")

    part = build_part(points)
    step = out / "plate.step"
    bd.export_step(part, str(step))
    png = out / "sketch_intersections.png"
    draw(curves, points, png)
    hole_volume = len(points) * math.pi * (HOLE_DIAMETER / 2) ** 2 * PLATE_THICKNESS
    print(f"part: {len(part.solids())} solid, {len(part.faces())} faces, volume {part.volume:.3f} "
          f"({len(points)} holes remove {hole_volume:.3f})")
    print(f"wrote {step} and {png}")
    return 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    raise SystemExit(main())

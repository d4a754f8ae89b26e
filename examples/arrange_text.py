"""Text outlines over a wavy pattern, cut into faces by ``arrange`` and extruded as a stepped relief.

The letters of a build123d ``Text`` and the borders of four wavy bands cross each other
everywhere. ``relief_cad.cad.build123d.arrange(..., faces=True)`` cuts every outline at every
crossing, connects the pieces through shared vertices and lets OCCT's face builder make the
bounded regions. Each region is classified (inside a letter, inside a band, both) with a point
OCCT finds inside it, and extruded to a height by its class: letters 2 mm, bands 1 mm, both
3 mm. Booleans could not give these regions in one step; here they come from one call.

Writes ``relief.step`` (the extruded regions), ``arrange_text.png`` (the regions coloured by
class; it is ``docs/images/arrange_text.png``) and prints the counts and an area check (the
regions' areas add up to the area of letters ∪ bands computed by OCCT's boolean fuse). Run::

    python examples/arrange_text.py [OUT_DIR]      # default ./out_arrange/
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

import build123d as bd
import numpy as np

from relief_cad.cad import build123d as rb

HEIGHTS = {"letter": 2.0, "band": 1.0, "both": 3.0}
COLOURS = {"letter": "#2b6cb0", "band": "#f6ad55", "both": "#9b2c2c"}


def letters() -> Any:
    """The text as build123d faces."""
    return bd.Text("RELIEF", font_size=20, font_style=bd.FontStyle.BOLD)


def bands() -> list[Any]:
    """Four wavy bands across the text, as faces bounded by two splines and two lines."""
    out = []
    for k in range(4):
        y0 = -9.0 + 5.0 * k
        low = [bd.Vector(x, y0 + 1.2 * math.sin(0.25 * x + k)) for x in range(-40, 45, 5)]
        high = [p + bd.Vector(0, 2.2) for p in low]
        wire = bd.Wire([
            bd.Edge.make_spline(low), bd.Edge.make_line(low[-1], high[-1]),
            bd.Edge.make_spline(high[::-1]), bd.Edge.make_line(high[0], low[0]),
        ])
        out.append(bd.Face(wire))
    return out


def inside(face: Any, point: Any) -> bool:
    """True when ``point`` lies inside ``face`` (OCCT's face classifier)."""
    from OCP.BRepClass import BRepClass_FaceClassifier
    from OCP.TopAbs import TopAbs_IN

    return bool(BRepClass_FaceClassifier(face.wrapped, point.to_pnt(), 1e-7).State() == TopAbs_IN)


def interior_point(face: Any) -> Any:
    """A point strictly inside a face (OCCT's own choice, as its booleans use)."""
    from OCP.BOPTools import BOPTools_AlgoTools3D
    from OCP.gp import gp_Pnt, gp_Pnt2d
    from OCP.IntTools import IntTools_Context

    p, uv = gp_Pnt(), gp_Pnt2d()
    BOPTools_AlgoTools3D.PointInFace_s(face.wrapped, p, uv, IntTools_Context())
    return bd.Vector(p.X(), p.Y(), p.Z())


def classify(region: Any, text_faces: list[Any], band_faces: list[Any]) -> str | None:
    p = interior_point(region)
    in_letter = any(inside(f, p) for f in text_faces)
    in_band = any(inside(f, p) for f in band_faces)
    if in_letter and in_band:
        return "both"
    return "letter" if in_letter else "band" if in_band else None


def draw(regions: list[tuple[Any, str]], path: Path) -> None:
    """Fill every region with the colour of its class (OCCT triangulation), outlines in black."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from OCP.BRep import BRep_Tool
    from OCP.BRepMesh import BRepMesh_IncrementalMesh
    from OCP.TopLoc import TopLoc_Location

    fig, ax = plt.subplots(figsize=(8, 3.2), dpi=100)
    for face, kind in regions:
        BRepMesh_IncrementalMesh(face.wrapped, 0.05)
        tri = BRep_Tool.Triangulation_s(face.wrapped, TopLoc_Location())
        if tri is None:
            continue
        nodes = np.array([tri.Node(i).Coord()[:2] for i in range(1, tri.NbNodes() + 1)])
        tris = [np.array(tri.Triangle(i).Get()) - 1 for i in range(1, tri.NbTriangles() + 1)]
        colour = COLOURS[kind]
        ax.add_collection(PolyCollection([nodes[t] for t in tris], facecolors=colour, edgecolors=colour,
                                     linewidths=0.3))
        for edge in face.edges():
            pts = np.array([tuple(edge.position_at(s))[:2] for s in np.linspace(0, 1, 30)])
            ax.plot(pts[:, 0], pts[:, 1], color="black", lw=0.4)
    ax.set_aspect("equal")
    ax.autoscale()
    ax.set_axis_off()
    ax.set_title("arrange(text + wavy bands, faces=True): letters, bands, both", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)


def main(out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    text = letters()
    text_faces = list(text.faces())
    band_faces = bands()
    regions = rb.arrange([text, *band_faces], faces=True)
    classified = [(f, kind) for f in regions if (kind := classify(f, text_faces, band_faces)) is not None]
    solids = [bd.extrude(f, HEIGHTS[kind]) for f, kind in classified]
    bd.export_step(bd.Compound(solids), str(out / "relief.step"))
    draw(classified, out / "arrange_text.png")
    union = text_faces[0].fuse(*text_faces[1:], *band_faces)
    counts = {k: sum(1 for _, kind in classified if kind == k) for k in HEIGHTS}
    print(f"edges in: {len(text.edges()) + sum(len(f.edges()) for f in band_faces)}")
    print(f"regions: {len(regions)} ({', '.join(f'{k}: {n}' for k, n in counts.items())})")
    area_regions = sum(f.area for f, _ in classified)
    print(f"area of the regions: {area_regions:.6f}; of letters ∪ bands (OCCT fuse): {union.area:.6f}")


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default="out_arrange", type=Path)
    main(parser.parse_args().out)

"""The shape of relief_cad.cad: one compat module, no import cycle, rendering that leaves matplotlib alone."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CAD = ROOT / "relief_cad" / "cad"
VERSION_SPECIFIC = ("OCP.TColgp", "OCP.TColStd", "OCP.TopTools", "OCP.collections")


def _imports(path: Path) -> list[tuple[str, int]]:
    """(module, level) of every import in a file (relative imports keep their level)."""
    out = []
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            out.append((node.module or "", node.level))
        elif isinstance(node, ast.Import):
            out.extend((alias.name, 0) for alias in node.names)
    return out


def test_version_specific_ocp_names_live_only_in_the_compat_module():
    users = sorted(
        str(p.relative_to(ROOT))
        for p in [*ROOT.glob("relief_cad/**/*.py"), *ROOT.glob("workbench/**/*.py"), *ROOT.glob("examples/*.py")]
        if any(m.startswith(VERSION_SPECIFIC) for m, _ in _imports(p))
    )
    assert users == ["relief_cad/cad/_compat.py"]
    assert "_s(" not in "".join(  # OCP 8 dropped TopoDS.Edge_s / Vertex_s: only the compat module downcasts
        line for p in CAD.glob("*.py") for line in p.read_text().splitlines() if "TopoDS." in line and "Edge_s" in line
    )


def test_no_import_cycle_between_the_public_functions_and_the_flavour_faces():
    local = {p.stem: {m.split(".")[0] for m, level in _imports(p) if level == 1} for p in CAD.glob("*.py")}
    # the flavour and topology modules sit below api; the flavour faces sit above it
    for low in ("flavour", "topology", "curvetypes", "_compat", "_checks", "exact", "render"):
        assert not local[low] & {"api", "build123d", "cadquery", "compare", "occt"}, (low, local[low])
    for face in ("build123d", "cadquery"):
        assert face not in local["api"] and face not in local["flavour"]

    def reaches(start: str, goal: str, seen: set[str]) -> bool:
        for nxt in local.get(start, set()) - seen:
            if nxt == goal or reaches(nxt, goal, seen | {nxt}):
                return True
        return False

    cyclic = [m for m in local if reaches(m, m, set())]
    assert cyclic == []


def test_rendering_leaves_the_matplotlib_backend_and_pyplot_alone():
    code = (
        "import matplotlib, sys\n"
        "matplotlib.use('svg')\n"
        "import build123d as bd\n"
        "from relief_cad.cad import compare\n"
        "png = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0))).plot_png()\n"
        "print(png[1:4] == b'PNG', matplotlib.get_backend(), 'matplotlib.pyplot' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True, cwd=ROOT)
    assert out.stdout.split() == ["True", "svg", "False"], out.stderr[-2000:]

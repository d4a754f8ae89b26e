"""The core never imports a CAD package: checked at run time and by reading the sources."""

from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

CORE = Path(__file__).resolve().parents[1] / "relief_cad"
ALLOWED_THIRD_PARTY = {"numpy", "cython"}
FORBIDDEN = ("OCP", "build123d", "cadquery")


def test_importing_relief_cad_loads_no_cad_package() -> None:
    code = (
        "import sys, relief_cad\n"
        "relief_cad.RationalBezier([[0, 0], [1, 1]])\n"
        f"bad = [m for m in sys.modules if m.split('.')[0] in {FORBIDDEN!r}]\n"
        "print(bad)\n"
        "sys.exit(1 if bad else 0)\n"
    )
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr


def test_core_sources_import_only_stdlib_numpy_cython() -> None:
    stdlib = set(sys.stdlib_module_names)
    offenders = []
    for path in sorted(CORE.glob("*.py")):
        tree = ast.parse(path.read_text(), filename=str(path))
        for node in ast.walk(tree):
            names: list[str] = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
                names = [node.module]
            for name in names:
                top = name.split(".")[0]
                if top not in stdlib and top not in ALLOWED_THIRD_PARTY and top != "relief_cad":
                    offenders.append(f"{path.name}: {name}")
                if top == "relief_cad" and name.startswith("relief_cad.cad"):
                    offenders.append(f"{path.name}: {name}")
    assert not offenders, offenders


def test_every_exported_name_exists() -> None:
    import relief_cad
    import relief_cad.cad

    for module in (relief_cad, relief_cad.cad):
        missing = [name for name in module.__all__ if not hasattr(module, name)]
        assert not missing, f"{module.__name__}.__all__ names missing attributes: {missing}"

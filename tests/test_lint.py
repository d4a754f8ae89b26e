"""ruff and mypy (strict) must be clean on the package and the workbench: run as part of the test suite."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", *args], cwd=ROOT, capture_output=True, text=True, timeout=900)


def test_ruff_clean() -> None:
    result = run("ruff", "check", "relief_cad", "workbench", "tests", "examples", "conftest.py", "noxfile.py")
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_strict_clean_on_relief_cad_and_the_workbench() -> None:
    result = run("mypy", "relief_cad", "workbench")
    assert result.returncode == 0, result.stdout + result.stderr

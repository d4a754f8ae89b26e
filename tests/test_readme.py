"""Every Python snippet in the README runs, and prints what the README says it prints."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from tests._env import needs_cadquery

ROOT = Path(__file__).resolve().parents[1]
BLOCK = re.compile(r"```(python)?\n(.*?)```", re.S)


def snippets() -> list[tuple[str, str | None]]:
    """(code, the plain block right after it if any) for each python block of the README."""
    blocks = [(m.group(1), m.group(2)) for m in BLOCK.finditer((ROOT / "README.md").read_text())]
    out = []
    for i, (lang, body) in enumerate(blocks):
        if lang == "python":
            nxt = blocks[i + 1] if i + 1 < len(blocks) and blocks[i + 1][0] is None else None
            out.append((body, nxt[1] if nxt else None))
    return out


def _params() -> list[object]:
    """One param per snippet; the CadQuery ones carry the ``cadquery`` marker (environment B only)."""
    return [
        pytest.param(i, marks=[needs_cadquery] if re.search(r"^import cadquery", code, re.M) else [])
        for i, (code, _) in enumerate(snippets())
    ]


@pytest.mark.parametrize("index", _params())
def test_readme_snippet(index: int) -> None:
    code, expected = snippets()[index]
    result = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=600,
                            env={"MPLBACKEND": "Agg", **__import__("os").environ})
    assert result.returncode == 0, result.stderr[-3000:]
    expected_lines = [ln for ln in (expected or "").splitlines() if ln.strip()]
    if not expected_lines or expected_lines[0].startswith(("python3 ", "bash ")):
        # the inline "# [Intersection(...)]" comments document the core snippet's output
        for comment in re.findall(r"^# (\[.*\])$", code, re.M):
            assert comment in result.stdout
        return
    got = [ln for ln in result.stdout.splitlines() if ln.strip()]
    assert len(got) == len(expected_lines), result.stdout
    for g, e in zip(got, expected_lines):
        if "Vertex(" in e:  # full-precision coordinates: compare to 9 digits
            nums_g = [float(x) for x in re.findall(r"-?\d+\.\d+(?:e-?\d+)?", g)]
            nums_e = [float(x) for x in re.findall(r"-?\d+\.\d+(?:e-?\d+)?", e)]
            assert nums_g == pytest.approx(nums_e, rel=1e-9, abs=1e-9)
        else:
            assert g == e

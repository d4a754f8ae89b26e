"""Deselection by environment, for every test path (tests/, the package doctests, workbench/).

Tests marked ``cadquery`` need CadQuery (environment B, nox session ``B``). Where CadQuery is
not installed they are deselected by name, each listed with the reason in the terminal
summary, and the doctests of the modules that import CadQuery (``CADQUERY_MODULES``) are not
collected, listed the same way. When the environment variable ``RELIEF_CAD_REQUIRE``
contains ``cadquery`` a missing CadQuery is an error instead. Nothing is skipped silently.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tests._env import HAS_CADQUERY

ROOT = Path(__file__).resolve().parent
CADQUERY_MODULES = (ROOT / "relief_cad" / "cad" / "cadquery.py",)
_REASON = "needs CadQuery, which this environment does not have (it runs in nox session B)"
_DESELECTED: list[str] = []


def pytest_configure(config: pytest.Config) -> None:
    """Register the ``cadquery`` marker; refuse a run that requires CadQuery without it."""
    config.addinivalue_line("markers", "cadquery: the test needs CadQuery (runs in environment B only)")
    required = os.environ.get("RELIEF_CAD_REQUIRE", "")
    if "cadquery" in required and not HAS_CADQUERY:
        raise pytest.UsageError("RELIEF_CAD_REQUIRE names cadquery, but cadquery cannot be imported here")


def pytest_ignore_collect(collection_path: Path, config: pytest.Config) -> bool | None:
    """Leave out the doctests of modules that import CadQuery where it is missing (listed)."""
    if not HAS_CADQUERY and collection_path in CADQUERY_MODULES:
        _DESELECTED.append(f"{collection_path.relative_to(ROOT)} (its doctests)")
        return True
    return None


def pytest_collection_modifyitems(config: pytest.Config, items: list[pytest.Item]) -> None:
    """Deselect tests marked ``cadquery`` where CadQuery is missing (listed)."""
    if HAS_CADQUERY:
        return
    keep, drop = [], []
    for item in items:
        (drop if item.get_closest_marker("cadquery") else keep).append(item)
    if drop:
        config.hook.pytest_deselected(items=drop)
        items[:] = keep
        _DESELECTED.extend(item.nodeid for item in drop)


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    """List every deselected test with the reason."""
    if _DESELECTED:
        terminalreporter.section(f"deselected: {len(_DESELECTED)} tests ({_REASON})")
        for nodeid in _DESELECTED:
            terminalreporter.write_line(f"DESELECTED {nodeid}: {_REASON}")

"""Shared pytest configuration: hypothesis profiles, the fuzz totals (deselection by environment: ../conftest.py)."""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

from tests._fuzz import summary_lines

settings.register_profile(
    "ci",
    derandomize=True,
    deadline=None,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large],
)
settings.register_profile("dev", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


def pytest_terminal_summary(terminalreporter: pytest.TerminalReporter) -> None:
    """Print the fuzz suite's totals (tried, refused, answered, properties checked; tests/_fuzz.py)."""
    lines = summary_lines()
    if lines:
        terminalreporter.section("fuzz totals (issue 15)")
        for line in lines:
            terminalreporter.write_line(line)

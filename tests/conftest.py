"""Shared pytest configuration: hypothesis profiles, the fuzz totals (deselection by environment: ../conftest.py)."""

from __future__ import annotations

import os

import pytest
from hypothesis import HealthCheck, settings

from tests._fuzz import summary_lines

# "ci": the same cases on every run of the same code. Hypothesis mixes the literal constants of the
# project's own modules into what it draws, so editing any module changes the cases (that is how the
# fuzz found subnormal and closed-curve inputs); no example database, so sessions A and B and a
# local run of one commit draw the same cases whatever ran before
settings.register_profile(
    "ci",
    derandomize=True,
    database=None,
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

"""Benchmark: how the cost grows with the degree (issue 16), up to the largest supported degree.

For random curves of degree 10, 100, 200 and :data:`relief_cad._checks.MAX_DEGREE` (256; a
degree of 500 or 1000 is refused with ``DegreeError``), in the plane, with seeded control points in
the unit square, it times (:func:`.timing.best_time`, best of ``repeat`` runs each, seconds):

* ``default_tolerance(c)``: the default tolerance, which samples the curve;
* ``intersect(c)``: the self-intersection;
* ``intersect(c, c)``: a curve against an exact copy of itself (one Overlap);
* ``intersect(c, line)``: the curve against a horizontal line through its middle.

Run ``python -m workbench bench degrees``; :func:`run` returns the table as a list of rows.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from relief_cad import RationalBezier, default_tolerance, intersect
from relief_cad._checks import MAX_DEGREE

from .timing import best_time

__all__ = ["DEGREES", "run"]

DEGREES = (10, 100, 200, MAX_DEGREE)


def _row(degree: int, repeat: int) -> dict[str, Any]:
    c = RationalBezier(np.random.default_rng(degree).random((degree + 1, 2)))
    mid = float(np.median(c.control_points[:, 1]))
    line = RationalBezier([[-1.0, mid], [2.0, mid]])
    found = len(intersect(c, line, on_budget="return"))
    return {
        "degree": degree,
        "default_tolerance s": best_time(lambda: default_tolerance(c), repeat=repeat),
        "self-intersection s": best_time(lambda: intersect(c, on_budget="return"), repeat=repeat),
        "against itself s": best_time(lambda: intersect(c, c, on_budget="return"), repeat=repeat),
        "against a line s": best_time(lambda: intersect(c, line, on_budget="return"), repeat=repeat),
        "line crossings": found,
    }


def run(repeat: int = 2) -> list[dict[str, Any]]:
    """One row per degree of :data:`DEGREES` (seconds, best of ``repeat``)."""
    return [_row(d, repeat) for d in DEGREES]


if __name__ == "__main__":
    from .bench import format_rows

    print(format_rows(run()))

"""CAD adapters: OCCT (OCP), build123d and CadQuery edges in, native vertices and edges out.

Importing this package imports OCP (the OCCT bindings) but neither build123d nor
CadQuery; the flavour-specific faces live in :mod:`relief_cad.cad.build123d` and
:mod:`relief_cad.cad.cadquery`. The core package :mod:`relief_cad` never imports
this one.

* :func:`segments` -- an edge as exact rational Bézier segments plus parameter maps;
* :func:`intersect` -- native vertices where edges of shapes meet;
* :func:`intersections` -- the rich results (:class:`EdgeIntersection`, :class:`EdgeOverlap`);
* :func:`split` -- edges cut at their intersections, as native edges sharing vertices;
* :func:`split_both` -- both shapes cut where they meet, sharing vertices and overlap edges;
* :func:`arrange` -- all edges cut at all intersections, connected; or the faces they bound;
* :func:`occt_intersections` -- OCCT's own answer on the same shapes, in the same result types;
* :func:`compare` -- relief_cad against OCCT, every disagreement judged by a 50-digit arbiter.

A missing CAD package raises :class:`~relief_cad.errors.AdapterUnavailableError`
naming the extra to install (``relief-cad[build123d]`` or ``relief-cad[cadquery]``); a
missing OCP and an unsupported OCP release get different messages (see :mod:`._compat`).

>>> from relief_cad import cad
>>> sorted(cad.__all__)[:3]
['Comparison', 'Disagreement', 'EdgeIntersection']
"""

from __future__ import annotations

from . import _compat  # noqa: F401  first: refuses a missing or unsupported OCP with a clear error
from .api import intersect, intersections, planar_curves, segments
from .arrangement import arrange, split_both
from .arrangement import split_connected as split  # the pieces share vertices (issue 13)
from .compare import (
    Comparison,
    Disagreement,
    Match,
    Verdict,
    arbitrate_overlap,
    arbitrate_point,
    compare,
)
from .occt import occt_intersections
from .ocp import Segment, edges_of
from .results import EdgeIntersection, EdgeOverlap, EdgeResult, EdgeResultList

__all__ = [
    "Comparison",
    "Disagreement",
    "Match",
    "Verdict",
    "arrange",
    "arbitrate_overlap",
    "arbitrate_point",
    "compare",
    "occt_intersections",
    "EdgeIntersection",
    "EdgeOverlap",
    "EdgeResult",
    "EdgeResultList",
    "Segment",
    "edges_of",
    "intersect",
    "intersections",
    "planar_curves",
    "segments",
    "split",
    "split_both",
]

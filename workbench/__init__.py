"""relief_cad's regression workbench: corpora, relief_cad vs OCCT comparison, reports, benchmarks.

Run ``python -m workbench --help`` (or ``relief-cad-workbench --help``). The main job::

    python -m workbench quickstart          # compare + report on the bundled corpus

writes ``./relief_cad_report/report.html``.
"""

from __future__ import annotations

__all__ = ["corpus", "run", "report", "bench"]

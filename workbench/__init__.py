"""relief_cad's regression workbench: corpora, relief_cad vs OCCT comparison, reports, benchmarks.

Installed as the package ``relief_cad_workbench`` (the folder is ``workbench/`` in the
repository). Run ``relief-cad-workbench --help`` or ``python -m relief_cad_workbench --help``.
The main job::

    relief-cad-workbench quickstart          # compare + report on the bundled corpus

writes ``./relief_cad_report/report.html``.
"""

from __future__ import annotations

__all__ = ["corpus", "run", "report", "bench", "versions", "findings", "plots"]

"""Make the workbench importable under its installed name, ``relief_cad_workbench``.

An installed checkout (``pip install -e .``) maps the folder ``workbench/`` to that package.
When the tests run from a source tree on ``PYTHONPATH`` instead, a symlink named
``relief_cad_workbench`` in a temporary folder does the same, for this process and for the
command-line subprocesses the tests start.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

if importlib.util.find_spec("relief_cad_workbench") is None:
    shim = (
        Path(tempfile.gettempdir())
        / f"relief_cad_workbench_shim_{hashlib.sha256(str(ROOT).encode()).hexdigest()[:12]}"
    )
    shim.mkdir(exist_ok=True)
    link = shim / "relief_cad_workbench"
    if not link.exists():
        try:
            link.symlink_to(ROOT / "workbench", target_is_directory=True)
        except FileExistsError:  # another test process made it meanwhile
            pass
    sys.path.insert(0, str(shim))
    os.environ["PYTHONPATH"] = os.pathsep.join([str(shim), str(ROOT), os.environ.get("PYTHONPATH", "")])

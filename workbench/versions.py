"""Tool versions and the code fingerprint written into every results file.

A results file is only ever extended by a run of the same corpus with the same tools, so
that two OCCT builds, or two relief_cad revisions, are never mixed in one table.
:func:`tool_versions` takes the CAD stack's versions from ``relief_cad.cad._compat.versions()``
(issue 11) when that module is there, and otherwise asks the installed distributions.
"""

from __future__ import annotations

import hashlib
import importlib.metadata as md
from pathlib import Path

__all__ = ["tool_versions", "code_fingerprint", "occt_label"]

_DISTS = ("cadquery-ocp", "cadquery-ocp-novtk", "build123d", "cadquery", "relief-cad", "numpy")


def _dist_version(name: str) -> str | None:
    try:
        return md.version(name)
    except md.PackageNotFoundError:
        return None


def code_fingerprint() -> str:
    """SHA-256 (first 16 hex digits) of relief_cad's Python sources and the workbench's runner.

    It changes whenever the code that produces a result changes, even when the package
    version number does not (the report's own code is left out: it only reads results).

    >>> len(code_fingerprint())
    16
    """
    import relief_cad

    h = hashlib.sha256()
    root = Path(relief_cad.__file__).parent
    files = [*sorted(root.rglob("*.py")), *sorted(root.rglob("*.pyx")), Path(__file__).with_name("run.py")]
    for f in files:
        h.update(f.name.encode())
        h.update(f.read_bytes())
    return h.hexdigest()[:16]


def tool_versions() -> dict[str, str]:
    """Versions of OCCT (from the OCP build), OCP, build123d, CadQuery, relief_cad and its code.

    Returns
    -------
    dict
        ``{"occt": "7.9.3", "ocp": "cadquery-ocp 7.9.3.1", "build123d": ..., "cadquery": ...,
        "relief_cad": "0.1.0", "code": <fingerprint>}``; a tool that is not installed is left out.

    >>> "code" in tool_versions()
    True
    """
    out: dict[str, str] = {}
    try:
        from relief_cad.cad._compat import versions  # type: ignore[import-not-found, unused-ignore]

        out = {k: str(v) for k, v in versions().items() if v is not None}
    except ImportError:  # before issue 11's compatibility module: read the distributions
        out = _from_distributions()
    if "relief_cad" not in out:  # run from a source checkout
        import relief_cad

        out["relief_cad"] = str(getattr(relief_cad, "__version__", "source"))
    out["code"] = code_fingerprint()
    return out


def _from_distributions() -> dict[str, str]:
    out: dict[str, str] = {}
    for name in _DISTS:
        v = _dist_version(name)
        if v is None:
            continue
        if name.startswith("cadquery-ocp"):
            out["ocp"] = f"{name} {v}"
            out["occt"] = ".".join(v.split(".")[:3])
        else:
            out[name.replace("-", "_")] = v
    return out


def occt_label(versions: dict[str, str]) -> str:
    """A short column label for a results file: ``"OCCT 7.9.3"`` (``"OCCT ?"`` if unknown).

    >>> occt_label({"occt": "8.0.1"})
    'OCCT 8.0.1'
    """
    return f"OCCT {versions.get('occt', '?')}"

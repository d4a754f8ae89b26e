"""``bench``: run the benchmarks the other modules define and print/write their tables.

Each benchmark lives in its own module with a ``run()`` function returning a list of row
dicts, or a dict whose list-of-dict values are tables (``"rows"``, ``"cases"``...) and
whose other values are single figures: ``workbench.bench_planar`` (planar intersector),
``workbench.bench_cad`` (CAD adapters), ``workbench.bench_space`` (space intersector).
Rows are printed as a table (µs per pair and ratios against OCCT, as the module reports
them) and written as JSON. A module that is missing or fails is reported, and the other
benchmarks still run.
"""

from __future__ import annotations

import importlib
import json
import os
import time
import traceback
from pathlib import Path
from typing import Any

from relief_cad.errors import ReliefCadError

__all__ = ["BENCHMARKS", "BenchNameError", "check_names", "run_bench", "format_rows", "format_result"]

_PKG = __package__ or "relief_cad_workbench"  # "workbench" when run from a source checkout
BENCHMARKS = {
    "planar": f"{_PKG}.bench_planar",
    "cad": f"{_PKG}.bench_cad",
    "space": f"{_PKG}.bench_space",
    "arrange": f"{_PKG}.bench_arrange",  # issue 13: arrange vs BOPAlgo_Builder
    "families": f"{_PKG}.bench_families",
    "degrees": f"{_PKG}.bench_degrees",  # issue 16: cost against the degree, up to the largest
}


def format_rows(rows: list[dict[str, Any]]) -> str:
    """Rows of dicts as an aligned text table (floats with 4 significant digits)."""
    if not rows:
        return "  (no rows)"
    cols: list[str] = []
    for r in rows:
        for k in r:
            if k not in cols:
                cols.append(k)

    def fmt(v: Any) -> str:
        if isinstance(v, float):
            return f"{v:.4g}"
        return str(v)

    cells = [[fmt(r.get(c, "")) for c in cols] for r in rows]
    widths = [max(len(c), *(len(row[i]) for row in cells)) for i, c in enumerate(cols)]
    out = ["  ".join(c.ljust(w) for c, w in zip(cols, widths, strict=True))]
    out.append("  ".join("-" * w for w in widths))
    out += ["  ".join(v.rjust(w) for v, w in zip(row, widths, strict=True)) for row in cells]
    return "\n".join(out)


def format_result(res: Any) -> str:
    """A benchmark's result as text: every list of row dicts as a table, scalars as lines."""
    if isinstance(res, list):
        return format_rows([r if isinstance(r, dict) else {"value": r} for r in res])
    if not isinstance(res, dict):
        return str(res)
    out = []
    for key, val in res.items():
        if isinstance(val, list) and val and all(isinstance(r, dict) for r in val):
            out.append(f"-- {key}")
            out.append(format_rows(val))
        elif isinstance(val, dict):
            out.append(
                f"-- {key}: "
                + ", ".join(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}" for k, v in val.items())
            )
        else:
            out.append(f"{key}: {val:.4g}" if isinstance(val, float) else f"{key}: {val}")
    return "\n".join(out)


class BenchNameError(ReliefCadError, ValueError):
    """A benchmark name that is not in :data:`BENCHMARKS` (nor ``all``)."""


def check_names(names: list[str]) -> None:
    """Raise :class:`BenchNameError` naming the first unknown benchmark and the valid names."""
    for name in names:
        if name != "all" and name not in BENCHMARKS:
            known = ", ".join([*BENCHMARKS, "all"])
            raise BenchNameError(f"expected a benchmark among {known}, received {name!r}")


def _run_one(name: str, kwargs: dict[str, Any]) -> dict[str, Any]:
    """One benchmark's result record: ok (with its result), missing or error."""
    modname = BENCHMARKS[name]
    try:
        mod = importlib.import_module(modname)
    except ImportError as exc:
        print(f"== bench {name}: MISSING: {modname} is not available ({exc})")
        return {"status": "missing", "reason": f"module {modname} is missing ({exc})"}
    t0 = time.perf_counter()
    try:
        res = mod.run(**kwargs) if kwargs else mod.run()
    except Exception as exc:  # noqa: BLE001
        print(f"== bench {name}: FAILED: {type(exc).__name__}: {exc}")
        reason = f"{type(exc).__name__}: {exc}"
        return {"status": "error", "reason": reason, "traceback": traceback.format_exc()}
    print(f"== bench {name} ({time.perf_counter() - t0:.1f} s)")
    print(format_result(res))
    return {"status": "ok", "seconds": time.perf_counter() - t0,
            "result": res if isinstance(res, (dict, list)) else str(res)}


def _save(results: dict[str, Any], out: str | Path | None) -> None:
    """Write ``results`` to ``out`` as JSON, atomically (a temporary file renamed into place)."""
    if out is None:
        return
    p = Path(out)
    p.parent.mkdir(parents=True, exist_ok=True)
    tmp = p.with_name(f".{p.name}.{os.getpid()}.tmp")
    tmp.write_text(json.dumps(results, indent=1, default=str))
    os.replace(tmp, p)


def run_bench(names: list[str], out: str | Path | None = None, **kwargs: Any) -> dict[str, Any]:
    """Run the named benchmarks (``all`` for every one); returns ``{name: result}``.

    ``out`` (JSON) is rewritten after each benchmark, so a run stopped by Ctrl-C keeps the
    finished ones, and the one it stopped is marked ``"interrupted"``.

    Raises
    ------
    BenchNameError
        A name is unknown (checked before any benchmark runs or ``out`` is written).
    """
    check_names(names)
    if not names or "all" in names:
        names = list(BENCHMARKS)
    results: dict[str, Any] = {}
    for name in names:
        try:
            results[name] = _run_one(name, kwargs)
        except KeyboardInterrupt:  # the finished benchmarks are kept, this one is marked
            results[name] = {"status": "interrupted", "reason": "interrupted (Ctrl-C) before it finished"}
            _save(results, out)
            raise
        _save(results, out)  # after each benchmark: an interrupted run keeps what it measured
    if out is not None:
        print(f"benchmark results written to {out}")
    return results

"""The compare runner: relief_cad and OCCT on every pair of a corpus, in parallel, resumable.

Results go to ``<out>/results.jsonl`` (one JSON object per corpus item, written and flushed
as soon as it is computed) and ``<out>/summary.json``. A second run on the same ``out``
skips the items already there (a half-written last line from a crash is dropped), so an
interrupted run continues where it stopped. Items run on all cores by default
(``multiprocessing``), or on a Dask cluster given its scheduler address. Bad items (broken
BREP text, a corrupt corpus line, a shape with no edges, any exception) become result lines
with ``"status": "error"`` and the reason; the run goes on.
"""

from __future__ import annotations

import json
import math
import os
import sys
import time
import traceback
from collections import defaultdict
from collections.abc import Iterable, Iterator
from pathlib import Path
from typing import Any, TextIO

from .corpus import CorpusError, Item, read_corpus

__all__ = ["evaluate", "run_compare", "summarize", "format_summary", "load_results", "Progress"]


# --------------------------------------------------------------------------- one item


_WARM = False


def _warm_up() -> None:
    """Run both sides once on a tiny pair so that JIT compilation/loading is not timed."""
    global _WARM
    if _WARM:
        return
    _WARM = True
    try:
        from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
        from OCP.gp import gp_Pnt

        from relief_cad.cad.compare import compare

        a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(1, 1, 0)).Edge()
        b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 1, 0), gp_Pnt(1, 0, 0)).Edge()
        compare(a, b)
        import numpy as np

        from .corpus import _bezier_edge

        compare(
            _bezier_edge(np.array([[0, 0], [1, 2], [2, -1], [3, 1.0]])),
            _bezier_edge(np.array([[0, 1], [1, -1], [2, 2], [3, 0.0]]), np.array([1, 2, 1, 1.0])),
        )
        compare(
            _bezier_edge(np.array([[0, 0, 0], [1, 2, 1], [2, -1, 1], [3, 1, 0.0]])),
            _bezier_edge(np.array([[0, 1, 0.5], [1, -1, 0], [2, 2, 1], [3, 0, 0.5]])),
        )
    except Exception:  # noqa: BLE001 - the real run reports errors per item
        pass


def evaluate(item: Item | CorpusError) -> dict[str, Any]:
    """Compare relief_cad and OCCT on one corpus item; never raises (errors become records)."""
    _warm_up()
    if isinstance(item, CorpusError):
        return {
            "id": getattr(item, "id", "corpus"),
            "family": "corpus",
            "status": "error",
            "stage": "corpus",
            "reason": str(item),
        }
    base: dict[str, Any] = {"id": item.id, "family": item.family, "meta": item.meta or {}}
    try:
        a, b = item.shapes()
    except CorpusError as exc:
        return {**base, "status": "error", "stage": "read", "reason": str(exc)}
    try:
        from relief_cad.cad.compare import compare

        t0 = time.perf_counter()
        comp = compare(a, b, tol=item.tol)
        d = comp.to_dict()
        d["times"]["total"] = time.perf_counter() - t0
    except Exception as exc:  # noqa: BLE001 - reported per item
        tb = traceback.extract_tb(exc.__traceback__)
        where = f" at {Path(tb[-1].filename).name}:{tb[-1].lineno}" if tb else ""
        return {
            **base,
            "status": "error",
            "stage": "compare",
            "reason": f"{type(exc).__name__}: {exc}{where}",
        }
    return {**base, "status": "ok", **d}


def _evaluate_batch(items: list[Item | CorpusError]) -> list[dict[str, Any]]:
    return [evaluate(i) for i in items]


# --------------------------------------------------------------------------- progress


class Progress:
    """A one-line progress bar with rate and ETA on stderr."""

    def __init__(self, total: int, done: int = 0, stream: TextIO | None = None, enabled: bool = True) -> None:
        self.total, self.done, self.start_done = total, done, done
        self.stream = stream or sys.stderr
        self.enabled = enabled
        self.t0 = time.perf_counter()
        self.last = 0.0

    def update(self, n: int = 1, force: bool = False) -> None:
        self.done += n
        now = time.perf_counter()
        if not self.enabled or (not force and now - self.last < 0.2 and self.done < self.total):
            return
        self.last = now
        elapsed = max(now - self.t0, 1e-9)
        rate = (self.done - self.start_done) / elapsed
        left = max(self.total - self.done, 0)
        eta = left / rate if rate > 0 else math.inf
        frac = self.done / self.total if self.total else 1.0
        width = 30
        bar = "#" * int(frac * width) + "-" * (width - int(frac * width))
        eta_s = time.strftime("%H:%M:%S", time.gmtime(eta)) if math.isfinite(eta) else "--:--:--"
        self.stream.write(
            f"\rcompare [{bar}] {self.done}/{self.total} {100 * frac:5.1f}% {rate:7.1f} pairs/s ETA {eta_s}"
        )
        if self.done >= self.total:
            self.stream.write("\n")
        self.stream.flush()


# --------------------------------------------------------------------------- resume


def load_results(path: str | os.PathLike[str], *, repair: bool = False) -> list[dict[str, Any]]:
    """Read a results file; with ``repair``, drop a half-written tail line from the file itself."""
    p = Path(path)
    if not p.exists():
        return []
    out: list[dict[str, Any]] = []
    good_bytes = 0
    with open(p, "rb") as f:
        data = f.read()
    pos = 0
    for raw in data.splitlines(keepends=True):
        try:
            if not raw.endswith(b"\n"):
                raise ValueError("unterminated")
            out.append(json.loads(raw))
            good_bytes = pos + len(raw)
        except ValueError:
            if repair:
                break
        pos += len(raw)
    if repair and good_bytes != len(data):
        with open(p, "r+b") as f:
            f.truncate(good_bytes)
    return out


def _count(corpus: str | os.PathLike[str]) -> int:
    try:
        return sum(1 for _ in read_corpus(corpus))
    except CorpusError:
        return 0


# --------------------------------------------------------------------------- runner


def run_compare(
    corpus: str | os.PathLike[str],
    out: str | os.PathLike[str],
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    limit: int | None = None,
    progress: bool = True,
    stop_after: int | None = None,
    batch: int = 4,
) -> dict[str, Any]:
    """Run the comparison on a corpus and return the summary (also written to ``summary.json``).

    Parameters
    ----------
    corpus : path
        A corpus file (see :mod:`workbench.corpus`).
    out : path
        Output folder (created); holds ``results.jsonl`` and ``summary.json``.
    workers : int, optional
        Processes (default: all cores); ``1`` runs in this process.
    scheduler : str, optional
        A Dask scheduler address (``tcp://host:8786``) or a ``distributed.Client``.
    limit : int, optional
        Only the first ``limit`` items of the corpus.
    progress : bool
        Show the progress bar on stderr.
    stop_after : int, optional
        Stop after this many new results, as if interrupted (for testing resume).
    batch : int
        Items per task.
    """
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    results_path = outdir / "results.jsonl"
    done_ids = {r.get("id") for r in load_results(results_path, repair=True)}
    total = _count(corpus)
    if limit is not None:
        total = min(total, limit)

    def todo() -> Iterator[Item | CorpusError]:
        try:
            for k, item in enumerate(read_corpus(corpus)):
                if limit is not None and k >= limit:
                    return
                if getattr(item, "id", None) in done_ids:
                    continue
                yield item
        except CorpusError as exc:
            yield exc

    def batches() -> Iterator[list[Item | CorpusError]]:
        buf: list[Item | CorpusError] = []
        for it in todo():
            buf.append(it)
            if len(buf) >= batch:
                yield buf
                buf = []
        if buf:
            yield buf

    already = min(len(done_ids), total)
    bar = Progress(total, already, enabled=progress)
    new = 0
    interrupted = False
    with open(results_path, "a", encoding="utf-8") as sink:

        def write(records: Iterable[dict[str, Any]]) -> bool:
            nonlocal new
            for rec in records:
                sink.write(json.dumps(rec, default=float) + "\n")
                new += 1
                bar.update()
            sink.flush()
            return stop_after is not None and new >= stop_after

        try:
            if scheduler is not None:
                interrupted = _run_dask(scheduler, batches(), write)
            else:
                n = workers or os.cpu_count() or 1
                if n <= 1:
                    for b in batches():
                        if write(_evaluate_batch(b)):
                            interrupted = True
                            break
                else:
                    import multiprocessing as mp

                    ctx = mp.get_context("fork" if sys.platform.startswith("linux") else "spawn")
                    import threading

                    # at most 4 batches per worker in flight: the pool's feeder thread would
                    # otherwise read a corpus of millions of pairs into memory
                    slots = threading.BoundedSemaphore(4 * n)

                    def bounded() -> Iterator[list[Item | CorpusError]]:
                        for b in batches():
                            slots.acquire()
                            yield b

                    pool = ctx.Pool(n, maxtasksperchild=200)
                    try:
                        for recs in pool.imap_unordered(_evaluate_batch, bounded(), chunksize=1):
                            slots.release()
                            if write(recs):
                                interrupted = True
                                break
                    finally:
                        pool.terminate()
                        pool.join()
        except KeyboardInterrupt:
            interrupted = True
    bar.update(0, force=True)
    results = load_results(results_path)
    summary = summarize(results)
    summary["complete"] = not interrupted and len({r.get("id") for r in results}) >= total
    summary["corpus"] = str(corpus)
    (outdir / "summary.json").write_text(json.dumps(summary, indent=1, default=float))
    return summary


def _run_dask(scheduler: Any, batches: Iterator[list[Item | CorpusError]], write: Any) -> bool:
    import importlib

    dist: Any = importlib.import_module("distributed")  # untyped library
    client = scheduler if isinstance(scheduler, dist.Client) else dist.Client(scheduler)
    own = client is not scheduler
    try:
        window = max(4, 4 * sum(client.nthreads().values()))
        ac = dist.as_completed()
        for _ in range(window):
            b = next(batches, None)
            if b is None:
                break
            ac.add(client.submit(_evaluate_batch, b, pure=False))
        for fut in ac:
            if write(fut.result()):
                for f in ac.futures:
                    f.cancel()
                return True
            b = next(batches, None)
            if b is not None:
                ac.add(client.submit(_evaluate_batch, b, pure=False))
        return False
    finally:
        if own:
            client.close()


# --------------------------------------------------------------------------- summary


def summarize(results: list[dict[str, Any]]) -> dict[str, Any]:
    """Aggregate result records by family and by OCCT route."""

    def blank() -> dict[str, Any]:
        return defaultdict(float)

    fam: dict[str, Any] = defaultdict(blank)
    route: dict[str, Any] = defaultdict(blank)
    errors = []
    for r in results:
        f = fam[r.get("family", "?")]
        f["pairs"] += 1
        if r.get("status") != "ok":
            f["errors"] += 1
            errors.append({"id": r.get("id"), "stage": r.get("stage"), "reason": r.get("reason")})
            continue
        s = r.get("score", {})
        side_err = r.get("errors", {})
        for tgt in [f] + [route[x] for x in (r.get("routes") or ["(none)"])]:
            tgt["ok"] += 1
            tgt["agreed"] += s.get("agreed", 0)
            tgt["relief_cad_right"] += s.get("relief_cad_right", 0)
            tgt["occt_right"] += s.get("occt_right", 0)
            tgt["neither"] += s.get("neither", 0)
            tgt["relief_cad_inaccurate"] += s.get("relief_cad_inaccurate", 0)
            tgt["occt_inaccurate"] += s.get("occt_inaccurate", 0)
            tgt["relief_cad_failed"] += 1 if "relief_cad" in side_err else 0
            tgt["occt_failed"] += 1 if "occt" in side_err else 0
            tgt["pairs_disagreeing"] += 1 if r.get("disagreements") else 0
            t = r.get("times", {})
            tgt["relief_cad_s"] += t.get("relief_cad", 0.0)
            tgt["occt_s"] += t.get("occt", 0.0)
            tgt["arbiter_s"] += t.get("arbiter", 0.0)
        route_pairs = r.get("routes") or ["(none)"]
        for x in route_pairs:
            route[x]["pairs"] += 1
    total: dict[str, float] = defaultdict(float)
    for v in fam.values():
        for k, x in v.items():
            total[k] += x
    return {
        "by_family": {k: dict(v) for k, v in sorted(fam.items())},
        "by_route": {k: dict(v) for k, v in sorted(route.items())},
        "total": dict(total),
        "errors": errors,
    }


_COLS = (
    ("pairs", "pairs"),
    ("errors", "err"),
    ("agreed", "agreed"),
    ("pairs_disagreeing", "pairs≠"),
    ("relief_cad_right", "relief✓"),
    ("occt_right", "occt✓"),
    ("neither", "neither"),
    ("relief_cad_inaccurate", "relief~"),
    ("occt_inaccurate", "occt~"),
)


def format_summary(summary: dict[str, Any]) -> str:
    """The summary as a terminal table (by family, then by OCCT route)."""
    lines = []
    for title, key in (("family", "by_family"), ("OCCT route", "by_route")):
        rows = list(summary.get(key, {}).items())
        if key == "by_family":
            rows.append(("TOTAL", summary.get("total", {})))
        head = (
            f"{title:<22}"
            + "".join(f"{c:>9}" for _, c in _COLS)
            + f"{'µs relief':>11}{'µs occt':>10}{'ratio':>7}"
        )
        lines.append(head)
        lines.append("-" * len(head))
        for name, v in rows:
            ok = max(v.get("ok", 0), 1)
            tr, to = 1e6 * v.get("relief_cad_s", 0) / ok, 1e6 * v.get("occt_s", 0) / ok
            ratio = f"{to / tr:7.2f}" if tr > 0 else "      -"
            lines.append(
                f"{name:<22}"
                + "".join(f"{int(v.get(k, 0)):>9d}" for k, _ in _COLS)
                + f"{tr:>11.0f}{to:>10.0f}{ratio}"
            )
        lines.append("")
    lines.append(
        "relief✓/occt✓: disagreements the arbiter decided for that side; "
        "~: agreed points reported farther than tol from the true point; ratio = occt time / relief time"
    )
    if summary.get("errors"):
        lines.append(f"{len(summary['errors'])} item(s) failed; first: {summary['errors'][0]['reason']}")
    return "\n".join(lines)

"""The compare runner: relief_cad and OCCT on every pair of a corpus, in parallel, resumable.

Results go to ``<out>/results.jsonl`` (one JSON object per corpus item, written and flushed
as soon as it is computed) and ``<out>/summary.json``. A second run on the same ``out``
skips the items already there (a damaged line, e.g. half-written by a crash, is moved to
``results.jsonl.damaged`` and its item runs again), so an interrupted run continues where it
stopped. Items run on all cores by default (``multiprocessing``), or on a Dask cluster given its
scheduler address. Bad items (broken
BREP text, a corrupt corpus line, a shape with no edges, any exception) become result lines
with ``"status": "error"`` and the reason; the run goes on.
"""

from __future__ import annotations

import importlib
import json
import multiprocessing as mp
import os
import signal
import sys
import time
import traceback
from collections import defaultdict
from collections.abc import Iterable, Iterator
from concurrent.futures import FIRST_COMPLETED, Executor, Future, ProcessPoolExecutor, wait
from contextlib import contextmanager
from pathlib import Path
from typing import Any, TextIO

from tqdm import tqdm  # type: ignore[import-untyped]

from relief_cad.errors import ReliefCadError

from ._signals import raise_kept_ctrl_c, sigint_held
from .corpus import CorpusError, CorpusInfo, Item, check_corpus, read_corpus
from .versions import tool_versions

__all__ = [
    "evaluate",
    "run_compare",
    "summarize",
    "format_summary",
    "load_results",
    "read_header",
    "open_results",
    "ResultsMismatchError",
    "ResultsBusyError",
    "results_lock",
    "repair_results",
    "damaged_path",
    "InlineExecutor",
    "HEADER_KEY",
    "agreed_counts",
    "speed_ratio",
    "RATIO_NOTE",
]


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


# --------------------------------------------------------------------------- results file

HEADER_KEY = "relief_cad_results"
"""Key of the first line of a results file: ``{"relief_cad_results": {corpus, sha256, versions}}``."""


class ResultsMismatchError(ReliefCadError, ValueError):
    """A results file that belongs to another corpus or to other tool versions.

    ``same_corpus`` is true when only the versions differ (the results may be recomputed there).
    """

    def __init__(self, message: str, *, same_corpus: bool = False) -> None:
        super().__init__(message)
        self.same_corpus = same_corpus


def _split_lines(data: bytes) -> tuple[list[bytes], list[bytes]]:
    """A results file's lines: the good ones (newline-ended JSON objects) and the damaged ones."""
    good: list[bytes] = []
    bad: list[bytes] = []
    for raw in data.splitlines(keepends=True):
        try:
            if not raw.endswith(b"\n"):
                raise ValueError("unterminated")
            if not isinstance(json.loads(raw), dict):
                raise ValueError("not an object")
            good.append(raw)
        except ValueError:  # also UnicodeDecodeError: a garbage line
            bad.append(raw)
    return good, bad


def damaged_path(path: str | os.PathLike[str]) -> Path:
    """Where :func:`repair_results` keeps the damaged lines of ``path``: ``<name>.damaged``."""
    p = Path(path)
    return p.with_name(p.name + ".damaged")


def repair_results(path: str | os.PathLike[str]) -> int:
    """Move the damaged lines of a results file (garbage, a half-written last line) aside.

    Every good record stays; the damaged lines are appended to :func:`damaged_path`, so nothing
    is lost, and the results file is rewritten without them (via a temporary file and a rename).
    Returns the number of lines set aside.
    """
    p = Path(path)
    good, bad = _split_lines(p.read_bytes())
    if not bad:
        return 0
    with open(damaged_path(p), "ab") as f:
        f.writelines(raw if raw.endswith(b"\n") else raw + b"\n" for raw in bad)
    tmp = p.with_name(f".{p.name}.{os.getpid()}.tmp")
    tmp.write_bytes(b"".join(good))
    os.replace(tmp, p)
    return len(bad)


def load_results(path: str | os.PathLike[str], *, repair: bool = False) -> list[dict[str, Any]]:
    """Read a results file's records (not its header), skipping damaged lines.

    ``repair`` first moves the damaged lines aside (:func:`repair_results`).
    """
    p = Path(path)
    if not p.exists():
        return []
    if repair:
        repair_results(p)
    recs = (json.loads(raw) for raw in _split_lines(p.read_bytes())[0])
    return [rec for rec in recs if HEADER_KEY not in rec]


def read_header(path: str | os.PathLike[str]) -> dict[str, Any] | None:
    """The header of a results file (``None`` when it has none, e.g. an older workbench's file)."""
    p = Path(path)
    if not p.is_file():
        return None
    with open(p, "rb") as f:
        first = f.readline()
    try:
        head = json.loads(first)
    except ValueError:
        return None
    return head.get(HEADER_KEY) if isinstance(head, dict) else None


def _header(info: CorpusInfo, versions: dict[str, str]) -> dict[str, Any]:
    return {"corpus": str(info.path), "sha256": info.sha256, "items": info.n_items, "versions": versions}


def _mismatch(path: Path, head: dict[str, Any] | None, info: CorpusInfo, versions: dict[str, str]) -> str:
    if head is None:
        return f"{path} has no header saying which corpus it belongs to (an older workbench wrote it)"
    if head.get("sha256") != info.sha256:
        return (
            f"{path} holds results of another corpus ({head.get('corpus')}, sha256 "
            f"{str(head.get('sha256'))[:12]}), not of {info.path} (sha256 {info.sha256[:12]})"
        )
    old = head.get("versions", {})
    diff = [
        f"{k} {old.get(k, '-')} -> {versions.get(k, '-')}"
        for k in sorted(set(old) | set(versions))
        if old.get(k) != versions.get(k)
    ]
    return f"{path} was made with other tool versions ({'; '.join(diff)})" if diff else ""


def open_results(
    path: Path, info: CorpusInfo, versions: dict[str, str], *, fresh: bool = False, say: Any = None
) -> list[dict[str, Any]]:
    """Start, or continue, a results file for this corpus and these versions; returns its records.

    Damaged lines are moved aside (:func:`repair_results`), and ``say`` (if given) is told how
    many and where.

    Raises
    ------
    ResultsMismatchError
        The file holds another corpus's results, or results of other tool versions, and
        ``fresh`` is false.
    """
    if fresh:
        path.unlink(missing_ok=True)
        (path.parent / "summary.json").unlink(missing_ok=True)
    if path.exists() and path.stat().st_size:
        head = read_header(path)
        why = _mismatch(path, head, info, versions)
        if why:
            same = head is not None and head.get("sha256") == info.sha256
            msg = f"{why}; give another --out, or --fresh to replace them"
            raise ResultsMismatchError(msg, same_corpus=same)
        moved = repair_results(path)
        if moved and say is not None:
            where = f"{moved} damaged line(s) of {path} in {damaged_path(path)}"
            say(f"set aside {where} (items left without a result run again)")
        return load_results(path)
    path.write_text(json.dumps({HEADER_KEY: _header(info, versions)}) + "\n", encoding="utf-8")
    return []


class ResultsBusyError(ReliefCadError, BlockingIOError):
    """A results folder that another run is writing to at this moment."""


@contextmanager
def results_lock(folder: Path) -> Iterator[None]:
    """Hold ``folder`` for one run: a second run on it is refused, not interleaved with this one.

    An exclusive ``flock`` on the folder itself (nothing is left behind in it); it ends with the
    process, whatever way the process ends. A process holding it may enter again (quickstart holds
    the folder around its compare). Where ``fcntl`` is missing (Windows) there is no lock.

    Raises
    ------
    ResultsBusyError
        Another run holds the folder.

    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as d, results_lock(Path(d)):
    ...     with results_lock(Path(d)):  # this process may enter again; another one is refused
    ...         print("held")
    held
    >>> issubclass(ResultsBusyError, BlockingIOError)
    True
    """
    try:
        import fcntl
    except ImportError:  # pragma: no cover - not POSIX
        yield
        return
    key = os.path.realpath(folder)
    if key in _HELD:
        yield
        return
    fd = os.open(folder, os.O_RDONLY)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            msg = (f"another run is writing to {folder}; expected a folder no other run uses: "
                   "wait for it, or give another --out")
            raise ResultsBusyError(msg) from None
        _HELD.add(key)
        try:
            yield
        finally:
            _HELD.discard(key)
    finally:
        os.close(fd)


_HELD: set[str] = set()  # the folders this process holds (results_lock)


# --------------------------------------------------------------------------- executors


class InlineExecutor(Executor):
    """An executor running each task at once in this process (``workers=1``)."""

    def submit(self, fn: Any, /, *args: Any, **kwargs: Any) -> Future[Any]:  # noqa: D102
        fut: Future[Any] = Future()
        try:
            fut.set_result(fn(*args, **kwargs))
        except Exception as exc:  # noqa: BLE001 - delivered through the future
            fut.set_exception(exc)
        return fut


def _ignore_sigint() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the parent alone handles Ctrl-C
    signal.signal(signal.SIGTERM, signal.SIG_DFL)  # and terminates its workers quietly


class SchedulerError(ReliefCadError, ConnectionError):
    """A Dask scheduler address that cannot be used (malformed, or nothing answers there)."""


def _client(dist: Any, address: str) -> Any:
    """A Dask client of the scheduler at ``address``, or :class:`SchedulerError` saying why not."""
    try:
        return dist.Client(address, timeout="10s")
    except (ValueError, OSError, TimeoutError) as exc:
        why = f"{type(exc).__name__}: {exc}"
        raise SchedulerError(f"--scheduler: expected the address of a running Dask scheduler such as "
                             f"tcp://10.0.0.1:8786, received {address!r} ({why})") from None


def _executor(workers: int | None, scheduler: Any, tasks: int) -> tuple[Executor, int, Any]:
    """The executor, its in-flight window (batches) and a closer (local pool or Dask).

    A local pool has no more processes than ``tasks`` (the batches to run).
    """
    if scheduler is not None:
        dist: Any = importlib.import_module("distributed")  # untyped library
        client = scheduler if isinstance(scheduler, dist.Client) else _client(dist, scheduler)
        own = client is not scheduler
        window = max(4, 4 * sum(client.nthreads().values()))
        return client.get_executor(pure=False), window, (client.close if own else (lambda: None))
    n = min(workers or os.cpu_count() or 1, tasks)
    if n <= 1:
        return InlineExecutor(), 1, lambda: None
    ctx = mp.get_context("fork" if sys.platform.startswith("linux") else "spawn")
    pool = ProcessPoolExecutor(n, mp_context=ctx, initializer=_ignore_sigint)
    return pool, 4 * n, lambda: None


def _stop(ex: Executor) -> None:
    """Shut an executor down now: queued tasks cancelled, local workers terminated."""
    procs = list((getattr(ex, "_processes", None) or {}).values())  # a local pool's workers
    try:
        ex.shutdown(wait=False, cancel_futures=True)
    except TypeError:  # Dask's ClientExecutor.shutdown(wait) has no cancel_futures
        ex.shutdown(wait=False)
    for proc in procs:
        proc.terminate()
    for proc in procs:
        proc.join(5)


def _drive(ex: Executor, window: int, batches: Iterator[list[Item | CorpusError]], write: Any) -> bool:
    """Keep ``window`` batches in flight and write results as they come; True if ``write`` stopped it."""
    pending: set[Future[Any]] = set()

    def fill() -> None:
        while len(pending) < window:
            b = next(batches, None)
            if b is None:
                return
            pending.add(ex.submit(_evaluate_batch, b))

    with sigint_held():
        fill()
    while pending:
        done, _ = wait(pending, timeout=0.25, return_when=FIRST_COMPLETED)  # short: Ctrl-C is seen
        for fut in done:
            pending.discard(fut)
            if write(fut.result()):
                return True
        raise_kept_ctrl_c()  # one that came while a finalizer ran (the CLI keeps it), once written
        with sigint_held():
            fill()
    return False


def _raise_interrupt(signum: int, frame: Any) -> None:
    raise KeyboardInterrupt


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
    fresh: bool = False,
    info: CorpusInfo | None = None,
    say: Any = None,
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
        Show the progress bar (tqdm) on stderr.
    stop_after : int, optional
        Stop after this many new results, as if interrupted (for testing resume).
    batch : int
        Items per task.
    fresh : bool
        Discard the results already in ``out`` instead of resuming them.
    info : CorpusInfo, optional
        The corpus's :func:`~workbench.corpus.check_corpus` answer, if already known.
    say : callable, optional
        Called with a one-line message when a run resumes (``"resuming: N of M ..."``), and
        when damaged lines of ``results.jsonl`` are set aside.

    Returns
    -------
    dict
        :func:`summarize`'s answer plus ``complete``, ``interrupted``, ``resumed`` (items found
        done), ``expected`` (items asked for), ``corpus`` and ``versions``.

    Raises
    ------
    CorpusError
        The corpus is unusable (see :func:`~workbench.corpus.check_corpus`).
    ResultsMismatchError
        ``out`` holds results of another corpus or other tool versions (and not ``fresh``).
    """
    info = info or check_corpus(corpus)
    versions = tool_versions()
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    with results_lock(outdir):
        return _compare_into(outdir, corpus, info, versions, workers=workers, scheduler=scheduler,
                             limit=limit, progress=progress, stop_after=stop_after, batch=batch, fresh=fresh,
                             say=say)


def _compare_into(outdir: Path, corpus: str | os.PathLike[str], info: CorpusInfo, versions: dict[str, str], *,
                  workers: int | None, scheduler: str | None, limit: int | None, progress: bool,
                  stop_after: int | None, batch: int, fresh: bool, say: Any) -> dict[str, Any]:
    """:func:`run_compare` once the folder is held: resume or start ``results.jsonl``, run, summarize."""
    results_path = outdir / "results.jsonl"
    expected = info.ids[:limit] if limit is not None else info.ids
    done_ids = {r.get("id") for r in open_results(results_path, info, versions, fresh=fresh, say=say)}
    already = len(done_ids & set(expected))
    if already and say is not None:
        say(f"resuming: {already} of {len(expected)} items already done in {results_path}")
    interrupted = False
    bar = tqdm(
        total=len(expected),
        initial=already,
        desc="compare",
        unit="pair",
        disable=not progress,
        file=sys.stderr,
        dynamic_ncols=True,
    )
    old_term = signal.signal(signal.SIGTERM, _raise_interrupt) if _main_thread() else None
    try:
        with open(results_path, "a", encoding="utf-8") as sink:
            write = _writer(sink, bar, stop_after)
            ex, window, close = _executor(workers, scheduler, -(-len(set(expected) - done_ids) // batch))
            try:
                _drive(ex, window, _batches(corpus, set(expected), done_ids, batch), write)
            except KeyboardInterrupt:
                interrupted = True
            finally:
                _stop(ex)
                close()
    finally:
        bar.close()
        if old_term is not None:
            signal.signal(signal.SIGTERM, old_term)
    results = load_results(results_path)
    summary = summarize(results)
    have = {r.get("id") for r in results}
    summary.update(
        complete=not interrupted and set(expected) <= have,  # --stop-after N with N items left: all done
        interrupted=interrupted,
        resumed=already,
        expected=len(expected),
        corpus=str(corpus),
        versions=versions,
    )
    (outdir / "summary.json").write_text(json.dumps(summary, indent=1, default=float))
    return summary


def _main_thread() -> bool:
    import threading

    return threading.current_thread() is threading.main_thread()


def _writer(sink: TextIO, bar: Any, stop_after: int | None) -> Any:
    new = 0

    def write(records: Iterable[dict[str, Any]]) -> bool:
        nonlocal new
        for rec in records:
            sink.write(json.dumps(rec, default=float) + "\n")
            new += 1
            bar.update()
        sink.flush()
        return stop_after is not None and new >= stop_after

    return write


def _batches(
    corpus: str | os.PathLike[str], wanted: set[str], done: set[Any], size: int
) -> Iterator[list[Item | CorpusError]]:
    buf: list[Item | CorpusError] = []
    for item in read_corpus(corpus):
        key = getattr(item, "id", None)
        if key not in wanted or key in done:
            continue
        buf.append(item)
        if len(buf) >= size:
            yield buf
            buf = []
    if buf:
        yield buf


# --------------------------------------------------------------------------- summary


def agreed_counts(rec: dict[str, Any]) -> tuple[int, int]:
    """Matches of one record: ``(agreed, loose)``.

    Agreed: both answers within ``tol`` of each other and of the arbiter's true point.
    Loose: matched only after refinement, or one side farther than ``tol`` from the truth.

    >>> agreed_counts({"tol": 1e-7, "agreed": [{"loose": False, "relief_error": 0, "occt_error": 0.3}]})
    (0, 1)
    """
    tol = float(rec.get("tol") or 0.0)
    strict = loose = 0
    for m in rec.get("agreed", []):
        errs = [e for e in (m.get("relief_error"), m.get("occt_error")) if e is not None]
        if m.get("loose") or any(e > tol for e in errs):
            loose += 1
        else:
            strict += 1
    return strict, loose


def speed_ratio(relief_s: float, occt_s: float) -> float:
    """The one speed ratio of the workbench: relief_cad time / OCCT time (below 1: relief_cad faster).

    >>> speed_ratio(1.0, 4.0)
    0.25
    """
    return relief_s / occt_s if occt_s > 0 else float("nan")


RATIO_NOTE = (
    "ratio = relief_cad time / OCCT time on the same pairs in the same run; below 1 = relief_cad faster"
)


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
        strict, loose = agreed_counts(r)
        for tgt in [f] + [route[x] for x in (r.get("routes") or ["(none)"])]:
            tgt["ok"] += 1
            tgt["agreed"] += strict
            tgt["loose"] += loose
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
    ("loose", "loose"),
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
            ratio = f"{speed_ratio(tr, to):7.2f}" if to > 0 else "      -"
            lines.append(
                f"{name:<22}"
                + "".join(f"{int(v.get(k, 0)):>9d}" for k, _ in _COLS)
                + f"{tr:>11.0f}{to:>10.0f}{ratio}"
            )
        lines.append("")
    lines.append(
        "agreed: both within tol of each other and of the arbiter's true point; loose: matched, but only "
        "after refinement or farther than tol; relief✓/occt✓: disagreements the arbiter decided for that "
        "side; neither: both wrong; ~: points farther than tol from the true point"
    )
    lines.append(RATIO_NOTE)
    errs = summary.get("errors") or []
    if errs:
        lines.append(f"{len(errs)} item(s) failed:")
        lines += [f"  {e['id']}: {e['reason']}" for e in errs[:20]]
        if len(errs) > 20:
            lines.append(f"  ... and {len(errs) - 20} more (all in results.jsonl and the report)")
    return "\n".join(lines)

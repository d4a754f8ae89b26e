"""Command line of the relief_cad workbench (relief-cad-workbench, or python -m relief_cad_workbench).

Exit status: 0 everything asked for was done; 1 some items or inputs failed (they are listed);
2 unusable input (one line says why); 3 stopped before the end (--stop-after); 130 interrupted
(Ctrl-C or SIGTERM; run the same command again to resume).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ._signals import (
    command_done,
    ctrl_c_in_finalizers_kept,
    ctrl_c_until_done,
    raise_kept_ctrl_c,
    sigint_held,
)

__all__ = [
    "main",
    "cli",
    "build_parser",
    "EXIT_OK",
    "EXIT_FAILED",
    "EXIT_BAD_INPUT",
    "EXIT_INCOMPLETE",
    "EXIT_INTERRUPTED",
]

EXIT_OK, EXIT_FAILED, EXIT_BAD_INPUT, EXIT_INCOMPLETE, EXIT_INTERRUPTED = 0, 1, 2, 3, 130

DESCRIPTION = """\
Compare relief_cad's curve/curve intersections with OpenCASCADE's on whole corpora of edge
pairs; where the two disagree, a 50-digit arbiter decides who is right.

commands:
  corpus      build a corpus file (random families, glyphs, sketches, STEP files)
  compare     relief_cad vs OCCT on every pair of a corpus, or of STEP files given directly
              (all cores, or a Dask cluster; resumable)
  report      a self-contained HTML report of one or several compare runs
  bench       the benchmarks (planar, cad, space, arrange, families, degrees) as tables and JSON
  quickstart  compare + report on the bundled corpus into ./relief_cad_report/

exit status: 0 everything asked for was done; 1 some items or inputs failed (listed);
2 unusable input; 3 stopped early (--stop-after); 130 interrupted (run again to resume)
"""


class _Usage(Exception):
    """Unusable input: printed as one ``error:`` line, exit status 2."""


def _say(msg: str) -> None:
    print(msg, file=sys.stderr)


def _int_at_least(low: int) -> Callable[[str], int]:
    """An argparse ``type``: an integer >= ``low``, else argparse's one-line error (exit status 2)."""

    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected an integer >= {low}, received {text!r}") from None
        if value < low:
            raise argparse.ArgumentTypeError(f"expected an integer >= {low}, received {value}")
        return value

    return parse


def _check_folder(path: str | Path, what: str) -> Path:
    """Refuse (:class:`_Usage`) an output folder that cannot be made or written; leaves nothing behind."""
    p = Path(path)
    if p.exists() and not p.is_dir():
        raise _Usage(f"{what}: expected a folder to write into, received {p}, an existing file")
    made = [q for q in (p, *p.parents) if not q.exists()]  # what mkdir creates, deepest first
    try:
        p.mkdir(parents=True, exist_ok=True)
        tempfile.TemporaryFile(dir=p).close()
    except OSError as exc:
        why = exc.strerror or exc
        raise _Usage(f"{what}: expected a folder that can be written, received {p} ({why})") from None
    finally:
        for q in made:
            with contextlib.suppress(OSError):
                q.rmdir()
    return p


def _check_file(path: str | Path, what: str) -> Path:
    """Refuse (:class:`_Usage`) an output file that cannot be written; leaves nothing behind."""
    p = Path(path)
    if p.is_dir():
        raise _Usage(f"{what}: expected a file name, received {p}, an existing folder")
    _check_folder(p.parent, f"{what} {p}")
    return p


def _cmd_corpus(args: argparse.Namespace) -> int:
    from .corpus import (
        CAD_FAMILIES,
        CONTACT_FAMILIES,
        RANDOM_FAMILIES,
        CorpusError,
        build_corpus,
        bundled_items,
        check_families,
        write_corpus,
    )

    fams = args.families.split(",") if args.families else [*RANDOM_FAMILIES, *CAD_FAMILIES, *CONTACT_FAMILIES]
    if not args.bundled:
        check_families(fams)
    _check_file(args.out, "OUT")
    problems: list[str] = []
    source = bundled_items() if args.bundled else build_corpus(fams, args.count, args.seed, args.step or ())

    def items() -> Any:  # the file is written (renamed into place) only when this ends normally
        n = 0
        for it in source:
            raise_kept_ctrl_c()  # one that came while a finalizer ran (see cli)
            if isinstance(it, CorpusError):
                problems.append(str(it))
                _say(f"skipped: {it}")
                continue
            n += 1
            yield it
        if n == 0:
            raise _Usage(f"no items: every input was skipped, {args.out} was not written")

    n = write_corpus(args.out, items())
    print(
        f"wrote {n} items ({', '.join(fams)}) to {args.out}"
        + (f"; {len(problems)} input(s) skipped" if problems else "")
    )
    return EXIT_FAILED if problems else EXIT_OK


def _is_step(p: Path) -> bool:
    if p.is_dir() or p.suffix.lower() in (".step", ".stp"):
        return True
    try:
        with open(p, "rb") as f:
            return f.read(12) == b"ISO-10303-21"
    except OSError:
        return False


def _step_corpus(inputs: list[Path], out: Path, count: int, within: bool) -> tuple[Path, list[str]]:
    """Build a corpus from STEP files/folders into ``out``; returns its path and the skipped inputs."""
    import hashlib
    import os

    from .corpus import CorpusError, step_family, write_corpus

    skipped: list[str] = []

    def items() -> Any:
        for it in step_family(inputs, count, across=not within):
            if isinstance(it, CorpusError):
                skipped.append(str(it))
                _say(f"skipped: {it}")
            else:
                yield it

    out.mkdir(parents=True, exist_ok=True)
    tmp = out / f".corpus-{os.getpid()}.jsonl"
    n = write_corpus(tmp, items())
    if n == 0:
        tmp.unlink(missing_ok=True)
        raise _Usage(f"no edge pairs from {', '.join(map(str, inputs))}: no usable STEP input")
    digest = hashlib.sha256(tmp.read_bytes()).hexdigest()[:12]
    final = out / f"step-corpus-{digest}.jsonl"
    tmp.replace(final)
    mode = "within each file" if within or len(inputs) < 2 else "across the files"
    _say(f"built {n} STEP edge pairs ({mode}) into {final}")
    return final, skipped


def _corpus_of(args: argparse.Namespace) -> tuple[Path, list[str]]:
    from .corpus import bundled_corpus_path

    inputs = [Path(x) for x in args.inputs]
    if not inputs:
        return bundled_corpus_path(), []
    missing = [p for p in inputs if not p.exists()]
    if missing:
        raise _Usage(f"{missing[0]}: no such file or folder")
    steps = [p for p in inputs if _is_step(p)]
    if steps:
        if len(steps) != len(inputs):
            raise _Usage("expected either one corpus file or STEP files/folders, received a mix of both")
        return _step_corpus(steps, Path(args.out), args.count, args.within)
    if len(inputs) > 1:
        raise _Usage(
            f"expected one corpus file, received {len(inputs)} (merge them with corpus, or run each)"
        )
    return inputs[0], []


def _finish(summary: dict[str, Any], skipped: list[str], results: Path, t0: float) -> int:
    from .run import format_summary

    print(format_summary(summary))
    for s in skipped:
        print(f"skipped input: {s}")
    took = f"{time.perf_counter() - t0:.1f} s"
    if summary.get("interrupted"):
        print(f"INTERRUPTED: {results} holds what was done; run the same command again to resume ({took})")
        return EXIT_INTERRUPTED
    if not summary.get("complete"):
        print(f"STOPPED before the end: results in {results}; run again to resume ({took})")
        return EXIT_INCOMPLETE
    failed = len(summary.get("errors") or []) + len(skipped)
    state = f"complete, {failed} failure(s) listed above" if failed else "complete"
    print(f"{state}: results in {results} ({took})")
    return EXIT_FAILED if failed else EXIT_OK


def _cmd_compare(args: argparse.Namespace) -> int:
    from .corpus import check_corpus
    from .run import run_compare

    t0 = time.perf_counter()
    _check_folder(args.out, "--out")
    corpus, skipped = _corpus_of(args)
    info = check_corpus(corpus)
    summary = run_compare(
        corpus,
        args.out,
        workers=args.workers,
        scheduler=args.scheduler,
        limit=args.limit,
        progress=not args.quiet,
        stop_after=args.stop_after,
        fresh=args.fresh,
        info=info,
        say=_say,
    )
    return _finish(summary, skipped, Path(args.out) / "results.jsonl", t0)


def _cmd_report(args: argparse.Namespace) -> int:
    from .report import write_report

    paths = [Path(x) for x in args.results]
    out = Path(args.out) if args.out else (paths[0] if paths[0].is_dir() else paths[0].parent)
    if args.out or out.exists():  # else the results are missing, and write_report says so
        _check_folder(out, "--out")
    path = write_report(paths, out, corpus=args.corpus, max_pictures=args.max_pictures)
    print(f"report written to {path.resolve()}")
    return EXIT_OK


def _cmd_bench(args: argparse.Namespace) -> int:
    from .bench import run_bench

    _check_file(args.json, "--json")
    try:
        res = run_bench(args.names or ["all"], args.json)
    except KeyboardInterrupt:
        print(f"\ninterrupted; the benchmarks that finished are in {args.json}", file=sys.stderr)
        return EXIT_INTERRUPTED
    return EXIT_OK if all(v.get("status") == "ok" for v in res.values()) else EXIT_FAILED


def _cmd_quickstart(args: argparse.Namespace) -> int:
    from .run import results_lock

    out = _check_folder(args.out, "--out")
    out.mkdir(parents=True, exist_ok=True)
    with results_lock(out):  # from the reuse check to the report
        return _quickstart_in(out, args)


def _quickstart_in(out: Path, args: argparse.Namespace) -> int:
    from .corpus import bundled_corpus_path, check_corpus
    from .report import write_report
    from .run import ResultsMismatchError, open_results, read_header, run_compare
    from .versions import tool_versions

    corpus, t0 = bundled_corpus_path(), time.perf_counter()
    info, results = check_corpus(corpus), out / "results.jsonl"
    fresh = args.fresh
    if not fresh and read_header(results) is not None:
        try:
            open_results(results, info, tool_versions(), say=_say)
            _say(f"reusing the results in {results} (same corpus, same code and tool versions)")
        except ResultsMismatchError as exc:
            if not exc.same_corpus:  # another corpus's results: refused, as compare does
                raise
            _say(f"{str(exc).split('; give')[0]}: running again from scratch")
            fresh = True
    print(f"comparing relief_cad with OCCT on the bundled corpus ({corpus.name}) ...")
    summary = run_compare(
        corpus, out, workers=args.workers, progress=not args.quiet, fresh=fresh, info=info, say=_say
    )
    code = _finish(summary, [], results, t0)
    path = write_report([out], out, corpus=corpus)
    print(f"\nreport: {path.resolve()}\n(open it in a browser; it is a single self-contained file)")
    return code


def _prog() -> str:
    name = Path(sys.argv[0]).name if sys.argv and sys.argv[0] else ""
    if name and name not in ("__main__.py", "-c", "-m"):
        return name
    return f"python -m {__package__ or 'relief_cad_workbench'}"


def _add_compare(sub: Any) -> None:
    m = sub.add_parser(
        "compare",
        help="relief_cad vs OCCT on every pair of a corpus, or of STEP files",
        description="Compare relief_cad with OCCT on every pair of a corpus file (made by the corpus "
        "command), or of STEP files and folders given directly: their edges are paired on the fly "
        "(across the files; --within for pairs inside each file). Resumes an interrupted run in the "
        "same --out folder; refuses a folder holding another corpus's results unless --fresh.",
    )
    m.add_argument(
        "inputs",
        nargs="*",
        metavar="INPUT",
        help="a corpus file (.jsonl / .jsonl.gz), or STEP files/folders (default: the bundled corpus)",
    )
    m.add_argument("--out", default="relief_cad_compare", help="output folder (default ./relief_cad_compare)")
    m.add_argument("--fresh", action="store_true", help="discard the results already in --out and start over")
    m.add_argument(
        "--within",
        action="store_true",
        help="STEP inputs: pair edges within each file instead of across the files",
    )
    m.add_argument(
        "--count",
        type=_int_at_least(1),
        default=200,
        help="STEP inputs: edge pairs to build in all (default 200)",
    )
    m.add_argument(
        "--workers",
        type=_int_at_least(1),
        default=None,
        help="worker processes (default: all cores; 1: in this process; never more than the batches to run)",
    )
    m.add_argument(
        "--scheduler",
        default=None,
        help="Dask scheduler address, e.g. tcp://10.0.0.1:8786 (instead of local processes)",
    )
    m.add_argument(
        "--limit", type=_int_at_least(1), default=None, help="only the first N items of the corpus"
    )
    m.add_argument("--quiet", action="store_true", help="no progress bar")
    m.add_argument(
        "--stop-after",
        type=_int_at_least(1),
        default=None,
        metavar="N",
        help="stop after N new results, as an interruption would (exit status 3; for testing resume)",
    )
    m.set_defaults(func=_cmd_compare)


def _add_corpus(sub: Any) -> None:
    c = sub.add_parser(
        "corpus",
        help="build a corpus file",
        description="Build a corpus file of edge pairs (JSON lines of OCCT BREP text).",
    )
    c.add_argument("out", help="output file (.jsonl or .jsonl.gz)")
    c.add_argument(
        "--families",
        default="",
        help="comma-separated families (default: all); random: cubic, "
        "rational, high-degree, ill-conditioned, tangent, overlap, shared-end, near-miss, scaled, "
        "space; CAD: glyph, sketch, step, conic (conics and splines in contact)",
    )
    c.add_argument("--count", type=_int_at_least(1), default=20, help="items per family (default 20)")
    c.add_argument("--seed", type=_int_at_least(0), default=0, help="seed of the random families (default 0)")
    c.add_argument(
        "--step",
        action="append",
        help="a STEP file or folder for the 'step' family (repeatable; default: the bundled parts)",
    )
    c.add_argument(
        "--bundled",
        action="store_true",
        help="write the bundled corpus's recipe (ignores the other "
        "options; this is how workbench/data/bundled.jsonl.gz is made)",
    )
    c.set_defaults(func=_cmd_corpus)


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the workbench command line."""
    p = argparse.ArgumentParser(
        prog=_prog(), description=DESCRIPTION, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    _add_corpus(sub)
    _add_compare(sub)
    r = sub.add_parser(
        "report",
        help="HTML report of one or several compare runs",
        description="Write a self-contained HTML report. Several results (one compare run "
        "per OCCT version on the same corpus) get one column per version.",
    )
    r.add_argument("results", nargs="+", help="compare output folder(s) or their results.jsonl")
    r.add_argument("--out", default=None, help="output folder (default: next to the first results)")
    r.add_argument(
        "--corpus", default=None, help="the corpus, for the pictures (default: as recorded by compare)"
    )
    r.add_argument(
        "--max-pictures", type=_int_at_least(0), default=200, help="at most this many pictures (default 200)"
    )
    r.set_defaults(func=_cmd_report)
    b = sub.add_parser("bench", help="the benchmarks (default: all of them)")
    b.add_argument("names", nargs="*", help="planar, cad, space, arrange, families, degrees or all")
    b.add_argument("--json", default="bench.json", help="write results here (default bench.json)")
    b.set_defaults(func=_cmd_bench)
    q = sub.add_parser(
        "quickstart",
        help="compare + report on the bundled corpus",
        description="Compare + report on the bundled corpus. Reuses the results in --out when "
        "they were made by the same code and tools, and says so; reruns them when other versions "
        "made them; refuses a folder holding another corpus's results unless --fresh.",
    )
    q.add_argument("--out", default="relief_cad_report", help="output folder (default ./relief_cad_report)")
    q.add_argument(
        "--workers", type=_int_at_least(1), default=None, help="worker processes (default: all cores)"
    )
    q.add_argument("--fresh", action="store_true", help="recompute even when the results could be reused")
    q.add_argument("--quiet", action="store_true", help="no progress bar")
    q.set_defaults(func=_cmd_quickstart)
    return p


def _preload() -> None:
    """Import relief_cad, the CAD layer (OCP) and build123d up front, where a Ctrl-C cannot cut them in half.

    build123d was imported on the first item a corpus family builds: a Ctrl-C half a second into
    ``corpus`` came during that import (pybind11 modules of OCP), and the run ended with status 0.
    """
    import relief_cad  # noqa: F401

    for name in ("relief_cad.cad", "build123d"):
        try:
            importlib.import_module(name)
        except ImportError:  # no OCP, or no build123d: the command that needs it says so
            pass


def main(argv: list[str] | None = None) -> int:
    """Run the workbench command line; returns the exit status (see the module docstring)."""
    try:
        args = build_parser().parse_args(argv)
        with sigint_held():
            _preload()
        from relief_cad.errors import ReliefCadError
    except KeyboardInterrupt:
        command_done()
        print("\ninterrupted before any work was done", file=sys.stderr)
        return EXIT_INTERRUPTED
    try:
        status = int(args.func(args))
        command_done()  # in this try: a Ctrl-C before it is handled below, one after is dropped
        return status
    except (_Usage, ReliefCadError) as exc:
        command_done()
        print(f"error: {exc}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        command_done()
        print("\ninterrupted; run the same command again to resume", file=sys.stderr)
        return EXIT_INTERRUPTED


def cli() -> None:
    """The console entry point: :func:`main`, then exit with its status.

    Once the command is done, a Ctrl-C has nothing left to stop: it is ignored from then on
    (``ctrl_c_until_done``), also while the interpreter shuts down (OCP's modules take a moment
    to unload), so it cannot kill the process by the signal and hide the real exit status. One
    that comes while a finalizer runs prints no traceback: the loops of compare and corpus raise
    it (``ctrl_c_in_finalizers_kept``). A Ctrl-C before ``main`` starts (while Python imports the
    standard library) is Python's own.
    """
    with ctrl_c_in_finalizers_kept(), ctrl_c_until_done():
        status = main()
    sys.exit(status)


if __name__ == "__main__":
    cli()

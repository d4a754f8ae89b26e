"""Command line of the relief_cad workbench (``python -m workbench`` / ``relief-cad-workbench``).

Subcommands::

    corpus      build a corpus file (random families, glyphs, sketches, STEP files)
    compare     relief_cad vs OCCT on every pair of a corpus (parallel, Dask, resumable)
    report      a self-contained HTML report of a compare run
    bench       the benchmarks (planar, cad, space, arrange) as a table and JSON
    quickstart  compare + report on the bundled corpus into ./relief_cad_report/
"""

from __future__ import annotations

import argparse
import sys
import time
from collections.abc import Iterator
from pathlib import Path

__all__ = ["main"]


def _cmd_corpus(args: argparse.Namespace) -> int:
    from .corpus import RANDOM_FAMILIES, CorpusError, Item, build_corpus, bundled_items, write_corpus

    fams = args.families.split(",") if args.families else list(RANDOM_FAMILIES) + ["glyph", "sketch", "step"]
    problems: list[str] = []
    source = bundled_items() if args.bundled else build_corpus(fams, args.count, args.seed, args.step or ())

    def items() -> Iterator[Item]:
        for it in source:
            if isinstance(it, CorpusError):
                problems.append(str(it))
                print(f"skipped: {it}", file=sys.stderr)
                continue
            yield it

    try:
        n = write_corpus(args.out, items())
    except CorpusError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    print(
        f"wrote {n} items ({', '.join(fams)}) to {args.out}"
        + (f"; {len(problems)} input(s) skipped" if problems else "")
    )
    return 0


def _cmd_compare(args: argparse.Namespace) -> int:
    from .corpus import bundled_corpus_path
    from .run import format_summary, run_compare

    corpus = args.corpus or bundled_corpus_path()
    if not Path(corpus).is_file():
        print(
            f"error: expected a corpus file (python -m workbench corpus OUT makes one), received {corpus}",
            file=sys.stderr,
        )
        return 2
    t0 = time.perf_counter()
    summary = run_compare(
        corpus,
        args.out,
        workers=args.workers,
        scheduler=args.scheduler,
        limit=args.limit,
        progress=not args.quiet,
        stop_after=args.stop_after,
    )
    print(format_summary(summary))
    state = "complete" if summary.get("complete") else "INTERRUPTED (run again to resume)"
    print(f"{state}: results in {Path(args.out) / 'results.jsonl'} ({time.perf_counter() - t0:.1f} s)")
    return 0 if summary.get("complete") else 3


def _cmd_report(args: argparse.Namespace) -> int:
    from .report import write_report

    path = write_report(
        args.results,
        args.out or (Path(args.results) if Path(args.results).is_dir() else Path(args.results).parent),
        corpus=args.corpus,
        max_pictures=args.max_pictures,
    )
    print(f"report written to {path.resolve()}")
    return 0


def _cmd_bench(args: argparse.Namespace) -> int:
    from .bench import run_bench

    res = run_bench(args.names or ["all"], args.json)
    return 0 if all(v.get("status") == "ok" for v in res.values()) else 1


def _cmd_quickstart(args: argparse.Namespace) -> int:
    from .corpus import bundled_corpus_path
    from .report import write_report
    from .run import format_summary, run_compare

    out = Path(args.out)
    print(f"comparing relief_cad with OCCT on the bundled corpus ({bundled_corpus_path().name}) ...")
    summary = run_compare(bundled_corpus_path(), out, workers=args.workers, progress=not args.quiet)
    print(format_summary(summary))
    path = write_report(out, out, corpus=bundled_corpus_path())
    print(f"\nreport: {path.resolve()}\n(open it in a browser; it is a single self-contained file)")
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the workbench command line."""
    p = argparse.ArgumentParser(
        prog="python -m workbench", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    sub = p.add_subparsers(dest="command", required=True)

    c = sub.add_parser("corpus", help="build a corpus file")
    c.add_argument("out", help="output file (.jsonl or .jsonl.gz)")
    c.add_argument(
        "--families",
        default="",
        help="comma-separated families (default: all); random: cubic, "
        "rational, high-degree, ill-conditioned, tangent, overlap, shared-end, near-miss, scaled, space; "
        "CAD: glyph, sketch, step",
    )
    c.add_argument("--count", type=int, default=20, help="items per family (default 20)")
    c.add_argument("--seed", type=int, default=0)
    c.add_argument(
        "--step",
        action="append",
        help="a STEP file or folder for the 'step' family (repeatable; default: the bundled parts)",
    )
    c.add_argument(
        "--bundled",
        action="store_true",
        help="write the bundled corpus's recipe (ignores the "
        "other options; this is how workbench/data/bundled.jsonl.gz is made)",
    )
    c.set_defaults(func=_cmd_corpus)

    m = sub.add_parser("compare", help="relief_cad vs OCCT on every pair of a corpus")
    m.add_argument("corpus", nargs="?", help="corpus file (default: the bundled corpus)")
    m.add_argument("--out", default="relief_cad_compare", help="output folder (default ./relief_cad_compare)")
    m.add_argument("--workers", type=int, default=None, help="processes (default: all cores)")
    m.add_argument("--scheduler", default=None, help="Dask scheduler address, e.g. tcp://10.0.0.1:8786")
    m.add_argument("--limit", type=int, default=None, help="only the first N items")
    m.add_argument("--quiet", action="store_true", help="no progress bar")
    m.add_argument("--stop-after", type=int, default=None, help=argparse.SUPPRESS)
    m.set_defaults(func=_cmd_compare)

    r = sub.add_parser("report", help="HTML report of a compare run")
    r.add_argument("results", help="compare output folder or its results.jsonl")
    r.add_argument("--out", default=None, help="output folder (default: next to the results)")
    r.add_argument("--corpus", default=None, help="the corpus (default: as recorded by compare)")
    r.add_argument("--max-pictures", type=int, default=200)
    r.set_defaults(func=_cmd_report)

    b = sub.add_parser("bench", help="benchmarks: planar, cad, space, arrange (default all)")
    b.add_argument("names", nargs="*", help="planar, cad, space, arrange or all")
    b.add_argument("--json", default="bench.json", help="write results here (default bench.json)")
    b.set_defaults(func=_cmd_bench)

    q = sub.add_parser("quickstart", help="compare + report on the bundled corpus")
    q.add_argument("--out", default="relief_cad_report", help="output folder (default ./relief_cad_report)")
    q.add_argument("--workers", type=int, default=None)
    q.add_argument("--quiet", action="store_true")
    q.set_defaults(func=_cmd_quickstart)
    return p


def main(argv: list[str] | None = None) -> int:
    """Run the workbench command line; returns the exit status."""
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args))
    except KeyboardInterrupt:
        print("\ninterrupted; run the same command again to resume", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())

"""``report``: a self-contained HTML report of one or several compare runs (viewable offline).

The page opens with a conclusion: what was compared, who was right how often, and where
each side fails, by kind (:mod:`workbench.findings`). Then: one column set per OCCT version
when several results files are given (one ``compare`` run per OCCT version on the same
corpus), the summary tables, full-width histograms, the slowest pairs with the likely
reason, the failed items, every disagreement (repeated copies grouped into one row with a
count) with a picture that has a legend and a zoomed inset per disputed spot, and a
glossary of every column. HTML comes from a jinja2 template with autoescape on.
"""

from __future__ import annotations

import base64
import datetime as _dt
import math
import statistics
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from relief_cad.errors import ReliefCadError

from .corpus import Item, check_corpus, read_corpus
from .findings import KINDS, findings, tally
from .plots import Picture, hist_png, pair_png
from .run import _COLS, RATIO_NOTE, agreed_counts, load_results, read_header, speed_ratio, summarize
from .versions import occt_label

__all__ = ["write_report", "ReportInputError", "GLOSSARY"]


class ReportInputError(ReliefCadError, ValueError):
    """A results path the report cannot use (missing, no results file in the folder, no records)."""


GLOSSARY = {
    "pairs": "corpus items (an edge pair, or one shape for its self-intersections)",
    "err": "items that could not be compared at all (unreadable BREP, no edges, a crash); listed below",
    "agreed": "points both sides report, within tol of each other and of the arbiter's true point",
    "loose": "points both report that match only after refinement, or with one side farther than tol "
    "from the true point (counted apart from agreed)",
    "pairs≠": "items with at least one disagreement",
    "relief✓": "disagreements the arbiter decided for relief_cad",
    "occt✓": "disagreements the arbiter decided for OCCT",
    "neither": "disagreements where both sides are wrong",
    "relief~ / occt~": "points of that side farther than tol from the arbiter's true point",
    "µs relief / µs OCCT": "mean wall time per item of one call in a worker process (after a warm-up)",
    "ratio": RATIO_NOTE,
    "route": "the OCCT algorithm that answered: Geom2dInt_GInter (planar), IntTools_EdgeEdge (space), "
    "BRepAlgoAPI_Section (fallback); (none) means OCCT reported nothing, so no route was recorded",
    "finding": "one kind of mistake by one side in one pair; repeated copies of one point are one "
    "finding with a count",
    "kinds of mistake": "missed: a true point not reported; spurious: a point that is not there; "
    "duplicate copies: the same point reported again; misplaced: a point reported off its true place; "
    "tangency as a segment: a tangent point reported as an overlap; overlap in pieces: an overlap "
    "reported as points or as part of its range; both wrong: the arbiter agrees with neither side",
}


@dataclass
class Run:
    """One results file: where it is, its header, records, summary and column label."""

    path: Path
    header: dict[str, Any]
    recs: list[dict[str, Any]]
    summary: dict[str, Any]
    label: str


def _results_file(p: Path) -> Path:
    if p.is_dir():
        if not (p / "results.jsonl").is_file():
            raise ReportInputError(f"{p}: no results.jsonl in this folder (compare --out {p} makes one)")
        return p / "results.jsonl"
    if not p.exists():
        raise ReportInputError(f"{p}: no such results file or folder")
    return p


def load_run(path: str | Path) -> Run:
    """Read one results file (or compare folder) for the report; :class:`ReportInputError` if unusable."""
    rp = _results_file(Path(path))
    recs = load_results(rp)
    if not recs:
        raise ReportInputError(f"{rp}: no results in this file (expected lines written by compare)")
    stray = next((i for i, r in enumerate(recs, 1) if "status" not in r or "a" in r), None)
    if stray is not None:  # e.g. a corpus file: its items are JSON objects too
        raise ReportInputError(
            f"{rp}: record {stray} is not a compare result (no status, or edge data as in a corpus "
            "file); give the folder or results.jsonl that compare wrote"
        )
    head = read_header(rp) or {}
    label = occt_label(head.get("versions", {})) if head else rp.parent.name
    return Run(rp, head, recs, summarize(recs), label)


def _check_same_corpus(runs: list[Run], corpus: str | Path | None) -> None:
    """Refuse runs of different corpora side by side, or a ``corpus`` that is not theirs.

    Items are matched by id, and ids repeat across corpora: another corpus's pictures or
    columns would show other edges under the same names.
    """
    sha = runs[0].header.get("sha256")
    for run in runs[1:]:
        if run.header.get("sha256") != sha:
            raise ReportInputError(
                f"{run.path} holds results of corpus {run.header.get('corpus')} (sha256 "
                f"{str(run.header.get('sha256'))[:12]}), {runs[0].path} of {runs[0].header.get('corpus')} "
                f"(sha256 {str(sha)[:12]}): side-by-side columns need runs of the same corpus"
            )
    if corpus is not None and sha is not None and Path(corpus).is_file():
        theirs = check_corpus(corpus).sha256
        if theirs != sha:
            raise ReportInputError(
                f"--corpus {corpus} (sha256 {theirs[:12]}) is not the corpus of {runs[0].path} "
                f"(sha256 {str(sha)[:12]}): its pictures would show other edges"
            )


def _b64(pic: Picture | None) -> str:
    return base64.b64encode(pic.png).decode("ascii") if pic and pic.png else ""


def _ms(r: dict[str, Any], side: str) -> float:
    return 1e6 * float(r.get("times", {}).get(side, 0.0))


def _slow_reason(r: dict[str, Any]) -> str:
    meta, fam = r.get("meta") or {}, r.get("family", "")
    if "degrees" in meta or "degree" in meta:
        return f"high degree {meta.get('degrees', meta.get('degree'))}: clipping cost grows with the degree"
    if fam in ("tangent", "near-miss") or any(x.get("kind") == "tangent" for x in r.get("relief", [])):
        return "tangency: Bézier clipping converges only linearly at a double root"
    if any(x.get("type") == "overlap" for x in r.get("relief", [])):
        return "overlap: both ends are located and the whole range is checked"
    if fam in ("glyph", "sketch", "step"):
        return "CAD edge: the time includes converting the B-spline into Bézier segments"
    return "not known"


def _slowest(recs: list[dict[str, Any]], n: int = 15) -> list[dict[str, Any]]:
    rows = []
    for r in recs:
        tr, to = _ms(r, "relief_cad"), _ms(r, "occt")
        if r.get("status") == "ok" and tr > 0 and to > 0:
            rows.append(
                {
                    "id": r["id"],
                    "family": r.get("family", ""),
                    "relief": tr,
                    "occt": to,
                    "ratio": speed_ratio(tr, to),
                    "reason": _slow_reason(r),
                }
            )
    return sorted(rows, key=lambda x: -x["ratio"])[:n]


def _ratios(recs: list[dict[str, Any]]) -> list[float]:
    return [x["ratio"] for x in _slowest(recs, n=10**9)]


def _conclusion(run: Run) -> dict[str, Any]:
    ok = [r for r in run.recs if r.get("status") == "ok"]
    fs = [f for r in ok for f in findings(r)]
    ratios = _ratios(run.recs)
    strict = sum(agreed_counts(r)[0] for r in ok)
    loose = sum(agreed_counts(r)[1] for r in ok)
    return {
        "pairs": len(run.recs),
        "ok": len(ok),
        "failed": len(run.recs) - len(ok),
        "families": sorted({str(r.get("family")) for r in run.recs}),
        "agreed": strict,
        "loose": loose,
        "pairs_all_agree": sum(1 for r in ok if not r.get("disagreements")),
        "findings": len(fs),
        "rows": sum(f.count for f in fs),
        "won": {s: sum(1 for f in fs if f.side == s) for s in ("occt", "relief_cad", "both")},
        "occt_kinds": tally(ok, "occt"),
        "relief_kinds": tally(ok, "relief_cad"),
        "both_kinds": tally(ok, "both"),
        "ratio_median": statistics.median(ratios) if ratios else math.nan,
        "ratio_worst": max(ratios) if ratios else math.nan,
        "ratio_best": min(ratios) if ratios else math.nan,
    }


def _table_rows(summary: dict[str, Any], key: str) -> list[dict[str, Any]]:
    rows = list(summary.get(key, {}).items())
    if key == "by_family":
        rows.append(("TOTAL", summary.get("total", {})))
    out = []
    for name, v in rows:
        ok = max(v.get("ok", 0), 1)
        tr, to = 1e6 * v.get("relief_cad_s", 0) / ok, 1e6 * v.get("occt_s", 0) / ok
        out.append(
            {
                "name": name,
                "cells": [int(v.get(k, 0)) for k, _ in _COLS],
                "relief": tr,
                "occt": to,
                "ratio": speed_ratio(tr, to),
            }
        )
    return out


def _occt_answer(r: dict[str, Any], tol: float) -> tuple[Any, ...]:
    pts = sorted(
        tuple(round(c / max(tol, 1e-12)) for c in x.get("point", ()))
        for x in r.get("occt", [])
        if "point" in x
    )
    return (len(r.get("occt", [])), tuple(pts))


def _versions_side_by_side(runs: list[Run]) -> list[dict[str, Any]]:
    """Per family: where the runs' OCCT answers differ from each other, and which run the arbiter backs."""
    by_id = [{r["id"]: r for r in run.recs if r.get("status") == "ok"} for run in runs]
    common = set(by_id[0]).intersection(*by_id[1:])
    fams: dict[str, dict[str, Any]] = {}
    for i in sorted(common):
        recs = [m[i] for m in by_id]
        tol = float(recs[0].get("tol") or 1e-7)
        f = fams.setdefault(
            str(recs[0].get("family")),
            {"pairs": 0, "differ": 0, "right": [0] * len(runs), "faults": [0] * len(runs)},
        )
        f["pairs"] += 1
        wrong = [sum(1 for x in findings(r) if x.side in ("occt", "both")) for r in recs]
        f["faults"] = [a + b for a, b in zip(f["faults"], wrong, strict=True)]
        if len({_occt_answer(r, 10 * tol) for r in recs}) > 1:
            f["differ"] += 1
            f["right"] = [a + (w == 0) for a, w in zip(f["right"], wrong, strict=True)]
    return [{"family": k, **v} for k, v in sorted(fams.items())]


def _cards(run: Run, items: dict[str, Item], max_pictures: int) -> list[dict[str, Any]]:
    cards: list[dict[str, Any]] = []
    for r in [x for x in run.recs if x.get("status") == "ok" and x.get("disagreements")]:
        pic = _picture(items.get(r["id"]), r) if len(cards) < max_pictures else None
        cards.append({"rec": r, "findings": findings(r), "pic": pic, "b64": _b64(pic), "run": run.label})
    return cards


def _spot(claim: dict[str, Any], edges_a: list[Any]) -> Any:
    if "point" in claim:
        return claim["point"]
    from .plots import edge_points

    t0, t1 = claim["t"]
    return edge_points(edges_a[claim["index_a"]], t0, t1, n=3)[1]


def _picture(item: Item | None, rec: dict[str, Any]) -> Picture | None:
    if item is None:
        return None
    from relief_cad.cad.occt import unique_edges

    try:
        a, b = item.shapes()
        ea = unique_edges(a)
        eb = [] if b is None else unique_edges(b)
        spots = [_spot(d["claim"], ea) for d in rec.get("disagreements", [])]
        return pair_png(ea, eb, rec, spots, title=f"{item.id} ({item.family})")
    except Exception:  # noqa: BLE001 - a picture is never worth failing the report; the card says so
        return None


def _items(corpus: Any, need: set[str]) -> dict[str, Item]:
    if not corpus or not need or not Path(corpus).is_file():
        return {}
    return {it.id: it for it in read_corpus(corpus) if isinstance(it, Item) and it.id in need}


def _histograms(run: Run) -> tuple[Picture, Picture]:
    err: dict[str, list[float]] = {"relief_cad": [], "OCCT": []}
    for r in run.recs:
        for m in r.get("agreed", []) if r.get("status") == "ok" else []:
            for key, name in (("relief_error", "relief_cad"), ("occt_error", "OCCT")):
                if m.get(key) is not None:
                    err[name].append(math.log10(max(float(m[key]), 1e-20)))
    h1 = hist_png(
        err,
        "log10(distance to the arbiter's true point) [model units], floored at 1e-20",
        "Error of matched points against the 50-digit arbiter",
    )
    logs = {"pairs": [math.log10(x) for x in _ratios(run.recs)]}
    h2 = hist_png(
        logs,
        "log10(relief_cad time / OCCT time) per pair: below 0 = relief_cad faster",
        "Speed ratio relief/OCCT per pair",
        mark_zero="equal speed",
    )
    return h1, h2


def write_report(
    results: str | Path | Sequence[str | Path],
    out: str | Path,
    *,
    corpus: str | Path | None = None,
    max_pictures: int = 200,
) -> Path:
    """Write ``report.html`` for one or several results files (or compare folders) into ``out``.

    Parameters
    ----------
    results : path or list of paths
        ``results.jsonl`` files or the folders holding them; several runs (one per OCCT
        version, same corpus) get side-by-side columns. The first is the main run.
    out : path
        Output folder; the report is ``<out>/report.html``.
    corpus : path, optional
        The corpus the results came from (for the pictures); default: as recorded by compare.
    max_pictures : int
        At most this many disagreement pictures per run (the rest are listed without one).

    Returns
    -------
    Path
        The report file.

    Raises
    ------
    ReportInputError
        A results path is missing, a folder holds no results.jsonl, a file has no records or
        records that compare did not write (a corpus file), runs of different corpora are
        given together, or ``corpus`` is not the runs' corpus.
    """
    import jinja2

    runs = [load_run(p) for p in ([results] if isinstance(results, (str, Path)) else results)]
    _check_same_corpus(runs, corpus)
    corpus = corpus or runs[0].header.get("corpus")
    need = {r["id"] for run in runs for r in run.recs if r.get("disagreements")}
    items = _items(corpus, need)
    h_err, h_time = _histograms(runs[0])
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(Path(__file__).parent / "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
    )
    env.filters["b64"] = _b64
    html = env.get_template("report.html.j2").render(
        runs=runs,
        main=runs[0],
        corpus=corpus,
        cols=[c for _, c in _COLS],
        kinds=KINDS,
        conclusion=_conclusion(runs[0]),
        conclusions=[_conclusion(r) for r in runs],
        families=_table_rows(runs[0].summary, "by_family"),
        routes=_table_rows(runs[0].summary, "by_route"),
        side_by_side=_versions_side_by_side(runs) if len(runs) > 1 else [],
        slowest=_slowest(runs[0].recs),
        h_err=h_err,
        h_time=h_time,
        ratio_note=RATIO_NOTE,
        cards=[c for run in runs for c in _cards(run, items, max_pictures)],
        glossary=GLOSSARY,
        generated=f"{_dt.datetime.now(_dt.timezone.utc):%Y-%m-%d %H:%M UTC}",
    )
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    path = outdir / "report.html"
    path.write_text(html, encoding="utf-8")
    return path

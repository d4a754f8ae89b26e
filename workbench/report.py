"""``report``: a self-contained HTML report of a compare run (viewable offline).

One file, no external assets: summary tables by family and by OCCT route, histograms of
each side's distance to the arbiter's true point on agreed points, a histogram of the
per-pair time ratio OCCT/relief_cad, the failed items with their reasons, and a picture
(inline PNG) of every disagreement with both answers marked (relief_cad: blue circles /
thick blue stretches; OCCT: red crosses / thin red stretches; the disputed result ringed
in orange) next to the arbiter's verdict.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import io
import json
import math
from pathlib import Path
from typing import Any

from .corpus import Item, read_corpus
from .run import _COLS, load_results, summarize

__all__ = ["write_report"]

_CSS = """
body{font-family:DejaVu Sans,Arial,sans-serif;margin:1.5em;color:#222;max-width:1200px}
h1{font-size:1.5em}h2{font-size:1.2em;border-bottom:1px solid #ccc;margin-top:1.6em}
table{border-collapse:collapse;margin:.5em 0;font-size:.85em}
td,th{border:1px solid #bbb;padding:2px 6px;text-align:right}
th{background:#eef}td.l,th.l{text-align:left}
.card{border:1px solid #ccc;border-radius:4px;padding:.6em;margin:.8em 0;
  display:flex;gap:1em;align-items:flex-start}
.card img{flex:none}.card .txt{font-size:.85em}
.win-relief_cad{color:#1565c0;font-weight:bold}.win-occt{color:#c62828;font-weight:bold}
.win-neither{color:#6d4c41;font-weight:bold}.small{font-size:.8em;color:#555}
"""


def _png_b64(png: bytes) -> str:
    return base64.b64encode(png).decode("ascii")


def _img(png: bytes, alt: str) -> str:
    if not png:
        return f"<p class='small'>(no picture: {html.escape(alt)})</p>"
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{_png_b64(png)}"/>'


def _hist_png(series: dict[str, list[float]], xlabel: str, title: str) -> bytes:
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:  # pragma: no cover
        return b""
    fig, ax = plt.subplots(figsize=(5.5, 3.0), dpi=72)
    data = {k: [x for x in v if math.isfinite(x)] for k, v in series.items()}
    allv = [x for v in data.values() for x in v]
    if allv:
        lo, hi = min(allv), max(allv)
        if hi - lo < 1:
            lo, hi = lo - 0.5, hi + 0.5
        bins = [lo + (hi - lo) * i / 30 for i in range(31)]
        for (name, v), color in zip(data.items(), ("tab:blue", "tab:red", "tab:green"), strict=False):
            if v:
                ax.hist(v, bins=bins, alpha=0.55, label=f"{name} (n={len(v)})", color=color)
        ax.legend(fontsize=7)
    else:
        ax.text(0.5, 0.5, "no data", ha="center", va="center", transform=ax.transAxes)
    ax.set_xlabel(xlabel, fontsize=8)
    ax.set_title(title, fontsize=9)
    ax.tick_params(labelsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    plt.close(fig)
    return buf.getvalue()


def _table(summary: dict[str, Any], key: str, title: str) -> str:
    rows = list(summary.get(key, {}).items())
    if key == "by_family":
        rows.append(("TOTAL", summary.get("total", {})))
    head = f"<th class='l'>{title}</th>" + "".join(f"<th>{html.escape(c)}</th>" for _, c in _COLS)
    head += "<th>µs/pair relief_cad</th><th>µs/pair OCCT</th><th>OCCT/relief time</th>"
    body = []
    for name, v in rows:
        ok = max(v.get("ok", 0), 1)
        tr, to = 1e6 * v.get("relief_cad_s", 0) / ok, 1e6 * v.get("occt_s", 0) / ok
        ratio = f"{to / tr:.2f}" if tr > 0 else "-"
        cells = "".join(f"<td>{int(v.get(k, 0))}</td>" for k, _ in _COLS)
        body.append(
            f"<tr><td class='l'>{html.escape(str(name))}</td>{cells}<td>{tr:.0f}</td><td>{to:.0f}</td>"
            f"<td>{ratio}</td></tr>"
        )
    return f"<table><thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _result_obj(d: dict[str, Any]) -> Any:
    from relief_cad.cad.results import EdgeIntersection, EdgeOverlap

    if d.get("type") == "overlap":
        return EdgeOverlap(
            d["index_a"],
            d["index_b"],
            None,
            None,
            tuple(d["t"]),
            tuple(d["u"]),
            None,
            route=d.get("route", ""),
        )
    return EdgeIntersection(
        d["index_a"],
        d["index_b"],
        None,
        None,
        d["t"],
        d["u"],
        tuple(d["point"]),
        d.get("kind", "crossing"),
        d.get("distance", 0.0),
        route=d.get("route", ""),
    )


def _where(d: dict[str, Any]) -> str:
    if d.get("type") == "overlap":
        return f"edges {d['index_a']}/{d['index_b']} t∈[{d['t'][0]:.6g}, {d['t'][1]:.6g}]"
    return f"edges {d['index_a']}/{d['index_b']} t={d['t']:.10g} u={d['u']:.10g}"


def _picture(item: Item | None, rec: dict[str, Any]) -> bytes:
    if item is None:
        return b""
    from relief_cad.cad.compare import plot_pair_png
    from relief_cad.cad.occt import unique_edges

    try:
        a, b = item.shapes()
        ea = unique_edges(a)
        eb = ea if b is None else unique_edges(b)
        relief = [_result_obj(x) for x in rec.get("relief", [])]
        occt = [_result_obj(x) for x in rec.get("occt", [])]
        hl = [_result_obj(x["claim"]) for x in rec.get("disagreements", [])]
        return plot_pair_png(
            ea, eb if b is not None else [], relief, occt, hl, size=(4.0, 3.2), title=item.id
        )
    except Exception:  # noqa: BLE001 - a picture is never worth failing the report
        return b""


def write_report(
    results: str | Path,
    out: str | Path,
    *,
    corpus: str | Path | None = None,
    max_pictures: int = 200,
) -> Path:
    """Write ``report.html`` for a results file (or a compare output folder) into ``out``.

    Parameters
    ----------
    results : path
        ``results.jsonl`` or the folder holding it (and ``summary.json``).
    out : path
        Output folder; the report is ``<out>/report.html``.
    corpus : path, optional
        The corpus the results came from (for the pictures); default: the one named in
        ``summary.json``.
    max_pictures : int
        At most this many disagreement pictures (the rest are listed without one).

    Returns
    -------
    Path
        The report file.
    """
    rp = Path(results)
    if rp.is_dir():
        rp = rp / "results.jsonl"
    recs = load_results(rp)
    summary = summarize(recs)
    if corpus is None:
        sj = rp.parent / "summary.json"
        if sj.exists():
            corpus = json.loads(sj.read_text()).get("corpus")
    dis_recs = [r for r in recs if r.get("status") == "ok" and r.get("disagreements")]
    need = {r["id"] for r in dis_recs[:max_pictures]}
    items: dict[str, Item] = {}
    if corpus and need and Path(corpus).exists():
        for it in read_corpus(corpus):
            if isinstance(it, Item) and it.id in need:
                items[it.id] = it

    # histograms
    err_rel: list[float] = []
    err_occ: list[float] = []
    ratios: list[float] = []
    for r in recs:
        if r.get("status") != "ok":
            continue
        for m in r.get("agreed", []):
            for key, dest in (("relief_error", err_rel), ("occt_error", err_occ)):
                e = m.get(key)
                if e is not None:
                    dest.append(math.log10(max(float(e), 1e-20)))
        t = r.get("times", {})
        if t.get("relief_cad", 0) > 0 and t.get("occt", 0) > 0 and "relief_cad" not in r.get("errors", {}):
            ratios.append(math.log10(t["occt"] / t["relief_cad"]))
    hist_err = _hist_png(
        {"relief_cad": err_rel, "OCCT": err_occ},
        "log10(distance to the true point) [model units]",
        "Error of agreed points vs the 50-digit arbiter (floored at 1e-20)",
    )
    hist_time = _hist_png(
        {"pairs": ratios},
        "log10(OCCT time / relief_cad time) per pair",
        "Timing ratio (> 0: relief_cad faster)",
    )

    tot = summary["total"]
    parts = [
        "<!DOCTYPE html><html><head><meta charset='utf-8'><title>relief_cad vs OCCT report</title>",
        f"<style>{_CSS}</style></head><body>",
        "<h1>relief_cad vs OCCT: comparison report</h1>",
        f"<p class='small'>generated {_dt.datetime.now(_dt.timezone.utc):%Y-%m-%d %H:%M UTC} from "
        f"{html.escape(str(rp))}; corpus {html.escape(str(corpus))}</p>",
        f"<p id='headline'><b>{int(tot.get('pairs', 0))}</b> items, "
        f"<b>{int(tot.get('errors', 0))}</b> failed; "
        f"<b>{int(tot.get('agreed', 0))}</b> results agreed; disagreements decided for relief_cad: "
        f"<b>{int(tot.get('relief_cad_right', 0))}</b>, for OCCT: <b>{int(tot.get('occt_right', 0))}</b>, "
        f"neither: <b>{int(tot.get('neither', 0))}</b>.</p>",
        "<h2>Summary by family</h2>",
        _table(summary, "by_family", "family"),
        "<h2>Summary by OCCT route</h2>",
        _table(summary, "by_route", "OCCT route"),
        "<p class='small'>relief✓ / occt✓: disagreements the arbiter decided for that side; "
        "~: agreed points reported farther than tol from the arbiter's true point; pairs≠: items with "
        "at least one disagreement.</p>",
        "<h2>Errors against the truth</h2>",
        _img(hist_err, "error histogram"),
        "<h2>Timing</h2>",
        _img(hist_time, "timing ratio histogram"),
        "<p class='small'>Wall time of one call per item in a worker process, after a warm-up that loads "
        "relief_cad's compiled kernels; relief_cad's time includes converting the edges to Bézier segments, "
        "OCCT's includes choosing the route (plane test, mapping to 2D). For steady-state speed use "
        "<code>python -m workbench bench</code>.</p>",
    ]
    if summary["errors"]:
        parts.append(
            f"<h2>Failed items ({len(summary['errors'])})</h2><table><thead><tr><th class='l'>id</th>"
            "<th class='l'>stage</th><th class='l'>reason</th></tr></thead><tbody>"
        )
        for e in summary["errors"]:
            parts.append(
                f"<tr><td class='l'>{html.escape(str(e['id']))}</td><td class='l'>"
                f"{html.escape(str(e['stage']))}</td><td class='l'>{html.escape(str(e['reason']))}</td></tr>"
            )
        parts.append("</tbody></table>")
    side_fail = [r for r in recs if r.get("status") == "ok" and r.get("errors")]
    if side_fail:
        parts.append(
            f"<h2>Items where one side raised ({len(side_fail)})</h2><table><thead><tr>"
            "<th class='l'>id</th><th class='l'>side</th><th class='l'>error</th></tr></thead><tbody>"
        )
        for r in side_fail:
            for side, msg in r["errors"].items():
                parts.append(
                    f"<tr><td class='l'>{html.escape(r['id'])}</td><td class='l'>{side}</td>"
                    f"<td class='l'>{html.escape(msg)}</td></tr>"
                )
        parts.append("</tbody></table>")
    parts.append(f"<h2 id='disagreements'>Disagreements ({len(dis_recs)} items)</h2>")
    if not dis_recs:
        parts.append("<p>None: relief_cad and OCCT agree on every item.</p>")
    for k, r in enumerate(dis_recs):
        pic = _picture(items.get(r["id"]), r) if k < max_pictures else b""
        rows = []
        for d in r["disagreements"]:
            rows.append(
                f"<tr><td class='l'>{html.escape(d.get('status', 'only ' + d['claimant']))}</td>"
                f"<td class='l'>{html.escape(_where(d['claim']))}"
                f"</td><td class='l'>{html.escape(d['claim'].get('kind', ''))}</td>"
                f"<td class='l win-{html.escape(d['winner'])}'>{html.escape(d['winner'])}</td>"
                f"<td class='l'>{html.escape(d['reason'])}</td></tr>"
            )
        parts.append(
            f"<div class='card'>{_img(pic, 'pair ' + r['id'])}<div class='txt'><b>{html.escape(r['id'])}</b> "
            f"({html.escape(r.get('family', ''))}; OCCT route {html.escape(', '.join(r.get('routes', [])))}; "
            f"tol {r.get('tol', 0):.3g})<table><thead><tr><th class='l'>claim</th><th class='l'>where</th>"
            f"<th class='l'>kind</th><th class='l'>right</th><th class='l'>why</th></tr></thead>"
            f"<tbody>{''.join(rows)}</tbody></table></div></div>"
        )
    # rendering check for headless browsers: count the images that decoded
    parts.append(
        "<script>window.addEventListener('load',function(){var n=0;for(var i of document.images)"
        "{if(i.complete&&i.naturalWidth>0)n++;}document.body.setAttribute('data-images-ok',n);"
        "document.body.setAttribute('data-images',document.images.length);});</script>"
    )
    parts.append("</body></html>")
    outdir = Path(out)
    outdir.mkdir(parents=True, exist_ok=True)
    path = outdir / "report.html"
    path.write_text("\n".join(parts), encoding="utf-8")
    return path

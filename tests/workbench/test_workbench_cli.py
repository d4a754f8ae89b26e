"""The workbench command line end to end: corpus -> compare (parallel, resumed, Dask) -> report -> Chromium."""

from __future__ import annotations

import gzip
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from relief_cad_workbench.corpus import Item, bundled_corpus_path, read_corpus
from relief_cad_workbench.run import load_results, run_compare

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


def cli(*args, check=True):
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([os.environ.get("PYTHONPATH", ""), str(ROOT)])}
    proc = subprocess.run([sys.executable, "-m", "relief_cad_workbench", *map(str, args)], capture_output=True,
                          text=True, env=env, timeout=600)
    assert "Traceback" not in proc.stderr, proc.stderr
    if check and proc.returncode != 0:
        raise AssertionError(f"exit {proc.returncode}\nstdout:\n{proc.stdout}\nstderr:\n{proc.stderr}")
    return proc


@pytest.fixture(scope="module")
def corpus(tmp_path_factory):
    """A small corpus built by the CLI, with a broken STEP file named, plus bad lines appended."""
    d = tmp_path_factory.mktemp("wb")
    broken = d / "broken.step"
    broken.write_text("ISO-10303-21;\nHEADER;\nthis is not STEP")
    path = d / "small.jsonl"
    proc = cli("corpus", path, "--families", "cubic,tangent,overlap,step", "--count", "2", "--seed", "3",
               "--step", ROOT / "workbench" / "data" / "step", "--step", broken, check=False)
    assert proc.returncode == 1  # a skipped input: not everything asked for was done
    assert "OCCT cannot read this STEP file" in proc.stderr and "wrote 8 items" in proc.stdout
    items = [i for i in read_corpus(path) if isinstance(i, Item)]
    assert [i.family for i in items].count("step") == 2
    # bad input: a corrupt line, and an item whose shape has no edges
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeVertex
    from OCP.gp import gp_Pnt
    from relief_cad_workbench.corpus import brep_text

    vertex = brep_text(BRepBuilderAPI_MakeVertex(gp_Pnt(0, 0, 0)).Vertex())
    with open(path, "a") as f:
        f.write('{"id": "broken", "a": \n')
        f.write(json.dumps({"id": "no-edges", "family": "bad", "a": vertex, "b": vertex}) + "\n")
    return path


def test_compare_resume_and_report_end_to_end(corpus, tmp_path):
    out = tmp_path / "run"
    # a run stopped early: after 3 results (exit status 3: incomplete), with 2 workers it still exits
    proc = cli("compare", corpus, "--out", out, "--workers", "2", "--stop-after", "3", check=False)
    assert proc.returncode == 3 and "STOPPED before the end" in proc.stdout
    first = load_results(out / "results.jsonl")
    assert len(first) >= 3
    # a crash in the middle of a line: the half line is dropped on resume
    with open(out / "results.jsonl", "a") as f:
        f.write('{"id": "half-writ')
    proc = cli("compare", corpus, "--out", out, "--workers", "2", check=False)
    assert f"resuming: {len(first)} of 10 items already done" in proc.stderr
    assert "compare:" in proc.stderr and "pair/s" in proc.stderr  # tqdm's bar
    assert proc.returncode == 1 and "complete, 2 failure(s) listed above" in proc.stdout and "TOTAL" in proc.stdout
    assert "no-edges:" in proc.stdout and "corrupt corpus line" in proc.stdout  # the failures, listed
    recs = load_results(out / "results.jsonl")
    ids = [r["id"] for r in recs]
    assert len(ids) == len(set(ids)) == 10  # 8 items + corrupt line + no-edge item, each once
    assert {r["id"] for r in first} <= set(ids)  # nothing computed was lost
    bad = {r["id"]: r for r in recs if r["status"] == "error"}
    assert "corrupt corpus line" in bad["small.jsonl:line-9"]["reason"]
    assert "no edges" in bad["no-edges"]["reason"]
    ok = [r for r in recs if r["status"] == "ok"]
    assert len(ok) == 8 and all("score" in r and r["routes"] is not None for r in ok)
    overlaps = [r for r in ok if r["family"] == "overlap"]
    assert any(m["occt"]["type"] == "overlap" for r in overlaps for m in r["agreed"]) or any(
        d["claim"]["type"] == "overlap" for r in overlaps for d in r["disagreements"]
    )
    proc = cli("report", out)
    report = out / "report.html"
    assert report.exists() and "report written to" in proc.stdout
    text = report.read_text()
    assert "Summary by family" in text and "Summary by OCCT route" in text
    assert text.index('id="conclusion"') < text.index("Summary by family")  # the conclusion comes first
    assert 'id="glossary"' in text and "below 1 = relief_cad faster" in text and "Slowest pairs" in text
    assert text.count("data:image/png;base64,") >= 2
    assert "no-edges" in text and "corrupt corpus line" in text
    assert "http://" not in text and "https://" not in text  # self-contained, offline
    if CHROMIUM is None:
        pytest.skip("chromium is not installed (apt-get install chromium)")
    dom = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         f"--user-data-dir={tmp_path / 'chromium'}", "--dump-dom", report.as_uri()],
        capture_output=True, text=True, timeout=120,
    ).stdout
    import re

    body = re.search(r"<body([^>]*)>", dom)
    assert body is not None, dom[:500]
    n_img = int(re.search(r'data-images="(\d+)"', body.group(1)).group(1))
    n_ok = int(re.search(r'data-images-ok="(\d+)"', body.group(1)).group(1))
    assert n_img >= 2 and n_ok == n_img  # every inline picture decoded and rendered
    assert dom.count("<table") >= 3 and "cubic" in dom
    imgs = re.findall(r"<img [^>]*>", dom)
    assert imgs and all('data-legend="1"' in i for i in imgs)  # every plot has its legend
    for i in (i for i in imgs if "pair" in i.split('class="')[1].split('"')[0]):
        insets, spots = (int(re.search(rf'data-{k}="(\d+)"', i).group(1)) for k in ("insets", "spots"))
        assert insets >= 1 and insets == min(spots, 4)  # a zoom inset on each disputed spot (up to 4)
    shot = tmp_path / "shot.png"
    subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         f"--user-data-dir={tmp_path / 'chromium'}", "--window-size=1000,1400", f"--screenshot={shot}",
         report.as_uri()],
        capture_output=True, timeout=120,
    )
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and shot.stat().st_size > 20_000


def test_compare_on_a_local_dask_cluster(corpus, tmp_path):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        assert client.status == "running"
        # the address, as `compare --scheduler tcp://...` passes it
        summary = run_compare(corpus, tmp_path / "dask", scheduler=cluster.scheduler_address, progress=False,
                              limit=6)
    assert summary["complete"]
    recs = load_results(tmp_path / "dask" / "results.jsonl")
    assert len(recs) == 6 and {r["status"] for r in recs} == {"ok"}
    assert summary["total"]["pairs"] == 6


def test_bundled_corpus_is_small_and_readable():
    path = bundled_corpus_path()
    assert path.exists() and path.stat().st_size < 400_000
    with gzip.open(path, "rt") as f:
        lines = f.readlines()
    fams = {json.loads(line)["family"] for line in lines}
    assert {"cubic", "ill-conditioned", "tangent", "overlap", "glyph", "sketch", "step"} <= fams


def test_bench_reports_a_missing_module(tmp_path, monkeypatch):
    from relief_cad_workbench import bench

    monkeypatch.setitem(bench.BENCHMARKS, "nothing", "relief_cad_workbench.bench_does_not_exist")
    res = bench.run_bench(["nothing"], tmp_path / "b.json")
    assert res["nothing"]["status"] == "missing" and "bench_does_not_exist" in res["nothing"]["reason"]
    assert json.loads((tmp_path / "b.json").read_text())["nothing"]["status"] == "missing"


def test_bench_interrupted_keeps_the_finished_benchmarks(tmp_path, monkeypatch):
    """Ctrl-C in the second benchmark: the first one's result is on disk, the second is marked."""
    import sys
    import types

    from relief_cad_workbench import bench

    stopped = types.ModuleType("relief_cad_workbench._bench_stopped_by_ctrl_c")

    def run() -> None:
        raise KeyboardInterrupt

    stopped.run = run  # type: ignore[attr-defined]
    monkeypatch.setitem(sys.modules, stopped.__name__, stopped)
    monkeypatch.setitem(bench.BENCHMARKS, "nothing", "relief_cad_workbench.bench_does_not_exist")
    monkeypatch.setitem(bench.BENCHMARKS, "stopped", stopped.__name__)
    with pytest.raises(KeyboardInterrupt):
        bench.run_bench(["nothing", "stopped"], tmp_path / "b.json")
    saved = json.loads((tmp_path / "b.json").read_text())
    assert saved["nothing"]["status"] == "missing" and saved["stopped"]["status"] == "interrupted"
    assert not list(tmp_path.glob(".*.tmp"))


def test_bench_cad_runs_with_or_without_cadquery():
    from relief_cad_workbench import bench_cad

    from tests._env import cq

    res = bench_cad.run(repeat=5, occt_repeat=5)
    rows = {r["pair"]: r for r in res["rows"]}
    # a line crossing a line once, an arc crossed twice by a line: every route that finds points agrees
    assert rows["line_line"]["relief_pts"] == rows["line_line"]["b3d_find_pts"] == 1
    assert rows["arc_line"]["relief_pts"] == 2 and rows["arc_line"]["relief_us"] > 0
    if cq is None:  # build123d 0.13 on OCP 8.0: CadQuery's column is empty, and says why
        assert rows["line_line"]["cq_split_us"] is None and "not installed" in res["cadquery"]
    else:
        assert rows["line_line"]["cq_split_pts"] == 1 and res["cadquery"] == "measured"
    assert all(r["relief_us"] > 0 for r in res["rows"])

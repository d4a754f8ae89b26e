"""The workbench command line's outputs: never destroyed or half-written, unwritable places refused
up front, bad numbers and names refused by one line (exit status 2), damaged results set aside."""

from __future__ import annotations

import json
import multiprocessing
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from relief_cad_workbench.__main__ import EXIT_BAD_INPUT, EXIT_INTERRUPTED, main
from relief_cad_workbench.corpus import random_family, write_corpus
from relief_cad_workbench.run import (
    ResultsBusyError,
    damaged_path,
    load_results,
    repair_results,
    results_lock,
    run_compare,
)

from .test_cli_inputs import ROOT, cli, error_line


@pytest.fixture(scope="module")
def small(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("outputs") / "small.jsonl"
    write_corpus(path, random_family("cubic", 4, seed=5))
    return path


def _leftovers(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.endswith(".tmp"))


# ---------------------------------------------------------------------- 1. corpus OUT, atomically


def test_a_failed_corpus_keeps_the_old_file_and_leaves_no_temporary(tmp_path):
    out = tmp_path / "good.jsonl"
    write_corpus(out, random_family("cubic", 3, seed=1))
    before = out.read_bytes()
    proc = cli("corpus", out, "--families", "cubic,bogus", "--count", "3")
    assert proc.returncode == EXIT_BAD_INPUT
    assert "expected a family in cubic, rational" in error_line(proc) and "received 'bogus'" in proc.stderr
    proc = cli("corpus", out, "--families", "cubic,near-miss,cubic", "--count", "3")  # ids twice
    assert proc.returncode == EXIT_BAD_INPUT
    assert "expected each family once, received 'cubic' twice" in error_line(proc)
    proc = cli("corpus", out, "--families", "step", "--count", "2", "--step", tmp_path / "nothere.step")
    assert proc.returncode == EXIT_BAD_INPUT and "no items: every input was skipped" in error_line(proc)
    assert out.read_bytes() == before and _leftovers(tmp_path) == []


def test_write_corpus_is_all_or_nothing(tmp_path):
    out = tmp_path / "c.jsonl.gz"
    assert write_corpus(out, random_family("cubic", 2, seed=1)) == 2
    before = out.read_bytes()

    def broken():
        yield from random_family("cubic", 2, seed=2)
        raise RuntimeError("the source failed half-way")

    with pytest.raises(RuntimeError):
        write_corpus(out, broken())
    assert out.read_bytes() == before and _leftovers(tmp_path) == []
    assert write_corpus(out, random_family("rational", 3, seed=1)) == 3 and out.read_bytes() != before


def test_a_ctrl_c_while_corpus_writes_keeps_the_old_file(tmp_path):
    out = tmp_path / "big.jsonl.gz"
    write_corpus(out, random_family("cubic", 3, seed=1))
    before = out.read_bytes()
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([os.environ.get("PYTHONPATH", ""), str(ROOT)])}
    proc = subprocess.Popen(
        [sys.executable, "-m", "relief_cad_workbench", "corpus", out, "--families", "conic", "--count", "100000"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, start_new_session=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL),
    )
    t0 = time.monotonic()
    while not _leftovers(tmp_path):  # the temporary file: the items are being written
        assert proc.poll() is None and time.monotonic() - t0 < 120, proc.communicate()
        time.sleep(0.05)
    time.sleep(0.5)
    # Ctrl-C again every half second until it stops: once in a CI run of the whole suite one
    # Ctrl-C came back with exit status 0 and no message (not reproduced alone). A Ctrl-C that
    # comes while a finalizer runs was lost that way; the CLI now keeps it (test_interrupt.py)
    for _ in range(60):
        os.killpg(proc.pid, signal.SIGINT)
        try:
            stdout, stderr = proc.communicate(timeout=0.5)
            break
        except subprocess.TimeoutExpired:
            continue
    else:
        proc.kill()
        pytest.fail("corpus did not stop on Ctrl-C within 30 s")
    assert proc.returncode == EXIT_INTERRUPTED and "Traceback" not in stderr, (proc.returncode, stderr)
    assert out.read_bytes() == before and _leftovers(tmp_path) == []


# ---------------------------------------------------------------------- 2. numeric options


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["corpus", "x.jsonl", "--count", "0"], "argument --count: expected an integer >= 1, received 0"),
        (["corpus", "x.jsonl", "--seed", "-1"], "argument --seed: expected an integer >= 0, received -1"),
        (["corpus", "x.jsonl", "--count", "many"], "argument --count: expected an integer >= 1, received 'many'"),
        (["compare", "--count", "-5"], "argument --count: expected an integer >= 1, received -5"),
        (["compare", "--workers", "0"], "argument --workers: expected an integer >= 1, received 0"),
        (["compare", "--workers", "-5"], "argument --workers: expected an integer >= 1, received -5"),
        (["compare", "--limit", "-2"], "argument --limit: expected an integer >= 1, received -2"),
        (["compare", "--stop-after", "0"], "argument --stop-after: expected an integer >= 1, received 0"),
        (["quickstart", "--workers", "0"], "argument --workers: expected an integer >= 1, received 0"),
        (["report", "r", "--max-pictures", "-1"], "argument --max-pictures: expected an integer >= 0, received -1"),
    ],
)
def test_numeric_options_out_of_range_are_refused_before_any_work(args, message, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit) as stop:
        main(args)
    assert stop.value.code == EXIT_BAD_INPUT
    err = capsys.readouterr().err
    assert err.rstrip().endswith(f"error: {message}") and "Traceback" not in err, err
    assert list(tmp_path.iterdir()) == []  # nothing written


def test_a_negative_seed_in_a_real_run_is_one_line_not_a_traceback(tmp_path):
    proc = cli("corpus", tmp_path / "c.jsonl", "--families", "cubic", "--count", "3", "--seed", "-1")
    assert proc.returncode == EXIT_BAD_INPUT and "expected an integer >= 0, received -1" in proc.stderr
    assert not (tmp_path / "c.jsonl").exists()


def test_a_local_pool_never_has_more_workers_than_batches():
    from relief_cad_workbench.run import InlineExecutor, _executor, _stop

    ex, _, close = _executor(100, None, 2)
    try:
        assert ex._max_workers == 2  # type: ignore[attr-defined]
    finally:
        _stop(ex)
        close()
    assert isinstance(_executor(8, None, 1)[0], InlineExecutor)


# ---------------------------------------------------------------------- 3. bench names


def test_bench_refuses_an_unknown_name_before_any_work_and_keeps_its_json(tmp_path):
    old = tmp_path / "bench.json"
    old.write_text('{"planar": {"status": "ok", "result": "an hour of earlier results"}}')
    before = old.read_bytes()
    proc = cli("bench", "degrees", "nosuch", "--json", old)
    assert proc.returncode == EXIT_BAD_INPUT
    line = error_line(proc)
    assert "received 'nosuch'" in line and "planar, cad, space, arrange, families, degrees, all" in line
    assert "== bench" not in proc.stdout and old.read_bytes() == before


# ---------------------------------------------------------------------- 4. unwritable outputs


def _unwritable_cases(d: Path, small: Path) -> dict[str, tuple[list[object], str]]:
    """name -> (arguments, the path the error line names)."""
    (d / "afile").write_text("a file, not a folder\n")
    afile = d / "afile"
    return {
        "corpus into a file's subfolder": (["corpus", afile / "x.jsonl", "--count", "1"], str(afile)),
        "corpus into /proc": (["corpus", "/proc/relief_cad_x.jsonl", "--count", "1"], "/proc"),
        "corpus onto a folder": (["corpus", d, "--count", "1"], f"{d}, an existing folder"),
        "compare --out a file": (["compare", small, "--out", afile, "--workers", "1", "--quiet"], str(afile)),
        "compare STEP --out a file": (["compare", ROOT / "workbench/data/step/bracket.step", "--out", afile],
                                      str(afile)),
        "quickstart --out /proc": (["quickstart", "--out", "/proc/relief_cad_qs", "--quiet"], "/proc/relief_cad_qs"),
        "quickstart --out a file": (["quickstart", "--out", afile, "--quiet"], str(afile)),
        "report --out a file": (["report", small.parent, "--out", afile], str(afile)),
        "bench --json in /proc": (["bench", "planar", "--json", "/proc/relief_cad_b.json"], "/proc"),
    }


UNWRITABLE = [
    "corpus into a file's subfolder",
    "corpus into /proc",
    "corpus onto a folder",
    "compare --out a file",
    "compare STEP --out a file",
    "quickstart --out /proc",
    "quickstart --out a file",
    "report --out a file",
    "bench --json in /proc",
]


@pytest.mark.parametrize("case", UNWRITABLE)
def test_an_unwritable_output_is_one_error_line_before_any_work(case, small, tmp_path):
    args, named = _unwritable_cases(tmp_path, small)[case]
    proc = cli(*args)
    assert proc.returncode == EXIT_BAD_INPUT, proc.stdout + proc.stderr
    line = error_line(proc)
    assert "expected a" in line and named in line, line
    assert proc.stdout == ""  # refused up front: nothing was run
    assert sorted(p.name for p in tmp_path.iterdir()) == ["afile"]  # and nothing left behind


# ---------------------------------------------------------------------- 5. damaged results lines


def test_a_damaged_line_in_the_middle_of_the_results_loses_no_good_record(small, tmp_path):
    out = tmp_path / "run"
    assert cli("compare", small, "--out", out, "--workers", "1", "--quiet").returncode == 0
    path = out / "results.jsonl"
    lines = path.read_bytes().splitlines(keepends=True)
    assert len(lines) == 5  # the header and 4 records
    path.write_bytes(b"".join([*lines[:2], b'{"id": "garbage\n', *lines[2:]]))
    proc = cli("compare", small, "--out", out, "--workers", "1", "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert f"set aside 1 damaged line(s) of {path} in {damaged_path(path)}" in proc.stderr
    assert "resuming: 4 of 4 items already done" in proc.stderr  # none of the good ones recomputed
    assert path.read_bytes() == b"".join(lines)
    assert damaged_path(path).read_bytes() == b'{"id": "garbage\n'


def test_repair_results_keeps_every_good_record_and_sets_the_rest_aside(tmp_path):
    path = tmp_path / "results.jsonl"
    good = [json.dumps({"id": f"r{k}"}).encode() + b"\n" for k in range(4)]
    path.write_bytes(good[0] + b"\xff\xfe junk\n" + good[1] + b"[1, 2]\n" + good[2] + good[3] + b'{"id": "half')
    assert repair_results(path) == 3
    assert path.read_bytes() == b"".join(good)
    assert damaged_path(path).read_bytes() == b'\xff\xfe junk\n[1, 2]\n{"id": "half\n'
    assert [r["id"] for r in load_results(path)] == ["r0", "r1", "r2", "r3"]
    assert repair_results(path) == 0 and len(damaged_path(path).read_bytes().splitlines()) == 3


# ---------------------------------------------------------------------- 6. quickstart and other corpora


def test_quickstart_refuses_a_folder_holding_another_corpus_results(small, tmp_path):
    out = tmp_path / "run"
    assert cli("compare", small, "--out", out, "--workers", "1", "--quiet").returncode == 0
    before = (out / "results.jsonl").read_bytes()
    proc = cli("quickstart", "--out", out, "--quiet", "--workers", "1")
    assert proc.returncode == EXIT_BAD_INPUT
    line = error_line(proc)
    assert "holds results of another corpus" in line and "small.jsonl" in line and "--fresh" in line
    assert (out / "results.jsonl").read_bytes() == before and not (out / "report.html").exists()


@pytest.mark.parametrize("address", ["foo", "tcp://"])
def test_a_scheduler_address_that_cannot_be_used_is_one_error_line(address, small, tmp_path):
    """--scheduler foo was a raw ValueError traceback from Dask (found by a CLI hunt)."""
    proc = cli("compare", small, "--out", tmp_path / "out", "--scheduler", address, "--quiet")
    assert proc.returncode == EXIT_BAD_INPUT, proc.stdout + proc.stderr
    line = error_line(proc)
    assert "--scheduler: expected the address of a running Dask scheduler" in line and repr(address) in line
    assert "Traceback" not in proc.stderr


# ---------------------------------------------------------------------- 7. one run per folder


@pytest.mark.parametrize("command", [("compare", "SMALL"), ("compare", "SMALL", "--fresh"), ("quickstart", "--fresh")])
def test_a_folder_another_run_is_writing_to_is_refused_and_left_alone(command, small, tmp_path):
    """Two runs on one --out interleaved their lines, and a --fresh one deleted the other's results."""
    out = tmp_path / "run"
    assert cli("compare", small, "--out", out, "--workers", "1", "--quiet").returncode == 0
    before = sorted((p.name, p.read_bytes()) for p in out.iterdir())
    args = [small if a == "SMALL" else a for a in command]
    with results_lock(out):  # another run holds the folder
        proc = cli(*args, "--out", out, "--workers", "1", "--quiet")
    assert proc.returncode == EXIT_BAD_INPUT, proc.stdout + proc.stderr
    line = error_line(proc)
    assert f"another run is writing to {out}" in line and "another --out" in line, line
    assert sorted((p.name, p.read_bytes()) for p in out.iterdir()) == before
    again = cli("compare", small, "--out", out, "--workers", "1", "--quiet")  # free again once it ends
    assert again.returncode == 0 and "resuming: 4 of 4 items already done" in again.stderr


def test_run_compare_in_a_held_folder_raises_a_blocking_io_error(small, tmp_path):
    out = tmp_path / "run"
    out.mkdir()
    with results_lock(out), pytest.raises(ResultsBusyError) as err:
        with results_lock(out.parent / "run"):  # this process may enter again (quickstart does)
            pass
        with multiprocessing.get_context("spawn").Pool(1) as pool:  # another process: refused
            pool.apply(run_compare, (small, out), {"workers": 1, "progress": False})
    assert isinstance(err.value, BlockingIOError) and "another run is writing to" in str(err.value)
    assert list(out.iterdir()) == []

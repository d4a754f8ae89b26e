"""The workbench command line on bad input: one clear line, the right exit status, never a traceback."""

from __future__ import annotations

import gzip
import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest
from relief_cad_workbench.__main__ import EXIT_BAD_INPUT, EXIT_FAILED, build_parser
from relief_cad_workbench.corpus import Item, bundled_step_dir, random_family, read_corpus, write_corpus
from relief_cad_workbench.run import read_header

ROOT = Path(__file__).resolve().parents[2]


def cli(*args, cwd=None):
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([os.environ.get("PYTHONPATH", ""), str(ROOT)])}
    # buffered, as a user runs it: with PYTHONUNBUFFERED (set on some machines) C stdio is
    # unbuffered too, and OCCT's messages were caught where buffered they came out after
    env.pop("PYTHONUNBUFFERED", None)
    proc = subprocess.run(
        [sys.executable, "-m", "relief_cad_workbench", *map(str, args)],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
        cwd=cwd,
    )
    assert "Traceback" not in proc.stderr + proc.stdout, proc.stderr
    assert (
        "\x1b[" not in proc.stderr + proc.stdout and "**** ERR" not in proc.stderr + proc.stdout
    )  # OCCT noise
    return proc


def error_line(proc):
    lines = [ln for ln in proc.stderr.splitlines() if ln.startswith("error: ")]
    assert len(lines) == 1, proc.stderr
    return lines[0]


@pytest.fixture(scope="module")
def small(tmp_path_factory):
    d = tmp_path_factory.mktemp("inputs")
    path = d / "small.jsonl.gz"
    write_corpus(path, random_family("cubic", 3, seed=5))
    return path


def _bad_inputs(d: Path, small: Path) -> dict[str, tuple[Path, str]]:
    """name -> (file, expected message pattern)."""
    (d / "garbage.bin").write_bytes(bytes(range(256)) * 40)
    (d / "latin1.jsonl").write_bytes('{"id": "caf\xe9"}\n'.encode("latin-1"))
    (d / "notes.txt").write_text("hello\nthis is not a corpus\n")
    (d / "empty.jsonl").write_text("\n\n")
    (d / "fake.jsonl.gz").write_text('{"id": 1}\n')
    (d / "cut.jsonl.gz").write_bytes(small.read_bytes()[: len(small.read_bytes()) // 2])
    (d / "broken.step").write_text("ISO-10303-21;\nHEADER;\nthis is not STEP\n")
    (d / "random.step").write_bytes(os.urandom(3000))
    return {
        "missing file": (d / "nothere.jsonl", r"nothere\.jsonl: no such file or folder"),
        "binary garbage": (d / "garbage.bin", r"garbage\.bin: not a corpus: binary data, not UTF-8"),
        "non-UTF-8": (d / "latin1.jsonl", r"latin1\.jsonl: not a corpus: binary data, not UTF-8"),
        "not a corpus": (d / "notes.txt", r"notes\.txt: not a corpus: no line is a JSON object"),
        "empty corpus": (d / "empty.jsonl", r"empty\.jsonl: empty corpus \(0 items\)"),
        "not gzip": (d / "fake.jsonl.gz", r"fake\.jsonl\.gz: named \.gz but is not gzip data"),
        "truncated gzip": (d / "cut.jsonl.gz", r"cut\.jsonl\.gz: truncated or damaged gzip data"),
        "unreadable STEP": (d / "broken.step", r"no edge pairs from .*broken\.step: no usable STEP input"),
        "random bytes as STEP": (
            d / "random.step",
            r"no edge pairs from .*random\.step: no usable STEP input",
        ),
    }


CASES = [
    "missing file",
    "binary garbage",
    "non-UTF-8",
    "not a corpus",
    "empty corpus",
    "not gzip",
    "truncated gzip",
    "unreadable STEP",
    "random bytes as STEP",
]


@pytest.mark.parametrize("case", CASES)
def test_compare_refuses_bad_input_with_one_line(case, small, tmp_path):
    path, pattern = _bad_inputs(tmp_path, small)[case]
    proc = cli("compare", path, "--out", tmp_path / "out", "--workers", "1", "--quiet")
    assert proc.returncode == EXIT_BAD_INPUT
    assert re.search(pattern, error_line(proc)), proc.stderr
    if case.endswith("STEP"):  # OCCT's reason is captured into the skipped line, not leaked
        assert re.search(r"skipped: .*OCCT cannot read this STEP file \(.+\)", proc.stderr), proc.stderr


def test_report_nowhere_and_an_empty_results_folder(tmp_path):
    proc = cli("report", tmp_path / "nowhere")
    assert proc.returncode == EXIT_BAD_INPUT
    assert re.search(r"nowhere: no such results file or folder", error_line(proc))
    proc = cli("report", tmp_path)
    assert proc.returncode == EXIT_BAD_INPUT and "no results.jsonl in this folder" in error_line(proc)
    assert not (tmp_path / "report.html").exists()


def test_report_refuses_a_corpus_file_and_runs_or_pictures_of_another_corpus(tmp_path, small):
    """Items are matched by id and ids repeat across corpora: another corpus would show other edges."""
    other = tmp_path / "other.jsonl"
    write_corpus(other, random_family("cubic", 3, seed=6))
    proc = cli("report", other, "--out", tmp_path / "r0")
    assert proc.returncode == EXIT_BAD_INPUT
    assert "record 1 is not a compare result" in error_line(proc)
    proc = cli("report", small, "--out", tmp_path / "r0")  # gzip: no line of it is a record
    assert proc.returncode == EXIT_BAD_INPUT and "no results in this file" in error_line(proc)
    for corpus, out in ((small, "ra"), (other, "rb")):
        assert cli("compare", corpus, "--out", tmp_path / out, "--quiet", "--workers", "1").returncode == 0
    proc = cli("report", tmp_path / "ra", tmp_path / "rb", "--out", tmp_path / "r1")
    assert proc.returncode == EXIT_BAD_INPUT
    assert "side-by-side columns need runs of the same corpus" in error_line(proc)
    proc = cli("report", tmp_path / "ra", "--corpus", other, "--out", tmp_path / "r2")
    assert proc.returncode == EXIT_BAD_INPUT and "is not the corpus of" in error_line(proc)
    assert not any((tmp_path / r / "report.html").exists() for r in ("r0", "r1", "r2"))
    assert cli("report", tmp_path / "ra", "--corpus", small, "--out", tmp_path / "r3").returncode == 0
    assert (tmp_path / "r3" / "report.html").is_file()


def test_corpus_names_missing_step_files_and_skips_do_not_eat_quota(tmp_path):
    out = tmp_path / "c.jsonl"
    proc = cli(
        "corpus",
        out,
        "--families",
        "step",
        "--count",
        "10",
        "--step",
        tmp_path / "nothere.step",
        "--step",
        bundled_step_dir(),
    )
    assert proc.returncode == EXIT_FAILED  # an input was skipped: not everything asked for was done
    assert re.search(r"skipped: .*nothere\.step: no such file$", proc.stderr, re.M), proc.stderr
    assert len([i for i in read_corpus(out) if isinstance(i, Item)]) == 10


def test_a_corpus_line_that_is_not_utf8_fails_alone(small, tmp_path):
    path = tmp_path / "mixed.jsonl"
    path.write_bytes(gzip.decompress(small.read_bytes()) + b'{"id": "caf\xe9", "a": "x"}\n')
    proc = cli("compare", path, "--out", tmp_path / "out", "--workers", "1", "--quiet")
    assert proc.returncode == EXIT_FAILED and "complete, 1 failure(s)" in proc.stdout
    assert re.search(r"line 4: corrupt corpus line \(not UTF-8 text", proc.stdout)


def test_two_corpora_never_share_a_results_folder(small, tmp_path):
    other = tmp_path / "other.jsonl"
    write_corpus(other, random_family("rational", 2, seed=5))
    out = tmp_path / "out"
    assert cli("compare", small, "--out", out, "--workers", "1", "--quiet").returncode == 0
    head = read_header(out / "results.jsonl")
    assert head["items"] == 3 and len(head["sha256"]) == 64
    assert {"occt", "ocp", "relief_cad", "code"} <= set(head["versions"])
    proc = cli("compare", other, "--out", out, "--workers", "1", "--quiet")
    assert proc.returncode == EXIT_BAD_INPUT
    assert re.search(
        r"holds results of another corpus .*small\.jsonl\.gz.*; give another --out, or --fresh",
        error_line(proc),
    )
    assert len(out.joinpath("results.jsonl").read_text().splitlines()) == 4  # untouched
    proc = cli("compare", other, "--out", out, "--workers", "1", "--quiet", "--fresh")
    assert proc.returncode == 0
    ids = [json.loads(x).get("id") for x in out.joinpath("results.jsonl").read_text().splitlines()[1:]]
    assert sorted(ids) == sorted(i.id for i in read_corpus(other))


def test_a_duplicated_id_is_a_failed_item_not_an_endless_interruption(small, tmp_path):
    items = [i for i in read_corpus(small) if isinstance(i, Item)]
    path = tmp_path / "dup.jsonl"
    write_corpus(path, [*items, items[0]])
    for _ in range(2):  # and the rerun resumes to the same answer
        proc = cli("compare", path, "--out", tmp_path / "out", "--workers", "1", "--quiet")
        assert proc.returncode == EXIT_FAILED and "INTERRUPTED" not in proc.stdout
        assert f"duplicate id '{items[0].id}' (first on line 1)" in proc.stdout
    assert "resuming: 4 of 4 items already done" in proc.stderr


def test_compare_takes_step_files_directly_across_or_within(tmp_path):
    steps = sorted(bundled_step_dir().glob("*.step"))
    proc = cli("compare", *steps, "--count", "4", "--out", tmp_path / "across", "--workers", "1", "--quiet")
    assert proc.returncode == 0 and "across the files" in proc.stderr
    ids = [json.loads(x)["id"] for x in (tmp_path / "across" / "results.jsonl").read_text().splitlines()[1:]]
    assert len(ids) == 4 and all(i.startswith("step-bracket+knob-") for i in ids)
    proc = cli(
        "compare",
        bundled_step_dir(),
        "--within",
        "--count",
        "4",
        "--out",
        tmp_path / "within",
        "--workers",
        "1",
        "--quiet",
    )
    assert proc.returncode == 0 and "within each file" in proc.stderr
    ids = [json.loads(x)["id"] for x in (tmp_path / "within" / "results.jsonl").read_text().splitlines()[1:]]
    assert sorted({i.rsplit("-", 1)[0] for i in ids}) == ["step-bracket", "step-knob"]


def _actions(parser):
    for a in parser._actions:
        if hasattr(a, "choices") and isinstance(a.choices, dict):
            for sub in a.choices.values():
                yield from _actions(sub)
        elif a.dest != "help":
            yield parser.prog, a


def test_help_names_the_program_is_plain_and_covers_every_option():
    proc = cli("compare", "--help")
    assert proc.returncode == 0 and proc.stdout.startswith("usage: python -m relief_cad_workbench compare")
    assert "STEP files" in proc.stdout and "--fresh" in proc.stdout
    top = cli("--help").stdout
    assert "``" not in top and ":func:" not in top and "exit status" in top
    missing = [f"{prog} {a.option_strings or a.dest}" for prog, a in _actions(build_parser()) if not a.help]
    assert not missing


def test_quickstart_reuses_its_results_and_reruns_when_the_code_changed(tmp_path):
    out = tmp_path / "qs"
    first = cli("quickstart", "--out", out, "--workers", "2", "--quiet")
    assert first.returncode == 0 and (out / "report.html").exists(), first.stdout + first.stderr
    again = cli("quickstart", "--out", out, "--workers", "2", "--quiet")
    assert again.returncode == 0 and "reusing the results in" in again.stderr
    assert "resuming: 122 of 122 items already done" in again.stderr
    # results made by another version of the code: quickstart says so and computes them again
    path = out / "results.jsonl"
    lines = path.read_text().splitlines(keepends=True)
    head = json.loads(lines[0])
    head["relief_cad_results"]["versions"]["code"] = "0123456789abcdef"
    path.write_text(json.dumps(head) + "\n" + "".join(lines[1:]))
    rerun = cli("quickstart", "--out", out, "--workers", "2", "--quiet")
    assert rerun.returncode == 0 and "running again from scratch" in rerun.stderr
    assert "code 0123456789abcdef ->" in rerun.stderr and "resuming" not in rerun.stderr
    assert read_header(path)["versions"]["code"] != "0123456789abcdef"

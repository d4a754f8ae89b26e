"""Property-based fuzz of the workbench command line on generated bad and odd corpora (issue 15).

A corpus is generated line by line (good items, duplicated ids, junk text, JSON that is not an
item, bytes that are not UTF-8, BREP text OCCT cannot read, blank lines), written plain or
gzipped, sometimes misnamed ``.gz`` or truncated, and given to ``compare`` with or without
``--stop-after``. A model predicts the exit status documented in ``workbench/__main__.py``
(0 done, 1 some items failed, 2 unusable input, 3 stopped early) and the failures: the run must
give exactly that, one ``error:`` line when (and only when) the status is 2, the failures
listed, one result line per corpus line, and never a traceback. The generated cases run
through ``main()`` in this process (cheap); two of them run as real ``python -m
relief_cad_workbench`` subprocesses. Counts: tests/_fuzz.py.
"""

from __future__ import annotations

import contextlib
import gzip
import io
import json
import os
import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from hypothesis import strategies as st
from relief_cad_workbench.__main__ import EXIT_BAD_INPUT, EXIT_FAILED, EXIT_INCOMPLETE, EXIT_OK, main
from relief_cad_workbench.corpus import random_family

from tests._fuzz import Case, Tally, fuzz

GOOD = [json.loads(item.to_json()) for item in random_family("cubic", 3, seed=11)]
KINDS = ["good", "good", "good", "good", "dup", "junk", "json", "binary", "brep", "blank"]


@dataclass
class Corpus:
    lines: list[bytes]
    gz: bool
    misnamed: bool  # plain data named .gz
    truncated: bool
    stop_after: int | None
    failures: int  # lines that must become failed items
    parsed: int  # lines read as items (the corpus is usable when > 0)


def _line(kind: str, k: int, used: list[str], text: str) -> tuple[bytes, bool, bool]:
    """One corpus line of ``kind``: (bytes, read as an item, a failure)."""
    if kind == "good" and k < len(GOOD) and GOOD[k]["id"] not in used:
        used.append(GOOD[k]["id"])
        return json.dumps(GOOD[k]).encode(), True, False
    if kind == "dup" and used:
        return json.dumps({**GOOD[0], "id": used[0]}).encode(), False, True
    if kind == "json":
        return json.dumps([text, 1, None][len(text) % 3]).encode(), False, True  # JSON, not an object
    if kind == "binary":
        return b"\xff\xfe" + text.encode() + b"\x80", False, True
    if kind == "brep":
        item_id = f"brep-{len(used)}"
        used.append(item_id)
        return json.dumps({"id": item_id, "a": "not BREP: " + text, "b": None}).encode(), True, True
    if kind == "blank":
        return b"   ", False, False
    return ("# " + text).encode(), False, True  # junk, and the kinds that could not be made


@st.composite
def corpora(draw: st.DrawFn) -> Corpus:
    kinds = draw(st.lists(st.sampled_from(KINDS), min_size=0, max_size=6))
    used: list[str] = []
    lines, parsed, failures = [], 0, 0
    for k, kind in enumerate(kinds):
        text = draw(st.text(st.characters(codec="utf-8", exclude_characters="\n\r"), max_size=12))
        raw, item, failed = _line(kind, k, used, text)
        lines.append(raw)
        parsed += item
        failures += failed
    gz = draw(st.booleans())
    n = sum(1 for ln in lines if ln.strip())
    stop = draw(st.none() | st.integers(1, max(1, n)))
    return Corpus(lines, gz, not gz and draw(st.integers(0, 5)) == 0, gz and draw(st.integers(0, 5)) == 0,
                  stop, failures, parsed)


def write(c: Corpus, folder: Path) -> Path:
    data = b"".join(ln + b"\n" for ln in c.lines)
    path = folder / ("corpus.jsonl.gz" if c.gz or c.misnamed else "corpus.jsonl")
    if c.gz:
        data = gzip.compress(data, mtime=0)
        if c.truncated:
            data = data[: max(12, len(data) // 2)]
    path.write_bytes(data)
    return path


def expected(c: Corpus) -> tuple[set[int], str]:
    """The exit statuses allowed and, for status 2, a pattern of the one error line.

    ``--stop-after N`` with more than N lines may stop early (3) or finish: results are written
    a batch at a time, so a run can reach N with everything done, and then it is complete.
    """
    nonblank = sum(1 for ln in c.lines if ln.strip())
    if c.misnamed:
        return {EXIT_BAD_INPUT}, "named .gz but is not gzip data"
    if c.truncated:
        return {EXIT_BAD_INPUT}, "truncated or damaged gzip data"
    if nonblank == 0:
        return {EXIT_BAD_INPUT}, r"empty corpus \(0 items\)"
    if c.parsed == 0:
        return {EXIT_BAD_INPUT}, "not a corpus"
    done = EXIT_FAILED if c.failures else EXIT_OK
    if c.stop_after is not None and c.stop_after < nonblank:
        return {EXIT_INCOMPLETE, done}, ""
    return {done}, ""


def check_run(case: Case, c: Corpus, path: Path, out: Path, code: int, stdout: str, stderr: str) -> None:
    want, pattern = expected(c)
    case.check("Traceback" not in stdout + stderr, "a traceback", stderr)
    case.check(code in want, f"exit status {code}, expected {want}", stdout, stderr)
    errors = [ln for ln in stderr.splitlines() if ln.startswith("error: ")]
    if code == EXIT_BAD_INPUT:
        case.check(len(errors) == 1 and path.name in errors[0] and re.search(pattern, errors[0]),
                   "not one clear error line", stderr)
        case.check(not (out / "results.jsonl").exists(), "results written for unusable input")
        return
    case.check(not errors, "an error line for usable input", stderr)
    results = (out / "results.jsonl").read_text().splitlines()
    nonblank = sum(1 for ln in c.lines if ln.strip())
    if code == EXIT_INCOMPLETE:
        case.check("STOPPED before the end" in stdout and c.stop_after + 1 <= len(results) <= nonblank,
                   "stopped, but not after --stop-after results with some left", stdout, len(results))
        return
    case.check(len(results) == 1 + nonblank, "not one result per corpus line", len(results), nonblank)
    if c.failures:
        case.check(f"complete, {c.failures} failure(s)" in stdout, stdout)
    else:
        case.check("complete: results in" in stdout, stdout)


def run_main(args: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(args)
    return code, out.getvalue(), err.getvalue()


def _args(path: Path, out: Path, c: Corpus) -> list[str]:
    extra = [] if c.stop_after is None else ["--stop-after", str(c.stop_after)]
    return ["compare", str(path), "--out", str(out), "--workers", "1", "--quiet", *extra]


ALL_DONE_AT_STOP = Corpus([json.dumps(GOOD[0]).encode()], False, False, False, 1, 0, 1)
"""--stop-after 1 on a one-item corpus: everything was done, exit 0 (it said "STOPPED", exit 3)."""


@fuzz("cli: compare on generated corpora", corpora(), examples=150, min_answered=0.3, max_answered=0.9,
      explicit=[(ALL_DONE_AT_STOP,)])
def test_fuzz_compare_corpora(case: Case, c: Corpus) -> None:
    with tempfile.TemporaryDirectory(prefix="relief_cad_fuzz_cli_") as tmp:
        path, out = write(c, Path(tmp)), Path(tmp) / "out"
        code, stdout, stderr = run_main(_args(path, out, c))
        check_run(case, c, path, out, code, stdout, stderr)
        if code == EXIT_BAD_INPUT:
            case.refused()  # its one error line was checked above
        else:
            case.answered()


SUBPROCESS_CASES = [  # generated kinds, run for real: an unusable file and a mixed corpus
    Corpus([b"# junk", b"\xff\xfe\x80", b"[1]"], False, False, False, None, 3, 0),
    Corpus([json.dumps(GOOD[0]).encode(), b"# junk", json.dumps(GOOD[0]).encode()], True, False, False,
           None, 2, 1),
]


def test_cli_subprocess_on_generated_corpora(tmp_path: Path) -> None:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([os.environ.get("PYTHONPATH", ""), str(Path.cwd())])}
    case = Case(Tally())  # the same checks, counted apart from the generators
    for k, c in enumerate(SUBPROCESS_CASES):
        folder = tmp_path / str(k)
        folder.mkdir()
        path, out = write(c, folder), folder / "out"
        proc = subprocess.run([sys.executable, "-m", "relief_cad_workbench", *_args(path, out, c)],
                              capture_output=True, text=True, env=env, timeout=300)
        check_run(case, c, path, out, proc.returncode, proc.stdout, proc.stderr)
    assert case.tally.properties >= 6

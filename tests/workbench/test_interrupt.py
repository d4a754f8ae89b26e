"""Ctrl-C stops compare promptly and leaves it resumable; a killed run resumes with nothing lost or doubled."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from relief_cad_workbench.__main__ import EXIT_INTERRUPTED, EXIT_OK
from relief_cad_workbench.corpus import Item, random_family, read_corpus, write_corpus

ROOT = Path(__file__).resolve().parents[2]
N = 4000  # corpus items: the compiled core runs 400 cubic pairs in about a second, inside a 1 s delay


def start(corpus: Path, out: Path) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([os.environ.get("PYTHONPATH", ""), str(ROOT)])}
    # Ctrl-C as a terminal's foreground job gets it: SIGINT at its default, even when this suite
    # runs as a background job (which a shell starts with SIGINT ignored, and children inherit that)
    return subprocess.Popen(
        [sys.executable, "-m", "relief_cad_workbench", "compare", corpus, "--out", out, "--workers", "2", "--quiet"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env, start_new_session=True,
        preexec_fn=_sigint_default,
    )


def _sigint_default() -> None:
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def records(out: Path) -> list[str]:
    path = out / "results.jsonl"
    if not path.exists():
        return []
    lines = path.read_bytes().split(b"\n")[1:]  # the header first
    ids = []
    for line in lines:
        try:
            ids.append(json.loads(line)["id"])
        except ValueError:  # a half-written last line
            pass
    return ids


def wait_for(out: Path, n: int, proc: subprocess.Popen[str], budget: float = 240.0) -> None:
    t0 = time.monotonic()
    while len(records(out)) < n:
        assert proc.poll() is None, proc.communicate()
        assert time.monotonic() - t0 < budget, f"fewer than {n} results after {budget} s"
        time.sleep(0.2)


@pytest.fixture(scope="module")
def corpus(tmp_path_factory) -> Path:
    # large enough that the resumed run is still going when its Ctrl-C comes
    path = tmp_path_factory.mktemp("sigint") / f"c{N}.jsonl"
    assert write_corpus(path, random_family("cubic", N, seed=21)) == N
    return path


def test_one_sigint_stops_compare_within_10_s_and_it_resumes(corpus, tmp_path):
    out = tmp_path / "run"
    ids = [i.id for i in read_corpus(corpus) if isinstance(i, Item)]
    # 1. killed outright (SIGKILL to the whole process group) part-way through
    proc = start(corpus, out)
    wait_for(out, 4, proc)
    os.killpg(proc.pid, signal.SIGKILL)
    proc.communicate(timeout=30)
    killed = set(records(out))
    # 2. resumed, then a single Ctrl-C (SIGINT to the whole group, as a terminal sends it)
    proc = start(corpus, out)
    wait_for(out, len(killed) + 4, proc)
    os.killpg(proc.pid, signal.SIGINT)
    t0 = time.monotonic()
    stdout, stderr = proc.communicate(timeout=60)
    assert time.monotonic() - t0 < 10.0, "compare took more than 10 s to stop on Ctrl-C"
    assert proc.returncode == EXIT_INTERRUPTED, (proc.returncode, stdout, stderr)
    assert "run the same command again to resume" in stdout, stdout
    assert "Traceback" not in stderr, stderr
    interrupted = records(out)
    assert killed <= set(interrupted) and len(interrupted) < len(ids)
    # 3. resumed to the end: every id exactly once, nothing computed before was lost
    proc = start(corpus, out)
    stdout, stderr = proc.communicate(timeout=600)
    assert proc.returncode == EXIT_OK, stdout + stderr
    assert f"resuming: {len(set(interrupted))} of {N}" in stderr
    final = records(out)
    assert sorted(final) == sorted(ids) and len(final) == len(set(final)) == N


@pytest.mark.parametrize("delay", [0.5, 1.0])  # start-up; a Ctrl-C mid-run is the test above
def test_a_sigint_during_start_up_exits_130_without_a_traceback(corpus, tmp_path, delay):
    """A Ctrl-C while the workbench imports OCP (about a second) must not cut that import in half.

    pybind11 turns a KeyboardInterrupt inside an extension's initialisation into an ImportError;
    swallowed, it left OCP half registered and every worker's ``import OCP`` failing, so the run
    went on and exited 1 with an ImportError, or the signal was lost.
    """
    proc = start(corpus, tmp_path / "run")
    time.sleep(delay)
    os.killpg(proc.pid, signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode == EXIT_INTERRUPTED, (proc.returncode, stdout, stderr)
    assert "interrupted" in stdout + stderr or "run the same command again to resume" in stdout
    assert "Traceback" not in stderr and "ImportError" not in stdout + stderr, stderr


def test_a_sigint_after_the_work_is_done_keeps_the_exit_status(tmp_path):
    """Once a command has finished, a Ctrl-C while Python shuts down must not turn 0 into -SIGINT."""
    path = tmp_path / "c8.jsonl"
    assert write_corpus(path, random_family("cubic", 8, seed=3)) == 8
    proc = start(path, tmp_path / "run")
    t0 = time.monotonic()
    while not (tmp_path / "run" / "summary.json").exists() and proc.poll() is None:
        assert time.monotonic() - t0 < 240, "no summary after 240 s"
        time.sleep(0.01)
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode in (EXIT_OK, EXIT_INTERRUPTED), (proc.returncode, stdout, stderr)
    assert "Traceback" not in stderr and "Exception ignored" not in stderr, stderr


def test_a_ctrl_c_while_the_workers_fork_is_held_and_raised_after() -> None:
    """The local pool forks its workers when compare submits its first tasks. A KeyboardInterrupt
    raised inside Python's fork handlers (logging's lock) is printed and ignored: a Ctrl-C one
    second in was lost and compare ran to the end with status 0. Submitting holds the Ctrl-C and
    raises it once the workers are forked."""
    from relief_cad_workbench._signals import sigint_held

    forked = False
    with pytest.raises(KeyboardInterrupt), sigint_held():
        os.kill(os.getpid(), signal.SIGINT)
        pid = os.fork()  # a fork with the signal pending: its handlers run, nothing is raised here
        if pid == 0:
            os._exit(0)
        os.waitpid(pid, 0)
        forked = True
    assert forked  # the block ran to its end; the Ctrl-C came after it
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler


class _CtrlCInFinalizer:
    """An object whose finalizer gets a real Ctrl-C (SIGINT to this process) while it runs."""

    def __del__(self) -> None:
        os.kill(os.getpid(), signal.SIGINT)
        for _ in range(2000):  # the handler runs here, in the finalizer, within a few ms
            time.sleep(0.001)


class _FailingFinalizer:
    def __del__(self) -> None:
        raise ValueError("a finalizer's own error")


def test_a_ctrl_c_that_comes_while_a_finalizer_runs_is_kept_silently_for_the_loop(monkeypatch) -> None:
    """tqdm's ``__del__`` got a Ctrl-C just after compare's work was done: "Exception ignored in"
    and a traceback were printed (once in CI); mid-run, such a Ctrl-C was lost."""
    from relief_cad_workbench._signals import ctrl_c_in_finalizers_kept, raise_kept_ctrl_c

    reported: list[BaseException | None] = []
    monkeypatch.setattr(sys, "unraisablehook", lambda info: reported.append(info.exc_value))
    old = signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a terminal
    try:
        with ctrl_c_in_finalizers_kept():
            obj = _CtrlCInFinalizer()
            del obj  # the finalizer runs and the Ctrl-C comes: nothing reported, nothing raised here
            failing = _FailingFinalizer()
            del failing
            with pytest.raises(KeyboardInterrupt):
                raise_kept_ctrl_c()
            raise_kept_ctrl_c()  # once only
        assert [type(e) for e in reported] == [ValueError]  # the finalizer's own error, as before
        assert sys.unraisablehook is not None and len(reported) == 1
        obj = _CtrlCInFinalizer()
        del obj  # outside the block: Python's way again
        assert [type(e) for e in reported] == [ValueError, KeyboardInterrupt]
    finally:
        signal.signal(signal.SIGINT, old)


def test_a_ctrl_c_kept_from_a_finalizer_stops_compare(tmp_path) -> None:
    from relief_cad_workbench._signals import ctrl_c_in_finalizers_kept
    from relief_cad_workbench.run import run_compare

    path = tmp_path / "c8.jsonl"
    assert write_corpus(path, random_family("cubic", 8, seed=3)) == 8
    with ctrl_c_in_finalizers_kept():
        obj = _CtrlCInFinalizer()
        old = signal.signal(signal.SIGINT, signal.default_int_handler)
        try:
            del obj  # a Ctrl-C, come while a finalizer ran, before compare's loop looks
        finally:
            signal.signal(signal.SIGINT, old)
        summary = run_compare(path, tmp_path / "run", workers=1, progress=False, batch=2)
    assert summary["interrupted"] and not summary["complete"]
    assert 0 < len(records(tmp_path / "run")) < 8


def test_a_ctrl_c_kept_from_a_finalizer_stops_corpus_and_keeps_the_old_file(tmp_path) -> None:
    from relief_cad_workbench.__main__ import main
    from relief_cad_workbench._signals import ctrl_c_in_finalizers_kept

    out = tmp_path / "c.jsonl"
    assert write_corpus(out, random_family("cubic", 3, seed=1)) == 3
    before = out.read_bytes()
    with ctrl_c_in_finalizers_kept():
        obj = _CtrlCInFinalizer()
        old = signal.signal(signal.SIGINT, signal.default_int_handler)
        try:
            del obj
        finally:
            signal.signal(signal.SIGINT, old)
        status = main(["corpus", str(out), "--families", "cubic", "--count", "50"])
    assert status == EXIT_INTERRUPTED and out.read_bytes() == before


def _ctrl_c_now() -> None:
    os.kill(os.getpid(), signal.SIGINT)
    for _ in range(2000):  # the handler runs within a few ms, here
        time.sleep(0.001)


def test_a_ctrl_c_stops_the_command_until_it_is_done_and_is_dropped_after() -> None:
    """Ignoring Ctrl-C once main had returned left a few instructions where one came as a
    KeyboardInterrupt out of the console entry point: a traceback and exit status -2."""
    from relief_cad_workbench._signals import command_done, ctrl_c_until_done

    before = signal.getsignal(signal.SIGINT)
    try:
        with ctrl_c_until_done():
            with pytest.raises(KeyboardInterrupt):
                _ctrl_c_now()  # the command's work: stopped
            command_done()
            _ctrl_c_now()  # done: nothing raised
            signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
            os.kill(os.getpid(), signal.SIGINT)  # pending as the block ends
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})  # delivered now: ignored
        assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN
        _ctrl_c_now()  # and so to the process's end
    finally:
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
        signal.signal(signal.SIGINT, before)


def test_main_marks_its_command_done_on_every_way_out(tmp_path, capsys) -> None:
    from relief_cad_workbench import _signals
    from relief_cad_workbench.__main__ import EXIT_BAD_INPUT, main

    for argv, status in ((["corpus", str(tmp_path / "c.jsonl"), "--families", "cubic", "--count", "2"], EXIT_OK),
                         (["compare", str(tmp_path / "missing.jsonl"), "--out", str(tmp_path / "o")],
                          EXIT_BAD_INPUT)):
        _signals._DONE[0] = False
        assert main(argv) == status
        assert _signals._DONE[0], argv

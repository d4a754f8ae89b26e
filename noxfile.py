"""The test suite in its two environments, one nox session each.

* ``A``: build123d 0.13 with the OCP 8.0 it brings (OCCT 8.0); no CadQuery.
* ``B``: CadQuery 2.8 + build123d 0.12 on OCP 7.9 (OCCT 7.9).
* ``S``: the kernels built with AddressSanitizer and UndefinedBehaviorSanitizer (``setup.py``,
  ``RELIEF_CAD_SANITIZE=1``) in a copy of the sources, running the core's fuzz and corpus tests:
  any memory error or undefined behaviour aborts the run. No CAD library.

``nox`` runs both (the README's test command). Tests that need CadQuery carry the
``cadquery`` marker: session A deselects them by name and lists each with the reason at
the end of its run (see ``conftest.py``); session B sets ``RELIEF_CAD_REQUIRE=cadquery``,
so there a missing CadQuery is an error, never a skip. Arguments after ``--`` go to
pytest, e.g. ``nox -s A -- tests/adapters -x``.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import nox

nox.options.sessions = ["A", "B", "S"]
nox.options.error_on_missing_interpreters = True

ENVIRONMENTS = {
    "A": {"extras": "test,build123d", "pins": ["build123d==0.13.*"], "require": "build123d"},
    "B": {
        "extras": "test,build123d,cadquery",
        "pins": ["cadquery==2.8.*", "build123d==0.12.*"],
        "require": "build123d,cadquery",
    },
}


def _run_tests(session: nox.Session, name: str) -> None:
    env = ENVIRONMENTS[name]
    # one resolver run: the project (built with its own build requirements) plus the pins
    session.install("-e", f".[{env['extras']}]", *env["pins"])
    session.run("python", "-c", "from relief_cad.cad._compat import versions; print(versions())")
    session.run(
        "python", "-m", "pytest", *session.posargs,
        env={"RELIEF_CAD_REQUIRE": str(env["require"]), "RELIEF_CAD_NOX_SESSION": name},
    )


@nox.session(name="A")
def env_a(session: nox.Session) -> None:
    """Environment A: build123d 0.13 on OCP 8.0 (CadQuery tests deselected by name)."""
    _run_tests(session, "A")


@nox.session(name="B")
def env_b(session: nox.Session) -> None:
    """Environment B: CadQuery 2.8 + build123d 0.12 on OCP 7.9 (every test)."""
    _run_tests(session, "B")


ROOT = Path(__file__).resolve().parent
# the core's fuzz and corpus tests: the inputs where a kernel could read or write out of bounds
SANITIZED_TESTS = [
    "tests/core/test_fuzz_core.py", "tests/core/test_planar_fuzz.py", "tests/core/test_space_fuzz.py",
    "tests/core/test_contacts.py", "tests/core/test_curves.py", "tests/core/test_touches_near_crossings.py",
    "tests/functional/test_contact_corpus.py", "tests/functional/test_planar_corpus.py",
    "tests/core/test_pool.py",  # pack_pairs writes the batch's curves into a growing buffer
    "tests/core/test_affine_rows.py",  # affine_rows writes into a caller's array, possibly its input
    "tests/core/test_inputs_clipping.py",  # bad packed arrays must be refused before the kernels read them
]
# what those tests import (pyproject's test extra without the workbench and CAD parts), and the build
SANITIZED_DEPS = ["numpy>=1.26", "cython>=3.1", "setuptools>=77", "pytest>=8", "pytest-timeout>=2.2",
                  "hypothesis>=6.100", "mpmath>=1.3"]


@nox.session(name="S")
def sanitized(session: nox.Session) -> None:
    """The kernels with AddressSanitizer + UndefinedBehaviorSanitizer on the core's fuzz and corpus tests.

    Built in place in a copy of the sources (``session.create_tmp()``), so the checkout's own
    kernels (those of sessions A and B, or a developer's) are never replaced by sanitized ones.
    """
    session.install(*SANITIZED_DEPS)
    src = Path(session.create_tmp()) / "src"
    shutil.rmtree(src, ignore_errors=True)
    src.mkdir(parents=True)
    for name in ("relief_cad", "tests"):
        shutil.copytree(ROOT / name, src / name, ignore=shutil.ignore_patterns("*.so", "*.c", "__pycache__"))
    for name in ("conftest.py", "pyproject.toml", "setup.py", "README.md"):
        shutil.copy2(ROOT / name, src / name)
    session.chdir(src)
    session.run("python", "setup.py", "-q", "build_ext", "--inplace", "-j", "2",
                env={"RELIEF_CAD_SANITIZE": "1"})
    libasan = subprocess.run(["gcc", "-print-file-name=libasan.so"], capture_output=True, text=True,
                             check=True).stdout.strip()
    session.run("python", "-m", "pytest", "-p", "no:cacheprovider", *SANITIZED_TESTS, *session.posargs,
                env={"LD_PRELOAD": libasan, "ASAN_OPTIONS": "detect_leaks=0:abort_on_error=1",
                     "UBSAN_OPTIONS": "print_stacktrace=1"})

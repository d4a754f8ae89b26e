"""The test suite in its two environments, one nox session each.

* ``A``: build123d 0.13 with the OCP 8.0 it brings (OCCT 8.0); no CadQuery.
* ``B``: CadQuery 2.8 + build123d 0.12 on OCP 7.9 (OCCT 7.9).

``nox`` runs both (the README's test command). Tests that need CadQuery carry the
``cadquery`` marker: session A deselects them by name and lists each with the reason at
the end of its run (see ``conftest.py``); session B sets ``RELIEF_CAD_REQUIRE=cadquery``,
so there a missing CadQuery is an error, never a skip. Arguments after ``--`` go to
pytest, e.g. ``nox -s A -- tests/adapters -x``.
"""

from __future__ import annotations

import nox

nox.options.sessions = ["A", "B"]
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

"""Planar corpus: relief_cad against certified truth (``planar_corpus.json``).

The truth comes from ``make_planar_corpus.py`` (exact sympy resultants on the
stored doubles, closed forms for designed contacts), never from relief_cad.
Tolerances: crossings 1e-13 in parameter (``param_tol`` overrides for
ill-conditioned families), tangent contacts ``tangent_tol`` (1e-7 by default),
overlap ends 1e-12, end points exactly 0/1.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from relief_cad.curves import RationalBezier
from relief_cad.intersection import intersect
from relief_cad.results import Intersection, Overlap

CASES: list[dict[str, Any]] = json.loads(Path(__file__).with_name("planar_corpus.json").read_text())


def _curve(rows: list[list[str]], w: list[str] | None) -> RationalBezier:
    pts = np.array([[float.fromhex(v) for v in r] for r in rows])
    return RationalBezier(pts, None if w is None else np.array([float.fromhex(v) for v in w]))


def _check(case: dict[str, Any], a: RationalBezier, b: RationalBezier, swap: bool = False) -> None:
    tol = case.get("tol")
    res = intersect(a, b, tol=tol) if not swap else intersect(b, a, tol=tol)
    pts = [r for r in res if isinstance(r, Intersection)]
    ovs = [r for r in res if isinstance(r, Overlap)]
    exp_pts = [e for e in case["expected"] if "overlap" not in e]
    exp_ovs = [e["overlap"] for e in case["expected"] if "overlap" in e]
    got = [(p.u, p.t, p.kind) if swap else (p.t, p.u, p.kind) for p in pts]
    assert len(got) == len(exp_pts), f"{case['name']}: expected {exp_pts}, got {got}"
    assert [r.t for r in pts] == sorted(r.t for r in pts)
    for e in exp_pts:
        tol = case.get("param_tol", 1e-13) if e["kind"] == "crossing" else case.get("tangent_tol", 1e-7)
        match = [g for g in got if abs(g[0] - e["t"]) <= tol and abs(g[1] - e["u"]) <= tol]
        assert match, f"{case['name']}: {e} not found within {tol} in {got}"
        assert match[0][2] == e["kind"], f"{case['name']}: kind of {e}: {match[0]}"
        if case.get("exact_ends"):
            for ge, ee in ((match[0][0], e["t"]), (match[0][1], e["u"])):
                if ee in (0.0, 1.0):
                    assert ge == ee
    assert len(ovs) == len(exp_ovs), f"{case['name']}: overlaps {ovs} vs {exp_ovs}"
    for o, e in zip(ovs, exp_ovs):
        t, u = (o.u, o.t) if swap else (o.t, o.u)
        if swap and t[0] > t[1]:
            t, u = (t[1], t[0]), (u[1], u[0])
        assert np.allclose(t, e[0], atol=1e-12, rtol=0) and np.allclose(u, e[1], atol=1e-12, rtol=0), (
            f"{case['name']}: overlap {o} vs {e}")


@pytest.mark.parametrize("case", CASES, ids=[c["name"] for c in CASES])
def test_corpus_case(case: dict[str, Any]) -> None:
    a = _curve(case["a"], case["wa"])
    b = _curve(case["b"], case["wb"])
    _check(case, a, b)


@pytest.mark.parametrize("case", CASES[::3], ids=[c["name"] for c in CASES[::3]])
def test_corpus_case_swapped(case: dict[str, Any]) -> None:
    a = _curve(case["a"], case["wa"])
    b = _curve(case["b"], case["wb"])
    _check(case, a, b, swap=True)

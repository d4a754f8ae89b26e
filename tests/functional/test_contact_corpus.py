"""Contact corpus: relief_cad against truth certified by construction (``contact_corpus.json``).

The cases come from ``make_contact_corpus.py`` (exact by construction, exact blossoming, sympy
root isolation), never from relief_cad. Pairs are checked like the planar corpus: right count,
right kind, crossings within 1e-13 in parameter, tangencies within 1e-7, overlap ends within
1e-12 and end parameters exactly 0/1. A case with ``"b": null`` is the self-intersection of ``a``.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from relief_cad.intersection import intersect
from relief_cad.results import Intersection, Overlap
from tests.functional.test_planar_corpus import _check, _curve

CASES: list[dict[str, Any]] = json.loads(Path(__file__).with_name("contact_corpus.json").read_text())
PAIRS = [c for c in CASES if c["b"] is not None]
SELF = [c for c in CASES if c["b"] is None]

@pytest.mark.parametrize("case", PAIRS, ids=[c["name"] for c in PAIRS])
def test_contact_pair(case: dict[str, Any]) -> None:
    _check(case, _curve(case["a"], case["wa"]), _curve(case["b"], case["wb"]))


@pytest.mark.parametrize("case", PAIRS[::4], ids=[c["name"] for c in PAIRS[::4]])
def test_contact_pair_swapped(case: dict[str, Any]) -> None:
    _check(case, _curve(case["a"], case["wa"]), _curve(case["b"], case["wb"]), swap=True)


@pytest.mark.parametrize("case", SELF, ids=[c["name"] for c in SELF])
def test_contact_self(case: dict[str, Any]) -> None:
    res = intersect(_curve(case["a"], case["wa"]))
    exp = [e["overlap"] for e in case["expected"]]
    assert not [r for r in res if isinstance(r, Intersection)], f"{case['name']}: stray points in {res}"
    ovs = [r for r in res if isinstance(r, Overlap)]
    assert len(ovs) == len(exp), f"{case['name']}: {res} vs {exp}"
    for o, (t, u) in zip(ovs, exp):
        assert np.allclose(o.t, t, atol=case.get("overlap_tol", 1e-12), rtol=0), (o, t)
        assert np.allclose(o.u, u, atol=case.get("overlap_tol", 1e-12), rtol=0), (o, u)
        for got, want in zip(o.t + o.u, t + u):
            if want in (0.0, 1.0):
                assert got == want

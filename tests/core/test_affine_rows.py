"""``affine_rows``: ``H @ M.T`` as one FMA chain per entry, the same bits compiled and uncompiled.

The CAD layer moves every converted control point by an edge's location, and onto the plane of a
planar model, with it. numpy's ``H @ M.T`` goes to the machine's BLAS, which sums with FMA on some
CPUs and not on others; the chain here is fixed: ``fma(M[j, k-1], H[i, k-1], ... M[j, 0] H[i, 0])``,
every step rounded once. Truth: the same chain in exact rationals (``fractions``), rounded per step.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from fractions import Fraction

import numpy as np
import pytest

from relief_cad._kernels.bezier import affine_rows


def _chain(h: list[float], m: list[float]) -> float:
    acc = m[0] * h[0]
    for a, b in zip(m[1:], h[1:], strict=True):
        acc = float(Fraction(a) * Fraction(b) + Fraction(acc))  # fma: one rounding
    return acc


def _data(seed: int, rows: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    h = rng.normal(size=(rows, 4)) * 10.0 ** rng.integers(-3, 4, size=(rows, 1))
    h[:, 3] = rng.uniform(0.2, 3.0, size=rows)  # weights
    m = rng.normal(size=(3, 4)) * np.array([1.0, 1.0, 1.0, 1e3])
    return h, m


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_each_entry_is_the_fma_chain(seed: int) -> None:
    h, m = _data(seed, 400)
    out = np.full((h.shape[0], 3), np.nan)
    affine_rows(h, m, out)
    want = [[_chain(row, mr) for mr in m.tolist()] for row in h.tolist()]
    assert out.tolist() == want
    # plain sums of products (no FMA) differ in the last bit somewhere: the data tell them apart
    plain = [[sum(a * b for a, b in zip(mr, row, strict=True)) for mr in m.tolist()] for row in h.tolist()]
    assert plain != want


def test_in_place_keeps_the_weights_and_a_plane_map_fills_two_columns() -> None:
    h, m = _data(4, 50)
    want = [[_chain(row, mr) for mr in m.tolist()] for row in h.tolist()]
    weights = h[:, 3].tolist()
    affine_rows(h, m, h)  # out is H: each row is read before it is written
    assert h[:, :3].tolist() == want and h[:, 3].tolist() == weights
    g, _ = _data(5, 50)
    plane = m[:2]
    out = np.zeros((g.shape[0], 3))
    affine_rows(g, plane, out)
    assert out[:, :2].tolist() == [[_chain(row, mr) for mr in plane.tolist()] for row in g.tolist()]
    assert not out[:, 2].any()


@pytest.mark.parametrize(("shape_h", "shape_m", "shape_out"), [((3, 4), (3, 3), (3, 3)), ((3, 5), (3, 5), (3, 3)),
                                                              ((3, 4), (3, 4), (2, 3)), ((3, 4), (3, 4), (3, 2))])
def test_mismatched_shapes_are_refused(shape_h: tuple[int, int], shape_m: tuple[int, int],
                                       shape_out: tuple[int, int]) -> None:
    with pytest.raises(ValueError, match="expected rows"):
        affine_rows(np.ones(shape_h), np.ones(shape_m), np.zeros(shape_out))


_PURE = """
import json, sys
import numpy as np
sys.path.insert(0, {root!r})
from tests.core.test_affine_rows import _data
from relief_cad._kernels import COMPILED
from relief_cad._kernels.bezier import affine_rows
h, m = _data(6, 200)
out = np.zeros((200, 3))
affine_rows(h, m, out)
print(json.dumps([COMPILED, [repr(x) for x in out.ravel().tolist()]]))
"""


def test_uncompiled_kernel_gives_the_same_bits() -> None:
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    run = subprocess.run([sys.executable, "-c", _PURE.format(root=root)], capture_output=True, text=True,
                         env=dict(os.environ, RELIEF_CAD_PURE="1"), timeout=600, check=False)
    assert run.returncode == 0, run.stderr[-2000:]
    compiled, values = json.loads(run.stdout.strip().splitlines()[-1])
    assert compiled is False
    h, m = _data(6, 200)
    out = np.zeros((200, 3))
    affine_rows(h, m, out)
    assert values == [repr(x) for x in out.ravel().tolist()]

"""Dump intersect / intersect_many results over 3000 seeded random pairs, bit-exact (float.hex).

Usage: ``python scripts/dump_intersections.py OUT [WORKERS]``; compare two dumps with ``cmp``
(before and after a change that must not change results, or between ``workers`` values).
"""

from __future__ import annotations

import sys

import numpy as np

from relief_cad import IntersectionList, Overlap, RationalBezier, intersect, intersect_many


def _pairs(n: int = 3000) -> list[tuple[RationalBezier, RationalBezier]]:
    """Rational curves of degree 1-5, polynomial cubics (some apart) and dyadic curves (end meetings)."""
    rng = np.random.default_rng(12345)
    out = []
    for k in range(n):
        da, db = rng.integers(1, 6, size=2)
        if k % 3 == 0:
            a = RationalBezier(rng.random((da + 1, 2)), 0.5 + rng.random(da + 1))
            b = RationalBezier(rng.random((db + 1, 2)), 0.5 + rng.random(db + 1))
        elif k % 3 == 1:
            a = RationalBezier(rng.random((4, 2)))
            b = RationalBezier(rng.random((4, 2)) + (rng.random(2) * 2 if k % 2 else 0))
        else:
            a = RationalBezier(rng.integers(0, 8, (da + 1, 2)) / 8.0)
            b = RationalBezier(rng.integers(0, 8, (db + 1, 2)) / 8.0)
        out.append((a, b))
    return out


def _fmt(res: IntersectionList) -> str:
    out = []
    for r in res:
        if isinstance(r, Overlap):
            out.append("O " + " ".join(x.hex() for x in (*r.t, *r.u)))
        else:
            out.append(f"{r.kind} " + " ".join(float(x).hex() for x in (r.t, r.u, *r.point, r.distance)))
    out += ["U " + " ".join(x.hex() for x in (bx.t0, bx.t1, bx.u0, bx.u1)) for bx in res.unresolved]
    return "; ".join(out)


def main() -> None:
    """Write the dump named on the command line."""
    pairs = _pairs()
    lines = []
    for i, (a, b) in enumerate(pairs):
        lines.append(f"{i} one {_fmt(intersect(a, b, on_budget='return'))}")
        if i % 5 == 0:
            lines.append(f"{i} tol {_fmt(intersect(a, b, tol=1e-6, on_budget='return'))}")
    workers = None if len(sys.argv) < 3 else int(sys.argv[2])
    for i, res in enumerate(intersect_many(pairs, on_budget="return", workers=workers)):
        lines.append(f"{i} many {_fmt(res)}")
    with open(sys.argv[1], "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print(len(lines), "lines,", sum(1 for line in lines if line.split(" ", 2)[2:] != [""]), "non-empty")


if __name__ == "__main__":
    main()

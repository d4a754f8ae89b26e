"""Cross-check relief_cad against OCCT on the same edges, with an exact arbiter.

:func:`compare` runs :func:`relief_cad.cad.intersections` and
:func:`relief_cad.cad.occt.occt_intersections` with one tolerance, matches their results
(points within the tolerance, overlaps whose parameter ranges meet), and sends every
disagreement to an arbiter that decides who is right.

This module holds the matching and the comparison types (:class:`Comparison`,
:class:`Match`, :class:`Disagreement`, :class:`Verdict`). The exact curve data lives in
:mod:`.exact`, the arbiter in :mod:`.arbiter`, the pictures in :mod:`.render`; their public
names are re-exported here.

>>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
>>> from OCP.gp import gp_Pnt
>>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
>>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
>>> v = arbitrate_point(a, b, 1.4, 1.4, tol=1e-7)
>>> v.holds, v.kind, round(v.t, 12), v.distance < 1e-40
(True, 'crossing', 1.414213562373, True)
"""

from __future__ import annotations

import base64
import dataclasses
import html
import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any, Literal

from ._checks import check_model_tol, check_tol
from .arbiter import (
    OverlapCheck,
    PointCheck,
    _closest_u,
    _one_place,
    _one_point_of,
    _rounding,
    arbitrate_overlap,
    arbitrate_point,
)
from .exact import ARBITER_DIGITS, ExactCurve
from .occt import default_occt_tolerance, occt_intersections
from .render import plot_pair_png, where
from .results import EdgeIntersection, EdgeOverlap, EdgeResult
from .topology import edges_of, usable_edges

__all__ = [
    "ARBITER_DIGITS",
    "Comparison",
    "Disagreement",
    "ExactCurve",
    "Match",
    "OverlapCheck",
    "PointCheck",
    "Verdict",
    "arbitrate_overlap",
    "arbitrate_point",
    "compare",
    "plot_pair_png",
]


Side = Literal["relief_cad", "occt"]


# --------------------------------------------------------------------------- comparison


@dataclass(frozen=True)
class Match:
    """A result both sides found.

    >>> import build123d as bd
    >>> m = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0))).agreed[0]
    >>> m.relief.kind, m.occt.route, m.distance < 1e-12
    ('crossing', 'Geom2dInt_GInter', True)

    Attributes
    ----------
    relief, occt : EdgeIntersection or EdgeOverlap
        The two results.
    distance : float
        Distance between the two reported points (largest end distance for overlaps).
    dt, du : float
        Parameter differences (largest end difference for overlaps).
    loose : bool
        Matched only after the arbiter refined both to the same true point (tangent
        contacts are located to about ``sqrt(tol)``; inaccurate answers).
    relief_error, occt_error : float
        Distance from each side's reported point to the arbiter's refined true point
        (``nan`` when not computed; overlaps).
    """

    relief: EdgeResult
    occt: EdgeResult
    distance: float
    dt: float
    du: float
    loose: bool = False
    relief_error: float = math.nan
    occt_error: float = math.nan


@dataclass(frozen=True)
class Verdict:
    """Who is right about one disagreement, and why.

    >>> v = Verdict(winner="relief_cad", truth="tangent", reason="OCCT reports a segment", distance=0.0)
    >>> v.winner, v.exact
    ('relief_cad', True)

    Attributes
    ----------
    winner : {"relief_cad", "occt", "neither"}
        The side whose answer matches the truth.
    truth : str
        What is really there: ``"crossing"``, ``"tangent"``, ``"overlap"``, ``"nothing"``
        or ``"duplicate"``.
    reason : str
        One sentence for a human.
    distance : float
        True distance at the refined candidate (largest sampled distance for overlaps).
    exact : bool
        False when a curve had no exact data.
    """

    winner: str
    truth: str
    reason: str
    distance: float
    exact: bool = True


@dataclass(frozen=True)
class Disagreement:
    """A result claimed by one side only (or an overlap/point conflict), with its verdict.

    >>> from relief_cad.cad.results import EdgeIntersection
    >>> claim = EdgeIntersection(0, 0, None, None, 0.5, 0.5, (1.0, 1.0, 0.0), "crossing")
    >>> d = Disagreement("relief_cad", claim, (), Verdict("relief_cad", "crossing", "OCCT missed it", 0.0))
    >>> d.status, d.index
    ('only relief_cad', (0, 0))

    Attributes
    ----------
    claimant : {"relief_cad", "occt"}
        The side that made the claim.
    claim : EdgeIntersection or EdgeOverlap
        The claim.
    counter : tuple of results
        What the other side reported instead in the same place (points inside a claimed
        overlap, or the overlap containing a claimed point); empty when it reported
        nothing.
    verdict : Verdict
        The arbiter's decision.
    """

    claimant: str
    claim: EdgeResult
    counter: tuple[EdgeResult, ...]
    verdict: Verdict

    @property
    def status(self) -> str:
        """``"only relief_cad"``, ``"only occt"``, or ``"range dispute"`` (both report an overlap).

        >>> from relief_cad.cad.results import EdgeIntersection
        >>> p = EdgeIntersection(0, 0, None, None, 0.5, 0.5, (1.0, 1.0, 0.0), "crossing")
        >>> Disagreement("occt", p, (), Verdict("occt", "crossing", "", 0.0)).status
        'only occt'
        """
        if isinstance(self.claim, EdgeOverlap) and any(isinstance(c, EdgeOverlap) for c in self.counter):
            return "range dispute"
        return f"only {self.claimant}"

    @property
    def index(self) -> tuple[int, int]:
        """The edge pair ``(index_a, index_b)``.

        >>> from relief_cad.cad.results import EdgeIntersection
        >>> p = EdgeIntersection(2, 5, None, None, 0.5, 0.5, (1.0, 1.0, 0.0), "crossing")
        >>> Disagreement("occt", p, (), Verdict("occt", "crossing", "", 0.0)).index
        (2, 5)
        """
        return (self.claim.index_a, self.claim.index_b)


def _res_dict(r: EdgeResult) -> dict[str, Any]:
    if isinstance(r, EdgeIntersection):
        return {
            "type": "point",
            "index_a": r.index_a,
            "index_b": r.index_b,
            "t": r.t,
            "u": r.u,
            "point": list(map(float, r.point)),
            "kind": r.kind,
            "distance": r.distance,
            "route": r.route,
        }
    return {
        "type": "overlap",
        "index_a": r.index_a,
        "index_b": r.index_b,
        "t": list(r.t),
        "u": list(r.u),
        "kind": "overlap",
        "route": r.route,
    }


@dataclass
class Comparison:
    """relief_cad's answer and OCCT's on the same shapes, matched, with verdicts.

    >>> import build123d as bd
    >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
    >>> c.agree, len(c.agreed), c.routes
    (True, 1, ['Geom2dInt_GInter'])

    Attributes
    ----------
    tol : float
        The tolerance both sides and the arbiter used.
    relief, occt : list of results
        The two answers as returned.
    agreed : list of Match
        Results both found.
    disagreements : list of Disagreement
        Every claim made by one side only, with the arbiter's verdict.
    routes : list of str
        The OCCT routes that answered (unique, in order).
    times : dict
        Wall times in seconds: ``relief_cad``, ``occt``, ``arbiter``.
    errors : dict
        Exceptions raised by a side (``{"relief_cad": "ValueError: ..."}``); that side's
        answer is then empty and every claim of the other side is arbitrated.
    skipped : list of (str, int, str)
        Edges that took no part: ``(shape, index, reason)`` with ``shape`` ``"a"`` or ``"b"``
        and ``index`` in :func:`~relief_cad.cad.topology.edges_of` order (degenerated edges:
        a sphere's poles, a cone's apex).
    """

    tol: float
    relief: list[EdgeResult]
    occt: list[EdgeResult]
    agreed: list[Match] = field(default_factory=list)
    disagreements: list[Disagreement] = field(default_factory=list)
    routes: list[str] = field(default_factory=list)
    times: dict[str, float] = field(default_factory=dict)
    errors: dict[str, str] = field(default_factory=dict)
    edges_a: list[Any] = field(default_factory=list, repr=False)
    edges_b: list[Any] = field(default_factory=list, repr=False)
    plot: bool = False
    skipped: list[tuple[str, int, str]] = field(default_factory=list)

    @property
    def only_relief(self) -> list[Disagreement]:
        """Disagreements claimed by relief_cad.

        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> c.only_relief
        []
        """
        return [d for d in self.disagreements if d.claimant == "relief_cad"]

    @property
    def only_occt(self) -> list[Disagreement]:
        """Disagreements claimed by OCCT.

        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> c.only_occt
        []
        """
        return [d for d in self.disagreements if d.claimant == "occt"]

    @property
    def agree(self) -> bool:
        """True when the two answers match completely.

        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> c.agree
        True
        """
        return not self.disagreements and not self.errors

    def score(self) -> dict[str, int]:
        """Count verdicts: how often each side was right on a disagreement.

        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> c.score()["agreed"], c.score()["occt_right"]
        (1, 0)

        Returns
        -------
        dict
            Keys ``agreed``, ``relief_cad_right``, ``occt_right``, ``neither`` and
            ``relief_cad_inaccurate`` / ``occt_inaccurate`` (agreed points reported farther
            than ``tol`` from the arbiter's true point).
        """
        s = {"agreed": len(self.agreed), "relief_cad_right": 0, "occt_right": 0, "neither": 0}
        for d in self.disagreements:
            key = {"relief_cad": "relief_cad_right", "occt": "occt_right"}.get(d.verdict.winner, "neither")
            s[key] += 1
        s["relief_cad_inaccurate"] = sum(1 for m in self.agreed if m.relief_error > self.tol)
        s["occt_inaccurate"] = sum(1 for m in self.agreed if m.occt_error > self.tol)
        return s

    def to_dict(self) -> dict[str, Any]:
        """Return a JSON-ready summary (no OCCT objects).

        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> import json
        >>> json.loads(json.dumps(c.to_dict()))["tol"] == c.tol
        True
        """
        return {
            "tol": self.tol,
            "routes": self.routes,
            "times": self.times,
            "errors": self.errors,
            "score": self.score(),
            "relief": [_res_dict(r) for r in self.relief],
            "occt": [_res_dict(r) for r in self.occt],
            "agreed": [
                {
                    "relief": _res_dict(m.relief),
                    "occt": _res_dict(m.occt),
                    "distance": m.distance,
                    "dt": m.dt,
                    "du": m.du,
                    "loose": m.loose,
                    "relief_error": None if math.isnan(m.relief_error) else m.relief_error,
                    "occt_error": None if math.isnan(m.occt_error) else m.occt_error,
                }
                for m in self.agreed
            ],
            "disagreements": [
                {
                    "claimant": d.claimant,
                    "status": d.status,
                    "claim": _res_dict(d.claim),
                    "counter": [_res_dict(c) for c in d.counter],
                    "winner": d.verdict.winner,
                    "truth": d.verdict.truth,
                    "reason": d.verdict.reason,
                    "distance": d.verdict.distance,
                    "exact": d.verdict.exact,
                }
                for d in self.disagreements
            ],
        }

    # ----- display

    def _rows(self) -> list[tuple[str, str, str, str, str, str]]:
        rows: list[tuple[str, str, str, str, str, str]] = []
        for m in self.agreed:
            r = m.relief
            place = where(r)
            rows.append(
                (
                    "agreed",
                    place,
                    r.kind,
                    f"{m.distance:.2e}",
                    f"{max(m.dt, m.du):.2e}",
                    ("matched after refinement; " if m.loose else "")
                    + (
                        f"error vs truth: relief_cad {m.relief_error:.1e}, OCCT {m.occt_error:.1e}"
                        if not math.isnan(m.relief_error)
                        else ""
                    ),
                )
            )
        for d in self.disagreements:
            rows.append(
                (
                    d.status,
                    where(d.claim),
                    d.claim.kind,
                    f"{d.verdict.distance:.2e}",
                    "",
                    f"{d.verdict.winner} right: {d.verdict.reason}"
                    if d.verdict.winner != "neither"
                    else f"neither: {d.verdict.reason}",
                )
            )
        return rows

    def __str__(self) -> str:
        s = self.score()
        head = (
            f"Comparison: tol={self.tol:.3g}, OCCT route(s): {', '.join(self.routes) or '-'}; "
            f"{s['agreed']} agreed, {len(self.disagreements)} disagreement(s) "
            f"(relief_cad right {s['relief_cad_right']}, OCCT right {s['occt_right']}, "
            f"neither {s['neither']})"
        )
        if self.errors:
            head += "\n" + "\n".join(f"  error in {k}: {v}" for k, v in self.errors.items())
        if self.skipped:
            head += "\n" + "\n".join(f"  skipped edge {k}[{i}]: {why}" for k, i, why in self.skipped)
        cols = ("status", "where (edges: params)", "kind", "dist", "dparam", "verdict")
        rows = self._rows()
        if not rows:
            return head + "\n  (no intersections on either side)"
        widths = [max(len(c), *(len(r[i]) for r in rows)) for i, c in enumerate(cols)]
        widths[-1] = min(widths[-1], 90)
        line = "  ".join(c.ljust(w) for c, w in zip(cols, widths, strict=False))
        out = [head, line, "  ".join("-" * w for w in widths)]
        out += ["  ".join(c[:w].ljust(w) for c, w in zip(r, widths, strict=False)) for r in rows]
        return "\n".join(out)

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        return self.to_html(plot=self.plot)

    def to_html(self, *, plot: bool = False) -> str:
        """Return an HTML table (and an inline PNG plot of both answers when ``plot``).

        Parameters
        ----------
        plot : bool
            Embed a matplotlib picture of the curves and both answers (base64 PNG).

        Returns
        -------
        str

        Examples
        --------
        >>> import build123d as bd
        >>> c = compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0)))
        >>> c.to_html().startswith("<"), "<img" in c.to_html(plot=True)
        (True, True)
        """
        s = self.score()
        rows = "".join(
            "<tr>" + "".join(f"<td>{html.escape(c)}</td>" for c in r) + "</tr>" for r in self._rows()
        )
        head = "".join(f"<th>{c}</th>" for c in ("status", "where", "kind", "dist", "dparam", "verdict"))
        img = ""
        if plot:
            png = self.plot_png()
            if png:
                b64 = base64.b64encode(png).decode()
                img = f'<img alt="curves and answers" src="data:image/png;base64,{b64}"/>'
        err = "".join(
            f"<p><b>error in {html.escape(k)}</b>: {html.escape(v)}</p>" for k, v in self.errors.items()
        )
        return (
            f"<div><p><b>relief_cad vs OCCT</b> (tol {self.tol:.3g}; "
            f"route {html.escape(', '.join(self.routes))}): "
            f"{s['agreed']} agreed, {len(self.disagreements)} disagreement(s): relief_cad right "
            f"{s['relief_cad_right']}, OCCT right {s['occt_right']}, neither {s['neither']}</p>{err}"
            f"<table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>{img}</div>"
        )

    def plot_png(self, *, size: tuple[float, float] = (5.0, 4.0)) -> bytes:
        """Draw the edges and both answers (relief_cad: circles, OCCT: crosses) as PNG bytes.

        Returns
        -------
        bytes
            PNG data (empty when matplotlib is missing).

        Examples
        --------
        >>> import build123d as bd
        >>> compare(bd.Line((0, 0), (2, 2)), bd.Line((0, 2), (2, 0))).plot_png()[1:4]
        b'PNG'
        """
        return plot_pair_png(
            self.edges_a,
            self.edges_b,
            self.relief,
            self.occt,
            [d.claim for d in self.disagreements],
            size=size,
        )


# --------------------------------------------------------------------------- matching


def _pt_dist(p: Sequence[float], q: Sequence[float]) -> float:
    return math.dist(tuple(map(float, p)), tuple(map(float, q)))


def _in_range(x: float, rng: tuple[float, float], pad: float) -> bool:
    lo, hi = min(rng), max(rng)
    return lo - pad <= x <= hi + pad


def _on_claim(p: EdgeIntersection, o: EdgeOverlap, ca: ExactCurve, cb: ExactCurve, pad: float) -> bool:
    """True when point ``p`` bears on overlap claim ``o``: its ``t`` in ``o``'s range (``pad`` of slack).

    On one edge (self-intersections) its ``u`` must lie in ``o``'s too: a double point at that
    ``t`` with another stretch of the edge says nothing of a self-overlap claimed there.
    """
    if not _in_range(p.t, o.t, pad):
        return False
    return ca is not cb or _in_range(cb.near(p.u, 0.5 * (o.u[0] + o.u[1])), o.u, pad)


def _merge_overlaps(results: list[EdgeResult], pad: float) -> list[EdgeResult]:
    """Join one side's overlaps whose ``t`` ranges meet (OCCT sometimes fragments one overlap)."""
    ovs = sorted((r for r in results if isinstance(r, EdgeOverlap)), key=lambda r: r.t[0])
    merged: list[EdgeOverlap] = []
    for o in ovs:
        if merged and o.t[0] <= merged[-1].t[1] + pad:
            last = merged[-1]
            if o.t[1] > last.t[1]:
                merged[-1] = dataclasses.replace(last, t=(last.t[0], o.t[1]), u=(last.u[0], o.u[1]))
            continue
        merged.append(o)
    return [r for r in results if isinstance(r, EdgeIntersection)] + list(merged)


def _match_side(
    relief: list[EdgeResult],
    occt: list[EdgeResult],
    exacts_a: list[ExactCurve],
    exacts_b: list[ExactCurve],
    tol: float,
    refine_all: bool = True,
) -> tuple[list[Match], list[Disagreement]]:
    """Match both sides' results edge pair by edge pair, and judge what is left (:class:`_PairMatch`)."""
    by_pair: dict[tuple[int, int], tuple[list[EdgeResult], list[EdgeResult]]] = {}
    for k, side in enumerate((relief, occt)):
        for r in side:
            by_pair.setdefault((r.index_a, r.index_b), ([], []))[k].append(r)
    agreed: list[Match] = []
    disagreements: list[Disagreement] = []
    for (ia, ib), (rel, occ) in sorted(by_pair.items()):
        pair = _PairMatch(exacts_a[ia], exacts_b[ib], rel, occ, tol, refine_all)
        pair.overlaps()
        pair.points()
        pair.loose_points()
        pair.leftovers()
        agreed.extend(pair.agreed)
        disagreements.extend(pair.disagreements)
    return agreed, disagreements


class _PairMatch:
    """The matching of one edge pair's results, in four steps called in order.

    1. :meth:`overlaps`: overlaps whose ``t`` ranges meet; those whose ends differ by more than
       tol are judged (whose range is right?);
    2. :meth:`points`: points within tol of each other, nearest first;
    3. :meth:`loose_points`: points the arbiter refines to one true point (or one touch);
    4. :meth:`leftovers`: every result still unmatched, judged by the arbiter.

    ``rel`` and ``occ`` are one side's results each, with fragmented overlaps joined.
    """

    def __init__(self, ca: ExactCurve, cb: ExactCurve, rel: list[EdgeResult], occ: list[EdgeResult],
                 tol: float, refine_all: bool) -> None:
        self.ca, self.cb, self.tol, self.refine_all = ca, cb, tol, refine_all
        self.pad = 1e-9 * (ca.last - ca.first) + 1e-12
        self.rel = _merge_overlaps(rel, self.pad)
        self.occ = _merge_overlaps(occ, self.pad)
        self.used_r: set[int] = set()
        self.used_o: set[int] = set()
        self.agreed: list[Match] = []
        self.disagreements: list[Disagreement] = []
        self._refined: dict[tuple[str, int], PointCheck] = {}
        self._cand: list[tuple[float, int, int]] = []

    def _take(self, match: Match, i: int, j: int) -> None:
        self.agreed.append(match)
        self.used_r.add(i)
        self.used_o.add(j)

    def overlaps(self) -> None:
        """Step 1: overlaps whose ``t`` ranges meet match; ends farther apart than tol are judged."""
        ca, pad = self.ca, self.pad
        for i, r in enumerate(self.rel):
            if not isinstance(r, EdgeOverlap):
                continue
            for j, o in enumerate(self.occ):
                if not isinstance(o, EdgeOverlap) or min(r.t[1], o.t[1]) < max(r.t[0], o.t[0]) - pad:
                    continue
                if i in self.used_r or j in self.used_o:
                    # a fragment of an overlap already matched (one side split it)
                    self.used_r.add(i)
                    self.used_o.add(j)
                    continue
                dt = max(abs(r.t[0] - o.t[0]), abs(r.t[1] - o.t[1]))
                du = max(abs(r.u[0] - o.u[0]), abs(r.u[1] - o.u[1]))
                pa = [[float(x) for x in ca.value(s)] for s in r.t]
                pb = [[float(x) for x in ca.value(s)] for s in o.t]
                dist = max(_pt_dist(pa[0], pb[0]), _pt_dist(pa[1], pb[1]))
                self._take(Match(r, o, dist, dt, du), i, j)
        for m in [m for m in self.agreed if m.distance > self.tol]:
            assert isinstance(m.relief, EdgeOverlap) and isinstance(m.occt, EdgeOverlap)
            self.agreed.remove(m)
            self.disagreements.append(_judge_ranges(self.ca, self.cb, m.relief, m.occt, self.tol))

    def _check(self, side: str, k: int, res: EdgeIntersection) -> PointCheck:
        """The arbiter's refinement of one side's point (``side`` "r" or "o", ``k`` its index), cached."""
        if (side, k) not in self._refined:
            ca, cb = self.ca, self.cb
            chk = arbitrate_point(ca, cb, res.t, res.u, tol=self.tol)
            if ca is cb and _one_point_of(ca, chk.t, chk.u, self.tol):
                # a double point of one edge that collapsed onto t == u, or the closing point
                # of a closed edge (its seam, at both ends of its range): not a double point
                chk = dataclasses.replace(chk, holds=False, kind="miss", distance=math.inf)
            self._refined[(side, k)] = chk
        return self._refined[(side, k)]

    def _open_points(self) -> list[tuple[float, int, int, EdgeIntersection, EdgeIntersection]]:
        """Pairs of points not matched yet, nearest first: (distance, i, j, relief's, OCCT's)."""
        out = []
        for d, i, j in self._cand:
            r, o = self.rel[i], self.occ[j]
            if i not in self.used_r and j not in self.used_o:
                assert isinstance(r, EdgeIntersection) and isinstance(o, EdgeIntersection)
                out.append((d, i, j, r, o))
        return out

    def points(self) -> None:
        """Step 2: points within tol of each other match, nearest first."""
        for i, r in enumerate(self.rel):
            if i in self.used_r or not isinstance(r, EdgeIntersection):
                continue
            for j, o in enumerate(self.occ):
                if j not in self.used_o and isinstance(o, EdgeIntersection):
                    self._cand.append((_pt_dist(r.point, o.point), i, j))
        self._cand.sort()
        for d, i, j, r, o in self._open_points():
            if i in self.used_r or j in self.used_o or d > self.tol:
                continue
            er = eo = math.nan
            if self.refine_all:
                truth = self._check("r", i, r)
                er, eo = _pt_dist(r.point, truth.point), _pt_dist(o.point, truth.point)
            self._take(Match(r, o, d, abs(r.t - o.t), abs(r.u - o.u), False, er, eo), i, j)

    def loose_points(self) -> None:
        """Step 3: points the arbiter refines to one true point, or to one touch that rounding split.

        Tangents are located to about ``sqrt(tol)``, and some answers are inaccurate.
        """
        loose = []
        for d, i, j, r, o in self._open_points():
            pr, po = self._check("r", i, r), self._check("o", j, o)
            dd = _pt_dist(pr.point, po.point)
            if pr.holds and po.holds and (dd <= self.tol or _one_touch(self.ca, self.cb, pr, po, self.tol)):
                loose.append((dd, d, i, j, r, o))
        for _dd, d, i, j, r, o in sorted(loose, key=lambda x: x[:4]):
            if i in self.used_r or j in self.used_o:
                continue
            pr, po = self._check("r", i, r), self._check("o", j, o)
            er, eo = _pt_dist(r.point, pr.point), _pt_dist(o.point, po.point)
            self._take(Match(r, o, d, abs(r.t - o.t), abs(r.u - o.u), True, er, eo), i, j)

    def leftovers(self) -> None:
        """Step 4: every result still unmatched, on either side, judged by the arbiter."""
        ca, cb, pad, tol = self.ca, self.cb, self.pad, self.tol
        for side, mine, theirs, used in (("relief_cad", self.rel, self.occ, self.used_r),
                                         ("occt", self.occ, self.rel, self.used_o)):
            other: Side = "occt" if side == "relief_cad" else "relief_cad"
            for k, claim in enumerate(mine):
                if k in used:
                    continue
                counter: tuple[EdgeResult, ...]
                if isinstance(claim, EdgeOverlap) and ca is cb and _one_stretch(claim, pad):
                    counter, verdict = (), _one_stretch_verdict(claim, other)
                elif isinstance(claim, EdgeOverlap):
                    counter, verdict = _judge_overlap(ca, cb, claim, theirs, pad, tol, side, other)
                else:
                    counter = tuple(
                        x for x in theirs if isinstance(x, EdgeOverlap) and _on_claim(claim, x, ca, cb, pad)
                    )
                    if counter:
                        continue  # judged from the overlap's side
                    check = self._check("r" if side == "relief_cad" else "o", k, claim)
                    verdict = _judge_point(check, claim, mine, theirs, k, tol, side, other, ca, cb)
                self.disagreements.append(Disagreement(side, claim, counter, verdict))


def _one_stretch(claim: EdgeOverlap, pad: float) -> bool:
    """True when a self-overlap claim's two ranges share their inside: the edge against itself.

    OCCT's self-intersection of one spline gave ``t (0.59089, 0.59181)`` against ``u (0.59089,
    0.61593)``; the arbiter found the edge on itself there and judged it a true overlap. A real
    self-overlap (a stretch run twice) has ranges that meet at most at an end (a fold).
    """
    lo, hi = min(claim.u), max(claim.u)
    return min(claim.t[1], hi) - max(claim.t[0], lo) > pad


def _one_stretch_verdict(claim: EdgeOverlap, other: Side) -> Verdict:
    """The verdict on a self-overlap claim whose ranges are one stretch (:func:`_one_stretch`)."""
    return Verdict(other, "nothing", f"not a self-overlap: its ranges t {claim.t[0]:.6g} .. {claim.t[1]:.6g} "
                   f"and u {min(claim.u):.6g} .. {max(claim.u):.6g} share their inside, one stretch of the "
                   "edge, where it only meets itself", 0.0)


def _coincide_around(ca: ExactCurve, cb: ExactCurve, check: PointCheck, tol: float) -> bool:
    """True when the curves coincide (to rounding) a little way on both sides of a tangent point."""
    import mpmath

    with mpmath.workdps(ARBITER_DIGITS):
        mp = ca.mp
        rounding = _rounding(ca, cb, tol)
        delta = mp.mpf(ca.last - ca.first) * mp.mpf("1e-3")
        near = 0
        for sgn in (-1, 1):
            t = mp.mpf(check.t) + sgn * delta
            if t < ca.first or t > ca.last:
                continue
            _, d = _closest_u(ca, cb, t, check.u)
            if d > rounding:
                return False
            near += 1
        return near > 0


def _one_touch(ca: ExactCurve, cb: ExactCurve, check: PointCheck, m: PointCheck | EdgeIntersection,
               tol: float) -> bool:
    """True when the tangent root ``check`` and the point ``m`` are one touch rounded into two roots.

    They are within 1e-3 of ``a``'s range and, at 7 points of ``a`` between them, the curves stay
    within the rounding level of the data (``1e-3 tol`` or ``1e-13`` of their size, as
    :func:`arbitrate_overlap` takes it): a touch whose data were rounded crosses and crosses back
    (roots 1e-7 apart in parameter, 1e-14 between), one contact at any tolerance.
    """
    import mpmath

    mt, mu = ca.near(m.t, check.t), cb.near(m.u, check.u)  # a touch at a closed edge's seam
    if check.kind != "tangent" or not _one_place([check.t, mt], ca):
        return False
    rounding = _rounding(ca, cb, tol)
    with mpmath.workdps(ARBITER_DIGITS):
        t0, t1, u0, u1 = (ca.mp.mpf(x) for x in (check.t, mt, check.u, mu))
        for q in range(1, 8):
            _, d = _closest_u(ca, cb, t0 + (t1 - t0) * q / 8, u0 + (u1 - u0) * q / 8)
            if d > rounding:
                return False
    return True


def _judge_ranges(
    ca: ExactCurve, cb: ExactCurve, rel: EdgeOverlap, occ: EdgeOverlap, tol: float
) -> Disagreement:
    """Both sides report an overlap here, with ends farther apart than tol: check both ranges."""
    rchk = arbitrate_overlap(ca, cb, rel.t, rel.u, tol=tol)
    ochk = arbitrate_overlap(ca, cb, occ.t, occ.u, tol=tol)
    worst = max(rchk.max_distance, ochk.max_distance)

    def rng(o: EdgeOverlap) -> str:
        return f"t [{o.t[0]:.6g}, {o.t[1]:.6g}]"

    if rchk.holds and ochk.holds:
        longer_r = (rel.t[1] - rel.t[0]) >= (occ.t[1] - occ.t[0])
        win, lose = ("relief_cad", "occt") if longer_r else ("occt", "relief_cad")
        claim, counter = (rel, occ) if longer_r else (occ, rel)
        reason = (
            f"both ranges are true overlaps; {lose} reports only part of it ({rng(counter)} of {rng(claim)})"
        )
        return Disagreement(win, claim, (counter,), Verdict(win, "overlap", reason, worst))
    if rchk.holds or ochk.holds:
        good, bad = (rel, occ) if rchk.holds else (occ, rel)
        win = "relief_cad" if rchk.holds else "occt"
        lose = "occt" if rchk.holds else "relief_cad"
        badchk = ochk if rchk.holds else rchk
        reason = (
            f"{lose}'s overlap {rng(bad)} goes beyond the coincidence (distance up to "
            f"{badchk.max_distance:.3g} > tol); {win}'s {rng(good)} holds"
        )
        return Disagreement(lose, bad, (good,), Verdict(win, "overlap", reason, badchk.max_distance))
    reason = (
        f"neither range holds: relief_cad {rng(rel)} (max distance {rchk.max_distance:.3g}), "
        f"OCCT {rng(occ)} (max distance {ochk.max_distance:.3g})"
    )
    return Disagreement("occt", occ, (rel,), Verdict("neither", ochk.status, reason, worst))


def _judge_point(
    check: PointCheck,
    claim: EdgeIntersection,
    mine: list[EdgeResult],
    theirs: list[EdgeResult],
    k: int,
    tol: float,
    side: str,
    other: str,
    ca: ExactCurve,
    cb: ExactCurve,
) -> Verdict:
    if not check.holds:
        return Verdict(
            other,
            "nothing",
            f"{side}'s point is spurious: the closest approach nearby is {check.distance:.3g} > tol"
            if math.isfinite(check.distance)
            else f"{side}'s double point is spurious: refining it collapses onto one parameter",
            check.distance,
            check.exact,
        )
    # duplicate: another result of the same side refines to the same true point
    for j, m in enumerate(mine):
        if j != k and isinstance(m, EdgeIntersection):
            if _pt_dist(m.point, check.point) <= tol and (j < k or _pt_dist(claim.point, check.point) > tol):
                return Verdict(
                    other,
                    "duplicate",
                    f"{side} reports this {check.kind} point twice",
                    check.distance,
                    check.exact,
                )
    for m in theirs:
        if isinstance(m, EdgeIntersection) and _pt_dist(m.point, check.point) <= tol:
            return Verdict(
                other,
                "duplicate",
                f"{side} reports a second, misplaced copy of a {check.kind} point both found "
                f"(it refines onto {other}'s point)",
                check.distance,
                check.exact,
            )
        if isinstance(m, EdgeIntersection) and _one_touch(ca, cb, check, m, tol):
            return Verdict(
                other,
                "duplicate",
                f"{side} reports a touch twice: its two roots, where rounding makes the curves cross "
                f"and cross back, are joined by a stretch within rounding ({other} gave one)",
                check.distance,
                check.exact,
            )
    if check.kind == "tangent" and _coincide_around(ca, cb, check, tol):
        return Verdict(
            "neither",
            "overlap",
            f"the curves coincide around this point: the truth is an overlap that neither side reported "
            f"({side} reported a {claim.kind} point)",
            check.distance,
            check.exact,
        )
    return Verdict(
        side,
        check.kind,
        f"{other} missed a true {check.kind} point (refined distance {check.distance:.3g} <= tol)",
        check.distance,
        check.exact,
    )


def _judge_overlap(
    ca: ExactCurve,
    cb: ExactCurve,
    claim: EdgeOverlap,
    theirs: Sequence[EdgeResult],
    pad: float,
    tol: float,
    side: str,
    other: str,
) -> tuple[tuple[EdgeResult, ...], Verdict]:
    """Judge an overlap claim that ``other`` did not match: ``other``'s evidence and the verdict.

    The evidence is ``other``'s points within the claimed range (``pad`` of slack in ``t``) and, when
    the claim fails, those at its true points: the true point of a range that only grazes a
    tangency (OCCT gives one contact as two abutting overlaps) may lie just outside it.
    """
    counter: tuple[EdgeResult, ...] = tuple(
        x for x in theirs if isinstance(x, EdgeIntersection) and _on_claim(x, claim, ca, cb, pad))
    chk = arbitrate_overlap(ca, cb, claim.t, claim.u, tol=tol)
    if chk.holds:
        return counter, Verdict(
            side,
            "overlap",
            f"the curves {'coincide' if chk.status == 'coincident' else 'stay within tol'} over the "
            f"range (max distance {chk.max_distance:.3g}); {other} "
            f"{'reported only points' if counter else 'missed it'}",
            chk.max_distance,
        )
    truth_pts = chk.points
    reach = max(tol, math.sqrt(tol * ca.size) * 10)

    def near(c: EdgeResult, pts: Sequence[PointCheck]) -> bool:
        return isinstance(c, EdgeIntersection) and any(_pt_dist(c.point, p.point) <= reach for p in pts)

    # the evidence outside the range: points at a true point that none inside it stands for
    # (the next crossing of two circles meeting twice 7e-5 apart is not this one's)
    alone = [p for p in truth_pts if not any(near(c, [p]) for c in counter)]
    counter += tuple(x for x in theirs if all(x is not c for c in counter) and near(x, alone))
    matched = len(counter) == len(truth_pts) and all(near(c, truth_pts) for c in counter)
    return counter, _overlap_failed(chk, counter, matched, other)


def _overlap_failed(chk: OverlapCheck, counter: tuple[EdgeResult, ...], matched: bool, other: str) -> Verdict:
    """The verdict on an overlap claim that does not hold: ``other`` wins when it gave the true points."""
    truth_pts = chk.points
    status = chk.status
    if status == "tangent":  # one contact, stretched by tol: a touch, or a crossing at a small angle
        status = truth_pts[0].kind if len(truth_pts) == 1 else status
        what = f"a {status} point, not an overlap (distance rises to {chk.max_distance:.3g} along the range)"
    elif status == "none":
        what = (
            f"nothing: the curves never come within tol along the range (closest sampled approach "
            f"{chk.min_distance:.3g}, farthest {chk.max_distance:.3g})"
        )
    else:
        what = (
            f"{len(truth_pts)} isolated point(s), not an overlap (max distance {chk.max_distance:.3g} > tol)"
        )
    if matched:
        return Verdict(
            other,
            status if status != "none" else "nothing",
            f"the true answer is {what}",
            chk.max_distance,
        )
    return Verdict(
        "neither",
        status,
        f"the true answer is {what}; {other} reported {len(counter)} point(s)",
        chk.max_distance,
    )


def _relief_intersections() -> Any:
    """Return :func:`relief_cad.cad.intersections` (from the package, else its module)."""
    import importlib

    pkg = importlib.import_module("relief_cad.cad")
    fn = getattr(pkg, "intersections", None)
    if fn is None:
        fn = importlib.import_module("relief_cad.cad.api").intersections
    return fn


def compare(
    a: Any,
    b: Any = None,
    *,
    tol: float | None = None,
    plot: bool = False,
    relief: Sequence[EdgeResult] | None = None,
    refine: bool = True,
) -> Comparison:
    """Compare relief_cad's intersections of ``a`` and ``b`` with OCCT's, with an exact arbiter.

    Parameters
    ----------
    a : TopoDS_Shape, build123d Shape or CadQuery Shape, or a list of them
        First shape (its unique edges take part; degenerated edges are skipped and listed
        in :attr:`Comparison.skipped`).
    b : same types, optional
        Second shape; ``None`` for self-intersections.
    tol : float, optional
        Tolerance for both sides and the arbiter; default the largest ``BRep_Tool``
        tolerance of the edges (OCCT's default, :func:`~relief_cad.cad.occt.default_occt_tolerance`).
    plot : bool
        Make the notebook view (``_repr_html_``) include a picture.
    relief : sequence of results, optional
        relief_cad's answer if already computed (otherwise :func:`relief_cad.cad.intersections`
        is called with ``tol``).
    refine : bool
        Also refine every agreed point, to measure each side's error against the truth
        (:attr:`Match.relief_error`, :attr:`Match.occt_error`).

    Returns
    -------
    Comparison

    Raises
    ------
    ShapeError
        A shape without edges with a curve, or an edge on an unbounded curve (errors of
        either side on usable shapes are recorded in :attr:`Comparison.errors` instead).
    InputTypeError, ToleranceError
        A ``tol`` that is not a number, or not a finite distance > 0.

    Examples
    --------
    >>> from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    >>> from OCP.gp import gp_Pnt
    >>> a = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(2, 2, 0)).Edge()
    >>> b = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 2, 0), gp_Pnt(2, 0, 0)).Edge()
    >>> c = compare(a, b, relief=[])  # as if relief_cad had missed the crossing
    >>> [(d.claimant, d.verdict.winner, d.verdict.truth) for d in c.disagreements]
    [('occt', 'occt', 'crossing')]
    """
    import mpmath

    given_tol = None if tol is None else check_tol(tol)
    edges_a, edges_b = edges_of(a), None if b is None else edges_of(b)
    usable_a, skipped_a = usable_edges(a, "a")
    usable_b, skipped_b = (usable_a, []) if b is None else usable_edges(b, "b")
    skipped = [("a", i, why) for i, why in skipped_a] + [("b", i, why) for i, why in skipped_b]
    if edges_b is None:
        edges_b = edges_a
    tol = default_occt_tolerance(*(e for _, e in usable_a), *(e for _, e in usable_b)) \
        if given_tol is None else float(check_model_tol(given_tol, [e for _, e in usable_a + usable_b]))
    errors: dict[str, str] = {}
    times: dict[str, float] = {}
    t0 = time.perf_counter()
    if relief is None:
        try:
            relief_res = list(_relief_intersections()(a, b, tol=tol))
        except Exception as exc:  # noqa: BLE001 - recorded, the comparison goes on
            errors["relief_cad"] = f"{type(exc).__name__}: {exc}"
            relief_res = []
    else:
        relief_res = list(relief)
    t1 = time.perf_counter()
    try:
        occt_res: list[EdgeResult] = list(occt_intersections(a, b, tol=tol))
    except Exception as exc:  # noqa: BLE001
        errors["occt"] = f"{type(exc).__name__}: {exc}"
        occt_res = []
    t2 = time.perf_counter()
    times["relief_cad"], times["occt"] = t1 - t0, t2 - t1
    with mpmath.workdps(ARBITER_DIGITS):
        exacts_a = _exact_curves(usable_a, len(edges_a))
        exacts_b = exacts_a if b is None else _exact_curves(usable_b, len(edges_b))
        agreed, dis = _match_side(relief_res, occt_res, exacts_a, exacts_b, float(tol), refine)
    times["arbiter"] = time.perf_counter() - t2
    routes = list(dict.fromkeys(r.route for r in occt_res))
    return Comparison(
        float(tol),
        relief_res,
        occt_res,
        agreed,
        dis,
        routes,
        times,
        errors,
        list(edges_a),
        list(edges_b),
        plot,
        skipped,
    )


def _exact_curves(usable: list[tuple[int, Any]], n: int) -> list[Any]:
    """Exact curves at the edges' indices (None at skipped, degenerated edges: no result names them)."""
    out: list[Any] = [None] * n
    for i, edge in usable:
        out[i] = ExactCurve(edge)
    return out

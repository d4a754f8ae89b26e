"""Report pictures drawn on ``matplotlib.figure.Figure`` (the user's pyplot backend is never touched).

Every picture has a legend. A pair's picture has one zoomed inset per disputed spot (copies
closer than the inset's window share one), joined to the spot by ``indicate_inset_zoom``.
"""

from __future__ import annotations

import io
import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Picture", "hist_png", "pair_png", "edge_points"]

MAX_INSETS = 4
"""At most this many zoom insets per pair picture (the caption says how many spots were left out)."""


@dataclass
class Picture:
    """A PNG and what it shows: ``legend`` (a legend is drawn), ``insets`` and ``spots`` (disputed spots)."""

    png: bytes
    legend: bool
    insets: int = 0
    spots: int = 0


def _png(fig: Any) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    return buf.getvalue()


def hist_png(series: dict[str, list[float]], xlabel: str, title: str, *, mark_zero: str = "") -> Picture:
    """A full-width histogram of one or more series (log-scale values), with a legend.

    ``mark_zero``: label of a vertical line at 0 (e.g. "equal speed"), none when empty.
    """
    from matplotlib.figure import Figure

    fig = Figure(figsize=(11.0, 3.0), dpi=80)
    ax = fig.add_subplot()
    data = {k: [x for x in v if math.isfinite(x)] for k, v in series.items()}
    allv = [x for v in data.values() for x in v]
    lo, hi = (min(allv), max(allv)) if allv else (-1.0, 1.0)
    if hi - lo < 1:
        lo, hi = lo - 0.5, hi + 0.5
    bins = [lo + (hi - lo) * i / 40 for i in range(41)]
    for (name, v), color in zip(
        data.items(), ("tab:blue", "tab:red", "tab:green", "tab:purple"), strict=False
    ):
        ax.hist(v, bins=bins, alpha=0.55, label=f"{name} (n={len(v)})", color=color)
    if mark_zero:
        ax.axvline(0.0, color="0.3", ls="--", lw=1, label=mark_zero)
    ax.legend(fontsize=8)
    ax.set_xlabel(xlabel, fontsize=9)
    ax.set_ylabel("count", fontsize=9)
    ax.set_title(title, fontsize=10)
    ax.tick_params(labelsize=8)
    return Picture(_png(fig), ax.get_legend() is not None)


def edge_points(edge: Any, t0: float | None = None, t1: float | None = None, n: int = 200) -> np.ndarray:
    """``(n, 3)`` points of an OCCT edge at evenly spaced parameters of ``[t0, t1]`` (default: all)."""
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    c = BRepAdaptor_Curve(edge)
    a = c.FirstParameter() if t0 is None else t0
    b = c.LastParameter() if t1 is None else t1
    pts = [c.Value(float(t)) for t in np.linspace(a, b, n)]
    return np.array([[p.X(), p.Y(), p.Z()] for p in pts])


class _Projector:
    """Projection onto the best-fit plane of the edges (the XY plane when they lie in it)."""

    def __init__(self, pts: np.ndarray) -> None:
        self.origin = pts.mean(axis=0)
        centred = np.vstack([pts - self.origin, np.zeros((max(0, 3 - len(pts)), 3))])
        _, _, vt = np.linalg.svd(centred, full_matrices=False)
        if abs(vt[2][2]) > 1 - 1e-9:
            self.basis, self.origin = np.eye(3)[:2], np.zeros(3)
        else:
            self.basis = vt[:2]

    def __call__(self, p: Any) -> np.ndarray:
        q: np.ndarray = (np.atleast_2d(np.asarray(p, dtype=float)) - self.origin) @ self.basis.T
        return q


_STYLE = {
    "relief": {"color": "tab:blue", "marker": "o", "lw": 5.0, "label": "relief_cad"},
    "occt": {"color": "tab:red", "marker": "x", "lw": 2.0, "label": "OCCT"},
}


def _draw_answers(ax: Any, proj: _Projector, edges_a: Sequence[Any], rec: dict[str, Any]) -> None:
    for side in ("relief", "occt"):
        st = _STYLE[side]
        for r in rec.get(side, []):
            if r.get("type") == "overlap" and r["index_a"] < len(edges_a):
                q = proj(edge_points(edges_a[r["index_a"]], float(r["t"][0]), float(r["t"][1]), n=60))
                ax.plot(q[:, 0], q[:, 1], color=st["color"], lw=st["lw"], alpha=0.5, zorder=3)
            elif "point" in r:
                q = proj(r["point"])
                face = "none" if st["marker"] == "o" else st["color"]
                ax.plot(q[:, 0], q[:, 1], st["marker"], ms=7, mec=st["color"], mfc=face, zorder=4)


def _legend(ax: Any) -> None:
    from matplotlib.lines import Line2D

    handles = [
        Line2D([], [], color="0.25", lw=1, label="edges of A"),
        Line2D([], [], color="0.6", lw=1, label="edges of B"),
        Line2D([], [], ls="", marker="o", mfc="none", mec="tab:blue", label="relief_cad point"),
        Line2D([], [], ls="", marker="x", color="tab:red", label="OCCT point"),
        Line2D([], [], color="tab:blue", lw=5, alpha=0.5, label="relief_cad overlap"),
        Line2D([], [], color="tab:red", lw=2, alpha=0.5, label="OCCT overlap"),
        Line2D([], [], ls="", marker="o", ms=14, mfc="none", mec="orange", mew=2, label="disputed"),
    ]
    ax.legend(
        handles=handles, loc="upper left", bbox_to_anchor=(0.0, -0.06), ncol=4, fontsize=7, frameon=False
    )


def _spots(points: list[np.ndarray], window: float) -> list[np.ndarray]:
    """Disputed points merged when closer than ``window`` (repeated copies share one inset)."""
    spots: list[np.ndarray] = []
    for p in points:
        if all(float(np.linalg.norm(p - s)) > window for s in spots):
            spots.append(p)
    return spots


def pair_png(
    edges_a: Sequence[Any], edges_b: Sequence[Any], rec: dict[str, Any], disputed: list[Any], title: str
) -> Picture:
    """A pair with both answers, a legend, and one zoom inset per disputed spot.

    Parameters
    ----------
    edges_a, edges_b : sequences of ``TopoDS_Edge``
        The pair's unique edges (``edges_b`` empty for a self-intersection item).
    rec : dict
        The compare record (``relief``/``occt`` answers as dicts).
    disputed : list
        3D points (model units) of the disputed claims.
    title : str
        Figure title.
    """
    from matplotlib.figure import Figure

    polys = [edge_points(e) for e in edges_a] + [edge_points(e) for e in edges_b]
    proj = _Projector(np.vstack(polys))
    fig = Figure(figsize=(11.0, 4.2), dpi=80)
    ax = fig.add_axes((0.04, 0.12, 0.4, 0.8))
    for k, poly in enumerate(polys):
        q = proj(poly)
        ax.plot(q[:, 0], q[:, 1], color="0.25" if k < len(edges_a) else "0.6", lw=1)
    _draw_answers(ax, proj, edges_a, rec)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_title(title, fontsize=9)
    ax.tick_params(labelsize=7)
    _legend(ax)
    lo, hi = ax.get_xlim(), ax.get_ylim()
    diag = math.hypot(lo[1] - lo[0], hi[1] - hi[0]) or 1.0
    window = max(20.0 * float(rec.get("tol") or 1e-7), 2e-3 * diag)
    flat = [proj(p)[0] for p in disputed]
    spots = _spots(flat, window)
    for k, s in enumerate(spots[:MAX_INSETS]):
        _inset(ax, proj, edges_a, rec, [*edges_a, *edges_b], s, window, k, len(edges_a))
    return Picture(_png(fig), ax.get_legend() is not None, min(len(spots), MAX_INSETS), len(spots))


def _near(edge: Any, proj: _Projector, spot: np.ndarray, window: float) -> np.ndarray | None:
    """Projected points of an edge, resampled finely where it passes within the inset's window."""
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    c = BRepAdaptor_Curve(edge)
    ts = np.linspace(c.FirstParameter(), c.LastParameter(), 801)
    q = proj(edge_points(edge, n=801))
    close = np.nonzero(np.max(np.abs(q - spot), axis=1) <= 3 * window)[0]
    if not len(close):
        return None
    lo, hi = ts[max(close[0] - 1, 0)], ts[min(close[-1] + 1, len(ts) - 1)]
    return proj(edge_points(edge, float(lo), float(hi), n=400))


def _inset(
    ax: Any,
    proj: _Projector,
    edges_a: Sequence[Any],
    rec: dict[str, Any],
    edges: list[Any],
    spot: np.ndarray,
    window: float,
    k: int,
    n_a: int,
) -> None:
    ins = ax.inset_axes((1.08 + 0.58 * (k % 2), 0.52 - 0.56 * (k // 2), 0.5, 0.48))
    for j, edge in enumerate(edges):
        q = _near(edge, proj, spot, window)
        if q is not None:
            ins.plot(q[:, 0], q[:, 1], color="0.25" if j < n_a else "0.6", lw=1)
    _draw_answers(ins, proj, edges_a, rec)
    ins.plot([spot[0]], [spot[1]], "o", ms=16, mfc="none", mec="orange", mew=2)
    ins.set_xlim(spot[0] - window, spot[0] + window)
    ins.set_ylim(spot[1] - window, spot[1] + window)
    ins.set_title(f"zoom {k + 1}: ±{window:.2g} units", fontsize=7)
    ins.tick_params(labelsize=6)
    ax.indicate_inset_zoom(ins, edgecolor="orange")
    ax.plot([spot[0]], [spot[1]], "o", ms=14, mfc="none", mec="orange", mew=2, zorder=5)

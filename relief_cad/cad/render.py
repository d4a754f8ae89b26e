"""Rendering of comparisons: text rows, HTML, and a picture of the edges and both answers.

Pictures are drawn on a :class:`matplotlib.figure.Figure` with the Agg canvas: this module
never calls ``matplotlib.use`` nor pyplot, so it leaves the caller's backend alone.

>>> from relief_cad.cad.results import EdgeIntersection
>>> where(EdgeIntersection(0, 1, None, None, 0.5, 0.25, (0.0, 0.0, 0.0), "crossing", 0.0))
'0/1: t=0.5 u=0.25'
"""

from __future__ import annotations

import io
from collections.abc import Sequence
from typing import Any

import numpy as np

from .exact import ExactCurve
from .results import EdgeIntersection, EdgeResult

__all__ = ["plot_pair_png", "where"]


def where(r: EdgeResult) -> str:
    """Return ``"index_a/index_b: t=... u=..."`` of a result (ranges for an overlap).

    >>> from relief_cad.cad.results import EdgeOverlap
    >>> where(EdgeOverlap(2, 3, None, None, (0.0, 1.0), (1.0, 2.0), None))
    '2/3: t=[0,1] u=[1,2]'
    """
    if isinstance(r, EdgeIntersection):
        return f"{r.index_a}/{r.index_b}: t={r.t:.10g} u={r.u:.10g}"
    return f"{r.index_a}/{r.index_b}: t=[{r.t[0]:.6g},{r.t[1]:.6g}] u=[{r.u[0]:.6g},{r.u[1]:.6g}]"


def _edge_range_polyline(edge: Any, t0: float, t1: float, n: int = 60) -> np.ndarray:
    """Points of the edge on ``[t0, t1]`` from its exact data (24 digits).

    OCCT's own evaluation of a high-degree Bézier curve goes through a power-basis cache
    and can be visibly wrong (spikes) on ill-conditioned curves; the exact data is not.
    """
    import mpmath

    with mpmath.workdps(24):
        c = ExactCurve(edge)
        pts = [[float(x) for x in c.value(mpmath.mpf(float(t)))] for t in np.linspace(t0, t1, n)]
    out: np.ndarray = np.array(pts)
    return out


def _edge_polyline(edge: Any, n: int = 160) -> np.ndarray:
    from OCP.BRep import BRep_Tool

    first, last = BRep_Tool.Range_s(getattr(edge, "wrapped", edge))
    return _edge_range_polyline(edge, first, last, n)


def plot_pair_png(
    edges_a: Sequence[Any],
    edges_b: Sequence[Any],
    relief: Sequence[EdgeResult],
    occt: Sequence[EdgeResult],
    highlight: Sequence[EdgeResult] = (),
    *,
    size: tuple[float, float] = (5.0, 4.0),
    title: str = "",
) -> bytes:
    """Draw edges (projected on their best-fit plane) and both answers as PNG bytes.

    Parameters
    ----------
    edges_a, edges_b : sequences of edges
        The unique edges of both shapes.
    relief, occt : sequences of results
        relief_cad's answer (blue circles / thick blue) and OCCT's (red crosses / thin red).
    highlight : sequence of results
        Disagreements, ringed in orange.
    size : tuple of float
        Figure size in inches.
    title : str
        Figure title.

    Returns
    -------
    bytes
        The PNG file's bytes; empty when matplotlib is unavailable.

    Examples
    --------
    >>> import build123d as bd
    >>> plot_pair_png([bd.Line((0, 0), (1, 1))], [bd.Line((0, 1), (1, 0))], [], [])[1:4]
    b'PNG'
    """
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:  # pragma: no cover - workbench extra not installed
        return b""
    polys = [_edge_polyline(e) for e in edges_a] + [_edge_polyline(e) for e in edges_b]
    pts = np.vstack(polys) if polys else np.zeros((1, 3))
    origin = pts.mean(axis=0)
    centred = np.vstack([pts - origin, np.zeros((max(0, 3 - pts.shape[0]), 3))])
    _, _, vt = np.linalg.svd(centred, full_matrices=False)  # thin: the full SVD is N x N
    if abs(vt[2][2]) > 1 - 1e-9:
        basis = np.array([[1.0, 0, 0], [0, 1.0, 0]])
        origin = np.zeros(3)
    else:
        basis = vt[:2]

    def proj(p: np.ndarray) -> np.ndarray:
        q: np.ndarray = (np.atleast_2d(p) - origin) @ basis.T
        return q

    fig = Figure(figsize=size, dpi=80)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    for k, poly in enumerate(polys):
        q = proj(poly)
        ax.plot(q[:, 0], q[:, 1], color="0.25" if k < len(edges_a) else "0.55", lw=1)
    for res, color, marker, lw in ((relief, "tab:blue", "o", 5), (occt, "tab:red", "x", 2)):
        for r in res:
            if isinstance(r, EdgeIntersection):
                q = proj(np.array(r.point))
                ax.plot(
                    q[:, 0],
                    q[:, 1],
                    marker=marker,
                    color=color,
                    ms=8 if marker == "o" else 9,
                    mfc="none",
                    mew=1.5,
                )
            else:
                edge = edges_a[r.index_a] if r.index_a < len(edges_a) else None
                if edge is not None:
                    q = proj(_edge_range_polyline(edge, r.t[0], r.t[1]))
                    ax.plot(q[:, 0], q[:, 1], color=color, lw=lw, alpha=0.6)
    for r in highlight:
        if isinstance(r, EdgeIntersection):
            q = proj(np.array(r.point))
        elif r.index_a < len(edges_a):
            q = proj(_edge_range_polyline(edges_a[r.index_a], r.t[0], r.t[1], 3))[1:2]
        else:
            continue
        ax.plot(q[:, 0], q[:, 1], marker="o", ms=18, mfc="none", color="orange", mew=2)
    span = np.ptp(proj(pts), axis=0)
    if span.min() > 0 and span.max() / span.min() < 8:
        ax.set_aspect("equal", adjustable="datalim")
    ax.set_title(title or "relief_cad (blue o) vs OCCT (red x); disagreements ringed", fontsize=8)
    ax.tick_params(labelsize=7)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", bbox_inches="tight")
    return buf.getvalue()

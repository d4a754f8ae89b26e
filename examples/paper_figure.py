"""The figures of Hlúšek's "Bezier curves intersection using relief perspective", redrawn.

Figure 1: the relief perspective ``φ_k`` (k = 2) in a side view: centre O, image plane
``z = 1``, vanishing plane ``z = 1 + k``, neutral plane ``z = -k``, the viewpoint
``S = (0, 0, -k)``; two points and their reliefs (on the line through O), and the
orthographic projection of each relief onto the image plane, which is the central
projection of the point from S.

Figure 2: the intersection scheme. Two space rational curves of the paper's form
(``Q = preimage_of_lift(P, k)`` of two planar rational curves P), their reliefs
``φ(Q)`` (the lifts, polynomial curves), and their central projections onto the image
plane. The projections cross twice (the candidates); only where the reliefs agree is the
candidate a real intersection, ``R = φ⁻¹(R^r)``: the other candidate is two different
points of one ray through O.

Run::

    python examples/paper_figure.py [OUT_DIR]        # default ./out_paper/

Writes ``paper_figure1.png`` and ``paper_figure2.png`` and prints the numbers drawn.
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path
from typing import Any

import numpy as np

from relief_cad import (
    RationalBezier,
    ReliefPerspective,
    intersect,
    intersect_space,
    preimage_of_lift,
    relief_scheme,
)

K = 2.0
# The lifts (reliefs) of the two curves: space polynomial curves whose z are the weights.
LIFT_A = np.array([(-2.0, -1.0, 1.0), (-0.5, 2.5, 2.0), (1.0, -1.5, 1.5), (2.5, 1.0, 1.2)])
_MID_A = 0.125 * LIFT_A[0] + 0.375 * LIFT_A[1] + 0.375 * LIFT_A[2] + 0.125 * LIFT_A[3]
_ENDS_B = np.array([(-1.4, -0.8, 1.3), (2.2, 0.0, 2.2)])
# Middle control point chosen so that lift B passes through lift A's point at t = 1/2 at u = 1/2.
LIFT_B = np.array([_ENDS_B[0], 2.0 * _MID_A - 0.5 * (_ENDS_B[0] + _ENDS_B[1]), _ENDS_B[1]])
# Figure 1's points (in the plane y = 0).
POINTS_FIG1 = np.array([(2.0, 0.0, 5.0), (-1.5, 0.0, 0.4)])


def planar_curves() -> tuple[RationalBezier, RationalBezier]:
    """The planar rational curves P (homogeneous rows = the lifts' control points)."""
    return RationalBezier.from_homogeneous(LIFT_A), RationalBezier.from_homogeneous(LIFT_B)


def space_curves() -> tuple[RationalBezier, RationalBezier]:
    """The paper's space curves Q = preimage_of_lift(P, k), whose reliefs are the lifts."""
    pa, pb = planar_curves()
    return preimage_of_lift(pa, K), preimage_of_lift(pb, K)


def figure1(path: Path) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """Draw the relief perspective in the plane y = 0; return (X, φ(X), projection from S)."""
    import matplotlib.pyplot as plt

    phi = ReliefPerspective(K)
    s = phi.viewpoint
    rows = []
    fig, ax = plt.subplots(figsize=(6.4, 5.6), dpi=100)
    xs = (-3.2, 3.2)
    for z, name, style, color in (
        (phi.image_plane_z, "image plane σ: z = 1", "-", "tab:blue"),
        (phi.vanishing_plane_z, f"vanishing plane z = 1 + k = {phi.vanishing_plane_z:g}", "--", "tab:orange"),
        (phi.neutral_plane_z, f"neutral plane z = -k = {phi.neutral_plane_z:g}", ":", "tab:gray"),
    ):
        ax.plot(xs, (z, z), style, color=color, lw=1.5)
        ax.text(xs[1], z + 0.08, name, ha="right", va="bottom", fontsize=8, color=color)
    ax.axhspan(phi.image_plane_z, phi.vanishing_plane_z, color="tab:orange", alpha=0.07)
    ax.text(-3.1, 2.0, "reliefs of all points\nwith z > 1", fontsize=7, color="tab:orange", va="center")
    ax.plot([0], [0], "ko")
    ax.annotate("O", (0, 0), xytext=(-14, -4), textcoords="offset points")
    ax.plot([s[0]], [s[2]], "ks")
    ax.annotate("S = (0, 0, -k)", (s[0], s[2]), xytext=(-8, 6), textcoords="offset points", fontsize=8,
                ha="right")
    for i, x in enumerate(POINTS_FIG1):
        xr = phi.apply(x)
        d = x - s
        foot = s + d * (phi.image_plane_z - s[2]) / d[2]  # central projection from S onto σ
        rows.append((x, xr, foot))
        far = x * 1.15 if x[2] > 1 else xr * 1.15
        ax.plot([0, far[0]], [0, far[2]], color="0.6", lw=0.8)  # the line through O, fixed by φ
        ax.plot([s[0], x[0]], [s[2], x[2]], color="tab:green", lw=0.8, ls="-.")  # ray from S
        ax.plot([xr[0], foot[0]], [xr[2], foot[2]], color="tab:red", lw=0.8, ls=":")  # orthographic drop
        ax.plot([x[0]], [x[2]], "o", color="tab:purple")
        ax.plot([xr[0]], [xr[2]], "o", color="tab:red")
        ax.plot([foot[0]], [foot[2]], "x", color="k")
        sub = "₁₂"[i]
        ax.annotate(f"X{sub}", (x[0], x[2]), xytext=(6, 2), textcoords="offset points", color="tab:purple")
        ax.annotate(f"φ(X{sub})", (xr[0], xr[2]), xytext=(6, -10), textcoords="offset points",
                    color="tab:red", fontsize=9)
    ax.set_xlim(-3.3, 3.3)
    ax.set_ylim(-2.6, 5.6)
    ax.set_xlabel("x")
    ax.set_ylabel("z")
    ax.set_aspect("equal")
    ax.set_title("Relief perspective φ_k, k = 2 (side view, y = 0)\n"
                 "φ(x, y, z) = (1+k)(x, y, z)/(z+k); the relief seen orthographically\n"
                 "= the point seen from S", fontsize=9)
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)
    return rows


def _plane(ax: Any, z: float, lo: np.ndarray, hi: np.ndarray, color: str, label: str) -> None:
    xx, yy = np.meshgrid([lo[0], hi[0]], [lo[1], hi[1]])
    ax.plot_surface(xx, yy, np.full_like(xx, z), color=color, alpha=0.12, linewidth=0, shade=False)
    ax.text(hi[0], lo[1], z, label, color=color, fontsize=7)


def figure2(path: Path) -> dict[str, Any]:
    """Draw the intersection scheme in 3D; return the candidates and the real intersections."""
    import matplotlib.pyplot as plt

    qa, qb = space_curves()
    scheme = relief_scheme(qa, qb, k=K)
    if scheme.frame.name != "model":  # the paper's curves lie in front of O: the model's own frame
        raise RuntimeError(f"expected the model's own frame, got {scheme.frame.name!r}")
    phi = scheme.perspective
    ar, br = scheme.a_relief, scheme.b_relief
    ai, bi = scheme.a_image, scheme.b_image
    candidates = intersect(ai, bi)  # Bézier clipping in the image plane: R^s
    real = intersect_space(qa, qb)  # the whole scheme, in space
    tol = 1e-9
    verdicts = []
    for c in candidates:
        gap = float(np.linalg.norm(ar(c.t) - br(c.u)))  # depth check on the reliefs
        verdicts.append((c, gap, gap <= tol))

    ts = np.linspace(0.0, 1.0, 300)
    fig = plt.figure(figsize=(8.0, 6.4), dpi=100)
    ax = fig.add_subplot(projection="3d")
    pts = np.vstack([qa(ts), qb(ts), ar(ts), br(ts)])
    lo, hi = pts.min(axis=0) - 0.3, pts.max(axis=0) + 0.3
    _plane(ax, phi.image_plane_z, lo, hi, "tab:blue", "image plane z = 1")
    _plane(ax, phi.vanishing_plane_z, lo, hi, "tab:orange", f"vanishing plane z = {phi.vanishing_plane_z:g}")
    for curve, relief, image, color, name in ((qa, ar, ai, "tab:blue", "P"), (qb, br, bi, "tab:green", "Q")):
        q, r, s = curve(ts), relief(ts), image(ts)
        ax.plot(q[:, 0], q[:, 1], q[:, 2], color=color, lw=2.2, label=f"space curve {name}")
        ax.plot(r[:, 0], r[:, 1], r[:, 2], color=color, lw=1.4, ls="--", label=f"relief {name}ʳ = φ({name})")
        ax.plot(s[:, 0], s[:, 1], np.ones_like(ts), color=color, lw=1.0, ls=":",
                label=f"projection {name}ˢ = ψ({name}ʳ)")
    ax.scatter([0], [0], [0], color="k", s=20)
    ax.text(0, 0, -0.25, "O", fontsize=9)
    for c, _gap, ok in verdicts:
        s = np.array([*ai(c.t), 1.0])
        ends = [ar(c.t), br(c.u), qa(c.t), qb(c.u)]
        far = max(ends, key=lambda p: float(np.linalg.norm(p)))
        ax.plot([0, far[0]], [0, far[1]], [0, far[2]], color="0.45", lw=0.7)  # ray through O
        ax.scatter(*s, marker="x", color="k", s=40)
        if ok:
            rr = ar(c.t)
            r = phi.inverse(rr)
            ax.scatter(*rr, marker="*", color="tab:red", s=120)
            ax.scatter(*r, marker="o", color="tab:red", s=60)
            ax.text(*r, "  R = φ⁻¹(Rʳ)", color="tab:red", fontsize=8)
            ax.text(*rr, "  Rʳ", color="tab:red", fontsize=8)
        else:
            for p in (ar(c.t), br(c.u)):
                ax.scatter(*p, marker="o", facecolors="none", edgecolors="0.3", s=40)
            ax.text(*s, "  candidate: reliefs differ", color="0.25", fontsize=7)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    ax.view_init(elev=14, azim=-62)
    ax.legend(loc="upper left", fontsize=7)
    ax.set_title("Intersection by relief perspective (k = 2): candidates Rˢ (x) on the image plane,\n"
                 "real only where the reliefs agree (★ Rʳ); R = φ⁻¹(Rʳ) on the space curves", fontsize=9)
    fig.savefig(path, bbox_inches="tight")
    plt.close(fig)
    return {"candidates": verdicts, "real": list(real)}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="Redraw the paper's figures 1 and 2.")
    parser.add_argument("out", nargs="?", default="out_paper", help="output folder")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    import matplotlib

    matplotlib.use("Agg")

    rows = figure1(out / "paper_figure1.png")
    print(f"Figure 1: relief perspective k = {K:g}")
    for i, (x, xr, foot) in enumerate(rows):
        print(f"  X{i + 1} = {tuple(round(float(c), 9) for c in x)}  phi(X) = "
              f"{tuple(round(float(c), 9) for c in xr)}  seen from S on z=1: "
              f"{tuple(round(float(c), 9) for c in foot)}")

    res = figure2(out / "paper_figure2.png")
    print(f"Figure 2: {len(res['candidates'])} candidate(s) in the image plane, {len(res['real'])} real")
    print(f"{'':>11}{'t':>14}{'u':>14}{'image x':>12}{'image y':>12}{'relief gap':>12}  verdict")
    for c, gap, ok in res["candidates"]:
        x, y = (float(v) for v in c.point)
        print(f"  candidate{c.t:>14.10f}{c.u:>14.10f}{x:>12.8f}{y:>12.8f}{gap:>12.3e}  "
              f"{'real' if ok else 'not real (depths differ)'}")
    for r in res["real"]:
        p = tuple(float(v) for v in r.point)
        print(f"  real R at t={r.t:.12f} u={r.u:.12f}: ({p[0]:.12f}, {p[1]:.12f}, {p[2]:.12f}) {r.kind}")
    print(f"wrote {out / 'paper_figure1.png'} and {out / 'paper_figure2.png'}")
    return 0


if __name__ == "__main__":
    os.environ.setdefault("MPLBACKEND", "Agg")
    raise SystemExit(main())

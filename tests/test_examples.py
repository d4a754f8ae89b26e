"""Run every script in ``examples/`` headless into a temporary folder and check its outputs.

The numbers the scripts print are checked against truth computed here independently of
relief_cad: closed forms (line/circle), sign changes of an implicit form sampled along the
other curve with OCCT's own evaluator and refined by bisection, and OCCT evaluation of the
edges at the printed parameters.
"""

from __future__ import annotations

import importlib.util
import math
import os
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import numpy as np
import pytest

from tests._env import needs_cadquery

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
SCRIPTS = sorted(p.name for p in EXAMPLES.glob("*.py"))
CHECKED = {"arrange_text.py", "build123d_sketch.py", "paper_figure.py", "step_intersections.py"}


def _run(script: str, *args: str, timeout: float = 240.0) -> str:
    env = dict(os.environ, MPLBACKEND="Agg")
    proc = subprocess.run(
        [sys.executable, str(EXAMPLES / script), *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=timeout,
    )
    assert proc.returncode == 0, f"{script} failed ({proc.returncode}):\n{proc.stdout}\n{proc.stderr}"
    return proc.stdout


def _load(script: str) -> ModuleType:
    spec = importlib.util.spec_from_file_location(f"example_{Path(script).stem}", EXAMPLES / script)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _check_png(path: Path, min_w: int = 300, min_h: int = 200, max_bytes: int = 600_000) -> None:
    import matplotlib.image as mpimg

    assert path.is_file() and 0 < path.stat().st_size <= max_bytes, path
    img = mpimg.imread(path)
    h, w = img.shape[:2]
    assert w >= min_w and h >= min_h, (path, img.shape)
    assert float(np.ptp(img[..., :3])) > 0.1, f"{path} is blank"


def _value(edge, t: float) -> np.ndarray:
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    p = BRepAdaptor_Curve(getattr(edge, "wrapped", edge)).Value(float(t))
    return np.array([p.X(), p.Y(), p.Z()])


def _roots_along(edge, f, n: int = 1500) -> list[np.ndarray]:
    """Points of ``edge`` where the implicit function ``f`` changes sign (OCCT evaluation, bisection)."""
    from OCP.BRepAdaptor import BRepAdaptor_Curve

    c = BRepAdaptor_Curve(edge.wrapped)
    t0, t1 = c.FirstParameter(), c.LastParameter()
    ts = np.linspace(t0, t1, n)
    vals = [f(_value(edge, t)) for t in ts]
    out = []
    for i in range(n - 1):
        if vals[i] == 0.0 or vals[i] * vals[i + 1] < 0.0:
            lo, hi, flo = ts[i], ts[i + 1], vals[i]
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                fm = f(_value(edge, mid))
                if (fm < 0.0) == (flo < 0.0):
                    lo, flo = mid, fm
                else:
                    hi = mid
            out.append(_value(edge, 0.5 * (lo + hi)))
    return out


# --------------------------------------------------------------------------- every script runs


def test_every_example_is_checked() -> None:
    assert set(SCRIPTS) == CHECKED, "a new example needs its own output checks here"
    assert (EXAMPLES / "cadquery_notebook.ipynb").is_file()
    assert (EXAMPLES / "README.md").is_file()


# --------------------------------------------------------------------------- build123d_sketch.py

_ROW = re.compile(
    r"^\s*(\d+)\s+(\w+)\s+(\w+)\s+(crossing|tangent)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", re.MULTILINE
)


def _segment_area(chord: float, sagitta: float) -> float:
    r = (chord**2 / 4 + sagitta**2) / (2 * sagitta)
    return r**2 * math.acos((r - sagitta) / r) - (r - sagitta) * math.sqrt(2 * r * sagitta - sagitta**2)


def test_build123d_sketch(tmp_path: Path) -> None:
    import build123d as bd

    out = tmp_path / "out"
    stdout = _run("build123d_sketch.py", str(out))
    mod = _load("build123d_sketch.py")
    curves = mod.construction_curves()
    names = list(curves)
    rows = _ROW.findall(stdout)
    assert len(rows) == int(re.search(r"(\d+) crossing\(s\)", stdout).group(1))

    # each printed point lies on both edges at the printed parameters (OCCT evaluation)
    found: dict[tuple[str, str], list[np.ndarray]] = {}
    for _i, na, nb, kind, x, y, t, u in rows:
        p = np.array([float(x), float(y), 0.0])
        assert kind == "crossing"
        assert np.linalg.norm(_value(curves[na], float(t)) - p) < 1e-5
        assert np.linalg.norm(_value(curves[nb], float(u)) - p) < 1e-5
        found.setdefault((na, nb), []).append(p)
    assert set(found) <= {(a, b) for i, a in enumerate(names) for b in names[i + 1:]}

    # independent truth: line as a signed distance, the arc's circle as |p - c| - r
    (lx0, ly0), (lx1, ly1) = (-45.0, 8.0), (45.0, -12.0)
    normal = np.array([-(ly1 - ly0), lx1 - lx0]) / math.hypot(lx1 - lx0, ly1 - ly0)

    def on_line(p: np.ndarray) -> float:
        return float((p[:2] - (lx0, ly0)) @ normal)

    centre, radius = np.array([0.0, -5.0]), 26.0
    a0, a1 = math.radians(-25.0), math.radians(205.0)

    def in_arc(p: np.ndarray) -> bool:
        ang = math.atan2(p[1] - centre[1], p[0] - centre[0])
        ang = ang if ang >= a0 else ang + 2 * math.pi
        return a0 - 1e-9 <= ang <= a1 + 1e-9

    def on_circle(p: np.ndarray) -> float:
        return float(np.linalg.norm(p[:2] - centre) - radius)

    truth = {
        ("spline", "line"): _roots_along(curves["spline"], on_line),
        ("spline", "arc"): [p for p in _roots_along(curves["spline"], on_circle) if in_arc(p)],
    }
    # line / circle in closed form: |l0 + s d - c|^2 = r^2
    d = np.array([lx1 - lx0, ly1 - ly0])
    f = np.array([lx0, ly0]) - centre
    qa, qb, qc = d @ d, 2 * f @ d, f @ f - radius**2
    disc = math.sqrt(qb * qb - 4 * qa * qc)
    line_arc = [np.array([*(np.array([lx0, ly0]) + s * d), 0.0]) for s in ((-qb - disc) / (2 * qa), (-qb + disc) / (2 * qa))]
    truth[("arc", "line")] = [p for p in line_arc if in_arc(p)]
    assert sum(len(v) for v in truth.values()) == 6
    for pair, expected in truth.items():
        got = found.get(pair, [])
        assert len(got) == len(expected), (pair, got, expected)
        for p in expected:
            assert min(np.linalg.norm(p - q) for q in got) < 2e-6, (pair, p, got)

    # the STEP re-imports as one solid with one cylindrical hole per point; volume in closed form
    step = out / "plate.step"
    assert step.is_file() and step.stat().st_size > 1000
    part = bd.import_step(str(step))
    assert len(part.solids()) == 1
    from OCP.BRepAdaptor import BRepAdaptor_Surface

    holes = []  # (axis location x, y) of the cylindrical faces of the hole radius
    for face in part.faces():
        if face.geom_type == bd.GeomType.CYLINDER:
            cyl = BRepAdaptor_Surface(face.wrapped).Cylinder()
            if abs(cyl.Radius() - mod.HOLE_DIAMETER / 2) < 1e-9:
                holes.append(np.array(cyl.Location().Coord()[:2]))
    assert len(holes) == len(rows)
    for p in (np.array([float(r[4]), float(r[5])]) for r in rows):
        assert min(np.linalg.norm(h - p) for h in holes) < 1e-5
    area = 100.0 * 50.0 + _segment_area(100.0, 18.0)
    volume = (area - len(rows) * math.pi * (mod.HOLE_DIAMETER / 2) ** 2) * mod.PLATE_THICKNESS
    assert part.volume == pytest.approx(volume, rel=1e-6)

    _check_png(out / "sketch_intersections.png")


# --------------------------------------------------------------------------- paper_figure.py

_FIG1 = re.compile(r"X\d = \(([^)]*)\)\s+phi\(X\) = \(([^)]*)\)\s+seen from S on z=1: \(([^)]*)\)")
_CAND = re.compile(r"candidate\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(real|not real)")
_REAL = re.compile(r"real R at t=(\S+) u=(\S+): \((\S+), (\S+), (\S+)\) (\w+)")


def _floats(s: str) -> np.ndarray:
    return np.array([float(v) for v in s.split(",")])


def test_paper_figure(tmp_path: Path) -> None:
    import sympy as sp

    out = tmp_path / "paper"
    stdout = _run("paper_figure.py", str(out))
    mod = _load("paper_figure.py")
    k = 2.0

    # Figure 1: phi(X) = (1+k) X / (z+k); the central projection from S = (0,0,-k) onto z=1
    # lands under the relief (the paper's property), both by closed form.
    fig1 = _FIG1.findall(stdout)
    assert len(fig1) == 2
    for xs, xrs, foots in fig1:
        x, xr, foot = _floats(xs), _floats(xrs), _floats(foots)
        assert np.allclose(xr, (1 + k) * x / (x[2] + k), atol=1e-9)
        s = np.array([0.0, 0.0, -k])
        assert np.allclose(foot, s + (x - s) * (1 + k) / (x[2] + k), atol=1e-9)
        assert np.allclose(foot[:2], xr[:2], atol=1e-9)

    # Figure 2: the candidates are where the lifts L_a(t), L_b(u) lie on one ray through O
    # (cross product 0); solved exactly with sympy from the control points.
    t, u = sp.symbols("t u")

    def bern(points: np.ndarray, var: sp.Symbol) -> list[sp.Expr]:
        n = len(points) - 1
        return [sp.expand(sum(sp.binomial(n, i) * var**i * (1 - var) ** (n - i) * sp.Rational(float(points[i, c]))
                              for i in range(n + 1))) for c in range(3)]

    la, lb = bern(mod.LIFT_A, t), bern(mod.LIFT_B, u)
    e1 = sp.expand(la[0] * lb[2] - la[2] * lb[0])
    e2 = sp.expand(la[1] * lb[2] - la[2] * lb[1])
    res = sp.Poly(sp.resultant(e1, e2, u), t)
    truth = []
    for (lo, hi), _mult in res.intervals(eps=sp.Rational(1, 10**25)):  # exact isolation of real roots
        tv = (lo + hi) / 2
        if not (-sp.Rational(1, 10**12) <= tv <= 1 + sp.Rational(1, 10**12)):
            continue
        for (ulo, uhi), _m in sp.Poly(e1.subs(t, tv), u).intervals(eps=sp.Rational(1, 10**20)):
            uv = (ulo + uhi) / 2
            if not (-sp.Rational(1, 10**12) <= uv <= 1 + sp.Rational(1, 10**12)):
                continue
            pa = np.array([float(c.subs(t, tv)) for c in la])
            pb = np.array([float(c.subs(u, uv)) for c in lb])
            if abs(float(e2.subs({t: tv, u: uv}))) < 1e-12 and pa @ pb > 0:
                truth.append((float(tv), float(uv), pa, pb))
    cands = _CAND.findall(stdout)
    assert len(cands) == len(truth) == 2
    for tv, uv, pa, pb in truth:
        row = min(cands, key=lambda r: abs(float(r[0]) - tv) + abs(float(r[1]) - uv))
        assert abs(float(row[0]) - tv) < 1e-9 and abs(float(row[1]) - uv) < 1e-9
        assert np.allclose([float(row[2]), float(row[3])], pa[:2] / pa[2], atol=1e-7)
        gap = float(np.linalg.norm(pa - pb))
        assert float(row[4]) == pytest.approx(gap, rel=1e-3, abs=1e-12)
        assert (row[5] == "real") == (gap < 1e-9)

    # the real intersection: t = u = 1/2 by construction, R = phi^-1(L_a(1/2)) exactly
    real = _REAL.findall(stdout)
    assert len(real) == 1
    m = [sp.Rational(1, 8) * (sp.Rational(float(mod.LIFT_A[0, c])) + 3 * sp.Rational(float(mod.LIFT_A[1, c]))
         + 3 * sp.Rational(float(mod.LIFT_A[2, c])) + sp.Rational(float(mod.LIFT_A[3, c]))) for c in range(3)]
    r_exact = [float(sp.Rational(2) * c / (3 - m[2])) for c in m]
    assert float(real[0][0]) == pytest.approx(0.5, abs=1e-10)
    assert float(real[0][1]) == pytest.approx(0.5, abs=1e-10)
    assert np.allclose([float(v) for v in real[0][2:5]], r_exact, atol=1e-10)
    assert real[0][5] == "crossing"

    _check_png(out / "paper_figure1.png")
    _check_png(out / "paper_figure2.png", min_w=500, min_h=400)


# --------------------------------------------------------------------------- step_intersections.py

_STEP_ROW = re.compile(
    r"^\s*(\d+) (\d+):\w+\s+(\d+):\w+\s+(crossing|tangent)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s+(\S+)\s*$", re.MULTILINE
)


def _occt_meeting_points(edges_a: list, edges_b: list, tol: float = 1e-6) -> list[np.ndarray]:
    """Points where edges meet, by OCCT's BRepExtrema_DistShapeShape on every edge pair (independent of relief_cad)."""
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib
    from OCP.BRepExtrema import BRepExtrema_DistShapeShape

    def box(e):
        b = Bnd_Box()
        BRepBndLib.Add_s(e, b)
        return b

    boxes_b = [box(e) for e in edges_b]
    points: list[np.ndarray] = []
    for ea in edges_a:
        ba = box(ea)
        for eb, bb in zip(edges_b, boxes_b):
            if ba.IsOut(bb):
                continue
            ext = BRepExtrema_DistShapeShape(ea, eb)
            if not ext.IsDone() or ext.Value() > tol:
                continue
            for k in range(1, ext.NbSolution() + 1):
                p = np.array(ext.PointOnShape1(k).Coord())
                if not any(np.linalg.norm(p - q) < 1e-5 for q in points):
                    points.append(p)
    return points


def _check_step_run(stdout: str, path_a: Path, path_b: Path, out: Path) -> int:
    import json

    from relief_cad.cad.occt import unique_edges

    mod = _load("step_intersections.py")
    edges_a, edges_b = unique_edges(mod.read_step(path_a)), unique_edges(mod.read_step(path_b))
    assert f"{path_a.name}: {len(edges_a)} edges; {path_b.name}: {len(edges_b)} edges" in stdout
    rows = _STEP_ROW.findall(stdout)
    assert len(rows) == int(re.search(r"relief_cad: (\d+) result", stdout).group(1)) > 0
    printed = []
    for _i, ia, ib, _kind, x, y, z, t, u in rows:
        p = np.array([float(x), float(y), float(z)])
        assert np.linalg.norm(_value(edges_a[int(ia)], float(t)) - p) < 1e-5
        assert np.linalg.norm(_value(edges_b[int(ib)], float(u)) - p) < 1e-5
        printed.append(p)
    truth = _occt_meeting_points(edges_a, edges_b)
    assert len(truth) == len(printed)
    for p in truth:
        assert min(np.linalg.norm(p - q) for q in printed) < 1e-5

    report = out / "report.html"
    text = report.read_text(encoding="utf-8")
    assert text.startswith("<!DOCTYPE html>") and "relief_cad vs OCCT" in text
    assert "<table>" in text and "data:image/png;base64," in text
    data = json.loads((out / "comparison.json").read_text(encoding="utf-8"))
    assert data["score"]["agreed"] == len(rows) and data["disagreements"] == []
    assert len(data["relief_cad"]) == len(rows)
    return len(rows)


def test_step_intersections_bundled(tmp_path: Path) -> None:
    out = tmp_path / "step"
    stdout = _run("step_intersections.py", "--out", str(out))
    bundled = EXAMPLES.parent / "workbench" / "data" / "step"
    n = _check_step_run(stdout, bundled / "bracket.step", bundled / "knob.step", out)
    # the knob's rim (radius 10 at z = 3) crosses the bracket's long edges y = +-8 at x = +-6
    for x in (-6.0, 6.0):
        for y in (-8.0, 8.0):
            assert re.search(rf"\s{x:.6f}\s+{y:.6f}\s+3\.000000\s", stdout), (x, y)
    assert n == 8


def test_step_intersections_given_files(tmp_path: Path) -> None:
    mod = _load("step_intersections.py")
    path_a, path_b = mod.make_demo_parts(tmp_path / "parts")
    out = tmp_path / "step"
    stdout = _run("step_intersections.py", str(path_a), str(path_b), "--out", str(out))
    assert _check_step_run(stdout, path_a, path_b, out) >= 2


def test_step_intersections_bad_file(tmp_path: Path) -> None:
    bad = tmp_path / "broken.step"
    bad.write_text("ISO-10303-21;\nthis is not a STEP file\n")
    proc = subprocess.run([sys.executable, str(EXAMPLES / "step_intersections.py"), str(bad), str(bad),
                           "--out", str(tmp_path / "o")], capture_output=True, text=True, timeout=120,
                          env=dict(os.environ, MPLBACKEND="Agg"))
    assert proc.returncode != 0 and "cannot read STEP file" in proc.stderr


# --------------------------------------------------------------------------- cadquery_notebook.ipynb


def _outputs_text(nb) -> list[str]:
    texts = []
    for cell in nb.cells:
        if cell.cell_type != "code":
            continue
        parts = []
        for o in cell.get("outputs", []):
            if o.output_type == "stream":
                parts.append(o.text)
            elif o.output_type in ("execute_result", "display_data"):
                parts.append(o.data.get("text/plain", ""))
                parts.append(o.data.get("text/html", ""))
        texts.append("\n".join(parts))
    return texts


def _check_notebook_outputs(nb) -> None:
    import cadquery as cq

    for cell in nb.cells:
        for o in cell.get("outputs", []):
            assert o.output_type != "error", f"{o.get('ename')}: {o.get('evalue')}"
    text = "\n".join(_outputs_text(nb))

    # 1. the plugin's points: the spline crosses the circle x^2 + y^2 = 4 where |p| - 2 changes sign
    points = [np.array([float(x), float(y)]) for x, y in re.findall(r"point \d+: \((\S+), (\S+), 0\.0\)", text)]
    spline = cq.Workplane("XY").spline([(-4, 0), (-2, 2.5), (0, -2.5), (2, 2.5), (4, 0)], includeCurrent=False).val()
    truth = _roots_along(spline, lambda p: float(np.hypot(p[0], p[1]) - 2.0), n=2000)
    assert len(points) == len(truth) == 4
    for p in truth:
        assert min(np.linalg.norm(p[:2] - q) for q in points) < 1e-8
    m = re.search(r"(\d+) holes; volume (\S+) \(expected (\S+)\)", text)
    assert m and int(m.group(1)) == 4 and float(m.group(2)) == pytest.approx(float(m.group(3)), abs=1e-7)
    assert len(re.findall(r"^crossing\s+t=", text, re.MULTILINE)) == 4
    assert "4 agreed, 0 disagreement(s)" in text  # the plugin's points and OCCT's agree
    assert "<table>" in text and "data:image/png;base64," in text  # table + plot in the HTML view

    # 4. the disagreement: T_20 crosses the axis at x = cos((2k - 1) pi / 40), all 20 found by relief_cad
    assert "relief_cad: 20 crossings" in text
    m = re.search(r"relief_cad: (\d+) points, OCCT: (\d+) points; agreed (\d+), disagreements (\d+): "
                  r"relief_cad right (\d+), OCCT right (\d+), neither (\d+)", text)
    assert m, "summary line missing"
    n_rel, n_occt, agreed, dis, rel_right, occt_right, neither = map(int, m.groups())
    assert n_rel == 20 and dis >= 1 and rel_right == dis and occt_right == 0 and neither == 0
    assert agreed + dis == 20
    missed = [float(t) for t in re.findall(r"only relief_cad t=(\S+): winner relief_cad \(crossing\)", text)]
    assert len(missed) == dis
    roots_t = [(math.cos((2 * k - 1) * math.pi / 40) + 1) / 2 for k in range(1, 21)]
    for t in missed:
        assert min(abs(t - r) for r in roots_t) < 1e-8


@needs_cadquery
def test_cadquery_notebook_saved_with_outputs() -> None:
    import nbformat

    nb = nbformat.read(EXAMPLES / "cadquery_notebook.ipynb", as_version=4)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert code and all(c.get("execution_count") for c in code), "save the notebook executed"
    _check_notebook_outputs(nb)


@needs_cadquery
def test_cadquery_notebook_executes(tmp_path: Path) -> None:
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.read(EXAMPLES / "cadquery_notebook.ipynb", as_version=4)
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs = []
    os.environ.setdefault("MPLBACKEND", "Agg")
    # "python3" is ipykernel's own spec in <venv>/share/jupyter/kernels (argv "python" is replaced by
    # the current interpreter by jupyter_client), so this runs in a fresh venv with ipykernel installed.
    NotebookClient(nb, timeout=240, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}}).execute()
    _check_notebook_outputs(nb)


_OVERLAP_ROW = re.compile(r"^\s*\d+ (\d+):line\s+(\d+):line\s+overlap\s+t=\[(\S+), (\S+)\] u=\[(\S+), (\S+)\]\s*$",
                          re.MULTILINE)


def test_step_intersections_overlapping_boxes(tmp_path: Path) -> None:
    """Two 10-unit cubes, the second shifted by 5 along x: 4 overlapping edges and 16 edge contacts."""
    import json

    import build123d as bd

    a = bd.Box(10, 10, 10, align=bd.Align.MIN)
    b = bd.Pos(5, 0, 0) * bd.Box(10, 10, 10, align=bd.Align.MIN)
    path_a, path_b = tmp_path / "box_a.step", tmp_path / "box_b.step"
    bd.export_step(a, str(path_a))
    bd.export_step(b, str(path_b))
    out = tmp_path / "boxes"
    stdout = _run("step_intersections.py", str(path_a), str(path_b), "--out", str(out))

    from relief_cad.cad.occt import unique_edges

    mod = _load("step_intersections.py")
    edges_a, edges_b = unique_edges(mod.read_step(path_a)), unique_edges(mod.read_step(path_b))
    # closed form: the 4 edges along x of box a run over x in [0, 10], those of box b over [5, 15];
    # they coincide over x in [5, 10], i.e. t in [5, 10] on a's edge and u in [0, 5] on b's.
    overlaps = _OVERLAP_ROW.findall(stdout)
    assert len(overlaps) == 4
    for ia, ib, t0, t1, u0, u1 in overlaps:
        assert [float(t0), float(t1), float(u0), float(u1)] == pytest.approx([5, 10, 0, 5], abs=1e-9)
        for t, u in ((float(t0), float(u0)), (float(t1), float(u1)), (7.5, 2.5)):
            assert np.linalg.norm(_value(edges_a[int(ia)], t) - _value(edges_b[int(ib)], u)) < 1e-9
    # the edges across x meet the other box's x edges at its corners x = 5 (b's) and x = 10 (a's), twice each
    rows = _STEP_ROW.findall(stdout)
    assert len(rows) == 16
    corners = {(x, y, z) for x in (5.0, 10.0) for y in (0.0, 10.0) for z in (0.0, 10.0)}
    seen: dict[tuple[float, float, float], int] = {}
    for _i, ia, ib, kind, x, y, z, t, u in rows:
        p = (float(x), float(y), float(z))
        assert p in corners and kind == "crossing"
        assert np.linalg.norm(_value(edges_a[int(ia)], float(t)) - p) < 1e-9
        assert np.linalg.norm(_value(edges_b[int(ib)], float(u)) - p) < 1e-9
        seen[p] = seen.get(p, 0) + 1
    assert seen == {c: 2 for c in corners}
    data = json.loads((out / "comparison.json").read_text(encoding="utf-8"))
    assert data["score"]["agreed"] == 20 and data["disagreements"] == []


# --------------------------------------------------------------------------- arrange_text.py (issue 13)
def test_arrange_text(tmp_path: Path) -> None:
    import build123d as bd

    out = _run("arrange_text.py", str(tmp_path))
    _check_png(tmp_path / "arrange_text.png")
    step = tmp_path / "relief.step"
    assert step.is_file()
    solids = bd.import_step(str(step)).solids()
    regions = re.search(r"regions: (\d+) \(letter: (\d+), band: (\d+), both: (\d+)\)", out)
    assert regions is not None, out
    _, letters, bands, both = map(int, regions.groups())
    assert letters > 0 and bands > 0 and both > 0
    assert len(solids) == letters + bands + both
    areas = re.search(r"area of the regions: (\S+); of letters ∪ bands \(OCCT fuse\): (\S+)", out)
    assert areas is not None, out
    assert math.isclose(float(areas.group(1)), float(areas.group(2)), rel_tol=1e-5)

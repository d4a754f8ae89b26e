"""Corpora of edge pairs for the relief_cad vs OCCT comparison.

Storage
-------
A corpus is a JSON-lines file (optionally gzip-compressed, ``.jsonl.gz``), one pair per line::

    {"id": "cubic-000017", "family": "cubic", "a": "<BREP text>", "b": "<BREP text>" | null,
     "tol": 1e-07 | null, "meta": {...}}

``a`` and ``b`` are OCCT BREP text (``BRepTools.Write``) of an edge, a wire or a compound
of edges: both relief_cad and OCCT read back exactly the same ``TopoDS`` edges (same curve
types, locations, tolerances), so the comparison never depends on a conversion done by the
corpus writer. ``b`` null means the self-intersections of ``a``. ``tol`` null means the
default (the edges' OCCT tolerance).

Families
--------
Random (seeded, reproducible; Bézier curves built as ``Geom_BezierCurve`` edges):
``cubic``, ``rational``, ``high-degree``, ``ill-conditioned`` (a line across a
degree-16..24 Chebyshev polynomial curve), ``tangent`` (a curve and its mirror image in
its tangent line), ``overlap`` (a curve and a piece of itself, possibly extending past
it), ``shared-end``, ``near-miss`` (a tangent pair moved apart by 0.3..30 tolerances),
``scaled`` (cubics at scales 1e-4..1e5 and offsets up to 1e6), ``space`` (crossing space
cubics).

CAD-derived: ``glyph`` (outlines of build123d ``Text`` in DejaVu fonts, two overlapping
copies), ``sketch`` (filleted and splined build123d sketches crossing each other) and
``step`` (edges of STEP files: pairs of edges of one face, and of neighbouring faces).
"""

from __future__ import annotations

import gzip
import io
import json
import math
import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from fractions import Fraction
from pathlib import Path
from typing import Any

import numpy as np

from relief_cad.errors import ReliefCadError

__all__ = [
    "RANDOM_FAMILIES",
    "CAD_FAMILIES",
    "CorpusError",
    "Item",
    "bundled_corpus_path",
    "bundled_step_dir",
    "brep_text",
    "read_shape",
    "read_corpus",
    "write_corpus",
    "random_family",
    "glyph_family",
    "sketch_family",
    "conic_family",
    "step_family",
    "step_files",
    "read_step",
    "check_corpus",
    "CorpusInfo",
    "build_corpus",
    "check_families",
    "bundled_items",
    "pair_text",
    "PAIR_MARK",
]

RANDOM_FAMILIES = (
    "cubic",
    "rational",
    "high-degree",
    "ill-conditioned",
    "tangent",
    "overlap",
    "shared-end",
    "near-miss",
    "scaled",
    "space",
)
CAD_FAMILIES = ("glyph", "sketch", "step")
CONTACT_FAMILIES = ("conic",)  # not in the bundled corpus

DATA_DIR = Path(__file__).resolve().parent / "data"


class CorpusError(ReliefCadError, ValueError):
    """A corpus line or input file that cannot be used (the reason is in the message)."""


def bundled_corpus_path() -> Path:
    """Path of the small corpus shipped with the workbench."""
    return DATA_DIR / "bundled.jsonl.gz"


def bundled_step_dir() -> Path:
    """Folder of the small STEP parts shipped with the workbench."""
    return DATA_DIR / "step"


@dataclass
class Item:
    """One corpus entry (a pair of shapes, or one shape for self-intersections)."""

    id: str
    family: str
    a: str
    b: str | None
    tol: float | None = None
    meta: dict[str, Any] | None = None

    def to_json(self) -> str:
        return json.dumps(
            {
                "id": self.id,
                "family": self.family,
                "a": self.a,
                "b": self.b,
                "tol": self.tol,
                "meta": self.meta or {},
            }
        )

    def shapes(self) -> tuple[Any, Any]:
        """The two shapes (``b`` None for self-intersection items).

        ``b == "#second"``: ``a`` is a compound of the two shapes written together, so that
        the vertices they share stay shared (the same ``TopoDS_Vertex``) after reading.
        """
        if self.b == PAIR_MARK:
            return _split_pair(read_shape(self.a))
        return read_shape(self.a), (read_shape(self.b) if self.b is not None else None)


# --------------------------------------------------------------------------- BREP text

PAIR_MARK = "#second"
"""Value of ``b`` for items whose ``a`` is a compound holding both shapes (shared topology)."""


def pair_text(a: Any, b: Any) -> str:
    """BREP text of a compound of two shapes (read back with :meth:`Item.shapes`)."""
    from OCP.BRep import BRep_Builder
    from OCP.TopoDS import TopoDS_Compound

    comp = TopoDS_Compound()
    builder = BRep_Builder()
    builder.MakeCompound(comp)
    builder.Add(comp, getattr(a, "wrapped", a))
    builder.Add(comp, getattr(b, "wrapped", b))
    return brep_text(comp)


def _split_pair(shape: Any) -> tuple[Any, Any]:
    from OCP.TopoDS import TopoDS_Iterator

    it = TopoDS_Iterator(shape)
    parts = []
    while it.More():
        parts.append(it.Value())
        it.Next()
    if len(parts) != 2:
        raise CorpusError(f"expected a compound of 2 shapes for a '{PAIR_MARK}' item, received {len(parts)}")
    return parts[0], parts[1]


def brep_text(shape: Any) -> str:
    """BREP text of a shape (build123d/CadQuery shapes are unwrapped)."""
    from OCP.BRepTools import BRepTools

    buf = io.BytesIO()
    BRepTools.Write_s(getattr(shape, "wrapped", shape), buf)
    return buf.getvalue().decode("ascii")


def read_shape(text: str) -> Any:
    """Read BREP text back into a ``TopoDS_Shape``; :class:`CorpusError` if unusable."""
    from OCP.BRep import BRep_Builder
    from OCP.BRepTools import BRepTools
    from OCP.TopoDS import TopoDS_Shape

    shape = TopoDS_Shape()
    try:
        BRepTools.Read_s(shape, io.BytesIO(text.encode("ascii")), BRep_Builder())
    except UnicodeEncodeError as exc:
        raise CorpusError(
            f"unreadable BREP text: expected ASCII, received {exc.object[exc.start : exc.end]!r}"
        ) from None
    except Exception as exc:  # noqa: BLE001
        raise CorpusError(f"unreadable BREP text: {exc}") from exc
    if shape.IsNull():
        raise CorpusError("BREP text holds no shape")
    return shape


# --------------------------------------------------------------------------- files


def _open(path: Path, mode: str, gz: bool | None = None) -> Any:
    if str(path).endswith(".gz") if gz is None else gz:
        return gzip.open(path, mode + "t", encoding="utf-8")
    return open(path, mode, encoding="utf-8")


def write_corpus(path: str | os.PathLike[str], items: Iterable[Item]) -> int:
    """Write items as JSON lines (gzip when the name ends in ``.gz``); returns the count.

    The lines go to a temporary file in the same folder, renamed over ``path`` only once every
    item is written: an error or a Ctrl-C while ``items`` runs removes it, and ``path`` keeps
    what it held.
    """
    p = Path(path)
    p.parent.mkdir(parents=True, exist_ok=True)
    tmp = p.with_name(f".{p.name}.{os.getpid()}.tmp")
    n = 0
    try:
        with _open(tmp, "w", gz=p.name.endswith(".gz")) as f:
            for item in items:
                f.write(item.to_json() + "\n")
                n += 1
        os.replace(tmp, p)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return n


GZIP_MAGIC = b"\x1f\x8b"


def _raw_lines(p: Path) -> Iterator[bytes]:
    """The file's lines as bytes (gunzipped when it is gzip data, whatever its name)."""
    with open(p, "rb") as f:
        gz = f.read(2) == GZIP_MAGIC
    if str(p).endswith(".gz") and not gz:
        raise CorpusError(f"{p}: named .gz but is not gzip data")
    with gzip.open(p, "rb") if gz else open(p, "rb") as f:
        yield from f


def _parse_line(raw: bytes, lineno: int, name: str) -> Item | CorpusError:
    try:
        d = json.loads(raw.decode("utf-8"))
        if not isinstance(d, dict) or not isinstance(d.get("a"), str):
            raise ValueError("expected an object with BREP text in 'a'")
        return Item(
            str(d.get("id", f"line-{lineno}")),
            str(d.get("family", "unknown")),
            d["a"],
            d.get("b"),
            d.get("tol"),
            d.get("meta") or {},
        )
    except UnicodeDecodeError as exc:
        reason: Exception = ValueError(f"not UTF-8 text: byte {raw[exc.start : exc.start + 1]!r}")
    except (ValueError, TypeError, KeyError) as exc:
        reason = exc
    err = CorpusError(f"{name} line {lineno}: corrupt corpus line ({reason})")
    err.id = f"{name}:line-{lineno}"  # type: ignore[attr-defined]
    return err


def read_corpus(path: str | os.PathLike[str]) -> Iterator[Item | CorpusError]:
    """Yield the items of a corpus; a corrupt line yields a :class:`CorpusError` naming it.

    A line whose id was already used yields a :class:`CorpusError` with the id
    ``<id>@line-<n>``, so that every line gets exactly one result.
    """
    p = Path(path)
    if not p.is_file():
        raise CorpusError(f"corpus file {p} does not exist")
    seen: dict[str, int] = {}
    try:
        for lineno, raw in enumerate(_raw_lines(p), 1):
            if not raw.strip():
                continue
            it = _parse_line(raw, lineno, p.name)
            if isinstance(it, Item) and it.id in seen:
                err = CorpusError(
                    f"{p.name} line {lineno}: duplicate id {it.id!r} (first on line {seen[it.id]})"
                )
                err.id = f"{it.id}@line-{lineno}"  # type: ignore[attr-defined]
                it = err
            elif isinstance(it, Item):
                seen[it.id] = lineno
            yield it
    except (OSError, EOFError, gzip.BadGzipFile) as exc:
        err = CorpusError(f"{p.name}: unreadable after the last good line ({exc})")
        err.id = f"{p.name}:unreadable"  # type: ignore[attr-defined]
        yield err


@dataclass
class CorpusInfo:
    """What :func:`check_corpus` found: item count, content hash, and the ids in order."""

    path: Path
    n_items: int
    sha256: str
    ids: list[str]


def check_corpus(path: str | os.PathLike[str]) -> CorpusInfo:
    """Read a whole corpus once: refuse an unusable file, else count, hash and list its ids.

    Raises
    ------
    CorpusError
        One line saying why the file is not a usable corpus: missing, a folder, named .gz
        but not gzip, truncated gzip, binary or non-UTF-8 data, not JSON lines, or empty.
        (Single corrupt lines in a good corpus are not refused: they become failed items.)
    """
    import hashlib

    p = Path(path)
    if not p.exists():
        raise CorpusError(f"{p}: no such file")
    if not p.is_file():
        raise CorpusError(f"{p}: expected a corpus file, received a folder")
    h = hashlib.sha256()
    ids: list[str] = []
    good = 0
    try:
        for raw in _raw_lines(p):
            h.update(raw)
    except (EOFError, gzip.BadGzipFile, OSError) as exc:
        raise CorpusError(f"{p}: truncated or damaged gzip data ({exc})") from None
    for it in read_corpus(p):
        ids.append(str(getattr(it, "id", "?")))
        good += isinstance(it, Item)
    if not ids:
        raise CorpusError(f"{p}: empty corpus (0 items)")
    if not good:
        raise CorpusError(f"{p}: {_not_a_corpus_reason(p)}")
    return CorpusInfo(p, len(ids), h.hexdigest(), ids)


def _not_a_corpus_reason(p: Path) -> str:
    head = b"".join(line for _, line in zip(range(64), _raw_lines(p), strict=False))[:8192]
    if head.startswith(b"ISO-10303-21"):
        return "a STEP file, not a corpus (give it to compare directly, or to corpus --step)"
    text = head.decode("utf-8", "replace")[:-3]  # the cut may split a character
    if "\x00" in text or "\ufffd" in text:
        return "not a corpus: binary data, not UTF-8 JSON lines"
    return "not a corpus: no line is a JSON object with BREP text in 'a'"


# --------------------------------------------------------------------------- Bézier helpers


def _bezier_edge(points: np.ndarray, weights: np.ndarray | None = None) -> Any:
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.Geom import Geom_BezierCurve
    from OCP.gp import gp_Pnt

    from relief_cad.cad._compat import Array1OfPnt, Array1OfReal

    pts = np.asarray(points, dtype=float)
    if pts.shape[1] == 2:
        pts = np.hstack([pts, np.zeros((len(pts), 1))])
    arr = Array1OfPnt(1, len(pts))
    for i, p in enumerate(pts):
        arr.SetValue(i + 1, gp_Pnt(float(p[0]), float(p[1]), float(p[2])))
    if weights is None:
        curve = Geom_BezierCurve(arr)
    else:
        w = Array1OfReal(1, len(pts))
        for i, x in enumerate(weights):
            w.SetValue(i + 1, float(x))
        curve = Geom_BezierCurve(arr, w)
    return BRepBuilderAPI_MakeEdge(curve).Edge()


def _line_edge(p: Any, q: Any) -> Any:
    from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge
    from OCP.gp import gp_Pnt

    p3 = list(map(float, p)) + [0.0] * (3 - len(p))
    q3 = list(map(float, q)) + [0.0] * (3 - len(q))
    return BRepBuilderAPI_MakeEdge(gp_Pnt(*p3), gp_Pnt(*q3)).Edge()


def _decasteljau(hom: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Point and the two halves' homogeneous control points at t (works outside [0, 1])."""
    pts = [np.array(hom, dtype=float)]
    left, right = [pts[0][0]], [pts[0][-1]]
    cur = pts[0]
    while len(cur) > 1:
        cur = (1 - t) * cur[:-1] + t * cur[1:]
        left.append(cur[0])
        right.append(cur[-1])
    return cur[0], np.array(left), np.array(right[::-1])


def _segment(points: np.ndarray, weights: np.ndarray, s0: float, s1: float) -> tuple[np.ndarray, np.ndarray]:
    hom = np.hstack([points * weights[:, None], weights[:, None]])
    _, _, right = _decasteljau(hom, s0)  # [s0, 1] (or beyond)
    local = (s1 - s0) / (1 - s0) if s0 != 1 else 0.0
    _, left, _ = _decasteljau(right, local)
    return left[:, :-1] / left[:, -1:], left[:, -1]


def _eval(points: np.ndarray, weights: np.ndarray, t: float) -> tuple[np.ndarray, np.ndarray]:
    hom = np.hstack([points * weights[:, None], weights[:, None]])
    n = len(points) - 1
    p, _, _ = _decasteljau(hom, t)
    d_hom = n * (hom[1:] - hom[:-1])
    dp, _, _ = _decasteljau(d_hom, t) if n > 0 else (np.zeros_like(p), None, None)
    pt = p[:-1] / p[-1]
    deriv = (dp[:-1] - pt * dp[-1]) / p[-1]
    return pt, deriv


def _chebyshev_bezier(n: int) -> list[float]:
    """Bernstein coefficients (exact, then rounded) of T_n(2t - 1)."""
    # power coefficients of T_n(x)
    c = [[Fraction(1)], [Fraction(0), Fraction(1)]]
    for k in range(2, n + 1):
        prev, prev2 = c[k - 1], c[k - 2]
        nxt = [Fraction(0)] * (k + 1)
        for i, v in enumerate(prev):
            nxt[i + 1] += 2 * v
        for i, v in enumerate(prev2):
            nxt[i] -= v
        c.append(nxt)
    tn = c[n]
    # substitute x = 2t - 1
    poly = [Fraction(0)] * (n + 1)
    for k, ck in enumerate(tn):
        if ck == 0:
            continue
        for j in range(k + 1):
            poly[j] += ck * math.comb(k, j) * (2**j) * (-1) ** (k - j)
    return [
        float(sum(Fraction(math.comb(i, k), math.comb(n, k)) * poly[k] for k in range(i + 1)))
        for i in range(n + 1)
    ]


def _mirror(points: np.ndarray, p: np.ndarray, d: np.ndarray) -> np.ndarray:
    d = d / np.linalg.norm(d)
    rel = points - p
    along = rel @ d
    out: np.ndarray = p + 2 * np.outer(along, d) - rel
    return out


# --------------------------------------------------------------------------- random families


def random_family(family: str, count: int, seed: int = 0) -> Iterator[Item]:
    """Yield ``count`` items of a seeded random family (see the module docstring)."""
    if family not in RANDOM_FAMILIES:
        raise CorpusError(f"expected a random family in {RANDOM_FAMILIES}, received {family!r}")
    rng = np.random.default_rng([seed, RANDOM_FAMILIES.index(family)])
    for k in range(count):
        item = _random_item(family, rng)
        a, b, meta = item
        yield Item(
            f"{family}-{seed}-{k:06d}",
            family,
            brep_text(a),
            brep_text(b) if b is not None else None,
            None,
            meta,
        )


def _rand_curve(rng: np.random.Generator, degree: int, dim: int = 2) -> np.ndarray:
    return rng.uniform(0.0, 1.0, (degree + 1, dim))


def _random_item(family: str, rng: np.random.Generator) -> tuple[Any, Any, dict[str, Any]]:
    if family == "cubic":
        return _bezier_edge(_rand_curve(rng, 3)), _bezier_edge(_rand_curve(rng, 3)), {}
    if family == "rational":
        da, db = (int(x) for x in rng.integers(2, 6, 2))
        wa, wb = rng.uniform(0.2, 5.0, da + 1), rng.uniform(0.2, 5.0, db + 1)
        return _bezier_edge(_rand_curve(rng, da), wa), _bezier_edge(_rand_curve(rng, db), wb), {}
    if family == "high-degree":
        da, db = (int(x) for x in rng.integers(10, 21, 2))
        return _bezier_edge(_rand_curve(rng, da)), _bezier_edge(_rand_curve(rng, db)), {"degrees": [da, db]}
    if family == "ill-conditioned":
        n = int(rng.integers(16, 25))
        amp = float(10 ** rng.uniform(-3, 0))
        ys = np.array(_chebyshev_bezier(n)) * amp
        xs = np.linspace(-1.0, 1.0, n + 1)
        y0 = float(rng.uniform(-0.5, 0.5)) * amp
        a = _bezier_edge(np.column_stack([xs, ys]))
        return a, _line_edge((-1.0, y0), (1.0, y0)), {"degree": n, "amplitude": amp}
    if family in ("tangent", "near-miss"):
        deg = int(rng.integers(2, 5))
        pts = _rand_curve(rng, deg)
        w = np.ones(deg + 1)
        t0 = float(rng.uniform(0.2, 0.8))
        p, d = _eval(pts, w, t0)
        mirrored = _mirror(pts, p, d)
        meta: dict[str, Any] = {"t0": t0}
        if family == "near-miss":
            normal = np.array([-d[1], d[0]]) / np.linalg.norm(d)
            gap = float(10 ** rng.uniform(-0.5, 1.5)) * 1e-7
            mirrored = mirrored + 2 * gap * normal * (1 if (pts[0] - p) @ normal < 0 else -1)
            meta["gap"] = gap
        if rng.uniform() < 0.5:  # half of them against the tangent line
            half = 0.5 * (0.3 + rng.uniform()) * d / np.linalg.norm(d)
            return (
                _bezier_edge(pts),
                _line_edge(
                    p - half + (mirrored[0] - _mirror(pts, p, d)[0]) * 0.5,
                    p + half + (mirrored[0] - _mirror(pts, p, d)[0]) * 0.5,
                ),
                meta,
            )
        return _bezier_edge(pts), _bezier_edge(mirrored), meta
    if family == "overlap":
        deg = int(rng.integers(2, 6))
        pts = _rand_curve(rng, deg)
        w = np.ones(deg + 1)
        s0, s1 = sorted(rng.uniform(-0.3, 1.3, 2))
        if rng.uniform() < 0.5:
            s0, s1 = s1, s0
        sp, sw = _segment(pts, w, s0, s1)
        return _bezier_edge(pts), _bezier_edge(sp, sw), {"s": [s0, s1]}
    if family == "shared-end":
        pa, pb = _rand_curve(rng, 3), _rand_curve(rng, 3)
        pb[0] = pa[-1] if rng.uniform() < 0.5 else pa[0]
        if rng.uniform() < 0.3:  # and tangent there
            pb[1] = pb[0] + (pa[-1] - pa[-2]) * rng.uniform(0.3, 2) if np.all(pb[0] == pa[-1]) else pb[1]
        return _bezier_edge(pa), _bezier_edge(pb), {}
    if family == "scaled":
        scale = float(10 ** rng.uniform(-4, 5))
        offset = rng.uniform(-1, 1, 2) * float(10 ** rng.uniform(0, 6))
        return (
            _bezier_edge(_rand_curve(rng, 3) * scale + offset),
            _bezier_edge(_rand_curve(rng, 3) * scale + offset),
            {"scale": scale},
        )
    # space: two cubics forced through one common point
    pa, pb = _rand_curve(rng, 3, 3), _rand_curve(rng, 3, 3)
    t0, u0 = rng.uniform(0.1, 0.9, 2)
    p, _ = _eval(pa, np.ones(4), float(t0))
    q, _ = _eval(pb, np.ones(4), float(u0))
    return _bezier_edge(pa), _bezier_edge(pb + (p - q)), {"t0": float(t0), "u0": float(u0)}


# --------------------------------------------------------------------------- CAD families


def _pairs_by_bbox(edges_a: list[Any], edges_b: list[Any] | None, limit: int) -> list[tuple[Any, Any]]:
    from OCP.Bnd import Bnd_Box
    from OCP.BRepBndLib import BRepBndLib

    def box(e: Any) -> Any:
        bb = Bnd_Box()
        BRepBndLib.Add_s(e, bb)
        bb.Enlarge(1e-6)
        return bb

    ba = [box(e) for e in edges_a]
    out: list[tuple[Any, Any]] = []
    if edges_b is None:
        for i in range(len(edges_a)):
            for j in range(i + 1, len(edges_a)):
                if not ba[i].IsOut(ba[j]):
                    out.append((edges_a[i], edges_a[j]))
    else:
        bb = [box(e) for e in edges_b]
        for i in range(len(edges_a)):
            for j in range(len(edges_b)):
                if not ba[i].IsOut(bb[j]):
                    out.append((edges_a[i], edges_b[j]))
    return out[:limit]


def glyph_family(count: int, seed: int = 0, text: str = "relief@&8") -> Iterator[Item]:
    """Pairs of glyph-outline edges of two overlapping copies of a build123d ``Text``."""
    import build123d as bd

    from relief_cad.cad.occt import unique_edges

    fonts = ["DejaVu Sans", "DejaVu Serif", "DejaVu Sans Mono"]
    rng = np.random.default_rng([seed, 101])
    k = 0
    for attempt in range(6):
        font = fonts[attempt % len(fonts)]
        t1 = bd.Text(text, 10, font=font)
        t2 = (
            bd.Pos(float(rng.uniform(0.5, 3)), float(rng.uniform(-1, 1)))
            * bd.Rot(0, 0, float(rng.uniform(-15, 15)))
            * bd.Text(text, 10, font=font)
        )
        ea, eb = unique_edges(t1), unique_edges(t2)
        pairs = _pairs_by_bbox(ea, eb, 10 * count)
        rng.shuffle(pairs)  # type: ignore[arg-type]
        for a, b in pairs:
            if k >= count:
                return
            yield Item(f"glyph-{seed}-{k:06d}", "glyph", brep_text(a), brep_text(b), None, {"font": font})
            k += 1


def sketch_family(count: int, seed: int = 0) -> Iterator[Item]:
    """Pairs of edges of filleted and splined build123d sketches laid across each other."""
    import build123d as bd

    from relief_cad.cad.occt import unique_edges

    rng = np.random.default_rng([seed, 202])
    k = 0
    for _ in range(20):
        w, h = (float(x) for x in rng.uniform(4, 10, 2))
        rect = bd.fillet(bd.Rectangle(w, h).vertices(), radius=float(rng.uniform(0.5, 1.5)))
        pts = [(float(x), float(y)) for x, y in rng.uniform(-6, 6, (5, 2))]
        spline = bd.Spline(*pts)
        slot = bd.Rot(0, 0, float(rng.uniform(0, 180))) * bd.SlotOverall(float(rng.uniform(6, 12)), 2.0)
        ell = bd.Pos(float(rng.uniform(-2, 2)), 0) * bd.Ellipse(
            float(rng.uniform(2, 5)), float(rng.uniform(1, 3))
        )
        shapes = [unique_edges(s) for s in (rect, [spline][0], slot, ell)]
        for i in range(len(shapes)):
            for j in range(i + 1, len(shapes)):
                for a, b in _pairs_by_bbox(shapes[i], shapes[j], 8):
                    if k >= count:
                        return
                    yield Item(f"sketch-{seed}-{k:06d}", "sketch", pair_text(a, b), PAIR_MARK, None, {})
                    k += 1
        # a wire against itself: its edges' self-intersections (shared vertices excluded)
        if k < count:
            wire = bd.Wire(rect.edges())
            yield Item(f"sketch-{seed}-{k:06d}", "sketch", brep_text(wire), None, None, {"self": True})
            k += 1
    return


CONIC_KINDS = ("circles", "ellipse-circle", "line-conic", "spline-at-joint", "spline-on-circle", "near-miss",
               "seam")


def conic_family(count: int, seed: int = 0) -> Iterator[Item]:
    """Pairs of build123d conics and splines in contact, at scales from 0.01 to 1000 (``meta["kind"]``).

    In turn: circles touching outside or inside (arcs or closed, the seam sometimes at the touch); an
    ellipse and a circle touching at a vertex (the ellipse's seam at one); a line tangent to a
    circle or an ellipse; a spline through an arc's middle, where both have a span joint (it crosses
    there and again close by); a spline through 9 points of an arc (crossings at each, the curves
    close between); circles 0.3 to 3 tol apart or overlapping (tol 1e-7); a line through, or
    tangent at, the seam of a closed periodic spline.
    """
    rng = np.random.default_rng([seed, 303])
    for k in range(count):
        kind = CONIC_KINDS[k % len(CONIC_KINDS)]
        a, b = _conic_pair(kind, rng)
        yield Item(f"conic-{seed}-{k:06d}", "conic", brep_text(a), brep_text(b), None, {"kind": kind})


def _conic_pair(kind: str, rng: np.random.Generator) -> tuple[Any, Any]:
    """One pair of :func:`conic_family`'s ``kind``, placed and turned at random.

    Not one screen: one short branch per kind, sharing the random placement.
    """
    import build123d as bd

    size = float(10 ** rng.uniform(-2, 3))
    r1 = size * float(rng.uniform(0.3, 1.0))
    r2 = size * float(rng.uniform(0.2, 2.0))
    turn = float(rng.uniform(0, 360))
    place = bd.Location(tuple(float(x) for x in rng.uniform(-1, 1, 2) * 10 ** rng.uniform(-1, 3)) + (0.0,),
                        (0, 0, 1), turn)

    def arc(r: float, at: float, full: bool) -> Any:  # an arc of 140 degrees about angle ``at``, or a circle
        if full:
            return bd.Edge.make_circle(r, bd.Plane.XY.rotated((0, 0, at)))
        return bd.Edge.make_circle(r, bd.Plane.XY, start_angle=at - 70, end_angle=at + 70)

    full = bool(rng.integers(0, 2))
    if kind == "circles":
        inside = bool(rng.integers(0, 2)) and r2 < r1
        d = r1 - r2 if inside else r1 + r2
        a = arc(r1, float(rng.choice([0.0, 37.0])) if full else 0.0, full)
        b = arc(r2, 0.0 if inside else 180.0, bool(rng.integers(0, 2))).moved(bd.Location((d, 0, 0)))
    elif kind == "ellipse-circle":
        rb = r1 * float(rng.uniform(0.1, 0.95))
        a = bd.Edge.make_ellipse(r1, rb, bd.Plane.XY)
        b = bd.Edge.make_circle(r2).moved(bd.Location((r1 + r2, 0, 0)))
    elif kind == "line-conic":
        rb = r1 * float(rng.uniform(0.1, 1.0))
        a = bd.Edge.make_ellipse(r1, rb, bd.Plane.XY) if rb < r1 else arc(r1, 90.0, full)
        phi = float(rng.uniform(0, 2 * math.pi)) if rb < r1 else math.pi / 2
        q, t = (r1 * math.cos(phi), rb * math.sin(phi)), (-r1 * math.sin(phi), rb * math.cos(phi))
        n, f, length = math.hypot(*t), float(rng.uniform(0.1, 0.9)), size * float(rng.uniform(0.2, 3))
        b = bd.Edge.make_line((q[0] - f * length * t[0] / n, q[1] - f * length * t[1] / n),
                              (q[0] + (1 - f) * length * t[0] / n, q[1] + (1 - f) * length * t[1] / n))
    elif kind == "spline-at-joint":
        a = arc(r1, 90.0, False)
        bend, half = float(rng.uniform(-0.5, 0.8)) / r1, r1 * float(rng.uniform(0.3, 1.5))
        b = bd.Edge.make_spline([bd.Vector(x, r1 + 0.5 * bend * x * x + 0.05 * bend * bend * x**3)
                                 for x in np.linspace(-half, half, 7)])
    elif kind == "spline-on-circle":
        a = arc(r1, 90.0, False)
        b = bd.Edge.make_spline([bd.Vector(r1 * math.cos(x), r1 * math.sin(x))
                                 for x in np.linspace(math.pi / 2 - 0.5, math.pi / 2 + 0.9, 9)])
    elif kind == "near-miss":
        gap = float(rng.choice([-3.0, -0.5, -0.3, 0.3, 0.5, 3.0])) * 1e-7
        a = arc(r1, 0.0, full)
        b = arc(r2, 180.0, bool(rng.integers(0, 2))).moved(bd.Location((r1 + r2 + gap, 0, 0)))
    else:  # seam
        n = int(rng.integers(4, 9))
        ang, rad = np.sort(rng.uniform(0, 2 * math.pi, n)), r1 * rng.uniform(0.6, 1.4, n)
        pts = [bd.Vector(float(r * math.cos(q)), float(r * math.sin(q)))
               for q, r in zip(ang, rad, strict=True)]
        a = bd.Edge.make_spline([*pts], periodic=True)  # (a list of VectorLike for the type checker)
        tg = a.tangent_at(0.0) if rng.integers(0, 2) else bd.Vector(1.0, 0.0)
        b = bd.Edge.make_line(pts[0] - tg * 2 * r1, pts[0] + tg * 2 * r1)
    return a.moved(place), b.moved(place)


def step_files(paths: Iterable[str | os.PathLike[str]]) -> list[Path]:
    """The STEP files named: files as given, folders searched for ``*.step`` / ``*.stp``."""
    files: list[Path] = []
    for p in map(Path, paths):
        if p.is_dir():
            files += sorted(x for x in p.rglob("*") if x.suffix.lower() in (".step", ".stp"))
        else:
            files.append(p)
    return files


def _flush_c_streams() -> None:
    """Flush the C library's stdio buffers (OCCT prints through them), where there is a C library."""
    import ctypes

    try:
        ctypes.CDLL(None).fflush(None)
    except (OSError, AttributeError):  # pragma: no cover - no C library to ask (Windows)
        pass


def _quiet_fds() -> Any:
    """A context manager sending C-level stdout/stderr to a temporary file, yielding it.

    The C library's buffers are flushed on the way in and out: OCCT prints through C stdio, which
    buffers a pipe or a file in full (unless Python runs unbuffered, ``-u``), so its messages
    came out after the file descriptors were restored, on the real stdout.
    """
    import contextlib
    import sys
    import tempfile

    @contextlib.contextmanager
    def cm() -> Iterator[Any]:
        sys.stdout.flush()
        sys.stderr.flush()
        _flush_c_streams()
        saved = [os.dup(1), os.dup(2)]
        with tempfile.TemporaryFile() as tmp:
            try:
                os.dup2(tmp.fileno(), 1)
                os.dup2(tmp.fileno(), 2)
                yield tmp
            finally:
                _flush_c_streams()
                os.dup2(saved[0], 1)
                os.dup2(saved[1], 2)
                os.close(saved[0])
                os.close(saved[1])

    return cm()


def read_step(path: str | os.PathLike[str]) -> Any:
    """Read a STEP file into one ``TopoDS_Shape``; OCCT's console messages are captured.

    Raises
    ------
    CorpusError
        One line: the file is missing, or OCCT cannot read it (with OCCT's own reason), or
        it holds no shape.
    """
    from OCP.IFSelect import IFSelect_RetDone
    from OCP.STEPControl import STEPControl_Reader

    p = Path(path)
    if not p.is_file():
        raise CorpusError(
            f"{p}: no such file" if not p.exists() else f"{p}: expected a STEP file, received a folder"
        )
    reader = STEPControl_Reader()
    with _quiet_fds() as tmp:
        try:
            status = reader.ReadFile(str(p))
        except Exception as exc:  # noqa: BLE001 - reported with the file name
            status, extra = None, f"{type(exc).__name__}: {exc}"
        else:
            extra = ""
        if status == IFSelect_RetDone:
            reader.TransferRoots()
        tmp.seek(0)
        noise = tmp.read().decode("utf-8", "replace")
    if status != IFSelect_RetDone:
        import re

        plain = re.sub("\x1b\\[[0-9;]*m", "", noise)
        said = [ln.strip(" *\t") for ln in plain.splitlines() if "ERR" in ln or "Error" in ln]
        why = extra or (said[0] if said else f"reader status {getattr(status, 'name', status)}")
        raise CorpusError(f"{p}: OCCT cannot read this STEP file ({why})")
    shape = reader.OneShape()
    if shape.IsNull():
        raise CorpusError(f"{p}: STEP file holds no shape")
    return shape


def _usable_steps(paths: Iterable[str | os.PathLike[str]]) -> Iterator[tuple[Path, Any] | CorpusError]:
    from relief_cad.cad.occt import unique_edges

    for f in step_files(paths):
        try:
            shape = read_step(f)
            if not unique_edges(shape):
                raise CorpusError(f"{f}: STEP shape with no edges")
        except CorpusError as err:
            err.id = f"step:{f.name}"  # type: ignore[attr-defined]
            yield err
            continue
        yield f, shape


def _faces(shape: Any) -> list[Any]:
    from OCP.TopAbs import TopAbs_FACE
    from OCP.TopExp import TopExp_Explorer

    faces = []
    ex = TopExp_Explorer(shape, TopAbs_FACE)
    while ex.More():
        faces.append(ex.Current())
        ex.Next()
    return faces


def _within_pairs(shape: Any, limit: int) -> list[tuple[Any, Any]]:
    from relief_cad.cad.occt import unique_edges

    pairs = []
    for face in _faces(shape):
        pairs += _pairs_by_bbox(unique_edges(face), None, 6)
    return pairs + _pairs_by_bbox(unique_edges(shape), None, limit)


def step_family(
    paths: Iterable[str | os.PathLike[str]], count: int, *, across: bool = False
) -> Iterator[Item | CorpusError]:
    """Pairs of edges of STEP files (files, or folders searched for ``*.step``/``*.stp``).

    Within a file (default): edges of one face (neighbours share a vertex: the ``shared-end``
    case of real parts) and edges of different faces whose boxes meet. With ``across``: an
    edge of one file against an edge of another whose boxes meet (two parts laid together).
    ``count`` is shared evenly among the files OCCT can read; each unusable file yields one
    :class:`CorpusError` and takes no share.
    """
    from relief_cad.cad.occt import unique_edges

    usable: list[tuple[Path, Any]] = []
    for got in _usable_steps(paths):
        if isinstance(got, CorpusError):
            yield got
        else:
            usable.append(got)
    groups: list[tuple[str, str, list[tuple[Any, Any]]]] = []
    if across and len(usable) >= 2:
        per = max(1, count // (len(usable) * (len(usable) - 1) // 2))
        for i, (fa, sa) in enumerate(usable):
            for fb, sb in usable[i + 1 :]:
                pairs = _pairs_by_bbox(unique_edges(sa), unique_edges(sb), per)
                groups.append((f"{fa.stem}+{fb.stem}", f"{fa.name} + {fb.name}", pairs))
    else:
        per = max(1, count // max(1, len(usable)))
        groups = [(f.stem, f.name, _within_pairs(shape, per)) for f, shape in usable]
    k = 0
    for name, file_meta, pairs in groups:
        got_n = 0
        seen: set[tuple[int, int]] = set()
        for a, b in pairs:
            key = (hash(a), hash(b))
            if key in seen:
                continue
            seen.add(key)
            if got_n >= per or k >= count:
                break
            yield Item(
                f"step-{name}-{got_n:06d}", "step", pair_text(a, b), PAIR_MARK, None, {"file": file_meta}
            )
            got_n += 1
            k += 1


BUNDLED_RECIPE = {"random_count": 8, "cad_count": 14, "seed": 7}
"""How ``workbench/data/bundled.jsonl.gz`` is made (``relief-cad-workbench corpus --bundled OUT``)."""


def bundled_items() -> Iterator[Item | CorpusError]:
    """The bundled corpus: 8 of each random family and 14 each of glyph, sketch and STEP pairs (seed 7)."""
    r = BUNDLED_RECIPE
    yield from build_corpus(RANDOM_FAMILIES, r["random_count"], r["seed"])
    yield from build_corpus(CAD_FAMILIES, r["cad_count"], r["seed"])


def build_corpus(
    families: Iterable[str],
    count: int,
    seed: int = 0,
    step_paths: Iterable[str | os.PathLike[str]] = (),
) -> Iterator[Item | CorpusError]:
    """Yield the items of the named families (``count`` each)."""
    for fam in families:
        if fam in RANDOM_FAMILIES:
            yield from random_family(fam, count, seed)
        elif fam == "glyph":
            yield from glyph_family(count, seed)
        elif fam == "sketch":
            yield from sketch_family(count, seed)
        elif fam == "step":
            yield from step_family(list(step_paths) or [bundled_step_dir()], count)
        elif fam == "conic":
            yield from conic_family(count, seed)
        else:
            check_families([fam])


def check_families(families: Iterable[str]) -> None:
    """Raise :class:`CorpusError` naming the first unknown or repeated family (and the known ones).

    A family named twice would give its items twice, under the same ids, which ``compare`` then
    refuses item by item.
    """
    known = RANDOM_FAMILIES + CAD_FAMILIES + CONTACT_FAMILIES
    seen: set[str] = set()
    for fam in families:
        if fam not in known:
            raise CorpusError(f"expected a family in {', '.join(known)}, received {fam!r}")
        if fam in seen:
            raise CorpusError(f"expected each family once, received {fam!r} twice")
        seen.add(fam)

"""Property-based fuzz of the core's public surface (issue 15): answers checked, refusals checked.

Generated: curves of degree 1 to 4 in the plane and in space (rational or not), pairs forced to
meet (a space pair meets only so), scaled by 2**-30 .. 2**30 (tiny and huge coordinates), and
bad arguments of every public function. Checked on every answer: parameters in [0, 1], the
curves meet within the tolerance at each reported contact; and the metamorphic relations
(swap of a and b, reversal t -> 1 - t, similarity maps, degree elevation, splitting,
determinism) on the transversal crossings (tangent contacts sit on the tolerance boundary by
construction). Every refusal must be a ReliefCadError that is also the matching built-in and
names what was expected and what came. Counts: tests/_fuzz.py.
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import strategies as st

from relief_cad import (
    RationalBezier,
    ReliefPerspective,
    central_projection,
    default_tolerance,
    intersect,
    intersect_line,
    intersect_many,
    lift,
    preimage_of_lift,
    relief_of_lift,
)
from relief_cad.errors import (
    DegenerateCurveError,
    DegreeError,
    InputTypeError,
    InvalidInputError,
    NonFiniteError,
    ProjectionError,
    ShapeError,
    SpanError,
    ToleranceError,
    WeightError,
)
from relief_cad.results import Intersection, IntersectionList, Overlap
from tests._fuzz import Case, fuzz
from tests.core.strategies import curves, spans

EPS = float(np.finfo(float).eps)
SAMPLES = np.linspace(0.0, 1.0, 9)
unit = st.floats(0.0, 1.0)
inner = st.floats(0.05, 0.95)


# ----------------------------------------------------------------------------- generators
def similarity(dim: int, angle: float, axis: np.ndarray, scale: float, shift: np.ndarray) -> np.ndarray:
    """Homogeneous matrix of a rotation (about ``axis`` in space), a uniform scale and a shift."""
    if dim == 2:
        rot = np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
    else:
        k = axis / (np.linalg.norm(axis) or 1.0)
        cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
        rot = np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross
    m = np.eye(dim + 1)
    m[:dim, :dim] = scale * rot
    m[:dim, dim] = shift
    return m


@st.composite
def similarities(draw: st.DrawFn, dim: int) -> np.ndarray:
    axis = np.array(draw(st.lists(st.floats(-1, 1), min_size=3, max_size=3))) + np.array([0, 0, 1e-3])
    shift = np.array(draw(st.lists(st.floats(-50, 50), min_size=dim, max_size=dim)))
    return similarity(dim, draw(st.floats(-math.pi, math.pi)), axis, draw(st.floats(0.1, 10.0)), shift)


def shifted(c: RationalBezier, v: np.ndarray) -> RationalBezier:
    m = np.eye(c.dim + 1)
    m[: c.dim, c.dim] = v
    return c.transformed(m)


@st.composite
def pairs(draw: st.DrawFn, dim: int, max_degree: int = 4) -> tuple[RationalBezier, RationalBezier]:
    """Two curves; in space (and in half the planar pairs) ``b`` is moved to pass through a point of ``a``."""
    a = draw(curves(dim=dim, max_degree=max_degree))
    b = draw(curves(dim=dim, max_degree=max_degree))
    if dim == 3 or draw(st.booleans()):
        b = shifted(b, a(draw(inner)) - b(draw(inner)))
    k = draw(st.integers(-30, 30))
    m = np.diag([2.0**k] * dim + [1.0])
    return a.transformed(m), b.transformed(m)


# ----------------------------------------------------------------------------- answers
def size(*cs: RationalBezier) -> float:
    pts = np.vstack([c.control_points for c in cs])
    return float(np.linalg.norm(pts.max(axis=0) - pts.min(axis=0)))


def bound(*cs: RationalBezier) -> float:
    """How far apart the curves may be at a reported contact: a few default tolerances."""
    return 8.0 * default_tolerance(*cs)


def sine(a: RationalBezier, t: float, b: RationalBezier, u: float) -> float:
    da, db = a.derivative(t), b.derivative(u)
    na, nb = float(np.linalg.norm(da)), float(np.linalg.norm(db))
    if not (na > 0.0 and nb > 0.0 and math.isfinite(na * nb)):
        return 0.0
    cos = float(np.dot(da / na, db / nb))
    return math.sqrt(max(0.0, 1.0 - cos * cos))


def param_tol(a: RationalBezier, t: float, b: RationalBezier, u: float) -> float:
    """Parameter accuracy of a transversal crossing: the data's rounding over speed times sine."""
    big = float(max(np.abs(a.control_points).max(), np.abs(b.control_points).max()))
    speed = min(float(np.linalg.norm(a.derivative(t))), float(np.linalg.norm(b.derivative(u))))
    return 1e-9 + 1e5 * EPS * big / (speed * max(sine(a, t, b, u), 1e-3))


def crossings(a: RationalBezier, b: RationalBezier, res: IntersectionList) -> list[Intersection]:
    """The well-conditioned crossings: interior, at an angle, not next to another result."""
    out = []
    for r in res.points:
        if r.kind != "crossing" or not (1e-4 < r.t < 1 - 1e-4 and 1e-4 < r.u < 1 - 1e-4):
            continue
        if sine(a, r.t, b, r.u) < 0.05:
            continue
        near = [q for q in res if q is not r and (isinstance(q, Overlap) or abs(q.t - r.t) < 1e-3)]
        if not near:
            out.append(r)
    return out


def has(res: IntersectionList, t: float, u: float, tol: float) -> bool:
    for r in res:
        if isinstance(r, Intersection) and abs(r.t - t) <= tol and abs(r.u - u) <= tol:
            return True
        if isinstance(r, Overlap) and min(r.t) - tol <= t <= max(r.t) + tol:
            return True
    return False


def check_answer(case: Case, a: RationalBezier, b: RationalBezier | None, res: IntersectionList) -> None:
    """Every reported contact is a contact: parameters in [0, 1], the curves meet there, sorted by t."""
    other = a if b is None else b
    near = bound(a, other)
    keys = [r.t if isinstance(r, Intersection) else r.t[0] for r in res]
    case.check(keys == sorted(keys), "not sorted by t", list(res))
    for r in res:
        ts, us = ((r.t,), (r.u,)) if isinstance(r, Intersection) else (r.t, r.u)
        for t, u in zip(ts, us):
            case.check(0.0 <= t <= 1.0 and 0.0 <= u <= 1.0, "parameter outside [0, 1]", r)
            gap = float(np.linalg.norm(a(t) - other(u)))
            case.check(gap <= near, f"the curves are {gap:.3g} apart at a contact (bound {near:.3g})", r)
        if b is None and isinstance(r, Intersection):
            case.check(r.t < r.u, "a self-intersection should have t < u", r)


def maps_onto(case: Case, src: tuple[RationalBezier, RationalBezier], res: IntersectionList,
              dst: tuple[RationalBezier, RationalBezier], got: IntersectionList, move, what: str) -> None:
    """Every clean crossing ``(t, u)`` of ``res`` is found in ``got`` at ``move(t, u)``."""
    for r in crossings(*src, res):
        t2, u2 = move(r.t, r.u)
        tol = max(param_tol(src[0], r.t, src[1], r.u), param_tol(dst[0], t2, dst[1], u2))
        case.check(has(got, t2, u2, tol), f"{what}: the crossing {r} is not at {(t2, u2)}", list(got), dst)


def run(a: RationalBezier, b: RationalBezier | None = None, **kw) -> IntersectionList:
    return intersect(a, b, on_budget="return", **kw)


# ----------------------------------------------------------------------------- constructor
BAD_ENTRIES = [  # (entry, error, built-in, words the message must hold)
    (float("nan"), NonFiniteError, ValueError, ("finite", "nan")),
    (float("inf"), NonFiniteError, ValueError, ("finite", "inf")),
    (10**400, NonFiniteError, ValueError, ("finite", "too large")),
    ("1.5", InputTypeError, TypeError, ("real numbers", "str")),
    (1 + 2j, InputTypeError, TypeError, ("real numbers", "complex")),
    (None, InputTypeError, TypeError, ("real numbers", "NoneType")),
]


@st.composite
def constructor_inputs(draw: st.DrawFn) -> tuple[object, object, tuple | None]:
    """Control points and weights, valid or with one defect; the expected refusal or None."""
    dim = draw(st.sampled_from([2, 3]))
    n = draw(st.integers(1, 6))
    mag = 10.0 ** draw(st.integers(-8, 8))
    pts = [[draw(st.floats(-1, 1)) * mag for _ in range(dim)] for _ in range(n + 1)]
    w = [draw(st.floats(0.1, 10.0)) for _ in range(n + 1)] if draw(st.booleans()) else None
    defect = draw(st.sampled_from(["none"] * 4 + ["entry", "weight", "shape", "one point", "ragged",
                                                  "ratio", "weights length", "curve"]))
    if defect == "entry":
        entry, err, builtin, words = draw(st.sampled_from(BAD_ENTRIES))
        pts[draw(st.integers(0, n))][draw(st.integers(0, dim - 1))] = entry
        return pts, w, (err, builtin, ("control_points", *words))
    if defect == "weight":
        w = [1.0] * (n + 1)
        w[draw(st.integers(0, n))] = draw(st.sampled_from([0.0, -1.0, -1e-300]))
        return pts, w, (WeightError, ValueError, ("weights", "> 0"))
    if defect == "shape":
        return [p + [0.0] * (4 - dim) for p in pts], w, (ShapeError, ValueError, ("shape", "not (",))
    if defect == "one point":
        return pts[:1], None, (DegreeError, ValueError, ("at least 2", "not 1"))
    if defect == "ragged":
        pts[-1] = pts[-1][:1]
        return pts, None, (InputTypeError, TypeError, ("control_points", "ragged"))
    if defect == "ratio":
        return pts, [1.0] * n + [1e16], (WeightError, ValueError, ("max / min", "1e+16"))
    if defect == "weights length":
        return pts, [1.0] * (n + 2), (ShapeError, ValueError, ("weights", f"({n + 1},)", f"({n + 2},)"))
    if defect == "curve":
        return RationalBezier([[0, 0], [1, 1]]), None, (InputTypeError, TypeError, ("RationalBezier",))
    return pts, w, None


@fuzz("core: RationalBezier()", constructor_inputs(), examples=1500, min_answered=0.2, max_answered=0.6)
def test_fuzz_constructor(case: Case, drawn: tuple[object, object, tuple | None]) -> None:
    pts, w, refusal = drawn
    if refusal is not None:
        err, builtin, words = refusal
        case.refuses(lambda: RationalBezier(pts, w), builtin, *words, error=err)
        return
    c = RationalBezier(pts, w)
    again = RationalBezier(pts, w)
    arr = np.asarray(pts, dtype=float)
    case.check(np.array_equal(c.control_points, arr) and c.degree == len(pts) - 1 and c.dim == arr.shape[1])
    case.check(c == again and hash(c) == hash(again), "same input, different curve")
    scale = float(np.abs(arr).max()) or 1.0
    ends = c.evaluate([0.0, 1.0])
    case.check(np.allclose(ends, arr[[0, -1]], rtol=0, atol=4 * EPS * scale), "ends", ends, arr)
    back = RationalBezier.from_homogeneous(c.homogeneous)
    case.check(np.allclose(back(SAMPLES), c(SAMPLES), rtol=0, atol=1e-13 * scale))
    case.answered()


# ----------------------------------------------------------------------------- curve operations
BAD_PARAMS = [  # (value, error, built-in, words)
    (None, InputTypeError, TypeError, ("real number", "NoneType")),
    ("a", InputTypeError, TypeError, ("real number", "str")),
    (True, InputTypeError, TypeError, ("real number", "bool")),
    ([0.5], InputTypeError, TypeError, ("real number", "list")),
    (0.5j, InputTypeError, TypeError, ("real number", "complex")),
    (float("nan"), NonFiniteError, ValueError, ("finite", "nan")),
    (10**400, NonFiniteError, ValueError, ("finite", "too large")),
]
BAD_ELEVATE = [
    (-1, DegreeError, ValueError, ("int >= 0", "-1")),
    (300, DegreeError, ValueError, ("at most 256", "would give degree")),
    ("a", InputTypeError, TypeError, ("int", "str")),
    (1.0, InputTypeError, TypeError, ("int", "float")),
    (None, InputTypeError, TypeError, ("int", "NoneType")),
    (True, InputTypeError, TypeError, ("int", "bool")),
]


def _close(case: Case, f: RationalBezier, g_values: np.ndarray, c: RationalBezier, what: str) -> None:
    scale = 1.0 + float(np.abs(c.control_points).max())
    got = f(SAMPLES)
    case.check(np.allclose(got, g_values, rtol=0, atol=1e-10 * scale), what, got, g_values)


# about a quarter of the split/segment/elevate cases draw bad arguments; hypothesis favours the small
# integers, so 40-50 % of all cases are refusals in practice (the bounds say "mostly answered", no more)
@fuzz("core: split/segment/elevate/reversed", curves(max_degree=5), st.sampled_from(["split", "segment",
      "elevate", "reversed"]), st.integers(0, 3), inner, unit, st.integers(0, 5),
      examples=1200, min_answered=0.3, max_answered=0.9)
def test_fuzz_curve_operations(case: Case, c: RationalBezier, op: str, bad: int, s: float, s2: float,
                               i: int) -> None:
    if bad == 0 and op in ("split", "segment"):
        value, err, builtin, words = BAD_PARAMS[i % len(BAD_PARAMS)]
        call = (lambda: c.split(value)) if op == "split" else (lambda: c.segment(s, value))
        case.refuses(call, builtin, *words, error=err)
        return
    if bad == 0 and op == "elevate":
        value, err, builtin, words = BAD_ELEVATE[i]
        case.refuses(lambda: c.elevate(value), builtin, *words, error=err)
        return
    if op == "split":
        left, right = c.split(s)
        _close(case, left, c(s * SAMPLES), c, "left piece")
        _close(case, right, c(s + (1 - s) * SAMPLES), c, "right piece")
        case.check(np.array_equal(left.homogeneous[-1], right.homogeneous[0]), "pieces do not join exactly")
    elif op == "segment":
        if s == s2:
            case.refuses(lambda: c.segment(s, s2), ValueError, "t0 != t1", error=DegenerateCurveError)
            return
        _close(case, c.segment(s, s2), c(s + (s2 - s) * SAMPLES), c, "segment")
    elif op == "elevate":
        e = c.elevate(i)
        case.check(e.degree == c.degree + i)
        _close(case, e, c(SAMPLES), c, "elevated")
    else:
        r = c.reversed()
        _close(case, r, c(1.0 - SAMPLES), c, "reversed")
        case.check(r.reversed() == c, "reversing twice changed the curve")
    case.answered()


# ----------------------------------------------------------------------------- metamorphic relations
def _swap(case: Case, pair: tuple[RationalBezier, RationalBezier]) -> None:
    a, b = pair
    ab, ba = run(a, b), run(b, a)
    check_answer(case, a, b, ab)
    check_answer(case, b, a, ba)
    maps_onto(case, (a, b), ab, (b, a), ba, lambda t, u: (u, t), "swap")
    maps_onto(case, (b, a), ba, (a, b), ab, lambda t, u: (u, t), "swap back")
    case.answered()


@fuzz("core: swap a, b (plane)", pairs(2), examples=700, min_answered=1.0)
def test_fuzz_swap_planar(case: Case, pair: tuple[RationalBezier, RationalBezier]) -> None:
    _swap(case, pair)


@fuzz("core: swap a, b (space)", pairs(3), examples=400, min_answered=1.0)
def test_fuzz_swap_space(case: Case, pair: tuple[RationalBezier, RationalBezier]) -> None:
    _swap(case, pair)


@fuzz("core: reversal t -> 1 - t", st.sampled_from([2, 3]).flatmap(pairs), examples=700, min_answered=1.0)
def test_fuzz_reversal(case: Case, pair: tuple[RationalBezier, RationalBezier]) -> None:
    a, b = pair
    ab, rev = run(a, b), run(a.reversed(), b)
    check_answer(case, a.reversed(), b, rev)
    maps_onto(case, (a, b), ab, (a.reversed(), b), rev, lambda t, u: (1.0 - t, u), "reversal")
    case.answered()


@fuzz("core: similarity maps", st.sampled_from([2, 3]).flatmap(
    lambda d: st.tuples(pairs(d), similarities(d))), st.integers(-20, 20), examples=700, min_answered=1.0)
def test_fuzz_similarity(case: Case, drawn: tuple, k: int) -> None:
    (a, b), m = drawn
    ab = run(a, b)
    ma, mb = a.transformed(m), b.transformed(m)
    mapped = run(ma, mb)
    check_answer(case, ma, mb, mapped)
    maps_onto(case, (a, b), ab, (ma, mb), mapped, lambda t, u: (t, u), "similarity")
    # a power-of-two scale is exact: the answer is the same, bit for bit
    p = np.diag([2.0**k] * a.dim + [1.0])
    scaled = run(a.transformed(p), b.transformed(p))
    case.check([(r.t, r.u, r.kind) for r in scaled.points] == [(r.t, r.u, r.kind) for r in ab.points],
               "scaling by a power of two changed the parameters", list(ab), list(scaled))
    case.answered()


@fuzz("core: degree elevation", st.sampled_from([2, 3]).flatmap(pairs), st.integers(1, 3),
      examples=500, min_answered=1.0)
def test_fuzz_elevation(case: Case, pair: tuple[RationalBezier, RationalBezier], r: int) -> None:
    a, b = pair
    ea, eb = a.elevate(r), b.elevate(r - 1)
    ab, up = run(a, b), run(ea, eb)
    check_answer(case, ea, eb, up)
    maps_onto(case, (a, b), ab, (ea, eb), up, lambda t, u: (t, u), "elevation")
    case.answered()


@fuzz("core: splitting", st.sampled_from([2, 3]).flatmap(pairs), inner, examples=500, min_answered=0.95)
def test_fuzz_splitting(case: Case, pair: tuple[RationalBezier, RationalBezier], s: float) -> None:
    a, b = pair
    ab = run(a, b)
    left, right = a.split(s)
    halves = IntersectionList(
        [Intersection(s * r.t, r.u, r.point, r.kind) for r in run(left, b).points]
        + [Intersection(s + (1 - s) * r.t, r.u, r.point, r.kind) for r in run(right, b).points])
    far = IntersectionList([r for r in ab if not isinstance(r, Intersection) or abs(r.t - s) > 1e-3])
    maps_onto(case, (a, b), far, (a, b), halves, lambda t, u: (t, u), "split")
    case.answered()


@fuzz("core: determinism", st.sampled_from([2, 3]).flatmap(pairs), st.booleans(), examples=400,
      min_answered=1.0)
def test_fuzz_determinism(case: Case, pair: tuple[RationalBezier, RationalBezier], self_: bool) -> None:
    a, b = pair
    b = None if self_ else b
    first = run(a, b)
    copy_a = RationalBezier(a.control_points.copy(), a.weights.copy())
    copy_b = None if b is None else RationalBezier(b.control_points.copy(), b.weights.copy())
    again = run(copy_a, copy_b)
    case.check(repr(first) == repr(again) and first.unresolved == again.unresolved,
               "the same input gave another answer", first, again)
    case.answered()


@fuzz("core: self-intersection", curves(dim=2, min_degree=3, max_degree=5),
      st.sampled_from([2, 3]).flatmap(similarities), examples=300, min_answered=1.0)
def test_fuzz_self_intersection(case: Case, c: RationalBezier, m: np.ndarray) -> None:
    c = c.embedded(m.shape[0] - 1)
    res = run(c)
    check_answer(case, c, None, res)
    rev = c.reversed()
    maps_onto(case, (c, c), res, (rev, rev), run(rev), lambda t, u: (1.0 - u, 1.0 - t), "reversal")
    mc = c.transformed(m)
    maps_onto(case, (c, c), res, (mc, mc), run(mc), lambda t, u: (t, u), "similarity")
    case.answered()


# ----------------------------------------------------------------------------- intersect_many, intersect_line
@fuzz("core: intersect_many", st.lists(pairs(2, 3), min_size=1, max_size=5), examples=300, min_answered=1.0)
def test_fuzz_intersect_many(case: Case, plist: list[tuple[RationalBezier, RationalBezier]]) -> None:
    many = intersect_many(plist, on_budget="return")
    case.check(len(many) == len(plist))
    for (a, b), res in zip(plist, many):
        one = run(a, b)
        check_answer(case, a, b, res)
        maps_onto(case, (a, b), one, (a, b), res, lambda t, u: (t, u), "intersect_many vs intersect")
        maps_onto(case, (a, b), res, (a, b), one, lambda t, u: (t, u), "intersect vs intersect_many")
    case.answered()


def met_at(res: IntersectionList, t: float, u: float, tol: float, utol: float) -> bool:
    """True when ``res`` meets the line at ``(t, u)``: a point within ``tol`` / ``utol``, or an overlap
    covering it (a curve within ``tol_used`` of the line along a stretch, which a coarser rounding
    floor, after a move far from the origin, may make of a steep crossing of a tiny curve)."""
    return any(abs(q.t - t) <= tol and abs(q.u - u) <= utol for q in res.points) or any(
        min(o.t) - tol <= t <= max(o.t) + tol and min(o.u) - utol <= u <= max(o.u) + utol for o in res.overlaps)


def line_crossings(c: RationalBezier, d: np.ndarray, res: IntersectionList) -> list[Intersection]:
    out = []
    for r in res.points:
        if r.kind == "crossing" and 1e-4 < r.t < 1 - 1e-4 and all(
                q is r or abs(q.t - r.t) > 1e-3 for q in res.points):
            dc = c.derivative(r.t)
            speed = float(np.linalg.norm(dc))
            if speed > 0.0 and abs(dc[0] * d[1] - dc[1] * d[0]) / speed > 0.05:
                out.append(r)
    return out


# a segment 2.3e-95 long: the reparametrised line's point p + d rounds to d (numpy 1.26 drew it)
_TINY_LINE = (RationalBezier([[0.0, 0.0], [0.0, 2.32789e-95]]), 0.5, 1.0, np.eye(3), 1.0)


@fuzz("core: intersect_line", curves(dim=2, max_degree=5), inner, st.floats(-math.pi, math.pi),
      similarities(2), st.floats(-3, 3), examples=600, min_answered=1.0, explicit=[_TINY_LINE])
def test_fuzz_intersect_line(case: Case, c: RationalBezier, t0: float, angle: float, m: np.ndarray,
                             lam: float) -> None:
    p, d = c(t0), np.array([math.cos(angle), math.sin(angle)])  # a line through c(t0)
    res = intersect_line(c, p, d, on_budget="return")
    near = bound(c)
    big = float(np.abs(c.control_points).max())
    for r in res.points:
        case.check(float(np.linalg.norm(c(r.t) - (p + r.u * d))) <= near * (1 + abs(r.u)), r)
    for o in res.overlaps:  # a stretch on the line: its ends are on the line at the given u
        for t, u in zip(o.t, o.u, strict=True):
            case.check(float(np.linalg.norm(c(t) - (p + u * d))) <= near * (1 + abs(u)), o)
    moved = intersect_line(c.transformed(m), m[:2, :2] @ p + m[:2, 2], m[:2, :2] @ d, on_budget="return")
    back = intersect_line(c, p + lam * d, -d, on_budget="return")
    # a point within tol_used of the line is a meeting: a crossing's parameter is known to
    # tol_used / (speed * sine), sine > 0.05 (a curve shorter than the tolerance, e.g. 7e-23 long
    # against the default 1e-9 of a line through a point 1 away, may be met at any t)
    used = max(res.tol_used, moved.tol_used / float(np.linalg.norm(m[:2, 0])), back.tol_used)
    # and the reparametrised line is only known to the rounding of its point p + lam d: beside a
    # tiny curve that is a shift of many times its length (p lost entirely at |p| = 1e-95)
    used = max(used, 2.0 * EPS * float(np.abs(p + lam * d).max()))
    for r in line_crossings(c, d, res):
        speed = float(np.linalg.norm(c.derivative(r.t)))
        tol = 1e-9 + 1e5 * EPS * big * (1 + abs(r.u)) / min(speed, 1.0) / 0.05 + used / min(speed, 1.0) / 0.05
        case.check(met_at(moved, r.t, r.u, tol, tol), "similarity", r, list(moved))
        case.check(met_at(back, r.t, lam - r.u, tol, tol * (1 + abs(lam))), "line reparametrised", r, list(back))
    dc = c.derivative(t0)
    speed = float(np.linalg.norm(dc))
    # crosses at t0 (a curve within the tolerance of the line all along, e.g. one ulp long at x = 1,
    # may be met anywhere: one contact within tol_used is the answer there)
    if speed > 1e-3 * size(c) > 1e3 * res.tol_used and abs(dc[0] * d[1] - dc[1] * d[0]) > 0.05 * speed:
        case.check(met_at(res, t0, 0.0, 1e-6, 1e-6 * (1 + big)), "the line through c(t0) misses c(t0)", t0, list(res))
    case.answered()


# ----------------------------------------------------------------------------- bad arguments
C2 = RationalBezier([[0, 0], [1, 2], [2, 0]])
C3 = RationalBezier([[0, 0, 0], [1, 2, 1], [2, 0, 0]])
BAD_ARGS = [  # (call on (a, b), error, built-in, words)
    (lambda a, b: intersect(a, "b"), InputTypeError, TypeError, ("b should be a RationalBezier", "str")),
    (lambda a, b: intersect(5, b), InputTypeError, TypeError, ("a should be a RationalBezier", "int")),
    (lambda a, b: intersect(a, b, tol="1e-3"), ToleranceError, TypeError, ("tol should be", "str")),
    (lambda a, b: intersect(a, b, tol=[1e-6]), ToleranceError, TypeError, ("tol should be", "list")),
    (lambda a, b: intersect(a, b, tol=True), ToleranceError, TypeError, ("tol should be", "bool")),
    (lambda a, b: intersect(a, b, tol=-1.0), ToleranceError, ValueError, ("tol should be", "-1.0")),
    (lambda a, b: intersect(a, b, tol=float("nan")), ToleranceError, ValueError, ("tol should be", "nan")),
    (lambda a, b: intersect(a, b, tol=10**400), ToleranceError, ValueError, ("tol should be", "digits")),
    (lambda a, b: intersect(a, b, budget=10**30), InvalidInputError, ValueError, ("budget should", str(10**30))),
    (lambda a, b: intersect(a, b, budget=2.5), InputTypeError, TypeError, ("budget should", "float")),
    (lambda a, b: intersect(a, b, on_budget="ignore"), InvalidInputError, ValueError,
     ("on_budget should", "'ignore'")),
    (lambda a, b: intersect(a, budget=0), InvalidInputError, ValueError, ("budget should", "not 0")),
    (lambda a, b: intersect_many(5), InputTypeError, TypeError, ("pairs should be", "int")),
    (lambda a, b: intersect_many([(a, b, a)]), InputTypeError, TypeError, ("pairs[0] should be", "tuple")),
    (lambda a, b: intersect_many([(a, 1.5)]), InputTypeError, TypeError, ("pairs[0][1]", "float")),
    (lambda a, b: intersect_many([(a, b)], tol=10**400), ToleranceError, ValueError, ("tol should", "digits")),
    (lambda a, b: intersect_line(a, "ab", (1, 0)), InputTypeError, TypeError, ("point", "str")),
    (lambda a, b: intersect_line(a, (0, 0), (0, 0)), InvalidInputError, ValueError,
     ("direction should be nonzero", "(0, 0)")),
    (lambda a, b: intersect_line(a, (0, 0, 0), (1, 0)), ShapeError, ValueError, ("shape (2,)", "(3,)")),
    (lambda a, b: default_tolerance(), InputTypeError, TypeError, ("needs at least one",)),
    (lambda a, b: default_tolerance("abc"), InputTypeError, TypeError, ("real numbers", "str")),
]


@fuzz("core: bad arguments", st.sampled_from(range(len(BAD_ARGS))), curves(dim=2), st.booleans(),
      examples=600, min_answered=0.0, max_answered=0.0)
def test_fuzz_bad_arguments(case: Case, i: int, c: RationalBezier, space: bool) -> None:
    call, err, builtin, words = BAD_ARGS[i]
    planar_only = "intersect_line" in call.__code__.co_names
    a, b = (c.embedded(3), C3) if space and not planar_only else (c, C2)
    case.refuses(lambda: call(a, b), builtin, *words, error=err)


# ----------------------------------------------------------------------------- relief maps
@st.composite
def space_curves_in_front(draw: st.DrawFn, k: float) -> RationalBezier:
    c = draw(curves(dim=3, max_degree=4))
    lo = float(c.control_points[:, 2].min())
    return shifted(c, np.array([0.0, 0.0, draw(st.floats(0.1, 5.0)) - lo]))  # every z > 0 > -k


@fuzz("core: relief maps", spans.flatmap(lambda k: st.tuples(st.just(k), space_curves_in_front(k))),
      curves(dim=2, max_degree=4), examples=800, min_answered=1.0)
def test_fuzz_relief_maps(case: Case, drawn: tuple[float, RationalBezier], p: RationalBezier) -> None:
    k, q = drawn
    phi = ReliefPerspective(k)
    pts = q(SAMPLES)

    def close(x: np.ndarray, y: np.ndarray, what: str, rel: float = 1e-9) -> None:
        case.check(np.allclose(x, y, rtol=0, atol=rel * (1.0 + float(np.abs(y).max()))), what, x, y)

    close(phi.inverse(phi.apply(pts)), pts, "inverse of apply")
    close(phi.apply(q)(SAMPLES), phi.apply(pts), "the relief of a curve is the curve of the reliefs")
    close(central_projection(q)(SAMPLES), central_projection(pts), "projection of a curve")
    close(central_projection(lift(p))(SAMPLES), p(SAMPLES), "the lift projects back")
    close(relief_of_lift(p, k)(SAMPLES), phi.apply(lift(p)(SAMPLES)), "relief_of_lift")
    if float(p.weights.max()) < 1.0 + k:
        pre = preimage_of_lift(p, k)
        close(phi.apply(pre)(SAMPLES), lift(p)(SAMPLES), "theorem: phi(Q) = lift(P)", 1e-8)
        close(central_projection(pre)(SAMPLES), p(SAMPLES), "psi(Q) = P", 1e-8)
    else:
        case.check(isinstance(_raises(lambda: preimage_of_lift(p, k)), WeightError), "inadmissible k")
    case.answered()


def _raises(call) -> BaseException | None:
    try:
        call()
    except Exception as exc:  # noqa: BLE001  the caller checks the class
        return exc
    return None


BAD_RELIEF = [
    (lambda k: ReliefPerspective(k), "k"),
    (lambda k: preimage_of_lift(C2, k), "k"),
    (lambda k: relief_of_lift(C2, k), "k"),
    (lambda k: ReliefPerspective(2.0).apply(C2), "dim"),
    (lambda k: central_projection("curve"), "type"),
    (lambda k: lift(C3), "dim"),
    (lambda k: central_projection(shifted(C3, np.array([0, 0, -5.0]))), "behind"),
    (lambda k: ReliefPerspective(2.0).apply([0.0, 0.0, -2.0]), "neutral"),
    (lambda k: ReliefPerspective(2.0).apply(shifted(C3, np.array([0, 0, -5.0]))), "past infinity"),
]
BAD_SPANS = [(1.0, SpanError, ValueError, ("!= 1", "1.0")), (0.0, SpanError, ValueError, ("> 0", "0.0")),
             (-2.0, SpanError, ValueError, ("> 0", "-2.0")), (float("nan"), SpanError, ValueError, ("nan",)),
             (10**400, SpanError, ValueError, ("too large",)), ("2", InputTypeError, TypeError, ("str",)),
             (None, InputTypeError, TypeError, ("NoneType",)), (True, InputTypeError, TypeError, ("bool",))]
OTHER_RELIEF = {
    "dim": (ShapeError, ValueError, ("should be a", "-D curve")),
    "type": (InputTypeError, TypeError, ("real numbers", "str")),
    "behind": (ProjectionError, ValueError, ("in front of the centre", "z = -")),
    "neutral": (ProjectionError, ValueError, ("neutral plane", "[0.0, 0.0, -2.0]")),
    "past infinity": (ProjectionError, ValueError, ("should all be > 0", "becomes")),
}


@fuzz("core: relief maps, bad input", st.integers(0, len(BAD_RELIEF) - 1), st.integers(0, len(BAD_SPANS) - 1),
      examples=300, min_answered=0.0, max_answered=0.0)
def test_fuzz_relief_bad_input(case: Case, i: int, j: int) -> None:
    call, kind = BAD_RELIEF[i]
    if kind == "k":
        k, err, builtin, words = BAD_SPANS[j]
        case.refuses(lambda: call(k), builtin, "span k", *words, error=err)
    else:
        err, builtin, words = OTHER_RELIEF[kind]
        case.refuses(lambda: call(None), builtin, *words, error=err)


# ----------------------------------------------------------------------------- audit: issue 15 items
def test_huge_tolerance_is_refused_and_accepted_ones_do_not_depend_on_the_order() -> None:
    # with tol=1e300, far beyond the curves' size, intersect(a, b) and intersect(b, a) gave different
    # answers (2 overlaps and 3): such a tolerance is refused; up to the cap the order does not matter
    a = RationalBezier([[0.3, -0.5], [-0.9, -1.0]])
    b = RationalBezier([[0.6, 0.8], [0.2, 0.5], [0.1, 0.9]])
    for x, y in ((a, b), (b, a)):
        with pytest.raises(ToleranceError, match="should be at most 0.01 of the inputs' size"):
            intersect(x, y, tol=1e300)
    rng = np.random.default_rng(3)
    for _ in range(40):
        a, b = RationalBezier(rng.random((3, 2))), RationalBezier(rng.random((4, 2)))
        tol = 0.009 * size(a, b)
        ab, ba = intersect(a, b, tol=tol), intersect(b, a, tol=tol)
        assert sorted((r.kind, round(r.u, 6), round(r.t, 6)) for r in ab.points) == sorted(
            (r.kind, round(r.t, 6), round(r.u, 6)) for r in ba.points), (ab, ba)
        assert len(ab.overlaps) == len(ba.overlaps)


def test_curve_against_itself_at_the_largest_degree_answers() -> None:
    # a random curve of the largest supported degree (256) against itself, or its reverse, ran for
    # minutes in the sampled coincidence test (O(n^3)); an exact copy is now one Overlap at once
    code = ("import numpy as np; from relief_cad import RationalBezier, intersect; "
            "c = RationalBezier(np.random.default_rng(0).random((257, 2))); "
            "print(intersect(c, c), intersect(c, c.reversed()))")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=30,
                          cwd=Path(__file__).resolve().parents[2])
    assert proc.stdout.strip() == ("[Overlap(t=(0.0, 1.0), u=(0.0, 1.0), kind='overlap')] "
                                   "[Overlap(t=(0.0, 1.0), u=(1.0, 0.0), kind='overlap')]"), proc.stderr


def test_fold_back_overlap_starts_where_the_curve_comes_back() -> None:
    """A curve that leaves a shared start point and comes back along the other curve (found by
    tests/adapters/test_fuzz_cad.py through cad.split, which lost a piece): one Overlap from where
    it comes back, and the start is a separate (tangent) contact; both argument orders."""
    a = RationalBezier([[0, 0], [-1, 0], [1, 0]])  # x(t) = 3t^2 - 2t: negative on (0, 2/3)
    b = RationalBezier([[0, 0], [0.5, 0]])
    back = (2 / 3, (2 + math.sqrt(10)) / 6)
    res = intersect(a, b)
    assert [o.t for o in res.overlaps] == [pytest.approx(back)] and [o.u for o in res.overlaps] == [(0.0, 1.0)]
    assert [(p.t, p.u, p.kind) for p in res.points] == [(0.0, 0.0, "tangent")]
    swapped = intersect(b, a)
    assert [o.u for o in swapped.overlaps] == [pytest.approx(back)] and [o.t for o in swapped.overlaps] == [(0.0, 1.0)]
    assert [(p.t, p.u, p.kind) for p in swapped.points] == [(0.0, 0.0, "tangent")]

r"""Rational Bézier curves in the plane and in space.

A rational Bézier curve of degree ``n`` with control points ``V_i`` (rows of an
``(n + 1, d)`` array, ``d`` in {2, 3}) and weights ``w_i > 0`` is

.. math::

    P(t) = \frac{\sum_i w_i V_i B_i^n(t)}{\sum_i w_i B_i^n(t)}, \qquad t \in [0, 1].

Internally the curve is kept as its *homogeneous* control points
``[w_i V_i, w_i]`` (shape ``(n + 1, d + 1)``): a polynomial curve one
dimension up, on which evaluation, subdivision and projective maps are plain
linear algebra. Evaluation and subdivision use de Casteljau's algorithm on
these homogeneous points (stable; no power basis).

>>> import numpy as np
>>> arc = RationalBezier([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], [1.0, np.sqrt(0.5), 1.0])
>>> p = arc(0.5)
>>> bool(np.isclose(np.hypot(*p), 1.0))
True
"""

from __future__ import annotations

import functools
import math
from typing import overload

import numpy as np

from ._checks import (
    MAX_WEIGHT_RATIO,
    as_real_array,
    check_count,
    check_degree,
    check_finite,
    check_param,
    check_weights,
)
from ._kernels.batch import kernel_views
from ._kernels.bezier import bernstein_product, decasteljau_rows, homogeneous_rows, split_rows
from ._types import FloatArray, ParamsLike, PointsLike
from .errors import (
    DegenerateCurveError,
    DegreeError,
    ProjectionError,
    ReliefCadError,
    ShapeError,
    WeightError,
)

__all__ = ["RationalBezier"]


def _decasteljau(h: FloatArray, t: FloatArray) -> tuple[FloatArray, FloatArray]:
    """Evaluate homogeneous control points ``h`` (n+1, k) at parameters ``t`` (m,).

    Returns the values ``H(t)`` (m, k) and derivatives ``H'(t)`` (m, k). Float data go through the
    compiled :func:`relief_cad._kernels.bezier.decasteljau_rows` (the same operations in the same
    order: the same bits); the numpy form below serves exact data (``Fraction`` objects).
    """
    if h.dtype == np.float64 and t.dtype == np.float64:
        return decasteljau_rows(h, t)  # type: ignore[no-any-return]
    n = h.shape[0] - 1
    m = t.shape[0]
    b = np.broadcast_to(h, (m,) + h.shape).copy()
    s = (1 - t)[:, None, None]
    tt = t[:, None, None]
    for r in range(1, n):
        b[:, : n + 1 - r] = s * b[:, : n + 1 - r] + tt * b[:, 1 : n + 2 - r]
    b0 = b[:, 0]
    b1 = b[:, 1]
    value = s[:, 0] * b0 + tt[:, 0] * b1
    deriv = n * (b1 - b0)
    return value, deriv


def _blossom_rows(h: FloatArray, params: FloatArray) -> FloatArray:
    """Blossom values: row ``j`` is the blossom of ``h`` at the n arguments ``params[j]``.

    ``params`` has shape (r, n); returns (r, k).
    """
    n = h.shape[0] - 1
    r = params.shape[0]
    b = np.broadcast_to(h, (r,) + h.shape).copy()
    for level in range(1, n + 1):
        tt = params[:, level - 1][:, None, None]
        b[:, : n + 1 - level] = (1.0 - tt) * b[:, : n + 1 - level] + tt * b[:, 1 : n + 2 - level]
    out: FloatArray = b[:, 0].copy()
    return out


def _product_bernstein(f: FloatArray, g: FloatArray) -> FloatArray:
    """Bernstein coefficients of the product of two Bernstein polynomials (rows are coefficients).

    ``f`` (p + 1,) or (p + 1, kf), ``g`` (q + 1,) or (q + 1, kg), with ``kf``, ``kg`` equal or 1.
    Term ``(i, j)`` is ``((C(p, i) C(q, j)) f_i) g_j``, the integer factor rounded once to a float,
    added to row ``i + j`` in order of ``i``; then row ``r`` is divided by ``C(p + q, r)``. Compiled
    (:func:`relief_cad._kernels.bezier.bernstein_product`).

    >>> _product_bernstein(np.array([1.0, 2.0]), np.array([3.0, 1.0])).tolist()   # (1 + t)(3 - 2t)
    [3.0, 3.5, 2.0]
    """
    fac, den = _product_factors(f.shape[0] - 1, g.shape[0] - 1)
    out: FloatArray = bernstein_product(f.reshape(f.shape[0], -1), g.reshape(g.shape[0], -1), fac, den)
    return out if f.ndim > 1 or g.ndim > 1 else out[:, 0]


@functools.cache
def _product_factors(p: int, q: int) -> tuple[FloatArray, FloatArray]:
    """``C(p, i) C(q, j)`` (p + 1, q + 1) and ``C(p + q, r)`` (p + q + 1,), each rounded once to a float."""
    fac = np.array([[float(math.comb(p, i) * math.comb(q, j)) for j in range(q + 1)] for i in range(p + 1)])
    den = np.array([float(math.comb(p + q, r)) for r in range(p + q + 1)])
    fac.flags.writeable = False
    den.flags.writeable = False
    return fac, den


def _elevate_rows(h: FloatArray, times: int) -> FloatArray:
    for _ in range(times):
        n = h.shape[0] - 1
        new = np.empty((n + 2,) + h.shape[1:])
        new[0] = h[0]
        new[n + 1] = h[n]
        for i in range(1, n + 1):
            a = i / (n + 1)
            new[i] = a * h[i - 1] + (1.0 - a) * h[i]
        h = new
    return h


class RationalBezier:
    """An immutable rational Bézier curve in the plane (d = 2) or in space (d = 3).

    Parameters
    ----------
    control_points : array_like, shape (n + 1, d)
        Control points ``V_i`` as rows, ``d`` in {2, 3}, ``n >= 1``.
    weights : array_like, shape (n + 1,), optional
        Weights ``w_i > 0``. ``None`` means all ones (a polynomial curve).

    Raises
    ------
    ShapeError
        If ``control_points`` is not ``(n + 1, 2)`` or ``(n + 1, 3)``, or ``weights`` does not
        have ``n + 1`` entries.
    DegreeError
        If there is only one control point (degree 0 is not a curve).
    NonFiniteError
        If a coordinate or weight is NaN or infinite.
    WeightError
        If a weight is zero or negative.

    Examples
    --------
    >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]])
    >>> c.degree, c.dim
    (2, 2)
    >>> c(0.5).tolist()
    [1.0, 1.0]
    >>> RationalBezier([[0, 0]])
    Traceback (most recent call last):
    ...
    relief_cad.errors.DegreeError: A curve needs at least 2 control points (degree >= 1), not 1.
    """

    __slots__ = ("_h", "_points", "_weights", "_polynomial", "_hodo", "_sbox", "_kv")

    _h: FloatArray
    _points: FloatArray | None
    _weights: FloatArray | None
    _polynomial: bool | None
    _hodo: RationalBezier | None  # the hodograph, built on first use (the curve is immutable)
    # the sampled box of the default tolerance, filled on first use by
    # relief_cad._kernels.bezier.sampled_tolerance (False: a degenerate sample)
    _sbox: tuple[float, float, float, float, float, float, float, int] | bool | None
    _kv: tuple[object, object] | None  # the control points and weights as the pair kernel takes them

    def __init__(self, control_points: PointsLike, weights: ParamsLike | None = None) -> None:
        pts = as_real_array(control_points, "control_points")
        if pts.ndim != 2 or pts.shape[1] not in (2, 3):
            raise ShapeError(
                f"control_points should have shape (n + 1, 2) or (n + 1, 3), not {pts.shape}"
            )
        if pts.shape[0] < 2:
            raise DegreeError(
                f"A curve needs at least 2 control points (degree >= 1), not {pts.shape[0]}."
            )
        check_degree(pts.shape[0] - 1)
        w = None if weights is None else _weights_of(weights, pts)
        # the rows in one compiled pass; None when a check fails, and the checks name it
        h = homogeneous_rows(pts, w, MAX_WEIGHT_RATIO)
        if h is None:
            h = _checked_rows(pts, w)
        self._set(h, pts, w)

    def _set(self, h: FloatArray, pts: FloatArray | None, w: FloatArray | None) -> None:
        h.flags.writeable = False
        self._h = h
        self._points = pts
        self._weights = w
        self._polynomial = None
        self._hodo = None
        self._sbox = None
        self._kv = None
        for arr in (pts, w):
            if arr is not None:
                arr.flags.writeable = False

    @classmethod
    def _trusted(cls, h: FloatArray) -> RationalBezier:
        """Build from homogeneous points known to be finite with positive weights (no checks).

        The Cartesian points and weights are derived on first use (this is the hot path of
        subdivision and of the CAD adapters).
        """
        obj = cls.__new__(cls)
        obj._set(np.array(h, dtype=np.float64), None, None)
        return obj

    @classmethod
    def _rebuilt(cls, pts: FloatArray, w: FloatArray) -> RationalBezier:
        """``RationalBezier(pts, w)`` for a valid curve's own ``control_points`` and ``weights``.

        The rows the constructor makes (``pts * w``, then ``w``) and the same arrays, without the
        checks the arrays passed when their curve was built; rows that overflow go through the
        constructor, which refuses them.
        """
        h = np.empty((pts.shape[0], pts.shape[1] + 1))
        with np.errstate(over="ignore", invalid="ignore"):
            h[:, :-1] = pts * w[:, None]
        h[:, -1] = w
        if not np.isfinite(h).all():
            return cls(pts, w)
        obj = cls.__new__(cls)
        obj._set(h, pts, w)
        return obj

    @classmethod
    def from_homogeneous(cls, homogeneous: PointsLike) -> RationalBezier:
        """Build a curve from homogeneous control points ``[w_i V_i, w_i]``.

        Parameters
        ----------
        homogeneous : array_like, shape (n + 1, d + 1)
            Rows ``(w x, w y, w)`` (planar) or ``(w x, w y, w z, w)`` (space); the last
            column holds the weights, which must be > 0.

        Returns
        -------
        RationalBezier

        Examples
        --------
        >>> RationalBezier.from_homogeneous([[0, 0, 1], [2, 2, 2], [2, 0, 1]]).control_points.tolist()
        [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
        >>> RationalBezier.from_homogeneous([[0, 0, 1], [1, 1, -1]])
        Traceback (most recent call last):
        ...
        relief_cad.errors.WeightError: homogeneous weights (last column) should all be > 0; weight 1 is -1.0
        """
        h = as_real_array(homogeneous, "homogeneous")
        if h.ndim != 2 or h.shape[1] not in (3, 4):
            raise ShapeError(
                f"homogeneous control points should have shape (n + 1, 3) or (n + 1, 4), not {h.shape}"
            )
        if h.shape[0] < 2:
            raise DegreeError(
                f"A curve needs at least 2 control points (degree >= 1), not {h.shape[0]}."
            )
        check_degree(h.shape[0] - 1)
        check_finite(h, "homogeneous")
        check_weights(h[:, -1], "homogeneous weights (last column)")
        pts = h[:, :-1] / h[:, -1:]
        check_finite(pts, "control points (homogeneous / weight)")
        obj = cls.__new__(cls)
        obj._set(h, pts, h[:, -1].copy())
        return obj

    # ------------------------------------------------------------------ properties
    @property
    def degree(self) -> int:
        """The degree ``n`` (number of control points minus one).

        >>> RationalBezier([[0, 0], [1, 1], [2, 0]]).degree
        2
        """
        return int(self._h.shape[0] - 1)

    @property
    def dim(self) -> int:
        """The dimension ``d`` of the space the curve lies in (2 or 3).

        >>> RationalBezier([[0, 0, 0], [1, 1, 1]]).dim
        3
        """
        return int(self._h.shape[1] - 1)

    @property
    def control_points(self) -> FloatArray:
        """Control points, shape ``(n + 1, d)``, read-only.

        >>> RationalBezier([[0, 0], [2, 4]], [1.0, 2.0]).control_points.tolist()
        [[0.0, 0.0], [2.0, 4.0]]
        """
        if self._points is None:
            pts = self._h[:, :-1] / self._h[:, -1:]
            pts.flags.writeable = False
            self._points = pts
        return self._points

    @property
    def weights(self) -> FloatArray:
        """Weights, shape ``(n + 1,)``, read-only, all > 0.

        >>> RationalBezier([[0, 0], [2, 4]]).weights.tolist()
        [1.0, 1.0]
        """
        if self._weights is None:
            w = self._h[:, -1].copy()
            w.flags.writeable = False
            self._weights = w
        return self._weights

    @property
    def homogeneous(self) -> FloatArray:
        """Homogeneous control points ``[w_i V_i, w_i]``, shape ``(n + 1, d + 1)``, read-only.

        >>> RationalBezier([[0, 0], [2, 4]], [1.0, 2.0]).homogeneous.tolist()
        [[0.0, 0.0, 1.0], [4.0, 8.0, 2.0]]
        """
        return self._h

    @property
    def is_polynomial(self) -> bool:
        """True when all weights are equal (the curve is a polynomial Bézier curve).

        >>> RationalBezier([[0, 0], [1, 1]], [2.0, 2.0]).is_polynomial
        True
        """
        if self._polynomial is None:
            w = self._h[:, -1]
            self._polynomial = bool(np.all(w == w[0]))
        return self._polynomial

    # ------------------------------------------------------------------ evaluation
    @overload
    def evaluate(self, t: float) -> FloatArray: ...

    @overload
    def evaluate(self, t: FloatArray) -> FloatArray: ...

    def evaluate(self, t: ParamsLike) -> FloatArray:
        """Evaluate the curve by homogeneous de Casteljau.

        Parameters
        ----------
        t : float or array_like, shape (m,)
            Parameters. Values outside ``[0, 1]`` extrapolate, as long as the
            curve's weight stays positive there.

        Returns
        -------
        ndarray, shape (d,) for a scalar ``t``, else (m, d)
            Points in model units.

        Raises
        ------
        NonFiniteError
            If a parameter is NaN or infinite.
        ProjectionError
            If the denominator ``sum w_i B_i(t)`` is not positive at a requested
            (extrapolated) parameter.

        Examples
        --------
        >>> c = RationalBezier([[0, 0], [1, 1]])
        >>> c.evaluate([0.0, 0.25]).tolist()
        [[0.0, 0.0], [0.25, 0.25]]
        >>> c.evaluate(float("nan"))
        Traceback (most recent call last):
        ...
        relief_cad.errors.NonFiniteError: t should be a finite number, not nan
        """
        values, _ = self._eval(t, derivative=False)
        return values

    __call__ = evaluate

    def derivative(self, t: ParamsLike) -> FloatArray:
        """Return the derivative ``dP/dt`` at ``t`` (quotient rule on homogeneous values).

        Parameters
        ----------
        t : float or array_like, shape (m,)

        Returns
        -------
        ndarray, shape (d,) or (m, d)
            Tangent vectors in model units per unit parameter.

        Examples
        --------
        >>> RationalBezier([[0, 0], [1, 2], [2, 0]]).derivative(0.0).tolist()
        [2.0, 4.0]
        """
        _, deriv = self._eval(t, derivative=True)
        return deriv

    def _eval(self, t: ParamsLike, derivative: bool) -> tuple[FloatArray, FloatArray]:
        if type(t) is np.ndarray and t.dtype == np.float64 and t.ndim == 1:
            tt = t  # the internal callers' form, taken as it is (read only, never kept)
        else:
            tt = as_real_array(t, "t")
        scalar = tt.ndim == 0
        if tt.ndim > 1:
            raise ShapeError(f"t should be a scalar or a 1-D array, not shape {tt.shape}")
        check_finite(tt, "t")
        tv = tt.reshape(-1)
        value, dvalue = _decasteljau(self._h, tv)
        w = value[:, -1:]
        if not (w > 0.0).all():
            i = int(np.argmin(w[:, 0] > 0.0))
            raise ProjectionError(
                f"the curve's weight should be > 0 where it is evaluated; at t={tv[i]!r} it is "
                f"{float(w[i, 0])!r}"
            )
        pts = value[:, :-1] / w
        if derivative:
            der = (dvalue[:, :-1] - pts * dvalue[:, -1:]) / w
        else:
            der = pts
        if scalar:
            return pts[0], der[0]
        return pts, der

    # ------------------------------------------------------------------ construction
    def hodograph(self) -> RationalBezier:
        """Return the derivative curve ``P'(t)`` as a Bézier curve (vectors as control points).

        For a polynomial curve this is the usual hodograph of degree ``n - 1``
        (elevated to degree 1 if ``n = 1``); for a rational curve it is the
        rational curve of degree ``2n`` with numerator ``X' w - X w'`` (elevated)
        and denominator ``w^2``.

        Examples
        --------
        >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]])
        >>> c.hodograph().control_points.tolist()
        [[2.0, 4.0], [2.0, -4.0]]
        >>> bool(np.allclose(c.hodograph()(0.3), c.derivative(0.3)))
        True
        """
        if self._hodo is None:
            self._hodo = self._make_hodograph()
        return self._hodo

    def _make_hodograph(self) -> RationalBezier:
        n = self.degree
        h = self._h
        if self.is_polynomial:
            pts = n * np.diff(self.control_points, axis=0)
            if n == 1:
                pts = np.vstack([pts, pts])
            return RationalBezier(pts)
        x = h[:, :-1]
        w = h[:, -1]
        dx = n * np.diff(x, axis=0)
        dw = n * np.diff(w)
        num = _product_bernstein(dx, w[:, None]) - _product_bernstein(x, dw[:, None])
        den = _product_bernstein(w, w)
        num = _elevate_rows(num, 1)
        hh = np.hstack([num, den[:, None]])
        return RationalBezier._trusted(hh)

    def split(self, t: float = 0.5) -> tuple[RationalBezier, RationalBezier]:
        """Split the curve at ``t`` into the pieces over ``[0, t]`` and ``[t, 1]``.

        Each piece is reparametrised to ``[0, 1]``.

        Raises
        ------
        DegenerateCurveError
            If ``t`` is not strictly between 0 and 1.

        Examples
        --------
        >>> left, right = RationalBezier([[0, 0], [2, 2]]).split(0.25)
        >>> left.control_points.tolist(), right.control_points.tolist()
        ([[0.0, 0.0], [0.5, 0.5]], [[0.5, 0.5], [2.0, 2.0]])
        """
        tv = check_param(t, "split parameter t")
        if not (0.0 < tv < 1.0):
            raise DegenerateCurveError(f"split parameter should lie in (0, 1), not {t!r}")
        left, right = split_rows(self._h, tv)  # compiled de Casteljau rounds
        return RationalBezier._trusted(left), RationalBezier._trusted(right)

    def segment(self, t0: float, t1: float) -> RationalBezier:
        """Return the piece of the curve over ``[t0, t1]``, reparametrised to ``[0, 1]``.

        Computed exactly by blossoming the homogeneous control points, so any
        interval works, including ``t0 > t1`` (reversed direction) and intervals
        reaching outside ``[0, 1]`` (extrapolation) as long as the weights stay
        positive there.

        Raises
        ------
        DegenerateCurveError
            If ``t0 == t1``.
        WeightError
            If the extrapolated piece would have non-positive weights (the interval
            reaches a point at infinity of the curve).

        Examples
        --------
        >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]])
        >>> c.segment(0.5, 0.0).control_points.tolist()
        [[1.0, 1.0], [0.5, 1.0], [0.0, 0.0]]
        >>> c.segment(0.5, 0.5)
        Traceback (most recent call last):
        ...
        relief_cad.errors.DegenerateCurveError: segment needs t0 != t1, got t0 = t1 = 0.5
        """
        a = check_param(t0, "segment bound t0")
        b = check_param(t1, "segment bound t1")
        if a == b:
            raise DegenerateCurveError(f"segment needs t0 != t1, got t0 = t1 = {a!r}")
        n = self.degree
        params = np.empty((n + 1, n))
        for i in range(n + 1):
            params[i, : n - i] = a
            params[i, n - i :] = b
        h = _blossom_rows(self._h, params)
        if not np.all(h[:, -1] > 0.0):
            raise WeightError(
                f"the piece over [{a!r}, {b!r}] would have non-positive weights "
                f"{h[:, -1].tolist()}: it reaches past a point at infinity of the curve"
            )
        check_finite(h, "segment control points")
        return RationalBezier._trusted(h)

    def reversed(self) -> RationalBezier:
        """Return the same curve run backwards (``t -> 1 - t``).

        Examples
        --------
        >>> RationalBezier([[0, 0], [1, 0]]).reversed().control_points.tolist()
        [[1.0, 0.0], [0.0, 0.0]]
        """
        return RationalBezier._trusted(self._h[::-1].copy())

    def elevate(self, r: int = 1) -> RationalBezier:
        """Raise the degree by ``r`` without changing the curve or its parameterisation.

        Examples
        --------
        >>> RationalBezier([[0, 0], [2, 0]]).elevate().control_points.tolist()
        [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]
        >>> RationalBezier([[0, 0], [2, 0]]).elevate(-1)
        Traceback (most recent call last):
        ...
        relief_cad.errors.DegreeError: elevate's r should be an int >= 0, not -1
        """
        times = check_count(r, "elevate's r")
        check_degree(self.degree + times, "elevate")
        return RationalBezier._trusted(_elevate_rows(self._h.copy(), times))

    def standard_form(self) -> RationalBezier:
        """Return the same geometry with end weights 1 (a Möbius reparametrisation).

        The weights become ``w_i λ^i / w_0`` with ``λ = (w_0 / w_n)^{1/n}``; the control
        points are unchanged. The new curve at ``s`` is the old one at
        ``t = λ s / (1 - s + λ s)`` (a Möbius reparametrisation fixing 0 and 1).

        Examples
        --------
        >>> c = RationalBezier([[0, 0], [1, 1], [2, 0]], [2.0, 1.0, 0.5]).standard_form()
        >>> [round(float(x), 12) for x in c.weights]
        [1.0, 1.0, 1.0]
        """
        n = self.degree
        w = self.weights
        log_lam = (math.log(w[0]) - math.log(w[n])) / n
        scale = np.exp(np.arange(n + 1) * log_lam - math.log(w[0]))
        new_w = w * scale
        new_w[0] = 1.0
        new_w[n] = 1.0
        return RationalBezier(self.control_points.copy(), new_w)

    def bounding_box(self) -> tuple[FloatArray, FloatArray]:
        """Return ``(lo, hi)``, the box of the control points, which contains the curve.

        Examples
        --------
        >>> lo, hi = RationalBezier([[0, 0], [1, 2], [2, 0]]).bounding_box()
        >>> lo.tolist(), hi.tolist()
        ([0.0, 0.0], [2.0, 2.0])
        """
        return self.control_points.min(axis=0), self.control_points.max(axis=0)

    def transformed(self, matrix: PointsLike) -> RationalBezier:
        """Apply a projective map (collineation) exactly through the homogeneous control points.

        Parameters
        ----------
        matrix : array_like, shape (d + 1, d + 1)
            Homogeneous matrix acting on column vectors ``(x, y, [z,] 1)``; an affine
            map has last row ``(0, ..., 0, 1)``.

        Raises
        ------
        ShapeError
            If the matrix is not ``(d + 1, d + 1)``.
        ProjectionError
            If the image would have non-positive weights (part of the curve goes
            to or through infinity under the map).

        Examples
        --------
        >>> shift = [[1, 0, 5], [0, 1, 0], [0, 0, 1]]
        >>> RationalBezier([[0, 0], [1, 0]]).transformed(shift).control_points.tolist()
        [[5.0, 0.0], [6.0, 0.0]]
        """
        m = as_real_array(matrix, "matrix")
        k = self.dim + 1
        if m.shape != (k, k):
            raise ShapeError(f"matrix should have shape ({k}, {k}) for a {self.dim}-D curve, not {m.shape}")
        check_finite(m, "matrix")
        h = self._h @ m.T
        if not np.all(h[:, -1] > 0.0):
            i = int(np.argmin(h[:, -1] > 0.0))
            raise ProjectionError(
                f"the transformed weights should all be > 0; weight {i} becomes {float(h[i, -1])!r} "
                "(the map sends that control point to or past infinity)"
            )
        check_finite(h, "transformed control points")
        return RationalBezier._trusted(h)

    def embedded(self, dim: int = 3) -> RationalBezier:
        """Return a planar curve placed in the plane ``z = 0`` of space (a space curve unchanged).

        Examples
        --------
        >>> RationalBezier([[1, 2], [3, 4]]).embedded().control_points.tolist()
        [[1.0, 2.0, 0.0], [3.0, 4.0, 0.0]]
        """
        if dim not in (2, 3) or dim < self.dim:
            raise ShapeError(f"embedded needs dim 3 (or the curve's own dim {self.dim}), not {dim!r}")
        if dim == self.dim:
            return self
        h = np.zeros((self._h.shape[0], 4))
        h[:, :2] = self._h[:, :2]
        h[:, 3] = self._h[:, 2]
        return RationalBezier._trusted(h)

    # ------------------------------------------------------------------ dunder
    def __repr__(self) -> str:
        pts = np.array2string(self.control_points, separator=", ", precision=6).replace("\n", "")
        if self.is_polynomial and self.weights[0] == 1.0:
            return f"RationalBezier({pts})"
        w = np.array2string(self.weights, separator=", ", precision=6)
        return f"RationalBezier({pts}, weights={w})"

    def __reduce__(self) -> tuple[object, tuple[object, ...]]:
        """Pickle (and copy) the arrays of the curve, not its caches (kernel views do not pickle).

        >>> import pickle
        >>> c = RationalBezier([[0, 0], [1, 2], [2, 0]], [1, 0.5, 1])
        >>> pickle.loads(pickle.dumps(c)) == c
        True
        """
        return _restore, (type(self), self._h, self._points, self._weights)

    def _kernel_views(self) -> tuple[object, object]:
        """The control points and weights as the pair kernel takes them (made once, then kept).

        See :func:`relief_cad._kernels.batch.kernel_views`: a planar curve's arrays are converted
        for the compiled kernel once instead of on every :func:`~relief_cad.intersect` call.
        """
        kv = self._kv
        if kv is None:
            kv = self._kv = kernel_views(self.control_points, self.weights)
        return kv

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, RationalBezier):
            return NotImplemented
        return self._h.shape == other._h.shape and bool(np.array_equal(self._h, other._h))

    def __hash__(self) -> int:
        return hash((self._h.shape, self._h.tobytes()))


def _weights_of(weights: ParamsLike, pts: FloatArray) -> FloatArray:
    """The constructor's weights as a new float64 array of one weight per point of ``pts``.

    Bad weights raise their error after that of non-finite points: the points are named first.
    """
    try:
        w = as_real_array(weights, "weights")
        if w.shape != (pts.shape[0],):
            raise ShapeError(f"weights should have shape ({pts.shape[0]},) to match {pts.shape[0]} "
                             f"control points, not {w.shape}")
    except ReliefCadError:
        check_finite(pts, "control_points")
        raise
    return w


def _checked_rows(pts: FloatArray, w: FloatArray | None) -> FloatArray:
    """The homogeneous rows of ``pts`` and ``w`` (None: all 1), raising the error that names a bad entry.

    The constructor's slow path, when :func:`relief_cad._kernels.bezier.homogeneous_rows` refused
    the arrays (the same rows, the same checks).
    """
    check_finite(pts, "control_points")
    if w is None:
        w = np.ones(pts.shape[0])
    else:
        check_finite(w, "weights")
        check_weights(w)
    h = np.empty((pts.shape[0], pts.shape[1] + 1))
    with np.errstate(over="ignore", invalid="ignore"):
        h[:, :-1] = pts * w[:, None]
    h[:, -1] = w
    check_finite(h, "weighted control points")
    return h


def _restore(cls: type[RationalBezier], h: FloatArray, pts: FloatArray | None,
             w: FloatArray | None) -> RationalBezier:
    """A curve from its pickled arrays (:meth:`RationalBezier.__reduce__`): the same bits, no checks."""
    obj = cls.__new__(cls)
    obj._set(h, pts, w)
    return obj

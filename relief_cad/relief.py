r"""The relief perspective of Hlúšek's paper, the central projection, and the paper's construction.

Notation follows the paper ("Bezier curves intersection using relief perspective"):
centre ``O = (0, 0, 0)``, image plane ``σ: z = 1``, span ``k > 0, k != 1``.

.. math::

    φ_k(x, y, z) = \frac{(1 + k)(x, y, z)}{z + k}, \qquad
    φ_k^{-1}(x, y, z) = \frac{k (x, y, z)}{1 + k - z}.

As a 4x4 homogeneous matrix ``φ`` is a collineation, so it maps a rational
Bézier curve to a rational Bézier curve of the same degree by mapping its
homogeneous control points. The vanishing plane is ``z = 1 + k`` (the image of
the points at infinity), the neutral plane ``z = -k`` (sent to infinity).

>>> phi = ReliefPerspective(2.0)
>>> phi.apply([1.0, 2.0, 1.0]).tolist()   # the image plane is fixed pointwise
[1.0, 2.0, 1.0]
>>> phi.vanishing_plane_z, phi.neutral_plane_z
(3.0, -2.0)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import overload

import numpy as np

from ._checks import as_real_array, check_curve, check_finite, check_param, check_span
from ._types import FloatArray, PointsLike
from .curves import RationalBezier
from .errors import (
    NoNeutralPlaneError,
    ProjectionError,
    ShapeError,
    ToleranceError,
    WeightError,
)

__all__ = [
    "NeutralPlaneFrame",
    "ReliefPerspective",
    "central_projection",
    "find_neutral_plane",
    "lift",
    "preimage_of_lift",
    "relief_of_lift",
]


def _as_points3(x: object, name: str) -> tuple[FloatArray, bool]:
    """``x`` as finite points of shape (m, 3), and whether it was one point of shape (3,).

    >>> _as_points3([1.0, 2.0], "x")
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: x should be a point of shape (3,), ... not an array of shape (2,)
    """
    arr = as_real_array(x, name)
    if arr.ndim not in (1, 2) or arr.shape[-1] != 3:
        raise ShapeError(f"{name} should be a point of shape (3,), points of shape (m, 3) or a 3-D "
                         f"RationalBezier, not an array of shape {arr.shape}")
    check_finite(arr, name)
    return (arr[None, :], True) if arr.ndim == 1 else (arr, False)


def _require_curve(curve: object, dim: int, name: str) -> RationalBezier:
    """``curve`` when it is a RationalBezier of dimension ``dim`` (2: planar, 3: space)."""
    checked = check_curve(curve, name)
    if checked.dim != dim:
        raise ShapeError(f"{name} should be a {dim}-D curve, not a {checked.dim}-D one")
    return checked


def _finite_image(out: FloatArray, name: str) -> FloatArray:
    """``out``, the image of the points ``name``, when no coordinate overflowed to inf (or NaN)."""
    check_finite(out, f"the image of {name} (overflow)")
    return out


def _map_points(matrix: FloatArray, pts: FloatArray, singular: str) -> FloatArray:
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):  # refused below
        h = np.hstack([pts, np.ones((pts.shape[0], 1))]) @ matrix.T
        out: FloatArray = h[:, :3] / h[:, 3:]
    w = h[:, 3]
    if np.any(w == 0.0):
        i = int(np.argmax(w == 0.0))
        raise ProjectionError(f"points should lie off the {singular}; point {pts[i].tolist()} lies on it "
                              "(its image is at infinity)")
    return _finite_image(out, "x")


class ReliefPerspective:
    r"""The relief perspective ``φ_k`` with centre O = (0, 0, 0), image plane z = 1 and span k.

    Parameters
    ----------
    k : float, default 2.0
        The span, ``k > 0`` and ``k != 1``.

    Attributes
    ----------
    k : float
        The span.
    centre : ndarray, shape (3,)
        The centre ``O`` (the origin).
    image_plane_z : float
        1.0: the image plane ``σ``, fixed pointwise.
    vanishing_plane_z : float
        ``1 + k``: the images of points at infinity.
    neutral_plane_z : float
        ``-k``: the plane sent to infinity.
    viewpoint : ndarray, shape (3,)
        ``S = (0, 0, -k)``: the orthographic projection of a relief onto ``σ``
        equals the central projection of the original from ``S``.
    matrix, inverse_matrix : ndarray, shape (4, 4)
        Homogeneous matrices of ``φ`` and ``φ⁻¹`` acting on column vectors ``(x, y, z, 1)``.

    Raises
    ------
    SpanError
        If ``k <= 0``, ``k == 1`` or ``k`` is not finite.

    Examples
    --------
    >>> phi = ReliefPerspective(2.0)
    >>> phi.apply([0.0, 0.0, 2.0]).tolist()   # a plane z = c maps to z = (1+k)c/(c+k)
    [0.0, 0.0, 1.5]
    >>> phi.inverse(phi.apply([0.3, -1.0, 5.0])).round(12).tolist()
    [0.3, -1.0, 5.0]
    >>> ReliefPerspective(1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.SpanError: the span k should be > 0 and != 1, not 1.0
    """

    def __init__(self, k: float = 2.0) -> None:
        self.k: float = check_span(k)
        kk = self.k
        self.centre: FloatArray = np.zeros(3)
        self.image_plane_z: float = 1.0
        self.vanishing_plane_z: float = 1.0 + kk
        self.neutral_plane_z: float = -kk
        self.viewpoint: FloatArray = np.array([0.0, 0.0, -kk])
        m = np.diag([1.0 + kk, 1.0 + kk, 1.0 + kk, kk])
        m[3, 2] = 1.0
        self.matrix: FloatArray = m
        mi = np.diag([kk, kk, kk, 1.0 + kk])
        mi[3, 2] = -1.0
        self.inverse_matrix: FloatArray = mi
        for arr in (self.centre, self.viewpoint, self.matrix, self.inverse_matrix):
            arr.flags.writeable = False

    def __repr__(self) -> str:
        return f"ReliefPerspective(k={self.k!r})"

    @overload
    def apply(self, x: RationalBezier) -> RationalBezier: ...

    @overload
    def apply(self, x: PointsLike) -> FloatArray: ...

    def apply(self, x: RationalBezier | PointsLike) -> RationalBezier | FloatArray:
        """Map points or a space curve by ``φ_k``.

        Parameters
        ----------
        x : array_like of shape (3,) or (m, 3), or a 3-D RationalBezier
            Points in model units, or a space curve (mapped exactly through its
            homogeneous control points).

        Returns
        -------
        ndarray of the same shape, or RationalBezier of the same degree

        Raises
        ------
        InputTypeError, ShapeError, NonFiniteError
            For ``x`` not a 3-D curve nor finite points of shape (3,) or (m, 3) (or an image
            that overflows).
        ProjectionError
            For a point on the neutral plane ``z = -k`` (sent to infinity), or a curve
            with a control point on or behind it (its image weights would not be positive).

        Examples
        --------
        >>> ReliefPerspective(3.0).apply([[0, 0, 0], [1, 1, 1]]).tolist()
        [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
        >>> ReliefPerspective(3.0).apply([0, 0, -3])
        Traceback (most recent call last):
        ...
        relief_cad.errors.ProjectionError: points should lie off the neutral plane z = -k; point ...
        """
        if isinstance(x, RationalBezier):
            return _require_curve(x, 3, "x").transformed(self.matrix)
        pts, single = _as_points3(x, "x")
        out = _map_points(self.matrix, pts, "neutral plane z = -k")
        return out[0] if single else out

    @overload
    def inverse(self, x: RationalBezier) -> RationalBezier: ...

    @overload
    def inverse(self, x: PointsLike) -> FloatArray: ...

    def inverse(self, x: RationalBezier | PointsLike) -> RationalBezier | FloatArray:
        """Map points or a space curve by ``φ_k⁻¹``.

        Raises
        ------
        InputTypeError, ShapeError, NonFiniteError
            As :meth:`apply`.
        ProjectionError
            For a point on the vanishing plane ``z = 1 + k`` (its preimage is at infinity),
            or a curve with a control point on or beyond it.

        Examples
        --------
        >>> ReliefPerspective(2.0).inverse([0.0, 0.0, 1.5]).tolist()
        [0.0, 0.0, 2.0]
        """
        if isinstance(x, RationalBezier):
            return _require_curve(x, 3, "x").transformed(self.inverse_matrix)
        pts, single = _as_points3(x, "x")
        out = _map_points(self.inverse_matrix, pts, "vanishing plane z = 1 + k")
        return out[0] if single else out


@overload
def central_projection(x: RationalBezier) -> RationalBezier: ...


@overload
def central_projection(x: PointsLike) -> FloatArray: ...


def central_projection(x: RationalBezier | PointsLike) -> RationalBezier | FloatArray:
    """Project from the centre O = (0, 0, 0) onto the image plane z = 1 (the paper's ψ).

    A point ``(x, y, z)`` goes to ``(x / z, y / z)``. A space rational curve with
    homogeneous control points ``(X, Y, Z, W)`` goes to the planar rational curve
    with homogeneous control points ``(X, Y, Z)``: same degree, weights ``Z_i``.

    Parameters
    ----------
    x : array_like of shape (3,) or (m, 3), or a 3-D RationalBezier

    Returns
    -------
    ndarray of shape (2,) or (m, 2), or a 2-D RationalBezier
        Coordinates in the image plane.

    Raises
    ------
    InputTypeError
        If ``x`` is neither a RationalBezier nor an array of real numbers.
    ShapeError
        If ``x`` is a planar curve, or points not of shape (3,) or (m, 3).
    NonFiniteError
        If a point is NaN or infinite, or its image overflows.
    ProjectionError
        If a point (or control point) has ``z <= 0``: it is not in front of the centre.

    Examples
    --------
    >>> central_projection([2.0, 4.0, 2.0]).tolist()
    [1.0, 2.0]
    >>> central_projection([1.0, 1.0, 0.0])
    Traceback (most recent call last):
    ...
    relief_cad.errors.ProjectionError: points should lie in front of the centre (z > 0); point 0 has z = 0.0
    """
    if isinstance(x, RationalBezier):
        curve = _require_curve(x, 3, "x")
        h = curve.homogeneous
        if not np.all(h[:, 2] > 0.0):
            i = int(np.argmin(h[:, 2] > 0.0))
            raise ProjectionError(
                "control points should lie in front of the centre (z > 0); "
                f"control point {i} has z = {float(curve.control_points[i, 2])!r}"
            )
        return RationalBezier.from_homogeneous(h[:, :3])
    pts, single = _as_points3(x, "x")
    if not np.all(pts[:, 2] > 0.0):
        i = int(np.argmin(pts[:, 2] > 0.0))
        raise ProjectionError(
            f"points should lie in front of the centre (z > 0); point {i} has z = {float(pts[i, 2])!r}"
        )
    with np.errstate(over="ignore"):  # refused by _finite_image
        out = _finite_image(pts[:, :2] / pts[:, 2:3], "x")
    return out[0] if single else out


def lift(curve: RationalBezier) -> RationalBezier:
    """Return the paper's lift ``P̄`` of a planar rational curve: a space *polynomial* curve.

    Control points ``(x_i w_i, y_i w_i, w_i)``, all weights 1; its central projection
    from O onto z = 1 is the planar curve again.

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier.
    ShapeError
        If ``curve`` is a space curve.

    Examples
    --------
    >>> lift(RationalBezier([[1, 2], [3, 4]], [1.0, 2.0])).control_points.tolist()
    [[1.0, 2.0, 1.0], [6.0, 8.0, 2.0]]
    """
    planar = _require_curve(curve, 2, "the curve to lift")
    return RationalBezier(planar.homogeneous.copy())


def preimage_of_lift(curve: RationalBezier, k: float) -> RationalBezier:
    r"""Return the paper's space rational curve ``Q`` whose relief under ``φ_k`` is the lift ``P̄``.

    .. math::

        W_i = \frac{k (x_i w_i, y_i w_i, w_i)}{1 + k - w_i}, \qquad Ω_i = 1 + k - w_i .

    Theorem (tested): ``φ_k(Q) = P̄ = lift(P)`` and ``ψ(Q) = P``.

    Parameters
    ----------
    curve : RationalBezier
        The planar curve ``P`` (dim 2) with weights ``w_i``.
    k : float
        The span; the construction needs ``1 + k > w_i`` for every weight.

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier or ``k`` is not a real number.
    ShapeError
        If ``curve`` is a space curve.
    SpanError
        If ``k`` is not an admissible span.
    WeightError
        If some ``w_i >= 1 + k``; the message names the weight and the smallest admissible k.

    Examples
    --------
    >>> P = RationalBezier([[0, 0], [1, 1], [2, 0]], [1.0, 0.5, 1.0])
    >>> Q = preimage_of_lift(P, 2.0)
    >>> Q.weights.tolist()
    [2.0, 2.5, 2.0]
    >>> preimage_of_lift(RationalBezier([[0, 0], [1, 1]], [1.0, 4.0]), 2.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.WeightError: the construction needs 1 + k > w_i: weight 1 is 4.0 and k = 2.0; ...
    """
    planar = _require_curve(curve, 2, "curve")
    kv = check_span(k)
    w = planar.weights
    bad = np.nonzero(w >= 1.0 + kv)[0]
    if bad.size:
        i = int(bad[np.argmax(w[bad])])
        raise WeightError(
            f"the construction needs 1 + k > w_i: weight {i} is {float(w[i])!r} and k = {kv!r}; "
            f"any k > {float(np.max(w)) - 1.0!r} (and != 1) works"
        )
    h = planar.homogeneous
    q = np.empty((h.shape[0], 4))
    q[:, :3] = kv * h
    q[:, 3] = 1.0 + kv - w
    return RationalBezier.from_homogeneous(q)


def relief_of_lift(curve: RationalBezier, k: float) -> RationalBezier:
    """Return the relief ``φ_k(P̄)`` of the lift of a planar curve, in closed form.

    Control points ``(1 + k)(x_i w_i, y_i w_i, w_i) / (w_i + k)``, weights ``w_i + k``.

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier or ``k`` is not a real number.
    ShapeError
        If ``curve`` is a space curve.
    SpanError
        If ``k`` is not an admissible span (finite, > 0 and != 1).

    Examples
    --------
    >>> relief_of_lift(RationalBezier([[0, 0], [1, 0]]), 2.0).weights.tolist()
    [3.0, 3.0]
    >>> relief_of_lift(RationalBezier([[0, 0, 0], [1, 0, 0]]), 2.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ShapeError: curve should be a 2-D curve, not a 3-D one
    """
    planar = _require_curve(curve, 2, "curve")
    kv = check_span(k)
    h = planar.homogeneous
    r = np.empty((h.shape[0], 4))
    r[:, :3] = (1.0 + kv) * h
    r[:, 3] = planar.weights + kv
    return RationalBezier.from_homogeneous(r)


@dataclass(frozen=True)
class NeutralPlaneFrame:
    """A frame in which a space curve has the paper's form ``Q``.

    >>> from relief_cad import RationalBezier, preimage_of_lift
    >>> q = preimage_of_lift(RationalBezier([[0, 0], [1, 1]], [1.0, 2.0]), 2.0)
    >>> frame = find_neutral_plane(q, k=2.0)
    >>> frame.k, frame.planar.degree, bool(abs(frame.plane_normal @ frame.plane_normal - 1) < 1e-12)
    (2.0, 1, True)

    Attributes
    ----------
    plane_point : ndarray, shape (3,)
        A point of the neutral plane, in model coordinates.
    plane_normal : ndarray, shape (3,)
        Unit normal of the neutral plane, pointing towards the curve.
    k : float
        The span: in the frame the neutral plane is ``z = -k``.
    matrix : ndarray, shape (4, 4)
        Homogeneous similarity taking model coordinates to frame coordinates
        (rotation, translation, uniform scale).
    inverse_matrix : ndarray, shape (4, 4)
        Its inverse.
    curve : RationalBezier
        The input curve in frame coordinates, its homogeneous control points scaled so that
        ``Z_i + k W_i = k (1 + k)`` (the paper's normalisation).
    planar : RationalBezier
        The planar curve ``P`` with ``preimage_of_lift(P, k) == curve``.
    """

    plane_point: FloatArray
    plane_normal: FloatArray
    k: float
    matrix: FloatArray
    inverse_matrix: FloatArray
    curve: RationalBezier
    planar: RationalBezier


def _null_space(a: FloatArray, rel: float) -> FloatArray:
    scale = np.linalg.norm(a, axis=0)
    scale[scale == 0.0] = 1.0
    an = a / scale
    _, s, vt = np.linalg.svd(an)
    smax = s[0] if s.size else 1.0
    full = np.zeros(an.shape[1])
    full[: s.size] = s
    basis = vt[full <= rel * smax].T
    out: FloatArray = basis / scale[:, None]
    return out


def _check_rtol(rtol: object) -> float:
    """``rtol`` as a float > 0 and < 1: a relative tolerance (dimensionless, not a distance).

    At ``rtol >= 1`` every direction would count as null, so nothing would be tested.

    >>> _check_rtol(1.0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: rtol should be a relative tolerance > 0 and < 1, not 1.0
    """
    value = check_param(rtol, "rtol")
    if not 0.0 < value < 1.0:
        raise ToleranceError(f"rtol should be a relative tolerance > 0 and < 1, not {value!r}")
    return value


def find_neutral_plane(curve: RationalBezier, k: float = 2.0, *, rtol: float = 1e-10) -> NeutralPlaneFrame:
    r"""Find a neutral plane of a space rational curve and the frame giving it the paper's form.

    The paper asks which space rational curves have the form ``Q`` of its construction.
    Answer: exactly those whose homogeneous control points ``(X_i, W_i)`` give one constant,
    non-zero value of the linear form of some plane ``n · x + d = 0``,

    .. math::

        n · X_i + d\, W_i = c \quad (\text{all } i), \qquad c \neq 0,

    i.e. ``W_i · dist(V_i, plane) = c`` (the weights' common scale is free). That plane is the
    neutral plane. In a frame with the plane at ``z = -k``, the centre O between the plane and
    the control points and the image plane at ``z = 1``, the curve is ``preimage_of_lift(P, k)``
    of a planar rational curve ``P`` with positive weights, and ``1 + k > w_i`` holds
    automatically. The span ``k`` is a free choice of the frame's scale.

    Parameters
    ----------
    curve : RationalBezier
        A space curve (a planar one is taken in z = 0).
    k : float, default 2.0
        The span wanted in the returned frame.
    rtol : float, default 1e-10
        Relative tolerance for the linear condition (on column-normalised data), > 0 and < 1.

    Returns
    -------
    NeutralPlaneFrame

    Raises
    ------
    InputTypeError
        If ``curve`` is not a RationalBezier, or ``k`` or ``rtol`` is not a real number.
    SpanError
        If ``k`` is not an admissible span (finite, > 0 and != 1).
    NonFiniteError, ToleranceError
        If ``rtol`` is NaN or infinite, or not > 0 and < 1.
    NoNeutralPlaneError
        If no such plane exists (the curve is not of the paper's form in any frame).

    Examples
    --------
    >>> P = RationalBezier([[0, 0], [1, 2], [2, 0]], [1.0, 0.5, 1.5])
    >>> frame = find_neutral_plane(preimage_of_lift(P, 3.0), k=3.0)
    >>> frame.planar.degree, frame.k
    (2, 3.0)
    >>> find_neutral_plane(RationalBezier([[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]]))
    Traceback (most recent call last):
    ...
    relief_cad.errors.NoNeutralPlaneError: the curve has no neutral plane: ...
    >>> find_neutral_plane(preimage_of_lift(P, 3.0), rtol=0)
    Traceback (most recent call last):
    ...
    relief_cad.errors.ToleranceError: rtol should be a relative tolerance > 0 and < 1, not 0.0
    """
    space = check_curve(curve, "curve").embedded(3)
    kv = check_span(k)
    rel = _check_rtol(rtol)
    h = space.homogeneous
    npts = h.shape[0]
    a = np.hstack([h, -np.ones((npts, 1))])
    basis = _null_space(a, rel)
    fail = NoNeutralPlaneError(
        "the curve has no neutral plane: no plane n.x + d = 0 gives W_i * (n.V_i + d) one constant "
        f"non-zero value over its {npts} control points, so it is not of the paper's form in any frame"
    )
    if basis.shape[1] == 0:
        raise fail
    size = float(np.linalg.norm(np.ptp(space.control_points, axis=0))) or 1.0
    best: tuple[FloatArray, float, float] | None = None
    rng = np.random.default_rng(12345)
    trials = [np.ones(basis.shape[1])] + [rng.standard_normal(basis.shape[1]) for _ in range(8)]
    for coeffs in trials:
        v = basis @ coeffs
        n = v[:3]
        nn = float(np.linalg.norm(n))
        if nn == 0.0:
            continue
        d = float(v[3]) / nn
        c = float(v[4]) / nn
        n = n / nn
        dist = space.control_points @ n + d
        if c < 0.0:
            n, d, c, dist = -n, -d, -c, -dist
        # A plane ever farther away tends to the plane at infinity (n -> 0): not a neutral plane.
        if c <= 0.0 or not np.all(dist > 1e-12 * size) or float(np.max(dist)) > 1e6 * size:
            continue
        best = (n, d, c)
        break
    if best is None:
        raise fail
    n, d, c = best
    dist = space.control_points @ n + d
    residual = h[:, :3] @ n + d * h[:, 3] - c
    if float(np.max(np.abs(residual))) > 1e-8 * c:
        raise fail
    # Frame: z axis along n, centre O at distance delta from the plane, unit s = delta / k.
    delta = 0.5 * float(np.min(dist))
    plane_point = -d * n
    origin = plane_point + delta * n
    helper = np.array([1.0, 0.0, 0.0]) if abs(n[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    e1 = np.cross(helper, n)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    rot = np.vstack([e1, e2, n])
    s = delta / kv
    m = np.eye(4)
    m[:3, :3] = rot / s
    m[:3, 3] = -(rot @ origin) / s
    mi = np.eye(4)
    mi[:3, :3] = rot.T * s
    mi[:3, 3] = origin
    framed = space.transformed(m).homogeneous
    lin = framed[:, 2] + kv * framed[:, 3]
    framed = framed * (kv * (1.0 + kv) / float(np.mean(lin)))
    q = RationalBezier.from_homogeneous(framed)
    planar = RationalBezier.from_homogeneous(
        np.column_stack([framed[:, 0] / kv, framed[:, 1] / kv, framed[:, 2] / kv])
    )
    return NeutralPlaneFrame(
        plane_point=plane_point,
        plane_normal=n,
        k=kv,
        matrix=m,
        inverse_matrix=mi,
        curve=q,
        planar=planar,
    )

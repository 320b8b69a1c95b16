"""Hybrid curves, and integrals of Bézier curves with guaranteed error bounds: chapter 20 of the notes.

A rational Bézier curve R(t) of degree r with weights w is, exactly, a
polynomial Bézier curve H(t) of any degree n >= 2 in which one control point,
number m (0 < m < n), is not fixed but moves along a rational curve M(t) of
degree r with the same weights (`hybrid_curve`, eqs. 20.2-20.6):

    R(t) = H(t) = Σ_{i≠m} B_i^n(t) P_i + B_m^n(t) M(t).

Freezing the moving point at the centre of the box around M's control points
gives a polynomial curve P(t) within ‖Δ‖ max B_m^n of R(t), ‖Δ‖ the box's half
diagonal (`polynomial_approximation`, eq. 20.7); halving the curve shrinks the
box. Polynomial curves have closed-form integrals, quadratic and cubic forms in
their control points: the area under the curve (`area_matrix`,
`polynomial_area`, eq. 20.13), the sector area (`sector_area`, 20.14), the first
moments (`moment_tensor`, `first_moments`, 20.16-20.17) and the volume of
revolution (`revolution_volume`, 20.18). Integrating P instead of R costs an
error bounded through the box (`integral_error_bounds`, 20.27-20.29), so
splitting R until every piece's bound fits its share of a tolerance gives the
integral of a rational curve with a guarantee (`adaptive_integral`,
`bezier_area`, §20.4). `trapezoid_area` and `simpson_area` are the two rules
the notes compare it with.

Integrals are signed: ∫ y dx is positive where the curve runs in +x above the
x-axis, the sector area ½∫(x dy - y dx) is positive for counterclockwise travel
about the origin, the volume π∫ y² dx has the sign of dx. Points are float
arrays (n+1, d) (planar (n+1, 2) for integrals); rational curves take positive
weights (r+1,) (then the curve lies in the hull of its control points, which
every bound here relies on).

Ref: T. W. Sederberg and M. Kakimoto, Approximating rational curves using polynomial curves, in
NURBS for Curve and Surface Design, G. Farin (ed.), SIAM, 1991, 149-158.
"""

from __future__ import annotations

from math import comb, pi
from typing import NamedTuple

import numpy as np

from ._validation import as_count, as_parameter, as_points, as_positive_weights, as_scalar
from .bezier import bernstein_matrix, derivative, elevate, evaluate, hodograph, subdivide, to_homogeneous
from .polynomials import bernstein_integral, bernstein_multiply

__all__ = [
    "HybridCurve",
    "hybrid_curve",
    "hybrid_point",
    "moving_box",
    "polynomial_approximation",
    "max_bernstein",
    "area_matrix",
    "moment_tensor",
    "polynomial_area",
    "sector_area",
    "first_moments",
    "revolution_volume",
    "polynomial_integral",
    "integral_error_bounds",
    "Integral",
    "Area",
    "adaptive_integral",
    "adaptive_area_plain",
    "bezier_area",
    "trapezoid_area",
    "simpson_area",
]

KINDS = ("area", "sector", "volume")
# The hybrid degree of the adaptive method. A piece's bound falls by about 2^(n+2) when it is halved; on
# random rational cubics degree 6 needs a fifth of the pieces of degree 4 at tol = 1e-12, and a level of
# pieces costs about the same at either degree (chapter 20 shows the measurements).
ADAPTIVE_DEGREE = 6
# Below FLOOR times the control points' size squared (cubed for volumes), rounding in the closed forms
# (about 1e-16 of each piece's value, over up to thousands of pieces) could exceed the tolerance: refused.
FLOOR = 1e-13
# The adaptive methods give up (a ValueError) rather than examine more pieces than this.
MAX_PIECES = 2**20


class HybridCurve(NamedTuple):
    """A hybrid curve: fixed control points (n+1, d) whose row m is NaN (it moves), and the moving point's curve.

    moving (r+1, d) and weights (r+1,) are the rational curve M(t) traced by control point m.
    """

    fixed: np.ndarray
    moving: np.ndarray
    weights: np.ndarray
    m: int


class Integral(NamedTuple):
    """What an integration method returns: the value, its error bound, the pieces it used and its work.

    work counts the pieces examined (hybrid and trapezoid methods: kept and split) or the integrand's
    evaluations (Simpson's rule). For Simpson's rule the bound is only an estimate.
    """

    value: float
    bound: float
    pieces: int
    work: int


class Area(float):
    """The float `bezier_area` returns, carrying its guaranteed error bound and the tolerance asked for.

    |area - exact| <= area.bound <= area.tol (up to rounding); in every other respect a plain float.
    """

    bound: float
    tol: float

    def __new__(cls, value: float, bound: float = 0.0, tol: float = 0.0):
        area = super().__new__(cls, value)
        area.bound, area.tol = float(bound), float(tol)
        return area


# --- input checking -------------------------------------------------------------------------------


def _positive_weights(weights, count: int) -> np.ndarray:
    return as_positive_weights(weights, count, "the hybrid form needs positive weights (no pole on the curve)")


def _planar(points, name: str = "points") -> np.ndarray:
    pts = as_points(points, name)
    if pts.shape[1] != 2:
        raise ValueError(f"{name}: integrals are taken of planar curves, expected shape (n+1, 2), got {pts.shape}")
    return pts


def _degree_and_split(degree, m) -> tuple[int, int]:
    n = as_count(degree, "degree", minimum=2)
    m = n // 2 if m is None else as_count(m, "m")
    if not 0 < m < n:
        raise ValueError(f"m: the moving control point must be an inner one, 0 < m < n = {n}, got {m}")
    return n, m


def _tolerance(tol, pts: np.ndarray, power: int = 2) -> float:
    """A positive tolerance no smaller than FLOOR · max|coordinate|^power (2 for areas, 3 for volumes)."""
    tol = as_scalar(tol, "tol")
    scale = float(np.abs(pts).max(initial=0.0)) ** power
    if not tol > 0:
        raise ValueError(f"tol: expected a positive tolerance, got {tol}")
    if tol < FLOOR * scale:
        raise ValueError(
            f"tol: {tol:g} is below what double precision can guarantee for these control points "
            f"({FLOOR:g} × max|coordinate|^{power} = {FLOOR * scale:.3g})"
        )
    return tol


# --- hybrid curves ----------------------------------------------------------------------------------


def _hybrid(R: np.ndarray, w: np.ndarray, n: int, m: int) -> tuple[np.ndarray, np.ndarray]:
    """Fixed points (..., n+1, d) (row m NaN) and moving points (..., r+1, d) of rational curves R (..., r+1, d).

    Equations (20.4)-(20.6), for any leading batch axes (w is (..., r+1)).
    Multiplying H = R by the weight function and comparing the coefficients of
    (1-t)^(n+r-k) t^k gives, for k = 0..n+r,
    Σ_j C(r,j) C(n,k-j) w_j R_j = Σ_{i≠m} C(n,i) C(r,k-i) w_(k-i) P_i + C(n,m) C(r,k-m) w_(k-m) M_(k-m):
    k < m fixes P_0..P_(m-1) upwards, k > m + r fixes P_n..P_(m+1) downwards, the rest gives M.
    """
    r = R.shape[-2] - 1
    P = np.full(R.shape[:-2] + (n + 1, R.shape[-1]), np.nan)
    wj = w[..., :, None]  # (..., r+1, 1): one weight per row of R

    def term(j: int, i: int) -> np.ndarray:  # C(r,j) C(n,i) w_j (R_j - P_i), i = k - j
        return comb(r, j) * comb(n, i) * wj[..., j, :] * (R[..., j, :] - P[..., i, :])

    for k in range(m):  # (20.4)
        total = sum((term(j, k - j) for j in range(1, min(r, k) + 1)), np.zeros_like(R[..., 0, :]))
        P[..., k, :] = R[..., 0, :] + total / (wj[..., 0, :] * comb(n, k))
    for k in range(n + r, m + r, -1):  # (20.5): P_(k-r), from the top down (it uses P_(k-j) with j < r)
        total = sum((term(j, k - j) for j in range(max(0, k - n), r)), np.zeros_like(R[..., 0, :]))
        P[..., k - r, :] = R[..., r, :] + total / (wj[..., r, :] * comb(n, k - r))
    M = np.empty_like(R)
    for i in range(r + 1):  # (20.6)
        js = [j for j in range(max(0, i + m - n), min(i + m, r) + 1) if j != i]
        total = sum((term(j, i + m - j) for j in js), np.zeros_like(R[..., 0, :]))
        M[..., i, :] = R[..., i, :] + total / (wj[..., i, :] * comb(n, m) * comb(r, i))
    return P, M


def hybrid_curve(points, weights, degree: int, m: int | None = None) -> HybridCurve:
    """The hybrid form of a rational Bézier curve: degree n, control point m moving on a rational curve. Notes §20.1.

    points: (r+1, d), r >= 0; weights: (r+1,) positive; degree: n >= 2; m: the
    moving control point, 0 < m < n (default n // 2). Returns
    HybridCurve(fixed (n+1, d) with row m NaN, moving (r+1, d), weights (r+1,), m):
    R(t) = Σ_{i≠m} B_i^n(t) fixed_i + B_m^n(t) M(t), M the rational curve of
    `moving` with the same weights (eqs. 20.4-20.6). The fixed points start at
    R_0 and end at R_r; M's control points collapse to one point when R is
    itself a polynomial curve of degree <= n.

    The notes' semicircle (Fig. 20.6) as a quartic hybrid:

    >>> from cagd_ref.hybrid import hybrid_curve
    >>> h = hybrid_curve([(0, 0), (0, 1), (1, 1), (1, 0)], [3, 1, 1, 3], 4)
    >>> h.fixed.round(6).tolist()
    [[0.0, 0.0], [0.0, 0.25], [nan, nan], [1.0, 0.25], [1.0, 0.0]]
    >>> h.moving.round(6).tolist()
    [[0.166667, 0.666667], [0.166667, 1.333333], [0.833333, 1.333333], [0.833333, 0.666667]]

    Ref: T. W. Sederberg and M. Kakimoto, Approximating rational curves using polynomial curves, in
    NURBS for Curve and Surface Design, G. Farin (ed.), SIAM, 1991, 149-158.
    """
    pts = as_points(points)
    w = _positive_weights(weights, len(pts))
    n, m = _degree_and_split(degree, m)
    fixed, moving = _hybrid(pts, w, n, m)
    return HybridCurve(fixed, moving, w, m)


def _checked_hybrid(hybrid) -> HybridCurve:
    try:
        fixed, moving, weights, m = hybrid
    except (TypeError, ValueError):
        raise TypeError("hybrid: expected a HybridCurve (fixed, moving, weights, m)") from None
    m = as_count(m, "hybrid")
    fixed = np.array(fixed, dtype=float)
    if fixed.ndim != 2 or not 0 < m < len(fixed) - 1:
        raise ValueError(f"hybrid: expected fixed points (n+1, d) with 0 < m < n, got shape {fixed.shape}, m = {m}")
    rest = np.delete(fixed, m, axis=0)
    as_points(rest, "hybrid")  # every fixed point but the moving one must be finite
    moving = as_points(moving, "hybrid")
    if moving.shape[1] != fixed.shape[1]:
        raise ValueError(f"hybrid: fixed and moving points of different dimension, {fixed.shape} and {moving.shape}")
    return HybridCurve(fixed, moving, _positive_weights(weights, len(moving)), m)


def hybrid_point(hybrid, t) -> np.ndarray:
    """Point(s) H(t) of a hybrid curve: M(t) first, then the polynomial curve with M(t) as point m. Notes (20.2).

    hybrid: a HybridCurve; t: a number -> (d,), k values -> (k, d).

    >>> from cagd_ref.hybrid import hybrid_curve, hybrid_point
    >>> h = hybrid_curve([(0, 0), (0, 1), (1, 1), (1, 0)], [3, 1, 1, 3], 2)
    >>> hybrid_point(h, 0.5).round(12).tolist()        # the top of the semicircle
    [0.5, 0.5]
    """
    fixed, moving, weights, m = _checked_hybrid(hybrid)
    ts, scalar = as_parameter(t)
    basis = bernstein_matrix(len(fixed) - 1, ts)  # (k, n+1)
    values = np.delete(basis, m, axis=1) @ np.delete(fixed, m, axis=0)
    values += basis[:, m : m + 1] * evaluate(moving, ts, weights)
    return values[0] if scalar else values


def _box(moving: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    low, high = moving.min(axis=-2), moving.max(axis=-2)
    return (low + high) / 2, (high - low) / 2


def moving_box(hybrid) -> tuple[np.ndarray, np.ndarray]:
    """(centre (d,), half-widths (d,)) of the box around the moving control points, which holds M(t). Notes §20.1.

    The notes call the half-widths |Δx|, |Δy| and the half diagonal ‖Δ‖.
    """
    return _box(_checked_hybrid(hybrid).moving)


def max_bernstein(n: int, m: int) -> float:
    """max over [0, 1] of B_m^n = C(n, m) m^m (n-m)^(n-m) / n^n, at t = m/n; C(n, n/2) / 2^n for m = n/2. Notes (20.7).

    >>> from cagd_ref.hybrid import max_bernstein
    >>> max_bernstein(4, 2), max_bernstein(2, 1)
    (0.375, 0.5)
    """
    n = as_count(n, "n")
    m = as_count(m, "m")
    if m > n:
        raise ValueError(f"m: expected 0 <= m <= n = {n}, got {m}")
    return comb(n, m) * (m**m) * ((n - m) ** (n - m)) / n**n if n else 1.0


def polynomial_approximation(points, weights, degree: int = ADAPTIVE_DEGREE, m: int | None = None):
    """A polynomial curve near a rational one: the hybrid with M(t) frozen at its box's centre. Notes (20.7), (20.10).

    points: (r+1, d), weights: (r+1,) positive, degree n >= 2, m as in
    `hybrid_curve`. Returns (control points (n+1, d), bound): the polynomial
    curve P(t) differs from R(t) by B_m^n(t) (centre - M(t)), so
    max |P(t) - R(t)| <= ‖Δ‖ max B_m^n = ‖Δ‖ C(n, n/2) / 2^n for m = n/2 (20.7).
    P interpolates R at both ends.

    >>> from cagd_ref.hybrid import polynomial_approximation
    >>> P, bound = polynomial_approximation([(0, 0), (0, 1), (1, 1), (1, 0)], [3, 1, 1, 3], 4)
    >>> P.round(6).tolist(), round(bound, 6)
    ([[0.0, 0.0], [0.0, 0.25], [0.5, 1.0], [1.0, 0.25], [1.0, 0.0]], 0.176777)
    """
    h = hybrid_curve(points, weights, degree, m)
    centre, half = _box(h.moving)
    approximation = h.fixed.copy()
    approximation[h.m] = centre
    n = len(approximation) - 1
    return approximation, float(np.linalg.norm(half) * max_bernstein(n, h.m))


# --- closed-form integrals of polynomial curves ------------------------------------------------------


def _area_matrix(n: int) -> np.ndarray:
    """A_ij = ∫ B_i^n (B_j^n)' dt = n ∫ B_i^n (B_(j-1)^(n-1) - B_j^(n-1)) dt.

    The products integrate in closed form: ∫ B_a^p B_b^q = C(p,a) C(q,b) / (C(p+q,a+b) (p+q+1)).
    """
    A = np.zeros((n + 1, n + 1))
    if n == 0:
        return A

    def product(i: int, k: int) -> float:  # n ∫ B_i^n B_k^(n-1) dt, zero for k outside 0..n-1
        return comb(n, i) * comb(n - 1, k) / (comb(2 * n - 1, i + k) * 2) if 0 <= k < n else 0.0

    for i in range(n + 1):
        for j in range(n + 1):
            A[i, j] = product(i, j - 1) - product(i, j)
    return A


def area_matrix(n: int) -> np.ndarray:
    """The (n+1, n+1) matrix A with ∫ y dx = yᵀ A x for a degree-n curve with control points (x_i, y_i). Notes (20.13).

    A_ij = ∫₀¹ B_i^n(t) (B_j^n)'(t) dt = n D_ij^(n) in the notes' notation; the
    notes' factor n is inside A. A + Aᵀ = diag(-1, 0, ..., 0, 1) (integrate
    (B_i B_j)' over [0, 1]), so the sector area uses only the antisymmetric part.
    n = 1 is the trapezoid (y0 + y1)(x1 - x0) / 2; n = 0 gives [[0]].

    >>> from cagd_ref.hybrid import area_matrix
    >>> (area_matrix(2) * 6).round(12).tolist()
    [[-3.0, 2.0, 1.0], [-2.0, 0.0, 2.0], [-1.0, -2.0, 3.0]]
    """
    return _area_matrix(as_count(n, "n"))


def _moment_tensor(n: int) -> np.ndarray:
    """T_ijk = ∫ B_i^n B_j^n (B_k^n)' dt, from ∫ B_a^n B_b^n B_c^(n-1) = C(n,a) C(n,b) C(n-1,c) / (C(3n-1,a+b+c) 3n)."""
    T = np.zeros((n + 1,) * 3)
    if n == 0:
        return T

    def triple(a: int, b: int, c: int) -> float:  # n ∫ B_a^n B_b^n B_c^(n-1)
        if not 0 <= c < n:
            return 0.0
        return comb(n, a) * comb(n, b) * comb(n - 1, c) / (comb(3 * n - 1, a + b + c) * 3)

    for i in range(n + 1):
        for j in range(n + 1):
            for k in range(n + 1):
                T[i, j, k] = triple(i, j, k - 1) - triple(i, j, k)
    return T


def moment_tensor(n: int) -> np.ndarray:
    """The tensor T (n+1, n+1, n+1) with ∫ y² dx = Σ T_ijk y_i y_j x_k and ∫ xy dx = Σ T_ijk x_i y_j x_k. Notes (20.16).

    T_ijk = ∫₀¹ B_i^n B_j^n (B_k^n)' dt = n D_ijk^(n) in the notes' notation.
    """
    return _moment_tensor(as_count(n, "n"))


def _polynomial_area(P: np.ndarray) -> np.ndarray:
    """∫ y dx of polynomial pieces P (..., n+1, 2)."""
    A = _area_matrix(P.shape[-2] - 1)
    return np.einsum("...i,ij,...j->...", P[..., 1], A, P[..., 0])


def _sector_area(P: np.ndarray) -> np.ndarray:
    """½∫(x dy - y dx) of polynomial pieces P (..., n+1, 2): Σ_{i<j} A_ij (P_i ∧ P_j)."""
    A = _area_matrix(P.shape[-2] - 1)
    x, y = P[..., 0], P[..., 1]
    return 0.5 * np.einsum("...i,ij,...j->...", x, A - A.T, y)


def _volume(P: np.ndarray) -> np.ndarray:
    """π∫ y² dx of polynomial pieces P (..., n+1, 2)."""
    T = _moment_tensor(P.shape[-2] - 1)
    y = P[..., 1]
    return pi * np.einsum("...i,...j,ijk,...k->...", y, y, T, P[..., 0])


def polynomial_area(points) -> float:
    """The signed area ∫ y dx under a polynomial Bézier curve, yᵀ A x with A = `area_matrix`(n). Notes (20.13).

    points: (n+1, 2), n >= 0. Positive where the curve runs in +x above the axis.

    >>> from cagd_ref.hybrid import polynomial_area
    >>> round(polynomial_area([(0, 0), (0, 1), (1, 1), (1, 0)]), 12)   # x = 3t² - 2t³, y = 3t(1 - t)
    0.6
    """
    return float(_polynomial_area(_planar(points)))


def sector_area(points) -> float:
    """The signed sector area ½∫(x dy - y dx) swept from the origin by a polynomial Bézier curve. Notes (20.14)-(20.15).

    points: (n+1, 2), n >= 0. Counterclockwise travel about the origin is
    positive. Equals Σ_{i<j} A_ij (x_i y_j - x_j y_i), A = `area_matrix`(n); a
    closed chain of curves gets the area it encloses.

    >>> from cagd_ref.hybrid import sector_area
    >>> round(sector_area([(1, 0), (1, 1), (0, 1)]), 6)   # triangle 1/2 plus the parabolic segment 2/3 · 1/2
    0.833333
    >>> sector_area([(1, 0), (0, 1)])                       # a straight line: the triangle with the origin
    0.5
    """
    return float(_sector_area(_planar(points)))


def first_moments(points) -> tuple[float, float]:
    """The first moments (Ix, Iy) = (∫ ½ y² dx, ∫ x y dx) of the region under a polynomial curve. Notes (20.16)-(20.17).

    points: (n+1, 2). Ix / area and Iy / area are the centroid's y and x for a
    curve above the axis with x increasing.

    >>> from cagd_ref.hybrid import first_moments
    >>> [round(v, 6) for v in first_moments([(0, 0), (1, 1)])]   # the triangle under y = x on [0, 1]
    [0.166667, 0.333333]
    """
    pts = _planar(points)
    T = _moment_tensor(len(pts) - 1)
    x, y = pts[:, 0], pts[:, 1]
    return 0.5 * float(np.einsum("i,j,ijk,k->", y, y, T, x)), float(np.einsum("i,j,ijk,k->", x, y, T, x))


def revolution_volume(points) -> float:
    """The signed volume π∫ y² dx swept by a polynomial Bézier curve turning about the x-axis: 2π Ix. Notes (20.18).

    points: (n+1, 2), n >= 0. Signed like the area: positive where x increases.

    >>> from cagd_ref.hybrid import revolution_volume
    >>> round(revolution_volume([(0, 0), (3, 2)]) / np.pi, 12)     # a cone of radius 2 and height 3: πR²h/3
    4.0
    """
    return float(_volume(_planar(points)))


def polynomial_integral(points, kind: str = "area") -> float:
    """One of the closed-form integrals of a polynomial curve by name: "area", "sector" or "volume". Notes §20.2.

    The same as `polynomial_area`, `sector_area`, `revolution_volume`; computed
    independently by multiplying Bernstein polynomials (the integrand x'y,
    ½(xy' - yx') or πx'y², whose integral is the mean of its coefficients),
    which is how the tests cross-check the matrices.
    """
    pts = _planar(points)
    if kind not in KINDS:
        raise ValueError(f"kind: expected one of {KINDS}, got {kind!r}")
    x, y = pts[:, 0], pts[:, 1]
    if len(pts) == 1:
        return 0.0
    dx, dy = hodograph(x[:, None])[:, 0], hodograph(y[:, None])[:, 0]
    if kind == "area":
        integrand = bernstein_multiply(dx, y)
    elif kind == "sector":
        integrand = 0.5 * (bernstein_multiply(dy, x) - bernstein_multiply(dx, y))
    else:
        integrand = pi * bernstein_multiply(bernstein_multiply(y, y), dx)
    return float(bernstein_integral(integrand)[-1])


# --- error bounds (20.27)-(20.29) ----------------------------------------------------------------


def _derivative_bounds(H: np.ndarray) -> np.ndarray:
    """Bounds (..., 2) on |x'(t)|, |y'(t)| over [0, 1] of rational pieces with homogeneous points H (..., r+1, 3).

    x' = (W X' - W' X) / W²: both sides in Bernstein form of degree 2r, the
    quotient lies between the extreme ratios of their coefficients (the
    coefficients of W² are positive for positive weights).
    """
    r = H.shape[-2] - 1
    batch = H.shape[:-2]
    cols = np.moveaxis(H, -2, 0).reshape(r + 1, -1, 3)  # (r+1, pieces, 3): coefficient rows, one column each
    X, W = cols[..., :2], cols[..., 2:]
    dX, dW = hodograph(X.reshape(r + 1, -1)).reshape(r, -1, 2), hodograph(W[..., 0]).reshape(r, -1, 1)
    square = bernstein_multiply(W[..., 0], W[..., 0])  # (2r+1, pieces)
    num = np.stack([bernstein_multiply(W[..., 0], dX[..., c]) - bernstein_multiply(dW[..., 0], X[..., c])
                    for c in range(2)], axis=-1)  # (2r, pieces, 2)
    num = elevate(num.reshape(2 * r, -1)).reshape(2 * r + 1, -1, 2)
    bound = np.abs(num / square[..., None]).max(axis=0)
    return bound.reshape(batch + (2,))


def _piece_bounds(H: np.ndarray, n: int, m: int, kind: str):
    """Polynomial approximations P (..., n+1, 2) of rational pieces H (..., r+1, 3) and bounds (...,) on the error.

    |x_H - x_P| = |x_M(t) - centre_x| B_m^n(t) <= |Δx| B_m^n(t), and ∫ B_m^n = 1/(n+1), so each
    integral of (20.27)-(20.29) with a factor |x_H - x_P| (or |y_H - y_P|) in it is at most |Δx|/(n+1)
    (or |Δy|/(n+1)) times the sup of the other factors: B_x'P = max |hodograph|, B_yP = max |y_i|, and
    the same for R from its control points and `_derivative_bounds`.
    """
    w = H[..., 2]
    R = H[..., :2] / w[..., None]
    fixed, moving = _hybrid(R, w, n, m)
    centre, half = _box(moving)
    fixed[..., m, :] = centre
    dx, dy = np.moveaxis(half / (n + 1), -1, 0)
    dR = _derivative_bounds(H)
    dP = np.abs(n * np.diff(fixed, axis=-2)).max(axis=-2)
    (bxr, byr), (bxp, byp) = np.moveaxis(dR, -1, 0), np.moveaxis(dP, -1, 0)
    if kind == "area":  # (20.27)
        bound = dx * byr + dy * bxp
    elif kind == "sector":  # (20.28), halved
        bound = 0.5 * (dx * (byr + byp) + dy * (bxr + bxp))
    else:  # π times (20.29)
        yr, yp = np.abs(R[..., 1]).max(axis=-1), np.abs(fixed[..., 1]).max(axis=-1)
        bound = pi * (2 * dx * byr * yr + dy * bxp * (yr + yp))
    return fixed, bound


def integral_error_bounds(points, weights, degree: int = ADAPTIVE_DEGREE) -> dict[str, float]:
    """Bounds on |∫ along R - ∫ along P|, P the degree-n approximation: area, sector, volume. Notes (20.27)-(20.29).

    points: (r+1, 2), weights: (r+1,) positive. Returns {"area": ..., "sector":
    ..., "volume": ...}: (20.27) for ∫ y dx, half of (20.28) for the sector area,
    π times (20.29) for the volume, with the factor max B_m^n of the notes'
    B_xPH replaced by ∫ B_m^n = 1/(n+1) (the difference |x_H - x_P| is
    |Δx| B_m^n(t) at most, and it is integrated, not maximised).
    """
    pts = _planar(points)
    w = _positive_weights(weights, len(pts))
    n, m = _degree_and_split(degree, None)
    H = to_homogeneous(pts, w)
    return {kind: float(_piece_bounds(H, n, m, kind)[1]) for kind in KINDS}


# --- the adaptive algorithm of §20.4 ---------------------------------------------------------------


_CLOSED_FORMS = {"area": _polynomial_area, "sector": _sector_area, "volume": _volume}


def _halves(H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Both halves (k, r+1, 3) of k homogeneous pieces (k, r+1, 3), split at t = 1/2 by one de Casteljau run."""
    k, rows, cols = H.shape
    left, right = subdivide(np.moveaxis(H, 0, 1).reshape(rows, k * cols), 0.5)
    return (np.moveaxis(half.reshape(rows, k, cols), 1, 0) for half in (left, right))


def _split(H: np.ndarray) -> np.ndarray:
    """The halves of the pieces H (k, r+1, 3), lefts first: (2k, r+1, 3), maybe (0, r+1, 3)."""
    return np.concatenate(list(_halves(H))) if len(H) else H


def _rational_curve(points, weights) -> tuple[np.ndarray, np.ndarray | None]:
    """Planar points and positive weights, None where the curve is polynomial (no weights, or all equal)."""
    pts = _planar(points)
    if weights is None:
        return pts, None
    w = _positive_weights(weights, len(pts))
    return pts, None if np.ptp(w) == 0 else w


def _adaptive(pts, w, tol: float, kind: str, n: int) -> Integral:
    """Breadth-first §20.4: all pieces of one level at once; a piece of parameter length h is kept when its
    bound is at most tol·h, so the kept bounds add up to at most tol."""
    if w is None or len(pts) <= 2:  # polynomial, or a (rational) line segment: exact at once
        return Integral(float(_CLOSED_FORMS[kind](pts)), 0.0, 1, 1)
    m = n // 2
    level, length = to_homogeneous(pts, w)[None], 1.0
    value, bound, pieces, work = 0.0, 0.0, 0, 0
    while len(level):
        work += len(level)
        if work > MAX_PIECES:
            raise ValueError(f"tol: {tol:g} needs more than {MAX_PIECES} pieces; ask for a larger tolerance")
        P, bounds = _piece_bounds(level, n, m, kind)
        done = bounds <= tol * length
        value += float(_CLOSED_FORMS[kind](P[done]).sum())
        bound += float(bounds[done].sum())
        pieces += int(done.sum())
        level, length = _split(level[~done]), length / 2
    return Integral(value, bound, pieces, work)


def adaptive_integral(points, weights=None, tol: float = 1e-9, kind: str = "area",
                      degree: int = ADAPTIVE_DEGREE) -> Integral:
    """An integral of a polynomial or rational curve to within tol, by hybrid curves and subdivision. Notes §20.4.

    points: (r+1, 2); weights: None or (r+1,) positive; kind: "area" (∫ y dx),
    "sector" (½∫(x dy - y dx)) or "volume" (π∫ y² dx); degree: the hybrid
    degree n >= 2 (m = n // 2). A polynomial curve is integrated exactly in
    closed form. A rational one is split in halves until every piece's bound
    ((20.27)-(20.29), see `integral_error_bounds`) is at most tol times its
    share of the parameter interval; the closed forms of the pieces' polynomial
    approximations add up to the result. Returns Integral(value, bound,
    pieces, work) with |value - exact| <= bound <= tol (up to rounding).
    tol must be positive and at least FLOOR · max|coordinate|² (cubed for volumes).

    >>> from cagd_ref.hybrid import adaptive_integral
    >>> result = adaptive_integral([(0, 0), (0, 1), (1, 1), (1, 0)], [3, 1, 1, 3], tol=1e-6)
    >>> abs(result.value - np.pi / 8) <= result.bound <= 1e-6, result.pieces
    (True, 8)
    """
    pts, w = _rational_curve(points, weights)
    if kind not in KINDS:
        raise ValueError(f"kind: expected one of {KINDS}, got {kind!r}")
    tol = _tolerance(tol, pts, 3 if kind == "volume" else 2)
    n, _ = _degree_and_split(degree, None)
    return _adaptive(pts, w, tol, kind, n)


def adaptive_area_plain(points, weights, tol: float = 1e-9, degree: int = ADAPTIVE_DEGREE) -> float:
    """The adaptive area of §20.4 in its plain recursive form (the teaching form the chapter shows). Notes §20.4.

    points: (r+1, 2), weights: (r+1,) positive. The piece of parameter length
    `share` is kept when its (20.27) bound is at most tol·share, else split at
    t = 1/2 on its homogeneous control points and each half integrated alike.
    `adaptive_integral` computes the same, a whole level of pieces at a time.
    """
    pts = _planar(points)
    w = _positive_weights(weights, len(pts))
    tol = _tolerance(tol, pts)
    n, m = _degree_and_split(degree, None)

    def area(H: np.ndarray, share: float) -> float:
        if share < 2.0**-60:
            raise ValueError(f"tol: {tol:g} cannot be reached by subdivision")
        P, bound = _piece_bounds(H, n, m, "area")
        if bound <= tol * share:
            return float(_polynomial_area(P))
        left, right = subdivide(H, 0.5)
        return area(left, share / 2) + area(right, share / 2)

    return area(to_homogeneous(pts, w), 1.0)


def bezier_area(points, weights=None, tol: float = 1e-9) -> float:
    """The signed area ∫ y dx along a polynomial or rational Bézier curve, to within tol. Notes §20.2, §20.4.

    points: (r+1, 2), r >= 0; weights: None or (r+1,) positive. Polynomial
    curves (and equal weights) get the exact closed form (20.13); rational
    ones the adaptive hybrid method of `adaptive_integral`. Positive where the
    curve runs in +x above the axis; reversing the curve flips the sign. tol:
    positive, at least FLOOR · max|coordinate|² (a ValueError below). The
    result is a float (an `Area`) that also carries its error bound `.bound`.

    The notes' semicircle (Fig. 20.6), whose area is π/8:

    >>> from cagd_ref.hybrid import bezier_area
    >>> semicircle, weights = [(0, 0), (0, 1), (1, 1), (1, 0)], [3, 1, 1, 3]
    >>> [abs(bezier_area(semicircle, weights, tol) - np.pi / 8) <= tol for tol in (1e-3, 1e-6, 1e-9)]
    [True, True, True]
    >>> round(bezier_area(semicircle), 12)                # the same points without weights: 3/5
    0.6
    """
    result = adaptive_integral(points, weights, tol)
    return Area(result.value, result.bound, tol)


# --- the two rules the notes compare with -------------------------------------------------------------


def _chord_bounds(H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Trapezoids under the chords (k,) of rational pieces H (k, r+1, 3), and bounds (k,) on their errors.

    The piece and its chord lie in the hull of its control points, inside the
    rectangle spanned along and across the chord; the area between them is
    at most that rectangle's (the loop of curve and chord is simple on the
    small pieces subdivision makes).
    """
    R = H[..., :2] / H[..., 2:]
    start, end = R[:, 0], R[:, -1]
    trapezoid = (start[:, 1] + end[:, 1]) * (end[:, 0] - start[:, 0]) / 2
    chord = end - start
    length = np.linalg.norm(chord, axis=1)
    unit = np.where(length[:, None] > 0, chord / np.where(length > 0, length, 1)[:, None], [1.0, 0.0])
    rel = R - start[:, None]
    along = np.einsum("kij,kj->ki", rel, unit)
    across = rel[..., 0] * unit[:, None, 1] - rel[..., 1] * unit[:, None, 0]
    return trapezoid, np.ptp(along, axis=1) * np.ptp(across, axis=1)


def trapezoid_area(points, weights=None, tol: float = 1e-6) -> Integral:
    """∫ y dx by trapezoids under the chords of subdivided pieces, with the notes' convex-hull error bound. Notes §20.4.

    A piece of parameter length h is kept when its bound (the rectangle around
    its control points along its chord) is at most tol·h. The bound of a piece
    falls like h³ against h^(n+2) for the hybrid method, so this needs many
    more pieces. Returns Integral(value, bound, pieces, work).
    """
    pts = _planar(points)
    w = np.ones(len(pts)) if weights is None else _positive_weights(weights, len(pts))
    tol = _tolerance(tol, pts)
    level, length = to_homogeneous(pts, w)[None], 1.0
    value, bound, pieces, work = 0.0, 0.0, 0, 0
    while len(level):
        work += len(level)
        if work > MAX_PIECES:
            raise ValueError(f"tol: {tol:g} needs more than {MAX_PIECES} trapezoids; ask for a larger tolerance")
        areas, bounds = _chord_bounds(level)
        done = bounds <= tol * length
        value += float(areas[done].sum())
        bound += float(bounds[done].sum())
        pieces += int(done.sum())
        level, length = _split(level[~done]), length / 2
    return Integral(value, bound, pieces, work)


def simpson_area(points, weights=None, tol: float = 1e-6) -> Integral:
    """∫ y dx = ∫₀¹ y(t) x'(t) dt by the composite Simpson rule, doubling the intervals until two agree. Notes §20.4.

    The heuristic of the notes: stop when |S_2k - S_k| / 15 <= tol (Richardson's
    estimate of the error of S_2k), which is not a guarantee. Returns
    Integral(value, estimate, intervals, evaluations of the integrand); every
    doubling reuses the previous evaluations.
    """
    pts = _planar(points)
    w = None if weights is None else _positive_weights(weights, len(pts))
    tol = _tolerance(tol, pts)

    def integrand(ts: np.ndarray) -> np.ndarray:
        return evaluate(pts, ts, w)[:, 1] * derivative(pts, ts, 1, w)[:, 0]

    ts = np.linspace(0.0, 1.0, 3)
    values = integrand(ts)
    previous = (values[0] + 4 * values[1] + values[2]) / 6
    while True:
        middles = (ts[:-1] + ts[1:]) / 2
        merged = np.empty(2 * len(ts) - 1)
        merged[0::2], merged[1::2] = values, integrand(middles)
        ts, values = np.linspace(0.0, 1.0, len(merged)), merged
        h = 1.0 / (len(ts) - 1)
        current = h / 3 * (values[0] + values[-1] + 4 * values[1:-1:2].sum() + 2 * values[2:-1:2].sum())
        estimate = abs(current - previous) / 15
        if estimate <= tol:
            return Integral(float(current), float(estimate), len(ts) - 1, len(ts))
        if len(ts) > MAX_PIECES:
            raise ValueError(f"tol: {tol:g} needs more than {MAX_PIECES} Simpson intervals")
        previous = current

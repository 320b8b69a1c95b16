"""Bézier curves, polynomial and rational: chapter 2 of the notes.

Control points are float arrays of shape (n+1, d). Rational curves live in
homogeneous coordinates: `to_homogeneous` lifts each point to w*(x, 1), every
algorithm runs on those (d+1)-dimensional points unchanged, and
`from_homogeneous` projects back. Parameters are a number (one point of shape
(d,) comes back) or a 1-D array of k values ((k, d) comes back).
"""

from __future__ import annotations

import functools
from math import comb

import numpy as np

from ._validation import (
    as_count,
    as_interval,
    as_parameter,
    as_points,
    as_positive_weights,
    as_scalar,
    as_tolerance,
    as_vector,
    as_weights,
)
from .polynomials import BLOCK, bernstein_horner, bernstein_to_power

__all__ = [
    "bernstein",
    "bernstein_matrix",
    "de_casteljau",
    "de_casteljau_plain",
    "de_casteljau_triangle",
    "subdivide",
    "elevate",
    "hodograph",
    "evaluate",
    "derivative",
    "curvature",
    "signed_curvature",
    "to_homogeneous",
    "from_homogeneous",
    "endpoint_derivatives",
    "endpoint_curvature",
    "circular_arc",
    "reparametrize_weights",
    "change_interval",
    "explicit_bezier",
    "explicit_rational_bezier",
    "difference_bound",
    "hausdorff_distance",
    "directed_hausdorff",
    "extreme_parameters",
    "bounding_box",
    "arc_length",
]


def _local_parameter(t, interval) -> tuple[np.ndarray, bool]:
    """Map t in `interval` to the local parameter of [0, 1], as a 1-D array."""
    ts, scalar = as_parameter(t)
    t0, t1 = as_interval(interval)
    if (t0, t1) == (0.0, 1.0):
        return ts, scalar  # already local: spare long arrays two passes
    return (ts - t0) / (t1 - t0), scalar


def bernstein(i: int, n: int, t):
    """The Bernstein polynomial B_i^n(t) = C(n, i) (1-t)^(n-i) t^i. Notes §2.1.

    i, n: integers with 0 <= i <= n. t: a number -> float; a 1-D array of k
    values -> (k,). Any real t is allowed (outside [0, 1] the formula extends).

    The cubic ones, B_0^3 = (1-t)³, B_1^3 = 3t(1-t)², B_2^3 = 3t²(1-t), B_3^3 = t³, at t = 1/2:

    >>> from cagd_ref.bezier import bernstein
    >>> [bernstein(i, 3, 0.5) for i in range(4)]
    [0.125, 0.375, 0.375, 0.125]
    >>> bernstein(1, 3, [0.0, 0.25, 1.0]).tolist()
    [0.0, 0.421875, 0.0]
    """
    n = as_count(n, "n")
    i = as_count(i, "i")
    if i > n:
        raise ValueError(f"i: expected 0 <= i <= n = {n}, got {i}")
    ts, scalar = as_parameter(t)
    values = comb(n, i) * (1 - ts) ** (n - i) * ts**i
    return float(values[0]) if scalar else values


def bernstein_matrix(n: int, t) -> np.ndarray:
    """All degree-n Bernstein polynomials B_0^n..B_n^n at t; each row sums to one. Notes §2.1.

    t: a number -> (n+1,); a 1-D array of k values -> (k, n+1).
    """
    n = as_count(n, "n")
    ts, scalar = as_parameter(t)
    i = np.arange(n + 1)
    binomials = np.array([comb(n, j) for j in i], dtype=float)
    values = binomials * (1 - ts[:, None]) ** (n - i) * ts[:, None] ** i
    return values[0] if scalar else values


def de_casteljau_triangle(points, t) -> list[np.ndarray]:
    """Every level of the de Casteljau triangle at a number t: level j has shape (n+1-j, d). Notes §2.3.

    Level 0 is the control polygon, the last level the single point P(t).
    Works for t outside [0, 1] too (extrapolation).
    """
    pts = as_points(points)
    tau = as_scalar(t, "t")
    levels = [pts]
    while len(levels[-1]) > 1:
        previous = levels[-1]
        levels.append((1 - tau) * previous[:-1] + tau * previous[1:])
    return levels


def _in_blocks(evaluator):
    """Decorator: an evaluator `f(points, t)` of all k parameters at once, run on blocks of BLOCK values.

    The vectorised algorithms below make a few passes over their working
    arrays per round. For one block those arrays are small enough to stay in
    the processor's cache through every round; for a million parameters at
    once they are hundreds of megabytes, streamed through memory again in each
    round. Up to BLOCK values the evaluator is called as it is; beyond, on
    consecutive blocks, whose (m, d) results fill one (k, d) array. Either way
    the result is the same.
    """

    @functools.wraps(evaluator)
    def in_blocks(points, t):
        ts, _ = as_parameter(t)
        if len(ts) <= BLOCK:
            return evaluator(points, t)
        # Filled coordinate-major, as the algorithms compute: each block's rows are copied contiguously.
        values = np.empty((as_points(points).shape[1], len(ts)))
        for start in range(0, len(ts), BLOCK):
            values[:, start : start + BLOCK] = evaluator(points, ts[start : start + BLOCK]).T
        return values.T

    return in_blocks


def de_casteljau_plain(points, t) -> np.ndarray:
    """The de Casteljau algorithm in its plain textbook form (the teaching form the chapter shows). Notes §2.3.

    points: (n+1, d). t: a number -> (d,), or a 1-D array of k values -> (k, d);
    any real t (outside [0, 1] the curve is extrapolated). Every parameter
    gets its own copy of the control polygon, and each of the n rounds of the
    triangle (2.4), P_i <- (1-t) P_i + t P_(i+1), replaces all copies by the
    polygon one point shorter.
    `de_casteljau` computes the same points, tuned for very many parameters.

    >>> from cagd_ref.bezier import de_casteljau_plain
    >>> cubic = [(2, 1), (4, 5), (8, 6), (9, 2)]      # the cubic of the notes' hodograph table, §2.7
    >>> de_casteljau_plain(cubic, 0.5).tolist()
    [5.875, 4.5]

    Ref: P. de Casteljau, Outillages méthodes calcul, André Citroën Automobiles, Paris, 1959;
    G. Farin, Curves and Surfaces for CAGD: A Practical Guide, 5th ed., Morgan Kaufmann, 2002.
    """
    pts = as_points(points)
    ts, scalar = as_parameter(t)
    tau = ts[:, None, None]  # one parameter per copy of the polygon
    level = np.broadcast_to(pts, (len(ts),) + pts.shape)  # (k, n+1, d)
    while level.shape[1] > 1:
        level = (1 - tau) * level[:, :-1] + tau * level[:, 1:]
    result = level[:, 0].copy()
    return result[0] if scalar else result


@_in_blocks
def de_casteljau(points, t) -> np.ndarray:
    """Point(s) of the Bézier curve on [0, 1] by repeated linear interpolation, tuned for many parameters. Notes §2.3.

    points: (n+1, d), any degree n >= 0 and dimension d >= 1. t: a number ->
    (d,), or a 1-D array of k values -> (k, d); t outside [0, 1] extrapolates.
    It computes what `de_casteljau_plain` computes (the teaching form), with
    all k parameters in place in coordinate-major arrays, and very long
    arrays a block at a time (see `_in_blocks`): that only makes it faster.

    >>> from cagd_ref.bezier import de_casteljau
    >>> cubic = [(2, 1), (4, 5), (8, 6), (9, 2)]      # the cubic of the notes' hodograph table, §2.7
    >>> de_casteljau(cubic, 0.5).tolist()
    [5.875, 4.5]
    >>> de_casteljau(cubic, [0.0, 1.0]).tolist()      # the curve interpolates its end points
    [[2.0, 1.0], [9.0, 2.0]]

    Ref: P. de Casteljau, Outillages méthodes calcul, André Citroën Automobiles, Paris, 1959;
    G. Farin, Curves and Surfaces for CAGD: A Practical Guide, 5th ed., Morgan Kaufmann, 2002.
    """
    pts = as_points(points)
    ts, scalar = as_parameter(t)
    s = 1 - ts
    # Every parameter gets its own copy of the polygon. The copies are stored
    # coordinate-major, (n+1, d, k), so that each round below is three in-place
    # passes over contiguous rows of k numbers, with no temporary arrays.
    level = np.repeat(pts[:, :, None], len(ts), axis=2)
    right = np.empty_like(level[:-1])
    for m in range(len(pts) - 1, 0, -1):  # this round turns m+1 points into m
        np.multiply(level[1 : m + 1], ts, out=right[:m])  # t P_(i+1)
        level[:m] *= s  # (1 - t) P_i
        level[:m] += right[:m]  # P_i <- (1 - t) P_i + t P_(i+1)
    # A copy in the usual (k, d) layout, so the result does not keep the whole triangle alive.
    result = level[0].T.copy()
    return result[0] if scalar else result


# Above this degree `evaluate` runs the de Casteljau triangle instead of the nested
# form: the factors C(n, i) P_i of the nested form would grow towards overflow
# (C(50, 25) is about 1.3e14), while the triangle only ever averages points.
MAX_NESTED_DEGREE = 50


def _curve_points(pts: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """Σ B_i^n(t) P_i at k parameters, (k, d): the nested Bernstein form (O(n) per point).

    Above MAX_NESTED_DEGREE it runs the de Casteljau triangle instead.
    """
    if len(pts) - 1 > MAX_NESTED_DEGREE:
        return de_casteljau(pts, ts)
    return bernstein_horner(pts, ts)


def subdivide(points, t=0.5) -> tuple[np.ndarray, np.ndarray]:
    """Split a Bézier curve at parameter t into two curves of the same degree. Notes §2.3.

    points: (n+1, d); t: a number. Returns (left, right), each (n+1, d): left
    covers [0, t] and right [t, 1], each reparametrised to [0, 1]. They are
    the two outer edges of the de Casteljau triangle. For t outside [0, 1]
    the two pieces extend the curve (the notes' subdivision at τ = 2).

    >>> from cagd_ref.bezier import subdivide
    >>> left, right = subdivide([(2, 1), (4, 5), (8, 6), (9, 2)], 0.5)   # the notes' cubic of §2.7
    >>> left.tolist()
    [[2.0, 1.0], [3.0, 3.0], [4.5, 4.25], [5.875, 4.5]]
    >>> right.tolist()
    [[5.875, 4.5], [7.25, 4.75], [8.5, 4.0], [9.0, 2.0]]

    Ref: G. Farin, Curves and Surfaces for CAGD: A Practical Guide, 5th ed., Morgan Kaufmann, 2002.
    """
    levels = de_casteljau_triangle(points, t)
    left = np.array([level[0] for level in levels])
    right = np.array([level[-1] for level in reversed(levels)])
    return left, right


def elevate(points, times: int = 1) -> np.ndarray:
    """Raise the degree by one (`times` times) without changing the curve: (n+1, d) -> (n+1+times, d). Notes §2.4.

    P*_i = α_i P_{i-1} + (1 - α_i) P_i with α_i = i / (n+1) (2.8); for a cubic
    α = 0, 1/4, 1/2, 3/4, 1, so P*_1 = P0/4 + 3 P1/4 and so on.

    >>> from cagd_ref.bezier import elevate
    >>> elevate([(2, 1), (4, 5), (8, 6), (9, 2)]).tolist()          # the notes' cubic of §2.7
    [[2.0, 1.0], [3.5, 4.0], [6.0, 5.5], [8.25, 5.0], [9.0, 2.0]]

    Ref: A. R. Forrest, Interactive interpolation and approximation by Bézier polynomials,
    The Computer Journal 15(1), 1972.
    """
    pts = as_points(points)
    times = as_count(times, "times")
    for _ in range(times):
        n = len(pts) - 1
        alpha = (np.arange(n + 2) / (n + 1))[:, None]
        padded_before = np.vstack([pts[:1], pts])
        padded_after = np.vstack([pts, pts[-1:]])
        pts = alpha * padded_before + (1 - alpha) * padded_after
    return pts


def hodograph(points, interval=(0, 1)) -> np.ndarray:
    """Control points of the first derivative curve: n/(t1-t0) (P_{i+1} - P_i), shape (n, d). Notes §2.7.

    points: (n+1, d) of a curve over interval = (t0, t1). The derivative of a
    degree-0 curve is the zero curve, returned as one zero point (1, d).
    The notes' table for the cubic (2, 1), (4, 5), (8, 6), (9, 2) over [0, 1/2]:

    >>> from cagd_ref.bezier import hodograph
    >>> first = hodograph([(2, 1), (4, 5), (8, 6), (9, 2)], (0, 0.5))
    >>> first.tolist()
    [[12.0, 24.0], [24.0, 6.0], [6.0, -24.0]]
    >>> hodograph(first, (0, 0.5)).tolist()
    [[48.0, -72.0], [-72.0, -120.0]]
    """
    pts = as_points(points)
    t0, t1 = as_interval(interval)
    n = len(pts) - 1
    if n == 0:
        return np.zeros_like(pts)
    return n / (t1 - t0) * np.diff(pts, axis=0)


def to_homogeneous(points, weights) -> np.ndarray:
    """Lift rational control points to homogeneous ones w_i (x_i, 1): (n+1, d) -> (n+1, d+1). Notes §2.9.

    weights: (n+1,), none of them zero (negative ones are allowed). The
    rational cubic of the notes' basis-conversion example (chapter 3):

    >>> from cagd_ref.bezier import to_homogeneous
    >>> to_homogeneous([(1, 2), (3, 4), (4, 3), (3, 1)], [1, 3, 1, 2]).tolist()
    [[1.0, 2.0, 1.0], [9.0, 12.0, 3.0], [4.0, 3.0, 1.0], [6.0, 2.0, 2.0]]
    """
    pts = as_points(points)
    w = as_weights(weights, len(pts))
    return np.hstack([pts * w[:, None], w[:, None]])


def from_homogeneous(homogeneous) -> tuple[np.ndarray, np.ndarray]:
    """Project homogeneous points back: (n+1, d+1) -> (points (n+1, d), weights (n+1,)). Notes §2.9.

    The last column holds the weights, none of which may be zero (a point at
    infinity). The notes' table of chapter 3, read as a rational cubic:

    >>> from cagd_ref.bezier import from_homogeneous
    >>> points, weights = from_homogeneous([(1.0, 2.0, 1.0), (9.0, 12.0, 3.0), (4.0, 3.0, 1.0), (6.0, 2.0, 2.0)])
    >>> points.tolist(), weights.tolist()
    ([[1.0, 2.0], [3.0, 4.0], [4.0, 3.0], [3.0, 1.0]], [1.0, 3.0, 1.0, 2.0])
    """
    h = as_points(homogeneous, "homogeneous")
    if h.shape[1] < 2:
        raise ValueError(f"homogeneous: expected at least 2 columns (coordinates and weight), got shape {h.shape}")
    w = h[:, -1]
    if np.any(w == 0):
        raise ValueError(f"homogeneous: a zero weight is a point at infinity, got weights {w.tolist()}")
    return h[:, :-1] / w[:, None], w.copy()


def _project(homogeneous_values: np.ndarray, ts: np.ndarray) -> np.ndarray:
    w = homogeneous_values[:, -1:]
    if np.any(w == 0):
        bad = ts[(w == 0).ravel()]
        raise ValueError(f"t: the rational curve passes through infinity (zero weight) at t = {bad.tolist()}")
    return homogeneous_values[:, :-1] / w


def evaluate(points, t, weights=None, interval=(0, 1)) -> np.ndarray:
    """Point(s) of a polynomial or rational Bézier curve defined over `interval`. Notes §2.2, §2.9.

    points: (n+1, d); weights: None or (n+1,). t: a number -> (d,), or k values -> (k, d).
    A rational curve is evaluated on its homogeneous control points and projected.
    The sum (2.2) is formed in nested form (see `_curve_points`), O(n) per point.

    >>> from cagd_ref.bezier import evaluate
    >>> cubic = [(2, 1), (4, 5), (8, 6), (9, 2)]                # the notes' cubic of §2.7
    >>> evaluate(cubic, 0.5).tolist()
    [5.875, 4.5]
    >>> evaluate(cubic, 7.0, interval=(5, 9)).tolist()          # §2.13: P over [0, 1] is Q(5 + 4t) over [5, 9]
    [5.875, 4.5]
    >>> quarter = [(1, 0), (1, 1), (0, 1)]                      # §2.12: weights 1, cos(θ/2), 1 for θ = π/2
    >>> np.round(evaluate(quarter, 0.5, weights=[1, np.sqrt(2) / 2, 1]), 6).tolist()
    [0.707107, 0.707107]
    """
    pts = as_points(points)
    tau, scalar = _local_parameter(t, interval)
    if weights is None:
        values = _curve_points(pts, tau)
    else:
        values = _project(_curve_points(to_homogeneous(pts, weights), tau), tau)
    return values[0].copy() if scalar else values


def _homogeneous_derivatives(h: np.ndarray, tau: np.ndarray, order: int, interval) -> list[np.ndarray]:
    """Values of the homogeneous curve and its first `order` derivatives at tau, each (k, d+1)."""
    values, curve = [], h
    for _ in range(order + 1):
        values.append(_curve_points(curve, tau))
        curve = hodograph(curve, interval)
    return values


def derivative(points, t, order: int = 1, weights=None, interval=(0, 1)) -> np.ndarray:
    """The `order`-th derivative vector(s) dᵏP/dtᵏ of a (rational) Bézier curve over `interval`. Notes §2.7, §2.9.2.

    Polynomial curves use repeated hodographs. A rational curve P = X / w is
    differentiated by the Leibniz rule on X = w P:
    P⁽ᵏ⁾ = (X⁽ᵏ⁾ - Σ_{j=1..k} C(k, j) w⁽ʲ⁾ P⁽ᵏ⁻ʲ⁾) / w.
    """
    pts = as_points(points)
    order = as_count(order, "order")
    tau, scalar = _local_parameter(t, interval)
    h = pts if weights is None else to_homogeneous(pts, weights)
    derivs = _homogeneous_derivatives(h, tau, order, interval)
    if weights is not None:
        w = [d[:, -1:] for d in derivs]
        p = [_project(derivs[0], tau)]
        for k in range(1, order + 1):
            correction = sum(comb(k, j) * w[j] * p[k - j] for j in range(1, k + 1))
            p.append((derivs[k][:, :-1] - correction) / w[0])
        derivs = p
    result = derivs[order]
    return result[0] if scalar else result


def signed_curvature(points, t, weights=None) -> np.ndarray | float:
    """Signed curvature of a planar curve (positive where it turns left): (x'y'' - y'x'') / |P'|³. Notes §2.9.3.

    Where the speed |P'| is zero (a cusp) the curvature is reported as infinite.
    """
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: signed curvature needs planar points of shape (n+1, 2), got {pts.shape}")
    first, second = _first_two_derivatives(pts, t, weights)
    cross = first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]
    return _finish_curvature(cross, first, t)


def curvature(points, t, weights=None) -> np.ndarray | float:
    """Curvature |P' × P''| / |P'|³ of a (rational) Bézier curve in any dimension d >= 2. Notes §2.9.3.

    points: (n+1, d); weights: None or (n+1,). Returns a float for a number t,
    (k,) for k values. Where the speed |P'| is zero (a cusp) the curvature is
    reported as infinite. The notes' example of (2.13): a rational quadratic
    with weights (1, 2, 4), first leg a = 5 and height h = 4 (the points were
    lost in the notes; these have that a and h) has κ(0) = 2/25:

    >>> from cagd_ref.bezier import curvature
    >>> round(curvature([(0, 0), (5, 0), (8, 4)], 0.0, weights=[1, 2, 4]), 12)
    0.08
    >>> np.round(curvature([(1, 0), (1, 1), (0, 1)], [0.0, 0.5], [1, np.sqrt(2) / 2, 1]), 12).tolist()   # unit circle
    [1.0, 1.0]
    """
    pts = as_points(points)
    if pts.shape[1] < 2:
        raise ValueError(f"points: curvature needs points of dimension >= 2, got shape {pts.shape}")
    first, second = _first_two_derivatives(pts, t, weights)
    # |v ∧ a| from the 2x2 minors v_i a_j - v_j a_i: the cross product's length in 2-D and 3-D,
    # valid in any dimension, and free of the cancellation of |v|²|a|² - (v·a)² on straight pieces.
    i, j = np.triu_indices(pts.shape[1], k=1)
    minors = first[:, i] * second[:, j] - first[:, j] * second[:, i]
    return _finish_curvature(np.linalg.norm(minors, axis=1), first, t)


def _first_two_derivatives(pts, t, weights):
    ts, _ = as_parameter(t)
    return derivative(pts, ts, 1, weights), derivative(pts, ts, 2, weights)


def _finish_curvature(numerator: np.ndarray, first: np.ndarray, t):
    speed = np.linalg.norm(first, axis=1)
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = np.where(speed > 0, numerator / np.where(speed > 0, speed, 1) ** 3, np.inf)
    return float(kappa[0]) if np.ndim(t) == 0 else kappa


def endpoint_derivatives(points, weights=None, interval=(0, 1)) -> tuple[np.ndarray, np.ndarray]:
    """First and second derivative vectors at the start t0 from the first three control points. Notes (2.11), (2.12).

    P'(t0) = n/(t1-t0) (w1/w0) (P1 - P0),
    P''(t0) = n(n-1)/(t1-t0)² (w2/w0) (P2 - P0) - 2n/(t1-t0)² (w1/w0) ((n w1 - w0)/w0) (P1 - P0).
    Needs degree n >= 2. Each result has shape (d,).
    """
    pts = as_points(points, min_count=3)
    n = len(pts) - 1
    w = np.ones(n + 1) if weights is None else as_weights(weights, n + 1)
    t0, t1 = as_interval(interval)
    h = t1 - t0
    first = n / h * (w[1] / w[0]) * (pts[1] - pts[0])
    second = n * (n - 1) / h**2 * (w[2] / w[0]) * (pts[2] - pts[0]) - 2 * n / h**2 * (w[1] / w[0]) * (
        (n * w[1] - w[0]) / w[0]
    ) * (pts[1] - pts[0])
    return first, second


def endpoint_curvature(points, weights=None) -> float:
    """Curvature at t = 0 from the first three control points: ((n-1)/n) (w0 w2 / w1²) h / a². Notes (2.13).

    a = |P1 - P0| is the length of the first leg and h the distance from P2 to the line P0 P1.
    """
    pts = as_points(points, min_count=3)
    n = len(pts) - 1
    w = np.ones(n + 1) if weights is None else as_weights(weights, n + 1)
    leg = pts[1] - pts[0]
    a2 = leg @ leg
    if a2 == 0:
        raise ValueError("points: P0 and P1 coincide, so the endpoint formula does not apply")
    offset = pts[2] - pts[0]
    h = np.sqrt(max(offset @ offset - (offset @ leg) ** 2 / a2, 0.0))
    return float((n - 1) / n * w[0] * w[2] / w[1] ** 2 * h / a2)


def circular_arc(center, radius, start_angle, sweep, degree: int = 2) -> tuple[np.ndarray, np.ndarray]:
    """A circular arc as a rational Bézier curve: (points (degree+1, 2), weights). Notes §2.12.

    Degree 2 has weights (1, cos(θ/2), 1) with the middle point where the end
    tangents meet; degree 3 is its degree elevation, with inner weights
    (1 + 2 cos(θ/2)) / 3. The sweep θ (radians, either sign) must satisfy 0 < |θ| < π.
    """
    c = as_points([center], "center")[0]
    if c.shape != (2,):
        raise ValueError(f"center: expected a 2-D point, got shape {c.shape}")
    r = as_scalar(radius, "radius")
    a = as_scalar(start_angle, "start_angle")
    theta = as_scalar(sweep, "sweep")
    degree = as_count(degree, "degree")
    if r <= 0:
        raise ValueError(f"radius: expected a positive radius, got {r}")
    if not 0 < abs(theta) < np.pi:
        raise ValueError(f"sweep: one rational quadratic covers 0 < |sweep| < π, got {theta}")
    if degree not in (2, 3):
        raise ValueError(f"degree: circular arcs are built in degree 2 or 3, got {degree}")
    half = theta / 2
    angles = np.array([a, a + half, a + theta])
    radii = np.array([r, r / np.cos(half), r])
    points = c + radii[:, None] * np.column_stack([np.cos(angles), np.sin(angles)])
    weights = np.array([1.0, np.cos(half), 1.0])
    if degree == 3:
        return from_homogeneous(elevate(to_homogeneous(points, weights)))
    return points, weights


def reparametrize_weights(weights, b) -> np.ndarray:
    """Weights after the rational-linear reparametrisation t = b u / ((1-u) + b u): w_i b^i. Notes §2.13.

    The curve keeps its control points and endpoints; b > 0 only changes the
    speed, b = -1 traces the complementary part of the curve (t outside [0, 1]).
    """
    w = as_vector(weights, "weights")
    w = as_weights(w, len(w))
    b = as_scalar(b, "b")
    if b == 0:
        raise ValueError("b: b = 0 collapses the curve to its first point")
    return w * b ** np.arange(len(w))


def change_interval(t, old, new):
    """Map parameter(s) t of interval `old` to the matching parameter(s) of interval `new` (affine map). Notes §2.13.

    P over [t0, t1] and Q over [s0, s1] with the same control points satisfy
    P(t) = Q(change_interval(t, (t0, t1), (s0, s1))).
    """
    ts, scalar = as_parameter(t)
    t0, t1 = as_interval(old, "old")
    s0, s1 = as_interval(new, "new")
    mapped = s0 + (ts - t0) * (s1 - s0) / (t1 - t0)
    return float(mapped[0]) if scalar else mapped


def explicit_bezier(coeffs, interval=(0, 1)) -> np.ndarray:
    """Control points (t0 + i/n (t1-t0), c_i) of the explicit curve y = Σ c_i B_i^n, shape (n+1, 2). Notes §2.15.

    A constant (n = 0) is raised to degree 1 so that x = t can be expressed.
    """
    c = as_vector(coeffs, "coeffs")
    t0, t1 = as_interval(interval)
    if len(c) == 1:
        c = np.repeat(c, 2)
    x = np.linspace(t0, t1, len(c))
    return np.column_stack([x, c])


def explicit_rational_bezier(coeffs, weights) -> tuple[np.ndarray, np.ndarray]:
    """The explicit rational curve y = Σ w_i y_i B_i^n / Σ w_i B_i^n on [0, 1] as a rational Bézier curve. Notes §2.15.

    x = t must share the denominator, so x = t Σ w_i B_i^n / Σ w_i B_i^n has
    degree n+1 and y is degree-elevated to match. Returns (points (n+2, 2), weights (n+2,)).
    """
    y = as_vector(coeffs, "coeffs")
    n = len(y) - 1
    w = as_weights(weights, n + 1)
    # t B_i^n = (i+1)/(n+1) B_{i+1}^{n+1}, so t w(t) has coefficients j w_{j-1} / (n+1).
    x_numerator = np.concatenate([[0.0], np.arange(1, n + 2) / (n + 1) * w])
    elevated = elevate(np.column_stack([w * y, w]))
    if np.any(elevated[:, 1] == 0):
        raise ValueError(
            f"weights: the degree-raised weights {elevated[:, 1].tolist()} include a zero "
            "(a control point at infinity), so the curve has no (points, weights) form"
        )
    return from_homogeneous(np.column_stack([x_numerator, elevated]))


def _same_degree(p: np.ndarray, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    if len(p) < len(q):
        p = elevate(p, len(q) - len(p))
    elif len(q) < len(p):
        q = elevate(q, len(p) - len(q))
    return p, q


def difference_bound(p, q) -> float:
    """Upper bound on max_t |P(t) - Q(t)|: the largest |P_i - Q_i| after raising both to one degree. Notes §2.6.

    The difference curve D(t) = P(t) - Q(t) has control points P_i - Q_i and lies
    in their convex hull, so no point of it is farther from the origin than they are.
    """
    p = as_points(p, "p")
    q = as_points(q, "q")
    if p.shape[1] != q.shape[1]:
        raise ValueError(f"p, q: curves of different dimension {p.shape[1]} and {q.shape[1]}")
    p, q = _same_degree(p, q)
    return float(np.max(np.linalg.norm(p - q, axis=1)))


def directed_hausdorff(p, q, samples: int = 1001) -> float:
    """max over s of min over t of |P(s) - Q(t)|, both curves sampled at `samples` parameters. Notes (2.9).

    Sampling makes this a lower bound that converges (error O(1/samples²) near
    smooth closest points) to the exact one-sided distance as samples grows.
    """
    p = as_points(p, "p")
    q = as_points(q, "q")
    if p.shape[1] != q.shape[1]:
        raise ValueError(f"p, q: curves of different dimension {p.shape[1]} and {q.shape[1]}")
    samples = as_count(samples, "samples", minimum=2)
    ts = np.linspace(0, 1, samples)
    a, b = de_casteljau(p, ts), de_casteljau(q, ts)
    # Distances from each point of P to the polyline through Q's samples, not just
    # its vertices, keep the error second order in the sample spacing.
    seg = b[1:] - b[:-1]
    rel = a[:, None, :] - b[None, :-1, :]
    lengths = np.einsum("ij,ij->i", seg, seg)
    u = np.clip(np.einsum("kij,ij->ki", rel, seg) / np.where(lengths > 0, lengths, 1), 0, 1)
    closest = np.linalg.norm(rel - u[..., None] * seg, axis=2).min(axis=1)
    return float(closest.max())


def hausdorff_distance(p, q, samples: int = 1001) -> float:
    """Symmetric Hausdorff distance max(d(P, Q), d(Q, P)) between two Bézier curves, by sampling. Notes §2.6."""
    return max(directed_hausdorff(p, q, samples), directed_hausdorff(q, p, samples))


# --- The course's own (not in the notes), after Pomax's primer: extremes, bounding boxes, arc length.


def _positive_weights(weights, count: int) -> np.ndarray | None:
    if weights is None:
        return None
    return as_positive_weights(weights, count, "expected positive weights (a curve that stays finite)")


def _velocity_numerators(pts: np.ndarray, weights) -> np.ndarray:
    """Power coefficients (m+1, d), one column per coordinate, of polynomials whose roots are the zeros of P'.

    Polynomial curve: the hodograph itself. Rational curve P = X / w: the numerator X' w - X w' of
    P' = (X' w - X w') / w² (the common factor 1/w² has no roots).
    """
    if weights is None:
        return bernstein_to_power(hodograph(pts))
    lifted = to_homogeneous(pts, weights)
    x = bernstein_to_power(lifted[:, :-1])  # (n+1, d): X(t) in the power basis
    w = bernstein_to_power(lifted[:, -1])  # (n+1,): w(t)
    poly = np.polynomial.polynomial
    numerators = np.zeros((2 * len(pts) - 1, pts.shape[1]))  # degree <= 2n - 1 (in fact 2n - 2)
    for k, col in enumerate(x.T):
        values = poly.polysub(poly.polymul(poly.polyder(col), w), poly.polymul(col, poly.polyder(w)))
        numerators[: len(values), k] = values
    return numerators


def extreme_parameters(points, weights=None) -> np.ndarray:
    """Sorted parameters in [0, 1] where a coordinate of the curve can be extreme: 0, 1 and the zeros of P'. Course.

    points: (n+1, d); weights: None or (n+1,) positive. A coordinate of P(t) takes its
    largest and smallest values on [0, 1] at t = 0, t = 1 or where its derivative vanishes:
    the roots in (0, 1) of the coordinates of the hodograph (of X' w - X w' for a rational
    curve). A coordinate that is constant contributes nothing. A parameter where every
    coordinate of P' vanishes (a cusp) is among them. Not in the notes: after Pomax's
    primer, "Extremities". Returns shape (k,), k >= 2.

    >>> from cagd_ref.bezier import extreme_parameters
    >>> extreme_parameters([(0, 0), (1, 2), (3, 2), (4, 0)]).tolist()   # y' = 6 - 12 t vanishes at 1/2
    [0.0, 0.5, 1.0]

    Ref: M. Kamermans, A Primer on Bézier Curves, https://pomax.github.io/bezierinfo/ (Extremities).
    """
    pts = as_points(points)
    w = _positive_weights(weights, len(pts))
    found = [np.array([0.0, 1.0])]
    for column in _velocity_numerators(pts, w).T:
        scale = np.abs(column).max()
        if scale == 0:
            continue  # a constant coordinate: every t is extreme, none is needed
        coefficients = np.polynomial.polynomial.polytrim(column, tol=1e-14 * scale)
        if len(coefficients) < 2:
            continue
        roots = np.polynomial.polynomial.polyroots(coefficients)
        # A root counts as real up to a generous imaginary part: an extra candidate is harmless
        # (it is only evaluated), a missed one would lose an extreme value.
        real = roots.real[np.abs(roots.imag) <= 1e-6 * (1 + np.abs(roots.real))]
        found.append(real[(real > 0) & (real < 1)])
    ts = np.unique(np.concatenate(found))
    return ts[np.concatenate([[True], np.diff(ts) > 1e-12])]  # a double root once


def bounding_box(points, weights=None) -> np.ndarray:
    """The smallest axis-aligned box holding the curve over [0, 1]: [[mins], [maxs]], shape (2, d). Course.

    points: (n+1, d); weights: None or (n+1,) positive. Each coordinate's extreme values
    are taken at the parameters of `extreme_parameters`. The box of the control points
    (convex hull property) holds this one and is usually larger. Not in the notes: after
    Pomax's primer, "Bounding boxes".

    >>> from cagd_ref.bezier import bounding_box
    >>> bounding_box([(0, 0), (1, 2), (3, 2), (4, 0)]).tolist()   # top at P(1/2) = (2, 1.5)
    [[0.0, 0.0], [4.0, 1.5]]

    Ref: M. Kamermans, A Primer on Bézier Curves, https://pomax.github.io/bezierinfo/ (Bounding boxes).
    """
    pts = as_points(points)
    w = _positive_weights(weights, len(pts))
    candidates = evaluate(pts, extreme_parameters(pts, w), weights=w)
    return np.array([candidates.min(axis=0), candidates.max(axis=0)])


# 16-point Gauss-Legendre rule on [0, 1]: exact for polynomials of degree <= 31.
_GAUSS_NODES, _GAUSS_WEIGHTS = np.polynomial.legendre.leggauss(16)
_GAUSS_NODES, _GAUSS_WEIGHTS = (_GAUSS_NODES + 1) / 2, _GAUSS_WEIGHTS / 2


def arc_length(points, weights=None, tol: float = 1e-12) -> float:
    """Length ∫₀¹ |P'(t)| dt of a polynomial or rational Bézier curve, by Gauss-Legendre quadrature. Course.

    points: (n+1, d); weights: None or (n+1,) positive; tol: relative accuracy wanted.
    The speed |P'| is smooth except where P' = 0, so [0, 1] is first cut at the
    `extreme_parameters` (which include every zero of P'); each piece gets a 16-point
    Gauss-Legendre rule, and all pieces are halved until two successive sums agree to
    within tol. For a polynomial curve the result lies between the chord |P_n - P_0|
    and the length of the control polygon. Not in the notes: after Pomax's primer,
    "Arc length".

    >>> from cagd_ref.bezier import arc_length
    >>> round(arc_length([(0, 0), (1, 1), (2, 2)]), 12)                 # a straight quadratic: the chord √8
    2.828427124746
    >>> round(arc_length([(1, 0), (1, 1), (0, 1)], [1, np.sqrt(2) / 2, 1]), 12)   # a quarter of the unit circle
    1.570796326795

    Ref: M. Kamermans, A Primer on Bézier Curves, https://pomax.github.io/bezierinfo/ (Arc length).
    """
    pts = as_points(points)
    w = _positive_weights(weights, len(pts))
    tol = as_tolerance(tol, below_one=True)
    breaks = extreme_parameters(pts, w)
    previous = None
    for _ in range(16):  # at most 2**15 halvings of each piece
        lo, hi = breaks[:-1, None], breaks[1:, None]
        ts = (lo + (hi - lo) * _GAUSS_NODES).ravel()
        speed = np.linalg.norm(derivative(pts, ts, 1, w), axis=1).reshape(len(lo), -1)
        total = float(((hi - lo)[:, 0] * (speed @ _GAUSS_WEIGHTS)).sum())
        if previous is not None and abs(total - previous) <= tol * max(abs(total), 1e-300):
            return total
        previous = total
        breaks = np.unique(np.concatenate([breaks, (breaks[:-1] + breaks[1:]) / 2]))
    return total

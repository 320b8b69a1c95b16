"""Offset curves, their cusps, PH curves with exact rational offsets, and offsets in practice: chapter 8 of the notes.

The offset of a planar curve Q(t) at radius ρ is P(t) = Q(t) + ρ N(t), where
N = (y', -x') / |Q'| is the unit normal on the **right** of the direction of
travel: a positive ρ puts the offset on our right as we walk along Q with t
increasing, a negative ρ on our left. Curvature is signed, positive where the
curve turns left, so the offset side is the concave one where ρκ < 0.

Differentiating gives P' = (1 + ρκ) Q': the offset runs parallel to its base
curve, has a cusp where 1 + ρκ = 0 and runs backwards where 1 + ρκ < 0. With
κ = g / σ³ written through two polynomials, g = x'y'' - y'x'' and
σ² = x'² + y'² (`curvature_polynomials`), the cusps are roots of the
polynomial σ⁶ - ρ² g² (`cusp_polynomial`), found in Bernstein form by
`cagd_ref.roots.bernstein_roots`.

The square root in σ = |Q'| keeps offsets out of the Bézier world, except where
x'² + y'² is the square of a polynomial σ: Pythagorean-hodograph (PH) curves,
whose offsets are rational Bézier curves of degree 2n - 1 (`ph_offset`). The
parabola is the other classic exception: after a rational change of parameter
its offset is a rational curve of degree 6 (`parabola_offset`).

What CAD systems do instead: approximate the offset within a tolerance, by
offsetting control polygons and subdividing (`tiller_hanson_offset`) or by
least-squares B-spline fits refined where the error is too large
(`fit_offset`, with the fitting of chapter 11), and cut away the parts of the
offset that come closer than |ρ| to the curve (`trim_offset`, which measures
distances with `distance_to_curve`).

Points are planar float arrays (n+1, 2), n >= 1; rational curves take positive
weights (n+1,). A parameter t is a number (one result of shape (2,)) or a 1-D
array of k values ((k, 2)).
"""

from __future__ import annotations

import numpy as np

from ._validation import (
    as_count,
    as_float_array,
    as_interval,
    as_parameter,
    as_points,
    as_positive_weights,
    as_scalar,
    as_tolerance,
    as_vector,
)
from .approximation import least_squares_fit
from .bezier import (
    derivative,
    elevate,
    evaluate,
    from_homogeneous,
    hodograph,
    signed_curvature,
    subdivide,
    to_homogeneous,
)
from .bspline import de_boor
from .polynomials import bernstein_horner, bernstein_multiply, bernstein_to_power, power_to_bernstein
from .roots import bernstein_roots

__all__ = [
    "offset_normal",
    "offset_point",
    "offset_derivative",
    "reverse_offset",
    "centre_of_curvature",
    "curvature_polynomials",
    "cusp_polynomial",
    "offset_cusps",
    "cusp_free_interval",
    "ph_hodograph",
    "ph_curve",
    "ph_cubic",
    "ph_speed",
    "is_pythagorean_hodograph",
    "ph_offset",
    "parabola_offset",
    "distance_to_curve",
    "offset_error",
    "trim_offset",
    "tiller_hanson",
    "tiller_hanson_offset",
    "fit_offset",
]

# Below this fraction of the control polygon's scale a speed counts as zero: the curve stops there.
ZERO_SPEED = 1e-12
# A local minimum of |1 + ρκ| this small is a cusp where 1 + ρκ touches zero without changing sign.
TOUCH = 1e-9
# Cusps closer than this are one: double precision cannot tell them apart (their swallowtail is ~1e-14 wide).
MERGE = 1e-6
# Relative size of the coefficients of σ⁶ - ρ² g² below which it vanishes identically.
IDENTICALLY_ZERO = 1e-12
# Relative residual |σ² - (x'² + y'²)| up to which a hodograph counts as Pythagorean.
PH_TOL = 1e-9
# A point of the offset closer to the curve than (1 - CLEARANCE) |ρ| is cut away by trimming.
CLEARANCE = 1e-9


# --- checking the input ----------------------------------------------------------------------


def planar_points(points, min_count: int = 2) -> np.ndarray:
    """Control points (n+1, 2) of a planar curve, n >= 1 (a ValueError otherwise)."""
    pts = as_points(points, min_count=min_count)
    if pts.shape[1] != 2:
        raise ValueError(f"points: offsets are planar, expected shape (n+1, 2), got shape {pts.shape}")
    return pts


def planar_curve(points, weights) -> tuple[np.ndarray, np.ndarray | None]:
    """Checked control points (n+1, 2) and weights (None, or n+1 positive numbers) of a planar curve."""
    pts = planar_points(points)
    if weights is None:
        return pts, None
    return pts, as_positive_weights(weights, len(pts), "offsets need positive weights (no pole on the curve)")


# --- Bernstein coefficient arithmetic (scalar polynomials on [0, 1]) -------------------------


def raise_degree(c: np.ndarray, degree: int) -> np.ndarray:
    """The same polynomial with Bernstein coefficients of a higher `degree`."""
    times = degree - (len(c) - 1)
    return elevate(c[:, None], times)[:, 0] if times else c


def bernstein_sum(*terms: np.ndarray) -> np.ndarray:
    """The sum of Bernstein polynomials of different degrees, at the highest of them."""
    degree = max(len(c) for c in terms) - 1
    return sum(raise_degree(c, degree) for c in terms)


def bernstein_product(*factors: np.ndarray) -> np.ndarray:
    """The product of Bernstein polynomials (chapter 2's product formula, one factor at a time)."""
    result = factors[0]
    for factor in factors[1:]:
        result = bernstein_multiply(result, factor)
    return result


def bernstein_derivative(c: np.ndarray) -> np.ndarray:
    """The derivative of a Bernstein polynomial: its hodograph, n (c_(i+1) - c_i)."""
    return hodograph(c[:, None])[:, 0]


# --- the offset and its derivative ----------------------------------------------------------


def tangents(pts: np.ndarray, ts: np.ndarray, weights) -> np.ndarray:
    """Q'(t) at k parameters, (k, 2), refusing parameters where the curve stops (|Q'| <= ZERO_SPEED n max|ΔP_i|)."""
    first = derivative(pts, ts, 1, weights)
    speed = np.linalg.norm(first, axis=1)
    # n max |P_(i+1) - P_i| bounds |Q'| for a polynomial curve: the yardstick for "zero".
    scale = (len(pts) - 1) * np.linalg.norm(np.diff(pts, axis=0), axis=1).max(initial=0.0)
    stopped = speed <= ZERO_SPEED * scale
    if np.any(stopped):
        raise ValueError(
            f"t: the curve stops (Q'(t) = 0) at t = {ts[stopped].tolist()[:5]}, where its normal, and so its offset, "
            "is undefined"
        )
    return first


def right_normals(first: np.ndarray) -> np.ndarray:
    """Unit normals (y', -x') / |Q'| on the right of the direction of travel, (k, 2)."""
    return np.column_stack([first[:, 1], -first[:, 0]]) / np.linalg.norm(first, axis=1)[:, None]


def offset_normal(points, t, weights=None) -> np.ndarray:
    """The unit normal N = (y', -x') / |Q'| on the right of the direction of travel. Notes §8.

    points: (n+1, 2); weights: None or (n+1,) positive. t: a number -> (2,),
    k values -> (k, 2). A ValueError where the curve stops (Q'(t) = 0).

    >>> from cagd_ref.offsets import offset_normal
    >>> offset_normal([(0, 0), (1, 2), (3, 2), (4, 0)], 0.5).tolist()   # moving in +x: right is down
    [0.0, -1.0]
    """
    pts, w = planar_curve(points, weights)
    ts, scalar = as_parameter(t)
    normals = right_normals(tangents(pts, ts, w))
    return normals[0].copy() if scalar else normals


def offset_point(points, t, rho, weights=None) -> np.ndarray:
    """Point(s) P(t) = Q(t) + ρ (y', -x') / |Q'| of the offset at radius ρ (positive: on the right). Notes §8.

    points: (n+1, 2), n >= 1; weights: None or (n+1,) positive (a rational
    curve, differentiated by the quotient rule). t: a number -> (2,), k values
    -> (k, 2). A ValueError where the curve stops (Q'(t) = 0: no normal).

    The arch below moves in +x at t = 1/2, so its right is below it:

    >>> from cagd_ref.offsets import offset_point
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]
    >>> offset_point(arch, 0.5, 0.3).tolist()
    [2.0, 1.2]
    >>> offset_point(arch, [0.0, 1.0], -1.0).round(6).tolist()   # on the left, outside the arch
    [[-0.894427, 0.447214], [4.894427, 0.447214]]
    """
    pts, w = planar_curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    points_on_offset = evaluate(pts, ts, w) + rho * offset_normal(pts, ts, w)
    return points_on_offset[0] if scalar else points_on_offset


def offset_derivative(points, t, rho, weights=None) -> np.ndarray:
    """The derivative P'(t) = (1 + ρκ(t)) Q'(t) of the offset at radius ρ, κ signed (left turns positive). Notes §8.

    The offset is parallel to its base curve wherever it is regular; it stops
    (a cusp) where 1 + ρκ = 0 and runs backwards where 1 + ρκ < 0. Shapes as
    in `offset_point`; a ValueError where Q'(t) = 0.

    >>> from cagd_ref.offsets import offset_derivative
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]     # κ(1/2) = -16/27 and Q'(1/2) = (4.5, 0)
    >>> offset_derivative(arch, 0.5, 0.3).round(6).tolist()
    [3.7, 0.0]
    >>> round(float(offset_derivative(arch, 0.5, 2.5)[0]), 6)   # 1 + ρκ < 0: it runs backwards
    -2.166667
    """
    pts, w = planar_curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    first = tangents(pts, ts, w)
    kappa = signed_curvature(pts, ts, w)
    result = (1 + rho * kappa)[:, None] * first
    return result[0] if scalar else result


def reverse_offset(points, t, rho, weights=None) -> np.ndarray:
    """Offset the offset back: P(t) - ρ N_P(t), with N_P the right normal of the offset P itself. Notes §8.

    Where 1 + ρκ > 0 the offset runs along Q and this gives Q(t) back; on an
    arc where 1 + ρκ < 0 the offset runs backwards, N_P = -N and the result is
    Q(t) + 2ρ N(t) instead: offsetting is undone only while |ρ| stays below the
    radius of curvature on the offset side. Shapes as in `offset_point`; a
    ValueError at a cusp of the offset (1 + ρκ = 0), where N_P is undefined.

    >>> from cagd_ref.offsets import reverse_offset
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]     # Q(1/2) = (2, 1.5), N(1/2) = (0, -1)
    >>> reverse_offset(arch, 0.5, 0.3).round(9).tolist()
    [2.0, 1.5]
    >>> reverse_offset(arch, 0.5, 2.5).round(9).tolist()   # between the cusps: Q + 2ρN
    [2.0, -3.5]
    """
    pts, w = planar_curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    first = tangents(pts, ts, w)
    factor = 1 + rho * signed_curvature(pts, ts, w)
    cusps = np.abs(factor) <= ZERO_SPEED
    if np.any(cusps):
        raise ValueError(f"t: the offset has a cusp (1 + ρκ = 0) at t = {ts[cusps].tolist()[:5]}, so no normal there")
    offset = evaluate(pts, ts, w) + rho * right_normals(first)
    back = offset - rho * right_normals(factor[:, None] * first)
    return back[0] if scalar else back


def centre_of_curvature(points, t, weights=None) -> np.ndarray:
    """The centre of curvature Q - N/κ (on the concave side, at distance 1/|κ|): a point of the evolute. Notes §8.

    Every cusp of every offset lies on this curve: at a cusp ρ = -1/κ, so
    P = Q + ρN = Q - N/κ. Shapes as in `offset_point`; a ValueError where
    κ = 0 (an inflection or a straight piece: the centre is at infinity).

    >>> from cagd_ref.offsets import centre_of_curvature
    >>> centre_of_curvature([(0, 0), (1, 2), (3, 2), (4, 0)], 0.5).tolist()   # 27/16 below Q(1/2) = (2, 1.5)
    [2.0, -0.1875]
    """
    pts, w = planar_curve(points, weights)
    ts, scalar = as_parameter(t)
    normals = right_normals(tangents(pts, ts, w))
    kappa = signed_curvature(pts, ts, w)
    flat = np.abs(kappa) * np.ptp(pts, axis=0).max() <= ZERO_SPEED
    if np.any(flat):
        raise ValueError(f"t: the curve does not bend (κ = 0) at t = {ts[flat].tolist()[:5]}: no finite centre")
    centres = evaluate(pts, ts, w) - normals / kappa[:, None]
    return centres[0] if scalar else centres


# --- cusps ------------------------------------------------------------------------------------


def curvature_polynomials(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Bernstein coefficients on [0, 1] of g and σ² with the signed curvature κ = g / (σ²)^(3/2). Notes §8.

    Polynomial curves: g = x'y'' - y'x'' (degree 2n-3) and σ² = x'² + y'²
    (degree 2n-2).
    Rational curves Q = (X, Y) / W: g = W³ det(H, H', H'') and
    σ² = |W (X', Y') - W' (X, Y)|², with H = (X, Y, W); the common factor W⁶
    of g² and (σ²)³ leaves κ unchanged.

    >>> from cagd_ref.offsets import curvature_polynomials
    >>> g, speed2 = curvature_polynomials([(0, 0), (1, 2), (3, 2), (4, 0)])
    >>> g.tolist(), speed2.tolist()      # g = -72(t² - t + 1), σ² = 9(2t² - 2t + 1)(2t² - 2t + 5)
    ([-72.0, -48.0, -48.0, -72.0], [45.0, 18.0, 15.0, 18.0, 45.0])
    """
    pts, w = planar_curve(points, weights)
    if w is None:
        first = hodograph(pts)
        second = hodograph(first)
        (x1, y1), (x2, y2) = first.T, second.T
        g = bernstein_sum(bernstein_product(x1, y2), -bernstein_product(y1, x2))
        return g, bernstein_sum(bernstein_product(x1, x1), bernstein_product(y1, y1))
    # Q = (X, Y) / W: Q' = D / W² with D = W (X', Y') - W' (X, Y), and Q' × Q'' = det(H, H', H'') / W³.
    h = to_homogeneous(pts, w)
    h1 = hodograph(h)
    h2 = hodograph(h1)
    (x, y, ww), (x1, y1, w1), (x2, y2, w2) = h.T, h1.T, h2.T
    dx = bernstein_sum(bernstein_product(ww, x1), -bernstein_product(w1, x))
    dy = bernstein_sum(bernstein_product(ww, y1), -bernstein_product(w1, y))
    det = bernstein_sum(
        bernstein_product(x, bernstein_sum(bernstein_product(y1, w2), -bernstein_product(w1, y2))),
        -bernstein_product(y, bernstein_sum(bernstein_product(x1, w2), -bernstein_product(w1, x2))),
        bernstein_product(ww, bernstein_sum(bernstein_product(x1, y2), -bernstein_product(y1, x2))),
    )
    return bernstein_product(ww, ww, ww, det), bernstein_sum(bernstein_product(dx, dx), bernstein_product(dy, dy))


def cusp_terms(g: np.ndarray, speed2: np.ndarray, rho: float) -> tuple[np.ndarray, float]:
    """(σ²)³ - ρ² g² in Bernstein form, and the size of its two terms (for relative tests)."""
    cubed = bernstein_product(speed2, speed2, speed2)
    squared = rho**2 * bernstein_product(g, g)
    scale = max(np.abs(cubed).max(), np.abs(squared).max())
    return bernstein_sum(cubed, -squared), scale


def cusp_polynomial(points, rho, weights=None) -> np.ndarray:
    """Bernstein coefficients on [0, 1] of f = σ⁶ - ρ² g², whose roots hold the cusps of the offset. Notes §8.

    1 + ρκ = 0 means σ³ = -ρ g; squaring gives this polynomial (degree 6n - 6
    for a polynomial curve). Squaring adds the roots of 1 - ρκ = 0 as well:
    those with ρ g(t) > 0 are cusps of the offset on the other side (radius
    -ρ), not of this one. f = σ⁶ (1 + ρκ)(1 - ρκ).
    """
    pts, w = planar_curve(points, weights)
    rho = as_scalar(rho, "rho")
    return cusp_terms(*curvature_polynomials(pts, w), rho)[0]


def touching_zeros(f: np.ndarray, roots: np.ndarray, factor) -> list[float]:
    """Where |1 + ρκ| has a local minimum (a critical point of f, or an end) of size <= TOUCH and no root nearby.

    A double root of f, where 1 + ρκ touches zero without crossing, may be lost
    to rounding (f stays a hair above zero). Each critical point of f bounds,
    with its neighbours, the pieces where f is monotone; a root found in the
    pieces beside a candidate already accounts for it.
    """
    slope = bernstein_derivative(f)
    critical = bernstein_roots(slope) if np.any(slope) else np.array([])
    stops = np.concatenate([[0.0], critical, [1.0]])
    found = []
    for k in range(len(stops)):
        lo, hi = stops[max(k - 1, 0)], stops[min(k + 1, len(stops) - 1)]
        if abs(factor(stops[k])) <= TOUCH and not np.any((roots >= lo) & (roots <= hi)):
            found.append(float(stops[k]))
    return found


def merge_close(ts: list[float]) -> np.ndarray:
    """Sorted parameters, those closer than MERGE replaced by their mean: rounding may split a double root in two."""
    groups: list[list[float]] = []
    for t in ts:
        if groups and t - groups[-1][-1] <= MERGE:
            groups[-1].append(t)
        else:
            groups.append([t])
    return np.array([sum(group) / len(group) for group in groups])


def offset_cusps(points, rho, weights=None) -> np.ndarray:
    """Sorted parameters t in [0, 1] where 1 + ρκ(t) = 0: the cusps of the offset at radius ρ. Notes §8.

    κ is the signed curvature (positive turning left), so cusps lie where the
    radius of curvature 1/|κ| equals |ρ| on the offset's side (ρκ < 0). The
    roots of `cusp_polynomial` are found in Bernstein form, those of the other
    side (ρ g > 0) dropped, and a point where 1 + ρκ only touches zero (ρ equal
    to a minimum radius of curvature) is reported once, as are cusps closer than
    MERGE = 1e-6. Returns (k,), maybe (0,). Where the curve almost stops the
    squared polynomial loses digits, and so do the cusps found there.
    A ValueError when 1 + ρκ vanishes identically (a circular arc offset to its
    centre) or the curve is a single point.

    The arch's tightest bend has radius 27/16 = 1.6875, at t = 1/2, on its right:

    >>> from cagd_ref.offsets import offset_cusps
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]
    >>> offset_cusps(arch, 2.5).round(10).tolist()
    [0.2059328696, 0.7940671304]
    >>> offset_cusps(arch, 1.5).tolist(), offset_cusps(arch, -2.5).tolist()
    ([], [])
    >>> offset_cusps(arch, 27 / 16).round(6).tolist()      # 1 + ρκ touches zero
    [0.5]

    Ref: R. T. Farouki and C. A. Neff, Analytic properties of plane offset curves, CAGD 7, 1990, 83-99.
    """
    pts, w = planar_curve(points, weights)
    rho = as_scalar(rho, "rho")
    if np.ptp(pts, axis=0).max() == 0:
        raise ValueError("points: all control points coincide, so the curve is a single point without normals")
    g, speed2 = curvature_polynomials(pts, w)
    f, scale = cusp_terms(g, speed2, rho)  # f = σ⁶ - ρ²g² = σ⁶ (1 + ρκ)(1 - ρκ)
    if np.abs(f).max() <= IDENTICALLY_ZERO * scale:
        raise ValueError(
            "rho: 1 + ρκ vanishes identically (a circular arc offset by its radius towards its centre: "
            "the whole offset collapses to one point)"
        )
    if rho == 0:
        return np.array([])
    moving = IDENTICALLY_ZERO * np.abs(speed2).max()  # σ² below this: the curve stops, κ is undefined

    def factor(t):  # 1 + ρκ(t)
        s2 = bernstein_horner(speed2, t)
        return 1 + rho * bernstein_horner(g, t) / s2**1.5 if s2 > moving else np.inf

    roots = bernstein_roots(f)
    # Squaring brought in the cusps of the other side (ρg > 0) and the points where the curve stops.
    kept = [float(t) for t in roots if rho * bernstein_horner(g, t) < 0 and bernstein_horner(speed2, t) > moving]
    return merge_close(sorted(kept + touching_zeros(f, roots, factor)))


def cusp_free_interval(points, weights=None) -> tuple[float, float]:
    """The radii (low, high), low < 0 < high, of cusp-free offsets: 1 + ρκ > 0 on [0, 1] for low < ρ < high. Notes §8.

    high = 1 / max(-κ) is the smallest radius of curvature where the curve
    turns right (the offset side of a positive ρ), low = -1 / max(κ) the same
    on the left; a side the curve never turns to gives ±inf. The extremes of κ
    are at the ends or at the roots of (κ (σ²)^(5/2))' ∝ g' σ² - (3/2) g (σ²)'.
    """
    pts, w = planar_curve(points, weights)
    g, speed2 = curvature_polynomials(pts, w)
    slope = bernstein_sum(
        bernstein_product(bernstein_derivative(g), speed2), -1.5 * bernstein_product(g, bernstein_derivative(speed2))
    )
    ends = np.array([0.0, 1.0])
    ts = np.concatenate([ends, bernstein_roots(slope)]) if np.any(slope) else ends
    s2 = bernstein_horner(speed2, ts)
    kappa = bernstein_horner(g, ts)[s2 > 0] / s2[s2 > 0] ** 1.5
    high = 1 / -kappa.min() if kappa.size and kappa.min() < 0 else np.inf
    low = -1 / kappa.max() if kappa.size and kappa.max() > 0 else -np.inf
    return float(low), float(high)


# --- Pythagorean-hodograph curves --------------------------------------------------------------


def ph_pair(u, v) -> tuple[np.ndarray, np.ndarray]:
    """Checked Bernstein coefficients (m+1,) of the two polynomials u and v of a PH curve."""
    u = as_vector(u, "u")
    v = as_vector(v, "v")
    if len(u) != len(v):
        raise ValueError(f"u, v: expected coefficients of the same degree, got {len(u)} and {len(v)}")
    return u, v


def ph_hodograph(u, v) -> np.ndarray:
    """The Pythagorean hodograph (u² - v², 2uv) in Bernstein form (2m+1, 2), from u, v (m+1,) of degree m. Notes §8.

    Its length is u² + v²: (u² - v²)² + (2uv)² = (u² + v²)², a perfect square.
    """
    u, v = ph_pair(u, v)
    return np.column_stack([bernstein_sum(bernstein_product(u, u), -bernstein_product(v, v)),
                            2 * bernstein_product(u, v)])


def ph_curve(p0, u, v) -> np.ndarray:
    """The PH curve of degree 2m+1 starting at p0 whose hodograph is (u² - v², 2uv): control points (2m+2, 2). Notes §8.

    u, v: Bernstein coefficients (m+1,) of two polynomials of degree m. The
    control points are p0 plus the running sums of the hodograph's
    coefficients divided by 2m+1 (a curve of degree n has the hodograph
    n (P_(i+1) - P_i), so P_(i+1) = P_i + h_i / n).
    """
    start = as_vector(p0, "p0", 2)
    h = ph_hodograph(u, v)
    return start + np.vstack([np.zeros(2), np.cumsum(h, axis=0) / len(h)])


def ph_cubic(p0, u, v) -> np.ndarray:
    """The PH cubic starting at p0 with x' = u² - v², y' = 2uv for linear u, v: control points (4, 2). Notes §8.

    p0: (2,); u = (u0, u1), v = (v0, v1): Bernstein coefficients of the two
    linear polynomials. The hodograph (u² - v², 2uv) has the coefficients
    (u0² - v0², 2u0v0), (u0u1 - v0v1, u0v1 + u1v0), (u1² - v1², 2u1v1), so
    P1 = P0 + (u0² - v0², 2u0v0)/3, P2 = P1 + (u0u1 - v0v1, u0v1 + u1v0)/3,
    P3 = P2 + (u1² - v1², 2u1v1)/3.

    >>> from cagd_ref.offsets import ph_cubic
    >>> ph_cubic((0, 0), (2, 1), (0, 1)).round(6).tolist()
    [[0.0, 0.0], [1.333333, 0.0], [2.0, 0.666667], [2.0, 1.333333]]

    Ref: R. T. Farouki and T. Sakkalis, Pythagorean hodographs, IBM J. Res. Develop. 34(5), 1990, 736-752.
    """
    u, v = ph_pair(u, v)
    if len(u) != 2:
        raise ValueError(f"u: a PH cubic takes linear u and v, two Bernstein coefficients each, got {len(u)}")
    return ph_curve(p0, u, v)


def polynomial_square_root(p: np.ndarray, tol: float) -> np.ndarray | None:
    """σ with σ² = p (Bernstein coefficients on [0, 1], p of even degree 2m): σ (m+1,), or None if p is no square.

    σ is the Taylor polynomial of √p about the place where p is largest (where
    the square root is best conditioned): with p = Σ p_j τ^j and σ = Σ s_j τ^j
    in τ = t - centre, matching the coefficients of σ² = p gives s_0 = √p_0 and
    s_j = (p_j - Σ_(0<i<j) s_i s_(j-i)) / (2 s_0). The result is accepted when
    σ² = p to within tol · max|p_i|; it is positive at the centre.
    """
    degree = (len(p) - 1) // 2
    grid = np.linspace(0, 1, 2 * degree + 3)
    centre = grid[np.argmax(bernstein_horner(p, grid))]
    power = bernstein_to_power(p, (-centre, 1 - centre))  # the same polynomial in τ = t - centre
    s = np.zeros(degree + 1)
    s[0] = np.sqrt(power[0])
    for j in range(1, degree + 1):
        s[j] = (power[j] - s[1:j] @ s[j - 1 : 0 : -1]) / (2 * s[0])
    sigma = power_to_bernstein(s, (-centre, 1 - centre))
    residual = np.abs(bernstein_sum(bernstein_product(sigma, sigma), -p)).max()
    return sigma if residual <= tol * np.abs(p).max() else None


def squared_speed(pts: np.ndarray) -> np.ndarray:
    """x'² + y'² of a polynomial curve in Bernstein form, degree 2n - 2."""
    x1, y1 = hodograph(pts).T
    return bernstein_sum(bernstein_product(x1, x1), bernstein_product(y1, y1))


def is_pythagorean_hodograph(points, tol: float = PH_TOL) -> bool:
    """Whether x'² + y'² is the square of a polynomial σ (to a relative `tol` on its Bernstein coefficients). Notes §8.

    points: (n+1, 2). A curve that is a single point has no hodograph to speak of: False.
    """
    pts = planar_points(points)
    tol = as_scalar(tol, "tol")
    if not tol > 0:
        raise ValueError(f"tol: expected a positive tolerance, got {tol}")
    speed2 = squared_speed(pts)
    return bool(np.any(speed2)) and polynomial_square_root(speed2, tol) is not None


def smallest_value(c: np.ndarray) -> tuple[float, float]:
    """The smallest value of Σ c_i B_i on [0, 1] and where it is taken (ends and critical points)."""
    slope = bernstein_derivative(c)
    ts = np.concatenate([[0.0, 1.0], bernstein_roots(slope) if np.any(slope) else []])
    values = bernstein_horner(c, ts)
    return float(values.min()), float(ts[np.argmin(values)])


def ph_speed(points) -> np.ndarray:
    """The parametric speed |Q'(t)| of a PH curve as a polynomial σ: Bernstein coefficients (n,) on [0, 1]. Notes §8.

    σ² = x'² + y'² (within the relative tolerance PH_TOL), found by
    `polynomial_square_root`; σ is positive where the curve moves fastest, and
    equals |Q'| on [0, 1] unless the curve stops. A ValueError when x'² + y'²
    is not a perfect square.
    """
    pts = planar_points(points)
    speed2 = squared_speed(pts)
    sigma = polynomial_square_root(speed2, PH_TOL) if np.any(speed2) else None
    if sigma is None:
        raise ValueError("points: x'² + y'² is not the square of a polynomial, so this is not a PH curve")
    return sigma


def ph_offset(points, rho) -> tuple[np.ndarray, np.ndarray]:
    """The exact offset of a PH curve at radius ρ, a rational Bézier curve of degree 2n-1: (points, weights). Notes §8.

    Returns points (2n, 2) and weights (2n,). With σ = |Q'| a polynomial of degree n-1, Q + ρ (y', -x') / σ has the
    homogeneous form (σ Q + ρ (y', -x'), σ): σQ has degree 2n-1 and the other
    two terms are raised to it. The weights are the coefficients of σ so
    raised; evaluated at t the curve gives Q(t) + ρ N(t). A ValueError if the
    curve is not PH, or stops somewhere in [0, 1] (min σ <= ZERO_SPEED max|σ_i|).

    >>> from cagd_ref.offsets import ph_cubic, ph_offset
    >>> points, weights = ph_offset(ph_cubic((0, 0), (2, 1), (0, 1)), 0.25)
    >>> weights.round(6).tolist()
    [4.0, 3.2, 2.6, 2.2, 2.0, 2.0]
    >>> points.round(6).tolist()
    [[0.0, -0.25], [1.0625, -0.25], [1.673077, 0.076923], [2.022727, 0.424242], [2.25, 0.833333], [2.25, 1.333333]]

    Ref: R. T. Farouki and T. Sakkalis, Pythagorean hodographs, IBM J. Res. Develop. 34(5), 1990, 736-752;
    R. T. Farouki, Pythagorean-Hodograph Curves: Algebra and Geometry Inseparable, Springer, 2008.
    """
    pts = planar_points(points)
    rho = as_scalar(rho, "rho")
    sigma = ph_speed(pts)  # degree n - 1, σ² = x'² + y'²
    lowest, where = smallest_value(sigma)
    if lowest <= ZERO_SPEED * np.abs(sigma).max():
        raise ValueError(f"points: the PH curve stops (Q' = 0) at t = {where:.6g}, where its offset is undefined")
    n = len(pts) - 1
    h = hodograph(pts)  # (x', y'), degree n - 1
    numerator = np.column_stack([bernstein_product(sigma, pts[:, 0]), bernstein_product(sigma, pts[:, 1])])
    numerator += rho * elevate(np.column_stack([h[:, 1], -h[:, 0]]), n)  # ρ (y', -x') raised to degree 2n - 1
    weights = raise_degree(sigma, 2 * n - 1)
    if np.any(weights == 0):
        raise ValueError("points: the offset has a control point at infinity (a zero weight); split the curve first")
    return numerator / weights[:, None], weights


# --- the parabola ------------------------------------------------------------------------------


def parabola_offset(rho, interval=(-1.0, 1.0)) -> tuple[np.ndarray, np.ndarray]:
    """The offset at radius ρ of the parabola (t, t²), t in `interval`: a rational Bézier curve of degree 6. Notes §8.

    The parameter change t = (ν² - 1) / (4ν), ν > 0, turns √(1 + 4t²) into
    (ν² + 1) / (2ν), and the offset into (X, Y) / W with
    X = 4ν(ν² - 1)(ν² + 4ρν + 1), Y = (ν² - 1)²(ν² + 1) - 32ρν³, W = 16ν²(ν² + 1),
    of degrees 5, 6 and 4 without a common factor. Over the ν-interval of
    `interval` (ν = 2t + √(4t² + 1)) that is a degree-6 rational Bézier curve:
    returns (points (7, 2), weights (7,)), positive ρ on the right (below the
    vertex, the convex side). The notes say eight; six is the least possible,
    as the offset's implicit equation has degree 6 and this form traces it once.
    """
    rho = as_scalar(rho, "rho")
    t0, t1 = as_interval(interval)
    nu0, nu1 = (2 * t + np.sqrt(4 * t * t + 1) for t in (t0, t1))
    power = np.array([
        [0.0, -4.0, -16 * rho, 0.0, 16 * rho, 4.0, 0.0],  # X
        [1.0, 0.0, -1.0, -32 * rho, -1.0, 0.0, 1.0],  # Y
        [0.0, 0.0, 16.0, 0.0, 16.0, 0.0, 0.0],  # W
    ]).T
    return from_homogeneous(power_to_bernstein(power, (nu0, nu1)))


# --- offsets in practice: distance to the curve, and trimming ------------------------------------


def foot_point_polynomials(pts: np.ndarray, weights) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(c0, c1, c2) in Bernstein form with (Q(s) - p) · Q'(s) ∝ c0 - p_x c1 - p_y c2 for every point p.

    Polynomial curves: c0 = Q · Q', (c1, c2) = Q' (degree 2n - 1). Rational
    curves Q = (X, Y) / W: the numerator (XY - pW) · D with D = W (X', Y') - W' (X, Y)
    (degree 3n - 1; the dropped factor 1/W³ is positive).
    """
    if weights is None:
        first = elevate(hodograph(pts), len(pts) - 1)
        return (bernstein_sum(bernstein_product(pts[:, 0], hodograph(pts)[:, 0]),
                              bernstein_product(pts[:, 1], hodograph(pts)[:, 1])), first[:, 0], first[:, 1])
    h = to_homogeneous(pts, weights)
    h1 = hodograph(h)
    (x, y, w), (x1, y1, w1) = h.T, h1.T
    dx = bernstein_sum(bernstein_product(w, x1), -bernstein_product(w1, x))
    dy = bernstein_sum(bernstein_product(w, y1), -bernstein_product(w1, y))
    c0 = bernstein_sum(bernstein_product(x, dx), bernstein_product(y, dy))
    return c0, bernstein_product(w, dx), bernstein_product(w, dy)


def distance_to_curve(points, xy, weights=None) -> np.ndarray | float:
    """The distance from point(s) `xy` to the curve Q(t), 0 <= t <= 1 (the nearest point anywhere on it). Notes §8.

    The nearest point is an end of the curve or a foot point, where Q(s) - p is
    perpendicular to Q'(s): a root of the polynomial (Q(s) - p) · Q'(s), of
    degree 2n - 1 (3n - 1 for a rational curve), found in Bernstein form
    (chapter 9). xy: (2,) -> a number, (k, 2) -> (k,).

    >>> from cagd_ref.offsets import distance_to_curve
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]
    >>> round(float(distance_to_curve(arch, (2.0, 1.2))), 12)     # on the offset at ρ = 0.3
    0.3
    >>> distance_to_curve(arch, [(2.0, -1.0), (-1.0, 0.0)]).round(6).tolist()   # the nearest point: the end (0, 0)
    [2.236068, 1.0]
    """
    pts, w = planar_curve(points, weights)
    query = query_points(xy)
    c0, c1, c2 = foot_point_polynomials(pts, w)
    scale = np.abs(c0).max() + (np.abs(c1).max() + np.abs(c2).max()) * np.abs(query).max(initial=0.0)
    distances = np.empty(len(query))
    for k, (px, py) in enumerate(query):
        g = c0 - px * c1 - py * c2  # (Q(s) - p) · Q'(s), up to a positive factor
        feet = bernstein_roots(g) if np.abs(g).max() > IDENTICALLY_ZERO * scale else np.array([])
        candidates = np.concatenate([[0.0, 1.0], feet])
        distances[k] = np.linalg.norm(evaluate(pts, candidates, w) - (px, py), axis=1).min()
    return float(distances[0]) if np.ndim(xy) == 1 else distances


def query_points(xy) -> np.ndarray:
    """Query points as a float array (k, 2): a single point (2,) becomes one row."""
    array = as_float_array(xy, "xy")
    array = array[None, :] if array.ndim == 1 else array
    if array.ndim != 2 or array.shape[1] != 2 or len(array) == 0:
        raise ValueError(f"xy: expected a point (2,) or points (k, 2) of the plane, got shape {np.shape(xy)}")
    return array


def offset_error(points, rho, xy, t, weights=None) -> np.ndarray | float:
    """How far point(s) `xy`, meant to lie on the offset near parameter(s) t, are from it: ||xy-Q(τ)|-|ρ||. Notes §8.

    τ is the foot point of xy on Q nearest to t: Newton's method on
    (Q(τ) - xy) · Q'(τ) = 0 started at t and kept in [0, 1]. The offset is the
    set of points at distance |ρ| from Q along a normal, so this is how far an
    approximate offset strays from it. xy: (2,)
    with a number t -> a number; (k, 2) and/or k parameters -> (k,) (a single
    point or parameter is used for all).

    >>> from cagd_ref.offsets import offset_error
    >>> arch = [(0, 0), (1, 2), (3, 2), (4, 0)]
    >>> round(float(offset_error(arch, 0.3, (2.0, 1.25), 0.5)), 12)    # 0.25 below Q(1/2) instead of 0.3
    0.05
    """
    pts, w = planar_curve(points, weights)
    rho = as_scalar(rho, "rho")
    query = query_points(xy)
    ts, scalar = as_parameter(t)
    scalar = scalar and np.ndim(xy) == 1
    if len(ts) != len(query) and 1 not in (len(ts), len(query)):
        raise ValueError(f"t: expected one parameter per point ({len(query)}), got {len(ts)}")
    ts, query = np.broadcast_arrays(ts[:, None], query)
    ts, query = ts[:, 0].copy(), query.copy()
    tau = np.clip(ts, 0.0, 1.0)
    for _ in range(8):  # Newton on F(τ) = (Q - xy) · Q', F' = |Q'|² + (Q - xy) · Q''
        gap = evaluate(pts, tau, w) - query
        first, second = derivative(pts, tau, 1, w), derivative(pts, tau, 2, w)
        slope = np.einsum("ij,ij->i", first, first) + np.einsum("ij,ij->i", gap, second)
        step = np.einsum("ij,ij->i", gap, first) / np.where(slope > 0, slope, np.inf)
        tau = np.clip(tau - step, 0.0, 1.0)
    errors = np.abs(np.linalg.norm(evaluate(pts, tau, w) - query, axis=1) - abs(rho))
    return float(errors[0]) if scalar else errors


def trim_offset(points, rho, weights=None, samples: int = 200) -> np.ndarray:
    """The parameter intervals (k, 2) where the offset keeps its distance |ρ| from all of the curve. Notes §8.

    A point P(t) of the offset is kept when no point of Q is closer to it than
    |ρ|: never on a backward arc (1 + ρκ < 0, where Q(t) is a local maximum of
    the distance from P(t)), elsewhere when `distance_to_curve` finds no point
    nearer than (1 - CLEARANCE) |ρ|. The test runs on `samples` even
    parameters plus the middle of every backward arc; where the verdict changes
    between neighbours, bisection finds the place (to about CLEARANCE = 1e-9,
    the slack the distance test allows). A kept
    stretch shorter than the grid's spacing can be missed. Returns the kept
    intervals [a, b], sorted; their inner ends are where the offset crosses
    itself (or the offset of another part of the curve, or the circle of
    radius |ρ| about an end of Q).

    >>> from cagd_ref.offsets import trim_offset
    >>> trim_offset([(0, 0), (1, 2), (3, 2), (4, 0)], -0.5).tolist()    # the convex side: all of it
    [[0.0, 1.0]]
    >>> pocket = [(-1.5, 2.25), (0, -2.25), (1.5, 2.25)]      # y = x² for -1.5 <= x <= 1.5, turning left
    >>> trim_offset(pocket, -0.8).round(6).tolist()            # inside: the swallowtail at the vertex goes
    [[0.0, 0.291833], [0.708167, 1.0]]
    """
    pts, w = planar_curve(points, weights)
    rho = as_scalar(rho, "rho")
    samples = as_count(samples, "samples", minimum=2)
    if rho == 0:
        return np.array([[0.0, 1.0]])
    cusps = offset_cusps(pts, rho, w)
    edges = np.concatenate([[0.0], cusps, [1.0]])
    grid = np.unique(np.concatenate([np.linspace(0.0, 1.0, samples), (edges[:-1] + edges[1:]) / 2]))
    grid = grid[np.all(np.abs(grid[:, None] - cusps[None, :]) > MERGE, axis=1)] if cusps.size else grid

    def kept(ts: np.ndarray) -> np.ndarray:
        forward = 1 + rho * signed_curvature(pts, ts, w) >= 0  # on a backward arc the tool cuts into Q near Q(t)
        far = distance_to_curve(pts, offset_point(pts, ts, rho, w), w) >= (1 - CLEARANCE) * abs(rho)
        return forward & far

    verdicts = kept(grid)
    intervals, start = [], grid[0] if verdicts[0] else None
    for (a, ok_a), (b, ok_b) in zip(zip(grid, verdicts), zip(grid[1:], verdicts[1:])):
        if ok_a == ok_b:
            continue
        lo, hi = a, b  # kept(lo) == ok_a != kept(hi)
        while hi - lo > 1e-13:
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if kept(np.array([mid]))[0] == ok_a else (lo, mid)
        edge = (lo + hi) / 2
        if ok_a:
            intervals.append((start, edge))
        else:
            start = edge
    if verdicts[-1]:
        intervals.append((start, grid[-1]))
    return np.array([(a, b) for a, b in intervals if b > a], dtype=float).reshape(-1, 2)


# --- offsets in practice: approximation within a tolerance ----------------------------------------


def tiller_hanson(points, rho) -> np.ndarray:
    """An approximate offset of the same degree: the control polygon's legs moved by ρ along their normals. Notes §8.

    points: (n+1, 2) of a polynomial curve. Each leg P_i P_(i+1) moves by ρ n_i
    (n_i its unit right normal); the new control points are the first and last
    moved end points and, between them, the meeting points of consecutive moved
    legs, R_i = P_i + ρ (n_(i-1) + n_i) / (1 + n_(i-1) · n_i). Exact for a line,
    and for a circular arc in rational form evaluated with its own weights (its
    legs are tangents of the circle, so the moved polygon is the arc's scaled
    about the centre); the end points and end tangents of the offset are always
    right. A ValueError for a leg of length zero or a polygon that turns back
    on itself.

    >>> from cagd_ref.offsets import tiller_hanson
    >>> tiller_hanson([(0, 0), (1, 0), (1, 1)], 0.5).tolist()     # turning left, offset on the right: outside
    [[0.0, -0.5], [1.5, -0.5], [1.5, 1.0]]

    Ref: W. Tiller and E. G. Hanson, Offsets of two-dimensional profiles, IEEE Computer Graphics and
    Applications 4(9), 1984, 36-46.
    """
    pts = planar_points(points)
    rho = as_scalar(rho, "rho")
    legs = np.diff(pts, axis=0)
    lengths = np.linalg.norm(legs, axis=1)
    if np.any(lengths <= ZERO_SPEED * lengths.max(initial=0.0)) or not lengths.max(initial=0.0) > 0:
        raise ValueError("points: a leg of the control polygon has length zero, so it has no normal")
    normals = np.column_stack([legs[:, 1], -legs[:, 0]]) / lengths[:, None]
    cosines = np.einsum("ij,ij->i", normals[:-1], normals[1:])
    if np.any(cosines <= -1 + 1e-12):
        raise ValueError("points: the control polygon turns back on itself (a turn of 180°): moved legs never meet")
    inner = pts[1:-1] + rho * (normals[:-1] + normals[1:]) / (1 + cosines)[:, None]
    return np.vstack([pts[0] + rho * normals[0], inner, pts[-1] + rho * normals[-1]])


def tiller_hanson_offset(points, rho, tol, samples: int = 33, max_pieces: int = 4096
                         ) -> tuple[np.ndarray, np.ndarray, float]:
    """Tiller and Hanson's offset within a tolerance: halve the curve until each piece's moved polygon is close enough.

    Returns (breaks (k+1,), pieces (k, n+1, 2), error): piece j approximates the
    offset for t in [breaks[j], breaks[j+1]]; error is the largest
    `offset_error` (how far the distance to Q is from |ρ|) over `samples` even
    parameters of every piece, at most `tol`. A ValueError when `max_pieces`
    pieces do not reach it (near a cusp they never do). Notes §8.

    >>> from cagd_ref.offsets import tiller_hanson_offset
    >>> breaks, pieces, error = tiller_hanson_offset([(0, 0), (1, 2), (3, 2), (4, 0)], -0.5, 1e-3)
    >>> len(pieces), error <= 1e-3
    (14, True)
    """
    pts = planar_points(points)
    rho = as_scalar(rho, "rho")
    tol = as_tolerance(tol)
    samples = as_count(samples, "samples", minimum=2)
    max_pieces = as_count(max_pieces, "max_pieces", minimum=1)
    s = np.linspace(0.0, 1.0, samples)
    pending, done = [(0.0, 1.0, pts)], []
    while pending:
        a, b, piece = pending.pop()
        approx = tiller_hanson(piece, rho)
        error = float(offset_error(piece, rho, evaluate(approx, s), s).max())
        if error <= tol:
            done.append((a, approx, error))
        elif len(done) + len(pending) >= max_pieces:
            raise ValueError(f"tol: {max_pieces} pieces do not reach {tol:g} (does the offset have a cusp?)")
        else:
            left, right = subdivide(piece, 0.5)
            pending += [((a + b) / 2, b, right), (a, (a + b) / 2, left)]
    done.sort(key=lambda item: item[0])
    breaks = np.array([a for a, _, _ in done] + [1.0])
    return breaks, np.array([approx for _, approx, _ in done]), max(error for _, _, error in done)


def fit_offset(points, rho, tol, weights=None, interval=(0.0, 1.0), degree: int = 3, max_spans: int = 4096
               ) -> tuple[np.ndarray, np.ndarray, float]:
    """A B-spline within `tol` of the offset over `interval`: least-squares fits, knots added where needed. Notes §8.

    Start with one Bézier span over the interval. Repeat: sample the exact
    offset at 2(n+1) parameters per span, fit a degree-n B-spline to the
    samples at those parameters (`approximation.least_squares_fit`, chapter 11),
    measure |A(t) - P(t)| at 16 parameters inside every span, and halve the
    spans where it exceeds tol. Returns (control points (c, 2), knots in the
    notes' convention (c + n - 1,), error), error <= tol being the largest
    measured distance. The parameter is the offset's own, so a cusp is no
    obstacle (P(t) is smooth there, only its speed vanishes). A ValueError
    when `max_spans` spans do not reach the tolerance.

    >>> from cagd_ref.offsets import fit_offset
    >>> control, knots, error = fit_offset([(0, 0), (1, 2), (3, 2), (4, 0)], -0.5, 1e-4)
    >>> len(control), error <= 1e-4
    (11, True)

    Ref: J. Hoschek, Spline approximation of offset curves, CAGD 5, 1988, 33-40 (least squares);
    G. Elber, I.-K. Lee and M.-S. Kim, Comparing offset curve approximation methods, IEEE CG&A 17(3), 1997, 62-71.
    """
    pts, w = planar_curve(points, weights)
    rho = as_scalar(rho, "rho")
    tol = as_tolerance(tol)
    a, b = as_interval(interval)
    n = as_count(degree, "degree", minimum=1)
    max_spans = as_count(max_spans, "max_spans", minimum=1)
    breaks = np.array([a, b])
    while True:
        knots = np.concatenate([np.full(n - 1, a), breaks, np.full(n - 1, b)])
        params = np.unique(np.concatenate([np.linspace(lo, hi, 2 * (n + 1)) for lo, hi in zip(breaks, breaks[1:])]))
        control = least_squares_fit(offset_point(pts, params, rho, w), params, knots, n)
        inside = np.linspace(0.0, 1.0, 18)[1:-1]
        checks = breaks[:-1, None] + inside[None, :] * np.diff(breaks)[:, None]  # (spans, 16)
        fitted = de_boor(control, knots, checks.ravel())
        gaps = np.linalg.norm(fitted - offset_point(pts, checks.ravel(), rho, w), axis=1)
        span_error = gaps.reshape(checks.shape).max(axis=1)
        if span_error.max() <= tol:
            return control, knots, float(span_error.max())
        if len(breaks) - 1 >= max_spans:
            raise ValueError(f"tol: {max_spans} spans do not reach {tol:g}")
        middles = (breaks[:-1] + breaks[1:])[span_error > tol] / 2
        breaks = np.sort(np.concatenate([breaks, middles]))

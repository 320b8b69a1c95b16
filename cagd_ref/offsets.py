"""Offset curves, their cusps, and Pythagorean-hodograph curves with exact rational offsets: chapter 8 of the notes.

The offset of a planar curve Q(t) at radius ρ is P(t) = Q(t) + ρ N(t), where
N = (y', -x') / |Q'| is the unit normal on the **right** of the direction of
travel: a positive ρ puts the offset on our right as we walk along Q with t
increasing, a negative ρ on our left. Curvature is signed, positive where the
curve turns left, so the offset side is the concave one where ρκ < 0.

Differentiating gives P' = (1 + ρκ) Q': the offset runs parallel to its base
curve, has a cusp where 1 + ρκ = 0 and runs backwards where 1 + ρκ < 0. With
κ = num / speed2^(3/2) written through two polynomials (`curvature_polynomials`),
the cusps are roots of the polynomial speed2³ - ρ² num² (`cusp_polynomial`),
found in Bernstein form by `cagd_ref.roots.bernstein_roots`.

The square root in |Q'| keeps offsets out of the Bézier world, except where
x'² + y'² is the square of a polynomial σ: Pythagorean-hodograph (PH) curves,
whose offsets are rational Bézier curves of degree 2n - 1 (`ph_offset`). The
parabola is the other classic exception: after a rational change of parameter
its offset is a rational curve of degree 6 (`parabola_offset`).

Points are planar float arrays (n+1, 2), n >= 1; rational curves take positive
weights (n+1,). A parameter t is a number (one result of shape (2,)) or a 1-D
array of k values ((k, 2)).
"""

from __future__ import annotations

import numpy as np

from ._validation import as_interval, as_parameter, as_points, as_positive_weights, as_scalar, as_vector
from .bezier import derivative, elevate, evaluate, from_homogeneous, hodograph, to_homogeneous
from .polynomials import bernstein_horner, bernstein_multiply, bernstein_to_power, power_to_bernstein
from .roots import bernstein_roots

__all__ = [
    "offset_normal",
    "offset_point",
    "offset_derivative",
    "reverse_offset",
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
]

# Below this fraction of the control polygon's scale a speed counts as zero: the curve stops there.
ZERO_SPEED = 1e-12
# A local minimum of |1 + ρκ| this small is a cusp where 1 + ρκ touches zero without changing sign.
TOUCH = 1e-9
# Cusps closer than this are one: double precision cannot tell them apart (their swallowtail is ~1e-14 wide).
MERGE = 1e-6
# Relative size of the coefficients of speed2³ - ρ² num² below which it vanishes identically.
IDENTICALLY_ZERO = 1e-12
# Relative residual |σ² - (x'² + y'²)| up to which a hodograph counts as Pythagorean.
PH_TOL = 1e-9


# --- input checking -----------------------------------------------------------------------


def _planar(points, min_count: int = 2) -> np.ndarray:
    pts = as_points(points, min_count=min_count)
    if pts.shape[1] != 2:
        raise ValueError(f"points: offsets are planar, expected shape (n+1, 2), got shape {pts.shape}")
    return pts


def _positive_weights(weights, count: int) -> np.ndarray | None:
    if weights is None:
        return None
    return as_positive_weights(weights, count, "offsets need positive weights (no pole on the curve)")


def _curve(points, weights) -> tuple[np.ndarray, np.ndarray | None]:
    pts = _planar(points)
    return pts, _positive_weights(weights, len(pts))


# --- Bernstein coefficient arithmetic (scalar polynomials on [0, 1]) -------------------------


def _raised(c: np.ndarray, degree: int) -> np.ndarray:
    """The same polynomial with Bernstein coefficients of a higher `degree`."""
    times = degree - (len(c) - 1)
    return elevate(c[:, None], times)[:, 0] if times else c


def _sum(*terms: np.ndarray) -> np.ndarray:
    """The sum of Bernstein polynomials of different degrees, at the highest of them."""
    degree = max(len(c) for c in terms) - 1
    return sum(_raised(c, degree) for c in terms)


def _product(*factors: np.ndarray) -> np.ndarray:
    result = factors[0]
    for factor in factors[1:]:
        result = bernstein_multiply(result, factor)
    return result


def _derivative(c: np.ndarray) -> np.ndarray:
    return hodograph(c[:, None])[:, 0]


# --- the offset and its derivative ----------------------------------------------------------


def _first_derivatives(pts, ts, weights) -> np.ndarray:
    """Q'(t) at k parameters, (k, 2), refusing parameters where the curve stops (Q' = 0)."""
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


def _right_normals(first: np.ndarray) -> np.ndarray:
    """Unit normals (y', -x') / |Q'| on the right of the direction of travel, (k, 2)."""
    return np.column_stack([first[:, 1], -first[:, 0]]) / np.linalg.norm(first, axis=1)[:, None]


def _finish(values: np.ndarray, scalar: bool) -> np.ndarray:
    return values[0].copy() if scalar else values


def offset_normal(points, t, weights=None) -> np.ndarray:
    """The unit normal N = (y', -x') / |Q'| on the right of the direction of travel. Notes §8.

    points: (n+1, 2); weights: None or (n+1,) positive. t: a number -> (2,),
    k values -> (k, 2). A ValueError where the curve stops (Q'(t) = 0).

    >>> from cagd_ref.offsets import offset_normal
    >>> offset_normal([(0, 0), (1, 2), (3, 2), (4, 0)], 0.5).tolist()   # moving in +x: right is down
    [0.0, -1.0]
    """
    pts, w = _curve(points, weights)
    ts, scalar = as_parameter(t)
    return _finish(_right_normals(_first_derivatives(pts, ts, w)), scalar)


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
    pts, w = _curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    normals = _right_normals(_first_derivatives(pts, ts, w))
    return _finish(evaluate(pts, ts, w) + rho * normals, scalar)


def _curvatures(pts, ts, weights) -> tuple[np.ndarray, np.ndarray]:
    """Q'(t) (k, 2) and the signed curvature κ(t) (k,)."""
    first = _first_derivatives(pts, ts, weights)
    second = derivative(pts, ts, 2, weights)
    cross = first[:, 0] * second[:, 1] - first[:, 1] * second[:, 0]
    return first, cross / np.linalg.norm(first, axis=1) ** 3


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
    pts, w = _curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    first, kappa = _curvatures(pts, ts, w)
    return _finish((1 + rho * kappa)[:, None] * first, scalar)


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
    pts, w = _curve(points, weights)
    ts, scalar = as_parameter(t)
    rho = as_scalar(rho, "rho")
    first, kappa = _curvatures(pts, ts, w)
    factor = 1 + rho * kappa
    cusps = np.abs(factor) <= ZERO_SPEED
    if np.any(cusps):
        raise ValueError(f"t: the offset has a cusp (1 + ρκ = 0) at t = {ts[cusps].tolist()[:5]}, so no normal there")
    offset = evaluate(pts, ts, w) + rho * _right_normals(first)
    return _finish(offset - rho * _right_normals(factor[:, None] * first), scalar)


# --- cusps ------------------------------------------------------------------------------------


def _curvature_parts(pts: np.ndarray, weights: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """Bernstein coefficients (num, speed2) with κ = num / speed2^(3/2) on [0, 1]."""
    if weights is None:
        first = hodograph(pts)
        second = hodograph(first)
        (x1, y1), (x2, y2) = first.T, second.T
        return _sum(_product(x1, y2), -_product(y1, x2)), _sum(_product(x1, x1), _product(y1, y1))
    # P = (X, Y) / W: P' = D / W² with D = W (X', Y') - W' (X, Y), and P' × P'' = det(H, H', H'') / W³.
    h = to_homogeneous(pts, weights)
    h1 = hodograph(h)
    h2 = hodograph(h1)
    (x, y, w), (x1, y1, w1), (x2, y2, w2) = h.T, h1.T, h2.T
    dx = _sum(_product(w, x1), -_product(w1, x))
    dy = _sum(_product(w, y1), -_product(w1, y))
    det = _sum(
        _product(x, _sum(_product(y1, w2), -_product(w1, y2))),
        -_product(y, _sum(_product(x1, w2), -_product(w1, x2))),
        _product(w, _sum(_product(x1, y2), -_product(y1, x2))),
    )
    return _product(w, w, w, det), _sum(_product(dx, dx), _product(dy, dy))


def curvature_polynomials(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Bernstein coefficients on [0, 1] of `num` and `speed2` with signed curvature κ = num / speed2^(3/2). Notes §8.

    Polynomial curves: num = x'y'' - y'x'' (degree 2n-3) and speed2 = x'² + y'²
    (degree 2n-2). Rational curves P = (X, Y) / W: num = W³ det(H, H', H'')
    and speed2 = |W (X', Y') - W' (X, Y)|², with H = (X, Y, W).
    """
    return _curvature_parts(*_curve(points, weights))


def _cusp_coefficients(num: np.ndarray, speed2: np.ndarray, rho: float) -> tuple[np.ndarray, float]:
    """speed2³ - ρ² num² in Bernstein form, and the size of its two terms (for relative tests)."""
    cubed = _product(speed2, speed2, speed2)
    squared = rho**2 * _product(num, num)
    scale = max(np.abs(cubed).max(), np.abs(squared).max())
    return _sum(cubed, -squared), scale


def cusp_polynomial(points, rho, weights=None) -> np.ndarray:
    """Bernstein coefficients on [0, 1] of speed2³ - ρ² num², whose roots hold the cusps of the offset. Notes §8.

    1 + ρκ = 0 means speed2^(3/2) = -ρ num; squaring gives this polynomial
    (degree 6n - 6 for a polynomial curve). Squaring adds the roots of
    1 - ρκ = 0 as well: those with ρ num(t) > 0 are cusps of the offset on the
    other side (radius -ρ), not of this one.
    """
    pts, w = _curve(points, weights)
    rho = as_scalar(rho, "rho")
    return _cusp_coefficients(*_curvature_parts(pts, w), rho)[0]


def _touching(f: np.ndarray, roots: np.ndarray, factor) -> list[float]:
    """Where |1 + ρκ| has a local minimum (a critical point of f, or an end) of size <= TOUCH and no root nearby.

    A double root of f, where 1 + ρκ touches zero without crossing, may be lost
    to rounding (f stays a hair above zero). Each critical point of f bounds,
    with its neighbours, the pieces where f is monotone; a root found in the
    pieces beside a candidate already accounts for it.
    """
    slope = _derivative(f)
    critical = bernstein_roots(slope) if np.any(slope) else np.array([])
    stops = np.concatenate([[0.0], critical, [1.0]])
    found = []
    for k in range(len(stops)):
        lo, hi = stops[max(k - 1, 0)], stops[min(k + 1, len(stops) - 1)]
        if abs(factor(stops[k])) <= TOUCH and not np.any((roots >= lo) & (roots <= hi)):
            found.append(float(stops[k]))
    return found


def offset_cusps(points, rho, weights=None) -> np.ndarray:
    """Sorted parameters t in [0, 1] where 1 + ρκ(t) = 0: the cusps of the offset at radius ρ. Notes §8.

    κ is the signed curvature (positive turning left), so cusps lie where the
    radius of curvature 1/|κ| equals |ρ| on the offset's side (ρκ < 0). The
    roots of `cusp_polynomial` are found in Bernstein form, those of the other
    side (ρ num > 0) dropped, and a point where 1 + ρκ only touches zero (ρ equal
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
    pts, w = _curve(points, weights)
    rho = as_scalar(rho, "rho")
    if np.ptp(pts, axis=0).max() == 0:
        raise ValueError("points: all control points coincide, so the curve is a single point without normals")
    num, speed2 = _curvature_parts(pts, w)
    f, scale = _cusp_coefficients(num, speed2, rho)
    if np.abs(f).max() <= IDENTICALLY_ZERO * scale:
        raise ValueError(
            "rho: 1 + ρκ vanishes identically (a circular arc offset by its radius towards its centre: "
            "the whole offset collapses to one point)"
        )
    if rho == 0:
        return np.array([])
    moving = IDENTICALLY_ZERO * np.abs(speed2).max()

    def factor(t):
        s2 = bernstein_horner(speed2, t)
        return 1 + rho * bernstein_horner(num, t) / s2**1.5 if s2 > moving else np.inf

    roots = bernstein_roots(f)
    # Squaring brought in the cusps of the other side (1 - ρκ = 0) and the points where the curve stops.
    kept = [float(t) for t in roots if rho * bernstein_horner(num, t) < 0 and bernstein_horner(speed2, t) > moving]
    return _merged(sorted(kept + _touching(f, roots, factor)))


def _merged(ts: list[float]) -> np.ndarray:
    """Parameters closer than MERGE become their mean: rounding may split a touching (double) root in two."""
    groups: list[list[float]] = []
    for t in ts:
        if groups and t - groups[-1][-1] <= MERGE:
            groups[-1].append(t)
        else:
            groups.append([t])
    return np.array([sum(group) / len(group) for group in groups])


def cusp_free_interval(points, weights=None) -> tuple[float, float]:
    """The radii (low, high), low < 0 < high, of cusp-free offsets: 1 + ρκ > 0 on [0, 1] for low < ρ < high. Notes §8.

    high = 1 / max(-κ) is the smallest radius of curvature where the curve
    turns right (the offset side of a positive ρ), low = -1 / max(κ) the same
    on the left; a side the curve never turns to gives ±inf. The extremes of κ
    are at the ends or at the roots of (κ speed2^(5/2))' ∝ num' speed2 - (3/2) num speed2'.
    """
    pts, w = _curve(points, weights)
    num, speed2 = _curvature_parts(pts, w)
    slope = _sum(_product(_derivative(num), speed2), -1.5 * _product(num, _derivative(speed2)))
    ends = np.array([0.0, 1.0])
    ts = np.concatenate([ends, bernstein_roots(slope)]) if np.any(slope) else ends
    s2 = bernstein_horner(speed2, ts)
    kappa = bernstein_horner(num, ts)[s2 > 0] / s2[s2 > 0] ** 1.5
    high = 1 / -kappa.min() if kappa.size and kappa.min() < 0 else np.inf
    low = -1 / kappa.max() if kappa.size and kappa.max() > 0 else -np.inf
    return float(low), float(high)


# --- Pythagorean-hodograph curves --------------------------------------------------------------


def _ph_pair(u, v) -> tuple[np.ndarray, np.ndarray]:
    u = as_vector(u, "u")
    v = as_vector(v, "v")
    if len(u) != len(v):
        raise ValueError(f"u, v: expected coefficients of the same degree, got {len(u)} and {len(v)}")
    return u, v


def _ph_hodograph(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    return np.column_stack([_sum(_product(u, u), -_product(v, v)), 2 * _product(u, v)])


def ph_hodograph(u, v) -> np.ndarray:
    """The Pythagorean hodograph (u² - v², 2uv) in Bernstein form (2m+1, 2), from u, v (m+1,) of degree m. Notes §8.

    Its length is u² + v²: (u² - v²)² + (2uv)² = (u² + v²)², a perfect square.
    """
    return _ph_hodograph(*_ph_pair(u, v))


def ph_curve(p0, u, v) -> np.ndarray:
    """The PH curve of degree 2m+1 starting at p0 whose hodograph is (u² - v², 2uv): control points (2m+2, 2). Notes §8.

    u, v: Bernstein coefficients (m+1,) of two polynomials of degree m. The
    control points are p0 plus the running sums of the hodograph's
    coefficients divided by 2m+1 (the integral of §2.17).
    """
    start = as_vector(p0, "p0", 2)
    h = _ph_hodograph(*_ph_pair(u, v))
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
    u, v = _ph_pair(u, v)
    if len(u) != 2:
        raise ValueError(f"u: a PH cubic takes linear u and v, two Bernstein coefficients each, got {len(u)}")
    return ph_curve(p0, u, v)


def _ph_speed(pts: np.ndarray, tol: float) -> np.ndarray | None:
    """σ (n,) in Bernstein form with σ² = x'² + y'², positive where Q is fastest; None if no polynomial fits."""
    h = hodograph(pts)
    (x1, y1) = h.T
    speed2 = _sum(_product(x1, x1), _product(y1, y1))
    degree = len(h) - 1
    if not np.any(speed2):
        return None
    # The Taylor polynomial of sqrt(speed2) about its largest value, where the square root is best conditioned:
    # s = Σ s_j τ^j with s² = p, so s_0 = sqrt(p_0) and s_j = (p_j - Σ_{0<i<j} s_i s_(j-i)) / (2 s_0).
    grid = np.linspace(0, 1, 2 * degree + 3)
    centre = grid[np.argmax(bernstein_horner(speed2, grid))]
    p = bernstein_to_power(speed2, (-centre, 1 - centre))  # the same polynomial in τ = t - centre
    s = np.zeros(degree + 1)
    s[0] = np.sqrt(p[0])
    for j in range(1, degree + 1):
        s[j] = (p[j] - s[1:j] @ s[j - 1 : 0 : -1]) / (2 * s[0])
    sigma = power_to_bernstein(s, (-centre, 1 - centre))
    residual = np.abs(_sum(_product(sigma, sigma), -speed2)).max()
    return sigma if residual <= tol * np.abs(speed2).max() else None


def is_pythagorean_hodograph(points, tol: float = PH_TOL) -> bool:
    """Whether x'² + y'² is the square of a polynomial σ (to a relative `tol` on its Bernstein coefficients). Notes §8.

    points: (n+1, 2). A curve that is a single point has no hodograph to speak of: False.
    """
    pts = _planar(points)
    tol = as_scalar(tol, "tol")
    if not tol > 0:
        raise ValueError(f"tol: expected a positive tolerance, got {tol}")
    return _ph_speed(pts, tol) is not None


def _minimum(c: np.ndarray) -> tuple[float, float]:
    """The smallest value of Σ c_i B_i on [0, 1] and where it is taken (ends and critical points)."""
    slope = _derivative(c)
    ts = np.concatenate([[0.0, 1.0], bernstein_roots(slope) if np.any(slope) else []])
    values = bernstein_horner(c, ts)
    return float(values.min()), float(ts[np.argmin(values)])


def ph_speed(points) -> np.ndarray:
    """The parametric speed |Q'(t)| of a PH curve as a polynomial σ: Bernstein coefficients (n,) on [0, 1]. Notes §8.

    σ² = x'² + y'² (within the relative tolerance PH_TOL); σ is positive where
    the curve moves fastest, and equals |Q'| on [0, 1] unless the curve stops.
    A ValueError when x'² + y'² is not a perfect square.
    """
    pts = _planar(points)
    sigma = _ph_speed(pts, PH_TOL)
    if sigma is None:
        raise ValueError("points: x'² + y'² is not the square of a polynomial, so this is not a PH curve")
    return sigma


def ph_offset(points, rho) -> tuple[np.ndarray, np.ndarray]:
    """The exact offset of a PH curve at radius ρ, a rational Bézier curve of degree 2n-1: (points, weights). Notes §8.

    Returns points (2n, 2) and weights (2n,). With σ = |Q'| a polynomial of degree n-1, Q + ρ (y', -x') / σ has the
    homogeneous form (σ Q + ρ (y', -x'), σ): σQ has degree 2n-1 and the other
    two terms are raised to it. The weights are the coefficients of σ so
    raised; evaluated at t the curve gives Q(t) + ρ N(t). A ValueError if the
    curve is not PH, or stops (σ = 0) somewhere in [0, 1].

    >>> from cagd_ref.offsets import ph_cubic, ph_offset
    >>> points, weights = ph_offset(ph_cubic((0, 0), (2, 1), (0, 1)), 0.25)
    >>> weights.round(6).tolist()
    [4.0, 3.2, 2.6, 2.2, 2.0, 2.0]
    >>> points.round(6).tolist()
    [[0.0, -0.25], [1.0625, -0.25], [1.673077, 0.076923], [2.022727, 0.424242], [2.25, 0.833333], [2.25, 1.333333]]

    Ref: R. T. Farouki and T. Sakkalis, Pythagorean hodographs, IBM J. Res. Develop. 34(5), 1990, 736-752;
    R. T. Farouki, Pythagorean-Hodograph Curves: Algebra and Geometry Inseparable, Springer, 2008.
    """
    pts = _planar(points)
    rho = as_scalar(rho, "rho")
    sigma = ph_speed(pts)
    lowest, where = _minimum(sigma)
    if lowest <= ZERO_SPEED * np.abs(sigma).max():
        raise ValueError(f"points: the PH curve stops (Q' = 0) at t = {where:.6g}, where its offset is undefined")
    n = len(pts) - 1
    h = hodograph(pts)
    numerator = np.column_stack([_product(sigma, pts[:, 0]), _product(sigma, pts[:, 1])])
    numerator += rho * elevate(np.column_stack([h[:, 1], -h[:, 0]]), n)
    weights = _raised(sigma, 2 * n - 1)
    if np.any(weights == 0):
        raise ValueError("points: the offset has a control point at infinity (a zero weight); split the curve first")
    return numerator / weights[:, None], weights


# --- the parabola ------------------------------------------------------------------------------


def parabola_offset(rho, interval=(-1.0, 1.0)) -> tuple[np.ndarray, np.ndarray]:
    """The offset at radius ρ of the parabola (t, t²), t in `interval`: a rational Bézier curve of degree 6. Notes §8.

    The parameter change t = (u² - 1) / (4u), u > 0, turns √(1 + 4t²) into
    (u² + 1) / (2u), and the offset into (X, Y) / W with
    X = 4u(u² - 1)(u² + 4ρu + 1), Y = (u² - 1)²(u² + 1) - 32ρu³, W = 16u²(u² + 1),
    of degrees 5, 6 and 4 without a common factor. Over the u-interval of
    `interval` (u = 2t + √(4t² + 1)) that is a degree-6 rational Bézier curve:
    returns (points (7, 2), weights (7,)), positive ρ on the right (below the
    vertex, the convex side). The notes say eight; six is enough, and the least
    possible, as the offset's implicit equation has degree 6.
    """
    rho = as_scalar(rho, "rho")
    t0, t1 = as_interval(interval)
    u0, u1 = (2 * t + np.sqrt(4 * t * t + 1) for t in (t0, t1))
    power = np.array([
        [0.0, -4.0, -16 * rho, 0.0, 16 * rho, 4.0, 0.0],  # X
        [1.0, 0.0, -1.0, -32 * rho, -1.0, 0.0, 1.0],  # Y
        [0.0, 0.0, 16.0, 0.0, 16.0, 0.0, 0.0],  # W
    ]).T
    return from_homogeneous(power_to_bernstein(power, (u0, u1)))

"""Intersections of lines and planar curves: chapter 7 of the notes.

Points and lines of the plane are homogeneous triples: a point (X, Y, W) is
the Cartesian (X/W, Y/W), a line (a, b, c) is a X + b Y + c W = 0, and the
meet of two lines (the join of two points) is their cross product, so two
parallel lines meet in a point at infinity (W = 0) as Bézout's theorem asks.
A parametric curve meets an implicit one where the curve, substituted into
the implicit equation, gives a polynomial that vanishes (§7.3). Two Bézier
curves are intersected by the four algorithms of §7.4: Bézier subdivision,
interval subdivision, implicitization and Bézier clipping (§7.7, after
Sederberg and Nishita), which `intersect_curves` implements for polynomial
and rational curves. Control points are planar, (n+1, 2); implicit curves are
coefficient arrays f[i, j] of x^i y^j (the layout of chapter 17).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from math import comb

import numpy as np

from . import _clipping
from ._clipping import OVERLAP_CHECK_AFTER, SLACK, THIN, TINY
from ._validation import as_count, as_float_array, as_line, as_points, as_scalar, as_tolerance, as_vector, as_weights
from .bezier import elevate, evaluate, hodograph, subdivide, to_homogeneous
from .interpolation import second_derivative_bounds
from .polynomials import bernstein_horner, bernstein_multiply, bernstein_to_power
from .roots import bernstein_roots

__all__ = [
    "homogeneous_circle_point",
    "circle_conic",
    "line_intersection",
    "project",
    "implicit_polynomial",
    "curve_implicit_bernstein",
    "curve_implicit_intersection",
    "osculating_circle_curvature",
    "flatness",
    "intersect_by_subdivision",
    "monotone_breaks",
    "intersect_by_intervals",
    "implicit_by_nullspace",
    "intersect_by_implicitization",
    "fat_line",
    "perpendicular_fat_line",
    "clip_range",
    "clip_curve",
    "homogeneous_fat_line",
    "explicit_meets",
    "clip_one_sided",
    "clip_trace",
    "search_steps",
    "curve_piece",
    "intersect_curves",
    "bezier_clipping",
    "merge_touching",
]

# Fat lines are widened by this much (times the size of the picture) so that
# rounding in the subdivided control points never clips away a true intersection.
PAD = 1e-12
# Kept ranges are widened by a few ulps (SLACK), so that rounding in a crossing never cuts off an end
# point. A stalled pair of pieces smaller than TINY (times the size of the picture) whose fat lines
# are no wider than THIN pads lie within rounding of each other: a tangential intersection. After
# OVERLAP_CHECK_AFTER clipping rounds, check once whether the curves share a piece. (Shared with
# the engine of `intersect_curves`, `_clipping`, where they are set.)
# A clip that keeps more than this fraction of both parameter ranges is stalling
# (several intersections, or a tangency): split the longer curve instead (§7.7.5).
STALL = 0.8
MAX_STEPS = 20_000
# The smallest tol `intersect_curves` accepts: a few units in the last place of a parameter near 1.
TOL_FLOOR = 1e-15
# The subdivision-type searches give up after this many pairs of pieces.
MAX_PAIRS = 200_000


# --- §7.1 Bézout's theorem: homogeneous coordinates and parameters -----------------------------


def homogeneous_circle_point(T, U) -> np.ndarray:
    """Point(s) ((U² - T²), 2TU) / (T² + U²) of the unit circle at homogeneous parameters (T, U), t = T/U. Notes (7.3).

    T, U: numbers or 1-D arrays that broadcast together; (2,) for two numbers,
    (k, 2) otherwise. With finite parameters the whole circle is swept: first
    quadrant 0 <= T <= 1, U = 1; second T = 1, U from 1 to 0; third T = -1, U
    from 0 to 1; fourth -1 <= T <= 0, U = 1. (T, U) = (0, 0) is no parameter.

    >>> homogeneous_circle_point(1.0, 0.0).tolist()       # t = ∞ is the point (-1, 0)
    [-1.0, 0.0]
    >>> np.round(homogeneous_circle_point([0.0, 0.5, 1.0], 1.0), 6).tolist()
    [[1.0, 0.0], [0.6, 0.8], [0.0, 1.0]]
    """
    t = as_float_array(T, "T")
    u = as_float_array(U, "U")
    if t.ndim > 1 or u.ndim > 1:
        raise ValueError(f"T, U: expected numbers or 1-D arrays, got shapes {t.shape} and {u.shape}")
    try:
        t, u = np.broadcast_arrays(t, u)
    except ValueError:
        raise ValueError(f"T, U: arrays of shapes {t.shape} and {u.shape} do not broadcast") from None
    norm = t * t + u * u
    if np.any(norm == 0):
        raise ValueError("T, U: (T, U) = (0, 0) is not a homogeneous parameter")
    return np.stack([(u * u - t * t) / norm, 2 * t * u / norm], axis=-1)


def circle_conic(center, radius) -> np.ndarray:
    """Coefficients f[i, j] of x^i y^j, shape (3, 3), of the circle (x - xc)² + (y - yc)² - r² = 0. Notes (7.1).

    Homogenised it is (X - xc W)² + (Y - yc W)² - r² W² = 0, which every circle
    satisfies at the two circular points (1, ±i, 0): that is where two circles
    spend two of their four Bézout intersections.

    >>> circle_conic([0.0, 0.0], 1.0).tolist()
    [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    xc, yc = as_vector(center, "center", dim=2)
    r = as_scalar(radius, "radius")
    if r <= 0:
        raise ValueError(f"radius: expected a positive radius, got {r}")
    f = np.zeros((3, 3))
    f[0, 0] = xc * xc + yc * yc - r * r
    f[1, 0], f[0, 1] = 0.0 - 2 * xc, 0.0 - 2 * yc  # 0.0 - ...: no negative zeros
    f[2, 0] = f[0, 2] = 1.0
    return f


# --- §7.2 the intersection of two lines -----------------------------------------------------------


def line_intersection(l1, l2) -> np.ndarray:
    """The homogeneous point (X, Y, W) = l1 × l2 where the lines a X + b Y + c W = 0 meet. Notes §7.2.

    l1, l2: (3,). Parallel lines meet at a point at infinity: W = 0 and (X, Y)
    is their common direction. Lines that coincide (l1 × l2 = 0 up to rounding,
    |l1 × l2| <= 1e-12 |l1| |l2|) have no single intersection: ValueError.

    >>> line_intersection([2.0, 1.0, -7.0], [-1.0, -1.0, 5.0]).tolist()
    [-2.0, -3.0, -1.0]
    >>> line_intersection([3.0, 4.0, 2.0], [3.0, 4.0, 3.0]).tolist()   # parallel: W = 0
    [4.0, -3.0, 0.0]
    """
    l1 = as_line(l1, "l1")
    l2 = as_line(l2, "l2")
    point = np.cross(l1, l2)
    if np.linalg.norm(point) <= 1e-12 * np.linalg.norm(l1) * np.linalg.norm(l2):
        raise ValueError(f"l1, l2: the lines {l1.tolist()} and {l2.tolist()} coincide, so they share every point")
    return point


def project(point) -> np.ndarray:
    """Π(X, Y, W) = (X/W, Y/W): homogeneous point(s) (3,) or (k, 3) to Cartesian (2,) or (k, 2). Notes §7.2.

    Π(λP) = Π(P) for every λ ≠ 0. A point at infinity (W = 0) has no Cartesian
    image: ValueError.

    >>> project([-2.0, -3.0, -1.0]).tolist()
    [2.0, 3.0]
    """
    p = as_float_array(point, "point")
    if p.shape[-1:] != (3,) or p.ndim > 2:
        raise ValueError(f"point: expected homogeneous point(s) of shape (3,) or (k, 3), got shape {p.shape}")
    if np.any(p[..., 2] == 0):
        raise ValueError("point: W = 0 is a point at infinity, in the direction (X, Y); it has no Cartesian image")
    return p[..., :2] / p[..., 2:]


# --- §7.3 a parametric curve and an implicit curve ---------------------------------------------------


def _implicit(f, name: str = "f") -> tuple[np.ndarray, int]:
    """Checked coefficients f[i, j] of x^i y^j and the total degree d = max{i + j : f[i, j] != 0}."""
    f = as_float_array(f, name)
    if f.ndim != 2 or f.size == 0:
        raise ValueError(f"{name}: expected a 2-D array of coefficients f[i, j] of x^i y^j, got shape {f.shape}")
    i, j = np.nonzero(f)
    if len(i) == 0:
        raise ValueError(f"{name}: the zero polynomial defines no curve")
    return f, int(np.max(i + j))


def implicit_polynomial(f, x, y, w=None) -> np.ndarray:
    """Ascending power coefficients of g(t) = f(X(t), Y(t), W(t)), the curve substituted into f homogenised. Notes §7.3.

    f: 2-D array, f[i, j] the coefficient of x^i y^j, total degree d (the
    largest i + j with f[i, j] != 0). x, y, w: ascending power coefficients of
    X(t), Y(t) and W(t) (w=None: W = 1, a polynomial curve). The implicit
    equation is homogenised, f(X, Y, W) = Σ f[i, j] X^i Y^j W^(d-i-j), so the
    rational curve x = X/W, y = Y/W needs no division. The result has length
    d·n + 1, n the largest of the degrees len(x) - 1, len(y) - 1, len(w) - 1
    (Bézout's count); its real roots are the parameters of the intersections.

    >>> circle = [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]      # x² + y² - 1
    >>> implicit_polynomial(circle, [-1.0, 2.0], [1.0, -9.0, 8.0]).tolist()
    [1.0, -22.0, 101.0, -144.0, 64.0]
    >>> parabola = [[1.0, 1.0], [2.0, 0.0], [1.0, 0.0]]                    # x² + 2x + y + 1
    >>> implicit_polynomial(parabola, [0.0, 1.0, 1.0], [0.0, 2.0], [1.0, 0.0, 1.0]).tolist()
    [1.0, 4.0, 5.0, 6.0, 4.0]
    """
    f, d = _implicit(f)
    x = as_vector(x, "x")
    y = as_vector(y, "y")
    w = np.ones(1) if w is None else as_vector(w, "w")
    n = max(len(x), len(y), len(w)) - 1
    powers = {name: _powers(c, d) for name, c in (("x", x), ("y", y), ("w", w))}
    g = np.zeros(d * n + 1)
    for i, j in zip(*np.nonzero(f)):
        term = np.convolve(np.convolve(powers["x"][i], powers["y"][j]), powers["w"][d - i - j])
        g[: len(term)] += f[i, j] * term
    return g


def _powers(c: np.ndarray, d: int) -> list[np.ndarray]:
    """c⁰, c¹, ..., c^d of a power-basis polynomial, as coefficient arrays."""
    found = [np.ones(1)]
    for _ in range(d):
        found.append(np.convolve(found[-1], c))
    return found


def _homogeneous_columns(points, weights, name: str = "points", weights_name: str = "weights") -> np.ndarray:
    """Planar control points (n+1, 2) and optional weights -> homogeneous rows w (x, y, 1), (n+1, 3)."""
    pts = _planar(points, name)
    if weights is None:
        return np.column_stack([pts, np.ones(len(pts))])
    return to_homogeneous(pts, as_weights(weights, len(pts), weights_name))


def _planar(points, name: str = "points", min_count: int = 1) -> np.ndarray:
    pts = as_points(points, name, min_count=min_count)
    if pts.shape[1] != 2:
        raise ValueError(f"{name}: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    return pts


def curve_implicit_bernstein(f, points, weights=None) -> np.ndarray:
    """Bernstein coefficients on [0, 1], (d·n + 1,), of g(t) = f(X(t), Y(t), W(t)) for a Bézier curve. Notes §7.3, §9.3.

    points: (n+1, 2), weights: None or (n+1,); f as in `implicit_polynomial`.
    Every term X^i Y^j W^(d-i-j) is a product of d polynomials of degree n,
    formed with the Bernstein product formula, so g comes out of degree d·n in
    the Bernstein basis with no change of basis: g(0) and g(1) are exactly the
    values of f at the end points, and `bernstein_roots` takes g as it is.

    >>> circle = [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    >>> [round(float(v), 6) for v in curve_implicit_bernstein(circle, [(-1.0, 1.0), (0.0, -3.5), (1.0, 0.0)])]
    [1.0, -4.5, 6.833333, -1.0, 0.0]
    """
    f, d = _implicit(f)
    h = _homogeneous_columns(points, weights)
    columns = [_bernstein_powers(h[:, k], d) for k in range(3)]
    g = np.zeros(d * (len(h) - 1) + 1)
    for i, j in zip(*np.nonzero(f)):
        g += f[i, j] * bernstein_multiply(bernstein_multiply(columns[0][i], columns[1][j]), columns[2][d - i - j])
    return g


def _bernstein_powers(c: np.ndarray, d: int) -> list[np.ndarray]:
    found = [np.ones(1)]
    for _ in range(d):
        found.append(bernstein_multiply(found[-1], c))
    return found


def curve_implicit_intersection(f, points, weights=None, tol: float = 1e-12) -> tuple[np.ndarray, np.ndarray]:
    """Parameters ts (k,) in [0, 1] and points (k, 2) where a Bézier curve meets the implicit curve f = 0. Notes §7.3.

    The roots of `curve_implicit_bernstein` found by `roots.bernstein_roots`
    (each to within tol). A curve that lies on f = 0 (g vanishes to rounding)
    has no isolated intersections: ValueError.

    >>> circle = [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    >>> ts, pts = curve_implicit_intersection(circle, [(-1.0, 1.0), (0.0, -3.5), (1.0, 0.0)])
    >>> np.round(ts, 5).tolist()
    [0.06118, 0.28147, 0.90735, 1.0]
    """
    f, d = _implicit(f)
    g = curve_implicit_bernstein(f, points, weights)
    tol = as_tolerance(tol, below_one=True)
    h = _homogeneous_columns(points, weights)
    i, j = np.nonzero(f)
    size = np.abs(h).max(axis=0)
    scale = np.sum(np.abs(f[i, j]) * size[0] ** i * size[1] ** j * size[2] ** (d - i - j))
    if np.abs(g).max() <= 1e-12 * scale:
        raise ValueError("f: the curve lies on the implicit curve f = 0 (the substitution vanishes identically)")
    ts = bernstein_roots(g, tol=tol)
    return ts, evaluate(_planar(points), ts, weights)


def osculating_circle_curvature(points, weights=None) -> float:
    """Signed curvature at t = 0 found as the circle with a triple intersection there: κ = 2 w0 y2 / x1². Notes §7.3.

    The curve is moved so that P(0) is the origin and its tangent the positive
    x-axis; then X(t) = x1 t + ..., Y(t) = y2 t² + ..., W(t) = w0 + ... in the
    power basis. The circle x² + y² - 2ρy = 0 of radius ρ touching the x-axis
    at the origin, homogenised X² + Y² - 2ρ Y W, gives (x1² - 2ρ w0 y2) t² +
    O(t³) after substitution: a double root at t = 0 for every ρ, a triple one
    (the osculating circle) for ρ = x1² / (2 w0 y2). Positive when the curve
    turns left. points: (n+1, 2) with n >= 1 and P1 != P0; weights: None or (n+1,).

    >>> round(osculating_circle_curvature([(0.0, 0.0), (2.0, 0.0), (3.0, 1.5), (5.0, 4.0)], [1.5, 0.7, 2.0, 1.0]), 10)
    1.5306122449
    """
    pts = _planar(points, min_count=2)
    w = np.ones(len(pts)) if weights is None else as_weights(weights, len(pts))
    tangent = pts[1] - pts[0]
    length = np.hypot(*tangent)
    if length == 0:
        raise ValueError("points: P1 coincides with P0, so the tangent at t = 0 is not given by P1 - P0")
    cos, sin = tangent / length
    moved = (pts - pts[0]) @ np.array([[cos, -sin], [sin, cos]])
    power = bernstein_to_power(to_homogeneous(moved, w))
    x1, y2, w0 = power[1, 0], (power[2, 1] if len(power) > 2 else 0.0), power[0, 2]
    return float(2 * w0 * y2 / x1**2)


# --- §7.4-7.6 Bézier subdivision, interval subdivision, implicitization ------------------------------


@dataclass(frozen=True)
class SearchStep:
    """One pair of pieces examined by a search: its depth, parameter ranges and what became of it.

    outcome: "rejected" (the pieces cannot meet), "split" (pieces subdivided),
    "clipped" (a round of Bézier clipping kept part of both), "found" (an
    intersection recorded).
    """

    depth: int
    t_range: tuple[float, float]
    u_range: tuple[float, float]
    outcome: str


def flatness(points) -> float:
    """Bound on the distance of a Bézier curve from its chord P0 Pn: √(Lx² + Ly²) / 8. Notes §7.5, (10.2)-(10.3).

    Lx = n(n-1) max |x_(i+2) - 2 x_(i+1) + x_i| bounds |x''| (likewise Ly, and
    every further coordinate); the chord interpolates the curve at both ends,
    so it deviates by at most L/8. points: (n+1, d); 0 for n < 2.

    >>> flatness([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)])     # the parabola's vertex is 1 off its chord
    1.0
    """
    pts = as_points(points)
    return _flatness(pts)


def _flatness(pts: np.ndarray) -> float:
    # (10.2)-(10.3) bound each coordinate of |P''|; the chord then errs by at most ‖L‖ / 8 (chapter 10).
    return float(np.linalg.norm(second_derivative_bounds(pts)) / 8)


def _two_curves(p, q) -> tuple[np.ndarray, np.ndarray]:
    return _planar(p, "p", min_count=2), _planar(q, "q", min_count=2)


def _scale(*arrays: np.ndarray) -> float:
    """The size of the picture: the largest coordinate (at least 1e-300, so that pads are never zero)."""
    return max(max(float(np.abs(a).max()) for a in arrays), 1e-300)


def _boxes_overlap(p: np.ndarray, q: np.ndarray, pad: float) -> bool:
    return bool(np.all(p.min(axis=0) <= q.max(axis=0) + pad) and np.all(q.min(axis=0) <= p.max(axis=0) + pad))


def _chord_hit(p: np.ndarray, q: np.ndarray, slack: float = 1e-6) -> tuple[float, float] | None:
    """Parameters (α, β) with p0 + α (pn - p0) = q0 + β (qn - q0), both in [0, 1] (plus slack); None if they miss."""
    r, s, gap = p[-1] - p[0], q[-1] - q[0], q[0] - p[0]
    denominator = r[0] * s[1] - r[1] * s[0]
    if denominator == 0:
        return None
    alpha = (gap[0] * s[1] - gap[1] * s[0]) / denominator
    beta = (gap[0] * r[1] - gap[1] * r[0]) / denominator
    if -slack <= alpha <= 1 + slack and -slack <= beta <= 1 + slack:
        return min(max(alpha, 0.0), 1.0), min(max(beta, 0.0), 1.0)
    return None


def intersect_by_subdivision(p, q, tol: float = 1e-9) -> np.ndarray:
    """Intersections (t, u), (k, 2) sorted, of two polynomial Bézier curves by Bézier subdivision [LR80]. Notes §7.5.

    Pairs of pieces whose bounding boxes of control points do not overlap are
    dropped; a piece that is not flat yet (its `flatness` above tol times the
    size of the picture) is halved; when both are flat their chords are
    intersected. Transversal intersections come out to within about tol.

    >>> p = [(0.0, 0.0), (10.0, 30.0), (20.0, -30.0), (30.0, 0.0)]
    >>> q = [(-2.0, 8.0), (40.0, 0.0), (-10.0, 0.0), (32.0, -8.0)]
    >>> np.round(intersect_by_subdivision(p, q)[2], 6).tolist()
    [0.5, 0.5]
    """
    pts_p, pts_q = _two_curves(p, q)
    return _subdivision_search(pts_p, pts_q, as_tolerance(tol, below_one=True))


def _subdivision_search(p: np.ndarray, q: np.ndarray, tol: float, log: list | None = None) -> np.ndarray:
    scale = _scale(p, q)
    flat, pad = tol * scale, PAD * scale
    stack = [(p, (0.0, 1.0), q, (0.0, 1.0), 0)]
    boxes = []
    for _ in range(MAX_PAIRS):
        if not stack:
            return _merge_boxes(boxes, tol, p, q, None, None)
        a, t_range, b, u_range, depth = stack.pop()
        if not _boxes_overlap(a, b, pad):
            _note(log, depth, t_range, u_range, "rejected")
            continue
        a_flat, b_flat = _flatness(a) <= flat, _flatness(b) <= flat
        if a_flat and b_flat:
            hit = _chord_hit(a, b)
            if hit is not None:
                t = t_range[0] + hit[0] * (t_range[1] - t_range[0])
                u = u_range[0] + hit[1] * (u_range[1] - u_range[0])
                boxes.append((t, t, u, u))
            _note(log, depth, t_range, u_range, "found" if hit is not None else "rejected")
            continue
        _note(log, depth, t_range, u_range, "split")
        pieces_a = [(a, t_range)] if a_flat else _halves(a, t_range)
        pieces_b = [(b, u_range)] if b_flat else _halves(b, u_range)
        stack += [(pa, ra, pb, rb, depth + 1) for pa, ra in reversed(pieces_a) for pb, rb in reversed(pieces_b)]
    raise RuntimeError(f"intersect_by_subdivision: more than {MAX_PAIRS} pairs of pieces; do the curves overlap?")


def _note(log: list | None, depth: int, t_range, u_range, outcome: str) -> None:
    if log is not None:
        log.append(SearchStep(depth, (float(t_range[0]), float(t_range[1])), (float(u_range[0]), float(u_range[1])),
                              outcome))


def _halves(points: np.ndarray, interval) -> list[tuple[np.ndarray, tuple[float, float]]]:
    left, right = subdivide(points, 0.5)
    middle = (interval[0] + interval[1]) / 2
    return [(left, (interval[0], middle)), (right, (middle, interval[1]))]


def intersect_by_intervals(p, q, tol: float = 1e-9) -> np.ndarray:
    """Intersections (t, u), (k, 2) sorted, of two polynomial Bézier curves by interval subdivision [KM83]. Notes §7.6.

    Each curve is first cut where x'(t) or y'(t) vanishes, so every piece is
    monotone in x and y and its bounding box is spanned by its two end points.
    Pieces are then halved by evaluating the curve at the midpoint of their
    parameter interval (no de Casteljau subdivision), pairs whose boxes miss
    each other are dropped, and pairs narrower than tol in both parameters
    are intersections.

    >>> p = [(0.0, 0.0), (10.0, 30.0), (20.0, -30.0), (30.0, 0.0)]
    >>> q = [(-2.0, 8.0), (40.0, 0.0), (-10.0, 0.0), (32.0, -8.0)]
    >>> np.round(intersect_by_intervals(p, q)[:, 0], 6).tolist()
    [0.111328, 0.388301, 0.5, 0.611699, 0.888672]
    """
    pts_p, pts_q = _two_curves(p, q)
    return _interval_search(pts_p, pts_q, as_tolerance(tol, below_one=True))


def monotone_breaks(points) -> np.ndarray:
    """Sorted parameters 0, ..., 1 where a polynomial Bézier curve has a horizontal or vertical tangent. Notes §7.6.

    points: (n+1, d). The roots in [0, 1] of each coordinate of the hodograph
    (a coordinate that is constant has none); between two neighbours the curve
    is monotone in every coordinate, so its bounding box is spanned by its ends.

    >>> monotone_breaks([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)]).tolist()
    [0.0, 0.5, 1.0]
    """
    return _monotone_breaks(as_points(points))


def _monotone_breaks(points: np.ndarray) -> np.ndarray:
    derivative = hodograph(points)
    found = [np.array([0.0, 1.0])]
    for k in range(points.shape[1]):
        if np.any(derivative[:, k]):
            found.append(bernstein_roots(derivative[:, k]))
    return np.unique(np.concatenate(found))


def _interval_search(p: np.ndarray, q: np.ndarray, tol: float, log: list | None = None) -> np.ndarray:
    pad = PAD * _scale(p, q)

    def pieces(points):
        ts = _monotone_breaks(points)
        values = bernstein_horner(points, ts)
        return [((ts[k], ts[k + 1]), values[k], values[k + 1]) for k in range(len(ts) - 1)]

    stack = [(a, b, 0) for a in pieces(p) for b in pieces(q)]
    boxes = []
    for _ in range(MAX_PAIRS):
        if not stack:
            return _merge_boxes(boxes, tol, p, q, None, None)
        a, b, depth = stack.pop()
        (t_range, a0, a1), (u_range, b0, b1) = a, b
        if not _boxes_overlap(np.array([a0, a1]), np.array([b0, b1]), pad):
            _note(log, depth, t_range, u_range, "rejected")
            continue
        narrow_a, narrow_b = t_range[1] - t_range[0] <= tol, u_range[1] - u_range[0] <= tol
        if narrow_a and narrow_b:
            boxes.append((*t_range, *u_range))
            _note(log, depth, t_range, u_range, "found")
            continue
        _note(log, depth, t_range, u_range, "split")
        halves_a = [a] if narrow_a else _evaluated_halves(p, a)
        halves_b = [b] if narrow_b else _evaluated_halves(q, b)
        stack += [(ha, hb, depth + 1) for ha in reversed(halves_a) for hb in reversed(halves_b)]
    raise RuntimeError(f"intersect_by_intervals: more than {MAX_PAIRS} pairs of pieces; do the curves overlap?")


def _evaluated_halves(points: np.ndarray, piece):
    (start, end), first, last = piece
    middle = (start + end) / 2
    point = bernstein_horner(points, middle)
    return [((start, middle), first, point), ((middle, end), point, last)]


def implicit_by_nullspace(points, weights=None) -> np.ndarray:
    """The implicit equation f[i, j] of x^i y^j, (n+1, n+1), of a degree-n Bézier curve, up to scale. Notes §7.4.

    f(P(t)) = 0 for all t is a homogeneous linear system for the
    (n+1)(n+2)/2 coefficients of a degree-n f: each column holds the
    Bernstein coefficients of X^i Y^j W^(n-i-j) (as in
    `curve_implicit_bernstein`). The right singular vector of its smallest
    singular value spans the solutions; it is scaled to unit length with its
    largest entry positive. Chapter 17 computes the same equation exactly, as
    a resultant (the implicitization algorithm of [SP86a]).

    >>> f = implicit_by_nullspace([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0])
    >>> (np.round(f / f[2, 0], 9) + 0.0).tolist()          # the unit circle x² + y² - 1
    [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    h = _homogeneous_columns(points, weights)
    return _nullspace_implicit(h)


def _nullspace_implicit(h: np.ndarray) -> np.ndarray:
    n = len(h) - 1
    columns = [_bernstein_powers(h[:, k], n) for k in range(3)]
    monomials = [(i, j) for i in range(n + 1) for j in range(n + 1 - i)]
    matrix = np.column_stack([
        bernstein_multiply(bernstein_multiply(columns[0][i], columns[1][j]), columns[2][n - i - j])
        for i, j in monomials
    ])
    vector = np.linalg.svd(matrix)[2][-1]
    vector = vector * np.sign(vector[np.argmax(np.abs(vector))])
    f = np.zeros((n + 1, n + 1))
    for (i, j), value in zip(monomials, vector):
        f[i, j] = value
    return f


def intersect_by_implicitization(p, q, p_weights=None, q_weights=None, tol: float = 1e-9) -> np.ndarray:
    """Intersections (t, u), (k, 2) sorted, by implicitizing P and substituting Q [SP86a]. Notes §7.4, ch. 17.

    Both curves are first moved and scaled into the unit box (the same map for
    both) to keep the implicit equation well conditioned. The roots u of
    f_P(Q(u)) give the points; the parameter t of each on P is recovered
    (inversion) among the roots of X(t) - x W(t) and Y(t) - y W(t). Points of
    the implicit curve that P does not reach for t in [0, 1] are dropped.
    Reliable in double precision for low degrees (the notes: up to five).

    >>> p = [(0.0, 0.0), (10.0, 30.0), (20.0, -30.0), (30.0, 0.0)]
    >>> q = [(-2.0, 8.0), (40.0, 0.0), (-10.0, 0.0), (32.0, -8.0)]
    >>> len(intersect_by_implicitization(p, q))
    5
    """
    pts_p, pts_q = _two_curves(p, q)
    tol = as_tolerance(tol, below_one=True)
    corner = np.minimum(pts_p.min(axis=0), pts_q.min(axis=0))
    size = max(_scale(pts_p - corner, pts_q - corner), 1e-300)
    hp = _homogeneous_columns((pts_p - corner) / size, p_weights, "p", "p_weights")
    hq = _homogeneous_columns((pts_q - corner) / size, q_weights, "q", "q_weights")
    g = curve_implicit_bernstein(_nullspace_implicit(hp), hq[:, :2] / hq[:, 2:], hq[:, 2])
    found = []
    for u in bernstein_roots(g, tol=min(tol, 1e-12)):
        point = bernstein_horner(hq, u)
        point = point[:2] / point[2]
        t, distance = _invert(hp, point)
        if distance <= 1e-6:
            found.append((t, t, u, u))
    return _merge_boxes(found, tol, pts_p, pts_q, p_weights, q_weights)


def _invert(h: np.ndarray, point: np.ndarray) -> tuple[float, float]:
    """The parameter t in [0, 1] of the homogeneous curve h nearest to `point`, and that distance."""
    candidates = [np.array([0.0, 1.0])]
    for k in range(2):
        coordinate = h[:, k] - point[k] * h[:, 2]
        if np.any(coordinate):
            candidates.append(bernstein_roots(coordinate))
    ts = np.concatenate(candidates)
    values = bernstein_horner(h, ts)
    distances = np.hypot(*(values[:, :2] / values[:, 2:] - point).T)
    best = int(np.argmin(distances))
    return float(ts[best]), float(distances[best])


# --- §7.7 Bézier clipping: fat lines ------------------------------------------------------------------


def fat_line(points) -> tuple[np.ndarray, float, float]:
    """The fat line (line, dmin, dmax): the band dmin <= a x + b y + c <= dmax around the control points. Notes §7.7.1.

    points: (n+1, 2), n >= 1 (weights, if any, must be positive, and do not
    matter). line = (a, b, c) is the line L̄ through P0 and Pn, oriented as
    P0 × Pn and normalised so that a² + b² = 1: then a x + b y + c is the
    signed distance to L̄. dmin and dmax are the smallest and largest signed
    distances of the control points, so dmin <= 0 <= dmax. By the convex hull
    property the curve lies in the band. P0 = Pn (a closed piece) has no line
    L̄: ValueError.

    >>> line, dmin, dmax = fat_line([(0.0, 0.0), (2.0, 1.0), (6.0, -2.0), (12.0, 0.0)])
    >>> line.tolist(), dmin, dmax
    ([0.0, 1.0, 0.0], -2.0, 1.0)
    """
    pts = as_points(points, min_count=2)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    if np.array_equal(pts[0], pts[-1]):
        raise ValueError(f"points: P0 = Pn = {pts[0].tolist()}, so there is no line through the two end points")
    a, b = pts[0, 1] - pts[-1, 1], pts[-1, 0] - pts[0, 0]  # the first two entries of P0 × Pn
    length = np.hypot(a, b)
    a, b = a / length, b / length
    # c from P0 after normalising, not the cross product's x0 yn - xn y0: for a short piece far from the
    # origin those two products nearly cancel, and the band would be wider than the piece.
    line = np.array([a, b, 0.0 - (a * pts[0, 0] + b * pts[0, 1])])
    distances = pts @ line[:2] + line[2]
    return line, float(min(distances.min(), 0.0)), float(max(distances.max(), 0.0))


def perpendicular_fat_line(points) -> tuple[np.ndarray, float, float]:
    """The fat line perpendicular to L̄: distances along P0 → Pn from the line through P0 at right angles. Notes §7.7.4.

    line = (a, b, c) with (a, b) the unit vector from P0 to Pn and a x0 + b y0
    + c = 0; (dmin, dmax) spans the control points' distances, so
    dmin <= 0 and dmax >= |Pn - P0|. Clipping against both fat lines and
    keeping the common range helps when the curve is short and wide.

    >>> line, dmin, dmax = perpendicular_fat_line([(0.0, 9.0), (2.0, 2.0), (6.0, 2.0), (5.0, 9.0)])
    >>> line.tolist(), dmin, dmax
    ([1.0, 0.0, 0.0], 0.0, 6.0)
    """
    pts = _planar(points, min_count=2)
    chord = pts[-1] - pts[0]
    length = np.hypot(*chord)
    if length == 0:
        raise ValueError(f"points: P0 = Pn = {pts[0].tolist()}, so the direction from P0 to Pn is undefined")
    a, b = chord / length
    line = np.array([a, b, 0.0 - (a * pts[0, 0] + b * pts[0, 1])])
    distances = pts @ line[:2] + line[2]
    return line, float(min(distances.min(), 0.0)), float(max(distances.max(), 0.0))


# --- §7.7.2 clipping against a fat line ---------------------------------------------------------------


def _hull_band(c: np.ndarray, low: float, high: float) -> tuple[float, float] | None:
    """`clip_range` without its checks, for a band that may be open on one side (low = -inf or high = inf)."""
    if not np.isfinite(low):  # a line below every control point clips nothing away
        low = min(c.min(), high) - 1.0
    if not np.isfinite(high):
        high = max(c.max(), low) + 1.0
    return clip_range(c, low, high)


def clip_range(coeffs, dmin, dmax) -> tuple[float, float] | None:
    """The part (t_lo, t_hi) of [0, 1] where the explicit curve (t, Σ c_i B_i^n) may be in the band. Notes §7.7.2.

    coeffs: (n+1,), the distances d_i of the control points of one curve from
    the other's line L̄ (7.10); the explicit curve has control points
    (i/n, d_i) (7.11). Its convex hull, not its control polygon, meets the
    band over exactly the returned interval; outside it the curve cannot be
    in the band, so that part can be clipped away. None when the hull misses
    the band. A degree-0 curve is the constant c_0 over [0, 1]. dmin > dmax:
    ValueError.

    >>> clip_range([-5.0, -1.0, 2.0, 3.0], -2.0, 1.0)
    (0.25, 0.75)
    >>> clip_range([4.0, 5.0, 3.0], -1.0, 1.0) is None
    True
    """
    c = as_vector(coeffs, "coeffs")
    low = as_scalar(dmin, "dmin")
    high = as_scalar(dmax, "dmax")
    if low > high:
        raise ValueError(f"dmin: expected dmin <= dmax, got dmin = {low} > dmax = {high}")
    n = len(c) - 1
    if n == 0:
        return (0.0, 1.0) if low <= c[0] <= high else None
    t = np.arange(n + 1) / n
    # The extreme points of hull ∩ band: control points inside the band, and the points where
    # a hull edge crosses d = dmin or d = dmax. Every hull edge joins two control points, so the
    # segments between all pairs that cross a line include them: no need to build the hull.
    found = [t[(c >= low) & (c <= high)]]
    for level in (low, high):
        s = c - level
        i, j = np.nonzero((s[:, None] < 0) & (s[None, :] > 0))  # P_i below, P_j above
        found.append(t[i] + (t[j] - t[i]) * (s[i] / (s[i] - s[j])))
    hits = np.concatenate(found)
    if hits.size == 0:
        return None
    return max(float(hits.min()), 0.0), min(float(hits.max()), 1.0)


def clip_curve(points, line, dmin, dmax, weights=None) -> tuple[float, float] | None:
    """Where on [0, 1] a (rational) Bézier curve may meet the band dmin <= a x + b y + c <= dmax. Notes §7.7.2, §7.7.6.

    points: (n+1, 2); line: (a, b, c) (a² + b² = 1 makes d a distance; any
    scale works). A polynomial curve clips with the explicit curve of its
    distances d_i = a x_i + b y_i + c (`clip_range`). A rational one (weights
    > 0) cannot: d(t) = Σ w_i d_i B_i / Σ w_i B_i is not a polynomial, so each
    bounding line is a one-sided clip of its own polynomial,
    Σ w_i (d_i - dmin) B_i >= 0 and Σ w_i (dmax - d_i) B_i >= 0, and the two
    ranges are intersected. (The notes print the first condition with
    "+ dmin", a sign error: with it true intersections are clipped away.)

    >>> clip_curve([(2.0, -5.0), (3.0, -1.0), (10.0, 2.0), (4.0, 3.0)], [0.0, 1.0, 0.0], -2.0, 1.0)
    (0.25, 0.75)
    """
    h = _homogeneous_columns(points, weights)
    line = as_line(line, "line")
    low = as_scalar(dmin, "dmin")
    high = as_scalar(dmax, "dmax")
    if low > high:
        raise ValueError(f"dmin: expected dmin <= dmax, got dmin = {low} > dmax = {high}")
    if weights is not None and np.any(h[:, 2] < 0):
        raise ValueError("weights: clipping relies on the convex hull property, which needs positive weights")
    return _clip_homogeneous(h, line, low, high, weights is not None)


def _clip_homogeneous(h: np.ndarray, line: np.ndarray, low: float, high: float, rational: bool):
    values = h @ line  # w_i (a x_i + b y_i + c)
    if not rational:
        return _hull_band(values, low, high)
    above = _hull_band(values - low * h[:, 2], 0.0, np.inf)
    below = _hull_band(high * h[:, 2] - values, 0.0, np.inf)
    return _common(above, below)


def _common(first, second):
    if first is None or second is None:
        return None
    lo, hi = max(first[0], second[0]), min(first[1], second[1])
    return (lo, hi) if lo <= hi else None


# --- §7.7.7-7.7.8 rational curves: the homogeneous fat line and one-sided clips ---------------------


def homogeneous_fat_line(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """A rational curve's fat line as lines (Lmin, Lmax), the curve on the positive side of both. Notes §7.7.7.

    L̄ = P0 × Pn = (a, b, c) from the homogeneous control points P_i =
    w_i (x_i, y_i, 1); the parallel line (a, b, c_i) through P_i has
    c_i = -a x_i - b y_i. Lmax = (a, b, max c_i) and Lmin = -(a, b, min c_i):
    then Lmax · P_i = w_i (max c - c_i) >= 0 and Lmin · P_i = w_i (c_i - min c)
    >= 0 for positive weights, so the curve lies in {Lmin · p >= 0, Lmax · p >= 0}.

    >>> points = [(2.0, 3.0), (4.0, 6.0), (4.0, 8.0), (8.0, 5.0), (10.0, 9.0)]
    >>> [line.tolist() for line in homogeneous_fat_line(points, [1.0, 3.0, 1.0, 4.0, 1.0])]
    [[6.0, -8.0, 40.0], [-6.0, 8.0, 8.0]]
    """
    h = _homogeneous_columns(points, weights)
    if np.any(h[:, 2] < 0):
        raise ValueError("weights: a fat line bounds the curve only for positive weights")
    base = np.cross(h[0], h[-1])
    if not np.any(base[:2]):
        raise ValueError("points: P0 = Pn, so there is no line L̄ through the two end points")
    offsets = -(h[:, :2] / h[:, 2:]) @ base[:2]
    lmax = np.array([base[0], base[1], offsets.max()])
    lmin = -np.array([base[0], base[1], offsets.min()])
    return lmin, lmax


def explicit_meets(values, end: str = "left") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The V rule's construction: the points E_i, lines from an end point to each E_i, their meets with the axis.

    values: (n+1,), the heights L · P_i of the explicit points E_i = (i/n, L · P_i, 1)
    (homogeneous). end: "left" (lines E0 × E_i, i = 1..n) or "right" (En × E_i,
    i = 0..n-1). Returns (E (n+1, 3), lines (n, 3), meets (n, 3)); each meet
    V_i = line × (0, 1, 0), the axis X = L(0, 1, 0); a line parallel to the
    axis meets it at infinity (W = 0). Notes §7.7.8.

    >>> E, lines, meets = explicit_meets([-40.0, -56.0, -20.0, 96.0, 294.0])
    >>> lines[0].tolist(), meets[0].tolist()
    ([16.0, 0.25, 10.0], [-10.0, 0.0, 16.0])
    """
    e = as_vector(values, "values")
    if len(e) < 2:
        raise ValueError(f"values: the construction needs at least two explicit points, got {len(e)}")
    if end not in ("left", "right"):
        raise ValueError(f"end: expected 'left' or 'right', got {end!r}")
    return _explicit_meets(e, end)


def _explicit_meets(e: np.ndarray, end: str):
    n = len(e) - 1
    points = np.column_stack([np.arange(n + 1) / n, e, np.ones(n + 1)])
    anchor, others = (points[0], points[1:]) if end == "left" else (points[-1], points[:-1])
    lines = np.cross(anchor, others)
    meets = np.cross(lines, np.array([0.0, 1.0, 0.0]))
    return points, lines, meets


def clip_one_sided(line, points, weights=None, exact: bool = False) -> tuple[float, float] | None:
    """The part (t_lo, t_hi) of [0, 1] that may be on the positive side of a line, by the V rule, or None. Notes §7.7.8.

    line: homogeneous (3,), the inside being line · p >= 0; points (n+1, 2),
    weights None or positive (n+1,). The explicit points are
    E_i = (i/n, line · w_i (x_i, y_i, 1)). If every E_i is below the axis,
    nothing survives (None). If E0 is below, the left end is clipped up to
    the smallest positive meet of the lines E0 E_i with the axis; if En is
    below, the right end from the largest meet below 1 of the lines En E_i.
    That is the steepest line out of the end point: never more than the exact
    hull crossing, and equal to it when the steepest E_i lies above the axis.
    exact=True returns the exact crossing of the convex hull instead.

    >>> points = [(0.0, 10.0), (0.0, 12.0), (5.0, 10.0), (8.0, 7.0), (11.0, 1.0)]
    >>> weights = [1.0, 1.0, 2.0, 3.0, 3.0]
    >>> low, high = clip_one_sided([6.0, -8.0, 40.0], points, weights)
    >>> round(low, 9), high
    (0.119760479, 1.0)
    """
    line = as_line(line, "line")
    pts = as_points(points)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    w = np.ones(len(pts)) if weights is None else as_weights(weights, len(pts))
    if np.any(w < 0):
        raise ValueError("weights: clipping relies on the convex hull property, which needs positive weights")
    e = to_homogeneous(pts, w) @ line  # the heights e_i = L · w_i (x_i, y_i, 1)
    if exact:  # the hull's own crossing: the band 0 <= e <= max e_i is the half-plane e >= 0
        return clip_range(e, 0.0, max(e.max(), 0.0))
    if np.all(e < 0):
        return None
    if len(e) == 1:
        return (0.0, 1.0)
    low, high = 0.0, 1.0
    if e[0] < 0:  # the left-most meet V_i of a line E_0 E_i with the axis to the right of E_0
        _, _, meets = explicit_meets(e, "left")
        v = meets[meets[:, 2] != 0]  # a line parallel to the axis meets it at infinity
        v = v[:, 0] / v[:, 2]
        low = float(v[v > 0].min())
    if e[-1] < 0:  # the right-most meet of a line E_n E_i with the axis to the left of E_n
        _, _, meets = explicit_meets(e, "right")
        v = meets[meets[:, 2] != 0]
        v = v[:, 0] / v[:, 2]
        high = float(v[v < 1].max())
    return low, high


# --- §7.7.3-7.7.6 iterating, multiple intersections, rational curves: the intersector ----------------


@dataclass(frozen=True)
class ClipStep:
    """One event of the Bézier-clipping search (`clip_trace`).

    kind: "clip" (curve "P" or "Q" clipped against the other's fat line),
    "rejected" (a clip left nothing of it), "split" (the curve halved after
    a stalled round) or "found". t_range, u_range: the global parameter ranges
    after the event. For a clip (or rejection): fat_line = (line, dmin, dmax),
    the padded parallel fat line of the other piece; values = the coefficients
    of the explicit curve against it (the distances d_i, or for a rational
    curve the one-sided pair w_i (d_i - dmin), w_i (dmax - d_i), shape (2, n+1));
    local = the kept range of [0, 1] (both fat lines), or None; perpendicular
    = the perpendicular fat line when it was used; before = the clipped
    curve's global range before the clip.
    """

    kind: str
    curve: str
    depth: int
    t_range: tuple[float, float]
    u_range: tuple[float, float]
    fat_line: tuple | None = None
    values: np.ndarray | None = None
    local: tuple[float, float] | None = None
    perpendicular: tuple | None = None
    before: tuple[float, float] | None = None


class _Piece:
    """A piece of a curve in the search: homogeneous control points over a global parameter range."""

    __slots__ = ("h", "lo", "hi")

    def __init__(self, h: np.ndarray, lo: float, hi: float):
        self.h, self.lo, self.hi = h, lo, hi

    @property
    def width(self) -> float:
        return self.hi - self.lo

    def cartesian(self) -> np.ndarray:
        return self.h[:, :2] / self.h[:, 2:]

    def restrict(self, lo: float, hi: float) -> _Piece:
        """The same curve over the local [lo, hi] of [0, 1]."""
        span = self.hi - self.lo
        return _Piece(_restrict(self.h, lo, hi), self.lo + span * lo, self.lo + span * hi)

    def halves(self) -> tuple[_Piece, _Piece]:
        left, right = subdivide(self.h, 0.5)
        middle = (self.lo + self.hi) / 2
        return _Piece(left, self.lo, middle), _Piece(right, middle, self.hi)


def _restrict(h: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Control points of the part lo <= t <= hi of a curve, reparametrised to [0, 1]: two subdivisions."""
    if lo > 0:
        h = subdivide(h, lo)[1]
    if hi < 1:
        h = subdivide(h, (hi - lo) / (1 - lo))[0]
    return h


def curve_piece(points, interval, weights=None) -> tuple[np.ndarray, np.ndarray | None]:
    """The part of a (rational) Bézier curve over interval = (a, b) ⊂ [0, 1] as a curve over [0, 1]. Notes §7.7.2.

    Returns (points (n+1, d), weights (n+1,) or None): what a clip keeps, by
    two de Casteljau subdivisions (at a, then at (b - a)/(1 - a) of the rest),
    on the homogeneous points of a rational curve. a = b gives the point P(a)
    n+1 times.

    >>> curve_piece([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], (0.0, 0.5))[0].tolist()
    [[0.0, 0.0], [0.5, 1.0], [1.0, 1.0]]
    """
    pts = as_points(points)
    lo, hi = (float(v) for v in as_vector(interval, "interval", dim=2))
    if not 0 <= lo <= hi <= 1:
        raise ValueError(f"interval: expected 0 <= a <= b <= 1, got ({lo}, {hi})")
    if weights is None:
        return _restrict(pts, lo, hi), None
    h = _restrict(to_homogeneous(pts, weights), lo, hi)
    return h[:, :-1] / h[:, -1:], h[:, -1].copy()


def _bands(points: np.ndarray, pad: float, perpendicular: bool) -> list[tuple[np.ndarray, float, float]]:
    """The fat line of a piece (padded), and the perpendicular one if asked; robust to P0 = Pn.

    A closed or tiny piece has no chord: the line through P0 and its farthest
    control point stands in (any direction bounds the curve, only less tightly).
    """
    chord = points[-1] - points[0]
    if np.hypot(*chord) <= pad:
        far = points[np.argmax(np.hypot(*(points - points[0]).T))] - points[0]
        chord = far if np.hypot(*far) > pad else np.array([1.0, 0.0])
    direction = chord / np.hypot(*chord)
    normals = [np.array([-direction[1], direction[0]])]
    if perpendicular:
        normals.append(direction)
    bands = []
    for a, b in normals:
        line = np.array([a, b, -(a * points[0, 0] + b * points[0, 1])])
        d = points @ line[:2] + line[2]
        bands.append((line, min(d.min(), 0.0) - pad, max(d.max(), 0.0) + pad))
    return bands


class _Search:
    """The Bézier-clipping search of `intersect_curves`, with an optional event log for `clip_trace`."""

    def __init__(self, hp, hq, rational, tol, max_steps, perpendicular=True, log=None):
        self.rational, self.tol, self.max_steps = rational, tol, max_steps
        self.perpendicular, self.log = perpendicular, log
        self.scale = _scale(hp[:, :2] / hp[:, 2:], hq[:, :2] / hq[:, 2:])
        self.pad = PAD * self.scale
        self.steps = 0
        self.boxes: list[tuple[float, float, float, float]] = []
        self.stack = [(_Piece(hp, 0.0, 1.0), _Piece(hq, 0.0, 1.0), 0)]

    def run(self, overlap_check=None) -> list:
        while self.stack:
            self._pair(*self.stack.pop(), overlap_check)
        return self.boxes

    def _pair(self, p: _Piece, q: _Piece, depth: int, overlap_check) -> None:
        while True:
            self.steps += 1
            if self.steps == OVERLAP_CHECK_AFTER and overlap_check is not None:
                overlap_check()
            if self.steps > self.max_steps:
                raise RuntimeError(
                    f"intersect_curves: gave up after {self.max_steps} clipping rounds, still working near "
                    f"t = {p.lo:.9g}, u = {q.lo:.9g}; the curves may touch there to high order or overlap a "
                    "little (raise max_steps or tol)"
                )
            if p.width <= self.tol and q.width <= self.tol:
                self.boxes.append((p.lo, p.hi, q.lo, q.hi))
                self._note("found", "", depth, p, q)
                return
            before = (p.width, q.width)
            p = self._clip(p, q, "P", depth)
            if p is None:
                return
            q = self._clip(q, p, "Q", depth)
            if q is None:
                return
            depth += 1
            if p.width > STALL * before[0] and q.width > STALL * before[1]:
                if self._indistinguishable(p, q):
                    self.boxes.append((p.lo, p.hi, q.lo, q.hi))
                    self._note("found", "", depth, p, q)
                else:
                    self._split(p, q, depth)
                return

    def _indistinguishable(self, p: _Piece, q: _Piece) -> bool:
        """Both pieces tiny and flat to within rounding: no clip can tell them apart (a tangency)."""
        for piece in (p, q):
            points = piece.cartesian()
            if np.ptp(points, axis=0).max() > TINY * self.scale:
                return False
            _, low, high = _bands(points, self.pad, False)[0]
            if high - low > THIN * self.pad:
                return False
        return True

    def _clip(self, piece: _Piece, other: _Piece, name: str, depth: int) -> _Piece | None:
        """Clip `piece` against the fat line(s) of `other`; None if nothing is left."""
        if piece.width <= self.tol < other.width:
            return piece  # converged: only the other curve still needs clipping
        bands = _bands(other.cartesian(), self.pad, self.perpendicular)
        rational = self.rational[name == "Q"]
        kept = (0.0, 1.0)
        for line, low, high in bands:
            kept = _common(kept, _clip_homogeneous(piece.h, line, low, high, rational))
            if kept is None:
                break
        clipped = None
        if kept is not None:
            lo, hi = max(kept[0] - SLACK, 0.0), min(kept[1] + SLACK, 1.0)
            clipped = piece if (lo, hi) == (0.0, 1.0) else piece.restrict(lo, hi)
        if self.log is not None:
            self._log_clip(name, depth, piece, other, clipped, bands, kept)
        return clipped

    def _split(self, p: _Piece, q: _Piece, depth: int) -> None:
        if p.width >= q.width:
            first, second = p.halves()
            self.stack += [(second, q, depth), (first, q, depth)]
            self._note("split", "P", depth, p, q)
        else:
            first, second = q.halves()
            self.stack += [(p, second, depth), (p, first, depth)]
            self._note("split", "Q", depth, p, q)

    def _note(self, kind: str, name: str, depth: int, p: _Piece, q: _Piece) -> None:
        if self.log is not None:
            self.log.append(ClipStep(kind, name, depth, (p.lo, p.hi), (q.lo, q.hi)))

    def _log_clip(self, name, depth, piece, other, clipped, bands, kept) -> None:
        line, low, high = bands[0]
        values = piece.h @ line
        if self.rational[name == "Q"]:
            values = np.stack([values - low * piece.h[:, 2], high * piece.h[:, 2] - values])
        after = clipped or piece
        p, q = (after, other) if name == "P" else (other, after)
        self.log.append(ClipStep("clip" if clipped else "rejected", name, depth, (p.lo, p.hi), (q.lo, q.hi),
                                 bands[0], values, kept, bands[1] if len(bands) > 1 else None, (piece.lo, piece.hi)))


def _curve_pair(p, q, p_weights, q_weights):
    """Checked planar curves (degree >= 1) and their homogeneous forms; weights must be positive."""
    pts_p, pts_q = _two_curves(p, q)
    homogeneous = []
    for pts, weights, name in ((pts_p, p_weights, "p_weights"), (pts_q, q_weights, "q_weights")):
        if weights is None:
            h = np.ones((len(pts), 3))
            h[:, :2] = pts
        else:
            w = as_weights(weights, len(pts), name)
            if np.any(w <= 0):
                raise ValueError(f"{name}: Bézier clipping needs positive weights (the convex hull property), "
                                 f"got {w.tolist()}")
            h = to_homogeneous(pts, w)
        homogeneous.append(h)
    return pts_p, pts_q, *homogeneous


def intersect_curves(p, q, tol: float = 1e-9, p_weights=None, q_weights=None, max_steps: int = MAX_STEPS,
                     perpendicular: bool = True) -> np.ndarray:
    """Every intersection (t, u) of two planar Bézier curves by Bézier clipping: (k, 2), sorted by t, u. Notes §7.7.

    p: (n+1, 2), q: (m+1, 2), degrees >= 1; p_weights, q_weights: None
    (polynomial) or positive weights of a rational curve. The search is the
    clipping of §7.7 that `clip_trace` shows one clip at a time: P against
    the fat line of Q, then Q against that of the clipped P (with
    perpendicular=True also against the perpendicular fat lines), and a
    round that keeps too much of both ranges splits the longer one (§7.7.5).
    Once two pieces can cross at most once (their tangent directions are
    separated) or both ranges are narrower than tol, Newton's method on
    P(t) = Q(u) finishes the intersection. What comes back:

    * a crossing, to within tol in t and u. tol must be at least 1e-15 (the
      spacing of doubles near 1 is 1.1e-16): ValueError below. When the
      rounding of P(t) - Q(u) could exceed tol/4, the last Newton step uses
      compensated arithmetic, which leaves a few units in the last place;
    * an intersection at an end of a curve (a shared end point), exactly at
      0 or 1;
    * a tangency (the curves touch), once: Newton's method on the tangency
      system (parallel tangents, P(t) - Q(u) normal to Q) gives about 1e-15
      where the curvatures differ; where they agree too (a triple contact)
      that system is singular and the middle of the stretch over which the
      curves stay together is reported, to about 1e-7.

    Curves that come closer than 8e-12 times the size of the picture (the
    largest coordinate, measured from P0) count as touching, and intersections closer than tol in both t and u, or with
    the curves that close all the way between them, are reported once. No
    intersection: an empty (0, 2) array. Curves that share a piece have no
    isolated intersections: ValueError. After max_steps clipping rounds the
    search gives up with a RuntimeError.
    Ref: T. W. Sederberg and T. Nishita, Curve intersection using Bézier clipping, CAD 22(9), 1990.

    >>> p = [(2.0, -5.0), (3.0, -1.0), (10.0, 2.0), (4.0, 3.0)]
    >>> q = [(0.0, 0.0), (2.0, 1.0), (6.0, -2.0), (12.0, 0.0)]
    >>> np.round(intersect_curves(p, q), 9).tolist()
    [[0.429289175, 0.548961333]]
    """
    if type(tol) is not float or not TOL_FLOOR <= tol < 1.0:
        tol = as_tolerance(tol, below_one=True)
        if tol < TOL_FLOOR:
            raise ValueError(f"tol: {tol:g} is below 1e-15, finer than double precision can place a parameter "
                             "(doubles near 1 are 1.1e-16 apart); ask for tol >= 1e-15")
    if type(max_steps) is not int or max_steps < 1:
        max_steps = as_count(max_steps, "max_steps", minimum=1)
    polynomial = p_weights is None and q_weights is None
    lists = (_planar_lists(p), _planar_lists(q)) if polynomial else (None, None)
    if lists[0] is None or lists[1] is None:
        pts_p, pts_q, hp, hq = _curve_pair(p, q, p_weights, q_weights)
        lists = (pts_p.T.tolist(), pts_q.T.tolist())
        weights = [None if p_weights is None else hp[:, 2].tolist(), None if q_weights is None else hq[:, 2].tolist()]
    else:
        weights = [None, None]
    # Both curves are moved so that P0 is the origin: the rounding of every evaluation then scales with the
    # size of the curves rather than with their distance from the origin.
    given = [(xs, ys, ws) for (xs, ys), ws in zip(lists, weights)]
    x0, y0 = lists[0][0][0], lists[0][1][0]
    curves = []
    for (xs, ys), ws in zip(lists, weights):
        xs, ys = [x - x0 for x in xs], [y - y0 for y in ys]
        if ws is not None:
            xs, ys = [x * w for x, w in zip(xs, ws)], [y * w for y, w in zip(ys, ws)]
        curves.append((xs, ys, ws))
    scale = 1e-300  # the size of the picture: the largest coordinate (Cartesian, for a rational curve)
    for xs, ys, ws in curves:
        size = max(max(xs), -min(xs), max(ys), -min(ys))
        scale = max(scale, size if ws is None else size / min(ws))

    def overlap_check():
        _raise_if_overlapping(*(_homogeneous_array(c) for c in curves))

    search_tol = max(tol, _clipping.FLOOR)
    try:
        if polynomial:  # on Python floats: faster than the batched search at every degree (3 to 25 measured)
            (px, py, _), (qx, qy, _) = curves
            boxes, crossings, contacts = _clipping.search(px, py, qx, qy, search_tol, max_steps, perpendicular,
                                                          scale, PAD * scale, overlap_check)
        else:
            found = _batched_search(*(_homogeneous_array(c) for c in curves), search_tol, max_steps, perpendicular,
                                    overlap_check, scale)
            boxes, crossings, contacts = [tuple(row[:4]) + (bool(row[4]),) for row in found.tolist()], [], []
    except _clipping.GaveUp as stop:
        raise RuntimeError(
            f"intersect_curves: gave up after {stop.steps} clipping rounds, still working near "
            f"t = {stop.t:.9g}, u = {stop.u:.9g}; the curves may touch there to high order or overlap a "
            "little (raise max_steps or tol)"
        ) from None
    found = _clipping.resolve(boxes, crossings, contacts, curves[0], curves[1], tol, scale, PAD * scale,
                              overlap_check, given)
    return np.array(found, dtype=float).reshape(-1, 2)


def _planar_lists(points) -> list | None:
    """[xs, ys] of finite planar control points (n+1, 2), n >= 1, or None: then the full checks say what is wrong."""
    try:
        array = np.asarray(points, dtype=float)
    except (TypeError, ValueError):
        return None
    if array.ndim != 2 or array.shape[1] != 2 or array.shape[0] < 2:
        return None
    xs, ys = array.T.tolist()
    if (sum(xs) + sum(ys)) * 0.0 != 0.0:  # NaN or infinity (or an overflow: the full checks decide)
        return None
    return [xs, ys]


def _homogeneous_array(curve) -> np.ndarray:
    """(xs, ys, ws) lists -> homogeneous rows (w x, w y, w), (n+1, 3)."""
    xs, ys, ws = curve
    return np.column_stack([xs, ys, np.ones(len(xs)) if ws is None else ws])


def clip_trace(p, q, tol: float = 1e-9, p_weights=None, q_weights=None, max_steps: int = MAX_STEPS,
               perpendicular: bool = False) -> list[ClipStep]:
    """Every event of the Bézier-clipping search of `intersect_curves`, in order: a list of ClipStep. Notes §7.7.3.

    With the default perpendicular=False only the parallel fat lines of the
    notes are used, so the first events reproduce the notes' iteration: the
    ranges of each clip (Table 7.2) shrink quadratically to one intersection.

    >>> p = [(2.0, -5.0), (3.0, -1.0), (10.0, 2.0), (4.0, 3.0)]
    >>> q = [(0.0, 0.0), (2.0, 1.0), (6.0, -2.0), (12.0, 0.0)]
    >>> [np.round(step.t_range if step.curve == "P" else step.u_range, 2).tolist() for step in clip_trace(p, q)[:2]]
    [[0.25, 0.75], [0.42, 0.63]]
    """
    _, _, hp, hq = _curve_pair(p, q, p_weights, q_weights)
    log: list[ClipStep] = []
    search = _Search(hp, hq, (p_weights is not None, q_weights is not None), as_tolerance(tol, below_one=True),
                     as_count(max_steps, "max_steps", minimum=1), perpendicular, log)
    search.run(lambda: _raise_if_overlapping(hp, hq))
    return log


def search_steps(p, q, method: str = "clipping", tol: float = 1e-9) -> list[SearchStep]:
    """The pairs of pieces a search examines, in order, for comparing the algorithms of §7.5-7.7. Notes §7.4.

    method: "subdivision" (Bézier subdivision, §7.5), "intervals" (interval
    subdivision, §7.6) or "clipping" (Bézier clipping, §7.7: one step per
    round of two clips, or per split). p, q: polynomial (n+1, 2) curves.

    >>> p = [(2.0, -5.0), (3.0, -1.0), (10.0, 2.0), (4.0, 3.0)]
    >>> q = [(0.0, 0.0), (2.0, 1.0), (6.0, -2.0), (12.0, 0.0)]
    >>> len(search_steps(p, q, "clipping")) < len(search_steps(p, q, "subdivision"))
    True
    """
    pts_p, pts_q = _two_curves(p, q)
    tol = as_tolerance(tol, below_one=True)
    log: list = []
    if method == "subdivision":
        _subdivision_search(pts_p, pts_q, tol, log)
        return log
    if method == "intervals":
        _interval_search(pts_p, pts_q, tol, log)
        return log
    if method != "clipping":
        raise ValueError(f"method: expected 'subdivision', 'intervals' or 'clipping', got {method!r}")
    steps = []
    for event in clip_trace(pts_p, pts_q, tol, perpendicular=True):
        if event.kind == "clip" and event.curve == "P":
            continue  # a round is reported once, after its second clip
        outcome = {"clip": "clipped"}.get(event.kind, event.kind)
        steps.append(SearchStep(event.depth, event.t_range, event.u_range, outcome))
    return steps


# --- §7.7 the plain Bézier-clipping loop, as chapter 7 states it --------------------------------------


def bezier_clipping(p, q, tol=1e-9, p_weights=None, q_weights=None, pad=1e-12,
                    perpendicular=True, max_rounds=1000, log=None) -> np.ndarray:
    """All intersections (t, u) of two Bézier curves by plain clipping. Notes §7.7.

    The loop of chapter 7's algorithm box, written to be read (`intersect_curves`
    runs the same clipping faster and finishes with Newton's method).
    p: (n+1, 2), q: (m+1, 2); p_weights, q_weights: None or positive weights.
    A pair of pieces is a pair of parameter ranges. A round clips P against
    the fat lines of Q's piece (the parallel one and, if `perpendicular`, the
    perpendicular one, both widened by `pad` times the largest coordinate),
    then Q against those of P's new piece. A round that keeps more than 80 %
    of both ranges splits the longer one, unless both pieces are smaller than
    1e-6 of the largest coordinate (a tangency: recorded). Pairs narrower
    than tol in t and in u are recorded, and recorded pairs that touch are
    merged (`merge_touching`). Returns (k, 2), sorted by t, then u. More than
    `max_rounds` rounds raise a RuntimeError (overlapping curves never end).
    log: None or a list; it receives (event, t_range, u_range) per event:
    "clip P", "clip Q", "missed" (a clip kept nothing), "split P", "split Q",
    "found".

    >>> p = [(2.0, -5.0), (3.0, -1.0), (10.0, 2.0), (4.0, 3.0)]
    >>> q = [(0.0, 0.0), (2.0, 1.0), (6.0, -2.0), (12.0, 0.0)]
    >>> np.round(bezier_clipping(p, q), 9).tolist()
    [[0.429289175, 0.548961333]]
    """
    curves = {}
    for name, points, weights in (("p", p, p_weights), ("q", q, q_weights)):
        points = as_points(points, name, min_count=2)
        if points.shape[1] != 2:
            raise ValueError(f"{name}: expected shape (n+1, 2), got {points.shape}")
        if weights is not None:
            weights = as_weights(weights, len(points), f"{name}_weights")
            if np.any(weights <= 0):
                raise ValueError(f"{name}_weights: must be positive, got {weights}")
        curves[name.upper()] = (points, weights)
    tol = as_tolerance(tol, below_one=True)
    size = max(np.abs(points).max() for points, _ in curves.values())
    pad = as_scalar(pad, "pad") * size
    max_rounds = as_count(max_rounds, "max_rounds", minimum=1)
    bands = (fat_line, perpendicular_fat_line) if perpendicular else (fat_line,)

    def piece(name, interval):  # control points (and weights) over [0, 1]
        points, weights = curves[name]
        return curve_piece(points, interval, weights)

    def fat_lines(points):
        end = points[-1]
        if np.array_equal(end, points[0]):  # a closed piece: aim at the farthest point
            end = points[np.argmax(np.hypot(*(points - points[0]).T))]
            if np.array_equal(end, points[0]):  # a single point: any direction
                end = points[0] + (1.0, 0.0)
        for band in bands:
            line, _, _ = band([points[0], end])
            d = points @ line[:2] + line[2]
            yield line, min(d.min(), 0.0) - pad, max(d.max(), 0.0) + pad

    def clip(name, interval, other):  # the part of interval that may meet `other`
        points, weights = piece(name, interval)
        low, high = 0.0, 1.0
        for line, dmin, dmax in fat_lines(other):
            kept = clip_curve(points, line, dmin, dmax, weights)
            if kept is None or kept[0] > high or kept[1] < low:
                return None
            low, high = max(low, kept[0]), min(high, kept[1])
        a, b = interval
        return (a + (b - a) * low, a + (b - a) * high)

    def tiny(name, interval):
        return np.ptp(piece(name, interval)[0], axis=0).max() <= 1e-6 * size

    def note(event, t_range, u_range):
        if log is not None:
            log.append((event, t_range, u_range))

    found, rounds = [], 0
    stack = [((0.0, 1.0), (0.0, 1.0))]
    while stack:
        t_range, u_range = stack.pop()
        while True:
            before = (t_range[1] - t_range[0], u_range[1] - u_range[0])
            if before[0] <= tol and before[1] <= tol:
                found.append((t_range, u_range))
                note("found", t_range, u_range)
                break
            rounds += 1
            if rounds > max_rounds:
                raise RuntimeError(f"over {max_rounds} rounds: do p and q overlap?")
            t_range = clip("P", t_range, piece("Q", u_range)[0])
            note("clip P" if t_range else "missed", t_range, u_range)
            if t_range is None:
                break
            u_range = clip("Q", u_range, piece("P", t_range)[0])
            note("clip Q" if u_range else "missed", t_range, u_range)
            if u_range is None:
                break
            after = (t_range[1] - t_range[0], u_range[1] - u_range[0])
            if after[0] > 0.8 * before[0] and after[1] > 0.8 * before[1]:  # 20 % rule
                if tiny("P", t_range) and tiny("Q", u_range):
                    found.append((t_range, u_range))
                    note("found", t_range, u_range)
                elif after[0] >= after[1]:
                    middle = (t_range[0] + t_range[1]) / 2
                    stack.append(((middle, t_range[1]), u_range))
                    stack.append(((t_range[0], middle), u_range))
                    note("split P", t_range, u_range)
                else:
                    middle = (u_range[0] + u_range[1]) / 2
                    stack.append((t_range, (middle, u_range[1])))
                    stack.append((t_range, (u_range[0], middle)))
                    note("split Q", t_range, u_range)
                break
    return merge_touching(found)


def merge_touching(boxes, gap=1e-6) -> np.ndarray:
    """One (t, u) per group of touching parameter boxes, sorted by t, u. Notes §7.7.5.

    boxes: pairs ((t0, t1), (u0, u1)). Two boxes touch when their t ranges and
    their u ranges both overlap once widened by gap; a group, all that touching
    links together, is reported at the middle of its t and u extent. So an
    intersection on a split parameter, found by both halves, comes out once.

    >>> s = 0.5 + 2**-21                        # 4.8e-7 from 0.5: within the gap
    >>> boxes = [((0.5, 0.5), (0.25, 0.25)), ((s, s), (0.25, 0.25)), ((0.9, 0.9), (0.1, 0.1))]
    >>> merge_touching(boxes, gap=1e-6).tolist()
    [[0.5000002384185791, 0.25], [0.9, 0.1]]
    """
    groups = []
    for interval_t, interval_u in boxes:
        (t0, t1), (u0, u1) = (as_vector(interval_t, "boxes", dim=2),
                              as_vector(interval_u, "boxes", dim=2))
        groups.append([float(t0), float(t1), float(u0), float(u1)])
    gap = as_scalar(gap, "gap")

    def touch(a, b):
        return (a[0] <= b[1] + gap and b[0] <= a[1] + gap
                and a[2] <= b[3] + gap and b[2] <= a[3] + gap)

    k = 0
    while k < len(groups):
        other = next((g for g in groups[k + 1:] if touch(groups[k], g)), None)
        if other is None:
            k += 1
            continue
        groups.remove(other)
        mine = groups[k]
        groups[k] = [min(mine[0], other[0]), max(mine[1], other[1]),
                     min(mine[2], other[2]), max(mine[3], other[3])]
        k = 0  # the larger group may now touch one it did not touch before
    found = sorted(((t0 + t1) / 2, (u0 + u1) / 2) for t0, t1, u0, u1 in groups)
    return np.array(found, dtype=float).reshape(-1, 2)


# --- the batched search of intersect_curves: every live pair of pieces clipped at once ----------------
#
# The searches above take one pair of pieces at a time and one NumPy step per clip: `clip_trace`
# records the stepper `_Search`, and `bezier_clipping` is the same loop written to be read, which
# chapter 7 shows. For polynomial curves `intersect_curves` runs the clipping
# on Python floats (`_clipping.search`); for rational curves it runs the same clipping on all live
# pairs of pieces together, here: the state is only the parameter ranges, (2, K) arrays lo and hi
# (row 0 for P, row 1 for Q, one column per pair of pieces); each round rebuilds every piece from
# the original curve, takes every fat line, clips every piece against its partner's and splits the
# stalled pairs, each as a few operations on whole arrays. Both curves of a pair are clipped against
# the fat lines of the other piece as it was at the start of the round (the plain search clips Q
# against the already clipped P), so that both halves of a round are one computation.


@functools.cache
def _batch_tables(n: int):
    """Constant tables for degree n: the blossom terms of a piece and the point pairs of a hull clip.

    Piece: the control points of the part [a, b] of a curve are its blossom values
    f(a^(n-i), b^i) = Σ_j M_ij P_j with M_ij = Σ_k B_k^i(b) B_(j-k)^(n-i)(a) (§6: the blossom is
    symmetric and affine in each argument), a sum of products b^k (1-b)^(i-k) a^(j-k) (1-a)^(n-i-j+k)
    with positive coefficients C(i, k) C(n-i, j-k): term r is entry high[r] of the table
    b^x (1-b)^y times entry low[r] of the table a^x (1-a)^y (x, y = 0..n, flattened), added into
    M[i_r, j_r] with coefficient coefs[r]. Hull clip: for the explicit points (i/n, s_i), pairs[0]
    gathers s_i and pairs[1] forms s_i - s_j over all i < j (a matrix on the points' axis), the
    crossing of segment i j with s = 0 is t_i + (t_j - t_i) s_i / (s_i - s_j).
    """
    terms = [(i, j, k) for i in range(n + 1) for j in range(n + 1) for k in range(max(0, i + j - n), min(i, j) + 1)]
    i, j, k = np.array(terms).T
    high = k * (n + 1) + (i - k)
    low = (j - k) * (n + 1) + (n - i - j + k)
    coefs = np.array([comb(a, c) * comb(n - a, b - c) for a, b, c in terms], dtype=float)
    first, second = np.triu_indices(n + 1, 1)
    count = len(first)
    gather = np.zeros((2 * count, n + 1))
    gather[np.arange(count), first] = 1.0
    gather[count + np.arange(count), first] = 1.0
    gather[count + np.arange(count), second] = -1.0
    t = np.arange(n + 1) / n
    return high, low, (i, j, coefs), gather, t[first][:, None], (t[second] - t[first])[:, None]


def _batch_curves(hp: np.ndarray, hq: np.ndarray) -> tuple[np.ndarray, int, np.ndarray]:
    """Both homogeneous curves at one degree n (the lower one elevated), folded into the blossom terms.

    Returns (folded (2, T, 3(n+1)), n, curves (2, n+1, 3)).
    """
    n = max(len(hp), len(hq)) - 1
    if len(hp) != len(hq):
        hp, hq = elevate(hp, n + 1 - len(hp)), elevate(hq, n + 1 - len(hq))
    curves = np.stack([hp, hq])
    i, j, coefs = _batch_tables(n)[2]
    folded = np.zeros((2, len(coefs), n + 1, 3))
    folded[:, np.arange(len(coefs)), i] = coefs[:, None] * curves[:, j]
    return folded.reshape(2, len(coefs), -1), n, curves


def _batch_pieces(lo: np.ndarray, hi: np.ndarray, folded: np.ndarray, n: int) -> np.ndarray:
    """Homogeneous control points (2, K, n+1, 3) of the pieces over [lo, hi] (each (2, K)) of both curves."""
    high, low = _batch_tables(n)[:2]
    k = lo.shape[1]
    powers = np.empty((4, 2, k, n + 1))  # b^x, (1-b)^x, a^x, (1-a)^x for x = 0..n
    powers[..., 0] = 1.0
    powers[..., 1:] = np.concatenate([hi, 1 - hi, lo, 1 - lo]).reshape(4, 2, k, 1)
    np.cumprod(powers, axis=-1, out=powers)
    b_table = (powers[0, ..., :, None] * powers[1, ..., None, :]).reshape(2, k, -1)
    a_table = (powers[2, ..., :, None] * powers[3, ..., None, :]).reshape(2, k, -1)
    products = np.take(b_table, high, axis=2) * np.take(a_table, low, axis=2)
    return (products @ folded).reshape(2, k, n + 1, 3)


_NORMAL_AND_CHORD = np.array([[0.0, 1.0, 1.0, 0.0], [-1.0, 0.0, 0.0, 1.0]])  # (dx, dy) -> columns (-dy, dx), (dx, dy)
_NORMAL = np.array([[0.0, 1.0], [-1.0, 0.0]])


def _batch_fat_lines(h: np.ndarray, pad: float, perpendicular: bool) -> tuple[np.ndarray, np.ndarray]:
    """Every piece's padded fat line(s) as one-sided conditions, and the unpadded width of the parallel band.

    h: (..., n+1, 3). Returns (A, width): A (..., 3, 2L) with L = 2 lines (parallel and
    perpendicular) or 1; the curve of the piece lies where x · A[:, c] >= 0 for every column c and
    homogeneous point x (lower and upper side of each band, as `_bands` pads them). The chord of a
    closed or tiny piece is replaced as in `_bands`.
    """
    points = h[..., :2] / h[..., 2:]
    start = points[..., 0, :]
    chord = points[..., -1, :] - start
    length = np.hypot(chord[..., 0], chord[..., 1])
    short = length <= pad
    if np.count_nonzero(short):
        offsets = points - start[..., None, :]
        distances = np.hypot(offsets[..., 0], offsets[..., 1])
        far = np.take_along_axis(offsets, distances.argmax(axis=-1)[..., None, None], axis=-2)[..., 0, :]
        far = np.where((distances.max(axis=-1) > pad)[..., None], far, [1.0, 0.0])
        chord = np.where(short[..., None], far, chord)
        length = np.hypot(chord[..., 0], chord[..., 1])
    lines = 2 if perpendicular else 1
    turn = _NORMAL_AND_CHORD if perpendicular else _NORMAL
    normals = ((chord / length[..., None]) @ turn).reshape(*length.shape, 2, lines)
    values = points @ normals  # (..., n+1, L): a x + b y of every control point
    low = np.minimum.reduce(values, axis=-2)
    high = np.maximum.reduce(values, axis=-2)
    sides = np.empty(length.shape + (3, 2 * lines))
    sides[..., :2, :lines] = normals
    np.negative(normals, out=sides[..., :2, lines:])
    np.subtract(pad, low, out=sides[..., 2, :lines])  # a x + b y - (low - pad) >= 0
    np.add(high, pad, out=sides[..., 2, lines:])  # (high + pad) - (a x + b y) >= 0
    return sides, high[..., 0] - low[..., 0]


def _batch_kept(s: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Local ranges (lo, hi) where every explicit curve (i/n, s[..., i, c]) may be >= 0; NaN or lo > hi if none.

    s: (..., n+1, B), one column per one-sided condition. Each range is `_hull_band(s, 0, inf)`
    computed for all pieces and conditions at once (crossings of all point pairs with s = 0, an end
    point that satisfies its condition is in), then the B ranges are intersected (the hull meets a
    band exactly where it meets both of its half-planes: the hull's vertical sections are segments).
    """
    gather, t_first, t_step = _batch_tables(n)[3:]
    count = len(t_first)
    g = gather @ s
    r = g[..., :count, :] / g[..., count:, :]  # where segment i j crosses s = 0, as a fraction of it
    crossing = np.where((r >= 0) & (r <= 1), t_first + t_step * r, np.nan)  # NaN: the segment does not cross
    lo = np.where(s[..., 0, :] >= 0, 0.0, np.fmin.reduce(crossing, axis=-2))  # fmin, fmax skip NaN
    hi = np.where(s[..., -1, :] >= 0, 1.0, np.fmax.reduce(crossing, axis=-2))
    return np.maximum.reduce(lo, axis=-1), np.minimum.reduce(hi, axis=-1)  # NaN (nothing kept) stays NaN


def _batched_search(hp, hq, tol, max_steps, perpendicular=True, overlap_check=None, scale=None) -> np.ndarray:
    """The boxes (k, 5) = (t_lo, t_hi, u_lo, u_hi, tangent) found by clipping all live pairs of pieces at once.

    tangent is 1.0 for the box of a stalled pair of pieces that are tiny and flat to rounding (a tangency),
    0.0 for a pair narrowed below tol.
    """
    folded, n, curves = _batch_curves(hp, hq)
    scale = _scale(hp[:, :2] / hp[:, 2:], hq[:, :2] / hq[:, 2:]) if scale is None else scale
    pad = PAD * scale
    lo, hi = np.zeros((2, 1)), np.ones((2, 1))
    boxes, steps, checked = [], 0, overlap_check is None
    with np.errstate(divide="ignore", invalid="ignore"):  # crossings of segments parallel to s = 0
        while lo.shape[1]:
            steps += lo.shape[1]
            if not checked and steps >= OVERLAP_CHECK_AFTER:
                checked = True
                overlap_check()
            if steps > max_steps:
                raise _clipping.GaveUp(max_steps, float(lo[0, 0]), float(lo[1, 0]))
            width = hi - lo
            narrow = width <= tol
            if np.count_nonzero(narrow):
                done = narrow[0] & narrow[1]
                if np.count_nonzero(done):
                    boxes.append(np.concatenate([lo[:, done], hi[:, done], np.zeros((1, np.count_nonzero(done)))]))
                    live = ~done
                    lo, hi, width, narrow = lo[:, live], hi[:, live], width[:, live], narrow[:, live]
                    if not lo.shape[1]:
                        break
            pieces = _batch_pieces(lo, hi, folded, n) if steps > 1 else curves[:, None]  # first: the whole curves
            sides = _batch_fat_lines(pieces, pad, perpendicular)[0]
            a, b = _batch_kept(pieces @ sides[::-1], n)  # each curve against the other's fat lines
            if np.count_nonzero(narrow):  # a converged piece is kept while the other one still needs clipping
                frozen = narrow & ~narrow[::-1]
                a, b = np.where(frozen, 0.0, a), np.where(frozen, 1.0, b)
            kept = a <= b
            alive = kept[0] & kept[1]
            a = np.maximum(a - SLACK, 0.0)
            b = np.minimum(b + SLACK, 1.0)
            new_lo = lo + width * a
            new_hi = hi - width * (1.0 - b)  # exactly hi when nothing is clipped at that end
            if np.count_nonzero(alive) < alive.size:
                new_lo, new_hi, width = new_lo[:, alive], new_hi[:, alive], width[:, alive]
            lo, hi = new_lo, new_hi
            wide = hi - lo > STALL * width
            stalled = wide[0] & wide[1]
            if np.count_nonzero(stalled):
                lo, hi = _batch_split(lo, hi, stalled, folded, n, scale, pad, boxes)
    if not boxes:
        return np.zeros((0, 5))
    found = np.concatenate(boxes, axis=1)  # rows t_lo, u_lo, t_hi, u_hi, tangent
    return found[[0, 2, 1, 3, 4]].T


def _batch_split(lo, hi, stalled, folded, n, scale, pad, boxes):
    """Stalled pairs: a found box if both pieces are tiny and flat to rounding (a tangency), else halve the longer."""
    rows = np.flatnonzero(stalled)
    pieces = _batch_pieces(lo[:, rows], hi[:, rows], folded, n)
    points = pieces[..., :2] / pieces[..., 2:]
    tiny = np.all(np.ptp(points, axis=-2).max(axis=-1) <= TINY * scale, axis=0)
    found = np.zeros(len(rows), dtype=bool)
    if np.count_nonzero(tiny):
        width = _batch_fat_lines(pieces[:, tiny], pad, False)[1] + 2 * pad  # the padded band, as `_bands`
        found[np.flatnonzero(tiny)[np.all(width <= THIN * pad, axis=0)]] = True
    if np.count_nonzero(found):
        boxes.append(np.concatenate([lo[:, rows[found]], hi[:, rows[found]], np.ones((1, np.count_nonzero(found)))]))
    split = rows[~found]
    longer = (hi[1, split] - lo[1, split] > hi[0, split] - lo[0, split]).astype(int)  # ties split P
    columns = np.arange(len(split))
    middle = (lo[longer, split] + hi[longer, split]) / 2
    first_hi, second_lo = hi[:, split], lo[:, split]  # copies (fancy indexing)
    first_hi[longer, columns] = middle
    second_lo[longer, columns] = middle
    keep = ~stalled
    return (np.concatenate([lo[:, keep], lo[:, split], second_lo], axis=1),
            np.concatenate([hi[:, keep], first_hi, hi[:, split]], axis=1))


def _raise_if_overlapping(hp: np.ndarray, hq: np.ndarray, samples: int = 201, coarse: int = 401) -> None:
    """ValueError if a run of P's sample points covering 1 % of [0, 1] lies on Q (within 1e-9 of the picture).

    Each of P's `samples` points is matched with the nearest of `coarse` points of Q, then moved to its
    nearest point on Q by Newton's method on (Q(u) - X) · Q'(u) = 0, all points at once.
    """
    values = bernstein_horner(hp, np.linspace(0.0, 1.0, samples))
    values = values[:, :2] / values[:, 2:]
    us = np.linspace(0.0, 1.0, coarse)
    dense = bernstein_horner(hq, us)
    dense = dense[:, :2] / dense[:, 2:]
    scale = _scale(dense, values)
    u = us[np.argmin(((values[:, None, :] - dense[None, :, :]) ** 2).sum(axis=2), axis=1)]
    first = hodograph(hq)
    second = hodograph(first)
    for _ in range(4):
        h, dh, ddh = (bernstein_horner(c, u) for c in (hq, first, second))
        w, dw, ddw = h[:, 2:], dh[:, 2:], ddh[:, 2:]
        point = h[:, :2] / w
        tangent = (dh[:, :2] - dw * point) / w
        curvature = (ddh[:, :2] - 2 * dw * tangent - ddw * point) / w
        gap = point - values
        slope = np.einsum("ij,ij->i", tangent, tangent) + np.einsum("ij,ij->i", gap, curvature)
        step = np.einsum("ij,ij->i", gap, tangent) / np.where(slope > 0, slope, np.inf)
        u = np.clip(u - step, 0.0, 1.0)
    foot = bernstein_horner(hq, u)
    near = np.hypot(*(foot[:, :2] / foot[:, 2:] - values).T) <= 1e-9 * scale
    run = longest = 0
    for flag in near:
        run = run + 1 if flag else 0
        longest = max(longest, run)
    if longest >= 3:
        raise ValueError("p, q: the curves overlap (they share a piece), so their intersections are not isolated")


def _merge_boxes(boxes, tol, p, q, p_weights, q_weights) -> np.ndarray:
    """One (t, u) per group of found boxes that touch (within tol), sorted; end parameters snapped when exact."""
    if not len(boxes):
        return np.zeros((0, 2))
    b = np.array(boxes, dtype=float)
    near_t = (b[:, None, 0] <= b[None, :, 1] + tol) & (b[None, :, 0] <= b[:, None, 1] + tol)
    near_u = (b[:, None, 2] <= b[None, :, 3] + tol) & (b[None, :, 2] <= b[:, None, 3] + tol)
    groups = _components(near_t & near_u)
    found = []
    for members in groups:
        t = (b[members, 0].min() + b[members, 1].max()) / 2
        u = (b[members, 2].min() + b[members, 3].max()) / 2
        found.append(_snap(t, u, tol, p, q, p_weights, q_weights))
    found = np.array(found)
    return found[np.lexsort((found[:, 1], found[:, 0]))]


def _components(adjacent: np.ndarray) -> list[np.ndarray]:
    """Connected components of a symmetric boolean adjacency matrix, as sorted index arrays."""
    unseen = np.ones(len(adjacent), dtype=bool)
    groups = []
    for start in range(len(adjacent)):
        if not unseen[start]:
            continue
        unseen[start] = False
        group, frontier = [start], [start]
        while frontier:
            node = frontier.pop()
            fresh = np.flatnonzero(adjacent[node] & unseen)
            unseen[fresh] = False
            group += fresh.tolist()
            frontier += fresh.tolist()
        groups.append(np.sort(group))
    return groups


def _snap(t, u, tol, p, q, p_weights, q_weights) -> tuple[float, float]:
    """Move t and u to an end of [0, 1] within tol if the curves meet there at least as closely."""
    candidates = [(t, u)]
    ends_t = [e for e in (0.0, 1.0) if abs(t - e) <= tol]
    ends_u = [e for e in (0.0, 1.0) if abs(u - e) <= tol]
    candidates += [(et, u) for et in ends_t] + [(t, eu) for eu in ends_u] + [(et, eu) for et in ends_t for eu in ends_u]
    if len(candidates) == 1:
        return float(t), float(u)
    ts, us = np.array(candidates).T
    gaps = np.hypot(*(evaluate(p, ts, p_weights) - evaluate(q, us, q_weights)).T)
    # The closest pair wins; on a tie the one with more end parameters (listed later).
    best = min(range(len(candidates)), key=lambda k: (gaps[k], -k))
    return float(candidates[best][0]), float(candidates[best][1])

"""Bilinear, birational and projective maps of planar quadrilaterals, and their inverses: chapter 21 of the notes.

A planar quad with corners P_ij (i along s, j along t) is the bilinear patch
P(s, t) = P00 s̄t̄ + P10 s t̄ + P01 s̄ t + P11 s t (s̄ = 1 - s, t̄ = 1 - t): a
tensor-product Bézier patch of degree (1, 1) (`quad_map`, evaluated by
`cagd_ref.surfaces.patch_point`). Unless the quad is a trapezoid, a point has
two pre-images in the (s, t)-plane, the roots of a quadratic
(`bilinear_inverse`).

Give the corners weights w_ij and the map becomes rational (eq. 21.2), with the
homogeneous corners Q̃_ij = w_ij (x_ij, y_ij, 1). Its s-iso-lines Is(s) join
the points Cs(s) (on t = 0) and Bs(s) (on t = 1); they form a *pencil*, all
through one point, exactly when the weights satisfy one equation (21.6),

    w00 w11 C10 C01 = w10 w01 C00 C11,

with C_ij twice the signed area of the triangle at corner (i, j) in the cycle
Q00 -> Q10 -> Q11 -> Q01 (`corner_determinants`). The vertex of that pencil is
the axis As, where the edges s = 0 and s = 1 meet; the t-iso-lines then form
the pencil through At, where t = 0 and t = 1 meet (`pencil_axes`). One
condition serves both families, so three weights are free and the fourth
follows (`birational_weight`). Each point lies on one line of each pencil, so
s and t are ratios of linear functions of x and y (21.8)-(21.11): the map is
birational (`birational_inverse`). All the points of the line As At share one
parameter pair, the map's base point (21.12) (`base_point`). The weights
(21.13) proportional to the triangle determinants of the *other three* corners
make the map projective, a homography of the plane (`projective_weights`,
`homography`); they satisfy (21.6) too.

A quad is a float array (2, 2, 2): quad[i, j] is the corner at s = i, t = j
(the same layout as a patch's control net). Weights are (2, 2) in the same
layout. Homogeneous points and lines are triples (X, Y, W) and (a, b, c), as in
`cagd_ref.geometry`: join and meet are cross products.

Ref: T. W. Sederberg and J. Zheng, Birational quadrilateral maps, Computer Aided Geometric Design 32, 2015, 1-4.
Ref: G. Wolberg, Digital Image Warping, IEEE Computer Society Press, 1990 (the bilinear and the projective maps).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._validation import as_float_array, as_parameter, as_points, as_scalar
from .geometry import join, meet

__all__ = [
    "quad_map",
    "homogeneous_quad",
    "bilinear_inverse",
    "corner_determinants",
    "pencil_axes",
    "isoparameter_lines",
    "weight_condition",
    "is_birational",
    "birational_weight",
    "birational_inverse",
    "BasePoint",
    "base_point",
    "projective_weights",
    "homography",
    "square_preimages",
    "warp_image",
]

# Relative size (to the quad's scale) below which two corners coincide, an area vanishes or edges are parallel.
FLAT = 1e-12
# Relative residual of (21.6) up to which weights count as birational.
BIRATIONAL_TOL = 1e-9
# How far outside [0, 1] a pre-image may fall (rounding) and still count as a point of the quad.
SQUARE_TOL = 1e-9
# Below this fraction of the quad's scale the homogeneous weight W of a point counts as zero: it is at infinity.
AT_INFINITY = 1e-12
# The corners in the cyclic order Q00 -> Q10 -> Q11 -> Q01 of the quad's boundary.
CYCLE = ((0, 0), (1, 0), (1, 1), (0, 1))


# --- input checking -----------------------------------------------------------------------------


def _scale(quad: np.ndarray) -> float:
    """The size of the quad: the diagonal of its bounding box."""
    corners = quad.reshape(4, 2)
    return float(np.linalg.norm(corners.max(axis=0) - corners.min(axis=0)))


def _corner_dets(quad: np.ndarray) -> np.ndarray:
    """C[i, j] = |Q_prev Q_ij Q_next| around the cycle Q00 -> Q10 -> Q11 -> Q01 (twice a signed area), (2, 2)."""
    c = np.empty((2, 2))
    for k, (i, j) in enumerate(CYCLE):
        prev, nxt = quad[CYCLE[k - 1]], quad[CYCLE[(k + 1) % 4]]
        a, b = prev - quad[i, j], nxt - quad[i, j]
        c[i, j] = b[0] * a[1] - b[1] * a[0]
    return c


def _checked_quad(quad) -> np.ndarray:
    """The quad as a float array (2, 2, 2) with four distinct corners, not all on one line."""
    q = as_float_array(quad, "quad")
    if q.shape != (2, 2, 2):
        raise ValueError(f"quad: expected shape (2, 2, 2), quad[i, j] the corner (x, y) at s = i, t = j, got {q.shape}")
    scale = _scale(q)
    corners = q.reshape(4, 2)
    gaps = np.linalg.norm(corners[:, None] - corners[None, :], axis=2) + np.eye(4) * (scale + 1.0)
    if scale == 0 or gaps.min() <= FLAT * scale:
        a, b = np.unravel_index(int(np.argmin(gaps)), gaps.shape)
        names = [f"Q{i}{j}" for i in (0, 1) for j in (0, 1)]
        raise ValueError(f"quad: corners {names[a]} and {names[b]} coincide, expected four distinct corners")
    if np.abs(_corner_dets(q)).max() <= FLAT * scale**2:
        raise ValueError("quad: the four corners lie on one line, so the quad encloses no area")
    return q


def _checked_weights(weights, name: str = "weights") -> np.ndarray:
    w = as_float_array(weights, name)
    if w.shape != (2, 2):
        raise ValueError(f"{name}: expected shape (2, 2), weights[i, j] for the corner at s = i, t = j, got {w.shape}")
    if not np.any(w):
        raise ValueError(f"{name}: expected at least one nonzero weight, got {w.tolist()}")
    return w


def _points(points, name: str = "points") -> tuple[np.ndarray, bool]:
    """Planar points (k, 2), and whether a single point (2,) came in."""
    p = as_float_array(points, name)
    if p.shape == (2,):
        return p[None, :], True
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError(f"{name}: expected a point (2,) or points (k, 2), got shape {p.shape}")
    return p, False


# --- the map ---------------------------------------------------------------------------------------


def _homogeneous(quad: np.ndarray, weights: np.ndarray | None) -> np.ndarray:
    """The homogeneous corners Q̃_ij = w_ij (x_ij, y_ij, 1), (2, 2, 3)."""
    h = np.concatenate([quad, np.ones((2, 2, 1))], axis=2)
    return h if weights is None else h * weights[:, :, None]


def homogeneous_quad(quad, weights=None) -> np.ndarray:
    """The homogeneous corners Q̃_ij = w_ij (x_ij, y_ij, 1) of a weighted quad, shape (2, 2, 3). Notes §21.1.

    quad: (2, 2, 2); weights: None (all ones) or (2, 2).

    >>> from cagd_ref.quad_maps import homogeneous_quad
    >>> homogeneous_quad([[(0, 0), (8, 6)], [(12, 0), (12, 4)]], [[1, 5 / 3], [1, 1]])[0, 1].round(6).tolist()
    [13.333333, 10.0, 1.666667]
    """
    q = _checked_quad(quad)
    return _homogeneous(q, None if weights is None else _checked_weights(weights))


def quad_map(quad, s, t, weights=None) -> np.ndarray:
    """The bilinear (or, with weights, rational bilinear) map of a quad at (s, t). Notes §21 (21.1), §21.1 (21.2).

    P(s, t) = P00 s̄t̄ + P10 s t̄ + P01 s̄ t + P11 s t, the degree-(1, 1)
    tensor-product Bézier patch of `cagd_ref.surfaces.patch_point`; with
    weights, the point of Q̃00 s̄t̄ + Q̃10 s t̄ + Q̃01 s̄ t + Q̃11 s t.
    quad: (2, 2, 2), quad[i, j] the corner at s = i, t = j; weights: None or
    (2, 2) (zeros allowed: the collinear case of §21.2 has w11 = 0). s, t:
    numbers -> (2,), or 1-D arrays that broadcast together (k pairs) -> (k, 2);
    any real values. A ValueError where a weighted map sends (s, t) to infinity.

    >>> from cagd_ref.quad_maps import quad_map
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]          # Figure 21.1: P00, P01 / P10, P11
    >>> quad_map(quad, 1 / 3, 3 / 4).round(12).tolist(), quad_map(quad, 2, 2).tolist()   # two pre-images of E
    ([8.0, 4.0], [8.0, 4.0])
    >>> quad_map(quad, 0.4, 2 / 3, [[1, 5 / 3], [1, 1]]).round(12).tolist()           # birational, w01 = 5/3
    [8.0, 4.0]
    """
    from .surfaces import patch_point

    q = _checked_quad(quad)
    as_parameter(s, "s")
    as_parameter(t, "t")
    if weights is None:
        return patch_point(q, s, t)
    h = patch_point(_homogeneous(q, _checked_weights(weights)), s, t)
    return _projected(h, q, "s, t")


def _projected(h: np.ndarray, quad: np.ndarray, name: str) -> np.ndarray:
    """Cartesian points of homogeneous ones (3,) or (k, 3), refusing those at infinity (W = 0 to rounding)."""
    rows = np.atleast_2d(h)
    reach = np.abs(quad).max() + _scale(quad)
    far = np.abs(rows[:, 2]) * reach <= AT_INFINITY * np.abs(rows[:, :2]).max(axis=1)
    far |= ~np.any(rows, axis=1)
    if np.any(far):
        raise ValueError(f"{name}: the weighted map sends {int(far.sum())} parameter pair(s) to infinity (W = 0)")
    points = rows[:, :2] / rows[:, 2:]
    return points[0] if h.ndim == 1 else points


# --- the bilinear inverse -------------------------------------------------------------------------


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The planar cross product a × b = a_x b_y - a_y b_x, row by row."""
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _quadratic_roots(a: float, b: np.ndarray, c: np.ndarray, size: float) -> tuple[np.ndarray, np.ndarray]:
    """The real roots of a u² + b u + c = 0 for k right-hand sides: (roots (k, 2), count (k,)), NaN-padded.

    `size` is the scale of b and c: a linear equation with b = c = 0 to
    rounding has every u as a root (count -1). Roots come without cancellation:
    q = -(b + sign(b) √D) / 2 gives u = q / a and u = c / q.
    """
    k = len(b)
    roots = np.full((k, 2), np.nan)
    count = np.zeros(k, dtype=int)
    if a == 0.0:
        linear = np.abs(b) > FLAT * size
        roots[linear, 0] = -c[linear] / b[linear]
        count[linear] = 1
        count[~linear & (np.abs(c) <= FLAT * size)] = -1
        return roots, count
    disc = b * b - 4 * a * c
    # A discriminant that vanishes to rounding is a double root: a point on the fold of the map.
    double = np.abs(disc) <= 1e-14 * (b * b + np.abs(4 * a * c))
    two = (disc > 0) & ~double
    root = np.sqrt(np.where(two, disc, 0.0))
    q = -0.5 * (b + np.where(b >= 0, root, -root))
    roots[double, 0] = -b[double] / (2 * a)
    count[double] = 1
    with np.errstate(divide="ignore", invalid="ignore"):
        pair = np.column_stack([q / a, np.where(q != 0, c / q, 0.0)])
    roots[two] = np.sort(pair[two], axis=1)
    count[two] = 2
    return roots, count


def _solve_for_first(h, e, f, g, size) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pre-images of h = e u + (f + g u) v for the first parameter u: (u (k, 2), v (k, 2), count (k,)).

    Crossing with f + g u removes v: (e×g) u² + (e×f - h×g) u - h×f = 0; then
    v is the coordinate of h - e u along f + g u.
    """
    a = float(_cross(e, g))
    if abs(a) <= FLAT * np.linalg.norm(e) * np.linalg.norm(g):
        a = 0.0  # the edges v = 0 and v = 1 are parallel: the equation is linear
    u, count = _quadratic_roots(a, _cross(e, f) - _cross(h, g), -_cross(h, f), size)
    direction = f[None, None, :] + g[None, None, :] * u[:, :, None]
    rest = h[:, None, :] - e[None, None, :] * u[:, :, None]
    with np.errstate(invalid="ignore", divide="ignore"):
        v = np.einsum("kri,kri->kr", rest, direction) / np.einsum("kri,kri->kr", direction, direction)
    return u, v, count


def _bilinear_roots(quad: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """All real pre-images of k points: pairs (k, 2, 2) sorted by s, NaN-padded; count (k,), -1: infinitely many."""
    p00, p10, p01, p11 = quad[0, 0], quad[1, 0], quad[0, 1], quad[1, 1]
    e, f, g = p10 - p00, p01 - p00, p00 - p10 - p01 + p11
    if np.linalg.norm(g) <= FLAT * (np.linalg.norm(e) + np.linalg.norm(f)):
        g = np.zeros(2)  # a parallelogram, up to rounding: the map is affine
    h = points - p00
    size = _scale(quad) ** 2 + np.abs(h).max(initial=0.0) ** 2
    # Solve for the parameter whose opposite edges are closer to parallel: its equation is (nearly) linear, and
    # the other parameter then never meets an iso-line that collapses to a point.
    sin_s = abs(_cross(e, g)) / max(np.linalg.norm(e) * np.linalg.norm(g), 1e-300)
    sin_t = abs(_cross(f, g)) / max(np.linalg.norm(f) * np.linalg.norm(g), 1e-300)
    if sin_s <= sin_t:
        s, t, count = _solve_for_first(h, e, f, g, size)
    else:
        t, s, count = _solve_for_first(h, f, e, g, size)
    pairs = np.stack([s, t], axis=2)
    order = np.lexsort((pairs[:, :, 1], pairs[:, :, 0]), axis=1)
    return np.take_along_axis(pairs, order[:, :, None], axis=1), count


def bilinear_inverse(quad, point) -> np.ndarray:
    """Every real pre-image (s, t) of a point under the bilinear map of a quad: (k, 2), k in {0, 1, 2}. Notes §21.

    With e = P10 - P00, f = P01 - P00, g = P00 - P10 - P01 + P11, h = X - P00
    and a × b = a_x b_y - a_y b_x, the equation h = e s + (f + g s) t crossed
    with f + g s gives (e × g) s² + (e × f - h × g) s - h × f = 0, whose roots
    come from a quadratic formula without cancellation; t then follows from s.
    The parameters are not restricted to [0, 1]. Two pre-images for a general
    quad (or none, or one double one on the fold), one for a trapezoid (its
    equation is linear). quad: (2, 2, 2); point: (2,). Rows sorted by s (then
    t). A ValueError for a point with infinitely many pre-images (the vertex
    of a trapezoid's pencil of lines).

    The notes' example, Figure 21.1: E = (8, 4) has the pre-images (1/3, 3/4) and (2, 2).

    >>> from cagd_ref.quad_maps import bilinear_inverse
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]
    >>> bilinear_inverse(quad, (8, 4)).round(12).tolist()
    [[0.333333333333, 0.75], [2.0, 2.0]]
    >>> bilinear_inverse([[(0, 0), (0, 1)], [(2, 0), (1, 1)]], (1, 0.5)).round(12).tolist()   # a trapezoid: one
    [[0.666666666667, 0.5]]
    """
    q = _checked_quad(quad)
    p, scalar = _points(point, "point")
    if not scalar:
        raise ValueError(f"point: expected one point of shape (2,), got shape {p.shape}")
    pairs, count = _bilinear_roots(q, p)
    if count[0] < 0:
        raise ValueError(f"point: {p[0].tolist()} has infinitely many pre-images (every line of the pencil meets it)")
    return pairs[0, : count[0]].copy()


# --- birational quads ------------------------------------------------------------------------------


def corner_determinants(quad) -> np.ndarray:
    """C[i, j] = |Q_prev Q_ij Q_next|: twice the signed area of the triangle at each corner, (2, 2). Notes §21.1.

    Around the cycle Q00 -> Q10 -> Q11 -> Q01: C00 = |Q01 Q00 Q10|, C10 =
    |Q00 Q10 Q11|, C11 = |Q10 Q11 Q01|, C01 = |Q11 Q01 Q00| (each a 3 × 3
    determinant of homogeneous points). All positive for a convex quad listed
    counterclockwise, one negative at a concave corner, zero where three
    corners are collinear. quad: (2, 2, 2).

    >>> from cagd_ref.quad_maps import corner_determinants
    >>> corner_determinants([[(0, 0), (8, 6)], [(12, 0), (12, 4)]]).tolist()   # [[C00, C01], [C10, C11]]
    [[72.0, 40.0], [48.0, 16.0]]
    """
    return _corner_dets(_checked_quad(quad))


def _unit(v: np.ndarray) -> np.ndarray:
    """A homogeneous triple scaled to length 1, with W >= 0 (or, at infinity, its first nonzero entry > 0)."""
    v = v / np.linalg.norm(v)
    lead = v[2] if abs(v[2]) > 1e-14 else v[np.flatnonzero(np.abs(v) > 1e-14)[0]]
    return (-v if lead < 0 else v) + 0.0  # no negative zeros


def _axes(quad: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    h = _homogeneous(quad, None)
    a_s = meet(join(h[0, 0], h[0, 1]), join(h[1, 0], h[1, 1]))
    a_t = meet(join(h[0, 0], h[1, 0]), join(h[0, 1], h[1, 1]))
    return _unit(a_s), _unit(a_t)


def pencil_axes(quad) -> tuple[np.ndarray, np.ndarray]:
    """The axes (As, At) of the two pencils, homogeneous (3,) each. Notes §21.1.

    As = (Q00 × Q01) × (Q10 × Q11), where the edges s = 0 and s = 1 meet,
    and At = (Q00 × Q10) × (Q01 × Q11), where the edges t = 0 and t = 1
    meet. Parallel edges meet at infinity (W = 0): both axes of a
    parallelogram are. Each triple is scaled to unit length with W >= 0 (at
    infinity: its first nonzero entry positive). quad: (2, 2, 2).

    Figure 21.1's quad: As = (12, 9) and At = (20, 0).

    >>> from cagd_ref.quad_maps import pencil_axes
    >>> a_s, a_t = pencil_axes([[(0, 0), (8, 6)], [(12, 0), (12, 4)]])
    >>> (a_s[:2] / a_s[2]).round(12).tolist(), (a_t[:2] / a_t[2] + 0.0).round(12).tolist()
    ([12.0, 9.0], [20.0, 0.0])
    """
    return _axes(_checked_quad(quad))


def _edge_points(h: np.ndarray, s: np.ndarray | None, t: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """The ends of the iso-lines: (Cs(s), Bs(s)) on t = 0 and t = 1, or (Ct(t), Bt(t)) on s = 0 and s = 1, (k, 3)."""
    if s is not None:
        u = s[:, None]
        return h[0, 0] * (1 - u) + h[1, 0] * u, h[0, 1] * (1 - u) + h[1, 1] * u
    u = t[:, None]
    return h[0, 0] * (1 - u) + h[0, 1] * u, h[1, 0] * (1 - u) + h[1, 1] * u


def isoparameter_lines(quad, s=None, t=None, weights=None) -> np.ndarray:
    """The homogeneous lines Is(s) = Cs(s) × Bs(s) (or It(t) = Ct(t) × Bt(t)) of the map, (3,) or (k, 3). Notes §21.1.

    Cs(s) = Q̃00 s̄ + Q̃10 s and Bs(s) = Q̃01 s̄ + Q̃11 s lie on the edges t = 0
    and t = 1; Ct(t) = Q̃00 t̄ + Q̃01 t and Bt(t) = Q̃10 t̄ + Q̃11 t on s = 0 and
    s = 1. Give exactly one of s and t (a number -> (3,), k values -> (k, 3)).
    quad: (2, 2, 2); weights: None or (2, 2). A line of a pencil through As
    (or At) when the weights are birational; a zero triple where both ends
    coincide.

    >>> from cagd_ref.quad_maps import isoparameter_lines
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]
    >>> line = isoparameter_lines(quad, t=0.75)
    >>> float(line @ [8, 4, 1])                       # E = (8, 4) lies on the line t = 3/4
    0.0
    """
    q = _checked_quad(quad)
    w = None if weights is None else _checked_weights(weights)
    if (s is None) == (t is None):
        raise TypeError("s, t: give exactly one of s and t")
    u, scalar = as_parameter(s if s is not None else t, "s" if s is not None else "t")
    start, end = _edge_points(_homogeneous(q, w), u if s is not None else None, u if t is not None else None)
    lines = np.cross(start, end)
    return lines[0] if scalar else lines


def _condition_terms(quad: np.ndarray, w: np.ndarray) -> tuple[float, float, float]:
    """The two sides of (21.6), w00 w11 C10 C01 and w10 w01 C00 C11, and the size below which they are zero."""
    c = _corner_dets(quad)
    left = w[0, 0] * w[1, 1] * c[1, 0] * c[0, 1]
    right = w[1, 0] * w[0, 1] * c[0, 0] * c[1, 1]
    return float(left), float(right), FLAT * np.abs(w).max() ** 2 * _scale(quad) ** 4


def weight_condition(quad, weights) -> float:
    """The relative residual (L - R) / (|L| + |R|) of (21.6), L = w00 w11 C10 C01, R = w10 w01 C00 C11. Notes §21.1.

    Zero exactly when the weights make the map birational (both families of
    iso-lines pencils); a number in [-1, 1] otherwise, 0 also when both sides
    vanish. quad: (2, 2, 2); weights: (2, 2).

    >>> from cagd_ref.quad_maps import weight_condition
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]
    >>> round(weight_condition(quad, [[1, 5 / 3], [1, 1]]), 12), weight_condition(quad, [[1, 1], [1, 1]])
    (0.0, 0.25)
    """
    left, right, zero = _condition_terms(_checked_quad(quad), _checked_weights(weights))
    total = abs(left) + abs(right)
    return 0.0 if total <= zero else (left - right) / total


def is_birational(quad, weights, tol: float = BIRATIONAL_TOL) -> bool:
    """Whether the weights satisfy (21.6) to within the relative residual `tol`. Notes §21.1.

    >>> from cagd_ref.quad_maps import is_birational
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]
    >>> is_birational(quad, [[1, 5 / 3], [1, 1]]), is_birational(quad, [[1, 1], [1, 1]])
    (True, False)
    """
    return abs(weight_condition(quad, weights)) <= as_scalar(tol, "tol")


def birational_weight(quad, weights) -> float:
    """The weight w11 of corner (1, 1) that makes the map birational, given w00, w10, w01. Notes §21.1 (21.6).

    From w00 w11 C10 C01 = w10 w01 C00 C11 (`corner_determinants`):
    w11 = w10 w01 C00 C11 / (w00 C10 C01). Positive for a convex quad with
    positive weights, negative when corner (1, 1) or (0, 0) is concave, zero
    when Q10, Q11, Q01 are collinear. quad: (2, 2, 2); weights: (2, 2)
    finite numbers, weights[1, 1] ignored. A ValueError when w00, w10 or w01
    is zero, or when no w11 can satisfy (21.6): C10 C01 = 0, that is Q00,
    Q10, Q11 or Q11, Q01, Q00 collinear.

    The notes' numbers: Figure 21.4a's concave quad needs w11 = -4.2.

    >>> from cagd_ref.quad_maps import birational_weight
    >>> round(birational_weight([[(0, 0), (8, 6)], [(12, 0), (6, 2)]], [[1, 1], [1, 1]]), 12)
    -4.2
    >>> round(birational_weight([[(0, 0), (8, 6)], [(12, 0), (12, 4)]], [[1, 1], [1, 0]]), 12)   # w01 = 1: w11 = 3/5
    0.6
    """
    q = _checked_quad(quad)
    w = _checked_weights(weights)
    given = [w[0, 0], w[1, 0], w[0, 1]]
    if not np.all(given):
        raise ValueError(f"weights: w00, w10 and w01 must be nonzero (a zero weight sends a corner to infinity), "
                         f"got {[float(v) for v in given]}")
    c = _corner_dets(q)
    denominator = w[0, 0] * c[1, 0] * c[0, 1]
    if abs(c[1, 0] * c[0, 1]) <= FLAT * _scale(q) ** 4:
        which = "Q00, Q10, Q11" if abs(c[1, 0]) <= abs(c[0, 1]) else "Q11, Q01, Q00"
        raise ValueError(f"quad: {which} are collinear (C10 C01 = 0), so (21.6) does not involve w11 and no "
                         "weight of corner (1, 1) makes the map birational")
    return float(w[1, 0] * w[0, 1] * c[0, 0] * c[1, 1] / denominator)


def _pencil_pair(axis: np.ndarray, first: np.ndarray, second: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """The lines axis × first and axis × second of a pencil, and how far from zero the smaller one is (relative)."""
    l0, l1 = np.cross(axis, first), np.cross(axis, second)
    reach = max(np.linalg.norm(first), np.linalg.norm(second))
    return l0, l1, min(np.linalg.norm(l0), np.linalg.norm(l1)) / max(reach, 1e-300)


def _inverse_lines(quad: np.ndarray, w: np.ndarray) -> tuple[tuple[np.ndarray, np.ndarray], tuple[np.ndarray, ...]]:
    """The lines (L0, L1) with s = L0·P / (L0 - L1)·P and (M0, M1) with t = M0·P / (M0 - M1)·P (21.8)-(21.11).

    Each parameter has two forms; the one whose two lines are both clearly
    nonzero is used, since in the collinear case As = Q01 makes (21.8) 0/0.
    """
    h = _homogeneous(quad, w)
    a_s, a_t = _axes(quad)
    s_forms = [_pencil_pair(a_s, h[0, 1], h[1, 1]), _pencil_pair(a_s, h[0, 0], h[1, 0])]  # (21.8), (21.9)
    t_forms = [_pencil_pair(a_t, h[1, 0], h[1, 1]), _pencil_pair(a_t, h[0, 0], h[0, 1])]  # (21.10), (21.11)
    best_s = max(s_forms, key=lambda form: form[2])
    best_t = max(t_forms, key=lambda form: form[2])
    return best_s[:2], best_t[:2]


def _ratios(lines: tuple[np.ndarray, np.ndarray], homogeneous: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Numerators L0·P, denominators (L0 - L1)·P, and the size below which they are zero, (k,) each."""
    l0, l1 = lines
    num, den = homogeneous @ l0, homogeneous @ (l0 - l1)
    zero = FLAT * (np.linalg.norm(l0) + np.linalg.norm(l1)) * np.linalg.norm(homogeneous, axis=1)
    return num, den, zero


def _birational_kernel(quad: np.ndarray, w: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(s, t) of k points by (21.8)-(21.11), (k, 2), and which rows are undefined or infinite (k,)."""
    s_lines, t_lines = _inverse_lines(quad, w)
    hp = np.column_stack([points, np.ones(len(points))])
    result, bad = np.empty((len(points), 2)), np.zeros(len(points), dtype=bool)
    for k, lines in enumerate((s_lines, t_lines)):
        num, den, zero = _ratios(lines, hp)
        bad |= np.abs(den) <= zero
        with np.errstate(divide="ignore", invalid="ignore"):
            result[:, k] = num / den
    return result, bad


def _birational_weights(quad: np.ndarray, weights) -> np.ndarray:
    w = _checked_weights(weights)
    left, right, zero = _condition_terms(quad, w)
    if abs(left - right) > BIRATIONAL_TOL * (abs(left) + abs(right)) + zero:
        raise ValueError(
            f"weights: {w.tolist()} do not make the map birational: (21.6) needs w00 w11 C10 C01 = w10 w01 C00 C11, "
            f"here {left:.6g} and {right:.6g} (birational_weight gives the w11 that does)"
        )
    return w


def birational_inverse(quad, weights, points) -> np.ndarray:
    """The pre-images (s, t) of points under a birational quad map, by its linear pencils (21.8)-(21.11). Notes §21.2.

    With the axes As, At (`pencil_axes`) and P = (x, y, 1),
    s = |As Q̃01 P| / (|As Q̃01 P| - |As Q̃11 P|) (21.8), or the same with Q̃00,
    Q̃10 (21.9); t = |At Q̃10 P| / (|At Q̃10 P| - |At Q̃11 P|) (21.10), or with
    Q̃00, Q̃01 (21.11). Both forms agree when no three corners are collinear;
    otherwise one is 0/0 and the other is used. quad: (2, 2, 2); weights:
    (2, 2) satisfying (21.6) (else a ValueError); points: (2,) -> (2,), (k, 2)
    -> (k, 2). Parameters are not restricted to [0, 1]. A ValueError for a
    point whose pre-image is undefined (As or At itself) or at infinity.

    The notes' example, Figure 21.2: with w01 = 5/3, E = (8, 4) has the one pre-image (2/5, 2/3).

    >>> from cagd_ref.quad_maps import birational_inverse
    >>> quad, weights = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]], [[1, 5 / 3], [1, 1]]
    >>> birational_inverse(quad, weights, (8, 4)).round(12).tolist()
    [0.4, 0.666666666667]
    """
    q = _checked_quad(quad)
    w = _birational_weights(q, weights)
    p, scalar = _points(points)
    result, bad = _birational_kernel(q, w, p)
    if np.any(bad):
        rows = np.flatnonzero(bad)
        raise ValueError(
            f"points: row(s) {rows[:5].tolist()} lie on an iso-line at infinity or on an axis of a pencil, where the "
            "pre-image is at infinity or undefined"
        )
    return result[0] if scalar else result


class BasePoint(NamedTuple):
    """The map's base point (s*, t*), and the singular line As At (homogeneous) that it is blown up into."""

    s: float
    t: float
    line: np.ndarray


def base_point(quad, weights) -> BasePoint:
    """The parameters (s*, t*) shared by every point of the line As At, where Q̃(s*, t*) = 0. Notes §21.3 (21.12).

    The two pencils share the line As × At: by (21.8)-(21.11) all its points
    have s* = the s of At and t* = the t of As. There the homogeneous map
    vanishes, so that one parameter pair is blown up into the whole line;
    the parameter line t = t* collapses to As, s = s* to At. quad: (2, 2, 2);
    weights: (2, 2) satisfying (21.6). A ValueError when a parameter of the
    base point is at infinity (parallel opposite edges, or an axis on an iso-line at infinity).

    >>> from cagd_ref.quad_maps import base_point
    >>> point = base_point([[(0, 0), (8, 6)], [(12, 0), (12, 4)]], [[1, 5 / 3], [1, 1]])
    >>> round(point.s, 12), round(point.t, 12), (point.line / point.line[0] * 9).round(12).tolist()
    (1.666666666667, 2.25, [9.0, 8.0, -180.0])
    """
    q = _checked_quad(quad)
    w = _birational_weights(q, weights)
    s_lines, t_lines = _inverse_lines(q, w)
    a_s, a_t = _axes(q)
    values = []
    for lines, axis, name in ((s_lines, a_t, "s"), (t_lines, a_s, "t")):
        num, den, zero = _ratios(lines, axis[None, :])
        if abs(den[0]) <= zero[0]:
            raise ValueError(f"quad: the base point's {name} is at infinity (its axis lies on an iso-line at infinity)")
        values.append(float(num[0] / den[0]))
    return BasePoint(values[0], values[1], np.cross(a_s, a_t))


# --- projective maps ---------------------------------------------------------------------------------


def _projective(quad: np.ndarray) -> np.ndarray:
    c = _corner_dets(quad)
    if np.abs(c).min() <= FLAT * _scale(quad) ** 2:
        raise ValueError("quad: three corners are collinear, so no projective map takes the square onto the quad")
    # Each corner's weight is the determinant of the other three corners: that of the opposite corner.
    w = np.array([[c[1, 1], c[1, 0]], [c[0, 1], c[0, 0]]])
    return w / w[0, 0]


def projective_weights(quad) -> np.ndarray:
    """The weights (21.13) that make the quad map projective, (2, 2), normalised to w00 = 1. Notes §21.4.

    Each corner is weighted by the signed determinant of the other three, up
    to one common factor: w00 by |Q10 Q01 Q11|, w10 by |Q00 Q01 Q11|, w01 by
    |Q00 Q11 Q10| and w11 by |Q00 Q01 Q10| (up to a common sign, the corner
    determinant of the opposite corner). Then
    Q̃00 - Q̃10 - Q̃01 + Q̃11 = 0, the st term of the map vanishes and
    Q(s, t) = Point(Q̃00 + (Q̃10 - Q̃00) s + (Q̃01 - Q̃00) t): a homography
    (the notes call it affine; it is affine only for a parallelogram). These
    weights satisfy (21.6). quad: (2, 2, 2); a ValueError when three corners
    are collinear (no projective map exists).

    Figure 21.1's quad: 16 : 40 : 48 : 72 = 2 : 5 : 6 : 9.

    >>> from cagd_ref.quad_maps import projective_weights
    >>> (projective_weights([[(0, 0), (8, 6)], [(12, 0), (12, 4)]]) * 2).round(12).tolist()
    [[2.0, 6.0], [5.0, 9.0]]
    """
    return _projective(_checked_quad(quad))


def homography(quad) -> np.ndarray:
    """The 3 × 3 matrix H of the projective map of a quad: H (s, t, 1) is the homogeneous point Q(s, t). Notes §21.4.

    Its columns are Q̃10 - Q̃00, Q̃01 - Q̃00 and Q̃00 for the weights of
    `projective_weights`; it sends the corners of the unit square to those of
    the quad. quad: (2, 2, 2), no three corners collinear.

    >>> from cagd_ref.quad_maps import homography
    >>> H = homography([[(0, 0), (8, 6)], [(12, 0), (12, 4)]])
    >>> x = H @ [1, 1, 1]
    >>> (x[:2] / x[2]).round(12).tolist()
    [12.0, 4.0]
    """
    q = _checked_quad(quad)
    h = _homogeneous(q, _projective(q))
    return np.column_stack([h[1, 0] - h[0, 0], h[0, 1] - h[0, 0], h[0, 0]])


# --- inverse maps on the unit square, and image warping ------------------------------------------------


def _in_square(params: np.ndarray) -> np.ndarray:
    return np.all((params >= -SQUARE_TOL) & (params <= 1 + SQUARE_TOL), axis=-1)


def square_preimages(quad, points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """The pre-images in the unit square [0, 1]² of k points: (params (k, 2), inside (k,) bool). Notes §21.5.

    Without weights the bilinear map is inverted (`bilinear_inverse`, the
    root in the square; the smaller s where a non-convex quad folds two
    into it); with weights, which must be birational, the rational linear
    inverse (`birational_inverse`). Rows of points with no pre-image in the
    square have inside False and params NaN. quad: (2, 2, 2); points (k, 2).

    >>> from cagd_ref.quad_maps import square_preimages
    >>> quad = [[(0, 0), (8, 6)], [(12, 0), (12, 4)]]
    >>> params, inside = square_preimages(quad, [(8, 4), (20, 20)])
    >>> params[0].round(12).tolist(), inside.tolist()
    ([0.333333333333, 0.75], [True, False])
    """
    q = _checked_quad(quad)
    p = as_points(points, "points")
    if p.shape[1] != 2:
        raise ValueError(f"points: expected planar points (k, 2), got shape {p.shape}")
    if weights is None:
        pairs, count = _bilinear_roots(q, p)
        ok = _in_square(pairs) & (count[:, None] > 0)
        first = np.argmax(ok, axis=1)
        params = pairs[np.arange(len(p)), first]
        inside = ok.any(axis=1)
    else:
        params, bad = _birational_kernel(q, _birational_weights(q, weights), p)
        inside = ~bad & _in_square(params)
    params = np.where(inside[:, None], np.clip(params, 0.0, 1.0), np.nan)
    return params, inside


def _raster_size(size) -> tuple[int, int]:
    shape = as_float_array(size, "size")
    if shape.shape != (2,) or np.any(shape < 1) or np.any(shape != np.round(shape)):
        raise ValueError(f"size: expected (rows, cols), two positive integers, got {np.ravel(shape).tolist()}")
    return int(shape[0]), int(shape[1])


def warp_image(image, quad, window, size, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """An image on the unit square drawn onto a quad by inverse mapping: (raster, covered). Notes §21.5.

    image: (rows, cols) or (rows, cols, channels); its column index runs with
    s and its row index with t (row 0 at t = 0). window: ((xmin, ymin),
    (xmax, ymax)), the part of the plane to draw; size: (rows, cols) of the
    raster. Each raster pixel's centre is sent back to (s, t) by
    `square_preimages` (bilinear without weights, birational with them) and
    takes the colour of the image's pixel there (nearest pixel). Rows of the
    raster run upwards in y, as the image's do in t. Pixels without a
    pre-image in the square keep 0 and are False in `covered`.

    >>> import numpy as np
    >>> from cagd_ref.quad_maps import warp_image
    >>> image = np.arange(4.0).reshape(2, 2)                              # 2 × 2 pixels
    >>> raster, covered = warp_image(image, [[(0, 0), (0, 1)], [(1, 0), (1, 1)]], ((0, 0), (1, 1)), (2, 2))
    >>> raster.tolist(), bool(covered.all())                             # the unit square: the image itself
    ([[0.0, 1.0], [2.0, 3.0]], True)
    """
    picture = as_float_array(image, "image")
    if picture.ndim not in (2, 3) or min(picture.shape[:2]) < 1:
        raise ValueError(f"image: expected shape (rows, cols) or (rows, cols, channels), got {picture.shape}")
    box = as_float_array(window, "window")
    if box.shape != (2, 2) or not np.all(box[1] > box[0]):
        raise ValueError(f"window: expected ((xmin, ymin), (xmax, ymax)), xmin < xmax and ymin < ymax, got {box.shape}")
    rows, cols = _raster_size(size)
    ys = box[0, 1] + (np.arange(rows) + 0.5) * (box[1, 1] - box[0, 1]) / rows
    xs = box[0, 0] + (np.arange(cols) + 0.5) * (box[1, 0] - box[0, 0]) / cols
    grid = np.stack(np.meshgrid(xs, ys), axis=-1).reshape(-1, 2)
    params, inside = square_preimages(quad, grid, weights)
    raster = np.zeros((rows * cols,) + picture.shape[2:])
    height, width = picture.shape[:2]
    col = np.minimum((params[inside, 0] * width).astype(int), width - 1)
    row = np.minimum((params[inside, 1] * height).astype(int), height - 1)
    raster[inside] = picture[row, col]
    return raster.reshape((rows, cols) + picture.shape[2:]), inside.reshape(rows, cols)

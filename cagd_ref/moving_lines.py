"""Moving lines: pencils, conics from two pencils, double points and compact implicit equations (chapter 18).

A homogeneous point is a triple (X, Y, W) and a line a triple (a, b, c), the
line a x + b y + c w = 0; a point lies on a line when their dot product is
zero, the line through two points and the point on two lines are cross
products (`cagd_ref.geometry.join`, `meet`). Read the same triple as a line or
as a point and you have the duality the chapter is built on.

A **moving line** L(t) is a family of lines whose coefficients are
polynomials in t. As a Bézier moving line it is an array (k+1, 3) of control
lines, L(t) = Σ B_i^k(t) L_i, evaluated by de Casteljau like any curve. The
matrices of §18.4 write their rows in the notes' *unscaled* basis
(1-t)^(d-j) t^j instead (`bezout_moving_lines`, `two_moving_lines`);
`unscaled_to_bernstein` converts. A moving line **follows** a rational curve
P(t) when L(t)·P(t) ≡ 0: every line of the family passes through the point of
the curve with the same parameter (`incidence` gives the Bernstein coefficients
of L·P, all zero for a moving line that follows).

Curves are planar control points (n+1, 2) with optional nonzero weights (n+1,),
homogenised to rows w_i (x_i, y_i, 1). Moving lines, homogeneous points and
implicit equations are all defined up to one common nonzero factor; the
implicit equations returned here use the layout of chapter 17
(`cagd_ref.algebra.implicitize`): c[i, j] is the coefficient of x^i y^j,
shape (n+1, n+1), scaled so that its largest coefficient is 1.

The functions named `*_plain` are the teaching forms the chapter shows: the
formulas as they stand, with no input checks; tests prove that they agree with
the checked, tuned functions the rest of the course calls.

Ref: T. W. Sederberg, T. Saito, D. Qi and K. S. Klimaszewski, Curve implicitization using moving lines,
CAGD 11(6), 1994, 687-706; D. A. Cox, T. W. Sederberg and F. Chen, The moving line ideal basis of planar
rational curves, CAGD 15(8), 1998, 803-827 (the mu-basis).
"""

from __future__ import annotations

from itertools import combinations
from math import comb

import numpy as np

from ._validation import as_count, as_float_array, as_line, as_points, as_scalar, as_vector, as_weights
from .bezier import de_casteljau, to_homogeneous
from .polynomials import bernstein_multiply, bernstein_to_power

__all__ = [
    "moving_line_eval",
    "incidence",
    "product_moving_line",
    "product_moving_line_plain",
    "pencil_parameter_line",
    "conic_from_pencils",
    "pencils_implicit",
    "quadratic_pencils",
    "nomogram_parameter",
    "axial_moving_line",
    "bezout_moving_lines",
    "bezout_moving_lines_plain",
    "unscaled_to_bernstein",
    "eliminate_leading",
    "cubic_pencil",
    "cubic_double_point",
    "cubic_double_point_plain",
    "double_point_parameters",
    "moving_lines_of_degree",
    "two_moving_lines",
    "mu_basis_coefficients",
    "axial_condition",
    "axial_combinations",
    "quartic_double_points",
    "moving_lines_implicit",
    "moving_line_implicit",
    "tangent_moving_line",
    "tangent_moving_line_plain",
    "envelope",
    "scaled_hodograph",
]

# Singular values below this fraction of the largest count as zero (rank decisions on lines of unit size).
RANK_TOL = 1e-9
# A triple smaller than this fraction of the triples it was made from is the zero triple.
ZERO_TRIPLE = 1e-10


# --- input checking -----------------------------------------------------------------------------------------


def _homogeneous(points, weights, min_count: int = 2) -> np.ndarray:
    """Planar control points (n+1, 2) and optional nonzero weights -> homogeneous rows w (x, y, 1), (n+1, 3)."""
    pts = as_points(points, min_count=min_count)
    if pts.shape[1] != 2:
        raise ValueError(f"points: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    if pts.shape[0] < min_count:
        raise ValueError(f"points: expected at least {min_count} control points, got {pts.shape[0]}")
    if weights is None:
        return np.column_stack([pts, np.ones(len(pts))])
    return to_homogeneous(pts, as_weights(weights, len(pts)))


def _triples(value, name: str) -> np.ndarray:
    """Control triples (k+1, 3) of a moving point or line, not all zero."""
    array = as_float_array(value, name)
    if array.ndim != 2 or array.shape[1] != 3 or array.shape[0] == 0:
        raise ValueError(f"{name}: expected control triples of shape (k+1, 3), got shape {array.shape}")
    if not np.any(array):
        raise ValueError(f"{name}: every triple is (0, 0, 0), which is no point and no line")
    return array


def _is_zero(triple: np.ndarray, *sources: np.ndarray) -> bool:
    scale = np.prod([np.linalg.norm(s) for s in sources]) if sources else 1.0
    return bool(np.linalg.norm(triple) <= ZERO_TRIPLE * scale)


def _binomials(n: int) -> np.ndarray:
    return np.array([comb(n, i) for i in range(n + 1)], dtype=float)


# --- moving lines as Bézier curves of triples ---------------------------------------------------------------


def moving_line_eval(lines, t) -> np.ndarray:
    """The line(s) L(t) = Σ B_i^k(t) L_i of a Bézier moving line, by de Casteljau on the triples. Notes §18.3.

    lines: control lines (k+1, 3). t: a number -> (3,), k values -> (k, 3).
    De Casteljau works on lines as on points (18.39)-(18.40): it only takes
    affine combinations of the triples.

    >>> moving_line_eval([(0.0, 3.0, 0.0), (3.0, 3.0, -9.0)], 0.5).tolist()    # the pencil of the notes' cubic
    [1.5, 3.0, -4.5]
    """
    lines = _triples(lines, "lines")
    return de_casteljau(lines, t)


def incidence(lines, points, weights=None) -> np.ndarray:
    """Bernstein coefficients (k+n+1,) of L(t)·P(t), all zero when L follows the curve. Notes §18.2 (18.14).

    lines: Bernstein control lines (k+1, 3); points (n+1, 2), weights None or
    (n+1,) nonzero. L(t)·P(t) is a polynomial of degree k+n: a sum of three
    Bernstein products (`polynomials.bernstein_multiply`), one per coordinate.

    >>> incidence([(0.0, 3.0, 0.0), (3.0, 3.0, -9.0)], [(0, 0), (0, 1), (1, 2), (3, 0)]).round(12).tolist()
    [0.0, 0.0, 0.0, 0.0, 0.0]
    """
    lines = _triples(lines, "lines")
    h = _homogeneous(points, weights)
    return sum(bernstein_multiply(lines[:, c], h[:, c]) for c in range(3))


def _product(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) P_i × Q_j, (m+n+1, 3): the control triples of P(t) × Q(t)."""
    m, n = len(p) - 1, len(q) - 1
    crosses = np.cross((p * _binomials(m)[:, None])[:, None, :], (q * _binomials(n)[:, None])[None, :, :])
    out = np.zeros((m + n + 1, 3))
    for i in range(m + 1):
        out[i : i + n + 1] += crosses[i]
    return out / _binomials(m + n)[:, None] + 0.0


def product_moving_line(p, q) -> np.ndarray:
    """Control triples (m+n+1, 3) of P(t) × Q(t): the moving line through two moving points. Notes §18.3.2 (18.44).

    p: control triples (m+1, 3) of a Bézier moving point (or line), q: (n+1, 3).
    L_k = (1/C(m+n,k)) Σ_{i+j=k} C(m,i) C(n,j) P_i × Q_j, so that
    L(t) = Σ B_k^(m+n)(t) L_k = P(t) × Q(t) for every t. By duality the same
    formula gives the moving point where two moving lines meet (18.49). The
    degree-one P and quadratic Q of (18.47):

    >>> product_moving_line([(0, 0, 1), (1, 0, 1)], [(0, 1, 1), (1, 1, 1), (2, 0, 1)]).round(6).tolist()
    [[-1.0, 0.0, 0.0], [-1.0, 0.333333, 0.333333], [-0.666667, 0.666667, 0.666667], [0.0, 1.0, 0.0]]

    (L_1 = (2 P_0 × Q_1 + P_1 × Q_0)/3, L_2 = (P_0 × Q_2 + 2 P_1 × Q_1)/3.)
    """
    return _product(_triples(p, "p"), _triples(q, "q"))


def product_moving_line_plain(p, q) -> np.ndarray:
    """The product formula (18.44) as it stands: the teaching form of `product_moving_line`. Notes §18.3.2.

    p: control triples (m+1, 3), q: (n+1, 3), finite numbers (only that is
    checked; `product_moving_line` checks the shapes too). Each product
    B_i^m(t) B_j^n(t) is C(m,i) C(n,j)/C(m+n,i+j) B_(i+j)^(m+n)(t), so the
    cross product P_i × Q_j, weighted by C(m,i) C(n,j), lands in control line
    i+j, which is divided by C(m+n, i+j) at the end.

    >>> product_moving_line_plain([(0, 0, 1), (1, 0, 1)], [(0, 1, 1), (1, 1, 1), (2, 0, 1)]).round(6).tolist()
    [[-1.0, 0.0, 0.0], [-1.0, 0.333333, 0.333333], [-0.666667, 0.666667, 0.666667], [0.0, 1.0, 0.0]]
    """
    p, q = as_float_array(p, "p"), as_float_array(q, "q")
    m, n = len(p) - 1, len(q) - 1
    lines = np.zeros((m + n + 1, 3))
    for i in range(m + 1):
        for j in range(n + 1):
            lines[i + j] += comb(m, i) * comb(n, j) * np.cross(p[i], q[j])
    for k in range(m + n + 1):
        lines[k] /= comb(m + n, k)
    return lines


# --- pencils and conics (§18.2) -----------------------------------------------------------------------------


def pencil_parameter_line(l0, l1, d0=1.0) -> np.ndarray:
    """The parameter line (P0, P1), (2, 2), of the pencil L(t) = (1-t) L0 + t L1. Notes §18.2 (18.18)-(18.20).

    l0, l1: lines (3,) meeting in a finite axis A. P0 lies on L0 at distance
    d0 > 0 from A, P1 on L1 at d1 = d0 √(a1² + b1²)/√(a0² + b0²) (18.19), both
    on the side given by turning the line's normal (a, b) a quarter turn
    counterclockwise. Then L(t) passes through (1-t) P0 + t P1 for every t:
    even marks on the segment P0 P1 are the pencil's parameters.

    >>> pencil_parameter_line([0.0, 1.0, 0.0], [-1.0, 1.0, 0.0], 1.0).round(6).tolist()   # y = 0 and y = x
    [[-1.0, 0.0], [-1.0, -1.0]]
    """
    l0, l1 = as_line(l0, "l0"), as_line(l1, "l1")
    d0 = as_scalar(d0, "d0")
    if d0 <= 0:
        raise ValueError(f"d0: expected a positive distance, got {d0}")
    axis = np.cross(l0, l1)
    if _is_zero(axis, l0, l1):
        raise ValueError("l0, l1: the two lines are the same line, which makes no pencil")
    if abs(axis[2]) <= ZERO_TRIPLE * np.linalg.norm(axis):
        raise ValueError("l0, l1: the lines are parallel; the pencil's axis is at infinity and has no parameter line")
    a = axis[:2] / axis[2]
    n0, n1 = np.hypot(*l0[:2]), np.hypot(*l1[:2])
    if n0 == 0 or n1 == 0:
        raise ValueError("l0, l1: the line at infinity (0, 0, c) has no direction")
    u0 = np.array([-l0[1], l0[0]]) / n0
    u1 = np.array([-l1[1], l1[0]]) / n1
    return np.array([a + d0 * u0, a + d0 * n1 / n0 * u1])


def conic_from_pencils(l00, l01, l10, l11) -> np.ndarray:
    """Homogeneous control points (3, 3) of the conic where the pencils L0(t), L1(t) meet. Notes §18.2 (18.25)-(18.27).

    Pencil 0 is L0(t) = (1-t) l00 + t l01, pencil 1 is L1(t) = (1-t) l10 + t l11
    (lines (3,)). Their meet L0(t) × L1(t) is the rational quadratic with
    P0 = l00 × l10, P1 = (l00 × l11 + l01 × l10)/2 and P2 = l01 × l11, rows
    (X, Y, W): its weights are the W's. A ValueError when a pencil is a single
    line (l00 ∥ l01) or both pencils have the same axis (they meet in a point).
    A pencil turning from x = 0 to y = 0 about (0, 0) and one turning from y = 0
    to x = 1 about (1, 0) meet on the circle x² + y² = x; the middle control
    point lies at infinity (W = 0), as in the classic half circle:

    >>> conic_from_pencils([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]).tolist()
    [[0.0, 0.0, 1.0], [0.0, -0.5, 0.0], [1.0, 0.0, 1.0]]
    """
    l00, l01, l10, l11 = (as_line(v, name) for v, name in ((l00, "l00"), (l01, "l01"), (l10, "l10"), (l11, "l11")))
    first, second = np.cross(l00, l01), np.cross(l10, l11)
    if _is_zero(first, l00, l01):
        raise ValueError("l00, l01: the first pencil is a single line (l00 and l01 are the same line)")
    if _is_zero(second, l10, l11):
        raise ValueError("l10, l11: the second pencil is a single line (l10 and l11 are the same line)")
    if _is_zero(np.cross(first, second), first, second):
        raise ValueError("l00, l01, l10, l11: both pencils turn about the same axis, so they meet in a point")
    return _product(np.array([l00, l01]), np.array([l10, l11]))


def _line_poly(line: np.ndarray, size: int) -> np.ndarray:
    """The linear form a x + b y + c as a coefficient array c[i, j] of x^i y^j, (size, size)."""
    out = np.zeros((size, size))
    out[0, 0], out[1, 0], out[0, 1] = line[2], line[0], line[1]
    return out


def _poly_mul(f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """The product of two bivariate coefficient arrays of one shape, truncated to that shape."""
    size = f.shape[0]
    out = np.zeros_like(f)
    for i, j in zip(*np.nonzero(f)):
        out[i:, j:] += f[i, j] * g[: size - i, : size - j]
    return out


def _normalised(c: np.ndarray) -> np.ndarray:
    """c divided by its largest coefficient (the first of those within rounding of the largest magnitude)."""
    magnitude = np.abs(c)
    top = magnitude.max()
    if top == 0:
        raise ValueError("points: the implicit equation vanishes identically")
    first = np.flatnonzero(magnitude.ravel() >= top * (1 - 1e-9))[0]
    return c / c.ravel()[first] + 0.0


def pencils_implicit(l00, l01, l10, l11) -> np.ndarray:
    """The implicit equation ℓ00 ℓ11 - ℓ01 ℓ10 = 0 of the conic of two pencils, c[i, j], (3, 3). Notes §18.2 (18.31).

    ℓij = aij x + bij y + cij: a point is on the conic when the two lines of one
    parameter t through it exist, that is when the 2×2 system (18.30) in
    (1-t, t) has a solution. Scaled so that the largest coefficient is 1.

    >>> pencils_implicit([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]).tolist()
    [[0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    conic_from_pencils(l00, l01, l10, l11)  # the same checks
    forms = [_line_poly(as_vector(v, "l", dim=3), 3) for v in (l00, l01, l10, l11)]
    return _normalised(_poly_mul(forms[0], forms[3]) - _poly_mul(forms[1], forms[2]))


def quadratic_pencils(points, weights=None) -> np.ndarray:
    """The two pencils (2, 2, 3) through P0 and P2 whose meet is a rational quadratic. Notes §18.2.2 (18.35).

    P(0) × P(t) and P(1) × P(t) vanish at t = 0 and t = 1: divided by t and by
    1-t they are the pencils L0(t) = P0 × (2P1 (1-t) + P2 t) and
    L1(t) = P2 × (P0 (1-t) + 2P1 t), returned as Bernstein control lines
    [[L0(0), L0(1)], [L1(0), L1(1)]] (homogeneous P_i = w_i (x_i, y_i, 1)).

    >>> quadratic_pencils([(0, 0), (1, 1), (2, 0)]).tolist()
    [[[-2.0, 2.0, 0.0], [0.0, 2.0, 0.0]], [[0.0, -2.0, 0.0], [-2.0, -2.0, 4.0]]]
    """
    h = _homogeneous(points, weights)
    if len(h) != 3:
        raise ValueError(f"points: expected the 3 control points of a quadratic, got {len(h)}")
    p0, p1, p2 = h
    return np.array([[np.cross(p0, 2 * p1), np.cross(p0, p2)], [np.cross(p2, p0), np.cross(p2, 2 * p1)]]) + 0.0


def nomogram_parameter(points, point, weights=None) -> float:
    """The parameter t of a point of a rational quadratic, read off a parameter line. Notes §18.2.2 (18.36)-(18.37).

    The line P0 Pp through the curve point Pp (2,) meets the parameter line of
    the pencil through P0, which runs from Pa = P0 + (2 w1/w2)(P1 - P0) (t = 0)
    to P2 (t = 1), at Pq; then t = |Pa Pq| / |Pa P2| (signed along Pa P2).

    >>> round(nomogram_parameter([(0, 0), (1, 1), (2, 0)], (1.5, 0.375)), 12)     # P(3/4) of the parabola
    0.75
    """
    h = _homogeneous(points, weights)
    if len(h) != 3:
        raise ValueError(f"points: expected the 3 control points of a quadratic, got {len(h)}")
    pp = as_vector(point, "point", dim=2)
    w = h[:, 2]
    p0, p1, p2 = h[:, :2] / w[:, None]
    pa = p0 + 2 * w[1] / w[2] * (p1 - p0)
    if np.allclose(pp, p0):
        raise ValueError("point: P0 itself lies on every line through P0; its parameter cannot be read this way")
    pq = np.cross(np.cross([*p0, 1.0], [*pp, 1.0]), np.cross([*pa, 1.0], [*p2, 1.0]))
    if abs(pq[2]) <= ZERO_TRIPLE * np.linalg.norm(pq):
        raise ValueError("point: the line from P0 through it is parallel to the parameter line")
    along = p2 - pa
    return float((pq[:2] / pq[2] - pa) @ along / (along @ along))


def axial_moving_line(axis, points, weights=None) -> np.ndarray:
    """The moving line PA × P(t) through a fixed axis PA (3,) and the curve, (n+1, 3). Notes §18.4.1 (18.53).

    Its control lines PA × P_i all pass through the axis. When the axis is a
    point of the curve, PA = P(τ), the moving line vanishes at t = τ (a base
    point) and its degree drops to n-1 after dividing by (t - τ).

    >>> axial_moving_line([0.0, 0.0, 1.0], [(1, 0), (1, 1)]).tolist()
    [[0.0, 1.0, 0.0], [-1.0, 1.0, 0.0]]
    """
    axis = as_line(axis, "axis")
    return np.cross(axis, _homogeneous(points, weights)) + 0.0


# --- the Bézout matrix of moving lines (§18.4) --------------------------------------------------------------


def _bezout(h: np.ndarray) -> np.ndarray:
    """L_ij = Σ_{l <= min(i,j), l+m = i+j+1, m <= n} C(n,l) C(n,m) P_l × P_m, (n, n, 3)."""
    n = len(h) - 1
    scaled = h * _binomials(n)[:, None]
    out = np.zeros((n, n, 3))
    for i in range(n):
        for j in range(n):
            for low in range(min(i, j) + 1):
                high = i + j + 1 - low
                if high <= n:
                    out[i, j] += np.cross(scaled[low], scaled[high])
    return out + 0.0


def bezout_moving_lines(points, weights=None) -> np.ndarray:
    """The n×n matrix of lines (n, n, 3): its rows are moving lines following the curve. Notes §18.4.2 (18.58), (18.62).

    L_ij = Σ C(n,l) C(n,m) P_l × P_m over l <= min(i, j), l + m = i + j + 1,
    m <= n, with homogeneous P_i = w_i (x_i, y_i, 1). Row i, read in the
    unscaled basis (1-t)^(n-1), (1-t)^(n-2) t, ..., t^(n-1), is a moving line
    L_i(t) with L_i(t)·P(t) ≡ 0, because P(τ) × P(t) / (t - τ) =
    Σ_ij L_ij (1-τ)^(n-1-i) τ^i (1-t)^(n-1-j) t^j. The matrix is symmetric; its
    determinant at (x, y, 1) is the implicit equation (Bézout's resultant).
    The notes' cubic (18.62):

    >>> bezout_moving_lines([(0, 0), (0, 1), (1, 2), (3, 0)]).tolist()
    ... # doctest: +NORMALIZE_WHITESPACE
    [[[-3.0, 0.0, 0.0], [-6.0, 3.0, 0.0], [0.0, 3.0, 0.0]],
     [[-6.0, 3.0, 0.0], [-9.0, 12.0, -9.0], [3.0, 9.0, -9.0]],
     [[0.0, 3.0, 0.0], [3.0, 9.0, -9.0], [6.0, 6.0, -18.0]]]
    """
    return _bezout(_homogeneous(points, weights))


def bezout_moving_lines_plain(points, weights=None) -> np.ndarray:
    """The matrix (18.58) as it stands: the teaching form of `bezout_moving_lines`. Notes §18.4.2.

    points: (n+1, 2), weights None or (n+1,) (checked by `to_homogeneous`). Entry (i, j)
    sums C(n,k) C(n,l) P_k × P_l over k <= min(i, j) with l = i+j+1-k <= n,
    the smaller index first in each cross product.

    >>> bezout_moving_lines_plain([(0, 0), (1, 2), (3, 0)], [1, 2, 1]).tolist()
    [[[-8.0, 4.0, 0.0], [0.0, 3.0, 0.0]], [[0.0, 3.0, 0.0], [8.0, 8.0, -24.0]]]
    """
    weights = np.ones(len(points)) if weights is None else weights
    h = to_homogeneous(points, weights)  # rows w_i (x_i, y_i, 1)
    n = len(h) - 1
    lines = np.zeros((n, n, 3))
    for i in range(n):
        for j in range(n):
            for k in range(min(i, j) + 1):
                other = i + j + 1 - k
                if other <= n:
                    lines[i, j] += comb(n, k) * comb(n, other) * np.cross(h[k], h[other])
    return lines


def unscaled_to_bernstein(rows) -> np.ndarray:
    """Rows in the unscaled basis (1-t)^(d-j) t^j -> Bernstein control lines: entry j divided by C(d, j). Notes §18.4.

    rows: (d+1, 3) for one moving line or (r, d+1, 3) for r of them; same shape back.

    >>> unscaled_to_bernstein([(0, 2, 0), (4, 4, -8), (4, -2, -8)]).tolist()      # La of (18.69)
    [[0.0, 2.0, 0.0], [2.0, 2.0, -4.0], [4.0, -2.0, -8.0]]
    """
    array = as_float_array(rows, "rows")
    if array.ndim not in (2, 3) or array.shape[-1] != 3 or array.shape[-2] == 0:
        raise ValueError(f"rows: expected (d+1, 3) or (r, d+1, 3) triples, got shape {array.shape}")
    return array / _binomials(array.shape[-2] - 1)[:, None]


def _eliminate(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Row combinations of moving lines (k, d+1, 3) that zero the leading column: (pivots, reduced).

    Every leading line passes through P0, so the leading column has rank r <= 2
    and k - r combinations annihilate it. Their leading entries are dropped (a
    factor t divided out); the reduced rows are scaled to unit size.
    """
    u, s, _ = np.linalg.svd(rows[:, 0, :])
    rank = int(np.sum(s > RANK_TOL * max(s[0], np.finfo(float).tiny))) if s.size else 0
    pivots = np.tensordot(u[:, :rank].T, rows, axes=1)
    reduced = np.tensordot(u[:, rank:].T, rows, axes=1)[:, 1:]
    sizes = np.linalg.norm(reduced.reshape(len(reduced), -1), axis=1)
    return pivots, reduced / np.where(sizes > 0, sizes, 1.0)[:, None, None]


def eliminate_leading(rows) -> tuple[np.ndarray, np.ndarray]:
    """One round of the notes' reduction: zero the leading column and divide by t. Notes §18.4.5 (18.80)-(18.82).

    rows: moving lines (k, d+1, 3) in the unscaled basis that follow one curve,
    d >= 1. Returns (pivots (r, d+1, 3), reduced (k-r, d, 3)): r <= 2 row
    combinations that keep a leading line, and k - r whose leading line is
    zero, with that entry dropped (a factor t divided out), so moving lines of
    one degree lower that follow the curve too, each scaled to unit size.

    >>> pivots, reduced = eliminate_leading(bezout_moving_lines([(0, 0), (0, 1), (1, 2), (3, 0)]))
    >>> ((reduced[0] / reduced[0, 0, 1] * 3).round(9) + 0).tolist()    # the pencil (18.64)
    [[0.0, 3.0, 0.0], [3.0, 3.0, -9.0]]
    """
    array = as_float_array(rows, "rows")
    if array.ndim != 3 or array.shape[2] != 3 or array.shape[1] < 2 or array.shape[0] == 0:
        raise ValueError(f"rows: expected moving lines (k, d+1, 3) with d >= 1, got shape {array.shape}")
    return _eliminate(array)


def _cubic_pencil(h: np.ndarray) -> np.ndarray:
    rows = _bezout(h)
    if np.linalg.matrix_rank(rows.reshape(3, 9), tol=RANK_TOL * np.abs(rows).max()) < 3:
        raise ValueError("points: the curve is not a true cubic (a degree-raised conic or a line has no double point)")
    _, reduced = _eliminate(rows)
    if len(reduced) != 1:
        raise ValueError("points: the curve is not a true cubic (its leading lines all coincide)")
    return reduced[0]


def cubic_pencil(points, weights=None) -> np.ndarray:
    """The pencil (2, 3) that follows a rational cubic, of unit size. Notes §18.4.2 (18.63)-(18.64).

    The combination of the three rows of `bezout_moving_lines` whose leading
    line vanishes, divided by t. Its axis is the double point, and with the
    pencil the parameter of a point comes back: t = ℓ0/(ℓ0 - ℓ1) with
    ℓk = L_k·(x, y, 1).

    >>> pencil = cubic_pencil([(0, 0), (0, 1), (1, 2), (3, 0)])
    >>> ((pencil / pencil[0, 1] * 3).round(9) + 0).tolist()
    [[0.0, 3.0, 0.0], [3.0, 3.0, -9.0]]
    """
    h = _homogeneous(points, weights)
    if len(h) != 4:
        raise ValueError(f"points: expected the 4 control points of a cubic, got {len(h)}")
    return _cubic_pencil(h)


def _point_sign(p: np.ndarray) -> np.ndarray:
    """A homogeneous point of unit length, W >= 0 (or its first nonzero entry positive when W = 0)."""
    p = p / np.linalg.norm(p)
    big = np.abs(p) > ZERO_TRIPLE
    lead = 2 if big[2] else int(np.argmax(big))
    return (p if p[lead] > 0 else -p) + 0.0


def cubic_double_point(points, weights=None) -> np.ndarray:
    """The double point of a rational cubic as a homogeneous point (3,): the axis of its pencil. Notes §18.4.2 (18.66).

    points: (4, 2); weights: None or (4,) nonzero. Every rational cubic has
    one double point (a crunode, a cusp or an acnode, whose two parameters
    are then complex), possibly at infinity (W = 0), wherever its parameters
    lie. Returned with unit length and W >= 0. A ValueError for a curve that
    is not a true cubic (collinear control points, a degree-raised conic).
    The notes' cubic crosses itself at (3, 0), at t = -1 and t = 1:

    >>> p = cubic_double_point([(0, 0), (0, 1), (1, 2), (3, 0)])
    >>> ((p / p[2]).round(9) + 0).tolist()
    [3.0, 0.0, 1.0]
    """
    h = _homogeneous(points, weights)
    if len(h) != 4:
        raise ValueError(f"points: expected the 4 control points of a cubic, got {len(h)}")
    pencil = _cubic_pencil(h)
    axis = np.cross(pencil[0], pencil[1])
    if _is_zero(axis, *pencil):
        raise ValueError("points: the pencil is a fixed line, so the curve is a line, not a cubic")
    return _point_sign(axis)


def cubic_double_point_plain(points, weights=None) -> np.ndarray:
    """The double point of a rational cubic, step by step: the teaching form of `cubic_double_point`. Notes §18.4.2.

    points: (4, 2), weights None or (4,); beyond finite numbers nothing is
    checked (`cubic_double_point` rejects curves that are not true cubics),
    and the point is not scaled (any nonzero multiple is the same point). The three rows of the
    3×3 matrix (18.58) are quadratic moving lines whose leading lines all pass
    through P0; a null vector c of those three leading lines combines the rows
    into a moving line with a zero leading line, that is with a factor t.
    What is left after dropping it is a pencil, and its axis is the double point.

    >>> p = cubic_double_point_plain([(0, 0), (0, 1), (1, 2), (3, 0)])
    >>> ((p / p[2]).round(9) + 0).tolist()
    [3.0, 0.0, 1.0]
    """
    rows = bezout_moving_lines_plain(points, weights)  # three quadratic moving lines
    u, _, _ = np.linalg.svd(rows[:, 0, :])  # the leading lines, one per row
    c = u[:, -1]  # c[0] row0 + c[1] row1 + c[2] row2 has a zero leading line
    pencil = np.tensordot(c, rows, axes=1)[1:]  # drop it: the factor t is gone
    return np.cross(pencil[0], pencil[1])  # the axis of the pencil


def double_point_parameters(points, weights=None) -> np.ndarray:
    """The two parameters (2,) of the double point of a rational cubic, complex for an acnode. Notes §18.4.2.

    The axial moving line D × P(t) through the double point D vanishes at both
    parameters, so its three cubic components share a quadratic factor; its
    roots are returned, real ones as real numbers (sorted), a complex pair
    as complex numbers. Two distinct real roots: a crunode; a double root: a
    cusp; a complex pair: an acnode. Roots at infinity (the curve reaches D
    only as t -> ±∞, as y = x³ its cusp at infinity) are left out, so fewer
    than two may come back.

    >>> double_point_parameters([(0, 0), (0, 1), (1, 2), (3, 0)]).round(9).tolist()   # the notes' cubic
    [-1.0, 1.0]
    """
    h = _homogeneous(points, weights)
    if len(h) != 4:
        raise ValueError(f"points: expected the 4 control points of a cubic, got {len(h)}")
    axis = np.cross(*_cubic_pencil(h))
    components = bernstein_to_power(np.cross(axis / np.linalg.norm(axis), h / np.abs(h).max()))
    # The components are q(t) times linear factors: the roots of their main direction that all share are q's.
    _, _, vt = np.linalg.svd(components.T)
    first = vt[0]
    roots = np.roots(first[::-1][np.argmax(np.abs(first[::-1]) > 1e-12):])
    values = np.array([np.polynomial.polynomial.polyval(roots, c) for c in components.T])
    residual = np.abs(values).max(axis=0, initial=0.0) / (np.abs(components).max() * (1 + np.abs(roots)) ** 3)
    found = roots[residual <= 1e-7]
    if np.all(np.abs(found.imag) <= 1e-7 * (1 + np.abs(found))):
        return np.sort(found.real) + 0.0
    return np.sort_complex(found)


# --- two moving lines (§18.4.3-18.4.6) ----------------------------------------------------------------------


def _incidence_matrix(h: np.ndarray, degree: int) -> np.ndarray:
    """The linear map from Bernstein control lines of one degree (flattened) to the coefficients of L·P."""
    n = len(h) - 1
    out = np.zeros((n + degree + 1, 3 * (degree + 1)))
    total = _binomials(n + degree)
    for j in range(degree + 1):
        for i in range(n + 1):
            out[i + j, 3 * j : 3 * j + 3] = comb(degree, j) * comb(n, i) / total[i + j] * h[i]
    return out


def _null_space(matrix: np.ndarray) -> np.ndarray:
    """An orthonormal basis of the null space, as rows."""
    _, s, vt = np.linalg.svd(matrix)
    rank = int(np.sum(s > RANK_TOL * s[0])) if s.size and s[0] > 0 else 0
    return vt[rank:]


def _following(h: np.ndarray, degree: int) -> np.ndarray:
    scale = np.abs(h).max()
    return _null_space(_incidence_matrix(h / scale, degree)).reshape(-1, degree + 1, 3)


def moving_lines_of_degree(points, degree, weights=None) -> np.ndarray:
    """A basis (k, degree+1, 3) of the Bernstein moving lines of one degree that follow the curve (not in the notes).

    The conditions L(t)·P(t) ≡ 0 are linear in the control lines: the
    Bernstein coefficients of L·P (degree n + degree) must all vanish. The
    null space of that (n+degree+1) × 3(degree+1) system (by SVD, rows of unit
    size) is the space of such moving lines; its dimension jumps at the
    degrees μ <= ν with μ + ν = n of the curve's μ-basis. Notes §18.4 (cross-check).

    >>> moving_lines_of_degree([(0, 0), (0, 1), (1, 2), (3, 0)], 1).shape   # one pencil follows a cubic
    (1, 2, 3)

    Ref: T. W. Sederberg and F. Chen, Implicitization using moving curves and surfaces, SIGGRAPH 1995.
    """
    h = _homogeneous(points, weights)
    degree = as_count(degree, "degree")
    return _following(h, degree)


def _mu_basis(h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two moving lines (Bernstein) of degrees μ <= ν, μ + ν = n, that generate all that follow the curve."""
    n = len(h) - 1
    for mu in range(n // 2 + 1):
        found = _following(h, mu)
        if len(found) >= 2:
            return found[0], found[1]
        if len(found) == 1:
            break
    p = found[0]
    nu = n - mu
    # Multiples p(t) B_k^(ν-μ)(t) follow too; q is what the degree-ν space has beyond them.
    multiples = np.array([_scalar_times(p, np.eye(nu - mu + 1)[k]) for k in range(nu - mu + 1)])
    basis, _ = np.linalg.qr(multiples.reshape(len(multiples), -1).T)
    candidates = _following(h, nu).reshape(-1, 3 * (nu + 1))
    rest = candidates - (candidates @ basis) @ basis.T
    _, _, vt = np.linalg.svd(rest)
    return p, vt[0].reshape(nu + 1, 3)


def _scalar_times(lines: np.ndarray, coeffs: np.ndarray) -> np.ndarray:
    """The moving line s(t) L(t) for a scalar Bernstein polynomial s."""
    return np.column_stack([bernstein_multiply(lines[:, c], coeffs) for c in range(3)])


def _to_unscaled(lines: np.ndarray) -> np.ndarray:
    return lines * _binomials(len(lines) - 1)[:, None]


def _two_lines(h: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two moving lines (unscaled rows): the notes' reduction, degrees ⌈n/2⌉ and ⌊n/2⌋, or a μ-basis if μ < ⌊n/2⌋."""
    n = len(h) - 1
    if len(_following(h, n - 1)) != n:
        # A true degree-n curve has exactly n independent moving lines of degree n-1 (the Bézout rows).
        raise ValueError("points: the curve's true degree is lower than its number of control points says "
                         "(a degree-raised curve?); reduce the degree first")
    if len(_following(h, n // 2 - 1)):
        # A moving line of degree below ⌊n/2⌋ follows (a triple point, §18.4.4): the reduction's last two
        # rows would share it as a factor, so take the generators (μ-basis) instead.
        p, q = _mu_basis(h)
        return _to_unscaled(q), _to_unscaled(p)
    rows = _bezout(h)
    rows = rows / np.abs(rows).max()
    pivots = rows[:0]
    while len(rows) > 2:
        pivots, rows = _eliminate(rows)
    if len(rows) == 2:
        return rows[0], rows[1]
    # n odd: one row of degree m is left; pair it with the pivot that is least a multiple of it.
    low = rows[0]
    multiples = np.array([np.vstack([low, np.zeros(3)]), np.vstack([np.zeros(3), low])]).reshape(2, -1)
    basis, _ = np.linalg.qr(multiples.T)
    flat = pivots.reshape(len(pivots), -1)
    rest = np.linalg.norm(flat - (flat @ basis) @ basis.T, axis=1) / np.linalg.norm(flat, axis=1)
    return pivots[int(np.argmax(rest))], low


def two_moving_lines(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Two moving lines of degrees ⌈n/2⌉ and ⌊n/2⌋ that meet only on the curve. Notes §18.4.5 (18.83)-(18.84).

    points: (n+1, 2), n >= 2; weights: None or (n+1,) nonzero. The notes'
    reduction: starting from `bezout_moving_lines`, zero the leading column of
    all but two rows and divide them by t (`eliminate_leading`), and repeat on
    the reduced rows until two are left (n = 2m: two of degree m), or one of
    degree m and a pivot of degree m+1 (n = 2m+1). Rows are scaled to unit
    size, so they differ from the notes' by row operations. If the curve has a
    point of multiplicity above ⌈n/2⌉ (the triple point of a quartic, §18.4.4),
    a moving line of lower degree follows and the two returned are its
    generators (μ-basis) of degrees ν > μ, ν + μ = n, found by null spaces.
    Returns (la, lb), la of the higher degree, each (d+1, 3) in the basis
    (1-t)^(d-j) t^j.

    >>> la, lb = two_moving_lines([(0, 0), (0, 1), (1, 2), (3, 2), (2, 0)])      # the notes' quartic
    >>> la.shape, lb.shape
    ((3, 3), (3, 3))
    """
    h = _homogeneous(points, weights, min_count=3)
    return _two_lines(h)


def mu_basis_coefficients(lines, low, high) -> tuple[np.ndarray, np.ndarray]:
    """Scalar polynomials f, g with L = f·low + g·high for a moving line L that follows the curve (not in the notes).

    lines: Bernstein control lines (m+1, 3) of a moving line L that follows a
    curve; low, high: Bernstein control lines of a mu-basis of that curve, of
    degrees mu <= n - mu (for example `two_moving_lines` turned into Bernstein
    form by `unscaled_to_bernstein`). Returns the Bernstein coefficients of f
    (degree m - mu) and of g (degree m - n + mu; an empty array when m < n - mu),
    found by least squares. A ValueError when L is not such a combination (to
    within 1e-9 of its size): by the theorem of Cox, Sederberg and Chen every
    moving line that follows the curve is one, with unique f and g.

    >>> pencil = [(0.0, 3.0, 0.0), (3.0, 3.0, -9.0)]                      # (18.64), the notes' cubic
    >>> rows = unscaled_to_bernstein(bezout_moving_lines([(0, 0), (0, 1), (1, 2), (3, 0)]))   # (18.62)
    >>> f, g = mu_basis_coefficients(rows[2], pencil, rows[0])              # row 2 = (1 + t) × the pencil
    >>> (f.round(12) + 0).tolist(), (g.round(12) + 0).tolist()
    ([1.0, 2.0], [0.0])

    Ref: D. A. Cox, T. W. Sederberg and F. Chen, The moving line ideal basis of planar rational curves,
    CAGD 15(8), 1998, 803-827.
    """
    lines, low, high = _triples(lines, "lines"), _triples(low, "low"), _triples(high, "high")
    m = len(lines) - 1
    columns = []
    sizes = []
    for basis in (low, high):
        k = m - (len(basis) - 1)
        sizes.append(max(k + 1, 0))
        for j in range(k + 1):
            columns.append(_scalar_times(basis, np.eye(k + 1)[j]).ravel())
    if not columns:
        raise ValueError("lines: its degree is below both degrees of the basis, so it is no combination of them")
    matrix = np.array(columns).T
    solution, *_ = np.linalg.lstsq(matrix, lines.ravel(), rcond=None)
    if np.abs(matrix @ solution - lines.ravel()).max() > 1e-9 * max(np.abs(lines).max(), 1e-300):
        raise ValueError("lines: it is not f·low + g·high; does it follow the curve of the basis?")
    return solution[: sizes[0]] + 0.0, solution[sizes[0] :] + 0.0


def axial_condition(la, lb) -> np.ndarray:
    """Power coefficients (4,) in s of det[L_0(s), L_1(s), L_2(s)] for L(s) = (1-s) la + s lb. Notes §18.4.3 (18.72).

    la, lb: quadratic moving lines (3, 3). The combination is axial (its three
    control lines meet in one point) where this cubic vanishes; the notes
    print it divided by 16 for their quartic (and call the parameter tau).

    >>> la = [(0, 2, 0), (4, 4, -8), (4, -2, -8)]                       # (18.69), the notes' quartic
    >>> lb = [(8, 6, 0), (28, 4, -24), (20, -14, -40)]
    >>> (axial_condition(la, lb).round(6) + 0).tolist()                 # 512 s³ - 512 s² - 128 s
    [0.0, -128.0, -512.0, 512.0]
    """
    la, lb = _triples(la, "la"), _triples(lb, "lb")
    if la.shape != (3, 3) or lb.shape != (3, 3):
        raise ValueError(f"la, lb: expected two quadratic moving lines of shape (3, 3), got {la.shape} and {lb.shape}")
    return _axial_cubic(la, lb) + 0.0


def _axial_cubic(la: np.ndarray, lb: np.ndarray) -> np.ndarray:
    """Power coefficients (4,) in τ of det[LQ0, LQ1, LQ2] for LQ = (1-τ) la + τ lb."""
    taus = np.array([0.0, 1 / 3, 2 / 3, 1.0])
    values = [np.linalg.det((1 - tau) * la + tau * lb) for tau in taus]
    return np.polynomial.polynomial.polyfit(taus, values, 3)


def axial_combinations(la, lb) -> tuple[np.ndarray, np.ndarray]:
    """Axial combinations (1-τ) la + τ lb of two quadratic moving lines, with their axes. Notes §18.4.3 (18.70)-(18.73).

    la, lb: quadratic moving lines (3, 3) (unscaled or Bernstein rows: the
    condition is the same). A combination is axial when its three control
    lines are concurrent, [LQ0, LQ1, LQ2] = 0: a cubic in τ (18.72). Returns
    (taus (k,), axes (k, 3)), complex where the roots are, each axis the cross
    product of two of the control lines, of unit length. A ValueError when
    every combination is axial (the curve has a triple point). For a quartic
    the axes are its double points.

    >>> la = [(0, 2, 0), (4, 4, -8), (4, -2, -8)]                       # (18.69), the notes' quartic
    >>> lb = [(8, 6, 0), (28, 4, -24), (20, -14, -40)]
    >>> taus, axes = axial_combinations(la, lb)
    >>> (np.round(taus.real, 6) + 0).tolist()                           # 0 and (1 ± √2)/2
    [-0.207107, 0.0, 1.207107]
    """
    la, lb = _triples(la, "la"), _triples(lb, "lb")
    if la.shape != (3, 3) or lb.shape != (3, 3):
        raise ValueError(f"la, lb: expected two quadratic moving lines of shape (3, 3), got {la.shape} and {lb.shape}")
    scale = max(np.abs(la).max(), np.abs(lb).max())
    la, lb = la / scale, lb / scale
    cubic = _axial_cubic(la, lb)
    if np.abs(cubic).max() <= RANK_TOL:
        raise ValueError("la, lb: every combination is axial: both are multiples of one pencil (a triple point)")
    taus = np.roots(cubic[::-1][np.argmax(np.abs(cubic[::-1]) > RANK_TOL * np.abs(cubic).max()):])
    taus = np.sort_complex(np.where(np.abs(taus.imag) <= 1e-12, taus.real, taus))
    axes = []
    for tau in taus:
        lines = (1 - tau) * la + tau * lb
        crosses = [np.cross(lines[i], lines[j]) for i, j in ((0, 1), (0, 2), (1, 2))]
        axis = max(crosses, key=np.linalg.norm)
        axes.append(axis / np.linalg.norm(axis))
    return taus, np.array(axes)


def quartic_double_points(points, weights=None) -> np.ndarray:
    """The three double points of a rational quartic, homogeneous (3, 3), complex where they are. Notes §18.4.3 (18.73).

    The axes of the axial combinations of the quartic's two quadratic moving
    lines (`two_moving_lines`, `axial_combinations`), counted with
    multiplicity: real or a complex-conjugate pair (two double points with
    complex coordinates), finite or at infinity. Each row has unit length and
    W real and >= 0 (at infinity: its first nonzero entry). A ValueError for a
    quartic with a triple point (§18.4.4).

    >>> p = quartic_double_points([(0, 0), (0, 1), (1, 2), (3, 2), (2, 0)])
    >>> sorted((np.round((p / p[:, 2:]).real, 6) + 0).tolist())          # (1, -√2), (1, √2), (2, 0)
    [[1.0, -1.414214, 1.0], [1.0, 1.414214, 1.0], [2.0, 0.0, 1.0]]
    """
    h = _homogeneous(points, weights)
    if len(h) != 5:
        raise ValueError(f"points: expected the 5 control points of a quartic, got {len(h)}")
    la, lb = _two_lines(h)
    if la.shape != lb.shape:
        raise ValueError("points: the quartic has a triple point (a pencil follows it); its axis is that point")
    _, axes = axial_combinations(la, lb)
    return np.array([_phase(axis) for axis in axes])


def _phase(p: np.ndarray) -> np.ndarray:
    """A complex homogeneous point of unit length with W real and >= 0 (or, at infinity, its first entry)."""
    p = p / np.linalg.norm(p)
    lead = 2 if abs(p[2]) > ZERO_TRIPLE else int(np.argmax(np.abs(p) > ZERO_TRIPLE))
    p = p * (abs(p[lead]) / p[lead])
    return np.where(np.abs(p.imag) <= 1e-12, p.real, p) if np.iscomplexobj(p) else p


# --- implicit equations from two moving lines (§18.4.6) ------------------------------------------------------


def _determinant(matrix: list[list[np.ndarray]]) -> np.ndarray:
    """det of a square matrix of bivariate polynomials (one array shape), by Laplace with shared minors."""
    size = len(matrix)
    one = np.zeros_like(matrix[0][0])
    one[0, 0] = 1.0
    minors = {(): one}
    for count in range(1, size + 1):
        row = size - count
        found = {}
        for columns in combinations(range(size), count):
            total = np.zeros_like(one)
            for position, column in enumerate(columns):
                term = _poly_mul(matrix[row][column], minors[columns[:position] + columns[position + 1 :]])
                total = total + term if position % 2 == 0 else total - term
            found[columns] = total
        minors = found
    return minors[tuple(range(size))]


def _resultant(la: np.ndarray, lb: np.ndarray) -> np.ndarray:
    """Res_t of two moving lines (unscaled rows) at (x, y, 1), by the (hybrid) Bézout matrix: c (n+1, n+1)."""
    if len(la) < len(lb):
        la, lb = lb, la
    d1, d2 = len(la) - 1, len(lb) - 1
    size = d1 + d2 + 1
    f = [_line_poly(line, size) for line in la]
    g = [_line_poly(line, size) for line in lb] + [np.zeros((size, size))] * (d1 - d2)
    matrix = [[np.zeros((size, size)) for _ in range(d1)] for _ in range(d1)]
    for i in range(d1):
        for j in range(d1):
            if i >= d2:
                # Rows of the Bézoutian past deg g are f_(d1) times shifted g: use g itself (hybrid Bézout matrix).
                k = j - (d1 - 1 - i)
                matrix[i][j] = g[k].copy() if 0 <= k <= d2 else np.zeros((size, size))
                continue
            for b in range(min(i, j) + 1):
                a = i + j + 1 - b
                if a <= d1:
                    matrix[i][j] = matrix[i][j] + _poly_mul(f[a], g[b]) - _poly_mul(f[b], g[a])
    return _determinant(matrix)


def _rows(value, name: str) -> np.ndarray:
    rows = _triples(value, name)
    if len(rows) < 1:
        raise ValueError(f"{name}: expected at least one control line")
    return rows


def moving_lines_implicit(la, lb) -> np.ndarray:
    """The implicit equation Res_t(la·P, lb·P) where two moving lines meet, (n+1, n+1). Notes §18.4.6 (18.85)-(18.87).

    la, lb: unscaled rows (d1+1, 3) and (d2+1, 3), n = d1 + d2. A point
    (x, y, 1) is on the curve when both ℓ_a(t) = Σ (la_j·(x, y, 1)) (1-t)^(d1-j) t^j
    and ℓ_b(t) vanish for one t, that is when their resultant is zero. It is
    the determinant of the d1×d1 (hybrid) Bézout matrix of ℓ_a and ℓ_b, whose
    entries are quadratic in x and y: for two lines of degree m (a generic
    curve of degree n = 2m) an m×m determinant where `bezout_moving_lines` has
    n×n; a μ-basis of degrees n - μ and μ gives an (n-μ)×(n-μ) one. Computed exactly as a polynomial, scaled so
    that the largest coefficient is 1; c[i, j] is the coefficient of x^i y^j.
    The two quadratic moving lines (18.69) of the notes' quartic give
    y⁴ + 4x³ + 2xy² - 16x² - 6y² + 16x = 0 (18.87):

    >>> c = moving_lines_implicit([(0, 2, 0), (4, 4, -8), (4, -2, -8)], [(8, 6, 0), (28, 4, -24), (20, -14, -40)])
    >>> ((16 * c).round(9) + 0).tolist()
    ... # doctest: +NORMALIZE_WHITESPACE
    [[0.0, 0.0, -6.0, 0.0, 1.0], [16.0, 0.0, 2.0, 0.0, 0.0], [-16.0, 0.0, 0.0, 0.0, 0.0],
     [4.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0, 0.0]]
    """
    la, lb = _rows(la, "la"), _rows(lb, "lb")
    la, lb = la / np.abs(la).max(), lb / np.abs(lb).max()
    try:
        return _normalised(_resultant(la, lb))
    except ValueError:
        raise ValueError("la, lb: the resultant vanishes identically: the moving lines share a factor") from None


def moving_line_implicit(points, weights=None) -> np.ndarray:
    """The implicit equation of a rational Bézier curve from two moving lines: c[i, j] of x^i y^j. Notes §18.4.6.

    points: (n+1, 2), n >= 1; weights: None or (n+1,) nonzero. The resultant
    (`moving_lines_implicit`) of the two moving lines of `two_moving_lines`;
    for a line (n = 1) the line itself. Defined up to a common factor: scaled
    so that its largest coefficient is 1 (the first of them, in the order of
    c.ravel(), if several have the largest magnitude). It vanishes at every
    point of the curve, for every real t. The notes' cubic,
    x³ - 6x² + 9x - 3y² = 0:

    >>> c = moving_line_implicit([(0, 0), (0, 1), (1, 2), (3, 0)])
    >>> ((9 * c).round(9) + 0).tolist()
    [[0.0, 0.0, -3.0, 0.0], [9.0, 0.0, 0.0, 0.0], [-6.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]]
    """
    h = _homogeneous(points, weights)
    h = h / np.abs(h).max()
    if len(h) == 2:
        return _normalised(_line_poly(np.cross(h[0], h[1]), 2))
    la, lb = _two_lines(h)
    try:
        return _normalised(_resultant(la, lb))
    except ValueError:
        raise ValueError("points: the implicit equation vanishes identically (a degree-raised curve?)") from None


# --- tangent moving lines, envelopes, reciprocal curves (§18.5) ---------------------------------------------


def _tangent(h: np.ndarray) -> np.ndarray:
    """n (Σ B_i^(n-1) H_i) × (Σ B_i^(n-1) H_(i+1)) = H(t) × H'(t), (2n-1, 3)."""
    n = len(h) - 1
    return n * _product(h[:-1], h[1:])


def tangent_moving_line(points, weights=None) -> np.ndarray:
    """The tangent moving line P(t) × P'(t) of a rational curve, control lines (2n-1, 3). Notes §18.5 (18.88)-(18.95).

    points: (n+1, 2), n >= 1; weights: None or (n+1,) nonzero; P(t) the
    homogeneous curve Σ B_i^n w_i (x_i, y_i, 1). The product P × P' has formal
    degree 2n-1, but its top terms cancel: with P = (1-t) A + t B and
    P' = n (B - A), where A(t), B(t) are the degree-(n-1) curves of P_0..P_(n-1)
    and P_1..P_n, P × P' = n A × B, of degree 2n-2 (18.95). L(t) passes through
    P(t) and is tangent there (it also contains P'(t)). The notes' cubic:

    >>> tangent_moving_line([(0, 0), (0, 1), (1, 2), (3, 0)]).tolist()
    [[-3.0, 0.0, 0.0], [-3.0, 1.5, 0.0], [-1.5, 3.0, -1.5], [1.5, 4.5, -4.5], [6.0, 6.0, -18.0]]
    """
    return _tangent(_homogeneous(points, weights))


def tangent_moving_line_plain(points, weights=None) -> np.ndarray:
    """The tangent moving line n P_0^(n-1)(t) × P_1^(n-1)(t): the teaching form of `tangent_moving_line`. Notes §18.5.

    points: (n+1, 2), weights None or (n+1,) (checked by `to_homogeneous`). The two curves
    of degree n-1 that de Casteljau's last step combines, of the first n and
    the last n homogeneous control points, multiplied by the product formula.

    >>> tangent_moving_line_plain([(0, 0), (0, 1), (1, 2), (3, 0)]).tolist()
    [[-3.0, 0.0, 0.0], [-3.0, 1.5, 0.0], [-1.5, 3.0, -1.5], [1.5, 4.5, -4.5], [6.0, 6.0, -18.0]]
    """
    weights = np.ones(len(points)) if weights is None else weights
    h = to_homogeneous(points, weights)  # rows w_i (x_i, y_i, 1)
    n = len(h) - 1
    return n * product_moving_line_plain(h[:-1], h[1:])


def envelope(lines) -> np.ndarray:
    """The envelope Point(L(t) × L'(t)) of a moving line: homogeneous control points (2m-1, 3). Notes §18.5 (18.96).

    lines: Bernstein control lines (m+1, 3), m >= 1. The dual of
    `tangent_moving_line`: the point where L(t) meets its neighbour L(t + δ)
    tends to L × L' as δ -> 0, and L(t) is tangent to the envelope there. The
    same product formula gives its control points, of degree 2m-2.

    >>> envelope([(0.0, 1.0, 0.0), (1.0, 0.0, -1.0), (0.0, 1.0, -2.0)]).tolist()   # from (1, 0) to (1, 2)
    [[-2.0, 0.0, -2.0], [-2.0, 0.0, 0.0], [2.0, 4.0, 2.0]]
    """
    lines = _triples(lines, "lines")
    if len(lines) < 2:
        raise ValueError("lines: a fixed line (degree 0) has no envelope")
    return _tangent(lines) + 0.0


def scaled_hodograph(points, weights=None) -> np.ndarray:
    """The scaled hodograph W(t)² P'(t) of a rational curve from its tangent moving line. Notes §18.5 (18.104)-(18.109).

    With the tangent control lines LT_i = (a_i, b_i, c_i), the parallel lines
    (a_i, b_i, 0) through the origin follow the polynomial curve with control
    points PH_i = (b_i, -a_i), which points along P'(t). It is W(t)² times the
    derivative, so for a polynomial curve the hodograph itself, degree-raised
    n-1 times. The notes' cubic, whose hodograph is (0, 3), (3, 3), (6, -6):

    >>> scaled_hodograph([(0, 0), (0, 1), (1, 2), (3, 0)]).tolist()
    [[0.0, 3.0], [1.5, 3.0], [3.0, 1.5], [4.5, -1.5], [6.0, -6.0]]
    """
    lines = _tangent(_homogeneous(points, weights))
    return np.column_stack([lines[:, 1], -lines[:, 0]]) + 0.0

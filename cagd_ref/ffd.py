"""Free-form deformation (FFD) in the plane: chapter 14 of the notes.

An FFD bends everything drawn inside an axis-parallel box (Xmin, Ymin)-(Xmax,
Ymax) at once. A point first gets local coordinates s = (x - Xmin)/(Xmax -
Xmin) and t = (y - Ymin)/(Ymax - Ymin) in [0, 1]² (`ffd_parameters`), then goes
where the rational tensor-product Bézier patch of degree (m, n) with control
points P_ij and weights w_ij sends (s, t) (`ffd`):

    (X, Y, W) = Σ_i Σ_j B_i^m(s) B_j^n(t) w_ij (x_ij, y_ij, 1),    point = (X/W, Y/W).

The evenly spaced lattice with equal weights is the identity map
(`identity_lattice`); moving its points deforms the box's contents. Points
outside the box stay where they are, so the deformation joins the undeformed
plane continuously only where the boundary rows of the lattice are left in
place; `freeze` resets the k+1 rows next to an edge for a C^k join and
`edge_continuity` measures the join. A line s = const of the box maps to a
rational Bézier curve of degree n whose control points are points of the row
curves (`isoline_image`), and a Bézier curve of degree k inside the box maps to
one of degree k(m + n) (`ffd_curve`), not to the curve of its moved control
points.

Conventions: a box is [[xmin, ymin], [xmax, ymax]], shape (2, 2); a lattice is
(m+1, n+1, 2) with i along x (s) and j along y (t), m, n >= 1, as a patch of
`cagd_ref.surfaces`; weights are None or positive, (m+1, n+1). Points are
(k, 2), or one point (2,).

Ref: T. W. Sederberg and S. R. Parry, Free-form deformation of solid geometric models,
SIGGRAPH 1986 (Computer Graphics 20(4)).
"""

from __future__ import annotations

from math import comb

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points, as_scalar
from .bezier import de_casteljau, from_homogeneous
from .polynomials import bernstein_multiply
from .surfaces import patch_point

__all__ = [
    "ffd_parameters",
    "identity_lattice",
    "ffd",
    "isoline_image",
    "freeze",
    "edge_continuity",
    "ffd_curve",
]

EDGES = ("bottom", "top", "left", "right")
# Relative to the box's diagonal: derivative jumps below this count as no jump (rounding).
JOIN_TOL = 1e-9


# --- input checking -----------------------------------------------------------------------


def _box(box) -> np.ndarray:
    corners = as_float_array(box, "box")
    if corners.shape != (2, 2):
        raise ValueError(f"box: expected [[xmin, ymin], [xmax, ymax]], shape (2, 2), got shape {corners.shape}")
    if not np.all(corners[0] < corners[1]):
        raise ValueError(f"box: expected xmin < xmax and ymin < ymax, got corners {corners.tolist()}")
    return corners


def _lattice(lattice) -> np.ndarray:
    grid = as_float_array(lattice, "lattice")
    if grid.ndim != 3 or grid.shape[2] != 2 or grid.shape[0] < 2 or grid.shape[1] < 2:
        raise ValueError(
            f"lattice: expected control points of shape (m+1, n+1, 2) with m, n >= 1, got shape {grid.shape}"
        )
    return grid


def _weights(weights, grid: np.ndarray) -> np.ndarray | None:
    if weights is None:
        return None
    w = as_float_array(weights, "weights")
    if w.shape != grid.shape[:2]:
        raise ValueError(f"weights: expected one per lattice point, shape {grid.shape[:2]}, got shape {w.shape}")
    if np.any(w <= 0):
        raise ValueError("weights: expected positive weights (W > 0 all over the box), got a weight <= 0")
    return w


def _planar_points(points) -> tuple[np.ndarray, bool]:
    """Points (k, 2) and whether a single point (2,) came in."""
    array = as_float_array(points, "points")
    if array.shape == (2,):
        return array.reshape(1, 2), True
    pts = as_points(array, min_count=0)
    if pts.shape[1] != 2:
        raise ValueError(f"points: FFD is planar, expected shape (k, 2) or (2,), got shape {pts.shape}")
    return pts, False


def _homogeneous(grid: np.ndarray, w: np.ndarray | None) -> np.ndarray:
    """The lattice lifted to w_ij (x_ij, y_ij, 1), shape (m+1, n+1, 3)."""
    ones = np.ones(grid.shape[:2]) if w is None else w
    return np.concatenate([grid * ones[..., None], ones[..., None]], axis=2)


# --- the map --------------------------------------------------------------------------------


def _local(pts: np.ndarray, corners: np.ndarray) -> np.ndarray:
    return (pts - corners[0]) / (corners[1] - corners[0])


def ffd_parameters(points, box) -> np.ndarray:
    """Local coordinates (s, t) of points in the box, (14.1): 0 <= s, t <= 1 inside it. Notes §14.

    s = (x - xmin)/(xmax - xmin), t = (y - ymin)/(ymax - ymin). points: (k, 2)
    -> (k, 2), or (2,) -> (2,); points outside the box get values outside
    [0, 1]. box: [[xmin, ymin], [xmax, ymax]] with xmin < xmax, ymin < ymax.
    The point of the notes' Figure 14.3, in a box of the course's choosing:

    >>> from cagd_ref.ffd import ffd_parameters
    >>> ffd_parameters((3.4, 0.1), [(1, -2), (5, 1)]).round(12).tolist()
    [0.6, 0.7]
    """
    pts, single = _planar_points(points)
    st = _local(pts, _box(box))
    return st[0] if single else st


def _identity(corners: np.ndarray, m: int, n: int) -> np.ndarray:
    xs = corners[0, 0] + np.arange(m + 1) / m * (corners[1, 0] - corners[0, 0])
    ys = corners[0, 1] + np.arange(n + 1) / n * (corners[1, 1] - corners[0, 1])
    grid = np.empty((m + 1, n + 1, 2))
    grid[..., 0] = xs[:, None]
    grid[..., 1] = ys[None, :]
    return grid


def identity_lattice(box, m: int, n: int) -> np.ndarray:
    """The evenly spaced lattice P_ij = (xmin + i/m (xmax - xmin), ymin + j/n (ymax - ymin)), (14.3). Notes §14.

    With equal weights its FFD is the identity: Bernstein polynomials reproduce
    linear functions. box (2, 2); m, n >= 1 the degrees along x and y ->
    (m+1, n+1, 2), i along x and j along y.

    >>> from cagd_ref.ffd import identity_lattice
    >>> lattice = identity_lattice([(0, 0), (3, 2)], 3, 2)    # the course's box for the notes' m = 3, n = 2
    >>> lattice.shape, lattice[1, 2].tolist(), lattice[3, 0].tolist()
    ((4, 3, 2), [1.0, 2.0], [3.0, 0.0])
    """
    corners = _box(box)
    return _identity(corners, as_count(m, "m", 1), as_count(n, "n", 1))


def _deform(pts: np.ndarray, grid: np.ndarray, corners: np.ndarray, w: np.ndarray | None) -> np.ndarray:
    """The kernel of `ffd` on checked arrays: local coordinates, then the patch at those inside the closed box."""
    st = _local(pts, corners)
    inside = np.all((st >= 0) & (st <= 1), axis=1)
    moved = pts.copy()
    if inside.any():
        moved[inside] = patch_point(grid, st[inside, 0], st[inside, 1], w)
    return moved


def ffd(points, lattice, box, weights=None) -> np.ndarray:
    """Free-form deformation of points by a rational tensor-product lattice, (14.2). Notes §14.

    points: (k, 2) -> (k, 2), or (2,) -> (2,); lattice: (m+1, n+1, 2) with i
    along x (s) and j along y (t), m, n >= 1; box: [[xmin, ymin], [xmax,
    ymax]]; weights: None (all 1) or (m+1, n+1) positive. A point of the
    closed box goes to Σ B_i^m(s) B_j^n(t) w_ij P_ij / Σ B_i^m(s) B_j^n(t) w_ij
    at its local (s, t); points outside the box are returned unchanged.

    The course's example A: the 3 x 3 identity lattice of the box (0, 0)-(3, 2)
    with its centre point moved from (1.5, 1) to (2.5, 2):

    >>> from cagd_ref.ffd import ffd, identity_lattice
    >>> box = [(0, 0), (3, 2)]
    >>> lattice = identity_lattice(box, 2, 2)
    >>> lattice[1, 1] = (2.5, 2.0)
    >>> (ffd([(0.75, 0.5), (1.5, 1.0), (3.4, 1.0)], lattice, box) * 64).round(9).tolist()   # the last is outside
    [[57.0, 41.0], [112.0, 80.0], [217.6, 64.0]]
    >>> weights = [[1, 1, 1], [1, 2, 1], [1, 1, 1]]
    >>> ffd((1.5, 1.0), lattice, box, weights).round(12).tolist()
    [1.9, 1.4]
    """
    pts, single = _planar_points(points)
    grid = _lattice(lattice)
    moved = _deform(pts, grid, _box(box), _weights(weights, grid))
    return moved[0] if single else moved


# --- images of the lines of the box ----------------------------------------------------------


def isoline_image(lattice, value, direction: str = "s", weights=None) -> tuple[np.ndarray, np.ndarray]:
    """The rational Bézier curve the line s = value (or t = value) of the box is deformed into. Notes §14.

    direction "s": the image of the vertical line s = value is the degree-n
    curve Σ_j B_j^n(t) H_j(value), whose control points are the points H_j(value)
    of the n+1 row curves H_j(s) = Σ_i B_i^m(s) w_ij (P_ij, 1) (homogeneous);
    returns its control points (n+1, 2) and weights (n+1,) (the W of each
    H_j). direction "t": the horizontal line t = value, the degree-m curve
    through the column curves V_i(t); (m+1, 2) and (m+1,). weights=None gives
    unit weights. value: a number in [0, 1], or k of them -> (k, n+1, 2) and
    (k, n+1).

    The course's example B (m = 3, n = 2): the notes' line s = .6, whose
    image is a quadratic:

    >>> from cagd_ref.ffd import identity_lattice, isoline_image
    >>> lattice = identity_lattice([(0, 0), (3, 2)], 3, 2)
    >>> lattice[1, 1], lattice[2, 2], lattice[3, 0] = (1.5, 1.5), (2, 3), (3.5, -0.5)
    >>> points, weights = isoline_image(lattice, 0.6)
    >>> points.round(12).tolist(), weights.tolist()
    ([[1.908, -0.108], [1.944, 1.144], [1.8, 2.432]], [1.0, 1.0, 1.0])
    """
    grid = _lattice(lattice)
    w = _weights(weights, grid)
    values, scalar = as_parameter(value, "value")
    if np.any((values < 0) | (values > 1)):
        raise ValueError(f"value: the line crosses the box only for 0 <= value <= 1, got {values.tolist()[:5]}")
    if direction not in ("s", "t"):
        raise ValueError(f"direction: expected 's' (a line s = value) or 't' (a line t = value), got {direction!r}")
    h = _homogeneous(grid, w)
    if direction == "t":
        h = h.transpose(1, 0, 2)
    # Each row of curves (one per j) is a single Bézier curve in R^(3(n+1)): one de Casteljau run evaluates all.
    rows = de_casteljau(h.reshape(len(h), -1), values).reshape(len(values), h.shape[1], 3)
    points, curve_weights = rows[..., :2] / rows[..., 2:], rows[..., 2]
    return (points[0], curve_weights[0]) if scalar else (points, curve_weights)


# --- continuity with the undeformed plane ------------------------------------------------------


def _check_edge(edge) -> str:
    if not isinstance(edge, str) or edge not in EDGES:
        raise ValueError(f"edge: expected one of {EDGES}, got {edge!r}")
    return edge


def _edge_rows(edge: str, order: int, m: int, n: int) -> tuple[slice, slice]:
    """Index of the order+1 rows (bottom, top) or columns (left, right) of the lattice next to an edge."""
    count = n if edge in ("bottom", "top") else m
    if order > count:
        raise ValueError(f"order: the lattice has {count + 1} rows across the {edge} edge, so order <= {count}, "
                         f"got {order}")
    near = {"bottom": (slice(None), slice(0, order + 1)), "top": (slice(None), slice(n - order, None)),
            "left": (slice(0, order + 1), slice(None)), "right": (slice(m - order, None), slice(None))}
    return near[edge]


def freeze(lattice, box, edge: str, order: int, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """Reset the order+1 lattice rows next to an edge to the identity (weights 1): a C^order join. Notes §14.

    edge: "bottom" (rows j = 0..order), "top" (j = n-order..n), "left"
    (columns i = 0..order) or "right" (i = m-order..m); order: 0 (C⁰), 1 (C¹),
    2 (C²), ... at most n (bottom, top) or m (left, right). The r-th
    derivative across the edge depends only on the r+1 rows next to it, so
    those rows at their identity positions with weight 1 make the deformation
    agree with the undeformed plane to order `order` there. Returns new arrays
    (lattice (m+1, n+1, 2), weights (m+1, n+1): ones where weights is None);
    the inputs are not modified.

    >>> from cagd_ref.ffd import freeze, identity_lattice
    >>> box = [(0, 0), (3, 2)]
    >>> bent = identity_lattice(box, 2, 3) + 0.5               # every point moved by (0.5, 0.5)
    >>> lattice, weights = freeze(bent, box, "bottom", 1)      # C¹: rows j = 0, 1 put back
    >>> lattice[:, :, 1].round(12).tolist(), weights[0].tolist()
    ([[0.0, 0.666666666667, 1.833333333333, 2.5], [0.0, 0.666666666667, 1.833333333333, 2.5], \
[0.0, 0.666666666667, 1.833333333333, 2.5]], [1.0, 1.0, 1.0, 1.0])
    """
    grid = _lattice(lattice)
    corners = _box(box)
    w = _weights(weights, grid)
    order = as_count(order, "order")
    m, n = grid.shape[0] - 1, grid.shape[1] - 1
    rows = _edge_rows(_check_edge(edge), order, m, n)
    frozen = grid.copy()
    frozen[rows] = _identity(corners, m, n)[rows]
    frozen_weights = np.ones((m + 1, n + 1)) if w is None else w.copy()
    frozen_weights[rows] = 1.0
    return frozen, frozen_weights


def _end_derivatives(h: np.ndarray, count: int) -> np.ndarray:
    """Derivatives 0..count at u = 0 of the projections of homogeneous Bézier curves h (N+1, k, 3): (count+1, k, 2).

    X^(r)(0) = N!/(N-r)! Δ^r H_0 (the hodograph rule), then the quotient rule
    F^(r) = (X^(r) - Σ_{l=1..r} C(r, l) W^(l) F^(r-l)) / W.
    """
    degree = len(h) - 1
    homogeneous = np.zeros((count + 1,) + h.shape[1:])
    difference, factor = h, 1.0
    for r in range(min(count, degree) + 1):
        homogeneous[r] = factor * difference[0]
        difference, factor = np.diff(difference, axis=0), factor * (degree - r)
    x, w = homogeneous[..., :2], homogeneous[..., 2:]
    f = np.zeros(x.shape)
    for r in range(count + 1):
        total = x[r].copy()
        binomial = 1.0
        for ell in range(1, r + 1):
            binomial = binomial * (r - ell + 1) / ell
            total -= binomial * w[ell] * f[r - ell]
        f[r] = total / w[0]
    return f


def edge_continuity(lattice, box, edge: str, weights=None, max_order: int = 3,
                    tol: float = JOIN_TOL) -> tuple[int, np.ndarray]:
    """How smoothly the FFD joins the undeformed plane across an edge of the box: (order, jumps). Notes §14.

    jumps[r], r = 0..max_order: the largest difference between the r-th
    derivative of the deformation across the edge (by the local coordinate
    that leaves the box, t for "bottom"/"top", s for "left"/"right") and the
    identity's, along the edge (sampled at enough points that a zero jump is
    zero all along). order: the largest r with jumps[0..r] <= tol times the
    box's diagonal, so C^order; -1 when the edge itself moves; max_order means
    "at least". weights as in `ffd`.

    >>> from cagd_ref.ffd import edge_continuity, freeze, identity_lattice
    >>> box = [(0, 0), (3, 2)]
    >>> bent = identity_lattice(box, 3, 3)
    >>> bent[:, 2:] += 0.4                                       # the upper two rows moved
    >>> edge_continuity(bent, box, "bottom")[0], edge_continuity(bent, box, "top")[0]
    (1, -1)
    """
    grid = _lattice(lattice)
    corners = _box(box)
    w = _weights(weights, grid)
    max_order = as_count(max_order, "max_order")
    tol = as_scalar(tol, "tol")
    if tol <= 0:
        raise ValueError(f"tol: expected a positive tolerance, got {tol}")
    _check_edge(edge)
    h = _homogeneous(grid, w)
    across_t = edge in ("bottom", "top")
    if not across_t:
        h = h.transpose(1, 0, 2)  # now the first axis runs along the edge and the second across it
    if edge in ("top", "right"):
        h = h[:, ::-1]  # run the across parameter from the edge inwards: u = 1 - t (or 1 - s)
    along = len(h) - 1
    # A zero jump is a polynomial of degree <= (max_order + 1) * along + 1 times a power of W: these many samples.
    samples = np.linspace(0.0, 1.0, max((max_order + 1) * along + 2, 33))
    curves = de_casteljau(h.reshape(len(h), -1), samples).reshape(len(samples), h.shape[1], 3)
    derivatives = _end_derivatives(curves.transpose(1, 0, 2), max_order)
    size = corners[1] - corners[0]
    identity = np.zeros_like(derivatives)
    start = 1 if edge in ("top", "right") else 0
    if across_t:
        identity[0, :, 0] = corners[0, 0] + samples * size[0]
        identity[0, :, 1] = corners[start, 1]
    else:
        identity[0, :, 0] = corners[start, 0]
        identity[0, :, 1] = corners[0, 1] + samples * size[1]
    if max_order >= 1:
        sign = -1.0 if start else 1.0  # u = 1 - t runs against t
        identity[1, :, 1 if across_t else 0] = sign * size[1 if across_t else 0]
    jumps = np.linalg.norm(derivatives - identity, axis=2).max(axis=1)
    small = jumps <= tol * np.hypot(*size)
    order = int(np.argmin(small)) - 1 if not small.all() else max_order
    return order, jumps


# --- the exact image of a Bézier curve ---------------------------------------------------------


def _powers(base: np.ndarray, count: int) -> list[np.ndarray]:
    """Bernstein coefficients of base^0 .. base^count (degrees 0, k, 2k, ...)."""
    powers = [np.ones(1)]
    for _ in range(count):
        powers.append(bernstein_multiply(powers[-1], base))
    return powers


def _basis_of(a: np.ndarray, b: np.ndarray, degree: int) -> np.ndarray:
    """C(d, i) a^(d-i) b^i for i = 0..d as Bernstein polynomials of one degree: columns of (d k + 1, d+1)."""
    pa, pb = _powers(a, degree), _powers(b, degree)
    return np.column_stack([comb(degree, i) * bernstein_multiply(pa[degree - i], pb[i]) for i in range(degree + 1)])


def ffd_curve(points, lattice, box, weights=None, curve_weights=None) -> tuple[np.ndarray, np.ndarray]:
    """The exact FFD image of a (rational) Bézier curve of degree k inside the box: degree k(m + n). Notes §14.

    With the curve's homogeneous local coordinates S(u), T(u) and weight
    ω(u) (degree k), B_i^m(S/ω) B_j^n(T/ω) = C(m,i) C(n,j) (ω-S)^(m-i) S^i
    (ω-T)^(n-j) T^j / ω^(m+n), and the common ω^(m+n) cancels in the projection,
    so the image Σ B_i^m B_j^n w_ij (P_ij, 1) is a rational curve of degree
    k(m + n). points: (k+1, 2), every control point in the closed box (so the
    whole curve is); curve_weights: None or (k+1,) positive. Returns the
    control points (k(m+n)+1, 2) and weights (k(m+n)+1,).

    >>> from cagd_ref.ffd import ffd_curve, identity_lattice
    >>> box = [(0, 0), (3, 2)]
    >>> lattice = identity_lattice(box, 2, 2)
    >>> lattice[1, 1] = (2.5, 2.0)
    >>> points, weights = ffd_curve([(0, 1), (3, 1)], lattice, box)   # the middle line: a quartic
    >>> points.round(12).tolist(), weights.round(12).tolist()
    ([[0.0, 1.0], [1.0, 1.25], [1.833333333333, 1.333333333333], [2.5, 1.25], [3.0, 1.0]], [1.0, 1.0, 1.0, 1.0, 1.0])
    """
    grid = _lattice(lattice)
    corners = _box(box)
    w = _weights(weights, grid)
    pts = as_points(points, min_count=1)
    if pts.shape[1] != 2:
        raise ValueError(f"points: FFD is planar, expected control points (k+1, 2), got shape {pts.shape}")
    st = _local(pts, corners)
    if np.any((st < 0) | (st > 1)):
        raise ValueError("points: every control point must lie in the box (then the curve does, and its image is "
                         "one Bézier curve)")
    if curve_weights is None:
        omega = np.ones(len(pts))
    else:
        omega = as_float_array(curve_weights, "curve_weights")
        if omega.shape != (len(pts),) or np.any(omega <= 0):
            raise ValueError(f"curve_weights: expected {len(pts)} positive weights, got {omega.tolist()}")
    s, t = st[:, 0] * omega, st[:, 1] * omega
    m, n = grid.shape[0] - 1, grid.shape[1] - 1
    along_s, along_t = _basis_of(omega - s, s, m), _basis_of(omega - t, t, n)
    # All (m+1)(n+1) products at once: column i(n+1) + j holds the factor of lattice point P_ij.
    products = bernstein_multiply(np.repeat(along_s, n + 1, axis=1), np.tile(along_t, m + 1))
    image = products @ _homogeneous(grid, w).reshape(-1, 3)
    return from_homogeneous(image)

"""Points, vectors, lines and conics: the toolkit of chapter 1 of the notes.

Points and vectors are NumPy arrays of shape (d,) (or (k, d) for many points).
Homogeneous lines and points in the plane are triples: a line ``a x + b y + c w = 0``
is ``(a, b, c)``, a point is ``(X, Y, W)``; joining and meeting are cross products.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, as_scalar, as_vector

__all__ = [
    "projection",
    "triangle_area",
    "rotate_about_axis",
    "rotation_matrix",
    "apply_transform",
    "affine_point",
    "implicit_line",
    "normalize_line",
    "signed_distance",
    "join",
    "meet",
    "conic_type",
    "conic_discriminant",
    "parametric_conic_type",
]

CONIC_TYPES = ("ellipse", "parabola", "hyperbola")


def projection(p, q) -> np.ndarray:
    """The projection of vector `p` onto vector `q`: ``(p·q / q·q) q``. Notes §1.2.

    p, q: vectors of the same shape (d,); `q` must not be the zero vector.
    Returns shape (d,). The notes' example: p · q = 27 and q · q = 81, so the
    projection of (3, 2, 1) onto (3, 6, 6) is a third of (3, 6, 6).

    >>> from cagd_ref.geometry import projection
    >>> projection([3, 2, 1], [3, 6, 6]).tolist()
    [1.0, 2.0, 2.0]
    """
    p = as_vector(p, "p")
    q = as_vector(q, "q", dim=p.shape[0])
    qq = q @ q
    if qq == 0:
        raise ValueError("q: cannot project onto the zero vector")
    return (p @ q) / qq * q


def triangle_area(p1, p2, p3) -> float:
    """Area of the triangle p1 p2 p3: half the length of (p2 - p1) × (p3 - p1). Notes §1.2, eq. (1.4).

    p1, p2, p3: points of one shape, (2,) or (3,). Returns a float >= 0. The
    notes' example: the edges (1, 3, 4) and (2, 1, 5) have the cross product
    (11, 3, -5), so the area is sqrt(155)/2.

    >>> from cagd_ref.geometry import triangle_area
    >>> round(triangle_area([1, 1, 1], [2, 4, 5], [3, 2, 6]), 3)
    6.225
    """
    p1 = as_vector(p1, "p1")
    if p1.shape[0] not in (2, 3):
        raise ValueError(f"p1: expected a 2-D or 3-D point, got shape {p1.shape}")
    p2 = as_vector(p2, "p2", dim=p1.shape[0])
    p3 = as_vector(p3, "p3", dim=p1.shape[0])
    # Padding 2-D points with z = 0 lets one 3-D cross product serve both cases.
    e1, e2 = np.zeros(3), np.zeros(3)
    e1[: p1.shape[0]] = p2 - p1
    e2[: p1.shape[0]] = p3 - p1
    return float(np.linalg.norm(np.cross(e1, e2)) / 2)


def _unit_axis(axis_direction) -> np.ndarray:
    n = as_vector(axis_direction, "axis_direction", dim=3)
    length = np.linalg.norm(n)
    if length == 0:
        raise ValueError("axis_direction: the axis direction must be a nonzero vector")
    return n / length


def rotate_about_axis(point, axis_point, axis_direction, angle) -> np.ndarray:
    """Rotate 3-D point(s) by `angle` radians about the axis through `axis_point` along `axis_direction`.

    point: (3,) or (k, 3); the result has the same shape. axis_point,
    axis_direction: (3,), the direction nonzero but not necessarily a unit
    vector. angle: radians, right-handed about the axis direction. The vector
    form of Notes §1.3, eqs. (1.6)-(1.9): C = B + ((P-B)·n) n, u = P - C,
    v = n × u, P* = C + u cos θ + v sin θ. The notes' example turns (5, 7, 3) a
    quarter turn about the axis through (1, 1, 1) along (2, 1, 2):

    >>> from cagd_ref.geometry import rotate_about_axis
    >>> np.round(rotate_about_axis([5, 7, 3], [1, 1, 1], [2, 1, 2], np.pi / 2), 6).tolist()
    [1.666667, 4.333333, 7.666667]

    Ref: O. Rodrigues, Des lois géométriques qui régissent les déplacements d'un système solide dans l'espace,
    J. Math. Pures Appl. 5 (1840), 380-440 (the rotation formula that bears his name).
    """
    pts = as_float_array(point, "point")
    if pts.shape[-1:] != (3,) or pts.ndim > 2:
        raise ValueError(f"point: expected shape (3,) or (k, 3), got {pts.shape}")
    b = as_vector(axis_point, "axis_point", dim=3)
    n = _unit_axis(axis_direction)
    theta = as_scalar(angle, "angle")
    c = b + np.outer((pts.reshape(-1, 3) - b) @ n, n)
    u = pts.reshape(-1, 3) - c
    v = np.cross(n, u)
    rotated = c + u * np.cos(theta) + v * np.sin(theta)
    return rotated.reshape(pts.shape)


def rotation_matrix(axis_point, axis_direction, angle) -> np.ndarray:
    """The 4x4 homogeneous matrix of the rotation of `rotate_about_axis`, acting on columns (x, y, z, 1). Notes §1.3.1.

    axis_point, axis_direction: (3,), the direction nonzero; angle: radians.
    The upper-left block is cos θ I + sin θ [n]× + (1 - cos θ) n nᵀ, the matrix
    (1.27) of the notes; the last column keeps the axis point fixed. On the
    notes' example of §1.3:

    >>> from cagd_ref.geometry import rotation_matrix
    >>> M = rotation_matrix([1, 1, 1], [2, 1, 2], np.pi / 2)
    >>> np.round(M @ [5, 7, 3, 1], 6).tolist()
    [1.666667, 4.333333, 7.666667, 1.0]

    Ref: O. Rodrigues, Des lois géométriques qui régissent les déplacements d'un système solide dans l'espace,
    J. Math. Pures Appl. 5 (1840), 380-440 (the rotation formula that bears his name).
    """
    b = as_vector(axis_point, "axis_point", dim=3)
    n = _unit_axis(axis_direction)
    theta = as_scalar(angle, "angle")
    cos, sin = np.cos(theta), np.sin(theta)
    cross = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    linear = cos * np.eye(3) + sin * cross + (1 - cos) * np.outer(n, n)
    matrix = np.eye(4)
    matrix[:3, :3] = linear
    # The axis point must stay fixed, which fixes the translation column.
    matrix[:3, 3] = b - linear @ b
    return matrix


def apply_transform(matrix, points) -> np.ndarray:
    """Apply a 4x4 homogeneous matrix to 3-D point(s) of shape (3,) or (k, 3); same shape back. Notes §1.3.1."""
    m = as_float_array(matrix, "matrix")
    if m.shape != (4, 4):
        raise ValueError(f"matrix: expected shape (4, 4), got {m.shape}")
    pts = as_float_array(points, "points")
    if pts.shape[-1:] != (3,) or pts.ndim > 2:
        raise ValueError(f"points: expected shape (3,) or (k, 3), got {pts.shape}")
    flat = pts.reshape(-1, 3)
    homogeneous = np.hstack([flat, np.ones((len(flat), 1))]) @ m.T
    if np.any(homogeneous[:, 3] == 0):
        raise ValueError("matrix: sends a point to infinity (its image has homogeneous coordinate w = 0)")
    return (homogeneous[:, :3] / homogeneous[:, 3:]).reshape(pts.shape)


def affine_point(p0, p1, t0, t1, t) -> np.ndarray:
    """Point at parameter t of the line with P(t0) = p0, P(t1) = p1. Notes §1.5.1, eq. (1.36).

    The affine form ``((t1-t) p0 + (t-t0) p1) / (t1-t0)``. p0, p1: points of
    shape (d,); t0 != t1. `t` is a number (result (d,)) or a 1-D array of k
    values (result (k, d)).
    """
    p0 = as_vector(p0, "p0")
    p1 = as_vector(p1, "p1", dim=p0.shape[0])
    t0, t1 = as_scalar(t0, "t0"), as_scalar(t1, "t1")
    if t0 == t1:
        raise ValueError("t0, t1: the two parameter values must differ")
    ts = as_float_array(t, "t")
    if ts.ndim > 1:
        raise ValueError(f"t: expected a number or a 1-D array, got shape {ts.shape}")
    s = ((ts - t0) / (t1 - t0))[..., None]
    return (1 - s) * p0 + s * p1


def implicit_line(p0, p1) -> np.ndarray:
    """Coefficients (a, b, c) of the line a x + b y + c = 0 through 2-D points p0 and p1. Notes §1.5.2."""
    p0 = as_vector(p0, "p0", dim=2)
    p1 = as_vector(p1, "p1", dim=2)
    if np.array_equal(p0, p1):
        raise ValueError("p0, p1: two distinct points are needed to define a line")
    return join(np.append(p0, 1.0), np.append(p1, 1.0))


def normalize_line(line) -> np.ndarray:
    """Scale (a, b, c) so that a² + b² = 1; then a x + b y + c is the signed distance. Notes §1.5.3."""
    line = as_vector(line, "line", dim=3)
    norm = np.hypot(line[0], line[1])
    if norm == 0:
        raise ValueError(f"line: a and b cannot both be zero, got {line.tolist()}")
    return line / norm


def signed_distance(line, points) -> np.ndarray | float:
    """Signed distance from 2-D point(s) (shape (2,) or (k, 2)) to the line (a, b, c). Notes §1.5.3."""
    a, b, c = normalize_line(line)
    pts = as_float_array(points, "points")
    if pts.shape[-1:] != (2,) or pts.ndim > 2:
        raise ValueError(f"points: expected shape (2,) or (k, 2), got {pts.shape}")
    distance = pts @ np.array([a, b]) + c
    return float(distance) if pts.ndim == 1 else distance


def join(p, q) -> np.ndarray:
    """The homogeneous line (a, b, c) through homogeneous points p = (X, Y, W) and q, shape (3,). Notes §1.5.2."""
    return np.cross(as_vector(p, "p", dim=3), as_vector(q, "q", dim=3))


def meet(l1, l2) -> np.ndarray:
    """The homogeneous point (X, Y, W) where lines l1 and l2 cross (W = 0 when parallel). Notes §1.5.2."""
    return np.cross(as_vector(l1, "l1", dim=3), as_vector(l2, "l2", dim=3))


def conic_discriminant(a, b, c) -> float:
    """b² - 4ac for the conic a x² + b xy + c y² + d x + e y + f = 0. Notes §1.6."""
    a, b, c = (as_scalar(v, name) for v, name in ((a, "a"), (b, "b"), (c, "c")))
    return b * b - 4 * a * c


def _classify(discriminant: float, scale: float) -> str:
    # A relative tolerance: the discriminant is a difference of products of size scale².
    if abs(discriminant) <= 1e-12 * scale * scale:
        return "parabola"
    return "hyperbola" if discriminant > 0 else "ellipse"


def conic_type(a, b, c, d, e, f) -> str:
    """'ellipse', 'parabola' or 'hyperbola' for a x² + b xy + c y² + d x + e y + f = 0. Notes §1.6.

    a, ..., f: numbers, not all of a, b, c zero. The type is the number of real
    points at infinity: the sign of b² - 4ac (negative: ellipse, zero:
    parabola, positive: hyperbola), zero meaning within 1e-12 max(|a|, |b|, |c|)².
    The notes work no numbers here; the unit circle, y = x² and xy = 1:

    >>> from cagd_ref.geometry import conic_type
    >>> conic_type(1, 0, 1, 0, 0, -1), conic_type(1, 0, 0, 0, -1, 0), conic_type(0, 1, 0, 0, 0, -1)
    ('ellipse', 'parabola', 'hyperbola')
    """
    for value, name in ((d, "d"), (e, "e"), (f, "f")):
        as_scalar(value, name)
    a, b, c = (as_scalar(v, name) for v, name in ((a, "a"), (b, "b"), (c, "c")))
    if a == b == c == 0:
        raise ValueError("a, b, c: all quadratic coefficients are zero, so this is a line, not a conic")
    return _classify(conic_discriminant(a, b, c), max(abs(a), abs(b), abs(c)))


def parametric_conic_type(denominator) -> str:
    """Conic type of a rational quadratic curve (X(t), Y(t)) / w(t), read off its denominator alone.

    `denominator` is (d0, d1, d2) for w(t) = d0 + d1 t + d2 t². The real roots of
    w are the parameters where the curve runs off to infinity, so the sign of
    d1² - 4 d0 d2 classifies the conic as the implicit discriminant does. Notes §1.6.1.
    """
    d0, d1, d2 = as_vector(denominator, "denominator", dim=3)
    if d0 == d1 == d2 == 0:
        raise ValueError("denominator: w(t) is identically zero")
    return _classify(d1 * d1 - 4 * d0 * d2, max(abs(d0), abs(d1), abs(d2)))

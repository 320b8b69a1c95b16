"""Plane algebraic curves: genus, singular points, intersections, discriminants and parametrization (chapter 19).

An implicit curve f(x, y) = Σ c[i, j] xⁱ yʲ = 0 is a 2-D array `c` of
coefficients, the layout of chapter 17 (`cagd_ref.algebra.implicitize`);
any shape (dx+1, dy+1) is accepted, and the arrays returned here are square,
(n+1, n+1) for a curve of total degree n. A univariate polynomial is a 1-D
array of ascending power coefficients, as in `numpy.polynomial`.

The chapter asks four questions of such a curve:

- **which points are singular, and of what kind.** Put the point at the
  origin and split f into homogeneous parts f̂_0 + f̂_1 + f̂_2 + ...; the
  multiplicity is the index of the first part that is not zero, and that part
  factors into the tangent lines there (the tangent cone). For a double point
  f̂_2 = A a² + B ab + C b² gives a crunode, a cusp or an acnode by the sign of
  B² - 4AC;
- **where two curves meet.** The resultant in y, a polynomial in x, has the
  x-coordinates of the intersections as roots; the GCD of f(x_k, y) and
  g(x_k, y) then gives the y that goes with each x_k;
- **where a curve has vertical tangents or double points.** Those are the
  roots of its discriminant Res_y(f, ∂f/∂y), the silhouette seen along y;
- **whether it has a rational parametrization, and which.** A curve of degree
  n with a point of multiplicity n-1 meets every line through that point in
  one more point, so the pencil of lines through it parametrizes the curve.
  The genus (n-1)(n-2)/2 - Σ r(r-1)/2 counts what stands in the way.

Everything is NumPy. Resultants of bivariate polynomials are computed as
exact polynomial determinants (no sampling), so integer data give integer
results up to rounding; the tests check them against SymPy.
"""

from __future__ import annotations

import numbers
from itertools import combinations

import numpy as np
from numpy.polynomial import polynomial as P

from ._validation import (
    as_count,
    as_float_array,
    as_interval,
    as_parameter,
    as_points,
    as_scalar,
    as_tolerance,
    as_vector,
)
from .algebra import _poly, _size, _trimmed, poly_gcd, resultant
from .bezier import from_homogeneous
from .polynomials import power_to_bernstein

__all__ = [
    "genus",
    "implicit_degree",
    "transform_implicit",
    "translate_implicit",
    "homogeneous_parts",
    "multiplicity",
    "tangent_cone",
    "tangent_directions",
    "classify_double_point",
    "discriminant",
    "curve_resultant",
    "curve_discriminant",
    "implicit_intersections",
    "singular_points",
    "parametrize_by_pencil",
    "pencil_point",
    "pencil_bezier",
    "conic_through_points",
    "circle_through_points",
]

# A homogeneous part, a value or a discriminant is zero when it is below this fraction of its scale.
ZERO_TOL = 1e-9
# Real roots closer than this (relative) are one root: a tangency, or a double point's two branches.
ROOT_MERGE = 1e-7
# A root whose imaginary part is below this (relative) is real: double roots split into near-real pairs.
IMAG_TOL = 1e-7
# The same for the roots of a resultant in x. Two points on one vertical line make a double root there, which
# rounding splits into a pair about sqrt(rounding) off the axis; candidates that are no points fail the residual test.
RESULTANT_IMAG_TOL = 1e-5
# An intersection point must make both polynomials this small relative to their sizes at that point.
RESIDUAL_TOL = 1e-8
# A singular value below this fraction of the largest one counts as zero (conic through five points).
RANK_TOL = 1e-9


# --- input checking and bivariate arithmetic ------------------------------------------------------------------


def _implicit(c, name: str = "c", constant_ok: bool = False) -> np.ndarray:
    """A bivariate coefficient array (dx+1, dy+1), not the zero polynomial (nor a constant, unless allowed)."""
    array = as_float_array(c, name)
    if array.ndim != 2 or array.size == 0:
        raise ValueError(f"{name}: expected a 2-D array c[i, j] of the coefficients of x^i y^j, got shape "
                         f"{array.shape}")
    if not np.any(array):
        raise ValueError(f"{name}: the zero polynomial is no curve (every point satisfies it)")
    if not constant_ok and not np.any(array.ravel()[1:]):
        raise ValueError(f"{name}: a nonzero constant is no curve (no point satisfies it)")
    return array


def _degree(c: np.ndarray) -> int:
    i, j = np.nonzero(c)
    return int((i + j).max()) if i.size else 0


def _square(c: np.ndarray, n: int) -> np.ndarray:
    """c as a square (n+1, n+1) array (n at least its total degree)."""
    out = np.zeros((n + 1, n + 1))
    i, j = np.nonzero(c)
    out[i, j] = c[i, j]
    return out


def _mul2(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The product of two bivariate polynomials in square arrays of one size, truncated to that size."""
    size = len(a)
    out = np.zeros_like(a)
    for i, j in zip(*np.nonzero(a)):
        out[i:, j:] += a[i, j] * b[: size - i, : size - j]
    return out


def _point(point, name: str = "point") -> np.ndarray:
    return as_vector(point, name, dim=2)


# --- §19.1 genus -------------------------------------------------------------------------------------------------


def genus(degree, multiplicities=()) -> int:
    """The genus (n-1)(n-2)/2 - Σ r(r-1)/2 of an irreducible curve of degree n with singular points of multiplicity r.

    degree: n >= 1. multiplicities: the multiplicities r (integers, 2 <= r <= n-1)
    of its ordinary singular points, complex ones and those at infinity included;
    a cusp counts as a double point. A double point takes one from the genus, a
    triple point three. Genus 0 means the curve is rational (unicursal): it has a
    parametrization by rational functions. A total that exceeds (n-1)(n-2)/2
    leaves a negative number, which no irreducible curve has: ValueError (the
    curve must be reducible, like the two concentric circles of §19.1).
    Notes §19.1.

    >>> genus(3, [2]), genus(3), genus(4, [2, 2, 2]), genus(4, [3])
    (0, 1, 0, 0)
    """
    n = as_count(degree, "degree", minimum=1)
    if isinstance(multiplicities, (str, bytes, dict, set)) or multiplicities is None:
        raise TypeError(f"multiplicities: expected a list of integers, got {type(multiplicities).__name__}")
    try:
        rs = list(multiplicities)
    except TypeError:
        raise TypeError(f"multiplicities: expected a list of integers, got {type(multiplicities).__name__}") from None
    total = 0
    for r in rs:
        if isinstance(r, numbers.Real) and not np.isfinite(r):
            raise ValueError(f"multiplicities: expected integers, got {r!r}")
        if isinstance(r, bool) or not isinstance(r, numbers.Integral):
            raise TypeError(f"multiplicities: expected integers, got {r!r}")
        if not 2 <= r <= n - 1:
            raise ValueError(f"multiplicities: a singular point of a curve of degree {n} has multiplicity 2..{n - 1}, "
                             f"got {int(r)}")
        total += int(r) * (int(r) - 1) // 2
    g = (n - 1) * (n - 2) // 2 - total
    if g < 0:
        raise ValueError(f"multiplicities: they take {total} from a genus of {(n - 1) * (n - 2) // 2}, which leaves "
                         f"{g}: a curve with that many singular points is reducible")
    return g


def implicit_degree(c) -> int:
    """The total degree of f(x, y) = Σ c[i, j] xⁱ yʲ: the largest i + j of a nonzero coefficient. Notes §19.1.

    >>> implicit_degree([[0.0, 0.0, 3.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])   # x³ + xy + 3y²
    3
    """
    return _degree(_implicit(c, constant_ok=True))


# --- changes of coordinates --------------------------------------------------------------------------------------


def _transform(c: np.ndarray, matrix: np.ndarray, shift: np.ndarray) -> np.ndarray:
    n = _degree(c)
    size = n + 1
    u, v = np.zeros((size, size)), np.zeros((size, size))
    u[0, 0], v[0, 0] = shift
    if n >= 1:
        u[1, 0], u[0, 1] = matrix[0]
        v[1, 0], v[0, 1] = matrix[1]
    one = np.zeros((size, size))
    one[0, 0] = 1.0
    u_powers, v_powers = [one], [one]
    for _ in range(n):
        u_powers.append(_mul2(u_powers[-1], u))
        v_powers.append(_mul2(v_powers[-1], v))
    out = np.zeros((size, size))
    for i, j in zip(*np.nonzero(c)):
        out += c[i, j] * _mul2(u_powers[i], v_powers[j])
    return out + 0.0


def transform_implicit(c, matrix, shift=(0.0, 0.0)) -> np.ndarray:
    """Coefficients (n+1, n+1) of f(M (x, y) + s): the curve moved by the inverse of the affine map p -> M p + s.

    c: c[i, j] of xⁱ yʲ, any shape; matrix M (2, 2), shift s (2,). A point p is on
    the new curve exactly when M p + s is on the old one, so a rotation by θ of
    the curve itself is matrix [[cos θ, sin θ], [-sin θ, cos θ]]. Notes §19.5.

    >>> transform_implicit([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[0, 1], [1, 0]], (1, 0)).tolist()
    [[1.0, 2.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    a = _implicit(c, constant_ok=True)
    m = as_float_array(matrix, "matrix")
    if m.shape != (2, 2):
        raise ValueError(f"matrix: expected a 2×2 matrix, got shape {m.shape}")
    return _transform(a, m, as_vector(shift, "shift", dim=2))


def translate_implicit(c, dx, dy) -> np.ndarray:
    """Coefficients (n+1, n+1) of f(x + dx, y + dy): the point (dx, dy) of the old curve is the new origin. Notes §19.5.

    The notes' cubic of §19.5 with its double point (2, 3) moved to the origin:

    >>> f = [[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0], [1, 0, 0, 0]]
    >>> translate_implicit(f, 2, 3).round(9).tolist()     # 2x² + 7xy + 6y² + x³ + 3x²y + 3xy² + y³
    [[0.0, 0.0, 6.0, 1.0], [0.0, 7.0, 3.0, 0.0], [2.0, 3.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]]
    """
    shift = np.array([as_scalar(dx, "dx"), as_scalar(dy, "dy")])
    return _transform(_implicit(c, constant_ok=True), np.eye(2), shift)


def homogeneous_parts(c) -> list[np.ndarray]:
    """The homogeneous parts f_0, ..., f_n of f: f_k (k+1,) holds γ_j, the coefficient of x^(k-j) y^j. Notes §19.2.

    >>> [g.tolist() for g in homogeneous_parts([[0.0, 0.0, 3.0], [0.0, 1.0, -2.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])]
    [[0.0], [0.0, 0.0], [0.0, 1.0, 3.0], [1.0, 0.0, -2.0, 0.0]]
    """
    a = _implicit(c, constant_ok=True)
    return _parts(_square(a, _degree(a)))


def _parts(sq: np.ndarray) -> list[np.ndarray]:
    n = len(sq) - 1
    return [np.array([sq[k - j, j] for j in range(k + 1)]) + 0.0 for k in range(n + 1)]


# --- §19.2 multiplicity, tangent cone, classification ---------------------------------------------------------------


def _local(c, point, tol) -> tuple[list[np.ndarray], int, float]:
    """The homogeneous parts at `point`, its multiplicity, and the scale the zero tests used."""
    a = _implicit(c)
    p = _point(point)
    tol = as_tolerance(tol, below_one=True)
    moved = _transform(a, np.eye(2), p)
    scale = float(np.abs(moved).max())
    parts = _parts(moved)
    r = next((k for k, g in enumerate(parts) if np.abs(g).max() > tol * scale), len(parts))
    return parts, r, scale


def multiplicity(c, point, tol: float = ZERO_TOL) -> int:
    """The multiplicity of `point` (2,) on f = 0: 0 off the curve, 1 at a simple point, 2 at a double point... §19.2.

    The curve is moved so that the point is the origin; the line x = a u,
    y = b u then meets it in Σ u^k f̂_k(a, b), and the multiplicity is the
    smallest k whose part f̂_k is not zero: every coefficient of the parts
    below it is at most tol times the largest coefficient of the moved
    polynomial.

    >>> multiplicity([[0.0, 0.0, 3.0], [0.0, 1.0, -2.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], (0, 0))   # x³-2xy²+xy+3y²
    2
    """
    return _local(c, point, tol)[1]


def tangent_cone(c, point, tol: float = ZERO_TOL) -> np.ndarray:
    """The lowest nonzero homogeneous part f̂_r at `point`, (r+1,): γ_j the coefficient of a^(r-j) b^j. Notes §19.2.

    Its linear factors b_k a - a_k b are the tangent lines at the point,
    directions (a_k, b_k): along them the line meets the curve r+1 times or
    more. A point off the curve (r = 0) raises ValueError.

    >>> tangent_cone([[0, 0, 3], [0, 1, -2], [0, 0, 0], [1, 0, 0]], (0, 0)).tolist()   # ab + 3b²
    [0.0, 1.0, 3.0]
    """
    parts, r, _ = _local(c, point, tol)
    if r == 0:
        raise ValueError("point: not on the curve (f is not zero there), so it has no tangent cone")
    return parts[r]


def tangent_directions(c, point, tol: float = ZERO_TOL) -> np.ndarray:
    """Unit directions (k, 2) of the real tangent lines at `point`, one per distinct line (k = 0 at an acnode). §19.2.

    The real roots of the tangent cone: b/a = m for the roots m of f̂_r(1, m),
    and the vertical direction (0, 1) when f̂_r has fewer than r roots that way.
    Each direction has a >= 0; they are sorted by a, then b.

    >>> tangent_directions([[0, 0, 3], [0, 1, -2], [0, 0, 0], [1, 0, 0]], (0, 0)).round(6).tolist()
    [[0.948683, -0.316228], [1.0, 0.0]]
    """
    g = tangent_cone(c, point, tol)
    found = []
    g_trim = _poly(g, "g")
    if len(g_trim) - 1 < len(g) - 1:
        found.append((0.0, 1.0))
    if len(g_trim) > 1:
        roots = P.polyroots(g_trim)
        real = roots[np.abs(roots.imag) <= IMAG_TOL * np.maximum(1.0, np.abs(roots))].real
        for m in _merged(np.sort(real)):
            found.append((1.0, m))
    d = np.array(found, dtype=float).reshape(-1, 2)
    d = d / np.linalg.norm(d, axis=1, keepdims=True) if len(d) else d
    return d[np.lexsort((d[:, 1], d[:, 0]))] if len(d) else d


def _merged(values: np.ndarray) -> np.ndarray:
    """Sorted values with runs closer than ROOT_MERGE (relative) replaced by their mean."""
    if values.size == 0:
        return values
    groups = [[values[0]]]
    for v in values[1:]:
        if abs(v - groups[-1][-1]) <= ROOT_MERGE * max(1.0, abs(v)):
            groups[-1].append(v)
        else:
            groups.append([v])
    return np.array([np.mean(g) for g in groups])


def classify_double_point(c, point, tol: float = ZERO_TOL) -> str:
    """'crunode', 'cusp' or 'acnode': the kind of the double point `point` (2,) of f = 0, from its tangent cone. §19.2.

    c: c[i, j] of xⁱ yʲ. Moved to the origin, f̂ = f̂_2 + f̂_3 + ... with
    f̂_2 = A a² + B ab + C b² (`tangent_cone`). D = B² - 4AC > 0: two real
    tangents, a **crunode** (the curve crosses itself); D = 0: one double
    tangent, a **cusp**; D < 0: two complex tangents, an **acnode** (an
    isolated real point). Zero tests are relative: a part is zero when its
    coefficients are at most tol times the largest coefficient of the moved
    polynomial, and D is zero when |D| <= tol (B² + 4|AC|). A point off the
    curve, a simple point or a point of multiplicity 3 or more raises
    ValueError. (A repeated tangent may also belong to a tacnode or a higher
    cusp: on curves of degree 4 and more, and on reducible cubics such as the
    parabola with its tangent y(y - x²). The test cannot tell, and calls it a
    cusp; on an irreducible cubic D = 0 is always an ordinary cusp.) Notes §19.2.

    >>> classify_double_point([[0, 0, 3], [0, 1, -2], [0, 0, 0], [1, 0, 0]], (0, 0))      # x³ - 2xy² + xy + 3y²
    'crunode'
    >>> classify_double_point([[0, 0, -3], [0, 0, 0], [0, 0, 0], [1, 0, 0]], (0, 0))      # x³ - 3y²
    'cusp'
    >>> classify_double_point([[0, 0, -3], [0, 0, 0], [-3, 0, 0], [1, 0, 0]], (0, 0))     # x³ - 3x² - 3y²
    'acnode'
    """
    tol = as_tolerance(tol, below_one=True)
    x0, y0 = as_vector(point, "point", dim=2)
    parts = homogeneous_parts(translate_implicit(c, x0, y0))  # f̂_0, f̂_1, f̂_2, ... at the point
    scale = max(np.abs(part).max() for part in parts)  # the largest coefficient of f̂
    r = next((k for k, part in enumerate(parts) if np.abs(part).max() > tol * scale), len(parts))
    if r != 2:
        what = {0: "not on the curve", 1: "a simple point of the curve"}.get(r, f"a point of multiplicity {r}")
        raise ValueError(f"point: {what}, not a double point")
    A, B, C = parts[2]  # f̂_2(a, b) = A a² + B ab + C b²
    D = B * B - 4 * A * C
    if abs(D) <= tol * (B * B + 4 * abs(A * C)):
        return "cusp"
    return "crunode" if D > 0 else "acnode"


# --- §19.3-19.4 resultants and discriminants -------------------------------------------------------------------


def discriminant(coeffs) -> float:
    """Res(p, p'), the resultant of a polynomial and its derivative: zero exactly when p has a repeated root. §19.4.

    coeffs: ascending power coefficients (n+1,), trailing zeros dropped, degree
    n >= 1. The resultant is Sylvester's determinant (`algebra.resultant`), so
    for the quadratic a t² + b t + c it is a (4ac - b²). Two other conventions
    vanish for the same p: the determinant of the Bézout matrix of p and p'
    (`algebra.bezout_matrix`, the notes' a²(b² - 4ac)) is (-1)^(n(n-1)/2) a_n
    times this number, and SymPy's `discriminant` is (-1)^(n(n-1)/2) / a_n
    times it, b² - 4ac for the quadratic. Notes §19.4.

    >>> discriminant([-5.0, 3.0, 2.0])             # 2t² + 3t - 5: a (4ac - b²) = 2 (-40 - 9)
    -98.0
    >>> round(discriminant([-2.0, 3.0, 0.0, -1.0]), 9)  # -(t - 1)² (t + 2): a double root
    0.0
    """
    p = _poly(coeffs, "coeffs")
    if len(p) < 2:
        raise ValueError(f"coeffs: a polynomial of degree >= 1 is needed (after dropping trailing zeros), got "
                         f"{p.tolist()}")
    return resultant(p, P.polyder(p)) + 0.0


def _polynomial_determinant(rows: list[list[np.ndarray | None]]) -> np.ndarray:
    """det of a square matrix of univariate polynomials (None for zero): Laplace expansion with memoised minors."""
    n = len(rows)
    minors: dict[tuple[int, ...], np.ndarray] = {(): np.ones(1)}
    for size in range(1, n + 1):
        row = rows[n - size]
        found = {}
        for columns in combinations(range(n), size):
            total = np.zeros(1)
            for position, column in enumerate(columns):
                entry = row[column]
                if entry is None:
                    continue
                minor = minors[columns[:position] + columns[position + 1 :]]
                term = P.polymul(entry, minor)
                total = P.polyadd(total, term) if position % 2 == 0 else P.polysub(total, term)
            found[columns] = total
        minors = found
    return minors[tuple(range(n))]


def _y_degree(c: np.ndarray) -> int:
    columns = np.flatnonzero(np.any(c != 0, axis=0))
    return int(columns[-1]) if columns.size else 0


def _resultant_y(f: np.ndarray, g: np.ndarray) -> np.ndarray:
    """Res_y(f, g) as ascending coefficients in x: Sylvester's matrix in y with polynomial entries in x."""
    m, n = _y_degree(f), _y_degree(g)
    if m == 0 and n == 0:
        return np.ones(1)
    fc = [_poly(f[:, k], "f") if np.any(f[:, k]) else None for k in range(m + 1)]
    gc = [_poly(g[:, k], "g") if np.any(g[:, k]) else None for k in range(n + 1)]
    size = m + n
    rows: list[list[np.ndarray | None]] = []
    for r in range(n):
        row: list[np.ndarray | None] = [None] * size
        for k in range(m + 1):
            row[r + k] = fc[m - k]
        rows.append(row)
    for r in range(m):
        row = [None] * size
        for k in range(n + 1):
            row[r + k] = gc[n - k]
        rows.append(row)
    det = _polynomial_determinant(rows)
    return det + 0.0


def _elimination(eliminate: str) -> bool:
    if eliminate not in ("x", "y"):
        raise ValueError(f"eliminate: expected 'x' or 'y', got {eliminate!r}")
    return eliminate == "x"


def curve_resultant(f, g, eliminate: str = "y") -> np.ndarray:
    """Res_y(f, g) (or Res_x): ascending coefficients (k,) of a polynomial in the other variable. Notes §19.3.

    f, g: c[i, j] of xⁱ yʲ. With eliminate="y", f and g are treated as
    polynomials in y with coefficients that depend on x; the
    determinant of their Sylvester matrix (the sign of SymPy's
    `resultant(f, g, y)`) is a polynomial in x of degree at most
    deg f · deg g, zero at the x of every common point (and of common points
    at infinity in the y direction). Computed exactly as a determinant of
    polynomials. Trailing zeros are dropped; a common factor of f and g gives
    the zero polynomial [0.]. The notes' circle and hyperbola of Figure 19.5:

    >>> circle = [[-4, -15, 6], [-2, 0, 0], [6, 0, 0]]
    >>> hyperbola = [[-1, 0, -1], [0, 0, 0], [1, 0, 0]]
    >>> curve_resultant(circle, hyperbola).round(9).tolist()             # 144x⁴ - 48x³ - 461x² + 40x + 325
    [325.0, 40.0, -461.0, -48.0, 144.0]
    >>> curve_resultant(circle, hyperbola, eliminate="x").round(9).tolist()   # 144y⁴ - 360y³ + 269y² - 60y
    [0.0, -60.0, 269.0, -360.0, 144.0]
    """
    a, b = _implicit(f, "f", constant_ok=True), _implicit(g, "g", constant_ok=True)
    if _elimination(eliminate):
        a, b = a.T, b.T
    return _trimmed(_resultant_y(a, b), 0.0)


def curve_discriminant(c, eliminate: str = "y") -> np.ndarray:
    """Res_y(f, ∂f/∂y) (or Res_x(f, ∂f/∂x)): its roots are the x of vertical tangents and singular points. §19.4.

    Seen along y, the curve's outline, its silhouette, turns back where the
    tangent is vertical, and branches cross at its singular points: both are
    where f(x, ·) has a repeated root. Ascending coefficients; ordinary double
    points give double roots. Not every real root is such a point: the
    repeated root may be a complex y, or the leading coefficient of f in y may
    vanish there (a vertical asymptote, as x = 0 for xy - 1, whose
    discriminant is x).

    >>> f = [[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0], [1, 0, 0, 0]]       # the cubic of §19.5
    >>> curve_discriminant(f).round(9).tolist()                  # (x - 2)² (27x² - 68x - 8): a double root at x = 2
    [-32.0, -240.0, 372.0, -176.0, 27.0]
    """
    a = _implicit(c)
    transpose = _elimination(eliminate)
    if transpose:
        a = a.T
    if a.shape[1] < 2 or not np.any(a[:, 1:]):
        raise ValueError(f"c: f does not depend on {eliminate}, so it has no discriminant in {eliminate}")
    derivative = P.polyder(a, axis=1)
    return _trimmed(_resultant_y(a, derivative), 0.0)


def _real_roots(r: np.ndarray) -> np.ndarray:
    if len(r) < 2:
        return np.zeros(0)
    roots = P.polyroots(r)
    real = np.abs(roots.imag) <= RESULTANT_IMAG_TOL * np.maximum(1.0, np.abs(roots))
    values = _merged(np.sort(roots[real].real))
    # Polish each root by a few Newton steps on r (simple roots gain digits; multiple ones do not move far).
    dr = P.polyder(r)
    for _ in range(3):
        slope = P.polyval(values, dr)
        step = np.where(np.abs(slope) > 1e-300, P.polyval(values, r) / np.where(slope == 0, 1.0, slope), 0.0)
        ok = np.abs(step) <= 1e-6 * np.maximum(1.0, np.abs(values))
        values = np.where(ok, values - step, values)
    return values


def _column_at(c: np.ndarray, x: float) -> np.ndarray:
    """f(x, y) as ascending coefficients in y."""
    return P.polyval(x, c) if c.shape[0] > 1 else c[0].copy()


def _intersect(f: np.ndarray, g: np.ndarray, transpose: bool) -> np.ndarray:
    a, b = (f.T, g.T) if transpose else (f, g)
    r = _resultant_y(a, b)
    bound = np.abs(a).sum() ** max(_y_degree(b), 1) * np.abs(b).sum() ** max(_y_degree(a), 1)
    if np.abs(r).max() <= 1e-12 * bound:
        raise ValueError("f, g: the curves share a component (their resultant vanishes identically)")
    points = []
    for x0 in _real_roots(_trimmed(r, 0.0)):
        ha, hb = _column_at(a, x0), _column_at(b, x0)
        sizes = [P.polyval(max(1.0, abs(x0)), np.abs(c)).max() for c in (a, b)]
        if np.abs(ha).max() <= 1e-10 * sizes[0] and np.abs(hb).max() <= 1e-10 * sizes[1]:
            raise ValueError(f"f, g: the curves share a component (the line {'y' if transpose else 'x'} = "
                             f"{x0:.6g} lies on both)")
        scale = max(np.abs(ha).max(), np.abs(hb).max())
        ha, hb = _trimmed(ha, 1e-13 * scale), _trimmed(hb, 1e-13 * scale)
        candidates = np.zeros(0)
        if ha.any() or hb.any():
            d = poly_gcd(ha, hb, tol=1e-7)
            candidates = _real_roots(d)
            if candidates.size == 0:
                # Rounding in x0 can hide the common root from Euclid: try the roots of the lower-degree one.
                lower = min((h for h in (ha, hb) if len(h) > 1), key=len, default=np.zeros(1))
                candidates = _real_roots(lower)
        for y0 in candidates:
            points.append((x0, y0))
    if not points:
        return np.zeros((0, 2))
    pts = np.array(points)
    pts = pts[:, ::-1] if transpose else pts
    return pts


def _finish_points(pts: np.ndarray, f: np.ndarray, g: np.ndarray, tol: float) -> np.ndarray:
    if len(pts) == 0:
        return np.zeros((0, 2))
    ok = np.ones(len(pts), dtype=bool)
    for c in (f, g):
        ok &= np.abs(P.polyval2d(pts[:, 0], pts[:, 1], c)) <= max(tol, RESIDUAL_TOL) * _size(c, pts)
    pts = pts[ok]
    pts = pts[np.lexsort((pts[:, 1], pts[:, 0]))]
    kept: list[np.ndarray] = []
    for p in pts:
        if not any(np.abs(p - q).max() <= ROOT_MERGE * max(1.0, np.abs(p).max()) for q in kept):
            kept.append(p)
    return np.array(kept).reshape(-1, 2) + 0.0


def implicit_intersections(f, g, tol: float = ZERO_TOL) -> np.ndarray:
    """The real points (k, 2) where f = 0 and g = 0 meet, sorted by x, then y, each once. Notes §19.3.

    f, g: c[i, j] of xⁱ yʲ. The x of every intersection is a root of
    Res_y(f, g) (`curve_resultant`); for each real root x_k the common roots of
    f(x_k, y) and g(x_k, y) are the roots of their GCD (`algebra.poly_gcd`),
    the notes' "clever way" that needs only one resultant and pairs the x
    with their y. A GCD of degree 2 or more means several points on one
    vertical line, all found. Points are kept when f and g are both zero there
    to rounding; complex points and points at infinity are not returned; a
    tangency is one point. When both curves are unions of vertical lines
    (no y at all) the roles of x and y swap. (0, 2) when the curves do not
    meet; a common component (the resultant is zero, or a vertical line
    x = x_k lies on both) raises ValueError.

    >>> circle = [[-4, -15, 6], [-2, 0, 0], [6, 0, 0]]             # 6x² + 6y² - 2x - 15y - 4
    >>> hyperbola = [[-1, 0, -1], [0, 0, 0], [1, 0, 0]]            # x² - y² - 1
    >>> (implicit_intersections(circle, hyperbola) * 12).round(9).tolist()   # twelve times the four points
    [[-15.0, 9.0], [-13.0, 5.0], [12.0, 0.0], [20.0, 16.0]]
    """
    a, b = _implicit(f, "f"), _implicit(g, "g")
    tol = as_tolerance(tol, below_one=True)
    transpose = _y_degree(a) == 0 and _y_degree(b) == 0
    return _finish_points(_intersect(a, b, transpose), a, b, tol)


def singular_points(c, tol: float = ZERO_TOL) -> np.ndarray:
    """The real singular points (k, 2) of f = 0, where f = ∂f/∂x = ∂f/∂y = 0, sorted by x, then y. Notes §19.5.

    The intersections of f_x = 0 and f_y = 0 (`implicit_intersections`), kept
    where f is zero too: a common zero of the two derivatives need not be on the
    curve. A curve whose derivatives share a component (a repeated factor, or
    f_x ≡ 0 together with a line) raises ValueError; so does a curve of degree 1.

    >>> f = [[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0], [1, 0, 0, 0]]   # (29/12, 11/4) has f = -1/432
    >>> singular_points(f).round(9).tolist()
    [[2.0, 3.0]]
    """
    a = _implicit(c)
    tol = as_tolerance(tol, below_one=True)
    fx, fy = P.polyder(a, axis=0), P.polyder(a, axis=1)
    if not np.any(fx) or not np.any(fy):
        # f depends on one variable only: its singular points are the multiple roots, lines of them.
        if _degree(a) <= 1:
            raise ValueError("c: a line has no singular points to look for (degree 1)")
        raise ValueError("c: f depends on one variable only, so its curve is a set of parallel lines")
    if _degree(a) <= 1:
        raise ValueError("c: a line has no singular points to look for (degree 1)")
    pts = _intersect(fx, fy, _y_degree(fx) == 0 and _y_degree(fy) == 0)
    pts = _finish_points(pts, fx, fy, tol)
    if len(pts) == 0:
        return pts
    on = np.abs(P.polyval2d(pts[:, 0], pts[:, 1], a)) <= max(tol, RESIDUAL_TOL) * _size(a, pts)
    return pts[on]


# --- §19.5 parametrization by a pencil of lines ----------------------------------------------------------------


def parametrize_by_pencil(c, point, tol: float = ZERO_TOL) -> np.ndarray:
    """Rows X(t), Y(t), W(t), (3, n+1) ascending power coefficients: the curve as the pencil of lines through `point`.

    c: c[i, j] of xⁱ yʲ, total degree n >= 2; point (2,): a point of
    multiplicity exactly n-1 (any point of a conic, the double point of a
    cubic, a triple point of a quartic). Moved to the origin the curve is
    f_(n-1) + f_n (homogeneous parts); the line y - y0 = t (x - x0) meets it
    there n-1 times and in one more point, at x - x0 = -f_(n-1)(1, t) / f_n(1, t).
    So, with f_(n-1), f_n the parts of f moved to `point`,

        W(t) = f_n(1, t),  X(t) = x0 W(t) - f_(n-1)(1, t),  Y(t) = y0 W(t) - t f_(n-1)(1, t),

    and (X/W, Y/W) is the curve's point on the line of slope t (t = ∞, the
    vertical line, is left out). No rescaling: the rows come from the
    coefficients of c as they are. The lower parts must be zero to within tol
    times the largest coefficient of the moved polynomial (they are dropped);
    a point of another multiplicity raises ValueError, and so does a point of
    multiplicity n (the curve is then n lines through it). Notes §19.5.

    >>> parametrize_by_pencil([[0, 0, 1], [-2, 0, 0], [1, 0, 0]], (0, 0)).tolist()   # x² - 2x + y²: x = 2/(1+t²)
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 0.0, 1.0]]
    >>> f = [[-21, 25, -9, 1], [46, -23, 3, 0], [-13, 3, 0, 0], [1, 0, 0, 0]]       # double point (2, 3)
    >>> parametrize_by_pencil(f, (2, 3)).round(9).tolist()     # x = (2t³ - t)/(t+1)³, y = (-3t³ + 2t² + 7t + 3)/(t+1)³
    [[0.0, -1.0, 0.0, 2.0], [3.0, 7.0, 2.0, -3.0], [1.0, 3.0, 3.0, 1.0]]
    """
    tol = as_tolerance(tol, below_one=True)
    x0, y0 = as_vector(point, "point", dim=2)
    n = implicit_degree(c)
    if n < 2:
        raise ValueError("c: a line (degree 1) needs no pencil; give a curve of degree 2 or more")
    parts = homogeneous_parts(translate_implicit(c, x0, y0))  # f̂_0, ..., f̂_n at the point
    scale = max(np.abs(part).max() for part in parts)
    r = next((k for k, part in enumerate(parts) if np.abs(part).max() > tol * scale), len(parts))
    if r != n - 1:
        if r == n:
            raise ValueError(f"point: it has multiplicity {n} on a curve of degree {n}, so the curve is {n} lines "
                             "through it, not one curve to parametrize")
        what = "not on the curve" if r == 0 else f"of multiplicity {r}"
        raise ValueError(f"point: it is {what}, but the pencil needs a point of multiplicity n - 1 = {n - 1}")
    # f̂_k(1, t) = Σ_j γ_j t^j when f̂_k(a, b) = Σ_j γ_j a^(k-j) b^j: the parts are already ascending in t.
    W = parts[n]  # f̂_n(1, t)
    low = np.append(parts[n - 1], 0.0)  # f̂_(n-1)(1, t), padded to n + 1 coefficients
    t_low = np.insert(parts[n - 1], 0, 0.0)  # t f̂_(n-1)(1, t)
    return np.array([x0 * W - low, y0 * W - t_low, W]) + 0.0


def _rows(xyw) -> np.ndarray:
    rows = as_float_array(xyw, "xyw")
    if rows.ndim != 2 or rows.shape[0] != 3 or rows.shape[1] == 0:
        raise ValueError(f"xyw: expected the rows X, Y, W of shape (3, n+1), got shape {rows.shape}")
    return rows


def pencil_point(xyw, t) -> np.ndarray:
    """The point (X(t)/W(t), Y(t)/W(t)) of a parametrization (3, n+1): (2,) for a number t, (k, 2) for k values. §19.5.

    W(t) = 0 is a point at infinity: ValueError naming the t.

    >>> pencil_point([[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [1.0, 0.0, 1.0]], [1.0, 1 / 3, 0.0, -0.5]).round(9).tolist()
    [[1.0, 1.0], [1.8, 0.6], [2.0, 0.0], [1.6, -0.8]]
    """
    rows = _rows(xyw)
    ts, single = as_parameter(t)
    values = np.stack([P.polyval(ts, rows[k]) for k in range(3)], axis=-1)
    w = values[:, 2]
    scale = np.abs(values).max(axis=1, initial=0.0)
    if np.any(np.abs(w) <= 1e-14 * np.maximum(scale, 1e-300)):
        bad = ts[np.abs(w) <= 1e-14 * np.maximum(scale, 1e-300)]
        raise ValueError(f"t: W(t) = 0, a point at infinity, at t = {bad.tolist()}")
    out = values[:, :2] / w[:, None]
    return out[0] if single else out


def pencil_bezier(xyw, interval=(0.0, 1.0)) -> tuple[np.ndarray, np.ndarray]:
    """The parametrization (3, n+1) over `interval` as a rational Bézier curve: (points, weights). Notes §19.5.

    The power coefficients of (X, Y, W) are converted to Bernstein form on
    the interval (`polynomials.power_to_bernstein`) and projected; a zero
    weight (a control point at infinity) raises ValueError. The pencil
    parametrization x = 12t² - 9, y = 12t³ - 9t of x³ + 9x² - 12y², over
    [-1, 1], gives the notes' control points of Figure 19.2 in reverse order:

    >>> points, weights = pencil_bezier([[-9, 0, 12, 0], [0, -9, 0, 12], [1, 0, 0, 0]], (-1, 1))
    >>> points.round(9).tolist(), weights.tolist()
    ([[3.0, -3.0], [-13.0, 15.0], [-13.0, -15.0], [3.0, 3.0]], [1.0, 1.0, 1.0, 1.0])
    """
    rows = _rows(xyw)
    lo, hi = as_interval(interval)
    h = power_to_bernstein(rows.T, (lo, hi))
    return from_homogeneous(h)


# --- §19.6 undetermined coefficients ---------------------------------------------------------------------------


def conic_through_points(points) -> np.ndarray:
    """The conic through five points, as c (3, 3) in the layout of `algebra.implicitize`, scaled so max |c| = 1 > 0.

    points: (5, 2). Each point gives one row (x², xy, y², x, y, 1) of a 5×6
    homogeneous system for (c20, c11, c02, c10, c01, c00); its null vector
    (SVD, columns scaled to unit length first) is the conic, unique up to a
    factor when the points are in general position. Three collinear points
    are fine (the conic is then a pair of lines); when the null space has
    more than one dimension (two points coincide, or four lie on one line)
    there is no single conic: ValueError. Entries with i + j > 2 are zero; the
    coefficient of largest magnitude is +1. Notes §19.6.

    >>> conic_through_points([(1, 0), (0, 1), (-1, 0), (0, -1), (0.6, 0.8)]).round(9).tolist()   # x² + y² - 1
    [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    pts = as_points(points)
    if pts.shape != (5, 2):
        raise ValueError(f"points: expected five planar points, shape (5, 2), got shape {pts.shape}")
    x, y = pts[:, 0], pts[:, 1]
    matrix = np.column_stack([x * x, x * y, y * y, x, y, np.ones(5)])
    norms = np.linalg.norm(matrix, axis=0)
    norms[norms == 0] = 1.0
    singular, vt = np.linalg.svd(matrix / norms)[1:]
    if singular[-1] <= RANK_TOL * singular[0]:  # RANK_TOL = 1e-9: the null space is not one line
        raise ValueError("points: they do not fix one conic (two coincide, or four lie on one line)")
    v = vt[-1] / norms
    c = np.zeros((3, 3))
    c[2, 0], c[1, 1], c[0, 2], c[1, 0], c[0, 1], c[0, 0] = v
    big = c.flat[np.argmax(np.abs(c))]
    c = c / big
    c[np.abs(c) <= 1e-15] = 0.0  # rounding noise of exact zeros
    return c + 0.0


def circle_through_points(p1, p2, p3) -> tuple[np.ndarray, float]:
    """The circle through three points: (centre (2,), radius), from A x + B y + C = x² + y². Notes §19.6.

    The three points give a 3×3 linear system for A, B, C; the centre is
    (a, b) = (A/2, B/2) and the radius √(C + a² + b²). Collinear points (or
    two equal ones) raise ValueError.

    >>> centre, radius = circle_through_points((1, 2), (4, 6), (5, -1))
    >>> centre.round(9).tolist(), round(radius, 7)
    ([4.5, 2.5], 3.5355339)
    """
    pts = np.array([_point(p, name) for p, name in ((p1, "p1"), (p2, "p2"), (p3, "p3"))])
    matrix = np.column_stack([pts, np.ones(3)])
    span = max(np.abs(pts).max(), 1.0)
    twice_area = abs(np.linalg.det(matrix))
    if twice_area <= 1e-12 * (np.ptp(pts, axis=0).max() or 1.0) ** 2 or twice_area <= 1e-14 * span**2:
        raise ValueError("p1, p2, p3: the points are collinear (or two coincide): no circle passes through them")
    a, b, cc = np.linalg.solve(matrix, (pts**2).sum(axis=1))
    centre = np.array([a / 2, b / 2])
    return centre + 0.0, float(np.sqrt(cc + centre @ centre))

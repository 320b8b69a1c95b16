"""Algebraic geometry for CAGD: resultants, GCDs, implicitization, inversion and intersection: chapter 17 of the notes.

Three tools turn questions about parametric curves into algebra:

- **implicitization**: the equation f(x, y) = 0 of a rational curve
  (x, y) = (X(t), Y(t)) / W(t), as the resultant in t of x W - X and y W - Y;
- **inversion**: the parameter t of a point of the curve, as a ratio
  t = num(x, y) / den(x, y) of two polynomials;
- **intersection**: substitute one curve into the other's implicit equation,
  find the roots of that polynomial of degree m n, invert.

Conventions. A scalar polynomial is a 1-D array of **ascending power
coefficients** (`f[i]` multiplies tⁱ, as in `numpy.polynomial`); trailing
zeros are dropped, so `[12, -7, 1, 0]` is the quadratic t² - 7t + 12. A
bivariate polynomial is a 2-D array `c[i, j]`, the coefficient of xⁱ yʲ
(`numpy.polynomial.polynomial.polyval2d(x, y, c)` evaluates it). A planar
rational Bézier curve is points (n+1, 2) and weights None or (n+1,) nonzero.
Implicit equations and inversion formulas are defined up to a common factor.

The resultant follows Sylvester (and SymPy, see `resultant`): `resultant(f, g)` is the
determinant of the Sylvester matrix, which for monic f, g is the product of
the differences of their roots. The notes build the resultant as the
determinant of the Bézout matrix instead (`bezout_matrix`). The two are
conventions, tied by det Bez(f, g) = (-1)^(n(n-1)/2) a_n^(n-m) Res(f, g) for f of
degree n and g of degree m <= n (chapter 19 meets the same pair in the
discriminant).
Implicitization from the control points (`bezout_lines`, `implicitize`) is the
same Bézout construction applied to lines l_ij = C(n,i) C(n,j) (H_i × H_j) of
the homogeneous control points H_i = w_i (x_i, y_i, 1); chapter 18 (moving
lines) builds on it.

The functions ending in `_plain` (`resultant_plain`, `bezout_matrix_plain`,
`poly_gcd_plain`, `implicitize_plain`, `inversion_plain`, `invert_plain`,
`intersect_implicit_plain`) are the textbook forms of the algorithms, the
code the chapter shows; the tests check that they agree with the tuned ones.

Everything here is NumPy; the chapter checks it against SymPy's exact
`resultant`, `gcd` and `groebner`.
"""

from __future__ import annotations

from functools import lru_cache
from itertools import combinations
from math import comb, exp, log

import numpy as np
from numpy.polynomial import polynomial as P

from ._validation import as_count, as_float_array, as_points, as_scalar, as_tolerance
from .bezier import elevate, evaluate, to_homogeneous
from .intersection import curve_implicit_bernstein
from .polynomials import bernstein_multiply, bernstein_to_power
from .roots import bernstein_roots

__all__ = [
    "coefficients",
    "homogeneous_points",
    "sylvester_matrix",
    "resultant",
    "resultant_plain",
    "root_product",
    "bezout_matrix",
    "bezout_from_brackets",
    "bezout_matrix_plain",
    "fraction_free_eliminate",
    "cramer_null_vector",
    "common_root_count",
    "euclid_steps",
    "poly_gcd",
    "poly_gcd_plain",
    "common_roots",
    "l_lines",
    "bezout_lines",
    "power_bezout_lines",
    "implicitize",
    "line_determinant",
    "implicitize_plain",
    "implicitize_power",
    "implicit_eval",
    "cubic_inversion_lines",
    "inversion",
    "invert",
    "inversion_plain",
    "invert_plain",
    "intersection_polynomial",
    "intersect_implicit",
    "intersect_implicit_plain",
    "surface_implicit_degree",
    "term_count",
    "sort_terms",
]

# An implicit equation whose coefficients are all below this fraction of the Hadamard bound of its matrix is zero:
# the curve's formal degree exceeds its true degree (a degree-raised curve).
VANISHING = 1e-10
# A null space direction counts when its singular value is below this fraction of the largest one.
NULL_TOL = 1e-9
# Bernstein roots of the intersection polynomial closer than this are one (a tangency).
ROOT_MERGE = 1e-7


# --- input checking ---------------------------------------------------------------------------------------------


def _poly(f, name: str) -> np.ndarray:
    """Ascending power coefficients (n+1,) with trailing zeros dropped; the zero polynomial is [0.]."""
    c = as_float_array(f, name)
    if c.ndim != 1 or c.size == 0:
        raise ValueError(f"{name}: expected ascending power coefficients of shape (n+1,), got shape {c.shape}")
    nonzero = np.flatnonzero(c)
    return c[: nonzero[-1] + 1] if nonzero.size else c[:1]


def _nonzero_poly(f, name: str) -> np.ndarray:
    c = _poly(f, name)
    if not c.any():
        raise ValueError(f"{name}: the zero polynomial has no degree (every number is a root of it)")
    return c


def coefficients(f, name: str = "f", zero_ok: bool = False) -> np.ndarray:
    """Ascending power coefficients (n+1,) of a polynomial, trailing zeros dropped: its true degree is n. Notes §17.3.

    Rejects what is not a 1-D array of finite numbers, and the zero polynomial
    (which has no degree) unless `zero_ok`, which gives it as [0.].

    >>> coefficients([12, -7, 1, 0]).tolist()          # t² - 7t + 12
    [12.0, -7.0, 1.0]
    """
    return _poly(f, name) if zero_ok else _nonzero_poly(f, name)


def homogeneous_points(points, weights=None, name: str = "points", weights_name: str = "weights") -> np.ndarray:
    """The homogeneous control points H_i = w_i (x_i, y_i, 1), (n+1, 3), of a planar rational Bézier curve. §17.6.

    points: (n+1, 2) with n >= 1; weights: None (all 1) or (n+1,) nonzero.
    Errors name the arguments as `name` and `weights_name`.

    >>> homogeneous_points([(4.0, 1.0), (5.0, 6.0)], [1.0, 2.0]).tolist()
    [[4.0, 1.0, 1.0], [10.0, 12.0, 2.0]]
    """
    return _homogeneous(points, weights, name, weights_name)


def _homogeneous(points, weights, name: str = "points", weights_name: str = "weights") -> np.ndarray:
    """Planar control points (n+1, 2), n >= 1, and optional weights -> rows w (x, y, 1), (n+1, 3)."""
    pts = as_points(points, name, min_count=2)
    if pts.shape[1] != 2:
        raise ValueError(f"{name}: expected planar control points of shape (n+1, 2), got shape {pts.shape}")
    if weights is None:
        return np.column_stack([pts, np.ones(len(pts))])
    w = as_float_array(weights, weights_name)
    if w.shape != (len(pts),):
        raise ValueError(f"{weights_name}: expected {len(pts)} weights (one per control point), got shape {w.shape}")
    if np.any(w == 0):
        raise ValueError(f"{weights_name}: weights must be nonzero, got {w.tolist()}")
    return to_homogeneous(pts, w)


def _xy(xy) -> tuple[np.ndarray, bool]:
    """Points (2,) or (k, 2) as (k, 2), and whether one point came in."""
    pts = as_float_array(xy, "xy")
    if pts.shape == (2,):
        return pts[None, :], True
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise ValueError(f"xy: expected a point (2,) or points (k, 2), got shape {pts.shape}")
    return pts, False


# --- §17.3 resultants -------------------------------------------------------------------------------------------


def _sylvester(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    m, n = len(a) - 1, len(b) - 1
    s = np.zeros((m + n, m + n))
    for r in range(n):
        s[r, r : r + m + 1] = a[::-1]
    for r in range(m):
        s[n + r, r : r + n + 1] = b[::-1]
    return s


def sylvester_matrix(f, g) -> np.ndarray:
    """The Sylvester matrix (n+m, n+m) of f (degree n) and g (degree m), ascending power coefficients. Notes §17.3.

    Its first m rows hold f's coefficients from the highest power down, each
    row shifted one column right of the one above (the polynomials t^(m-1) f,
    ..., t f, f); the last n rows do the same for g. A row vector (u, v) times
    it gives the coefficients of u f + v g (deg u < m, deg v < n). Its
    determinant is the resultant (`resultant`). Trailing zeros of f and g are
    dropped first; the zero polynomial is rejected.

    >>> sylvester_matrix([12.0, -7.0, 1.0], [2.0, -3.0, 1.0]).tolist()
    [[1.0, -7.0, 12.0, 0.0], [0.0, 1.0, -7.0, 12.0], [1.0, -3.0, 2.0, 0.0], [0.0, 1.0, -3.0, 2.0]]
    """
    a, b = coefficients(f, "f"), coefficients(g, "g")  # trailing zeros dropped
    n, m = len(a) - 1, len(b) - 1  # the degrees of f and g
    s = np.zeros((n + m, n + m))
    for r in range(m):  # the m rows of f: t^(m-1) f, ..., t f, f
        s[r, r : r + n + 1] = a[::-1]  # highest power first
    for r in range(n):  # the n rows of g: t^(n-1) g, ..., t g, g
        s[m + r, r : r + m + 1] = b[::-1]
    return s


def _resultant(a: np.ndarray, b: np.ndarray) -> float:
    m, n = len(a) - 1, len(b) - 1
    if m == 0 or n == 0:
        return float(a[0] ** n * b[0] ** m)
    # Res(αf, βg) = αⁿ βᵐ Res(f, g): determinant of the equilibrated matrix, the scales put back through logarithms,
    # so that degree-20 resultants of large coefficients neither overflow nor lose digits.
    # Scaling by powers of two is exact, so integer data keep their integer resultants to rounding of the LU alone.
    sa, sb = (2.0 ** np.round(np.log2(np.abs(c).max())) for c in (a, b))
    matrix = _sylvester(a / sa, b / sb)
    with np.errstate(over="ignore"):
        value = np.linalg.det(matrix) * sa**n * sb**m
    if not np.isfinite(value):
        sign, logdet = np.linalg.slogdet(matrix)
        value = sign * exp(min(logdet + n * log(sa) + m * log(sb), 710.0))
        if not np.isfinite(value):
            raise ValueError("f, g: the resultant overflows double precision")
    return float(value) + 0.0


def resultant(f, g) -> float:
    """The resultant Res(f, g), Sylvester's determinant (the sign of SymPy's `resultant`). Notes §17.3.

    f, g: ascending power coefficients (n+1,) and (m+1,), trailing zeros
    dropped (the true degrees count). Res(f, g) = 0 exactly when f and g have a
    common root (their leading coefficients being nonzero by construction).
    For f = a ∏(t - f_i), g = b ∏(t - g_j) it equals aᵐ bⁿ ∏∏ (f_i - g_j),
    so Res(g, f) = (-1)^(mn) Res(f, g); a constant c gives Res(c, g) = cᵐ and
    Res(c1, c2) = 1. The zero polynomial is rejected. The determinant is taken
    of the matrix scaled by powers of two (exact), so that high degrees neither
    overflow nor lose digits; `resultant_plain` is the same without the scaling.

    The notes' determinants are Bézout's (`bezout_matrix`), another convention:
    det Bez = (-1)^(n(n-1)/2) a_nⁿ⁻ᵐ Res(f, g), so the notes' -1611 for two cubics
    is the Bézout value of the resultant that is 1611 here.

    SymPy's `resultant(f, g, t)` agrees except when deg f < deg g and both
    degrees are odd: it then returns Res(g, f) = -Res(f, g) (sympy/sympy#10666,
    open in SymPy 1.14); `sylvester(f, g, t, method=1).det()` always agrees.

    Ref: J. J. Sylvester, Philosophical Magazine 16, 1840.

    >>> round(resultant([12.0, -7.0, 1.0], [2.0, -3.0, 1.0]), 9)   # (t-3)(t-4), (t-1)(t-2): (3-2)(3-1)(4-2)(4-1)
    12.0
    >>> round(resultant([1.0, 3.0, -2.0, 1.0], [4.0, -1.0, 3.0, 2.0]), 6)
    1611.0
    >>> abs(round(resultant([-4.0, -11.0, -1.0, 1.0], [4.0, -5.0, -7.0, 2.0]), 9))   # common root t = 4
    0.0
    """
    return _resultant(_nonzero_poly(f, "f"), _nonzero_poly(g, "g"))


def resultant_plain(f, g) -> float:
    """Res(f, g) as the determinant of the Sylvester matrix: the plain form of `resultant`. Notes §17.3.

    >>> round(resultant_plain([1.0, 3.0, -2.0, 1.0], [4.0, -1.0, 3.0, 2.0]), 6)
    1611.0
    """
    return float(np.linalg.det(sylvester_matrix(f, g)))


def _roots(values, name: str) -> np.ndarray:
    if values is None or isinstance(values, (str, bytes, dict, set)):
        raise TypeError(f"{name}: expected numbers, got {type(values).__name__}")
    try:
        r = np.array(values, dtype=complex)
    except (TypeError, ValueError) as err:
        raise TypeError(f"{name}: expected numbers ({err})") from None
    if r.ndim != 1:
        raise ValueError(f"{name}: expected a 1-D list of roots, got shape {r.shape}")
    if not np.all(np.isfinite(r)):
        raise ValueError(f"{name}: expected finite roots, got NaN or infinity")
    return r


def root_product(f_roots, g_roots, f_lead=1.0, g_lead=1.0) -> float | complex:
    """aⁿ bᵐ ∏_i ∏_j (f_i - g_j), the resultant from the roots (17.3), generalised to leading coefficients a, b.

    f_roots (m,), g_roots (n,): the roots, real or complex (with multiplicity);
    f_lead, g_lead: the leading coefficients a and b. A real number when the
    result is real to rounding (roots in conjugate pairs). Notes §17.3, (17.2)-(17.3).

    >>> root_product([3.0, 4.0], [2.0, 1.0])
    12.0
    """
    fr, gr = _roots(f_roots, "f_roots"), _roots(g_roots, "g_roots")
    a, b = as_scalar(f_lead, "f_lead"), as_scalar(g_lead, "g_lead")
    value = a ** len(gr) * b ** len(fr) * np.prod(fr[:, None] - gr[None, :])
    if abs(value.imag) <= 1e-12 * max(abs(value), 1.0):
        return float(value.real)
    return complex(value)


# --- the Bézout matrix: one kernel for numbers, power-form curves and Bézier curves ------------------------------


@lru_cache(maxsize=32)
def _bezout_terms(n: int) -> tuple[np.ndarray, ...]:
    """Index arrays (row, column, k, m) of every bracket (k m) in the n×n Bézout matrix.

    Entry (r, c) is L_{i,j} with i = n-1-r, j = n-1-c, the sum of the
    brackets (k m) with m <= min(i, j), k + m = i + j + 1, k <= n.
    """
    terms = [(n - 1 - i, n - 1 - j, i + j + 1 - m, m)
             for i in range(n) for j in range(n) for m in range(min(i, j) + 1) if i + j + 1 - m <= n]
    if not terms:
        return (np.zeros(0, int),) * 4
    return tuple(np.array(column, dtype=int) for column in zip(*terms))


def _bezout_forms(rows: np.ndarray) -> np.ndarray:
    """(n, n, 3) Bézout matrix whose brackets are cross products rows[k] × rows[m] of rows (n+1, 3)."""
    n = len(rows) - 1
    cross = np.cross(rows[:, None, :], rows[None, :, :])
    r, c, k, m = _bezout_terms(n)
    forms = np.zeros((n, n, 3))
    np.add.at(forms, (r, c), cross[k, m])
    return forms


def bezout_matrix(f, g) -> np.ndarray:
    """The notes' Bézout matrix (n, n) of f and g (ascending coefficients), padded to one degree n. Notes §17.3 (17.8).

    With brackets (a_k b_m) = a_k b_m - a_m b_k, row r = n-1-i, column
    c = n-1-j holds Σ (a_k b_m) over m <= min(i, j), k = i+j+1-m <= n. It is
    symmetric, and its rows are the coefficients of the auxiliary polynomials
    h_1 .. h_n against [t^(n-1), ..., t, 1]: a common root of f and g makes
    B [t^(n-1), ..., 1]ᵀ = 0. det B = (-1)^(n(n-1)/2) a_nⁿ⁻ᵐ Res(f, g) when g
    has degree m <= n = deg f. Two constants give a (0, 0) matrix.

    Ref: SymPy `subresultants_qq_zz.bezout(f, g, t, method='prs')` (the same matrix, entry for entry).

    >>> bezout_matrix([1.0, 3.0, -2.0, 1.0], [4.0, -1.0, 3.0, 2.0]).tolist()
    [[7.0, -7.0, 2.0], [-7.0, -5.0, -11.0], [2.0, -11.0, 13.0]]
    >>> bezout_matrix([12.0, -7.0, 1.0], [2.0, -3.0, 1.0]).tolist()
    [[4.0, -10.0], [-10.0, 22.0]]
    """
    a, b = _nonzero_poly(f, "f"), _nonzero_poly(g, "g")
    n = max(len(a), len(b)) - 1
    rows = np.zeros((n + 1, 3))
    rows[: len(a), 0], rows[: len(b), 1] = a, b
    return _bezout_forms(rows)[:, :, 2] + 0.0


def bezout_from_brackets(brackets) -> np.ndarray:
    """The n×n Bézout matrix assembled from its brackets (n+1, n+1, ...): the rule (17.8). Notes §17.3, §17.6.

    brackets[k, m] is the bracket (a_k b_m) = a_k b_m - a_m b_k of two
    polynomials of degree n (a number), or the line l_km of a Bézier curve (an
    array (3,)). Rows and columns are counted i, j = n-1, ..., 0 from the top
    left, and entry (i, j) is the sum of brackets[k, m] over m <= min(i, j)
    with k = i + j + 1 - m <= n.

    >>> bezout_from_brackets(np.array([[0, -1, 2], [1, 0, 3], [-2, -3, 0]])).tolist()   # (a2 b1), (a2 b0); (a1 b0)
    [[-3.0, -2.0], [-2.0, 1.0]]
    """
    brackets = as_float_array(brackets, "brackets")
    if brackets.ndim < 2 or brackets.shape[0] != brackets.shape[1] or brackets.shape[0] < 1:
        raise ValueError(f"brackets: expected an array (n+1, n+1, ...), got shape {brackets.shape}")
    n = len(brackets) - 1
    matrix = np.zeros((n, n) + brackets.shape[2:])
    for r, i in enumerate(range(n - 1, -1, -1)):
        for c, j in enumerate(range(n - 1, -1, -1)):
            for m in range(min(i, j) + 1):
                k = i + j + 1 - m
                if k <= n:
                    matrix[r, c] += brackets[k, m]
    return matrix


def bezout_matrix_plain(f, g) -> np.ndarray:
    """The notes' Bézout matrix (17.8) from its brackets: the plain form of `bezout_matrix`. Notes §17.3.

    >>> bezout_matrix_plain([1.0, 3.0, -2.0, 1.0], [4.0, -1.0, 3.0, 2.0]).tolist()
    [[7.0, -7.0, 2.0], [-7.0, -5.0, -11.0], [2.0, -11.0, 13.0]]
    """
    a, b = coefficients(f, "f"), coefficients(g, "g")
    n = max(len(a), len(b)) - 1
    a, b = np.pad(a, (0, n + 1 - len(a))), np.pad(b, (0, n + 1 - len(b)))  # the lower degree padded
    brackets = np.outer(a, b) - np.outer(b, a)  # brackets[k, m] = a_k b_m - a_m b_k
    return bezout_from_brackets(brackets) + 0.0


# --- §17.4 the common root ----------------------------------------------------------------------------------------


def _square(matrix, name: str = "matrix") -> np.ndarray:
    m = as_float_array(matrix, name)
    if m.ndim != 2:
        raise ValueError(f"{name}: expected a 2-D array, got shape {m.shape}")
    return m


def fraction_free_eliminate(matrix, tol: float = 1e-14) -> np.ndarray:
    """Row echelon form by fraction-free (Bareiss) elimination: integers stay integers. Notes §17.4.

    matrix: (r, c). Step k replaces every entry below and right of the pivot
    by (M_kk M_ij - M_ik M_kj) / (previous pivot), an exact division for
    integer data; a zero pivot is swapped with a lower row (and the row
    negated, to keep the determinant), a column with no pivot is skipped. The
    last pivot of a square nonsingular matrix is its determinant; the number
    of nonzero rows is the rank, so for a Bézout matrix n - rank counts the
    common roots (`common_root_count`). tol: an entry below tol times the
    largest one counts as zero when a pivot is sought.

    Ref: E. H. Bareiss, Sylvester's identity and multistep integer-preserving Gaussian elimination, Math. Comp. 1968.

    >>> fraction_free_eliminate([[7.0, -7.0, 2.0], [-7.0, -5.0, -11.0], [2.0, -11.0, 13.0]]).tolist()
    [[7.0, -7.0, 2.0], [0.0, -84.0, -63.0], [0.0, 0.0, -1611.0]]
    """
    m = as_float_array(matrix, "matrix")  # a copy: the input is not changed
    if m.ndim != 2:
        raise ValueError(f"matrix: expected a 2-D array, got shape {m.shape}")
    zero = as_tolerance(tol, below_one=True) * np.abs(m).max(initial=0.0)
    rows, cols = m.shape
    previous, r = 1.0, 0  # the previous pivot, and the row that gets the next one
    for c in range(cols):
        if r == rows:
            break
        nonzero = np.flatnonzero(np.abs(m[r:, c]) > zero)
        if nonzero.size == 0:  # no pivot in this column: go on to the next one
            m[r:, c] = 0.0
            continue
        p = r + int(nonzero[0])
        if p != r:  # swap the pivot row up, negated so that the determinant is kept
            m[[r, p]] = m[[p, r]]
            m[r] = -m[r]
        pivot = m[r, c]
        # every entry below and right of the pivot: (M_kk M_ij - M_ik M_kj) / previous pivot, exact for integers
        m[r + 1 :, c + 1 :] = (pivot * m[r + 1 :, c + 1 :] - np.outer(m[r + 1 :, c], m[r, c + 1 :])) / previous
        m[r + 1 :, c] = 0.0
        previous, r = pivot, r + 1
    m[r:] = 0.0
    return m + 0.0


def cramer_null_vector(matrix) -> np.ndarray:
    """The null vector of an (n-1, n) matrix by Cramer's rule: v_j = (-1)^j (the minor without column j). Notes §17.4.

    For two rows of three this is their cross product. Applied to the first
    n-1 rows of a singular Bézout matrix it gives (T^(n-1), T^(n-2)U, ..., U^(n-1))
    at the common root t = T/U; it is zero when those rows are dependent (more
    than one common root, or a special position).

    >>> cramer_null_vector([[-5.0, 17.0, 12.0], [17.0, -60.0, -32.0]]).round(9).tolist()   # t = 176/44 = 44/11 = 4
    [176.0, 44.0, 11.0]
    """
    m = _square(matrix)
    if m.shape[1] != m.shape[0] + 1:
        raise ValueError(f"matrix: expected shape (n-1, n), got {m.shape}")
    n = m.shape[1]
    return np.array([(-1) ** j * np.linalg.det(np.delete(m, j, axis=1)) if n > 1 else 1.0 for j in range(n)]) + 0.0


def common_root_count(f, g, tol: float = 1e-9) -> int:
    """The number of common roots (with multiplicity, complex ones too) of f and g: n - rank of the Bézout matrix.

    The rank is numerical: singular values below tol times the largest one
    count as zero. Requires deg f = n (pad g, not f). Notes §17.4.

    >>> common_root_count([-6.0, 11.0, -6.0, 1.0], [-8.0, 14.0, -7.0, 1.0])     # t = 1 and t = 2
    2
    """
    a, b = _nonzero_poly(f, "f"), _nonzero_poly(g, "g")
    tol = as_tolerance(tol, below_one=True)
    if len(b) > len(a):
        a, b = b, a
    matrix = bezout_matrix(a, b)
    if matrix.size == 0:
        return 0
    singular = np.linalg.svd(matrix, compute_uv=False)
    return int(len(matrix) - np.count_nonzero(singular > tol * singular[0]))


def _trimmed(r: np.ndarray, zero: float) -> np.ndarray:
    """r with its leading (highest) coefficients below `zero` removed; all of them gone is the zero polynomial [0.]."""
    keep = np.flatnonzero(np.abs(r) > zero)
    return r[: keep[-1] + 1].copy() if keep.size else np.zeros(1)


def _euclid(a: np.ndarray, b: np.ndarray, tol: float) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    if len(a) < len(b):
        a, b = b, a
    steps = []
    while b.any():
        q, r = P.polydiv(a, b)
        # A remainder coefficient is rounding noise when it is tiny next to the polynomials it came from.
        r = _trimmed(r, tol * max(np.abs(a).max(), np.abs(b).max()))
        steps.append((a, b, q, r))
        a, b = b, r
    return steps


def euclid_steps(f, g, tol: float = 1e-9) -> list[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """Euclid's algorithm on polynomials: every step (dividend, divisor, quotient, remainder), ascending. Notes §17.4.

    The higher-degree polynomial is divided first (f on a tie); then divisor
    and remainder move up until the remainder is zero. The last step's
    divisor is the GCD (up to scale). In floating point a remainder
    coefficient counts as zero when it is below tol times the largest
    coefficient of that step's dividend and divisor.

    >>> for a, b, q, r in euclid_steps([4.0, -1.0, 3.0, 2.0], [1.0, 3.0, -2.0, 1.0]):
    ...     print(np.round(q, 6).tolist(), np.round(r, 6).tolist())
    [2.0] [2.0, -7.0, 7.0]
    [-0.142857, 0.142857] [1.285714, 1.714286]
    [-7.145833, 4.083333] [11.1875]
    [0.114924, 0.153232] [0.0]
    """
    a, b = _poly(f, "f"), _poly(g, "g")
    tol = as_tolerance(tol, below_one=True)
    if not a.any() and not b.any():
        raise ValueError("f, g: both are the zero polynomial, whose GCD is undefined")
    return _euclid(a, b, tol)


def poly_gcd(f, g, tol: float = 1e-9) -> np.ndarray:
    """The monic greatest common divisor of f and g by Euclid's algorithm, ascending power coefficients. Notes §17.4.

    f, g: ascending power coefficients (float input is fine); one of them may
    be the zero polynomial (gcd(f, 0) is f made monic), not both. The result is
    the last nonzero remainder divided by its leading coefficient: [1.] when
    f and g have no common root. tol: the relative size below which a
    remainder's coefficient is rounding noise (see `euclid_steps`).

    >>> poly_gcd([-4.0, -11.0, -1.0, 1.0], [4.0, -5.0, -7.0, 2.0]).round(9).tolist()      # t - 4
    [-4.0, 1.0]
    >>> poly_gcd([-6.0, 11.0, -6.0, 1.0], [-8.0, 14.0, -7.0, 1.0]).round(9).tolist()      # t² - 3t + 2
    [2.0, -3.0, 1.0]
    >>> poly_gcd([1.0, 3.0, -2.0, 1.0], [4.0, -1.0, 3.0, 2.0]).tolist()                   # no common root
    [1.0]
    """
    a, b = _poly(f, "f"), _poly(g, "g")
    tol = as_tolerance(tol, below_one=True)
    if not a.any() and not b.any():
        raise ValueError("f, g: both are the zero polynomial, whose GCD is undefined")
    steps = _euclid(a, b, tol)
    last = steps[-1][1] if steps else (a if a.any() else b)
    return last / last[-1] + 0.0


def poly_gcd_plain(f, g, tol: float = 1e-9) -> np.ndarray:
    """The monic GCD by Euclid's algorithm with a relative zero test: the plain form of `poly_gcd`. Notes §17.4.

    >>> poly_gcd_plain([-4.0, -11.0, -1.0, 1.0], [4.0, -5.0, -7.0, 2.0]).round(9).tolist()      # t - 4
    [-4.0, 1.0]
    """
    a = np.trim_zeros(coefficients(f, "f", zero_ok=True), "b")  # the zero polynomial: empty
    b = np.trim_zeros(coefficients(g, "g", zero_ok=True), "b")
    tol = as_tolerance(tol, below_one=True)
    if a.size == 0 and b.size == 0:
        raise ValueError("f, g: both are the zero polynomial, whose GCD is undefined")
    if len(a) < len(b):
        a, b = b, a  # divide the higher degree by the lower
    while b.size:
        r = P.polydiv(a, b)[1]
        zero = tol * max(np.abs(a).max(), np.abs(b).max())  # rounding noise next to a and b
        while r.size and abs(r[-1]) <= zero:  # drops the noise from the top; all of it: r = 0
            r = r[:-1]
        a, b = b, r
    return a / a[-1]  # the last nonzero remainder, monic


def common_roots(f, g, tol: float = 1e-9) -> np.ndarray:
    """The real common roots of f and g, sorted: the real roots of their GCD (multiple ones repeated). Notes §17.4.

    >>> common_roots([-6.0, 11.0, -6.0, 1.0], [-8.0, 14.0, -7.0, 1.0]).round(9).tolist()
    [1.0, 2.0]
    """
    d = poly_gcd(f, g, tol)
    if len(d) == 1:
        return np.zeros(0)
    roots = P.polyroots(d)
    real = np.abs(roots.imag) <= 1e-7 * np.maximum(1.0, np.abs(roots))
    return np.sort(roots[real].real)


# --- §17.5-17.6 implicitization ----------------------------------------------------------------------------------


def _times_line(line: np.ndarray, poly: np.ndarray) -> np.ndarray:
    """(a x + b y + c) · poly for a bivariate poly[i, j] whose degree leaves room in its array."""
    a, b, c = line
    out = c * poly
    out[1:, :] += a * poly[:-1, :]
    out[:, 1:] += b * poly[:, :-1]
    return out


def _line_determinant(forms: np.ndarray) -> np.ndarray:
    """det of an (n, n) matrix of linear forms (n, n, 3) as a bivariate polynomial (n+1, n+1).

    Laplace expansion along the rows, bottom up, remembering the minor of
    every column subset: n 2ⁿ⁻¹ products of a line and a polynomial, exact for
    integer data, no sampling (which would need a badly conditioned solve).
    """
    n = forms.shape[0]
    one = np.zeros((n + 1, n + 1))
    one[0, 0] = 1.0
    minors = {(): one}
    for size in range(1, n + 1):
        row = n - size
        found = {}
        for columns in combinations(range(n), size):
            total = np.zeros((n + 1, n + 1))
            for position, column in enumerate(columns):
                rest = columns[:position] + columns[position + 1 :]
                term = _times_line(forms[row, column], minors[rest])
                total = total + term if position % 2 == 0 else total - term
            found[columns] = total
        minors = found
    return minors[tuple(range(n))] + 0.0


def _vanishes(f: np.ndarray, forms: np.ndarray, size: float) -> bool:
    """True when det is zero to rounding: every coefficient tiny next to the Hadamard bound of the matrix."""
    bound = np.prod([np.sum((np.abs(row[:, 0]) + np.abs(row[:, 1])) * size + np.abs(row[:, 2])) for row in forms])
    i, j = np.indices(f.shape)
    return bool(np.abs(f * size ** (i + j)).max() <= VANISHING * bound)


def _checked_implicit(forms: np.ndarray, size: float, name: str = "points") -> np.ndarray:
    f = _line_determinant(forms)
    if _vanishes(f, forms, size):
        raise ValueError(
            f"{name}: the implicit equation vanishes identically: the curve's degree is lower than its number of "
            "control points says (a degree-raised curve?); reduce the degree first"
        )
    return f


def l_lines(points, weights=None) -> np.ndarray:
    """Every line l_ij = C(n,i) C(n,j) w_i w_j det[[x, y, 1], [x_i, y_i, 1], [x_j, y_j, 1]] as (a, b, c), (n+1, n+1, 3).

    l[i, j] = (a, b, c) means a x + b y + c; it is C(n,i) C(n,j) (H_i × H_j)
    for the homogeneous control points H_i = w_i (x_i, y_i, 1), the line
    through P_i and P_j, and l[j, i] = -l[i, j]. Notes §17.6.

    >>> l_lines([(1.0, 0.0), (5.0, 0.0), (5.0, 2.0), (4.0, 3.0)])[3, 2].tolist()     # l32 = 3x + 3y - 21
    [3.0, 3.0, -21.0]
    """
    h = _homogeneous(points, weights)
    n = len(h) - 1
    rows = h * np.array([comb(n, i) for i in range(n + 1)], dtype=float)[:, None]
    return np.cross(rows[:, None, :], rows[None, :, :]) + 0.0


def bezout_lines(points, weights=None) -> np.ndarray:
    """The Bézout matrix of a rational Bézier curve as lines (n, n, 3): entry [r, c] is L_{n-1-r, n-1-c}. Notes §17.6.

    L_{i,j} = Σ l_km over m <= min(i, j), k = i+j+1-m <= n, with l_km from
    `l_lines`; the matrix is symmetric. Each entry (a, b, c) is the line
    a x + b y + c. At a point P(t) of the curve the matrix annihilates the
    Bernstein vector [t^(n-1), t^(n-2)(1-t), ..., (1-t)^(n-1)] (in this order,
    highest power of t first), so det = 0 on the curve: `implicitize`.
    Rows r = 0 and r = n-1 give the inversion formulas (17.11) of a quadratic.

    >>> bezout_lines([(1.0, -2.0), (1.0, -1.0), (2.0, 1.0)])[0].tolist()     # [l21, l20] of a parabola
    [[4.0, -2.0, -6.0], [3.0, -1.0, -5.0]]
    """
    h = _homogeneous(points, weights)
    n = len(h) - 1
    return _bezout_forms(h * np.array([comb(n, i) for i in range(n + 1)], dtype=float)[:, None]) + 0.0


def implicitize(points, weights=None) -> np.ndarray:
    """The implicit equation f(x, y) = 0 of a rational Bézier curve: c[i, j] of xⁱ yʲ, (n+1, n+1). Notes §17.6.

    points: (n+1, 2), n >= 1; weights: None or (n+1,) nonzero. f is the
    determinant of the Bézout matrix of lines (`bezout_lines`), computed
    exactly as a polynomial (no sampling): integer data give integer
    coefficients. Entries with i + j > n are zero. Defined up to a common
    factor: compare after normalising. A curve of lower true degree
    (degree-raised, so that f vanishes identically) raises ValueError; an
    improper parametrisation or collinear control points give a power of the
    true equation (e.g. the line to the n-th power).

    >>> f = implicitize([(1.0, -2.0), (1.0, -1.0), (2.0, 1.0)])    # the parabola x = t²+1, y = t²+2t-2 of §17.2
    >>> f.tolist()                                                  # -(x² - 2xy + y² - 10x + 6y + 13)
    [[-13.0, -6.0, -1.0], [10.0, 2.0, 0.0], [-1.0, 0.0, 0.0]]
    >>> (implicitize([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0]).round(12) + 0).tolist()
    [[1.0, 0.0, -1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    return _implicit_of(_homogeneous(points, weights))


def line_determinant(matrix) -> np.ndarray:
    """The determinant of an (n, n) matrix of lines (a, b, c) = a x + b y + c, as c[i, j] of xⁱ yʲ, (n+1, n+1). §17.6.

    Laplace expansion along the first row, with exact polynomial arithmetic:
    a line times a polynomial is the polynomial shifted one place along x
    (times a), one along y (times b), and kept (times c). n! products: the
    plain form of what `implicitize` computes with every minor reused.

    >>> x, y, x_minus_1 = [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, -1.0]
    >>> line_determinant([[x, y], [y, x_minus_1]]).tolist()                       # x (x - 1) - y²
    [[0.0, 0.0, -1.0], [-1.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
    """
    matrix = as_float_array(matrix, "matrix")
    n = len(matrix)
    if n and matrix.shape != (n, n, 3):
        raise ValueError(f"matrix: expected lines (n, n, 3), got shape {matrix.shape}")
    if n == 0:
        return np.ones((1, 1))
    total = np.zeros((n + 1, n + 1))
    for column in range(n):
        minor = line_determinant(np.delete(matrix[1:], column, axis=1))  # (n, n): degree n - 1
        a, b, c = matrix[0, column]
        term = np.zeros((n + 1, n + 1))
        term[:n, :n] += c * minor
        term[1:, :n] += a * minor  # a x · minor
        term[:n, 1:] += b * minor  # b y · minor
        total += (-1) ** column * term
    return total + 0.0


def implicitize_plain(points, weights=None) -> np.ndarray:
    """The implicit equation as det of the Bézout matrix of the lines l_ij: the plain form of `implicitize`. §17.6.

    >>> implicitize_plain([(1.0, -2.0), (1.0, -1.0), (2.0, 1.0)]).tolist()     # -(x² - 2xy + y² - 10x + 6y + 13)
    [[-13.0, -6.0, -1.0], [10.0, 2.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    lines = l_lines(points, weights)  # lines[i, j] = l_ij = C(n,i) C(n,j) H_i × H_j, the brackets
    return line_determinant(bezout_from_brackets(lines))


def _implicit_of(h: np.ndarray, name: str = "points") -> np.ndarray:
    n = len(h) - 1
    forms = _bezout_forms(h * np.array([comb(n, i) for i in range(n + 1)], dtype=float)[:, None])
    size = max(1.0, float(np.abs(h[:, :2] / h[:, 2:]).max()))
    return _checked_implicit(forms, size, name)


def _power_rows(x, y, w) -> np.ndarray:
    columns = [_nonzero_poly(x, "x"), _nonzero_poly(y, "y"), np.ones(1) if w is None else _nonzero_poly(w, "w")]
    n = max(len(c) for c in columns) - 1
    if n < 1:
        raise ValueError("x, y, w: constants describe a point, not a curve")
    rows = np.zeros((n + 1, 3))
    for k, c in enumerate(columns):
        rows[: len(c), k] = c
    return rows


def power_bezout_lines(x, y, w=None) -> np.ndarray:
    """The Bézout matrix in t of p = x W(t) - X(t) and q = y W(t) - Y(t), as lines (n, n, 3). Notes §17.5.

    x, y, w: ascending power coefficients of X, Y, W (w=None: W = 1). Entry
    (a, b, c) is the line a x + b y + c; the bracket (p_k q_m) is the line
    (X_k, Y_k, W_k) × (X_m, Y_m, W_m), placed as in `bezout_matrix`.

    >>> power_bezout_lines([1.0, 0.0, 1.0], [-2.0, 2.0, 1.0]).tolist()     # [[2, x - y - 3], [x - y - 3, 2x - 2]]
    [[[0.0, 0.0, 2.0], [1.0, -1.0, -3.0]], [[1.0, -1.0, -3.0], [2.0, 0.0, -2.0]]]
    """
    return _bezout_forms(_power_rows(x, y, w)) + 0.0


def implicitize_power(x, y, w=None) -> np.ndarray:
    """The implicit equation of (x, y) = (X(t), Y(t)) / W(t) from power coefficients, (n+1, n+1). Notes §17.5.

    x, y, w: ascending power coefficients of X, Y and W (w=None: W = 1); n is
    the largest degree. f(x, y) is the determinant of the Bézout matrix of
    p = x W(t) - X(t) and q = y W(t) - Y(t) with respect to t, whose brackets
    (p_k q_m) are the lines (X_k, Y_k, W_k) × (X_m, Y_m, W_m). It equals
    `implicitize` of the same curve in Bézier form, and (-1)^(n(n-1)/2) times
    SymPy's `resultant(p, q, t)`.

    >>> implicitize_power([1.0, 0.0, 1.0], [-2.0, 2.0, 1.0]).tolist()     # x = t² + 1, y = t² + 2t - 2
    [[-13.0, -6.0, -1.0], [10.0, 2.0, 0.0], [-1.0, 0.0, 0.0]]
    """
    return _checked_implicit(_bezout_forms(_power_rows(x, y, w)), 1.0, "x, y, w")


def implicit_eval(coeffs, xy) -> float | np.ndarray:
    """f(x, y) = Σ c[i, j] xⁱ yʲ at a point (2,) -> a number, or at points (k, 2) -> (k,). Notes §17.1.

    >>> implicit_eval([[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[0.6, 0.8], [1.0, 1.0]]).round(12).tolist()
    [0.0, 1.0]
    """
    c = as_float_array(coeffs, "coeffs")
    if c.ndim != 2 or c.size == 0:
        raise ValueError(f"coeffs: expected a 2-D array c[i, j] of x^i y^j, got shape {c.shape}")
    pts, single = _xy(xy)
    values = P.polyval2d(pts[:, 0], pts[:, 1], c)
    return float(values[0]) if single else values


# --- §17.6-17.7 inversion -----------------------------------------------------------------------------------------


def _as_poly2(line: np.ndarray) -> np.ndarray:
    """A line (a, b, c) as the bivariate array [[c, b], [a, 0]]."""
    return np.array([[line[2], line[1]], [line[0], 0.0]])


def cubic_inversion_lines(points, weights=None) -> tuple[np.ndarray, np.ndarray, float, float]:
    """The notes' cubic inversion t = l_b / (l_b - l_a) by one row operation: (l_a, l_b, c1, c2). Notes (17.12)-(17.14).

    All of l32, l31, l30 pass through P3, so c1 l32 + c2 l31 + l30 ≡ 0 with
    c1 = w0 |P0 P1 P3| / (3 w2 |P1 P2 P3|) and c2 = -w0 |P0 P2 P3| / (3 w1 |P1 P2 P3|)
    (|A B C| the determinant of the rows (A, 1), (B, 1), (C, 1)). Adding c1
    times row 1 and c2 times row 2 to row 3 of the Bézout matrix leaves
    [0, l_a, l_b] with l_a = c1 l31 + c2 (l30 + l21) + l20 and
    l_b = c1 l30 + c2 l20 + l10, hence (1-t)(l_a t + l_b (1-t)) = 0 on the
    curve. Lines as (a, b, c); ValueError when P1, P2, P3 are collinear.

    >>> la, lb, c1, c2 = cubic_inversion_lines([(1.0, 0.0), (5.0, 0.0), (5.0, 2.0), (4.0, 3.0)])
    >>> (la.round(9) + 0).tolist(), (lb.round(9) + 0).tolist(), round(c1, 9), round(c2, 9)   # t = 2y / (x + y - 1)
    ([3.0, -3.0, -3.0], [0.0, -6.0, 0.0], 2.0, -1.0)
    """
    h = _homogeneous(points, weights)
    if len(h) != 4:
        raise ValueError(f"points: expected the 4 control points of a cubic, got {len(h)}")
    pts, w = h[:, :2] / h[:, 2:], h[:, 2]

    def area(i, j, k):
        return float(np.linalg.det(np.column_stack([pts[[i, j, k]], np.ones(3)])))

    base = area(1, 2, 3)
    if abs(base) <= 1e-12 * max(1.0, np.abs(pts).max()) ** 2:
        raise ValueError("points: P1, P2, P3 are collinear, so the row operation of (17.13) does not exist")
    c1 = w[0] * area(0, 1, 3) / (3 * w[2] * base)
    c2 = -w[0] * area(0, 2, 3) / (3 * w[1] * base)
    lines = l_lines(points, weights)
    la = c1 * lines[3, 1] + c2 * (lines[3, 0] + lines[2, 1]) + lines[2, 0]
    lb = c1 * lines[3, 0] + c2 * lines[2, 0] + lines[1, 0]
    return la + 0.0, lb + 0.0, float(c1), float(c2)


def _monomials(k: int) -> list[tuple[int, int]]:
    return [(i, j) for i in range(k + 1) for j in range(k + 1 - i)]


def _inversion_family(h: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """A basis of inversion formulas (num, den) of the homogeneous curve h (n+1, 3), each t = num/den on the curve."""
    n = len(h) - 1
    if n == 1:
        # Lines through P0 and P1 perpendicular to the chord: s = d·(X - P0)/|d|², t = w0 s / (w0 s + w1 (1 - s)).
        p0, p1 = h[0, :2] / h[0, 2], h[1, :2] / h[1, 2]
        d = p1 - p0
        if not d.any():
            raise ValueError("points: the two control points coincide, so the curve is a single point")
        w0, w1 = h[0, 2], h[1, 2]
        num = w0 * np.array([d[0], d[1], -d @ p0])
        den = num + w1 * np.array([-d[0], -d[1], d @ p1])
        return [(_as_poly2(num), _as_poly2(den))]
    if n == 3:
        try:
            la, lb, _, _ = cubic_inversion_lines(h[:, :2] / h[:, 2:], h[:, 2])
        except ValueError:
            return _nullspace_inversions(h)
        return [(_as_poly2(lb), _as_poly2(lb - la))]
    if n == 2:
        # The two rows of (17.11) combined so that the denominator is constant along the curve (c / W).
        lines = _bezout_forms(h * np.array([1.0, 2.0, 1.0])[:, None])
        l21, l20, l10 = lines[0, 0], lines[0, 1], lines[1, 1]
        num, den = l20 - l10, 2 * l20 - l21 - l10
        # On the curve den·(x, y, 1) = c / W(t) with c = den·H0; c = 0 means every l_ij is one line.
        if abs(den @ h[0]) <= 1e-12 * np.abs(den).sum() * np.abs(h).max():
            raise ValueError("points: the control points are collinear, so the curve is a line and not invertible "
                             "by a ratio of lines")
        return [(_as_poly2(num), _as_poly2(den))]
    return _nullspace_inversions(h)


def _nullspace_inversions(h: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every (f, g) of degree k = n-2 with t g(P(t)) - f(P(t)) ≡ 0, from the null space of (17.20) in Bernstein form."""
    n = len(h) - 1
    k = n - 2
    powers = [[np.ones(1)] for _ in range(3)]
    for column in range(3):
        for _ in range(k):
            powers[column].append(bernstein_multiply(powers[column][-1], h[:, column]))
    monomials = _monomials(k)
    values = [bernstein_multiply(bernstein_multiply(powers[0][i], powers[1][j]), powers[2][k - i - j])
              for i, j in monomials]
    # t g - f: g's monomials times t (Bernstein [0, 1]), f's raised by one degree.
    columns = [bernstein_multiply(v, np.array([0.0, 1.0])) for v in values]
    columns += [-elevate(v[:, None])[:, 0] for v in values]
    matrix = np.column_stack(columns)
    norms = np.linalg.norm(matrix, axis=0)
    norms[norms == 0] = 1.0
    _, singular, vt = np.linalg.svd(matrix / norms, full_matrices=True)
    padded = np.concatenate([singular, np.zeros(vt.shape[0] - len(singular))])
    null = vt[padded <= NULL_TOL * singular[0]] / norms
    family = []
    for vector in null:
        g, f = np.zeros((k + 1, k + 1)), np.zeros((k + 1, k + 1))
        for index, (i, j) in enumerate(monomials):
            g[i, j], f[i, j] = vector[index], vector[len(monomials) + index]
        family.append((f, g))
    if not family:
        raise ValueError("points: found no inversion formula (is the curve degenerate?)")
    return family


def _normalised(num: np.ndarray, den: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    big = den.flat[np.argmax(np.abs(den))]
    return num / big + 0.0, den / big + 0.0


def _cartesian_values(poly: np.ndarray, h: np.ndarray, ts: np.ndarray) -> np.ndarray:
    pts = evaluate(h[:, :2] / h[:, 2:], ts, h[:, 2])
    return P.polyval2d(pts[:, 0], pts[:, 1], poly)


def inversion(points, weights=None) -> tuple[np.ndarray, np.ndarray]:
    """An inversion formula t = num(x, y) / den(x, y) of a rational Bézier curve: (num, den), each c[i, j] of xⁱ yʲ.

    Degree k of num and den: 1 for n <= 3, n - 2 beyond (arrays (k+1, k+1)).
    n = 1: the projection onto the chord, corrected for the weights; n = 2:
    the two rows of (17.11) combined so that den is a nonzero constant over
    the curve (no 0/0 anywhere on a conic); n = 3: the row operation
    (17.13) of `cubic_inversion_lines` (exact for integer data), or where
    P1, P2, P3 are collinear the null space of the linear system
    (17.15)-(17.20) in the Bernstein basis, unique up to scale for a cubic;
    n >= 4: that null space (of dimension n - 2), the member whose den is
    closest to 1 over t in [0, 1] (least squares). Like every single member
    of that family it also gives 0/0 at n - 3 ordinary points of the curve,
    which is why `invert` evaluates a whole basis instead. Scaled so that
    den's largest coefficient is +1. At a double point num = den = 0.
    Notes §17.6, §17.7.

    >>> num, den = inversion([(1.0, 0.0), (5.0, 0.0), (5.0, 2.0), (4.0, 3.0)])
    >>> (np.round(num / num[0, 1], 9) + 0).tolist(), (np.round(2 * den / num[0, 1], 9) + 0).tolist()   # 2y/(x+y-1)
    ([[0.0, 1.0], [0.0, 0.0]], [[-1.0, 1.0], [1.0, 0.0]])
    """
    h = _homogeneous(points, weights)
    family = _inversion_family(h)
    if len(family) == 1:
        return _normalised(*family[0])
    ts = np.linspace(0.0, 1.0, 4 * len(h) + 1)
    values = np.column_stack([_cartesian_values(g, h, ts) for _, g in family])
    mix = np.linalg.lstsq(values, np.ones(len(ts)), rcond=None)[0]
    return _normalised(sum(c * f for c, (f, _) in zip(mix, family)), sum(c * g for c, (_, g) in zip(mix, family)))


def _size(poly: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Σ |c_ij| max(1, |x|)^i max(1, |y|)^j at every point: the scale rounding errors of a value are measured against.

    Every coefficient counts, even where its monomial is small: a coefficient that is rounding noise (zero in
    exact arithmetic) must not make a value that is zero to rounding look significant.
    """
    big = np.maximum(np.abs(pts), 1.0)
    return P.polyval2d(big[:, 0], big[:, 1], np.abs(poly))


def _invert(family, pts: np.ndarray, tol: float) -> np.ndarray:
    best = np.full(len(pts), -1.0)
    result = np.zeros(len(pts))
    degenerate = np.ones(len(pts), dtype=bool)
    for num, den in family:
        top, bottom = P.polyval2d(pts[:, 0], pts[:, 1], num), P.polyval2d(pts[:, 0], pts[:, 1], den)
        size_top, size_bottom = _size(num, pts), _size(den, pts)
        quality = np.abs(bottom) / np.maximum(size_bottom, 1e-300)
        both_zero = (np.abs(top) <= tol * size_top) & (np.abs(bottom) <= tol * size_bottom)
        better = (quality > best) & ~both_zero
        result[better] = top[better] / bottom[better]
        best[better] = quality[better]
        degenerate &= both_zero
    if np.any(degenerate):
        bad = pts[degenerate][0]
        raise ValueError(f"xy: ({bad[0]:.6g}, {bad[1]:.6g}) is a singular point of the curve (the inversion gives "
                         "0/0): more than one parameter reaches it")
    infinite = best <= tol
    if np.any(infinite):
        bad = pts[infinite][0]
        raise ValueError(f"xy: ({bad[0]:.6g}, {bad[1]:.6g}) has an infinite parameter (den = 0, num != 0)")
    return result


def invert(points, xy, weights=None, tol: float = 1e-9) -> float | np.ndarray:
    """The parameter t of a point (2,) -> a number, or of points (k, 2) -> (k,), on a rational curve. Notes §17.7.

    Evaluates inversion formulas t = num(x, y)/den(x, y) (`inversion`); for
    n >= 4, where several independent formulas exist, each point uses the one
    whose den is largest there. Valid for every real t, not only [0, 1]. A
    point where every formula gives 0/0 (both below tol times their size) is a
    double point or a cusp: ValueError, never NaN. For a point off the curve
    the value means nothing (check `implicit_eval` of `implicitize` first).

    >>> cubic = [(1.0, 0.0), (5.0, 0.0), (5.0, 2.0), (4.0, 3.0)]
    >>> round(invert(cubic, [4.375, 1.125]), 12)                                    # P(1/2) = (35/8, 9/8)
    0.5
    >>> invert([(1.0, -2.0), (1.0, -1.0), (2.0, 1.0)], [[5.0, -2.0], [1.0, -2.0]]).round(12).tolist()   # §17.2
    [-2.0, 0.0]
    """
    h = _homogeneous(points, weights)
    pts, single = _xy(xy)
    tol = as_tolerance(tol, below_one=True)
    family = _inversion_family(h)
    ts = _invert([_normalised(*pair) for pair in family], pts, tol)
    return float(ts[0]) if single else ts


def inversion_plain(points, weights=None, basis: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """An inversion formula t = num/den by linear algebra, (17.15)-(17.20) in the power basis: the plain form. §17.7.

    For a curve of degree n >= 2, num and den have degree k = max(1, n - 2)
    (arrays (k+1, k+1), c[i, j] of xⁱ yʲ). Their coefficients are a null
    vector of the linear system t·den(X, Y, W) - num(X, Y, W) ≡ 0, with
    X(t), Y(t), W(t) the homogeneous curve in the power basis and every
    monomial made homogeneous, xⁱ yʲ -> Xⁱ Yʲ W^(k-i-j). The null space has
    the dimension r = (k+1)(k+2) - (k n + 2), the excess of unknowns over
    equations: 2 for n = 2, 1 for n = 3, n - 2 from n = 4 on. The default
    returns its last singular vector, one member (`inversion` chooses the
    member best conditioned on [0, 1]); basis=True returns all r members of
    a basis, (nums, dens) of shape (r, k+1, k+1). For n >= 4 every single
    member gives 0/0 at n - 3 ordinary points of the curve as well as at its
    double points (`invert_plain` therefore uses the whole basis). A line
    (n = 1) has degenerate members (num = den = the line itself):
    ValueError, `inversion` projects onto the chord.

    >>> num, den = inversion_plain([(4.0, 1.0), (5.0, 6.0), (5.0, 0.0), (6.0, 4.0)], [1.0, 2.0, 2.0, 1.0])
    >>> (np.round(156 * num / den[1, 0], 6) + 0).tolist()        # (1089 x - 172 y - 4184) / (156 x - 8 y + 758)
    [[-4184.0, -172.0], [1089.0, 0.0]]
    >>> inversion_plain([(0.0, 0.0), (1.0, 2.0), (3.0, -1.0), (4.0, 2.0), (5.0, 0.0)], basis=True)[1].shape
    (2, 3, 3)
    """
    h = bernstein_to_power(homogeneous_points(points, weights))  # X, Y, W: ascending power coefficients in t
    n = len(h) - 1
    if n < 2:
        raise ValueError("points: a line (n = 1) has no unique inversion by this system; `inversion` handles it")
    k = max(1, n - 2)
    monomials = [(i, j) for i in range(k + 1) for j in range(k + 1 - i)]
    size = k * n + 2  # coefficients of t·den - num: degree k n + 1
    values = []  # each monomial X^i Y^j W^(k-i-j) as a polynomial in t
    for i, j in monomials:
        value = np.ones(1)
        for column, power in ((0, i), (1, j), (2, k - i - j)):
            for _ in range(power):
                value = np.convolve(value, h[:, column])
        values.append(value)
    den_columns = [np.pad(np.concatenate([[0.0], v]), (0, size - len(v) - 1)) for v in values]  # t · monomial
    num_columns = [-np.pad(v, (0, size - len(v))) for v in values]
    matrix = np.column_stack(den_columns + num_columns)  # size equations, 2 len(monomials) unknowns
    members = matrix.shape[1] - matrix.shape[0]  # the dimension of the null space
    null = np.linalg.svd(matrix)[2][-members:]  # the right singular vectors of the smallest singular values
    nums, dens = np.zeros((members, k + 1, k + 1)), np.zeros((members, k + 1, k + 1))
    for index, (i, j) in enumerate(monomials):
        dens[:, i, j], nums[:, i, j] = null[:, index], null[:, len(monomials) + index]
    return (nums, dens) if basis else (nums[-1], dens[-1])


def invert_plain(points, xy, weights=None, tol: float = 1e-9) -> float | np.ndarray:
    """The parameter of a point (2,) or points (k, 2) of a curve of degree n >= 2, from `inversion_plain`. §17.7.

    The plain form of `invert`: at every point it evaluates each member of a
    basis of the inversion formulas and uses the one whose den is largest
    there, relative to the size of its terms. A point where every member has
    den = 0 (below tol times that size) is a double point, where num = 0 as
    well: ValueError. One member alone is not enough from n = 4 on: it is
    also 0/0 at n - 3 ordinary points of the curve.

    >>> invert_plain([(1.0, 0.0), (5.0, 0.0), (5.0, 2.0), (4.0, 3.0)], [[4.375, 1.125], [-26.0, 9.0]]).round(9).tolist()
    [0.5, -1.0]
    """
    nums, dens = inversion_plain(points, weights, basis=True)
    pts = as_float_array(xy, "xy")
    single = pts.shape == (2,)  # one point gives a number
    if not single and (pts.ndim != 2 or pts.shape[1] != 2):
        raise ValueError(f"xy: expected a point (2,) or points (k, 2), got shape {pts.shape}")
    tol = as_tolerance(tol, below_one=True)
    x, y = pts.reshape(-1, 2).T
    big_x, big_y = np.maximum(np.abs(x), 1), np.maximum(np.abs(y), 1)
    best, ts = np.zeros(len(x)), np.zeros(len(x))
    for num, den in zip(nums, dens):  # every member of the basis, at every point
        top, bottom = P.polyval2d(x, y, num), P.polyval2d(x, y, den)
        size = P.polyval2d(big_x, big_y, np.abs(num) + np.abs(den))  # the size of the terms at each point
        quality = np.abs(bottom) / size
        quality[np.abs(bottom) <= tol * size] = 0.0  # den = 0 to rounding: this member is of no use here
        better = quality > best
        ts[better], best[better] = top[better] / bottom[better], quality[better]
    if np.any(best == 0):
        raise ValueError("xy: every inversion formula has den = 0 there: a double point of the curve (num = 0 too, "
                         "two parameters reach it) or a point that no finite t reaches")
    return float(ts[0]) if single else ts


# --- §17.8 intersection by implicitization ------------------------------------------------------------------------


def intersection_polynomial(p, q, p_weights=None, q_weights=None) -> np.ndarray:
    """Bernstein coefficients (mn+1,) on [0, 1] of g(u) = f_P(X_Q(u), Y_Q(u), W_Q(u)): P implicitized, Q substituted.

    f_P = `implicitize(p, p_weights)` (degree m) homogenised, so a rational Q
    needs no division; the real roots of g in [0, 1] are the parameters u of
    the intersections on Q (Bézout: at most m n). Notes §17.8.

    >>> intersection_polynomial([(0.0, 0.0), (1.0, 1.0)], [(0.0, 1.0), (1.0, 0.0)]).tolist()    # y = x meets x + y = 1
    [-1.0, 1.0]
    """
    hp = _homogeneous(p, p_weights, "p", "p_weights")
    hq = _homogeneous(q, q_weights, "q", "q_weights")
    f = _implicit_of(hp, "p")
    return curve_implicit_bernstein(f, hq[:, :2] / hq[:, 2:], hq[:, 2])


def _parameters_at(hp: np.ndarray, point: np.ndarray, family, tol: float) -> list[float]:
    """The parameters t of P at a point of P: the inversion, or at a double point those in [0, 1] of X - xW, Y - yW."""
    try:
        return [float(_invert(family, point[None, :], tol)[0])]
    except ValueError:
        pass
    pts = hp[:, :2] / hp[:, 2:]
    candidates = []
    for column in range(2):
        coordinate = hp[:, column] - point[column] * hp[:, 2]
        if np.abs(coordinate).max() > 1e-12 * np.abs(hp).max():
            candidates.append(bernstein_roots(coordinate))
    ts = np.concatenate(candidates) if candidates else np.zeros(0)
    if ts.size == 0:
        return []
    found = evaluate(pts, ts, hp[:, 2])
    near = np.hypot(*(found - point).T) <= 1e-6 * max(1.0, float(np.abs(point).max()))
    return sorted({round(float(t), 12) for t in ts[near]})


def intersect_implicit(p, q, p_weights=None, q_weights=None, tol: float = 1e-9) -> np.ndarray:
    """Intersections (t, u), (k, 2), of two rational Bézier curves by implicitization and inversion. Notes §17.8.

    Implicitize P (degree m), substitute Q (degree n): the real roots u in
    [0, 1] of the degree-mn polynomial `intersection_polynomial`; the point
    Q(u) is inverted on P (`invert`) and kept when its t lies in [0, 1]. A
    tangency (a double root of g) is one row. Rows sorted by t, then u;
    (0, 2) when the curves do not meet. Curves on one implicit curve
    (g ≡ 0) raise ValueError. tol: the root tolerance, and the slack allowed
    when t is tested against [0, 1].

    >>> p = [(4.0, 1.0), (5.0, 6.0), (5.0, 0.0), (6.0, 4.0)]
    >>> q = [(7.0, 4.0), (1.0, 2.0), (9.0, 2.0), (3.0, 4.0)]
    >>> hits = intersect_implicit(p, q, [1.0, 2.0, 2.0, 1.0], [1.0, 2.0, 2.0, 1.0])
    >>> len(hits), np.round(hits[3], 6).tolist()             # nine; the notes print 0.3397 for 0.3997
    (9, [0.399672, 0.921891])
    """
    hp = _homogeneous(p, p_weights, "p", "p_weights")
    hq = _homogeneous(q, q_weights, "q", "q_weights")
    tol = as_tolerance(tol, below_one=True)
    f = _implicit_of(hp, "p")
    g = curve_implicit_bernstein(f, hq[:, :2] / hq[:, 2:], hq[:, 2])
    i, j = np.indices(f.shape)
    size = np.abs(hq).max(axis=0)
    scale = float(np.sum(np.abs(f) * size[0] ** i * size[1] ** j * size[2] ** np.maximum(len(f) - 1 - i - j, 0)))
    if np.abs(g).max() <= 1e-12 * scale:
        raise ValueError("p, q: the curves lie on one implicit curve (the substitution vanishes identically)")
    us = bernstein_roots(g, tol=min(tol, 1e-12))
    if us.size:
        us = us[np.concatenate([[True], np.diff(us) > ROOT_MERGE])]
    family = [_normalised(*pair) for pair in _inversion_family(hp)]
    rows = []
    for u, point in zip(us, evaluate(hq[:, :2] / hq[:, 2:], us, hq[:, 2])):
        for t in _parameters_at(hp, point, family, tol):
            if -tol <= t <= 1 + tol:
                rows.append((min(max(t, 0.0), 1.0), float(u)))
    return np.array(sorted(rows), dtype=float).reshape(-1, 2)


def intersect_implicit_plain(p, q, p_weights=None, q_weights=None, tol: float = 1e-9) -> np.ndarray:
    """Intersections (t, u), (k, 2), by implicitization, the four steps of §17.8: the plain form. Notes §17.8.

    Assumes no intersection at a double point of P (where `invert` has no
    single answer); `intersect_implicit` handles those and curves on one
    implicit curve.

    >>> intersect_implicit_plain([(0.0, 0.0), (1.0, 1.0)], [(0.0, 1.0), (1.0, 0.0)]).tolist()
    [[0.5, 0.5]]
    """
    homogeneous_points(p, p_weights, "p", "p_weights")  # the input checked, errors naming p and p_weights
    X, Y, W = homogeneous_points(q, q_weights, "q", "q_weights").T  # Q's H_k, the Bernstein coefficients
    tol = as_tolerance(tol, below_one=True)
    f = implicitize(p, p_weights)  # 1. P's implicit equation, degree m
    m, n = len(f) - 1, len(X) - 1
    g = np.zeros(m * n + 1)  # 2. g(u) = Σ c_ij X^i Y^j W^(m-i-j), degree m n
    for i in range(m + 1):
        for j in range(m + 1 - i):
            term = np.ones(1)
            for factor, power in ((X, i), (Y, j), (W, m - i - j)):
                for _ in range(power):
                    term = bernstein_multiply(term, factor)
            g += f[i, j] * term
    us = bernstein_roots(g)  # 3. its real roots in [0, 1]
    if us.size == 0:
        return np.zeros((0, 2))
    ts = np.atleast_1d(invert(p, evaluate(q, us, q_weights), p_weights))  # 4. each point's t on P
    keep = (ts >= -tol) & (ts <= 1 + tol)
    rows = np.column_stack([np.clip(ts[keep], 0.0, 1.0), us[keep]])
    return rows[np.lexsort((rows[:, 1], rows[:, 0]))]


# --- §17.9-17.11 surfaces and term orders -------------------------------------------------------------------------


def surface_implicit_degree(kind: str, degree, base_points: int = 0) -> int:
    """The implicit degree of a rational patch: n² (triangular, degree n) or 2mn (bidegree (m, n)), less base points.

    kind: "triangular" with `degree` an integer n, or "tensor" with `degree`
    a pair (m, n). A generic line meets the surface in as many points as two
    plane sections meet in parameter space: n² by Bézout's theorem for two
    curves of degree n, 2mn for two curves of bidegree (m, n) (Bézout's count
    (m+n)², less m² and n² at the two points at infinity of the axes); every simple
    base point (a parameter where x = y = z = w = 0) is one of those
    intersections that maps to no point, and lowers the degree by one.
    Notes §17.9, §17.10.

    >>> surface_implicit_degree("tensor", (3, 3)), surface_implicit_degree("triangular", 2, base_points=1)
    (18, 3)
    """
    b = as_count(base_points, "base_points")
    if kind == "triangular":
        n = as_count(degree, "degree", minimum=1)
        full = n * n
    elif kind == "tensor":
        if not isinstance(degree, (tuple, list)) or len(degree) != 2:
            raise TypeError(f"degree: a tensor-product patch needs a bidegree (m, n), got {degree!r}")
        full = 2 * as_count(degree[0], "degree", minimum=1) * as_count(degree[1], "degree", minimum=1)
    else:
        raise ValueError(f"kind: expected 'triangular' or 'tensor', got {kind!r}")
    if b >= full:
        raise ValueError(f"base_points: a patch of implicit degree {full} cannot have {b} base points")
    return full - b


def term_count(degree: int, variables: int = 3) -> int:
    """The number of monomials of total degree <= `degree` in `variables` variables: C(degree + variables, variables).

    A bicubic patch's implicit equation (degree 18 in x, y, z) has up to 1330. Notes §17.9.

    >>> term_count(18)
    1330
    """
    d = as_count(degree, "degree")
    v = as_count(variables, "variables", minimum=1)
    return comb(d + v, v)


ORDERS = ("lex", "grlex", "grevlex")


def sort_terms(exponents, order: str = "lex") -> list[tuple[int, ...]]:
    """Exponent vectors sorted from the leading term down, by a term order. Notes §17.11.

    exponents: a list of equal-length tuples of non-negative integers (the
    variables in their declared order, x > y > z ...; permute the tuples to
    declare another). order: "lex" (compare the exponents left to right),
    "grlex" (the notes' deglex: total degree first, then lex) or "grevlex"
    (total degree first, then the smaller exponent of the last variable wins).

    >>> sort_terms([(2, 2, 1), (1, 3, 2), (3, 0, 1), (0, 2, 0), (1, 0, 3), (0, 0, 0)])   # 3x²y²z + 4xy³z² + ...
    [(3, 0, 1), (2, 2, 1), (1, 3, 2), (1, 0, 3), (0, 2, 0), (0, 0, 0)]
    """
    if order not in ORDERS:
        raise ValueError(f"order: expected one of {ORDERS}, got {order!r}")
    terms = [tuple(as_count(e, "exponents") for e in term) for term in exponents]
    if len({len(term) for term in terms}) > 1:
        raise ValueError("exponents: every exponent vector needs one entry per variable")
    keys = {
        "lex": lambda e: e,
        "grlex": lambda e: (sum(e), e),
        "grevlex": lambda e: (sum(e), tuple(-x for x in reversed(e))),
    }
    return sorted(terms, key=keys[order], reverse=True)

"""Scalar polynomials in the power and Bernstein bases: notes §2.16 and chapter 3.

Coefficient arrays are (n+1,) for one polynomial or (n+1, d) for d polynomials
at once (the columns), so curve coordinates and homogeneous coordinates convert,
multiply and evaluate in one call. Power coefficients are ascending
(a0 + a1 t + ..., as `numpy.polynomial`) in the global parameter t. Bernstein
coefficients are on [0, 1], or on `interval=(t0, t1)` where a function takes
one: then B_i^n is evaluated at the local parameter u = (t - t0) / (t1 - t0).
"""

from __future__ import annotations

from math import comb

import numpy as np
from numpy.typing import ArrayLike

from ._validation import as_coefficients, as_count, as_interval, as_parameter, as_scalar

__all__ = [
    "horner",
    "bernstein_horner",
    "bernstein_horner_plain",
    "evaluation_cost",
    "difference_table",
    "substitute_affine",
    "bernstein_to_power",
    "power_to_bernstein",
    "bernstein_multiply",
    "bernstein_integral",
    "bernstein_area",
]

# C(n, n/2) no longer fits in a double from n = 1030 on.
MAX_BINOMIAL_DEGREE = 1029
# Parameters evaluated together: small enough for the cache, large enough for NumPy.
BLOCK = 32768


def _binomials(n: int, name: str = "coeffs") -> np.ndarray:
    """C(n, 0), ..., C(n, n) as floats, shape (n+1,)."""
    if n > MAX_BINOMIAL_DEGREE:
        raise ValueError(
            f"{name}: degree {n} is too high; the binomial coefficients C(n, i) overflow a float "
            f"beyond degree {MAX_BINOMIAL_DEGREE}"
        )
    return np.array([comb(n, i) for i in range(n + 1)], dtype=float)


def _column(values: np.ndarray, like: np.ndarray) -> np.ndarray:
    """A 1-D array (m,) shaped to broadcast against rows of coefficients `like` (·,) or (·, d): (m,) or (m, 1).

    Serves per-coefficient factors such as the binomials, and per-point parameters.
    """
    return values.reshape((-1,) + (1,) * (like.ndim - 1))


def _constant(row: np.ndarray, count: int) -> np.ndarray:
    """`count` copies of one coefficient row: (count,) or (count, d)."""
    return np.broadcast_to(row, (count,) + row.shape).copy()


def _finish(values: np.ndarray, scalar: bool):
    """One value (float, or (d,)) for a scalar parameter; the (k,) or (k, d) array otherwise."""
    if scalar:
        return values[0] if values.ndim > 1 else float(values[0])
    return values


def substitute_affine(coeffs: ArrayLike, shift: float, scale: float) -> np.ndarray:
    """Power coefficients of q(u) = p(shift + scale u) from those of p, same shape. Notes §2.13, §3.3.

    coeffs: (n+1,) or (n+1, d) ascending power coefficients. Horner's scheme
    again, but on polynomials: q starts as a_n and is multiplied by the linear
    factor (shift + scale u) before each lower coefficient is added. The
    notes' example of §2.13, P(t) = (t² + t - 1, 2t² - t + 3) with t = 2s + 1:

    >>> from cagd_ref.polynomials import substitute_affine
    >>> substitute_affine([(-1, 3), (1, -1), (1, 2)], 1.0, 2.0).tolist()   # Q(s) = (4s² + 6s + 1, 8s² + 6s + 4)
    [[1.0, 4.0], [6.0, 6.0], [4.0, 8.0]]
    """
    coeffs = as_coefficients(coeffs)
    shift, scale = as_scalar(shift, "shift"), as_scalar(scale, "scale")
    q = coeffs[-1:].copy()
    for coefficient in coeffs[-2::-1]:
        widened = np.zeros((len(q) + 1,) + q.shape[1:])
        widened[:-1] += shift * q
        widened[1:] += scale * q
        widened[0] += coefficient
        q = widened
    return q


def horner(coeffs: ArrayLike, t: ArrayLike) -> float | np.ndarray:
    """Evaluate a0 + a1 t + ... + an tⁿ in nested form, n multiplies and n adds per point. Notes §3.1.

    coeffs: ascending power coefficients (n+1,) or (n+1, d). t: a number ->
    float or (d,); a 1-D array of k values -> (k,) or (k, d).
    The homogeneous (X, Y, W) power form of the notes' rational cubic (§3.3), one column each:

    >>> from cagd_ref.polynomials import horner
    >>> power = [(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)]
    >>> horner(power, 0.5).tolist()
    [5.75, 6.125, 1.875]
    >>> horner([1, 24, -39, 20], [0.0, 1.0]).tolist()                # X alone: X(0) = 1, X(1) = 6
    [1.0, 6.0]

    Ref: W. G. Horner, A new method of solving numerical equations of all orders, by continuous
    approximation, Philosophical Transactions of the Royal Society of London 109, 1819.
    """
    a = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    tt = _column(ts, a)
    value = _constant(a[-1], len(ts))
    for coefficient in a[-2::-1]:
        value = value * tt + coefficient
    return _finish(value, scalar)


def bernstein_horner_plain(coeffs: ArrayLike, t: ArrayLike) -> float | np.ndarray:
    """The nested Bernstein form in its plain teaching form (what chapter 3 shows), on [0, 1]. Notes §3.2.

    With s = 1 - t and c_i = C(n, i) b_i the sum Σ b_i B_i^n(t) is
    (((c0 s + c1 t) s + c2 t²) s + ...) s + cn tⁿ: a running power tⁱ and one
    factor s per step, O(n) per point. coeffs: Bernstein coefficients (n+1,)
    or (n+1, d); shapes as in `horner`. `bernstein_horner` computes the same
    values, tuned for very many parameters, and also over any interval.

    >>> from cagd_ref.polynomials import bernstein_horner_plain
    >>> bernstein_horner_plain([1, 9, 4, 6], 0.5)      # X of the notes' rational cubic (§3.3) at t = 1/2
    5.75

    Ref: L. L. Schumaker and W. Volk, Efficient evaluation of multivariate polynomials, CAGD 3, 1986.
    """
    b = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    n = len(b) - 1
    c = b * _column(_binomials(n), b)  # C(n, i) b_i, once per polynomial
    tt = _column(ts, b)
    s = 1 - tt
    value, power = _constant(c[0], len(ts)), np.ones_like(tt)
    for coefficient in c[1:]:
        power = power * tt  # tⁱ
        value = value * s + coefficient * power  # one more factor s on every earlier term, then + c_i tⁱ
    return _finish(value, scalar)


def bernstein_horner(coeffs: ArrayLike, t: ArrayLike, interval: ArrayLike = (0, 1)) -> float | np.ndarray:
    """Evaluate Σ b_i B_i^n(u) in the nested Bernstein form, O(n) per point, tuned for many parameters. Notes §3.2.

    With s = 1 - u the sum is (((c0 s + c1 u) s + c2 u²) s + ...) s + cn uⁿ,
    where c_i = C(n, i) b_i is formed once per polynomial; each point then
    costs 3n multiplies and n + 1 adds (see `evaluation_cost`), against the
    O(n²) of the de Casteljau triangle. coeffs: Bernstein coefficients (n+1,)
    or (n+1, d) on `interval`; u = (t - t0) / (t1 - t0). Shapes as in `horner`.
    It computes what `bernstein_horner_plain` (the teaching form) computes, in
    place, coordinate-major and a block of parameters at a time.
    This is also how `cagd_ref.bezier.evaluate` computes curve points.
    The notes' rational cubic (§3.3), homogeneous (X, Y, W) Bernstein coefficients:

    >>> from cagd_ref.polynomials import bernstein_horner
    >>> bernstein_horner([(1.0, 2.0, 1.0), (9.0, 12.0, 3.0), (4.0, 3.0, 1.0), (6.0, 2.0, 2.0)], 0.5).tolist()
    [5.75, 6.125, 1.875]
    >>> bernstein_horner([1, 9, 4, 6], [2.0, 4.0], interval=(2, 4)).tolist()   # the same X over [2, 4]
    [1.0, 6.0]

    Ref: L. L. Schumaker and W. Volk, Efficient evaluation of multivariate polynomials, CAGD 3, 1986.
    """
    b = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    t0, t1 = as_interval(interval)
    n = len(b) - 1
    c = (b * _column(_binomials(n), b)).reshape(n + 1, -1)  # (n+1, d): one column per polynomial
    u = ts if (t0, t1) == (0.0, 1.0) else (ts - t0) / (t1 - t0)
    # Coordinate-major results, filled a block of parameters at a time: each pass runs over
    # contiguous numbers, and a block's arrays stay in the processor's cache for all n steps.
    values = np.empty((c.shape[1], len(u)))
    for start in range(0, len(u), BLOCK):
        x = u[start : start + BLOCK]
        value = values[:, start : start + BLOCK]
        if n == 0:
            value[:] = c[0][:, None]
            continue
        s, power = 1 - x, np.ones_like(x)
        np.multiply(c[0][:, None], s, out=value)  # c0 s
        for coefficient in c[1:-1]:
            power *= x  # uⁱ
            value += coefficient[:, None] * power  # + c_i uⁱ
            value *= s  # ... then the next factor s
        value += c[-1][:, None] * (power * x)  # + c_n uⁿ
    return _finish(values.T if b.ndim == 2 else values[0], scalar)


def evaluation_cost(degree: int) -> dict[str, tuple[int, int]]:
    """Floating-point (multiplies, adds) per evaluation point of a degree-n polynomial, by method. Notes §3.1, §3.2.

    Keys: "horner" (power form, (n, n)), "bernstein_horner" (nested Bernstein
    form with C(n, i) b_i precomputed once: (3n, n + 1)) and "de_casteljau"
    (n(n+1)/2 interpolations (1-t) a + t b of 2 multiplies and 1 add each,
    plus 1 - t once). Divisions count as multiplies, subtractions as adds;
    a degree-0 polynomial costs nothing.
    """
    n = as_count(degree, "degree")
    if n == 0:
        return {"horner": (0, 0), "bernstein_horner": (0, 0), "de_casteljau": (0, 0)}
    steps = n * (n + 1) // 2
    return {
        "horner": (n, n),
        "bernstein_horner": (3 * n, n + 1),
        "de_casteljau": (2 * steps, steps + 1),
    }


def difference_table(coeffs: ArrayLike) -> list[np.ndarray]:
    """Forward differences of the coefficients, row j holding Δʲ b_i for i = 0..n-j. Notes §3.3.

    Rows have shape (n+1-j,) or (n+1-j, d); row 0 is a copy of `coeffs`. The
    left column (row j, entry 0) gives the derivatives at 0:
    B^(j)(0) = n!/(n-j)! Δʲ b_0.
    """
    b = as_coefficients(coeffs)
    rows = [b]
    while len(rows[-1]) > 1:
        rows.append(np.diff(rows[-1], axis=0))
    return rows


def bernstein_to_power(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Bernstein coefficients on `interval` -> ascending power coefficients in t, same shape. Notes §3.3, (3.1).

    On [0, 1] the power coefficients are the Taylor coefficients at 0,
    a_i = B^(i)(0) / i! = C(n, i) Δⁱ b_0: the left column of the difference
    table scaled by the binomials. On [t0, t1] that gives the polynomial in
    u = (t - t0) / (t1 - t0), which is then rewritten in t.
    The notes' table read downwards, homogeneous (X, Y, W) columns:

    >>> from cagd_ref.polynomials import bernstein_to_power
    >>> bernstein_to_power([(1.0, 2.0, 1.0), (9.0, 12.0, 3.0), (4.0, 3.0, 1.0), (6.0, 2.0, 2.0)]).tolist()
    [[1.0, 2.0, 1.0], [24.0, 30.0, 6.0], [-39.0, -57.0, -12.0], [20.0, 27.0, 7.0]]
    """
    b = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    leading = np.array([row[0] for row in difference_table(b)])
    local = leading * _column(_binomials(len(b) - 1), b)
    return substitute_affine(local, -t0 / (t1 - t0), 1 / (t1 - t0))


def power_to_bernstein(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Ascending power coefficients in t -> Bernstein coefficients on `interval`, same shape. Notes §3.3.

    The left column of the difference table is a_j / C(n, j); running the
    table backwards (each entry is the one to its left plus the one below
    that) fills in the top row, which holds the Bernstein coefficients. On
    [t0, t1] the polynomial is first rewritten in u, t = t0 + (t1 - t0) u.
    The notes' example: a rational cubic given by its homogeneous power form.

    >>> from cagd_ref.polynomials import power_to_bernstein
    >>> power_to_bernstein([(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)]).round(12).tolist()
    [[1.0, 2.0, 1.0], [9.0, 12.0, 3.0], [4.0, 3.0, 1.0], [6.0, 2.0, 2.0]]
    """
    a = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    local = substitute_affine(a, t0, t1 - t0)
    column = local / _column(_binomials(len(a) - 1), local)
    # `column[j]` is the entry Δʲ at the current position; stepping one place to
    # the right replaces Δʲ by Δʲ + Δʲ⁺¹ for every order j at once.
    top = [column[0]]
    while len(column) > 1:
        column = column[:-1] + column[1:]
        top.append(column[0])
    return np.array(top)


def bernstein_multiply(f: ArrayLike, g: ArrayLike) -> np.ndarray:
    """Bernstein coefficients of the product of two Bernstein polynomials (degrees m and n -> m + n). Notes §9.3.

    h_k = Σ_{i+j=k} C(m, i) C(n, j) / C(m+n, k) f_i g_j. Both inputs (m+1,)/(n+1,)
    or both (·, d) for column-wise products; the same on any common interval.
    The notes give only the formula; a course example, (1 + t)(3 + 2t) = 3 + 5t + 2t²:

    >>> from cagd_ref.polynomials import bernstein_multiply
    >>> (bernstein_multiply([1, 2], [3, 4, 5]) * 3).round(12).tolist()     # <3, 14/3, 7, 10>, times 3
    [9.0, 14.0, 21.0, 30.0]
    """
    f = as_coefficients(f, "f")
    g = as_coefficients(g, "g")
    if f.ndim != g.ndim or f.shape[1:] != g.shape[1:]:
        raise ValueError(f"f, g: coefficient arrays must have matching columns, got shapes {f.shape} and {g.shape}")
    m, n = len(f) - 1, len(g) - 1
    product_binomials = _binomials(m + n, "f, g")
    scaled_f = f * _column(_binomials(m, "f"), f)
    scaled_g = g * _column(_binomials(n, "g"), g)
    product = np.zeros((m + n + 1,) + f.shape[1:])
    for i in range(m + 1):
        product[i : i + n + 1] += scaled_f[i] * scaled_g
    return product / _column(product_binomials, product)


def bernstein_integral(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Coefficients of the antiderivative q (degree n+1, q(t0) = 0) of p = Σ p_i B_i^n over `interval`. Notes §2.16.

    q_0 = 0 and q_i = (t1 - t0)/(n+1) (p_0 + ... + p_{i-1}), eqs. (2.17)-(2.19);
    shape (n+2,) or (n+2, d). The last coefficient is the area (2.20), the
    mean of the p_i. The notes give only the formulas; a course example:

    >>> from cagd_ref.polynomials import bernstein_integral
    >>> bernstein_integral([3, 6, 9]).tolist()              # q = (0, 3, 9, 18) / 3; area 6 = mean(3, 6, 9)
    [0.0, 1.0, 3.0, 6.0]
    """
    p = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    n = len(p) - 1
    zero = np.zeros((1,) + p.shape[1:])
    return (t1 - t0) / (n + 1) * np.concatenate([zero, np.cumsum(p, axis=0)])


def bernstein_area(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> float | np.ndarray:
    """Area under an explicit Bézier curve over `interval`: (t1 - t0) times the mean coefficient. Notes §2.16 (2.20)."""
    return bernstein_integral(coeffs, interval)[-1]

"""Scalar polynomials in the power and Bernstein bases: notes §2.16 and chapter 3.

Coefficient arrays are (n+1,) for one polynomial or (n+1, d) for d polynomials
at once (the columns), so curve coordinates and homogeneous coordinates convert,
multiply and evaluate in one call. Power coefficients are ascending
(a0 + a1 t + ..., as `numpy.polynomial`) in the global parameter t. Bernstein
coefficients are on [0, 1], or on `interval=(t0, t1)` where a function takes
one: then B_i^n is evaluated at the local parameter s = (t - t0) / (t1 - t0).
"""

from __future__ import annotations

from math import comb

import numpy as np
from numpy.typing import ArrayLike

from ._validation import as_coefficients, as_count, as_interval, as_parameter, as_scalar

__all__ = [
    "horner",
    "horner_with_derivative",
    "bernstein_horner",
    "bernstein_horner_plain",
    "evaluation_cost",
    "difference_table",
    "substitute_affine",
    "bernstein_to_power",
    "power_to_bernstein",
    "power_to_bernstein_interval",
    "power_to_rational_bezier",
    "bernstein_multiply",
    "bernstein_integral",
    "bernstein_area",
]

# C(n, n/2) no longer fits in a double from n = 1030 on.
MAX_BINOMIAL_DEGREE = 1029
# A converted weight this small against the largest one is zero up to rounding: a point at infinity.
ZERO_WEIGHT = 1e-12
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


def _scaled_by_binomials(b: np.ndarray, binomials: np.ndarray) -> np.ndarray:
    """β_i = C(n, i) b_i, shape of b; ValueError when one of them overflows a float (|b_i| C(n, i) > 1.8e308)."""
    with np.errstate(over="ignore"):
        beta = b * _column(binomials, b)
    if not np.all(np.isfinite(beta)):
        n = len(b) - 1
        raise ValueError(
            f"coeffs: C(n, i) b_i overflows a float at degree {n} (largest |b_i| {np.abs(b).max():.3g}); "
            "every |b_i| C(n, i) must stay below 1.8e308"
        )
    return beta


def _column(values: np.ndarray, like: np.ndarray) -> np.ndarray:
    """A 1-D array (m,) shaped to broadcast against rows of coefficients `like` (·,) or (·, d): (m,) or (m, 1).

    Serves per-coefficient factors such as the binomials, and per-point parameters.
    """
    return values.reshape((-1,) + (1,) * (like.ndim - 1))


def _finish(values: np.ndarray, scalar: bool):
    """One value (float, or (d,)) for a scalar parameter; the (k,) or (k, d) array otherwise."""
    if scalar:
        return values[0] if values.ndim > 1 else float(values[0])
    return values


def substitute_affine(coeffs: ArrayLike, shift: float, scale: float) -> np.ndarray:
    """Power coefficients of g(s) = p(shift + scale s) from those of p, same shape. Notes §2.13, §3.3.

    coeffs: (n+1,) or (n+1, d) ascending power coefficients. Horner's scheme
    again, but on polynomials: g starts as a_n and is multiplied by the linear
    factor (shift + scale s) before each lower coefficient is added. The
    notes' example of §2.13, P(t) = (t² + t - 1, 2t² - t + 3) with t = 2s + 1:

    >>> from cagd_ref.polynomials import substitute_affine
    >>> substitute_affine([(-1, 3), (1, -1), (1, 2)], 1.0, 2.0).tolist()   # Q(s) = (4s² + 6s + 1, 8s² + 6s + 4)
    [[1.0, 4.0], [6.0, 6.0], [4.0, 8.0]]
    """
    coeffs = as_coefficients(coeffs)
    shift, scale = as_scalar(shift, "shift"), as_scalar(scale, "scale")
    g = coeffs[-1:].copy()
    for coefficient in coeffs[-2::-1]:
        widened = np.zeros((len(g) + 1,) + g.shape[1:])
        widened[:-1] += shift * g
        widened[1:] += scale * g
        widened[0] += coefficient
        g = widened
    return g


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
    columns = a.reshape(len(a), -1)  # (n+1, d): one polynomial per column
    tt = ts[:, None]  # (k, 1): one row per parameter
    h = np.ones_like(tt) * columns[-1]  # h_n = a_n at every parameter, (k, d)
    for coefficient in columns[-2::-1]:
        h = tt * h + coefficient  # h_(i-1) = τ h_i + a_(i-1)
    values = h if a.ndim == 2 else h[:, 0]
    if scalar:
        return values[0] if a.ndim == 2 else float(values[0])
    return values


def horner_with_derivative(coeffs: ArrayLike, t: ArrayLike) -> tuple:
    """Value and first derivative of a0 + a1 t + ... + an tⁿ in one nested pass. Notes §3.1 (used by §9's Newton steps).

    Horner's h_i at τ are the coefficients of the quotient q(t) = h_1 + h_2 t
    + ... + h_n t^(n-1) of p(t) by t - τ, and p'(τ) = q(τ); so a second Horner
    recurrence, h'_n = 0, h'_(i-1) = τ h'_i + h_i, runs beside the first and
    ends with h'_0 = p'(τ): 2n multiplies and 2n adds per point.
    coeffs: ascending power coefficients (n+1,) or (n+1, d). t (the τ above):
    a number -> (value, derivative), floats or (d,) each; a 1-D array of k
    values -> two arrays (k,) or (k, d). The course's example 2 - 3t + t³ at
    τ = 2, whose quotient by t - 2 is t² + 2t + 1:

    >>> from cagd_ref.polynomials import horner_with_derivative
    >>> horner_with_derivative([2, -3, 0, 1], 2.0)                     # p(2) = 4, p'(2) = 3·2² - 3 = 9
    (4.0, 9.0)
    >>> value, slope = horner_with_derivative([(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)], [0.0, 1.0])
    >>> slope.tolist()                        # the notes' (X, Y, W) of §3.3: a_1, then 3 (H_3 - H_2)
    [[24.0, 30.0, 6.0], [6.0, -3.0, 3.0]]

    Ref: W. G. Horner, Philosophical Transactions of the Royal Society of London 109, 1819; D. E. Knuth, The Art of
    Computer Programming, vol. 2, §4.6.4.
    """
    a = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    columns = a.reshape(len(a), -1)  # (n+1, d): one polynomial per column
    tt = ts[:, None]  # (k, 1): one row per parameter
    h = np.ones_like(tt) * columns[-1]  # h_n = a_n
    h_prime = np.zeros_like(h)  # h'_n = 0
    for coefficient in columns[-2::-1]:
        h_prime = tt * h_prime + h  # h'_(i-1) = τ h'_i + h_i, with the h_i of this step
        h = tt * h + coefficient  # h_(i-1) = τ h_i + a_(i-1)
    value, slope = (h, h_prime) if a.ndim == 2 else (h[:, 0], h_prime[:, 0])
    if scalar:
        return (value[0], slope[0]) if a.ndim == 2 else (float(value[0]), float(slope[0]))
    return value, slope


def bernstein_horner_plain(coeffs: ArrayLike, t: ArrayLike) -> float | np.ndarray:
    """The nested Bernstein form in its plain teaching form (what chapter 3 shows), on [0, 1]. Notes §3.2.

    With β_i = C(n, i) b_i the sum Σ b_i B_i^n(τ) is
    (((β_0 (1-τ) + β_1 τ)(1-τ) + β_2 τ²)(1-τ) + ...)(1-τ) + β_n τⁿ: a running
    power τⁱ and one factor 1 - τ per step, O(n) per point. coeffs: Bernstein
    coefficients (n+1,) or (n+1, d); t (the τ above) and the shapes as in
    `horner`. `bernstein_horner` computes the same values, tuned for very many
    parameters, and also over any interval. Every β_i must fit in a float:
    ValueError for a degree above 1029 (C(n, n/2) alone overflows) and for
    any |b_i| C(n, i) above 1.8e308 (at degree 1029 already for |b_i| >= 1.26).

    >>> from cagd_ref.polynomials import bernstein_horner_plain
    >>> bernstein_horner_plain([1, 9, 4, 6], 0.5)      # X of the notes' rational cubic (§3.3) at t = 1/2
    5.75

    Ref: L. L. Schumaker and W. Volk, Efficient evaluation of multivariate polynomials, CAGD 3, 1986.
    """
    b = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    n = len(b) - 1
    if n > MAX_BINOMIAL_DEGREE:
        raise ValueError(f"coeffs: degree {n} is too high; C(n, i) overflows a float beyond degree 1029")
    binomials = np.array([comb(n, i) for i in range(n + 1)], dtype=float)
    with np.errstate(over="ignore"):
        beta = b.reshape(n + 1, -1) * binomials[:, None]  # β_i = C(n, i) b_i, once per polynomial
    if not np.all(np.isfinite(beta)):
        raise ValueError(f"coeffs: C(n, i) b_i overflows a float at degree {n}; |b_i| C(n, i) must stay below 1.8e308")
    tt = ts[:, None]  # (k, 1): one row per parameter
    one_minus_t = 1 - tt
    value, power = np.ones_like(tt) * beta[0], np.ones_like(tt)  # v_0 = β_0, τ⁰
    for coefficient in beta[1:]:
        power = power * tt  # τⁱ
        value = value * one_minus_t + coefficient * power  # v_i = v_(i-1) (1-τ) + β_i τⁱ
    values = value if b.ndim == 2 else value[:, 0]
    if scalar:
        return values[0] if b.ndim == 2 else float(values[0])
    return values


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
    Every c_i must fit in a float: ValueError for a degree above 1029 and for
    any |b_i| C(n, i) above 1.8e308, instead of infinities in the result.
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
    c = _scaled_by_binomials(b, _binomials(n)).reshape(n + 1, -1)  # (n+1, d): one column per polynomial
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
    p^(j)(0) = n!/(n-j)! Δʲ b_0.
    """
    b = as_coefficients(coeffs)
    rows = [b]
    while len(rows[-1]) > 1:
        rows.append(np.diff(rows[-1], axis=0))
    return rows


def bernstein_to_power(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Bernstein coefficients on `interval` -> ascending power coefficients in t, same shape. Notes §3.3, (3.1).

    On [0, 1] the power coefficients are the Taylor coefficients at 0,
    a_i = p^(i)(0) / i! = C(n, i) Δⁱ b_0: the left column of the difference
    table scaled by the binomials. On [t0, t1] that gives the polynomial in
    s = (t - t0) / (t1 - t0), which is then rewritten in t.
    The notes' table read downwards, homogeneous (X, Y, W) columns:

    >>> from cagd_ref.polynomials import bernstein_to_power
    >>> bernstein_to_power([(1.0, 2.0, 1.0), (9.0, 12.0, 3.0), (4.0, 3.0, 1.0), (6.0, 2.0, 2.0)]).tolist()
    [[1.0, 2.0, 1.0], [24.0, 30.0, 6.0], [-39.0, -57.0, -12.0], [20.0, 27.0, 7.0]]
    """
    b = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    n = len(b) - 1
    if n > MAX_BINOMIAL_DEGREE:
        raise ValueError(f"coeffs: degree {n} is too high; C(n, i) overflows a float beyond degree 1029")
    binomials = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    left_column = np.array([row[0] for row in difference_table(b.reshape(n + 1, -1))])  # Δʲ b_0
    local = binomials[:, None] * left_column  # a_j = C(n, j) Δʲ b_0: powers of s, (3.1)
    power = substitute_affine(local, -t0 / (t1 - t0), 1 / (t1 - t0))  # s = (t - t0) / (t1 - t0)
    return power.reshape(b.shape)


def power_to_bernstein(coeffs: ArrayLike, interval: ArrayLike = (0, 1)) -> np.ndarray:
    """Ascending power coefficients in t -> Bernstein coefficients on `interval`, same shape. Notes §3.3.

    The left column of the difference table is a_j / C(n, j); running the
    table backwards (each entry is the one to its left plus the one below
    that) fills in the top row, which holds the Bernstein coefficients. On
    [t0, t1] the polynomial is first rewritten in s, t = t0 + (t1 - t0) s.
    The notes' example: a rational cubic given by its homogeneous power form.

    >>> from cagd_ref.polynomials import power_to_bernstein
    >>> power_to_bernstein([(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)]).round(12).tolist()
    [[1.0, 2.0, 1.0], [9.0, 12.0, 3.0], [4.0, 3.0, 1.0], [6.0, 2.0, 2.0]]
    """
    a = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    n = len(a) - 1
    if n > MAX_BINOMIAL_DEGREE:
        raise ValueError(f"coeffs: degree {n} is too high; C(n, i) overflows a float beyond degree 1029")
    binomials = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    local = substitute_affine(a.reshape(n + 1, -1), t0, t1 - t0)  # powers of s, t = t0 + (t1 - t0) s
    column = local / binomials[:, None]  # the left column: Δʲ b_0 = a_j / C(n, j)
    top = [column[0]]  # b_0
    for _ in range(n):
        # one place to the right, every order j at once: Δʲ b_(k+1) = Δʲ b_k + Δʲ⁺¹ b_k
        column = column[:-1] + column[1:]
        top.append(column[0])  # b_(k+1)
    return np.array(top).reshape(a.shape)


def power_to_bernstein_interval(coeffs: ArrayLike, interval: ArrayLike) -> np.ndarray:
    """Ascending power coefficients in t -> Bernstein coefficients over [t0, t1], same shape. Notes §2.2, §2.13.

    Two steps: rewrite p in the local parameter s of the interval,
    g(s) = p(t0 + (t1 - t0) s), by Horner's rule on polynomials
    (`substitute_affine`); then convert g on [0, 1] with the difference table
    (notes §3.3).
    `power_to_bernstein(coeffs, interval)` gives the same. coeffs: (n+1,) or
    (n+1, d); interval: (t0, t1) with t0 < t1. t² over [1, 3] has the
    coefficients 1, 1·3, 9 (its blossom at (1, 1), (1, 3), (3, 3)):

    >>> from cagd_ref.polynomials import power_to_bernstein_interval
    >>> power_to_bernstein_interval([0, 0, 1], (1, 3)).tolist()
    [1.0, 3.0, 9.0]
    >>> power_to_bernstein_interval([(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)], (0, 0.5))[-1].tolist()
    [5.75, 6.125, 1.875]

    The second call restricts the notes' rational cubic (§3.3) to [0, 1/2]: its
    last coefficient row is the homogeneous point at t = 1/2.
    """
    a = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    local = substitute_affine(a, t0, t1 - t0)  # g(s) = p(t0 + (t1 - t0) s), in powers of s
    return power_to_bernstein(local)  # the difference table on [0, 1]


def power_to_rational_bezier(coeffs: ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Homogeneous power form (X, Y, ..., W) -> control points (n+1, d) and weights (n+1,). Notes §3.3.

    coeffs: (n+1, d+1), row j the coefficients of tʲ in every homogeneous
    coordinate, the last column W. The conversion is linear, so each column
    goes through the difference table on its own; the top row then holds the
    homogeneous control points w_i (P_i, 1), which are divided by their
    weights. A weight that is zero (up to rounding: |w_i| <= 1e-12 max|w_j|)
    is a control point at infinity and raises ValueError. The notes' example:

    >>> from cagd_ref.polynomials import power_to_rational_bezier
    >>> points, weights = power_to_rational_bezier([(1, 2, 1), (24, 30, 6), (-39, -57, -12), (20, 27, 7)])
    >>> points.round(12).tolist(), weights.round(12).tolist()
    ([[1.0, 2.0], [3.0, 4.0], [4.0, 3.0], [3.0, 1.0]], [1.0, 3.0, 1.0, 2.0])
    """
    h = as_coefficients(coeffs)
    if h.ndim != 2 or h.shape[1] < 2:
        raise ValueError(
            f"coeffs: expected homogeneous coefficients of shape (n+1, d+1), d >= 1, the last column W, "
            f"got shape {h.shape}"
        )
    homogeneous = power_to_bernstein(h)  # rows w_i (P_i, 1): the top row of the table
    weights = homogeneous[:, -1]
    if np.any(np.abs(weights) <= ZERO_WEIGHT * np.abs(weights).max()):
        raise ValueError(f"coeffs: a zero weight puts a control point at infinity, got weights {weights.tolist()}")
    return homogeneous[:, :-1] / weights[:, None], weights


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

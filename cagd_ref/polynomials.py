"""Scalar polynomials in the power and Bernstein bases: notes §2.16 and chapter 3.

Coefficient arrays are (n+1,) for one polynomial or (n+1, d) for d polynomials
at once (the columns), so curve coordinates and homogeneous coordinates convert,
multiply and evaluate in one call. Power coefficients are ascending
(a0 + a1 t + ..., as `numpy.polynomial`); Bernstein coefficients are on [0, 1].
"""

from __future__ import annotations

from math import comb

import numpy as np

from ._validation import as_coefficients, as_interval, as_parameter

__all__ = [
    "horner",
    "bernstein_horner",
    "difference_table",
    "bernstein_to_power",
    "power_to_bernstein",
    "bernstein_multiply",
    "bernstein_integral",
    "bernstein_area",
]


def _binomials(n: int) -> np.ndarray:
    return np.array([comb(n, i) for i in range(n + 1)], dtype=float)


def _column(values: np.ndarray, like: np.ndarray) -> np.ndarray:
    """Broadcast a (n+1,) factor against coefficients of shape (n+1,) or (n+1, d)."""
    return values.reshape((-1,) + (1,) * (like.ndim - 1))


def _finish(values: np.ndarray, scalar: bool):
    if scalar:
        return values[0] if values.ndim > 1 else float(values[0])
    return values


def horner(coeffs, t):
    """Evaluate a0 + a1 t + ... + an tⁿ by nested multiplication, n multiplies and adds. Notes ch. 3.

    coeffs: (n+1,) or (n+1, d). t: a number -> float or (d,); k values -> (k,) or (k, d).
    """
    a = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    tt = ts.reshape((-1,) + (1,) * (a.ndim - 1))
    value = np.broadcast_to(a[-1], (len(ts),) + a.shape[1:]).copy()
    for coefficient in a[-2::-1]:
        value = value * tt + coefficient
    return _finish(value, scalar)


def bernstein_horner(coeffs, t):
    """Evaluate Σ b_i B_i^n(t) by the nested Bernstein form, O(n) per point. Notes ch. 3.

    With s = 1 - t the sum is ((b0 C(n,0) s + b1 C(n,1) t) s + b2 C(n,2) t²) s + ...,
    building the powers of t and the binomials as it goes, so no powers of s
    and no de Casteljau triangle are needed. Shapes as in `horner`.
    """
    b = as_coefficients(coeffs)
    ts, scalar = as_parameter(t)
    n = len(b) - 1
    tt = ts.reshape((-1,) + (1,) * (b.ndim - 1))
    if n == 0:
        return _finish(np.broadcast_to(b[0], (len(ts),) + b.shape[1:]).copy(), scalar)
    s = 1 - tt
    power, binomial = np.ones_like(tt), 1.0
    value = b[0] * s
    for i in range(1, n):
        power = power * tt
        binomial = binomial * (n - i + 1) / i
        value = (value + power * binomial * b[i]) * s
    return _finish(value + power * tt * b[n], scalar)


def difference_table(coeffs) -> list[np.ndarray]:
    """Forward differences of the coefficients: row j holds Δʲ b_i, i = 0..n-j. Notes ch. 3."""
    b = as_coefficients(coeffs)
    rows = [b]
    while len(rows[-1]) > 1:
        rows.append(np.diff(rows[-1], axis=0))
    return rows


def bernstein_to_power(coeffs) -> np.ndarray:
    """Bernstein coefficients on [0, 1] -> ascending power coefficients: a_i = C(n, i) Δⁱ b_0. Notes (3.1)."""
    b = as_coefficients(coeffs)
    leading = np.array([row[0] for row in difference_table(b)])
    return leading * _column(_binomials(len(b) - 1), b)


def power_to_bernstein(coeffs) -> np.ndarray:
    """Ascending power coefficients -> Bernstein coefficients on [0, 1]. Notes ch. 3.

    The left column of the difference table is a_i / C(n, i); running the table
    backwards (each entry is the one to its left plus the one below that) fills
    in the top row, which holds the Bernstein coefficients.
    """
    a = as_coefficients(coeffs)
    n = len(a) - 1
    column = a / _column(_binomials(n), a)
    # `column[j]` is the entry Δʲ at the current position; stepping one place to
    # the right replaces Δʲ by Δʲ + Δʲ⁺¹ for every order j at once.
    top = [column[0]]
    for _ in range(n):
        column = column[:-1] + column[1:]
        top.append(column[0])
    return np.array(top)


def bernstein_multiply(f, g) -> np.ndarray:
    """Bernstein coefficients of the product of two Bernstein polynomials (degrees m and n -> m + n). Notes ch. 9.

    h_k = Σ_{i+j=k} C(m, i) C(n, j) / C(m+n, k) f_i g_j. Both inputs (m+1,)/(n+1,)
    or both (·, d) for column-wise products.
    """
    f = as_coefficients(f, "f")
    g = as_coefficients(g, "g")
    if f.ndim != g.ndim or f.shape[1:] != g.shape[1:]:
        raise ValueError(f"f, g: coefficient arrays must have matching columns, got shapes {f.shape} and {g.shape}")
    m, n = len(f) - 1, len(g) - 1
    scaled_f = f * _column(_binomials(m), f)
    scaled_g = g * _column(_binomials(n), g)
    product = np.zeros((m + n + 1,) + f.shape[1:])
    for i in range(m + 1):
        product[i : i + n + 1] += scaled_f[i] * scaled_g
    return product / _column(_binomials(m + n), product)


def bernstein_integral(coeffs, interval=(0, 1)) -> np.ndarray:
    """Coefficients of the antiderivative q (degree n+1, q(t0) = 0) of p = Σ p_i B_i^n over `interval`. Notes (2.17)-(2.19).

    q_0 = 0 and q_i = (t1 - t0)/(n+1) (p_0 + ... + p_{i-1}); shape (n+2,) or (n+2, d).
    """
    p = as_coefficients(coeffs)
    t0, t1 = as_interval(interval)
    n = len(p) - 1
    zero = np.zeros((1,) + p.shape[1:])
    return (t1 - t0) / (n + 1) * np.concatenate([zero, np.cumsum(p, axis=0)])


def bernstein_area(coeffs, interval=(0, 1)):
    """Area under an explicit Bézier curve over `interval`: (t1 - t0) times the mean coefficient. Notes (2.20)."""
    return bernstein_integral(coeffs, interval)[-1]

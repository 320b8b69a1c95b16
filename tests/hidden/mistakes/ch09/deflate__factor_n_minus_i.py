"""Uses the factor (n - i)/n of the mirror image instead of n/(i+1)."""
import numpy as np


def deflate(coeffs):
    y = np.asarray(coeffs, dtype=float)
    if y.ndim != 1 or len(y) < 2:
        raise ValueError("coeffs: expected a vector of degree >= 1")
    if abs(y[0]) > 1e-12 * np.abs(y).max():
        raise ValueError("coeffs: y_0 is not zero")
    n = len(y) - 1
    return (n - np.arange(n)) / n * y[1:]

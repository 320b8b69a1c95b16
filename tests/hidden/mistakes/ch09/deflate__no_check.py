"""Deflates without checking that f(0) = 0, so a polynomial that t does not divide gets a wrong answer."""
import numpy as np


def deflate(coeffs):
    y = np.asarray(coeffs, dtype=float)
    if y.ndim != 1 or len(y) < 2:
        raise ValueError("coeffs: expected a vector of degree >= 1")
    n = len(y) - 1
    return n * y[1:] / np.arange(1, n + 1)

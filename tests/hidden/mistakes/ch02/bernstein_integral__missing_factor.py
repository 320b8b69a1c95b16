"""Prefix sums of the coefficients without the factor 1/(n+1)."""
import numpy as np


def bernstein_integral(coeffs):
    p = np.array(coeffs, dtype=float)
    if p.ndim not in (1, 2) or len(p) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    zero = np.zeros((1,) + p.shape[1:])
    return np.concatenate([zero, np.cumsum(p, axis=0)])

"""Divides the prefix sums by the degree n instead of n + 1."""
import numpy as np


def bernstein_integral(coeffs):
    p = np.array(coeffs, dtype=float)
    if p.ndim not in (1, 2) or len(p) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    n = max(len(p) - 1, 1)
    q = np.zeros((len(p) + 1,) + p.shape[1:])
    for i in range(1, len(p) + 1):
        q[i] = q[i - 1] + p[i - 1] / n
    return q

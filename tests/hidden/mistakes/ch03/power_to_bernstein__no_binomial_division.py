"""Loads the power coefficients into the left column without dividing them by C(n, j)."""
import numpy as np


def power_to_bernstein(coeffs):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    column = a.copy()
    top = [column[0]]
    while len(column) > 1:
        column = column[:-1] + column[1:]
        top.append(column[0])
    return np.array(top)

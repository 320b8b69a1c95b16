"""Reads the last entry of each difference row (the differences at t = 1) instead of the first."""
from math import comb

import numpy as np


def bernstein_to_power(coeffs):
    b = np.array(coeffs, dtype=float)
    if b.ndim not in (1, 2) or len(b) == 0 or not np.all(np.isfinite(b)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    n = len(b) - 1
    row, column = b, [b[-1]]
    while len(row) > 1:
        row = row[1:] - row[:-1]
        column.append(row[-1])
    scale = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    return np.array(column) * scale.reshape((-1,) + (1,) * (b.ndim - 1))

"""Stops after dividing by C(n, j): returns the left column of the table, not its top row."""
from math import comb

import numpy as np


def power_to_bernstein(coeffs):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    n = len(a) - 1
    scale = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    return a / scale.reshape((-1,) + (1,) * (a.ndim - 1))

"""Puts the exponent i on (1 - t) and n - i on t, which gives B_{n-i}^n instead of B_i^n."""
from math import comb

import numpy as np


def bernstein(i, n, t):
    if not 0 <= i <= n:
        raise ValueError("need 0 <= i <= n")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    value = comb(n, i) * (1 - ts) ** i * ts ** (n - i)
    return float(value) if ts.ndim == 0 else value

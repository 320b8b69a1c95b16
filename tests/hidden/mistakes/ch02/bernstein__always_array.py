"""Turns t into an array with np.atleast_1d and so returns shape (1,) instead of a float for a number t."""
from math import factorial

import numpy as np


def bernstein(i, n, t):
    if i < 0 or i > n:
        raise ValueError("need 0 <= i <= n")
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1:
        raise ValueError("t must be a number or a 1-D array")
    binomial = factorial(n) / (factorial(i) * factorial(n - i))
    return binomial * (1 - t) ** (n - i) * t ** i

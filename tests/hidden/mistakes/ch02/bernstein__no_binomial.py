"""Leaves out the binomial coefficient C(n, i): only (1-t)^(n-i) t^i."""
import numpy as np


def bernstein(i, n, t):
    if not 0 <= i <= n:
        raise ValueError("need 0 <= i <= n")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    value = (1 - ts) ** (n - i) * ts ** i
    return float(value) if ts.ndim == 0 else value

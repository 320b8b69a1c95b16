"""Σ e_k B_k(t) without the absolute value: right on [0, 1] only."""
from math import comb

import numpy as np


def error_curve(errors, t):
    e = np.array(errors, dtype=float)
    if e.ndim not in (1, 2) or len(e) == 0 or not np.all(np.isfinite(e)):
        raise ValueError("errors: expected (n+1,) or (n+1, d)")
    if np.any(e < 0):
        raise ValueError("errors: expected non-negative errors")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)):
        raise ValueError("t: expected a number or a 1-D array")
    scalar = ts.ndim == 0
    ts = np.atleast_1d(ts)
    n = len(e) - 1
    k = np.arange(n + 1)
    basis = np.array([comb(n, i) for i in k]) * (1 - ts[:, None]) ** (n - k) * ts[:, None] ** k
    values = basis @ e
    if scalar:
        return float(values[0]) if e.ndim == 1 else values[0]
    return values

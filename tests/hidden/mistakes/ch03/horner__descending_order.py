"""Reads the coefficients highest power first (numpy.polyval's order) instead of ascending."""
import numpy as np


def horner(coeffs, t):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = ts[..., None] if a.ndim == 2 else ts
    h = a[0] + 0 * tt
    for coefficient in a[1:]:
        h = h * tt + coefficient
    return float(h) if h.ndim == 0 else h

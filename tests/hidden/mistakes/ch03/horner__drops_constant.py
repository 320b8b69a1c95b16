"""Stops the loop one step early: the last multiply by t is done but a0 is never added."""
import numpy as np


def horner(coeffs, t):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = ts[..., None] if a.ndim == 2 else ts
    n = len(a) - 1
    h = a[n] + 0 * tt
    for i in range(n - 1, 0, -1):
        h = h * tt + a[i]
    if n > 0:
        h = h * tt
    return float(h) if h.ndim == 0 else h

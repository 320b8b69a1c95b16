"""Updates h before d, so d picks up the new h: d = t d + h_(i-1) instead of t d + h_i."""
import numpy as np


def _checked(coeffs, t):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)):
        raise ValueError("t must be a number or a 1-D array")
    return a, ts


def horner_with_derivative(coeffs, t):
    a, ts = _checked(coeffs, t)
    tt = ts[..., None] if a.ndim == 2 else ts
    h = a[-1] + 0 * tt
    d = 0 * h
    for coefficient in a[-2::-1]:
        h = h * tt + coefficient
        d = d * tt + h
    if h.ndim == 0:
        return float(h), float(d)
    return h, d

"""Differentiates by shifting the coefficients, a_i t^i -> a_i t^(i-1), forgetting the factor i."""
import numpy as np


def _checked(coeffs, t):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0 or not np.all(np.isfinite(a)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)):
        raise ValueError("t must be a number or a 1-D array")
    return a, ts


def _horner(a, tt):
    h = a[-1] + 0 * tt
    for coefficient in a[-2::-1]:
        h = h * tt + coefficient
    return h


def horner_with_derivative(coeffs, t):
    a, ts = _checked(coeffs, t)
    tt = ts[..., None] if a.ndim == 2 else ts
    h = _horner(a, tt)
    d = _horner(a[1:], tt) if len(a) > 1 else 0 * h
    if h.ndim == 0:
        return float(h), float(d)
    return h, d

"""Updates the running binomial as bc·(n-i)/i instead of bc·(n-i+1)/i."""
import numpy as np


def bernstein_horner(coeffs, t):
    b = np.array(coeffs, dtype=float)
    if b.ndim not in (1, 2) or len(b) == 0 or not np.all(np.isfinite(b)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = ts[..., None] if b.ndim == 2 else ts
    n = len(b) - 1
    u = 1 - tt
    bc, tn = 1.0, 1.0
    value = b[0] * u
    for i in range(1, n):
        tn = tn * tt
        bc = bc * (n - i) / i
        value = (value + tn * bc * b[i]) * u
    value = value + tn * tt * b[n]
    return float(value) if value.ndim == 0 else value

"""Returns cumsum(p)/(n+1), dropping q_0 = 0: one coefficient too few, each shifted one place."""
import numpy as np


def bernstein_integral(coeffs):
    p = np.array(coeffs, dtype=float)
    if p.ndim not in (1, 2) or len(p) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    return np.cumsum(p, axis=0) / len(p)

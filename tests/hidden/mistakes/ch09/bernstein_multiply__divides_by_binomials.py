"""Turns the binomials upside down: divides by C(m, i) C(n, j) and multiplies by C(m+n, k)."""
from math import comb

import numpy as np


def bernstein_multiply(f, g):
    f = np.asarray(f, dtype=float)
    g = np.asarray(g, dtype=float)
    if f.ndim not in (1, 2) or f.ndim != g.ndim or f.shape[1:] != g.shape[1:] or len(f) == 0 or len(g) == 0:
        raise ValueError("f, g: expected matching coefficient arrays")
    m, n = len(f) - 1, len(g) - 1
    h = np.zeros((m + n + 1,) + f.shape[1:])
    for i in range(m + 1):
        for j in range(n + 1):
            h[i + j] += f[i] * g[j] / (comb(m, i) * comb(n, j))
    for k in range(m + n + 1):
        h[k] *= comb(m + n, k)
    return h

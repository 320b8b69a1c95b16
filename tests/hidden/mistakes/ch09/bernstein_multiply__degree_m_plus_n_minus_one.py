"""Allocates m + n coefficients for the product instead of m + n + 1, so the last one is lost."""
from math import comb

import numpy as np


def bernstein_multiply(f, g):
    f = np.asarray(f, dtype=float)
    g = np.asarray(g, dtype=float)
    if f.ndim not in (1, 2) or f.ndim != g.ndim or f.shape[1:] != g.shape[1:] or len(f) == 0 or len(g) == 0:
        raise ValueError("f, g: expected matching coefficient arrays")
    m, n = len(f) - 1, len(g) - 1
    h = np.zeros((max(m + n, 1),) + f.shape[1:])
    for i in range(m + 1):
        for j in range(n + 1):
            if i + j < len(h):
                h[i + j] += comb(m, i) * comb(n, j) / comb(m + n, i + j) * f[i] * g[j]
    return h

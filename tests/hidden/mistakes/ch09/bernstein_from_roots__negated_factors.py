"""Writes the linear factor as <r - t0, r - t1>, i.e. r - t: the sign is wrong for an odd number of roots."""
from math import comb

import numpy as np


def _multiply(f, g):
    m, n = len(f) - 1, len(g) - 1
    h = np.zeros(m + n + 1)
    for i in range(m + 1):
        for j in range(n + 1):
            h[i + j] += comb(m, i) * comb(n, j) / comb(m + n, i + j) * f[i] * g[j]
    return h


def bernstein_from_roots(roots, interval=(0, 1), leading=1.0):
    r = np.asarray(roots, dtype=float)
    iv = np.asarray(interval, dtype=float)
    if r.ndim != 1 or iv.shape != (2,) or not iv[0] < iv[1]:
        raise ValueError("roots, interval: bad input")
    t0, t1 = iv
    p = np.array([float(leading)])
    for root in r:
        p = _multiply(p, np.array([root - t0, root - t1]))
    return p

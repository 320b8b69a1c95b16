"""Forgets to divide L_k by C(m+n, k): the lines are right only at the two ends."""
from math import comb

import numpy as np


def _triples(value, name):
    a = np.array(value, dtype=float)
    if a.ndim != 2 or a.shape[1] != 3 or len(a) == 0 or not np.all(np.isfinite(a)) or not np.any(a):
        raise ValueError(name + ": expected (k+1, 3) triples")
    return a


def product_moving_line(p, q):
    p, q = _triples(p, "p"), _triples(q, "q")
    m, n = len(p) - 1, len(q) - 1
    out = np.zeros((m + n + 1, 3))
    for i in range(m + 1):
        for j in range(n + 1):
            out[i + j] += comb(m, i) * comb(n, j) * np.cross(p[i], q[j])
    return out

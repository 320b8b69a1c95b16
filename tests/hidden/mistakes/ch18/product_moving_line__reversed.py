"""Crosses Q × P instead of P × Q: every control line negated."""
from math import comb

import numpy as np


def _triples(value, name):
    a = np.array(value, dtype=float)
    if a.ndim != 2 or a.shape[1] != 3 or len(a) == 0 or not np.all(np.isfinite(a)) or not np.any(a):
        raise ValueError(name + ": expected (k+1, 3) triples")
    return a


def _product(p, q):
    m, n = len(p) - 1, len(q) - 1
    out = np.zeros((m + n + 1, 3))
    for i in range(m + 1):
        for j in range(n + 1):
            out[i + j] += comb(m, i) * comb(n, j) * np.cross(p[i], q[j])
    return out / np.array([comb(m + n, k) for k in range(m + n + 1)], dtype=float)[:, None]


def product_moving_line(p, q):
    return _product(_triples(q, "q"), _triples(p, "p"))

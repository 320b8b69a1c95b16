"""Scales every control line to unit length: each is the same line, but the moving line is another."""
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
    lines = _product(_triples(p, "p"), _triples(q, "q"))
    sizes = np.linalg.norm(lines, axis=1)
    return lines / np.where(sizes > 0, sizes, 1.0)[:, None]

"""Drops trailing zero coefficients, so the result is shorter than d·n + 1."""
import numpy as np


def implicit_polynomial(f, x, y, w=None):
    f = np.asarray(f, dtype=float)
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    w = np.ones(1) if w is None else np.asarray(w, dtype=float)
    if f.ndim != 2 or x.ndim != 1 or y.ndim != 1 or w.ndim != 1:
        raise ValueError("f must be 2-D, x, y, w 1-D")
    i, j = np.nonzero(f)
    if len(i) == 0:
        raise ValueError("f is zero")
    d = int((i + j).max())
    n = max(len(x), len(y), len(w)) - 1

    def power(c, k):
        r = np.ones(1)
        for _ in range(k):
            r = np.convolve(r, c)
        return r

    g = np.zeros(d * n + 1)
    for a, b in zip(i, j):
        term = np.convolve(np.convolve(power(x, a), power(y, b)), power(w, d - a - b))
        g[: len(term)] += f[a, b] * term
    return np.trim_zeros(g, 'b') if np.any(g) else g[:1]

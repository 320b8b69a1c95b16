"""Convolves the coefficients as if they were power coefficients: the binomial weights are left out."""
import numpy as np


def bernstein_multiply(f, g):
    f = np.asarray(f, dtype=float)
    g = np.asarray(g, dtype=float)
    if f.ndim not in (1, 2) or f.ndim != g.ndim or f.shape[1:] != g.shape[1:] or len(f) == 0 or len(g) == 0:
        raise ValueError("f, g: expected matching coefficient arrays")
    h = np.zeros((len(f) + len(g) - 1,) + f.shape[1:])
    for i in range(len(f)):
        h[i : i + len(g)] += f[i] * g
    return h

"""Forgets the factor 1/3: a cubic's hodograph is 3 (P_(i+1) - P_i), not P_(i+1) - P_i."""
import numpy as np
from math import comb


def ph_cubic(p0, u, v):
    p0 = np.array(p0, dtype=float)
    u = np.array(u, dtype=float)
    v = np.array(v, dtype=float)
    if p0.shape != (2,) or u.shape != (2,) or v.shape != (2,):
        raise ValueError("p0, u, v: two numbers each")
    (u0, u1), (v0, v1) = u, v
    h = np.array([[u0 * u0 - v0 * v0, 2 * u0 * v0], [u0 * u1 - v0 * v1, u0 * v1 + u1 * v0],
                  [u1 * u1 - v1 * v1, 2 * u1 * v1]])
    return np.vstack([p0, p0 + np.cumsum(h, axis=0)])

"""Forgets the interval: uses n (P_{i+1} - P_i), correct only on [0, 1]."""
import numpy as np


def hodograph(points, interval=(0, 1)):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    t0, t1 = interval
    if not t0 < t1:
        raise ValueError("interval must have t0 < t1")
    n = len(P) - 1
    if n == 0:
        return np.zeros_like(P)
    return n * (P[1:] - P[:-1])

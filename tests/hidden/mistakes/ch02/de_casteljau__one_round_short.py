"""Runs the interpolation loop n - 1 times instead of n (range(1, n)), stopping one level above the point."""
import numpy as np


def de_casteljau(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)[:, None, None]
    level = np.repeat(P[None], len(tt), axis=0)
    n = len(P) - 1
    for _ in range(1, n):
        level = (1 - tt) * level[:, :-1] + tt * level[:, 1:]
    result = level[:, 0]
    return result[0] if ts.ndim == 0 else result

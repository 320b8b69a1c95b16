"""Interpolates with t P_i + (1 - t) P_{i+1}, which traces the curve backwards (evaluates P(1 - t))."""
import numpy as np


def _point(P, t):
    level = P.copy()
    while len(level) > 1:
        level = t * level[:-1] + (1 - t) * level[1:]
    return level[0]


def de_casteljau(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    ts = np.asarray(t, dtype=float)
    if ts.ndim == 0:
        return _point(P, float(ts))
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.array([_point(P, s) for s in ts]).reshape(len(ts), P.shape[1])

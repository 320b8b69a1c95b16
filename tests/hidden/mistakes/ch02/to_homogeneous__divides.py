"""Divides the coordinates by the weight instead of multiplying (the projection direction, not the lift)."""
import numpy as np


def to_homogeneous(points, weights):
    P = np.array(points, dtype=float)
    w = np.array(weights, dtype=float)
    if P.ndim != 2 or w.shape != (len(P),):
        raise ValueError("need points (n+1, d) and n+1 weights")
    if np.any(w == 0):
        raise ValueError("weights must be nonzero")
    return np.hstack([P / w[:, None], w[:, None]])

"""Right values, but scales the caller's points array in place (np.asarray does not copy a float array)."""
import numpy as np


def to_homogeneous(points, weights):
    P = np.asarray(points, dtype=float)
    w = np.asarray(weights, dtype=float)
    if P.ndim != 2 or w.shape != (len(P),):
        raise ValueError("need points (n+1, d) and n+1 weights")
    if np.any(w == 0):
        raise ValueError("weights must be nonzero")
    P *= w[:, None]
    return np.hstack([P, w[:, None]])

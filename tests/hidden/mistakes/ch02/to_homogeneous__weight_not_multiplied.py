"""Appends the weight as a last column but does not multiply the coordinates by it: (x, w) instead of (w x, w)."""
import numpy as np


def to_homogeneous(points, weights):
    P = np.array(points, dtype=float)
    w = np.array(weights, dtype=float)
    if P.ndim != 2 or w.shape != (len(P),):
        raise ValueError("need points (n+1, d) and n+1 weights")
    if np.any(w == 0):
        raise ValueError("weights must be nonzero")
    return np.column_stack([P, w])

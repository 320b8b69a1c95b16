"""Returns the Cartesian control points of Q and R, (n, d), without their weights."""
import numpy as np


def split_qr(points, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected shape (n+1, d) with n >= 1")
    if weights is not None:
        w = np.array(weights, dtype=float)
        if w.shape != (len(P),) or np.any(w == 0):
            raise ValueError("weights: expected n+1 nonzero weights")
    return P[:-1], P[1:]

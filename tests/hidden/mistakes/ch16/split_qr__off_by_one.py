"""Takes R as P_1 .. P_(n-1), one point short (a slice ending one too early)."""
import numpy as np


def split_qr(points, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected shape (n+1, d) with n >= 1")
    w = np.ones(len(P)) if weights is None else np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w == 0):
        raise ValueError("weights: expected n+1 nonzero weights")
    H = np.column_stack([P * w[:, None], w])
    return H[:-1], H[1:-1]

"""Checks the weights but never uses them: always evaluates the polynomial curve."""
import numpy as np


def evaluate(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    if weights is not None:
        w = np.asarray(weights, dtype=float)
        if w.shape != (len(P),) or np.any(w == 0):
            raise ValueError("need n+1 nonzero weights")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    s = np.atleast_1d(ts)[:, None, None]
    level = np.broadcast_to(P, (len(s),) + P.shape)
    for _ in range(len(P) - 1):
        level = (1 - s) * level[:, :-1] + s * level[:, 1:]
    out = level[:, 0]
    return out[0] if ts.ndim == 0 else out

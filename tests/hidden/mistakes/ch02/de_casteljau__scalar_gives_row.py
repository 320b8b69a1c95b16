"""Always returns shape (k, d): a number t comes back as a (1, d) array instead of a (d,) point."""
import numpy as np


def de_casteljau(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    ts = np.atleast_1d(np.asarray(t, dtype=float))
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    out = np.empty((len(ts), P.shape[1]))
    for k, s in enumerate(ts):
        level = P
        for _ in range(len(P) - 1):
            level = (1 - s) * level[:-1] + s * level[1:]
        out[k] = level[0]
    return out

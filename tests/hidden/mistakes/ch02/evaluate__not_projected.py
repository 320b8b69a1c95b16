"""Runs de Casteljau on the homogeneous points w_i (P_i, 1) but drops the last coordinate instead of dividing by it."""
import numpy as np


def _casteljau(P, ts):
    level = np.repeat(P[None], len(ts), axis=0)
    s = ts[:, None, None]
    while level.shape[1] > 1:
        level = (1 - s) * level[:, :-1] + s * level[:, 1:]
    return level[:, 0]


def evaluate(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)
    if weights is None:
        out = _casteljau(P, tt)
    else:
        w = np.array(weights, dtype=float)
        if w.shape != (len(P),) or np.any(w == 0):
            raise ValueError("need n+1 nonzero weights")
        out = _casteljau(np.column_stack([P * w[:, None], w]), tt)[:, :-1]
    return out[0] if ts.ndim == 0 else out

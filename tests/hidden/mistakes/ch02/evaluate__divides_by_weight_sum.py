"""Normalises by the plain sum of the weights instead of the weighted Bernstein sum w(t) at each t."""
from math import comb

import numpy as np


def evaluate(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)[:, None]
    n = len(P) - 1
    i = np.arange(n + 1)
    B = np.array([comb(n, k) for k in i]) * (1 - tt) ** (n - i) * tt ** i
    if weights is None:
        out = B @ P
    else:
        w = np.array(weights, dtype=float)
        if w.shape != (n + 1,) or np.any(w == 0):
            raise ValueError("need n+1 nonzero weights")
        out = (B * w) @ P / w.sum()
    return out[0] if ts.ndim == 0 else out

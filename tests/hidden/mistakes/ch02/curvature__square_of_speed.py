"""Divides |P' × P''| by |P'|² instead of the cube of the speed |P'|³."""
import numpy as np


def _derivatives(H, ts):
    """Values, first and second derivatives of the polynomial curve with control points H."""
    out = []
    for _ in range(3):
        level = np.repeat(H[None], len(ts), axis=0)
        s = ts[:, None, None]
        while level.shape[1] > 1:
            level = (1 - s) * level[:, :-1] + s * level[:, 1:]
        out.append(level[:, 0])
        n = len(H) - 1
        H = n * np.diff(H, axis=0) if n > 0 else np.zeros_like(H)
    return out


def curvature(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] < 2:
        raise ValueError("points must have shape (n+1, d) with d >= 2")
    ts = np.asarray(t, dtype=float)
    tt = np.atleast_1d(ts)
    w = np.ones(len(P)) if weights is None else np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w == 0):
        raise ValueError("need n+1 nonzero weights")
    X, X1, X2 = _derivatives(np.column_stack([P * w[:, None], w]), tt)
    W, W1, W2 = X[:, -1:], X1[:, -1:], X2[:, -1:]
    p = X[:, :-1] / W
    d1 = (X1[:, :-1] - W1 * p) / W
    d2 = (X2[:, :-1] - 2 * W1 * d1 - W2 * p) / W
    if P.shape[1] == 2:
        cross = np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])
    else:
        cross = np.linalg.norm(np.cross(d1, d2), axis=1)
    speed = np.linalg.norm(d1, axis=1)
    kappa = cross / speed ** 2
    return float(kappa[0]) if ts.ndim == 0 else kappa

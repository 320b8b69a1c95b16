"""Uses the polynomial formula on the control points even when weights are given (the hodograph of a rational curve is not n ΔP_i)."""
import numpy as np


def _eval(P, ts):
    level = np.repeat(P[None], len(ts), axis=0)
    s = ts[:, None, None]
    while level.shape[1] > 1:
        level = (1 - s) * level[:, :-1] + s * level[:, 1:]
    return level[:, 0]


def curvature(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] < 2:
        raise ValueError("points must have shape (n+1, d) with d >= 2")
    if weights is not None and np.any(np.asarray(weights, dtype=float) == 0):
        raise ValueError("weights must be nonzero")
    ts = np.asarray(t, dtype=float)
    tt = np.atleast_1d(ts)
    n = len(P) - 1
    D1 = n * np.diff(P, axis=0) if n >= 1 else np.zeros_like(P)
    D2 = (n - 1) * np.diff(D1, axis=0) if n >= 2 else np.zeros_like(P)
    v, a = _eval(D1, tt), _eval(D2, tt)
    if P.shape[1] == 2:
        cross = np.abs(v[:, 0] * a[:, 1] - v[:, 1] * a[:, 0])
    else:
        cross = np.linalg.norm(np.cross(v, a), axis=1)
    kappa = cross / np.linalg.norm(v, axis=1) ** 3
    return float(kappa[0]) if ts.ndim == 0 else kappa

"""In the plane returns (x'y'' - y'x'')/|P'|³ without the absolute value, so curves turning clockwise get negative curvature."""
import numpy as np


def _eval(P, ts):
    level = np.repeat(P[None], len(ts), axis=0)
    s = ts[:, None, None]
    while level.shape[1] > 1:
        level = (1 - s) * level[:, :-1] + s * level[:, 1:]
    return level[:, 0]


def _hodo(P):
    n = len(P) - 1
    return n * np.diff(P, axis=0) if n >= 1 else np.zeros_like(P)


def curvature(points, t, weights=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] < 2:
        raise ValueError("points must have shape (n+1, d) with d >= 2")
    w = np.ones(len(P)) if weights is None else np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w == 0):
        raise ValueError("need n+1 nonzero weights")
    ts = np.asarray(t, dtype=float)
    tt = np.atleast_1d(ts)
    H = np.column_stack([P * w[:, None], w])
    X, X1, X2 = _eval(H, tt), _eval(_hodo(H), tt), _eval(_hodo(_hodo(H)), tt)
    p = X[:, :-1] / X[:, -1:]
    v = (X1[:, :-1] - X1[:, -1:] * p) / X[:, -1:]
    a = (X2[:, :-1] - 2 * X1[:, -1:] * v - X2[:, -1:] * p) / X[:, -1:]
    if P.shape[1] == 2:
        cross = v[:, 0] * a[:, 1] - v[:, 1] * a[:, 0]
    else:
        cross = np.linalg.norm(np.cross(v, a), axis=1)
    kappa = cross / np.linalg.norm(v, axis=1) ** 3
    return float(kappa[0]) if ts.ndim == 0 else kappa

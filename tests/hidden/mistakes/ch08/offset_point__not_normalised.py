"""Forgets to divide the normal by |Q'|, so the offset is at distance rho |Q'(t)|, not rho."""
import numpy as np
from math import comb


def _curve(points, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError("points must have shape (n+1, 2) with n >= 1")
    if weights is None:
        return P, None
    w = np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w <= 0):
        raise ValueError("weights must be n+1 positive numbers")
    return P, w


def _params(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.atleast_1d(ts), ts.ndim == 0


def _bez(C, ts):
    n = len(C) - 1
    ts = np.asarray(ts, dtype=float)[:, None]
    i = np.arange(n + 1)
    B = np.array([comb(n, k) for k in i]) * (1 - ts) ** (n - i) * ts ** i
    return B @ C


def _hod(C):
    n = len(C) - 1
    return n * np.diff(C, axis=0) if n else np.zeros_like(C)


def _derivs(P, w, ts):
    """Q, Q', Q'' at ts."""
    if w is None:
        H = P
    else:
        H = np.column_stack([P * w[:, None], w])
    H1, H2 = _hod(H), _hod(_hod(H))
    X, X1, X2 = _bez(H, ts), _bez(H1, ts), _bez(H2, ts)
    if w is None:
        return X, X1, X2
    W, W1, W2 = X[:, 2:], X1[:, 2:], X2[:, 2:]
    Q = X[:, :2] / W
    Q1 = (X1[:, :2] - W1 * Q) / W
    Q2 = (X2[:, :2] - 2 * W1 * Q1 - W2 * Q) / W
    return Q, Q1, Q2


def _check_speed(P, Q1):
    speed = np.linalg.norm(Q1, axis=1)
    if np.any(speed <= 1e-12 * (len(P) - 1) * np.abs(np.diff(P, axis=0)).max()):
        raise ValueError("the curve stops at a requested t")
    return speed


def offset_point(points, t, rho, weights=None):
    P, w = _curve(points, weights)
    ts, scalar = _params(t)
    rho = float(rho)
    Q, Q1, _ = _derivs(P, w, ts)
    speed = _check_speed(P, Q1)
    out = Q + rho * np.column_stack([Q1[:, 1], -Q1[:, 0]])
    return out[0] if scalar else out

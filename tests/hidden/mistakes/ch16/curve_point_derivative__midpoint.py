"""Takes p as the midpoint of q and r instead of the point at t R_w / P_w along the segment."""
import numpy as np
from math import comb


def _prepare(points, t, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) < 1:
        raise ValueError("points: expected shape (n+1, d)")
    w = np.ones(len(P)) if weights is None else np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w == 0):
        raise ValueError("weights: expected n+1 nonzero weights")
    ts = np.array(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t: expected a number or a 1-D array")
    H = np.column_stack([P * w[:, None], w])
    if len(H) == 1:
        H = np.vstack([H, H])
    return H, np.atleast_1d(ts), ts.ndim == 0


def _bez(C, ts):
    n = len(C) - 1
    i = np.arange(n + 1)
    B = np.array([comb(n, k) for k in i]) * (1 - ts[:, None]) ** (n - i) * ts[:, None] ** i
    return B @ C


def _qr(points, t, weights):
    H, ts, scalar = _prepare(points, t, weights)
    Q, R = _bez(H[:-1], ts), _bez(H[1:], ts)
    Pw = (1 - ts) * Q[:, -1] + ts * R[:, -1]
    if np.any(Pw == 0):
        raise ValueError("t: the curve passes through infinity")
    p = ((1 - ts)[:, None] * Q + ts[:, None] * R)[:, :-1] / Pw[:, None]
    return len(H) - 1, ts, scalar, Q, R, Pw, p


def curve_point_derivative(points, t, weights=None):
    n, ts, scalar, Q, R, Pw, p = _qr(points, t, weights)
    q, r = Q[:, :-1] / Q[:, -1:], R[:, :-1] / R[:, -1:]
    dp = n * Q[:, -1:] * R[:, -1:] / Pw[:, None] ** 2 * (r - q)
    p = (q + r) / 2
    return (p[0], dp[0]) if scalar else (p, dp)

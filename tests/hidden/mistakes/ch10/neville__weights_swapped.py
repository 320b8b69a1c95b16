"""Puts (τ - t_i) on the left point and (t_(i+r) - τ) on the right one: each step reflects instead of interpolating."""
import numpy as np


def neville(ts, points, t):
    ts = np.array(ts, dtype=float)
    P = np.array(points, dtype=float)
    if ts.ndim != 1 or len(ts) == 0 or len(np.unique(ts)) != len(ts):
        raise ValueError("ts: expected distinct nodes")
    if P.ndim not in (1, 2) or len(P) != len(ts):
        raise ValueError("points: one per node")
    tau = np.array(t, dtype=float)
    if tau.ndim > 1:
        raise ValueError("t: a number or a 1-D array")
    u = np.atleast_1d(tau).reshape((-1,) + (1,) * P.ndim)
    level = np.broadcast_to(P, (u.shape[0],) + P.shape).copy()
    n = len(ts) - 1
    for r in range(1, n + 1):
        first = ts[: n + 1 - r].reshape((-1,) + (1,) * (P.ndim - 1))
        last = ts[r:].reshape((-1,) + (1,) * (P.ndim - 1))
        level = ((u - first) * level[:, :-1] + (last - u) * level[:, 1:]) / (last - first)
    return level[0, 0] if tau.ndim == 0 else level[:, 0]

"""Stops one level early and returns p_(0..n-1)(τ), the interpolant of all points but the last."""
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
    for r in range(1, n):
        first = ts[: n + 1 - r].reshape((-1,) + (1,) * (P.ndim - 1))
        last = ts[r:].reshape((-1,) + (1,) * (P.ndim - 1))
        level = ((last - u) * level[:, :-1] + (u - first) * level[:, 1:]) / (last - first)
    return level[0, 0] if tau.ndim == 0 else level[:, 0]

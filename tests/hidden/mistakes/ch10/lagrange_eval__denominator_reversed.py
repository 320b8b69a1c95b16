"""Divides by (t_j - t_i) instead of (t_i - t_j): every basis function is off by the sign (-1)^n."""
import numpy as np


def lagrange_eval(ts, points, t):
    ts = np.array(ts, dtype=float)
    P = np.array(points, dtype=float)
    if ts.ndim != 1 or len(ts) == 0 or len(np.unique(ts)) != len(ts):
        raise ValueError("ts: expected distinct nodes")
    if P.ndim not in (1, 2) or len(P) != len(ts):
        raise ValueError("points: one per node")
    tau = np.array(t, dtype=float)
    if tau.ndim > 1:
        raise ValueError("t: a number or a 1-D array")
    u = np.atleast_1d(tau)
    basis = np.ones((len(u), len(ts)))
    for i in range(len(ts)):
        for j in range(len(ts)):
            if j != i:
                basis[:, i] *= (u - ts[j]) / (ts[j] - ts[i])
    values = basis @ P
    return values[0] if tau.ndim == 0 else values

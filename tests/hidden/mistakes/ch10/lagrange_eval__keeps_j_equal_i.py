"""Multiplies over every j, including j = i: the factor (t - t_i)/(t_i - t_i) makes NaN and infinities."""
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
    with np.errstate(divide="ignore", invalid="ignore"):
        basis = np.ones((len(u), len(ts)))
        for i in range(len(ts)):
            for j in range(len(ts)):
                basis[:, i] *= (u - ts[j]) / (ts[i] - ts[j])
        values = basis @ P
    return np.array(values[0]) if tau.ndim == 0 else values

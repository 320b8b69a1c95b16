"""Written for a single number t: an array of parameters collapses into one point."""
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
    result = 0.0
    for i in range(len(ts)):
        weight = 1.0
        for j in range(len(ts)):
            if j != i:
                weight = weight * (tau - ts[j]) / (ts[i] - ts[j])
        result = result + np.sum(weight) * P[i]
    return result

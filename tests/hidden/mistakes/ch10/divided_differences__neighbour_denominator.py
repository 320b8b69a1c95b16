"""Divides every level by t_(i+1) - t_i, the gap of neighbouring nodes: right only for unit spacing at level 1."""
import numpy as np


def divided_differences(ts, values):
    ts = np.array(ts, dtype=float)
    c = np.array(values, dtype=float)
    if ts.ndim != 1 or len(ts) == 0 or len(np.unique(ts)) != len(ts):
        raise ValueError("ts: expected distinct nodes")
    if c.ndim not in (1, 2) or len(c) != len(ts):
        raise ValueError("values: one per node")
    columns = [c]
    for k in range(1, len(ts)):
        prev = columns[-1]
        step = (ts[1 : len(prev)] - ts[: len(prev) - 1]).reshape((-1,) + (1,) * (c.ndim - 1))
        columns.append((prev[1:] - prev[:-1]) / step)
    return np.array([col[0] for col in columns])

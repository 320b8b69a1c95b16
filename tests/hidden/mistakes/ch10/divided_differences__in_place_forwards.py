"""Updates one array in place from the top down, so each entry uses a neighbour that was already overwritten."""
import numpy as np


def divided_differences(ts, values):
    ts = np.array(ts, dtype=float)
    c = np.array(values, dtype=float)
    if ts.ndim != 1 or len(ts) == 0 or len(np.unique(ts)) != len(ts):
        raise ValueError("ts: expected distinct nodes")
    if c.ndim not in (1, 2) or len(c) != len(ts):
        raise ValueError("values: one per node")
    n = len(ts) - 1
    for k in range(1, n + 1):
        for i in range(k, n + 1):  # should run from n down to k
            c[i] = (c[i] - c[i - 1]) / (ts[i] - ts[i - k])
    return c

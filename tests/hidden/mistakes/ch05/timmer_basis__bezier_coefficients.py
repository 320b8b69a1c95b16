"""Copies Bézier's factor 3 into the middle functions, 3t(1-t)² and 3t²(1-t), so the four no longer sum to one."""
import numpy as np


def timmer_basis(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    values = np.stack([(1 - ts) ** 2 * (1 - 2 * ts), 3 * ts * (1 - ts) ** 2, 3 * ts**2 * (1 - ts), ts**2 * (2 * ts - 1)], axis=-1)
    return values

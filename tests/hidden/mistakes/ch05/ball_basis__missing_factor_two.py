"""Leaves out the factor 2 of the middle functions: t(1-t)² and t²(1-t)."""
import numpy as np


def ball_basis(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.stack([(1 - ts) ** 2, ts * (1 - ts) ** 2, ts**2 * (1 - ts), ts**2], axis=-1)

"""Builds np.array([f0, f1, f2, f3]), so k parameters give shape (4, k) instead of (k, 4)."""
import numpy as np


def ball_basis(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.array([(1 - ts) ** 2, 2 * ts * (1 - ts) ** 2, 2 * ts**2 * (1 - ts), ts**2])

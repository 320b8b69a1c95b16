"""Always returns shape (k, 4): a number t comes back as a (1, 4) array instead of shape (4,)."""
import numpy as np


def timmer_basis(t):
    ts = np.atleast_1d(np.asarray(t, dtype=float))
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.column_stack([(1 - ts) ** 2 * (1 - 2 * ts), 4 * ts * (1 - ts) ** 2, 4 * ts**2 * (1 - ts), ts**2 * (2 * ts - 1)])

"""Lists the functions from f3 down to f0; at t = 1/2 the values look right because the set is symmetric."""
import numpy as np


def timmer_basis(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.stack([ts**2 * (2 * ts - 1), 4 * ts**2 * (1 - ts), 4 * ts * (1 - ts) ** 2, (1 - ts) ** 2 * (1 - 2 * ts)], axis=-1)

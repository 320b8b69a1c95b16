"""Uses the Bézier end functions (1-t)³ and t³ instead of Ball's quadratic (1-t)² and t²."""
import numpy as np


def ball_basis(t):
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    return np.stack([(1 - ts) ** 3, 2 * ts * (1 - ts) ** 2, 2 * ts**2 * (1 - ts), ts**3], axis=-1)

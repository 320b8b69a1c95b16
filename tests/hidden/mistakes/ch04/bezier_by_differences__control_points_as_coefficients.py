"""Marches the control points as if they were power coefficients: P(t) = P_0 + P_1 t + ... + P_n tⁿ."""
from math import factorial

import numpy as np


def bezier_by_differences(points, steps):
    a = np.array(points, dtype=float)
    if a.ndim != 2 or len(a) == 0 or not np.isfinite(a).all():
        raise ValueError("points must be a finite array of shape (n+1, d)")
    if not isinstance(steps, (int, np.integer)):
        raise TypeError("steps must be an integer")
    if steps < 1:
        raise ValueError("steps must be >= 1")
    n, delta = len(a) - 1, 1.0 / steps
    stirling = np.zeros((n + 1, n + 1))
    stirling[0, 0] = 1.0
    for k in range(1, n + 1):
        for j in range(1, k + 1):
            stirling[k, j] = j * stirling[k - 1, j] + stirling[k - 1, j - 1]
    column = np.array([factorial(j) * sum(stirling[k, j] * a[k] * delta**k for k in range(n + 1))
                       for j in range(n + 1)])
    out = np.empty((steps + 1, a.shape[1]))
    for i in range(steps + 1):
        out[i] = column[0]
        column[:-1] = column[:-1] + column[1:]
    return out

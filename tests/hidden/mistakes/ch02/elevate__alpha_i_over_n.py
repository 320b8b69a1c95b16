"""Uses α_i = i/n (the old degree) instead of i/(n+1)."""
import numpy as np


def elevate(points):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) == 0:
        raise ValueError("points must have shape (n+1, d) with at least one point")
    n = len(P) - 1
    Q = np.empty((n + 2, P.shape[1]))
    Q[0], Q[-1] = P[0], P[-1]
    for i in range(1, n + 1):
        alpha = i / n
        Q[i] = alpha * P[i - 1] + (1 - alpha) * P[i]
    return Q

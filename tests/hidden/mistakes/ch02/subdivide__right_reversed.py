"""Collects the right half from the top level down (P_n^0, P_{n-1}^1, ...), so its control points come out in reverse order."""
import numpy as np


def subdivide(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    if np.ndim(t) != 0:
        raise ValueError("t must be a single number")
    left, right = [P[0]], [P[-1]]
    level = P
    while len(level) > 1:
        level = (1 - t) * level[:-1] + t * level[1:]
        left.append(level[0])
        right.append(level[-1])
    return np.array(left), np.array(right)

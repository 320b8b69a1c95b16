"""Returns (right, left) instead of (left, right)."""
import numpy as np


def subdivide(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    if np.ndim(t) != 0:
        raise ValueError("t must be a single number")
    levels = [P]
    for _ in range(len(P) - 1):
        levels.append((1 - t) * levels[-1][:-1] + t * levels[-1][1:])
    first = np.array([lev[0] for lev in levels])
    last = np.array([lev[-1] for lev in levels[::-1]])
    return last, first

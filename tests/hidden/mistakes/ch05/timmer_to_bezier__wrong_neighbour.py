"""Writes P2 = (4 Q2 - Q1)/3, subtracting the neighbour Q1 instead of the end point Q3."""
import numpy as np


def timmer_to_bezier(points):
    Q = np.array(points, dtype=float)
    if Q.ndim != 2 or len(Q) != 4:
        raise ValueError("points must have shape (4, d)")
    return np.array([Q[0], (4 * Q[1] - Q[0]) / 3, (4 * Q[2] - Q[1]) / 3, Q[3]])

"""Applies the notes' Bézier-to-Timmer formulas Q1 = (P0 + 3 P1)/4, Q2 = (P3 + 3 P2)/4 in the wrong direction."""
import numpy as np


def timmer_to_bezier(points):
    Q = np.array(points, dtype=float)
    if Q.ndim != 2 or len(Q) != 4:
        raise ValueError("points must have shape (4, d)")
    return np.array([Q[0], (Q[0] + 3 * Q[1]) / 4, (Q[3] + 3 * Q[2]) / 4, Q[3]])

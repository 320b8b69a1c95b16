"""Assumes Timmer's control points already are the Bézier ones and returns a copy of them."""
import numpy as np


def timmer_to_bezier(points):
    Q = np.array(points, dtype=float)
    if Q.ndim != 2 or len(Q) != 4:
        raise ValueError("points must have shape (4, d)")
    return Q.copy()

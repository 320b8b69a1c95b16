"""Adds the coordinate bounds, L_x + L_y, instead of combining them by Pythagoras."""
import numpy as np


def bezier_segments_needed(points, tol):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) == 0:
        raise ValueError("points: expected shape (n+1, d)")
    if not tol > 0:
        raise ValueError("tol: expected a tolerance > 0")
    n = len(P) - 1
    if n < 2:
        return 1
    L = n * (n - 1) * np.abs(np.diff(P, n=2, axis=0)).max(axis=0)
    return max(1, int(np.ceil(np.sqrt(L.sum() / (8 * tol)))))

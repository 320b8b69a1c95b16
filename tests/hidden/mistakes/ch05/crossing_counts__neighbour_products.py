"""Counts neighbours whose heights have a negative product, so a crossing through a vertex on the line
(heights 1, 0, -1) is missed."""
import numpy as np


def crossing_counts(values, points, line):
    V, P, L = np.array(values, dtype=float), np.array(points, dtype=float), np.array(line, dtype=float)
    if V.ndim != 2 or P.shape != (V.shape[1], 2) or L.shape != (3,) or not np.any(L[:2]):
        raise ValueError("bad input")
    if not (np.all(np.isfinite(V)) and np.all(np.isfinite(P)) and np.all(np.isfinite(L))):
        raise ValueError("NaN or infinity")

    def changes(h):
        return int(np.count_nonzero(h[1:] * h[:-1] < 0))

    return changes(P @ L[:2] + L[2]), changes(V @ P @ L[:2] + L[2])

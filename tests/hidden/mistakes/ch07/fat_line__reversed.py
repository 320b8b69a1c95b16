"""Takes the line through Pn and P0 (Pn × P0): the opposite orientation swaps and negates dmin, dmax."""
import numpy as np


def fat_line(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError("points must be (n+1, 2) with n >= 1")
    line = np.cross([*P[-1], 1.0], [*P[0], 1.0])
    norm = np.hypot(line[0], line[1])
    if norm == 0:
        raise ValueError("P0 = Pn")
    line = line / norm
    d = P @ line[:2] + line[2]
    return line, min(d.min(), 0.0), max(d.max(), 0.0)

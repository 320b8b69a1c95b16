"""Solves the 2x2 system a x + b y = -c for the Cartesian point: parallel lines make the system singular."""
import numpy as np


def line_intersection(l1, l2):
    a = np.asarray(l1, dtype=float)
    b = np.asarray(l2, dtype=float)
    if a.shape != (3,) or b.shape != (3,):
        raise ValueError("lines must be 3-vectors")
    x, y = np.linalg.solve(np.array([a[:2], b[:2]]), -np.array([a[2], b[2]]))
    return np.array([x, y, 1.0])

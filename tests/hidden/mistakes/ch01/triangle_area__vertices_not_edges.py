"""Crosses the position vectors p2 × p3 instead of the edge vectors (p2 - p1) × (p3 - p1)."""
import numpy as np


def triangle_area(p1, p2, p3):
    p1, p2, p3 = (np.asarray(p, dtype=float) for p in (p1, p2, p3))
    if not (p1.shape == p2.shape == p3.shape) or p1.shape not in ((2,), (3,)):
        raise ValueError("expected three 2-D or three 3-D points")
    if p1.shape == (2,):
        p2, p3 = np.append(p2, 0.0), np.append(p3, 0.0)
    return float(np.linalg.norm(np.cross(p2, p3))) / 2

"""In 2-D returns the signed area x1 y2 - x2 y1 over 2, negative for a clockwise triangle."""
import numpy as np


def triangle_area(p1, p2, p3):
    p1, p2, p3 = (np.asarray(p, dtype=float) for p in (p1, p2, p3))
    if not (p1.shape == p2.shape == p3.shape) or p1.shape not in ((2,), (3,)):
        raise ValueError("expected three 2-D or three 3-D points")
    a, b = p2 - p1, p3 - p1
    if p1.shape == (2,):
        return float(a[0] * b[1] - a[1] * b[0]) / 2
    return float(np.linalg.norm(np.cross(a, b))) / 2

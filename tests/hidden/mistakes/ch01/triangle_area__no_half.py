"""Returns the length of the cross product, forgetting the factor 1/2 (the parallelogram's area)."""
import numpy as np


def triangle_area(p1, p2, p3):
    p1, p2, p3 = (np.asarray(p, dtype=float) for p in (p1, p2, p3))
    if not (p1.shape == p2.shape == p3.shape) or p1.shape not in ((2,), (3,)):
        raise ValueError("expected three 2-D or three 3-D points")
    if p1.shape == (2,):
        p1, p2, p3 = (np.append(p, 0.0) for p in (p1, p2, p3))
    return float(np.linalg.norm(np.cross(p2 - p1, p3 - p1)))

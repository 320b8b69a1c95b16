"""Returns l1 × l2 even when the lines coincide: the zero vector (0, 0, 0) is no point."""
import numpy as np


def line_intersection(l1, l2):
    a = np.asarray(l1, dtype=float)
    b = np.asarray(l2, dtype=float)
    if a.shape != (3,) or b.shape != (3,):
        raise ValueError("lines must be 3-vectors")
    if not a.any() or not b.any():
        raise ValueError("(0, 0, 0) is not a line")
    p = np.cross(a, b)
    return p

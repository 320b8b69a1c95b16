"""Normalises the cross product to W = 1 without checking W: a point at infinity becomes inf/NaN."""
import numpy as np


def line_intersection(l1, l2):
    a = np.asarray(l1, dtype=float)
    b = np.asarray(l2, dtype=float)
    if a.shape != (3,) or b.shape != (3,):
        raise ValueError("lines must be 3-vectors")
    if not a.any() or not b.any():
        raise ValueError("(0, 0, 0) is not a line")
    p = np.cross(a, b)
    if np.linalg.norm(p) <= 1e-12 * np.linalg.norm(a) * np.linalg.norm(b):
        raise ValueError("the lines coincide")
    with np.errstate(divide='ignore', invalid='ignore'):
        return p / p[2]

"""Computes v = u × n instead of n × u, so every rotation goes the wrong way round."""
import numpy as np


def rotate_about_axis(point, axis_point, axis_direction, angle):
    P = np.asarray(point, dtype=float)
    B = np.asarray(axis_point, dtype=float)
    n = np.asarray(axis_direction, dtype=float)
    if P.shape[-1] != 3 or B.shape != (3,) or n.shape != (3,):
        raise ValueError("expected 3-D points and a 3-D axis direction")
    length = np.linalg.norm(n)
    if length == 0:
        raise ValueError("axis_direction must be nonzero")
    n = n / length
    C = B + ((P - B) @ n)[..., None] * n
    u = P - C
    v = np.cross(u, n)
    return C + u * np.cos(angle) + v * np.sin(angle)

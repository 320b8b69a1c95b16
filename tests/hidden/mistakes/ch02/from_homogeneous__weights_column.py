"""Slices the weights with H[:, -1:], returning a column of shape (n+1, 1) instead of (n+1,)."""
import numpy as np


def from_homogeneous(homogeneous):
    H = np.array(homogeneous, dtype=float)
    if H.ndim != 2 or H.shape[1] < 2:
        raise ValueError("homogeneous must have shape (n+1, d+1) with d >= 1")
    w = H[:, -1:]
    if np.any(w == 0):
        raise ValueError("zero weight")
    return H[:, :-1] / w, w

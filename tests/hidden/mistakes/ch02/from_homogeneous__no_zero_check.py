"""Divides without checking for a zero weight, returning infinities instead of raising a ValueError."""
import numpy as np


def from_homogeneous(homogeneous):
    H = np.array(homogeneous, dtype=float)
    if H.ndim != 2 or H.shape[1] < 2:
        raise ValueError("homogeneous must have shape (n+1, d+1) with d >= 1")
    w = H[:, -1]
    with np.errstate(divide="ignore", invalid="ignore"):
        return H[:, :-1] / w[:, None], w

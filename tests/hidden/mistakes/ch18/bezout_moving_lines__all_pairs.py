"""Sums over every pair l < m with l + m = i + j + 1, dropping l <= min(i, j): L_02 becomes L_11."""
from math import comb

import numpy as np


def _homogeneous(points, weights):
    pts = np.array(points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 2 or not np.all(np.isfinite(pts)):
        raise ValueError("points: expected (n+1, 2) with n >= 1")
    if weights is None:
        return np.column_stack([pts, np.ones(len(pts))])
    w = np.array(weights, dtype=float)
    if w.shape != (len(pts),) or np.any(w == 0) or not np.all(np.isfinite(w)):
        raise ValueError("weights: expected n+1 nonzero numbers")
    return np.column_stack([pts * w[:, None], w])


def bezout_moving_lines(points, weights=None):
    h = _homogeneous(points, weights)
    n = len(h) - 1
    s = h * np.array([comb(n, i) for i in range(n + 1)], dtype=float)[:, None]
    out = np.zeros((n, n, 3))
    for i in range(n):
        for j in range(n):
            for low in range(n + 1):
                high = i + j + 1 - low
                if low < high <= n:
                    out[i, j] += np.cross(s[low], s[high])
    return out

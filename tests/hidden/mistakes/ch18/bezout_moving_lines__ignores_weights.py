"""Crosses the Cartesian points (x_i, y_i, 1), forgetting the weights."""
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


def _bezout(h, binomial_degree=None):
    n = len(h) - 1
    b = n if binomial_degree is None else binomial_degree
    s = h * np.array([comb(b, i) for i in range(n + 1)], dtype=float)[:, None]
    out = np.zeros((n, n, 3))
    for i in range(n):
        for j in range(n):
            for low in range(min(i, j) + 1):
                high = i + j + 1 - low
                if high <= n:
                    out[i, j] += np.cross(s[low], s[high])
    return out


def bezout_moving_lines(points, weights=None):
    h = _homogeneous(points, weights)
    return _bezout(h / h[:, 2:])

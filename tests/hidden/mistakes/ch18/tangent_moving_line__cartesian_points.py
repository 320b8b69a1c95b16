"""Crosses the Cartesian points (x_i, y_i, 1): right for polynomial curves only."""
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


def _product(p, q):
    m, n = len(p) - 1, len(q) - 1
    out = np.zeros((m + n + 1, 3))
    for i in range(m + 1):
        for j in range(n + 1):
            out[i + j] += comb(m, i) * comb(n, j) * np.cross(p[i], q[j])
    return out / np.array([comb(m + n, k) for k in range(m + n + 1)], dtype=float)[:, None]


def tangent_moving_line(points, weights=None):
    h = _homogeneous(points, weights)
    h = h / h[:, 2:]
    return (len(h) - 1) * _product(h[:-1], h[1:])

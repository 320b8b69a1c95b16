"""Builds the matrix from the Cartesian points, forgetting the weights."""
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


def _pencil(h):
    if len(h) != 4:
        raise ValueError("points: expected 4 control points")
    rows = _bezout(h)
    if np.linalg.matrix_rank(rows.reshape(3, 9), tol=1e-9 * np.abs(rows).max()) < 3:
        raise ValueError("points: not a true cubic")
    u, s, vt = np.linalg.svd(rows[:, 0, :])
    c = u[:, -1]
    pencil = np.tensordot(c, rows, axes=1)[1:]
    return pencil


def cubic_double_point(points, weights=None):
    h = _homogeneous(points, weights)
    pencil = _pencil(h / h[:, 2:])
    axis = np.cross(pencil[0], pencil[1])
    return axis / np.linalg.norm(axis)

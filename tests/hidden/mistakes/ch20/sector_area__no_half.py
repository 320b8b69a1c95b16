"""Drops the 1/2: returns ∫(x dy - y dx), twice the sector area."""
from math import comb

import numpy as np


def _planar(points):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) == 0:
        raise ValueError("points must have shape (n+1, 2)")
    return P


def _matrix(n):
    A = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(n + 1):
            for k, sign in ((j - 1, 1), (j, -1)):
                if 0 <= k < n:
                    A[i, j] += sign * comb(n, i) * comb(n - 1, k) / (comb(2 * n - 1, i + k) * 2)
    return A


def _product(f, g):
    m, n = len(f) - 1, len(g) - 1
    h = np.zeros(m + n + 1)
    for i in range(m + 1):
        for j in range(n + 1):
            h[i + j] += comb(m, i) * comb(n, j) * f[i] * g[j]
    return h / np.array([comb(m + n, k) for k in range(m + n + 1)])


def _integral(*factors):
    result = factors[0]
    for f in factors[1:]:
        result = _product(result, f)
    return float(result.mean())


def _hodograph(c):
    return (len(c) - 1) * np.diff(c) if len(c) > 1 else np.zeros(1)


def sector_area(points):
    P = _planar(points)
    x, y = P[:, 0], P[:, 1]
    A = _matrix(len(P) - 1)
    return float(x @ (A - A.T) @ y)

"""Drops the weights from (20.4)-(20.6): right only when all weights are equal."""
from math import comb

import numpy as np


def down(n, m, r):
    return range(n + r, m + r, -1)


def w_(w, j):
    return 1.0


def skip(j, i):
    return j != i




def hybrid_curve(points, weights, degree, m=None):
    R = np.array(points, dtype=float)
    w = np.array(weights, dtype=float)
    if R.ndim != 2 or w.shape != (len(R),) or np.any(w <= 0):
        raise ValueError("points must be (r+1, d) with r+1 positive weights")
    n = int(degree)
    if n < 2:
        raise ValueError("degree must be at least 2")
    m = n // 2 if m is None else int(m)
    if not 0 < m < n:
        raise ValueError("m must satisfy 0 < m < n")
    r = len(R) - 1
    P = np.full((n + 1, R.shape[1]), np.nan)
    for k in range(m):
        total = sum((comb(r, j) * comb(n, k - j) * w_(w, j) * (R[j] - P[k - j]) for j in range(1, min(r, k) + 1)),
                    np.zeros(R.shape[1]))
        P[k] = R[0] + total / (w_(w, 0) * comb(n, k))
    for k in down(n, m, r):
        total = sum((comb(r, j) * comb(n, k - j) * w_(w, j) * (R[j] - P[k - j]) for j in range(max(0, k - n), r)),
                    np.zeros(R.shape[1]))
        P[k - r] = R[r] + total / (w_(w, r) * comb(n, k - r))
    M = np.empty_like(R)
    for i in range(r + 1):
        js = [j for j in range(max(0, i + m - n), min(i + m, r) + 1) if skip(j, i)]
        total = sum((comb(r, j) * comb(n, i + m - j) * w_(w, j) * (R[j] - P[i + m - j]) for j in js),
                    np.zeros(R.shape[1]))
        M[i] = R[i] + total / (w_(w, i) * comb(n, m) * comb(r, i))
    return P, M, w, m

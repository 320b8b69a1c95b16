"""Integrates y x' by Simpson's rule on 16 intervals whatever the tolerance."""
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


def _checked(points, weights, tol):
    P = _planar(points)
    if weights is not None:
        w = np.array(weights, dtype=float)
        if w.shape != (len(P),) or np.any(w <= 0):
            raise ValueError("weights must be positive, one per point")
    else:
        w = None
    tol = float(tol)
    if not tol > 0 or tol < 1e-13 * np.abs(P).max() ** 2:
        raise ValueError("tol out of range")
    return P, w


def bezier_area(points, weights=None, tol=1e-9):
    P, w = _checked(points, weights, tol)
    if len(P) == 1:
        return 0.0
    w = np.ones(len(P)) if w is None else w
    ts = np.linspace(0, 1, 33)
    n = len(P) - 1
    B = np.array([[comb(n, i) * (1 - t) ** (n - i) * t ** i for i in range(n + 1)] for t in ts])
    dB = np.array([[n * ((comb(n - 1, i - 1) * (1 - t) ** (n - i) * t ** (i - 1) if i > 0 else 0)
                       - (comb(n - 1, i) * (1 - t) ** (n - 1 - i) * t ** i if i < n else 0))
                   for i in range(n + 1)] for t in ts])
    W, dW = B @ w, dB @ w
    X, dX = B @ (w * P[:, 0]), dB @ (w * P[:, 0])
    Y = B @ (w * P[:, 1])
    f = (Y / W) * (dX * W - X * dW) / W**2
    return float((f[0] + f[-1] + 4 * f[1:-1:2].sum() + 2 * f[2:-1:2].sum()) / (3 * 32))

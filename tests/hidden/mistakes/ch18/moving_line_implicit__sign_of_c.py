"""Substitutes (x, y, -1) into the lines: the curve turned a half turn about the origin."""
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


def _line(line, size):
    out = np.zeros((size, size))
    out[0, 0], out[1, 0], out[0, 1] = line[2], line[0], line[1]
    return out


def _mul(f, g):
    size = len(f)
    out = np.zeros_like(f)
    for i, j in zip(*np.nonzero(f)):
        out[i:, j:] += f[i, j] * g[: size - i, : size - j]
    return out


def _det(m):
    if len(m) == 1:
        return m[0][0]
    total = np.zeros_like(m[0][0])
    for k in range(len(m)):
        minor = [row[:k] + row[k + 1:] for row in m[1:]]
        total = total + (-1) ** k * _mul(m[0][k], _det(minor))
    return total


def _implicit(h, third=1.0):
    rows = _bezout(h)
    n = len(rows)
    c = _det([[_line(rows[i, j] * [1.0, 1.0, third], n + 1) for j in range(n)] for i in range(n)])
    if np.abs(c).max() <= 1e-9 * np.abs(rows).max() ** n:
        raise ValueError("points: the implicit equation vanishes identically")
    return c / np.abs(c).max()


def moving_line_implicit(points, weights=None):
    return _implicit(_homogeneous(points, weights), third=-1.0)

"""Drops the minus sign: x - x0 = +f_(n-1)(1, t) / f_n(1, t)."""
from math import comb

import numpy as np


def _c(c):
    a = np.array(c, dtype=float)
    if a.ndim != 2 or a.size == 0 or not np.all(np.isfinite(a)) or not np.any(a):
        raise ValueError("c: expected a nonzero 2-D array")
    return a


def _p(point):
    p = np.array(point, dtype=float)
    if p.shape != (2,) or not np.all(np.isfinite(p)):
        raise ValueError("point: expected 2 numbers")
    return p


def _translate(c, x0, y0):
    i, j = np.nonzero(c)
    n = int((i + j).max())
    out = np.zeros((n + 1, n + 1))
    for a, b in zip(i, j):
        for k in range(a + 1):
            for m in range(b + 1):
                out[k, m] += c[a, b] * comb(a, k) * x0 ** (a - k) * comb(b, m) * y0 ** (b - m)
    return out


def _parts(c):
    n = len(c) - 1
    return [np.array([c[k - j, j] for j in range(k + 1)]) for k in range(n + 1)]


def _multiplicity(parts, scale, tol):
    for k, g in enumerate(parts):
        if np.abs(g).max() > tol * scale:
            return k
    return len(parts)


def _setup(c, point):
    c, p = _c(c), _p(point)
    m = _translate(c, *p)
    n = len(m) - 1
    if n < 2:
        raise ValueError("c: degree below 2")
    parts = _parts(m)
    if _multiplicity(parts, np.abs(m).max(), 1e-9) != n - 1:
        raise ValueError("point: not of multiplicity n - 1")
    return p, n, parts[n - 1], parts[n]


def parametrize_by_pencil(c, point):
    p, n, low, top = _setup(c, point)
    x = np.zeros(n + 1)
    x[:n] = low
    y = np.zeros(n + 1)
    y[1:] = low
    return np.array([p[0] * top + x, p[1] * top + y, top])

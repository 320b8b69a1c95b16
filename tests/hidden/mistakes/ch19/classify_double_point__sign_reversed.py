"""Reads the sign of B² - 4AC the wrong way round: positive gives an acnode."""
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


def classify_double_point(c, point):
    c, p = _c(c), _p(point)
    m = _translate(c, *p)
    parts = _parts(m)
    if _multiplicity(parts, np.abs(m).max(), 1e-9) != 2:
        raise ValueError("point: not a double point")
    a, b, cc = parts[2]
    d = b * b - 4 * a * cc
    if abs(d) <= 1e-9 * (b * b + 4 * abs(a * cc)):
        return "cusp"
    return "acnode" if d > 0 else "crunode"

"""Freezes order rows instead of order + 1: C0 freezes nothing."""
from math import comb

import numpy as np


def _box(box):
    b = np.array(box, dtype=float)
    if b.shape != (2, 2) or not np.all(np.isfinite(b)) or not np.all(b[0] < b[1]):
        raise ValueError("box: expected [[xmin, ymin], [xmax, ymax]] with xmin < xmax, ymin < ymax")
    return b


def _points(points):
    p = np.array(points, dtype=float)
    single = p.shape == (2,)
    p = p.reshape(1, 2) if single else p
    if p.ndim != 2 or p.shape[1] != 2:
        raise ValueError("points: expected shape (k, 2) or (2,)")
    return p, single


def _lattice(lattice, weights):
    L = np.array(lattice, dtype=float)
    if L.ndim != 3 or L.shape[2] != 2 or L.shape[0] < 2 or L.shape[1] < 2:
        raise ValueError("lattice: expected shape (m+1, n+1, 2) with m, n >= 1")
    if weights is None:
        return L, np.ones(L.shape[:2])
    w = np.array(weights, dtype=float)
    if w.shape != L.shape[:2] or np.any(w <= 0):
        raise ValueError("weights: expected positive weights of shape (m+1, n+1)")
    return L, w


def _basis(degree, u):
    i = np.arange(degree + 1)
    c = np.array([comb(degree, k) for k in i], dtype=float)
    u = np.asarray(u, dtype=float)[:, None]
    return c * u**i * (1 - u) ** (degree - i)


def _identity(b, m, n):
    L = np.empty((m + 1, n + 1, 2))
    L[..., 0] = (b[0, 0] + np.arange(m + 1) / m * (b[1, 0] - b[0, 0]))[:, None]
    L[..., 1] = (b[0, 1] + np.arange(n + 1) / n * (b[1, 1] - b[0, 1]))[None, :]
    return L


def freeze(lattice, box, edge, order, weights=None):
    b = _box(box)
    L, w = _lattice(lattice, weights)
    m, n = L.shape[0] - 1, L.shape[1] - 1
    if not isinstance(order, int) or order < 0:
        raise ValueError("order: expected an integer >= 0")
    if edge not in ("bottom", "top", "left", "right"):
        raise ValueError("edge: bottom, top, left or right")
    if order > (n if edge in ("bottom", "top") else m):
        raise ValueError("order: too many rows")
    k = order
    rows = {"bottom": (slice(None), slice(0, k)), "top": (slice(None), slice(n + 1 - k, None)),
            "left": (slice(0, k), slice(None)), "right": (slice(m + 1 - k, None), slice(None))}[edge]
    L, w = L.copy(), w.copy()
    L[rows] = _identity(b, m, n)[rows]
    w[rows] = 1.0
    return L, w

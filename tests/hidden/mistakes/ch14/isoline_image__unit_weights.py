"""Returns the projected points H_j with unit weights: loses the rational form."""
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


def isoline_image(lattice, value, direction="s", weights=None):
    L, w = _lattice(lattice, weights)
    v = np.array(value, dtype=float)
    scalar = v.ndim == 0
    v = v.reshape(-1) if scalar else v
    if v.ndim != 1 or np.any(~np.isfinite(v)) or np.any((v < 0) | (v > 1)):
        raise ValueError("value: expected numbers in [0, 1]")
    if direction not in ("s", "t"):
        raise ValueError("direction: 's' or 't'")
    H = np.concatenate([L * w[..., None], w[..., None]], axis=2)
    if direction == "t":
        H = H.transpose(1, 0, 2)
    rows = np.einsum("ki,ijd->kjd", _basis(H.shape[0] - 1, v), H)
    points, weights_out = rows[..., :2] / rows[..., 2:], np.ones(rows.shape[:2])
    return (points[0], weights_out[0]) if scalar else (points, weights_out)

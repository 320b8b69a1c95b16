"""Slices the Cartesian net and appends the weights, (P_ij, w_ij), instead of w_ij (P_ij, 1)."""
import numpy as np


def _net(points, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 3 or P.shape[0] < 2 or P.shape[1] < 2:
        raise ValueError("points: expected shape (m+1, n+1, d) with m, n >= 1")
    w = np.ones(P.shape[:2]) if weights is None else np.array(weights, dtype=float)
    if w.shape != P.shape[:2] or np.any(w == 0):
        raise ValueError("weights: expected (m+1, n+1) nonzero weights")
    return P, w


def sub_patches(points, weights=None):
    P, w = _net(points, weights)
    H = np.concatenate([P, w[..., None]], axis=2)
    m, n = H.shape[0] - 1, H.shape[1] - 1
    return H[:m, :n], H[1:, :n], H[:m, 1:], H[1:, 1:]

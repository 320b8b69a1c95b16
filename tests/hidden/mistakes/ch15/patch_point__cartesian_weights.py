"""Blends the Cartesian points with the weights in the numerator only, never dividing by Σ w B: wrong for rational nets."""
from math import comb

import numpy as np


def _prepare(points, s, t, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 3 or not np.all(np.isfinite(P)):
        raise ValueError("points: expected shape (m+1, n+1, d)")
    w = np.ones(P.shape[:2]) if weights is None else np.array(weights, dtype=float)
    if w.shape != P.shape[:2] or np.any(w == 0):
        raise ValueError("weights: expected (m+1, n+1) nonzero weights")
    ss, ts = np.array(s, dtype=float), np.array(t, dtype=float)
    if ss.ndim > 1 or ts.ndim > 1:
        raise ValueError("s, t: expected numbers or 1-D arrays")
    scalar = ss.ndim == 0 and ts.ndim == 0
    try:
        ss, ts = np.broadcast_arrays(np.atleast_1d(ss), np.atleast_1d(ts))
    except ValueError:
        raise ValueError("s, t: do not broadcast") from None
    return P, w, ss, ts, scalar


def _basis(n, x):
    i = np.arange(n + 1)
    return np.array([comb(n, k) for k in i]) * (1 - x[:, None]) ** (n - i) * x[:, None] ** i


def patch_point(points, s, t, weights=None):
    P, w, ss, ts, scalar = _prepare(points, s, t, weights)
    p = np.einsum("ki,kj,ijd->kd", _basis(P.shape[0] - 1, ss), _basis(P.shape[1] - 1, ts), P * w[..., None])
    return p[0] if scalar else p

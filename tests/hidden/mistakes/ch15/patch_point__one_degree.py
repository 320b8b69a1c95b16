"""Uses the degree m of the first index for both directions (padding the missing columns with the last one)."""
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
    H = np.concatenate([P * w[..., None], w[..., None]], axis=2)
    m = P.shape[0] - 1
    cols = np.minimum(np.arange(m + 1), P.shape[1] - 1)
    H = H[:, cols]
    X = np.einsum("ki,kj,ijd->kd", _basis(m, ss), _basis(m, ts), H)
    if np.any(X[:, -1] == 0):
        raise ValueError("s, t: weight zero")
    p = X[:, :-1] / X[:, -1:]
    return p[0] if scalar else p

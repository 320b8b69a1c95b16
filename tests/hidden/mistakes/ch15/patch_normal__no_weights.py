"""Differentiates the Cartesian net as if it were polynomial: right at the corners only, turned elsewhere."""
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


def _derivatives(P, w, ss, ts):
    H = np.concatenate([P * w[..., None], w[..., None]], axis=2)
    m, n = P.shape[0] - 1, P.shape[1] - 1
    Bs, Bt = _basis(m, ss), _basis(n, ts)
    dBs = np.zeros_like(Bs) if m == 0 else m * (np.pad(_basis(m - 1, ss), ((0, 0), (1, 0))) - np.pad(_basis(m - 1, ss), ((0, 0), (0, 1))))
    dBt = np.zeros_like(Bt) if n == 0 else n * (np.pad(_basis(n - 1, ts), ((0, 0), (1, 0))) - np.pad(_basis(n - 1, ts), ((0, 0), (0, 1))))
    X = np.einsum('ki,kj,ijd->kd', Bs, Bt, H)
    Xs = np.einsum('ki,kj,ijd->kd', dBs, Bt, H)
    Xt = np.einsum('ki,kj,ijd->kd', Bs, dBt, H)
    p = X[:, :-1] / X[:, -1:]
    ps = (Xs[:, :-1] - p * Xs[:, -1:]) / X[:, -1:]
    pt = (Xt[:, :-1] - p * Xt[:, -1:]) / X[:, -1:]
    return ps, pt


def _check(P):
    if P.shape[2] != 3:
        raise ValueError('points: expected a net in space')


def _unit(normal, scalar):
    length = np.linalg.norm(normal, axis=1)
    if np.any(length < 1e-12):
        raise ValueError('s, t: P_s x P_t vanishes')
    normal = normal / length[:, None]
    return normal[0] if scalar else normal


def patch_normal(points, s, t, weights=None):
    P, w, ss, ts, scalar = _prepare(points, s, t, weights)
    _check(P)
    ps, pt = _derivatives(P, np.ones_like(w), ss, ts)
    return _unit(np.cross(ps, pt), scalar)

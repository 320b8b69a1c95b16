"""Forgets the degrees: p_s = A_w B_w / P_w² (Π(B) - Π(A)) without the factor m, and p_t without n."""
import numpy as np
from math import comb


def _prepare(points, s, t, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 3:
        raise ValueError("points: expected shape (m+1, n+1, d)")
    w = np.ones(P.shape[:2]) if weights is None else np.array(weights, dtype=float)
    if w.shape != P.shape[:2] or np.any(w == 0):
        raise ValueError("weights: expected (m+1, n+1) nonzero weights")
    ss, ts = np.array(s, dtype=float), np.array(t, dtype=float)
    if ss.ndim > 1 or ts.ndim > 1:
        raise ValueError("s, t: expected numbers or 1-D arrays")
    scalar = ss.ndim == 0 and ts.ndim == 0
    ss, ts = np.broadcast_arrays(np.atleast_1d(ss), np.atleast_1d(ts))
    H = np.concatenate([P * w[..., None], w[..., None]], axis=2)
    return H, ss, ts, scalar


def _basis(n, x):
    i = np.arange(n + 1)
    return np.array([comb(n, k) for k in i]) * (1 - x[:, None]) ** (n - i) * x[:, None] ** i


def _values(H, ss, ts):
    """The four sub-patches at (s, t), true scale: S[k][l] of shape (K, D)."""
    m, n = H.shape[0] - 1, H.shape[1] - 1
    Bs, Bt = _basis(m - 1, ss), _basis(n - 1, ts)
    return [[np.einsum("ki,kj,ijd->kd", Bs, Bt, H[k:k + m, l:l + n]) for l in (0, 1)] for k in (0, 1)]


def _tangent(a, b, w, degree):
    return degree * (a[:, -1:] * b[:, :-1] - b[:, -1:] * a[:, :-1]) / (w * w)[:, None]


def _finish(p, ps, pt, scalar):
    return (p[0], ps[0], pt[0]) if scalar else (p, ps, pt)


def _point(S, ss, ts):
    s, t = ss[:, None], ts[:, None]
    A = (1 - t) * S[0][0] + t * S[0][1]
    B = (1 - t) * S[1][0] + t * S[1][1]
    C = (1 - s) * S[0][0] + s * S[1][0]
    D = (1 - s) * S[0][1] + s * S[1][1]
    X = (1 - s) * A + s * B
    if np.any(X[:, -1] == 0):
        raise ValueError("s, t: the patch passes through infinity")
    return A, B, C, D, X


def patch_point_tangents(points, s, t, weights=None):
    H, ss, ts, scalar = _prepare(points, s, t, weights)
    m, n = H.shape[0] - 1, H.shape[1] - 1
    A, B, C, D, X = _point(_values(H, ss, ts), ss, ts)
    w = X[:, -1]
    ps, pt = _tangent(A, B, w, 1), _tangent(C, D, w, 1)
    p = X[:, :-1] / X[:, -1:]
    return _finish(p, ps, pt, scalar)

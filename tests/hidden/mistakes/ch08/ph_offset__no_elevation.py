"""Pads rho (y', -x') and sigma with zeros to degree 2n-1 instead of raising their degree."""
import numpy as np
from math import comb


def _curve(points, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError("points must have shape (n+1, 2) with n >= 1")
    if weights is None:
        return P, None
    w = np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w <= 0):
        raise ValueError("weights must be n+1 positive numbers")
    return P, w


def _bez(C, ts):
    n = len(C) - 1
    ts = np.asarray(ts, dtype=float)[:, None]
    i = np.arange(n + 1)
    B = np.array([comb(n, k) for k in i]) * (1 - ts) ** (n - i) * ts ** i
    return B @ C


def _hod(C):
    n = len(C) - 1
    return n * np.diff(C, axis=0) if n else np.zeros_like(C)


def _mul(f, g):
    m, k = len(f) - 1, len(g) - 1
    h = np.zeros(m + k + 1)
    for i in range(m + 1):
        for j in range(k + 1):
            h[i + j] += comb(m, i) * comb(k, j) * f[i] * g[j]
    return h / np.array([comb(m + k, j) for j in range(m + k + 1)])


def _raise(c, deg):
    c = np.array(c, dtype=float)
    return np.concatenate([c, np.zeros(deg + 1 - len(c))])
    while len(c) - 1 < deg:
        m = len(c) - 1
        a = np.arange(m + 2) / (m + 1)
        c = a * np.concatenate([[0.0], c]) + (1 - a) * np.concatenate([c, [0.0]])
    return c


def ph_offset(points, rho):
    P, _ = _curve(points, None)
    rho = float(rho)
    n = len(P) - 1
    h = _hod(P)
    s2 = _mul(h[:, 0], h[:, 0]) + _mul(h[:, 1], h[:, 1])
    nodes = (1 - np.cos((2 * np.arange(n) + 1) * np.pi / (2 * n))) / 2
    speed = np.linalg.norm(_bez(h, nodes), axis=1)
    B = np.array([[comb(n - 1, i) * (1 - t) ** (n - 1 - i) * t ** i for i in range(n)] for t in nodes])
    sigma = np.linalg.solve(B, speed)
    if np.abs(_mul(sigma, sigma) - s2).max() > 1e-9 * np.abs(s2).max():
        raise ValueError("points: not a PH curve")
    if _bez(sigma[:, None], np.linspace(0, 1, 1001)).min() <= 1e-12 * np.abs(sigma).max():
        raise ValueError("points: the curve stops")
    num = np.column_stack([_mul(sigma, P[:, 0]), _mul(sigma, P[:, 1])])
    num += rho * np.column_stack([_raise(h[:, 1], 2 * n - 1), _raise(-h[:, 0], 2 * n - 1)])
    wts = _raise(sigma, 2 * n - 1)
    return num / wts[:, None], wts

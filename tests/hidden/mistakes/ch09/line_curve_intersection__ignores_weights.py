"""Substitutes the control points but forgets their weights: f_i = a x_i + b y_i + c."""
from math import comb

import numpy as np


def _roots(f):
    """Real roots in [0, 1] of Σ f_i B_i^n through the power basis (good enough at these low degrees)."""
    n = len(f) - 1
    power = np.array([comb(n, k) * sum((-1) ** (k - i) * comb(k, i) * f[i] for i in range(k + 1))
                      for k in range(n + 1)])
    while len(power) > 1 and abs(power[-1]) < 1e-14 * np.abs(power).max():
        power = power[:-1]
    if len(power) == 1:
        return np.empty(0)
    found = np.roots(power[::-1])
    real = np.sort(found[np.abs(found.imag) < 1e-9].real)
    real = real[(real >= -1e-12) & (real <= 1 + 1e-12)].clip(0, 1)
    return real[np.concatenate([[True], np.diff(real) > 1e-9])] if len(real) else real


def _curve(points, weights, ts):
    n = len(points) - 1
    basis = np.array([[comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)] for t in ts])
    basis = basis.reshape(len(ts), n + 1)
    return (basis @ (weights[:, None] * points)) / (basis @ weights)[:, None]


def line_curve_intersection(points, line, weights=None):
    P = np.asarray(points, dtype=float)
    L = np.asarray(line, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2:
        raise ValueError("points: expected (n+1, 2)")
    if L.shape != (3,) or not np.any(L[:2]):
        raise ValueError("line: expected (a, b, c) with (a, b) != 0")
    w = np.ones(len(P)) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w == 0):
        raise ValueError("weights: expected nonzero weights, one per point")
    f = P @ L[:2] + L[2]
    if not np.any(f):
        raise ValueError("line: the curve lies on the line")
    ts = _roots(f)
    return ts, _curve(P, w, ts)

"""Divides by (2m)! only, forgetting C(2m, m): 24 instead of 144 for the quartic."""
from math import comb, factorial

import numpy as np


def hermite_interval(derivs0, derivs1, bound, interval=(0, 1)):
    d0, d1 = np.array(derivs0, dtype=float), np.array(derivs1, dtype=float)
    b = np.array(bound, dtype=float)
    a, z = (float(x) for x in interval)
    if d0.shape != d1.shape or d0.ndim not in (1, 2) or len(d0) == 0 or not (a < z):
        raise ValueError("derivs0, derivs1: expected two arrays of one shape (m,) or (m, d)")
    if not (np.all(np.isfinite(d0)) and np.all(np.isfinite(d1)) and np.all(np.isfinite(b))):
        raise ValueError("derivs0: expected finite numbers")
    scalar = d0.ndim == 1
    d0, d1 = d0.reshape(len(d0), -1), d1.reshape(len(d1), -1)
    if b.shape != ((2,) if scalar else (d0.shape[1], 2)) or np.any(b.reshape(-1, 2)[:, 0] > b.reshape(-1, 2)[:, 1]):
        raise ValueError("bound: expected [lo, hi] per coordinate")
    b = b.reshape(-1, 2)
    m = len(d0)
    n = 2 * m - 1
    h = z - a
    d0 = d0 * (h ** np.arange(m))[:, None]
    d1 = d1 * (h ** np.arange(m))[:, None]
    P = np.zeros((n + 1, d0.shape[1]))
    for j in range(m):
        for i in range(j + 1):
            w = comb(j, i) * factorial(n - i) / factorial(n)
            P[j] += w * d0[i]
            P[n - j] += (-1) ** i * w * d1[i]
    E = np.zeros((n + 2, P.shape[1]))
    E[0], E[-1] = P[0], P[-1]
    for k in range(1, n + 1):
        E[k] = k / (n + 1) * P[k - 1] + (1 - k / (n + 1)) * P[k]
    factor = (-1) ** m * h ** (2 * m) / factorial(2 * m)
    lo, hi = E.copy(), E.copy()
    ends = factor * b
    lo[m] += ends.min(axis=1)
    hi[m] += ends.max(axis=1)
    result = np.stack([lo, hi], axis=-1)
    return result[:, 0] if scalar else result

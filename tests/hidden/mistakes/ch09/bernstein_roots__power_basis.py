"""Converts to the power basis and calls numpy.roots: fine at low degree, hopeless for Wilkinson-type roots."""
from math import comb

import numpy as np


def bernstein_roots(coeffs, interval=(0, 1), tol=1e-12):
    y = np.asarray(coeffs, dtype=float)
    iv = np.asarray(interval, dtype=float)
    if y.ndim != 1 or len(y) == 0 or not np.any(y):
        raise ValueError("coeffs: expected a nonzero vector")
    if iv.shape != (2,) or not iv[0] < iv[1]:
        raise ValueError("interval: expected t0 < t1")
    if not 0 < tol < 1:
        raise ValueError("tol: expected 0 < tol < 1")
    n = len(y) - 1
    power = np.zeros(n + 1)  # a_k = C(n, k) Σ_i (-1)^(k-i) C(k, i) y_i
    for k in range(n + 1):
        power[k] = comb(n, k) * sum((-1) ** (k - i) * comb(k, i) * y[i] for i in range(k + 1))
    while len(power) > 1 and power[-1] == 0:
        power = power[:-1]
    if len(power) == 1:
        return np.empty(0)
    found = np.roots(power[::-1])
    real = np.sort(found[np.abs(found.imag) < 1e-7].real)
    real = real[(real >= -1e-12) & (real <= 1 + 1e-12)].clip(0, 1)
    real = real[np.concatenate([[True], np.diff(real) > 1e-9])] if len(real) else real
    return iv[0] + (iv[1] - iv[0]) * real

"""Returns march - exact with its sign: the statement asks for the size of the error."""
from math import factorial

import numpy as np


def float32_drift(coeffs, delta, count):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    if not (np.isfinite(a).all() and np.isfinite(delta)):
        raise ValueError("coeffs and delta must be finite")
    if not isinstance(count, (int, np.integer)):
        raise TypeError("count must be an integer")
    if count < 0:
        raise ValueError("count must be >= 0")
    n = len(a) - 1
    stirling = np.zeros((n + 1, n + 1))
    stirling[0, 0] = 1.0
    for k in range(1, n + 1):
        for j in range(1, k + 1):
            stirling[k, j] = j * stirling[k - 1, j] + stirling[k - 1, j - 1]
    column = np.array([factorial(j) * sum(stirling[k, j] * a[k] * delta**k for k in range(n + 1))
                       for j in range(n + 1)]).astype(np.float32)
    march = np.empty((count,) + a.shape[1:], dtype=np.float32)
    for i in range(count):
        march[i] = column[0]
        column[:-1] = column[:-1] + column[1:]
    exact = np.polynomial.polynomial.polyval(delta * np.arange(count), a, tensor=True).T
    return march.astype(float) - exact.reshape(march.shape)

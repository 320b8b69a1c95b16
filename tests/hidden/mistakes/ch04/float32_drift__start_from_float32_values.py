"""Takes the starting differences from the difference table of the first n + 1 values, computed in float32:
the subtractions of nearly equal values lose most of single precision's seven digits."""
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
    first = np.polynomial.polynomial.polyval(delta * np.arange(n + 1), a, tensor=True).T.astype(np.float32)
    column = [first[0]]
    while len(first) > 1:
        first = np.diff(first, axis=0)
        column.append(first[0])
    column = np.array(column, dtype=np.float32)
    march = np.empty((count,) + a.shape[1:], dtype=np.float32)
    for i in range(count):
        march[i] = column[0]
        column[:-1] = column[:-1] + column[1:]
    exact = np.polynomial.polynomial.polyval(delta * np.arange(count), a, tensor=True).T
    return np.abs(march.astype(float) - exact.reshape(march.shape))

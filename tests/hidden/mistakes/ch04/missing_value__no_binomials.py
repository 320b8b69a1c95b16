"""Writes the n-th difference as the plain alternating sum Σ (-1)ⁿ⁻ⁱ f_i, without the binomial coefficients."""
import numpy as np


def missing_value(values, index):
    if not isinstance(index, (int, np.integer)):
        raise TypeError("index must be an integer")
    f = np.array(values, dtype=float)
    if f.ndim not in (1, 2) or len(f) < 2:
        raise ValueError("values must have shape (n+1,) or (n+1, d) with n >= 1")
    n = len(f) - 1
    if not 0 <= index <= n:
        raise ValueError("index out of range")
    known = [i for i in range(n + 1) if i != index]
    if not np.isfinite(f[known]).all():
        raise ValueError("values must be finite")
    rest = sum((-1) ** (n - i) * f[i] for i in known)
    found = -rest / (-1) ** (n - index)
    return float(found) if f.ndim == 1 else found

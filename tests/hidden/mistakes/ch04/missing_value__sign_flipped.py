"""Solves Σ (-1)ⁿ⁻ⁱ C(n, i) f_i = 0 for the unknown but drops the minus sign when moving the known terms over."""
from math import comb

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
    rest = sum((-1) ** (n - i) * comb(n, i) * f[i] for i in known)
    found = rest / ((-1) ** (n - index) * comb(n, index))
    return float(found) if f.ndim == 1 else found

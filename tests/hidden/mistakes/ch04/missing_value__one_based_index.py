"""Reads `index` as the notes' parameter t = 1, 2, ..., so it solves for the entry one place to the left."""
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
    hole = max(index - 1, 0)
    known = [i for i in range(n + 1) if i != hole]
    f = np.where(np.isfinite(f), f, 0.0)
    rest = sum((-1) ** (n - i) * comb(n, i) * f[i] for i in known)
    found = -rest / ((-1) ** (n - hole) * comb(n, hole))
    return float(found) if f.ndim == 1 else found

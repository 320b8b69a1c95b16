"""Forgets the factor n!/(n-r)!."""

import numpy as np


def derivative_bounds(coeffs, r):
    p = np.array(coeffs, dtype=float)
    if p.ndim not in (1, 2) or len(p) == 0 or not np.all(np.isfinite(p)):
        raise ValueError("coeffs: expected finite (n+1,) or (n+1, d)")
    if isinstance(r, bool) or not isinstance(r, (int, np.integer)) or r < 0:
        raise ValueError("r: expected an integer >= 0")
    n = len(p) - 1
    columns = p.reshape(len(p), -1)
    if r > n:
        bounds = np.zeros((columns.shape[1], 2))
    else:
        diffs = np.diff(columns, n=r, axis=0)
        bounds = np.column_stack([diffs.min(axis=0), diffs.max(axis=0)])
    return bounds[0] if p.ndim == 1 else bounds

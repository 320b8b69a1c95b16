"""Takes the starting differences from the difference table of f(t0), ..., f(t0 + n δ): right in exact arithmetic,
but the subtractions of nearby values lose digits that the loop then amplifies (the accuracy cases)."""
import numpy as np


def forward_difference_eval(coeffs, t0, delta, count):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    if not isinstance(count, (int, np.integer)):
        raise TypeError("count must be an integer")
    if count < 0:
        raise ValueError("count must be >= 0")
    if not (np.isfinite(a).all() and np.isfinite(t0) and np.isfinite(delta)):
        raise ValueError("coeffs, t0 and delta must be finite")
    n = len(a) - 1
    ts = t0 + delta * np.arange(n + 1)
    values = np.zeros((n + 1,) + a.shape[1:])
    for c in a[::-1]:  # Horner's rule at the n + 1 first parameters
        values = values * (ts if a.ndim == 1 else ts[:, None]) + c
    column = [values[0]]
    while len(values) > 1:
        values = np.diff(values, axis=0)
        column.append(values[0])
    column = np.array(column)
    out = np.empty((count,) + a.shape[1:])
    for k in range(count):
        out[k] = column[0]
        column[:-1] = column[:-1] + column[1:]
    return out

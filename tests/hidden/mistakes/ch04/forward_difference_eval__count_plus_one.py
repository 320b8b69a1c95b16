"""Follows "for i = 1 to k" literally after storing f(t0), returning count + 1 values instead of count."""
import numpy as np


def forward_difference_eval(coeffs, t0, delta, count):
    a = np.array(coeffs, dtype=float)
    if a.ndim not in (1, 2) or len(a) == 0:
        raise ValueError("coeffs must have shape (n+1,) or (n+1, d)")
    if not isinstance(count, (int, np.integer)):
        raise TypeError("count must be an integer")
    if count < 0:
        raise ValueError("count must be >= 0")
    n = len(a) - 1
    ts = t0 + delta * np.arange(n + 1)
    values = np.array([sum(c * t**k for k, c in enumerate(a)) for t in ts])
    column = [values[0]]
    while len(values) > 1:
        values = np.diff(values, axis=0)
        column.append(values[0])
    column = np.array(column)
    out = [column[0].copy()]
    for _ in range(count):
        column[:-1] = column[:-1] + column[1:]
        out.append(column[0].copy())
    return np.array(out).reshape((count + 1,) + a.shape[1:])

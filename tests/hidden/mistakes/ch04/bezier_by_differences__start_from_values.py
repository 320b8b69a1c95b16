"""Starts the march from the difference table of P(0), P(δ), ..., P(n δ): right in exact arithmetic, but the
subtractions of nearby values lose digits that 400 steps of degree 6 amplify far beyond 1e-8."""
from math import comb

import numpy as np


def bezier_by_differences(points, steps):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, d)")
    if not isinstance(steps, (int, np.integer)):
        raise TypeError("steps must be an integer")
    if steps < 1:
        raise ValueError("steps must be >= 1")
    n, delta = len(p) - 1, 1.0 / steps
    t = delta * np.arange(n + 1)
    values = np.array([sum(comb(n, i) * (1 - ti) ** (n - i) * ti**i * p[i] for i in range(n + 1)) for ti in t])
    column = [values[0]]
    while len(values) > 1:
        values = np.diff(values, axis=0)
        column.append(values[0])
    column = np.array(column)
    out = np.empty((steps + 1, p.shape[1]))
    for i in range(steps + 1):
        out[i] = column[0]
        column[:-1] = column[:-1] + column[1:]
    return out

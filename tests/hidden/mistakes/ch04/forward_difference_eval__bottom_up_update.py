"""Updates the differences from the bottom up, so f is advanced with an already updated Δ¹."""
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
        values = values[1:] - values[:-1]
        column.append(values[0])
    column = np.array(column)
    out = []
    for _ in range(count):
        out.append(column[0].copy())
        for j in range(n - 1, -1, -1):
            column[j] = column[j] + column[j + 1]
    return np.array(out).reshape((count,) + a.shape[1:])

"""Subtracts the other way round, f(t_i) - f(t_{i+1}), so every odd row has the wrong sign."""
import numpy as np


def forward_difference_table(values):
    v = np.array(values, dtype=float)
    if v.ndim not in (1, 2) or len(v) == 0:
        raise ValueError("values must have shape (n+1,) or (n+1, d)")
    rows = [v]
    while len(rows[-1]) > 1:
        row = rows[-1]
        rows.append(row[:-1] - row[1:])
    return rows

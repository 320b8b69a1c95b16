"""Stops while a row still has two entries, so the single n-th difference is missing (n rows, not n+1)."""
import numpy as np


def forward_difference_table(values):
    v = np.array(values, dtype=float)
    if v.ndim not in (1, 2) or len(v) == 0:
        raise ValueError("values must have shape (n+1,) or (n+1, d)")
    rows = [v]
    while len(rows[-1]) > 2:
        rows.append(np.diff(rows[-1], axis=0))
    return rows

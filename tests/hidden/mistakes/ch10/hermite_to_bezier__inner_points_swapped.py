"""Returns the inner control points in the wrong order: p0, p1 - d1/3, p0 + d0/3, p1."""
import numpy as np


def hermite_to_bezier(p0, p1, d0, d1):
    rows = [np.array(v, dtype=float) for v in (p0, p1, d0, d1)]
    if any(r.ndim != 1 for r in rows) or len({len(r) for r in rows}) != 1:
        raise ValueError("p0, p1, d0, d1: expected vectors of one dimension")
    p0, p1, d0, d1 = rows
    return np.array([p0, p1 - d1 / 3, p0 + d0 / 3, p1])

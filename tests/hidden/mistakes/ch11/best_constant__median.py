"""Takes the median as the best L2 constant (it is the best L1 constant); the error is still the sum of squares."""
import numpy as np


def best_constant(values, norm="l2"):
    g = np.asarray(values, dtype=float)
    if g.ndim != 1 or len(g) == 0:
        raise ValueError("values: expected a non-empty 1-D array")
    if norm == "l2":
        best = float(np.median(g))
        return best, float(np.sum((g - best) ** 2))
    if norm == "linf":
        return (g.max() + g.min()) / 2, (g.max() - g.min()) / 2
    raise ValueError("norm: expected 'l2' or 'linf'")

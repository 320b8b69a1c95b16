"""Counts d as the fraction bits after a hidden leading 1, so keeps d + 1 significant bits."""
import numpy as np


def round_to_bits(x, d):
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 1:
        raise ValueError("d must be an integer >= 1")
    if isinstance(x, str):
        raise TypeError("x must be numbers")
    values = np.asarray(x, dtype=float)
    if not np.all(np.isfinite(values)):
        raise ValueError("x must be finite")
    f, e = np.frexp(values)
    out = np.ldexp(np.rint(np.ldexp(f, d + 1)), e - d - 1) if d < 52 else values
    return float(out) if out.ndim == 0 else out

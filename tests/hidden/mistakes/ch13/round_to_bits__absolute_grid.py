"""Rounds to the absolute grid of multiples of 2^-d, not relative to the exponent of x."""
import numpy as np


def round_to_bits(x, d):
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 1:
        raise ValueError("d must be an integer >= 1")
    if isinstance(x, str):
        raise TypeError("x must be numbers")
    values = np.asarray(x, dtype=float)
    if not np.all(np.isfinite(values)):
        raise ValueError("x must be finite")
    out = np.rint(values * 2.0**d) / 2.0**d
    return float(out) if out.ndim == 0 else out

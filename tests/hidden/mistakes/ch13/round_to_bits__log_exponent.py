"""Finds the exponent with log2, which gives NaN for zero."""
import numpy as np


def round_to_bits(x, d):
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or d < 1:
        raise ValueError("d must be an integer >= 1")
    if isinstance(x, str):
        raise TypeError("x must be numbers")
    values = np.asarray(x, dtype=float)
    if not np.all(np.isfinite(values)):
        raise ValueError("x must be finite")
    with np.errstate(divide="ignore", invalid="ignore"):
        e = np.floor(np.log2(np.abs(values))) + 1
        out = np.rint(values * 2.0 ** (d - e)) * 2.0 ** (e - d)
    return float(out) if out.ndim == 0 else out

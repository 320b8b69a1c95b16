"""Chops the extra bits (rounds towards zero) instead of rounding to nearest."""
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
    out = np.ldexp(np.trunc(np.ldexp(f, d)), e - d) if d < 53 else values
    return float(out) if out.ndim == 0 else out

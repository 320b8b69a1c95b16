"""Rounds ties away from zero (floor(y + 1/2)) instead of to even."""
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
    y = np.ldexp(f, d)
    out = np.ldexp(np.sign(y) * np.floor(np.abs(y) + 0.5), e - d) if d < 53 else values
    return float(out) if out.ndim == 0 else out

"""Uses the whole spacing to the neighbours, b ± 2^(e-d), instead of half of it."""
import numpy as np


def float_interval(b, d, exact=False):
    if isinstance(d, bool) or not isinstance(d, (int, np.integer)) or not 1 <= d <= 50:
        raise ValueError("d must be an integer in 1..50")
    if np.ndim(b) != 0:
        raise ValueError("b must be a number")
    b = float(b)
    if not np.isfinite(b):
        raise ValueError("b must be finite")
    f, e = np.frexp(b)
    if np.ldexp(np.rint(np.ldexp(f, d)), e - d) != b:
        raise ValueError("b has more than d bits")
    if b == 0:
        return 0.0, 0.0
    half = float(np.ldexp(1.0, int(e) - d))
    below = half / 2 if exact and abs(f) == 0.5 else half
    return (b - half, b + below) if b < 0 else (b - below, b + half)

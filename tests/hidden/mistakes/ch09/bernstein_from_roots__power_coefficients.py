"""Multiplies the factors in the power basis (numpy.polynomial) and returns power coefficients, never converting."""
import numpy as np
from numpy.polynomial import polynomial as P


def bernstein_from_roots(roots, interval=(0, 1), leading=1.0):
    r = np.asarray(roots, dtype=float)
    iv = np.asarray(interval, dtype=float)
    if r.ndim != 1 or iv.shape != (2,) or not iv[0] < iv[1]:
        raise ValueError("roots, interval: bad input")
    return float(leading) * P.polyfromroots(r) if len(r) else np.array([float(leading)])

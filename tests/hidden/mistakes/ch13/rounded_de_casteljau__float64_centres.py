"""Computes the centres in float64 instead of d-bit arithmetic."""
import math
from fractions import Fraction

import numpy as np


def _fl(x, d):
    if d >= 53:
        return x
    f, e = np.frexp(x)
    return np.ldexp(np.rint(np.ldexp(f, d)), e - d)


def rounded_de_casteljau(points, t, eta, radii=None):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[0] < 1 or not np.all(np.isfinite(P)):
        raise ValueError("points must be finite, of shape (n+1, dim)")
    eta = float(eta)
    d = -math.log2(eta) if eta > 0 else 0.5
    if d != int(d) or not (2 <= d <= 25 or d == 53):
        raise ValueError("eta must be 2**-d, 2 <= d <= 25 or d = 53")
    d = int(d)
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)) or np.any(_fl(ts, d) != ts):
        raise ValueError("t must be d-bit numbers, a number or 1-D")
    scalar = ts.ndim == 0
    ts = np.atleast_1d(ts)
    R = np.zeros_like(P) if radii is None else np.array(radii, dtype=float)
    if R.shape != P.shape or np.any(R < 0) or not np.all(np.isfinite(R)):
        raise ValueError("radii must be >= 0, shaped like points")
    gamma = eta / (1 - eta)
    centres, radius = [], []
    for tk in ts:
        s = _fl(1 - tk, d)
        w = 1.0 if Fraction(s) == 1 - Fraction(tk) else 2.0
        c = _fl(P, d)
        r = np.abs(P - c) + R
        while len(c) > 1:
            a, b, ea, eb = c[:-1], c[1:], r[:-1], r[1:]
            c = (1 - tk) * a + tk * b
            r = abs(1 - tk) * ea + abs(tk) * eb + gamma * (w * abs(1 - tk) * np.abs(a) + abs(tk) * np.abs(b) + np.abs(c))
        centres.append(c[0])
        radius.append(r[0])
    centres, radius = np.array(centres), np.array(radius)
    return (centres[0], radius[0]) if scalar else (centres, radius)

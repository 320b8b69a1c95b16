"""Reads the knots in the usual c + n + 1 convention (degree = len(knots) - len(points) - 1), two degrees too low."""
import numpy as np


def de_boor(points, knots, t):
    P = np.array(points, dtype=float)
    T = np.array(knots, dtype=float)
    if P.ndim != 2 or T.ndim != 1 or np.any(np.diff(T) < 0):
        raise ValueError("points must be (c, d) and knots non-decreasing")
    n = len(T) - len(P) - 1
    if n < 1:
        raise ValueError("knots: too few knots for the points")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)
    a, b = T[n], T[len(P)]
    if np.any((tt < a) | (tt > b)):
        raise ValueError("t outside the domain")
    j = np.clip(np.searchsorted(T, tt, side="right") - 1, n, len(P) - 1)
    d = [P[j - n + k] for k in range(n + 1)]
    for r in range(1, n + 1):
        for k in range(n, r - 1, -1):
            i = j - n + k
            alpha = ((tt - T[i]) / (T[i + n + 1 - r] - T[i]))[:, None]
            d[k] = (1 - alpha) * d[k - 1] + alpha * d[k]
    out = d[n]
    return out[0] if ts.ndim == 0 else out

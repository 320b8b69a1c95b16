"""Uses t_(i+n-r+1) instead of t_(i+n-r) as the upper knot of the de Boor ratio: one knot too far to the right."""
import numpy as np


def de_boor(points, knots, t):
    P = np.array(points, dtype=float)
    T = np.array(knots, dtype=float)
    if P.ndim != 2 or T.ndim != 1 or np.any(np.diff(T) < 0):
        raise ValueError("points must be (c, d) and knots non-decreasing")
    n = len(T) - len(P) + 1
    if n < 1:
        raise ValueError("knots: too few knots for the points")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)
    a, b = T[n - 1], T[len(P) - 1]
    if np.any((tt < a) | (tt > b)):
        raise ValueError("t outside the domain")
    padded = np.concatenate([T, [T[-1]]])
    last = max(j for j in range(n - 1, len(P) - 1) if T[j] < T[j + 1])
    j = np.minimum(np.searchsorted(T, tt, side="right") - 1, last)
    d = [P[j - n + 1 + k] for k in range(n + 1)]
    for r in range(1, n + 1):
        for k in range(n, r - 1, -1):
            i = j - n + 1 + k
            hi = padded[np.minimum(i + n - r + 1, len(T))]
            alpha = ((tt - T[i - 1]) / (hi - T[i - 1]))[:, None]
            d[k] = (1 - alpha) * d[k - 1] + alpha * d[k]
    out = d[n]
    return out[0] if ts.ndim == 0 else out

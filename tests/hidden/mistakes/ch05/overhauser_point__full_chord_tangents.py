"""Uses the whole chords P2 - P0 and P3 - P1 as end tangents instead of half of them."""
import numpy as np


def overhauser_point(points, t):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) < 4:
        raise ValueError("points must have shape (c, d) with c >= 4")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)
    if np.any((tt < 0) | (tt > len(P) - 3)):
        raise ValueError("t out of range")
    j = np.minimum(np.floor(tt).astype(int), len(P) - 4)
    u = (tt - j)[:, None]
    h00, h10, h01, h11 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2
    start, end = P[j + 1], P[j + 2]
    out = h00 * start + h10 * (P[j + 2] - P[j]) + h01 * end + h11 * (P[j + 3] - P[j + 1])
    return out[0] if ts.ndim == 0 else out

"""Takes segment floor(t) without clamping, so t = c - 3 asks for a fifth point past the end and fails."""
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
    j = np.floor(tt).astype(int)
    u = (tt - j)[:, None]
    f = 0.5 * np.hstack([-u * (1 - u) ** 2, 2 - 5 * u**2 + 3 * u**3, u + 4 * u**2 - 3 * u**3, -(u**2) * (1 - u)])
    out = np.einsum("ki,kid->kd", f, P[j[:, None] + np.arange(4)])
    return out[0] if ts.ndim == 0 else out

"""A Hermite segment whose tangent at point i is the chord (P_i+1 - P_i-1)/(t_i+1 - t_i-1): a different
non-uniform scheme from the blend of two parabolas (it agrees only for evenly spaced parameters)."""
import numpy as np


def catmull_rom_point(points, params, t):
    P = np.array(points, dtype=float)
    knots = np.array(params, dtype=float)
    if P.ndim != 2 or len(P) < 4 or knots.shape != (len(P),) or np.any(np.diff(knots) <= 0):
        raise ValueError("bad points or params")
    if not (np.all(np.isfinite(P)) and np.all(np.isfinite(knots))):
        raise ValueError("NaN or infinity")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1 or not np.all(np.isfinite(ts)):
        raise ValueError("bad t")
    tt = np.atleast_1d(ts)
    if np.any((tt < knots[1]) | (tt > knots[-2])):
        raise ValueError("t out of range")
    j = np.clip(np.searchsorted(knots, tt, side="right") - 2, 0, len(P) - 4)
    width = (knots[j + 2] - knots[j + 1])[:, None]
    u = (tt[:, None] - knots[j + 1][:, None]) / width
    d1 = (P[j + 2] - P[j]) / (knots[j + 2] - knots[j])[:, None] * width
    d2 = (P[j + 3] - P[j + 1]) / (knots[j + 3] - knots[j + 1])[:, None] * width
    h0, h1 = 2 * u**3 - 3 * u**2 + 1, -2 * u**3 + 3 * u**2
    h2, h3 = u**3 - 2 * u**2 + u, u**3 - u**2
    out = h0 * P[j + 1] + h1 * P[j + 2] + h2 * d1 + h3 * d2
    return out[0] if ts.ndim == 0 else out

"""Finds the segment by the parameters but then evaluates the uniform Overhauser segment at the local fraction
u = (t - t_j+1)/(t_j+2 - t_j+1): right for evenly spaced parameters only."""
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
    u = ((tt - knots[j + 1]) / (knots[j + 2] - knots[j + 1]))[:, None]
    f = 0.5 * np.hstack([-u * (1 - u) ** 2, 2 - 5 * u**2 + 3 * u**3, u + 4 * u**2 - 3 * u**3, -(u**2) * (1 - u)])
    out = np.einsum("ki,kid->kd", f, P[j[:, None] + np.arange(4)])
    return out[0] if ts.ndim == 0 else out

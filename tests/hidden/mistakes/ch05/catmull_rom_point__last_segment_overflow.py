"""Takes the segment from searchsorted without clamping, so t = t_m-2 (the very end) asks for a point past
the last one."""
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
    j = np.searchsorted(knots, tt, side="right") - 2
    idx = j[:, None] + np.arange(4)
    k, w, x = knots[idx], P[idx], tt[:, None]

    def lerp(level, a, b):
        left, right = k[:, a : a + level.shape[1] - 1], k[:, b : b + level.shape[1] - 1]
        s = ((x - left) / (right - left))[:, :, None]
        return (1 - s) * level[:, :-1] + s * level[:, 1:]

    out = lerp(lerp(lerp(w, 0, 1), 0, 2), 1, 2)[:, 0]
    return out[0] if ts.ndim == 0 else out

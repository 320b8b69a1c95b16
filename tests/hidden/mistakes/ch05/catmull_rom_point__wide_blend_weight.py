"""Blends the two parabolas with the weight (t - t_j)/(t_j+3 - t_j) across all four parameters instead of
(t - t_j+1)/(t_j+2 - t_j+1) across the middle interval: still through the points, wrong in between."""
import numpy as np


def _parabola(ts, pts, t):
    (a, b, c), (p, q, r) = ts, pts
    pq = ((b - t) * p + (t - a) * q) / (b - a)
    qr = ((c - t) * q + (t - b) * r) / (c - b)
    return ((c - t) * pq + (t - a) * qr) / (c - a)


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
    k = knots[j[:, None] + np.arange(4)].T[:, :, None]  # (4, k, 1)
    w = P[j[:, None] + np.arange(4)].transpose(1, 0, 2)  # (4, k, d)
    x = tt[:, None]
    left = _parabola(k[:3], w[:3], x)
    right = _parabola(k[1:], w[1:], x)
    share = (x - k[0]) / (k[3] - k[0])
    out = (1 - share) * left + share * right
    return out[0] if ts.ndim == 0 else out

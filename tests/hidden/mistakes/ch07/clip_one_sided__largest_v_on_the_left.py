"""Takes the largest positive meet on the left (and the smallest below 1 on the right)."""
import numpy as np


def clip_one_sided(line, points, weights=None):
    L = np.asarray(line, dtype=float)
    P = np.asarray(points, dtype=float)
    if L.shape != (3,) or not L.any():
        raise ValueError("bad line")
    if P.ndim != 2 or P.shape[1] != 2:
        raise ValueError("bad points")
    w = np.ones(len(P)) if weights is None else np.asarray(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w <= 0):
        raise ValueError("weights must be positive, one per point")
    e = w * (P @ L[:2] + L[2])
    if np.all(e < 0):
        return None
    n = len(e) - 1
    if n == 0:
        return (0.0, 1.0)
    t = np.arange(n + 1) / n
    lo, hi = 0.0, 1.0
    if e[0] < 0:
        vs = [-e[0] * t[i] / (e[i] - e[0]) for i in range(1, n + 1) if e[i] != e[0]]
        lo = min(max(v for v in vs if v > 0), 1.0)
    if e[-1] < 0:
        vs = [1 + e[-1] * (1 - t[i]) / (e[i] - e[-1]) for i in range(n) if e[i] != e[-1]]
        hi = max(min(v for v in vs if v < 1), 0.0)
    return (lo, hi)

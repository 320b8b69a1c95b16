"""Computes the exact crossing of the convex hull, not the notes' V rule."""
import numpy as np


def _band(c, low, high):
    n = len(c) - 1
    if n == 0:
        return (0.0, 1.0) if low <= c[0] <= high else None
    t = np.arange(n + 1) / n
    found = list(t[(c >= low) & (c <= high)])
    for level in (low, high):
        if not np.isfinite(level):
            continue
        for a in range(n + 1):
            for b in range(n + 1):
                if c[a] < level < c[b]:
                    found.append(t[a] + (t[b] - t[a]) * (level - c[a]) / (c[b] - c[a]))
    if not found:
        return None
    return max(min(found), 0.0), min(max(found), 1.0)


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
    return _band(e, 0.0, np.inf)
    n = len(e) - 1
    if n == 0:
        return (0.0, 1.0)
    t = np.arange(n + 1) / n
    lo, hi = 0.0, 1.0
    if e[0] < 0:
        vs = [-e[0] * t[i] / (e[i] - e[0]) for i in range(1, n + 1) if e[i] != e[0]]
        lo = min(v for v in vs if v > 0)
    if e[-1] < 0:
        vs = [1 + e[-1] * (1 - t[i]) / (e[i] - e[-1]) for i in range(n) if e[i] != e[-1]]
        hi = max(v for v in vs if v < 1)
    return (lo, hi)

"""Uses only the crossings with the two lines, forgetting control points inside the band."""
import numpy as np


def _band(c, low, high):
    n = len(c) - 1
    if n == 0:
        return None
    t = np.arange(n + 1) / n
    found = []
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


def clip_range(coeffs, dmin, dmax):
    c = np.asarray(coeffs, dtype=float)
    if c.ndim != 1 or len(c) == 0:
        raise ValueError("coeffs must be 1-D and not empty")
    if dmin > dmax:
        raise ValueError("dmin > dmax")
    return _band(c, float(dmin), float(dmax))

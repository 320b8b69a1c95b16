"""Returns (0, 1) when the hull misses the band, instead of None."""
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
        return (0.0, 1.0)
    return max(min(found), 0.0), min(max(found), 1.0)


def clip_range(coeffs, dmin, dmax):
    c = np.asarray(coeffs, dtype=float)
    if c.ndim != 1 or len(c) == 0:
        raise ValueError("coeffs must be 1-D and not empty")
    if dmin > dmax:
        raise ValueError("dmin > dmax")
    return _band(c, float(dmin), float(dmax))

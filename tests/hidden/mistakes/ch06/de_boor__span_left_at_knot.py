"""Finds the span with searchsorted(side='left'), so a t equal to a knot (the start of the domain above all) lands one span too early."""
import numpy as np


def de_boor(points, knots, t):
    P = np.array(points, dtype=float)
    T = np.array(knots, dtype=float)
    if P.ndim != 2 or T.ndim != 1 or np.any(np.diff(T) < 0):
        raise ValueError("points must be (c, d) and knots non-decreasing")
    n = len(T) - len(P) + 1
    if n < 1:
        raise ValueError("knots: too few knots for the points")
    ts = np.asarray(t, dtype=float)
    if ts.ndim > 1:
        raise ValueError("t must be a number or a 1-D array")
    tt = np.atleast_1d(ts)
    a, b = T[n - 1], T[len(P) - 1]
    if np.any((tt < a) | (tt > b)):
        raise ValueError("t outside the domain")
    out = []
    for s in tt:
        j = int(np.searchsorted(T, s, side="left")) - 1
        j = min(max(j, 0), len(P) - 2)
        level = [P[i].copy() for i in range(j - n + 1, j + 2)]
        for r in range(1, n + 1):
            new = []
            for k in range(r, n + 1):
                i = j - n + 1 + k
                lo, hi = T[i - 1], T[i + n - r]
                alpha = (s - lo) / (hi - lo)
                new.append((1 - alpha) * level[k - r] + alpha * level[k - r + 1])
            level = new
        out.append(level[0])
    out = np.array(out)
    return out[0] if ts.ndim == 0 else out

"""Treats the knots as the c + n + 1 convention, so the degree and every knot index are off (by two and by one)."""
import numpy as np


def _check(points, knots):
    P = np.array(points, dtype=float)
    T = np.array(knots, dtype=float)
    if P.ndim != 2 or T.ndim != 1:
        raise ValueError("points must be (c, d) and knots 1-D")
    if np.any(np.diff(T) < 0):
        raise ValueError("knots must not decrease")
    n = len(T) - len(P) - 1
    if n < 1:
        raise ValueError("knots: too few knots for the points")
    return P, T, n


def insert_knot(points, knots, t):
    P, T, n = _check(points, knots)
    if np.ndim(t) != 0:
        raise ValueError("t must be one number")
    t = float(t)
    if not T[n] <= t <= T[len(P)]:
        raise ValueError("t outside the domain")
    j = min(int(np.searchsorted(T, t, side="right")) - 1, len(P) - 1)
    new = []
    for m in range(j - n + 1, j + 1):
        alpha = (t - T[m]) / (T[m + n] - T[m])
        new.append((1 - alpha) * P[m - 1] + alpha * P[m])
    points_out = np.vstack([P[: j - n + 1], new, P[j:]])
    return points_out, np.insert(T, j + 1, t)

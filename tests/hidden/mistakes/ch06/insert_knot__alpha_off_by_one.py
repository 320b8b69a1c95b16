"""Divides by t_(m+n) - t_(m-1) instead of t_(m+n-1) - t_(m-1): the label window is one knot too wide."""
import numpy as np


def _check(points, knots):
    P = np.array(points, dtype=float)
    T = np.array(knots, dtype=float)
    if P.ndim != 2 or T.ndim != 1:
        raise ValueError("points must be (c, d) and knots 1-D")
    if np.any(np.diff(T) < 0):
        raise ValueError("knots must not decrease")
    n = len(T) - len(P) + 1
    if n < 1:
        raise ValueError("knots: too few knots for the points")
    return P, T, n


def insert_knot(points, knots, t):
    P, T, n = _check(points, knots)
    if np.ndim(t) != 0:
        raise ValueError("t must be one number")
    t = float(t)
    if not T[n - 1] <= t <= T[len(P) - 1]:
        raise ValueError("t outside the domain")
    if np.count_nonzero(T == t) >= n:
        raise ValueError("t already has multiplicity n")
    last = max(j for j in range(n - 1, len(P) - 1) if T[j] < T[j + 1])
    j = min(int(np.searchsorted(T, t, side="right")) - 1, last)
    new = []
    for m in range(j - n + 2, j + 2):
        upper = T[min(m + n, len(T) - 1)]
        alpha = (t - T[m - 1]) / (upper - T[m - 1])
        new.append((1 - alpha) * P[m - 1] + alpha * P[m])
    points_out = np.vstack([P[: j - n + 2], new, P[j + 1 :]])
    return points_out, np.insert(T, j + 1, t)

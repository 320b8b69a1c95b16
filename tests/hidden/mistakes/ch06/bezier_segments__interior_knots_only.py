"""Raises only the knots strictly inside the domain to multiplicity n, forgetting its two ends."""
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
    t = float(t)
    last = max(j for j in range(n - 1, len(P) - 1) if T[j] < T[j + 1])
    j = min(int(np.searchsorted(T, t, side="right")) - 1, last)
    new = []
    for m in range(j - n + 2, j + 2):
        alpha = (t - T[m - 1]) / (T[m + n - 1] - T[m - 1])
        new.append((1 - alpha) * P[m - 1] + alpha * P[m])
    return np.vstack([P[: j - n + 2], new, P[j + 1 :]]), np.insert(T, j + 1, t)


def bezier_segments(points, knots):
    P, T, n = _check(points, knots)
    a, b = T[n - 1], T[len(P) - 1]
    for v in np.unique(T[(T > a) & (T < b)]):
        for _ in range(n - np.count_nonzero(T == v)):
            P, T = insert_knot(P, T, v)
    segments = []
    for j in range(n - 1, len(P) - 1):
        if T[j] < T[j + 1]:
            segments.append(P[j - n + 1 : j + 2])
    return np.array(segments)

"""Uses the span of the smallest argument but never checks the other segments, so ambiguous arguments get a value."""
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


def _polar(P, T, n, j, u):
    """The polar de Boor triangle of span j with argument u[r-1] at level r."""
    level = [P[i].copy() for i in range(j - n + 1, j + 2)]
    for r in range(1, n + 1):
        new = []
        for k in range(r, n + 1):
            i = j - n + 1 + k
            alpha = (u[r - 1] - T[i - 1]) / (T[i + n - r] - T[i - 1])
            new.append((1 - alpha) * level[k - r] + alpha * level[k - r + 1])
        level = new
    return level[0]


def _spans(P, T, n):
    return [j for j in range(n - 1, len(P) - 1) if T[j] < T[j + 1]]


def _span_of(P, T, n, x):
    spans = _spans(P, T, n)
    x = min(max(x, T[n - 1]), T[len(P) - 1])
    inside = [j for j in spans if T[j] <= x < T[j + 1]]
    return inside[0] if inside else spans[-1]


def _arguments(P, T, n, args):
    u = np.array(args, dtype=float)
    if u.shape != (n,):
        raise ValueError("args: need n arguments")
    if u.min() < T[0] or u.max() > T[-1]:
        raise ValueError("args outside the knot vector")
    return u


def blossom(points, knots, args):
    P, T, n = _check(points, knots)
    u = _arguments(P, T, n, args)
    return _polar(P, T, n, _span_of(P, T, n, u.min()), u)

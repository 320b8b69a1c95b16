"""Starts Cox-de Boor from t_m <= t < t_(m+1) everywhere, so every basis function is 0 at the end of the domain."""
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


def _basis_input(knots, degree, i, t):
    T = np.array(knots, dtype=float)
    if isinstance(degree, bool) or not isinstance(degree, int) or degree < 1:
        raise ValueError("degree must be an integer >= 1")
    if T.ndim != 1 or np.any(np.diff(T) < 0) or len(T) < 2 * degree:
        raise ValueError("bad knots")
    c = len(T) - degree + 1
    if not 0 <= i < c:
        raise ValueError("i out of range")
    ts = np.asarray(t, dtype=float)
    tt = np.atleast_1d(ts)
    if ts.ndim > 1 or np.any((tt < T[degree - 1]) | (tt > T[c - 1])):
        raise ValueError("t outside the domain")
    return T, c, ts, tt


def bspline_basis(knots, degree, i, t):
    T, c, ts, tt = _basis_input(knots, degree, i, t)
    u = np.concatenate([T[:1], T, T[-1:]])
    N = np.zeros((len(tt), len(u) - 1))
    for m in range(len(u) - 1):
        N[:, m] = (u[m] <= tt) & (tt < u[m + 1])
    for p in range(1, degree + 1):
        new = np.zeros((len(tt), len(u) - 1 - p))
        for m in range(len(u) - 1 - p):
            d1, d2 = u[m + p] - u[m], u[m + p + 1] - u[m + 1]
            left = (tt - u[m]) / d1 * N[:, m] if d1 > 0 else 0.0
            right = (u[m + p + 1] - tt) / d2 * N[:, m + 1] if d2 > 0 else 0.0
            new[:, m] = left + right
        N = new
    values = N[:, i]
    return float(values[0]) if ts.ndim == 0 else values

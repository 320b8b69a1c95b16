"""Rejects every knot span without a parameter, as if an empty span made the normal equations singular."""
import numpy as np


def _basis(knots, n, ts, order=0, closed_end=True):
    """Collocation matrix (k, c) of the order-th derivatives by Cox-de Boor on the padded knots (0/0 = 0)."""
    U = np.concatenate([knots[:1], knots, knots[-1:]])
    c = len(knots) - n + 1
    ts = np.asarray(ts, dtype=float)
    end = knots[c - 1]
    B = np.zeros((len(ts), len(U) - 1))
    for i in range(len(U) - 1):
        B[:, i] = (U[i] <= ts) & (ts < U[i + 1])
    if closed_end:
        last = max(i for i in range(len(U) - 1) if U[i] < U[i + 1] and U[i + 1] <= end)
        B[ts == end, last] = 1.0
    for p in range(1, n + 1):
        new = np.zeros((len(ts), len(U) - 1 - p))
        for i in range(len(U) - 1 - p):
            d1, d2 = U[i + p] - U[i], U[i + p + 1] - U[i + 1]
            if p > n - order:
                a = p / d1 if d1 > 0 else 0.0
                b = p / d2 if d2 > 0 else 0.0
                new[:, i] = a * B[:, i] - b * B[:, i + 1]
            else:
                a = (ts - U[i]) / d1 if d1 > 0 else 0.0
                b = (U[i + p + 1] - ts) / d2 if d2 > 0 else 0.0
                new[:, i] = a * B[:, i] + b * B[:, i + 1]
        B = new
    return B


def _check(points, params, knots, degree):
    P = np.asarray(points, dtype=float)
    s = np.asarray(params, dtype=float)
    T = np.asarray(knots, dtype=float)
    if P.ndim != 2 or s.ndim != 1 or len(s) != len(P):
        raise ValueError("points/params: shapes do not match")
    if not isinstance(degree, int) or degree < 1 or np.any(np.diff(T) < 0) or len(T) < 2 * degree:
        raise ValueError("knots/degree: bad knot vector or degree")
    c = len(T) - degree + 1
    if np.any(s < T[degree - 1]) or np.any(s > T[c - 1]):
        raise ValueError("params: outside the domain")
    return P, s, T, c


def least_squares_fit(points, params, knots, degree):
    P, s, T, c = _check(points, params, knots, degree)
    for a, b in zip(T[degree - 1 : c - 1], T[degree:c]):
        if b > a and not np.any((s >= a) & (s <= b)):
            raise ValueError(f"params: no parameter in the knot span [{a}, {b}]")
    N = _basis(T, degree, s)
    if np.linalg.matrix_rank(N) < c:
        raise ValueError("params: singular normal equations")
    return np.linalg.solve(N.T @ N, N.T @ P)

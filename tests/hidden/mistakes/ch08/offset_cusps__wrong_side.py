"""Solves 1 - rho kappa = 0: the cusps of the offset at -rho, on the other side."""
import numpy as np
from math import comb


def _curve(points, weights):
    P = np.array(points, dtype=float)
    if P.ndim != 2 or P.shape[1] != 2 or len(P) < 2:
        raise ValueError("points must have shape (n+1, 2) with n >= 1")
    if weights is None:
        return P, None
    w = np.array(weights, dtype=float)
    if w.shape != (len(P),) or np.any(w <= 0):
        raise ValueError("weights must be n+1 positive numbers")
    return P, w


def _bez(C, ts):
    n = len(C) - 1
    ts = np.asarray(ts, dtype=float)[:, None]
    i = np.arange(n + 1)
    B = np.array([comb(n, k) for k in i]) * (1 - ts) ** (n - i) * ts ** i
    return B @ C


def _hod(C):
    n = len(C) - 1
    return n * np.diff(C, axis=0) if n else np.zeros_like(C)


def _derivs(P, w, ts):
    """Q, Q', Q'' at ts."""
    if w is None:
        H = P
    else:
        H = np.column_stack([P * w[:, None], w])
    H1, H2 = _hod(H), _hod(_hod(H))
    X, X1, X2 = _bez(H, ts), _bez(H1, ts), _bez(H2, ts)
    if w is None:
        return X, X1, X2
    W, W1, W2 = X[:, 2:], X1[:, 2:], X2[:, 2:]
    Q = X[:, :2] / W
    Q1 = (X1[:, :2] - W1 * Q) / W
    Q2 = (X2[:, :2] - 2 * W1 * Q1 - W2 * Q) / W
    return Q, Q1, Q2


def _g(P, w, rho, ts):
    _, Q1, Q2 = _derivs(P, w, ts)
    speed = np.linalg.norm(Q1, axis=1)
    return 1 - rho * (Q1[:, 0] * Q2[:, 1] - Q1[:, 1] * Q2[:, 0]) / speed ** 3


def offset_cusps(points, rho, weights=None):
    P, w = _curve(points, weights)
    rho = float(rho)
    if np.all(P == P[0]):
        raise ValueError("all control points coincide")
    ts = np.linspace(0, 1, 4001)
    g = _g(P, w, rho, ts)
    if np.all(np.abs(g[::100]) <= 1e-9):
        raise ValueError("1 + rho kappa vanishes identically")
    if rho == 0:
        return np.array([])
    found = list(ts[g == 0])
    for i in np.flatnonzero(g[:-1] * g[1:] < 0):
        a, b = ts[i], ts[i + 1]
        ga = g[i]
        for _ in range(60):
            m = (a + b) / 2
            gm = _g(P, w, rho, [m])[0]
            if (gm < 0) == (ga < 0):
                a, ga = m, gm
            else:
                b = m
        found.append((a + b) / 2)
    # local minima of |g| touching zero: golden-section refinement around grid minima
    ag = np.abs(g)
    idx = [i for i in range(len(ts)) if (i == 0 or ag[i] <= ag[i - 1]) and (i == len(ts) - 1 or ag[i] <= ag[i + 1])]
    for i in idx:
        if ag[i] > 1e-3:
            continue
        a, b = ts[max(i - 1, 0)], ts[min(i + 1, len(ts) - 1)]
        for _ in range(80):
            m1, m2 = a + (b - a) * 0.382, a + (b - a) * 0.618
            if abs(_g(P, w, rho, [m1])[0]) < abs(_g(P, w, rho, [m2])[0]):
                b = m2
            else:
                a = m1
        m = (a + b) / 2
        if abs(_g(P, w, rho, [m])[0]) <= 1e-9:
            found.append(m)
    found.sort()
    merged = []
    for t in found:
        if merged and t - merged[-1][-1] <= 1e-6:
            merged[-1].append(t)
        else:
            merged.append([t])
    return np.array([sum(m) / len(m) for m in merged])

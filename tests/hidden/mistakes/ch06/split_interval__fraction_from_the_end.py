"""Places the new knot at fraction * d from the end of the interval instead of from its start."""
import numpy as np


def _knot(d, k):
    """t_k of the periodic knots with t_0 = 0 (d cyclic)."""
    c = len(d)
    if k >= 0:
        return float(sum(d[i % c] for i in range(k)))
    return -float(sum(d[i % c] for i in range(k, 0)))


def _insert(P, T, n, u):
    last = max(j for j in range(n - 1, len(P) - 1) if T[j] < T[j + 1])
    j = min(int(np.searchsorted(T, u, side="right")) - 1, last)
    new = []
    for m in range(j - n + 2, j + 2):
        alpha = (u - T[m - 1]) / (T[m + n - 1] - T[m - 1])
        new.append((1 - alpha) * P[m - 1] + alpha * P[m])
    return np.vstack([P[: j - n + 2], new, P[j + 1 :]]), np.insert(T, j + 1, u)


def _inputs(points, intervals, index, fraction):
    P = np.array(points, dtype=float)
    d = np.array(intervals, dtype=float)
    if P.ndim != 2 or d.ndim != 1 or np.any(d < 0):
        raise ValueError("bad points or intervals")
    if isinstance(index, bool) or not isinstance(index, int) or index < 0:
        raise ValueError("index must be a non-negative integer")
    f = float(fraction)
    if not 0 <= f <= 1:
        raise ValueError("fraction must lie in [0, 1]")
    return P, d, index, f


def _split_open(P, d, q, f, from_end=False):
    T = np.concatenate([[0.0], np.cumsum(d)])
    n = len(T) - len(P) + 1
    if n < 1 or not n - 1 <= q <= len(T) - n - 1:
        raise ValueError("index outside the domain")
    u = T[q + 1] - f * d[q] if from_end else T[q] + f * d[q]
    P2, T2 = _insert(P, T, n, u)
    return P2, np.diff(T2)


def _split_closed(P, d, q, f, n, s):
    c = len(P)
    if len(d) != c or q >= c:
        raise ValueError("closed curves have one interval per point")
    label = lambda m: P[(m - s) % c]  # noqa: E731
    u = _knot(d, q) + f * d[q]
    new = []
    for m in range(q - n + 2, q + 2):
        lo, hi = _knot(d, m - 1), _knot(d, m + n - 1)
        alpha = (u - lo) / (hi - lo)
        new.append((1 - alpha) * label(m - 1) + alpha * label(m))
    rest = [label(m - 1) for m in range(q + 2, q - n + 3 + c)]
    by_label = new + rest
    labels = list(range(q - n + 2, q - n + 3 + c))
    out = [None] * (c + 1)
    for m, point in zip(labels, by_label):
        out[(m - s) % (c + 1)] = point
    return np.array(out), np.concatenate([d[:q], [f * d[q], (1 - f) * d[q]], d[q + 1 :]])


def split_interval(points, intervals, index, fraction, *, degree=None):
    P, d, q, f = _inputs(points, intervals, index, fraction)
    if degree is None:
        return _split_open(P, d, q, f, from_end=True)
    return _split_closed(P, d, q, 1 - f, degree, -((degree - 1) // 2))[0], np.concatenate([d[:q], [f * d[q], (1 - f) * d[q]], d[q + 1 :]])

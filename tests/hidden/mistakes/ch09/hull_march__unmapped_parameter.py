"""Records the local crossing c of the current piece as the root, not a + (1 - a) c."""
import numpy as np


def _check(coeffs, interval, tol):
    y = np.asarray(coeffs, dtype=float)
    iv = np.asarray(interval, dtype=float)
    if y.ndim != 1 or len(y) == 0 or not np.any(y):
        raise ValueError("coeffs: expected a nonzero vector")
    if iv.shape != (2,) or not iv[0] < iv[1]:
        raise ValueError("interval: expected t0 < t1")
    if not 0 < tol < 1:
        raise ValueError("tol: expected 0 < tol < 1")
    return y, iv


def _split(c, t):
    left, right, level = [], [], np.array(c, dtype=float)
    while len(level):
        left.append(level[0])
        right.append(level[-1])
        level = (1 - t) * level[:-1] + t * level[1:]
    return np.array(left), np.array(right[::-1])


def _zero(value, c):
    return abs(value) <= 1e-12 * np.abs(c).max()


def _leftmost(y):
    n = len(y) - 1
    x = np.arange(n + 1) / n
    found = [x[i] for i in range(n + 1) if y[i] == 0]
    for i in range(n + 1):
        for j in range(n + 1):
            if y[i] < 0 < y[j]:
                found.append(x[i] - y[i] * (x[j] - x[i]) / (y[j] - y[i]))
    return min(found) if found else None


def hull_march(coeffs, interval=(0, 1), tol=1e-12):
    y, (t0, t1) = _check(coeffs, interval, tol)
    roots, ends = [], 0
    while len(y) > 1 and _zero(y[-1], y):
        n = len(y) - 1
        y = n * y[:-1] / np.arange(n, 0, -1)
        ends += 1
    a = 0.0
    for _ in range(100000):
        if len(y) < 2:
            break
        n = len(y) - 1
        if _zero(y[0], y):
            roots.append(a)
            y = n * y[1:] / np.arange(1, n + 1)
            continue
        c = _leftmost(y)
        if c is None:
            break
        t = a + (1 - a) * c
        right = _split(y, c)[1]
        if t - a <= tol or _zero(right[0], right) or np.sign(right[0]) != np.sign(y[0]):
            roots.append(c)
            y = n * right[1:] / np.arange(1, n + 1)
        else:
            y = right
        a = t
    return t0 + (t1 - t0) * np.array(roots + [1.0] * ends)

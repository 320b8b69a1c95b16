"""Returns a root found at a split point twice: once by each half."""
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


def _value(c, t):
    return _split(c, t)[0][-1]


def _bisect(c, a, b, tol):
    """The root of a piece with one sign change; c are its coefficients on [a, b]."""
    lo, hi, f_lo = 0.0, 1.0, c[0]
    while (hi - lo) * (b - a) > tol:
        mid = (lo + hi) / 2
        f_mid = _value(c, mid)
        if f_mid == 0:
            return a + (b - a) * mid
        if np.sign(f_mid) == np.sign(f_lo):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
    return a + (b - a) * (lo + hi) / 2


def _search(c, a, b, tol, found):
    signs = np.sign(c[c != 0])
    changes = np.count_nonzero(signs[1:] != signs[:-1])
    if c[0] == 0:
        found.append(a)
    if c[-1] == 0:
        found.append(b)
    if changes == 0:
        return
    if changes == 1 and c[0] != 0 and c[-1] != 0:
        found.append(_bisect(c, a, b, tol))
        return
    if b - a <= tol:
        found.append((a + b) / 2)
        return
    left, right = _split(c, 0.5)
    _search(left, a, (a + b) / 2, tol, found)
    _search(right, (a + b) / 2, b, tol, found)


def bernstein_roots(coeffs, interval=(0, 1), tol=1e-12):
    y, (t0, t1) = _check(coeffs, interval, tol)
    found = []
    _search(y, 0.0, 1.0, tol, found)
    return t0 + (t1 - t0) * np.sort(np.array(found, dtype=float))

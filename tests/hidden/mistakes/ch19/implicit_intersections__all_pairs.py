"""Pairs every root x of Res_y with every root y of Res_x, without asking which pairs lie on both curves."""
import numpy as np
from numpy.polynomial import polynomial as P


def _c(c, name):
    a = np.array(c, dtype=float)
    if a.ndim != 2 or a.size == 0 or not np.all(np.isfinite(a)):
        raise ValueError(name + ": expected a 2-D array")
    if not np.any(a.ravel()[1:]):
        raise ValueError(name + ": a constant")
    return a


def _ydeg(c):
    cols = np.flatnonzero(np.any(c != 0, axis=0))
    return int(cols[-1])


def _deg(c):
    i, j = np.nonzero(c)
    return int((i + j).max())


def _column(c, x):
    return P.polyval(x, c)


def _sylvester_det(a, b):
    m, n = len(a) - 1, len(b) - 1
    if m == 0 or n == 0:
        return a[0] ** n * b[0] ** m
    s = np.zeros((m + n, m + n))
    for r in range(n):
        s[r, r:r + m + 1] = a[::-1]
    for r in range(m):
        s[n + r, r:r + n + 1] = b[::-1]
    return np.linalg.det(s)


def _resultant_y(f, g):
    m, n = _ydeg(f), _ydeg(g)
    bound = max(_deg(f) * _deg(g), 1)
    xs = np.cos(np.pi * (np.arange(bound + 1) + 0.5) / (bound + 1)) * 2
    values = [_sylvester_det(_column(f, x)[: m + 1], _column(g, x)[: n + 1]) for x in xs]
    return P.polyfit(xs, values, bound)


def _gcd(a, b, tol=1e-7):
    def trim(r, zero):
        keep = np.flatnonzero(np.abs(r) > zero)
        return r[: keep[-1] + 1] if keep.size else np.zeros(1)
    a, b = trim(a, 0), trim(b, 0)
    if len(a) < len(b):
        a, b = b, a
    while b.any():
        q, r = P.polydiv(a, b)
        r = trim(r, tol * max(np.abs(a).max(), np.abs(b).max()))
        a, b = b, r
    return a / a[-1]


def _real(r):
    r = np.array(r, dtype=float)
    if not np.any(r):
        return np.zeros(0)
    nz = np.flatnonzero(np.abs(r) > 1e-12 * np.abs(r).max())
    r = r[: nz[-1] + 1]
    if len(r) < 2:
        return np.zeros(0)
    roots = P.polyroots(r)
    real = np.sort(roots[np.abs(roots.imag) < 1e-7 * (1 + np.abs(roots))].real)
    out = []
    for v in real:
        if not out or abs(v - out[-1]) > 1e-6 * (1 + abs(v)):
            out.append(v)
    return np.array(out)


def implicit_intersections(f, g):
    f, g = _c(f, "f"), _c(g, "g")
    xs = _real(_resultant_y(f, g)) if _ydeg(f) + _ydeg(g) > 0 else np.zeros(0)
    ys = _real(_resultant_y(f.T, g.T)) if _ydeg(f.T) + _ydeg(g.T) > 0 else np.zeros(0)
    pts = [(x, y) for x in xs for y in ys]
    return np.array(sorted(pts), dtype=float).reshape(-1, 2)

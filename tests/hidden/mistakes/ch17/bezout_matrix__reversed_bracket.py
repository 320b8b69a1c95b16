"""Uses the bracket a_m b_k - a_k b_m: every entry has the wrong sign."""
import numpy as np
from math import comb
from numpy.polynomial import polynomial as P


def _poly(f):
    c = np.array(f, dtype=float)
    if c.ndim != 1 or c.size == 0 or not np.all(np.isfinite(c)):
        raise ValueError("f: expected finite coefficients (n+1,)")
    nz = np.flatnonzero(c)
    return c[: nz[-1] + 1] if nz.size else c[:1]


def _nonzero(f):
    c = _poly(f)
    if not c.any():
        raise ValueError("f: the zero polynomial")
    return c


def _sylvester(a, b):
    m, n = len(a) - 1, len(b) - 1
    s = np.zeros((m + n, m + n))
    for r in range(n):
        s[r, r:r + m + 1] = a[::-1]
    for r in range(m):
        s[n + r, r:r + n + 1] = b[::-1]
    return s


def _bezout(a, b):
    n = max(len(a), len(b)) - 1
    A, B = np.zeros(n + 1), np.zeros(n + 1)
    A[:len(a)], B[:len(b)] = a, b
    M = np.zeros((n, n))
    for i in range(n):
        for j in range(n):
            for m in range(min(i, j) + 1):
                k = i + j + 1 - m
                if k <= n:
                    M[n - 1 - i, n - 1 - j] += A[k] * B[m] - A[m] * B[k]
    return M


def _curve(points, weights):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or p.shape[1] != 2 or len(p) < 2 or not np.all(np.isfinite(p)):
        raise ValueError("points: expected (n+1, 2)")
    if weights is None:
        return np.column_stack([p, np.ones(len(p))])
    w = np.array(weights, dtype=float)
    if w.shape != (len(p),) or np.any(w == 0) or not np.all(np.isfinite(w)):
        raise ValueError("weights: expected n+1 nonzero weights")
    return np.column_stack([p * w[:, None], w])


def _times_line(line, poly):
    a, b, c = line
    out = c * poly
    out[1:, :] += a * poly[:-1, :]
    out[:, 1:] += b * poly[:, :-1]
    return out


def _det(forms, cols, row, size):
    if not cols:
        one = np.zeros((size, size))
        one[0, 0] = 1.0
        return one
    total = np.zeros((size, size))
    for pos, c in enumerate(cols):
        term = _times_line(forms[row][c], _det(forms, cols[:pos] + cols[pos + 1:], row + 1, size))
        total += term if pos % 2 == 0 else -term
    return total


def _implicit(H, binomials=True):
    n = len(H) - 1
    rows = H * np.array([comb(n, i) if binomials else 1 for i in range(n + 1)], dtype=float)[:, None]
    forms = [[np.zeros(3) for _ in range(n)] for _ in range(n)]
    for i in range(n):
        for j in range(n):
            for m in range(min(i, j) + 1):
                k = i + j + 1 - m
                if k <= n:
                    forms[n - 1 - i][n - 1 - j] = forms[n - 1 - i][n - 1 - j] + np.cross(rows[k], rows[m])
    f = _det(forms, list(range(n)), 0, n + 1)
    if np.abs(f).max() <= 1e-10 * max(1.0, np.abs(H).max()) ** n * 10 ** n:
        raise ValueError("points: the implicit equation vanishes (degree raised)")
    return f


def _to_power(c):
    n = len(c) - 1
    out = np.zeros(n + 1)
    for i in range(n + 1):
        # C(n, i) t^i (1-t)^(n-i)
        term = comb(n, i) * P.polymul(P.polypow([0.0, 1.0], i), P.polypow([1.0, -1.0], n - i))
        out[:len(term)] += c[i] * term
    return out


def _gcd(a, b, tol=1e-9):
    a, b = _poly(a), _poly(b)
    if len(a) < len(b):
        a, b = b, a
    while b.any():
        q, r = P.polydiv(a, b)
        scale = max(np.abs(a).max(), np.abs(b).max())
        keep = np.flatnonzero(np.abs(r) > tol * scale)
        r = r[: keep[-1] + 1] if keep.size else np.zeros(1)
        a, b = b, r
    return a / a[-1]


def _invert_one(H, x, y):
    X, Y, W = (_to_power(H[:, k]) for k in range(3))
    d = _gcd(P.polysub(X, x * W), P.polysub(Y, y * W))
    if len(d) == 1:
        raise ValueError("xy: not on the curve")
    if len(d) > 2:
        raise ValueError("xy: a double point")
    return -d[0] / d[1]


def _invert(points, xy, weights=None):
    H = _curve(points, weights)
    pts = np.array(xy, dtype=float)
    if not np.all(np.isfinite(pts)):
        raise ValueError("xy: not finite")
    if pts.shape == (2,):
        return _invert_one(H, *pts)
    if pts.ndim != 2 or pts.shape[1] != 2:
        raise ValueError("xy: expected (2,) or (k, 2)")
    return np.array([_invert_one(H, *p) for p in pts])

def bezout_matrix(f, g):
    return -_bezout(_nonzero(f), _nonzero(g)) + 0.0

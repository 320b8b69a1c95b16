"""Returns the textbook discriminant (b² - 4ac for a quadratic): (-1)^(n(n-1)/2) Res(p, dp) / a_n."""
import numpy as np
from numpy.polynomial import polynomial as P


def _poly(coeffs, strip=True):
    c = np.array(coeffs, dtype=float)
    if c.ndim != 1 or c.size == 0 or not np.all(np.isfinite(c)):
        raise ValueError("coeffs: expected (n+1,) finite numbers")
    if strip:
        nz = np.flatnonzero(c)
        c = c[: nz[-1] + 1] if nz.size else c[:1]
    if len(c) < 2 or not np.any(c[1:]):
        raise ValueError("coeffs: degree below 1")
    return c


def _sylvester_det(a, b):
    m, n = len(a) - 1, len(b) - 1
    if m == 0 or n == 0:
        return a[0] ** n * b[0] ** m
    s = np.zeros((m + n, m + n))
    for r in range(n):
        s[r, r:r + m + 1] = a[::-1]
    for r in range(m):
        s[n + r, r:r + n + 1] = b[::-1]
    return float(np.linalg.det(s))


def discriminant(coeffs):
    p = _poly(coeffs)
    n = len(p) - 1
    return (-1) ** (n * (n - 1) // 2) * _sylvester_det(p, P.polyder(p)) / p[-1]

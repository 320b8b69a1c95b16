"""Returns the notes' value, chapter 17's Bézout determinant of p and p' (a²(b² - 4ac) for a quadratic):
(-1)^(n(n-1)/2) a_n Res(p, p'), another convention than the Sylvester determinant the exercise asks for."""
import numpy as np
from numpy.polynomial import polynomial as P


def _poly(coeffs):
    c = np.array(coeffs, dtype=float)
    if c.ndim != 1 or c.size == 0 or not np.all(np.isfinite(c)):
        raise ValueError("coeffs: expected (n+1,) finite numbers")
    nz = np.flatnonzero(c)
    c = c[: nz[-1] + 1] if nz.size else c[:1]
    if len(c) < 2:
        raise ValueError("coeffs: degree below 1")
    return c


def _bezout(a, b):
    """The Bézout matrix of chapter 17 (17.8), b padded with zeros to the degree of a."""
    n = len(a) - 1
    bb = np.zeros(n + 1)
    bb[: len(b)] = b
    m = np.zeros((n, n))
    for i in range(n):
        for j in range(n):
            for k in range(min(i, j) + 1):
                high = i + j + 1 - k
                if high <= n:
                    m[n - 1 - i, n - 1 - j] += a[high] * bb[k] - a[k] * bb[high]
    return m


def discriminant(coeffs):
    p = _poly(coeffs)
    return float(np.linalg.det(_bezout(p, P.polyder(p))))

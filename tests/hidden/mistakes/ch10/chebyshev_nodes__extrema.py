"""Uses the extrema cos(iπ/(n-1)) (Chebyshev-Lobatto points, which include a and b) instead of the zeros."""
import numpy as np


def chebyshev_nodes(a, b, n):
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise TypeError("n: expected an integer >= 1") if not isinstance(n, (int, np.integer)) else ValueError("n: >= 1")
    a, b = float(a), float(b)
    if not a < b:
        raise ValueError("a, b: expected a < b")
    if n == 1:
        return np.array([(a + b) / 2])
    i = np.arange(n)
    return np.sort((a + b) / 2 + (b - a) / 2 * np.cos(i * np.pi / (n - 1)))

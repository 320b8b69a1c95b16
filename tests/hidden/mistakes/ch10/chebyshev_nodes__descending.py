"""Returns the nodes in the order of i, which is decreasing: the cosine falls from near 1 to near -1."""
import numpy as np


def chebyshev_nodes(a, b, n):
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise TypeError("n: expected an integer >= 1") if not isinstance(n, (int, np.integer)) else ValueError("n: >= 1")
    a, b = float(a), float(b)
    if not a < b:
        raise ValueError("a, b: expected a < b")
    i = np.arange(n)
    return (a + b) / 2 + (b - a) / 2 * np.cos((2 * i + 1) * np.pi / (2 * n))

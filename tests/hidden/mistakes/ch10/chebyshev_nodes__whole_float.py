"""Takes a whole float such as 3.0 for a count (the statement says a float is no count, even a whole one)."""
import numpy as np


def chebyshev_nodes(a, b, n):
    if isinstance(n, bool) or not isinstance(n, (int, float, np.integer, np.floating)) or n != int(n):
        raise TypeError("n: expected an integer")
    n = int(n)
    if n < 1:
        raise ValueError("n: expected an integer >= 1")
    a, b = float(a), float(b)
    if not a < b:
        raise ValueError("a, b: expected a < b")
    i = np.arange(n)
    return np.sort((a + b) / 2 + (b - a) / 2 * np.cos((2 * i + 1) * np.pi / (2 * n)))

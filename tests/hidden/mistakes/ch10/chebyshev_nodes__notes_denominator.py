"""Copies the notes' (10.6) as printed: cos((2i+1)π/(2n+2)) for i = 0..n-1, which mixes n and n+1 nodes."""
import numpy as np


def chebyshev_nodes(a, b, n):
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise TypeError("n: expected an integer >= 1") if not isinstance(n, (int, np.integer)) else ValueError("n: >= 1")
    a, b = float(a), float(b)
    if not a < b:
        raise ValueError("a, b: expected a < b")
    i = np.arange(n)
    return np.sort((a + b) / 2 + (b - a) / 2 * np.cos((2 * i + 1) * np.pi / (2 * n + 2)))

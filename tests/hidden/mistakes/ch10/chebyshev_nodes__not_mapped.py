"""Returns the Chebyshev zeros on [-1, 1] and forgets the affine map to [a, b]."""
import numpy as np


def chebyshev_nodes(a, b, n):
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise TypeError("n: expected an integer >= 1") if not isinstance(n, (int, np.integer)) else ValueError("n: >= 1")
    a, b = float(a), float(b)
    if not a < b:
        raise ValueError("a, b: expected a < b")
    i = np.arange(n)
    return np.sort(np.cos((2 * i + 1) * np.pi / (2 * n)))

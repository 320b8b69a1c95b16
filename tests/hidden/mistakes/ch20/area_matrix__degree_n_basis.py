"""Uses B^n instead of B^(n-1) for the derivative's basis."""
from math import comb

import numpy as np


def area_matrix(n):
    if isinstance(n, bool) or not isinstance(n, int):
        raise TypeError("n must be an integer")
    if n < 0:
        raise ValueError("n must be >= 0")
    A = np.zeros((n + 1, n + 1))
    if n == 0:
        return A

    def product(i, k):
        if not 0 <= k <= n:
            return 0.0
        return n * comb(n, i) * comb(n, k) / (comb(2 * n, i + k) * (2 * n + 1))
    for i in range(n + 1):
        for j in range(n + 1):
            A[i, j] = 1 * (product(i, j - 1) - product(i, j))
    return A

"""Returns the homogeneous rows w_i P_i as the control points: forgets to divide by the weights."""
from math import comb

import numpy as np


def _power_to_bernstein(a):
    n = len(a) - 1
    scale = np.array([comb(n, j) for j in range(n + 1)], dtype=float)
    column = a / scale[:, None]
    top = [column[0]]
    while len(column) > 1:
        column = column[:-1] + column[1:]
        top.append(column[0])
    return np.array(top)


def _checked(coeffs):
    h = np.array(coeffs, dtype=float)
    if h.ndim != 2 or len(h) == 0 or h.shape[1] < 2 or not np.all(np.isfinite(h)):
        raise ValueError("coeffs must be finite numbers of shape (n+1, d+1), d >= 1")
    return h


def power_to_rational_bezier(coeffs):
    h = _power_to_bernstein(_checked(coeffs))
    w = h[:, -1]
    if np.any(np.abs(w) <= 1e-12 * np.abs(w).max()):
        raise ValueError("a zero weight")
    return h[:, :-1], w

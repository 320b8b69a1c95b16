"""Averages n + 1 consecutive knots (the c + n + 1 habit) instead of the n knots of each polar label."""
import numpy as np


def _greville_input(knots, degree):
    T = np.array(knots, dtype=float)
    if isinstance(degree, bool) or not isinstance(degree, int) or degree < 1:
        raise ValueError("degree must be an integer >= 1")
    if T.ndim != 1 or np.any(np.diff(T) < 0) or len(T) < 2 * degree:
        raise ValueError("bad knots")
    return T


def greville(knots, degree):
    T = _greville_input(knots, degree)
    c = len(T) - degree + 1
    padded = np.concatenate([T, T[-1:]])
    return np.array([padded[i : i + degree + 1].mean() for i in range(c)])

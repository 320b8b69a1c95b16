"""Averages t_(i+1) ... t_(i+n), one knot to the right, and so returns one abscissa too few."""
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
    return np.array([T[i + 1 : i + 1 + degree].mean() for i in range(c - 1)])

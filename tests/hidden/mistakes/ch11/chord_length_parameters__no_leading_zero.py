"""Starts the cumulative sum at the first chord: M - 1 parameters, the first sample gets none."""
import numpy as np


def chord_length_parameters(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected at least two samples of shape (M, d)")
    s = np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))
    if s[-1] == 0:
        raise ValueError("points: no length")
    return s / s[-1]

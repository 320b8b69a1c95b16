"""Returns the running chord lengths without dividing by the total, so the last is the length, not 1."""
import numpy as np


def chord_length_parameters(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected at least two samples of shape (M, d)")
    steps = np.linalg.norm(np.diff(P, axis=0), axis=1)
    if steps.sum() == 0:
        raise ValueError("points: no length")
    return np.concatenate([[0.0], np.cumsum(steps)])

"""Returns evenly spaced parameters (11.4) instead of chord lengths (11.5)."""
import numpy as np


def chord_length_parameters(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected at least two samples of shape (M, d)")
    return np.linspace(0.0, 1.0, len(P))

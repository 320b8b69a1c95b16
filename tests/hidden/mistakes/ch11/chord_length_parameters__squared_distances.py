"""Adds up squared chord lengths (no square root), which weights long chords far too much."""
import numpy as np


def chord_length_parameters(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected at least two samples of shape (M, d)")
    steps = np.sum(np.diff(P, axis=0) ** 2, axis=1)
    if steps.sum() == 0:
        raise ValueError("points: no length")
    s = np.concatenate([[0.0], np.cumsum(steps)])
    return s / s[-1]

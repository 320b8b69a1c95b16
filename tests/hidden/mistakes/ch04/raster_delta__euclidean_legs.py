"""Takes d as the longest leg of the control polygon, measured with the Euclidean length."""
import numpy as np


def raster_delta(points):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, 2)")
    n = len(p) - 1
    if n == 0:
        return 1.0
    d = np.linalg.norm(np.diff(p, axis=0), axis=1).max()
    return 1.0 / max(n * d, 1.0)

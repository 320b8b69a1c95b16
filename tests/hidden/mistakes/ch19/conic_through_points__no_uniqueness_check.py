"""Returns a null vector even when the points do not fix one conic (four on a line, or two equal)."""
import numpy as np


def _points(points):
    p = np.array(points, dtype=float)
    if p.shape != (5, 2) or not np.all(np.isfinite(p)):
        raise ValueError("points: expected shape (5, 2)")
    return p


def _rows(p):
    x, y = p.T
    return np.column_stack([x * x, x * y, y * y, x, y, np.ones(5)])


def _layout(v):
    c = np.zeros((3, 3))
    c[2, 0], c[1, 1], c[0, 2], c[1, 0], c[0, 1], c[0, 0] = v
    return c / c.flat[np.argmax(np.abs(c))]


def conic_through_points(points):
    m = _rows(_points(points))
    _, s, vt = np.linalg.svd(m)
    return _layout(vt[-1])

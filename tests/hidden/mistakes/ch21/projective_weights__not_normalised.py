"""Returns the raw determinants, not divided by w00."""
import numpy as np


def _quad(quad):
    q = np.array(quad, dtype=float)
    if q.shape != (2, 2, 2) or not np.all(np.isfinite(q)):
        raise ValueError("quad: expected shape (2, 2, 2)")
    corners = q.reshape(4, 2)
    size = np.linalg.norm(corners.max(axis=0) - corners.min(axis=0))
    for a in range(4):
        for b in range(a + 1, 4):
            if np.linalg.norm(corners[a] - corners[b]) <= 1e-12 * size:
                raise ValueError("quad: two corners coincide")
    if np.abs(_dets(q)).max() <= 1e-12 * size**2:
        raise ValueError("quad: the corners are collinear")
    return q


def _det(a, b, c):
    return float(np.linalg.det(np.array([[*a, 1.0], [*b, 1.0], [*c, 1.0]])))


def _dets(q):
    """[[C00, C01], [C10, C11]]."""
    return np.array([[_det(q[0, 1], q[0, 0], q[1, 0]), _det(q[1, 1], q[0, 1], q[0, 0])],
                     [_det(q[0, 0], q[1, 0], q[1, 1]), _det(q[1, 0], q[1, 1], q[0, 1])]])


def projective_weights(quad):
    q = _quad(quad)
    c = _dets(q)
    size = np.linalg.norm(q.reshape(4, 2).max(axis=0) - q.reshape(4, 2).min(axis=0))
    if np.abs(c).min() <= 1e-12 * size**2:
        raise ValueError("quad: three corners are collinear")
    w = np.array([[c[1, 1], c[1, 0]], [c[0, 1], c[0, 0]]])
    return -w

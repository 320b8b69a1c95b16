"""Returns (At, As): the axis of the t-pencil first."""
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


def _h(p):
    return np.array([p[0], p[1], 1.0])


def pencil_axes(quad):
    q = _quad(quad)
    a_s = np.cross(np.cross(_h(q[0, 0]), _h(q[0, 1])), np.cross(_h(q[1, 0]), _h(q[1, 1])))
    a_t = np.cross(np.cross(_h(q[0, 0]), _h(q[1, 0])), np.cross(_h(q[0, 1]), _h(q[1, 1])))
    return a_t, a_s

"""Reads quad[i][j] as the corner at s = j, t = i: s and t come out exchanged."""
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


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _roots(a, b, c, size):
    if a == 0:
        if abs(b) <= 1e-12 * size:
            if abs(c) <= 1e-12 * size:
                raise ValueError("point: infinitely many pre-images")
            return []
        return [-c / b]
    d = b * b - 4 * a * c
    if abs(d) <= 1e-14 * (b * b + abs(4 * a * c)):
        return [-b / (2 * a)]
    if d < 0:
        return []
    q = -0.5 * (b + np.copysign(np.sqrt(d), b))
    return [q / a, c / q]


def _solve(h, e, f, g, size):
    a = _cross(e, g)
    if abs(a) <= 1e-12 * np.linalg.norm(e) * np.linalg.norm(g):
        a = 0.0
    result = []
    for u in _roots(a, _cross(e, f) - _cross(h, g), -_cross(h, f), size):
        d = f + g * u
        result.append((u, float((h - e * u) @ d / (d @ d))))
    return result


def bilinear_inverse(quad, point):
    q = _quad(quad).transpose(1, 0, 2)
    x = np.array(point, dtype=float)
    if x.shape != (2,) or not np.all(np.isfinite(x)):
        raise ValueError("point: expected shape (2,)")
    e, f = q[1, 0] - q[0, 0], q[0, 1] - q[0, 0]
    g = q[0, 0] - q[1, 0] - q[0, 1] + q[1, 1]
    h = x - q[0, 0]
    size = np.linalg.norm(q.reshape(4, 2).max(axis=0) - q.reshape(4, 2).min(axis=0)) ** 2 + np.abs(h).max() ** 2
    sin_s = abs(_cross(e, g)) / max(np.linalg.norm(e) * np.linalg.norm(g), 1e-300)
    sin_t = abs(_cross(f, g)) / max(np.linalg.norm(f) * np.linalg.norm(g), 1e-300)
    if sin_s <= sin_t:
        pairs = _solve(h, e, f, g, size)
    else:
        pairs = [(s, t) for t, s in _solve(h, f, e, g, size)]
    return np.array(sorted(pairs), dtype=float).reshape(-1, 2)

"""Divides the axes by W first: an axis at infinity (parallel edges) breaks."""
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


def _h(p, w=1.0):
    return w * np.array([p[0], p[1], 1.0])


def _unit(v):
    return v / np.linalg.norm(v)


def _form(axis, a, b):
    l0, l1 = np.cross(axis, a), np.cross(axis, b)
    return l0, l1, min(np.linalg.norm(l0), np.linalg.norm(l1)) / max(np.linalg.norm(a), np.linalg.norm(b))


def birational_inverse(quad, weights, points):
    q = _quad(quad)
    w = np.array(weights, dtype=float)
    if w.shape != (2, 2) or not np.all(np.isfinite(w)) or not np.any(w):
        raise ValueError("weights: expected shape (2, 2)")
    c = _dets(q)
    size = np.linalg.norm(q.reshape(4, 2).max(axis=0) - q.reshape(4, 2).min(axis=0))
    left, right = w[0, 0] * w[1, 1] * c[1, 0] * c[0, 1], w[1, 0] * w[0, 1] * c[0, 0] * c[1, 1]
    if abs(left - right) > 1e-9 * (abs(left) + abs(right)) + 1e-12 * np.abs(w).max() ** 2 * size**4:
        raise ValueError("weights: not birational")
    p = np.array(points, dtype=float)
    single = p.shape == (2,)
    p = np.atleast_2d(p)
    if p.ndim != 2 or p.shape[1] != 2 or not np.all(np.isfinite(p)):
        raise ValueError("points: expected (2,) or (k, 2)")
    qt = {(i, j): _h(q[i, j], w[i, j]) for i in (0, 1) for j in (0, 1)}
    a_s = np.cross(np.cross(_h(q[0, 0]), _h(q[0, 1])), np.cross(_h(q[1, 0]), _h(q[1, 1])))
    a_t = np.cross(np.cross(_h(q[0, 0]), _h(q[1, 0])), np.cross(_h(q[0, 1]), _h(q[1, 1])))
    a_s, a_t = a_s / a_s[2], a_t / a_t[2]
    a_s, a_t = _unit(a_s), _unit(a_t)
    s_forms = [_form(a_s, qt[0, 1], qt[1, 1]), _form(a_s, qt[0, 0], qt[1, 0])]
    t_forms = [_form(a_t, qt[1, 0], qt[1, 1]), _form(a_t, qt[0, 0], qt[0, 1])]
    hp = np.column_stack([p, np.ones(len(p))])
    out = []
    for forms in (s_forms, t_forms):
        l0, l1, _ = max(forms, key=lambda f: f[2])
        num, den = hp @ l0, hp @ (l0 - l1)
        if np.any(np.abs(den) <= 1e-12 * (np.linalg.norm(l0) + np.linalg.norm(l1)) * np.linalg.norm(hp, axis=1)):
            raise ValueError("points: a pre-image at infinity")
        out.append(num / den)
    result = np.column_stack(out)
    return result[0] if single else result

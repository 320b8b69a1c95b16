"""Multiplies the weights in twice: w_i² P_i in the numerator (as if P_i were already homogeneous)."""
import numpy as np


def _mesh(mesh):
    if not isinstance(mesh, dict) or "vertices" not in mesh or "edges" not in mesh:
        raise TypeError("mesh: expected a dict with 'vertices' and 'edges'")
    if set(mesh) - {"vertices", "edges", "frame"}:
        raise ValueError("mesh: unknown keys")
    V = np.array(mesh["vertices"], dtype=float)
    if V.ndim != 2 or V.shape[1] != 2 or len(V) == 0 or not np.all(np.isfinite(V)):
        raise ValueError("mesh: vertices must have shape (V, 2)")
    if len(np.unique(V, axis=0)) != len(V):
        raise ValueError("mesh: two vertices at the same place")
    E = np.array(mesh["edges"], dtype=float).reshape(-1, 2) if len(mesh["edges"]) else np.zeros((0, 2))
    if np.any(E != np.round(E)) or np.any(E < 0) or np.any(E >= len(V)):
        raise ValueError("mesh: bad edge indices")
    E = E.astype(int)
    a, b = V[E[:, 0]], V[E[:, 1]]
    if np.any(E[:, 0] == E[:, 1]) or np.any((a[:, 0] != b[:, 0]) & (a[:, 1] != b[:, 1])):
        raise ValueError("mesh: an edge is neither horizontal nor vertical")
    if mesh.get("frame") is None:
        lo, hi = V.min(axis=0), V.max(axis=0)
        F = np.stack([lo - 2, lo - 1, hi + 1, hi + 2], axis=1)
    else:
        F = np.array(mesh["frame"], dtype=float)
        if F.shape != (2, 4):
            raise ValueError("mesh: frame must be (2, 4)")
    return V, E, F


def _crossings(V, E, axis, value):
    # positions (along the other axis) of edges perpendicular to the line {x_axis = value} that meet it
    a, b = V[E[:, 0]], V[E[:, 1]]
    perpendicular = a[:, 1 - axis] == b[:, 1 - axis]
    lo, hi = np.minimum(a[:, axis], b[:, axis]), np.maximum(a[:, axis], b[:, axis])
    meets = perpendicular & (lo <= value) & (value <= hi)
    return np.unique(a[meets, 1 - axis])


def infer_knot_vectors(mesh, vertex):
    V, E, F = _mesh(mesh)
    if isinstance(vertex, bool) or not isinstance(vertex, (int, np.integer)):
        raise TypeError("vertex: expected an integer")
    if not 0 <= vertex < len(V):
        raise ValueError("vertex: out of range")
    s, t = V[vertex]
    out = []
    for axis, centre, other in ((0, s, t), (1, t, s)):
        hits = _crossings(V, E, 1 - axis, other)
        up = list(hits[hits > centre]) + list(F[axis, 2:])
        down = list(hits[hits < centre][::-1]) + [F[axis, 1], F[axis, 0]]
        out.append(np.array([down[1], down[0], centre, up[0], up[1]]))
    return out[0], out[1]


def _cubic(k, x):
    # cubic B-spline basis function on the five knots k, by the Cox-de Boor recursion (0/0 taken as 0)
    x = np.asarray(x, dtype=float)
    N = [((k[i] <= x) & (x < k[i + 1])).astype(float) for i in range(4)]
    for p in (1, 2, 3):
        new = []
        for i in range(4 - p):
            left = (x - k[i]) / (k[i + p] - k[i]) * N[i] if k[i + p] > k[i] else 0 * x
            right = (k[i + p + 1] - x) / (k[i + p + 1] - k[i + 1]) * N[i + 1] if k[i + p + 1] > k[i + 1] else 0 * x
            new.append(left + right)
        N = new
    return N[0]


def _inputs(mesh, points, s, t, weights):
    V, E, F = _mesh(mesh)
    P = np.array(points, dtype=float)
    if P.ndim != 2 or len(P) != len(V) or not np.all(np.isfinite(P)):
        raise ValueError("points: one row per vertex")
    w = np.ones(len(V)) if weights is None else np.array(weights, dtype=float)
    if w.shape != (len(V),) or np.any(w == 0) or not np.all(np.isfinite(w)):
        raise ValueError("weights: one nonzero weight per vertex")
    ss, tt = np.array(s, dtype=float), np.array(t, dtype=float)
    if ss.ndim > 1 or tt.ndim > 1 or not (np.all(np.isfinite(ss)) and np.all(np.isfinite(tt))):
        raise ValueError("s, t: numbers or 1-D arrays")
    scalar = ss.ndim == 0 and tt.ndim == 0
    try:
        ss, tt = np.broadcast_arrays(np.atleast_1d(ss), np.atleast_1d(tt))
    except ValueError:
        raise ValueError("s, t: do not broadcast") from None
    lo, hi = V.min(axis=0), V.max(axis=0)
    if np.any((ss < lo[0]) | (ss > hi[0]) | (tt < lo[1]) | (tt > hi[1])):
        raise ValueError("s, t: outside the domain")
    return V, P, w, ss, tt, scalar


def tspline_point(mesh, points, s, t, weights=None):
    V, P, w, ss, tt, scalar = _inputs(mesh, points, s, t, weights)
    num = np.zeros((len(ss), P.shape[1]))
    den = np.zeros(len(ss))
    for i in range(len(V)):
        sk, tk = infer_knot_vectors(mesh, i)
        B = _cubic(sk, ss) * _cubic(tk, tt)
        num += (w[i] * w[i] * B)[:, None] * P[i]
        den += w[i] * B
    if np.any(den == 0):
        raise ValueError("weights: the denominator vanishes")
    out = num / den[:, None]
    return out[0] if scalar else out

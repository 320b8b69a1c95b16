"""Ignores the mesh's frame: always unit knot intervals beyond the mesh."""
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
    if True:  # the given frame is ignored
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

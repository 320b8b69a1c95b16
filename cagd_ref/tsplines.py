"""Cubic T-splines: T-meshes, knot vectors by Rule 1, the T-spline equation and local refinement. Notes §15.7.

A T-mesh is plain data, a dict, so that it prints, saves and goes to a graded function as it is::

    mesh = {
        "vertices": [(0, 0), (1, 0), ...],   # (V, 2): the knot coordinates (s, t) of the control points
        "edges": [(0, 1), (0, 4), ...],      # (E, 2): pairs of vertex indices; an edge joins two vertices of
                                             #   one row (equal t) or of one column (equal s)
        "frame": [[-2, -1, 9, 10],           # optional (2, 4): the two knots beyond each side of the mesh,
                  [-2, -1, 8, 9]],           #   s then t, for rays that leave it (default: unit intervals)
    }

`tmesh` builds and checks one (and can join the consecutive vertices of every row and column for you).
Control point i sits at the knot coordinates vertices[i]; its blending function is
B_i(s, t) = N[s_i0..s_i4](s) · N[t_i0..t_i4](t), a product of two cubic B-spline basis functions
whose knot vectors Rule 1 reads off the mesh (`infer_knot_vectors`): walk from (s_i2, t_i2) to the
right and take the s values of the first two vertical edges the ray meets, then to the left, up and
down. The surface is P(s, t) = Σ w_i P_i B_i / Σ w_i B_i, computed as the projection of
Σ H_i B_i with H_i = w_i (P_i, 1) (`tspline_point`). The B_i need not sum to one.

Local refinement (`local_refinement`) inserts control points and keeps the surface: blending
functions are split by knot insertion (`refine_blending_function`, (15.14)-(15.17)), carried as
records (knot vectors and a homogeneous point) and summed where they meet, until every record agrees
with Rule 1 on the refined mesh (`violations`). The new control points are P~_j = Σ_i c_ji P_i (15.23).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from ._validation import _describe, as_count, as_float_array, as_parameter, as_points, as_weights
from .bezier import from_homogeneous, to_homogeneous
from .knot_intervals import cubic_basis_from_intervals, refine_basis
from .surfaces import _pairs

__all__ = [
    "tmesh",
    "mesh_domain",
    "frame_knots",
    "knot_coordinates",
    "mesh_intervals",
    "infer_knot_vectors",
    "all_knot_vectors",
    "cubic_blending",
    "blending_function",
    "blending_values",
    "tspline_point",
    "refine_blending_function",
    "blending_records",
    "violations",
    "local_refinement",
]

MESH_KEYS = ("vertices", "edges", "frame")


# --------------------------------------------------------------------------- the T-mesh as data


def _as_vertices(vertices, name: str) -> np.ndarray:
    verts = as_float_array(vertices, name)
    if verts.ndim != 2 or verts.shape[1] != 2 or len(verts) == 0:
        raise ValueError(f"{name}: expected knot coordinates of shape (V, 2), V >= 1, got shape {verts.shape}")
    _, first, counts = np.unique(verts, axis=0, return_index=True, return_counts=True)
    if np.any(counts > 1):
        twice = verts[first[counts > 1][0]].tolist()
        raise ValueError(f"{name}: two vertices at the same knot coordinates {twice}")
    return verts


def _as_edges(edges, count: int, verts: np.ndarray, name: str) -> np.ndarray:
    if edges is None or isinstance(edges, (str, bytes, Mapping)):
        raise TypeError(f"{name}: expected pairs of vertex indices, got {_describe(edges)}")
    try:
        array = np.array(edges, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name}: expected pairs of vertex indices, got {_describe(edges)}") from None
    if array.size == 0:
        return np.zeros((0, 2), dtype=int)
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"{name}: expected pairs of vertex indices, shape (E, 2), got shape {array.shape}")
    if not np.all(np.isfinite(array)) or np.any(array != np.round(array)):
        raise ValueError(f"{name}: vertex indices must be whole numbers, got {_describe(edges)}")
    pairs = array.astype(int)
    if pairs.min() < 0 or pairs.max() >= count:
        raise ValueError(f"{name}: vertex indices must lie in 0..{count - 1}, got {pairs.tolist()}")
    a, b = verts[pairs[:, 0]], verts[pairs[:, 1]]
    if np.any(pairs[:, 0] == pairs[:, 1]):
        raise ValueError(f"{name}: an edge joins a vertex to itself")
    slanted = (a[:, 0] != b[:, 0]) & (a[:, 1] != b[:, 1])
    if np.any(slanted):
        k = int(np.flatnonzero(slanted)[0])
        raise ValueError(f"{name}: edge {pairs[k].tolist()} is neither horizontal (equal t) nor vertical (equal s)")
    return pairs


def _unit_frame(verts: np.ndarray) -> np.ndarray:
    low, high = verts.min(axis=0), verts.max(axis=0)
    return np.stack([low - 2, low - 1, high + 1, high + 2], axis=1)


def _as_frame(frame, verts: np.ndarray, name: str) -> np.ndarray:
    if frame is None:
        return _unit_frame(verts)
    f = as_float_array(frame, name)
    if f.shape != (2, 4):
        raise ValueError(f"{name}: expected [[s_-2, s_-1, s_+1, s_+2], [t_-2, t_-1, t_+1, t_+2]], got shape {f.shape}")
    low, high = verts.min(axis=0), verts.max(axis=0)
    for axis, letter in enumerate("st"):
        a, b, c, d = f[axis]
        if not (a < b < low[axis] and high[axis] < c < d):
            raise ValueError(
                f"{name}: the {letter} frame knots must satisfy {letter}_-2 < {letter}_-1 < {low[axis]:g} (the "
                f"mesh's smallest {letter}) and {high[axis]:g} < {letter}_+1 < {letter}_+2, got {f[axis].tolist()}"
            )
    return f


def _parts(mesh, name: str = "mesh") -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Checked (vertices (V, 2), edges (E, 2) int, frame (2, 4)) of a T-mesh dict; fresh arrays."""
    if not isinstance(mesh, Mapping):
        raise TypeError(f"{name}: expected a dict with 'vertices', 'edges' and optionally 'frame', got "
                        f"{_describe(mesh)}")
    missing = [key for key in ("vertices", "edges") if key not in mesh]
    unknown = [key for key in mesh if key not in MESH_KEYS]
    if missing or unknown:
        raise ValueError(f"{name}: expected the keys 'vertices', 'edges' (and optionally 'frame'); missing "
                         f"{missing}, unknown {unknown}")
    verts = _as_vertices(mesh["vertices"], f"{name}['vertices']")
    edges = _as_edges(mesh["edges"], len(verts), verts, f"{name}['edges']")
    frame = _as_frame(mesh.get("frame"), verts, f"{name}['frame']")
    return verts, edges, frame


def _joined_consecutive(verts: np.ndarray, skip) -> list[tuple[int, int]]:
    skipped = {frozenset(pair) for pair in skip}
    edges = []
    for axis in (1, 0):  # rows (equal t), then columns (equal s)
        for value in np.unique(verts[:, axis]):
            on_line = np.flatnonzero(verts[:, axis] == value)
            ordered = on_line[np.argsort(verts[on_line, 1 - axis])]
            for a, b in zip(ordered[:-1], ordered[1:]):
                if frozenset((int(a), int(b))) not in skipped:
                    edges.append((int(a), int(b)))
    return edges


def tmesh(vertices, edges=None, frame=None, skip=()) -> dict:
    """A checked T-mesh dict {"vertices", "edges", "frame"} of plain lists. Notes §15.7.

    vertices: (V, 2) knot coordinates (s, t), all different. edges: (E, 2) vertex-index pairs, each
    joining two vertices of a row or of a column; None joins the consecutive vertices of every row and
    every column, except the pairs listed in `skip`. frame: (2, 4) knots beyond the mesh
    [[s_-2, s_-1, s_+1, s_+2], [t_-2, t_-1, t_+1, t_+2]]; None gives unit intervals beyond the
    smallest and largest s and t. Raises ValueError/TypeError for anything else.
    """
    verts = _as_vertices(vertices, "vertices")
    if edges is None:
        edges = _joined_consecutive(verts, _as_edges(skip, len(verts), verts, "skip").tolist())
    pairs = _as_edges(edges, len(verts), verts, "edges")
    f = _as_frame(frame, verts, "frame")
    return {"vertices": verts.tolist(), "edges": pairs.tolist(), "frame": f.tolist()}


def mesh_domain(mesh) -> tuple[tuple[float, float], tuple[float, float]]:
    """The parameter box ((s_min, s_max), (t_min, t_max)) spanned by the vertices: where the T-spline lives."""
    verts, _, _ = _parts(mesh)
    low, high = verts.min(axis=0), verts.max(axis=0)
    return (float(low[0]), float(high[0])), (float(low[1]), float(high[1]))


def frame_knots(mesh) -> np.ndarray:
    """The frame knots (2, 4) of a mesh: its own, or unit intervals beyond each side."""
    return _parts(mesh)[2]


# --------------------------------------------------------------------------- knot intervals and coordinates


def _as_oriented(edges, intervals, name: str, other: str) -> tuple[np.ndarray, np.ndarray]:
    d = as_float_array(intervals, other).reshape(-1)
    pairs = np.zeros((0, 2), dtype=int) if np.size(edges) == 0 else np.asarray(edges)
    if pairs.ndim != 2 or pairs.shape[1] != 2 or pairs.dtype.kind not in "iu":
        raise ValueError(f"{name}: expected integer vertex-index pairs of shape (E, 2), got {_describe(edges)}")
    if len(d) != len(pairs):
        raise ValueError(f"{other}: expected one knot interval per edge ({len(pairs)}), got {len(d)}")
    if np.any(d < 0):
        raise ValueError(f"{other}: knot intervals must be non-negative, got {d.tolist()}")
    return pairs, d


def knot_coordinates(h_edges, h_intervals, v_edges, v_intervals, origin: int = 0) -> np.ndarray:
    """Knot coordinates (V, 2) of a T-mesh given in knot-interval form, with vertex `origin` at (0, 0). Notes §15.7.

    h_edges: (Eh, 2) pairs (left vertex, right vertex) with the knot intervals h_intervals (Eh,);
    v_edges: (Ev, 2) pairs (lower vertex, upper vertex) with v_intervals (Ev,). Walking an edge adds its
    interval to s (horizontal) or t (vertical). T-mesh rule 1 (opposite sides of every face have equal
    interval sums) is exactly what makes the walk independent of the path: a ValueError names the first
    edge where two paths disagree, or the vertices no edge reaches.

    >>> knot_coordinates([(0, 1), (2, 3)], [2, 2], [(0, 2), (1, 3)], [1, 1])   # a 2 x 2 grid
    array([[0., 0.],
           [2., 0.],
           [0., 1.],
           [2., 1.]])
    """
    h, dh = _as_oriented(h_edges, h_intervals, "h_edges", "h_intervals")
    v, dv = _as_oriented(v_edges, v_intervals, "v_edges", "v_intervals")
    count = int(max(h.max(initial=-1), v.max(initial=-1))) + 1
    start = as_count(origin, "origin")
    if start >= max(count, 1):
        raise ValueError(f"origin: expected a vertex index below {count}, got {start}")
    count = max(count, start + 1)
    if h.size and h.min() < 0 or v.size and v.min() < 0:
        raise ValueError("h_edges: vertex indices must be non-negative")
    # steps[k] = (from, to, ds, dt) in both directions
    steps = [(a, b, d, 0.0) for (a, b), d in zip(h.tolist(), dh)]
    steps += [(a, b, 0.0, d) for (a, b), d in zip(v.tolist(), dv)]
    neighbours: dict[int, list] = {}
    for a, b, ds, dt in steps:
        neighbours.setdefault(a, []).append((b, ds, dt))
        neighbours.setdefault(b, []).append((a, -ds, -dt))
    coords = np.full((count, 2), np.nan)
    coords[start] = 0.0
    queue = [start]
    while queue:
        here = queue.pop(0)
        for there, ds, dt in neighbours.get(here, []):
            target = coords[here] + (ds, dt)
            if np.isnan(coords[there, 0]):
                coords[there] = target
                queue.append(there)
            elif not np.allclose(coords[there], target, rtol=1e-12, atol=1e-12):
                raise ValueError(
                    f"h_intervals: the intervals violate T-mesh rule 1: vertex {there} is reached at "
                    f"{coords[there].tolist()} and at {target.tolist()} (opposite sides of a face differ)"
                )
    unreached = np.flatnonzero(np.isnan(coords[:, 0]))
    if unreached.size:
        raise ValueError(f"h_edges: vertices {unreached.tolist()} are not connected to the origin")
    return coords


def mesh_intervals(mesh) -> dict:
    """The knot-interval form of a mesh: {"h_edges" (left, right), "h_intervals", "v_edges" (lower, upper),
    "v_intervals"}, the inverse of `knot_coordinates`. Notes §15.7, Fig. 15.17a."""
    verts, edges, _ = _parts(mesh)
    a, b = verts[edges[:, 0]], verts[edges[:, 1]]
    horizontal = a[:, 1] == b[:, 1]
    swap = np.where(horizontal, a[:, 0] > b[:, 0], a[:, 1] > b[:, 1])
    oriented = np.where(swap[:, None], edges[:, ::-1], edges)
    lengths = np.abs(b - a).sum(axis=1)
    return {"h_edges": oriented[horizontal], "h_intervals": lengths[horizontal],
            "v_edges": oriented[~horizontal], "v_intervals": lengths[~horizontal]}


# --------------------------------------------------------------------------- Rule 1


def _hits(verts: np.ndarray, edges: np.ndarray, axis: int, value: float) -> np.ndarray:
    """Sorted distinct positions where the edges across direction `axis` meet the line {x_axis = value}.

    axis 1: the line t = value, met by vertical edges (their s values); axis 0: s = value, met by
    horizontal edges (their t values). Segments are closed: an edge that ends on the line counts.
    """
    a, b = verts[edges[:, 0]], verts[edges[:, 1]]
    across = a[:, 1 - axis] == b[:, 1 - axis]  # vertical edges for axis 1 (equal s)
    low, high = np.minimum(a[:, axis], b[:, axis]), np.maximum(a[:, axis], b[:, axis])
    meets = across & (low <= value) & (value <= high)
    return np.unique(a[meets, 1 - axis])


def _rule1(verts: np.ndarray, edges: np.ndarray, frame: np.ndarray, s: float, t: float):
    knots = []
    for axis, centre, other in ((0, s, t), (1, t, s)):
        hits = _hits(verts, edges, 1 - axis, other)
        up = np.concatenate([hits[hits > centre], frame[axis, 2:]])[:2]
        down = np.concatenate([hits[hits < centre][::-1], frame[axis, 1::-1]])[:2]
        knots.append(np.array([down[1], down[0], centre, up[0], up[1]]))
    return knots[0], knots[1]


def infer_knot_vectors(mesh, vertex) -> tuple[np.ndarray, np.ndarray]:
    """The knot vectors (s_knots (5,), t_knots (5,)) of a vertex's blending function by Rule 1. Notes §15.7.

    mesh: a T-mesh dict (see the module: "vertices" (V, 2), "edges" (E, 2), optional "frame" (2, 4));
    vertex: the index of the control point. With (s_2, t_2) = vertices[vertex], s_3 and s_4 are the s
    values of the first two vertical edges met by the ray (s_2 + α, t_2), α > 0; s_1 and s_0 those met
    by (s_2 - α, t_2); t_3, t_4 and t_1, t_0 likewise from the horizontal edges met going up and down.
    An edge that merely ends on the ray (a T-junction) is met; the vertex's own edges are not. A ray that
    leaves the mesh takes the frame knots on that side. Both vectors come back increasing.

    The numerical example of Fig. 15.17 (the mesh is `notes_example("15.tmesh")`), control point P10 at (2, 3):

    >>> from cagd_course.examples import notes_example
    >>> mesh = notes_example("15.tmesh").inputs["mesh"]
    >>> s_knots, t_knots = infer_knot_vectors(mesh, 10)
    >>> s_knots.tolist(), t_knots.tolist()
    ([0.0, 1.0, 2.0, 5.0, 7.0], [0.0, 1.0, 3.0, 5.0, 6.0])
    >>> [v.tolist() for v in infer_knot_vectors(mesh, 0)]      # P0: the frame supplies s_0, s_1, t_0, t_1
    [[-2.0, -1.0, 0.0, 1.0, 7.0], [-2.0, -1.0, 0.0, 1.0, 6.0]]
    """
    verts, edges, frame = _parts(mesh)
    index = as_count(vertex, "vertex")
    if index >= len(verts):
        raise ValueError(f"vertex: expected an index below {len(verts)} (the number of vertices), got {index}")
    return _rule1(verts, edges, frame, *verts[index])


def all_knot_vectors(mesh) -> tuple[np.ndarray, np.ndarray]:
    """Rule 1 for every vertex: s_knots (V, 5) and t_knots (V, 5), row i for control point i. Notes §15.7."""
    verts, edges, frame = _parts(mesh)
    rows = [_rule1(verts, edges, frame, s, t) for s, t in verts]
    return np.array([r[0] for r in rows]), np.array([r[1] for r in rows])


# --------------------------------------------------------------------------- blending functions


def _as_knot_vector(knots, name: str) -> np.ndarray:
    k = as_float_array(knots, name)
    if k.shape != (5,) or np.any(np.diff(k) < 0) or not k[0] < k[4]:
        raise ValueError(f"{name}: expected five non-decreasing knots, the first below the last, got "
                         f"{_describe(knots)}")
    return k


def _cubic(knots: np.ndarray, x: np.ndarray) -> np.ndarray:
    return cubic_basis_from_intervals(np.diff(knots), x - knots[0])


def cubic_blending(knots, x):
    """The cubic B-spline basis function N[k_0, ..., k_4](x) on five knots (0 outside [k_0, k_4]). Notes (15.9).

    A number gives a float, k numbers (k,). Evaluated piece by piece (`knot_intervals.cubic_basis_from_intervals`).
    """
    k = _as_knot_vector(knots, "knots")
    xs, scalar = as_parameter(x, "x")
    values = _cubic(k, xs)
    return float(values[0]) if scalar else values


def blending_function(s_knots, t_knots, s, t):
    """B(s, t) = N[s_knots](s) · N[t_knots](t), a T-spline blending function. Notes (15.9).

    s, t: numbers or 1-D arrays that broadcast; two numbers give a float, k pairs (k,).
    """
    sk, tk = _as_knot_vector(s_knots, "s_knots"), _as_knot_vector(t_knots, "t_knots")
    ss, ts, scalar = _pairs(s, t)
    values = _cubic(sk, ss) * _cubic(tk, ts)
    return float(values[0]) if scalar else values


def _basis_matrix(s_knots: np.ndarray, t_knots: np.ndarray, ss: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """(k, V): B_i at each of the k pairs, one column per blending function."""
    if len(ss) == 0:
        return np.zeros((0, len(s_knots)))
    return np.stack([_cubic(sk, ss) * _cubic(tk, ts) for sk, tk in zip(s_knots, t_knots)], axis=1)


def blending_values(mesh, s, t) -> np.ndarray:
    """All blending functions of a mesh at (s, t): (V,) for two numbers, (k, V) for k pairs. Notes (15.13).

    The values do not sum to one in general (the numerical example: 12869/12600 at (3, 4)).
    """
    s_knots, t_knots = all_knot_vectors(mesh)
    ss, ts, scalar = _pairs(s, t)
    values = _basis_matrix(s_knots, t_knots, ss, ts)
    return values[0] if scalar else values


def tspline_point(mesh, points, s, t, weights=None) -> np.ndarray:
    """A point of the T-spline surface, P(s, t) = Σ w_i P_i B_i(s, t) / Σ w_i B_i(s, t). Notes (15.7)-(15.9).

    mesh: a T-mesh dict (module docstring); points: (V, d), row i the control point at vertices[i];
    weights: (V,) nonzero, or None for all 1. B_i = N[s_i](s) N[t_i](t) with the knot vectors of Rule 1
    (`infer_knot_vectors`). The sum is the projection of Σ H_i B_i, H_i = w_i (P_i, 1): the weight
    multiplies once, in the numerator and in the denominator. s, t: numbers or 1-D arrays that
    broadcast, inside the box of the vertices ((s_min, s_max), (t_min, t_max)); two numbers give (d,),
    k pairs (k, d). Raises ValueError outside that box and where Σ w_i B_i = 0.

    The numerical example of Fig. 15.17 with control points P_i = (s_i, t_i, i): at (3, 4) the blending
    functions sum to 12869/12600, not 1, so the denominator is needed even with unit weights.

    >>> from cagd_course.examples import notes_example
    >>> mesh = notes_example("15.tmesh").inputs["mesh"]
    >>> points = [(s, t, i) for i, (s, t) in enumerate(mesh["vertices"])]
    >>> tspline_point(mesh, points, 3, 4).round(6)
    array([ 2.813088,  4.196936, 13.069668])
    >>> tspline_point(mesh, points, [3, 0], [4, 0], [2] * 28).shape     # k pairs: (k, d); equal weights cancel
    (2, 3)
    """
    verts, edges, frame = _parts(mesh)
    pts = as_points(points, "points")
    if len(pts) != len(verts):
        raise ValueError(f"points: expected one control point per vertex ({len(verts)}), got {len(pts)}")
    w = np.ones(len(pts)) if weights is None else as_weights(weights, len(pts))
    ss, ts, scalar = _pairs(s, t)
    low, high = verts.min(axis=0), verts.max(axis=0)
    outside = (ss < low[0]) | (ss > high[0]) | (ts < low[1]) | (ts > high[1])
    if np.any(outside):
        k = int(np.flatnonzero(outside)[0])
        raise ValueError(f"s: ({ss[k]:g}, {ts[k]:g}) lies outside the domain [{low[0]:g}, {high[0]:g}] × "
                         f"[{low[1]:g}, {high[1]:g}] of the T-mesh")
    rows = [_rule1(verts, edges, frame, a, b) for a, b in verts]
    basis = _basis_matrix(np.array([r[0] for r in rows]), np.array([r[1] for r in rows]), ss, ts)
    homogeneous = basis @ to_homogeneous(pts, w)
    scale = np.abs(basis) @ np.abs(w)
    if np.any(np.abs(homogeneous[:, -1]) <= 1e-13 * scale) or np.any(scale == 0):
        raise ValueError("weights: the denominator Σ w_i B_i(s, t) vanishes at a requested point")
    result = homogeneous[:, :-1] / homogeneous[:, -1:]
    return result[0] if scalar else result


# --------------------------------------------------------------------------- refinement of blending functions


def refine_blending_function(s_knots, t_knots, knot, direction: str = "s") -> list:
    """Insert one knot into B = N[s_knots] N[t_knots]: [(c, s_knots, t_knots), ...] summing to B. Notes (15.14)-(15.17).

    direction "s" or "t" says which knot vector gets `knot`. Inside the support, k in (k_0, k_4), B splits
    into c N[first five of the six knots] + d N[last five] with c = min(1, (k - k_0)/(k_3 - k_0)) and
    d = min(1, (k_4 - k)/(k_4 - k_1)) (`knot_intervals.refine_basis`); outside it, B is returned
    unchanged as [(1.0, s_knots, t_knots)].

    >>> [(c, s.tolist()) for c, s, _ in refine_blending_function([0, 1, 2, 5, 7], [0, 1, 2, 3, 4], 3)]
    [(0.6, [0.0, 1.0, 2.0, 3.0, 5.0]), (0.6666666666666666, [1.0, 2.0, 3.0, 5.0, 7.0])]
    """
    sk, tk = _as_knot_vector(s_knots, "s_knots"), _as_knot_vector(t_knots, "t_knots")
    value = as_float_array(knot, "knot")
    if value.ndim != 0:
        raise ValueError(f"knot: expected a single number, got shape {value.shape}")
    if direction not in ("s", "t"):
        raise ValueError(f"direction: expected 's' or 't', got {direction!r}")
    k = float(value)
    local = sk if direction == "s" else tk
    if not local[0] < k < local[4]:
        return [(1.0, sk, tk)]
    pieces = []
    for coefficient, refined in refine_basis(local, k):
        if coefficient != 0:
            pieces.append((float(coefficient), refined, tk.copy()) if direction == "s" else
                          (float(coefficient), sk.copy(), refined))
    return pieces


# --------------------------------------------------------------------------- local refinement


def blending_records(mesh, points, weights=None) -> list:
    """One record (s_knots (5,), t_knots (5,), H (d+1,)) per vertex: Rule-1 knots, H_i = w_i (P_i, 1). Notes §15.7.

    The state local refinement works on: a T-spline is Π(Σ H B) summed over its records.
    """
    verts, _, _ = _parts(mesh)
    pts = as_points(points, "points")
    if len(pts) != len(verts):
        raise ValueError(f"points: expected one control point per vertex ({len(verts)}), got {len(pts)}")
    w = np.ones(len(pts)) if weights is None else as_weights(weights, len(pts))
    s_knots, t_knots = all_knot_vectors(mesh)
    return [(sk, tk, h) for sk, tk, h in zip(s_knots, t_knots, to_homogeneous(pts, w))]


def _record_violation(record, rule) -> tuple[int, str, float] | None:
    """(kind, direction, knot): 1 with a missing knot to insert, 2 with an extra knot; None if it obeys Rule 1."""
    sk, tk = record[0], record[1]
    for direction, have, want in (("s", sk, rule[0]), ("t", tk, rule[1])):
        for x in want:
            if have[0] < x < have[4] and x not in have:
                return 1, direction, float(x)
    for direction, have, want in (("s", sk, rule[0]), ("t", tk, rule[1])):
        for x in (have[3], have[1], have[4], have[0]):  # nearest the centre first
            if x not in want:
                return 2, direction, float(x)
    return None


def _diagnose(verts, edges, frame, records):
    where = {(float(s), float(t)): i for i, (s, t) in enumerate(verts)}
    v1, v2, found = [], [], set()
    for r, record in enumerate(records):
        centre = (float(record[0][2]), float(record[1][2]))
        vertex = where.get(centre)
        if vertex is None:  # a function centred where there is no control point yet: add one there
            v2.append((r, None, centre))
            continue
        found.add(vertex)
        problem = _record_violation(record, _rule1(verts, edges, frame, *centre))
        if problem is not None:
            (v1 if problem[0] == 1 else v2).append((r, problem[1], problem[2]))
    v3 = [i for i in range(len(verts)) if i not in found]
    return v1, v2, v3


def _as_records(records, d_name: str = "records") -> list:
    if isinstance(records, (str, bytes, Mapping)) or records is None:
        raise TypeError(f"{d_name}: expected a list of (s_knots, t_knots, H), got {_describe(records)}")
    checked = []
    for record in records:
        if len(record) != 3:
            raise ValueError(f"{d_name}: each record is (s_knots (5,), t_knots (5,), H (d+1,))")
        checked.append((_as_knot_vector(record[0], "records"), _as_knot_vector(record[1], "records"),
                        as_float_array(record[2], "records").reshape(-1)))
    return checked


def violations(mesh, records) -> tuple[list, list, list]:
    """Which records break Rule 1 on `mesh`: (v1, v2, v3). Notes §15.7, local refinement.

    records: [(s_knots, t_knots, H), ...], each centred at (s_knots[2], t_knots[2]).
    v1: indices of records missing a knot that Rule 1 dictates for their vertex, strictly inside their
    support (Violation 1: cured by knot insertion); v2: indices of records with a knot Rule 1 does not
    dictate, or centred where there is no vertex (Violation 2: cured by a new control point);
    v3: vertices that no record is centred at (Violation 3).
    """
    verts, edges, frame = _parts(mesh)
    v1, v2, v3 = _diagnose(verts, edges, frame, _as_records(records))
    return [r for r, _, _ in v1], [r for r, _, _ in v2], v3


class _Refinement:
    """The mutable state of the local refinement algorithm: a mesh in pieces and the records."""

    def __init__(self, verts, edges, frame, records):
        self.verts = [tuple(map(float, v)) for v in verts]
        self.edges = [tuple(sorted(map(int, e))) for e in edges]
        self.frame = frame
        self.records = [(sk.copy(), tk.copy(), h.copy()) for sk, tk, h in records]
        self.log = []

    def arrays(self):
        return np.array(self.verts), np.array(self.edges, dtype=int).reshape(-1, 2)

    def mesh(self) -> dict:
        return {"vertices": [list(v) for v in self.verts], "edges": [list(e) for e in self.edges],
                "frame": self.frame.tolist()}

    def diagnose(self):
        verts, edges = self.arrays()
        return _diagnose(verts, edges, self.frame, self.records)

    def snapshot(self, action: str, detail: str) -> None:
        v1, v2, v3 = self.diagnose()
        self.log.append({
            "action": action, "detail": detail, "mesh": self.mesh(),
            "records": [(sk.copy(), tk.copy(), h.copy()) for sk, tk, h in self.records],
            "violations": ([r for r, _, _ in v1], [r for r, _, _ in v2], v3),
        })

    def add_record(self, sk, tk, h) -> None:
        for k, (ok, ot, oh) in enumerate(self.records):
            if np.array_equal(ok, sk) and np.array_equal(ot, tk):
                self.records[k] = (ok, ot, oh + h)
                return
        self.records.append((sk, tk, h))

    def add_vertex(self, point) -> int:
        """Append a vertex, splitting an edge it lies inside; returns its index."""
        s, t = point
        if (s, t) in self.verts:
            raise ValueError(f"new_vertices: there is already a vertex at {[s, t]}")
        index = len(self.verts)
        self.verts.append((float(s), float(t)))
        for e, (a, b) in enumerate(self.edges):
            (sa, ta), (sb, tb) = self.verts[a], self.verts[b]
            inside = ((ta == tb == t and min(sa, sb) < s < max(sa, sb)) or
                      (sa == sb == s and min(ta, tb) < t < max(ta, tb)))
            if inside:
                self.edges[e] = tuple(sorted((a, index)))
                self.edges.append(tuple(sorted((b, index))))
                break
        return index

    def add_edge(self, a: int, b: int) -> None:
        pair = tuple(sorted((a, b)))
        if pair not in self.edges:
            self.edges.append(pair)

    def join_nearest(self, index: int) -> None:
        """Join a new vertex to its nearest neighbour in each of the four directions, where no edge leaves it
        that way and the joining segment crosses no edge."""
        verts, edges = self.arrays()
        here = verts[index]
        for axis in (0, 1):
            along, other = verts[:, axis], verts[:, 1 - axis]
            for sign in (1, -1):
                leaving = [e for e in edges if index in e and
                           verts[e[0] if e[1] == index else e[1], 1 - axis] == here[1 - axis] and
                           sign * (verts[e[0] if e[1] == index else e[1], axis] - here[axis]) > 0]
                if leaving:
                    continue
                ahead = np.flatnonzero((other == here[1 - axis]) & (sign * (along - here[axis]) > 0))
                if ahead.size == 0:
                    continue
                nearest = int(ahead[np.argmin(np.abs(along[ahead] - here[axis]))])
                low, high = sorted((here[axis], along[nearest]))
                a, b = verts[edges[:, 0]], verts[edges[:, 1]]
                across = a[:, axis] == b[:, axis]  # perpendicular edges
                crosses = (across & (low < a[:, axis]) & (a[:, axis] < high) &
                           (np.minimum(a[:, 1 - axis], b[:, 1 - axis]) < here[1 - axis]) &
                           (here[1 - axis] < np.maximum(a[:, 1 - axis], b[:, 1 - axis])))
                if not crosses.any():
                    self.add_edge(index, nearest)
                    verts, edges = self.arrays()


def _fmt(x: float) -> str:
    return f"{x:g}"


def _knots_text(sk, tk) -> str:
    return f"N[{', '.join(map(_fmt, sk))}]·N[{', '.join(map(_fmt, tk))}]"


def local_refinement(mesh, points, new_vertices, new_edges=(), weights=None, max_steps: int = 200):
    """Insert control points into a T-spline without changing its surface: (mesh, points, weights, log). Notes §15.7.

    new_vertices: (k, 2) knot coordinates of the control points to add (step 1); each one splits an edge
    it lies inside, and new_edges (pairs of indices into the enlarged vertex list: the old vertices keep
    0..V-1, the new ones follow in order) adds the edges the designer wants. Then, with the blending
    functions kept as records apart from the mesh (`blending_records`): while some record misses a knot
    Rule 1 dictates inside its support (Violation 1), every such record gets that knot
    (`refine_blending_function`) and its pieces go to the records centred where they are centred, summed
    with records of equal knots; when none does but a record has a knot Rule 1 does not dictate, or is
    centred where there is no vertex (Violation 2), a vertex is added there (on the record's centre row
    or column) and joined to its nearest neighbours. At the end every vertex has one record, with its
    Rule-1 knots, and its homogeneous point gives the new control point and weight (15.23).

    log: one dict per step {"action", "detail", "mesh", "records", "violations" (v1, v2, v3) after the step}.
    Raises RuntimeError if the steps run out or a vertex is left without a blending function.

    The notes' Fig. 15.20 (`notes_example("15.refinement")`): inserting P2 on a mesh with unit weights
    also adds P3 and leaves two control points with weights other than 1.

    >>> from cagd_course.examples import notes_example
    >>> example = notes_example("15.refinement")
    >>> mesh, vertices, edges = (example.inputs[k] for k in ("mesh", "new_vertices", "new_edges"))
    >>> points = [(s, t, (s - 3) * (t - 4) / 8) for s, t in mesh["vertices"]]
    >>> refined, new_points, new_weights, log = local_refinement(mesh, points, vertices, edges)
    >>> len(refined["vertices"]), new_weights[-2:].round(6).tolist()
    (39, [1.083333, 1.25])
    """
    verts, edges, frame = _parts(mesh)
    records = blending_records(mesh, points, weights)
    new = as_float_array(new_vertices, "new_vertices")
    if new.size == 0:
        new = new.reshape(0, 2)
    if new.ndim != 2 or new.shape[1] != 2:
        raise ValueError(f"new_vertices: expected knot coordinates of shape (k, 2), got shape {new.shape}")
    low, high = verts.min(axis=0), verts.max(axis=0)
    if np.any(new < low) or np.any(new > high):
        raise ValueError("new_vertices: new control points must lie in the box of the mesh's vertices")
    steps = as_count(max_steps, "max_steps", minimum=1)
    state = _Refinement(verts, edges, frame, records)
    state.snapshot("start", "the T-mesh, every blending function by Rule 1")
    added = [state.add_vertex(tuple(p)) for p in new]
    count = len(state.verts)
    extra = _as_edges(new_edges, count, np.array(state.verts), "new_edges")
    for a, b in extra.tolist():
        state.add_edge(a, b)
    verts_now = np.array(state.verts)
    for index in added:
        ends = [verts_now[b if a == index else a] for a, b in state.edges if index in (a, b)]
        directions = {("row" if e[1] == verts_now[index, 1] else "column") for e in ends}
        if directions != {"row", "column"}:
            raise ValueError(f"new_edges: the new control point at {verts_now[index].tolist()} needs an edge along "
                             "its row and one along its column (lie on an edge, or be joined by new_edges)")
    if added:
        where = ", ".join(f"({_fmt(s)}, {_fmt(t)})" for s, t in new)
        state.snapshot("insert", f"step 1: control point(s) inserted at {where}")
    for _ in range(steps):
        v1, v2, _v3 = state.diagnose()
        if v1:
            guilty = sorted({r for r, _, _ in v1})
            todo = [(state.records[r], direction, knot) for r, direction, knot in v1]
            state.records = [rec for r, rec in enumerate(state.records) if r not in guilty]
            lines = []
            for (sk, tk, h), direction, knot in todo:
                pieces = refine_blending_function(sk, tk, knot, direction)
                for coefficient, psk, ptk in pieces:
                    state.add_record(psk, ptk, coefficient * h)
                lines.append(f"{_knots_text(sk, tk)} + {direction} = {_fmt(knot)}")
            state.snapshot("violation 1", "knot insertion: " + "; ".join(lines))
            continue
        if v2:
            r, direction, knot = v2[0]
            sk, tk, _ = state.records[r]
            if direction is None:
                point = (float(sk[2]), float(tk[2]))
            else:
                point = (knot, float(tk[2])) if direction == "s" else (float(sk[2]), knot)
            if not (low[0] <= point[0] <= high[0] and low[1] <= point[1] <= high[1]):
                raise RuntimeError(f"local refinement would need a control point outside the mesh at {point}")
            index = state.add_vertex(point)
            state.join_nearest(index)
            why = ("no control point at its centre" if direction is None else
                   f"{direction} = {_fmt(knot)} is not dictated by Rule 1")
            state.snapshot("violation 2", f"control point added at ({_fmt(point[0])}, {_fmt(point[1])}): "
                           f"{_knots_text(sk, tk)} has {why}")
            continue
        break
    else:
        raise RuntimeError(f"local refinement did not finish in {steps} steps")
    v1, v2, v3 = state.diagnose()
    if v1 or v2 or v3:
        raise RuntimeError(f"local refinement left violations: {len(v1)}, {len(v2)}, vertices without a function {v3}")
    where = {(float(sk[2]), float(tk[2])): h for sk, tk, h in state.records}
    homogeneous = np.array([where[v] for v in state.verts])
    new_points, new_weights = from_homogeneous(homogeneous)
    state.snapshot("done", "no violations: every control point has one blending function, by Rule 1")
    return state.mesh(), new_points, new_weights, state.log

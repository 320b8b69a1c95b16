"""Figures of T-splines (notes §15.7): T-meshes, knot intervals, Rule-1 rays, knot crosses, blending functions.

Every function draws into the Axes it is given and returns it. A T-mesh is the dict of
`cagd_ref.tsplines` ({"vertices", "edges", optional "frame"}). Meshes are drawn in the parameter plane
(s to the right, t up), their pre-image; the surface itself goes through `plot_tspline_surface`,
which triangulates a grid of surface points and hands it to `plotting.surfaces`.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.patches import Rectangle

from cagd_ref import tsplines
from cagd_ref._validation import as_count, as_float_array

from ._style import check_axes
from .surfaces import finish_3d, plot_triangles

__all__ = ["plot_tmesh", "plot_knot_cross", "plot_rays", "plot_blending", "plot_tspline_surface", "tjunctions"]


def _parts(mesh):
    vertices = np.array(tsplines.tmesh(mesh["vertices"], mesh["edges"], mesh.get("frame"))["vertices"])
    return vertices, np.asarray(mesh["edges"], dtype=int).reshape(-1, 2)


def tjunctions(mesh) -> np.ndarray:
    """Indices of the interior vertices with exactly three edges (the T-junctions of the mesh)."""
    vertices, edges = _parts(mesh)
    degree = np.bincount(edges.ravel(), minlength=len(vertices))
    low, high = vertices.min(axis=0), vertices.max(axis=0)
    interior = np.all((vertices > low) & (vertices < high), axis=1)
    return np.flatnonzero((degree == 3) & interior)


def plot_tmesh(ax, mesh, labels: bool = True, intervals: bool = False, color: str = "0.25",
               highlight=None, show_knots: bool = True) -> Axes:
    """The T-mesh in the (s, t) plane: edges, vertices (T-junctions in purple), labels P_i. Notes §15.7, Fig. 15.17.

    intervals: write each edge's knot interval at its middle (the knot-interval form, Fig. 15.17a);
    highlight: a vertex index drawn larger, in red; show_knots: the distinct s and t values as ticks.
    """
    check_axes(ax)
    vertices, edges = _parts(mesh)
    for a, b in edges:
        ax.plot(*vertices[[a, b]].T, color=color, linewidth=1.4, zorder=2)
        if intervals:
            middle = vertices[[a, b]].mean(axis=0)
            length = float(np.abs(vertices[b] - vertices[a]).sum())
            horizontal = vertices[a, 1] == vertices[b, 1]
            ax.annotate(f"{length:g}", middle, xytext=(0, 3) if horizontal else (3, 0), textcoords="offset points",
                        fontsize=8, color="C0", ha="center" if horizontal else "left",
                        va="bottom" if horizontal else "center")
    junctions = tjunctions(mesh)
    ax.plot(*vertices.T, "o", color=color, markersize=4, zorder=3)
    if junctions.size:
        ax.plot(*vertices[junctions].T, "o", color="C4", markersize=5, zorder=4)
    if highlight is not None:
        index = as_count(highlight, "highlight")
        ax.plot(*vertices[index], "o", color="C3", markersize=8, zorder=5)
    if labels:
        for i, (s, t) in enumerate(vertices):
            ax.annotate(f"$P_{{{i}}}$", (s, t), xytext=(3, 3), textcoords="offset points", fontsize=8, zorder=6)
    if show_knots:
        ax.set_xticks(np.unique(vertices[:, 0]))
        ax.set_yticks(np.unique(vertices[:, 1]))
    ax.set_aspect("equal")
    if not ax.get_xlabel():
        ax.set(xlabel="s", ylabel="t")
    return ax


def plot_knot_cross(ax, s_knots, t_knots, color: str = "C3", alpha: float = 0.12, label: str | None = None) -> Axes:
    """A blending function's knot cross: its support, the 5 + 5 knot lines inside it, its centre. Fig. 15.16."""
    check_axes(ax)
    sk, tk = as_float_array(s_knots, "s_knots"), as_float_array(t_knots, "t_knots")
    if sk.shape != (5,) or tk.shape != (5,):
        raise ValueError(f"s_knots: expected two knot vectors of five knots, got {sk.shape} and {tk.shape}")
    ax.add_patch(Rectangle((sk[0], tk[0]), sk[4] - sk[0], tk[4] - tk[0], facecolor=color, alpha=alpha,
                           edgecolor=color, linewidth=1.2, label=label, zorder=1))
    for s in sk:
        ax.plot([s, s], [tk[0], tk[4]], ":", color=color, linewidth=0.9, zorder=1)
    for t in tk:
        ax.plot([sk[0], sk[4]], [t, t], ":", color=color, linewidth=0.9, zorder=1)
    ax.plot(sk[2], tk[2], "+", color=color, markersize=10, zorder=5)
    return ax


def plot_rays(ax, mesh, vertex, color: str = "C1") -> Axes:
    """The four Rule-1 rays from a vertex, each drawn to its second knot, with the knots marked. Notes §15.7, Rule 1."""
    check_axes(ax)
    s_knots, t_knots = tsplines.infer_knot_vectors(mesh, vertex)
    s, t = s_knots[2], t_knots[2]
    for end in (s_knots[0], s_knots[4]):
        ax.annotate("", (end, t), (s, t), arrowprops={"arrowstyle": "->", "color": color, "linewidth": 1.6})
    for end in (t_knots[0], t_knots[4]):
        ax.annotate("", (s, end), (s, t), arrowprops={"arrowstyle": "->", "color": color, "linewidth": 1.6})
    ax.plot(s_knots[[0, 1, 3, 4]], [t] * 4, "s", color=color, markersize=5, zorder=5)
    ax.plot([s] * 4, t_knots[[0, 1, 3, 4]], "s", color=color, markersize=5, zorder=5)
    return ax


def plot_blending(ax, s_knots, t_knots, samples: int = 61, cmap: str = "Greens", alpha: float = 0.8) -> Axes:
    """A heat map of B(s, t) = N[s_knots](s) N[t_knots](t) over its support. Notes (15.9)."""
    check_axes(ax)
    sk, tk = as_float_array(s_knots, "s_knots"), as_float_array(t_knots, "t_knots")
    s = np.linspace(sk[0], sk[4], samples)
    t = np.linspace(tk[0], tk[4], samples)
    values = np.outer(tsplines.cubic_blending(tk, t), tsplines.cubic_blending(sk, s))
    ax.contourf(s, t, np.ma.masked_less_equal(values, 1e-9), levels=12, cmap=cmap, alpha=alpha, zorder=0)
    return ax


def plot_tspline_surface(ax, mesh, points, weights=None, samples: int = 25, color: str = "C0",
                         net: bool = True) -> Axes:
    """The T-spline surface in 3-D (a triangulated grid of its points) and, if `net`, its control mesh. Notes (15.7)."""
    check_axes(ax)
    (s0, s1), (t0, t1) = tsplines.mesh_domain(mesh)
    s, t = np.meshgrid(np.linspace(s0, s1, samples), np.linspace(t0, t1, samples), indexing="ij")
    surface = tsplines.tspline_point(mesh, points, s.ravel(), t.ravel(), weights)
    k = np.arange(samples * samples).reshape(samples, samples)
    quads = np.stack([k[:-1, :-1], k[1:, :-1], k[1:, 1:], k[:-1, 1:]], axis=-1).reshape(-1, 4)
    triangles = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    plot_triangles(ax, surface, triangles, color=color, alpha=0.45, edges=False)
    pts = as_float_array(points, "points")
    if net:
        for a, b in np.asarray(mesh["edges"], dtype=int).reshape(-1, 2):
            ax.plot(*pts[[a, b]].T, "--", color="0.4", linewidth=0.8)
        ax.scatter(*pts.T, color="0.3", s=8, depthshade=False)
    finish_3d(ax, np.vstack([surface, pts]))
    return ax

"""Figures of tensor-product Bézier patches in 3-D: the patch with its iso-curves, the control net, tangent planes.

Every function draws into the 3-D Axes it is given (``projection="3d"``) and returns it. `finish_3d`
gives a figure equal axes, a fixed view and few ticks, so that patches keep their shape and stay
readable; where ipympl is installed the figure can be turned with the mouse.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from cagd_ref._validation import as_float_array, as_vector
from cagd_ref.surfaces import iso_curve, patch_normal, patch_point

from ._style import check_axes

__all__ = ["patch_grid", "plot_patch", "plot_control_net", "plot_tangent_plane", "finish_3d", "plot_iso_curve",
           "plot_triangles", "plot_normals", "label_3d"]

NET_STYLE = {"color": "0.45", "linestyle": "--", "linewidth": 0.8, "marker": "o", "markersize": 3}


def _three_d(ax) -> None:
    check_axes(ax)
    if ax.name != "3d":
        raise TypeError("ax: expected 3-D axes (projection='3d')")


def _net(points) -> np.ndarray:
    net = as_float_array(points, "points")
    if net.ndim != 3 or net.shape[2] != 3:
        raise ValueError(f"points: expected a control net in space, shape (m+1, n+1, 3), got shape {net.shape}")
    return net


def patch_grid(points, weights=None, samples: int = 21) -> np.ndarray:
    """Points of the patch on a regular samples × samples grid of (s, t), shape (samples, samples, d)."""
    grid = np.linspace(0.0, 1.0, samples)
    s, t = np.meshgrid(grid, grid, indexing="ij")
    return patch_point(points, s.ravel(), t.ravel(), weights).reshape(samples, samples, -1)


def plot_patch(ax, points, weights=None, samples: int = 13, iso: int = 5, color: str = "C0", alpha: float = 0.25,
               label: str | None = None) -> Axes:
    """The patch as a shaded surface with `iso` iso-curves in each direction (s = const and t = const). Notes §15.1."""
    _three_d(ax)
    net = _net(points)
    grid = patch_grid(net, weights, samples)
    ax.plot_surface(*np.moveaxis(grid, 2, 0), color=color, alpha=alpha, linewidth=0, shade=True)
    fine = np.linspace(0.0, 1.0, 4 * samples)
    for k, value in enumerate(np.linspace(0.0, 1.0, iso)):
        for s, t in ((np.full_like(fine, value), fine), (fine, np.full_like(fine, value))):
            ax.plot(*patch_point(net, s, t, weights).T, color=color, linewidth=0.8,
                    label=label if k == 0 and s[0] == value else None)
    return ax


def plot_control_net(ax, points, **style) -> Axes:
    """The control net: the rows (i fixed) and columns (j fixed) of control points joined by dashed lines."""
    _three_d(ax)
    net = _net(points)
    label = style.pop("label", None)
    style = {**NET_STYLE, **style}
    for i in range(net.shape[0]):
        ax.plot(*net[i].T, **style, label=label if i == 0 else None)
    for j in range(net.shape[1]):
        ax.plot(*net[:, j].T, **{**style, "marker": ""})
    return ax


def plot_tangent_plane(ax, point, p_s, p_t, size: float = 0.5, color: str = "C2", alpha: float = 0.3) -> Axes:
    """A square of side 2·size in the plane through `point` spanned by p_s and p_t (the tangent plane)."""
    _three_d(ax)
    p = as_vector(point, "point", dim=3)
    a = as_vector(p_s, "p_s", dim=3)
    b = as_vector(p_t, "p_t", dim=3)
    e1 = a / np.linalg.norm(a)
    e2 = b - (b @ e1) * e1
    e2 /= np.linalg.norm(e2)
    corners = [p + size * (x * e1 + y * e2) for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    ax.add_collection3d(Poly3DCollection([corners], facecolor=color, edgecolor=color, alpha=alpha))
    return ax


def finish_3d(ax, points, elev: float = 25.0, azim: float = -60.0, margin: float = 0.08,
              ticks: bool = True) -> Axes:
    """Equal axes around `points` (any array of 3-D points), a fixed view, three ticks per axis, axis labels.

    ticks=False drops the tick labels (for small panels whose coordinates nobody reads); tick labels are 8 pt.
    """
    _three_d(ax)
    pts = as_float_array(points, "points").reshape(-1, 3)
    low, high = pts.min(axis=0), pts.max(axis=0)
    centre, half = (low + high) / 2, (1 + margin) * max(float(np.max(high - low)) / 2, 1e-9)
    ax.set(xlim=(centre[0] - half, centre[0] + half), ylim=(centre[1] - half, centre[1] + half),
           zlim=(centre[2] - half, centre[2] + half))
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=elev, azim=azim)
    for axis, name in ((ax.xaxis, "x"), (ax.yaxis, "y"), (ax.zaxis, "z")):
        axis.set_major_locator(MaxNLocator(3))
        axis.set_label_text(name, fontsize=8)
        if not ticks:
            axis.set_ticklabels([])
            axis.labelpad = -12  # the name next to the axis, where the tick labels would be
    ax.tick_params(labelsize=8, pad=0)
    return ax


def plot_iso_curve(ax, points, value, direction: str = "s", weights=None, color: str = "C3", beads: bool = True,
                   label: str | None = None) -> Axes:
    """An iso-parameter curve P(c, t) ("s") or P(s, c) ("t") with its beads and their control polygon. Notes §15.1.

    The beads are the points at `value` of the control curves of that direction (`surfaces.iso_curve`):
    the iso-curve's own control points, drawn as squares joined by a thin line.
    """
    _three_d(ax)
    net = _net(points)
    fine = np.linspace(0.0, 1.0, 61)
    fixed = np.full_like(fine, float(value))
    s, t = (fixed, fine) if direction == "s" else (fine, fixed)
    ax.plot(*patch_point(net, s, t, weights).T, color=color, linewidth=2.2, label=label)
    if beads:
        bead_points, _ = iso_curve(net, value, direction, weights)
        ax.plot(*bead_points.T, "s:", color=color, markersize=5, linewidth=0.9)
    return ax


def plot_triangles(ax, vertices, triangles, color: str = "C0", alpha: float = 0.35, edges: bool = True) -> Axes:
    """A triangle mesh (vertices (V, 3), triangles (T, 3) indices), as from `surfaces.tessellate`. Notes §15.4."""
    _three_d(ax)
    v = as_float_array(vertices, "vertices")
    tri = np.asarray(triangles, dtype=int)
    ax.add_collection3d(Poly3DCollection(v[tri], facecolor=color, alpha=alpha,
                                         edgecolor="0.25" if edges else "none", linewidth=0.3))
    return ax


def plot_normals(ax, points, s, t, weights=None, length: float = 0.5, color: str = "black") -> Axes:
    """Unit normals P_s × P_t (scaled by `length`) at the pairs (s, t) of the patch. Notes §15.3."""
    _three_d(ax)
    net = _net(points)
    base = np.atleast_2d(patch_point(net, s, t, weights))
    normals = np.atleast_2d(patch_normal(net, s, t, weights))
    ax.quiver(*base.T, *(length * normals).T, color=color, arrow_length_ratio=0.2, linewidth=1)
    return ax


def label_3d(ax, point, text: str, offset=(4, 4), **style):
    """Write `text` next to a 3-D point, `offset` points away, as a 2-D annotation at the point's projection.

    Call it after `finish_3d` (the projection needs the final limits and view). Unlike ``ax.text`` on 3-D axes,
    the label's drawn extent is known, so it can be placed apart from its neighbours.
    """
    from mpl_toolkits.mplot3d import proj3d

    _three_d(ax)
    x, y, z = as_vector(point, "point", dim=3)
    px, py, _ = proj3d.proj_transform(x, y, z, ax.get_proj())
    style = {"fontsize": 8, "textcoords": "offset points", **style}
    return ax.annotate(text, (px, py), xytext=offset, **style)

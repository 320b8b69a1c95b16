"""Static figures for the course: control polygons, curves, de Casteljau triangles, combs, conics, vectors.

Every function draws into a matplotlib Axes `ax` it is given and returns that
same Axes, so calls chain and several drawings share one picture. Planar
drawings switch on an equal aspect ratio (circles look round) and label the
axes x and y unless the caller already labelled them. Extra keyword arguments
(`**style`) go to the underlying matplotlib call and override the defaults.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection
from matplotlib.patches import FancyArrowPatch

from ._validation import as_count, as_float_array, as_interval, as_points, as_vector
from .bezier import bernstein_matrix, de_casteljau_triangle
from .continuity import curvature_comb

__all__ = [
    "plot_control_polygon",
    "plot_bezier",
    "plot_de_casteljau",
    "plot_curvature_comb",
    "plot_implicit",
    "plot_vector",
    "bezier_samples",
]

POLYGON_STYLE = {"color": "0.45", "linestyle": "--", "linewidth": 1.0, "marker": "o", "markersize": 5}
CURVE_STYLE = {"color": "C0", "linewidth": 2.0}


def _check_axes(ax) -> None:
    if not isinstance(ax, Axes):
        raise TypeError(f"ax: expected a matplotlib Axes, got {type(ax).__name__}")


def _planar_points(points, name: str = "points") -> np.ndarray:
    pts = as_points(points, name)
    if pts.shape[1] != 2:
        raise ValueError(f"{name}: expected planar points of shape (n+1, 2), got shape {pts.shape}")
    return pts


def _finish_planar(ax: Axes, adjustable: str = "datalim") -> Axes:
    """Equal aspect and x/y axis labels (kept if the caller already set some).

    "datalim" grows the limits to keep the axes box; "box" (for fixed limits)
    reshapes the box instead.
    """
    ax.set_aspect("equal", adjustable=adjustable)
    if not ax.get_xlabel():
        ax.set_xlabel("x")
    if not ax.get_ylabel():
        ax.set_ylabel("y")
    return ax


def bezier_samples(points, weights=None, interval=(0, 1), samples: int = 200) -> np.ndarray:
    """Points of a (rational) Bézier curve at `samples` parameters evenly spread over `interval`, shape (samples, d).

    The curve is the one defined on [0, 1] (Notes §2.2, §2.9); `interval` only
    chooses which parameters to draw, so (-0.5, 1.5) shows the extrapolated
    curve. Unlike `bezier.evaluate`, zero and negative weights are accepted:
    where the denominator vanishes or changes sign the curve runs off to
    infinity, and those samples become NaN so a plot breaks the line there.
    """
    pts = as_points(points)
    t0, t1 = as_interval(interval)
    samples = as_count(samples, "samples", minimum=2)
    basis = bernstein_matrix(len(pts) - 1, np.linspace(t0, t1, samples))
    if weights is None:
        return basis @ pts
    w = as_float_array(weights, "weights")
    if w.shape != (len(pts),):
        raise ValueError(f"weights: expected {len(pts)} weights (one per control point), got shape {w.shape}")
    denominator = basis @ w
    numerator = basis @ (w[:, None] * pts)
    # A sign change between neighbours means a pole lies between them: break the line there.
    pole = np.zeros(samples, dtype=bool)
    pole[1:] = np.sign(denominator[1:]) != np.sign(denominator[:-1])
    tiny = np.abs(denominator) <= 1e-12 * np.abs(w).max()
    with np.errstate(divide="ignore", invalid="ignore"):
        curve = numerator / denominator[:, None]
    curve[pole | tiny] = np.nan
    return curve


def plot_control_polygon(ax, points, labels=True, label: str = "P", legend: str | None = None, **style) -> Axes:
    """Draw a planar control polygon (n+1, 2): dashed legs, dots at the points, labels P0..Pn. Notes §2.2.

    `labels` is True (label every point), False (none) or a sequence of n+1
    strings ("" leaves a point unlabelled, e.g. a joint another curve labels).
    `label` is the letter of the default labels (typeset as P_0, P_1, ...);
    `legend` is an optional legend entry for the polygon.
    """
    _check_axes(ax)
    pts = _planar_points(points)
    ax.plot(pts[:, 0], pts[:, 1], **{**POLYGON_STYLE, "label": legend, **style})
    if labels is True:
        labels = [f"${label}_{{{i}}}$" for i in range(len(pts))]
    elif labels is False or labels is None:
        labels = []
    elif isinstance(labels, str) or len(labels) != len(pts):
        raise ValueError(f"labels: expected True, False or {len(pts)} strings, got {labels!r}")
    for text, (x, y) in zip(labels, pts):
        if text:
            ax.annotate(text, (x, y), xytext=(4, 5), textcoords="offset points", fontsize=10)
    return _finish_planar(ax)


def plot_bezier(ax, points, weights=None, interval=(0, 1), samples: int = 200, **style) -> Axes:
    """Draw a planar (rational) Bézier curve, control points (n+1, 2), for t in `interval`. Notes §2.2, §2.9.

    See `bezier_samples` for what `interval` and `weights` mean; pass `label=`
    for a legend entry.
    """
    _check_axes(ax)
    curve = bezier_samples(_planar_points(points), weights, interval, samples)
    ax.plot(curve[:, 0], curve[:, 1], **{**CURVE_STYLE, **style})
    return _finish_planar(ax)


def plot_de_casteljau(ax, points, t, curve: bool = True) -> Axes:
    """Draw the de Casteljau triangle at parameter t: the curve, every level's polygon and P(t). Notes §2.3.

    points: (n+1, 2). Level 0 is the control polygon (labelled P_0..P_n),
    levels 1..n-1 are the polygons of intermediate points, each in its own
    colour, and level n is the point P(t), drawn large and labelled.
    """
    _check_axes(ax)
    levels = de_casteljau_triangle(_planar_points(points), t)
    if curve:
        plot_bezier(ax, levels[0], color="C0", alpha=0.5, label="curve")
    plot_control_polygon(ax, levels[0], legend="control polygon")
    for r, level in enumerate(levels[1:-1], start=1):
        ax.plot(level[:, 0], level[:, 1], "o-", color=f"C{r % 9 + 1}", markersize=4, linewidth=1, label=f"level {r}")
    point = levels[-1][0]
    ax.plot(point[0], point[1], "o", color="black", markersize=8, label=f"P({float(t):.3g})")
    ax.annotate(f"$P({float(t):.3g})$", point, xytext=(6, -14), textcoords="offset points")
    return _finish_planar(ax)


def plot_curvature_comb(ax, points, count: int = 50, length: float = 1.0, weights=None, **style) -> Axes:
    """Draw a curvature comb of a planar Bézier curve: `count` teeth and the comb curve through their tips. Notes §2.11.

    The longest tooth has length `length`; teeth point away from the centre of
    curvature (see `continuity.curvature_comb`). `color` sets both parts.
    """
    _check_axes(ax)
    bases, tips = curvature_comb(_planar_points(points), count, length, weights)
    color = style.pop("color", "C3")
    teeth = LineCollection(np.stack([bases, tips], axis=1), colors=color, linewidths=0.8, alpha=0.7)
    ax.add_collection(teeth)
    ax.plot(tips[:, 0], tips[:, 1], **{"color": color, "linewidth": 1.2, "label": "comb", **style})
    ax.update_datalim(np.vstack([bases, tips]))
    ax.autoscale_view()
    return _finish_planar(ax)


def plot_implicit(ax, f, xlim, ylim, resolution: int = 300, **style) -> Axes:
    """Draw the zero set f(x, y) = 0 over the box xlim × ylim as a contour line. Notes §1.5.2, §1.6.

    `f` takes two arrays of equal shape and returns the values elementwise (it
    is called once, on a resolution × resolution grid). Pass `label=` for a
    legend entry and `colors=` / `linewidths=` as for `Axes.contour`.
    """
    _check_axes(ax)
    if not callable(f):
        raise TypeError(f"f: expected a function f(x, y), got {type(f).__name__}")
    x0, x1 = as_interval(xlim, "xlim")
    y0, y1 = as_interval(ylim, "ylim")
    resolution = as_count(resolution, "resolution", minimum=2)
    x, y = np.meshgrid(np.linspace(x0, x1, resolution), np.linspace(y0, y1, resolution))
    values = np.broadcast_to(np.asarray(f(x, y), dtype=float), x.shape)
    legend = style.pop("label", None)
    options = {"colors": "C0", "linewidths": 2.0, **style}
    # A zero set that misses the box is an empty picture, not an error.
    if np.nanmin(values) <= 0 <= np.nanmax(values):
        ax.contour(x, y, values, levels=[0.0], **options)
    if legend is not None:
        # Contour sets carry no legend entry, so a line with no points stands in for it.
        ax.plot([], [], color=np.atleast_1d(options["colors"])[0], linewidth=np.atleast_1d(options["linewidths"])[0], label=legend)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return _finish_planar(ax, adjustable="box")


def plot_vector(ax, tail, vector, label: str | None = None, **style) -> Axes:
    """Draw the vector `vector` as an arrow starting at point `tail` (both (2,) on 2-D axes, (3,) on 3-D axes). Notes §1.1.

    `label` (mathtext allowed, e.g. "$\\mathbf{v}$") is written next to the arrow's head.
    """
    _check_axes(ax)
    three_d = ax.name == "3d"
    dim = 3 if three_d else 2
    start = as_vector(tail, "tail", dim=dim)
    direction = as_vector(vector, "vector", dim=dim)
    head = start + direction
    color = style.pop("color", "C1")
    if three_d:
        ax.quiver(*start, *direction, color=color, arrow_length_ratio=0.12, **style)
    else:
        defaults = {"arrowstyle": "-|>", "mutation_scale": 15, "color": color, "linewidth": 1.5}
        arrow = FancyArrowPatch(start, head, **{**defaults, **style})
        ax.add_patch(arrow)
        ax.update_datalim(np.vstack([start, head]))
        ax.autoscale_view()
    if label is not None:
        # Nudge the label a little past the head so it does not sit on the arrow.
        offset = 0.06 * direction
        ax.text(*(head + offset), label, color=color, fontsize=11)
    return ax if three_d else _finish_planar(ax)

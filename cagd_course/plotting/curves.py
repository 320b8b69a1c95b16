"""Figures of Bézier curves: control polygons, curves (rational too), de Casteljau triangles, curvature combs.

Notes chapter 2. Every function draws into the matplotlib Axes `ax` it is given
and returns it, so calls chain and several drawings share one picture.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import LineCollection

from cagd_ref._validation import as_count, as_float_array, as_interval, as_points
from cagd_ref.bezier import bernstein_matrix, de_casteljau_triangle
from cagd_ref.continuity import curvature_comb

from ._style import CURVE_STYLE, POLYGON_STYLE, check_axes, finish_planar, planar_points

__all__ = ["plot_control_polygon", "plot_bezier", "plot_de_casteljau", "plot_curvature_comb", "bezier_samples"]


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
    check_axes(ax)
    pts = planar_points(points)
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
    return finish_planar(ax)


def plot_bezier(ax, points, weights=None, interval=(0, 1), samples: int = 200, **style) -> Axes:
    """Draw a planar (rational) Bézier curve, control points (n+1, 2), for t in `interval`. Notes §2.2, §2.9.

    See `bezier_samples` for what `interval` and `weights` mean; pass `label=`
    for a legend entry.
    """
    check_axes(ax)
    curve = bezier_samples(planar_points(points), weights, interval, samples)
    ax.plot(curve[:, 0], curve[:, 1], **{**CURVE_STYLE, **style})
    return finish_planar(ax)


def plot_de_casteljau(ax, points, t, curve: bool = True) -> Axes:
    """Draw the de Casteljau triangle at parameter t: the curve, every level's polygon and P(t). Notes §2.3.

    points: (n+1, 2). Level 0 is the control polygon (labelled P_0..P_n),
    levels 1..n-1 are the polygons of intermediate points, each in its own
    colour, and level n is the point P(t), drawn large and labelled.
    """
    check_axes(ax)
    levels = de_casteljau_triangle(planar_points(points), t)
    if curve:
        plot_bezier(ax, levels[0], color="C0", alpha=0.5, label="curve")
    plot_control_polygon(ax, levels[0], legend="control polygon")
    for r, level in enumerate(levels[1:-1], start=1):
        ax.plot(level[:, 0], level[:, 1], "o-", color=f"C{r % 9 + 1}", markersize=4, linewidth=1, label=f"level {r}")
    point = levels[-1][0]
    ax.plot(point[0], point[1], "o", color="black", markersize=8, label=f"P({float(t):.3g})")
    ax.annotate(f"$P({float(t):.3g})$", point, xytext=(6, -14), textcoords="offset points")
    return finish_planar(ax)


def plot_curvature_comb(ax, points, count: int = 50, length: float = 1.0, weights=None, **style) -> Axes:
    """Draw a curvature comb of a planar Bézier curve: `count` teeth and the comb curve through their tips. Notes §2.11.

    The longest tooth has length `length`; teeth point away from the centre of
    curvature (see `continuity.curvature_comb`). `color` sets both parts.
    """
    check_axes(ax)
    bases, tips = curvature_comb(planar_points(points), count, length, weights)
    color = style.pop("color", "C3")
    teeth = LineCollection(np.stack([bases, tips], axis=1), colors=color, linewidths=0.8, alpha=0.7)
    ax.add_collection(teeth)
    ax.plot(tips[:, 0], tips[:, 1], **{"color": color, "linewidth": 1.2, "label": "comb", **style})
    ax.update_datalim(np.vstack([bases, tips]))
    ax.autoscale_view()
    return finish_planar(ax)

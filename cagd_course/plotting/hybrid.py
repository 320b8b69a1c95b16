"""Figures of chapter 20 (hybrid curves and integrals): hybrids with their moving point, boxes, shaded areas.

Every function draws into the Axes it is given and returns it. The hybrid
figure rebuilds the notes' Figure 20.1 (a rational cubic as hybrids of degree
2 to 8, with the moving point's polygon), `plot_moving_boxes` Figure 20.2 (the
pieces of a split curve, each with its moving point's box), `shade_area` and
`shade_sector` Figures 20.3-20.6 (the region under a curve, the sector from
the origin).
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.colors import to_rgba
from matplotlib.patches import Rectangle

from cagd_ref import bezier, hybrid

from ._style import POLYGON_STYLE, check_axes, finish_planar, planar_points
from .curves import bezier_samples, plot_bezier, plot_control_polygon

__all__ = ["plot_hybrid", "plot_moving_boxes", "shade_area", "shade_sector", "piece_curves"]

MOVING_COLOR = "C3"
FIXED_COLOR = "C0"


def _box_patch(centre, half, **style) -> Rectangle:
    return Rectangle(tuple(centre - half), 2 * half[0], 2 * half[1], **{"fill": False, **style})


def plot_hybrid(ax, h: hybrid.HybridCurve, t: float | None = None, labels: bool = True) -> Axes:
    """A planar hybrid curve: fixed points, the moving point's polygon and box, M(t) and H(t). Notes Fig. 20.1.

    With t, the moving point is drawn at M(t), on the path it traces, and the
    hybrid's control polygon is closed through it: the polygon whose Bézier
    curve passes through H(t) = R(t). The curve itself is left to the caller.
    """
    check_axes(ax)
    fixed, moving, weights, m = hybrid._checked_hybrid(h)
    planar_points(moving, "h")
    n = len(fixed) - 1
    rest = np.delete(fixed, m, axis=0)
    ax.plot(*rest.T, "o", color=FIXED_COLOR, markersize=6, label="fixed control points")
    if labels:
        for i, point in zip([i for i in range(n + 1) if i != m], rest):
            ax.annotate(f"$P_{{{i}}}$", point, xytext=(4, -12), textcoords="offset points", fontsize=9)
    plot_control_polygon(ax, moving, labels=[f"$M_{{{i}}}$" for i in range(len(moving))] if labels else False,
                         color=MOVING_COLOR, alpha=0.7, legend=f"moving point's polygon (degree {len(moving) - 1})")
    centre, half = hybrid._box(moving)
    ax.add_patch(_box_patch(centre, half, edgecolor=MOVING_COLOR, linestyle=":", linewidth=1.2))
    path = bezier_samples(moving, weights, samples=120)
    ax.plot(*path.T, color=MOVING_COLOR, linewidth=1.0, alpha=0.6)
    if t is not None:
        mt = bezier.evaluate(moving, t, weights)
        polygon = fixed.copy()
        polygon[m] = mt
        ax.plot(*polygon.T, **{**POLYGON_STYLE, "marker": None, "alpha": 0.8})
        ax.plot(*mt, "o", color=MOVING_COLOR, markersize=8, label=f"M(t), control point {m} of degree {n}")
        ax.plot(*hybrid.hybrid_point(h, t), "*", color="black", markersize=12, label="H(t) = R(t)")
    return finish_planar(ax)


def piece_curves(points, weights, depth: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """The 2^depth pieces (points, weights) of a rational curve split at the halves, depth times. Notes §20.1."""
    pieces = [bezier.to_homogeneous(points, weights)]
    for _ in range(depth):
        pieces = [half for piece in pieces for half in bezier.subdivide(piece, 0.5)]
    return [bezier.from_homogeneous(piece) for piece in pieces]


def plot_moving_boxes(ax, points, weights, depth: int, degree: int = 4) -> Axes:
    """The pieces of a rational curve after `depth` halvings, each with its moving point's box. Notes Fig. 20.2."""
    check_axes(ax)
    for k, (p, w) in enumerate(piece_curves(planar_points(points), weights, depth)):
        h = hybrid.hybrid_curve(p, w, degree)
        centre, half = hybrid._box(h.moving)
        color = f"C{k % 2 + 1}"
        plot_bezier(ax, p, w, samples=60, color=color, linewidth=2.0)
        ax.add_patch(_box_patch(centre, half, edgecolor=color, linewidth=1.0))
        ax.plot(*h.moving.T, ".", color=color, markersize=3)
    return finish_planar(ax)


def shade_area(ax, points, weights=None, samples: int = 300, **style) -> Axes:
    """The region between a (rational) Bézier curve and the x-axis, blue where ∫ y dx counts positive. Notes Fig. 20.3.

    A piece of the curve adds its area where it runs in +x above the axis (or
    in -x below it) and subtracts it otherwise: those parts are shaded blue and
    red, so that the signed area is blue minus red.
    """
    check_axes(ax)
    curve = bezier_samples(planar_points(points), weights, samples=samples)
    x, y = curve.T
    # The sign of y dx on each little step of the sampled curve; steps where neither y nor dx changes sign
    # form runs along which the curve is monotone in x on one side of the axis: one polygon per run, so
    # no seams show between neighbouring strips.
    side, direction = np.sign(y[:-1] + y[1:]), np.sign(np.diff(x))
    sign = side * direction
    breaks = np.flatnonzero((side[1:] != side[:-1]) | (direction[1:] != direction[:-1])) + 1
    polygons, colors = [], []
    for start, stop in zip(np.r_[0, breaks], np.r_[breaks, len(sign)]):
        if sign[start] == 0:
            continue
        run = curve[start : stop + 1]
        polygons.append(np.vstack([run, [[run[-1, 0], 0.0], [run[0, 0], 0.0]]]))
        colors.append(to_rgba("C0" if sign[start] > 0 else "C3"))
    ax.add_collection(PolyCollection(polygons, facecolors=colors, linewidths=0, alpha=style.get("alpha", 0.25)))
    ax.axhline(0, color="0.3", linewidth=0.8)
    return finish_planar(ax)


def shade_sector(ax, points, weights=None, samples: int = 200, **style) -> Axes:
    """The sector swept by the segment from the origin to a point running along the curve. Notes Fig. 20.4."""
    check_axes(ax)
    curve = bezier_samples(planar_points(points), weights, samples=samples)
    ax.fill(np.r_[0.0, curve[:, 0]], np.r_[0.0, curve[:, 1]], **{"color": "C2", "alpha": 0.25, **style})
    ax.plot([0, curve[0, 0]], [0, curve[0, 1]], color="C2", linewidth=1)
    ax.plot([0, curve[-1, 0]], [0, curve[-1, 1]], color="C2", linewidth=1)
    ax.plot(0, 0, "k+", markersize=10)
    return finish_planar(ax)

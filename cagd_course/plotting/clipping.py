"""Figures of curve intersection: fat lines, explicit distance curves with their hulls, the V rule, search boxes.

Notes chapter 7. Every function draws into the matplotlib Axes `ax` it is given
and returns it. A fat line is an infinite band, so it is drawn cut to a box
`extent = (xmin, xmax, ymin, ymax)` that the caller chooses (usually the
picture's limits); an explicit curve (t, d(t)) is drawn over its parameter
interval with t across.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.collections import PolyCollection
from matplotlib.colors import to_rgba
from matplotlib.patches import Polygon, Rectangle

from cagd_ref._validation import as_float_array, as_vector
from cagd_ref.blending_properties import convex_hull
from cagd_ref.intersection import explicit_meets
from cagd_ref.polynomials import bernstein_horner

from ._style import POLYGON_STYLE, check_axes, finish_planar

__all__ = [
    "band_polygon",
    "picture_extent",
    "plot_line",
    "plot_fat_line",
    "plot_explicit_clip",
    "plot_v_rule",
    "plot_parameter_pairs",
    "plot_boxes",
]

BAND_COLOR = "C1"
HULL_COLOR = "C2"
KEPT_COLOR = "C2"


def _extent(extent) -> tuple[float, float, float, float]:
    box = as_vector(extent, "extent", dim=4)
    if not (box[0] < box[1] and box[2] < box[3]):
        raise ValueError(f"extent: expected (xmin, xmax, ymin, ymax), xmin < xmax and ymin < ymax, got {box.tolist()}")
    return tuple(float(v) for v in box)


def picture_extent(*point_sets, margin: float = 0.15) -> tuple[float, float, float, float]:
    """A box (xmin, xmax, ymin, ymax) around planar point sets, widened by `margin` of its size on each side."""
    points = np.vstack([as_float_array(p, "point_sets").reshape(-1, 2) for p in point_sets])
    low, high = points.min(axis=0), points.max(axis=0)
    pad = margin * max(float((high - low).max()), 1e-9)
    return (low[0] - pad, high[0] + pad, low[1] - pad, high[1] + pad)


def band_polygon(line, low: float, high: float, extent) -> np.ndarray:
    """The part of the band low <= a x + b y + c <= high inside the box `extent`: polygon vertices (k, 2), maybe k = 0.

    The box is cut by the two half-planes in turn (Sutherland-Hodgman); a
    band of width zero gives a degenerate polygon along the line.
    """
    a, b, c = as_vector(line, "line", dim=3)
    x0, x1, y0, y1 = _extent(extent)
    polygon = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    for sign, level in ((1.0, low), (-1.0, high)):
        if not np.isfinite(level):
            continue
        polygon = _cut(polygon, lambda p, s=sign, v=level: s * (p @ np.array([a, b]) + c - v))
    return polygon


def _cut(polygon: np.ndarray, value) -> np.ndarray:
    """The part of a convex polygon where value(p) >= 0."""
    if len(polygon) == 0:
        return polygon
    v = value(polygon)
    kept = []
    for k in range(len(polygon)):
        p, q, vp, vq = polygon[k], polygon[(k + 1) % len(polygon)], v[k], v[(k + 1) % len(polygon)]
        if vp >= 0:
            kept.append(p)
        if (vp >= 0) != (vq >= 0):
            kept.append(p + (q - p) * (vp / (vp - vq)))
    return np.array(kept).reshape(-1, 2)


def _line_segment(a: float, b: float, c: float, extent) -> np.ndarray:
    """The part of the line a x + b y + c = 0 inside the box, as its two end points (none if it misses)."""
    norm = a * a + b * b
    if norm == 0:
        return np.zeros((0, 2))
    x0, x1, y0, y1 = _extent(extent)
    start, direction = -c / norm * np.array([a, b]), np.array([-b, a])
    low, high = -np.inf, np.inf
    # Liang-Barsky: the parameters s where start + s·direction is inside each slab of the box.
    for origin, step, lo, hi in ((start[0], direction[0], x0, x1), (start[1], direction[1], y0, y1)):
        if step == 0:
            if not lo <= origin <= hi:
                return np.zeros((0, 2))
            continue
        s0, s1 = sorted(((lo - origin) / step, (hi - origin) / step))
        low, high = max(low, s0), min(high, s1)
    if low > high:
        return np.zeros((0, 2))
    return np.array([start + low * direction, start + high * direction])


def plot_line(ax, line, extent, **style) -> Axes:
    """The homogeneous line (a, b, c), a x + b y + c = 0, drawn across the box `extent` (pass label= for a legend)."""
    check_axes(ax)
    a, b, c = as_vector(line, "line", dim=3)
    segment = _line_segment(a, b, c, extent)
    if len(segment):
        ax.plot(*segment.T, **{"color": "k", "linewidth": 1.0, **style})
    return ax


def plot_fat_line(ax, line, dmin: float, dmax: float, extent, color: str = BAND_COLOR, label: str | None = "fat line",
                  baseline: bool = True, alpha: float = 0.16) -> Axes:
    """Shade the fat line dmin <= a x + b y + c <= dmax inside `extent` and draw its two edges. Notes §7.7.1.

    line: (3,) with a² + b² = 1 for distances (any scale works); baseline=True
    also draws L̄ itself (d = 0), thin and dotted. The band reaches the edges
    of `extent`, so the picture's limits grow to it.
    """
    check_axes(ax)
    a, b, c = as_vector(line, "line", dim=3)
    shape = band_polygon([a, b, c], dmin, dmax, extent)
    if len(shape) >= 3:
        ax.add_patch(Polygon(shape, closed=True, facecolor=color, alpha=alpha, edgecolor="none", label=label))
    levels = [(dmin, "--"), (dmax, "--")] + ([(0.0, ":")] if baseline else [])
    for level, style in levels:
        segment = _line_segment(a, b, c - level, extent)
        if len(segment):
            ax.plot(*segment.T, style, color=color, linewidth=1.0)
    return finish_planar(ax)


def plot_explicit_clip(ax, values, dmin: float, dmax: float, kept=None, interval=(0.0, 1.0), curve: bool = True,
                       hull: bool = True, label: str = "d", parameter: str = "t") -> Axes:
    """The explicit curve (t, d(t)): control points (t_i, d_i), their hull, the band, the kept range. Notes §7.7.2.

    values: the d_i, (n+1,). The band dmin <= d <= dmax is shaded (an
    infinite dmin or dmax draws a half-plane, for the one-sided clips of
    rational curves); kept = (t_lo, t_hi) on the local [0, 1], or None, is
    marked on the parameter interval `interval` the explicit curve is drawn over,
    its range written in the top margin of the panel (clear of the lines).
    parameter names the abscissa (the x-axis label and the legend): "u" when
    the clipped curve is Q.
    """
    check_axes(ax)
    d = as_vector(values, "values")
    t0, t1 = (float(v) for v in as_vector(interval, "interval", dim=2))
    ts = np.linspace(t0, t1, len(d)) if len(d) > 1 else np.array([t0])
    top = max(d.max(), dmax if np.isfinite(dmax) else d.max())
    bottom = min(d.min(), dmin if np.isfinite(dmin) else d.min())
    room = 0.12 * max(top - bottom, 1e-12)
    # A half-plane is shaded to just beyond the points, on its own side of its edge.
    low = dmin if np.isfinite(dmin) else min(bottom, dmax) - room
    high = dmax if np.isfinite(dmax) else max(top, dmin) + room
    ax.axhspan(low, high, color=BAND_COLOR, alpha=0.16, label=_band_label(dmin, dmax, label))
    for level in (dmin, dmax):
        if np.isfinite(level):
            ax.axhline(level, color=BAND_COLOR, linestyle="--", linewidth=1.0)
    ax.axhline(0.0, color="0.6", linewidth=0.8)
    points = np.column_stack([ts, d])
    if hull and len(points) >= 3:
        ax.add_patch(Polygon(convex_hull(points), closed=True, facecolor=HULL_COLOR, alpha=0.15,
                             edgecolor=HULL_COLOR, linewidth=1.0, label="convex hull"))
    ax.plot(*points.T, **{**POLYGON_STYLE, "label": f"control points ({parameter}_i, {label}_i)"})
    if curve and len(d) > 1:
        s = np.linspace(0.0, 1.0, 200)
        ax.plot(t0 + (t1 - t0) * s, bernstein_horner(d, s), color="C0", linewidth=2.0,
                label=f"{label}({parameter})")
    if kept is not None:
        lo, hi = (t0 + (t1 - t0) * float(v) for v in kept)
        ax.axvspan(lo, hi, color=KEPT_COLOR, alpha=0.10)
        for v in (lo, hi):
            ax.axvline(v, color=KEPT_COLOR, linewidth=1.4)
        ax.annotate(f"kept [{lo:.4g}, {hi:.4g}]", ((lo + hi) / 2, 1.0), xycoords=("data", "axes fraction"),
                    xytext=(0, -3), textcoords="offset points", ha="center", va="top", fontsize=8, color=KEPT_COLOR,
                    bbox=dict(boxstyle="round,pad=0.15", facecolor="white", edgecolor="none", alpha=0.85))
    ax.set_xlim(t0 - 0.03 * (t1 - t0), t1 + 0.03 * (t1 - t0))
    # Room at the top for the kept range's label.
    ax.set_ylim(min(low, bottom) - room, max(high, top) + (3.5 if kept is not None else 2) * room)
    ax.set_xlabel(parameter)
    ax.set_ylabel(label)
    return ax


def _band_label(dmin: float, dmax: float, name: str = "d") -> str:
    if not np.isfinite(dmin):
        return f"{_number(dmax)} ≥ {name}"
    if not np.isfinite(dmax):
        return f"{name} ≥ {_number(dmin)}"
    return f"band [{_number(dmin)}, {_number(dmax)}]"


def _number(value: float) -> str:
    return f"{value:.4g}".replace("-", "−")  # a minus sign, not a hyphen


def plot_v_rule(ax, values, end: str = "left", color: str = "C3", label_meets: str = "all",
                label_points: bool = True) -> Axes:
    """The V rule: points E_i, the lines from the end point to each E_i and their meets V_i with the axis. Notes §7.7.8.

    values: the heights e_i = L · P_i, (n+1,); end "left" (lines E0 Ei) or
    "right" (En Ei). Each line is drawn from its end point to where it meets
    the axis and V_i is marked; label_meets "all" labels every V_i with its
    parameter, "clip" only the one the rule clips at (the left-most meet right
    of E0, or the right-most left of En), "none" none; label_points=False
    leaves the E_i unlabelled.
    """
    check_axes(ax)
    if label_meets not in ("all", "clip", "none"):
        raise ValueError(f"label_meets: expected 'all', 'clip' or 'none', got {label_meets!r}")
    points, lines, meets = explicit_meets(values, end)
    finite = meets[:, 2] != 0
    vs = meets[finite, 0] / meets[finite, 2]
    inside = vs[vs > 0] if end == "left" else vs[vs < 1]
    clip_at = (inside.min() if end == "left" else inside.max()) if len(inside) else None
    anchor = points[0] if end == "left" else points[-1]
    others = range(1, len(points)) if end == "left" else range(len(points) - 1)
    ax.axhline(0.0, color="0.5", linewidth=0.9)
    ax.plot(points[:, 0], points[:, 1], "o", color="k", markersize=5)
    if label_points:
        for i, p in enumerate(points):
            ax.annotate(f"$E_{{{i}}}$", p[:2], xytext=(4, 4), textcoords="offset points", fontsize=9)
    for k, (i, meet) in enumerate(zip(others, meets)):
        if meet[2] == 0:
            continue  # parallel to the axis: the meet is at infinity
        v = meet[0] / meet[2]
        ends = np.array([anchor[:2], [v, 0.0], points[i, :2]])
        span = ends[np.argsort(ends[:, 0])][[0, -1]]
        ax.plot(*span.T, color=color, linewidth=0.9, alpha=0.7)
        ax.plot(v, 0.0, "v", color=color, markersize=6)
        if label_meets == "none" or (label_meets == "clip" and v != clip_at):
            continue
        # The labels sit in three staggered rows along the bottom of the panel, joined to their meets by thin
        # leaders: next to the axis they would collide with each other and with the E_i labels.
        # (The leader is an annotation of its own, so that the label's extent is the text alone.)
        row = (v, 0.03 + 0.08 * (k % 3))
        ax.annotate("", (v, 0.0), xytext=row, textcoords=("data", "axes fraction"),
                    arrowprops=dict(arrowstyle="-", color=color, linewidth=0.5, alpha=0.6, shrinkA=10, shrinkB=3))
        ax.annotate(f"$V_{{{i}}}$={v:.4g}", row, xycoords=("data", "axes fraction"), fontsize=8, ha="center",
                    va="bottom", color=color)
    ax.set_xlabel("t")
    return ax


def plot_parameter_pairs(ax, steps, depth: int, found=None, color: str = "C0") -> Axes:
    """The pairs of parameter ranges a search examined at one depth, as rectangles in the (t, u) square. Notes §7.4.

    steps: SearchStep records (`intersection.search_steps`); pairs that were
    kept (split, clipped, found) are outlined, rejected ones faint; found:
    (k, 2) intersections drawn as stars.
    """
    check_axes(ax)
    boxes = {True: [], False: []}
    for step in steps:
        if step.depth == depth:
            (t0, t1), (u0, u1) = step.t_range, step.u_range
            t1, u1 = max(t1, t0 + 2e-3), max(u1, u0 + 2e-3)  # a converged pair still shows as a dot
            boxes[step.outcome == "rejected"].append([(t0, u0), (t1, u0), (t1, u1), (t0, u1)])
    # One collection per kind: hundreds of rectangles draw as fast as one.
    for rejected, shapes in boxes.items():
        if shapes:
            ax.add_collection(PolyCollection(shapes, facecolors="0.8" if rejected else color,
                                             edgecolors="0.6" if rejected else color, linewidths=0.6,
                                             alpha=0.35 if rejected else 0.3))
    if found is not None and len(found):
        ax.plot(*np.asarray(found).T, "*", color="C3", markersize=9)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_aspect("equal", adjustable="box")
    ax.set(xticks=[0, 0.5, 1], yticks=[0, 0.5, 1], xlabel="t (on P)", ylabel="u (on Q)")
    return ax


def plot_boxes(ax, point_sets, color: str = "C0", alpha: float = 0.12, label: str | None = None,
               edge_alpha: float | None = None, zorder: float | None = None, linestyle: str = "-") -> Axes:
    """The x-y bounding box of each set of control points (one (n+1, 2) array each): the boxes of §7.5-7.6.

    alpha is the opacity of the fill, and of the outline unless edge_alpha is
    given (a strong outline keeps small boxes visible); zorder above 2 draws
    the boxes over the curves; linestyle is that of the outline.
    """
    check_axes(ax)
    face = to_rgba(color, alpha)
    edge = to_rgba(color, alpha if edge_alpha is None else edge_alpha)
    for k, points in enumerate(point_sets):
        p = as_float_array(points, "point_sets")
        (x0, y0), (x1, y1) = p.min(axis=0), p.max(axis=0)
        ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, facecolor=face, edgecolor=edge, linewidth=0.8,
                               linestyle=linestyle, label=label if k == 0 else None,
                               **({} if zorder is None else {"zorder": zorder})))
    ax.autoscale_view()
    return finish_planar(ax)

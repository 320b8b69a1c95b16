"""B-spline figures in the notes' knot convention: polar labels, segment-coloured curves, knot-interval labels.

A degree-n B-spline with c control points has c + n - 1 knots and control
point i carries the polar label f(t_i, ..., t_(i+n-1)) (Notes §6.1-6.3). These
helpers draw such curves segment by segment, label their control points and de
Boor triangles, and hang knot intervals on the edges or vertices of a polygon
(Notes §6.13). Chapter 6 and its explorers draw with them.
"""

from __future__ import annotations

import numpy as np

from cagd_ref._validation import as_count, as_float_array, as_parameter, as_points
from cagd_ref.bspline import bezier_segment_intervals, bezier_segments, de_boor, degree, domain
from cagd_ref.knot_intervals import closed_to_open

from .curves import plot_control_polygon

__all__ = [
    "polar_label",
    "control_point_labels",
    "triangle_labels",
    "segment_samples",
    "closed_curve_points",
    "plot_bspline",
    "interval_label_positions",
    "plot_knot_intervals",
    "knot_label",
]

SEGMENT_COLORS = ("C0", "C3", "C2", "C1", "C4", "C9")
SEGMENT_SAMPLES = 40


def knot_label(value: float) -> str:
    """A knot value for a label: integers without a decimal point, others with up to three digits."""
    return f"{value:.3g}" if abs(value - round(value)) > 1e-9 else str(int(round(value)))


def polar_label(args, name: str = "P") -> str:
    """The text 'P(1,2,3)' for the polar value with arguments `args` (any sequence of numbers). Notes §6.1."""
    return f"{name}(" + ",".join(knot_label(a) for a in np.ravel(as_float_array(args, "args"))) + ")"


def control_point_labels(knots, degree: int, name: str = "P") -> list[str]:
    """Polar labels f(t_i, ..., t_(i+n-1)) of the c control points of a degree-n B-spline. Notes §6.1, §6.2.

    knots: (c+n-1,) in the notes' convention. Returns c strings.
    """
    kn = as_float_array(knots, "knots")
    n = as_count(degree, "degree", minimum=1)
    return [polar_label(kn[i : i + n], name) for i in range(len(kn) - n + 1)]


def triangle_labels(knots, degree: int, span: int, t: float) -> list[list[str]]:
    """Polar labels of the de Boor triangle at t on span j. Notes §6.8.

    Point i of level r is f(t^r, t_(j-n+1+i+r) ... t_(j+i)).

    Returns one list of strings per level (n+1-r labels on level r).
    """
    kn = as_float_array(knots, "knots")
    n = degree
    local = kn[span - n + 1 : span + n + 1]
    # Arguments are listed in increasing order: the polar form is symmetric, and sorted labels read best.
    return [[polar_label(sorted([t] * r + list(local[i + r : i + n]))) for i in range(n + 1 - r)] for r in range(n + 1)]


def segment_samples(points, knots, per_segment: int = SEGMENT_SAMPLES) -> tuple[np.ndarray, np.ndarray]:
    """Points of every segment of positive length: (intervals (s, 2), samples (s, per_segment, d)). Notes §6.3.

    All parameters go to `de_boor` in one call; each row of samples runs over one knot span.
    """
    pts = as_points(points)
    n = degree(pts, knots)
    intervals = bezier_segment_intervals(knots, n)
    u = np.linspace(0.0, 1.0, as_count(per_segment, "per_segment", minimum=2))
    ts = intervals[:, :1] + (intervals[:, 1:] - intervals[:, :1]) * u
    # Rounding can push the last sample a hair past the domain's end.
    a, b = domain(knots, n)
    curve = de_boor(pts, knots, np.clip(ts.ravel(), a, b))
    return intervals, curve.reshape(len(intervals), len(u), -1)


def closed_curve_points(points, intervals, degree: int, t) -> np.ndarray:
    """Points of a closed periodic B-spline with knot intervals (origin at the start of d_0), any t. Notes §6.5, §6.13.

    t is taken modulo the period sum(intervals), so two labellings of the same
    curve with the same origin can be compared at the same parameters.
    t: a number -> (d,), k numbers -> (k, d).
    """
    open_points, open_knots = closed_to_open(points, intervals, degree)
    a, b = domain(open_knots, degree)
    ts, scalar = as_parameter(t)
    values = de_boor(open_points, open_knots, a + np.mod(ts - a, b - a))
    return values[0] if scalar else values


# ---------------------------------------------------------------- drawing


def _point_labels(labels, points: np.ndarray, knots, n: int):
    """Resolve the `labels` option of `plot_bspline` into a list of strings (or False)."""
    if labels is True:
        return control_point_labels(knots, n)
    if labels == "index":
        return [f"$P_{{{i}}}$" for i in range(len(points))]
    return labels


def _knot_value_label(ax, text: str, where, tangent, polygon: np.ndarray) -> None:
    """Write a knot value beside the curve, on the side away from the nearest control point.

    The control points carry their own labels (up and to the right of each point), so a knot value
    written on the far side of the curve from the nearest one does not cover them.
    """
    where = np.asarray(where, dtype=float)
    tangent = np.asarray(tangent, dtype=float)
    length = np.hypot(*tangent)
    normal = np.array([-tangent[1], tangent[0]]) / length if length > 0 else np.array([0.0, -1.0])
    nearest = polygon[np.argmin(np.linalg.norm(polygon - where, axis=1))]
    if normal @ (where - nearest) < 0 or (normal @ (where - nearest) == 0 and normal[1] > 0):
        normal = -normal
    ha = "left" if normal[0] > 0.35 else "right" if normal[0] < -0.35 else "center"
    va = "bottom" if normal[1] > 0.35 else "top" if normal[1] < -0.35 else "center"
    ax.annotate(text, where, xytext=tuple(9 * normal), textcoords="offset points", fontsize=8, ha=ha, va=va)


def plot_bspline(ax, points, knots, labels=True, knot_marks: bool = True, knot_values: bool = True,
                 bezier_polygons: bool = False, colors=SEGMENT_COLORS, polygon_legend: str | None = "control polygon",
                 **style):
    """Draw a planar B-spline: its polygon, each segment in its own colour, the knots on the curve. Notes §6.2, §6.3.

    points: (c, 2); knots: (c+n-1,). labels: True (polar labels f(...)),
    "index" (P_0, P_1, ...), False, or c strings. `knot_marks` ticks the
    curve at the knots, `knot_values` writes t=... there. With `bezier_polygons` the
    Bézier control polygon of every segment is drawn too (dotted). `style`
    goes to the curve's lines. Returns ax.
    """
    pts = as_points(points)
    n = degree(pts, knots)
    plot_control_polygon(ax, pts, labels=_point_labels(labels, pts, knots, n), legend=polygon_legend)
    intervals, samples = segment_samples(pts, knots)
    for k, curve in enumerate(samples):
        color = colors[k % len(colors)]
        ax.plot(*curve.T, **{"color": color, "linewidth": 2.2, **style})
    if knot_marks:
        ax.plot(*np.vstack([samples[:, 0], samples[-1:, -1]]).T, "k|", markersize=9)
    if knot_marks and knot_values:
        places = [(span[0], curve[0], curve[1] - curve[0]) for span, curve in zip(intervals, samples)]
        places.append((intervals[-1, 1], samples[-1, -1], samples[-1, -1] - samples[-1, -2]))
        for value, where, tangent in places:
            _knot_value_label(ax, f"t={knot_label(value)}", where, tangent, pts)
    ax.margins(x=0.16, y=0.12)
    if bezier_polygons:
        for k, segment in enumerate(bezier_segments(pts, knots)):
            ax.plot(*segment.T, "s:", color=colors[k % len(colors)], markersize=3, linewidth=1, alpha=0.8)
    return ax


def interval_label_positions(points, intervals, degree: int | None = None) -> np.ndarray:
    """Where each knot interval belongs on the polygon: (m, 2), one row per interval. Notes §6.13.

    Odd degree: midpoints of edges; even degree: vertices. Open curves
    (degree=None, intervals = np.diff(knots)) hang their (n-1)//2 end-condition
    intervals on phantom edges or vertices continuing the first and last legs.
    Closed curves (degree=n): interval i sits on edge P_i P_(i+1) or vertex P_i.
    """
    pts = as_points(points)
    d = as_float_array(intervals, "intervals")
    if degree is not None:
        n = as_count(degree, "degree", minimum=1)
        return 0.5 * (pts + np.roll(pts, -1, axis=0)) if n % 2 else pts.copy()
    n = len(d) - len(pts) + 2
    extra = (n - 1) // 2
    # Phantom places are spaced along the end legs, continuing the polygon outwards.
    start_step, end_step = 0.5 * (pts[0] - pts[1]), 0.5 * (pts[-1] - pts[-2])
    ahead = np.arange(extra, 0, -1)[:, None]
    behind = np.arange(1, extra + 1)[:, None]
    if n % 2:
        inner = 0.5 * (pts[:-1] + pts[1:])
        return np.vstack([pts[0] + (ahead - 0.5) * start_step, inner, pts[-1] + (behind - 0.5) * end_step])
    return np.vstack([pts[0] + ahead * start_step, pts, pts[-1] + behind * end_step])


def _label_normals(places: np.ndarray, closed: bool) -> np.ndarray:
    """Unit normals (m, 2) to the polygon through the label places: outward when closed, to the left when open."""
    if closed:
        tangents = np.roll(places, -1, axis=0) - np.roll(places, 1, axis=0)
    else:
        tangents = np.gradient(places, axis=0)
    normals = np.column_stack([-tangents[:, 1], tangents[:, 0]])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    if closed:
        normals *= np.sign(np.einsum("ij,ij->i", normals, places - places.mean(axis=0)) + 1e-300)[:, None]
    return normals


def plot_knot_intervals(ax, points, intervals, degree: int | None = None, text_color: str = "C3", label: str = "d",
                        polygon: bool = True, side: float = 1.0, **style):
    """Draw a control polygon labelled with knot intervals d_i = value (closed if `degree` is given). Notes §6.13.

    Open curves: intervals = np.diff(knots), numbered from -((n-1)//2) as in
    the notes; phantom edges/vertices for the end-condition intervals are
    drawn dotted. `label` is the letter of the labels (None writes the bare
    numbers), written in `text_color` and pushed
    off the polygon along its normal (side=1: outwards or to the left, -1: the
    other way, so two labellings of one polygon stay apart); `style` goes to
    the polygon. Returns ax.
    """
    pts = as_points(points)
    d = as_float_array(intervals, "intervals")
    places = interval_label_positions(pts, d, degree)
    if polygon:
        ring = np.vstack([pts, pts[:1]]) if degree is not None else pts
        plot_control_polygon(ax, ring, labels=False, **style)
    if degree is None and len(places) > len(pts) - 1:
        ax.plot(*np.vstack([places[0], pts[0]]).T, ":", color="0.5")
        ax.plot(*np.vstack([pts[-1], places[-1]]).T, ":", color="0.5")
    offsets = 10 * side * _label_normals(places, degree is not None)
    # The notes number an open curve's intervals so that d_i sits on edge P_i P_(i+1) (or vertex P_i):
    # the end-condition intervals before P_0 get negative numbers.
    first = 0 if degree is not None else -((len(d) - len(pts) + 1) // 2)
    for i, (value, place, offset) in enumerate(zip(d, places, offsets), start=first):
        text = knot_label(value) if label is None else f"${label}_{{{i}}}$={knot_label(value)}"
        ax.annotate(text, place, xytext=offset, textcoords="offset points", fontsize=8, color=text_color,
                    ha="center", va="center")
    return ax

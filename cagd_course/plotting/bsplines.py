"""B-spline figures in the notes' knot convention: polar labels, segment-coloured curves, knot-interval labels.

A degree-n B-spline with c control points has c + n - 1 knots and control
point i carries the polar label P(t_i, ..., t_(i+n-1)) (Notes §6.1-6.3). These
helpers draw such curves segment by segment, label their control points and de
Boor triangles, and hang knot intervals on the edges or vertices of a polygon
(Notes §6.13). Chapter 6 and its explorers draw with them.
"""

from __future__ import annotations

import numpy as np
from matplotlib.transforms import Bbox

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
    "outward_directions",
    "label_points_outward",
    "place_labels",
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
    """Polar labels P(t_i, ..., t_(i+n-1)) of the c control points of a degree-n B-spline. Notes §6.1, §6.2.

    knots: (c+n-1,) in the notes' convention. Returns c strings.
    """
    kn = as_float_array(knots, "knots")
    n = as_count(degree, "degree", minimum=1)
    return [polar_label(kn[i : i + n], name) for i in range(len(kn) - n + 1)]


def triangle_labels(knots, degree: int, span: int, t: float) -> list[list[str]]:
    """Polar labels of the de Boor triangle at t on span j. Notes §6.8.

    Point i of level r is P(t^r, t_(j-n+1+i+r) ... t_(j+i)).

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


def outward_directions(points, closed: bool = False) -> np.ndarray:
    """Unit vectors (c, 2) pointing away from a planar polygon at each vertex: where a vertex label goes.

    At an inner vertex the direction is P_i minus the midpoint of its neighbours (the curve of a
    control polygon bends the other way); at the ends of an open polygon it continues the end leg
    outwards. Where a vertex lies on the line of its neighbours, the normal pointing away from the
    polygon's centre is used.
    """
    pts = as_points(points)
    if len(pts) < 2:
        return np.tile([0.0, 1.0], (len(pts), 1))
    before = np.roll(pts, 1, axis=0)
    after = np.roll(pts, -1, axis=0)
    if not closed:
        before[0], after[-1] = 2 * pts[0] - pts[1], 2 * pts[-1] - pts[-2]
    away = pts - 0.5 * (before + after)
    chord = after - before
    normal = np.column_stack([-chord[:, 1], chord[:, 0]])
    normal *= np.where(np.einsum("ij,ij->i", normal, pts - pts.mean(axis=0)) < 0, -1.0, 1.0)[:, None]
    flat = np.linalg.norm(away, axis=1) <= 1e-3 * np.maximum(np.linalg.norm(chord, axis=1), 1e-300)
    if not closed:  # the ends continue their legs outwards
        away[0], away[-1] = pts[0] - pts[1], pts[-1] - pts[-2]
        flat[[0, -1]] = np.linalg.norm(away[[0, -1]], axis=1) == 0
    direction = np.where(flat[:, None], normal, away)
    length = np.linalg.norm(direction, axis=1, keepdims=True)
    return np.where(length > 0, direction / np.where(length > 0, length, 1.0), [0.0, 1.0])


def _alignment(u: np.ndarray) -> tuple[str, str]:
    """Text alignment for a label placed in the direction u (unit vector) from its point."""
    ha = "left" if u[0] > 0.38 else "right" if u[0] < -0.38 else "center"
    va = "bottom" if u[1] > 0.38 else "top" if u[1] < -0.38 else "center"
    return ha, va


def label_points_outward(ax, points, labels, closed: bool = False, distance: float = 6.0, directions=None,
                         fontsize: float = 8, **style):
    """Write labels next to the vertices of a planar polygon, each on the side facing away from it. Notes §6.1.

    points: (c, 2); labels: c strings ("" skips a point). `directions` (c, 2) overrides the
    directions of `outward_directions` (in data units; rows of zeros keep the computed one).
    The directions are corrected for the axes' current scale, so they also work without an
    equal aspect. `style` goes to the texts (e.g. color). Returns ax.
    """
    pts = as_points(points)
    if len(labels) != len(pts):
        raise ValueError(f"labels: expected {len(pts)} strings, got {len(labels)}")
    u = outward_directions(pts, closed)
    if directions is not None:
        given = as_float_array(directions, "directions")
        if given.shape != pts.shape:
            raise ValueError(f"directions: expected shape {pts.shape}, got {given.shape}")
        keep = np.linalg.norm(given, axis=1) == 0
        u = np.where(keep[:, None], u, given)
    ax.autoscale_view()
    corner = ax.transData.transform(pts.mean(axis=0))
    scale = np.abs(ax.transData.transform(pts.mean(axis=0) + 1.0) - corner)
    scale = np.where(scale > 0, scale, 1.0)
    for text, point, vector in zip(labels, pts, u):
        if not text:
            continue
        screen = vector * scale
        screen /= max(np.linalg.norm(screen), 1e-300)
        ha, va = _alignment(screen)
        ax.annotate(text, point, xytext=tuple(distance * screen), textcoords="offset points", fontsize=fontsize,
                    ha=ha, va=va, **style)
    return ax


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
                 polygon_style: dict | None = None, **style):
    """Draw a planar B-spline: its polygon, each segment in its own colour, the knots on the curve. Notes §6.2, §6.3.

    points: (c, 2); knots: (c+n-1,). labels: True (polar labels P(...)),
    "index" (P_0, P_1, ...), False, or c strings. `knot_marks` ticks the
    curve at the knots, `knot_values` writes t=... there. With `bezier_polygons` the
    Bézier control polygon of every segment is drawn too (dotted). `polygon_style`
    (matplotlib line keywords) replaces the grey dashed look of the control polygon,
    e.g. to tell a new polygon from an old one; `style` goes to the curve's lines. Returns ax.
    """
    pts = as_points(points)
    n = degree(pts, knots)
    plot_control_polygon(ax, pts, labels=False, legend=polygon_legend, **(polygon_style or {}))
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
    names = _point_labels(labels, pts, knots, n)
    if names:
        label_points_outward(ax, pts, names)
    return ax


def _obstacle_pixels(ax, spacing: float = 2.5) -> np.ndarray:
    """Display-pixel points (m, 2) along every visible line and marker of ax, `spacing` px apart on lines."""
    found = [np.empty((0, 2))]
    for line in ax.get_lines():
        if not line.get_visible():
            continue
        xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
        xy = xy[np.all(np.isfinite(xy), axis=1)]
        if len(xy) == 0:
            continue
        found.append(xy)
        if line.get_linestyle() not in ("None", "", " ") and len(xy) > 1:
            steps = np.maximum(np.ceil(np.linalg.norm(np.diff(xy, axis=0), axis=1) / spacing), 1).astype(int)
            for start, end, count in zip(xy[:-1], xy[1:], steps):
                if count > 1:
                    found.append(start + np.linspace(0, 1, count + 1)[1:-1, None] * (end - start))
    return np.vstack(found)


def place_labels(ax, points, labels, prefer=None, distances=(5.0, 9.0, 14.0), fontsize: float = 8, candidates=None,
                 **style):
    """Write labels next to points where they cover the fewest lines, markers and other labels. Notes §6.

    For every label, 16 directions at each of `distances` (points) are tried, in turn, and the
    place whose box covers the fewest drawn line pixels and markers of `ax` wins; any overlap with a
    text already on `ax` (or inside the axes' frame edge) rules a place out when another is free.
    `prefer` (c, 2) gives, per point, a direction to favour on ties (e.g. `outward_directions`);
    `candidates` (c, k, 2) replaces the 16 directions by k unit vectors (data units) per point.
    Call it after everything else is drawn and the limits are set. Returns ax.
    """
    pts = as_points(points)
    if len(labels) != len(pts):
        raise ValueError(f"labels: expected {len(pts)} strings, got {len(labels)}")
    fig = ax.figure
    ax.get_xlim()  # settles pending autoscaling
    ax.apply_aspect()  # and the box an equal aspect asks for: the data transform is final
    renderer = fig.canvas.get_renderer()
    obstacles = _obstacle_pixels(ax)
    frame = ax.get_window_extent(renderer)
    taken = [t.get_window_extent(renderer) for t in ax.texts if t.get_visible() and t.get_text().strip()]
    angles = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    unit = np.column_stack([np.cos(angles), np.sin(angles)])
    prefer_u = np.zeros_like(pts) if prefer is None else as_float_array(prefer, "prefer")
    pixels_per_point = fig.dpi / 72.0
    per_point = None if candidates is None else as_float_array(candidates, "candidates")
    to_screen = np.abs(ax.transData.transform(pts.mean(axis=0) + 1.0) - ax.transData.transform(pts.mean(axis=0)))
    for number, (text, point, favour) in enumerate(zip(labels, pts, prefer_u)):
        if not text:
            continue
        if per_point is not None:  # the caller's directions, turned into screen directions
            unit = per_point[number] * to_screen
            unit = unit / np.maximum(np.linalg.norm(unit, axis=1, keepdims=True), 1e-300)
        # The label's size does not depend on where it goes: measure it once.
        probe = ax.annotate(text, point, fontsize=fontsize, **style)
        size = probe.get_window_extent(renderer)
        probe.remove()
        width, height = size.width, size.height
        anchor = ax.transData.transform(point)
        best, best_score = None, np.inf
        for distance in distances:
            for u in unit:
                ha, va = _alignment(u)
                x = anchor[0] + distance * u[0] * pixels_per_point
                y = anchor[1] + distance * u[1] * pixels_per_point
                x0 = x - {"left": 0.0, "center": 0.5, "right": 1.0}[ha] * width
                y0 = y - {"bottom": 0.0, "center": 0.5, "top": 1.0}[va] * height
                box = Bbox.from_bounds(x0, y0, width, height)
                inside = ((obstacles[:, 0] >= box.x0 - 1) & (obstacles[:, 0] <= box.x1 + 1)
                          & (obstacles[:, 1] >= box.y0 - 1) & (obstacles[:, 1] <= box.y1 + 1))
                clash = sum(box.overlaps(other) for other in taken)
                outside = not (frame.x0 + 2 <= box.x0 and box.x1 <= frame.x1 - 2
                               and frame.y0 + 2 <= box.y0 and box.y1 <= frame.y1 - 2)
                liking = float(u @ favour) / max(float(np.linalg.norm(favour)), 1e-300)
                score = 1000 * (clash + outside) + np.count_nonzero(inside) + 0.08 * distance - 0.5 * liking
                if score < best_score:
                    best, best_score, best_box = (tuple(distance * u), ha, va), score, box
            if best_score < 1:  # a clean place at this distance: do not go farther
                break
        offset, ha, va = best
        ax.annotate(text, point, xytext=offset, textcoords="offset points", fontsize=fontsize, ha=ha, va=va,
                    **style)
        taken.append(best_box)
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


def _label_normals(places: np.ndarray, closed: bool, points: np.ndarray | None = None) -> np.ndarray:
    """Unit normals (m, 2) to the polygon through the label places, pointing away from the polygon.

    Closed: away from its centre. Open: to the side the neighbouring vertices' labels face
    (`outward_directions` of `points`), so interval labels and point labels stay off the curve.
    """
    if closed:
        tangents = np.roll(places, -1, axis=0) - np.roll(places, 1, axis=0)
    else:
        tangents = np.gradient(places, axis=0)
    normals = np.column_stack([-tangents[:, 1], tangents[:, 0]])
    normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
    if closed:
        normals *= np.sign(np.einsum("ij,ij->i", normals, places - places.mean(axis=0)) + 1e-300)[:, None]
    elif points is not None and len(points) > 1:
        nearest = np.argsort(np.linalg.norm(places[:, None] - points[None], axis=2), axis=1)[:, :2]
        hint = outward_directions(points)[nearest].sum(axis=1)
        normals *= np.where(np.einsum("ij,ij->i", normals, hint) < 0, -1.0, 1.0)[:, None]
    return normals


def plot_knot_intervals(ax, points, intervals, degree: int | None = None, text_color: str = "C3", label: str = "d",
                        polygon: bool = True, side: float = 1.0, **style):
    """Draw a control polygon labelled with knot intervals d_i = value (closed if `degree` is given). Notes §6.13.

    Open curves: intervals = np.diff(knots), numbered from -((n-1)//2) as in
    the notes; phantom edges/vertices for the end-condition intervals are
    drawn dotted. `label` is the letter of the labels (None writes the bare
    numbers), written in `text_color` and pushed
    off the polygon along its normal (side=1: outwards, away from the curve,
    -1: the other way, so two labellings of one polygon stay apart); `style`
    goes to the polygon. Returns ax.
    """
    pts = as_points(points)
    d = as_float_array(intervals, "intervals")
    places = interval_label_positions(pts, d, degree)
    if polygon:
        ring = np.vstack([pts, pts[:1]]) if degree is not None else pts
        plot_control_polygon(ax, ring, labels=False, **style)
    if degree is None and len(places) > len(pts) - 1:
        # Phantom edges (or the steps to phantom vertices) are half as long as the end leg they continue:
        # draw them dotted out to the last phantom vertex (a small circle), well past the end point's label.
        extra = (len(d) - len(pts) + 1) // 2
        outer_start = pts[0] + extra * 0.5 * (pts[0] - pts[1])
        outer_end = pts[-1] + extra * 0.5 * (pts[-1] - pts[-2])
        for end, outer in ((pts[0], outer_start), (pts[-1], outer_end)):
            ax.plot(*np.vstack([end, outer]).T, ":", color="0.35", linewidth=1.4)
            ax.plot(*outer, "o", color="0.35", markersize=3.5, markerfacecolor="white")
    normals = _label_normals(places, degree is not None, pts)
    # The notes number an open curve's intervals so that d_i sits on edge P_i P_(i+1) (or vertex P_i):
    # the end-condition intervals before P_0 get negative numbers.
    first = 0 if degree is not None else -((len(d) - len(pts) + 1) // 2)
    texts = [knot_label(value) if label is None else f"${label}_{{{i}}}$={knot_label(value)}"
             for i, value in enumerate(d, start=first)]
    if degree is None:  # open: each label on the side of its edge where it covers least
        both_sides = np.stack([side * normals, -side * normals], axis=1)
        return place_labels(ax, places, texts, prefer=side * normals, distances=(7.0, 11.0), candidates=both_sides,
                            color=text_color)
    for text, place, normal in zip(texts, places, normals):
        ax.annotate(text, place, xytext=tuple(10 * side * normal), textcoords="offset points", fontsize=8,
                    color=text_color, ha="center", va="center")
    return ax

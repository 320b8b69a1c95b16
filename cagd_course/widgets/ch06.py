"""Explorers of chapter 6 of the notes (B-spline curves), and the drawing helpers they share with the chapter.

The helpers draw a B-spline in the notes' knot convention (c + n - 1 knots,
control point i labelled P(t_i, ..., t_(i+n-1))): the curve segment by
segment, polar labels on the control points, knot-interval labels on the
edges or vertices of the polygon. The explorers use them for the knot vector,
the de Boor triangle, knot insertion, interval splitting and local control.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np

from cagd_ref._validation import as_count, as_float_array, as_points
from cagd_ref.bspline import (
    basis_matrix,
    bezier_end_knots,
    bezier_segment_intervals,
    bezier_segments,
    continuity_at_knots,
    de_boor,
    de_boor_triangle,
    degree,
    domain,
    insert_knot,
    knot_multiplicities,
)
from cagd_ref.knot_intervals import split_interval

from ..examples import notes_example
from ..plotting.bsplines import (
    closed_curve_points,
    control_point_labels,
    knot_label,
    label_points_outward,
    outward_directions,
    place_labels,
    plot_bspline,
    plot_knot_intervals,
    segment_samples,
    triangle_labels,
)
from ..plotting.curves import plot_control_polygon
from ._base import Explorer, TwoPanels, _control_points, _fmt, _slider, bare_axes

__all__ = [
    "splitting_construction",
    "knot_vector_editor",
    "de_boor_explorer",
    "knot_insertion_explorer",
    "knot_interval_explorer",
    "local_control_explorer",
    "KnotVectorEditor",
    "DeBoorExplorer",
    "KnotInsertionExplorer",
    "KnotIntervalExplorer",
    "LocalControlExplorer",
]

# A wavy open polygon of eight points: a cubic over it has five segments with Bézier end knots.
CHAPTER_POINTS = np.array(
    [[0.0, 0.0], [1.0, 2.2], [3.0, 3.0], [4.5, 0.8], [6.5, 0.5], [8.0, 2.8], [10.0, 3.2], [11.0, 0.8]]
)
CHAPTER_KNOTS = bezier_end_knots(len(CHAPTER_POINTS), 3)
# A closed pentagon of our own with the knot intervals 3, 1, 2, 2, 1 of the notes' splitting example (Figure 6.15).
PENTAGON = np.array([[0.0, 0.0], [4.0, -0.5], [5.5, 2.5], [2.5, 5.0], [-1.0, 3.0]])
PENTAGON_INTERVALS = notes_example("06.interval_splitting").inputs["intervals"]
BASIS_SAMPLES = 301
# The polygon after knot insertion, drawn over the old grey dashed one (the chapter's figure uses the same).
NEW_POLYGON_STYLE = {"color": "0.15", "linestyle": "-", "linewidth": 1.1, "markersize": 4}
SAME_CURVE_TOL = 1e-9


# ---------------------------------------------------------------- knot vector editor


def _merge_knots(values: list[float], multiplicity: int) -> list[float]:
    """Slider knots u1..uk with u2 repeated `multiplicity` times: its copies replace u3, u4, ..., then u1."""
    if len(values) < 2:
        return list(values)
    order = [1] + list(range(2, len(values))) + [0]
    merged = list(values)
    for slot in order[1:multiplicity]:
        merged[slot] = values[1]
    return sorted(merged)


class KnotVectorEditor(TwoPanels, Explorer):
    """Interior knots on sliders and a multiplicity: curve, Bézier segments, basis functions. Notes §6.2-6.4, §6.14."""

    def __init__(self, points=None, degree: int = 3):
        self.points = _control_points(points, CHAPTER_POINTS)
        self.degree = as_count(degree, "degree", minimum=1)
        count = len(self.points) - self.degree - 1
        if count < 2:
            raise ValueError(
                f"points: the editor needs at least {self.degree + 3} control points for degree {self.degree}, "
                f"got {len(self.points)}"
            )
        self.end = float(count + 1)
        controls = {
            f"u{k}": _slider(widgets.FloatSlider, f"u{k}", min=0.05, max=self.end - 0.05, step=0.05, value=float(k))
            for k in range(1, count + 1)
        }
        controls["multiplicity"] = widgets.Dropdown(description="mult. of u2", options=list(range(1, self.degree + 1)),
                                                    value=1)
        controls["spacing"] = widgets.Dropdown(description="spacing", options=["sliders", "uniform"], value="sliders")
        super().__init__(controls)

    def knots_for(self, values: dict) -> np.ndarray:
        """The knot vector the controls describe: n-fold end knots 0 and `end`, interior knots from the sliders."""
        slots = range(1, len(self.points) - self.degree)
        uniform = values["spacing"] == "uniform"
        inner = _merge_knots([float(k) if uniform else values[f"u{k}"] for k in slots], values["multiplicity"])
        n = self.degree
        return np.concatenate([np.zeros(n), inner, np.full(n, self.end)])

    def compute(self, **values) -> dict:
        knots = self.knots_for(values)
        try:
            joints, orders = continuity_at_knots(knots, self.degree)
        except ValueError as err:
            # Name the controls that made the bad knot vector, not the internal argument.
            raise ValueError(f"u1..u{len(self.points) - self.degree - 1}, multiplicity: {err}") from None
        ts = np.linspace(0.0, self.end, BASIS_SAMPLES)
        intervals, samples = segment_samples(self.points, knots)
        return {
            "knots": knots,
            "joints": joints,
            "continuity": orders,
            "intervals": intervals,
            "curve": samples,
            "segments": bezier_segments(self.points, knots),
            "ts": ts,
            "basis": basis_matrix(knots, self.degree, ts),
            "uniform": bool(np.ptp(np.diff(np.unique(knots))) < 1e-9),
        }

    def draw(self, ax, state: dict) -> None:
        plot_bspline(ax, self.points, state["knots"], labels=False, bezier_polygons=True)
        ax.set_title("knots " + "[" + ", ".join(knot_label(k) for k in state["knots"]) + "]", fontsize=9)
        lower = self.lower_axes()
        lower.set_prop_cycle(None)  # the same colour for B_i on every redraw
        lower.plot(state["ts"], state["basis"], linewidth=1.3)
        values, counts = knot_multiplicities(state["knots"])
        lower.vlines(values, 0, 1.05, color="0.7", linewidth=0.8, zorder=0)
        for value, count in zip(values[1:-1], counts[1:-1]):
            if count > 1:
                lower.annotate(f"×{count}", (value, 1.05), fontsize=8, ha="center")
        lower.set_xlim(0, self.end)
        lower.set_ylim(0, 1.15)
        lower.set_yticks([0, 1])
        last = len(self.points) - 1
        lower.set_xlabel(f"t   (basis functions $N_0^{self.degree}$ ... $N_{{{last}}}^{self.degree}$, left to right)",
                         fontsize=8)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        joints = ", ".join(f"t={knot_label(v)}: C<sup>{k}</sup>" for v, k in zip(state["joints"], state["continuity"]))
        spacing = "uniform" if state["uniform"] else "non-uniform"
        return f"{spacing} knots; {len(state['segments'])} Bézier segments<br>{joints}"


def knot_vector_editor(points=None, degree: int = 3) -> KnotVectorEditor:
    """Sliders u1.. for the interior knots, a multiplicity for u2 and a uniform-spacing switch. Notes §6.2-6.4.

    points: (c, 2), default eight points; degree n (c >= n + 3). The knots
    are n copies of 0, the sorted interior knots, n copies of c - n
    (Bézier end conditions). Multiplicity m repeats u2 m times, its copies
    taking the places of u3, u4, ... and then u1. `update` returns {"knots",
    "joints", "continuity" (order at each interior knot), "intervals" (s, 2),
    "curve" (s, 40, 2), "segments" (s, n+1, 2), "ts", "basis" (301, c), "uniform"}.
    """
    return KnotVectorEditor(points, degree)


# ---------------------------------------------------------------- de Boor


def _spline_inputs(points, knots) -> tuple[np.ndarray, np.ndarray, int]:
    """Planar control points (c, 2), knots (notes' convention) and degree; default: the chapter's cubic."""
    pts = _control_points(points, CHAPTER_POINTS)
    kn = CHAPTER_KNOTS.copy() if knots is None else as_float_array(knots, "knots")
    return pts, kn, degree(pts, kn)


class DeBoorExplorer(Explorer):
    """The de Boor triangle at t: the span's n+1 control points, each level of affine combinations, P(t). Notes §6.8."""

    figsize = (6.5, 4.8)

    def __init__(self, points=None, knots=None):
        self.points, self.knots, self.degree = _spline_inputs(points, knots)
        a, b = domain(self.knots, self.degree)
        t = _slider(widgets.FloatSlider, "t", min=a, max=b, step=0.01, value=round(0.4 * a + 0.6 * b, 2),
                    readout_format=".2f")
        step = _slider(widgets.IntSlider, "levels", min=0, max=self.degree, value=self.degree)
        super().__init__({"t": t, "step": step})

    def compute(self, t: float, step: int) -> dict:
        levels, span = de_boor_triangle(self.points, self.knots, t)
        return {
            "t": t,
            "step": step,
            "span": span,
            "levels": levels,
            "point": levels[-1][0],
            "labels": triangle_labels(self.knots, self.degree, span, t),
        }

    def draw(self, ax, state: dict) -> None:
        plot_bspline(ax, self.points, self.knots, labels=False, knot_values=False, alpha=0.45)
        step = state["step"]
        for r, level in enumerate(state["levels"][: step + 1]):
            style = {"marker": "o", "markersize": 4 + (r == 0) * 2, "linewidth": 1.4 if r else 2.5}
            legend = {0: "the span's control points", 1: "levels 1, 2, ..."}.get(r)
            ax.plot(*level.T, color=f"C{(r + 4) % 10}", label=legend, **style)
        if step == self.degree:
            ax.plot(*state["point"], "k*", markersize=13, label=f"P({state['t']:.2f})")
        j = state["span"]
        span = f"[{knot_label(self.knots[j])}, {knot_label(self.knots[j + 1])}]"
        ax.set_title(f"de Boor at t = {state['t']:.2f}, span {span}", fontsize=10)
        ax.legend(fontsize=8, loc="lower center", ncol=3)
        bare_axes(ax)
        # Only the span's points and the newest level are labelled (deeper levels crowd near the curve),
        # each label where it covers the fewest lines.
        first = state["levels"][0]
        place_labels(ax, first, state["labels"][0], prefer=outward_directions(first))
        if step:
            place_labels(ax, state["levels"][step], state["labels"][step])

    def describe(self, state: dict) -> str:
        return f"P({state['t']:.2f}) = {_fmt(state['point'])}"


def de_boor_explorer(points=None, knots=None) -> DeBoorExplorer:
    """Slider `t` over the domain and `step` (levels shown, 0..n): the de Boor triangle with polar labels. Notes §6.8.

    points: (c, 2), knots: (c+n-1,) in the notes' convention (default the
    chapter's cubic). `update` returns {"t", "span" j (t in [t_j, t_(j+1)]),
    "step", "levels" (list, level r of shape (n+1-r, 2), all n+1 of them),
    "point" (2,), "labels" (polar label strings per level)}. The drawing shows
    levels 0..step and labels level 0 and level `step`.
    """
    return DeBoorExplorer(points, knots)


# ---------------------------------------------------------------- knot insertion


def _new_label_indices(old_knots: np.ndarray, new_knots: np.ndarray, n: int) -> np.ndarray:
    """Indices of the control points whose polar labels did not exist before the insertion."""
    old = {tuple(old_knots[i : i + n]) for i in range(len(old_knots) - n + 1)}
    return np.array([i for i in range(len(new_knots) - n + 1) if tuple(new_knots[i : i + n]) not in old], dtype=int)


class KnotInsertionExplorer(Explorer):
    """Boehm's knot insertion, once or repeatedly at one t: old and new polygons, one unchanged curve. Notes §6.7."""

    figsize = (6.5, 4.8)

    def __init__(self, points=None, knots=None):
        self.points, self.knots, self.degree = _spline_inputs(points, knots)
        a, b = domain(self.knots, self.degree)
        self.check_ts = np.linspace(a, b, 97)
        self.curve = de_boor(self.points, self.knots, self.check_ts)
        t = _slider(widgets.FloatSlider, "t", min=a, max=b, step=0.01, value=round(0.55 * a + 0.45 * b, 2),
                    readout_format=".2f")
        times = _slider(widgets.IntSlider, "times", min=1, max=self.degree, value=1)
        super().__init__({"t": t, "times": times})

    def compute(self, t: float, times: int) -> dict:
        room = self.degree - int(np.count_nonzero(self.knots == t))
        points, knots = self.points, self.knots
        for _ in range(min(times, room)):
            points, knots = insert_knot(points, knots, t)
        full = room - min(times, room) == 0
        return {
            "t": t,
            "inserted": min(times, room),
            "old_points": self.points.copy(),
            "old_knots": self.knots.copy(),
            "points": points,
            "knots": knots,
            "new": _new_label_indices(self.knots, knots, self.degree),
            "deviation": float(np.abs(de_boor(points, knots, self.check_ts) - self.curve).max()),
            "point": _exposed_point(points, knots, self.degree, t) if full else None,
        }

    def draw(self, ax, state: dict) -> None:
        # The old polygon grey and dashed, the new one solid and dark: the two are told apart at a glance.
        ax.plot(*self.points.T, "o--", color="0.6", markersize=5, linewidth=1, label="old polygon")
        plot_bspline(ax, state["points"], state["knots"], labels=False, knot_values=False, polygon_legend="new polygon",
                     polygon_style=NEW_POLYGON_STYLE, alpha=0.8)
        new = state["points"][state["new"]]
        ax.plot(*new.T, "o", color="C3", markersize=8, markerfacecolor="white", markeredgewidth=2, label="new points")
        labels = control_point_labels(state["knots"], self.degree)
        if state["point"] is not None:
            ax.plot(*state["point"], "k*", markersize=12, label=f"P({state['t']:.2f}) exposed")
        ax.set_title(f"inserting t = {state['t']:.2f} {state['inserted']}×; curve moved by {state['deviation']:.1e}",
                     fontsize=10)
        ax.legend(fontsize=8, loc="lower center", ncol=2)
        bare_axes(ax)
        # New points lie close together: each label goes where it covers the fewest lines.
        place_labels(ax, state["points"][state["new"]], [labels[i] for i in state["new"]], color="C3")

    def describe(self, state: dict) -> str:
        knots = ", ".join(knot_label(k) for k in state["knots"])
        allowed = f" (t already a knot: only {state['inserted']} more allowed)"
        note = "" if state["inserted"] == self.values["times"] else allowed
        return f"new knots [{html.escape(knots)}]{note}"


def _exposed_point(points: np.ndarray, knots: np.ndarray, n: int, t: float) -> np.ndarray:
    """The control point labelled P(t, ..., t), which exists once t is an n-fold knot: it is the curve point P(t)."""
    labels = knots[np.arange(len(points))[:, None] + np.arange(n)]
    return points[np.flatnonzero(np.all(labels == t, axis=1))[0]]


def knot_insertion_explorer(points=None, knots=None) -> KnotInsertionExplorer:
    """Slider `t` for the new knot and `times` (1..n): insert t that many times (as multiplicity allows). Notes §6.7.

    `update` returns {"t", "inserted", "old_points", "old_knots", "points",
    "knots", "new" (indices of the points with new polar labels), "deviation"
    (largest change of the curve over 97 parameters, ~1e-15), "point" (the curve
    point P(t), once t has multiplicity n; else None)}.
    """
    return KnotInsertionExplorer(points, knots)


# ---------------------------------------------------------------- knot intervals


def splitting_construction(points, intervals, index: int, fraction: float) -> tuple[np.ndarray, np.ndarray]:
    """The notes' ruler construction for splitting interval `index` of a closed cubic. Notes §6.13.1, Fig. 6.16.

    Each of the edges P_(q-1)P_q, P_qP_(q+1), P_(q+1)P_(q+2) is cut into three
    parts in the ratio d_(i-1) : d_i : d_(i+1) of its neighbouring intervals;
    the part belonging to d_q is then cut at `fraction`. Returns (the cut
    points (3, 2, 2): for each edge the ends of the d_q part, the new points (3, 2)).
    """
    pts = as_points(points)
    d = as_float_array(intervals, "intervals")
    c, q = len(pts), index
    edges = np.arange(q - 1, q + 2) % c
    before, own, after = d[(edges - 1) % c], d[edges], d[(edges + 1) % c]
    total = before + own + after
    start, end = pts[edges], pts[(edges + 1) % c]
    cut = np.stack([before / total, (before + own) / total], axis=1)
    ends = start[:, None] + cut[..., None] * (end - start)[:, None]
    # The d_q part is the last third of the first edge, the middle of the second, the first of the third.
    part = ends.copy()
    part[0] = [ends[0, 1], end[0]]
    part[2] = [start[2], ends[2, 0]]
    new = part[:, 0] + fraction * (part[:, 1] - part[:, 0])
    return part, new


class KnotIntervalExplorer(Explorer):
    """A closed cubic labelled with knot intervals; split one interval at a fraction (knot insertion). Notes §6.13.1."""

    figsize = (6.5, 5.2)

    def __init__(self, points=None, intervals=None):
        self.points = _control_points(points, PENTAGON, min_count=4)
        self.intervals = PENTAGON_INTERVALS.copy() if intervals is None else as_float_array(intervals, "intervals")
        self.degree = 3
        period = self.intervals.sum()
        self.check_ts = np.linspace(0.0, period, 101)
        self.curve = closed_curve_points(self.points, self.intervals, self.degree, self.check_ts)
        index = widgets.Dropdown(description="interval", options=list(range(len(self.points))), value=0)
        fraction = _slider(widgets.FloatSlider, "fraction", min=0.0, max=1.0, step=0.01, value=1 / 3,
                           readout_format=".2f")
        super().__init__({"index": index, "fraction": fraction})

    def compute(self, index: int, fraction: float) -> dict:
        points, intervals = split_interval(self.points, self.intervals, index, fraction, degree=self.degree)
        part, construction = splitting_construction(self.points, self.intervals, index, fraction)
        after = closed_curve_points(points, intervals, self.degree, self.check_ts)
        return {
            "index": index,
            "fraction": fraction,
            "points": points,
            "intervals": intervals,
            "parts": part,
            "construction": construction,
            "deviation": float(np.abs(after - self.curve).max()),
        }

    def draw(self, ax, state: dict) -> None:
        ax.plot(*self.curve.T, color="C0", linewidth=2, label="curve (unchanged)")
        plot_knot_intervals(ax, self.points, self.intervals, self.degree, text_color="0.3", label=None, color="0.6")
        for start, end in state["parts"]:
            ax.plot(*np.array([start, end]).T, color="C3", linewidth=4, alpha=0.35)
        ring = np.vstack([state["points"], state["points"][:1]])
        ax.plot(*ring.T, "o-", color="C2", markersize=4, linewidth=1.2, label="after splitting")
        ax.plot(*state["construction"].T, "o", color="C3", markersize=8, markerfacecolor="white", markeredgewidth=2,
                label="new points (construction)")
        plot_knot_intervals(ax, state["points"], state["intervals"], self.degree, text_color="C2", label=None,
                            polygon=False, side=-1)
        d = self.intervals[state["index"]]
        ax.set_title(f"split $d_{state['index']}$ = {knot_label(d)} into {knot_label(state['fraction'] * d)} + "
                     f"{knot_label((1 - state['fraction']) * d)}", fontsize=10)
        ax.legend(fontsize=8, loc="upper right")
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        values = ", ".join(knot_label(v) for v in state["intervals"])
        return f"intervals ({values}); curve moved by {state['deviation']:.1e}"


def knot_interval_explorer(points=None, intervals=None) -> KnotIntervalExplorer:
    """Dropdown `index` and slider `fraction`: split a knot interval of a closed periodic cubic. Notes §6.13.1.

    points: (c, 2), intervals: (c,), one per edge (default a pentagon with
    intervals 3, 1, 2, 2, 1). `update` returns {"index", "fraction", "points"
    (c+1, 2), "intervals" (c+1,), "parts" (3, 2, 2: the pieces of the three
    edges that belong to the split interval), "construction" (3, 2: the points
    the ruler construction gives, equal to the new points), "deviation"}.
    """
    return KnotIntervalExplorer(points, intervals)


# ---------------------------------------------------------------- local control


class LocalControlExplorer(Explorer):
    """Move one control point: only the segments whose span lies in its support change. Notes §6.3, §6.14."""

    figsize = (6.5, 4.8)

    def __init__(self, points=None, knots=None):
        self.points, self.knots, self.degree = _spline_inputs(points, knots)
        self.segments = bezier_segments(self.points, self.knots)
        self.intervals = bezier_segment_intervals(self.knots, self.degree)
        controls = {
            "index": widgets.Dropdown(description="point", options=list(range(len(self.points))),
                                      value=len(self.points) // 2),
            "dx": _slider(widgets.FloatSlider, "dx", min=-3.0, max=3.0, step=0.05, value=0.0),
            "dy": _slider(widgets.FloatSlider, "dy", min=-3.0, max=3.0, step=0.05, value=1.5),
        }
        super().__init__(controls)

    def support(self, index: int) -> tuple[float, float]:
        """Parameter interval (t_(i-1), t_(i+n)) ∩ domain where control point i has influence."""
        n, kn = self.degree, self.knots
        a, b = domain(kn, n)
        low = kn[index - 1] if index >= 1 else a
        high = kn[index + n] if index + n < len(kn) else b
        return max(low, a), min(high, b)

    def compute(self, index: int, dx: float, dy: float) -> dict:
        moved = self.points.copy()
        moved[index] += (dx, dy)
        segments = bezier_segments(moved, self.knots)
        changed = np.flatnonzero(np.abs(segments - self.segments).max(axis=(1, 2)) > SAME_CURVE_TOL)
        return {"index": index, "points": moved, "segments": segments, "changed": changed,
                "support": self.support(index)}

    def draw(self, ax, state: dict) -> None:
        _, old = segment_samples(self.points, self.knots)
        _, new = segment_samples(state["points"], self.knots)
        for curve in old:
            ax.plot(*curve.T, color="0.75", linewidth=3)
        for k, curve in enumerate(new):
            moved = k in state["changed"]
            ax.plot(*curve.T, color="C3" if moved else "C0", linewidth=2.2)
        ax.plot(*np.vstack([new[:, 0], new[-1:, -1]]).T, "k|", markersize=9)
        plot_control_polygon(ax, state["points"], labels=False)
        label_points_outward(ax, state["points"], [f"$P_{{{i}}}$" for i in range(len(self.points))], fontsize=10)
        ax.plot(*self.points[state["index"]], "o", color="0.6", markersize=7)
        ax.plot(*state["points"][state["index"]], "o", color="C3", markersize=9)
        ax.plot([], [], color="C3", label="changed segments")
        ax.plot([], [], color="C0", label="unchanged segments")
        ax.plot([], [], color="0.75", linewidth=3, label="before")
        a, b = state["support"]
        ax.set_title(f"moving $P_{{{state['index']}}}$ changes {len(state['changed'])} of {len(self.segments)} "
                     f"segments, t in [{knot_label(a)}, {knot_label(b)}]", fontsize=10)
        ax.legend(fontsize=8, loc="lower center", ncol=3)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        spans = ", ".join(f"[{knot_label(a)}, {knot_label(b)}]" for a, b in self.intervals[state["changed"]])
        return f"changed segments: {spans or 'none'}"


def local_control_explorer(points=None, knots=None) -> LocalControlExplorer:
    """Dropdown `index` and sliders `dx`, `dy`: displace one control point and see which segments move. Notes §6.3.

    `update` returns {"index", "points", "segments" (s, n+1, 2), "changed"
    (indices of the segments that moved: at most n+1 consecutive ones),
    "support" (the parameter interval (t_(i-1), t_(i+n)) clipped to the domain)}.
    """
    return LocalControlExplorer(points, knots)

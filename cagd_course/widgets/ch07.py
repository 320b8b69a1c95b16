"""Explorers of chapter 7 of the notes (curve intersection).

Bézout's count of intersections with the points at infinity and the complex
ones, a lab for clipping one explicit curve against a band (the exact hull,
the control polygon and the notes' V rule side by side), a stepper through the
Bézier-clipping search of two curves, and a comparison of the pairs of pieces
that Bézier subdivision, interval subdivision and Bézier clipping examine.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np

from cagd_course.examples import notes_example
from cagd_ref.bezier import evaluate
from cagd_ref.intersection import (
    circle_conic,
    clip_one_sided,
    clip_range,
    clip_trace,
    curve_piece,
    implicit_polynomial,
    intersect_curves,
    search_steps,
)
from cagd_ref.polynomials import bernstein_horner

from ..plotting.clipping import picture_extent, plot_explicit_clip, plot_fat_line, plot_parameter_pairs
from ..plotting.curves import plot_bezier, plot_control_polygon
from ._base import Explorer, _slider, _swatch

__all__ = [
    "bezout_explorer",
    "clip_lab_explorer",
    "clipping_explorer",
    "subdivision_comparison_explorer",
    "polygon_clip",
    "BezoutExplorer",
    "ClipLabExplorer",
    "ClippingExplorer",
    "SubdivisionComparisonExplorer",
]

P_COLOR, Q_COLOR = "C0", "C4"


def _pair(name: str) -> dict:
    """Curves p, q (and weights) of a worked example of chapter 7."""
    example = notes_example(f"07.{name}")
    pair = {"p": example.inputs["p"], "q": example.inputs["q"], "p_weights": None, "q_weights": None}
    pair.update({key: example.inputs[key] for key in ("p_weights", "q_weights") if key in example.inputs})
    return pair


# The stepper's and the comparison's curve pairs: the notes' figures (as the course rebuilt them) and more.
PRESETS = {
    "one intersection (Fig. 7.5)": "clip_curves",
    "two intersections, a split (Fig. 7.9)": "two_intersections",
    "five intersections": "five_intersections",
    "rational: quarter circle and cubic": "rational_clip",
}


class _Panels:
    """Mixin: extra axes next to the explorer's main one, cleared with it on every redraw."""

    panel_boxes: tuple = ()

    def panels(self) -> list:
        if not getattr(self, "extra", None):
            self.ax.set_position(self.panel_boxes[0])
            self.extra = [self.figure.add_axes(box) for box in self.panel_boxes[1:]]
        return self.extra

    def _clear(self) -> None:
        super()._clear()
        main = self.ax
        try:
            for axes in getattr(self, "extra", None) or []:
                self.ax = axes  # Explorer._clear empties self.ax: point it at each panel in turn
                super()._clear()
        finally:
            self.ax = main


# ---------------------------------------------------------------- Bézout


class BezoutExplorer(Explorer):
    """The unit circle and a line or a second circle: Bézout's count, complex and infinite points included. Notes §7.1.

    A line meets a conic 1 · 2 = 2 times and two circles meet 2 · 2 = 4 times,
    counting complex intersections and those at infinity: every circle passes
    through the circular points (1, ±i, 0), so two circles have at most two
    finite intersections left. The second circle on top of the first (offset
    0, radius 1) is the same curve: a common component, which Bézout's theorem
    excludes, and infinitely many common points.
    """

    figsize = (6.2, 5.0)

    def __init__(self):
        controls = {
            "other": widgets.Dropdown(description="second curve", options=["line", "circle"], value="circle"),
            "offset": _slider(widgets.FloatSlider, "offset", min=-3.0, max=3.0, step=0.05, value=1.2),
            "radius": _slider(widgets.FloatSlider, "radius", min=0.2, max=3.0, step=0.05, value=0.8),
        }
        super().__init__(controls)

    def compute(self, other: str, offset: float, radius: float) -> dict:
        circle = circle_conic([0.0, 0.0], 1.0)
        at_infinity = []
        common = other == "circle" and abs(offset) < 1e-12 and abs(radius - 1.0) < 1e-12
        if common:
            # The same circle twice: every point is common, and Bézout's count (which assumes no common
            # component) does not apply.
            return {"other": other, "offset": offset, "radius": radius, "count": np.inf, "common_component": True,
                    "finite": [], "real": np.zeros((0, 2)), "at_infinity": []}
        if other == "line":
            # The line y = offset, x = t: substituting gives a quadratic in t.
            g = implicit_polynomial(circle, [0.0, 1.0], [offset])
            roots = np.roots(g[::-1])
            points = [(complex(t), complex(offset)) for t in roots]
            count = 2
        else:
            count = 4
            at_infinity = [(1, 1j, 0), (1, -1j, 0)]
            if abs(offset) < 1e-12:
                points = []  # concentric: the radical line is the line at infinity, both meets are circular points
                at_infinity = at_infinity * 2
            else:
                # Subtracting the equations leaves the radical line x = c; on it, y² = 1 - c².
                c = (offset**2 + 1 - radius**2) / (2 * offset)
                g = implicit_polynomial(circle, [c], [0.0, 1.0])
                points = [(complex(c), complex(y)) for y in np.roots(g[::-1])]
        real = [(p[0].real, p[1].real) for p in points if abs(p[0].imag) < 1e-9 and abs(p[1].imag) < 1e-9]
        return {"other": other, "offset": offset, "radius": radius, "count": count, "common_component": False,
                "finite": points, "real": np.array(real).reshape(-1, 2), "at_infinity": at_infinity}

    def draw(self, ax, state: dict) -> None:
        theta = np.linspace(0, 2 * np.pi, 200)
        ax.plot(np.cos(theta), np.sin(theta), color=P_COLOR, linewidth=2)
        if state["other"] == "line":
            ax.plot([-3.5, 3.5], [state["offset"]] * 2, color=Q_COLOR, linewidth=2)
        else:
            r, c = state["radius"], state["offset"]
            style = "--" if state["common_component"] else "-"  # dashed: visible on top of the first circle
            ax.plot(c + r * np.cos(theta), r * np.sin(theta), style, color=Q_COLOR, linewidth=2)
        if len(state["real"]):
            ax.plot(*state["real"].T, "o", color="C3", markersize=8)
        ax.set_xlim(-3.5, 3.5)
        ax.set_ylim(-3.2, 3.2)
        ax.set_aspect("equal", adjustable="box")
        ax.set(xticks=[-3, 0, 3], yticks=[-3, 0, 3])
        if state["common_component"]:
            ax.set_title("the same circle twice: a common component,\ninfinitely many common points "
                         "(Bézout's theorem does not apply)", fontsize=9)
            return
        finite = len(state["finite"])
        ax.set_title(f"Bézout: {state['count']} intersections = {len(state['real'])} real + "
                     f"{finite - len(state['real'])} complex + {len(state['at_infinity'])} at infinity", fontsize=9)

    def describe(self, state: dict) -> str:
        if state["common_component"]:
            return (f"{_swatch(P_COLOR)} x² + y² = 1 and {_swatch(Q_COLOR)} the second circle are the same curve: "
                    "every point is common. Bézout's theorem counts the intersections of curves without a common "
                    "component; move the offset or the radius to separate them.")
        rows = [f"({_complex(x)}, {_complex(y)})" for x, y in state["finite"]]
        rows += [f"({_complex(X)}, {_complex(Y)}, {W}) at infinity" for X, Y, W in state["at_infinity"]]
        other = "the line" if state["other"] == "line" else "the second circle"
        key = (f"{_swatch(P_COLOR)} x² + y² = 1, {_swatch(Q_COLOR)} {other}, {_swatch('C3')} real intersections")
        return key + "<br>intersections:<br>" + "<br>".join(html.escape(row) for row in rows)


def _complex(z) -> str:
    z = complex(z)
    if abs(z.imag) < 1e-9:
        return f"{z.real:.4g}".replace("-", "−")  # a minus sign, not a hyphen
    return f"{z.real:.4g}".replace("-", "−") + f"{'+' if z.imag >= 0 else '−'}{abs(z.imag):.4g}i"


def bezout_explorer() -> BezoutExplorer:
    """Dropdown `other` (line or circle), sliders `offset` (the line's height, or the second centre's x) and `radius`.

    `update` returns {"other", "offset", "radius", "count" (Bézout's number;
    inf for the same circle twice), "common_component" (True when the second
    circle is the first: Bézout's hypothesis fails), "finite" (the finite
    intersections as complex pairs), "real" (r, 2), "at_infinity" (the
    homogeneous points at infinity, the circular points (1, ±i, 0) for two
    circles)}. Notes §7.1.
    """
    return BezoutExplorer()


# ---------------------------------------------------------------- the clip lab


def polygon_clip(values, dmin: float, dmax: float) -> tuple[float, float] | None:
    """Where the control polygon (not the hull) of the explicit curve (i/n, d_i) meets the band: the unsafe clip.

    Only consecutive control points are joined, so an edge can stay outside
    the band while the curve itself dips into it; the lab shows where that cuts
    away a part of the curve that lies in the band.
    """
    d = np.asarray(values, dtype=float)
    n = len(d) - 1
    if n == 0:
        return (0.0, 1.0) if dmin <= d[0] <= dmax else None
    t = np.arange(n + 1) / n
    found = list(t[(d >= dmin) & (d <= dmax)])
    for level in (dmin, dmax):
        s = d - level
        for i in np.flatnonzero(s[:-1] * s[1:] < 0):
            found.append(t[i] + (t[i + 1] - t[i]) * s[i] / (s[i] - s[i + 1]))
    return (min(found), max(found)) if found else None


class ClipLabExplorer(Explorer):
    """An explicit curve (t, d(t)) against a band: the exact hull clip, the polygon's and the V rule's. Notes §7.7.2."""

    figsize = (6.6, 4.8)
    MAX_DEGREE = 5

    def __init__(self, values=None, dmin: float = -2.0, dmax: float = 1.0):
        start = list(notes_example("07.first_clip").inputs["distances"]) if values is None else list(values)
        if not 2 <= len(start) <= self.MAX_DEGREE + 1:
            raise ValueError(f"values: the lab takes 2 to {self.MAX_DEGREE + 1} heights, got {len(start)}")
        controls = {"degree": widgets.Dropdown(description="degree", options=list(range(1, self.MAX_DEGREE + 1)),
                                               value=len(start) - 1)}
        padded = start + [0.0] * (self.MAX_DEGREE + 1 - len(start))
        for i, value in enumerate(padded):
            controls[f"d{i}"] = _slider(widgets.FloatSlider, f"d{i}", min=-8.0, max=8.0, step=0.1, value=float(value))
        controls["dmin"] = _slider(widgets.FloatSlider, "dmin", min=-6.0, max=6.0, step=0.1, value=dmin)
        controls["dmax"] = _slider(widgets.FloatSlider, "dmax", min=-6.0, max=6.0, step=0.1, value=dmax)
        super().__init__(controls)

    def compute(self, degree: int, dmin: float, dmax: float, **heights) -> dict:
        if dmin > dmax:
            raise ValueError(f"dmin, dmax: expected dmin <= dmax, got {dmin} > {dmax}")
        d = np.array([heights[f"d{i}"] for i in range(degree + 1)])
        points = np.column_stack([np.arange(degree + 1) / degree, d])
        # The V rule clips the explicit curve, a planar Bézier curve, against each edge of the band as a line.
        lower = clip_one_sided([0.0, 1.0, -dmin], points)
        upper = clip_one_sided([0.0, -1.0, dmax], points)
        v_rule = None if lower is None or upper is None else (max(lower[0], upper[0]), min(lower[1], upper[1]))
        if v_rule is not None and v_rule[0] > v_rule[1]:
            v_rule = None
        ts = np.linspace(0.0, 1.0, 401)
        curve = bernstein_horner(d, ts)
        inside = ts[(curve >= dmin) & (curve <= dmax)]
        polygon = polygon_clip(d, dmin, dmax)
        lost = inside if polygon is None else inside[(inside < polygon[0]) | (inside > polygon[1])]
        return {"values": d, "dmin": dmin, "dmax": dmax, "hull": clip_range(d, dmin, dmax), "polygon": polygon,
                "v_rule": v_rule, "inside": inside, "lost": lost}

    def draw(self, ax, state: dict) -> None:
        plot_explicit_clip(ax, state["values"], state["dmin"], state["dmax"], kept=state["hull"])
        # The three clips, labelled for the legend. The V rule's range often coincides with the hull's, so it is
        # drawn as a bar along the bottom of the panel, where it stays visible beside the hull's lines.
        if state["hull"] is not None:
            ax.plot([], [], color="C2", linewidth=1.4, label="hull clip (exact)")
        if state["polygon"] is not None:
            for k, v in enumerate(state["polygon"]):
                ax.axvline(v, linestyle="--", color="C3", linewidth=1.6,
                           label="polygon clip (unsafe)" if k == 0 else None)
        if state["v_rule"] is not None:
            ax.plot(state["v_rule"], [0.04, 0.04], transform=ax.get_xaxis_transform(), color="C4", linewidth=3,
                    marker="|", markersize=14, markeredgewidth=2.5, label="V rule clip")
        if len(state["lost"]):
            ax.plot(state["lost"], bernstein_horner(state["values"], state["lost"]), ".", color="C3", markersize=4,
                    label="cut away by the polygon")
        handles, labels = ax.get_legend_handles_labels()
        keep = [k for k, name in enumerate(labels) if not name.startswith("control points")]
        ax.legend([handles[k] for k in keep], [labels[k] for k in keep], fontsize=8, loc="upper left",
                  framealpha=0.9)
        verdict = "the polygon clip is UNSAFE" if len(state["lost"]) else "all three clips are safe"
        ax.set_title(f"band [{state['dmin']:.2g}, {state['dmax']:.2g}]: {verdict}".replace("-", "−"), fontsize=9)

    def describe(self, state: dict) -> str:
        def show(clip):
            return "nothing left" if clip is None else f"[{clip[0]:.4f}, {clip[1]:.4f}]"

        lost = (f"<br>{_swatch('C3')} curve in the band but cut away by the polygon clip: "
                f"t in [{state['lost'].min():.3f}, {state['lost'].max():.3f}]" if len(state["lost"]) else "")
        return (f"{_swatch('C2')} exact hull (green lines and strip): {show(state['hull'])}<br>"
                f"{_swatch('C4')} V rule (the bar along the bottom): {show(state['v_rule'])}<br>"
                f"{_swatch('C3')} control polygon (red dashed lines): {show(state['polygon'])}{lost}")


def clip_lab_explorer(values=None, dmin: float = -2.0, dmax: float = 1.0) -> ClipLabExplorer:
    """Dropdown `degree` (1-5), sliders `d0`..`d5` for the heights and `dmin`, `dmax` for the band. Notes §7.7.2.

    values: the starting heights (default the notes' first clip, -5, -1, 2, 3).
    `update` returns {"values", "dmin", "dmax", "hull" (the exact clip), "v_rule"
    (the notes' V rule against both edges), "polygon" (the control polygon's,
    unsafe), "inside" (sampled t where the curve is in the band), "lost" (those
    the polygon clip would cut away)}.
    """
    return ClipLabExplorer(values, dmin, dmax)


# ---------------------------------------------------------------- the clipping stepper


class ClippingExplorer(_Panels, Explorer):
    """Step through the Bézier-clipping search: curves, fat line, explicit distance curve, ranges. Notes §7.7."""

    figsize = (6.9, 3.4)
    panel_boxes = ([0.02, 0.14, 0.45, 0.72], [0.58, 0.14, 0.39, 0.72])
    key_in_readout = True

    def __init__(self, preset: str = "one intersection (Fig. 7.5)"):
        if preset not in PRESETS:
            raise ValueError(f"preset: expected one of {list(PRESETS)}, got {preset!r}")
        self._traces: dict = {}
        controls = {
            "preset": widgets.Dropdown(description="curves", options=list(PRESETS), value=preset),
            "step": _slider(widgets.IntSlider, "clip", min=0, max=self.clip_count(preset, False) - 1, value=0),
            "perpendicular": widgets.Checkbox(description="also the perpendicular fat line", value=False),
        }
        for name in ("preset", "perpendicular"):
            controls[name].observe(self._fit_steps, names="value")
        super().__init__(controls)

    def clip_count(self, preset: str, perpendicular: bool) -> int:
        """How many clips the search of these curves makes (the range of the `step` slider)."""
        return sum(event.kind in ("clip", "rejected") for event in self.trace(preset, perpendicular)[1])

    def _fit_steps(self, change=None) -> None:
        # Runs before the redraw: a step beyond the new search's last clip moves to that clip.
        self.controls["step"].max = self.clip_count(self.controls["preset"].value,
                                                    self.controls["perpendicular"].value) - 1

    def trace(self, preset: str, perpendicular: bool) -> tuple[dict, list]:
        key = (preset, perpendicular)
        if key not in self._traces:
            pair = _pair(PRESETS[preset])
            events = clip_trace(pair["p"], pair["q"], p_weights=pair["p_weights"], q_weights=pair["q_weights"],
                                perpendicular=perpendicular)
            self._traces[key] = (pair, events)
        return self._traces[key]

    def compute(self, preset: str, step: int, perpendicular: bool) -> dict:
        pair, events = self.trace(preset, perpendicular)
        clips = [k for k, event in enumerate(events) if event.kind in ("clip", "rejected")]
        if not 0 <= step < len(clips):
            raise ValueError(f"step: this search has clips 0 to {len(clips) - 1}, got {step}")
        event = events[clips[step]]
        # What followed this clip up to the next one (a split, an intersection found) belongs to this step.
        history = events[: clips[step + 1]] if step + 1 < len(clips) else events
        clipped = event.curve
        other = "Q" if clipped == "P" else "P"
        ranges = {"P": event.t_range, "Q": event.u_range}
        other_range = ranges[other]
        before = event.before
        found = np.array([[(e.t_range[0] + e.t_range[1]) / 2, (e.u_range[0] + e.u_range[1]) / 2]
                          for e in history if e.kind == "found"]).reshape(-1, 2)
        return {
            "preset": preset, "step": step, "steps": len(clips), "event": event, "history": history, "pair": pair,
            "clipped": clipped, "other": other, "before": before, "after": None if event.kind == "rejected" else
            ranges[clipped], "other_range": other_range, "found": found,
            "intersections": intersect_curves(pair["p"], pair["q"], p_weights=pair["p_weights"],
                                              q_weights=pair["q_weights"]) if step == len(clips) - 1 else None,
        }

    def draw(self, ax, state: dict) -> None:
        right = self.panels()[0]
        pair, event = state["pair"], state["event"]
        curves = {"P": (pair["p"], pair["p_weights"], P_COLOR), "Q": (pair["q"], pair["q_weights"], Q_COLOR)}
        extent = picture_extent(pair["p"], pair["q"])
        line, dmin, dmax = event.fat_line
        plot_fat_line(ax, line, dmin, dmax, extent, label=None)
        if event.perpendicular is not None:
            plot_fat_line(ax, *event.perpendicular, extent, color="C5", label=None, baseline=False)
        for points, weights, color in curves.values():
            plot_bezier(ax, points, weights, color=color, linewidth=1.0, alpha=0.5)
        points, weights, color = curves[state["other"]]
        plot_bezier(ax, *curve_piece(points, state["other_range"], weights), color=color, linewidth=3.0)
        points, weights, color = curves[state["clipped"]]
        piece = curve_piece(points, state["before"], weights)
        plot_control_polygon(ax, piece[0], labels=False, color=color, alpha=0.6)
        if state["after"] is not None:
            plot_bezier(ax, *curve_piece(points, state["after"], weights), color=color, linewidth=3.0)
        else:
            plot_bezier(ax, *piece, color="C3", linewidth=2.0, linestyle="--")
        if len(state["found"]):
            p, w, _ = curves["P"]
            ax.plot(*evaluate(p, state["found"][:, 0], w).T, "*", color="C3", markersize=12)
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        ax.set_aspect("equal", adjustable="box")
        ax.set(xticks=[], yticks=[], xlabel="", ylabel="")
        ax.set_title(f"clip {state['step'] + 1} of {state['steps']}: {state['clipped']} against the fat line of "
                     f"{state['other']}", fontsize=9)
        local = event.local
        parameter = "t" if state["clipped"] == "P" else "u"  # the clipped curve's own parameter
        if np.ndim(event.values) == 1:
            plot_explicit_clip(right, event.values, dmin, dmax, kept=local, label="d", parameter=parameter)
        else:
            plot_explicit_clip(right, event.values[0], 0.0, np.inf, kept=local, label="w(d − dmin)",
                               parameter=parameter)
            right.plot(np.linspace(0, 1, event.values.shape[1]), event.values[1], "s--", color="C5", markersize=4)
        right.set_xlabel(f"{parameter}, local to the piece")
        right.set_title(f"distances of {state['clipped']}'s piece from the fat line" +
                        ("" if event.perpendicular is None else " (parallel one)"), fontsize=9)
        right.locator_params(nbins=4)

    def describe(self, state: dict) -> str:
        rows = []
        for event in state["history"]:
            if event.kind in ("clip", "rejected"):
                kept = "nothing" if event.local is None else _range(event.local)
                rows.append(f"<tr><td>{event.curve}</td><td>{kept}</td><td>{_range(event.t_range)}</td>"
                            f"<td>{_range(event.u_range)}</td></tr>")
            else:
                rows.append(f"<tr><td colspan=4><i>{event.kind} {event.curve}</i></td></tr>")
        event = state["event"]
        perpendicular = f", {_swatch('C5')} the perpendicular one" if event.perpendicular is not None else ""
        right = ("the one-sided curves w(d − dmin) (circles) and w(dmax − d) (squares), both to be >= 0"
                 if np.ndim(event.values) == 2 else "d(t) with its control points, hull (green) and band (orange)")
        key = (f"{_swatch(P_COLOR)} P, {_swatch(Q_COLOR)} Q (thick: the pieces), {_swatch('C1')} the fat line "
               f"(dashed edges, L̄ dotted){perpendicular}, {_swatch('C3')} found. Right: {right}.<br>")
        table = key + ("<table><tr><th>clip</th><th>kept (local)</th><th>t range</th><th>u range</th></tr>"
                 + "".join(rows[-12:]) + "</table>")
        if state["intersections"] is not None:
            table += "all intersections: " + html.escape(str(np.round(state["intersections"], 9).tolist()))
        return table


def _range(interval) -> str:
    lo, hi = interval
    return f"[{lo:.6f}, {hi:.6f}]"


def clipping_explorer(preset: str = "one intersection (Fig. 7.5)") -> ClippingExplorer:
    """Dropdown `preset` (a pair of curves), slider `step` (the clip shown) and a checkbox `perpendicular`. Notes §7.7.

    Every clip of the Bézier-clipping search that `clip_trace` records: the left panel shows
    both curves, the fat line of the curve that clips (and its perpendicular
    one if ticked), the piece being clipped with its control polygon and what
    is kept; the right panel the explicit curve of the distances with its hull,
    the band and the kept range. `update` returns {"preset", "step", "steps",
    "event" (the ClipStep), "history" (every event up to it), "pair", "clipped",
    "other", "before", "after" (global ranges of the clipped curve), "other_range",
    "found" (intersections found so far), "intersections" (at the last step)}.
    """
    return ClippingExplorer(preset)


# ---------------------------------------------------------------- comparing the algorithms


METHODS = {"subdivision": "Bézier subdivision", "intervals": "interval subdivision", "clipping": "Bézier clipping"}


class SubdivisionComparisonExplorer(_Panels, Explorer):
    """The pairs of pieces that Bézier subdivision, interval subdivision and clipping examine per depth. Notes §7.4."""

    figsize = (6.9, 3.3)
    panel_boxes = ([0.07, 0.13, 0.26, 0.6], [0.39, 0.13, 0.26, 0.6], [0.71, 0.13, 0.26, 0.6])

    def __init__(self, preset: str = "five intersections"):
        if preset not in PRESETS:
            raise ValueError(f"preset: expected one of {list(PRESETS)}, got {preset!r}")
        self._runs: dict = {}
        controls = {
            "preset": widgets.Dropdown(description="curves", options=[k for k in PRESETS if "rational" not in k],
                                       value=preset),
            "depth": _slider(widgets.IntSlider, "depth", min=0, max=20, value=3),
        }
        super().__init__(controls)

    def run(self, preset: str) -> dict:
        if preset not in self._runs:
            pair = _pair(PRESETS[preset])
            steps = {method: search_steps(pair["p"], pair["q"], method) for method in METHODS}
            depths = 1 + max(s.depth for found in steps.values() for s in found)
            counts = {m: np.bincount([s.depth for s in found], minlength=depths) for m, found in steps.items()}
            self._runs[preset] = (pair, steps, counts, intersect_curves(pair["p"], pair["q"]))
        return self._runs[preset]

    def compute(self, preset: str, depth: int) -> dict:
        pair, steps, counts, found = self.run(preset)
        return {"preset": preset, "depth": depth, "steps": steps, "counts": counts, "found": found,
                "totals": {m: len(s) for m, s in steps.items()}}

    def draw(self, ax, state: dict) -> None:
        for axes, (method, title) in zip([ax, *self.panels()], METHODS.items()):
            plot_parameter_pairs(axes, state["steps"][method], state["depth"], state["found"])
            count = state["counts"][method]
            examined = int(count[state["depth"]]) if state["depth"] < len(count) else 0
            axes.set_title(f"{title}\n{examined} pairs at depth {state['depth']}\n({state['totals'][method]} in all)",
                           fontsize=8)
            axes.tick_params(labelsize=8)
            if axes is not ax:
                axes.set_ylabel("")  # the three squares share the u axis: one label says it

    def describe(self, state: dict) -> str:
        counts = state["counts"]
        depths = max(len(c) for c in counts.values())
        header = "<tr><th>depth</th>" + "".join(f"<th>{title}</th>" for title in METHODS.values()) + "</tr>"
        rows = []
        for d in range(min(depths, 24)):
            cells = "".join(f"<td>{int(c[d]) if d < len(c) else ''}</td>" for c in counts.values())
            style = " style='font-weight:bold'" if d == state["depth"] else ""
            rows.append(f"<tr{style}><td>{d}</td>{cells}</tr>")
        totals = "<tr><td>all</td>" + "".join(f"<td>{state['totals'][m]}</td>" for m in METHODS) + "</tr>"
        return "<table>" + header + "".join(rows) + totals + "</table>"


def subdivision_comparison_explorer(preset: str = "five intersections") -> SubdivisionComparisonExplorer:
    """Dropdown `preset` (two polynomial curves), slider `depth`: the pairs each method examines there. Notes §7.4.

    Each panel is the square of parameters (t, u): a pair of pieces is the
    rectangle of their ranges, outlined if it was kept (split, clipped or
    found), grey if it was rejected; stars are the intersections. `update`
    returns {"preset", "depth", "steps" (SearchStep lists by method), "counts"
    (pairs per depth, by method), "totals", "found"}.
    """
    return SubdivisionComparisonExplorer(preset)

"""Explorers of chapter 5 of the notes: four cubic forms on one control polygon, and a line
that counts its crossings with a polygon and its curve (variation diminishing)."""

from __future__ import annotations

import html

import ipywidgets as widgets
import matplotlib.colors
import numpy as np

from cagd_ref.blending import FORMS, blend, to_bezier
from cagd_ref.blending_properties import convex_hull, distance_outside_hull, line_crossings

from ..plotting import plot_control_polygon
from ._base import CURVE_SAMPLES, DEFAULT_CUBIC, Explorer, _control_points, _fmt, _slider
from .ch02 import ControlPointEditor

__all__ = [
    "blending_forms_explorer",
    "variation_diminishing_explorer",
    "BlendingFormsExplorer",
    "VariationDiminishingExplorer",
]

FORM_COLORS = {"bezier": "C0", "timmer": "C3", "ball": "C2", "overhauser": "C4"}
COLOR_CODES = {form: matplotlib.colors.to_hex(color) for form, color in FORM_COLORS.items()}
FORM_NAMES = {"bezier": "Bézier", "timmer": "Timmer", "ball": "Ball", "overhauser": "Overhauser"}
SAMPLES = np.linspace(0.0, 1.0, CURVE_SAMPLES)


def _cubic_polygon(points, default: np.ndarray) -> np.ndarray:
    """Four planar control points (4, 2) given to a factory, or a copy of the default."""
    pts = _control_points(points, default, min_count=4)
    if len(pts) != 4:
        raise ValueError(
            f"points: the cubic forms have exactly 4 control points, expected shape (4, 2), got {pts.shape}"
        )
    return pts


def _fill_hull(ax, points: np.ndarray) -> None:
    hull = convex_hull(points)
    ax.fill(hull[:, 0], hull[:, 1], color="0.85", alpha=0.6, zorder=0)


# ---------------------------------------------------------------- four forms, one polygon


class BlendingFormsExplorer(ControlPointEditor):
    """Bézier, Timmer, Ball and Overhauser cubics drawn from the same four control points. Notes §5.1-§5.3."""

    def __init__(self, points=None, draggable: bool | None = None):
        super().__init__(_cubic_polygon(points, DEFAULT_CUBIC), None, draggable)

    def compute(self, **values) -> dict:
        points = self.current_points(values)
        curves = {form: blend(basis, points, SAMPLES) for form, basis in FORMS.items()}
        return {
            "points": points,
            "curves": curves,
            "midpoints": {form: blend(basis, points, 0.5) for form, basis in FORMS.items()},
            "bezier_points": {form: to_bezier(form, points) for form in FORMS},
            "hull_escape": {form: float(distance_outside_hull(points, curve).max()) for form, curve in curves.items()},
        }

    def draw(self, ax, state: dict) -> None:
        _fill_hull(ax, state["points"])
        plot_control_polygon(ax, state["points"])
        for form, curve in state["curves"].items():
            ax.plot(*curve.T, color=FORM_COLORS[form], linewidth=2)
        middle = np.array(list(state["midpoints"].values()))
        ax.scatter(*middle.T, c=[FORM_COLORS[form] for form in state["midpoints"]], s=25, zorder=3)
        ax.set_xlim(*self.limits)
        ax.set_ylim(*self.limits)
        ax.set_aspect("equal", adjustable="box")
        # The colours are named in the title rather than a legend, which would add a third to the drawing time.
        ax.set_title("Bézier (blue), Timmer (red), Ball (green), Overhauser (purple)\n"
                     "grey: convex hull of the points; dots: t = 1/2", fontsize=9)

    def describe(self, state: dict) -> str:
        rows = "".join(
            f"<tr><td style='color:{COLOR_CODES[form]}'>{FORM_NAMES[form]}</td>"
            f"<td>{_fmt(state['midpoints'][form])}</td>"
            f"<td>{state['hull_escape'][form]:.3g}</td></tr>"
            for form in FORMS
        )
        return f"<table><tr><th>form</th><th>P(1/2)</th><th>outside hull by</th></tr>{rows}</table>"


def blending_forms_explorer(points=None, draggable: bool | None = None) -> BlendingFormsExplorer:
    """Sliders x0, y0, ..., x3, y3 for four control points shared by the four cubic forms. Notes §5.

    Draws the Bézier, Timmer, Ball and Overhauser (one segment, P1 to P2)
    cubics over the shaded convex hull; `draggable` as in `control_point_editor`.
    `update` returns {"points" (4, 2), "curves" (form -> (200, 2)), "midpoints"
    (form -> P(1/2), (2,)), "bezier_points" (form -> equivalent Bézier control
    points (4, 2)), "hull_escape" (form -> largest distance of the curve outside the hull)}.
    """
    return BlendingFormsExplorer(points, draggable)


# ---------------------------------------------------------------- variation diminishing

ZIGZAG = np.array([[0.0, 0.0], [1.0, 2.5], [2.5, -0.5], [4.0, 2.0]])
CROSSING_SAMPLES = np.linspace(0.0, 1.0, 801)


class VariationDiminishingExplorer(Explorer):
    """A line across a control polygon: how often it meets the polygon, how often the curve. Notes §5, property 4."""

    def __init__(self, points=None, form: str = "bezier", offset: float = 0.0):
        self.points = _cubic_polygon(points, ZIGZAG)
        self.centre = self.points.mean(axis=0)
        low, high = self.points.min(axis=0), self.points.max(axis=0)
        margin = 0.35 * max(high - low)
        self.box = (low - margin, high + margin)
        reach = float(np.linalg.norm(high - low)) / 2 + margin
        if isinstance(offset, bool) or not isinstance(offset, (int, float)) or not abs(offset) <= round(reach, 1):
            raise ValueError(f"offset: expected a number in [{-round(reach, 1)}, {round(reach, 1)}], got {offset!r}")
        controls = {
            "angle": _slider(widgets.FloatSlider, "angle (°)", min=0.0, max=180.0, step=1.0, value=0.0),
            "offset": _slider(widgets.FloatSlider, "offset", min=-round(reach, 1), max=round(reach, 1), step=0.02,
                              value=float(offset)),
            "form": widgets.Dropdown(options=list(FORMS), value=form, description="form",
                                     layout=widgets.Layout(width="300px")),
        }
        super().__init__(controls)

    def line(self, angle: float, offset: float) -> np.ndarray:
        """The line (a, b, c), a x + b y + c = 0, at `angle` degrees, `offset` from the centroid along its normal."""
        theta = np.radians(angle)
        normal = np.array([-np.sin(theta), np.cos(theta)])
        return np.append(normal, -(normal @ self.centre + offset))

    def compute(self, angle: float, offset: float, form: str) -> dict:
        line = self.line(angle, offset)
        curve = blend(FORMS[form], self.points, CROSSING_SAMPLES)
        polygon_hits = line_crossings(self.points, line)
        curve_hits = line_crossings(curve, line)
        return {
            "form": form,
            "line": line,
            "curve": curve,
            "polygon_crossings": polygon_hits,
            "curve_crossings": curve_hits,
            "p": len(polygon_hits),
            "c": len(curve_hits),
            "holds": len(curve_hits) <= len(polygon_hits),
        }

    def draw(self, ax, state: dict) -> None:
        color = FORM_COLORS[state["form"]]
        # No legend (it would double the drawing time): the title and the readout name the markers.
        plot_control_polygon(ax, self.points)
        ax.plot(*state["curve"].T, color=color, linewidth=2)
        a, b, c = state["line"]
        foot, direction = -c * np.array([a, b]), np.array([-b, a])
        ends = foot + np.outer([-100.0, 100.0], direction)
        ax.plot(*ends.T, color="k", linewidth=1)
        ax.plot(*state["polygon_crossings"].T, "s", color="0.3", markersize=8, fillstyle="none")
        ax.plot(*state["curve_crossings"].T, "o", color=color, markersize=5)
        ax.set_xlim(self.box[0][0], self.box[1][0])
        ax.set_ylim(self.box[0][1], self.box[1][1])
        ax.set_aspect("equal", adjustable="box")
        if not state["holds"]:
            self._zoom(ax, state, color)
        verdict = "c ≤ p" if state["holds"] else "c > p: not variation diminishing"
        # Two lines: the counts, then the verdict (one line would run past a narrow frame when c > p).
        ax.set_title(f"{FORM_NAMES[state['form']]} curve: c = {state['c']} crossings (dots), "
                     f"polygon: p = {state['p']} (squares)\n{verdict}", fontsize=9)

    def _zoom(self, ax, state: dict, color) -> None:
        """A counterexample can be tiny (a dip of 0.1 on a 6-unit frame): enlarge the curve's crossings in an inset."""
        hits = state["curve_crossings"]
        low, high = hits.min(axis=0), hits.max(axis=0)
        centre, span = (low + high) / 2, max(float(np.max(high - low)), 1e-3)
        x_half = 0.75 * span
        near = state["curve"][np.abs(state["curve"][:, 0] - centre[0]) <= x_half]  # what the inset shows
        near = np.vstack([near, hits]) if len(near) else hits
        y_half = 0.75 * max(float(np.ptp(near[:, 1])), 0.05 * span) + 1e-9
        centre = np.array([centre[0], (near[:, 1].min() + near[:, 1].max()) / 2])
        inset = ax.inset_axes([0.03, 0.6, 0.42, 0.36])
        inset.plot(*self.points.T, "--", color="0.55", linewidth=1)
        inset.plot(*self.points.T, "o", color="0.3", markersize=4)
        inset.plot(*state["curve"].T, color=color, linewidth=1.5)
        a, b, c = state["line"]
        foot, direction = -c * np.array([a, b]), np.array([-b, a])
        inset.plot(*(foot + np.outer([-100.0, 100.0], direction)).T, color="k", linewidth=1)
        inset.plot(*hits.T, "o", color=color, markersize=4)
        inset.set_xlim(centre[0] - x_half, centre[0] + x_half)
        inset.set_ylim(centre[1] - y_half, centre[1] + y_half)
        inset.set_xticks([])
        inset.set_yticks([])
        ax.indicate_inset_zoom(inset, edgecolor="0.4")

    def describe(self, state: dict) -> str:
        mark = "✓ c ≤ p" if state["holds"] else "<b style='color:#b00'>✗ c &gt; p</b>"
        name = html.escape(FORM_NAMES[state["form"]])
        return f"{name}: the line meets the polygon {state['p']} times and the curve {state['c']} times. {mark}"


def variation_diminishing_explorer(points=None, form: str = "bezier", offset: float = 0.0
                                   ) -> VariationDiminishingExplorer:
    """Sliders `angle` (0..180°) and `offset` move a line; dropdown `form` picks the cubic form. Notes §5.

    points: four planar control points (4, 2). The line passes through the
    centroid of the points when offset is 0; `offset` is where the slider
    starts (the book's static frames turn the line at that offset). `update` returns {"line" (a, b, c),
    "curve" (801, 2), "polygon_crossings" (p, 2), "curve_crossings" (c, 2),
    "p", "c", "holds" (c <= p), "form"}.
    """
    if form not in FORMS:
        raise ValueError(f"form: expected one of {list(FORMS)}, got {form!r}")
    return VariationDiminishingExplorer(points, form, offset)

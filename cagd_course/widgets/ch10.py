"""Explorers of chapter 10 of the notes (polynomial interpolation).

The interpolation playground moves data points and their parameters (with
ipympl both can be dragged: the points in the upper panel, the nodes in the
Lagrange basis below); the Runge explorer compares uniform and Chebyshev
nodes on a function; the Neville stepper builds the triangle level by level
next to Newton's table; the flattening explorer counts chords for a
tolerance; the Hermite explorer turns end tangents, set by their
components, into Bézier points.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np

from cagd_ref._validation import as_float_array, as_points, as_vector
from cagd_ref.approximation import centripetal_parameters, chord_length_parameters
from cagd_ref.interpolation import (
    bernstein_interpolation,
    bezier_segments_needed,
    chebyshev_nodes,
    chord_deviation,
    chord_gaps,
    divided_difference_table,
    hermite_eval,
    hermite_to_bezier,
    lagrange_basis,
    lagrange_eval,
    neville_triangle,
    next_table_row,
    node_polynomial,
    node_polynomial_max,
    second_derivative_bounds,
)

from ..plotting.curves import plot_control_polygon
from ..plotting.interpolation import (
    neville_label,
    parameter_label,
    plot_flattening,
    plot_hermite,
    plot_interpolant,
    plot_lagrange_basis,
    plot_neville,
    plot_node_polynomial,
)
from ._base import Explorer, TwoPanels, _control_points, _fmt, _slider, _swatch
from .ch02 import ControlPointEditor

__all__ = [
    "interpolation_explorer",
    "runge_explorer",
    "neville_explorer",
    "flattening_explorer",
    "hermite_explorer",
    "InterpolationExplorer",
    "RungeExplorer",
    "NevilleExplorer",
    "FlatteningExplorer",
    "HermiteExplorer",
]

# §10.1: the running cubic through four points at t = 0, 1/4, 3/4, 1.
NOTES_POINTS = np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 3.0], [2.0, 4.0]])
NOTES_TS = np.array([0.0, 0.25, 0.75, 1.0])
# §10.3-10.4: the cubic with P(0), P(1), P(3), P(4).
NEWTON_TS = np.array([0.0, 1.0, 3.0, 4.0])
NEWTON_POINTS = np.array([[0.0, 0.0], [3.0, 3.0], [5.0, 3.0], [7.0, 0.0]])
# The course's flattening and Hermite example: one cubic, two descriptions.
FLAT_CUBIC = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.0]])
SAMPLES = 201
PARAMETER_MODES = ["sliders", "uniform", "chord length", "centripetal", "Chebyshev"]
NODE_PICK = 0.04  # how close (in t) a click must be to grab a node
GAP_SAMPLES = 2000  # parameters for the flattening explorer's gap profile, shared among the chords
TANGENT_RANGE = 12.0  # the Hermite explorer's tangent components run over [-12, 12]


def _table(rows: list[list[str]], header: list[str]) -> str:
    """A small HTML table for a readout (cells already escaped)."""
    head = "".join(f"<th style='padding:0 6px'>{h}</th>" for h in header)
    body = "".join("<tr>" + "".join(f"<td style='padding:0 6px'>{c}</td>" for c in row) + "</tr>" for row in rows)
    return f"<table style='font-size:90%'><tr>{head}</tr>{body}</table>"


# ---------------------------------------------------------------- the interpolation playground


class _ExtraControls(Explorer):
    """One step of the initialisation chain between ControlPointEditor and Explorer: adds `extra_controls()`.

    ControlPointEditor builds the coordinate sliders and the dragging; this
    appends the subclass's own controls before Explorer lays out the panel.
    """

    def __init__(self, controls: dict, **options):
        super().__init__({**controls, **self.extra_controls()}, **options)

    def extra_controls(self) -> dict:
        return {}


def _data_parameters(points, exponent: float = 1.0) -> np.ndarray:
    """Chapter 11's chord-length (exponent 1) or centripetal (1/2) parameters; uniform ones if all points coincide."""
    try:
        if exponent == 1.0:
            return chord_length_parameters(points)
        return centripetal_parameters(points, exponent)
    except ValueError:
        return np.linspace(0.0, 1.0, len(as_points(points, min_count=2)))


class InterpolationExplorer(TwoPanels, ControlPointEditor, _ExtraControls):
    """Data points and their parameters -> the interpolant, its Bézier polygon, its Lagrange basis. Notes §10.1-10.2."""

    figsize = (6.5, 7.0)

    def __init__(self, points=None, draggable: bool | None = None):
        start = _control_points(points, NOTES_POINTS, min_count=2)
        self.degree = len(start) - 1
        self._node: int | None = None
        self.window = None  # fixed on the first drawing, so the view stays put while points are dragged
        super().__init__(start, None, draggable)

    def extra_controls(self) -> dict:
        n = self.degree
        initial = NOTES_TS if n == 3 else np.linspace(0.0, 1.0, n + 1)
        controls = {"parameters": widgets.Dropdown(description="parameters", options=PARAMETER_MODES, value="sliders")}
        for i in range(1, n):
            controls[f"t{i}"] = _slider(widgets.FloatSlider, f"t{i}", min=0.01, max=0.99, step=0.01,
                                        value=float(initial[i]), readout_format=".2f")
        options = [("none", -1)] + [(f"L{i}", i) for i in range(n + 1)]
        controls["highlight"] = widgets.Dropdown(description="highlight", options=options, value=-1)
        controls["bezier"] = widgets.Checkbox(description="Bézier polygon", value=True)
        return controls

    def parameters(self, values: dict) -> np.ndarray:
        """The nodes t_0..t_n of the controls: from the sliders (ends 0 and 1), uniform, chord length, centripetal or
        Chebyshev."""
        n, mode = self.degree, values["parameters"]
        if mode == "uniform":
            return np.linspace(0.0, 1.0, n + 1)
        if mode == "chord length":
            return _data_parameters(self.current_points(values))
        if mode == "centripetal":
            return _data_parameters(self.current_points(values), 0.5)
        if mode == "Chebyshev":
            return chebyshev_nodes(0.0, 1.0, n + 1)
        return np.array([0.0] + [values[f"t{i}"] for i in range(1, n)] + [1.0])

    def compute(self, **values) -> dict:
        points = self.current_points(values)
        ts = self.parameters(values)
        grid = np.linspace(0.0, 1.0, SAMPLES)
        try:
            curve = lagrange_eval(ts, points, grid)
        except ValueError as err:
            names = f"t1..t{self.degree - 1}" if values["parameters"] == "sliders" else "parameters"
            raise ValueError(f"{names}: {err}") from None
        basis = lagrange_basis(ts, grid)
        return {
            "points": points,
            "ts": ts,
            "curve": curve,
            "bezier": bernstein_interpolation(ts, points),
            "grid": grid,
            "basis": basis,
            "min_basis": float(basis.min()),
            "highlight": None if values["highlight"] < 0 else int(values["highlight"]),
        }

    def draw(self, ax, state: dict) -> None:
        plot_interpolant(ax, state["ts"], state["points"], interval=(0.0, 1.0))
        if self.values["bezier"]:
            # The end points are data points, labelled with their parameters already.
            inner = [""] + [f"$\\mathbf{{b}}_{{{i}}}$" for i in range(1, self.degree)] + [""]
            plot_control_polygon(ax, state["bezier"], labels=inner, color="C2", alpha=0.8)
        if self.window is None:
            # The sliders' square and the first Bézier polygon: interpolants' control points stray far.
            box = np.vstack([state["bezier"], [[self.limits[0]] * 2, [self.limits[1]] * 2]])
            self.window = (box.min(axis=0) - 0.5, box.max(axis=0) + 0.5)
        low, high = self.window
        ax.set_xlim(low[0], high[0])
        ax.set_ylim(low[1], high[1])
        ax.set_aspect("equal", adjustable="box")
        action = "Drag the points (above) and the nodes (below)" if self.draggable else "Move the points"
        ax.set_title(f"{action}: the cubic through them" if self.degree == 3 else action, fontsize=10)
        lower = self.lower_axes()
        plot_lagrange_basis(lower, state["ts"], interval=(0.0, 1.0), highlight=state["highlight"])
        if len(lower.get_legend_handles_labels()[1]) >= 2:
            legend = lower.legend(fontsize=8, loc="upper center", ncol=min(len(state["ts"]), 6))
            # Headroom for the legend, as in Figure 10.4(a): the peaks of the L_i stay below its box.
            low = lower.get_ylim()[0]
            top = max(float(state["basis"].max()), 1.0)
            below = legend.get_window_extent().transformed(lower.transAxes.inverted()).y0 - 0.04
            lower.set_ylim(low, low + (top - low) / below)
        lower.set_xlabel("t: the Lagrange basis functions and the nodes", fontsize=8)

    def describe(self, state: dict) -> str:
        ts = ", ".join(parameter_label(t).split("= ")[1] for t in state["ts"])
        bezier = " ".join(_fmt(p) for p in state["bezier"])
        hull = ("negative basis values: the curve is no convex combination of its data"
                if state["min_basis"] < -1e-12 else "all basis values >= 0 here")
        return (f"nodes t = ({ts})<br>{_swatch('C2')} Bézier points <b>b</b>: {bezier}<br>"
                f"smallest L<sub>i</sub>(t) on [0, 1]: {state['min_basis']:.3f} ({hull})")

    # Dragging the nodes in the lower panel, as plain methods so tests can drive them without a browser.
    def pick_node(self, t: float, radius: float = NODE_PICK) -> int | None:
        """Index i (1..n-1) of the interior node nearest to t within `radius`, else None (the ends stay at 0, 1)."""
        ts = self.state["ts"]
        inner = np.abs(ts[1:-1] - t)
        if len(inner) == 0 or inner.min() > radius:
            return None
        return int(np.argmin(inner)) + 1

    def move_node(self, index: int, t: float) -> dict:
        """Put node `index` at t (clamped to the slider range); other modes are first copied into the sliders."""
        if not 1 <= index <= self.degree - 1:
            raise ValueError(f"index: expected an interior node 1..{self.degree - 1}, got {index}")
        values = {f"t{i}": float(np.clip(v, 0.01, 0.99)) for i, v in enumerate(self.state["ts"][1:-1], start=1)}
        values[f"t{index}"] = float(np.clip(t, 0.01, 0.99))
        return self.update(parameters="sliders", **values)

    def on_press(self, event) -> None:
        if getattr(self, "lower", None) is not None and event.inaxes is self.lower and event.xdata is not None:
            self._node = self.pick_node(event.xdata)
        else:
            super().on_press(event)

    def on_motion(self, event) -> None:
        if self._node is not None and event.inaxes is self.lower and event.xdata is not None:
            self.move_node(self._node, event.xdata)
        else:
            super().on_motion(event)

    def on_release(self, event) -> None:
        self._node = None
        super().on_release(event)


def interpolation_explorer(points=None, draggable: bool | None = None) -> InterpolationExplorer:
    """Sliders x0, y0, ... for the data, a choice of parameters, sliders t1..t(n-1): the interpolant. Notes §10.1-10.2.

    points: (n+1, 2), default the notes' four points (0, 0), (2, 2), (0, 3), (2, 4)
    with t = 0, 1/4, 3/4, 1. `parameters` is "sliders" (t_0 = 0, t_n = 1 and the
    sliders between), "uniform", "chord length", "centripetal" (section 10.1.1) or "Chebyshev" (the n+1
    Chebyshev nodes of [0, 1]); `highlight` picks a basis function to shade,
    `bezier` shows the curve's Bézier polygon. With `draggable` (ipympl) the
    points and the interior nodes can be dragged: `pick`/`move_point` and
    `pick_node`/`move_node` do it. `update` returns {"points", "ts", "curve"
    (201, 2), "bezier" (n+1, 2), "grid", "basis" (201, n+1), "min_basis", "highlight"}.
    """
    return InterpolationExplorer(points, draggable)


# ---------------------------------------------------------------- Runge's phenomenon


FUNCTIONS = {
    "Runge 1/(1+25x²)": lambda x: 1.0 / (1.0 + 25.0 * x**2),
    "exp(x)": np.exp,
    "sin(3x)": lambda x: np.sin(3.0 * x),
    "|x|": np.abs,
}
LOWER_PANELS = ["ω(x) = Π(x - xᵢ)", "Lagrange basis", "error f - p"]


class RungeExplorer(TwoPanels, Explorer):
    """A function interpolated at N uniform or Chebyshev nodes on [-1, 1]; ω, basis or error below. Notes §10.6."""

    figsize = (6.5, 6.6)
    interval = (-1.0, 1.0)

    def __init__(self):
        controls = {
            "function": widgets.Dropdown(description="f", options=list(FUNCTIONS), value="Runge 1/(1+25x²)"),
            "count": _slider(widgets.IntSlider, "nodes N", min=2, max=21, value=11),
            "spacing": widgets.Dropdown(description="spacing", options=["uniform", "Chebyshev"], value="uniform"),
            "lower": widgets.Dropdown(description="below", options=LOWER_PANELS, value=LOWER_PANELS[0]),
        }
        self.x = np.linspace(*self.interval, 801)
        super().__init__(controls)

    def nodes(self, spacing: str, count: int) -> np.ndarray:
        a, b = self.interval
        return chebyshev_nodes(a, b, count) if spacing == "Chebyshev" else np.linspace(a, b, count)

    def compute(self, function: str, count: int, spacing: str, lower: str) -> dict:
        a, b = self.interval
        f = FUNCTIONS[function]
        nodes = self.nodes(spacing, count)
        p = lagrange_eval(nodes, f(nodes), self.x)
        fx = f(self.x)
        maxima = {kind: node_polynomial_max(self.nodes(kind, count), a, b) for kind in ("uniform", "Chebyshev")}
        basis = lagrange_basis(nodes, self.x)
        return {
            "function": function,
            "spacing": spacing,
            "lower": lower,
            "nodes": nodes,
            "x": self.x,
            "f": fx,
            "p": p,
            "omega": node_polynomial(nodes, self.x),
            "omega_max": maxima[spacing],
            "omega_max_uniform": maxima["uniform"],
            "omega_max_chebyshev": maxima["Chebyshev"],
            "optimum": 2 * ((b - a) / 4) ** count,
            "error": float(np.abs(fx - p).max()),
            "basis": basis,
            "lebesgue": float(np.abs(basis).sum(axis=1).max()),
        }

    def draw(self, ax, state: dict) -> None:
        nodes, f = state["nodes"], FUNCTIONS[state["function"]]
        ax.plot(state["x"], state["f"], color="0.55", linewidth=3, alpha=0.6)
        ax.plot(state["x"], state["p"], color="C0", linewidth=1.6)
        ax.plot(nodes, f(nodes), "o", color="C3", markersize=5)
        low, high = state["f"].min(), state["f"].max()
        pad = 0.6 * (high - low) + 1e-9
        ax.set_ylim(low - pad, high + pad)  # Runge's overshoot runs off the top: the clipping is the point
        ax.set_xlim(*self.interval)
        ax.set_title(f"degree {len(nodes) - 1} interpolant of {state['function']} at {len(nodes)} "
                     f"{state['spacing']} nodes", fontsize=10)
        lower = self.lower_axes()
        if state["lower"] == LOWER_PANELS[0]:
            plot_node_polynomial(lower, nodes, *self.interval)
            lower.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
        elif state["lower"] == LOWER_PANELS[1]:
            plot_lagrange_basis(lower, nodes, interval=self.interval, samples=201)
            lower.set_ylim(-2.5, 2.5)
        else:
            lower.plot(state["x"], state["f"] - state["p"], color="C3", linewidth=1.2)
            lower.axhline(0, color="0.6", linewidth=0.6)
            lower.set_xlim(*self.interval)
        lower.set_xlabel(f"x   (below: {state['lower']})", fontsize=8)

    def describe(self, state: dict) -> str:
        n = len(state["nodes"])
        rows = [
            ["max |ω| on [-1, 1]", f"{state['omega_max_uniform']:.3g}", f"{state['omega_max_chebyshev']:.3g}"],
            ["2((b-a)/4)<sup>N</sup>", "", f"{state['optimum']:.3g}"],
        ]
        return (_table(rows, ["", "uniform", "Chebyshev"])
                + f"{state['spacing']} nodes, N = {n}: max |f - p| = {state['error']:.3g}, "
                f"Lebesgue constant max Σ|L<sub>i</sub>| = {state['lebesgue']:.3g}")


def runge_explorer() -> RungeExplorer:
    """Dropdowns `function`, `spacing` (uniform / Chebyshev), `lower`, a slider `count` (N = 2..21 nodes). Notes §10.6.

    The interval is [-1, 1]. `update` returns {"nodes" (N,), "x" (801,), "f",
    "p", "omega", "omega_max" (for the chosen spacing), "omega_max_uniform",
    "omega_max_chebyshev", "optimum" (2((b-a)/4)^N), "error" (max |f - p|),
    "basis" (801, N), "lebesgue" (max Σ|L_i|)}.
    """
    return RungeExplorer()


# ---------------------------------------------------------------- Neville's triangle


def _html_label(first: int, last: int) -> str:
    """P<sub>012</sub> for the Neville point p_(first..last), as `neville_label` writes it in a figure."""
    return neville_label(first, last).strip("$").replace("_{", "<sub>").replace("}", "</sub>")


class NevilleExplorer(Explorer):
    """Neville's triangle at τ, level by level, beside the row τ adds to Newton's table. Notes §10.3-10.4."""

    figsize = (6.5, 5.0)

    def __init__(self, ts=None, points=None):
        self.ts = NEWTON_TS.copy() if ts is None else as_float_array(ts, "ts")
        self.points = _control_points(points, NEWTON_POINTS)
        self.table = divided_difference_table(self.ts, self.points)
        self.bottom = np.array([column[-1] for column in self.table])
        n = len(self.points) - 1
        lo, hi = float(self.ts.min()), float(self.ts.max())
        margin = 0.25 * (hi - lo)
        controls = {
            "tau": _slider(widgets.FloatSlider, "τ", min=lo - margin, max=hi + margin, step=0.05,
                           value=2.0 if ts is None else round(0.5 * (lo + hi), 2), readout_format=".2f"),
            "level": _slider(widgets.IntSlider, "level", min=0, max=n, value=n),
        }
        super().__init__(controls)

    def compute(self, tau: float, level: int) -> dict:
        triangle = neville_triangle(self.ts, self.points, tau)
        return {
            "tau": tau,
            "level": level,
            "triangle": triangle,
            "point": triangle[-1][0],
            "row": next_table_row(self.ts, self.bottom, tau),
        }

    def draw(self, ax, state: dict) -> None:
        plot_neville(ax, self.ts, self.points, state["tau"], level=state["level"])
        # The label of P(τ) further up and to the left, with a leader line to its point and a white ground
        # over the lines that meet there: at the default offset it crowds the labels of the level below.
        top = neville_label(0, len(self.points) - 1)
        for text in [text for text in ax.texts if text.get_text() == top]:
            text.remove()
            ax.annotate(top, text.xy, xytext=(-50, 16), textcoords="offset points", fontsize=9,
                        color=text.get_color(), bbox={"facecolor": "white", "edgecolor": "none", "alpha": 0.8,
                                                      "pad": 0.3},
                        arrowprops={"arrowstyle": "-", "color": text.get_color(), "linewidth": 0.8,
                                    "shrinkA": 0, "shrinkB": 5})
        # Room below the lowest and above the highest point: their 't = ...' labels stay off the frame and ticks.
        low, high = ax.get_ylim()
        ax.set_ylim(low - 0.12 * (high - low), high + 0.08 * (high - low))
        ax.set_title(f"Neville's scheme at τ = {state['tau']:.2f}: levels 1..{state['level']}", fontsize=10)

    def describe(self, state: dict) -> str:
        n = len(self.points) - 1
        rows = [[html.escape(parameter_label(t))] + [
            f"{_html_label(i - r, i)} {_fmt(level[i - r])}" if r <= min(i, state["level"]) else ""
            for r, level in enumerate(state["triangle"])] for i, t in enumerate(self.ts)]
        neville = _table(rows, ["node"] + [f"level {r}" for r in range(n + 1)])
        newton = " ".join(_fmt(g) for g in state["row"])
        return (f"{neville}Newton's table, new row for τ = {state['tau']:.2f}: {newton}<br>"
                f"its first entry is P(τ), the same point as Neville's: {_fmt(state['point'])}")


def neville_explorer(ts=None, points=None) -> NevilleExplorer:
    """Sliders `tau` (τ) and `level` (0..n): Neville's triangle at τ with the partial interpolants. Notes §10.4.

    ts: (n+1,) nodes and points (n+1, 2), default the notes' example (nodes 0, 1,
    3, 4). `update` returns {"tau", "level", "triangle" (level r of shape
    (n+1-r, 2)), "point" P(τ), "row" (the row τ appends to the divided-difference
    table, first entry P(τ))}.
    """
    return NevilleExplorer(ts, points)


# ---------------------------------------------------------------- flattening


def _fewest_chords(points, tol: float, upper: int) -> int:
    """The smallest m <= upper whose measured chord deviation is <= tol, by bisection (the deviation falls with m)."""
    low, high = 0, upper  # deviation(low) > tol (or low = 0), deviation(high) <= tol
    while high - low > 1:
        middle = (low + high) // 2
        if chord_deviation(points, middle) <= tol:
            high = middle
        else:
            low = middle
    return high


class FlatteningExplorer(TwoPanels, Explorer):
    """A tolerance -> the chords the second-difference bound asks for, the bound and the measured gap. Notes §10.6."""

    figsize = (6.5, 6.2)

    def __init__(self, points=None):
        self.points = _control_points(points, FLAT_CUBIC)
        self.bounds = second_derivative_bounds(self.points)
        tol = widgets.FloatLogSlider(description="tol", base=10, min=-4, max=0, step=0.05, value=0.1,
                                     continuous_update=True, readout_format=".1e")
        super().__init__({"tol": tol})

    def compute(self, tol: float) -> dict:
        m = bezier_segments_needed(self.points, tol)
        t, gaps = chord_gaps(self.points, m, samples=max(9, GAP_SAMPLES // m))
        return {
            "tol": tol,
            "segments": m,
            "bounds": self.bounds,
            "bound": float(np.linalg.norm(self.bounds) / (8 * m**2)),
            "deviation": chord_deviation(self.points, m),
            "fewest": _fewest_chords(self.points, tol, m),
            "t": t,
            "gaps": gaps,
        }

    def draw(self, ax, state: dict) -> None:
        plot_flattening(ax, self.points, segments=state["segments"])
        ax.set_title(f"{state['segments']} chords keep the curve within tol = {state['tol']:.1e}", fontsize=10)
        lower = self.lower_axes()
        lower.plot(state["t"], state["gaps"], color="C3", linewidth=1.2)
        lower.axhline(state["bound"], color="C0", linestyle="--", linewidth=1)
        lower.axhline(state["tol"], color="k", linestyle=":", linewidth=1)
        lower.set_xlim(0, 1)
        lower.set_ylim(0, 1.15 * state["tol"])
        lower.ticklabel_format(axis="y", style="sci", scilimits=(-2, 3))
        lower.set_xlabel("t: gap ‖P(t) - chord(t)‖ (red), bound ‖L‖/(8m²) (dashed), tol (dotted)", fontsize=8)

    def describe(self, state: dict) -> str:
        bounds = ", ".join(f"{b:.4g}" for b in state["bounds"])
        return (f"L = ({bounds}), ‖L‖ = {np.linalg.norm(state['bounds']):.4g}<br>"
                f"m = ⌈√(‖L‖ / (8 tol))⌉ = {state['segments']} chords<br>"
                f"bound ‖L‖ / (8m²) = {state['bound']:.3e} &nbsp; measured gap = {state['deviation']:.3e}<br>"
                f"fewest chords that meet tol (measured): {state['fewest']}")


def flattening_explorer(points=None) -> FlatteningExplorer:
    """Slider `tol` (1e-4 .. 1, logarithmic): flatten a Bézier curve into the chords the bound asks for. Notes §10.6.

    points: (n+1, 2), default the cubic (0, 0), (1, 3), (3, 3), (4, 0). `update`
    returns {"tol", "segments" m, "bounds" (L_x, L_y), "bound" ‖L‖/(8m²),
    "deviation" (measured max ‖P(t) - chord(t)‖), "fewest" (the smallest m that
    meets tol when measured), "t", "gaps" (the gap profile drawn below)}.
    """
    return FlatteningExplorer(points)


# ---------------------------------------------------------------- Hermite


class HermiteExplorer(Explorer):
    """End tangents by their components -> the cubic Hermite curve and its Bézier polygon. Notes §10.7.

    Components rather than angle and length: the course's example P'(0) = (3, 9),
    P'(1) = (3, -9) then sits exactly on the sliders (its angle, 71.565...°, and
    length, √90, do not), and so do its Bézier points (1, 3), (3, 3).
    """

    figsize = (6.0, 4.6)
    static_control = "d0y"  # the static figure tilts the start tangent up and down

    def __init__(self, p0=(0.0, 0.0), p1=(4.0, 0.0), d0=(3.0, 9.0), d1=(3.0, -9.0)):
        self.p0, self.p1 = as_vector(p0, "p0", dim=2), as_vector(p1, "p1", dim=2)
        start, end = as_vector(d0, "d0", dim=2), as_vector(d1, "d1", dim=2)
        controls = {}
        for name, label, value in (("d0x", "P'(0) x", start[0]), ("d0y", "P'(0) y", start[1]),
                                   ("d1x", "P'(1) x", end[0]), ("d1y", "P'(1) y", end[1])):
            controls[name] = _slider(widgets.FloatSlider, label, min=-TANGENT_RANGE, max=TANGENT_RANGE, step=0.5,
                                     value=float(np.clip(value, -TANGENT_RANGE, TANGENT_RANGE)))
        super().__init__(controls)

    def compute(self, d0x: float, d0y: float, d1x: float, d1y: float) -> dict:
        d0, d1 = np.array([d0x, d0y], dtype=float), np.array([d1x, d1y], dtype=float)
        return {
            "d0": d0,
            "d1": d1,
            "bezier": hermite_to_bezier(self.p0, self.p1, d0, d1),
            "curve": hermite_eval(self.p0, self.p1, d0, d1, np.linspace(0.0, 1.0, SAMPLES)),
        }

    def draw(self, ax, state: dict) -> None:
        plot_hermite(ax, self.p0, self.p1, state["d0"], state["d1"])
        ax.set_title("the Hermite cubic: its inner Bézier points are a third of a tangent from the ends", fontsize=9)

    def describe(self, state: dict) -> str:
        return (f"P'(0) = {_fmt(state['d0'])}, P'(1) = {_fmt(state['d1'])}<br>"
                "Bézier points: " + " ".join(_fmt(p) for p in state["bezier"]))


def hermite_explorer(p0=(0.0, 0.0), p1=(4.0, 0.0), d0=(3.0, 9.0), d1=(3.0, -9.0)) -> HermiteExplorer:
    """Sliders `d0x`, `d0y`, `d1x`, `d1y` (-12..12, steps of 0.5): the components of P'(0) and P'(1). Notes §10.7.

    The defaults are the course's example, P'(0) = (3, 9) and P'(1) = (3, -9),
    whose Bézier points are (0, 0), (1, 3), (3, 3), (4, 0). `update` returns
    {"d0", "d1", "bezier" (4, 2), "curve" (201, 2)}.
    """
    return HermiteExplorer(p0, p1, d0, d1)

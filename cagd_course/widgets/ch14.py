"""Explorers of chapter 14 of the notes (free-form deformation): a lattice editor, iso-line images, freezing, curves.

The lattice editor is Figures 14.1 and 14.2 made live: pick a lattice point
(or drag it, with ipympl), move it and change its weight, and a grid, a circle
and a word deform with it; the readout says how each edge of the box joins the
undeformed plane. The iso-line explorer draws Figures 14.6-14.9: the row (or
column) curves, their points at s (or t), and the Bézier curve those points
control. The freezing explorer is Figure 14.5: a line crossing the bottom edge
and the curvature along it, torn, kinked, smooth or curvature-continuous as
0, 1, 2 or 3 rows are frozen. The last compares deforming a curve with
deforming its control points.
"""

from __future__ import annotations

import html
from importlib.util import find_spec

import ipywidgets as widgets
import numpy as np

from cagd_ref import bezier
from cagd_ref.ffd import edge_continuity, ffd, ffd_curve, freeze, identity_lattice, isoline_image

from ..plotting.curves import plot_control_polygon
from ..plotting.deformation import (
    circle_polyline,
    deform_polyline,
    glyph_polyline,
    grid_polyline,
    plot_box,
    plot_isoline_construction,
    plot_lattice,
)
from ._base import Explorer, TwoPanels, _slider, _want_ipympl

__all__ = [
    "lattice_editor",
    "isoline_explorer",
    "freeze_explorer",
    "curve_image_explorer",
    "LatticeEditor",
    "IsolineExplorer",
    "FreezeExplorer",
    "CurveImageExplorer",
]

BOX = np.array([[0.0, 0.0], [3.0, 2.0]])  # the course's box of chapter 14
EDGE_NAMES = ("bottom", "top", "left", "right")
DEGREES = {"min": 1, "max": 5}


def _join_label(order: int, at_least: bool) -> str:
    if order < 0:
        return "torn"
    return f"C<sup>{order}</sup>" + ("+" if at_least else "")


def _joins(lattice, box, weights, max_order: int = 3) -> dict[str, int]:
    return {edge: edge_continuity(lattice, box, edge, weights, max_order)[0] for edge in EDGE_NAMES}


def _bare(ax, box, margin: float = 0.45) -> None:
    (x0, y0), (x1, y1) = box
    pad = margin * max(x1 - x0, y1 - y0)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set(xticks=[], yticks=[], xlabel="", ylabel="")


# ---------------------------------------------------------------- the lattice editor


class LatticeEditor(Explorer):
    """Move and weight the points of an FFD lattice: a grid, a circle and a word deform live. Notes §14, Figs 14.1-14.2.

    The sliders x, y and w show the selected point P_ij (pick it with i, j or
    the mouse); changing m or n starts again from the identity lattice.
    """

    figsize = (6.6, 5.2)
    static_control = "y"

    def __init__(self, m: int = 2, n: int = 2, word: str = "CAGD", draggable: bool | None = None,
                 glyph_samples: int = 16):
        self.box = BOX.copy()
        self.lattice = identity_lattice(self.box, m, n)
        self.weights = np.ones((m + 1, n + 1))
        self._selected = (m // 2, n // 2)
        self.shapes = {
            "grid": grid_polyline(self.box, 12, 8, 40),
            "circle": circle_polyline([0.75, 1.0], 0.5, 160),
            "word": glyph_polyline(word, [[1.4, 0.6], [2.85, 1.4]], samples=glyph_samples, margin=0.0),
        }
        (x0, y0), (x1, y1) = self.box
        pad = 0.45 * max(x1 - x0, y1 - y0)
        self.limits = ((x0 - pad, x1 + pad), (y0 - pad, y1 + pad))
        i, j = self._selected
        x, y = self.lattice[i, j]
        controls = {
            "m": _slider(widgets.IntSlider, "m", value=m, **DEGREES),
            "n": _slider(widgets.IntSlider, "n", value=n, **DEGREES),
            "i": _slider(widgets.IntSlider, "point i", min=0, max=m, value=i),
            "j": _slider(widgets.IntSlider, "point j", min=0, max=n, value=j),
            "x": _slider(widgets.FloatSlider, "x", min=self.limits[0][0], max=self.limits[0][1], step=0.01,
                         value=float(x), readout_format=".2f"),
            "y": _slider(widgets.FloatSlider, "y", min=self.limits[1][0], max=self.limits[1][1], step=0.01,
                         value=float(y), readout_format=".2f"),
            "w": _slider(widgets.FloatLogSlider, "weight", min=-1, max=1, value=1.0, readout_format=".2f"),
        }
        self.draggable = _want_ipympl() if draggable is None else bool(draggable)
        if self.draggable and find_spec("ipympl") is None:
            raise ValueError("draggable: dragging points needs the ipympl package, which is not installed")
        self._dragged: tuple[int, int] | None = None
        super().__init__(controls, interactive_canvas=self.draggable)
        self.reset_button = widgets.Button(description="reset to identity")
        self.reset_button.on_click(lambda _: self.reset())
        panel = self.widget.children[1]
        panel.children = panel.children[:-1] + (self.reset_button, panel.children[-1])
        if self.draggable:
            self.canvas.mpl_connect("button_press_event", self.on_press)
            self.canvas.mpl_connect("motion_notify_event", self.on_motion)
            self.canvas.mpl_connect("button_release_event", self.on_release)

    def compute(self, m: int, n: int, i: int, j: int, x: float, y: float, w: float) -> dict:
        if self.lattice.shape[:2] != (m + 1, n + 1):
            self.lattice = identity_lattice(self.box, m, n)
            self.weights = np.ones((m + 1, n + 1))
            self._selected = None
        i, j = min(i, m), min(j, n)
        # The sliders edit the selected point; a new selection only shows its values (see `_show_selected`).
        if (i, j) == self._selected:
            self.lattice[i, j] = (x, y)
            self.weights[i, j] = w
        self._selected = (i, j)
        weights = None if np.all(self.weights == 1) else self.weights
        deformed = {name: deform_polyline(line, self.lattice, self.box, weights) for name, line in self.shapes.items()}
        joins = _joins(self.lattice, self.box, weights)
        return {
            "lattice": self.lattice.copy(),
            "weights": self.weights.copy(),
            "selected": (i, j),
            "deformed": deformed,
            "joins": joins,
            "displacement": float(np.linalg.norm(self.lattice - identity_lattice(self.box, m, n), axis=2).max()),
        }

    def update(self, **values) -> dict:
        """Set controls and redraw, as for every explorer; a new selection (i, j, m, n) is applied first."""
        selection = {name: values.pop(name) for name in ("m", "n", "i", "j") if name in values}
        if selection or not values:
            super().update(**selection)
            self._show_selected()
        if values:
            super().update(**values)
            self._show_selected()
        return self.state

    def _on_control(self, change) -> None:
        if self._syncing:
            return
        super()._on_control(change)
        self._show_selected()

    def _show_selected(self) -> None:
        """Put the selected point's coordinates and weight on the sliders (without recomputing)."""
        i, j = self.state["selected"]
        m, n = self.lattice.shape[0] - 1, self.lattice.shape[1] - 1
        x, y = self.lattice[i, j]
        self._syncing = True
        try:
            self.controls["i"].max, self.controls["j"].max = m, n
            self.controls["i"].value, self.controls["j"].value = i, j
            self.controls["x"].value = float(np.clip(x, *self.limits[0]))
            self.controls["y"].value = float(np.clip(y, *self.limits[1]))
            self.controls["w"].value = float(self.weights[i, j])
        finally:
            self._syncing = False

    def reset(self) -> dict:
        """Back to the identity lattice (unit weights) of the current degrees."""
        m, n = self.lattice.shape[0] - 1, self.lattice.shape[1] - 1
        self.lattice = identity_lattice(self.box, m, n)
        self.weights = np.ones((m + 1, n + 1))
        i, j = self.state["selected"]
        return self.update(x=float(self.lattice[i, j, 0]), y=float(self.lattice[i, j, 1]), w=1.0)

    def draw(self, ax, state: dict) -> None:
        shown = state["deformed"]
        plot_box(ax, self.box, label=None)
        ax.plot(*shown["grid"].T, color="0.6", linewidth=0.6)
        ax.plot(*shown["circle"].T, color="C0", linewidth=1.8)
        ax.plot(*shown["word"].T, color="black", linewidth=1.3)
        plot_lattice(ax, state["lattice"], state["weights"], highlight=state["selected"], legend=None)
        i, j = state["selected"]
        action = "drag a lattice point" if self.draggable else "pick a point (i, j), move it with x, y"
        ax.set_title(f"FFD of degree ({len(state['lattice']) - 1}, {state['lattice'].shape[1] - 1}): {action}",
                     fontsize=10)
        _bare(ax, self.box)

    def describe(self, state: dict) -> str:
        i, j = state["selected"]
        x, y = state["lattice"][i, j]
        joins = ", ".join(f"{edge} {_join_label(order, order == 3)}" for edge, order in state["joins"].items())
        return (f"P<sub>{i}{j}</sub> = ({x:.3g}, {y:.3g}), weight {state['weights'][i, j]:.3g}<br>"
                f"largest move of a lattice point {state['displacement']:.3g}<br>"
                f"joins with the undeformed plane: {joins}")

    # Mouse dragging, as plain methods so tests can drive them without a browser.
    def pick(self, x: float, y: float, radius: float = 0.15) -> tuple[int, int] | None:
        """(i, j) of the lattice point nearest to (x, y) within `radius` (data units), else None."""
        distances = np.linalg.norm(self.lattice - np.array([x, y], dtype=float), axis=2)
        index = np.unravel_index(int(np.argmin(distances)), distances.shape)
        return (int(index[0]), int(index[1])) if distances[index] <= radius else None

    def move_point(self, i: int, j: int, x: float, y: float) -> dict:
        """Select P_ij and move it to (x, y) (clamped to the sliders' range)."""
        self.update(i=i, j=j)
        x, y = float(np.clip(x, *self.limits[0])), float(np.clip(y, *self.limits[1]))
        return self.update(x=x, y=y)

    def on_press(self, event) -> None:
        if event.inaxes is self.ax and event.xdata is not None:
            self._dragged = self.pick(event.xdata, event.ydata)

    def on_motion(self, event) -> None:
        if self._dragged is not None and event.inaxes is self.ax and event.xdata is not None:
            self.move_point(*self._dragged, event.xdata, event.ydata)

    def on_release(self, event) -> None:
        self._dragged = None


def lattice_editor(m: int = 2, n: int = 2, word: str = "CAGD", draggable: bool | None = None) -> LatticeEditor:
    """Sliders `m`, `n` (1-5), `i`, `j` (the selected point), `x`, `y`, `w` (its position and weight). Notes §14.

    A grid, a circle and `word` (its glyph outlines) in the box (0, 0)-(3, 2)
    deform with the lattice; a button resets it to the identity. With
    `draggable` (ipympl) the lattice points can be dragged: `pick` and
    `move_point` do it. `update` returns {"lattice" (m+1, n+1, 2), "weights",
    "selected" (i, j), "deformed" (dict of polylines "grid", "circle", "word"),
    "joins" (edge -> order of continuity with the undeformed plane, -1 torn, 3
    meaning at least 3), "displacement" (the largest move of a lattice point)}.
    """
    return LatticeEditor(m, n, word, draggable)


# ---------------------------------------------------------------- iso-line images


# The lattice of the notes' Figures 14.6-14.9 in the course's version (example B): m = 3, n = 2.
EXAMPLE_B = identity_lattice(BOX, 3, 2)
EXAMPLE_B[1, 1], EXAMPLE_B[2, 2], EXAMPLE_B[3, 0] = (1.5, 1.5), (2.0, 3.0), (3.5, -0.5)


class IsolineExplorer(Explorer):
    """The image of a line s = const (or t = const): row (column) curves and their points. Notes §14, Figs 14.6-14.9."""

    figsize = (6.6, 5.2)

    def __init__(self, direction: str = "s", value: float = 0.6, weight: float = 1.0):
        controls = {
            "direction": widgets.ToggleButtons(description="line", options=[("s = const", "s"), ("t = const", "t")],
                                               value=direction),
            "value": _slider(widgets.FloatSlider, "value", min=0.0, max=1.0, step=0.05, value=value,
                             readout_format=".2f"),
            "weight": _slider(widgets.FloatLogSlider, "w₁₁", min=-1, max=1, value=weight, readout_format=".2f"),
        }
        super().__init__(controls)

    def compute(self, direction: str, value: float, weight: float) -> dict:
        weights = np.ones((4, 3))
        weights[1, 1] = weight
        points, curve_weights = isoline_image(EXAMPLE_B, value, direction, weights)
        box = BOX
        u = np.linspace(0.0, 1.0, 41)
        line = (np.column_stack([np.full(41, box[0, 0] + value * 3.0), u * 2.0]) if direction == "s"
                else np.column_stack([u * 3.0, np.full(41, box[0, 1] + value * 2.0)]))
        deformed = ffd(line, EXAMPLE_B, box, weights)
        return {
            "direction": direction,
            "value": value,
            "weights": weights,
            "points": points,
            "curve_weights": curve_weights,
            "degree": len(points) - 1,
            "deviation": float(np.abs(bezier.evaluate(points, u, curve_weights) - deformed).max()),
            "grid": deform_polyline(grid_polyline(box, 6, 4, 40), EXAMPLE_B, box, weights),
        }

    def draw(self, ax, state: dict) -> None:
        ax.plot(*state["grid"].T, color="0.7", linewidth=0.7)
        plot_lattice(ax, EXAMPLE_B, state["weights"], legend=None, alpha=0.4)
        plot_isoline_construction(ax, EXAMPLE_B, state["value"], state["direction"], state["weights"])
        name = "row curves H_j(s)" if state["direction"] == "s" else "column curves V_i(t)"
        ax.set_title(f"{state['direction']} = {state['value']:.2f} maps to a curve of degree {state['degree']}, "
                     f"controlled by points of the {name}", fontsize=9)
        ax.legend(fontsize=8, loc="lower right")
        _bare(ax, BOX, 0.35)

    def describe(self, state: dict) -> str:
        name = "H" if state["direction"] == "s" else "V"
        rows = "<br>".join(f"{name}<sub>{k}</sub>({state['value']:.2f}) = ({p[0]:.4g}, {p[1]:.4g}), weight {w:.4g}"
                           for k, (p, w) in enumerate(zip(state["points"], state["curve_weights"])))
        return f"{rows}<br>curve vs FFD of the line: {state['deviation']:.1e}"


def isoline_explorer(direction: str = "s", value: float = 0.6, weight: float = 1.0) -> IsolineExplorer:
    """Toggle `direction` ("s" or "t"), sliders `value` (0-1) and `weight` (of P_11). Notes §14, Figs 14.6-14.9.

    On the course's m = 3, n = 2 lattice (example B). `update` returns
    {"direction", "value", "weights" (4, 3), "points" and "curve_weights" of the
    image curve (degree n = 2 for s, m = 3 for t), "degree", "deviation"
    (largest distance to the FFD of points of the line), "grid"}.
    """
    return IsolineExplorer(direction, value, weight)


# ---------------------------------------------------------------- freezing


FREEZE_BOX = np.array([[0.0, 0.0], [3.0, 2.0]])
FREEZE_DEGREES = (3, 4)
ORDERS = [("none", -1), ("C0: 1 row", 0), ("C1: 2 rows", 1), ("C2: 3 rows", 2)]
LINE_X = 1.5  # the line crossing the bottom edge, at s = 1/2


def bent_lattice(strength: float) -> np.ndarray:
    """The freezing figures' lattice: every row pushed sideways (most in the middle column) and up."""
    m, n = FREEZE_DEGREES
    lattice = identity_lattice(FREEZE_BOX, m, n)
    i = np.arange(m + 1)[:, None]
    j = np.arange(n + 1)[None, :]
    lattice[..., 0] += strength * np.sin(np.pi * i / m) * (0.8 + 0.4 * j / n)
    lattice[..., 1] += strength * 0.25 * np.sin(np.pi * i / m)
    return lattice


class FreezeExplorer(TwoPanels, Explorer):
    """A line crossing the bottom edge, deformed with 0-3 rows frozen; its curvature below. Notes §14, Fig. 14.5."""

    static_control = "order"

    def __init__(self, order: int = 1, strength: float = 0.6):
        controls = {
            "order": widgets.Dropdown(description="frozen", options=ORDERS, value=order),
            "strength": _slider(widgets.FloatSlider, "strength", min=0.0, max=1.0, step=0.05, value=strength,
                                readout_format=".2f"),
        }
        super().__init__(controls)

    def compute(self, order: int, strength: float) -> dict:
        lattice = bent_lattice(strength)
        if order >= 0:
            lattice, _ = freeze(lattice, FREEZE_BOX, "bottom", order)
        # Inside the box the line x = 1.5 becomes the image of s = 1/2, a curve of degree n; below it stays put.
        s = (LINE_X - FREEZE_BOX[0, 0]) / (FREEZE_BOX[1, 0] - FREEZE_BOX[0, 0])
        points, weights = isoline_image(lattice, s)
        u = np.linspace(0.0, 1.0, 201)
        inside = bezier.evaluate(points, u, weights)
        outside = np.column_stack([np.full(2, LINE_X), [-1.0, 0.0]])
        kappa = bezier.signed_curvature(points, u, weights)
        tangent = bezier.derivative(points, 0.0, 1, weights)
        joined, jumps = edge_continuity(lattice, FREEZE_BOX, "bottom", max_order=3)
        return {
            "order": order,
            "lattice": lattice,
            "inside": inside,
            "outside": outside,
            "u": u,
            "curvature": kappa,
            "gap": float(np.linalg.norm(inside[0] - outside[-1])),
            "kink": float(np.degrees(np.arctan2(abs(tangent[0]), tangent[1]))),
            "curvature_jump": float(abs(kappa[0])),
            "continuity": joined,
            "jumps": jumps,
            "grid": deform_polyline(grid_polyline(FREEZE_BOX, 6, 4, 40), lattice, FREEZE_BOX),
        }

    def draw(self, ax, state: dict) -> None:
        ax.plot(*state["grid"].T, color="0.7", linewidth=0.7)
        plot_lattice(ax, state["lattice"], legend=None, alpha=0.5)
        frozen = state["order"] + 1
        if frozen:
            ax.plot(*state["lattice"][:, :frozen].reshape(-1, 2).T, "s", color="C2", markersize=7,
                    label=f"{frozen} frozen row{'s' if frozen > 1 else ''}")
        ax.plot(*state["outside"].T, color="black", linewidth=2.2, label="the line outside the box")
        ax.plot(*state["inside"].T, color="C0", linewidth=2.2, label="its image inside")
        ax.axhline(FREEZE_BOX[0, 1], color="C3", linewidth=0.8, linestyle=":")
        labels = {-1: "torn", 0: "C⁰: a kink", 1: "C¹: the curvature jumps", 2: "C²", 3: "C³ or better"}
        ax.set_title(f"freezing at the bottom edge: {labels[state['continuity']]}", fontsize=10)
        ax.legend(fontsize=8, loc="lower right")
        ax.set_xlim(-0.6, 3.6)
        ax.set_ylim(-1.0, 2.6)
        ax.set_aspect("equal", adjustable="box")
        ax.set(xticks=[], yticks=[], xlabel="", ylabel="")
        lower = self.lower_axes()
        height = FREEZE_BOX[1, 1] - FREEZE_BOX[0, 1]
        lower.plot([-0.5, 0.0], [0.0, 0.0], color="black", linewidth=2, label="outside: κ = 0")
        lower.plot(state["u"] * height, state["curvature"], color="C0", linewidth=2, label="inside: κ of the image")
        lower.axvline(0.0, color="C3", linewidth=0.8, linestyle=":")
        lower.set_xlabel("height above the bottom edge (before deforming)", fontsize=8)
        lower.set_ylabel("κ", fontsize=8)
        lower.set_ylim(-1.6, 1.6)
        lower.legend(fontsize=8, loc="upper right")

    def describe(self, state: dict) -> str:
        jumps = ", ".join(f"{j:.2g}" for j in state["jumps"])
        return (f"gap at the edge {state['gap']:.3g}; the tangent turns by {state['kink']:.3g}°; "
                f"curvature just inside {state['curvature_jump']:.3g}<br>"
                f"largest jump of the derivatives 0, 1, 2, 3 across the edge: {jumps}")


def freeze_explorer(order: int = 1, strength: float = 0.6) -> FreezeExplorer:
    """Dropdown `order` (-1: none, 0, 1, 2 rows + 1 frozen) and slider `strength`. Notes §14, Fig. 14.5.

    A degree-(3, 4) lattice pushed sideways; the line x = 1.5 crosses its
    bottom edge. `update` returns {"order", "lattice", "inside" (201, 2) the
    image of the line in the box, "outside", "u", "curvature" along the image,
    "gap" (how far the line is torn at the edge), "kink" (degrees the tangent
    turns there), "curvature_jump", "continuity" (from `edge_continuity`),
    "jumps", "grid"}.
    """
    return FreezeExplorer(order, strength)


# ---------------------------------------------------------------- curves: the points or the curve


CURVES = {
    "cubic": np.array([[0.3, 0.3], [0.9, 1.8], [2.0, 0.2], [2.7, 1.5]]),
    "quadratic": np.array([[0.3, 1.7], [1.5, -0.0], [2.7, 1.7]]),
    "line": np.array([[0.2, 0.4], [2.8, 1.6]]),
}


def twisted_lattice(m: int, n: int, strength: float) -> np.ndarray:
    """The identity lattice of the box turned about its centre, more the farther up a row is."""
    lattice = identity_lattice(BOX, m, n)
    centre = BOX.mean(axis=0)
    angle = strength * (np.arange(n + 1) / n - 0.5)[None, :]
    offset = lattice - centre
    cos, sin = np.cos(angle), np.sin(angle)
    lattice[..., 0] = centre[0] + cos * offset[..., 0] - sin * offset[..., 1]
    lattice[..., 1] = centre[1] + sin * offset[..., 0] + cos * offset[..., 1]
    return lattice


class CurveImageExplorer(Explorer):
    """Deform a Bézier curve, or only its control points? The exact image has degree k(m + n). Notes §14."""

    figsize = (6.6, 5.0)
    static_control = "strength"

    def __init__(self, curve: str = "cubic", m: int = 2, n: int = 2, strength: float = 1.2):
        controls = {
            "curve": widgets.Dropdown(description="curve", options=list(CURVES), value=curve),
            "m": _slider(widgets.IntSlider, "m", value=m, min=1, max=4),
            "n": _slider(widgets.IntSlider, "n", value=n, min=1, max=4),
            "strength": _slider(widgets.FloatSlider, "twist", min=-1.5, max=1.5, step=0.05, value=strength,
                                readout_format=".2f"),
        }
        super().__init__(controls)

    def compute(self, curve: str, m: int, n: int, strength: float) -> dict:
        points = CURVES[curve]
        lattice = twisted_lattice(m, n, strength)
        u = np.linspace(0.0, 1.0, 201)
        sampled = ffd(bezier.evaluate(points, u), lattice, BOX)
        moved_points = ffd(points, lattice, BOX)
        naive = bezier.evaluate(moved_points, u)
        exact_points, exact_weights = ffd_curve(points, lattice, BOX)
        exact = bezier.evaluate(exact_points, u, exact_weights)
        return {
            "curve": curve,
            "points": points,
            "lattice": lattice,
            "sampled": sampled,
            "moved_points": moved_points,
            "naive": naive,
            "exact_points": exact_points,
            "exact_weights": exact_weights,
            "degree": len(points) - 1,
            "image_degree": len(exact_points) - 1,
            "naive_error": float(np.abs(naive - sampled).max()),
            "exact_error": float(np.abs(exact - sampled).max()),
            "grid": deform_polyline(grid_polyline(BOX, 6, 4, 40), lattice, BOX),
        }

    def draw(self, ax, state: dict) -> None:
        ax.plot(*state["grid"].T, color="0.75", linewidth=0.7)
        plot_lattice(ax, state["lattice"], legend=None, alpha=0.35)
        plot_control_polygon(ax, state["exact_points"], labels=False, color="C0", alpha=0.5, marker="s",
                             markersize=3, legend=f"control polygon of the image (degree {state['image_degree']})")
        ax.plot(*state["sampled"].T, color="C0", linewidth=3, alpha=0.6, label="the curve, deformed")
        plot_control_polygon(ax, state["moved_points"], labels=False, color="C3", alpha=0.8,
                             legend="its control points, deformed")
        ax.plot(*state["naive"].T, color="C3", linewidth=1.6, linestyle="--",
                label=f"the curve of those points (degree {state['degree']})")
        ax.set_title(f"degree {state['degree']} in a ({len(state['lattice']) - 1}, "
                     f"{state['lattice'].shape[1] - 1}) lattice: the image has degree {state['image_degree']}",
                     fontsize=10)
        ax.legend(fontsize=8, loc="lower right")
        _bare(ax, BOX, 0.3)

    def describe(self, state: dict) -> str:
        k = state["degree"]
        return (f"k = {k}: the image is a Bézier curve of degree k(m + n) = {state['image_degree']}<br>"
                f"curve of the deformed control points: up to {state['naive_error']:.3g} off<br>"
                f"exact image of degree {state['image_degree']}: {state['exact_error']:.1e} off "
                f"(weights {html.escape(', '.join(f'{w:.3g}' for w in state['exact_weights'][:3]))}, ...)")


def curve_image_explorer(curve: str = "cubic", m: int = 2, n: int = 2, strength: float = 1.2) -> CurveImageExplorer:
    """Dropdown `curve`, sliders `m`, `n` (1-4) and `strength` (the lattice's twist). Notes §14.

    `update` returns {"curve", "points", "lattice", "sampled" (201, 2) the curve
    deformed point by point, "moved_points" and "naive" (the curve of the
    deformed control points), "exact_points" and "exact_weights" (`ffd_curve`,
    degree k(m + n)), "degree", "image_degree", "naive_error", "exact_error"
    (largest distances to the sampled image), "grid"}.
    """
    return CurveImageExplorer(curve, m, n, strength)

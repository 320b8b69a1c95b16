"""Explorers of chapter 18 of the notes (moving lines): a pencil and its parameter line, two pencils sweeping a
conic, the double point of a cubic as the axis of a pencil, and a tangent moving line with the reciprocal curve.

The pencil explorer is Figures 18.3 and 18.4 with a t slider: the member L(t)
of the pencil passes through the mark t of its parameter line (the nomogram).
The conic explorer is Figures 18.1, 18.6 and 18.7: two pencils and the conic
their meets trace. The double-point finder moves two control points of a
cubic and follows the pencil that the cubic's 3×3 matrix of moving lines
reduces to (Figure 18.11). The tangent explorer draws the tangent moving line
and, beside it, the reciprocal curve traced by the tangent lines read as points
(Figures 18.14-18.17).
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from cagd_ref import bezier, moving_lines
from cagd_ref.geometry import conic_type

from ..plotting.algebraic import plot_implicit
from ..plotting.curves import bezier_samples, plot_control_polygon
from ..plotting.pencils import AXIS_STYLE, plot_line, plot_lines, plot_parameter_line, plot_pencil, plot_points, set_box
from ._base import Explorer, _fmt, _slider, bare_axes

__all__ = [
    "pencil_explorer",
    "two_pencils_explorer",
    "double_point_explorer",
    "tangent_explorer",
    "PencilExplorer",
    "TwoPencilsExplorer",
    "DoublePointExplorer",
    "TangentExplorer",
]

T = {"min": 0.0, "max": 1.0, "step": 0.01, "readout_format": ".2f"}
ANGLE = {"min": -180.0, "max": 180.0, "step": 1.0, "readout_format": ".0f"}
ELEVEN = np.linspace(0.0, 1.0, 11)


def _through(point, normal_degrees: float, size: float = 1.0) -> np.ndarray:
    """The line through a point whose normal (a, b) has the given direction and length."""
    phi = np.radians(normal_degrees)
    normal = size * np.array([np.cos(phi), np.sin(phi)])
    return np.array([normal[0], normal[1], -normal @ np.asarray(point, dtype=float)])


def _clip_to_box(point, box, margin: float = 0.04) -> np.ndarray | None:
    """None when the point (2,) lies in the box; else the point where the segment from the box's centre to it
    leaves the box (pulled in by `margin` of the box size, so a marker there stays visible)."""
    (x0, x1), (y0, y1) = box
    point = np.asarray(point, dtype=float)
    if x0 <= point[0] <= x1 and y0 <= point[1] <= y1:
        return None
    centre = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
    half = (1 - margin) * np.array([(x1 - x0) / 2, (y1 - y0) / 2])
    direction = point - centre
    scale = np.min(half / np.maximum(np.abs(direction), 1e-300))
    return centre + scale * direction


def _cartesian(point) -> np.ndarray | None:
    point = np.asarray(point)
    if abs(point[2]) <= 1e-12 * np.linalg.norm(point):
        return None
    return (point[:2] / point[2]).real


# ---------------------------------------------------------------- a pencil and its parameter line


class PencilExplorer(Explorer):
    """A pencil about the origin, its parameter line with even marks, the member through mark t. Notes §18.2.1."""

    BOX = ((-3.0, 3.0), (-3.0, 3.0))

    def __init__(self, t: float = 0.3):
        controls = {
            "t": _slider(widgets.FloatSlider, "t", value=t, **T),
            "phi0": _slider(widgets.FloatSlider, "normal of L0 (°)", value=90.0, **ANGLE),
            "phi1": _slider(widgets.FloatSlider, "normal of L1 (°)", value=150.0, **ANGLE),
            "size1": _slider(widgets.FloatSlider, "|(a1, b1)|", value=1.0, min=0.2, max=4.0, step=0.05),
            "d0": _slider(widgets.FloatSlider, "d0", value=1.5, min=0.2, max=2.5, step=0.05),
        }
        super().__init__(controls)

    def compute(self, t: float, phi0: float, phi1: float, size1: float, d0: float) -> dict:
        l0, l1 = _through((0.0, 0.0), phi0), _through((0.0, 0.0), phi1, size1)
        try:
            ends = moving_lines.pencil_parameter_line(l0, l1, d0)
        except ValueError:
            raise ValueError("phi1: L1 must differ from L0 (normals not parallel)") from None
        line = moving_lines.moving_line_eval([l0, l1], t)
        mark = (1 - t) * ends[0] + t * ends[1]
        return {
            "t": t,
            "l0": l0,
            "l1": l1,
            "line": line,
            "ends": ends,
            "mark": mark,
            "d1": float(np.linalg.norm(ends[1])),
            "incidence": float(line @ [*mark, 1.0]),
            "counterclockwise": bool(l0[0] * l1[1] - l1[0] * l0[1] > 0),
        }

    def draw(self, ax, state: dict) -> None:
        box = self.BOX
        plot_pencil(ax, state["l0"], state["l1"], *box, ts=ELEVEN, linewidth=0.8, alpha=0.5)
        plot_line(ax, state["l0"], *box, color="0.2", linewidth=1.4, label="L0 (t = 0)")
        plot_line(ax, state["l1"], *box, color="0.2", linewidth=1.4, linestyle="--", label="L1 (t = 1)")
        plot_parameter_line(ax, state["ends"], ticks=np.linspace(0, 1, 5))
        plot_line(ax, state["line"], *box, color="C3", linewidth=2.2, label=f"L({state['t']:.2f})")
        ax.plot(*state["mark"], "o", color="C3", markersize=7)
        ax.plot(0.0, 0.0, **AXIS_STYLE, label="axis PA")
        ax.legend(fontsize=8, loc="upper left")
        ax.set_title("a pencil passes through the marks of its parameter line", fontsize=10)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        sense = "counterclockwise (a0 b1 &gt; a1 b0)" if state["counterclockwise"] else "clockwise (a0 b1 &lt; a1 b0)"
        d0, d1 = np.linalg.norm(state["ends"][0]), state["d1"]
        crowd = ("spread symmetrically, neither end favoured (d0 = d1)" if np.isclose(d0, d1) else
                 f"crowded near {'L0' if d0 > d1 else 'L1'}, the end of the parameter line farther from the axis")
        return "<br>".join([
            f"d0 = {d0:.3f}, d1 = {d1:.3f}: "
            f"d0/d1 = |(a0, b0)|/|(a1, b1)| = {1 / np.linalg.norm(state['l1'][:2]):.3f}",
            f"L(t)·P(t) = {state['incidence']:.1e}: the member of parameter t meets the mark t",
            f"the pencil turns {sense}; equal steps of t are {crowd}",
        ])


def pencil_explorer(t: float = 0.3) -> PencilExplorer:
    """Sliders `t`, `phi0`, `phi1` (directions of the normals, degrees), `size1` and `d0`: the nomogram. Notes §18.2.1.

    `update` returns {"t", "l0", "l1", "line" L(t), "ends" (2, 2) of the
    parameter line, "mark" its point of parameter t, "d1", "incidence" L(t)·P(t)
    (zero to rounding), "counterclockwise"}.
    """
    return PencilExplorer(t)


# ---------------------------------------------------------------- two pencils and their conic


# The course's two pencils of Figure 18.7: axes (0, 0) and (4, 0), and no line of one pencil through the
# other's axis, so that P0, P2 and the two auxiliary points Qa = l00 × l11, Qb = l01 × l10 are four distinct points.
FIGURE_18_7 = np.array([[2.0, -1.0, 0.0], [2.0, -3.0, 0.0], [2.0, 3.0, -8.0], [4.0, 2.0, -16.0]])
TURN = {"min": -90.0, "max": 90.0, "step": 1.0, "readout_format": ".0f"}


def _turn_about(line: np.ndarray, axis, degrees: float) -> np.ndarray:
    """The line (3,) turned counterclockwise by `degrees` about the point `axis` (2,) on it; same normal length."""
    phi = np.radians(degrees)
    rotation = np.array([[np.cos(phi), -np.sin(phi)], [np.sin(phi), np.cos(phi)]])
    normal = rotation @ line[:2]
    return np.array([normal[0], normal[1], -normal @ np.asarray(axis, dtype=float)])


class TwoPencilsExplorer(Explorer):
    """Two pencils, the meet of their members of one t, and the conic it traces. Notes §18.2.1, Figs. 18.6, 18.7."""

    BOX = ((-0.8, 4.8), (-1.3, 4.6))
    AXES = (np.array([0.0, 0.0]), np.array([4.0, 0.0]))

    def __init__(self, t: float = 0.5):
        controls = {
            "t": _slider(widgets.FloatSlider, "t", value=t, **T),
            "turn01": _slider(widgets.FloatSlider, "turn L01 (°)", value=0.0, **TURN),
            "turn11": _slider(widgets.FloatSlider, "turn L11 (°)", value=0.0, **TURN),
        }
        super().__init__(controls)

    def compute(self, t: float, turn01: float, turn11: float) -> dict:
        a0, a1 = self.AXES
        l00, l01, l10, l11 = FIGURE_18_7
        lines = [l00, _turn_about(l01, a0, turn01), l10, _turn_about(l11, a1, turn11)]
        try:
            control = moving_lines.conic_from_pencils(*lines)
        except ValueError as err:
            raise ValueError(f"turn01, turn11: {err}") from None
        coeffs = moving_lines.pencils_implicit(*lines)
        try:
            kind = conic_type(coeffs[2, 0], coeffs[1, 1], coeffs[0, 2], coeffs[1, 0], coeffs[0, 1], coeffs[0, 0])
        except ValueError:
            kind = "pair of lines"
        pencil0 = moving_lines.moving_line_eval(lines[:2], t)
        pencil1 = moving_lines.moving_line_eval(lines[2:], t)
        return {
            "t": t,
            "lines": np.array(lines),
            "control": control,
            "weights": control[:, 2],
            "implicit": coeffs,
            "kind": kind,
            "members": (pencil0, pencil1),
            "point": np.cross(pencil0, pencil1),
            "qa": np.cross(lines[0], lines[3]),
            "qb": np.cross(lines[1], lines[2]),
            "ticks": bezier.de_casteljau(control, ELEVEN),
        }

    def draw(self, ax, state: dict) -> None:
        box = self.BOX
        lines = state["lines"]
        plot_pencil(ax, lines[0], lines[1], *box, ts=ELEVEN, cmap="Blues", linewidth=0.7, alpha=0.45)
        plot_pencil(ax, lines[2], lines[3], *box, ts=ELEVEN, cmap="Greens", linewidth=0.7, alpha=0.45)
        c = state["implicit"]
        i, j = np.indices(c.shape)
        plot_implicit(ax, lambda x, y: np.einsum("ij,ij...->...", c, x[None, None] ** i[..., None, None]
                                                 * y[None, None] ** j[..., None, None]),
                      *box, resolution=200, colors="black", linewidths=1.8, label=f"the conic ({state['kind']})")
        for member, color in zip(state["members"], ("C0", "C2")):
            plot_line(ax, member, *box, color=color, linewidth=2.0)
        plot_points(ax, state["ticks"], markersize=3, color="0.3")
        plot_points(ax, state["control"], labels=[f"P{k}" for k in range(3)], offsets=[(-16, 6), (6, 6), (6, 6)],
                    color="C1", markersize=7)
        plot_points(ax, [state["qa"], state["qb"]], labels=["Qa", "Qb"], offsets=[(6, 2), (6, -12)], color="C4",
                    marker="s", markersize=5)
        plot_points(ax, [state["point"]], color="C3", markersize=9)
        set_box(ax, *box)
        ax.legend(fontsize=8, loc="lower left")
        ax.set_title(f"two pencils meet at P({state['t']:.2f}) on a conic", fontsize=10)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        c = state["implicit"]
        terms = [(c[2, 0], "x²"), (c[1, 1], "xy"), (c[0, 2], "y²"), (c[1, 0], "x"), (c[0, 1], "y"), (c[0, 0], "")]
        equation = " ".join(f"{v:+.3g}{name}" for v, name in terms if abs(v) > 1e-12) + " = 0"
        point = _cartesian(state["point"])
        where = "at infinity" if point is None else _fmt(point)
        return "<br>".join([
            f"P0 = l00 × l10, P1 = (Qa + Qb)/2, P2 = l01 × l11; weights {_fmt(state['weights'])}",
            f"ℓ00 ℓ11 − ℓ01 ℓ10 = {equation}: {state['kind']}",
            f"P({state['t']:.2f}) = {where}",
        ])


def two_pencils_explorer(t: float = 0.5) -> TwoPencilsExplorer:
    """Sliders `t`, `turn01`, `turn11` (turn the pencils' second lines about their axes): a conic. Notes §18.2.1.

    The pencils turn about (0, 0) and (4, 0); at zero turns they are the course's
    lines of Figure 18.7, l00 = (2, -1, 0), l01 = (2, -3, 0), l10 = (2, 3, -8),
    l11 = (4, 2, -16), which meet on an ellipse. `update` returns {"t", "lines"
    (4, 3), "control" (3, 3) homogeneous, "weights", "implicit" (3, 3), "kind",
    "members" (the two lines of parameter t), "point" their meet, "qa" = l00 × l11,
    "qb" = l01 × l10, "ticks" (11, 3) the points of t = 0, 0.1, ..., 1}.
    """
    return TwoPencilsExplorer(t)


# ---------------------------------------------------------------- the double point of a cubic


CUBICS = {
    "notes' cubic (crunode)": np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 2.0], [3.0, 0.0]]),
    "loop inside [0, 1]": np.array([[0.0, 0.0], [4.0, 3.0], [-1.0, 3.0], [3.0, 0.0]]),
    "cusp": np.array([[0.0, 0.0], [3.0, 3.0], [0.0, 3.0], [3.0, 0.0]]),
    "acnode": np.array([[3.0, 0.0], [3.0, 1.0], [4.0, 2.0], [6.0, 6.0]]),
}
SHIFT = {"min": -2.0, "max": 2.0, "step": 0.05, "readout_format": ".2f"}


def _kind(parameters: np.ndarray) -> str:
    if len(parameters) < 2:
        return "reached only as t → ±∞"
    if np.iscomplexobj(parameters):
        return "acnode (complex parameters)"
    if abs(parameters[1] - parameters[0]) < 1e-4:
        return "cusp (one double parameter)"
    return "crunode (two real parameters)"


class DoublePointExplorer(Explorer):
    """A cubic whose inner control points move, its pencil and the pencil's axis: the double point. Notes §18.4.2."""

    def __init__(self, curve: str = "notes' cubic (crunode)"):
        controls = {
            "curve": widgets.Dropdown(description="curve", options=list(CUBICS), value=curve),
            "dx1": _slider(widgets.FloatSlider, "move P1: x", value=0.0, **SHIFT),
            "dy1": _slider(widgets.FloatSlider, "move P1: y", value=0.0, **SHIFT),
            "dx2": _slider(widgets.FloatSlider, "move P2: x", value=0.0, **SHIFT),
            "dy2": _slider(widgets.FloatSlider, "move P2: y", value=0.0, **SHIFT),
        }
        super().__init__(controls)

    # From the cusp preset, moving P1 sideways passes acnode (dx1 < 0), cusp (dx1 = 0) and crunode (dx1 > 0):
    # the page without a kernel sweeps that path.
    static_control = "dx1"

    def compute(self, curve: str, dx1: float, dy1: float, dx2: float, dy2: float) -> dict:
        points = CUBICS[curve] + np.array([[0.0, 0.0], [dx1, dy1], [dx2, dy2], [0.0, 0.0]])
        try:
            point = moving_lines.cubic_double_point(points)
        except ValueError as err:
            raise ValueError(f"dx1, dy1, dx2, dy2: {err}") from None
        pencil = moving_lines.cubic_pencil(points)
        parameters = moving_lines.double_point_parameters(points)
        low, high = points.min(axis=0), points.max(axis=0)
        margin = 0.35 * max(high - low) + 0.5
        return {
            "points": points,
            "double_point": point,
            "cartesian": _cartesian(point),
            "pencil": pencil,
            "parameters": parameters,
            "kind": _kind(parameters),
            "box": ((low[0] - margin, high[0] + margin), (low[1] - margin, high[1] + margin)),
        }

    def draw(self, ax, state: dict) -> None:
        points, box = state["points"], state["box"]
        members = moving_lines.moving_line_eval(state["pencil"], np.linspace(-2.0, 3.0, 26))
        plot_lines(ax, members, *box, cmap="viridis", linewidth=0.7, alpha=0.45)
        ax.plot(*bezier_samples(points, interval=(-3.0, 4.0), samples=700).T, color="C0", linewidth=1.0,
                linestyle=":", label="t outside [0, 1]")
        ax.plot(*bezier_samples(points).T, color="C0", linewidth=2.4, label="t in [0, 1]")
        plot_control_polygon(ax, points, labels=True, alpha=0.6)
        real = state["parameters"][np.isreal(state["parameters"])].real
        if real.size:
            ax.plot(*bezier.evaluate(points, real).T, "o", color="C1", markersize=5)
        if state["cartesian"] is not None:
            ax.plot(*state["cartesian"], **AXIS_STYLE, label="axis of the pencil = double point")
        set_box(ax, *box)
        ax.legend(fontsize=8, loc="lower left")
        ax.set_title(f"double point: {state['kind']}", fontsize=10)

    def describe(self, state: dict) -> str:
        point = state["double_point"]
        where = "at infinity, direction " + _fmt(point[:2]) if state["cartesian"] is None else _fmt(state["cartesian"])
        parameters = ", ".join(f"{p:.4g}" for p in state["parameters"]) or "none finite"
        gap = ""
        if len(state["parameters"]) == 2:
            size = abs(state["parameters"][1] - state["parameters"][0])
            gap = " (|t₁ − t₂| ≈ 0)" if size < 1e-6 else f" (|t₁ − t₂| = {size:.3g})"
        return "<br>".join([
            f"pencil {_fmt(state['pencil'][0])} (1 − t) + {_fmt(state['pencil'][1])} t",
            f"its axis, the double point: {where}",
            f"reached at t = {parameters}{gap}: {state['kind']}",
        ])


def double_point_explorer(curve: str = "notes' cubic (crunode)") -> DoublePointExplorer:
    """Dropdown `curve` and sliders `dx1`, `dy1`, `dx2`, `dy2` moving P1 and P2: a cubic's double point. Notes §18.4.2.

    The "cusp" preset has its cusp at zero shifts; moving P1 sideways (`dx1`)
    opens it into a loop (dx1 > 0, a crunode) or closes it to an isolated
    point (dx1 < 0, an acnode), the path the static figure sweeps.

    `update` returns {"points" (4, 2), "double_point" (3,) homogeneous,
    "cartesian" (2,) or None at infinity, "pencil" (2, 3), "parameters" (the
    parameters of the double point, complex for an acnode), "kind", "box"}.
    """
    return DoublePointExplorer(curve)


# ---------------------------------------------------------------- tangent moving lines and reciprocal curves


TANGENT_CURVES = {
    "S-curve (inflection)": np.array([[-1.5, -1.0], [-0.5, 2.0], [0.5, -3.0], [1.5, 0.5]]),
    "cusp": np.array([[-1.5, -1.2], [1.5, 1.8], [-1.5, 1.8], [1.5, -1.2]]),
    "arch (convex)": np.array([[-2.0, -1.0], [-1.0, 1.5], [1.0, 1.5], [2.0, -1.0]]),
}


class TangentExplorer(Explorer):
    """A curve with its tangent moving line, and the reciprocal curve the tangents trace read as points. Notes §18.5."""

    figsize = (6.9, 3.6)

    def __init__(self, curve: str = "S-curve (inflection)", t: float = 0.5):
        controls = {
            "curve": widgets.Dropdown(description="curve", options=list(TANGENT_CURVES), value=curve),
            "t": _slider(widgets.FloatSlider, "t", value=t, **T),
        }
        super().__init__(controls)

    static_control = "t"

    def dual_axes(self):
        if getattr(self, "dual", None) is None:
            self.ax.set_position([0.03, 0.08, 0.45, 0.8])
            self.dual = self.figure.add_axes([0.52, 0.08, 0.45, 0.8])
        return self.dual

    def _clear(self) -> None:
        super()._clear()
        if getattr(self, "dual", None) is not None:
            main, self.ax = self.ax, self.dual
            try:
                super()._clear()
            finally:
                self.ax = main

    def compute(self, curve: str, t: float) -> dict:
        points = TANGENT_CURVES[curve]
        lines = moving_lines.tangent_moving_line(points)
        ts = np.linspace(0.0, 1.0, 400)
        traced = bezier.de_casteljau(lines, ts)
        with np.errstate(divide="ignore", invalid="ignore"):
            reciprocal = traced[:, :2] / traced[:, 2:]
        reciprocal[np.abs(reciprocal).max(axis=1) > 40] = np.nan  # tangents through the origin go to infinity
        h = bezier.to_homogeneous(points, np.ones(len(points)))
        envelope = bezier.de_casteljau(moving_lines.envelope(lines), ts)
        curve_h = bezier.de_casteljau(h, ts)
        return {
            "curve": curve,
            "points": points,
            "t": t,
            "lines": lines,
            "tangent": moving_lines.moving_line_eval(lines, t),
            "point": bezier.evaluate(points, t),
            "reciprocal": reciprocal,
            "dual_point": _cartesian(moving_lines.moving_line_eval(lines, t)),
            # The envelope of the tangent lines is the curve again: L × L' is a multiple of P(t).
            "envelope_error": float(np.abs(np.cross(envelope, curve_h)).max() / np.abs(envelope).max()),
            "hodograph": moving_lines.scaled_hodograph(points),
        }

    def draw(self, ax, state: dict) -> None:
        points = state["points"]
        box = ((-3.0, 3.0), (-3.0, 3.0))
        family = moving_lines.moving_line_eval(state["lines"], np.linspace(0.0, 1.0, 31))
        plot_lines(ax, family, *box, cmap="viridis", linewidth=0.6, alpha=0.4)
        ax.plot(*bezier_samples(points).T, color="black", linewidth=2.2, label="curve A = P(t)")
        plot_line(ax, state["tangent"], *box, color="C3", linewidth=2.0, label="tangent = Line(B(t))")
        ax.plot(*state["point"], "o", color="C3", markersize=6)
        ax.plot(0.0, 0.0, "+", color="0.3", markersize=10)
        set_box(ax, *box)
        ax.legend(fontsize=8, loc="lower left")
        ax.set_title("tangent lines envelop the curve", fontsize=10)
        bare_axes(ax)
        dual = self.dual_axes()
        dual_box = ((-4.0, 4.0), (-4.0, 4.0))
        dual.plot(*state["reciprocal"].T, color="C2", linewidth=2.2, label="reciprocal curve B = Point(P × P')")
        plot_line(dual, [*state["point"], 1.0], *dual_box, color="C0", linewidth=2.0, label="Line(A(t))")
        if state["dual_point"] is not None:
            inside = _clip_to_box(state["dual_point"], dual_box)
            if inside is None:
                dual.plot(*state["dual_point"], "o", color="C3", markersize=6, label="B(t)")
            else:  # off the panel: a hollow marker on its edge, in the direction of B(t)
                dual.plot(*inside, "o", color="C3", markersize=8, markerfacecolor="none", markeredgewidth=2,
                          label="B(t) is off the panel, this way")
        dual.plot(0.0, 0.0, "+", color="0.3", markersize=10)
        set_box(dual, *dual_box)
        dual.legend(fontsize=8, loc="lower left")
        dual.set_title("the dual picture: Line(A(t)) touches B at B(t)", fontsize=10)
        bare_axes(dual)

    def describe(self, state: dict) -> str:
        where = "at infinity" if state["dual_point"] is None else _fmt(state["dual_point"])
        return "<br>".join([
            f"tangent line at t = {state['t']:.2f}: {_fmt(state['tangent'])}; read as a point: {where}",
            "an inflection of A is a cusp of B, a cusp of A an inflection of B",
            f"envelope of the tangent lines vs the curve: |L × L' ∥ P| error {state['envelope_error']:.1e}",
        ])


def tangent_explorer(curve: str = "S-curve (inflection)", t: float = 0.5) -> TangentExplorer:
    """Dropdown `curve` and slider `t`: the tangent moving line and the reciprocal curve. Notes §18.5.

    The default t = 0.5 lies next to the S-curve's inflection (t = 0.485), so
    B(t) starts next to the reciprocal's cusp; where B(t) leaves the panel (a
    tangent line close to the origin), a hollow marker on the panel's edge
    points towards it.

    `update` returns {"curve", "points", "t", "lines" (2n-1, 3) the tangent
    moving line, "tangent" its line at t, "point" P(t), "reciprocal" (400, 2)
    the reciprocal curve (NaN where it runs off), "dual_point" B(t) or None,
    "envelope_error", "hodograph" the scaled hodograph (2n-1, 2)}.
    """
    return TangentExplorer(curve, t)

"""Explorers of chapter 21 of the notes (maps of quadrilaterals): the bilinear map, birational weights, warping.

All three move the four corners of a quad (sliders, or with ipympl the mouse;
the points are listed around the boundary, Q00, Q10, Q11, Q01). The quad
explorer adds a point E and shows the bilinear map's iso-lines, both
pre-images of E in the (s, t)-plane below, and the fold where a non-convex quad
folds over itself. The birational explorer sets three weights and solves
(21.6) for the fourth as the corners move, so both families of iso-lines stay
pencils through their axes As and At. The warp explorer draws one picture
through the bilinear, the birational and the projective map of the same quad.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from cagd_ref import quad_maps

from ..plotting.quads import (
    T_COLOR,
    course_image,
    isoline_samples,
    plot_axes_points,
    plot_fold,
    plot_isolines,
    plot_quad,
    plot_warped,
)
from ._base import TwoPanels, _fmt, _slider
from .ch02 import ControlPointEditor
from .ch10 import _ExtraControls

__all__ = [
    "quad_explorer",
    "birational_explorer",
    "warp_explorer",
    "QuadExplorer",
    "BirationalExplorer",
    "WarpExplorer",
]

# Figure 21.1's quad, listed around its boundary: Q00, Q10, Q11, Q01.
NOTES_CORNERS = np.array([[0.0, 0.0], [12.0, 0.0], [12.0, 4.0], [8.0, 6.0]])
NOTES_E = np.array([8.0, 4.0])
ISO_VALUES = np.linspace(0.0, 1.0, 5)
CORNER_SLIDERS = "x0..y3"


def _quad_of(corners: np.ndarray) -> np.ndarray:
    """Corners around the boundary (Q00, Q10, Q11, Q01) -> the quad [[Q00, Q01], [Q10, Q11]], (2, 2, 2)."""
    return np.array([[corners[0], corners[3]], [corners[1], corners[2]]])


def _checked(corners: np.ndarray) -> np.ndarray:
    quad = _quad_of(corners)
    try:
        quad_maps.corner_determinants(quad)
    except ValueError as err:
        raise ValueError(f"{CORNER_SLIDERS}: {err}") from None
    return quad


def _kind(quad: np.ndarray) -> str:
    negative = int((quad_maps.corner_determinants(quad) < 0).sum())
    if negative in (0, 4):
        return "convex"
    return "non-convex" if negative in (1, 3) else "twisted"


def _square(ax) -> None:
    ax.plot([0, 1, 1, 0, 0], [0, 0, 1, 1, 0], color="black", linewidth=1.2)
    ax.set_xlabel("s", fontsize=8)
    ax.set_ylabel("t", fontsize=8)


# ---------------------------------------------------------------- the bilinear map and its two pre-images


class QuadExplorer(TwoPanels, ControlPointEditor, _ExtraControls):
    """Four corners and a point E: the bilinear iso-lines, E's pre-images below, the fold. Notes §21, Fig. 21.1."""

    figsize = (6.5, 7.4)

    def __init__(self, corners=None, point=None, draggable: bool | None = None):
        start = np.vstack([NOTES_CORNERS if corners is None else np.asarray(corners, dtype=float),
                           NOTES_E if point is None else np.asarray(point, dtype=float)])
        if start.shape != (5, 2):
            raise ValueError(f"corners, point: expected four corners (4, 2) and a point (2,), got {start.shape}")
        super().__init__(start, None, draggable)

    def extra_controls(self) -> dict:
        return {"extend": widgets.Checkbox(description="t from 0 to 2 (Fig. 21.1b)", value=False)}

    def compute(self, **values) -> dict:
        points = self.current_points(values)
        quad = _checked(points[:4])
        point = points[4]
        try:
            pre = quad_maps.bilinear_inverse(quad, point)
        except ValueError as err:
            raise ValueError(f"x4, y4: {err}") from None
        inside = np.all((pre >= -1e-9) & (pre <= 1 + 1e-9), axis=1)
        return {"points": points, "quad": quad, "point": point, "preimages": pre, "inside": inside,
                "kind": _kind(quad), "extend": values["extend"]}

    def draw(self, ax, state: dict) -> None:
        quad = state["quad"]
        t_span = (0.0, 2.0) if state["extend"] else (0.0, 1.0)
        plot_isolines(ax, quad, values=ISO_VALUES, family="s", span=t_span)
        plot_isolines(ax, quad, values=np.linspace(*t_span, 9 if state["extend"] else 5), family="t")
        plot_quad(ax, quad)
        plot_fold(ax, quad)
        for t in state["preimages"][:, 1]:
            line = isoline_samples(quad, t=[t], span=(-0.5, 2.5))[0]
            ax.plot(*line.T, color=T_COLOR, linestyle=":", linewidth=1.6)
        ax.plot(*state["point"], "o", color="C1", markersize=8, label="E (draggable)")
        ax.set_xlim(*self.limits)
        ax.set_ylim(*self.limits)
        ax.set_aspect("equal", adjustable="box")
        count = len(state["preimages"])
        ax.set_title(f"{state['kind']} quad: E has {count} pre-image{'s' if count != 1 else ''} "
                     f"({int(state['inside'].sum())} in the square)", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")
        lower = self.lower_axes()
        _square(lower)
        for (s, t), inside in zip(state["preimages"], state["inside"]):
            lower.plot(s, t, "o", color="C1" if inside else "0.5", markersize=8)
            lower.annotate(f"({s:.3g}, {t:.3g})", (s, t), xytext=(6, 4), textcoords="offset points", fontsize=8)
        lower.set_xlim(-0.6, 2.6)
        lower.set_ylim(-0.6, 2.6)
        lower.set_aspect("equal", adjustable="box")

    def describe(self, state: dict) -> str:
        c = quad_maps.corner_determinants(state["quad"])
        rows = [f"E = {_fmt(state['point'])}: pre-images " +
                (", ".join(_fmt(p) for p in state["preimages"]) or "none (E is beyond the fold)")]
        rows.append(f"corner determinants C00, C10, C11, C01 = {c[0, 0]:.3g}, {c[1, 0]:.3g}, {c[1, 1]:.3g}, "
                    f"{c[0, 1]:.3g}")
        if state["kind"] != "convex":
            rows.append("the fold (green) runs through the quad: part of it is covered twice by the square")
        return "<br>".join(rows)


def quad_explorer(corners=None, point=None, draggable: bool | None = None) -> QuadExplorer:
    """Sliders x0, y0 .. x3, y3 for the corners (Q00, Q10, Q11, Q01) and x4, y4 for E: the bilinear map. Notes §21.

    Default: Figure 21.1's quad and E = (8, 4). `extend` draws the t-lines for
    t in [0, 2] (Figure 21.1b). With `draggable` (ipympl) the points can be
    dragged. `update` returns {"points" (5, 2), "quad" (2, 2, 2), "point",
    "preimages" (k, 2), "inside" (k,) bool, "kind" ('convex', 'non-convex',
    'twisted'), "extend"}.
    """
    return QuadExplorer(corners, point, draggable)


# ---------------------------------------------------------------- birational weights


class BirationalExplorer(ControlPointEditor, _ExtraControls):
    """Three weights on sliders, the fourth from (21.6): both families of iso-lines are pencils. Notes §21.1-21.3."""

    figsize = (6.5, 6.0)

    def __init__(self, corners=None, draggable: bool | None = None):
        start = NOTES_CORNERS if corners is None else np.asarray(corners, dtype=float)
        if start.shape != (4, 2):
            raise ValueError(f"corners: expected four corners (4, 2), got {start.shape}")
        super().__init__(start, None, draggable)

    def extra_controls(self) -> dict:
        options = {"min": -3.0, "max": 3.0, "step": 0.05, "readout_format": ".2f"}
        return {
            "w00": _slider(widgets.FloatSlider, "w00", value=1.0, **options),
            "w10": _slider(widgets.FloatSlider, "w10", value=1.0, **options),
            "w01": _slider(widgets.FloatSlider, "w01", value=5 / 3, **options),
            "solve": widgets.Checkbox(description="w11 from (21.6)", value=True),
        }

    def compute(self, **values) -> dict:
        quad = _checked(self.current_points(values))
        weights = np.array([[values["w00"], values["w01"]], [values["w10"], 1.0]])
        if values["solve"]:
            try:
                weights[1, 1] = quad_maps.birational_weight(quad, weights)
            except ValueError as err:
                raise ValueError(f"w00, w10, w01: {err}") from None
        a_s, a_t = quad_maps.pencil_axes(quad)
        birational = quad_maps.is_birational(quad, weights)
        base = quad_maps.base_point(quad, weights) if birational and np.any(weights[1, 1]) else None
        return {"points": self.current_points(values), "quad": quad, "weights": weights, "axes": (a_s, a_t),
                "residual": quad_maps.weight_condition(quad, weights), "birational": birational, "base": base}

    def draw(self, ax, state: dict) -> None:
        quad, weights = state["quad"], state["weights"]
        plot_isolines(ax, quad, weights, ISO_VALUES, "s")
        plot_isolines(ax, quad, weights, ISO_VALUES, "t")
        # Dashed: the same lines run on beyond the quad, to the axes when they are pencils.
        plot_isolines(ax, quad, weights, ISO_VALUES, "s", span=(-3.0, 4.0), label=False, linestyle="--",
                      linewidth=0.6, alpha=0.5)
        plot_isolines(ax, quad, weights, ISO_VALUES, "t", span=(-3.0, 4.0), label=False, linestyle="--",
                      linewidth=0.6, alpha=0.5)
        plot_quad(ax, quad)
        plot_axes_points(ax, quad)
        a_s, a_t = state["axes"]
        # The frame of the sliders, widened to show both pencils' axes when they lie near it (A_t = (20, 0) of
        # the notes' quad lies just right of the default frame).
        low, high = np.array([self.limits] * 2, dtype=float).T
        reach = 2 * (high - low)
        for axis in (a_s, a_t):
            if abs(axis[2]) > 1e-12:
                point = axis[:2] / axis[2]
                if np.all((point > low - reach) & (point < high + reach)):
                    low, high = np.minimum(low, point - 2.5), np.maximum(high, point + 2.5)
        if state["base"] is not None:
            line = state["base"].line
            xs = np.array([low[0], high[0]])
            if abs(line[1]) > 1e-12:
                ax.plot(xs, -(line[0] * xs + line[2]) / line[1], ":", color="C2", label="singular line $A_sA_t$")
        ax.set_xlim(low[0], high[0])
        ax.set_ylim(low[1], high[1])
        ax.set_aspect("equal", adjustable="box")
        title = "birational: two pencils" if state["birational"] else "not birational: the iso-lines miss the axes"
        ax.set_title(f"w11 = {weights[1, 1]:.4g}, {title}", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")

    def describe(self, state: dict) -> str:
        w = state["weights"]
        rows = [f"weights w00, w10, w01, w11 = {w[0, 0]:.3g}, {w[1, 0]:.3g}, {w[0, 1]:.3g}, {w[1, 1]:.4g}",
                f"(21.6) residual (L − R)/(|L| + |R|) = {state['residual']:.2e}"]
        if state["base"] is not None:
            rows.append(f"base point (s*, t*) = ({state['base'].s:.4g}, {state['base'].t:.4g}): the whole line "
                        "A<sub>s</sub>A<sub>t</sub> has these parameters")
        return "<br>".join(rows)


def birational_explorer(corners=None, draggable: bool | None = None) -> BirationalExplorer:
    """Corner sliders x0..y3 (Q00, Q10, Q11, Q01), weights w00, w10, w01 and `solve` (w11 from (21.6)). Notes §21.1.

    Default: Figure 21.2's quad with w01 = 5/3. With `solve` off, w11 = 1.
    `update` returns {"points" (4, 2), "quad", "weights" (2, 2), "axes" (As,
    At) homogeneous, "residual" of (21.6), "birational", "base" (a
    `quad_maps.BasePoint` or None)}.
    """
    return BirationalExplorer(corners, draggable)


# ---------------------------------------------------------------- image warping


class WarpExplorer(ControlPointEditor, _ExtraControls):
    """One picture through three maps of the same quad: bilinear, birational, projective. Notes §21.4-21.5."""

    figsize = (6.9, 3.0)  # the book's column: its text is shown at full size
    MAPS = ("bilinear", "birational", "projective")

    def __init__(self, corners=None, resolution: int = 96, draggable: bool | None = None):
        start = NOTES_CORNERS if corners is None else np.asarray(corners, dtype=float)
        if start.shape != (4, 2):
            raise ValueError(f"corners: expected four corners (4, 2), got {start.shape}")
        self.image = course_image(32)
        self.resolution = int(resolution)
        self.panels = None
        super().__init__(start, None, draggable)

    def extra_controls(self) -> dict:
        return {"grid": widgets.Checkbox(description="iso-lines", value=True)}

    def weights_of(self, quad: np.ndarray, kind: str):
        if kind == "bilinear":
            return None
        if kind == "projective":
            return quad_maps.projective_weights(quad)
        weights = np.ones((2, 2))
        weights[1, 1] = quad_maps.birational_weight(quad, weights)
        return weights

    def compute(self, **values) -> dict:
        quad = _checked(self.current_points(values))
        corners = quad.reshape(4, 2)
        low, high = corners.min(axis=0), corners.max(axis=0)
        margin = 0.05 * (high - low).max()
        window = (tuple(low - margin), tuple(high + margin))
        size = (self.resolution, self.resolution)
        maps = {}
        for kind in self.MAPS:
            try:
                weights = self.weights_of(quad, kind)
            except ValueError as err:
                raise ValueError(f"{CORNER_SLIDERS}: {err}") from None
            raster, covered = quad_maps.warp_image(self.image, quad, window, size, weights)
            maps[kind] = {"weights": weights, "raster": raster, "covered": covered}
        return {"points": self.current_points(values), "quad": quad, "window": window, "maps": maps,
                "grid": values["grid"]}

    def _panels(self):
        if self.panels is None:
            self.ax.set_position([0.03, 0.08, 0.3, 0.8])
            self.panels = [self.ax, self.figure.add_axes([0.36, 0.08, 0.3, 0.8]),
                           self.figure.add_axes([0.69, 0.08, 0.3, 0.8])]
        return self.panels

    def _clear(self) -> None:
        super()._clear()
        for panel in (self.panels or [])[1:]:
            main, self.ax = self.ax, panel
            try:
                super()._clear()
            finally:
                self.ax = main

    def draw(self, ax, state: dict) -> None:
        for panel, kind in zip(self._panels(), self.MAPS):
            entry = state["maps"][kind]
            plot_warped(panel, entry["raster"], entry["covered"], state["window"], state["quad"])
            if state["grid"]:
                plot_isolines(panel, state["quad"], entry["weights"], ISO_VALUES, "s", label=False, linewidth=0.7)
                plot_isolines(panel, state["quad"], entry["weights"], ISO_VALUES, "t", label=False, linewidth=0.7)
            panel.set_title(f"{kind} map", fontsize=9)
            panel.set(xticks=[], yticks=[], xlabel="", ylabel="")

    def describe(self, state: dict) -> str:
        rows = []
        for kind in self.MAPS[1:]:
            w = state["maps"][kind]["weights"]
            rows.append(f"{kind}: w00, w10, w01, w11 = {w[0, 0]:.3g}, {w[1, 0]:.3g}, {w[0, 1]:.3g}, {w[1, 1]:.3g}")
        rows.append("the inverse of each: a square root (bilinear), a ratio of linear functions (the other two)")
        return "<br>".join(rows)


def warp_explorer(corners=None, resolution: int = 96, draggable: bool | None = None) -> WarpExplorer:
    """Corner sliders x0..y3 (Q00, Q10, Q11, Q01) and `grid`: the course's picture warped three ways. Notes §21.5.

    Each panel pulls every pixel of a `resolution`² raster back to the square
    (`quad_maps.warp_image`): by the bilinear inverse, by the birational one
    (w00 = w10 = w01 = 1 and w11 from (21.6)) and by the projective one (the
    weights (21.13)). `update` returns {"points" (4, 2), "quad", "window",
    "maps" {kind: {"weights", "raster", "covered"}}, "grid"}.
    """
    return WarpExplorer(corners, resolution, draggable)

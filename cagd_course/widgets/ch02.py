"""Explorers of chapter 2 of the notes: de Casteljau, control points, weights, elevation,
subdivision, curvature combs and continuity of joined curves."""

from __future__ import annotations

import html
from importlib.util import find_spec

import ipywidgets as widgets
import numpy as np

from cagd_ref._validation import as_count, as_float_array, as_points
from cagd_ref.bezier import de_casteljau, de_casteljau_triangle, elevate, signed_curvature, subdivide
from cagd_ref.continuity import continuity, curvature_comb

from ..plotting.curves import (
    bezier_samples,
    plot_bezier,
    plot_control_polygon,
    plot_curvature_comb,
    plot_de_casteljau,
)
from ._base import (
    CURVE_SAMPLES,
    DEFAULT_CUBIC,
    FAMILY_WEIGHTS,
    Explorer,
    _control_points,
    _fmt,
    _slider,
    _swatch,
    _want_ipympl,
)
from ._static import frame_count

__all__ = [
    "de_casteljau_explorer",
    "control_point_editor",
    "rational_weight_explorer",
    "degree_elevation_explorer",
    "subdivision_explorer",
    "curvature_comb_explorer",
    "continuity_explorer",
    "vertex_distance",
    "subdivide_all",
    "DeCasteljauExplorer",
    "ControlPointEditor",
    "RationalWeightExplorer",
    "DegreeElevationExplorer",
    "SubdivisionExplorer",
    "CurvatureCombExplorer",
    "ContinuityExplorer",
]

# ---------------------------------------------------------------- de Casteljau


def _fit_view(ax, points, pad: float = 0.12) -> None:
    """Equal-aspect limits around `points` (k, 2), with a margin of `pad` times their larger extent.

    The margin leaves room for the point labels. The shorter direction is
    widened to the shape of the axes box, so that matplotlib's equal aspect
    has nothing left to adjust (it would warn about fixed limits otherwise).
    """
    pts = np.asarray(points, dtype=float).reshape(-1, 2)
    low, high = pts.min(axis=0), pts.max(axis=0)
    span = high - low + 2 * pad * max(float((high - low).max()), 1e-9)
    width, height = ax.figure.get_size_inches()
    box = ax.get_position(original=True)
    ratio = (box.height * height) / (box.width * width)  # y extent over x extent of the box
    span = np.maximum(span, [span[1] / ratio, span[0] * ratio])
    centre = (low + high) / 2
    ax.set_xlim(centre[0] - span[0] / 2, centre[0] + span[0] / 2)
    ax.set_ylim(centre[1] - span[1] / 2, centre[1] + span[1] / 2)


class DeCasteljauExplorer(Explorer):
    """The de Casteljau triangle at t and the two halves it splits the curve into. Notes §2.3."""

    key_in_readout = True

    def __init__(self, points=None, extrapolate: bool = False):
        self.points = _control_points(points, DEFAULT_CUBIC)
        self.extrapolate = bool(extrapolate)
        low, high = (-0.5, 1.5) if self.extrapolate else (0.0, 1.0)
        t = _slider(widgets.FloatSlider, "t", min=low, max=high, step=0.01, value=0.5, readout_format=".2f")
        super().__init__({"t": t})

    def compute(self, t: float) -> dict:
        left, right = subdivide(self.points, t)
        return {
            "t": t,
            "point": de_casteljau(self.points, t),
            "left": left,
            "right": right,
            "levels": de_casteljau_triangle(self.points, t),
        }

    def draw(self, ax, state: dict) -> None:
        t = state["t"]
        plot_bezier(ax, self.points, label="P(t), 0 ≤ t ≤ 1", color="C0", alpha=0.6)
        if self.extrapolate:
            plot_bezier(ax, self.points, interval=(-0.5, 1.5), color="C0", linestyle=":", linewidth=1)
        plot_de_casteljau(ax, self.points, t, curve=False)
        ax.plot(*state["left"].T, color="C4", linewidth=6, alpha=0.35)
        ax.plot(*state["right"].T, color="C5", linewidth=6, alpha=0.35)
        # The view fits the triangle (inside [0, 1]: the control polygon), not the dotted extension,
        # which would shrink the construction to a corner of the panel.
        _fit_view(ax, np.vstack(state["levels"]))
        ax.set_title(f"de Casteljau's algorithm at t = {t:.2f}")

    def describe(self, state: dict) -> str:
        # The colour key lives here rather than in a legend: drawing legend text
        # would cost more than everything else an update does.
        t = state["t"]
        return (
            f"P({t:.2f}) = {_fmt(state['point'])}<br>"
            f"{_swatch('C0')} the curve &nbsp; {_swatch('C4')} left piece [0, {t:.2f}] &nbsp; "
            f"{_swatch('C5')} right piece [{t:.2f}, 1]<br>"
            "grey dashes: control polygon; coloured polygons: levels 1, 2, ... of the triangle; black: P(t)"
        )


def de_casteljau_explorer(points=None, extrapolate: bool = False) -> DeCasteljauExplorer:
    """Slider `t` through de Casteljau's triangle (t in [0, 1], or [-0.5, 1.5] with `extrapolate`). Notes §2.3.

    points: (n+1, 2), default a cubic. `update(t=...)` returns {"point" (2,),
    "left" (n+1, 2), "right" (n+1, 2), "levels" (list of level polygons), "t"}.
    """
    return DeCasteljauExplorer(points, extrapolate)


# ---------------------------------------------------------------- control points


class ControlPointEditor(Explorer):
    """Sliders (and, with ipympl, the mouse) move the control points of a Bézier curve. Notes §2.2, §2.9."""

    def __init__(self, points=None, weights=None, draggable: bool | None = None):
        start = _control_points(points, DEFAULT_CUBIC)
        self.weights = None if weights is None else as_float_array(weights, "weights")
        bezier_samples(start, self.weights, samples=2)  # checks the weights against the points once
        self.count = len(start)
        low, high = start.min(), start.max()
        margin = max(0.5 * (high - low), 1.0)
        self.limits = (float(np.floor(low - margin)), float(np.ceil(high + margin)))
        self.pick_radius = 0.05 * (self.limits[1] - self.limits[0])
        controls = {}
        for i, (x, y) in enumerate(start):
            for axis, value in (("x", x), ("y", y)):
                controls[f"{axis}{i}"] = _slider(
                    widgets.FloatSlider, f"{axis}{i}", min=self.limits[0], max=self.limits[1], step=0.05, value=value
                )
        self.draggable = _want_ipympl() if draggable is None else bool(draggable)
        if self.draggable and find_spec("ipympl") is None:
            raise ValueError("draggable: dragging points needs the ipympl package, which is not installed")
        self._dragged: int | None = None
        super().__init__(controls, interactive_canvas=self.draggable)
        if self.draggable:
            self.canvas.mpl_connect("button_press_event", self.on_press)
            self.canvas.mpl_connect("motion_notify_event", self.on_motion)
            self.canvas.mpl_connect("button_release_event", self.on_release)

    def current_points(self, values: dict | None = None) -> np.ndarray:
        """The control points held by the sliders (or by `values`, a dict of slider values), (n+1, 2)."""
        v = self.values if values is None else values
        return np.array([[v[f"x{i}"], v[f"y{i}"]] for i in range(self.count)], dtype=float)

    def compute(self, **values) -> dict:
        points = self.current_points(values)
        return {"points": points, "curve": bezier_samples(points, self.weights, samples=CURVE_SAMPLES)}

    def draw(self, ax, state: dict) -> None:
        plot_bezier(ax, state["points"], self.weights, label="curve")
        plot_control_polygon(ax, state["points"], legend="control polygon")
        ax.set_xlim(*self.limits)
        ax.set_ylim(*self.limits)
        ax.set_aspect("equal", adjustable="box")
        if frame_count():  # a static page: one slider (x0) is swept, nothing can be dragged
            title = "The curve follows P0 as the slider x0 moves it"
        elif self.draggable:
            title = "Drag the control points, or use the sliders"
        else:
            title = "Move the control points with the sliders"
        ax.set_title(title)
        ax.legend(fontsize=8, loc="upper right")

    # Mouse dragging, as plain methods so tests can drive them without a browser.
    def pick(self, x: float, y: float, radius: float | None = None) -> int | None:
        """Index of the control point nearest to (x, y) if it lies within `radius` (data units), else None."""
        radius = self.pick_radius if radius is None else radius
        distances = np.hypot(*(self.current_points() - np.array([x, y], dtype=float)).T)
        nearest = int(np.argmin(distances))
        return nearest if distances[nearest] <= radius else None

    def move_point(self, index: int, x: float, y: float) -> dict:
        """Move control point `index` to (x, y), clamped to the sliders' range, and update."""
        index = as_count(index, "index")
        if index >= self.count:
            raise ValueError(f"index: expected 0 <= index < {self.count}, got {index}")
        x, y = np.clip([x, y], *self.limits)
        return self.update(**{f"x{index}": float(x), f"y{index}": float(y)})

    def on_press(self, event) -> None:
        """Mouse button down: grab the control point under the pointer, if any."""
        if event.inaxes is self.ax and event.xdata is not None:
            self._dragged = self.pick(event.xdata, event.ydata)

    def on_motion(self, event) -> None:
        """Mouse moved: carry the grabbed point along."""
        if self._dragged is not None and event.inaxes is self.ax and event.xdata is not None:
            self.move_point(self._dragged, event.xdata, event.ydata)

    def on_release(self, event) -> None:
        """Mouse button up: let go of the point."""
        self._dragged = None


def control_point_editor(points=None, weights=None, draggable: bool | None = None) -> ControlPointEditor:
    """Sliders x0, y0, x1, y1, ... for the control points of a (rational) Bézier curve. Notes §2.2.

    points: (n+1, 2), default a cubic; weights: None or (n+1,). With
    `draggable=True` (needs ipympl; None means "if running in a kernel with
    ipympl") the points can also be dragged: `pick` finds the nearest point
    within a radius and `move_point` moves it. `update` returns
    {"points" (n+1, 2), "curve" (200, 2)}.
    """
    return ControlPointEditor(points, weights, draggable)


# ---------------------------------------------------------------- rational weights


class RationalWeightExplorer(Explorer):
    """One weight of a rational Bézier curve on a log slider, over a family of fixed weights. Notes §2.9, Fig. 2.13."""

    def __init__(self, points=None, index=None):
        self.points = _control_points(points, DEFAULT_CUBIC, min_count=3)
        n = len(self.points) - 1
        self.index = n // 2 if index is None else as_count(index, "index")
        if self.index > n:
            raise ValueError(f"index: expected 0 <= index <= {n}, got {self.index}")
        # The grey family does not depend on the slider: sample it once.
        self.family = {
            w: bezier_samples(self.points, self.weights_with(w), samples=CURVE_SAMPLES) for w in FAMILY_WEIGHTS
        }
        weight = _slider(widgets.FloatLogSlider, f"w{self.index}", base=10, min=-2, max=2, step=0.02, value=1.0)
        super().__init__({"weight": weight})

    def weights_with(self, weight: float) -> np.ndarray:
        """All weights: one everywhere except `weight` at the explored index, (n+1,)."""
        w = np.ones(len(self.points))
        w[self.index] = weight
        return w

    def compute(self, weight: float) -> dict:
        weights = self.weights_with(weight)
        return {
            "weight": weight,
            "weights": weights,
            "curve": bezier_samples(self.points, weights, samples=CURVE_SAMPLES),
            "family": self.family,
        }

    def draw(self, ax, state: dict) -> None:
        plot_control_polygon(ax, self.points, legend="control polygon")
        # Label each family member where it comes closest to the weighted point, the spot the weight pulls.
        target = self.points[self.index]
        for w, curve in state["family"].items():
            ax.plot(*curve.T, color="0.6", linewidth=1)
            near = curve[np.nanargmin(np.hypot(*(curve - target).T))]
            ax.annotate(f"{w:g}", near, fontsize=8, color="0.35", xytext=(3, -9), textcoords="offset points")
        name = f"$w_{{{self.index}}}$"
        plot_bezier(ax, self.points, state["weights"], color="C3", label=f"{name} = {state['weight']:.3g}")
        family = ", ".join(f"{w:g}" for w in FAMILY_WEIGHTS)
        ax.set_title(f"Changing weight {name}\n(grey: {name} = {family})", fontsize=9, pad=14)
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        return f"weights = {_fmt(state['weights'])}"


def rational_weight_explorer(points=None, index=None) -> RationalWeightExplorer:
    """Log slider `weight` (0.01..100) for the weight of control point `index` (default the middle one). Notes §2.9.

    Draws the curves for weights 0, 0.5, 1, 2, 5, 10 (grey, as in the notes'
    Fig. 2.13) and the current one. `update` returns {"weights" (n+1,),
    "curve" (200, 2), "weight", "family" (dict weight -> (200, 2))}.
    """
    return RationalWeightExplorer(points, index)


# ---------------------------------------------------------------- convergence of polygons


def vertex_distance(vertices, points, samples: int = 2001) -> float:
    """Largest distance from any of `vertices` (k, d) to the Bézier curve of `points`. Notes §2.4, §2.5.

    The curve is replaced by the polyline through `samples` of its points; the
    error of that is O(1/samples²) of the curve's size.
    """
    v = as_points(vertices, "vertices")
    curve = de_casteljau(points, np.linspace(0, 1, as_count(samples, "samples", minimum=2)))
    segments = curve[1:] - curve[:-1]
    offsets = v[:, None, :] - curve[None, :-1, :]
    lengths = np.einsum("ij,ij->i", segments, segments)
    u = np.clip(np.einsum("kij,ij->ki", offsets, segments) / np.where(lengths > 0, lengths, 1), 0, 1)
    return float(np.linalg.norm(offsets - u[..., None] * segments, axis=2).min(axis=1).max())


def subdivide_all(points, depth: int) -> np.ndarray:
    """Split a Bézier curve at t = 1/2 `depth` times over: 2**depth polygons, shape (2**depth, n+1, d). Notes §2.5.

    All pieces of one generation are halved together on a stacked array.
    """
    pieces = as_points(points)[None]
    for _ in range(as_count(depth, "depth")):
        level, lefts, rights = pieces, [pieces[:, 0]], [pieces[:, -1]]
        while level.shape[1] > 1:
            level = 0.5 * (level[:, :-1] + level[:, 1:])
            lefts.append(level[:, 0])
            rights.append(level[:, -1])
        left = np.stack(lefts, axis=1)
        right = np.stack(rights[::-1], axis=1)
        # Interleave so the pieces stay in parameter order: left0, right0, left1, right1, ...
        pieces = np.stack([left, right], axis=1).reshape(-1, *left.shape[1:])
    return pieces


class DegreeElevationExplorer(Explorer):
    """Repeated degree elevation: the polygons close in on the curve. Notes §2.4."""

    def __init__(self, points=None):
        self.points = _control_points(points, DEFAULT_CUBIC)
        steps = _slider(widgets.IntSlider, "steps", min=0, max=20, value=1)
        super().__init__({"steps": steps})

    def compute(self, steps: int) -> dict:
        polygon = elevate(self.points, steps)
        return {"steps": steps, "polygon": polygon, "distance": vertex_distance(polygon, self.points)}

    def draw(self, ax, state: dict) -> None:
        plot_bezier(ax, self.points, label="curve")
        for k in range(1, state["steps"]):
            ax.plot(*elevate(self.points, k).T, color="0.75", linewidth=0.8)
        plot_control_polygon(ax, self.points, labels=False, color="0.3", legend=f"degree {len(self.points) - 1}")
        degree = len(state["polygon"]) - 1
        ax.plot(*state["polygon"].T, "o-", color="C1", markersize=3, linewidth=1.2, label=f"degree {degree}")
        steps = state["steps"]
        ax.set_title(f"Degree elevation, {steps} step{'s' * (steps != 1)}: max vertex distance {state['distance']:.3g}")
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        return f"degree {len(state['polygon']) - 1}, max distance from a vertex to the curve: {state['distance']:.4g}"


def degree_elevation_explorer(points=None) -> DegreeElevationExplorer:
    """Slider `steps` (0..20): the control polygon after that many degree elevations. Notes §2.4.

    `update` returns {"polygon" (n+1+steps, 2), "distance", "steps"}, where
    distance is the largest distance from a vertex of the polygon to the curve
    (see `vertex_distance`); it goes to zero as steps grows.
    """
    return DegreeElevationExplorer(points)


class SubdivisionExplorer(Explorer):
    """Repeated midpoint subdivision: 2^depth polygons that hug the curve. Notes §2.5."""

    def __init__(self, points=None):
        self.points = _control_points(points, DEFAULT_CUBIC)
        depth = _slider(widgets.IntSlider, "depth", min=0, max=6, value=1)
        super().__init__({"depth": depth})

    def compute(self, depth: int) -> dict:
        polygons = subdivide_all(self.points, depth)
        distance = vertex_distance(polygons.reshape(-1, 2), self.points)
        return {"depth": depth, "polygons": polygons, "distance": distance}

    def draw(self, ax, state: dict) -> None:
        plot_bezier(ax, self.points, color="0.6", linewidth=4, alpha=0.5, label="curve")
        plot_control_polygon(ax, self.points, color="0.6", legend="original polygon")
        for k, polygon in enumerate(state["polygons"]):
            ax.plot(*polygon.T, "o-", color=("C0", "C3")[k % 2], markersize=2.5, linewidth=1)
        count = len(state["polygons"])
        _fit_view(ax, self.points)  # room above the top control point for its label
        ax.set_title(f"Subdivision depth {state['depth']}: {count} polygon{'s' * (count > 1)}, "
                     f"max vertex distance {state['distance']:.3g}", fontsize=10, pad=14)
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        return f"{len(state['polygons'])} pieces, max distance from a vertex to the curve: {state['distance']:.4g}"


def subdivision_explorer(points=None) -> SubdivisionExplorer:
    """Slider `depth` (0..6): the curve split at t = 1/2 repeatedly into 2**depth pieces. Notes §2.5.

    `update` returns {"polygons" (2**depth, n+1, 2), "distance", "depth"};
    distance is the largest distance from any vertex of any piece to the curve.
    """
    return SubdivisionExplorer(points)


# ---------------------------------------------------------------- curvature


def _max_curvature(points, count: int, weights=None) -> float:
    """Largest finite |κ| at the comb's `count` parameters (0 if the curve is straight)."""
    kappa = np.abs(signed_curvature(points, np.linspace(0, 1, count), weights))
    finite = kappa[np.isfinite(kappa)]
    return float(finite.max()) if finite.size else 0.0


class CurvatureCombExplorer(Explorer):
    """A curvature comb with adjustable tooth count and longest-tooth length. Notes §2.11."""

    def __init__(self, points=None, weights=None):
        self.points = _control_points(points, DEFAULT_CUBIC)
        self.weights = weights
        teeth = _slider(widgets.IntSlider, "teeth", min=2, max=200, value=50)
        length = _slider(widgets.FloatSlider, "length", min=0.1, max=3.0, step=0.05, value=1.0)
        super().__init__({"teeth": teeth, "length": length})

    def compute(self, teeth: int, length: float) -> dict:
        bases, tips = curvature_comb(self.points, teeth, length, self.weights)
        return {"bases": bases, "tips": tips, "max_curvature": _max_curvature(self.points, teeth, self.weights)}

    def draw(self, ax, state: dict) -> None:
        plot_bezier(ax, self.points, self.weights, label="curve")
        plot_control_polygon(ax, self.points, legend="control polygon")
        teeth = len(state["bases"])
        plot_curvature_comb(ax, self.points, teeth, self.values["length"], self.weights)
        # The longest tooth has the chosen length; it stands where |κ| is largest.
        ax.set_title(
            f"Curvature comb, {teeth} teeth: longest tooth {self.values['length']:g}, "
            f"at max |κ| = {state['max_curvature']:.3g}",
            fontsize=10,
        )
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        return f"max |κ| = {state['max_curvature']:.4g}"


def curvature_comb_explorer(points=None, weights=None) -> CurvatureCombExplorer:
    """Sliders `teeth` (2..200) and `length` (longest tooth, 0.1..3) of a curvature comb. Notes §2.11.

    `update` returns {"bases" (teeth, 2), "tips" (teeth, 2), "max_curvature"}:
    each tooth's length is length * |κ| / max_curvature.
    """
    return CurvatureCombExplorer(points, weights)


JOIN_P = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.5]])
JOIN_Q_END = np.array([8.0, 1.0])


class ContinuityExplorer(Explorer):
    """Two cubics meeting at P3 = Q0; sliders move Q1, Q2 and the length h of Q's interval. Notes §2.10, §2.11."""

    def __init__(self):
        # Default Q1 = P3 + (P3 - P2): with h = 1 the joint starts out C1.
        q1 = 2 * JOIN_P[3] - JOIN_P[2]
        controls = {
            "q1x": _slider(widgets.FloatSlider, "Q1 x", min=-2.0, max=10.0, step=0.05, value=q1[0]),
            "q1y": _slider(widgets.FloatSlider, "Q1 y", min=-6.0, max=6.0, step=0.05, value=q1[1]),
            "q2x": _slider(widgets.FloatSlider, "Q2 x", min=-2.0, max=10.0, step=0.05, value=6.5),
            "q2y": _slider(widgets.FloatSlider, "Q2 y", min=-6.0, max=6.0, step=0.05, value=-1.0),
            "h": _slider(widgets.FloatSlider, "Q length", min=0.25, max=4.0, step=0.05, value=1.0),
        }
        super().__init__(controls)

    def compute(self, q1x: float, q1y: float, q2x: float, q2y: float, h: float) -> dict:
        q = np.array([JOIN_P[3], [q1x, q1y], [q2x, q2y], JOIN_Q_END])
        result = continuity(JOIN_P, q, (0.0, 1.0), (1.0, 1.0 + h))
        return {"continuity": result, "text": str(result), "p": JOIN_P.copy(), "q": q, "h": h}

    def draw(self, ax, state: dict) -> None:
        p, q = state["p"], state["q"]
        # One scale for both combs, so their teeth can be compared across the joint.
        kp, kq = _max_curvature(p, 40), _max_curvature(q, 40)
        largest = max(kp, kq, 1e-300)
        for points, kappa, color, name in ((p, kp, "C0", "P"), (q, kq, "C2", "Q")):
            plot_bezier(ax, points, color=color, label=f"{name}")
            # Q0 is P3: one label at the joint is enough.
            names = [f"${name}_{{{i}}}$" if (name, i) != ("Q", 0) else "" for i in range(len(points))]
            plot_control_polygon(ax, points, labels=names)
            if kappa > 0:
                plot_curvature_comb(ax, points, 40, 1.5 * kappa / largest, color=color, alpha=0.8, label=None)
        ax.set_title(f"Joint: {state['text']}   (P on [0, 1], Q on [1, {1 + state['h']:.2f}])", fontsize=10)
        ax.legend(fontsize=8, loc="upper right")

    def describe(self, state: dict) -> str:
        return f"<b>{html.escape(state['text'])}</b>"


def continuity_explorer() -> ContinuityExplorer:
    """Two cubics joined at P3 = Q0; controls `q1x, q1y, q2x, q2y` and Q's interval length `h`. Notes §2.10.

    P lives on [0, 1] and Q on [1, 1 + h]. Both curves get curvature combs on
    one common scale. `update` returns {"continuity" (a `Continuity`), "text"
    (e.g. "C1, G1"), "p", "q", "h"}.
    """
    return ContinuityExplorer()

"""Explorers of chapter 4 of the notes: rasterising a Bézier curve by forward differencing, and the
rounding drift of forward differencing against Horner's rule."""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.collections import LineCollection

from cagd_ref.forward_differencing import bezier_by_differences, drift, find_gaps, pixels_along, raster_delta
from cagd_ref.polynomials import bernstein_to_power

from ..examples import notes_example
from ..plotting.curves import bezier_samples, plot_control_polygon
from ._base import CURVE_SAMPLES, Explorer, _control_points, _slider

__all__ = ["raster_explorer", "drift_explorer", "RasterExplorer", "DriftExplorer"]

# The course's cubic in pixel coordinates: largest neighbour difference 23, so the notes' δ is 1/69.
(RASTER_CUBIC,) = notes_example("04.raster_cubic").args("points")
# The same shape blown up to nearly 900 pixels wide, where float32 drift becomes visible in pixels.
DRIFT_CUBIC = 25.0 * RASTER_CUBIC
PRECISIONS = {"float32": np.float32, "float64": np.float64}


# ---------------------------------------------------------------- rasterising


class RasterExplorer(Explorer):
    """Pixels painted by forward differencing a Bézier curve with step δ; gaps marked in red. Notes §4.1."""

    figsize = (6.4, 4.8)

    def __init__(self, points=None, delta: float | None = None):
        self.points = _control_points(points, RASTER_CUBIC)
        self.bound = raster_delta(self.points)
        self.curve = bezier_samples(self.points, samples=CURVE_SAMPLES)
        low = np.floor(np.minimum(self.points.min(axis=0), self.curve.min(axis=0))) - 1
        high = np.ceil(np.maximum(self.points.max(axis=0), self.curve.max(axis=0))) + 1
        self.origin = low.astype(int)
        self.size = (high - low).astype(int)
        # The slider reaches down to the bound even for curves thousands of pixels long.
        lowest = min(-3.0, float(np.floor(np.log10(self.bound))))
        slider = _slider(widgets.FloatLogSlider, "δ", base=10, min=lowest, max=np.log10(0.5), step=0.01,
                         value=self.bound, readout_format=".4f")
        self.grid_lines = self._grid_lines()
        super().__init__({"delta": slider})
        if delta is not None:
            self.update(delta=delta)

    def _grid_lines(self) -> np.ndarray:
        """The pixel borders as segments (k, 2, 2): one collection draws far faster than minor ticks."""
        (x0, y0), (w, h) = self.origin, self.size
        xs, ys = x0 + np.arange(w + 1), y0 + np.arange(h + 1)
        vertical = [[(x, y0), (x, y0 + h)] for x in xs]
        horizontal = [[(x0, y), (x0 + w, y)] for y in ys]
        return np.array(vertical + horizontal, dtype=float)

    def compute(self, delta: float) -> dict:
        steps = int(np.ceil(1.0 / delta))
        samples = bezier_by_differences(self.points, steps)
        pixels = pixels_along(samples)
        gaps = find_gaps(pixels)
        # How far the march ends from P_n: a rounding error, which matters where P_n lies on a pixel border.
        end_error = float(np.abs(samples[-1] - self.points[-1]).max())
        return {
            "delta": delta,
            "steps": steps,
            "step": 1.0 / steps,
            "bound": self.bound,
            "samples": samples,
            "pixels": pixels,
            "gaps": gaps,
            "gap_count": len(gaps),
            "end_error": end_error,
        }

    def image(self, pixels: np.ndarray) -> np.ndarray:
        """A (rows, columns) 0/1 image of the grid with the given pixels on, row 0 at the bottom."""
        picture = np.zeros(self.size[::-1])
        columns, rows = (pixels - self.origin).T
        picture[rows, columns] = 1.0
        return picture

    def draw(self, ax, state: dict) -> None:
        (x0, y0), (w, h) = self.origin, self.size
        ax.imshow(self.image(state["pixels"]), cmap="Blues", vmin=0, vmax=1.6, origin="lower",
                  extent=(x0, x0 + w, y0, y0 + h), interpolation="nearest")
        ax.add_collection(LineCollection(self.grid_lines, colors="0.85", linewidths=0.4))
        ax.plot(*self.curve.T, color="0.3", linewidth=0.8, label="the curve")
        plot_control_polygon(ax, self.points, labels=False, color="0.6", markersize=3)
        ax.plot(*state["samples"].T, ".", color="k", markersize=3, label=f"{state['steps'] + 1} points")
        centres = state["pixels"] + 0.5
        jumps = np.stack([centres[state["gaps"]], centres[state["gaps"] + 1]], axis=1)
        ax.add_collection(LineCollection(jumps, colors="C3", linewidths=2, label=f"{state['gap_count']} gaps"))
        ax.set_xlim(x0, x0 + w)
        ax.set_ylim(y0, y0 + h)
        ax.set_aspect("equal", adjustable="box")
        ax.set_title(f"δ = 1/{state['steps']} (gap-free bound 1/(n d) = {state['bound']:.4f}): "
                     f"{state['gap_count']} gaps", fontsize=10)
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        verdict = "no gaps" if state["gap_count"] == 0 else f"<b style='color:#b00'>{state['gap_count']} gaps</b>"
        end = ("the march ends exactly at the last control point" if state["end_error"] == 0 else
               f"the march ends {state['end_error']:.1e} px from the last control point (rounding)")
        return (f"bound δ ≤ {state['bound']:.4f}; step used 1/{state['steps']} = {state['step']:.4f}<br>"
                f"{state['steps'] + 1} points, {len(state['pixels'])} pixels, {verdict}; {end}")


def raster_explorer(points=None, delta: float | None = None) -> RasterExplorer:
    """Log slider `delta` (0.001..0.5): the pixels a planar Bézier curve paints when forward differenced. Notes §4.1.

    points: (n+1, 2) in pixel units, default a cubic spanning about 40 x 30
    pixels; `delta` is the starting step (default the gap-free bound
    `raster_delta(points)`). The curve is marched in ceil(1/δ) steps.
    `update(delta=...)` returns {"bound", "delta", "steps", "step",
    "samples" (steps+1, 2), "pixels" (m, 2), "gaps" (positions), "gap_count",
    "end_error" (largest coordinate distance of the last sample from P_n)}.
    """
    return RasterExplorer(points, delta)


# ---------------------------------------------------------------- drift


class DriftExplorer(Explorer):
    """Error of forward differencing and of Horner's rule along one curve, in float32 or float64. Notes ch. 4."""

    figsize = (6.4, 4.2)

    def __init__(self, points=None):
        self.points = _control_points(points, DRIFT_CUBIC)
        self.coeffs = bernstein_to_power(self.points)
        controls = {
            "steps": _slider(widgets.IntSlider, "steps", min=10, max=20000, step=10, value=2000),
            "precision": widgets.Dropdown(options=list(PRECISIONS), value="float32", description="precision"),
        }
        super().__init__(controls)
        self.figure.subplots_adjust(left=0.13, bottom=0.13)

    def compute(self, steps: int, precision: str) -> dict:
        forward, horner = drift(self.coeffs, 0.0, 1.0 / steps, steps + 1, PRECISIONS[precision])
        return {
            "steps": steps,
            "precision": precision,
            "forward_error": forward,
            "horner_error": horner,
            "final_forward": float(forward[-1]),
            "largest_horner": float(horner.max()),
        }

    def draw(self, ax, state: dict) -> None:
        # The largest error so far, at a few hundred log-spaced steps: the trend, at a fraction of the drawing cost.
        k = np.unique(np.geomspace(1, state["steps"], 300).astype(int))
        if ax.get_xscale() != "log":
            # Set once: switching scales rebuilds the tick machinery, the dearest part of a redraw.
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.minorticks_off()
        for key, color, name in (("forward_error", "C3", "forward differencing"), ("horner_error", "C0", "Horner")):
            envelope = np.maximum.accumulate(state[key])[k]
            shown = envelope > 0  # a log axis cannot show exact zeros
            if not shown.any():  # Horner in float64 is the reference itself: no curve, no legend entry
                continue
            ax.plot(k[shown], envelope[shown], color=color, linewidth=1.5, label=f"{name} ({state['precision']})")
        ax.axhline(0.5, color="0.5", linestyle="--", linewidth=1, label="half a pixel")
        ax.set_xlabel("step k (t = k / steps)")
        ax.set_ylabel("largest error so far (pixels)")
        ax.set_title(f"{state['steps']} steps over [0, 1] in {state['precision']}: "
                     f"forward differencing ends {state['final_forward']:.2g} px off", fontsize=10)
        # Middle left: the curves start low and climb to the right, the half-pixel line runs along the top.
        ax.legend(fontsize=8, loc="center left")

    def describe(self, state: dict) -> str:
        if state["largest_horner"] == 0:
            horner = (f"Horner in {state['precision']} is the reference itself (error 0), "
                      "so it has no curve on the logarithmic axes")
        else:
            horner = f"Horner: never more than {state['largest_horner']:.3g} px off"
        return f"forward differencing: {state['final_forward']:.3g} px off at t = 1; {horner}"


def drift_explorer(points=None) -> DriftExplorer:
    """Slider `steps` (10..20000) and dropdown `precision` ("float32"/"float64"): rounding drift. Notes ch. 4.

    points: (n+1, 2), default a cubic nearly 900 pixels wide. The curve is
    evaluated at t = k / steps, k = 0..steps, by forward differencing and by
    Horner's rule in the chosen precision, each against Horner in float64.
    `update` returns {"forward_error" (steps+1,), "horner_error" (steps+1,),
    "final_forward" (forward error at t = 1), "largest_horner" (Horner's
    largest error), "steps", "precision"}.
    """
    return DriftExplorer(points)

"""Explorers of chapter 11 of the notes (approximation and fairing).

The best constant under two error measures; a fitting lab (noisy samples Q_k of
a shape, parametrization, parameter correction, knots, number of control points,
fairing weight λ, with the residuals and the curvature of the fit); the family of
faired fits as λ grows, shrinking towards the least-squares line, with
interpolation constraints as an option; and fairing within tolerance boxes.
Samples are drawn blue and control polygons red, as in the notes' figures.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from cagd_ref._validation import as_count, as_float_array, as_points, as_scalar
from cagd_ref.approximation import (
    best_constant,
    box_faired_fit,
    centripetal_parameters,
    chord_length_parameters,
    constrained_fit,
    estimate_frames,
    faired_fit,
    fairing_energy,
    fit_error,
    fitting_knots,
    least_squares_fit,
    parameter_correction,
    spline_curvature,
    uniform_parameters,
)
from cagd_ref.bspline import bezier_end_knots, de_boor

from ..examples import notes_example
from ..plotting.fitting import (
    fit_samples,
    plot_boxes,
    plot_error_measures,
    plot_fit,
    plot_residuals,
    plot_samples,
)
from ._base import Explorer, TwoPanels, _slider, _swatch, bare_axes

__all__ = [
    "FIT_SHAPES",
    "sample_shape",
    "best_constant_explorer",
    "fitting_explorer",
    "fairing_weight_explorer",
    "box_fit_explorer",
    "BestConstantExplorer",
    "FittingExplorer",
    "FairingWeightExplorer",
    "BoxFitExplorer",
]

PARAMETRIZATIONS = {"uniform": uniform_parameters, "chord length": chord_length_parameters,
                    "centripetal": centripetal_parameters}
FIT_SHAPES = ("half ellipse", "wave", "spiral")
CONSTRAINTS = {"none": [], "ends": [0, -1], "ends and middle": [0, "middle", -1]}
CURVE_POINTS = 160
SEED = 7


def sample_shape(shape: str, count: int, unevenness: float = 0.0, noise: float = 0.0, seed: int = SEED) -> np.ndarray:
    """Noisy samples (count, 2) of a planar shape at parameters between evenly spaced and random. Notes §11.3.

    shape: "half ellipse" (4 cos θ, 2.5 sin θ), θ in [0, π], the course's arc;
    "wave" (x, 1.5 + sin x), x in [-5, 5]; "spiral" (r cos θ, r sin θ) with
    r = 1 + θ/π, θ in [0, 2.5π]. unevenness in [0, 1] blends the evenly spaced
    parameters with sorted uniform random ones (the ends stay put); noise is the
    standard deviation of the Gaussian noise added to each coordinate. The
    same seed gives the same samples.
    """
    if shape not in FIT_SHAPES:
        raise ValueError(f"shape: expected one of {', '.join(FIT_SHAPES)}, got {shape!r}")
    m = as_count(count, "count", minimum=4)
    blend = as_scalar(unevenness, "unevenness")
    sigma = as_scalar(noise, "noise")
    if not 0 <= blend <= 1 or sigma < 0:
        raise ValueError(f"unevenness: expected a number in [0, 1] and noise >= 0, got {blend} and {sigma}")
    rng = np.random.default_rng(seed)
    random = np.sort(rng.uniform(0, 1, m))
    random[[0, -1]] = 0.0, 1.0
    u = (1 - blend) * np.linspace(0, 1, m) + blend * random
    if shape == "half ellipse":
        theta = np.pi * u
        points = np.column_stack([4 * np.cos(theta), 2.5 * np.sin(theta)])
    elif shape == "wave":
        x = -5 + 10 * u
        points = np.column_stack([x, 1.5 + np.sin(x)])
    else:
        theta = 2.5 * np.pi * u
        r = 1 + theta / np.pi
        points = np.column_stack([r * np.cos(theta), r * np.sin(theta)])
    return points + sigma * rng.normal(size=points.shape)


def _course_arc(points):
    """Planar samples given to a factory, or the course's uneven half ellipse (chapter data)."""
    pts = notes_example("11.uneven_arc").inputs["points"] if points is None else as_points(points)
    if pts.shape[1] != 2 or len(pts) < 6:
        raise ValueError(f"points: the explorers draw planar samples, expected shape (M >= 6, 2), got {pts.shape}")
    return pts


# ---------------------------------------------------------------- best constant


class BestConstantExplorer(Explorer):
    """Five numbers on sliders: the best constant and its error under the L2 and the L∞ measure. Notes §11.1, §11.2."""

    key_in_readout = True

    figsize = (6.5, 4.2)

    def __init__(self, values=None):
        start = notes_example("11.best_constant_l2").inputs["values"] if values is None else as_float_array(
            values, "values")
        if start.shape != (5,):
            raise ValueError(f"values: the explorer has five sliders, expected five numbers, got shape {start.shape}")
        controls = {f"g{k}": _slider(widgets.FloatSlider, f"g{k}", min=0.0, max=10.0, step=0.1, value=float(v))
                    for k, v in enumerate(start)}
        super().__init__(controls)

    def compute(self, **values) -> dict:
        g = np.array([values[f"g{k}"] for k in range(5)])
        if np.ptp(g) == 0:
            raise ValueError("g0..g4: the five numbers are all equal; move one so there is something to approximate")
        l2, linf = best_constant(g, "l2"), best_constant(g, "linf")
        return {"values": g, "l2": l2, "linf": linf,
                "linf_at_mean": float(np.max(np.abs(g - l2[0]))), "l2_at_midrange": float(np.sum((g - linf[0]) ** 2))}

    def draw(self, ax, state: dict) -> None:
        plot_error_measures(ax, state["values"])
        ax.set_title(f"best L2 constant {state['l2'][0]:.3g} (mean), best L∞ constant {state['linf'][0]:.3g} "
                     "(midrange)", fontsize=10)

    def describe(self, state: dict) -> str:
        (mean, e2), (mid, einf) = state["l2"], state["linf"]
        return (f"{_swatch('C0')} L2: A = {mean:.4g}, e = Σ(A−g)² = {e2:.4g} (the midrange gives "
                f"{state['l2_at_midrange']:.4g})<br>{_swatch('C3')} L∞: A = {mid:.4g}, e = max|A−g| = {einf:.4g} "
                f"(the mean gives {state['linf_at_mean']:.4g})<br>each curve is divided by its minimum; "
                "ticks on the axis: the numbers g")


def best_constant_explorer(values=None) -> BestConstantExplorer:
    """Sliders g0..g4 (default the notes' G = {2, 3, 3, 5, 7}): both error measures as functions of A. Notes §11.1.

    `update` returns {"values" (5,), "l2" (A, e), "linf" (A, e), "linf_at_mean", "l2_at_midrange"}.
    """
    return BestConstantExplorer(values)


# ---------------------------------------------------------------- fitting lab


class FittingExplorer(TwoPanels, Explorer):
    """Fit a cubic to noisy samples: parameters, knots, control points, fairing; residuals, curvature. Notes §11.3."""

    key_in_readout = True

    def __init__(self, shape: str = "half ellipse"):
        controls = {
            "shape": widgets.Dropdown(description="shape", options=list(FIT_SHAPES), value=shape),
            "samples": _slider(widgets.IntSlider, "samples", min=8, max=80, value=30),
            "unevenness": _slider(widgets.FloatSlider, "uneven", min=0.0, max=1.0, step=0.05, value=1.0),
            "noise": _slider(widgets.FloatSlider, "noise", min=0.0, max=0.3, step=0.01, value=0.05),
            "parametrization": widgets.Dropdown(description="params", options=list(PARAMETRIZATIONS),
                                                value="chord length"),
            "knots": widgets.Dropdown(description="knots", options=["uniform", "averaging"], value="uniform"),
            "count": _slider(widgets.IntSlider, "control pts", min=4, max=25, value=10),
            "fair": widgets.Checkbox(description="fairing", value=False),
            "weight": _slider(widgets.FloatLogSlider, "λ", min=-8, max=1, step=0.1, value=1e-4),
            "corrections": _slider(widgets.IntSlider, "corrections", min=0, max=10, value=0),
        }
        super().__init__(controls)

    def compute(self, shape, samples, unevenness, noise, parametrization, knots, count, fair, weight,
                corrections=0) -> dict:
        points = sample_shape(shape, samples, unevenness, noise)
        params = PARAMETRIZATIONS[parametrization](points)
        n = 3
        if count > samples and knots == "averaging":
            raise ValueError(f"count: averaging needs at most one control point per sample ({samples}), got {count}")
        knot_vector = fitting_knots(params, count, n, knots)
        w = weight if fair else 0.0
        try:
            control, params, history = parameter_correction(points, params, knot_vector, n, corrections, w)
        except ValueError as err:
            raise ValueError(f"knots, count: {err} (try the averaging knots or fewer control points)") from None
        lsq, worst = fit_error(points, params, control, knot_vector)
        on_curve = de_boor(control, knot_vector, params)
        ts, curve = fit_samples(control, knot_vector, CURVE_POINTS)
        return {
            "points": points, "params": params, "knots": knot_vector, "control": control, "weight": w,
            "history": history,
            "on_curve": on_curve, "residuals": np.linalg.norm(on_curve - points, axis=1), "lsq": lsq,
            "max_error": worst, "energy": fairing_energy(control, knot_vector), "ts": ts, "curve": curve,
            "curvature": spline_curvature(control, knot_vector, ts),
        }

    def draw(self, ax, state: dict) -> None:
        plot_samples(ax, state["points"])
        plot_fit(ax, state["control"], state["knots"])
        plot_residuals(ax, state["points"], state["on_curve"])
        fairing = f", λ = {state['weight']:.2g}" if state["weight"] else ""
        corrected = f", corrected {len(state['history']) - 1}×" if len(state["history"]) > 1 else ""
        ax.set_title(f"{len(state['control'])} control points, {self.values['parametrization']} parameters"
                     f"{corrected}{fairing}", fontsize=10)
        bare_axes(ax)
        lower = self.lower_axes()
        lower.plot(state["ts"], state["curvature"], color="C2", linewidth=1.3, label="curvature κ(t)")
        scale = np.abs(state["curvature"]).max() / max(state["residuals"].max(), 1e-12)
        lower.vlines(state["params"], 0, state["residuals"] * scale, color="C1", linewidth=1.5)
        lower.axhline(0.0, color="0.8", linewidth=0.8, zorder=0)
        low, high = min(state["curvature"].min(), 0.0), max(state["curvature"].max(), 0.0)
        lower.vlines(np.unique(state["knots"]), low, high, color="0.85", linewidth=0.8, zorder=0)
        lower.set_xlim(state["ts"][0], state["ts"][-1])
        lower.set_xlabel("parameter t (grey lines: knots; stems at the parameters τ_k)", fontsize=8)
        lower.set_ylabel("κ(t); stems: residuals", fontsize=8)
        lower.locator_params(nbins=4)

    def describe(self, state: dict) -> str:
        key = (f"{_swatch('C0')} samples &nbsp; {_swatch('k')} fit &nbsp; {_swatch('C3')} control polygon &nbsp; "
               f"{_swatch('C1')} residuals &nbsp; {_swatch('C2')} curvature κ(t) (below, residuals scaled to it)")
        corrected = ""
        if len(state["history"]) > 1:
            corrected = (f" (before {len(state['history']) - 1} parameter corrections: "
                         f"{state['history'][0]:.4g})")
        return (f"{key}<br>Lsq = Σ‖P(τ_k) − Q_k‖² = {state['lsq']:.4g}{corrected}, largest residual "
                f"{state['max_error']:.3g}<br>"
                f"bending energy ∫‖P''‖² = {state['energy']:.4g}; curvature from {state['curvature'].min():.3g} "
                f"to {state['curvature'].max():.3g}")


def fitting_explorer(shape: str = "half ellipse") -> FittingExplorer:
    """The fitting lab: a cubic B-spline fitted to noisy samples of a shape. Notes §11.3, §11.4.

    Controls: `shape` (see `sample_shape`), `samples` (8-80), `unevenness`,
    `noise`, `parametrization` ("uniform", "chord length", "centripetal"),
    `knots` ("uniform" or "averaging", Bézier end knots either way), `count`
    control points (4-25), `fair` (on/off) and its `weight` λ, and `corrections`
    (0-10 rounds of parameter correction, `approximation.parameter_correction`).
    The lower panel plots the curvature of the fit over t and each sample's
    residual (scaled to the curvature's range). `update` returns {"points",
    "params" (after correction), "knots", "control", "weight", "history" (Lsq
    after each fit), "on_curve", "residuals", "lsq", "max_error", "energy", "ts",
    "curve", "curvature"}; a singular fit (parameters that fail the
    Schoenberg-Whitney condition) is a ValueError naming the controls.
    """
    return FittingExplorer(shape)


# ---------------------------------------------------------------- the fairing weight


class FairingWeightExplorer(TwoPanels, Explorer):
    """Faired fits of one data set for growing weights λ: they shrink towards the least-squares line. Notes §11.4."""

    key_in_readout = True

    family = tuple(10.0 ** k for k in range(-6, 3))
    curve_weights = 10.0 ** np.linspace(-7, 3, 21)

    def __init__(self, points=None, count: int = 10):
        self.points = _course_arc(points)
        self.params = chord_length_parameters(self.points)
        self.degree = 3
        self.knots = bezier_end_knots(as_count(count, "count", minimum=4), self.degree, 0.0, 1.0)
        design = np.column_stack([np.ones_like(self.params), self.params])
        coefficients = np.linalg.lstsq(design, self.points, rcond=None)[0]
        self.line = np.array([coefficients[0], coefficients[0] + coefficients[1]])  # P(0), P(1) of the limit
        self._cache: dict = {}
        controls = {
            "weight": _slider(widgets.FloatLogSlider, "λ", min=-7, max=3, step=0.1, value=1e-2),
            "constraints": widgets.Dropdown(description="through", options=list(CONSTRAINTS), value="none"),
        }
        for constraints in CONSTRAINTS:  # all at once, so that switching the dropdown stays quick
            self.curves(constraints)
        super().__init__(controls)

    def targets(self, constraints: str) -> np.ndarray:
        """Indices of the samples the curve must pass through."""
        middle = len(self.points) // 2
        return np.array([middle if k == "middle" else k % len(self.points) for k in CONSTRAINTS[constraints]], int)

    def fit(self, weight: float, constraints: str) -> np.ndarray:
        chosen = self.targets(constraints)
        if len(chosen) == 0:
            return faired_fit(self.points, self.params, self.knots, self.degree, weight)
        return constrained_fit(self.points, self.params, self.knots, self.degree, weight, self.points[chosen],
                               self.params[chosen])

    def curves(self, constraints: str) -> dict:
        """The family of curves and the L-curve (Lsq, energy) over the weight grid, computed once per constraint set."""
        if constraints not in self._cache:
            family = [fit_samples(self.fit(w, constraints), self.knots, CURVE_POINTS)[1] for w in self.family]
            fits = [self.fit(w, constraints) for w in self.curve_weights]
            lsq = [fit_error(self.points, self.params, f, self.knots)[0] for f in fits]
            energy = [fairing_energy(f, self.knots) for f in fits]
            self._cache[constraints] = {"family": family, "curve_lsq": np.array(lsq), "curve_energy": np.array(energy)}
        return self._cache[constraints]

    def compute(self, weight: float, constraints: str) -> dict:
        control = self.fit(weight, constraints)
        _, curve = fit_samples(control, self.knots, CURVE_POINTS)
        lsq, worst = fit_error(self.points, self.params, control, self.knots)
        return {"weight": weight, "control": control, "curve": curve, "lsq": lsq, "max_error": worst,
                "energy": fairing_energy(control, self.knots), "height": float(np.ptp(curve[:, 1])),
                "targets": self.targets(constraints), **self.curves(constraints)}

    def draw(self, ax, state: dict) -> None:
        for curve in state["family"]:
            ax.plot(*curve.T, color="0.75", linewidth=0.9)
        ax.plot(*self.line.T, "--", color="C4", linewidth=1.2, label="least-squares line (λ → ∞)")
        plot_samples(ax, self.points)
        plot_fit(ax, state["control"], self.knots, label=f"λ = {state['weight']:.2g}")
        if len(state["targets"]):
            ax.plot(*self.points[state["targets"]].T, "o", color="C3", markersize=9, markerfacecolor="none",
                    markeredgewidth=2, label="interpolated")
        ax.set_title(f"faired fits for λ = 1e-6 ... 1e2 (grey); height {state['height']:.3g}", fontsize=10)
        bare_axes(ax)
        lower = self.lower_axes()
        # Logarithms on linear axes: log-scale tick labels would cost more than the rest of the drawing.
        lower.plot(np.log10(state["curve_lsq"]), np.log10(state["curve_energy"]), color="0.4", linewidth=1.2)
        lower.plot([np.log10(state["lsq"])], [np.log10(state["energy"])], "o", color="k", markersize=7)
        lower.set_xlabel("log₁₀ Lsq, Lsq = Σ‖P(τ_k) − Q_k‖²  (λ = 1e-7 ... 1e3; dot: current)", fontsize=8)
        lower.set_ylabel("log₁₀ ∫‖P''‖²", fontsize=8)
        lower.locator_params(nbins=5)
        lower.tick_params(labelsize=8)

    def describe(self, state: dict) -> str:
        key = (f"{_swatch('k')} λ = {state['weight']:.3g} &nbsp; {_swatch('0.75')} λ = 1e-6, 1e-5, ..., 1e2 "
               f"&nbsp; {_swatch('C4')} least-squares line (the limit) &nbsp; {_swatch('C0')} samples")
        if len(state["targets"]):
            key += f" &nbsp; {_swatch('C3')} interpolated"
        return (f"{key}<br>Lsq = {state['lsq']:.4g}, largest residual {state['max_error']:.3g}, "
                f"energy {state['energy']:.4g}, height of the arc {state['height']:.3g}")


def fairing_weight_explorer(points=None, count: int = 10) -> FairingWeightExplorer:
    """Slider `weight` λ (log scale), dropdown `constraints` ("none", "ends", "ends and middle"). Notes §11.4, §11.4.1.

    points: planar samples (M, 2), default the course's uneven half ellipse;
    chord-length parameters and a cubic with `count` control points and uniform
    Bézier end knots. The grey family (λ = 1e-6 ... 1e2) shrinks towards
    the dashed least-squares line; with constraints the curve keeps passing
    through the chosen samples. The lower panel is the L-curve of energy against
    Lsq. `update` returns {"weight", "control", "curve", "lsq", "max_error",
    "energy", "height", "targets", "family" (one curve per family weight), "curve_lsq", "curve_energy"
    (the L-curve over 21 weights 1e-7 ... 1e3)}.
    """
    return FairingWeightExplorer(points, count)


# ---------------------------------------------------------------- tolerance boxes


class BoxFitExplorer(Explorer):
    """The fairest curve through a box around every sample, boxes along the axes or along the curve. Notes §11.4.2."""

    key_in_readout = True

    figsize = (6.5, 4.8)

    def __init__(self, points=None):
        self.points = _course_arc(points)
        self.params = chord_length_parameters(self.points)
        self.degree = 3
        controls = {
            "half_width": _slider(widgets.FloatSlider, "half size", min=0.05, max=0.6, step=0.01, value=0.15),
            "frame": widgets.Dropdown(description="boxes", options=["axes", "curve", "fit"], value="axes"),
            "along": _slider(widgets.FloatSlider, "× along t", min=1.0, max=4.0, step=0.25, value=2.0),
            "count": _slider(widgets.IntSlider, "control pts", min=6, max=14, value=10),
        }
        super().__init__(controls)

    def compute(self, half_width: float, frame: str, along: float, count: int) -> dict:
        knots = bezier_end_knots(count, self.degree, 0.0, 1.0)
        sizes = np.array([half_width, half_width]) if frame == "axes" else np.array([along * half_width, half_width])
        sizes = np.tile(sizes, (len(self.points), 1))
        lsq_fit = least_squares_fit(self.points, self.params, knots, self.degree)
        control = box_faired_fit(self.points, self.params, knots, self.degree, sizes, frame=frame)
        offsets = de_boor(control, knots, self.params) - self.points
        frames = "axes"
        if frame != "axes":  # the notes' estimate from neighbouring samples, or the tangents of the first fit
            frames = estimate_frames(self.points) if frame == "curve" else estimate_frames(
                self.points, lsq_fit, knots, self.params)
            tangents, normals = frames
            offsets = np.column_stack([np.sum(offsets * tangents, axis=1), np.sum(offsets * normals, axis=1)])
        active = np.flatnonzero(np.any(np.abs(offsets) > sizes * (1 - 1e-4), axis=1))
        return {"knots": knots, "sizes": sizes, "frames": frames, "lsq_fit": lsq_fit, "control": control,
                "active": active,
                "energy": fairing_energy(control, knots), "energy_lsq": fairing_energy(lsq_fit, knots),
                "lsq": fit_error(self.points, self.params, control, knots)[0]}

    def draw(self, ax, state: dict) -> None:
        plot_boxes(ax, self.points, state["sizes"], state["frames"], active=state["active"])
        plot_fit(ax, state["lsq_fit"], state["knots"], polygon=False, label="least squares", color="0.6",
                 linewidth=1.2, linestyle="--")
        plot_samples(ax, self.points)
        plot_fit(ax, state["control"], state["knots"], label="fairest within the boxes")
        ax.set_title(f"bending energy {state['energy_lsq']:.4g} (least squares) → {state['energy']:.4g}; "
                     f"{len(state['active'])} boxes touched", fontsize=10)
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        key = (f"{_swatch('k')} fairest curve within the boxes &nbsp; {_swatch('0.6')} least squares &nbsp; "
               f"{_swatch('C0')} samples &nbsp; {_swatch('C1')} boxes (shaded: touched)")
        return (f"{key}<br>energy ∫‖P''‖² = {state['energy']:.4g} against {state['energy_lsq']:.4g} for least "
                f"squares; Lsq = {state['lsq']:.4g}")


def box_fit_explorer(points=None) -> BoxFitExplorer:
    """Sliders `half_width`, `along` (tangential stretch of tangent boxes), `count`; dropdown `frame`. Notes §11.4.2.

    points: planar samples (M, 2), default the course's uneven half ellipse with
    chord-length parameters. Each sample gets a box of half size `half_width`
    (and `along` × that along the tangent for frame "curve", the notes' tangent
    estimate from neighbouring samples, or "fit", the tangent of the least-squares
    fit at the sample's parameter); the cubic with
    `count` control points of least bending energy through all boxes is found
    by `approximation.box_faired_fit`. Boxes too small to reach are a
    ValueError. `update` returns {"knots", "sizes" (M, 2), "frames" ("axes" or
    the pair (tangents, normals) of the boxes), "lsq_fit",
    "control", "active" (indices of the boxes the curve touches), "energy",
    "energy_lsq", "lsq"}.
    """
    return BoxFitExplorer(points)

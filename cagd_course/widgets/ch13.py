"""Explorers of chapter 13 of the notes (floating-point error): the chaotic band, a rounded affine map, the number line.

The band explorer is Figure 13.1 with a precision slider: a polynomial
evaluated in d-bit arithmetic at a few hundred parameters in a zoom window
around a root, over its exact values, with the guaranteed radius of rounded de
Casteljau and the a-priori bound as bands. The affine-map explorer is Figure
13.2: two boxes, their exact image at t and the image widened for the rounding
of d-bit arithmetic, exaggerated by a small d. The number-line explorer shows
the d-bit numbers around a real x, its neighbours, the interval of reals that
round to it, and its string in the notes' format.
"""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np

from cagd_ref import floating
from cagd_ref._validation import as_scalar, as_vector

from ..plotting.rounding import box_limits, plot_band, plot_box, plot_number_line
from ._base import Explorer, _fmt, _slider

__all__ = [
    "band_explorer",
    "affine_roundoff_explorer",
    "number_line_explorer",
    "BandExplorer",
    "AffineRoundoffExplorer",
    "NumberLineExplorer",
]

FIGURE_13_1 = np.array([1.0, -3.0, 9.0, -27.0])  # (1 - 4t)³, a triple root at t = 1/4
PRECISIONS = [("8 bits", 8), ("11 bits = float16", 11), ("16 bits", 16), ("20 bits", 20), ("24 bits = float32", 24),
              ("53 bits = float64", 53)]
METHOD_NAMES = {"de Casteljau": "de_casteljau", "Horner (power form)": "horner",
                "nested Bernstein form": "bernstein_horner"}
SAMPLES = 301


def _sign_changes(values: np.ndarray) -> int:
    signs = np.sign(values[values != 0])
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


# ---------------------------------------------------------------- the band of Figure 13.1


class BandExplorer(Explorer):
    """Values of a polynomial in d-bit arithmetic near a root, the exact curve, the radius and bound. Figure 13.1."""

    figsize = (6.6, 4.6)

    def __init__(self, coeffs=None, centre: float = 0.25, bits: int = 24, half_width: float = 5e-5):
        self.coeffs = FIGURE_13_1 if coeffs is None else as_vector(coeffs, "coeffs")
        self.centre = as_scalar(centre, "centre")
        controls = {
            "bits": widgets.SelectionSlider(description="precision", options=PRECISIONS, value=bits,
                                            continuous_update=True, layout=widgets.Layout(width="300px")),
            "half_width": _slider(widgets.FloatLogSlider, "zoom ± t", value=half_width, base=10, min=-9, max=-1,
                                  step=0.25, readout_format=".1e"),
            "method": widgets.Dropdown(description="method", options=list(METHOD_NAMES), value="de Casteljau"),
        }
        super().__init__(controls)

    def compute(self, bits: int, half_width: float, method: str) -> dict:
        eta = floating.machine_unit(bits)
        t = np.unique(floating.round_to_bits(self.centre + np.linspace(-half_width, half_width, SAMPLES), bits))
        values = floating.evaluate_in_precision(self.coeffs, t, bits, METHOD_NAMES[method])
        exact = floating.exact_value(self.coeffs, t)
        radius = None
        if METHOD_NAMES[method] == "de_casteljau":
            radius = floating.rounded_de_casteljau(self.coeffs[:, None], t, eta)[1][:, 0]
        inside = (t >= 0) & (t <= 1)
        bound = np.full(len(t), np.nan)
        bound[inside] = floating.error_bound(self.coeffs, t[inside], eta)
        error = np.abs(values - exact)
        return {
            "bits": bits,
            "eta": eta,
            "method": method,
            "t": t,
            "values": values,
            "exact": exact,
            "radius": radius,
            "bound": bound,
            "sign_changes": _sign_changes(values),
            "exact_sign_changes": _sign_changes(exact),
            "max_error": float(error.max()),
            "contained": None if radius is None else bool(np.all(error <= radius)),
            "at_centre": floating.evaluate_in_precision(self.coeffs, self.centre, bits, METHOD_NAMES[method]),
        }

    def draw(self, ax, state: dict) -> None:
        plot_band(ax, state["t"], state["values"], state["exact"], state["radius"], state["bound"], self.centre)
        ax.set_ylabel("value")
        ax.set_title(f"{state['method']} in {state['bits']}-bit arithmetic: {state['sign_changes']} sign changes",
                     fontsize=10, pad=14)
        ax.legend(fontsize=8, loc="upper right")

    def describe(self, state: dict) -> str:
        lines = [
            f"η = 2<sup>−{state['bits']}</sup> = {state['eta']:.3g}",
            f"{len(state['t'])} distinct {state['bits']}-bit parameters in the window",
            f"sign changes: {state['sign_changes']} computed, {state['exact_sign_changes']} exact",
            f"largest error {state['max_error']:.3g}, a-priori bound up to {np.nanmax(state['bound']):.3g}",
            f"value at t = {self.centre:g} itself: {state['at_centre']:.3g}",
        ]
        if state["contained"] is not None:
            lines.append("exact values inside computed ± radius: " + ("all" if state["contained"] else "NOT all"))
        return "<br>".join(lines)


def band_explorer(coeffs=None, centre: float = 0.25, bits: int = 24, half_width: float = 5e-5) -> BandExplorer:
    """Slider `bits` (precision), log slider `half_width` (zoom) and dropdown `method`: Figure 13.1. Notes §13.

    coeffs: Bernstein coefficients (n+1,) (default 1, -3, 9, -27, i.e.
    (1 - 4t)³); centre: the parameter to zoom in on. `update` returns {"bits",
    "eta", "method", "t" (k,) the distinct d-bit parameters, "values" (k,)
    computed, "exact" (k,), "radius" (k,) of rounded de Casteljau or None
    for the other methods, "bound" (k,) a-priori (NaN outside [0, 1]),
    "sign_changes", "exact_sign_changes", "max_error", "contained",
    "at_centre" (the value computed at `centre` itself)}.
    """
    return BandExplorer(coeffs, centre, bits, half_width)


# ---------------------------------------------------------------- the affine map of Figure 13.2


class AffineRoundoffExplorer(Explorer):
    """Two boxes, their exact affine image at t (solid) and the image widened for d-bit rounding (dashed). Fig. 13.2."""

    figsize = (6.4, 4.8)

    def __init__(self, c0=(1.0, 1.0), e0=(0.3, 0.2), c1=(4.0, 3.0), e1=(0.2, 0.4), t: float = 0.5, bits: int = 5):
        self.boxes = tuple(as_vector(v, name, 2) for v, name in ((c0, "c0"), (e0, "e0"), (c1, "c1"),
                                                                          (e1, "e1")))
        if np.any(self.boxes[1] < 0) or np.any(self.boxes[3] < 0):
            raise ValueError("e0, e1: expected radii >= 0")
        controls = {
            "t": _slider(widgets.FloatSlider, "t", value=t, min=-1.0, max=2.0, step=0.01, readout_format=".2f"),
            "bits": _slider(widgets.IntSlider, "bits d", value=bits, min=2, max=25),
        }
        super().__init__(controls)

    def compute(self, t: float, bits: int) -> dict:
        c0, e0, c1, e1 = self.boxes
        eta = floating.machine_unit(bits)
        tau = floating.round_to_bits(t, bits)  # the parameter itself is a d-bit number
        exact_centre = (1 - tau) * c0 + tau * c1
        exact_radius = abs(1 - tau) * e0 + abs(tau) * e1
        centre, radius = floating.rounded_affine_map(c0, e0, c1, e1, tau, eta)
        notes = floating.affine_roundoff(c0, c1, tau, eta)
        return {
            "t": tau,
            "bits": bits,
            "eta": eta,
            "exact_centre": exact_centre,
            "exact_radius": exact_radius,
            "centre": centre,
            "radius": radius,
            "notes_widening": notes,
            "widening": radius - exact_radius,
        }

    def draw(self, ax, state: dict) -> None:
        c0, e0, c1, e1 = self.boxes
        line = np.linspace(-1, 2, 2)[:, None]
        ax.plot(*((1 - line) * c0 + line * c1).T, color="0.8", linewidth=0.8, zorder=0)
        plot_box(ax, c0, e0, color="C0", label="[P0]")
        plot_box(ax, c1, e1, color="C1", label="[P1]")
        plot_box(ax, state["exact_centre"], state["exact_radius"], color="black", label="(1−t)[P0] + t[P1], exact")
        plot_box(ax, state["centre"], state["radius"], color="C3", linestyle="--",
                 label=f"computed in {state['bits']}-bit arithmetic")
        for centre, name in ((c0, "[P0]"), (c1, "[P1]")):
            ax.annotate(name, centre, ha="center", va="center", fontsize=9)
        xlim, ylim = box_limits((c0, e0), (c1, e1), (state["centre"], state["radius"]))
        ax.set(xlim=xlim, ylim=ylim, aspect="equal", xlabel="x", ylabel="y")
        ax.set_title(f"t = {state['t']:.4g}, η = 2^−{state['bits']}: the image box widened by ε(t)", fontsize=10)
        ax.legend(fontsize=8, loc="upper left")

    def describe(self, state: dict) -> str:
        eta = state["eta"]
        return "<br>".join([
            f"t rounded to {state['bits']} bits: {state['t']:.6g}",
            f"exact image: centre {_fmt(state['exact_centre'])}, radius {_fmt(state['exact_radius'])}",
            f"widening used: {_fmt(state['widening'] / eta)} η",
            f"(13.7) as printed: {_fmt(state['notes_widening'] / eta)} η",
        ])


def affine_roundoff_explorer(c0=(1.0, 1.0), e0=(0.3, 0.2), c1=(4.0, 3.0), e1=(0.2, 0.4), t: float = 0.5,
                             bits: int = 5) -> AffineRoundoffExplorer:
    """Sliders `t` (-1 to 2) and `bits` (2 to 25): the boxes c ± e mapped at t with roundoff. Notes §13, Fig. 13.2.

    c0, e0, c1, e1: centres and radii (2,) of the two boxes. `update` returns
    {"t" (rounded to d bits), "bits", "eta", "exact_centre", "exact_radius",
    "centre", "radius" (of `rounded_affine_map`), "notes_widening" ((13.7)),
    "widening" (radius - exact_radius)}, vectors (2,).
    """
    return AffineRoundoffExplorer(c0, e0, c1, e1, t, bits)


# ---------------------------------------------------------------- the number line


class NumberLineExplorer(Explorer):
    """The d-bit numbers near x, x's neighbours and rounding interval, and its string in the notes' format."""

    figsize = (6.6, 2.8)

    def __init__(self, x: float = 1 / 3, bits: int = 6):
        controls = {
            "x": widgets.FloatText(description="x", value=x, layout=widgets.Layout(width="300px")),
            "bits": _slider(widgets.IntSlider, "bits d", value=bits, min=1, max=30),
        }
        super().__init__(controls)
        self.figure.subplots_adjust(bottom=0.3, top=0.8)

    def compute(self, x: float, bits: int) -> dict:
        if not np.isfinite(x) or x == 0:
            raise ValueError("x: expected a finite nonzero number")
        low, high = floating.neighbours(x, bits)
        rounded = floating.round_to_bits(x, bits)
        interval = floating.float_interval(rounded, bits, exact=True)
        try:
            encoded = floating.encode_float(x, 8, bits)
        except ValueError:
            encoded = None
        return {
            "x": x,
            "bits": bits,
            "neighbours": (low, high),
            "rounded": rounded,
            "interval": interval,
            "error": rounded - x,
            "relative_error": abs(rounded - x) / abs(x),
            "eta": floating.machine_unit(bits),
            "encoded": encoded,
        }

    def draw(self, ax, state: dict) -> None:
        plot_number_line(ax, state["x"], state["bits"])
        ax.set_title(f"x = {state['x']:.10g} among the {state['bits']}-bit numbers", fontsize=10)
        ax.legend(fontsize=8, loc="upper center", ncol=4, bbox_to_anchor=(0.5, 1.0))

    def describe(self, state: dict) -> str:
        low, high = state["neighbours"]
        lo, hi = state["interval"]
        lines = [
            f"neighbours: {low:.10g} &lt; x &lt; {high:.10g}" if low < state["x"] < high
            else f"x is a {state['bits']}-bit number; its neighbours are {low:.10g} and {high:.10g}",
            f"fl(x) = {state['rounded']:.10g}, error {state['error']:.3g} "
            f"(relative {state['relative_error']:.3g} &le; η = {state['eta']:.3g})",
            f"reals that round to fl(x): [{lo:.10g}, {hi:.10g}]",
        ]
        if state["encoded"] is not None:
            sign, exponent, fraction = state["encoded"].split("|")
            lines.append("notes' format: <code><span style='color:#b00'>" + sign + "</span>|<span style='color:#06c'>"
                         + exponent + "</span>|" + html.escape(fraction) + "</code>")
        return "<br>".join(lines)


def number_line_explorer(x: float = 1 / 3, bits: int = 6) -> NumberLineExplorer:
    """Text box `x` and slider `bits` (1 to 30): x among the d-bit numbers. Notes §13.

    `update` returns {"x", "bits", "neighbours" (low, high), "rounded",
    "interval" (the reals that round to fl(x), exactly), "error",
    "relative_error", "eta", "encoded" (the notes' string with an 8-bit
    exponent and d fraction bits, or None beyond its range)}.
    """
    return NumberLineExplorer(x, bits)

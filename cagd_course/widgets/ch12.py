"""Explorers of chapter 12 (interval Bézier curves): boxes and envelopes, Hermite enclosures, degree reduction.

The interval curve explorer is Figures 12.1, 12.5 and 12.6 with sliders: the
control boxes scaled by a size factor, the region the curve sweeps with its
bounding corner curves, and the box [P](t) at a parameter t that may leave
[0, 1], where the box inflates like (|1-t| + |t|)^n. The Hermite explorer
encloses a function on 2^depth pieces by Hermite interval polynomials of a
chosen order and compares the guaranteed bound with the true error. The
degree reduction explorer encloses a curve of degree 7 in quartic interval
pieces and plots the bound against the subdivision depth.
"""

from __future__ import annotations

import math

import ipywidgets as widgets
import numpy as np

from cagd_ref import bezier
from cagd_ref import interval_bezier as ib

from ..plotting.intervals import box_patch, plot_boxes, plot_corner_curves, plot_interval_band, plot_swept_region
from ._base import Explorer, TwoPanels, _fmt, _slider

__all__ = [
    "interval_curve_explorer",
    "hermite_interval_explorer",
    "degree_reduction_explorer",
    "IntervalCurveExplorer",
    "HermiteIntervalExplorer",
    "DegreeReductionExplorer",
]

# The chapter's interval curves as (centres, errors): the course cubic, a curve moving north-east throughout, and the
# quarter circle's quartic interval arc (12.78).
_QUARTER = ib.hermite_interval([[1.0, 0.0], [0.0, math.pi / 2]], [[0.0, 1.0], [-math.pi / 2, 0.0]],
                               [[0.0, math.pi**4 / 16]] * 2)
CURVES = {
    "cubic": (np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]),
              np.array([[0.1, 0.1], [0.2, 0.1], [0.1, 0.3], [0.0, 0.2]])),
    "rising cubic": (np.array([[0.0, 0.0], [1.0, 0.5], [2.0, 2.5], [4.0, 3.0]]),
                     np.array([[0.1, 0.1], [0.2, 0.15], [0.15, 0.25], [0.1, 0.1]])),
    "quarter circle (quartic)": ib.center_error(_QUARTER),
}
SAMPLES = 160


class IntervalCurveExplorer(Explorer):
    """Boxes, swept region, corner curves and the box [P](t) for any real t. Notes §12.2, Figs. 12.1, 12.5, 12.6."""

    figsize = (6.4, 5.0)

    def __init__(self, size: float = 1.0, t: float = 0.5):
        super().__init__({
            "curve": widgets.Dropdown(description="curve", options=list(CURVES), value="cubic"),
            "size": _slider(widgets.FloatSlider, "box size", value=size, min=0.0, max=3.0, step=0.1),
            "t": _slider(widgets.FloatSlider, "t", value=t, min=-1.0, max=2.0, step=0.05),
            "corners": widgets.Checkbox(description="corner curves (envelope)", value=True),
        })

    static_control = "t"

    def compute(self, curve: str, size: float, t: float, corners: bool) -> dict:
        centres, errors = CURVES[curve]
        boxes = ib.boxes_from_center(centres, size * errors)
        box = ib.interval_de_casteljau(boxes, t)
        inside = float(np.clip(t, 0, 1))
        return {
            "curve": curve,
            "boxes": boxes,
            "t": t,
            "box": box,
            "error": 0.5 * (box[:, 1] - box[:, 0]),
            # The same errors at the nearest parameter of [0, 1]: the growth outside is the ratio of the two.
            "error_inside": ib.error_curve(size * errors, inside),
            "growth": (abs(1 - t) + abs(t)) ** (len(centres) - 1),
            "pieces": ib.envelope_pieces(boxes) if corners else [],
            "corners": corners,
        }

    def draw(self, ax, state: dict) -> None:
        boxes, t = state["boxes"], state["t"]
        if not 0 <= t <= 1:
            span = (min(t, 0.0), max(t, 1.0))
            plot_swept_region(ax, boxes, span, samples=SAMPLES, color="#fde0c5", label="swept outside [0, 1]")
        plot_swept_region(ax, boxes, samples=SAMPLES)
        centre = bezier.de_casteljau(boxes.mean(axis=2), np.linspace(min(t, 0), max(t, 1), 200))
        ax.plot(centre[:, 0], centre[:, 1], color="C0", linewidth=1.6, label="centre curve")
        if state["corners"]:
            plot_corner_curves(ax, boxes)
        plot_boxes(ax, boxes, labels=True)
        ax.add_patch(box_patch(state["box"], facecolor="none", edgecolor="C4", alpha=1.0, linewidth=2.0, zorder=6))
        ax.plot(*state["box"].mean(axis=1), "o", color="C4", markersize=5, zorder=7, label=f"[P]({t:.2f})")
        ax.set_title(f"interval Bézier curve: the box [P]({t:.2f})", fontsize=10)
        ax.legend(fontsize=8, loc="best")

    def describe(self, state: dict) -> str:
        box, t = state["box"], state["t"]
        lines = [
            f"[P]({t:.2f}) = [{box[0, 0]:.4g}, {box[0, 1]:.4g}] × [{box[1, 0]:.4g}, {box[1, 1]:.4g}]",
            f"half-widths ẽ(t) = {_fmt(state['error'])}",
        ]
        if not 0 <= t <= 1:
            lines.append(f"outside [0, 1]: |B_k(t)| sum to (|1-t| + |t|)^n = {state['growth']:.4g}, "
                         f"against {_fmt(state['error_inside'])} at the nearest end")
        if state["pieces"]:
            lines.append("bounding corner curves: " + ", ".join(
                f"{a:.2f}–{b:.2f}: {p[0]}/{p[1]}" for a, b, p in state["pieces"]))
        return "<br>".join(lines)


def interval_curve_explorer(size: float = 1.0, t: float = 0.5) -> IntervalCurveExplorer:
    """An interval Bézier curve with a box-size slider and a t slider that may leave [0, 1]."""
    return IntervalCurveExplorer(size=size, t=t)


# ---------------------------------------------------------------- Hermite interval approximation


def _sine_range(u0: float, u1: float) -> tuple[float, float]:
    """The exact range of sin over [u0, u1]: the end values, and ±1 where a crest or a trough lies inside."""
    values = [math.sin(u0), math.sin(u1)]
    if math.floor((u1 - math.pi / 2) / (2 * math.pi)) >= math.ceil((u0 - math.pi / 2) / (2 * math.pi)):
        values.append(1.0)
    if math.floor((u1 + math.pi / 2) / (2 * math.pi)) >= math.ceil((u0 + math.pi / 2) / (2 * math.pi)):
        values.append(-1.0)
    return min(values), max(values)


def _exp_data(k: int, a: float, b: float):
    return math.exp(a), math.exp(b), (math.exp(a), math.exp(b))


def _sine_data(k: int, a: float, b: float):
    """The k-th derivative of sin(πt/2) is (π/2)^k sin(πt/2 + kπ/2)."""
    scale, shift = (math.pi / 2) ** k, k * math.pi / 2
    low, high = _sine_range(math.pi * a / 2 + shift, math.pi * b / 2 + shift)
    return scale * math.sin(math.pi * a / 2 + shift), scale * math.sin(math.pi * b / 2 + shift), (scale * low,
                                                                                                    scale * high)


def _reciprocal_data(k: int, a: float, b: float):
    """The k-th derivative of 1/(1+t) is (-1)^k k!/(1+t)^(k+1): monotone, so its range is its end values."""
    value = [(-1) ** k * math.factorial(k) / (1 + x) ** (k + 1) for x in (a, b)]
    return value[0], value[1], (min(value), max(value))


# name -> (f, derivative data (f^(k)(a), f^(k)(b), range of f^(k) on [a, b]))
FUNCTIONS = {
    "exp(t)": (np.exp, _exp_data),
    "sin(πt/2)": (lambda t: np.sin(np.pi * t / 2), _sine_data),
    "1/(1+t)": (lambda t: 1 / (1 + t), _reciprocal_data),
}


def hermite_pieces(function: str, order: int, depth: int) -> list[tuple[float, float, np.ndarray]]:
    """Hermite interval polynomials of degree 2·order enclosing a function on 2^depth pieces of [0, 1]."""
    _, data = FUNCTIONS[function]
    edges = np.linspace(0, 1, 2**depth + 1)
    pieces = []
    for a, b in zip(edges[:-1], edges[1:]):
        rows = [data(k, a, b) for k in range(order)]
        bound = data(2 * order, a, b)[2]
        coeffs = ib.hermite_interval([r[0] for r in rows], [r[1] for r in rows], bound, (a, b))
        pieces.append((float(a), float(b), coeffs))
    return pieces


class HermiteIntervalExplorer(TwoPanels, Explorer):
    """Enclosing a function by Hermite interval polynomials: the band, and the bound against the true error. §12.3."""

    def __init__(self, function: str = "exp(t)", order: int = 2, depth: int = 0):
        super().__init__({
            "function": widgets.Dropdown(description="f", options=list(FUNCTIONS), value=function),
            "order": _slider(widgets.IntSlider, "order m", value=order, min=1, max=4),
            "depth": _slider(widgets.IntSlider, "halvings", value=depth, min=0, max=4),
        })

    static_control = "order"

    def compute(self, function: str, order: int, depth: int) -> dict:
        f, _ = FUNCTIONS[function]
        pieces = hermite_pieces(function, order, depth)
        bound = error = 0.0
        for a, b, coeffs in pieces:
            t = np.linspace(a, b, 65)
            band = ib.interval_de_casteljau(coeffs, (t - a) / (b - a))
            centre = band.mean(axis=1)
            bound = max(bound, float(0.5 * (band[:, 1] - band[:, 0]).max()))
            error = max(error, float(np.abs(f(t) - centre).max()))
        return {"function": function, "order": order, "degree": 2 * order, "depth": depth, "pieces": pieces,
                "bound": bound, "error": error, "middle_widths": [float(c[order, 1] - c[order, 0]) for *_, c in pieces]}

    def draw(self, ax, state: dict) -> None:
        f, _ = FUNCTIONS[state["function"]]
        for i, (a, b, coeffs) in enumerate(state["pieces"]):
            plot_interval_band(ax, coeffs, (a, b), samples=80, label="interval polynomial" if i == 0 else None)
        t = np.linspace(0, 1, 200)
        ax.plot(t, f(t), color="black", linewidth=1.2, label="f(t)")
        ax.set_title(f"{state['function']}: degree {state['degree']} interval pieces, {len(state['pieces'])} of them",
                     fontsize=10)
        ax.legend(fontsize=8, loc="upper left")
        lower = self.lower_axes()
        # Room at the left for the lower panel's small numbers (−0.010) and its label.
        ax.set_position([0.13, 0.40, 0.83, 0.52])
        lower.set_position([0.13, 0.07, 0.83, 0.25])
        for i, (a, b, coeffs) in enumerate(state["pieces"]):
            plot_interval_band(lower, coeffs, (a, b), samples=80, relative_to=f, label="band − f" if i == 0 else None)
        lower.axhline(0.0, color="black", linewidth=1.0)
        lower.set_ylabel("minus f", fontsize=8)
        lower.legend(fontsize=8, loc="upper right")

    def describe(self, state: dict) -> str:
        ratio = state["bound"] / state["error"] if state["error"] else math.inf
        return "<br>".join([
            f"degree {state['degree']} Hermite enclosure (order m = {state['order']}), {len(state['pieces'])} piece(s)",
            f"guaranteed bound (largest half-width): {state['bound']:.3e}",
            f"true error of the centre: {state['error']:.3e} (bound / true = {ratio:.3g})",
            f"middle coefficient width (12.64): {max(state['middle_widths']):.3e}",
        ])


def hermite_interval_explorer(function: str = "exp(t)", order: int = 2, depth: int = 0) -> HermiteIntervalExplorer:
    """Hermite interval approximation of a function with order and subdivision controls."""
    return HermiteIntervalExplorer(function=function, order=order, depth=depth)


# ---------------------------------------------------------------- degree reduction with guaranteed bounds

REDUCTION_CURVES = {
    "wave (degree 7)": np.array([[0.0, 0.0], [1.0, 2.5], [2.0, -1.5], [3.0, 2.0], [4.0, -2.0], [5.0, 1.5],
                                 [6.0, -1.0], [7.0, 0.5]]),
    "loop (degree 6)": np.array([[0.0, 0.0], [4.0, 1.0], [5.0, 4.0], [2.0, 5.0], [0.5, 3.0], [3.0, 1.0],
                                 [6.0, 0.5]]),
}
MAX_DEPTH = 5


def enclosure_quality(points: np.ndarray, depth: int, samples: int = 65) -> dict:
    """The quartic pieces after `depth` halvings, their guaranteed bound and the true deviation of their centres."""
    pieces = ib.interval_degree_reduce(points, depth)
    s = np.linspace(0, 1, samples)
    bound = deviation = 0.0
    for i, piece in enumerate(pieces):
        box = ib.interval_de_casteljau(piece, s)
        truth = bezier.de_casteljau(points, (i + s) / len(pieces))
        bound = max(bound, float(0.5 * (box[..., 1] - box[..., 0]).max()))
        deviation = max(deviation, float(np.abs(truth - box.mean(axis=2)).max()))
    return {"pieces": pieces, "bound": bound, "deviation": deviation}


class DegreeReductionExplorer(TwoPanels, Explorer):
    """A curve enclosed in quartic interval pieces; the bound and the true deviation against the depth. §12.3."""

    def __init__(self, curve: str = "wave (degree 7)", depth: int = 1):
        self._history = {name: [enclosure_quality(p, d) for d in range(MAX_DEPTH + 1)]
                         for name, p in REDUCTION_CURVES.items()}
        super().__init__({
            "curve": widgets.Dropdown(description="curve", options=list(REDUCTION_CURVES), value=curve),
            "depth": _slider(widgets.IntSlider, "halvings", value=depth, min=0, max=MAX_DEPTH),
        })

    static_control = "depth"

    def compute(self, curve: str, depth: int) -> dict:
        quality = self._history[curve][depth]
        return {"curve": curve, "depth": depth, "points": REDUCTION_CURVES[curve], **quality,
                "bounds": [q["bound"] for q in self._history[curve]],
                "deviations": [q["deviation"] for q in self._history[curve]]}

    def draw(self, ax, state: dict) -> None:
        points = state["points"]
        count = len(state["pieces"])
        for i, piece in enumerate(state["pieces"]):
            plot_swept_region(ax, piece, samples=max(40, 240 // count), color="C1" if i % 2 else "C2",
                              label="quartic interval pieces" if i == 0 else None)
        curve = bezier.de_casteljau(points, np.linspace(0, 1, 300))
        ax.plot(curve[:, 0], curve[:, 1], color="black", linewidth=1.0, label=f"degree {len(points) - 1} curve")
        ax.plot(points[:, 0], points[:, 1], "--o", color="0.6", linewidth=0.8, markersize=3)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(f"{count} quartic interval piece{'s' if count > 1 else ''}", fontsize=10)
        ax.legend(fontsize=8, loc="best")
        lower = self.lower_axes()
        depths = np.arange(MAX_DEPTH + 1)
        lower.semilogy(depths, state["bounds"], "o-", color="C3", label="guaranteed bound")
        lower.semilogy(depths, state["deviations"], "s--", color="C0", label="true deviation")
        lower.axvline(state["depth"], color="0.5", linewidth=0.8)
        lower.set_xlabel("halvings", fontsize=8)
        lower.legend(fontsize=8)

    def describe(self, state: dict) -> str:
        ratio = state["bound"] / state["deviation"] if state["deviation"] else math.inf
        lines = [f"{len(state['pieces'])} quartic piece(s) after {state['depth']} halving(s)",
                 f"guaranteed bound {state['bound']:.3e}; true deviation {state['deviation']:.3e}; "
                 f"bound / true = {ratio:.3g}"]
        if state["depth"]:
            lines.append(f"the bound shrank {state['bounds'][state['depth'] - 1] / state['bound']:.3g}× "
                         "in the last halving (≈ 2⁵ once the pieces are small)")
        return "<br>".join(lines)


def degree_reduction_explorer(curve: str = "wave (degree 7)", depth: int = 1) -> DegreeReductionExplorer:
    """Degree reduction with guaranteed bounds: subdivision depth against the enclosure's width."""
    return DegreeReductionExplorer(curve=curve, depth=depth)

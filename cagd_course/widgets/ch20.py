"""Explorers of chapter 20 of the notes (hybrid curves): the moving point, shrinking boxes, areas with a guarantee.

The hybrid explorer is Figure 20.1 with sliders: a rational cubic written as a
polynomial curve of a chosen degree whose middle control point rides on M(t);
moving t moves M(t) and the point H(t) = R(t) together. The box explorer is
Figure 20.2: split the curve, and every piece's moving point lives in a smaller
box. The area explorer runs the adaptive method of §20.4 at a tolerance set by
a slider, and sets its pieces, bound, true error and cost beside Simpson's rule
and the trapezoid rule with its convex-hull bound.
"""

from __future__ import annotations

import time

import ipywidgets as widgets
import numpy as np

from cagd_ref import bezier, hybrid

from ..plotting.curves import plot_bezier, plot_control_polygon
from ..plotting.hybrid import piece_curves, plot_hybrid, plot_moving_boxes, shade_area
from ._base import Explorer, TwoPanels, _control_points, _slider

__all__ = [
    "hybrid_explorer",
    "moving_box_explorer",
    "adaptive_area_explorer",
    "HybridExplorer",
    "MovingBoxExplorer",
    "AdaptiveAreaExplorer",
]

# The chapter's curves: the notes' semicircle (Fig. 20.6) and Example 1 of Fig. 20.5 completed with the
# course's own P3 = (15, 4), w3 = 1 (the notes' P3 and w3 are lost), and a flatter arch with strong weights.
CURVES = {
    "semicircle (notes, Fig. 20.6)": (np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]),
                                      np.array([3.0, 1.0, 1.0, 3.0])),
    "Example 1 (P3, w3 the course's)": (np.array([[2.0, 5.0], [6.0, 10.0], [13.0, 7.0], [15.0, 4.0]]),
                                        np.array([1.0, 2.0, 3.0, 1.0])),
    "weighted arch": (np.array([[0.0, 0.5], [1.0, 3.0], [3.0, 3.0], [4.0, 1.0]]), np.array([1.0, 6.0, 0.6, 1.0])),
}
YOUR_CURVE = "your curve"
DEGREES = (2, 3, 4, 6, 8)
# Trapezoids get slow below this tolerance (about 10^5 pieces on the semicircle at 1e-8): the explorer skips them.
TRAPEZOID_LIMIT = 1e-7


def _curve_choice(points, weights, default: str):
    """The curves an explorer offers (first the one given) and the dropdown that picks one."""
    if points is None:
        return dict(CURVES), widgets.Dropdown(description="curve", options=list(CURVES), value=default)
    pts = _control_points(points, CURVES[default][0])
    w = np.ones(len(pts)) if weights is None else np.array(weights, dtype=float)
    hybrid.hybrid_curve(pts, w, 2)  # checks the weights (positive, one per point) now, not at the first update
    curves = {YOUR_CURVE: (pts, w), **CURVES}
    return curves, widgets.Dropdown(description="curve", options=list(curves), value=YOUR_CURVE)


# ---------------------------------------------------------------- the hybrid and its moving point


class HybridExplorer(Explorer):
    """A rational curve as a hybrid of a chosen degree: fixed points, M's polygon and box, M(t) and H(t). Fig. 20.1."""

    static_control = "t"

    def __init__(self, points=None, weights=None, degree: int = 4, t: float = 0.3):
        self.curves, curve = _curve_choice(points, weights, "semicircle (notes, Fig. 20.6)")
        controls = {
            "curve": curve,
            "degree": widgets.Dropdown(description="degree n", options=list(DEGREES), value=degree),
            "t": _slider(widgets.FloatSlider, "t", value=t, min=0.0, max=1.0, step=0.02, readout_format=".2f"),
        }
        super().__init__(controls)

    def compute(self, curve: str, degree: int, t: float) -> dict:
        points, weights = self.curves[curve]
        h = hybrid.hybrid_curve(points, weights, degree)
        centre, half = hybrid.moving_box(h)
        _, bound = hybrid.polynomial_approximation(points, weights, degree)
        return {
            "curve": curve,
            "points": points,
            "weights": weights,
            "hybrid": h,
            "t": t,
            "moving_point": bezier.evaluate(h.moving, t, weights),
            "point": hybrid.hybrid_point(h, t),
            "gap": float(np.linalg.norm(hybrid.hybrid_point(h, t) - bezier.evaluate(points, t, weights))),
            "delta": float(np.linalg.norm(half)),
            "bound": bound,
        }

    def draw(self, ax, state: dict) -> None:
        plot_control_polygon(ax, state["points"], labels=False, alpha=0.3)
        plot_bezier(ax, state["points"], state["weights"], color="black", linewidth=2.2, label="rational curve R")
        plot_hybrid(ax, state["hybrid"], state["t"], labels=len(state["hybrid"].fixed) <= 7)
        n = len(state["hybrid"].fixed) - 1
        ax.set_title(f"degree-{n} hybrid, moving point m = {state['hybrid'].m}: ‖Δ‖ = {state['delta']:.4f}",
                     fontsize=10)
        ax.legend(fontsize=8, loc="lower center")

    def describe(self, state: dict) -> str:
        h = state["hybrid"]
        return "<br>".join([
            f"M(t) = ({state['moving_point'][0]:.4f}, {state['moving_point'][1]:.4f}), "
            f"H(t) = ({state['point'][0]:.4f}, {state['point'][1]:.4f})",
            f"|H(t) − R(t)| = {state['gap']:.1e} (the hybrid is exact)",
            f"box half diagonal ‖Δ‖ = {state['delta']:.5f}; freezing M at its centre stays within "
            f"‖Δ‖·max B_{h.m}^{len(h.fixed) - 1} = {state['bound']:.5f} of R (20.7)",
        ])


def hybrid_explorer(points=None, weights=None, degree: int = 4, t: float = 0.3) -> HybridExplorer:
    """Dropdowns `curve`, `degree` (2, 3, 4, 6, 8) and slider `t`: the hybrid curve and its moving point. Notes §20.1.

    points, weights: a planar rational curve offered first as "your curve".
    `update` returns {"curve", "points", "weights", "hybrid" (a HybridCurve),
    "t", "moving_point" M(t), "point" H(t), "gap" |H(t) - R(t)|, "delta" ‖Δ‖,
    "bound" (20.7)}.
    """
    return HybridExplorer(points, weights, degree, t)


# ---------------------------------------------------------------- subdivision shrinks the box


class MovingBoxExplorer(TwoPanels, Explorer):
    """The pieces of a split rational curve with their moving points' boxes; below, ‖Δ‖ against depth. Fig. 20.2."""

    static_control = "depth"

    def __init__(self, points=None, weights=None, depth: int = 1, degree: int = 4):
        self.curves, curve = _curve_choice(points, weights, "semicircle (notes, Fig. 20.6)")
        self._deltas: dict[tuple[str, int], list[float]] = {}
        controls = {
            "curve": curve,
            "depth": _slider(widgets.IntSlider, "depth", value=depth, min=0, max=5),
            "degree": widgets.Dropdown(description="degree n", options=list(DEGREES), value=degree),
        }
        super().__init__(controls)

    def _largest_deltas(self, curve: str, degree: int) -> list[float]:
        """The largest ‖Δ‖ over the pieces at depths 0..5, for one curve and degree (kept: sliders come back)."""
        key = (curve, degree)
        if key not in self._deltas:
            points, weights = self.curves[curve]
            self._deltas[key] = []
            for depth in range(6):
                pieces = piece_curves(points, weights, depth)
                boxes = [hybrid.moving_box(hybrid.hybrid_curve(p, w, degree))[1] for p, w in pieces]
                self._deltas[key].append(float(np.linalg.norm(boxes, axis=1).max()))
        return self._deltas[key]

    def compute(self, curve: str, depth: int, degree: int) -> dict:
        points, weights = self.curves[curve]
        deltas = {n: self._largest_deltas(curve, n) for n in (2, 4, 6)}
        return {"curve": curve, "points": points, "weights": weights, "depth": depth, "degree": degree,
                "pieces": 2**depth, "delta": self._largest_deltas(curve, degree)[depth], "deltas": deltas}

    def draw(self, ax, state: dict) -> None:
        plot_moving_boxes(ax, state["points"], state["weights"], state["depth"], state["degree"])
        ax.set_title(f"{state['pieces']} piece(s), degree-{state['degree']} hybrids: largest ‖Δ‖ = "
                     f"{state['delta']:.2e}", fontsize=10)
        lower = self.lower_axes()
        lower.set_position([0.14, 0.07, 0.83, 0.25])  # room for the log-scale tick labels and the y-label
        for n, values in state["deltas"].items():
            lower.semilogy(range(6), values, "o-", markersize=4, label=f"n = {n}")
        lower.axvline(state["depth"], color="0.5", linestyle=":")
        lower.set_xlabel("depth of subdivision")
        lower.set_ylabel("max ‖Δ‖", fontsize=9)
        lower.legend(fontsize=8)

    def describe(self, state: dict) -> str:
        values = state["deltas"][4]
        ratios = ", ".join(f"{a / b:.1f}" for a, b in zip(values[:-1], values[1:]))
        return (f"largest ‖Δ‖ at depth {state['depth']}: {state['delta']:.3e}<br>"
                f"each halving divides it (n = 4) by {ratios}")


def moving_box_explorer(points=None, weights=None, depth: int = 1, degree: int = 4) -> MovingBoxExplorer:
    """Slider `depth` (0-5), dropdowns `curve`, `degree`: every piece with its moving point's box. Notes §20.1.

    `update` returns {"curve", "points", "weights", "depth", "degree",
    "pieces", "delta" (largest ‖Δ‖ of the pieces), "deltas" ({n: largest ‖Δ‖
    at depths 0..5} for n = 2, 4, 6)}.
    """
    return MovingBoxExplorer(points, weights, depth, degree)


# ---------------------------------------------------------------- the adaptive area with a guarantee


def _timed(function, *args, **kwargs):
    start = time.perf_counter()
    result = function(*args, **kwargs)
    return result, time.perf_counter() - start


class AdaptiveAreaExplorer(TwoPanels, Explorer):
    """The area under a rational curve to a tolerance: the pieces used, bound and true error, against Simpson. §20.4."""

    static_control = "tol"

    def __init__(self, points=None, weights=None, tol: float = 1e-6):
        self.curves, curve = _curve_choice(points, weights, "semicircle (notes, Fig. 20.6)")
        self._exact: dict[str, float] = {}
        controls = {
            "curve": curve,
            "tol": _slider(widgets.FloatLogSlider, "tol", value=tol, base=10, min=-10, max=-1, step=1,
                           readout_format=".0e"),
        }
        super().__init__(controls)

    def exact(self, curve: str) -> float:
        """The area to within 1e-13 · max|coordinate|², once per curve (the explorer's "true" value)."""
        if curve not in self._exact:
            points, weights = self.curves[curve]
            tol = 10 * hybrid.FLOOR * np.abs(points).max() ** 2
            self._exact[curve] = hybrid.adaptive_integral(points, weights, tol).value
        return self._exact[curve]

    def compute(self, curve: str, tol: float) -> dict:
        points, weights = self.curves[curve]
        exact = self.exact(curve)
        ours, seconds = _timed(hybrid.adaptive_integral, points, weights, tol)
        simpson, simpson_seconds = _timed(hybrid.simpson_area, points, weights, tol)
        trapezoid = None
        if tol >= TRAPEZOID_LIMIT:
            trapezoid = hybrid.trapezoid_area(points, weights, tol)
        joints = self._joints(points, weights, tol)
        return {
            "curve": curve,
            "points": points,
            "weights": weights,
            "tol": tol,
            "exact": exact,
            "hybrid": ours,
            "error": abs(ours.value - exact),
            "seconds": seconds,
            "simpson": simpson,
            "simpson_error": abs(simpson.value - exact),
            "simpson_seconds": simpson_seconds,
            "trapezoid": trapezoid,
            "joints": joints,
        }

    @staticmethod
    def _joints(points, weights, tol) -> np.ndarray:
        """Where the kept pieces meet: the same subdivision as `adaptive_integral`, in the plain recursive form."""
        h0 = bezier.to_homogeneous(points, weights)
        found: list[float] = []

        def visit(h, start, length):
            _, bound = hybrid._piece_bounds(h, hybrid.ADAPTIVE_DEGREE, hybrid.ADAPTIVE_DEGREE // 2, "area")
            if bound <= tol * length:
                found.append(start)
                return
            left, right = bezier.subdivide(h, 0.5)
            visit(left, start, length / 2)
            visit(right, start + length / 2, length / 2)

        visit(h0, 0.0, 1.0)
        return np.array(found[1:])

    def draw(self, ax, state: dict) -> None:
        points, weights = state["points"], state["weights"]
        shade_area(ax, points, weights)
        plot_control_polygon(ax, points, labels=False, alpha=0.4)
        plot_bezier(ax, points, weights, color="black", linewidth=2.0)
        if state["joints"].size:
            ax.plot(*bezier.evaluate(points, state["joints"], weights).T, "|", color="C3", markersize=14,
                    markeredgewidth=1.5, label="where the pieces meet")
            ax.legend(fontsize=8, loc="lower center")
        result = state["hybrid"]
        ax.set_title(f"tol = {state['tol']:.0e}: {result.pieces} piece(s), area {result.value:.10f}", fontsize=10)
        lower = self.lower_axes()
        names = ["hybrid pieces examined", "Simpson evaluations"]
        work = [result.work, state["simpson"].work]
        if state["trapezoid"] is not None:
            names.append("trapezoids examined")
            work.append(state["trapezoid"].work)
        rows = np.arange(len(work))
        lower.barh(rows, work, color=["C0", "C1", "C2"][: len(work)])
        for row, name, amount in zip(rows, names, work):
            lower.text(1.2, row, f"{name}: {amount}", va="center", fontsize=8)
        lower.set_xscale("log")
        lower.set_xlim(1, 1e6)
        lower.set_yticks([])
        lower.set_xlabel("work (log scale)")

    def describe(self, state: dict) -> str:
        ours, simpson = state["hybrid"], state["simpson"]
        lines = [
            f"hybrid (n = {hybrid.ADAPTIVE_DEGREE}): {ours.pieces} pieces kept of {ours.work} examined, "
            f"bound {ours.bound:.1e}, true error {state['error']:.1e}, {state['seconds'] * 1e3:.2f} ms",
            f"Simpson: {simpson.work} evaluations, its estimate {simpson.bound:.1e}, "
            f"true error {state['simpson_error']:.1e} (no guarantee), {state['simpson_seconds'] * 1e3:.2f} ms",
        ]
        trapezoid = state["trapezoid"]
        if trapezoid is None:
            lines.append(f"trapezoids with the hull bound: skipped below tol = {TRAPEZOID_LIMIT:g} (too many pieces)")
        else:
            lines.append(f"trapezoids with the hull bound: {trapezoid.pieces} pieces, bound {trapezoid.bound:.1e}, "
                         f"true error {abs(trapezoid.value - state['exact']):.1e}")
        return "<br>".join(lines)


def adaptive_area_explorer(points=None, weights=None, tol: float = 1e-6) -> AdaptiveAreaExplorer:
    """Slider `tol` (1e-10 to 1e-1) and dropdown `curve`: the adaptive area of §20.4 beside Simpson's rule. Notes §20.4.

    `update` returns {"curve", "points", "weights", "tol", "exact", "hybrid"
    (an Integral), "error", "seconds", "simpson" (an Integral), "simpson_error",
    "simpson_seconds", "trapezoid" (an Integral or None below 1e-7), "joints"
    (parameters where the kept pieces meet)}.
    """
    return AdaptiveAreaExplorer(points, weights, tol)

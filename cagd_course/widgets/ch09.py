"""Explorers of chapter 9 of the notes (root finding in Bernstein form).

A stepper through convex hull marching (Figure 9.1) on a choice of
polynomials, among them the double root where the march crawls, with the
choice of stepping to the control polygon instead of the hull (to watch that
rule jump a root); the conditioning claim of [FR87] measured on
Wilkinson-type roots with a degree slider, each error against its bound
η K(r); and a line sweeping across the rational quartic of §7.7.8, with the
explicit curve whose roots are the intersections.
"""

from __future__ import annotations

from functools import cache

import ipywidgets as widgets
import numpy as np

from cagd_course.examples import notes_example
from cagd_ref._validation import as_vector
from cagd_ref.bezier import to_homogeneous
from cagd_ref.polynomials import bernstein_horner, horner
from cagd_ref.roots import (
    bernstein_from_roots,
    bernstein_roots,
    hull_crossing,
    hull_march_steps,
    line_curve_intersection,
    wilkinson_polynomial,
)

from ..plotting._style import finish_planar, hide_from_legend
from ..plotting.curves import plot_bezier, plot_control_polygon
from ..plotting.roots import mark_roots, plot_conditioning, plot_explicit, plot_march_step, plot_root_errors
from ._base import Explorer, TwoPanels, _slider

__all__ = [
    "hull_march_explorer",
    "conditioning_explorer",
    "line_curve_explorer",
    "HullMarchExplorer",
    "ConditioningExplorer",
    "LineCurveExplorer",
    "root_errors",
]

# The polynomials the marching explorer offers: the chapter's example, the notes' pitfall, roots at
# the ends, a slow simple root (a far coefficient dwarfs the slope) and a double root (the crawl).
MARCH_PRESETS = {
    "Figure 9.1 (course quartic)": notes_example("09.hull_marching").inputs["coeffs"],
    "<1, -1, 2, -3>: hull against polygon": np.array([1.0, -1.0, 2.0, -3.0]),
    "the pitfall: a linear f": notes_example("09.pitfall").inputs["coeffs"],
    "roots at both ends": np.array([0.0, 1.0, -1.0, 0.0]),
    "§7.3: curve ∩ circle": notes_example("07.circle_curve").results["bernstein"],
    "a slow simple root": np.array([0.65, -0.36, -0.24, 0.72, 0.45, -7.08]),
    "a double root: the crawl": bernstein_from_roots([0.3, 0.3, 0.7]),
}
EVENTS = {"step": "step", "end": "no more roots", "stalled": "still crawling"}  # "root": see _event
RULES = {"convex hull": "hull", "control polygon (wrong)": "polygon"}
MARCH_SHOWN = 100  # steps per root the march is cut at (a double root would go on for ever)
DEGREES = (2, 25)
BERNSTEIN, POWER = "bernstein_roots (Bernstein form)", "numpy.roots (power form)"
ETA = 2.0**-53  # the unit round-off of doubles
CELL = " style='padding:1px 10px;text-align:right'"  # readout table cells, kept apart


# ---------------------------------------------------------------- convex hull marching


class HullMarchExplorer(Explorer):
    """Convex hull marching step by step: the piece f_[t_k, 1], its hull and the next crossing. Notes §9.1, Fig. 9.1."""

    figsize = (6.5, 4.6)

    def __init__(self, coeffs=None):
        self.presets = dict(MARCH_PRESETS)
        if coeffs is not None:
            self.presets = {"your polynomial": as_vector(coeffs, "coeffs"), **self.presets}
        first = next(iter(self.presets))
        controls = {
            "polynomial": widgets.Dropdown(description="f", options=list(self.presets),
                                           layout=widgets.Layout(width="300px")),
            # The slider runs over the march's steps, t_0 to its end (so do the static page's frames).
            "step": _slider(widgets.IntSlider, "step k", min=0,
                            max=len(self._march(tuple(self.presets[first]))) - 1, value=0),
            "rule": widgets.Dropdown(description="step to", options=list(RULES),
                                     layout=widgets.Layout(width="300px")),
        }
        for name in ("polynomial", "rule"):
            controls[name].observe(self._fit_steps, names="value")
        super().__init__(controls)

    def _fit_steps(self, change=None) -> None:
        # Runs before the redraw: the slider's range follows the new march (a step beyond its end moves there).
        coeffs = self.presets[self.controls["polynomial"].value]
        self.controls["step"].max = len(self._march(tuple(coeffs), RULES[self.controls["rule"].value])) - 1

    @staticmethod
    @cache
    def _march(coeffs: tuple, rule: str = "hull") -> tuple:
        return tuple(hull_march_steps(np.array(coeffs), max_steps=MARCH_SHOWN, rule=rule))

    def compute(self, polynomial: str, step: int, rule: str = "convex hull") -> dict:
        coeffs = self.presets[polynomial]
        steps = self._march(tuple(coeffs), RULES[rule])
        k = min(step, len(steps) - 1)
        starts = np.array([s.start for s in steps[: k + 1]])
        moves = np.diff(starts)
        # Successive step lengths towards one root shrink by this factor: linear convergence.
        # Both steps must head for the same root: none across a root that was divided out.
        same_root = (len(moves) >= 2 and moves[-2] > 0
                     and steps[k - 1].root is None and steps[k - 2].root is None)
        ratio = float(moves[-1] / moves[-2]) if same_root else None
        return {
            "polynomial": polynomial,
            "rule": rule,
            "coeffs": coeffs,
            "steps": steps,
            "step": k,
            "start": steps[k].start,
            "crossing": steps[k].crossing,
            "event": steps[k].event,
            "roots": np.array([s.root for s in steps[: k + 1] if s.root is not None]),
            "value": float(bernstein_horner(coeffs, steps[k].start)),
            "ratio": ratio,
        }

    def draw(self, ax, state: dict) -> None:
        plot_march_step(ax, state["steps"], state["step"], state["coeffs"])
        ax.set_xlim(-0.03, 1.03)
        low, high = float(np.min(state["coeffs"])), float(np.max(state["coeffs"]))
        room = 0.1 * max(high - low, 1e-12)
        ax.set_ylim(min(low, 0) - room, max(high, 0) + room)
        ax.legend(fontsize=8, loc="best")
        event = _event(state["steps"][state["step"]], state["step"])
        to = "hull" if RULES[state["rule"]] == "hull" else "polygon"
        ax.set_title(f"marching to the {to}, k = {state['step']} of {len(state['steps']) - 1}: {event}",
                     fontsize=10)

    def describe(self, state: dict) -> str:
        k, steps, coeffs = state["step"], state["steps"], state["coeffs"]
        # f itself at t_k (after a deflation the piece's first coefficient is no longer f's value).
        rows = "".join(
            f"<tr><td{CELL}>{j}</td><td{CELL}>{s.start:.12f}</td>"
            f"<td{CELL}>{bernstein_horner(coeffs, s.start):.3e}</td><td{CELL}>{_event(s, j)}</td></tr>"
            for j, s in list(enumerate(steps[: k + 1]))[-6:]
        )
        head = "".join(f"<th{CELL}>{name}</th>" for name in ("k", "t_k", "f(t_k)", "event"))
        table = f"<table style='border-collapse:collapse'><tr>{head}</tr>{rows}</table>"
        found = ", ".join(f"{t:.12g}" for t in state["roots"]) or "none yet"
        if state["ratio"] is not None:
            ratio = f"<br>step ratio {state['ratio']:.3f}"
        elif k >= 2 and any(s.root is not None for s in steps[k - 2 : k]):
            ratio = "<br>step ratio — (a root was just divided out: the ratio starts again)"
        else:
            ratio = ""
        truth = ", ".join(f"{t:.12g}" for t in bernstein_roots(state["coeffs"])) or "none"
        return f"{table}roots: {found}{ratio}<br>the roots (bernstein_roots): {truth}"


def _event(step, k: int) -> str:
    """What step k does, for the title and the table: a root is named by its index (t_6 for the notes' k = 6)."""
    if step.event != "root":
        return EVENTS[step.event]
    return f"t_{k if step.crossing is None else k + 1} is a root"


def hull_march_explorer(coeffs=None) -> HullMarchExplorer:
    """Dropdowns `polynomial` and `rule`, slider `step` (0 to the march's last step): §9.1 step by step. Notes Fig. 9.1.

    coeffs: Bernstein coefficients (n+1,) on [0, 1], offered first as "your
    polynomial". Presets: the course's quartic standing in for Figure 9.1, the
    cubic <1, -1, 2, -3> (whose control polygon makes a march jump its root),
    the linear pitfall, roots at both ends, §7.3's curve ∩ circle, a slow
    simple root and a double root (where the march crawls). `rule` steps to
    the "convex hull" (the algorithm) or to the "control polygon (wrong)".
    `update` returns {"polynomial", "rule", "coeffs", "steps" (the `MarchStep`s, cut at 100 per root),
    "step" (k shown), "start" (t_k), "crossing" (t_(k+1) or None), "event",
    "roots" (found so far), "value" (f(t_k), of f itself), "ratio" (of
    the last two step lengths, or None before two steps towards the same root)}.
    """
    return HullMarchExplorer(coeffs)


# ---------------------------------------------------------------- conditioning


def root_errors(found, exact) -> np.ndarray:
    """For each exact root (n,), the distance to the nearest computed root (real or complex); inf if there is none."""
    found = np.asarray(found, dtype=complex).reshape(-1)
    exact = as_vector(exact, "exact")
    if found.size == 0:
        return np.full(len(exact), np.inf)
    return np.abs(found[None, :] - exact[:, None]).min(axis=1)


@cache
def _wilkinson_run(degree: int) -> dict:
    bernstein, power, exact = wilkinson_polynomial(degree)
    found = {BERNSTEIN: bernstein_roots(bernstein), POWER: np.roots(power[::-1])}
    # The condition number of each root, K(r) = Σ |c_i φ_i(r)| / |w'(r)|, with w'(r_k) = Π_(j≠k) (r_k - r_j).
    slopes = np.abs([np.prod(r - np.delete(exact, k)) for k, r in enumerate(exact)])
    condition = {BERNSTEIN: bernstein_horner(np.abs(bernstein), exact) / slopes,
                 POWER: horner(np.abs(power), exact) / slopes}
    return {"exact": exact, "found": found, "errors": {name: root_errors(f, exact) for name, f in found.items()},
            "condition": condition}


class ConditioningExplorer(TwoPanels, Explorer):
    """Wilkinson-type roots k/(n+1) from either basis: each root's error, and the largest for every n. Notes ch. 9."""

    def __init__(self, degree: int = 20):
        self.degrees = np.arange(DEGREES[0], DEGREES[1] + 1)
        self.largest = {name: [float(_wilkinson_run(int(n))["errors"][name].max()) for n in self.degrees]
                        for name in (BERNSTEIN, POWER)}
        slider = _slider(widgets.IntSlider, "degree n", min=DEGREES[0], max=DEGREES[1], value=degree)
        super().__init__({"degree": slider})

    def compute(self, degree: int) -> dict:
        run = _wilkinson_run(int(degree))
        largest = {name: float(errors.max()) for name, errors in run["errors"].items()}
        return {
            "degree": int(degree),
            "exact": run["exact"],
            "found": run["found"],
            "errors": run["errors"],
            "condition": run["condition"],
            "largest": largest,
            "ratio": largest[POWER] / max(largest[BERNSTEIN], np.finfo(float).tiny),
        }

    def draw(self, ax, state: dict) -> None:
        plot_root_errors(ax, state["exact"], state["found"])
        for (name, condition), color in zip(state["condition"].items(), ("C0", "C3")):
            basis = "Bernstein" if name == BERNSTEIN else "power"
            ax.plot(state["exact"], ETA * condition, "--", color=color, linewidth=1.0, label=f"η·K(r), {basis}")
        ax.set_xlim(0, 1)
        ax.set_ylim(1e-17, 1)
        ax.legend(fontsize=8, loc="upper left")
        n = state["degree"]
        ax.set_title(f"the roots k/{n + 1} of a degree-{n} polynomial: the error of each", fontsize=10)
        lower = self.lower_axes()
        # Room at the left for the log axes' labels (10^-16 is wide).
        ax.set_position([0.14, 0.40, 0.82, 0.52])
        lower.set_position([0.14, 0.07, 0.82, 0.25])
        plot_conditioning(lower, self.degrees, self.largest, highlight=state["degree"])
        lower.set_ylim(1e-17, 1)
        hide_from_legend(lower)  # the same two series as above: the legend there names them

    def describe(self, state: dict) -> str:
        largest, condition = state["largest"], state["condition"]
        return (f"degree {state['degree']}: largest error {largest[BERNSTEIN]:.1e} (Bernstein), "
                f"{largest[POWER]:.1e} (power form)<br>the power form is {state['ratio']:.1e} times worse; "
                f"largest η·K(r): {ETA * condition[BERNSTEIN].max():.1e} (Bernstein), "
                f"{ETA * condition[POWER].max():.1e} (power)")


def conditioning_explorer(degree: int = 20) -> ConditioningExplorer:
    """Slider `degree` (2..25): the roots k/(n+1) found from the Bernstein and the power form. Notes ch. 9 ([FR87]).

    Both coefficient lists are the correctly rounded exact ones
    (`cagd_ref.roots.wilkinson_polynomial`). The dashed lines are η K(r), the
    bound on each root's error from the condition number of the chapter.
    `update` returns {"degree", "exact" (n,), "found" {method: roots},
    "errors" {method: (n,)}, "condition" {method: (n,) K(r)}, "largest"
    {method: float}, "ratio" (power error / Bernstein error)}.
    """
    return ConditioningExplorer(degree)


# ---------------------------------------------------------------- line ∩ rational curve


class LineCurveExplorer(TwoPanels, Explorer):
    """A line swept across a rational curve; below, f(t) = Σ w_i (a x_i + b y_i + c) B_i^n and its roots. Notes §9.4."""

    def __init__(self, points=None, weights=None):
        quartic = notes_example(notes_example("09.line_curve").inputs["curve"])
        self.points = quartic.inputs["points"] if points is None else np.asarray(points, dtype=float)
        self.weights = quartic.inputs["weights"] if weights is None else as_vector(weights, "weights")
        to_homogeneous(self.points, self.weights)  # checks the pair
        self.middle = len(self.points) // 2
        span = float(np.linalg.norm(np.ptp(self.points, axis=0)))
        controls = {
            # The default is the notes' Lmin = (6, -8, 40), normalised: x cos θ + y sin θ = 4 at θ = 126.87°
            # (exactly, so that the readout gives the chapter's parameter).
            "angle": _slider(widgets.FloatSlider, "angle °", min=0.0, max=180.0, step=0.01,
                             value=float(np.degrees(np.arctan2(0.8, -0.6)))),
            "offset": _slider(widgets.FloatSlider, "offset", min=-span, max=span, step=0.05, value=4.0),
            "weight": _slider(widgets.FloatLogSlider, f"w{self.middle}", base=10, min=-1.0, max=1.0, step=0.02,
                              value=float(self.weights[self.middle])),
        }
        super().__init__(controls)

    def compute(self, angle: float, offset: float, weight: float) -> dict:
        weights = self.weights.copy()
        weights[self.middle] = weight
        theta = np.radians(angle)
        # x cos θ + y sin θ = offset: the line at signed distance `offset` from the origin, normal at angle θ.
        line = np.array([np.cos(theta), np.sin(theta), -offset])
        values = to_homogeneous(self.points, weights) @ line
        ts, pts = line_curve_intersection(self.points, line, weights)
        return {"angle": angle, "offset": offset, "weights": weights, "line": line, "values": values,
                "ts": ts, "points": pts, "hull": hull_crossing(values)}

    def draw(self, ax, state: dict) -> None:
        plot_control_polygon(ax, self.points, labels=True, alpha=0.6)
        plot_bezier(ax, self.points, state["weights"], color="C0", label="rational curve")
        a, b, c = state["line"]
        centre = -c * np.array([a, b])  # the foot of the perpendicular from the origin
        reach = 2 * float(np.linalg.norm(np.ptp(self.points, axis=0))) + np.linalg.norm(centre)
        ends = centre + np.outer([-reach, reach], [-b, a])
        box = (self.points.min(axis=0), self.points.max(axis=0))
        margin = 0.15 * (box[1] - box[0])
        ax.plot(*ends.T, color="C1", linewidth=1.4, label="line")
        if len(state["points"]):
            ax.plot(*state["points"].T, "o", color="C3", markersize=8, label="intersections")
        ax.set_xlim(box[0][0] - margin[0], box[1][0] + margin[0])
        ax.set_ylim(box[0][1] - margin[1], box[1][1] + margin[1])
        finish_planar(ax, adjustable="box")
        ax.legend(fontsize=8, loc="upper right")
        ax.set_title(f"{len(state['ts'])} intersection{'s' if len(state['ts']) != 1 else ''}: "
                     f"{a:.2f} x + {b:.2f} y {'+' if c >= 0 else '-'} {abs(c):.2f} = 0", fontsize=10)
        lower = self.lower_axes()
        plot_explicit(lower, state["values"], label="f(t) = line · P(t), times w(t)")
        mark_roots(lower, state["ts"], label=None)
        lower.set_xlim(-0.03, 1.03)
        lower.legend(fontsize=8, loc="best")

    def describe(self, state: dict) -> str:
        values = ", ".join(f"{v:.3g}" for v in state["values"])
        found = "; ".join(f"t = {t:.6f} at ({x:.4f}, {y:.4f})" for t, (x, y) in zip(state["ts"], state["points"]))
        return f"f_i = w_i (a x_i + b y_i + c) = ({values})<br>{found or 'the line misses the curve'}"


def line_curve_explorer(points=None, weights=None) -> LineCurveExplorer:
    """Sliders `angle`, `offset` (the line x cos θ + y sin θ = offset) and the middle weight. Notes §9.4.

    points (n+1, 2), weights (n+1,): default the rational quartic of §7.7.8.
    `update` returns {"angle", "offset", "weights", "line" (a, b, c), "values"
    (f_i), "ts" (k,), "points" (k, 2), "hull" (where the hull of the f_i meets
    the axis, or None)}.
    """
    return LineCurveExplorer(points, weights)

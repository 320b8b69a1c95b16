"""Explorers of chapter 8 of the notes (offset curves): offsets and their cusps, the PH cubic's exact offset, gouging.

The offset explorer is Figures 8.1 and 8.2 with a radius slider: the offset,
its backward-running arc between the cusps, the circle of the tightest bend on
the offset's side, and the graph of 1 + ρκ(t) whose zeros are the cusps. The PH
lab builds a Pythagorean-hodograph cubic from u and v and lays its exact
rational offset over the sampled Q + ρN. The gouging explorer runs a cutting
tool of radius |ρ| along the offset, shows where it cuts into the curve, and
the trimmed tool path that keeps its distance everywhere.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np
from matplotlib.patches import Circle

from cagd_ref import bezier, offsets
from cagd_ref.polynomials import bernstein_horner

from ..plotting.curves import bezier_samples, plot_bezier, plot_control_polygon
from ..plotting.offsets import draw_cusp_condition, draw_offset, offset_samples, plot_osculating_circle
from ._base import Explorer, TwoPanels, _control_points, _fmt, _slider, bare_axes

__all__ = [
    "offset_explorer",
    "ph_offset_explorer",
    "gouging_explorer",
    "OffsetExplorer",
    "PHOffsetExplorer",
    "GougingExplorer",
]

# The chapter's curves: the convex arch (tightest bend 27/16 at t = 1/2, on its right), the S-curve with an
# inflection at t = 1/2, a parabola y = x² (tightest bend 1/2 at its vertex, on its left) and a hook whose
# end curls back towards its start (a tool inside it hits the other wall before any bend is too tight).
CURVES = {
    "convex arch": np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]),
    "S-curve (inflection)": np.array([[0.0, 0.0], [1.0, 2.0], [2.0, -2.0], [3.0, 0.0]]),
    "parabola y = x²": np.array([[-1.5, 2.25], [0.0, -2.25], [1.5, 2.25]]),
    "hook": np.array([[0.0, 0.0], [6.0, 0.0], [4.0, 5.0], [1.0, 0.8]]),
}
YOUR_CURVE = "your curve"
SAMPLES = 400
KEYED_PANEL = [0.03, 0.40, 0.62, 0.52]  # the upper drawing of a two-panel explorer, leaving the right for its key
RADIUS = {"min": -3.0, "max": 3.0, "step": 0.05, "readout_format": ".2f"}


def _curve_choice(points, default: str) -> tuple[dict, widgets.Dropdown]:
    """The curves an explorer offers (the chapter's, and first the one given) and the dropdown that picks one."""
    if points is None:
        return dict(CURVES), widgets.Dropdown(description="curve", options=list(CURVES), value=default)
    curves = {YOUR_CURVE: _control_points(points, CURVES[default]), **CURVES}
    return curves, widgets.Dropdown(description="curve", options=list(curves), value=YOUR_CURVE)


def _key_beside(ax, position) -> None:
    """Move the drawing to `position` (figure fractions) and put its legend to its right, where no curve, offset or
    circle can run under it whatever the sliders say."""
    ax.set_position(position)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)


def _label_away_from_offset(ax, points, rho: float) -> None:
    """Label the control points P_0..P_n on the side of the polygon away from the offset at ρ (which lies on the right
    for ρ > 0): at each point, against ρ times the mean of the right normals of the legs that meet there."""
    legs = np.diff(points, axis=0)
    lengths = np.linalg.norm(legs, axis=1)
    normals = np.column_stack([legs[:, 1], -legs[:, 0]]) / np.where(lengths > 0, lengths, 1.0)[:, None]
    at_points = np.vstack([normals[:1], normals[:-1] + normals[1:], normals[-1:]])
    side = -1.0 if rho >= 0 else 1.0
    for i, (point, normal) in enumerate(zip(points, at_points)):
        size = np.linalg.norm(normal)
        away = side * (normal / size if size > 1e-12 else np.array([0.0, 1.0]))
        ax.annotate(f"$P_{{{i}}}$", point, xytext=tuple(11 * away), textcoords="offset points", ha="center",
                    va="center", fontsize=10)


def _radius(value) -> str:
    return ("-∞" if value < 0 else "∞") if np.isinf(value) else f"{value:.4g}"


# ---------------------------------------------------------------- offsets and cusps


class OffsetExplorer(TwoPanels, Explorer):
    """An offset with its cusps and backward arc, the tightest bend's circle, 1 + ρκ below. Notes §8, Figs. 8.1-8.2."""

    def __init__(self, points=None, rho: float = 2.0):
        self.curves, curve = _curve_choice(points, "convex arch")
        super().__init__({"curve": curve, "rho": _slider(widgets.FloatSlider, "ρ", value=rho, **RADIUS)})

    def compute(self, curve: str, rho: float) -> dict:
        points = self.curves[curve]
        ts, offset, factor = offset_samples(points, rho, samples=SAMPLES)
        cusps = offsets.offset_cusps(points, rho)
        low, high = offsets.cusp_free_interval(points)
        # The bends towards the offset's side (ρκ < 0) limit it; the tightest has the radius that first makes a cusp.
        limit = high if rho > 0 else -low if rho < 0 else np.inf
        tightest = None
        if np.isfinite(limit):
            tightest = (float(offsets.offset_cusps(points, np.sign(rho) * limit)[0]), float(limit))
        return {
            "curve": curve,
            "points": points,
            "rho": rho,
            "ts": ts,
            "offset": offset,
            "factor": factor,
            "cusps": cusps,
            "cusp_points": offsets.offset_point(points, cusps, rho) if cusps.size else np.zeros((0, 2)),
            "interval": (low, high),
            "tightest": tightest,
            "backward": factor < 0,
        }

    def draw(self, ax, state: dict) -> None:
        points, rho = state["points"], state["rho"]
        plot_control_polygon(ax, points, labels=False, alpha=0.4)
        plot_bezier(ax, points, color="black", linewidth=2.2, label="base curve Q")
        draw_offset(ax, state["offset"], state["factor"], state["cusp_points"], legend=f"offset ρ = {rho:.2f}")
        if state["tightest"] is not None:
            plot_osculating_circle(ax, points, state["tightest"][0])
            ax.plot([], [], ":", color="C2", label="tightest bend on this side")
        count = len(state["cusps"])
        ax.set_title(f"offset at ρ = {rho:.2f}: {count} cusp{'s' if count != 1 else ''}", fontsize=10)
        lower = self.lower_axes()
        _key_beside(ax, KEYED_PANEL)
        bare_axes(ax)
        draw_cusp_condition(lower, state["ts"], state["factor"], state["cusps"])
        lower.set_xticks([0, 0.5, 1])
        lower.set_ylabel("1 + ρκ(t)", fontsize=8, labelpad=1)  # a label, not a legend that a peak could run under

    def describe(self, state: dict) -> str:
        low, high = state["interval"]
        lines = [f"no cusps for {_radius(low)} &lt; ρ &lt; {_radius(high)}"]
        if state["tightest"] is not None:
            t, radius = state["tightest"]
            lines.append(f"tightest bend on the offset's side: radius {radius:.4g} at t = {t:.3f}")
        if state["cusps"].size:
            lines.append("cusps at t = " + ", ".join(f"{t:.4f}" for t in state["cusps"]))
            lines.append(f"runs backwards on {state['backward'].mean():.0%} of [0, 1]")
        return "<br>".join(lines)


def offset_explorer(points=None, rho: float = 2.0) -> OffsetExplorer:
    """Dropdown `curve` and slider `rho` (ρ from -3 to 3): an offset, its cusps and the cusp condition. Notes §8.

    points: (n+1, 2), offered first as "your curve" (default: the chapter's
    curves only). `update` returns {"curve", "points", "rho", "ts" (400,),
    "offset" (400, 2), "factor" (1 + ρκ at ts), "cusps" (k,), "cusp_points"
    (k, 2), "interval" (low, high) of cusp-free radii, "tightest" (t, radius)
    of the offset side's tightest bend or None, "backward" (where 1 + ρκ < 0)}.
    """
    return OffsetExplorer(points, rho)


# ---------------------------------------------------------------- PH curves


class PHOffsetExplorer(TwoPanels, Explorer):
    """A PH cubic from u and v, its exact rational offset over the sampled one, and σ(t) = |Q'(t)| below. Notes §8."""

    def __init__(self, u=(2.0, 1.0), v=(0.0, 1.0), rho: float = 0.25):
        options = {"min": -2.0, "max": 2.0, "step": 0.05, "readout_format": ".2f"}
        controls = {
            "u0": _slider(widgets.FloatSlider, "u0", value=float(u[0]), **options),
            "u1": _slider(widgets.FloatSlider, "u1", value=float(u[1]), **options),
            "v0": _slider(widgets.FloatSlider, "v0", value=float(v[0]), **options),
            "v1": _slider(widgets.FloatSlider, "v1", value=float(v[1]), **options),
            "rho": _slider(widgets.FloatSlider, "ρ", value=rho, **options),
        }
        super().__init__(controls)

    def compute(self, u0: float, u1: float, v0: float, v1: float, rho: float) -> dict:
        cubic = offsets.ph_cubic((0.0, 0.0), (u0, u1), (v0, v1))
        try:
            points, weights = offsets.ph_offset(cubic, rho)
        except ValueError as err:
            raise ValueError(f"u0, u1, v0, v1: {err}") from None
        ts = np.linspace(0.0, 1.0, 201)
        exact = bezier.evaluate(points, ts, weights)
        sampled = offsets.offset_point(cubic, ts, rho)
        sigma = offsets.ph_speed(cubic)
        speed = np.linalg.norm(bezier.derivative(cubic, ts), axis=1)
        return {
            "cubic": cubic,
            "rho": rho,
            "points": points,
            "weights": weights,
            "ts": ts,
            "exact": exact,
            "sampled": sampled,
            "deviation": float(np.abs(exact - sampled).max()),
            "sigma": sigma,
            "speed": speed,
            "speed_error": float(np.abs(bernstein_horner(sigma, ts) - speed).max()),
        }

    def draw(self, ax, state: dict) -> None:
        cubic, points, weights = state["cubic"], state["points"], state["weights"]
        plot_control_polygon(ax, cubic, labels=False)
        _label_away_from_offset(ax, cubic, state["rho"])
        plot_bezier(ax, cubic, color="black", linewidth=2.2, label="PH cubic Q")
        plot_control_polygon(ax, points, labels=[f"{w:.3g}" for w in weights], color="C3", alpha=0.6,
                             marker="s", markersize=4, legend="offset's control points (weights)")
        ax.plot(*state["exact"].T, color="C3", linewidth=2, label="exact rational offset (degree 5)")
        ax.plot(*state["sampled"][::8].T, "o", color="C0", markersize=3.5, label="Q + ρN, sampled")
        ax.set_title(f"ρ = {state['rho']:.2f}: exact quintic vs Q + ρN, gap {state['deviation']:.1e}",
                     fontsize=10)
        ax.margins(0.1)  # room for the labels of the points at the edges
        lower = self.lower_axes()
        _key_beside(ax, KEYED_PANEL)
        bare_axes(ax)
        lower.plot(state["ts"], bernstein_horner(state["sigma"], state["ts"]), color="C2", label="σ(t) = u² + v²")
        lower.plot(state["ts"][::10], state["speed"][::10], "o", color="black", markersize=3, label="|Q'(t)|")
        lower.set_xlim(0, 1)
        lower.set_ylim(bottom=0)
        lower.set_xticks([0, 0.5, 1])
        lower.set_xlabel("t")
        lower.legend(fontsize=8, loc="lower left")

    def describe(self, state: dict) -> str:
        weights = ", ".join(f"{w:.4g}" for w in state["weights"])
        sigma = ", ".join(f"{s:.4g}" for s in state["sigma"])
        return (f"σ = ⟨{sigma}⟩ (Bernstein), |σ − |Q'|| ≤ {state['speed_error']:.1e}<br>"
                f"offset weights ({weights})<br>exact vs sampled offset: {state['deviation']:.1e}")


def ph_offset_explorer(u=(2.0, 1.0), v=(0.0, 1.0), rho: float = 0.25) -> PHOffsetExplorer:
    """Sliders `u0`, `u1`, `v0`, `v1` (the linear u, v) and `rho`: a PH cubic and its exact offset. Notes §8.

    `update` returns {"cubic" (4, 2), "rho", "points" (6, 2), "weights" (6,)
    of the rational offset, "ts", "exact" and "sampled" (201, 2), "deviation"
    (largest distance between them, ~1e-15), "sigma" (3,) Bernstein
    coefficients of the speed, "speed" (201,) |Q'| sampled, "speed_error"}.
    Settings where the cubic stops (u and v share a root) are refused.
    """
    return PHOffsetExplorer(u, v, rho)


# ---------------------------------------------------------------- gouging


def _stretches(ts: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """The runs of consecutive samples where `mask` holds, as (k, 2) first and last parameters."""
    edges = np.diff(np.concatenate([[0], mask.astype(int), [0]]))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    return np.column_stack([ts[starts], ts[stops]]) if starts.size else np.zeros((0, 2))


def _gouge_depths(curve: np.ndarray, path: np.ndarray, radius: float) -> np.ndarray:
    """How far each point of the curve lies inside the swept tool: radius - its distance to the tool's path."""
    path = path[np.all(np.isfinite(path), axis=1)]
    distance = np.linalg.norm(curve[:, None, :] - path[None, :, :], axis=2).min(axis=1)
    return radius - distance


class GougingExplorer(Explorer):
    """A tool of radius |ρ| whose centre runs along the offset: where it cuts into the curve, and why. Notes §8."""

    figsize = (6.5, 5.0)

    def __init__(self, points=None, rho: float = -0.8, t: float = 0.45):
        self.curves, curve = _curve_choice(points, "parabola y = x²")
        controls = {
            "curve": curve,
            "rho": _slider(widgets.FloatSlider, "ρ", value=rho, **RADIUS),
            "t": _slider(widgets.FloatSlider, "tool at t", min=0.0, max=1.0, step=0.01, value=t,
                         readout_format=".2f"),
        }
        super().__init__(controls)

    def compute(self, curve: str, rho: float, t: float) -> dict:
        points = self.curves[curve]
        ts, path, factor = offset_samples(points, rho, samples=SAMPLES)
        base = bezier_samples(points, samples=SAMPLES)
        depth = _gouge_depths(base, path, abs(rho))
        size = float(np.ptp(base, axis=0).max())
        gouged = depth > 1e-9 * size
        regular = np.abs(factor) > 1e-9
        reverse = np.full_like(path, np.nan)
        reverse[regular] = offsets.reverse_offset(points, ts[regular], rho)
        # At a cusp the offset-back jumps from Q to Q + 2ρN: break its line there.
        reverse[1:][np.sign(factor[1:]) != np.sign(factor[:-1])] = np.nan
        cusps = offsets.offset_cusps(points, rho)
        tool = offsets.offset_point(points, t, rho)
        cut = float(max(abs(rho) - np.linalg.norm(base - tool, axis=1).min(), 0.0))
        at_t = float(1 + rho * bezier.signed_curvature(points, t))
        # The chapter's definition, position by position: local where the points of Q next to Q(t) are closer than
        # |ρ|, which is exactly where 1 + ρκ < 0 (the theorem on q''); global where the tool clears them but still
        # cuts, so the closer points lie on another part of Q.
        kind = "local" if at_t < 0 else ("global" if cut > 1e-9 * size else "none")
        # The same verdict for every sampled position of the path: which kinds occur along it.
        reach = abs(rho) - np.linalg.norm(path[:, None, :] - base[None, :, :], axis=2).min(axis=1)
        forward_cuts = (factor > 0) & (reach > 1e-9 * size)
        gouging = tuple(name for name, found in [("local", np.any(factor < 0)), ("global", np.any(forward_cuts))]
                        if found)
        # The tool path a CAM system keeps: the stretches of the offset at distance |ρ| from all of the curve.
        trimmed = offsets.trim_offset(points, rho) if rho != 0 else np.array([[0.0, 1.0]])
        kept_paths = [offsets.offset_point(points, np.linspace(a, b, max(int(SAMPLES * (b - a)), 2)), rho)
                      for a, b in trimmed]
        return {
            "curve": curve,
            "points": points,
            "rho": rho,
            "t": t,
            "base": base,
            "path": path,
            "path_factor": factor,
            "reverse": reverse,
            "gouged": gouged,
            "depth": float(max(depth.max(), 0.0)),
            "cusps": cusps,
            "tool": tool,
            "contact": bezier.evaluate(points, t),
            "cut": cut,
            "factor": at_t,
            "kind": kind,
            "gouging": gouging,
            "global_at": _stretches(ts, forward_cuts),
            "trimmed": trimmed,
            "kept_paths": kept_paths,
        }

    def draw(self, ax, state: dict) -> None:
        rho, base = state["rho"], state["base"]
        # The gouged stretches are a band under the curve, which stays on top and visible.
        cut = np.where(state["gouged"][:, None], base, np.nan)
        ax.plot(*cut.T, color="C1", linewidth=7, alpha=0.45, solid_capstyle="butt", zorder=2, label="gouged")
        for k, path in enumerate(state["kept_paths"]):
            ax.plot(*path.T, color="C2", linewidth=5, alpha=0.45, zorder=2,
                    label="trimmed tool path" if k == 0 else None)
        ax.plot(*base.T, color="black", linewidth=2, zorder=4, label="curve to cut")
        draw_offset(ax, state["path"], state["path_factor"], legend="tool centre's path (raw offset)",
                    linewidth=1.2, zorder=3)
        if rho != 0:
            ax.add_patch(Circle(tuple(state["tool"]), abs(rho), color="C0", alpha=0.12, zorder=1))
            ax.add_patch(Circle(tuple(state["tool"]), abs(rho), fill=False, color="C0", linewidth=1.2, zorder=3))
        ax.plot(*np.array([state["tool"], state["contact"]]).T, "o-", color="C0", markersize=4, linewidth=1,
                zorder=5)
        titles = {"none": "no cut here", "local": "local gouging", "global": "global gouging"}
        ax.set_title(f"tool radius {abs(rho):.2f} at t = {state['t']:.2f}: {titles[state['kind']]}", fontsize=10)
        if ax is self.ax:
            _key_beside(ax, [0.02, 0.03, 0.62, 0.86])
        else:  # drawn into someone else's figure, which keeps its own layout
            ax.legend(fontsize=8, loc="best")
        ax.autoscale_view()
        bare_axes(ax)

    def describe(self, state: dict) -> str:
        lines = [f"deepest gouge {state['depth']:.3g}"]
        if not state["gouging"]:
            lines.append("no position of the tool cuts into the curve")
        if "local" in state["gouging"]:
            lines.append("local gouging: cusps at t = " + ", ".join(f"{c:.3f}" for c in state["cusps"]) +
                         "; where the path runs backwards between them, the bend is tighter than the tool")
        if "global" in state["gouging"]:
            where = "t in " + ", ".join(f"[{a:.3f}, {b:.3f}]" for a, b in state["global_at"])
            if "local" in state["gouging"]:
                lines.append(f"global gouging too, at forward positions ({where}): the tool clears the stretch it "
                             "follows and reaches another part of the curve")
            else:
                lines.append(f"1 + ρκ > 0 everywhere, yet the tool cuts ({where}): global gouging, the curve comes "
                             "back within ρ of itself")
        verdict = {"none": "cuts nothing", "local": f"cuts {state['cut']:.3g} deep, local gouging",
                   "global": f"cuts {state['cut']:.3g} deep, global gouging"}[state["kind"]]
        lines.append(f"at t = {state['t']:.2f}: 1 + ρκ = {state['factor']:.3f}, this position {verdict}; "
                     f"tool centre {_fmt(state['tool'])}")
        kept = ", ".join(f"[{a:.3f}, {b:.3f}]" for a, b in state["trimmed"]) or "none"
        lines.append(f"trimmed path keeps t in {kept}")
        return "<br>".join(lines)


def gouging_explorer(points=None, rho: float = -0.8, t: float = 0.45) -> GougingExplorer:
    """Dropdown `curve`, sliders `rho` (the tool's radius and side) and `t` (where the tool is). Notes §8.

    The tool's centre follows the offset at ρ; a point of the curve is gouged
    when some tool position covers it. `update` returns {"curve", "points",
    "rho", "t", "base" and "path" (400, 2) samples of the curve and of the
    tool's path, "reverse" (the path offset back by -ρ with its own normal: the
    curve again, except on the backward arc), "gouged" (400,) bool, "depth"
    (deepest gouge), "cusps", "tool" (2,) centre at t, "contact" Q(t), "cut"
    (how deep the tool at t cuts), "factor" (1 + ρκ(t)), "kind" (the tool at
    t: "none", "local": 1 + ρκ(t) < 0, the points next to Q(t) are closer
    than |ρ|, "global": it clears them but cuts another part of the curve),
    "gouging" (the kinds that occur along the whole path, e.g. ("local",
    "global") for a swallowtail, whose forward arms cut the opposite wall
    before they cross), "global_at" (k, 2) the stretches of sampled t
    where the path gouges globally, "trimmed" (k, 2) parameter intervals of the path kept by trimming
    (`offsets.trim_offset`), "kept_paths" (their points, one array each)}.
    """
    return GougingExplorer(points, rho, t)


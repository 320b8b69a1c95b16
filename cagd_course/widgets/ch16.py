"""Explorers of chapter 16 of the notes: points and tangents from Q and R, the pseudo-power switch, sub-patches.

The Q–R explorer is the notes' Figure 16.1 with a moving t: the curve, its two degree-(n-1) curves Q and
R, the tangent segment from q to r through p and the true derivative beside it. The switch explorer
shows why the pseudo-power form changes at t = 1/2: the error of the unswitched form, the switched one
and the nested Bernstein form as 1 - t shrinks. The sub-patch explorer draws a patch in 3-D with its
four sub-patch points at (s, t), the two tangent segments through the point, the tangent plane and the
normal, and counts the operations against de Casteljau's.
"""

from __future__ import annotations

from fractions import Fraction

import ipywidgets as widgets
import numpy as np

from cagd_ref import bezier, surfaces
from cagd_ref.polynomials import bernstein_horner, horner

from ..examples import notes_example
from ..plotting.curves import plot_control_polygon
from ..plotting.surfaces import finish_3d, label_3d, plot_control_net, plot_patch, plot_tangent_plane
from ..plotting.vectors import plot_vector
from ._base import Explorer, _fmt, _slider, _swatch, _want_ipympl

__all__ = [
    "qr_tangent_explorer",
    "pseudo_switch_explorer",
    "sub_patch_explorer",
    "QRTangentExplorer",
    "PseudoSwitchExplorer",
    "SubPatchExplorer",
]

_CUBIC = notes_example("16.rational_cubic")
_PATCH = notes_example("16.rational_patch")
_TORUS = notes_example("16.torus")

# Planar curves for the Q–R explorer; the weight slider sets the weight of the second control point.
CURVES = {
    "cubic arch": np.array([[0.0, 0.0], [1.0, 2.5], [3.0, 2.5], [4.0, 0.0]]),
    "quarter circle": np.array([[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]),
    "quintic": np.array([[0.0, 0.0], [0.5, 2.0], [2.0, 3.0], [3.5, 0.5], [4.5, 2.5], [6.0, 1.0]]),
}
_CIRCLE_WEIGHT = float(np.sqrt(0.5))


def _patches() -> dict[str, tuple[np.ndarray, np.ndarray | None]]:
    """The sub-patch explorer's patches: (net (m+1, n+1, 3), weights or None)."""
    rng = np.random.default_rng(16)
    bicubic = np.stack(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"), axis=2)
    bicubic = np.concatenate([bicubic, rng.uniform(-1.2, 1.2, (4, 4, 1))], axis=2)
    return {
        "torus patch": (_TORUS.inputs["points"], _TORUS.inputs["weights"]),
        "rational (2, 1) patch": (_PATCH.inputs["points"], _PATCH.inputs["weights"]),
        "random bicubic": (bicubic, None),
        "wavy bicubic, rational": (bicubic, np.where(np.add.outer(np.arange(4), np.arange(4)) % 2, 2.5, 1.0)),
    }


# ---------------------------------------------------------------- Q, R and the tangent


class QRTangentExplorer(Explorer):
    """A curve with its Q and R, the tangent segment q r through p and the true derivative. Notes §16, Fig. 16.1."""

    figsize = (6.4, 4.6)
    static_control = "t"

    def __init__(self, t: float = 0.35, weight: float = 1.0):
        controls = {
            "curve": widgets.Dropdown(description="curve", options=list(CURVES), value="cubic arch"),
            "t": _slider(widgets.FloatSlider, "t", min=0.0, max=1.0, step=0.01, value=t, readout_format=".2f"),
            "weight": _slider(widgets.FloatLogSlider, "w₁", base=10, min=-1, max=1, step=0.02, value=weight),
        }
        super().__init__(controls)

    def compute(self, curve: str, t: float, weight: float) -> dict:
        points = CURVES[curve]
        weights = np.ones(len(points))
        weights[1] = weight * (_CIRCLE_WEIGHT if curve == "quarter circle" else 1.0)
        q_net, r_net = surfaces.split_qr(points, weights)
        p, q, r = surfaces.curve_point_tangent(points, t, weights)
        _, derivative = surfaces.curve_point_derivative(points, t, weights)
        n = len(points) - 1
        ts = np.linspace(0.0, 1.0, 161)
        q_w, r_w = bernstein_horner(q_net[:, -1], t), bernstein_horner(r_net[:, -1], t)
        p_w = (1 - t) * q_w + t * r_w
        return {
            "curve": curve,
            "points": points,
            "weights": weights,
            "t": t,
            "p": p,
            "q": q,
            "r": r,
            "derivative": derivative,
            "ratio": float(t * r_w / p_w),
            "factor": float(n * q_w * r_w / p_w**2),
            "samples": bezier.evaluate(points, ts, weights),
            "q_curve": _projected(q_net, ts),
            "r_curve": _projected(r_net, ts),
        }

    def draw(self, ax, state: dict) -> None:
        points = state["points"]
        plot_control_polygon(ax, points, labels=True, alpha=0.5)
        ax.plot(*state["samples"].T, color="black", linewidth=2.2, label="curve p(t)")
        ax.plot(*state["q_curve"].T, "--", color="C0", linewidth=1.2, label="Q: first n points")
        ax.plot(*state["r_curve"].T, "--", color="C3", linewidth=1.2, label="R: last n points")
        q, r, p = state["q"], state["r"], state["p"]
        reach = 0.35 * (r - q)
        ax.plot(*np.array([q - reach, r + reach]).T, color="C2", linewidth=1, alpha=0.6)
        ax.plot(*np.array([q, r]).T, "o-", color="C2", linewidth=2, markersize=5, label="segment q r (tangent)")
        step = state["derivative"] / (len(points) - 1)
        plot_vector(ax, p, step, color="C1")
        # named at its middle, below the arrow: its tip can sit on a control point's label
        ax.annotate("p′/n", p + 0.6 * step, xytext=(4, -12), textcoords="offset points", color="C1")
        ax.plot(*p, "ko", markersize=6)
        ax.annotate("q", q, xytext=(-10, 6), textcoords="offset points", color="C0")
        ax.annotate("r", r, xytext=(4, 6), textcoords="offset points", color="C3")
        ax.annotate("p", p, xytext=(4, -12), textcoords="offset points")
        ax.set_title(f"t = {state['t']:.2f}: p divides q r at {state['ratio']:.3f}", fontsize=10)
        ax.legend(fontsize=8, loc="best")
        ax.set(xticks=[], yticks=[], xlabel="", ylabel="")

    def describe(self, state: dict) -> str:
        length = np.linalg.norm(state["r"] - state["q"])
        return (f"p = {_fmt(state['p'])}, p′ = {_fmt(state['derivative'])}<br>"
                f"p = q + {state['ratio']:.4f} (r − q): the fraction t R_w / P_w<br>"
                f"|p′| = {np.linalg.norm(state['derivative']):.4g} = {state['factor']:.4g} × |r − q| "
                f"(n Q_w R_w / P_w²; n = {len(state['points']) - 1}, |r − q| = {length:.4g})")


def _projected(homogeneous: np.ndarray, ts: np.ndarray) -> np.ndarray:
    values = bernstein_horner(homogeneous, ts)
    return values[:, :-1] / values[:, -1:]


def qr_tangent_explorer(t: float = 0.35, weight: float = 1.0) -> QRTangentExplorer:
    """Dropdown `curve`, sliders `t` and `weight` (w₁, log scale): Figure 16.1 with a moving t. Notes §16.

    `update` returns {"curve", "points", "weights", "t", "p", "q", "r" (2,), "derivative" (2,) the true
    p'(t), "ratio" (t R_w / P_w, where p sits on q r), "factor" (n Q_w R_w / P_w², |p'| / |r - q|),
    "samples", "q_curve", "r_curve" (161, 2)}.
    """
    return QRTangentExplorer(t, weight)


# ---------------------------------------------------------------- the switch at t = 1/2


def _relative_errors(values: np.ndarray, exact: np.ndarray) -> np.ndarray:
    """|value - exact| / |exact|, infinite where the value is not finite."""
    with np.errstate(invalid="ignore"):
        return np.where(np.isfinite(values), np.abs(values - exact) / np.abs(exact), np.inf)


def _unswitched(hat: np.ndarray, ts: np.ndarray) -> np.ndarray:
    """The first pseudo-power form alone, u = t/(1 - t) for every t: inf or NaN where it breaks down."""
    values = np.full(len(ts), np.nan)
    finite = ts < 1
    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
        u = ts[finite] / (1 - ts[finite])
        usable = np.isfinite(u)
        values[np.flatnonzero(finite)[usable]] = horner(hat, u[usable]) * (1 - ts[finite][usable]) ** (len(hat) - 1)
    return values


class PseudoSwitchExplorer(Explorer):
    """Errors of the pseudo-power form with and without the switch at 1/2, as t approaches 1. Notes §16 (16.10)."""

    figsize = (6.4, 4.4)
    static_control = "gap"
    gaps = np.concatenate([np.logspace(-16, -0.31, 64), [0.0]])  # 1 - t, and t = 1 itself

    def __init__(self, degree: int = 40, gap: float = 1e-8):
        controls = {
            "degree": _slider(widgets.IntSlider, "degree N", min=1, max=60, value=degree),
            "gap": _slider(widgets.FloatLogSlider, "1 − t", base=10, min=-16, max=-0.31, step=0.25, value=gap,
                           readout_format=".1e"),
        }
        super().__init__(controls)
        self.figure.subplots_adjust(left=0.14)

    def compute(self, degree: int, gap: float) -> dict:
        coeffs = 2.0 ** np.arange(degree + 1)  # (1 + t)^N in Bernstein form
        hat = surfaces.pseudo_power(coeffs)
        ts = np.append(1 - self.gaps, 1 - gap)
        exact = np.array([float((1 + Fraction(t)) ** degree) for t in ts])
        methods = {
            "u = t/(1−t) only": _unswitched(hat, ts),
            "switched at ½": surfaces.pseudo_horner(coeffs, ts),
            "nested Bernstein (ch. 3)": bernstein_horner(coeffs, ts),
        }
        errors = {name: _relative_errors(values, exact) for name, values in methods.items()}
        return {
            "degree": degree,
            "gap": gap,
            "t": float(ts[-1]),
            "exact": float(exact[-1]),
            "values": {name: float(values[-1]) for name, values in methods.items()},
            "errors": {name: e[:-1] for name, e in errors.items()},
            "error_at_t": {name: float(e[-1]) for name, e in errors.items()},
            "broken": self.gaps[~np.isfinite(errors["u = t/(1−t) only"][:-1])],
        }

    def draw(self, ax, state: dict) -> None:
        shown = self.gaps[:-1]  # 1 - t = 0 has no place on a log axis: the readout reports it
        floor = 1e-18
        for (name, errors), color in zip(state["errors"].items(), ("C3", "C0", "0.5")):
            values = np.clip(errors[:-1], floor, None)
            finite = np.isfinite(values)
            ax.plot(shown[finite], values[finite], "o-", color=color, markersize=3, linewidth=1.2, label=name)
        broken = state["broken"][state["broken"] > 0]
        if broken.size:
            ax.plot(broken, np.full(broken.size, 1.0), "x", color="C3", markersize=6,
                    label="unswitched: inf or NaN")
        ax.axvline(state["gap"], color="C2", linewidth=1)
        ax.axhline(np.finfo(float).eps, color="0.7", linewidth=0.8, linestyle=":")
        ax.set(xscale="log", yscale="log", xlim=(5e-17, 1), ylim=(floor / 2, 10), xlabel="1 − t",
               ylabel="relative error")
        failure = (f"overflows from 1 − t = {broken.max():.0e} on" if broken.size else "fails only at t = 1")
        ax.set_title(f"(1 + t)^{state['degree']} near t = 1: the first form alone {failure}", fontsize=10)
        ax.legend(fontsize=8, loc="upper right")
        ax.figure.subplots_adjust(bottom=0.14)  # room for the axis name under the tick labels

    def describe(self, state: dict) -> str:
        rows = [f"t = 1 − {state['gap']:.1e}: exact {state['exact']:.10g}"]
        for (name, value), color in zip(state["values"].items(), ("C3", "C0", "0.5")):
            rows.append(f"{_swatch(color)} {name}: {value:.10g} (error {state['error_at_t'][name]:.1e})")
        rows.append("at t = 1 exactly, u = t/(1 − t) divides by zero; the switched form uses u = 0 there")
        return "<br>".join(rows)


def pseudo_switch_explorer(degree: int = 40, gap: float = 1e-8) -> PseudoSwitchExplorer:
    """Sliders `degree` (N = 1..60) and `gap` (1 - t, log scale): (1 + t)^N by three forms near t = 1. Notes §16.

    `update` returns {"degree", "gap", "t", "exact", "values" and "error_at_t" (by method, at t),
    "errors" (by method, relative errors at the explorer's 65 values of 1 - t, the last one 0; inf where
    the value is not finite), "broken" (the values of 1 - t where the unswitched form fails)}.
    """
    return PseudoSwitchExplorer(degree, gap)


# ---------------------------------------------------------------- four sub-patches and the tangent plane


class SubPatchExplorer(Explorer):
    """A patch in 3-D with its four sub-patch points at (s, t), the tangent segments, plane and normal. Notes §16."""

    figsize = (6.6, 5.4)
    static_control = "s"

    def __init__(self, s: float = 0.35, t: float = 0.6, rotatable: bool | None = None):
        self.patches = _patches()
        controls = {
            "patch": widgets.Dropdown(description="patch", options=list(self.patches), value="torus patch"),
            "s": _slider(widgets.FloatSlider, "s", min=0.0, max=1.0, step=0.01, value=s, readout_format=".2f"),
            "t": _slider(widgets.FloatSlider, "t", min=0.0, max=1.0, step=0.01, value=t, readout_format=".2f"),
        }
        self.rotatable = _want_ipympl() if rotatable is None else bool(rotatable)
        super().__init__(controls, projection="3d", interactive_canvas=self.rotatable)

    def compute(self, patch: str, s: float, t: float) -> dict:
        points, weights = self.patches[patch]
        m, n = points.shape[0] - 1, points.shape[1] - 1
        p, p_s, p_t = surfaces.patch_point_tangents(points, s, t, weights)
        # The sub-patch values at their true scale: each sub-net's homogeneous points evaluated as a patch.
        values = {name: surfaces.patch_point(sub, s, t)
                  for name, sub in zip(("00", "10", "01", "11"), surfaces.sub_patches(points, weights))}
        blends = {
            "A": (1 - t) * values["00"] + t * values["01"], "B": (1 - t) * values["10"] + t * values["11"],
            "C": (1 - s) * values["00"] + s * values["10"], "D": (1 - s) * values["01"] + s * values["11"],
        }
        corners = {name: v[:-1] / v[-1] for name, v in values.items()}
        ends = {name: v[:-1] / v[-1] for name, v in blends.items()}
        c00, c10, c01, c11 = (corners[k] for k in ("00", "10", "01", "11"))
        volume = float(np.linalg.det(np.array([c01 - c00, c10 - c00, c11 - c00])) / 6)
        normal = surfaces.patch_normal(points, s, t, weights)
        three = np.cross(c10 - c00, c01 - c00)
        angle = float(np.degrees(np.arccos(min(abs(three @ normal) / np.linalg.norm(three), 1.0))))
        costs = surfaces.point_tangent_cost(max(m, 1), max(n, 1))
        return {
            "patch": patch, "points": points, "weights": weights, "s": s, "t": t, "degrees": (m, n),
            "p": p, "p_s": p_s, "p_t": p_t, "normal": normal, "corners": corners, "ends": ends,
            "volume": volume, "angle": angle, "costs": costs,
        }

    def draw(self, ax, state: dict) -> None:
        points, weights = state["points"], state["weights"]
        plot_patch(ax, points, weights, samples=9, iso=5, color="C0", alpha=0.18)
        plot_control_net(ax, points, alpha=0.5)
        corners, ends, p = state["corners"], state["ends"], state["p"]
        box = np.array(list(corners.values()))
        ax.plot(*box[[0, 1, 3, 2, 0]].T, ":", color="C4", linewidth=1)
        ax.scatter(*box.T, color="C4", s=22, depthshade=False)
        ax.plot(*np.array([ends["A"], ends["B"]]).T, "-", color="C3", linewidth=2)
        ax.plot(*np.array([ends["C"], ends["D"]]).T, "-", color="C1", linewidth=2)
        size = 0.25 * float(np.ptp(points.reshape(-1, 3), axis=0).max())
        plot_tangent_plane(ax, p, state["p_s"], state["p_t"], size=size, color="C2", alpha=0.3)
        ax.quiver(*p, *(size * state["normal"]), color="black", arrow_length_ratio=0.15)
        ax.scatter(*p, color="black", s=25, depthshade=False)
        finish_3d(ax, points.reshape(-1, 3), elev=35, azim=-35)
        # labels after the view is fixed, each pushed away from the centre of the four points
        middle = box.mean(axis=0)
        for key, point in corners.items():
            label_3d(ax, point, f"S{key}", color="C4", offset=self._away(ax, point, middle), ha="center",
                     va="center")
        ax.set_title(f"(s, t) = ({state['s']:.2f}, {state['t']:.2f}): four sub-patch points, tangent plane",
                     fontsize=9)

    @staticmethod
    def _away(ax, point, middle) -> tuple[float, float]:
        """An offset (points) of 12 pt from `point`, on the side away from `middle`, as seen on the screen."""
        from mpl_toolkits.mplot3d import proj3d

        (px, py, _), (mx, my, _) = (proj3d.proj_transform(*q, ax.get_proj()) for q in (point, middle))
        d = np.array([px - mx, py - my])
        d = d / (np.linalg.norm(d) or 1.0)
        return (12 * d[0], 12 * d[1])

    def describe(self, state: dict) -> str:
        m, n = state["degrees"]
        sub, casteljau = state["costs"]["sub_patches"], state["costs"]["de_casteljau"]
        return (f"{_swatch('C4')} Π(S^kl), the four sub-patch points &nbsp; {_swatch('C3')} A–B (along s) &nbsp; "
                f"{_swatch('C1')} C–D (along t) &nbsp; {_swatch('C2')} tangent plane<br>"
                f"p = {_fmt(state['p'])}, normal {_fmt(state['normal'])}<br>"
                f"volume of the four points' tetrahedron {state['volume']:.3g}: the plane of three of them is "
                f"{state['angle']:.1f}° off the tangent plane<br>"
                f"degree ({m}, {n}): sub-patches {sub[0]} × and {sub[1]} + (16(mn − 1)); "
                f"de Casteljau to the same 2 × 2 net {casteljau[0]} × and {casteljau[1]} +")


def sub_patch_explorer(s: float = 0.35, t: float = 0.6, rotatable: bool | None = None) -> SubPatchExplorer:
    """Dropdown `patch`, sliders `s` and `t`: the four sub-patches and the tangent plane in 3-D. Notes §16.

    `rotatable` shows an ipympl canvas to turn with the mouse (default: when running in a kernel with
    ipympl installed). `update` returns {"patch", "points", "weights", "s", "t", "degrees" (m, n), "p",
    "p_s", "p_t", "normal" (3,), "corners" (the four Π(S^kl) by "00", "10", "01", "11"), "ends" (Π of
    the blends "A", "B", "C", "D": A–B is tangent along s, C–D along t), "volume" (of the tetrahedron of
    the four corners), "angle" (degrees between the plane of three corners and the tangent plane),
    "costs" (`surfaces.point_tangent_cost`)}.
    """
    return SubPatchExplorer(s, t, rotatable)

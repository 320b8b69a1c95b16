"""Explorers of chapter 15 of the notes: tensor-product Bézier patches (the T-spline explorers live elsewhere).

The patch editor moves one control point of a degree (3, 2) patch in x, y and z while the iso-curves and
a few normals follow. The iso-curve explorer is the notes' "beads on wires": the control curves of one
direction, the beads at a parameter c, and the iso-curve they control. The tessellation explorer turns
a tolerance into steps (n_s, n_t) by the bound of §15.4 and sets the bound beside the measured error.
The curvature explorer lifts P20, P11, P02 above the corner's tangent plane and reads off K and H,
by the control-net formulas and by the fundamental forms.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from cagd_ref import surfaces
from cagd_ref.bezier import evaluate

from ..examples import notes_example
from ..plotting.surfaces import finish_3d, label_3d, plot_control_net, plot_iso_curve, plot_normals, plot_patch
from ._base import Explorer, _fmt, _slider, _swatch, _want_ipympl

__all__ = [
    "patch_editor",
    "iso_curve_explorer",
    "tessellation_explorer",
    "curvature_explorer",
    "PatchEditor",
    "IsoCurveExplorer",
    "TessellationExplorer",
    "CurvatureExplorer",
]

_FIG = notes_example("15.patch")
_TESS = notes_example("15.tessellation")
_SPECIAL = notes_example("15.special_tessellations")


def _lattice(z, dx: float = 1.0, dy: float = 1.0) -> np.ndarray:
    z = np.asarray(z, dtype=float)
    i, j = np.meshgrid(np.arange(z.shape[0]), np.arange(z.shape[1]), indexing="ij")
    return np.stack([dx * i, dy * j, z], axis=2)


FIGURE_PATCH = _lattice(_FIG.inputs["z"], 1.0, 1.5)  # the degree (3, 2) patch of Figs. 15.1-15.4


def _tessellation_patches() -> dict[str, np.ndarray]:
    rng = np.random.default_rng(15)
    return {
        "bicubic of Fig. 15.5": _lattice(_TESS.inputs["z"]),
        "ruled (M1 = 0)": np.asarray(_SPECIAL.inputs["ruled"], dtype=float),
        "bilinear (M1 = M3 = 0)": np.asarray(_SPECIAL.inputs["bilinear"], dtype=float),
        "random biquartic": _lattice(rng.uniform(-1, 1, (5, 5)), 1.0, 1.0),
    }


class _ThreeD(Explorer):
    figsize = (6.4, 5.2)

    def _start(self, controls: dict, rotatable: bool | None) -> None:
        self.rotatable = _want_ipympl() if rotatable is None else bool(rotatable)
        super().__init__(controls, projection="3d", interactive_canvas=self.rotatable)


# ---------------------------------------------------------------- the patch editor


class PatchEditor(_ThreeD):
    """Move one control point of a degree (3, 2) patch in x, y, z: iso-curves and normals follow. Notes §15.1."""

    static_control = "dz"

    def __init__(self, point: str = "P11", dz: float = 0.0, rotatable: bool | None = None):
        labels = [f"P{i}{j}" for i in range(4) for j in range(3)]
        controls = {
            "point": widgets.Dropdown(description="point", options=labels, value=point),
            "dx": _slider(widgets.FloatSlider, "Δx", min=-1.5, max=1.5, step=0.05, value=0.0),
            "dy": _slider(widgets.FloatSlider, "Δy", min=-1.5, max=1.5, step=0.05, value=0.0),
            "dz": _slider(widgets.FloatSlider, "Δz", min=-3.0, max=3.0, step=0.05, value=dz),
        }
        self._start(controls, rotatable)

    def compute(self, point: str, dx: float, dy: float, dz: float) -> dict:
        i, j = int(point[1]), int(point[2])
        net = FIGURE_PATCH.copy()
        net[i, j] += (dx, dy, dz)
        grid = np.array([0.25, 0.5, 0.75])
        s, t = (g.ravel() for g in np.meshgrid(grid, grid, indexing="ij"))
        try:
            normals = surfaces.patch_normal(net, s, t)
        except ValueError:
            normals = None
        return {"point": point, "index": (i, j), "points": net, "moved": net[i, j].copy(), "s": s, "t": t,
                "centre": surfaces.patch_point(net, 0.5, 0.5), "normals": normals}

    def draw(self, ax, state: dict) -> None:
        net = state["points"]
        plot_patch(ax, net, samples=9, iso=6, color="C0", alpha=0.2)
        plot_control_net(ax, net, alpha=0.6)
        ax.scatter(*state["moved"], color="C3", s=45, depthshade=False)
        if state["normals"] is not None:
            plot_normals(ax, net, state["s"], state["t"], length=0.8, color="black")
        finish_3d(ax, net.reshape(-1, 3), elev=28, azim=-55)
        label_3d(ax, state["moved"], state["point"], color="C3", fontsize=9, offset=(5, 3))
        ax.set_title(f"degree (3, 2) patch: {state['point']} moved to {_fmt(state['moved'])}", fontsize=10)

    def describe(self, state: dict) -> str:
        i, j = state["index"]
        which = "a corner: the patch passes through it" if (i in (0, 3) and j in (0, 2)) else (
            "on the boundary: it moves one boundary curve" if i in (0, 3) or j in (0, 2) else "inside the net")
        normal = "undefined somewhere" if state["normals"] is None else _fmt(state["normals"][4])
        return (f"{state['point']} = {_fmt(state['moved'])}, {which}<br>"
                f"P(½, ½) = {_fmt(state['centre'])}, unit normal there {normal}<br>"
                f"{_swatch('C0')} iso-curves s, t = 0, 0.2, …, 1 &nbsp; black: normals P_s × P_t at 9 points")


def patch_editor(point: str = "P11", dz: float = 0.0, rotatable: bool | None = None) -> PatchEditor:
    """Dropdown `point` (P00 … P32), sliders `dx`, `dy`, `dz`: edit the degree (3, 2) patch. Notes §15.1.

    `update` returns {"point", "index" (i, j), "points" (4, 3, 3) the edited net, "moved" (3,),
    "s", "t" (9,) the normals' parameters, "centre" P(½, ½), "normals" (9, 3) or None where undefined}.
    """
    return PatchEditor(point, dz, rotatable)


# ---------------------------------------------------------------- beads on wires


class IsoCurveExplorer(_ThreeD):
    """Control curves of one direction, their beads at c and the iso-curve they control. Notes §15.1 (15.5)."""

    static_control = "c"

    def __init__(self, direction: str = "s", c: float = 0.4, weight: float = 1.0, rotatable: bool | None = None):
        controls = {
            "direction": widgets.ToggleButtons(description="fix", options=["s", "t"], value=direction),
            "c": _slider(widgets.FloatSlider, "c", min=0.0, max=1.0, step=0.02, value=c, readout_format=".2f"),
            "weight": _slider(widgets.FloatLogSlider, "w₁₁", base=10, min=-1, max=1, step=0.05, value=weight),
        }
        self._start(controls, rotatable)

    def compute(self, direction: str, c: float, weight: float) -> dict:
        net = FIGURE_PATCH
        weights = np.ones(net.shape[:2])
        weights[1, 1] = weight
        beads, bead_weights = surfaces.iso_curve(net, c, direction, weights)
        taus = np.linspace(0.0, 1.0, 5)
        on_curve = evaluate(beads, taus, bead_weights)
        s, t = (np.full_like(taus, c), taus) if direction == "s" else (taus, np.full_like(taus, c))
        on_patch = surfaces.patch_point(net, s, t, weights)
        wires = surfaces.control_curves(net, direction)
        return {"direction": direction, "c": c, "weight": weight, "points": net, "weights": weights,
                "wires": wires, "beads": beads, "bead_weights": bead_weights,
                "gap": float(np.abs(on_curve - on_patch).max())}

    def draw(self, ax, state: dict) -> None:
        net, weights, direction = state["points"], state["weights"], state["direction"]
        plot_patch(ax, net, weights, samples=9, iso=2, color="C0", alpha=0.15)
        plot_control_net(ax, net, alpha=0.35)
        fine = np.linspace(0.0, 1.0, 41)
        wire_weights = weights.T if direction == "s" else weights
        for wire, w in zip(state["wires"], wire_weights):
            ax.plot(*evaluate(wire, fine, w).T, color="C2", linewidth=1.4)
        plot_iso_curve(ax, net, state["c"], direction, weights, color="C3")
        finish_3d(ax, net.reshape(-1, 3), elev=30, azim=-58)
        other = "t" if direction == "s" else "s"
        ax.set_title(f"{direction} = {state['c']:.2f}: beads on the {direction}-control curves control P as a curve "
                     f"in {other}", fontsize=9)

    def describe(self, state: dict) -> str:
        direction = state["direction"]
        rows = "<br>".join(f"Q{k} = {_fmt(b)}, weight {w:.4g}" for k, (b, w) in
                           enumerate(zip(state["beads"], state["bead_weights"])))
        return (f"{_swatch('C2')} the {direction}-control curves (wires) &nbsp; {_swatch('C3')} beads and the "
                f"iso-curve<br>{rows}<br>largest |curve on the beads − patch| at 5 points: {state['gap']:.1e}")


def iso_curve_explorer(direction: str = "s", c: float = 0.4, weight: float = 1.0,
                       rotatable: bool | None = None) -> IsoCurveExplorer:
    """Toggle `direction` (the parameter held fixed), sliders `c` and `weight` (w₁₁): beads on wires. Notes §15.1.

    `update` returns {"direction", "c", "weight", "points", "weights", "wires" (the control curves of that
    direction), "beads" and "bead_weights" (the iso-curve's control points and weights), "gap" (largest
    difference between the curve on the beads and the patch, at five parameters)}.
    """
    return IsoCurveExplorer(direction, c, weight, rotatable)


# ---------------------------------------------------------------- tessellation budget


class TessellationExplorer(_ThreeD):
    """The steps (n_s, n_t) for a tolerance by the bound of §15.4, the mesh, and the measured error. Notes §15.4."""

    static_control = "log_tol"
    MAX_LINES = 18

    def __init__(self, log_tol: float = -3.0, patch: str = "bicubic of Fig. 15.5", rotatable: bool | None = None):
        self.patches = _tessellation_patches()
        controls = {
            "log_tol": _slider(widgets.FloatSlider, "log₁₀ tol", min=-4.0, max=-0.5, step=0.1, value=log_tol,
                               readout_format=".1f"),
            "patch": widgets.Dropdown(description="patch", options=list(self.patches), value=patch),
            "k_rule": widgets.Dropdown(description="k", options=["optimal √(M3/M1)", "k = 1"],
                                       value="optimal √(M3/M1)"),
        }
        self._start(controls, rotatable)

    def compute(self, log_tol: float, patch: str, k_rule: str) -> dict:
        net = self.patches[patch]
        tol = float(10.0**log_tol)
        bounds = surfaces.second_difference_bounds(net)
        delta_s, delta_t = surfaces.tessellation_deltas(net, tol)
        if k_rule == "k = 1" and min(bounds[0], bounds[2]) > 0:
            m1, m2, m3 = bounds
            delta_s = delta_t = min(1.0, float(np.sqrt(8 * tol / (m1 + 2 * m2 + m3))))
        n_s, n_t = int(np.ceil(1 / delta_s)), int(np.ceil(1 / delta_t))
        error = surfaces.tessellation_error(net, n_s, n_t, samples=4, max_cells=300)
        bound = (bounds[0] * delta_s**2 + 2 * bounds[1] * delta_s * delta_t + bounds[2] * delta_t**2) / 8
        return {"patch": patch, "points": net, "tol": tol, "bounds": bounds, "delta_s": delta_s, "delta_t": delta_t,
                "n_s": n_s, "n_t": n_t, "triangles": 2 * n_s * n_t, "error": error, "bound": float(bound),
                "k_rule": k_rule}

    def draw(self, ax, state: dict) -> None:
        net, n_s, n_t = state["points"], state["n_s"], state["n_t"]
        ax.plot_surface(*np.moveaxis(surfaces.patch_point(
            net, *(g.ravel() for g in np.meshgrid(np.linspace(0, 1, 11), np.linspace(0, 1, 11), indexing="ij"))
        ).reshape(11, 11, 3), 2, 0), color="C0", alpha=0.2, linewidth=0)
        step_s, step_t = max(1, -(-n_s // self.MAX_LINES)), max(1, -(-n_t // self.MAX_LINES))
        fine = np.linspace(0.0, 1.0, 25)
        for i in [*range(0, n_s, step_s), n_s]:
            ax.plot(*surfaces.patch_point(net, np.full_like(fine, i / n_s), fine).T, color="0.3", linewidth=0.5)
        for j in [*range(0, n_t, step_t), n_t]:
            ax.plot(*surfaces.patch_point(net, fine, np.full_like(fine, j / n_t)).T, color="0.3", linewidth=0.5)
        finish_3d(ax, net.reshape(-1, 3), elev=35, azim=-60)
        thinned = " (every few grid lines drawn)" if step_s > 1 or step_t > 1 else ""
        ax.set_title(f"tol = {state['tol']:.1e}: {n_s} × {n_t} cells, {state['triangles']} triangles{thinned}",
                     fontsize=9)

    def describe(self, state: dict) -> str:
        m1, m2, m3 = state["bounds"]
        return (f"M1 = {m1:.4g}, M2 = {m2:.4g}, M3 = {m3:.4g} ({state['k_rule']})<br>"
                f"δs = {state['delta_s']:.6g}, δt = {state['delta_t']:.6g} → n_s = {state['n_s']}, "
                f"n_t = {state['n_t']}, {state['triangles']} triangles<br>"
                f"bound ⅛(M1 δs² + 2 M2 δs δt + M3 δt²) = {state['bound']:.3e} ≤ tol; "
                f"measured error (on a sample of cells) {state['error']:.3e}")


def tessellation_explorer(log_tol: float = -3.0, patch: str = "bicubic of Fig. 15.5",
                          rotatable: bool | None = None) -> TessellationExplorer:
    """Slider `log_tol`, dropdowns `patch` and `k_rule`: the tessellation budget of §15.4. Notes §15.4.

    `update` returns {"patch", "points", "tol", "bounds" (M1, M2, M3), "delta_s", "delta_t", "n_s", "n_t",
    "triangles" (2 n_s n_t), "bound" (the error bound at these steps), "error" (measured on up to 300
    cells), "k_rule"}.
    """
    return TessellationExplorer(log_tol, patch, rotatable)


# ---------------------------------------------------------------- curvature at a corner


class CurvatureExplorer(_ThreeD):
    """Heights h20, h11, h02 of a biquadratic net over its corner plane against K and H. Notes §15.9."""

    static_control = "h11"

    def __init__(self, h20: float = 0.5, h11: float = 0.0, h02: float = 0.5, w11: float = 1.0,
                 rotatable: bool | None = None):
        controls = {
            "h20": _slider(widgets.FloatSlider, "h20", min=-1.0, max=1.0, step=0.05, value=h20),
            "h11": _slider(widgets.FloatSlider, "h11", min=-1.0, max=1.0, step=0.05, value=h11),
            "h02": _slider(widgets.FloatSlider, "h02", min=-1.0, max=1.0, step=0.05, value=h02),
            "w11": _slider(widgets.FloatLogSlider, "w₁₁", base=10, min=-1, max=1, step=0.05, value=w11),
        }
        self._start(controls, rotatable)

    def compute(self, h20: float, h11: float, h02: float, w11: float) -> dict:
        net = _lattice(np.zeros((3, 3)), 0.5, 0.5)
        net[2, 0, 2], net[1, 1, 2], net[0, 2, 2] = h20, h11, h02
        net[2, 2, 2] = h20 + h02  # the far corner follows, so the patch stays a graph over the square
        weights = np.ones((3, 3))
        weights[1, 1] = w11
        gaussian, mean = surfaces.corner_curvatures(net, weights)
        e, f, g, l_, m_, n_ = surfaces.corner_fundamental_forms(net, weights)
        det = e * g - f * f
        k1, k2 = surfaces.principal_curvatures(net, weights)
        return {"points": net, "weights": weights, "heights": (h20, h11, h02), "gaussian": gaussian, "mean": mean,
                "forms": (e, f, g, l_, m_, n_), "gaussian_forms": (l_ * n_ - m_ * m_) / det,
                "mean_forms": (n_ * e - 2 * m_ * f + l_ * g) / (2 * det), "principal": (k1, k2)}

    def draw(self, ax, state: dict) -> None:
        net, weights = state["points"], state["weights"]
        plot_patch(ax, net, weights, samples=7, iso=4, color="C0", alpha=0.25)
        plot_control_net(ax, net, alpha=0.6)
        for key, color in (((2, 0), "C3"), ((1, 1), "C4"), ((0, 2), "C1")):
            top = net[key]
            ax.plot([top[0], top[0]], [top[1], top[1]], [0.0, top[2]], color=color, linewidth=2.5)
        ax.quiver(*net[0, 0], 0, 0, 0.5, color="black", arrow_length_ratio=0.2)
        finish_3d(ax, np.vstack([net.reshape(-1, 3), [[0, 0, -1], [0, 0, 1]]]), elev=22, azim=-50)
        for key, color in (((2, 0), "C3"), ((1, 1), "C4"), ((0, 2), "C1")):
            label_3d(ax, net[key], f"P{key[0]}{key[1]}", color=color, offset=(4, 2))
        kind = ("elliptic" if state["gaussian"] > 1e-12 else "hyperbolic" if state["gaussian"] < -1e-12
                else "parabolic or flat")
        ax.set_title(f"corner (0, 0): K = {state['gaussian']:.3f}, H = {state['mean']:.3f} ({kind})", fontsize=10)

    def describe(self, state: dict) -> str:
        h20, h11, h02 = state["heights"]
        k1, k2 = state["principal"]
        return (f"{_swatch('C3')} h20 = {h20:.2f} &nbsp; {_swatch('C4')} h11 = {h11:.2f} &nbsp; "
                f"{_swatch('C1')} h02 = {h02:.2f} (heights above the plane of P00, P10, P01)<br>"
                f"from the net (15.54)-(15.55): K = {state['gaussian']:.6g}, H = {state['mean']:.6g}<br>"
                f"from the fundamental forms: K = {state['gaussian_forms']:.6g}, H = {state['mean_forms']:.6g}<br>"
                f"principal curvatures k1 = {k1:.4g}, k2 = {k2:.4g}")


def curvature_explorer(h20: float = 0.5, h11: float = 0.0, h02: float = 0.5, w11: float = 1.0,
                       rotatable: bool | None = None) -> CurvatureExplorer:
    """Sliders `h20`, `h11`, `h02` (heights of P20, P11, P02) and `w11`: K and H at the corner. Notes §15.9.

    `update` returns {"points", "weights", "heights", "gaussian", "mean" (the control-net formulas),
    "forms" (E, F, G, L, M, N), "gaussian_forms", "mean_forms" (from the forms), "principal" (k1, k2)}.
    """
    return CurvatureExplorer(h20, h11, h02, w11, rotatable)

"""Explorers of §15.7 of the notes: T-meshes and Rule 1, and the local refinement algorithm step by step.

The T-mesh explorer draws a mesh of the chapter (Fig. 15.17 or Fig. 15.15) in the parameter plane, picks a
control point, shoots its four Rule-1 rays, draws the knot cross and support of its blending function
with a heat map of it, and reports every blending function at a point (s, t): at (3, 4) of Fig. 15.17
that is the notes' B10 = 0.23. The refinement stepper replays the run of Fig. 15.20 (insert P2, which
forces P3) one step at a time, colouring the functions guilty of Violation 1 and 2 and the control points
without a function (Violation 3), and checks that the surface never changes.
"""

from __future__ import annotations

import ipywidgets as widgets
import numpy as np

from cagd_ref import tsplines

from ..examples import notes_example
from ..plotting.tmeshes import plot_blending, plot_knot_cross, plot_rays, plot_tmesh
from ._base import Explorer, _slider, _swatch

__all__ = ["tmesh_explorer", "refinement_stepper_explorer", "TMeshExplorer", "RefinementStepper"]

_E2 = notes_example("15.tmesh")
_E3 = notes_example("15.rule1")
_E4 = notes_example("15.refinement")

MESHES = {
    "Fig. 15.17 (numerical example)": _E2.inputs["mesh"],
    "Fig. 15.15 (Rule 1 examples)": _E3.inputs["mesh"],
}


def _knots(values) -> str:
    return "[" + ", ".join(f"{v:g}" for v in values) + "]"


class TMeshExplorer(Explorer):
    """A T-mesh, one vertex's Rule-1 rays, knot cross and blending function, and all B_i at (s, t). Notes §15.7."""

    figsize = (6.6, 5.4)
    static_control = "vertex"

    def __init__(self, vertex: int = 10, s: float = 3.0, t: float = 4.0, intervals: bool = False):
        first = MESHES[next(iter(MESHES))]
        controls = {
            "mesh": widgets.Dropdown(description="mesh", options=list(MESHES), value=next(iter(MESHES))),
            "vertex": widgets.Dropdown(description="vertex", options=[(f"P{i}", i) for i in
                                                                     range(len(first["vertices"]))], value=vertex),
            "s": _slider(widgets.FloatSlider, "s", min=0.0, max=12.0, step=0.25, value=s),
            "t": _slider(widgets.FloatSlider, "t", min=0.0, max=8.0, step=0.25, value=t),
            "intervals": widgets.Checkbox(description="knot intervals", value=intervals),
        }
        self._mesh_name = controls["mesh"].value
        controls["mesh"].observe(self._new_mesh, names="value")
        super().__init__(controls)

    def _new_mesh(self, change) -> None:
        # A different mesh has a different number of vertices: keep the vertex choice in range.
        count = len(MESHES[change["new"]]["vertices"])
        vertex = self.controls["vertex"]
        self._syncing, previous = True, self._syncing
        try:
            value = min(vertex.value, count - 1)
            vertex.options = [(f"P{i}", i) for i in range(count)]
            vertex.value = value
        finally:
            self._syncing = previous

    def compute(self, mesh: str, vertex: int, s: float, t: float, intervals: bool) -> dict:
        data = MESHES[mesh]
        count = len(data["vertices"])
        if vertex >= count:
            raise ValueError(f"vertex: the mesh {mesh!r} has {count} vertices, got {vertex}")
        (s0, s1), (t0, t1) = tsplines.mesh_domain(data)
        if not (s0 <= s <= s1 and t0 <= t <= t1):
            raise ValueError(f"s: ({s:g}, {t:g}) lies outside the mesh's domain [{s0:g}, {s1:g}] × [{t0:g}, {t1:g}]")
        s_knots, t_knots = tsplines.infer_knot_vectors(data, vertex)
        values = tsplines.blending_values(data, s, t)
        return {
            "mesh": mesh, "data": data, "vertex": vertex, "s": s, "t": t, "intervals": intervals,
            "s_knots": s_knots, "t_knots": t_knots, "value": float(values[vertex]), "values": values,
            "nonzero": [int(i) for i in np.flatnonzero(values > 1e-15)], "total": float(values.sum()),
        }

    def draw(self, ax, state: dict) -> None:
        data = state["data"]
        plot_blending(ax, state["s_knots"], state["t_knots"])
        plot_knot_cross(ax, state["s_knots"], state["t_knots"])
        plot_tmesh(ax, data, labels=not state["intervals"], intervals=state["intervals"], highlight=state["vertex"])
        plot_rays(ax, data, state["vertex"])
        ax.plot(state["s"], state["t"], "*", color="black", markersize=11, zorder=7)
        frame = tsplines.frame_knots(data)
        ax.set(xlim=(frame[0, 0] - 0.3, frame[0, 3] + 0.3), ylim=(frame[1, 0] - 0.3, frame[1, 3] + 0.3))
        ax.set_title(f"P{state['vertex']}: B = N{_knots(state['s_knots'])}(s) · N{_knots(state['t_knots'])}(t)",
                     fontsize=9)

    def describe(self, state: dict) -> str:
        listed = ", ".join(f"B{i} = {state['values'][i]:.4g}" for i in state["nonzero"])
        return (f"{_swatch('C1')} Rule-1 rays &nbsp; {_swatch('C3')} support and knot lines &nbsp; "
                f"{_swatch('C4')} T-junctions<br>"
                f"s-knots {_knots(state['s_knots'])}, t-knots {_knots(state['t_knots'])}<br>"
                f"B{state['vertex']}({state['s']:g}, {state['t']:g}) = {state['value']:.6g}<br>"
                f"nonzero at ({state['s']:g}, {state['t']:g}): {listed}<br>"
                f"Σ B_i = {state['total']:.6g} (not 1: the denominator of (15.7) matters)")


def tmesh_explorer(vertex: int = 10, s: float = 3.0, t: float = 4.0, intervals: bool = False) -> TMeshExplorer:
    """Dropdowns `mesh` and `vertex`, sliders `s`, `t`, checkbox `intervals`: Rule 1 on a T-mesh. Notes §15.7.

    `update` returns {"mesh", "data" (the mesh dict), "vertex", "s", "t", "intervals", "s_knots", "t_knots"
    (5,), "value" (B_vertex(s, t)), "values" (V,) every B_i(s, t), "nonzero" (indices), "total" (Σ B_i)}.
    """
    return TMeshExplorer(vertex, s, t, intervals)


# ---------------------------------------------------------------- the refinement stepper


def _run():
    mesh = _E4.inputs["mesh"]
    vertices = np.asarray(mesh["vertices"], dtype=float)
    points = np.column_stack([vertices, (vertices[:, 0] - 3) * (vertices[:, 1] - 4) / 8])
    refined, new_points, new_weights, log = tsplines.local_refinement(
        mesh, points, _E4.inputs["new_vertices"], _E4.inputs["new_edges"].astype(int))
    s, t = (a.ravel() for a in np.meshgrid(np.linspace(0, 8, 17), np.linspace(0, 8, 17)))
    before = tsplines.tspline_point(mesh, points, s, t)
    # Every step's records sum to the same surface: Π(Σ H B) over the records of that step.
    changes = []
    for entry in log:
        total = sum(np.outer(tsplines.blending_function(sk, tk, s, t), h) for sk, tk, h in entry["records"])
        changes.append(float(np.abs(total[:, :-1] / total[:, -1:] - before).max()))
    return refined, new_weights, log, changes


class RefinementStepper(Explorer):
    """The local refinement of Fig. 15.20 one step at a time: the violations of each step in colour. Notes §15.7."""

    figsize = (6.4, 5.6)
    static_control = "step"
    COLOURS = ("C3", "C0", "C4")

    def __init__(self, step: int = 1):
        self.refined, self.weights, self.log, self.changes = _run()
        controls = {"step": _slider(widgets.IntSlider, "step", min=0, max=len(self.log) - 1, value=step)}
        super().__init__(controls)

    def compute(self, step: int) -> dict:
        entry = self.log[step]
        v1, v2, v3 = entry["violations"]
        records = entry["records"]
        return {
            "step": step, "action": entry["action"], "detail": entry["detail"], "mesh": entry["mesh"],
            "records": len(records), "v1": [records[r][:2] for r in v1], "v2": [records[r][:2] for r in v2],
            "v3": [entry["mesh"]["vertices"][i] for i in v3], "change": self.changes[step],
            "weights": self.weights if entry["action"] == "done" else None,
        }

    def draw(self, ax, state: dict) -> None:
        plot_tmesh(ax, state["mesh"], labels=False)
        for (sk, tk) in state["v1"]:
            plot_knot_cross(ax, sk, tk, color=self.COLOURS[0], alpha=0.08)
        for (sk, tk) in state["v2"]:
            plot_knot_cross(ax, sk, tk, color=self.COLOURS[1], alpha=0.15)
        for point in state["v3"]:
            ax.plot(*point, "o", color=self.COLOURS[2], markersize=11, fillstyle="none", markeredgewidth=2)
        for point in _E4.inputs["new_vertices"].tolist() + [_E4.results["added"].tolist()]:
            if point in state["mesh"]["vertices"]:
                ax.annotate("P2" if point == [4.0, 3.0] else "P3", point, xytext=(4, -12),
                            textcoords="offset points", color="C3", fontsize=9)
        ax.set(xlim=(-1.5, 9.5), ylim=(-1.5, 9.5))
        ax.set_title(f"step {state['step']}: {state['action']} — violations 1, 2, 3: {len(state['v1'])}, "
                     f"{len(state['v2'])}, {len(state['v3'])}", fontsize=10)

    def describe(self, state: dict) -> str:
        rows = [f"{_swatch('C3')} Violation 1 (a knot missing) &nbsp; {_swatch('C0')} Violation 2 (a knot too many) "
                f"&nbsp; {_swatch('C4')} Violation 3 (no function)", state["detail"],
                f"{state['records']} blending functions; max |P − P_before| on a grid: {state['change']:.1e}"]
        if state["weights"] is not None:
            changed = {i: w for i, w in enumerate(state["weights"]) if abs(w - 1) > 1e-12}
            rows.append("new weights: " + ", ".join(f"P{i}: {w:.6g}" for i, w in changed.items())
                        + " (13/12 and 5/4), all others 1")
        return "<br>".join(rows)


def refinement_stepper_explorer(step: int = 1) -> RefinementStepper:
    """Slider `step` over the run of Fig. 15.20 (`notes_example("15.refinement")`). Notes §15.7.

    `update` returns {"step", "action", "detail", "mesh" (that step's mesh), "records" (how many), "v1", "v2"
    (knot vectors (s, t) of the guilty functions), "v3" (vertices without a function), "change" (max
    distance of that step's surface from the original on a grid), "weights" (at the last step)}.
    """
    return RefinementStepper(step)

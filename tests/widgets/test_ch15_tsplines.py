"""cagd_course.widgets, §15.7: the T-mesh explorer and the refinement stepper through `update`; the T-mesh figures."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import tmeshes  # noqa: E402

E2 = notes_example("15.tmesh")
E4 = notes_example("15.refinement")


def test_the_tmesh_explorer_shows_b10_at_3_4():
    explorer = widgets.tmesh_explorer()
    assert list(explorer.controls) == ["mesh", "vertex", "s", "t", "intervals"]
    state = explorer.update(vertex=10, s=3.0, t=4.0)
    assert state["s_knots"].tolist() == [0, 1, 2, 5, 7] and state["t_knots"].tolist() == [0, 1, 3, 5, 6]
    assert state["value"] == pytest.approx(0.23, rel=1e-13)
    assert state["total"] == pytest.approx(12869 / 12600, rel=1e-13)
    assert set(state["nonzero"]).isdisjoint(E2.results["zero"].astype(int).tolist())
    assert "B10(3, 4) = 0.23" in explorer.readout.value


def test_the_tmesh_explorer_switches_mesh_and_keeps_the_vertex_in_range():
    explorer = widgets.tmesh_explorer()
    explorer.update(mesh="Fig. 15.15 (Rule 1 examples)", vertex=29, s=3.0, t=4.0)
    assert explorer.state["s_knots"].tolist() == [0, 1, 3, 4, 6]  # P1 of Fig. 15.15
    explorer.update(vertex=50)
    explorer.controls["mesh"].value = "Fig. 15.17 (numerical example)"
    assert explorer.values["vertex"] == 27
    with pytest.raises(ValueError, match="^s"):
        explorer.update(s=11.0)
    state = explorer.update(intervals=True)
    assert state["intervals"] and any(text.get_text() == "6" for text in explorer.ax.texts)


def test_the_stepper_replays_fig_15_20_without_changing_the_surface():
    explorer = widgets.refinement_stepper_explorer()
    counts = []
    for step in range(explorer.controls["step"].max + 1):
        state = explorer.update(step=step)
        counts.append([len(state["v1"]), len(state["v2"]), len(state["v3"])])
        assert state["change"] < 1e-12
    assert counts == E4.results["counts"].astype(int).tolist()
    assert "13/12" in explorer.readout.value
    np.testing.assert_allclose(sorted(w for w in state["weights"] if abs(w - 1) > 1e-12), [13 / 12, 5 / 4])


def test_the_tmesh_figures():
    ax = Figure().add_subplot()
    mesh = E2.inputs["mesh"]
    assert tmeshes.plot_tmesh(ax, mesh, intervals=True, highlight=10) is ax
    assert len(ax.lines) == 43 + 3  # the edges, the vertices, the T-junctions, the highlighted vertex
    assert tmeshes.tjunctions(mesh).tolist() == [6, 7, 10, 12, 13, 15, 16, 17, 20, 21]
    tmeshes.plot_knot_cross(ax, [0, 1, 2, 5, 7], [0, 1, 3, 5, 6])
    assert len(ax.patches) == 1
    tmeshes.plot_rays(ax, mesh, 10)
    tmeshes.plot_blending(ax, [0, 1, 2, 5, 7], [0, 1, 3, 5, 6])
    with pytest.raises(TypeError, match="^ax"):
        tmeshes.plot_tmesh("not axes", mesh)
    with pytest.raises(ValueError, match="^s_knots"):
        tmeshes.plot_knot_cross(ax, [0, 1, 2], [0, 1, 3, 5, 6])
    ax3 = Figure().add_subplot(projection="3d")
    points = np.column_stack([mesh["vertices"], E2.inputs["heights"]])
    assert tmeshes.plot_tspline_surface(ax3, mesh, points, samples=9) is ax3
    assert len(ax3.collections) == 2  # the triangles and the control points

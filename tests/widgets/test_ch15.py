"""cagd_course.widgets, chapter 15: the patch editor, beads on wires, tessellation budget and corner curvature."""


import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import surfaces as figures  # noqa: E402
from cagd_ref import surfaces  # noqa: E402

TESS = notes_example("15.tessellation")


def test_the_patch_editor_moves_one_point_and_the_patch_follows():
    editor = widgets.patch_editor()
    assert list(editor.controls) == ["point", "dx", "dy", "dz"] and editor.ax.name == "3d"
    before = editor.update(point="P11", dz=0.0)["centre"]
    state = editor.update(point="P11", dz=1.0)
    np.testing.assert_allclose(state["moved"], [1.0, 1.5, 3.0])
    # P(½, ½) rises by B_1^3(½) B_1^2(½) = 3/8 · 1/2 for a unit lift of P11.
    np.testing.assert_allclose(state["centre"] - before, [0, 0, 3 / 16], atol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(state["normals"], axis=1), 1.0)
    corner = editor.update(point="P32", dx=0.0, dz=0.5)
    np.testing.assert_allclose(surfaces.patch_point(corner["points"], 1.0, 1.0), corner["moved"])
    assert "a corner" in editor.readout.value


def test_beads_on_wires_control_the_iso_curve():
    explorer = widgets.iso_curve_explorer()
    for direction in ("s", "t"):
        state = explorer.update(direction=direction, c=0.3, weight=3.0)
        assert state["gap"] < 1e-13
        assert len(state["beads"]) == (3 if direction == "s" else 4)
        assert state["wires"].shape == ((3, 4, 3) if direction == "s" else (4, 3, 3))
    assert "wires" in explorer.readout.value


def test_the_tessellation_explorer_reproduces_the_notes_example():
    explorer = widgets.tessellation_explorer()
    state = explorer.update(log_tol=-3.0, patch="bicubic of Fig. 15.5")
    assert (state["n_s"], state["n_t"], state["triangles"]) == (150, 130, 39000)
    assert state["bounds"] == (48.0, 36.0, 36.0)
    assert state["bound"] == pytest.approx(state["tol"], rel=1e-12)  # the optimum spends the whole budget
    assert 0 < state["error"] <= state["tol"]
    equal = explorer.update(k_rule="k = 1")
    assert equal["triangles"] == 39200 > state["triangles"]
    ruled = explorer.update(k_rule="optimal √(M3/M1)", patch="bilinear (M1 = M3 = 0)")
    assert ruled["n_s"] == 1 and ruled["n_t"] == 250


def test_the_curvature_explorer_agrees_with_the_fundamental_forms():
    explorer = widgets.curvature_explorer()
    for values in ({"h20": 0.5, "h11": 0.0, "h02": 0.5}, {"h20": -0.3, "h11": 0.4, "h02": 0.7, "w11": 2.0}):
        state = explorer.update(**values)
        assert state["gaussian"] == pytest.approx(state["gaussian_forms"], rel=1e-12, abs=1e-12)
        assert state["mean"] == pytest.approx(state["mean_forms"], rel=1e-12, abs=1e-12)
    state = explorer.update(h20=0.5, h11=0.0, h02=0.5, w11=1.0)
    assert (state["gaussian"], state["mean"]) == pytest.approx((1.0, 1.0))  # the paraboloid z = (x² + y²)/2
    assert "fundamental forms" in explorer.readout.value


def test_the_chapter_15_figures_draw_into_3d_axes():
    ax = Figure().add_subplot(projection="3d")
    net = np.stack([*np.meshgrid(np.arange(3.0), np.arange(3.0), indexing="ij"), np.eye(3)], axis=2)
    assert figures.plot_iso_curve(ax, net, 0.4, "t") is ax
    assert len(ax.lines) == 2  # the curve and its beads
    vertices, triangles = surfaces.tessellate(net, 2, 3)
    figures.plot_triangles(ax, vertices, triangles)
    figures.plot_normals(ax, net, [0.2, 0.8], 0.5)
    assert len(ax.collections) == 2
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_triangles(Figure().add_subplot(), vertices, triangles)

"""cagd_course.widgets, chapter 14: the lattice editor, the iso-line, freezing and curve-image explorers, figures."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import deformation as figures  # noqa: E402
from cagd_course.widgets.ch14 import BOX, EXAMPLE_B  # noqa: E402
from cagd_ref import bezier, ffd  # noqa: E402

B = notes_example("14.example_b")


# ---------------------------------------------------------------- the lattice editor


def test_the_editor_starts_at_the_identity_and_moves_the_selected_point():
    editor = widgets.lattice_editor()
    state = editor.state
    assert state["selected"] == (1, 1) and state["displacement"] == 0
    np.testing.assert_allclose(state["deformed"]["word"], editor.shapes["word"], atol=1e-13, equal_nan=True)
    assert set(state["joins"].values()) == {3}  # the identity joins everywhere
    state = editor.update(x=2.5, y=2.0)
    np.testing.assert_array_equal(state["lattice"][1, 1], [2.5, 2.0])
    example = notes_example("14.example_a")
    moved = ffd.ffd(example.inputs["points"], state["lattice"], BOX)
    np.testing.assert_allclose(moved, example.results["deformed"], atol=1e-14)
    # Only the centre moved, one row and one column in from every edge: each edge still joins with C0.
    assert state["joins"] == {"bottom": 0, "top": 0, "left": 0, "right": 0}
    finite = np.all(np.isfinite(editor.shapes["circle"]), axis=1)
    np.testing.assert_allclose(state["deformed"]["circle"][finite],
                               ffd.ffd(editor.shapes["circle"][finite], state["lattice"], BOX), atol=1e-14)


def test_selecting_a_point_shows_its_values_without_moving_anything():
    editor = widgets.lattice_editor()
    editor.update(x=2.5, y=2.0, w=2.0)
    before = editor.state["lattice"].copy()
    editor.update(i=2, j=0)
    np.testing.assert_array_equal(editor.state["lattice"], before)
    assert editor.values["x"] == 3.0 and editor.values["y"] == 0.0 and editor.values["w"] == 1.0
    editor.update(i=1, j=1)
    assert editor.values["x"] == 2.5 and editor.values["w"] == pytest.approx(2.0)
    example = notes_example("14.example_a")
    np.testing.assert_allclose(ffd.ffd(example.inputs["points"][:2], editor.state["lattice"], BOX,
                                       editor.state["weights"]), example.results["deformed_weighted"], atol=1e-14)


def test_moving_a_boundary_point_tears_its_edges_and_changing_a_degree_resets():
    editor = widgets.lattice_editor()
    state = editor.move_point(0, 0, -0.3, -0.2)
    assert state["selected"] == (0, 0) and state["joins"]["bottom"] == -1 and state["joins"]["left"] == -1
    # P_00 is two rows (n = 2) from the top: it enters the second derivative there, C1 is left.
    assert state["joins"]["top"] == 1 and state["joins"]["right"] == 1
    state = editor.update(m=3)
    assert state["lattice"].shape == (4, 3, 2) and state["displacement"] == 0
    assert editor.controls["i"].max == 3
    editor.update(x=1.2)
    assert editor.reset()["displacement"] == 0


def test_the_editor_picks_the_nearest_lattice_point():
    editor = widgets.lattice_editor(2, 3, draggable=False)
    assert editor.pick(1.45, 0.7) == (1, 1)
    assert editor.pick(0.7, 0.3) is None
    with pytest.raises(ValueError, match="^x"):
        editor.update(x=10.0)


# ---------------------------------------------------------------- iso-lines


def test_the_isoline_explorer_reproduces_example_b():
    explorer = widgets.isoline_explorer()
    state = explorer.state
    assert state["degree"] == B.results["isoline_s_degree"]
    np.testing.assert_allclose(state["points"], B.results["row_points"], atol=1e-14)
    assert state["deviation"] < 1e-13
    state = explorer.update(direction="t", value=B.inputs["t"])
    assert state["degree"] == B.results["isoline_t_degree"]
    np.testing.assert_allclose(state["points"], B.results["column_points"], atol=1e-14)
    state = explorer.update(direction="s", value=B.inputs["s"], weight=B.inputs["heavy_weight"])
    np.testing.assert_allclose(state["curve_weights"], B.results["heavy_row_weights"], atol=1e-14)
    assert state["deviation"] < 1e-13


# ---------------------------------------------------------------- freezing


def test_freezing_more_rows_smooths_the_join_one_order_at_a_time():
    explorer = widgets.freeze_explorer()
    torn = explorer.update(order=-1)
    assert torn["continuity"] == -1 and torn["gap"] > 0.1
    kinked = explorer.update(order=0)
    assert kinked["continuity"] == 0 and kinked["gap"] < 1e-12 and kinked["kink"] > 5
    smooth = explorer.update(order=1)
    assert smooth["continuity"] == 1 and smooth["kink"] < 1e-9 and smooth["curvature_jump"] > 0.1
    curvature = explorer.update(order=2)
    assert curvature["continuity"] == 2 and curvature["curvature_jump"] < 1e-9
    assert explorer.update(order=2, strength=0.0)["continuity"] == 3


# ---------------------------------------------------------------- curves


def test_deforming_control_points_differs_from_deforming_the_curve():
    explorer = widgets.curve_image_explorer()
    state = explorer.state
    assert state["image_degree"] == 3 * (2 + 2) and state["exact_error"] < 1e-12
    assert state["naive_error"] > 0.05
    state = explorer.update(curve="line", m=3, n=1, strength=0.0)  # no twist: the identity
    assert state["image_degree"] == 4 and state["naive_error"] < 1e-13


# ---------------------------------------------------------------- figures


def test_glyph_outlines_are_quadratic_bezier_curves_inside_the_box():
    contours = figures.glyph_segments("Bézier", BOX)
    segments = [s for contour in contours for s in contour]
    assert {len(s) - 1 for s in segments} <= {1, 2} and any(len(s) == 3 for s in segments)
    points = np.vstack(segments)
    assert np.all(points >= BOX[0]) and np.all(points <= BOX[1])
    for contour in contours:  # each contour is closed and its segments join end to start
        np.testing.assert_allclose(contour[0][0], contour[-1][-1], atol=1e-12)
        for a, b in zip(contour, contour[1:]):
            np.testing.assert_allclose(a[-1], b[0], atol=1e-12)
    line = figures.segments_polyline(contours, samples=5)
    assert np.isnan(line).any(axis=1).sum() == len(contours) - 1


def test_deform_polyline_keeps_the_breaks():
    grid = figures.grid_polyline(BOX, 3, 2, 5)
    assert np.isnan(grid[:, 0]).sum() == 3 + 1 + 2 + 1 - 1
    moved = figures.deform_polyline(grid, EXAMPLE_B, BOX)
    np.testing.assert_array_equal(np.isnan(moved), np.isnan(grid))
    finite = ~np.isnan(grid[:, 0])
    np.testing.assert_allclose(moved[finite], ffd.ffd(grid[finite], EXAMPLE_B, BOX))


def test_the_isoline_construction_figure_draws_the_image_curve():
    ax = Figure().add_subplot()
    figures.plot_isoline_construction(ax, EXAMPLE_B, 0.6)
    image = [line for line in ax.lines if "degree 2" in str(line.get_label())][0]
    np.testing.assert_allclose(image.get_xydata()[0], bezier.evaluate(np.array(B.results["row_points"]), 0.0))
    assert sum(str(line.get_label()).startswith("row curves") for line in ax.lines) == 1
    with pytest.raises(ValueError, match="^box"):
        figures.plot_box(ax, [[1.0, 1.0], [0.0, 0.0]])

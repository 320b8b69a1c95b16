"""cagd_course.widgets, chapter 20: the hybrid, moving-box and adaptive-area explorers driven through `update`."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import hybrid as figures  # noqa: E402
from cagd_course.widgets.ch20 import CURVES, TRAPEZOID_LIMIT  # noqa: E402
from cagd_ref import bezier, hybrid  # noqa: E402

SEMICIRCLE = notes_example("20.semicircle")
NOTES_CURVE = "semicircle (notes, Fig. 20.6)"


def test_the_hybrid_explorer_moves_m_t_and_h_t_together_for_every_degree():
    explorer = widgets.hybrid_explorer()
    assert list(explorer.controls) == ["curve", "degree", "t"]
    points, weights = SEMICIRCLE.args("points", "weights")
    for degree in (2, 4, 8):
        for t in (0.0, 0.3, 0.5, 1.0):
            state = explorer.update(curve=NOTES_CURVE, degree=degree, t=t)
            assert state["gap"] < 1e-12
            np.testing.assert_allclose(state["point"], bezier.evaluate(points, t, weights), atol=1e-12)
            np.testing.assert_allclose(state["moving_point"], bezier.evaluate(state["hybrid"].moving, t, weights))
    state = explorer.update(degree=4, t=0.5)
    assert state["delta"] == pytest.approx(SEMICIRCLE.results["quartic_delta"])
    assert state["bound"] == pytest.approx(SEMICIRCLE.results["quartic_bound"])
    np.testing.assert_allclose(state["point"], SEMICIRCLE.results["point_at_half"], atol=1e-12)
    assert "‖Δ‖ = 0.47140" in explorer.readout.value


def test_your_curve_comes_first_and_bad_weights_are_refused_at_once():
    explorer = widgets.hybrid_explorer([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], [1.0, 2.0, 1.0])
    assert explorer.controls["curve"].value == "your curve"
    assert explorer.state["gap"] < 1e-12
    with pytest.raises(ValueError, match=r"^weights\b"):
        widgets.hybrid_explorer([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], [1.0, -2.0, 1.0])


def test_the_box_explorer_shows_the_boxes_shrink_with_depth():
    explorer = widgets.moving_box_explorer()
    state = explorer.update(curve=NOTES_CURVE, depth=1, degree=4)
    assert state["pieces"] == 2
    assert state["delta"] == pytest.approx(SEMICIRCLE.results["quartic_delta_half"], rel=1e-10)
    for n, values in state["deltas"].items():
        assert values[0] == pytest.approx(SEMICIRCLE.results["quartic_delta"] if n == 4 else values[0])
        assert all(a > b for a, b in zip(values[:-1], values[1:])), n
    assert state["deltas"][2][1] == pytest.approx(SEMICIRCLE.results["quadratic_delta_half"], rel=1e-10)


def test_the_area_explorer_keeps_its_guarantee_and_beats_simpson_on_work():
    explorer = widgets.adaptive_area_explorer()
    assert list(explorer.controls) == ["curve", "tol"]
    assert explorer.exact(NOTES_CURVE) == pytest.approx(SEMICIRCLE.results["area"], abs=1e-12)
    for tol in (1e-2, 1e-5, 1e-9):
        state = explorer.update(curve=NOTES_CURVE, tol=tol)
        result = state["hybrid"]
        assert state["error"] <= result.bound + 1e-14 and result.bound <= tol * (1 + 1e-9)
        assert len(state["joints"]) == result.pieces - 1
        assert np.all(np.diff(state["joints"]) > 0)
        assert (state["trapezoid"] is None) == (tol < TRAPEZOID_LIMIT)
    assert state["simpson"].work > result.work
    assert "skipped" in explorer.readout.value and "Simpson" in explorer.readout.value


@pytest.mark.parametrize("curve", list(CURVES))
def test_every_curve_of_the_chapter_runs_in_every_explorer(curve):
    for factory in (widgets.hybrid_explorer, widgets.moving_box_explorer, widgets.adaptive_area_explorer):
        explorer = factory()
        state = explorer.update(curve=curve)
        assert state["curve"] == curve
        assert explorer.view.value[:4] == b"\x89PNG"


def test_the_figures_draw_into_the_axes_they_are_given():
    points, weights = SEMICIRCLE.args("points", "weights")
    ax = Figure().add_subplot()
    assert figures.plot_hybrid(ax, hybrid.hybrid_curve(points, weights, 4), 0.4) is ax
    assert len(ax.patches) == 1  # the moving point's box
    assert figures.shade_area(ax, points, weights) is ax and len(ax.collections) == 1
    assert figures.shade_sector(ax, points, weights) is ax
    assert figures.plot_moving_boxes(ax, points, weights, 2) is ax
    assert len(ax.patches) == 2 + 4  # the first box and the sector, then one box per piece
    pieces = figures.piece_curves(points, weights, 2)
    assert len(pieces) == 4
    np.testing.assert_allclose(bezier.evaluate(pieces[1][0], 0.0, pieces[1][1]), bezier.evaluate(points, 0.25, weights))
    with pytest.raises(TypeError, match=r"^ax\b"):
        figures.shade_area(None, points, weights)

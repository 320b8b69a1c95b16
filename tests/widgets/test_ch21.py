"""cagd_course.widgets, chapter 21: the quad, birational and warp explorers and their figures, without a browser."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import quads  # noqa: E402
from cagd_ref import quad_maps  # noqa: E402

BILINEAR = notes_example("21.bilinear")
CONCAVE = notes_example("21.concave")


def test_the_quad_explorer_starts_with_the_notes_point_e():
    explorer = widgets.quad_explorer(draggable=False)
    state = explorer.state
    np.testing.assert_allclose(state["quad"], BILINEAR.inputs["quad"])
    np.testing.assert_allclose(state["preimages"], BILINEAR.results["preimages"], atol=1e-12)
    assert state["inside"].tolist() == [True, False] and state["kind"] == "convex"
    assert "(0.3333, 0.75)" in explorer.readout.value


def test_dragging_e_beyond_the_fold_leaves_no_preimage_and_a_concave_corner_folds():
    explorer = widgets.quad_explorer(draggable=False)
    state = explorer.move_point(4, 17.0, 5.0)  # f(17, 5) < 0
    assert len(state["preimages"]) == 0 and "none" in explorer.readout.value
    state = explorer.update(x2=6.0, y2=2.0, x4=6.66, y4=2.16)  # Figure 21.4a's concave corner
    assert state["kind"] == "non-convex" and state["inside"].sum() == 2  # the square covers E twice
    assert "fold" in explorer.readout.value


def test_a_degenerate_quad_is_refused_and_rolled_back():
    explorer = widgets.quad_explorer(draggable=False)
    with pytest.raises(ValueError, match="^x0..y3: quad: corners"):
        explorer.update(x1=0.0, y1=0.0)
    assert explorer.values["x1"] == 12.0


def test_the_birational_explorer_keeps_the_weight_condition_while_dragging():
    explorer = widgets.birational_explorer(draggable=False)
    assert explorer.state["weights"][1, 1] == pytest.approx(1.0)  # w01 = 5/3: Figure 21.2
    base = explorer.state["base"]
    assert (base.s, base.t) == pytest.approx((5 / 3, 9 / 4))
    rng = np.random.default_rng(0)
    for _ in range(5):
        x, y = rng.uniform(9, 14), rng.uniform(2, 6)
        state = explorer.move_point(2, x, y)
        assert state["birational"] and abs(state["residual"]) < 1e-12
        lines = quad_maps.isoparameter_lines(state["quad"], s=[0.1, 0.5, 0.9], weights=state["weights"])
        assert np.abs((lines / np.linalg.norm(lines, axis=1)[:, None]) @ state["axes"][0]).max() < 1e-12
    state = explorer.update(solve=False)
    assert not state["birational"] and state["base"] is None and "not birational" in explorer.ax.get_title()


def test_the_concave_corner_gets_the_notes_negative_weight():
    explorer = widgets.birational_explorer(draggable=False)
    state = explorer.update(x2=6.0, y2=2.0, w01=1.0)
    assert state["weights"][1, 1] == pytest.approx(CONCAVE.results["w11"])


def test_the_warp_explorer_draws_three_maps_of_one_quad():
    explorer = widgets.warp_explorer(draggable=False)
    state = explorer.state
    assert set(state["maps"]) == {"bilinear", "birational", "projective"}
    projective = notes_example("21.projective").results["weights"]
    np.testing.assert_allclose(state["maps"]["projective"]["weights"], projective)
    coverage = [entry["covered"].mean() for entry in state["maps"].values()]
    assert max(coverage) - min(coverage) < 0.02 and min(coverage) > 0.4  # one quad, three interiors
    assert not np.array_equal(state["maps"]["bilinear"]["raster"], state["maps"]["projective"]["raster"])
    assert [ax.get_title() for ax in explorer.panels] == ["bilinear map", "birational map", "projective map"]


def test_isoline_samples_break_where_a_weighted_line_runs_through_infinity():
    quad, weights = CONCAVE.args("quad", "weights")
    weights[1, 1] = CONCAVE.results["w11"]
    lines = quads.isoline_samples(quad, weights, t=[0.9], span=(0.0, 1.0))
    assert np.isnan(lines).any() and np.isfinite(lines).sum() > 100
    straight = quads.isoline_samples(BILINEAR.inputs["quad"], s=[0.5])
    assert np.isfinite(straight).all()


def test_the_figures_draw_into_the_axes_they_get():
    ax = Figure().add_subplot()
    quad = BILINEAR.inputs["quad"]
    assert quads.plot_quad(ax, quad) is ax and len(ax.texts) == 4
    assert quads.plot_isolines(ax, quad, family="s") is ax
    assert quads.plot_axes_points(ax, quad) is ax
    assert quads.plot_fold(ax, quad) is ax
    image = quads.course_image(16)
    assert image.shape == (16, 16, 3) and image.min() >= 0 and image.max() <= 1
    with pytest.raises(ValueError, match="^family"):
        quads.plot_isolines(ax, quad, family="u")
    with pytest.raises(TypeError, match="^ax"):
        quads.plot_quad("not axes", quad)

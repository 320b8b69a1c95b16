"""cagd_course.widgets, chapter 11: the approximation explorers driven through `update`, without a browser."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting.fitting import box_corners  # noqa: E402
from cagd_ref import approximation as ap  # noqa: E402
from cagd_ref.bspline import bezier_end_knots, de_boor  # noqa: E402

# ---------------------------------------------------------------- samples of shapes


@pytest.mark.parametrize("shape", widgets.FIT_SHAPES)
def test_sample_shapes_are_seeded_and_blend_even_and_random_parameters(shape):
    even = widgets.sample_shape(shape, 25)
    assert even.shape == (25, 2)
    np.testing.assert_array_equal(widgets.sample_shape(shape, 25, 0.7, 0.1), widgets.sample_shape(shape, 25, 0.7, 0.1))
    assert not np.allclose(widgets.sample_shape(shape, 25, 0.7, 0.1, seed=8), widgets.sample_shape(shape, 25, 0.7, 0.1))
    # Without noise the ends stay the shape's ends whatever the unevenness.
    np.testing.assert_allclose(widgets.sample_shape(shape, 25, 1.0)[[0, -1]], even[[0, -1]], atol=1e-12)
    with pytest.raises(ValueError, match="^unevenness"):
        widgets.sample_shape(shape, 25, 1.5)
    with pytest.raises(ValueError, match="^shape"):
        widgets.sample_shape("circle", 25)


# ---------------------------------------------------------------- best constant


def test_best_constant_explorer_starts_from_the_notes_examples():
    explorer = widgets.best_constant_explorer()
    state = explorer.state
    assert state["l2"] == (notes_example("11.best_constant_l2").results["value"],
                           notes_example("11.best_constant_l2").results["error"])
    assert state["linf"] == (4.5, 2.5)
    assert state["linf_at_mean"] == notes_example("11.best_constant_linf").results["error_at_mean"]
    state = explorer.update(g4=17.0 / 10)
    assert state["l2"][0] == pytest.approx(np.mean([2, 3, 3, 5, 1.7]))
    with pytest.raises(ValueError, match="^g0..g4"):
        explorer.update(g0=4.0, g1=4.0, g2=4.0, g3=4.0, g4=4.0)


# ---------------------------------------------------------------- fitting lab


def test_fitting_explorer_state_is_the_faired_fit_of_its_samples():
    explorer = widgets.fitting_explorer()
    state = explorer.update(count=9, fair=True, weight=1e-3, parametrization="centripetal", knots="averaging")
    params = ap.centripetal_parameters(state["points"])
    np.testing.assert_allclose(state["params"], params)
    knots = ap.fitting_knots(params, 9, 3, "averaging")
    np.testing.assert_allclose(state["knots"], knots)
    np.testing.assert_allclose(state["control"], ap.faired_fit(state["points"], params, knots, 3, 1e-3), atol=1e-12)
    np.testing.assert_allclose(state["residuals"], np.linalg.norm(de_boor(state["control"], knots, params)
                                                                  - state["points"], axis=1), atol=1e-12)
    assert state["lsq"] == pytest.approx(np.sum(state["residuals"] ** 2))
    np.testing.assert_allclose(state["curvature"], ap.spline_curvature(state["control"], knots, state["ts"]))


def test_the_fitting_lab_shows_why_chord_length_wins_on_uneven_samples():
    explorer = widgets.fitting_explorer()
    chord = explorer.update(unevenness=1.0, noise=0.05, parametrization="chord length", fair=False)["lsq"]
    uniform = explorer.update(parametrization="uniform")["lsq"]
    assert uniform > 10 * chord
    even_chord = explorer.update(unevenness=0.0, parametrization="chord length")["lsq"]
    even_uniform = explorer.update(parametrization="uniform")["lsq"]
    assert even_uniform < 3 * even_chord


def test_fairing_in_the_lab_lowers_the_energy_and_raises_the_error():
    explorer = widgets.fitting_explorer()
    plain = explorer.update(count=20, fair=False)
    faired = explorer.update(fair=True, weight=1e-3)
    assert faired["energy"] < plain["energy"] and faired["lsq"] > plain["lsq"]


def test_a_knot_span_without_samples_is_reported_and_rolled_back():
    explorer = widgets.fitting_explorer()
    explorer.update(samples=8, count=4, knots="uniform")
    with pytest.raises(ValueError, match="^knots, count: params: the normal equations are singular"):
        explorer.update(count=25)
    assert explorer.values["count"] == 4
    # From a slider there is no caller: the readout shows the problem instead.
    explorer.controls["count"].value = 25
    assert "singular" in explorer.readout.value
    assert explorer.update(count=25, fair=True, weight=1e-4)["control"].shape == (25, 2)  # fairing fills the gaps


# ---------------------------------------------------------------- the fairing weight


def test_fairing_weight_explorer_shrinks_towards_the_line():
    explorer = widgets.fairing_weight_explorer()
    heights = [explorer.update(weight=w)["height"] for w in (1e-6, 1e-3, 1e-1, 10.0)]
    assert np.all(np.diff(heights) < 0) and heights[0] > 2.4
    # In the limit the arc is the least-squares line, whose rise over the parameter range is small.
    line_height = abs(explorer.line[1, 1] - explorer.line[0, 1])
    assert explorer.update(weight=1000.0)["height"] == pytest.approx(line_height, abs=1e-3)
    state = explorer.state
    assert np.all(np.diff(state["curve_lsq"]) > 0) and np.all(np.diff(state["curve_energy"]) < 0)
    assert len(state["family"]) == len(explorer.family)


@pytest.mark.parametrize("constraints", ["ends", "ends and middle"])
def test_with_constraints_the_curve_passes_through_the_chosen_samples_for_every_weight(constraints):
    explorer = widgets.fairing_weight_explorer()
    for weight in (1e-5, 1e-2, 10.0):
        state = explorer.update(weight=weight, constraints=constraints)
        chosen = state["targets"]
        np.testing.assert_allclose(de_boor(state["control"], explorer.knots, explorer.params[chosen]),
                                   explorer.points[chosen], atol=1e-9)
    assert len(state["targets"]) == {"ends": 2, "ends and middle": 3}[constraints]


# ---------------------------------------------------------------- boxes


@pytest.mark.parametrize("frame", ["axes", "curve"])
def test_box_fit_explorer_keeps_the_curve_in_its_boxes(frame):
    explorer = widgets.box_fit_explorer()
    state = explorer.update(half_width=0.12, frame=frame, along=2.5, count=10)
    points, params = explorer.points, explorer.params
    knots = bezier_end_knots(10, 3, 0.0, 1.0)
    np.testing.assert_allclose(state["control"], ap.box_faired_fit(points, params, knots, 3, state["sizes"], frame),
                               atol=1e-12)
    offset = de_boor(state["control"], knots, params) - points
    if frame == "curve":
        tangents, normals = ap.estimate_frames(points)
        offset = np.column_stack([np.sum(offset * tangents, axis=1), np.sum(offset * normals, axis=1)])
        assert state["sizes"][0].tolist() == [0.3, 0.12]
    assert np.all(np.abs(offset) <= state["sizes"] * (1 + 1e-6))
    assert len(state["active"]) >= 2 and state["energy"] < state["energy_lsq"]
    corners = box_corners(points, state["sizes"], frame)
    np.testing.assert_allclose(corners.mean(axis=1), points, atol=1e-12)


def test_boxes_too_small_are_refused_by_name():
    explorer = widgets.box_fit_explorer()
    with pytest.raises(ValueError, match="^half_width"):
        explorer.update(half_width=0.05, count=6)
    assert explorer.values["half_width"] == 0.15


def test_parameter_correction_in_the_lab_repairs_uniform_parameters():
    explorer = widgets.fitting_explorer()
    plain = explorer.update(unevenness=1.0, parametrization="uniform", count=10, fair=False, corrections=0)
    corrected = explorer.update(corrections=6)
    assert len(corrected["history"]) == 7 and corrected["history"][0] == pytest.approx(plain["lsq"])
    assert np.all(np.diff(corrected["history"]) <= 1e-12) and corrected["lsq"] < plain["lsq"] / 10
    params = ap.parameter_correction(corrected["points"], ap.uniform_parameters(corrected["points"]),
                                     corrected["knots"], 3, 6)[1]
    np.testing.assert_allclose(corrected["params"], params)

"""The explorers of chapter 4 (cagd_course.widgets.ch04), driven without a browser."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from cagd_course import widgets
from cagd_course.examples import notes_example
from cagd_course.widgets import ch04
from cagd_ref.bezier import de_casteljau
from cagd_ref.forward_differencing import drift, raster_delta, rasterize
from cagd_ref.polynomials import bernstein_to_power

CUBIC = np.array([[1.0, 1.0], [4.0, 12.0], [15.0, 14.0], [18.0, 2.0]])  # largest neighbour step 12: δ = 1/36



def test_the_chapter_module_exports_its_explorers():
    assert set(ch04.__all__) == {"raster_explorer", "drift_explorer", "RasterExplorer", "DriftExplorer"}
    for name in ch04.__all__:
        assert getattr(widgets, name) is getattr(ch04, name)


# ---------------------------------------------------------------- rasteriser


def test_raster_explorer_starts_gap_free_at_the_notes_bound():
    explorer = widgets.raster_explorer(CUBIC)
    state = explorer.state
    assert state["bound"] == pytest.approx(1 / 36) == raster_delta(CUBIC)
    assert state["steps"] == 36 and state["gap_count"] == 0
    np.testing.assert_array_equal(state["pixels"], rasterize(CUBIC))
    assert "no gaps" in explorer.readout.value


def test_raster_explorer_starts_from_the_course_cubic_of_the_examples():
    example = notes_example("04.raster_cubic")
    explorer = widgets.raster_explorer()
    np.testing.assert_array_equal(explorer.points, example.inputs["points"])
    assert explorer.state["bound"] == pytest.approx(example.results["delta"])
    assert explorer.state["steps"] == example.results["steps"] and explorer.state["gap_count"] == 0
    np.testing.assert_array_equal(widgets.drift_explorer().points, 25 * example.inputs["points"])


def test_raster_explorer_points_pixels_and_gaps_for_a_large_step():
    explorer = widgets.raster_explorer(CUBIC)
    state = explorer.update(delta=0.1)
    assert state["steps"] == 10 and state["step"] == pytest.approx(0.1)
    np.testing.assert_allclose(state["samples"], de_casteljau(CUBIC, np.linspace(0, 1, 11)), atol=1e-10)
    np.testing.assert_array_equal(state["pixels"], rasterize(CUBIC, 0.1))
    jumps = np.abs(np.diff(state["pixels"], axis=0)).max(axis=1)
    assert state["gap_count"] == np.count_nonzero(jumps > 1) > 0
    np.testing.assert_array_equal(state["gaps"], np.flatnonzero(jumps > 1))
    assert f"{state['gap_count']} gaps" in explorer.readout.value
    # every painted pixel is lit in the drawn image, and nothing else
    picture = explorer.image(state["pixels"])
    assert picture.sum() == len({tuple(p) for p in state["pixels"]})


def test_raster_explorer_gaps_grow_with_the_step():
    explorer = widgets.raster_explorer()
    counts = [explorer.update(delta=d)["gap_count"] for d in (0.01, 0.05, 0.2)]
    assert counts[0] == 0 < counts[1]
    assert counts[2] <= counts[1]  # fewer points, so fewer (but wider) jumps


def test_raster_explorer_reports_where_the_march_ends():
    explorer = widgets.raster_explorer()  # the course cubic ends at (37, 5), a pixel corner
    state = explorer.update(delta=1 / 54)
    assert state["steps"] == 54
    last = state["samples"][-1]
    assert state["end_error"] == np.abs(last - explorer.points[-1]).max() < 1e-12
    if state["end_error"] > 0:
        assert "from the last control point (rounding)" in explorer.readout.value
    else:
        assert "exactly at the last control point" in explorer.readout.value


def test_raster_explorer_uses_a_steps_count_that_never_exceeds_delta():
    explorer = widgets.raster_explorer(CUBIC)
    state = explorer.update(delta=0.03)
    assert state["steps"] == 34 and state["step"] <= 0.03


def test_raster_explorer_rejects_bad_points_and_steps():
    with pytest.raises(ValueError, match="points"):
        widgets.raster_explorer(np.zeros((3, 3)))
    explorer = widgets.raster_explorer(CUBIC)
    with pytest.raises(ValueError, match="delta"):
        explorer.update(delta=0.9)
    assert explorer.values["delta"] == pytest.approx(1 / 36)


def test_raster_explorer_starting_step_and_long_curves():
    assert widgets.raster_explorer(CUBIC, delta=0.1).state["steps"] == 10
    with pytest.raises(ValueError, match="delta"):
        widgets.raster_explorer(CUBIC, delta=5.0)
    long_curve = 40 * CUBIC  # bound 1/1440, below the default slider range
    explorer = widgets.raster_explorer(long_curve)
    assert explorer.values["delta"] == pytest.approx(1 / 1440)
    assert explorer.state["steps"] == 1440 and explorer.state["gap_count"] == 0


def test_raster_explorer_leaves_the_points_alone():
    points = CUBIC.copy()
    widgets.raster_explorer(points).update(delta=0.2)
    np.testing.assert_array_equal(points, CUBIC)


# ---------------------------------------------------------------- drift


def test_drift_explorer_errors_are_those_of_drift():
    explorer = widgets.drift_explorer(CUBIC)
    state = explorer.update(steps=400, precision="float32")
    forward, horner = drift(bernstein_to_power(CUBIC), 0.0, 1 / 400, 401, np.float32)
    np.testing.assert_array_equal(state["forward_error"], forward)
    np.testing.assert_array_equal(state["horner_error"], horner)
    assert state["final_forward"] == forward[-1]
    assert state["largest_horner"] == horner.max()


def test_drift_explorer_float32_drifts_more_with_more_steps():
    explorer = widgets.drift_explorer()
    few = explorer.update(steps=100, precision="float32")["final_forward"]
    many = explorer.update(steps=20000)["final_forward"]
    assert many > 10 * few
    state = explorer.update(precision="float64")
    assert state["final_forward"] < 1e-6
    assert state["largest_horner"] == 0.0
    assert "float64" in explorer.ax.get_title()


def test_drift_explorer_float64_names_no_horner_curve_it_cannot_draw():
    explorer = widgets.drift_explorer()
    explorer.update(steps=2000, precision="float64")
    labels = [text.get_text() for text in explorer.ax.get_legend().get_texts()]
    assert not any(label.startswith("Horner") for label in labels)
    assert "reference itself" in explorer.describe(explorer.state)
    explorer.update(precision="float32")
    labels = [text.get_text() for text in explorer.ax.get_legend().get_texts()]
    assert "Horner (float32)" in labels


def test_drift_explorer_rejects_unknown_precisions():
    explorer = widgets.drift_explorer()
    with pytest.raises(TypeError, match="precision"):
        explorer.update(precision="float16")
    assert explorer.values["precision"] == "float32"


SETTINGS = [(10, "float32"), (2000, "float32"), (20000, "float32"), (2000, "float64")]


@pytest.mark.parametrize("steps, precision", SETTINGS)
def test_drift_explorer_legend_leaves_the_half_pixel_line_and_the_curves_free(steps, precision):
    explorer = widgets.drift_explorer()
    explorer.update(steps=steps, precision=precision)
    explorer.figure.canvas.draw()
    box = explorer.ax.get_legend().get_window_extent()
    for line in explorer.ax.get_lines():
        if line.get_label() == "half a pixel":  # an axhline across the whole width, at 0.5 px
            height = explorer.ax.transData.transform([(1.0, 0.5)])[0, 1]
            assert not box.y0 <= height <= box.y1
            continue
        x, y = line.get_transform().transform(np.column_stack(line.get_data())).T
        inside = (box.x0 <= x) & (x <= box.x1) & (box.y0 <= y) & (y <= box.y1)
        assert not inside.any(), line.get_label()

"""cagd_course.widgets, chapter 12: the interval curve, Hermite and degree-reduction explorers, and their figures."""

import math

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import intervals as figures  # noqa: E402
from cagd_course.widgets.ch12 import FUNCTIONS, _sine_range, hermite_pieces  # noqa: E402
from cagd_ref import interval_bezier as ib  # noqa: E402

CUBIC = notes_example("12.cubic")


def test_the_interval_curve_explorer_shows_the_course_cubic_s_boxes():
    explorer = widgets.interval_curve_explorer()
    assert list(explorer.controls) == ["curve", "size", "t", "corners"]
    for t, expected in zip(CUBIC.inputs["t"], CUBIC.results["boxes"]):
        state = explorer.update(curve="cubic", size=1.0, t=float(t))
        np.testing.assert_allclose(state["box"], expected, atol=1e-12)
    assert "outside [0, 1]" in explorer.readout.value  # the last t is -1/2
    state = explorer.update(t=0.5)
    assert "outside" not in explorer.readout.value
    assert state["pieces"] == [(0.0, 0.5, ("TL", "BR")), (0.5, 1.0, ("TR", "BL"))]


def test_box_size_scales_the_errors_and_inflation_follows_the_bernstein_sum():
    explorer = widgets.interval_curve_explorer()
    small = explorer.update(curve="cubic", size=0.5, t=2.0)
    large = explorer.update(size=2.0)
    np.testing.assert_allclose(large["error"], 4 * small["error"])
    np.testing.assert_allclose(np.diff(large["box"], axis=1)[:, 0] / 2, large["error"])
    assert large["growth"] == 27.0
    zero = explorer.update(size=0.0)
    np.testing.assert_allclose(zero["box"][:, 0], zero["box"][:, 1])
    assert explorer.update(corners=False)["pieces"] == []


def test_the_quarter_circle_curve_is_the_notes_arc():
    state = widgets.interval_curve_explorer().update(curve="quarter circle (quartic)", t=0.5, size=1.0)
    exact = notes_example("12.quarter_circle").results["max_error_exact"]
    np.testing.assert_allclose(state["error"], [exact, exact], rtol=1e-12)


def test_sine_range_is_exact():
    assert _sine_range(0.0, 0.5) == (0.0, math.sin(0.5))
    assert _sine_range(1.0, 2.0) == (math.sin(1.0), 1.0)
    assert _sine_range(4.0, 5.0)[0] == -1.0
    assert _sine_range(0.0, 7.0) == (-1.0, 1.0)


@pytest.mark.parametrize("function", list(FUNCTIONS))
@pytest.mark.parametrize("order, depth", [(1, 0), (2, 1), (3, 2), (4, 0)])
def test_every_hermite_enclosure_holds_its_function(function, order, depth):
    f, _ = FUNCTIONS[function]
    for a, b, coeffs in hermite_pieces(function, order, depth):
        t = np.linspace(a, b, 101)
        band = ib.interval_de_casteljau(coeffs, (t - a) / (b - a))
        assert np.all(band[:, 0] <= f(t) + 1e-12) and np.all(f(t) <= band[:, 1] + 1e-12)


def test_the_hermite_explorer_reproduces_example_1_and_the_bound_is_safe():
    explorer = widgets.hermite_interval_explorer()
    state = explorer.update(function="exp(t)", order=2, depth=0)
    example = notes_example("12.hermite_exp")
    (_, _, coeffs), = state["pieces"]
    np.testing.assert_allclose(coeffs[:, 0], example.results["lo"], atol=1e-14)
    assert state["error"] <= state["bound"]
    finer = explorer.update(depth=2)
    assert finer["bound"] < state["bound"] / 100 and len(finer["pieces"]) == 4
    assert "bound / true" in explorer.readout.value


def test_the_degree_reduction_explorer_shrinks_the_bound_and_never_beats_the_truth():
    explorer = widgets.degree_reduction_explorer()
    states = [explorer.update(depth=d) for d in range(6)]
    bounds = [s["bound"] for s in states]
    assert all(s["deviation"] <= s["bound"] for s in states)
    assert all(b1 / b2 > 16 for b1, b2 in zip(bounds[2:], bounds[3:]))
    assert len(states[-1]["pieces"]) == 32
    example = notes_example("12.derivative_bounds")
    assert states[0]["pieces"].shape == (1, 5, 2, 2) and example.inputs["r"] == 4


def test_plotting_helpers_draw_into_the_axes():
    boxes = ib.boxes_from_center(*CUBIC.args("centers", "errors"))
    ax = Figure().add_subplot()
    figures.plot_interval_curve(ax, boxes, corners=True)
    assert len(ax.patches) == 4 and len(ax.collections) == 1
    labels = [line.get_label() for line in ax.lines]
    assert "centre curve" in labels and any(label.startswith("corner curves") for label in labels)
    band_ax = Figure().add_subplot()
    coeffs = ib.hermite_interval(*notes_example("12.hermite_exp").args("derivs0", "derivs1", "bound"))
    figures.plot_interval_band(band_ax, coeffs, f=np.exp, relative_to=np.exp)
    assert band_ax.get_xlabel() == "t" and len(band_ax.lines) == 3
    with pytest.raises(ValueError, match="^boxes"):
        figures.plot_boxes(ax, np.zeros((3, 3, 2)))

"""cagd_course.widgets, chapter 13: the band, affine-map and number-line explorers driven through `update`."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import rounding as figures  # noqa: E402
from cagd_ref import floating  # noqa: E402

FIGURE = notes_example("13.figure_13_1")
BOXES = notes_example("13.figure_13_2")


def test_the_band_is_chaotic_contained_and_exactly_zero_at_the_root():
    explorer = widgets.band_explorer()
    assert list(explorer.controls) == ["bits", "half_width", "method"]
    state = explorer.update(bits=24, half_width=FIGURE.inputs["window"] / 2, method="de Casteljau")
    assert state["at_centre"] == 0.0 and state["contained"]
    assert state["sign_changes"] > 100 and state["exact_sign_changes"] == 1
    computed = floating.evaluate_in_precision(FIGURE.inputs["coeffs"], state["t"], 24)
    np.testing.assert_array_equal(state["values"], computed)
    assert np.all(np.abs(state["values"] - state["exact"]) <= state["radius"])
    assert np.all(state["radius"] <= state["bound"])
    assert "off the frame" in " ".join(text.get_text() for text in explorer.ax.texts)


def test_more_bits_shrink_the_band_and_other_methods_have_no_radius():
    explorer = widgets.band_explorer()
    coarse = explorer.update(bits=11, half_width=1e-2)["max_error"]
    fine = explorer.update(bits=53, half_width=5e-7)["max_error"]
    assert fine < 1e-15 < 1e-6 < coarse
    state = explorer.update(bits=24, half_width=5e-5, method="Horner (power form)")
    assert state["radius"] is None and state["contained"] is None
    assert np.all(np.abs(state["values"] - state["exact"]) <= state["bound"])
    with pytest.raises(TypeError, match="^bits"):
        explorer.update(bits=23)  # not a precision of the slider


def test_the_band_explorer_takes_a_polynomial_of_its_own():
    explorer = widgets.band_explorer([1.0, -1.0, 1.0], centre=0.5, bits=20, half_width=1e-3)  # (1 - 2t)²: a double root
    state = explorer.state
    assert state["contained"] and np.all(state["exact"] >= 0) and state["at_centre"] == 0.0


def test_the_affine_explorer_rebuilds_figure_13_2():
    explorer = widgets.affine_roundoff_explorer()
    state = explorer.update(t=BOXES.inputs["t"], bits=int(BOXES.inputs["bits"]))
    np.testing.assert_allclose(state["exact_centre"], BOXES.results["centre"])
    np.testing.assert_allclose(state["exact_radius"], BOXES.results["exact_radius"])
    eta = state["eta"]
    np.testing.assert_allclose(state["widening"], state["notes_widening"] / (1 - eta), rtol=1e-12)  # 1 - t exact
    outside = explorer.update(t=1.6)
    assert outside["t"] == 1.625 and np.all(outside["widening"] > outside["notes_widening"])  # 1 - t rounded
    assert np.all(explorer.update(bits=25)["widening"] < 1e-6)
    rectangles = [p for p in explorer.ax.patches if p.get_linestyle() == "--"]
    np.testing.assert_allclose(rectangles[0].get_width(), 2 * explorer.state["radius"][0])


def test_the_number_line_shows_the_neighbours_of_one_third():
    third = notes_example("13.one_third")
    state = widgets.number_line_explorer().update(x=1 / 3, bits=int(third.inputs["fraction_bits"]))
    assert state["neighbours"] == (third.results["lower"], third.results["upper"])
    assert state["encoded"] == third.results["lower_bits"].replace("|100000001|", "|10000001|")
    lo, hi = state["interval"]
    assert lo <= 1 / 3 <= hi and state["relative_error"] <= state["eta"]
    with pytest.raises(ValueError, match="^x"):
        widgets.number_line_explorer().update(x=0.0)


def test_the_number_line_figure_marks_every_d_bit_number():
    fig = Figure()
    ax = fig.add_subplot()
    figures.plot_number_line(ax, 0.3, 3)
    ticks = np.sort(np.concatenate([seg[:, 0] for seg in ax.collections[0].get_segments()]))[::2]
    np.testing.assert_array_equal(ticks, floating.round_to_bits(ticks, 3))
    spacing = np.diff(ticks)
    assert set(spacing) <= {2.0**-5, 2.0**-4, 2.0**-3}  # the spacing doubles at every power of two

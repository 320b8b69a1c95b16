"""cagd_course.widgets, chapter 17: the implicit-curve, common-root and intersection explorers driven through update."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import implicit_curves as figures  # noqa: E402
from cagd_ref import algebra, bezier  # noqa: E402

LOOP = notes_example("17.bezier_cubic")
TABLE = notes_example("17.intersection")


def test_the_implicit_curve_explorer_starts_on_the_loop_cubic():
    explorer = widgets.implicit_curve_explorer()
    state = explorer.state
    np.testing.assert_array_equal(state["points"], LOOP.inputs["points"])
    np.testing.assert_array_equal(state["implicit"], LOOP.results["implicit"])
    assert state["t"] == pytest.approx(0.5) and state["relative_value"] < 1e-12
    np.testing.assert_allclose(state["back"], state["probe"])
    assert "on the curve" in explorer.readout.value and "t = num/den = 0.5" in explorer.readout.value


def test_the_probe_at_the_double_point_reads_zero_over_zero():
    explorer = widgets.implicit_curve_explorer()
    state = explorer.update(px=1.0, py=0.0)
    assert state["singular"] and state["t"] is None and state["back"] is None
    assert "double point" in explorer.readout.value


def test_weights_change_the_implicit_equation_and_the_inversion():
    explorer = widgets.implicit_curve_explorer()
    state = explorer.update(w1=2.0, w2=0.5, px=3.0, py=1.0)
    expected = algebra.implicitize(state["points"], [1.0, 2.0, 0.5, 1.0])
    np.testing.assert_allclose(state["implicit"], expected)
    point = bezier.evaluate(state["points"], 0.3, state["weights"])
    state = explorer.update(px=round(float(point[0]), 1), py=round(float(point[1]), 1))
    assert state["relative_value"] > 1e-9 or state["t"] is not None
    with pytest.raises(ValueError, match="^points"):
        widgets.implicit_curve_explorer([(0.0, 0.0), (1.0, 1.0)])


def test_the_common_root_detector_counts_the_shared_roots():
    explorer = widgets.common_root_explorer()
    state = explorer.state  # f: 1, 2, 3; g: 1, 2, -1 -> two common roots
    assert state["rank"] == 1 and state["common_count"] == 2
    np.testing.assert_allclose(state["common_roots"], [1.0, 2.0], atol=1e-9)
    np.testing.assert_allclose(state["gcd"], [2.0, -3.0, 1.0], atol=1e-9)
    assert state["resultant"] == pytest.approx(0.0, abs=1e-9)
    state = explorer.update(g0=-2.0, g1=0.5)  # no common root
    assert state["rank"] == 3 and state["common_roots"].size == 0
    assert state["resultant"] == pytest.approx(state["root_product"], rel=1e-9)
    # The notes' sign: det(Bézout) = (-1)^(3·2/2) Res for two cubics.
    assert state["bezout_determinant"] == pytest.approx(-state["resultant"], rel=1e-9)
    assert "Sylvester" in explorer.readout.value


def test_the_intersection_explorer_reproduces_the_nine_rows():
    explorer = widgets.implicit_intersection_explorer()
    state = explorer.state
    assert len(state["hits"]) == 9 and len(state["polynomial"]) == 10
    np.testing.assert_allclose(state["hits"][:, 0], TABLE.results["t1_exact"], atol=1e-9)
    np.testing.assert_allclose(state["points"], TABLE.results["points"], atol=1e-4)
    np.testing.assert_allclose(state["u_roots"], np.sort(TABLE.results["t2_exact"]), atol=1e-9)
    moved = explorer.update(dy=-1.5)
    assert len(moved["hits"]) < 9
    assert "degree 9" in explorer.readout.value


def test_the_figures_draw_into_the_axes_given():
    ax = Figure().add_subplot()
    assert figures.plot_sign_regions(ax, LOOP.results["implicit"], (-1, 6), (-2, 5)) is ax
    assert figures.plot_extended_curve(ax, LOOP.inputs["points"]) is ax
    named = Figure().add_subplot()
    figures.plot_extended_curve(named, LOOP.inputs["points"], label="on [0, 1]", extension_label="beyond")
    labels = [line.get_label() for line in named.get_lines()]
    assert labels.count("beyond") == 1 and labels.count("on [0, 1]") == 1  # one legend entry for both dashed pieces
    assert figures.plot_intersection_polynomial(ax, TABLE.results["bernstein"], TABLE.results["t2_exact"]) is ax
    assert figures.plot_polynomials(ax, [[2.0, -3.0, 1.0], [-1.0, 1.0]], common=[1.0]) is ax
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_sign_regions(None, LOOP.results["implicit"], (-1, 6), (-2, 5))
    with pytest.raises(ValueError, match="^coeffs"):
        figures.plot_sign_regions(ax, [1.0, 2.0], (-1, 6), (-2, 5))


def test_the_close_up_of_the_intersection_polynomial_shows_the_two_close_roots():
    zoom = Figure().add_subplot()
    table = TABLE.results
    assert figures.plot_polynomial_window(zoom, table["bernstein"], (0.905, 0.955), table["t2_exact"]) is zoom
    assert zoom.get_xlim() == (0.905, 0.955) and len(zoom.lines[-1].get_xdata()) == 2  # the two close roots


def test_the_common_root_readout_names_both_conventions():
    explorer = widgets.common_root_explorer(g_roots=(-2.0, 0.5, -1.0))
    text = explorer.readout.value
    assert "Bézout's convention" in text and "Sylvester" in text

"""cagd_course.widgets.ch03: the basis-conversion and accuracy explorers, driven without a browser."""

import matplotlib

matplotlib.use("Agg")

from fractions import Fraction

import numpy as np
import numpy.polynomial.polynomial as npp
import pytest
from matplotlib.colors import to_hex
from matplotlib.figure import Figure

from cagd_course import widgets
from cagd_course.examples import notes_example
from cagd_course.widgets import ch03
from cagd_ref.bezier import de_casteljau
from cagd_ref.polynomials import bernstein_to_power, power_to_bernstein

# The notes' rational cubic, one homogeneous coordinate at a time: Bernstein column -> power column.
RATIONAL = notes_example("03.rational_cubic")
NOTES_COLUMNS = {
    name: (RATIONAL.results["bernstein"][:, k], RATIONAL.inputs["power"][:, k]) for k, name in enumerate("XYW")
}


def test_module_exports_what_the_tests_cover():
    assert set(ch03.__all__) == {
        "basis_conversion_explorer", "accuracy_explorer", "evenly_spaced_roots", "draw_difference_table",
        "draw_backward_fill", "difference_table_html", "power_text",
        "BasisConversionExplorer", "AccuracyExplorer",
    }
    assert set(ch03.__all__) <= set(widgets.__all__)


# ---------------------------------------------------------------- basis conversion


def test_basis_conversion_of_the_notes_columns():
    explorer = widgets.basis_conversion_explorer()
    for bernstein, power in NOTES_COLUMNS.values():
        state = explorer.update(**{f"b{i}": b for i, b in enumerate(bernstein)})
        np.testing.assert_allclose(state["power"], power, atol=1e-12)
        assert [row[0] for row in state["table"]] == pytest.approx(power / RATIONAL.results["binomials"])
        np.testing.assert_allclose(state["bernstein_values"], state["power_values"], atol=1e-12)
        np.testing.assert_allclose(state["power_values"], npp.polyval(state["t"], power), atol=1e-12)


def test_basis_conversion_default_is_the_notes_weights_and_sliders_move_it():
    explorer = widgets.basis_conversion_explorer()
    assert list(explorer.controls) == ["b0", "b1", "b2", "b3"]
    np.testing.assert_allclose(explorer.state["power"], NOTES_COLUMNS["W"][1])
    assert explorer.state["text"] == "1 + 6t − 12t² + 7t³"
    x_bernstein, x_power = NOTES_COLUMNS["X"]
    state = explorer.update(**{f"b{i}": b for i, b in enumerate(x_bernstein)})
    np.testing.assert_allclose(state["power"], x_power)
    # The drawn curve is the explicit Bézier curve with control points (i/3, b_i).
    control = np.column_stack([np.arange(4) / 3, state["bernstein"]])
    np.testing.assert_allclose(np.column_stack([state["t"], state["bernstein_values"]]),
                               de_casteljau(control, state["t"]), atol=1e-12)
    assert "24t" in explorer.readout.value


def test_basis_conversion_table_is_shown_in_the_readout():
    explorer = widgets.basis_conversion_explorer()
    assert len(explorer.figure.axes) == 1 and explorer.ax.get_legend() is None
    readout = explorer.readout.value
    # The notes' weights: top row 1, 3, 1, 2; left column 1, 2, -4, 3; power 1, 6, -12, 7.
    for entry in (">7<", ">-4<", ">-12<", "← ×3", "Δ³"):
        assert entry in readout
    explorer.update(b3=-2.5)
    assert ">-2.5<" in explorer.readout.value


def test_difference_table_html_matches_the_drawn_table():
    html_table = widgets.difference_table_html([0.0, 1.0, 4.0])
    assert html_table.count("<tr>") == 4  # header and three rows
    assert ">4<" in html_table and "← ×2" in html_table and "Δ²" in html_table


@pytest.mark.parametrize("bad, error", [
    ([1.0], ValueError),                       # degree 0: nothing to convert
    (np.ones(8), ValueError),                  # beyond the sliders' degree 6
    ([[1.0, 2.0], [3.0, 4.0]], ValueError),    # one polynomial only
    ([0.0, 16.0], ValueError),                 # outside the sliders' range
    ("abc", TypeError),
])
def test_basis_conversion_rejects_bad_coefficients(bad, error):
    with pytest.raises(error, match="^coeffs"):
        widgets.basis_conversion_explorer(bad)


def test_basis_conversion_leaves_the_callers_array_alone_and_rejects_bad_slider_values():
    coeffs = np.array([1.0, -2.0, 3.0])
    explorer = widgets.basis_conversion_explorer(coeffs)
    explorer.update(b0=5.0)
    assert coeffs.tolist() == [1.0, -2.0, 3.0]
    with pytest.raises(ValueError, match="b1"):
        explorer.update(b1=20.0)
    with pytest.raises(TypeError, match="b5"):
        explorer.update(b5=1.0)
    assert explorer.values["b1"] == -2.0


# ---------------------------------------------------------------- helpers


@pytest.mark.parametrize("coeffs, text", [
    ([1, 6, -12, 7], "1 + 6t − 12t² + 7t³"),
    ([0, -1, 0, 0, 2.5], "−t + 2.5t⁴"),
    ([-3, 1, 1], "−3 + t + t²"),
    ([0.0, 0.0], "0"),
    ([1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4], "1 + 4t¹¹"),
])
def test_power_text(coeffs, text):
    assert widgets.power_text(coeffs) == text
    assert widgets.power_text(coeffs, "u") == text.replace("t", "u")


def test_power_text_rejects_columns():
    with pytest.raises(ValueError, match="coeffs"):
        widgets.power_text([[1, 2], [3, 4]])


def test_draw_difference_table_of_homogeneous_rows():
    figure = Figure(figsize=(9, 3))
    ax = figure.add_subplot()
    rows = RATIONAL.results["bernstein"].astype(int)
    assert widgets.draw_difference_table(ax, rows) is ax
    texts = [t.get_text() for t in ax.texts]
    # The notes' left column a_j / C(3, j) and the power coefficients a_j beside it, as (X, Y, W) triples.
    for row in [*RATIONAL.results["left_column"], *RATIONAL.inputs["power"]]:
        assert "(" + ",".join(str(int(v)) for v in row) + ")" in texts
    assert not ax.axison
    bare = Figure().add_subplot()
    widgets.draw_difference_table(bare, [2.0, 5.0], power=False, fontsize=9)
    assert sorted(t.get_text() for t in bare.texts) == sorted(["2", "5", "3", "Δ⁰", "Δ¹", "$b_i$ (Bernstein)"])
    assert {t.get_fontsize() for t in bare.texts} <= {9, 10}


def test_draw_backward_fill_fills_one_column_per_step():
    # The weights of the notes' example: left column a_j / C(3, j) = 1, 2, -4, 7; top row 1, 3, 1, 2.
    left = [1.0, 2.0, -4.0, 7.0]
    for step, filled in [(0, ["1", "2", "-4", "7"]), (1, ["3", "-2", "3"]), (3, ["1", "3", "1", "2"])]:
        ax = Figure().add_subplot()
        assert widgets.draw_backward_fill(ax, left, step) is ax
        texts = [t.get_text() for t in ax.texts]
        for entry in filled:
            assert entry in texts
        assert texts.count(" · ") == sum(max(0, 4 - i) for i in range(step + 1, 4))  # the empty slots
        arrows = [a for a in ax.texts if getattr(a, "arrow_patch", None) is not None]
        assert len(arrows) == (0 if step == 0 else 2 * (4 - step))
        assert not ax.axison
        # Orange marks the newest column only: the given left column is neutral (its top entry blue).
        faces = {
            t.get_position(): to_hex(t.get_bbox_patch().get_facecolor())
            for t in ax.texts if t.get_bbox_patch() is not None and t.get_text() != " · "
        }
        assert faces[(0, 0)] == ch03.GIVEN_CORNER_STYLE["facecolor"]
        assert all(faces[(0, -j)] == ch03.GIVEN_STYLE["facecolor"] for j in (1, 2, 3))
        fresh = {face for (x, _), face in faces.items() if x == step and step > 0}
        assert fresh <= {ch03.FRESH_STYLE["facecolor"]}
        assert ch03.FRESH_STYLE["facecolor"] not in {faces[(0, -j)] for j in range(4)}
    with pytest.raises(ValueError, match="step"):
        widgets.draw_backward_fill(Figure().add_subplot(), left, 4)
    with pytest.raises(ValueError, match="left_column"):
        widgets.draw_backward_fill(Figure().add_subplot(), [[1.0, 2.0]], 0)


# ---------------------------------------------------------------- accuracy of the two bases


def test_evenly_spaced_roots_are_exact():
    data = ch03.evenly_spaced_roots(3, samples=8)
    # (t - 1/4)(t - 1/2)(t - 3/4) = -3/32 + 11/16 t - 3/2 t² + t³
    np.testing.assert_array_equal(data["power"], [-3 / 32, 11 / 16, -3 / 2, 1])
    np.testing.assert_allclose(data["bernstein"], power_to_bernstein(data["power"]), atol=1e-15)
    np.testing.assert_allclose(bernstein_to_power(data["bernstein"]), data["power"], atol=1e-15)
    np.testing.assert_array_equal(data["t"], np.arange(1, 8) / 8)
    roots = [Fraction(1, 4), Fraction(1, 2), Fraction(3, 4)]
    expected = [float(np.prod([Fraction(j, 8) - r for r in roots])) for j in range(1, 8)]
    np.testing.assert_array_equal(data["exact"], expected)
    assert data["exact"][1] == data["exact"][3] == data["exact"][5] == 0.0  # the roots themselves
    with pytest.raises(ValueError, match="count"):
        ch03.evenly_spaced_roots(0)


def test_accuracy_explorer_shows_the_bernstein_form_far_ahead():
    explorer = widgets.accuracy_explorer()
    assert list(explorer.controls) == ["roots"] and explorer.values["roots"] == 12
    previous_ratio = 0.0
    for roots in (4, 12, 20):
        state = explorer.update(roots=roots)
        assert len(state["power"]) == roots + 1 and state["t"].shape == state["power_error"].shape
        u = 2.0**-53
        # Each error stays under its bound: (2n+1) u resp. (3n+2) u times the condition number (to first order).
        assert np.all(state["power_error"] <= (2 * roots + 2) * u * state["power_condition"])
        assert np.all(state["bernstein_error"] <= (3 * roots + 3) * u * state["bernstein_condition"])
        assert np.all(state["bernstein_condition"] <= state["power_condition"] * (1 + 1e-12))  # Farouki–Rajan
        ratio = state["power_error"].max() / state["bernstein_error"].max()
        assert ratio > previous_ratio
        previous_ratio = ratio
    assert previous_ratio > 1e6
    assert "ratio" in explorer.readout.value and explorer.ax.get_legend() is None


def test_accuracy_explorer_range_and_bad_values():
    with pytest.raises(ValueError, match="roots"):
        widgets.accuracy_explorer(roots=1)
    with pytest.raises(TypeError, match="roots"):
        widgets.accuracy_explorer(roots=2.5)
    explorer = widgets.accuracy_explorer(roots=5)
    with pytest.raises(ValueError, match="roots"):
        explorer.update(roots=21)
    assert explorer.values["roots"] == 5

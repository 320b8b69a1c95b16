"""cagd_course.widgets, chapter 19: the double-point classifier, the pencil parametrization and the silhouette."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from numpy.polynomial import polynomial as P  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import singular_points as figures  # noqa: E402
from cagd_course.widgets.ch19 import CURVES, SILHOUETTES  # noqa: E402
from cagd_ref import algebra  # noqa: E402


@pytest.mark.parametrize("k, kind, lines", [(3.0, "crunode", 2), (0.0, "cusp", 1), (-3.0, "acnode", 0)])
def test_the_classifier_passes_through_the_three_kinds(k, kind, lines):
    state = widgets.double_point_kind_explorer().update(k=k)
    assert state["kind"] == kind and len(state["directions"]) == lines
    assert np.sign(state["discriminant"]) == np.sign(k)


def test_the_classifier_reproduces_figures_19_3_and_19_4():
    explorer = widgets.double_point_kind_explorer()
    for k, name in ((0.0, "19.cusp"), (-3.0, "19.acnode")):
        state = explorer.update(k=k)
        example = notes_example(name)
        assert np.allclose(state["c"], example.inputs["c"])
        assert state["kind"] == example.results["kind"]


@pytest.mark.parametrize("curve", list(CURVES))
def test_every_pencil_point_lies_on_the_curve_and_the_line(curve):
    explorer = widgets.pencil_parametrization_explorer(curve)
    for t in (-2.5, -0.4, 0.3, 1.7):
        state = explorer.update(t=t)
        if state["xy"] is None:
            continue
        assert abs(state["residual"]) < 1e-10
        x0, y0 = state["point"]
        assert state["xy"][1] - y0 == pytest.approx(t * (state["xy"][0] - x0), abs=1e-9)


def test_the_pencil_explorer_starts_on_figure_19_6():
    example = notes_example("19.circle_pencil")
    explorer = widgets.pencil_parametrization_explorer()
    for t, point in zip(example.inputs["t"], example.results["points"]):
        assert np.allclose(explorer.update(t=float(t))["xy"], point)
    assert np.allclose(explorer.state["xyw"], example.results["pencil"])


def test_the_silhouette_roots_are_vertical_tangents_and_the_double_point():
    explorer = widgets.silhouette_explorer()
    state = explorer.state
    example = notes_example("19.silhouette")
    assert np.allclose(state["discriminant"], example.results["discriminant"])
    assert np.allclose(state["roots"], sorted([2.0, 2.0, *example.results["vertical_tangents"]]), atol=1e-6)
    turned = explorer.update(angle=40.0)
    assert len(turned["roots"]) >= 2
    for x in turned["roots"]:
        column = P.polyval(x, turned["c"])  # f(x, y) as a polynomial in y has a double root there
        assert len(algebra.poly_gcd(column, P.polyder(column), tol=1e-5)) >= 2
    assert len(explorer.figure.axes) == 2
    assert set(SILHOUETTES) == set(explorer.controls["curve"].options)


def test_figures_check_their_axes_and_break_at_poles():
    ax = Figure().add_subplot()
    figures.plot_parametrization(ax, notes_example("19.cubic_pencil").results["pencil"], (-3, 3))
    xs = ax.lines[0].get_xdata()
    assert np.isnan(xs).any()  # W(t) = 1 + 2t + 3t² + 4t³ changes sign once
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_curve(None, [[0, 1], [1, 0]], (0, 1), (0, 1))
    with pytest.raises(ValueError, match="^c"):
        figures.plot_curve(ax, [1.0, 2.0], (0, 1), (0, 1))

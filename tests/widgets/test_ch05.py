"""Explorers of chapter 5 (cagd_course.widgets.ch05), driven without a browser through `update` and their controls."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from cagd_course import widgets
from cagd_course.widgets import ch05
from cagd_ref.bezier import de_casteljau
from cagd_ref.blending import FORMS, blend, to_bezier
from cagd_ref.blending_properties import line_crossings

POLYGON = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [4.0, 0.5]])
FLAT = np.array([[0.0, 0.0], [1.5, 0.0], [3.0, 0.0], [4.0, 3.0]])  # three points on the x-axis, one high above



def test_the_chapter_module_exports_its_factories():
    assert set(ch05.__all__) == {
        "blending_forms_explorer", "variation_diminishing_explorer",
        "BlendingFormsExplorer", "VariationDiminishingExplorer",
    }
    assert all(getattr(widgets, name) is getattr(ch05, name) for name in ch05.__all__)


# ---------------------------------------------------------------- four forms on one polygon


def test_forms_explorer_draws_each_form_from_the_shared_points():
    explorer = widgets.blending_forms_explorer(POLYGON, draggable=False)
    state = explorer.update(x2=3.5, y2=2.0)
    points = POLYGON.copy()
    points[2] = [3.5, 2.0]
    np.testing.assert_array_equal(state["points"], points)
    ts = np.linspace(0, 1, len(state["curves"]["bezier"]))
    for form, basis in FORMS.items():
        np.testing.assert_allclose(state["curves"][form], blend(basis, points, ts), atol=1e-12)
        # The readout's Bézier points trace the same curve with de Casteljau.
        np.testing.assert_allclose(state["bezier_points"][form], to_bezier(form, points))
        np.testing.assert_allclose(de_casteljau(state["bezier_points"][form], ts), state["curves"][form], atol=1e-12)


def test_forms_explorer_midpoints_tell_the_forms_apart():
    state = widgets.blending_forms_explorer(POLYGON, draggable=False).state
    p0, p1, p2, p3 = POLYGON
    middle = state["midpoints"]
    np.testing.assert_allclose(middle["bezier"], (p0 + 3 * p1 + 3 * p2 + p3) / 8)
    np.testing.assert_allclose(middle["timmer"], (p1 + p2) / 2)  # Timmer goes through the middle of P1 P2
    np.testing.assert_allclose(middle["ball"], POLYGON.mean(axis=0))  # Ball: all four weights are 1/4
    np.testing.assert_allclose(middle["overhauser"], (-p0 + 9 * p1 + 9 * p2 - p3) / 16)
    assert "Timmer" in widgets.blending_forms_explorer(POLYGON, draggable=False).readout.value


def test_forms_explorer_reports_which_curves_leave_the_hull():
    escape = widgets.blending_forms_explorer(POLYGON, draggable=False).state["hull_escape"]
    assert escape["bezier"] == pytest.approx(0.0, abs=1e-12) and escape["ball"] == pytest.approx(0.0, abs=1e-12)
    assert escape["overhauser"] > 0.1  # the Catmull-Rom segment bulges over the leg P1 P2


def test_forms_explorer_points_can_be_dragged():
    explorer = widgets.blending_forms_explorer(POLYGON, draggable=False)
    state = explorer.move_point(3, 4.0, 2.0)
    assert state["points"][3].tolist() == [4.0, 2.0]
    np.testing.assert_allclose(state["curves"]["timmer"][-1], [4.0, 2.0])


def test_forms_explorer_needs_four_planar_points():
    with pytest.raises(ValueError, match="points"):
        widgets.blending_forms_explorer(POLYGON[:3])
    with pytest.raises(ValueError, match="points"):
        widgets.blending_forms_explorer(np.zeros((4, 3)))


# ---------------------------------------------------------------- variation diminishing


def test_line_passes_through_the_centroid_and_moves_with_the_offset():
    explorer = widgets.variation_diminishing_explorer(POLYGON)
    centre = POLYGON.mean(axis=0)
    a, b, c = explorer.update(angle=35.0, offset=0.0)["line"]
    assert a * centre[0] + b * centre[1] + c == pytest.approx(0.0, abs=1e-12)
    assert np.arctan2(-a, b) == pytest.approx(np.radians(35.0))  # direction (b, -a) at 35°
    a, b, c = explorer.update(offset=0.7)["line"]
    assert a * centre[0] + b * centre[1] + c == pytest.approx(-0.7)


def test_counts_are_the_crossings_of_polygon_and_curve():
    explorer = widgets.variation_diminishing_explorer()
    state = explorer.update(angle=0.0, offset=0.0, form="bezier")
    assert (state["p"], state["c"]) == (3, 3) and state["holds"]
    state = explorer.update(offset=-0.8)
    assert (state["p"], state["c"]) == (3, 1)  # c = p - 2j with j = 1
    np.testing.assert_allclose(state["polygon_crossings"], line_crossings(explorer.points, state["line"]))
    assert len(state["curve_crossings"]) == state["c"]
    assert "3 times" in explorer.readout.value


def test_timmer_and_overhauser_cross_a_line_the_flat_polygon_misses():
    explorer = widgets.variation_diminishing_explorer(FLAT)
    for form in ("timmer", "overhauser"):
        state = explorer.update(angle=0.0, offset=-0.8, form=form)  # the line y = -0.05
        assert (state["p"], state["c"], state["holds"]) == (0, 2, False)
        assert "c &gt; p" in explorer.readout.value
    for form in ("bezier", "ball"):
        assert explorer.update(form=form)["c"] == 0


@pytest.mark.parametrize("form", ["bezier", "ball"])
def test_bezier_and_ball_never_cross_more_than_the_polygon(form):
    explorer = widgets.variation_diminishing_explorer()
    for angle in np.arange(0.0, 180.0, 15.0):
        for offset in np.linspace(-2.5, 2.5, 11):
            state = explorer.compute(angle=angle, offset=offset, form=form)
            assert state["c"] <= state["p"]
            assert (state["p"] - state["c"]) % 2 == 0  # both curves start at P0 and end at P3


def test_bad_form_and_points_are_rejected():
    with pytest.raises(ValueError, match="form"):
        widgets.variation_diminishing_explorer(form="hermite")
    with pytest.raises(ValueError, match="points"):
        widgets.variation_diminishing_explorer(np.zeros((5, 2)))
    explorer = widgets.variation_diminishing_explorer()
    with pytest.raises(TypeError, match="form"):
        explorer.update(form="hermite")
    assert explorer.values["form"] == "bezier"
    with pytest.raises(ValueError, match="angle"):
        explorer.update(angle=270.0)


def test_points_given_to_the_factories_are_not_modified():
    points = POLYGON.copy()
    widgets.blending_forms_explorer(points, draggable=False).update(x0=1.0)
    widgets.variation_diminishing_explorer(points).update(offset=1.0)
    np.testing.assert_array_equal(points, POLYGON)


def test_the_line_can_start_at_an_offset():
    explorer = widgets.variation_diminishing_explorer(FLAT, form="timmer", offset=-0.8)
    state = explorer.state
    np.testing.assert_allclose(state["line"], [0.0, 1.0, 0.05])  # y = -0.05 below the three collinear points
    assert (state["p"], state["c"], state["holds"]) == (0, 2, False)
    with pytest.raises(ValueError, match="offset"):
        widgets.variation_diminishing_explorer(FLAT, offset=100.0)
    with pytest.raises(ValueError, match="offset"):
        widgets.variation_diminishing_explorer(FLAT, offset="low")

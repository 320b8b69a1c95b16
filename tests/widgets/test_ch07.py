"""cagd_course.widgets, chapter 7: the intersection explorers driven through `update` and their controls."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_ref.intersection import clip_range, intersect_curves  # noqa: E402
from cagd_ref.polynomials import bernstein_horner  # noqa: E402

# ---------------------------------------------------------------- Bézout


@pytest.mark.parametrize("other, offset, radius, real, complex_, infinite", [
    ("line", 0.5, 1.0, 2, 0, 0),
    ("line", 2.0, 1.0, 0, 2, 0),  # the line misses the circle: a complex pair
    ("circle", 1.2, 0.8, 2, 0, 2),
    ("circle", 2.5, 0.5, 0, 2, 2),  # disjoint circles still meet four times
    ("circle", 0.0, 0.5, 0, 0, 4),  # concentric: only at the circular points, twice each
])
def test_bezout_always_counts_every_intersection(other, offset, radius, real, complex_, infinite):
    state = widgets.bezout_explorer().update(other=other, offset=offset, radius=radius)
    assert len(state["real"]) == real and len(state["at_infinity"]) == infinite
    assert len(state["finite"]) - real == complex_
    assert len(state["finite"]) + len(state["at_infinity"]) == state["count"] == (2 if other == "line" else 4)
    for x, y in state["real"]:
        assert x * x + y * y == pytest.approx(1)


def test_the_same_circle_twice_has_infinitely_many_common_points_not_four_at_infinity():
    explorer = widgets.bezout_explorer()
    state = explorer.update(other="circle", offset=0.0, radius=1.0)
    assert state["common_component"] and state["count"] == np.inf
    assert state["finite"] == [] and state["at_infinity"] == [] and len(state["real"]) == 0
    assert "infinitely many" in explorer.ax.get_title() and "same curve" in explorer.describe(state)
    # Concentric but different circles still meet exactly four times, at the circular points.
    state = explorer.update(radius=0.5)
    assert not state["common_component"] and state["count"] == 4 and len(state["at_infinity"]) == 4


def test_a_tangent_line_meets_the_circle_in_a_double_point():
    state = widgets.bezout_explorer().update(other="line", offset=1.0)
    np.testing.assert_allclose(state["real"], [[0.0, 1.0], [0.0, 1.0]], atol=1e-7)


# ---------------------------------------------------------------- the clip lab


def _cut_by_the_polygon(state):
    """The lost samples really lie in the band, and outside the polygon's range."""
    lost = state["lost"]
    curve = bernstein_horner(state["values"], lost)
    assert np.all((curve >= state["dmin"]) & (curve <= state["dmax"]))
    assert np.all((lost < state["polygon"][0]) | (lost > state["polygon"][1]))
    return lost


def test_clip_lab_starts_on_the_notes_first_clip_where_the_polygon_is_already_unsafe():
    state = widgets.clip_lab_explorer().state
    assert state["hull"] == tuple(notes_example("07.first_clip").results["clip"])
    assert state["v_rule"] == pytest.approx(state["hull"])
    # The polygon's edge E1 E2 reaches d = 1 at t = 5/9, but the curve stays in the band until t ≈ 0.61.
    assert state["polygon"] == pytest.approx((0.25, 5 / 9))
    lost = _cut_by_the_polygon(state)
    assert lost.min() > 5 / 9 and 0.6 < lost.max() < state["hull"][1]


def test_clip_lab_shows_the_polygon_is_unsafe_on_both_sides():
    state = widgets.clip_lab_explorer().update(d0=-5.0, d1=-6.0, d2=3.0, d3=3.0, dmin=-2.0, dmax=1.0)
    assert state["hull"] == pytest.approx((0.25, 23 / 27))
    assert state["polygon"] == pytest.approx((13 / 27, 16 / 27))
    lost = _cut_by_the_polygon(state)
    assert lost.min() < 13 / 27 and lost.max() > 16 / 27


def test_clip_lab_shows_the_v_rule_stopping_short_of_the_hull():
    values = notes_example("07.v_rule_gap").inputs["values"]
    lab = widgets.clip_lab_explorer(values, dmin=0.0, dmax=5.0)
    assert lab.state["v_rule"][0] == pytest.approx(2 / 7)
    assert lab.state["hull"][0] == pytest.approx(0.4)
    assert lab.state["hull"] == clip_range(values, 0.0, 5.0)


def test_clip_lab_degree_and_bad_band():
    lab = widgets.clip_lab_explorer()
    assert len(lab.update(degree=5)["values"]) == 6
    with pytest.raises(ValueError, match="dmin"):
        lab.update(dmin=2.0, dmax=1.0)
    assert lab.values["dmin"] == -2.0  # rolled back


# ---------------------------------------------------------------- the clipping stepper


def test_stepper_reproduces_the_notes_first_two_clips():
    stepper = widgets.clipping_explorer()
    first = stepper.update(step=0)
    assert first["clipped"] == "P" and first["before"] == (0.0, 1.0)
    np.testing.assert_allclose(first["event"].values, notes_example("07.first_clip").inputs["distances"], atol=1e-12)
    np.testing.assert_allclose(first["after"], (0.25, 0.75), atol=1e-9)
    second = stepper.update(step=1)
    assert second["clipped"] == "Q"
    np.testing.assert_allclose(second["after"], notes_example("07.iterating").results["second_clip"], atol=0.005)


def test_stepper_runs_to_the_intersections_and_through_a_split():
    stepper = widgets.clipping_explorer("two intersections, a split (Fig. 7.9)")
    last = stepper.update(step=stepper.controls["step"].max)
    example = notes_example("07.two_intersections")
    np.testing.assert_allclose(last["intersections"], np.column_stack([example.results["t"], example.results["u"]]),
                               atol=1e-9)
    assert any(event.kind == "split" for event in last["history"])
    assert len(last["found"]) == 2


def test_stepper_fits_the_slider_to_each_search_and_shows_rational_clips():
    stepper = widgets.clipping_explorer()
    stepper.update(preset="five intersections")
    steps = stepper.controls["step"].max
    assert steps > 20
    with pytest.raises(ValueError, match="step"):
        stepper.update(preset="one intersection (Fig. 7.5)", step=steps)
    state = stepper.update(preset="rational: quarter circle and cubic", step=0, perpendicular=True)
    assert np.shape(state["event"].values) == (2, 3) and state["event"].perpendicular is not None
    pair = notes_example("07.rational_clip")
    last = stepper.update(step=stepper.controls["step"].max)
    np.testing.assert_allclose(last["intersections"], [pair.results["intersection"]], atol=1e-9)


# ---------------------------------------------------------------- comparing the algorithms


def test_comparison_counts_every_examined_pair_and_clipping_needs_fewest():
    explorer = widgets.subdivision_comparison_explorer()
    state = explorer.update(depth=0)
    for method, steps in state["steps"].items():
        assert state["counts"][method].sum() == state["totals"][method] == len(steps)
        assert state["counts"][method][0] >= 1
    assert state["totals"]["clipping"] * 10 < state["totals"]["subdivision"] < state["totals"]["intervals"]
    example = notes_example("07.five_intersections")
    np.testing.assert_allclose(state["found"], intersect_curves(*example.args("p", "q")))
    one = explorer.update(preset="one intersection (Fig. 7.5)")
    assert len(one["found"]) == 1 and one["totals"]["clipping"] < state["totals"]["clipping"]

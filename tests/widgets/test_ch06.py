"""cagd_course.widgets, chapter 6: the B-spline explorers driven through `update` and their sliders, no browser."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from cagd_course import widgets
from cagd_course.plotting.bsplines import polar_label
from cagd_ref.bspline import bezier_end_knots, continuity_at_knots, de_boor, insert_knot
from cagd_ref.knot_intervals import split_interval

POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [5.0, 1.0], [7.0, 1.0], [8.0, 3.0], [10.0, 3.5]])
KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 4.0, 4.0, 4.0])  # cubic, 7 points, non-uniform, Bézier ends


# ---------------------------------------------------------------- knot vector editor


def test_knot_vector_editor_builds_the_knots_from_the_sliders():
    editor = widgets.knot_vector_editor(POINTS)
    assert list(editor.controls) == ["u1", "u2", "u3", "multiplicity", "spacing"]
    state = editor.update(u1=2.0, u2=0.5, u3=3.5)
    assert state["knots"].tolist() == [0, 0, 0, 0.5, 2.0, 3.5, 4, 4, 4]  # sorted, n-fold ends at 0 and c - n
    assert not state["uniform"]
    assert len(state["segments"]) == 4
    assert np.allclose(state["basis"].sum(axis=1), 1.0)
    assert editor.update(spacing="uniform")["knots"].tolist() == [0, 0, 0, 1, 2, 3, 4, 4, 4]
    assert editor.state["uniform"]


@pytest.mark.parametrize("multiplicity, order", [(1, 2), (2, 1), (3, 0)])
def test_multiplicity_lowers_the_continuity_at_u2(multiplicity, order):
    editor = widgets.knot_vector_editor(POINTS)
    state = editor.update(u1=1.0, u2=2.0, u3=3.0, multiplicity=multiplicity, spacing="sliders")
    assert np.count_nonzero(state["knots"] == 2.0) == multiplicity
    joints, orders = continuity_at_knots(state["knots"], 3)
    assert orders[joints == 2.0][0] == order
    assert np.array_equal(state["continuity"], orders)
    if multiplicity == 3:
        # A triple knot in a cubic: the curve passes through the control point labelled P(2, 2, 2).
        assert np.any(np.all(np.isclose(POINTS, de_boor(POINTS, state["knots"], 2.0)), axis=1))


def test_knot_vector_editor_rejects_a_knot_beyond_the_degree():
    editor = widgets.knot_vector_editor()  # eight points: four interior knots u1..u4
    with pytest.raises(ValueError, match="knot"):
        editor.update(u1=2.0, u2=2.0, multiplicity=3)
    assert editor.values["multiplicity"] == 1  # the rejected update is rolled back


# ---------------------------------------------------------------- de Boor


@pytest.mark.parametrize("t", [0.0, 0.4, 1.0, 2.7, 4.0])
def test_de_boor_explorer_point_is_de_boor(t):
    explorer = widgets.de_boor_explorer(POINTS, KNOTS)
    state = explorer.update(t=t)
    assert np.allclose(state["point"], de_boor(POINTS, KNOTS, t))
    assert [len(level) for level in state["levels"]] == [4, 3, 2, 1]
    assert state["labels"][-1] == [polar_label([t] * 3)]
    assert KNOTS[state["span"]] <= t <= KNOTS[state["span"] + 1]


def test_de_boor_levels_carry_their_polar_labels():
    state = widgets.de_boor_explorer(POINTS, KNOTS).update(t=2.0)  # span [1, 2.5]
    assert state["labels"][0] == ["P(0,0,1)", "P(0,1,2.5)", "P(1,2.5,3)", "P(2.5,3,4)"]
    assert state["labels"][1] == ["P(0,1,2)", "P(1,2,2.5)", "P(2,2.5,3)"]
    assert np.allclose(state["levels"][0], POINTS[1:5])


def test_de_boor_step_shows_levels_one_by_one():
    explorer = widgets.de_boor_explorer(POINTS, KNOTS)
    lines = []
    for step in range(4):
        explorer.update(step=step)
        lines.append(len(explorer.ax.lines))
    assert lines[0] < lines[1] < lines[2] < lines[3]


# ---------------------------------------------------------------- knot insertion


@pytest.mark.parametrize("times", [1, 2, 3])
def test_knot_insertion_keeps_the_curve(times):
    explorer = widgets.knot_insertion_explorer(POINTS, KNOTS)
    state = explorer.update(t=1.7, times=times)
    assert state["deviation"] < 1e-12
    assert np.count_nonzero(state["knots"] == 1.7) == times
    assert len(state["points"]) == len(POINTS) + times
    assert len(state["new"]) == 3 + times - 1  # labels that contain the new knot
    expected_points, expected_knots = POINTS, KNOTS
    for _ in range(times):
        expected_points, expected_knots = insert_knot(expected_points, expected_knots, 1.7)
    assert np.allclose(state["points"], expected_points) and np.array_equal(state["knots"], expected_knots)
    assert (state["point"] is None) == (times < 3)


def test_knot_insertion_draws_the_old_and_the_new_polygon_apart():
    # The old polygon grey and dashed, the new one solid: a reader tells them apart at a glance.
    explorer = widgets.knot_insertion_explorer(POINTS, KNOTS)
    explorer.update(t=1.7, times=1)
    lines = {line.get_label(): line for line in explorer.ax.get_lines()}
    old, new = lines["old polygon"], lines["new polygon"]
    assert old.get_linestyle() == "--" and new.get_linestyle() == "-"
    assert old.get_color() != new.get_color()
    assert len(new.get_xdata()) == len(POINTS) + 1


def test_inserting_a_full_multiplicity_exposes_the_curve_point():
    explorer = widgets.knot_insertion_explorer(POINTS, KNOTS)
    state = explorer.update(t=2.2, times=3)
    assert np.allclose(state["point"], de_boor(POINTS, KNOTS, 2.2))
    # t = 1 is already a knot: two more copies reach multiplicity 3.
    state = explorer.update(t=1.0, times=3)
    assert state["inserted"] == 2
    assert np.allclose(state["point"], de_boor(POINTS, KNOTS, 1.0))
    assert "only 2" in explorer.readout.value


# ---------------------------------------------------------------- knot intervals


@pytest.mark.parametrize("index, fraction", [(0, 1 / 3), (0, 0.5), (2, 0.25), (4, 0.0), (3, 1.0)])
def test_splitting_an_interval_matches_the_construction_and_keeps_the_curve(index, fraction):
    explorer = widgets.knot_interval_explorer()
    state = explorer.update(index=index, fraction=fraction)
    d = explorer.intervals
    assert state["deviation"] < 1e-12
    assert np.isclose(state["intervals"].sum(), d.sum())
    assert np.allclose(state["intervals"][index : index + 2], [fraction * d[index], (1 - fraction) * d[index]])
    points, _ = split_interval(explorer.points, d, index, fraction, degree=3)
    assert np.allclose(state["points"], points)
    # The ruler construction gives exactly the three new points.
    new = np.array([p for p in state["points"] if not np.any(np.all(np.isclose(p, explorer.points), axis=1))])
    assert all(np.any(np.all(np.isclose(c, state["points"]), axis=1)) for c in state["construction"])
    assert len(new) <= 3


def test_construction_cuts_edges_in_proportion_to_the_neighbouring_intervals():
    square = np.array([[0.0, 0.0], [6.0, 0.0], [6.0, 6.0], [0.0, 6.0]])
    parts, new = widgets.splitting_construction(square, [1.0, 4.0, 1.0, 2.0], 1, 0.5)
    # Edge P1P2 (interval d1 = 4, neighbours d0 = 1, d2 = 1): its d1 part is the middle 4/6.
    assert np.allclose(parts[1], [[6, 1], [6, 5]])
    assert np.allclose(new[1], [6, 3])


# ---------------------------------------------------------------- local control


def test_moving_an_interior_point_changes_n_plus_one_segments():
    explorer = widgets.local_control_explorer()  # cubic, 8 points, 5 segments
    state = explorer.update(index=4, dx=0.5, dy=-1.0)
    assert state["changed"].tolist() == [1, 2, 3, 4]
    a, b = state["support"]
    assert (a, b) == (1.0, 5.0)
    assert np.all(explorer.intervals[state["changed"], 0] >= a) and np.all(explorer.intervals[state["changed"], 1] <= b)


@pytest.mark.parametrize("index, changed", [(0, [0]), (1, [0, 1]), (3, [0, 1, 2, 3]), (7, [4])])
def test_local_control_near_the_ends(index, changed):
    explorer = widgets.local_control_explorer()
    assert explorer.update(index=index, dx=1.0, dy=0.0)["changed"].tolist() == changed


def test_no_move_changes_nothing():
    explorer = widgets.local_control_explorer(POINTS, KNOTS)
    assert explorer.update(dx=0.0, dy=0.0)["changed"].tolist() == []
    assert "none" in explorer.readout.value


def test_explorers_accept_other_knot_vectors():
    knots = bezier_end_knots(len(POINTS), 2, end=3.0)
    explorer = widgets.local_control_explorer(POINTS, knots)
    state = explorer.update(index=3, dy=1.0)
    assert len(state["changed"]) == 3  # quadratic: n + 1 = 3 segments
    assert np.allclose(widgets.de_boor_explorer(POINTS, knots).update(t=1.3)["point"], de_boor(POINTS, knots, 1.3))

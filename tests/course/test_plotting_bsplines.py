"""cagd_course.plotting.bsplines: polar labels, segment samples, knot-interval label places (Notes §6.1-6.3, §6.13)."""

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.plotting import bsplines
from cagd_ref.bspline import de_boor

POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [5.0, 1.0], [7.0, 1.0], [8.0, 3.0], [10.0, 3.5]])
KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 4.0, 4.0, 4.0])  # cubic, 7 points, non-uniform, Bézier ends


def test_control_point_labels_follow_the_notes_convention():
    # Figure 6.6.b: the knots [0, 0, 0, 1, 3, 4, 4, 4] label the points P(0,0,0), P(0,0,1), ..., P(4,4,4).
    figure = notes_example("06.bezier_end_conditions")
    labels = ["P(" + ",".join(str(int(k)) for k in row) + ")" for row in figure.results["labels"]]
    assert bsplines.control_point_labels(*figure.args("knots", "degree")) == labels
    assert labels[2] == "P(0,1,3)"
    assert bsplines.polar_label([2.5, 1 / 3], "f") == "f(2.5,0.333)"


def test_segment_samples_lie_on_the_curve_span_by_span():
    intervals, samples = bsplines.segment_samples(POINTS, KNOTS, per_segment=5)
    assert intervals.tolist() == [[0, 1], [1, 2.5], [2.5, 3], [3, 4]]
    assert samples.shape == (4, 5, 2)
    ts = np.linspace(intervals[:, 0], intervals[:, 1], 5).T
    assert np.allclose(samples, de_boor(POINTS, KNOTS, ts.ravel()).reshape(4, 5, 2))


def test_interval_labels_hang_one_phantom_past_each_end_of_an_open_cubic():
    places = bsplines.interval_label_positions(POINTS, np.diff(KNOTS))
    assert places.shape == (8, 2)  # 6 edges + 2 phantom edges
    assert np.allclose(places[1:-1], (POINTS[:-1] + POINTS[1:]) / 2)
    assert np.allclose(places[0], POINTS[0] + 0.25 * (POINTS[0] - POINTS[1]))
    closed = bsplines.interval_label_positions(POINTS[:4], [1, 1, 1, 1], degree=2)
    assert np.allclose(closed, POINTS[:4])  # even degree: on the vertices


def test_closed_curve_points_are_periodic():
    d = np.array([1.0, 2.0, 1.0, 1.5, 0.5])
    pentagon = np.array([[0, 0], [3, 0], [4, 2], [2, 4], [-1, 2]], dtype=float)
    ts = np.array([0.3, 1.7, 4.9])
    once_round = bsplines.closed_curve_points(pentagon, d, 3, ts + d.sum())
    assert np.allclose(bsplines.closed_curve_points(pentagon, d, 3, ts), once_round)

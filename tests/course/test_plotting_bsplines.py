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


def test_phantom_edges_reach_past_the_end_points():
    # Figure 6.11: the dotted phantom edge runs from P_0 to a phantom vertex half the end leg away,
    # with its interval written at the middle (not a stub hidden under the end point's label).
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    bsplines.plot_knot_intervals(ax, POINTS, np.diff(KNOTS), polygon=False)
    dotted = [line.get_xydata() for line in ax.get_lines() if line.get_linestyle() == ":"]
    starts = {tuple(np.round(xy[0], 9)): xy[-1] for xy in dotted}
    assert np.allclose(starts[tuple(POINTS[0])], POINTS[0] + 0.5 * (POINTS[0] - POINTS[1]))
    assert np.allclose(starts[tuple(POINTS[-1])], POINTS[-1] + 0.5 * (POINTS[-1] - POINTS[-2]))
    plt.close(fig)


def test_plot_bspline_takes_a_style_for_its_polygon():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    bsplines.plot_bspline(ax, POINTS, KNOTS, labels=False, polygon_legend="new",
                          polygon_style={"color": "k", "linestyle": "-"})
    polygon = next(line for line in ax.get_lines() if line.get_label() == "new")
    assert polygon.get_linestyle() == "-" and polygon.get_color() == "k"
    assert len(polygon.get_xdata()) == len(POINTS)
    plt.close(fig)


def test_closed_curve_points_are_periodic():
    d = np.array([1.0, 2.0, 1.0, 1.5, 0.5])
    pentagon = np.array([[0, 0], [3, 0], [4, 2], [2, 4], [-1, 2]], dtype=float)
    ts = np.array([0.3, 1.7, 4.9])
    once_round = bsplines.closed_curve_points(pentagon, d, 3, ts + d.sum())
    assert np.allclose(bsplines.closed_curve_points(pentagon, d, 3, ts), once_round)


def test_outward_directions_point_away_from_the_polygon():
    # An arch: the inner vertices' labels go up and out, the end labels continue the end legs.
    arch = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
    u = bsplines.outward_directions(arch)
    assert np.allclose(np.linalg.norm(u, axis=1), 1)
    assert u[1, 1] > 0 and u[2, 1] > 0  # above the arch, where the curve is not
    assert np.allclose(u[0], -np.array([1.0, 2.0]) / np.sqrt(5))  # continues the leg P1 -> P0
    # A square, closed: every label points away from its centre.
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    closed = bsplines.outward_directions(square, closed=True)
    assert (np.einsum("ij,ij->i", closed, square - 0.5) > 0).all()


def test_place_labels_keeps_a_label_off_a_line_through_its_point():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(4, 3))
    ax.plot([0, 10], [5, 5], color="k")  # a horizontal line through the labelled point
    ax.set(xlim=(0, 10), ylim=(0, 10))
    bsplines.place_labels(ax, [[5.0, 5.0]], ["a label"])
    fig.canvas.draw()
    box = ax.texts[0].get_window_extent()
    line_y = ax.transData.transform((5.0, 5.0))[1]
    assert not (box.y0 <= line_y <= box.y1)  # above or below the line, not across it
    plt.close(fig)

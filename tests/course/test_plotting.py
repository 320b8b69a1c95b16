"""cagd_course.plotting: each function draws what it promises into the Axes it is given."""

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure
from matplotlib.patches import FancyArrowPatch

from cagd_course import plotting
from cagd_ref.bezier import circular_arc, curvature, de_casteljau, de_casteljau_triangle

CUBIC = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]])


@pytest.fixture
def ax():
    return Figure().add_subplot()


def test_control_polygon_draws_one_dashed_line_and_a_label_per_point(ax):
    original = CUBIC.copy()
    assert plotting.plot_control_polygon(ax, CUBIC) is ax
    (line,) = ax.lines
    assert np.array_equal(line.get_xydata(), CUBIC)
    assert line.get_linestyle() == "--"
    assert [t.get_text() for t in ax.texts] == ["$P_{0}$", "$P_{1}$", "$P_{2}$", "$P_{3}$"]
    assert ax.get_aspect() == 1.0
    assert np.array_equal(CUBIC, original)


def test_control_polygon_label_options(ax):
    plotting.plot_control_polygon(ax, CUBIC, label="Q", color="red")
    assert ax.texts[2].get_text() == "$Q_{2}$"
    assert matplotlib.colors.same_color(ax.lines[0].get_color(), "red")
    other = Figure().add_subplot()
    plotting.plot_control_polygon(other, CUBIC, labels=False)
    assert len(other.texts) == 0
    plotting.plot_control_polygon(other, CUBIC, labels=["", "a", "", "b"])
    assert [t.get_text() for t in other.texts] == ["a", "b"]


def test_control_polygon_rejects_bad_input(ax):
    with pytest.raises(ValueError, match="points"):
        plotting.plot_control_polygon(ax, np.zeros((3, 3)))
    with pytest.raises(ValueError, match="labels"):
        plotting.plot_control_polygon(ax, CUBIC, labels=["a"])
    with pytest.raises(TypeError, match="ax"):
        plotting.plot_control_polygon("not axes", CUBIC)


def test_bezier_curve_samples_the_curve(ax):
    assert plotting.plot_bezier(ax, CUBIC, samples=50, label="c") is ax
    (line,) = ax.lines
    xy = line.get_xydata()
    assert xy.shape == (50, 2)
    assert np.allclose(xy, de_casteljau(CUBIC, np.linspace(0, 1, 50)))
    assert line.get_label() == "c"


def test_rational_curve_draws_a_circular_arc(ax):
    points, weights = circular_arc([1.0, -1.0], 2.0, 0.3, 2.0)
    plotting.plot_bezier(ax, points, weights)
    xy = ax.lines[0].get_xydata()
    assert np.allclose(np.hypot(xy[:, 0] - 1, xy[:, 1] + 1), 2.0)


def test_negative_weight_breaks_the_line_at_the_poles():
    # With a middle weight -1 the denominator (1-t)² - 2t(1-t) + t² vanishes twice in (0, 1).
    samples = plotting.bezier_samples([[1, 0], [1, 1], [0, 1]], [1, -1, 1], samples=401)
    broken = np.isnan(samples[:, 0])
    assert 2 <= broken.sum() <= 4
    assert np.all(np.isfinite(samples[~broken]))


def test_interval_draws_the_extrapolated_curve(ax):
    plotting.plot_bezier(ax, CUBIC, interval=(-0.5, 1.5), samples=5)
    assert np.allclose(ax.lines[0].get_xydata(), de_casteljau(CUBIC, np.linspace(-0.5, 1.5, 5)))


def test_bezier_rejects_bad_weights_and_interval(ax):
    with pytest.raises(ValueError, match="weights"):
        plotting.plot_bezier(ax, CUBIC, weights=[1, 2])
    with pytest.raises(ValueError, match="interval"):
        plotting.plot_bezier(ax, CUBIC, interval=(1, 0))


@pytest.mark.parametrize("t", [0.0, 0.3, 1.0])
def test_de_casteljau_draws_every_level_and_the_point(ax, t):
    assert plotting.plot_de_casteljau(ax, CUBIC, t) is ax
    levels = de_casteljau_triangle(CUBIC, t)
    # curve + control polygon + levels 1 .. n-1 + the point P(t)
    assert len(ax.lines) == 1 + 1 + (len(CUBIC) - 2) + 1
    drawn = [line.get_xydata() for line in ax.lines[1:]]
    for level, xy in zip(levels, drawn):
        assert np.allclose(level, xy)
    assert np.allclose(drawn[-1][0], de_casteljau(CUBIC, t))


def test_de_casteljau_without_curve(ax):
    plotting.plot_de_casteljau(ax, CUBIC, 0.5, curve=False)
    # control polygon + levels 1 .. n-1 + the point P(t), no curve
    assert len(ax.lines) == 1 + (len(CUBIC) - 2) + 1


def test_curvature_comb_teeth_are_proportional_to_curvature(ax):
    count, length = 30, 1.5
    assert plotting.plot_curvature_comb(ax, CUBIC, count=count, length=length) is ax
    (teeth,) = [c for c in ax.collections if isinstance(c, LineCollection)]
    segments = np.array(teeth.get_segments())
    assert segments.shape == (count, 2, 2)
    lengths = np.linalg.norm(segments[:, 1] - segments[:, 0], axis=1)
    kappa = curvature(CUBIC, np.linspace(0, 1, count))
    assert np.allclose(lengths, length * kappa / kappa.max())
    assert np.allclose(ax.lines[-1].get_xydata(), segments[:, 1])


def test_implicit_circle_lies_on_the_zero_set(ax):
    assert plotting.plot_implicit(ax, lambda x, y: x**2 + y**2 - 1, (-2, 2), (-2, 2), label="circle") is ax
    (contour,) = ax.collections
    vertices = np.vstack(contour.allsegs[0])
    assert len(vertices) > 50
    assert np.allclose(np.hypot(vertices[:, 0], vertices[:, 1]), 1.0, atol=1e-3)
    assert [line.get_label() for line in ax.lines] == ["circle"]
    assert ax.get_xlim() == (-2.0, 2.0)


def test_implicit_with_no_real_points_draws_nothing(ax):
    plotting.plot_implicit(ax, lambda x, y: x**2 + y**2 + 1, (-1, 1), (-1, 1))
    assert len(ax.collections) == 0


def test_implicit_rejects_bad_input(ax):
    with pytest.raises(TypeError, match="f"):
        plotting.plot_implicit(ax, 3, (0, 1), (0, 1))
    with pytest.raises(ValueError, match="xlim"):
        plotting.plot_implicit(ax, lambda x, y: x, (1, 0), (0, 1))


def test_vector_2d_is_an_arrow_from_tail_to_head(ax):
    assert plotting.plot_vector(ax, [1, 2], [3, -1], label="v") is ax
    (arrow,) = ax.patches
    assert isinstance(arrow, FancyArrowPatch)
    tail, head = arrow._posA_posB
    assert np.allclose(tail, [1, 2]) and np.allclose(head, [4, 1])
    assert [t.get_text() for t in ax.texts] == ["v"]
    # The arrow is inside the view.
    x0, x1 = ax.get_xlim()
    assert x0 <= 1 and x1 >= 4


def test_vector_3d_uses_a_quiver():
    ax = Figure().add_subplot(projection="3d")
    assert plotting.plot_vector(ax, [0, 0, 0], [1, 2, 3], label="n") is ax
    assert len(ax.collections) == 1
    assert ax.texts[0].get_text() == "n"
    with pytest.raises(ValueError, match="tail"):
        plotting.plot_vector(ax, [0, 0], [1, 2, 3])


def test_vector_rejects_wrong_dimension(ax):
    with pytest.raises(ValueError, match="vector"):
        plotting.plot_vector(ax, [0, 0], [1, 2, 3])


def test_hide_from_legend_keeps_a_panel_out_of_legends_and_leaves_the_others():
    figure = Figure()
    first, second = figure.subplots(1, 2)
    for ax in (first, second):
        ax.plot([0, 1], [0, 1], label="curve")
        ax.scatter([0, 1], [1, 0], label="points")
        ax.plot([0, 1], [1, 1], label=None)  # a series with no label at all is left alone
    assert plotting.hide_from_legend(second) is second
    assert second.get_legend_handles_labels() == ([], [])
    assert first.get_legend_handles_labels()[1] == ["curve", "points"]
    with pytest.raises(TypeError, match="ax"):
        plotting.hide_from_legend(figure)

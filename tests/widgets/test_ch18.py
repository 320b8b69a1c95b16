"""cagd_course.widgets, chapter 18: the pencil, two-pencil, double-point and tangent explorers, and their figures."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import pencils as figures  # noqa: E402
from cagd_course.widgets.ch18 import CUBICS, FIGURE_18_7  # noqa: E402
from cagd_ref import bezier, moving_lines  # noqa: E402


def test_the_member_of_parameter_t_passes_through_the_mark_t():
    explorer = widgets.pencil_explorer()
    for t in (0.0, 0.35, 1.0):
        state = explorer.update(t=t, size1=2.5, d0=1.2)
        assert abs(state["incidence"]) < 1e-12
        assert state["d1"] == pytest.approx(1.2 * 2.5)  # d0/d1 = |(a0, b0)|/|(a1, b1)| (18.19)
    assert explorer.update(phi0=90.0, phi1=150.0)["counterclockwise"]
    assert not explorer.update(phi0=150.0, phi1=90.0)["counterclockwise"]
    with pytest.raises(ValueError, match="^phi1"):
        explorer.update(phi0=30.0, phi1=-150.0)  # the same line
    assert explorer.values["phi1"] == 90.0  # rejected values are undone


def test_the_two_pencils_explorer_starts_on_the_lines_of_figure_18_7():
    explorer = widgets.two_pencils_explorer()
    state = explorer.state
    np.testing.assert_allclose(state["lines"], FIGURE_18_7, atol=1e-12)
    assert state["kind"] == "ellipse"
    np.testing.assert_allclose(state["weights"], [8.0, 10.0, 16.0])
    np.testing.assert_allclose(state["control"][1], (state["qa"] + state["qb"]) / 2)  # P1 halfway from Qa to Qb
    pa, pb = (q[:2] / q[2] for q in (state["qa"], state["qb"]))
    assert np.linalg.norm(pa - pb) > 1 and min(np.linalg.norm(state["control"][k, :2] / state["control"][k, 2] - q)
                                               for k in (0, 2) for q in (pa, pb)) > 0.5  # four distinct points
    c = state["implicit"]
    for t in (0.0, 0.4, 1.0):
        point = explorer.update(t=t)["point"]
        x, y = point[:2] / point[2]
        assert sum(c[i, j] * x**i * y**j for i in range(3) for j in range(3)) == pytest.approx(0, abs=1e-12)
    assert explorer.update(turn11=40.0)["kind"] == "hyperbola"
    turned = explorer.state["lines"][3]
    assert turned @ [4.0, 0.0, 1.0] == pytest.approx(0, abs=1e-12)  # still through the axis (4, 0)
    assert np.linalg.norm(turned[:2]) == pytest.approx(np.linalg.norm(FIGURE_18_7[3, :2]))


@pytest.mark.parametrize("curve, kind", [("notes' cubic (crunode)", "crunode"), ("loop inside [0, 1]", "crunode"),
                                         ("cusp", "cusp"), ("acnode", "acnode")])
def test_the_double_point_finder_names_the_kind(curve, kind):
    state = widgets.double_point_explorer(curve).state
    assert state["kind"].startswith(kind)
    point = state["double_point"]
    np.testing.assert_allclose(np.cross(np.cross(*state["pencil"]), point), 0, atol=1e-12)  # the axis
    real = state["parameters"][np.isreal(state["parameters"])].real
    for t in real:
        np.testing.assert_allclose(bezier.evaluate(state["points"], t), state["cartesian"], atol=1e-6)


def test_moving_a_control_point_moves_the_double_point_with_the_pencil():
    explorer = widgets.double_point_explorer()
    first = explorer.state["cartesian"]
    np.testing.assert_allclose(first, notes_example("18.cubic").results["double_point"][:2], atol=1e-12)
    state = explorer.update(dx1=0.4, dy2=-0.3)
    np.testing.assert_allclose(state["points"][1:3], CUBICS["notes' cubic (crunode)"][1:3] + [[0.4, 0.0], [0.0, -0.3]])
    assert np.linalg.norm(state["cartesian"] - first) > 0.1
    np.testing.assert_allclose(state["double_point"], moving_lines.cubic_double_point(state["points"]))


def test_the_cusp_preset_is_a_slider_path_through_acnode_cusp_and_crunode():
    explorer = widgets.double_point_explorer("cusp")
    assert explorer.main_control() == "dx1"
    kinds = [explorer.update(dx1=float(v))["kind"].split()[0] for v in np.round(np.linspace(-2, 2, 21), 12)]
    assert kinds == ["acnode"] * 10 + ["cusp"] + ["crunode"] * 10
    state = explorer.update(dx1=0.0)
    np.testing.assert_allclose(state["cartesian"], bezier.evaluate(state["points"], 0.5), atol=1e-9)
    assert "|t₁ − t₂| ≈ 0" in explorer.describe(state)


def test_the_tangent_explorer_starts_with_the_dual_point_in_view():
    explorer = widgets.tangent_explorer()
    state = explorer.state
    assert np.all(np.abs(state["dual_point"]) < 4)
    labels = [line.get_label() for line in explorer.dual.get_lines()]
    assert "B(t)" in labels
    explorer.update(t=0.3)  # the tangent passes near the origin: B(t) = (1.55, 4.91) is off the panel
    labels = [line.get_label() for line in explorer.dual.get_lines()]
    assert "B(t) is off the panel, this way" in labels


def test_the_tangent_explorer_draws_the_reciprocal_curve():
    explorer = widgets.tangent_explorer()
    state = explorer.update(t=0.4)
    points = state["points"]
    np.testing.assert_allclose(state["tangent"] @ [*state["point"], 1.0], 0, atol=1e-12)
    # The dual line of P(t) passes through B(t), the tangent line read as a point.
    assert np.dot([*state["point"], 1.0], [*state["dual_point"], 1.0]) == pytest.approx(0, abs=1e-12)
    assert state["envelope_error"] < 1e-12
    np.testing.assert_allclose(state["hodograph"], bezier.elevate(bezier.hodograph(points), 2))
    assert len(explorer.figure.axes) == 2


def test_line_segments_cross_the_box_and_skip_the_line_at_infinity():
    segments = figures.line_segments([[0.0, 1.0, -1.0], [0.0, 0.0, 1.0]], (-2, 2), (-2, 2))
    assert np.all(segments[0, :, 1] == pytest.approx(1.0))
    assert min(segments[0, :, 0]) < -2 < 2 < max(segments[0, :, 0])
    assert np.isnan(segments[1]).all()
    ax = Figure().add_subplot()
    figures.plot_pencil(ax, [0.0, 1.0, 0.0], [1.0, 1.0, -1.0], (-2, 2), (-2, 2))
    assert ax.get_xlim() == (-2, 2) and len(ax.collections) == 1
    figures.plot_points(ax, [[1.0, 2.0, 1.0], [1.0, 0.0, 0.0]], labels=["a", "b"])
    assert [t.get_text() for t in ax.texts] == ["a"]
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_line(None, [1.0, 0.0, 0.0], (0, 1), (0, 1))
    with pytest.raises(ValueError, match="^ends"):
        figures.plot_parameter_line(ax, [[0.0, 0.0]])

"""cagd_course.widgets, chapter 16: the Q–R tangent, pseudo-power switch and sub-patch explorers through `update`."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import surfaces as figures  # noqa: E402
from cagd_ref import bezier, surfaces  # noqa: E402

TORUS = notes_example("16.torus")
PATCH = notes_example("16.rational_patch")


# ---------------------------------------------------------------- Q, R and the tangent


def test_the_qr_explorer_puts_p_on_the_tangent_segment():
    explorer = widgets.qr_tangent_explorer()
    assert list(explorer.controls) == ["curve", "t", "weight"]
    state = explorer.update(curve="cubic arch", t=0.3, weight=2.5)
    points, weights = state["points"], state["weights"]
    assert weights.tolist() == [1.0, 2.5, 1.0, 1.0]
    np.testing.assert_allclose(state["p"], bezier.evaluate(points, 0.3, weights), rtol=1e-13)
    np.testing.assert_allclose(state["p"], state["q"] + state["ratio"] * (state["r"] - state["q"]), rtol=1e-13)
    np.testing.assert_allclose(state["derivative"], bezier.derivative(points, 0.3, 1, weights), rtol=1e-12)
    np.testing.assert_allclose(state["derivative"], state["factor"] * (state["r"] - state["q"]), rtol=1e-12)
    assert state["factor"] != pytest.approx(3.0)  # unequal weights: |p'| is not n |r - q|
    assert "t R_w / P_w" in explorer.readout.value


def test_the_qr_explorer_on_the_quarter_circle_keeps_the_circle():
    state = widgets.qr_tangent_explorer().update(curve="quarter circle", weight=1.0, t=0.5)
    example = notes_example("16.quarter_circle")
    np.testing.assert_allclose(state["p"], example.results["p"], rtol=1e-14)
    np.testing.assert_allclose(state["derivative"], example.results["derivative"], rtol=1e-13)
    np.testing.assert_allclose(np.linalg.norm(state["samples"], axis=1), 1.0, rtol=1e-14)


def test_polynomial_weights_make_the_factor_the_degree():
    state = widgets.qr_tangent_explorer().update(curve="quintic", weight=1.0, t=0.62)
    assert state["factor"] == pytest.approx(5.0, rel=1e-14)


# ---------------------------------------------------------------- the switch


def test_the_switch_explorer_shows_the_overflow_of_the_first_form():
    explorer = widgets.pseudo_switch_explorer()
    state = explorer.update(degree=40, gap=1e-8)
    assert not np.isfinite(state["values"]["u = t/(1−t) only"])
    assert state["error_at_t"]["switched at ½"] < 1e-14
    assert state["broken"].size and state["broken"].max() >= 1e-8
    assert np.all(np.isfinite(state["errors"]["switched at ½"])) and state["errors"]["switched at ½"].max() < 1e-13
    assert "overflows" in explorer.ax.get_title()


def test_at_moderate_degree_only_t_equal_one_breaks_the_first_form():
    state = widgets.pseudo_switch_explorer().update(degree=7, gap=1e-15)
    errors = state["errors"]["u = t/(1−t) only"]
    assert np.isinf(errors[-1]) and np.all(errors[:-1] < 1e-14)  # the last value is t = 1 itself
    assert state["broken"].tolist() == [0.0]


# ---------------------------------------------------------------- sub-patches


def test_the_sub_patch_explorer_on_the_torus():
    explorer = widgets.sub_patch_explorer()
    assert list(explorer.controls) == ["patch", "s", "t"] and explorer.ax.name == "3d"
    state = explorer.update(patch="torus patch", s=0.5, t=0.5)
    np.testing.assert_allclose(state["p"], TORUS.results["p"][0], atol=1e-10)
    np.testing.assert_allclose(state["normal"], TORUS.results["normal"][0], atol=1e-10)
    # A–B points along p_s and C–D along p_t, both through p.
    ends, p = state["ends"], state["p"]
    for (a, b), tangent in ((("A", "B"), state["p_s"]), (("C", "D"), state["p_t"])):
        direction = ends[b] - ends[a]
        scale = np.linalg.norm(direction) * np.linalg.norm(tangent)
        assert np.linalg.norm(np.cross(direction, tangent)) < 1e-12 * scale
        assert np.linalg.norm(np.cross(p - ends[a], direction)) < 1e-12 * np.linalg.norm(direction) ** 2
    assert state["costs"] == {"sub_patches": (48, 48), "de_casteljau": (80, 40)}  # degree (2, 2)


def test_the_sub_patch_explorer_reports_the_coplanarity_trap():
    state = widgets.sub_patch_explorer().update(patch="random bicubic", s=0.3, t=0.6)
    assert abs(state["volume"]) > 1e-3 and state["angle"] > 1.0
    assert "° off the tangent plane" in widgets.sub_patch_explorer().readout.value


def test_the_sub_patch_explorer_reaches_the_far_corner():
    state = widgets.sub_patch_explorer().update(patch="rational (2, 1) patch", s=1.0, t=1.0)
    np.testing.assert_allclose(state["p"], PATCH.inputs["points"][-1, -1], atol=1e-14)
    np.testing.assert_allclose(state["normal"], surfaces.patch_normal(PATCH.inputs["points"], 1.0, 1.0,
                                                                      PATCH.inputs["weights"]))


# ---------------------------------------------------------------- figures


def test_the_surface_figures_draw_into_3d_axes_only():
    fig = Figure()
    ax = fig.add_subplot(projection="3d")
    points, weights = TORUS.inputs["points"], TORUS.inputs["weights"]
    assert figures.plot_patch(ax, points, weights, samples=5, iso=3) is ax
    assert len(ax.lines) == 6 and len(ax.collections) == 1
    figures.plot_control_net(ax, points)
    assert len(ax.lines) == 12
    p, p_s, p_t = surfaces.patch_point_tangents(points, 0.5, 0.5, weights)
    figures.plot_tangent_plane(ax, p, p_s, p_t, size=0.5)
    assert len(ax.collections) == 2  # the surface and the tangent plane
    figures.finish_3d(ax, points.reshape(-1, 3))
    low, high = ax.get_xlim()
    assert high - low == pytest.approx(ax.get_zlim()[1] - ax.get_zlim()[0])
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_patch(Figure().add_subplot(), points, weights)
    with pytest.raises(ValueError, match="^points"):
        figures.plot_control_net(ax, points[..., :2])
    np.testing.assert_allclose(figures.patch_grid(points, weights, 3)[1, 1], p)

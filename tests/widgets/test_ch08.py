"""cagd_course.widgets, chapter 8: the offset, PH and gouging explorers driven through `update`, and their figures."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import offsets as figures  # noqa: E402
from cagd_course.widgets.ch08 import CURVES  # noqa: E402
from cagd_ref import bezier, offsets  # noqa: E402

ARCH = notes_example("08.arch")
INFLECTION = notes_example("08.inflection")


# ---------------------------------------------------------------- offsets and cusps


def test_the_offset_explorer_shows_the_arch_s_cusps_and_tightest_bend():
    explorer = widgets.offset_explorer()
    assert list(explorer.controls) == ["curve", "rho"]
    state = explorer.update(curve="convex arch", rho=ARCH.inputs["rho_cusps"])
    np.testing.assert_allclose(state["cusps"], ARCH.results["cusps"], atol=1e-12)
    np.testing.assert_allclose(state["cusp_points"], offsets.offset_point(ARCH.inputs["points"], state["cusps"], 2.5))
    assert state["interval"][0] == -np.inf and state["interval"][1] == pytest.approx(ARCH.results["min_radius"])
    assert state["tightest"] == pytest.approx((0.5, ARCH.results["min_radius"]), abs=1e-6)
    first, second = ARCH.results["cusps"]
    assert np.array_equal(state["backward"], (state["ts"] > first) & (state["ts"] < second))
    assert "0.2059, 0.7941" in explorer.readout.value and "-∞ &lt; ρ &lt; 1.688" in explorer.readout.value


def test_the_convex_side_has_no_cusps_and_no_limiting_bend():
    state = widgets.offset_explorer().update(curve="convex arch", rho=-3.0)
    assert state["cusps"].size == 0 and state["tightest"] is None and not state["backward"].any()
    assert np.all(state["factor"] > 0)


def test_an_inflection_moves_the_cusps_to_the_other_arc_with_the_side():
    explorer = widgets.offset_explorer()
    right = explorer.update(curve="S-curve (inflection)", rho=INFLECTION.inputs["rho"])
    np.testing.assert_allclose(right["cusps"], INFLECTION.results["cusps"], atol=1e-12)
    left = explorer.update(rho=-INFLECTION.inputs["rho"])
    np.testing.assert_allclose(left["cusps"], INFLECTION.results["cusps_left"], atol=1e-12)
    assert left["tightest"][1] == pytest.approx(INFLECTION.results["min_radius"], rel=1e-10)


def test_the_offset_explorer_takes_a_curve_of_its_own():
    mine = [(0.0, 0.0), (2.0, 3.0), (5.0, -1.0), (6.0, 2.0)]
    explorer = widgets.offset_explorer(mine, rho=0.8)
    assert explorer.values["curve"] == "your curve"
    state = explorer.state
    np.testing.assert_allclose(state["offset"], offsets.offset_point(mine, state["ts"], 0.8))
    np.testing.assert_allclose(state["cusps"], offsets.offset_cusps(mine, 0.8))
    with pytest.raises(ValueError, match="^points"):
        widgets.offset_explorer([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)])


def test_the_lower_panel_draws_the_cusp_condition():
    explorer = widgets.offset_explorer()
    explorer.update(curve="convex arch", rho=2.5)
    line = explorer.lower.lines[0]
    np.testing.assert_allclose(line.get_ydata(), explorer.state["factor"])
    cusp_marks = [ln for ln in explorer.lower.lines if ln.get_marker() == "v"][0]
    np.testing.assert_allclose(cusp_marks.get_xdata(), ARCH.results["cusps"])


# ---------------------------------------------------------------- PH curves


def test_the_ph_explorer_reproduces_the_example():
    explorer = widgets.ph_offset_explorer()
    state = explorer.state
    example = notes_example("08.ph_offset")
    np.testing.assert_allclose(state["cubic"], example.inputs["points"], atol=1e-15)
    np.testing.assert_allclose(state["points"], example.results["points"], atol=1e-14)
    np.testing.assert_allclose(state["weights"], example.results["weights"], atol=1e-14)
    assert state["deviation"] < 1e-13 and state["speed_error"] < 1e-13
    assert "4, 3.2, 2.6, 2.2, 2, 2" in explorer.readout.value


@pytest.mark.parametrize("values", [dict(u0=-1.0, u1=0.5, v0=1.5, v1=1.0, rho=0.7), dict(u0=1.0, v1=-2.0, rho=-1.9)])
def test_the_exact_offset_follows_the_sliders(values):
    state = widgets.ph_offset_explorer().update(**values)
    assert state["deviation"] < 1e-12
    np.testing.assert_allclose(bezier.evaluate(state["points"], state["ts"], state["weights"]), state["sampled"],
                               atol=1e-12)


def test_a_cubic_that_stops_is_refused_and_the_sliders_roll_back():
    explorer = widgets.ph_offset_explorer()
    with pytest.raises(ValueError, match=r"^u0, u1, v0, v1: points: the PH curve stops"):
        explorer.update(u0=1.0, u1=-1.0, v0=1.0, v1=-1.0)
    assert explorer.values["u1"] == 1.0
    explorer.controls["u1"].value = -1.0  # from a slider the message shows in the readout instead
    explorer.controls["v0"].value = 1.0
    explorer.controls["v1"].value = -1.0
    explorer.controls["u0"].value = 1.0
    assert "stops" in explorer.readout.value


# ---------------------------------------------------------------- gouging


def test_a_tool_larger_than_the_tightest_bend_gouges_locally():
    explorer = widgets.gouging_explorer()
    state = explorer.update(curve="convex arch", rho=2.0, t=0.5)
    assert state["kind"] == "local" and state["depth"] > 0.1 and state["gouged"].any()
    assert len(state["cusps"]) == 2 and state["factor"] < 0
    np.testing.assert_allclose(state["tool"], offsets.offset_point(ARCH.inputs["points"], 0.5, 2.0))
    # The deepest gouge is the deepest cut of some tool position: max over t of the cut at t.
    cuts = [explorer.update(t=t)["cut"] for t in np.linspace(0, 1, 101)]
    assert 0 < state["cut"] <= max(cuts) == pytest.approx(state["depth"], rel=1e-3)
    safe = explorer.update(rho=1.5, t=0.5)
    assert safe["kind"] == "none" and safe["depth"] < 1e-9 and not safe["gouged"].any()


def test_the_hook_is_gouged_by_a_tool_that_fits_every_bend():
    points = CURVES["hook"]
    low, _ = offsets.cusp_free_interval(points)
    rho = 0.9 * low  # inside the curl, smaller than its tightest bend
    explorer = widgets.gouging_explorer()
    state = explorer.update(curve="hook", rho=rho, t=0.07)  # near the start of the path: it cuts the free end
    assert state["cusps"].size == 0 and state["kind"] == "global" and state["cut"] > 0.1 and state["depth"] > 0.1
    assert state["gouging"] == ("global",) and state["factor"] > 0
    assert np.all(1 + rho * bezier.signed_curvature(points, np.linspace(0, 1, 401)) > 0)
    assert "yet the tool cuts" in explorer.readout.value and "global gouging" in explorer.readout.value
    clear = explorer.update(t=0.5)  # a position that cuts nothing, on a path that gouges elsewhere
    assert clear["kind"] == "none" and clear["cut"] == 0 and clear["gouging"] == ("global",)
    assert "this position cuts nothing" in explorer.readout.value


def test_a_swallowtail_gouges_locally_on_its_backward_arc_and_globally_before_its_crossing():
    pocket = CURVES["parabola y = x²"]
    explorer = widgets.gouging_explorer()
    crossing = offsets.trim_offset(pocket, -0.8)[0, 1]
    first, second = offsets.offset_cusps(pocket, -0.8)
    vertex = explorer.update(curve="parabola y = x²", rho=-0.8, t=0.5)
    assert vertex["kind"] == "local" and vertex["factor"] < 0 and vertex["gouging"] == ("local", "global")
    arm = explorer.update(t=0.35)  # between the crossing and the first cusp: forward, and still cutting
    assert crossing < 0.35 < first and arm["kind"] == "global" and arm["factor"] > 0 and arm["cut"] > 0.1
    assert "global gouging too" in explorer.readout.value
    # The forward positions that gouge are exactly those between the crossings and the cusps.
    (a, b), (c, d) = arm["global_at"]
    assert crossing < a < b < first and second < c < d < 1 - crossing
    assert b - a > first - crossing - 0.01 and d - c > first - crossing - 0.01
    assert explorer.update(t=0.1)["kind"] == "none"


def test_the_path_offset_back_is_the_curve_except_between_the_cusps():
    state = widgets.gouging_explorer().update(curve="convex arch", rho=2.0)
    ts = np.linspace(0, 1, len(state["reverse"]))
    first, second = offsets.offset_cusps(ARCH.inputs["points"], 2.0)
    outside = ((ts < first - 0.01) | (ts > second + 0.01)) & np.isfinite(state["reverse"][:, 0])
    inside = (ts > first + 0.01) & (ts < second - 0.01)
    np.testing.assert_allclose(state["reverse"][outside], state["base"][outside], atol=1e-12)
    far = state["base"] + 4.0 * offsets.offset_normal(ARCH.inputs["points"], ts)
    np.testing.assert_allclose(state["reverse"][inside], far[inside], atol=1e-12)


# ---------------------------------------------------------------- the layouts


def _beside(explorer) -> bool:
    """True when the drawing's legend stands to the right of it, not on it."""
    canvas = explorer.figure.canvas
    canvas.draw()
    drawing = explorer.ax.get_window_extent()
    key = explorer.ax.get_legend().get_window_extent()
    return key.x0 >= drawing.x1 and key.x1 <= explorer.figure.bbox.x1


@pytest.mark.parametrize(
    "make, values",
    [
        (widgets.offset_explorer, dict(curve="convex arch", rho=2.0)),
        (widgets.offset_explorer, dict(curve="hook", rho=1.5)),
        (widgets.ph_offset_explorer, dict(rho=0.25)),
        (widgets.ph_offset_explorer, dict(u0=-1.0, u1=1.5, v0=1.0, v1=0.5, rho=0.8)),
        (widgets.gouging_explorer, dict(curve="parabola y = x²", rho=-0.8, t=0.45)),
    ],
)
def test_the_explorers_keep_their_legend_beside_the_drawing(make, values):
    explorer = make()
    explorer.update(**values)
    assert _beside(explorer)


@pytest.mark.parametrize("rho", [0.25, -0.8])
def test_the_ph_lab_labels_its_control_points_away_from_the_offset(rho):
    explorer = widgets.ph_offset_explorer()
    state = explorer.update(rho=rho)
    cubic = state["cubic"]
    labels = [text for text in explorer.ax.texts if text.get_text().startswith("$P_")]
    assert [text.get_text() for text in labels] == [f"$P_{{{i}}}$" for i in range(4)]
    legs = np.diff(cubic, axis=0)
    right = np.column_stack([legs[:, 1], -legs[:, 0]])
    right /= np.linalg.norm(right, axis=1)[:, None]
    at_points = np.vstack([right[:1], right[:-1] + right[1:], right[-1:]])
    for text, normal in zip(labels, at_points):
        assert np.sign(rho) * (np.asarray(text.xyann) @ normal) < 0  # on the far side from the offset


# ---------------------------------------------------------------- the figures


def test_offset_samples_break_where_the_curve_stops():
    stops = [(0.0, 0.0), (0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]
    ts, curve, factor = figures.offset_samples(stops, 0.5, samples=11)
    assert np.isnan(curve[0]).all() and np.isnan(factor[0])
    np.testing.assert_allclose(curve[1:], offsets.offset_point(stops, ts[1:], 0.5))


def test_plot_offset_draws_both_kinds_of_arc_and_the_cusps():
    ax = Figure().add_subplot()
    assert figures.plot_offset(ax, ARCH.inputs["points"], 2.5) is ax
    labels = [line.get_label() for line in ax.lines]
    assert labels == ["offset ρ = 2.5", "runs backwards (1 + ρκ < 0)", "cusps"]
    np.testing.assert_allclose(np.column_stack(ax.lines[2].get_data()),
                               offsets.offset_point(ARCH.inputs["points"], ARCH.results["cusps"], 2.5), atol=1e-12)
    plain = Figure().add_subplot()
    figures.plot_offset(plain, ARCH.inputs["points"], -1.0)
    assert len(plain.lines) == 1  # the convex side: neither backward arcs nor cusps


def test_plot_offsets_and_the_circle_of_curvature():
    ax = Figure().add_subplot()
    figures.plot_offsets(ax, INFLECTION.inputs["points"], [0.2, -0.2, 0.4])
    assert len(ax.lines) >= 3
    figures.plot_osculating_circle(ax, ARCH.inputs["points"], 0.5)
    circle = ax.patches[0]
    assert circle.radius == pytest.approx(ARCH.results["min_radius"])
    np.testing.assert_allclose(circle.center, [2.0, 1.5 - ARCH.results["min_radius"]])
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_offset("not an axes", ARCH.inputs["points"], 1.0)


def test_the_gouging_explorer_trims_the_path_to_what_keeps_its_distance():
    explorer = widgets.gouging_explorer()
    state = explorer.update(curve="parabola y = x²", rho=-0.8, t=0.5)
    assert state["kind"] == "local" and state["trimmed"].shape == (2, 2)
    np.testing.assert_allclose(state["trimmed"], offsets.trim_offset(CURVES["parabola y = x²"], -0.8))
    kept = np.vstack(state["kept_paths"])
    distance = offsets.distance_to_curve(CURVES["parabola y = x²"], kept)
    assert np.all(distance >= 0.8 * (1 - 1e-9))
    assert "trimmed path keeps t in [0.000, 0.292], [0.708, 1.000]" in explorer.readout.value
    state = explorer.update(curve="convex arch", rho=-1.0)  # outside the arch: nothing to trim
    assert state["trimmed"].tolist() == [[0.0, 1.0]] and state["kind"] == "none"

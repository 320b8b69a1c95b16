"""cagd_course.widgets, chapter 9: the root-finding explorers driven through `update`, and their figures."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting.roots import (  # noqa: E402
    mark_roots,
    plot_conditioning,
    plot_derivative_look,
    plot_explicit,
    plot_march_step,
    plot_root_errors,
)
from cagd_ref.bezier import evaluate, to_homogeneous  # noqa: E402
from cagd_ref.roots import bcom_steps, bernstein_roots, hull_march, hull_march_steps, wilkinson_polynomial  # noqa: E402

MARCHING = notes_example("09.hull_marching")


def _axes():
    return Figure().add_subplot()


# ---------------------------------------------------------------- hull marching


def test_the_march_explorer_retraces_the_chapter_example():
    explorer = widgets.hull_march_explorer()
    state = explorer.update(polynomial="Figure 9.1 (course quartic)", step=0)
    assert state["start"] == 0.0 and state["crossing"] == MARCHING.results["steps"][0]
    state = explorer.update(step=MARCHING.results["k"] - 1)  # the sixth step declares the first root
    assert state["event"] == "root"
    assert explorer.ax.get_title().endswith("k = 5 of 20: t_6 is a root")  # named as the chapter names it
    assert "t_6 is a root" in explorer.describe(state)
    np.testing.assert_allclose(state["roots"], MARCHING.results["roots"][:1], atol=1e-12)
    # the slider ends where the march ends
    last = explorer.update(step=explorer.controls["step"].max)
    assert last["event"] == "end" and last["step"] == len(last["steps"]) - 1 == 20
    np.testing.assert_allclose(last["roots"], hull_march(MARCHING.inputs["coeffs"]), atol=1e-14)
    with pytest.raises(ValueError, match="^step"):
        explorer.update(step=21)


def test_the_march_readout_shows_f_itself_after_a_deflation():
    explorer = widgets.hull_march_explorer()
    state = explorer.update(polynomial="Figure 9.1 (course quartic)", step=6)  # the piece after the first root
    assert state["steps"][6].coeffs[0] < -4  # the deflated polynomial's first coefficient
    assert abs(state["value"]) < 1e-14  # f(t_6): t_6 is the root
    text = explorer.describe(state)
    assert "-4.333e+00" not in text and ">f(t_k)<" in text


def test_the_step_slider_follows_the_march_so_the_static_frames_show_it_all():
    explorer = widgets.hull_march_explorer()
    name, frames, start = explorer.static_frames(21)
    assert name == "step" and start == 0
    assert [f["label"] for f in frames] == [str(k) for k in range(21)]  # one frame per step of the quartic
    assert len({f["alt"] for f in frames}) == 21  # no two frames alike
    explorer.update(polynomial="a double root: the crawl", step=50)
    assert explorer.controls["step"].max == 100
    state = explorer.update(polynomial="the pitfall: a linear f")  # a shorter march: the step moves to its end
    assert explorer.controls["step"].max == 1 and state["step"] == 1


def test_the_step_ratio_shows_linear_convergence_and_the_crawl():
    explorer = widgets.hull_march_explorer()
    simple = explorer.update(polynomial="Figure 9.1 (course quartic)", step=15)["ratio"]
    crawl = explorer.update(polynomial="a double root: the crawl", step=100)  # the march is cut at 100 steps
    assert 0.05 < simple < 0.5
    assert crawl["event"] == "stalled" and crawl["ratio"] > 0.9 and crawl["roots"].size == 0
    assert 0.28 < crawl["start"] < 0.3


def test_the_step_ratio_starts_again_after_a_root_is_divided_out():
    explorer = widgets.hull_march_explorer()
    name = "Figure 9.1 (course quartic)"
    before = explorer.update(polynomial=name, step=5)  # the step that declares the first root
    assert before["event"] == "root" and 0 < before["ratio"] < 1
    for k in (6, 7):  # a step length before the deflation is no measure of the next root
        state = explorer.update(polynomial=name, step=k)
        assert state["ratio"] is None
        assert "step ratio —" in explorer.describe(state)
    after = explorer.update(polynomial=name, step=8)  # two steps towards the second root
    assert 0 < after["ratio"] < 1


def test_the_pitfall_preset_finds_its_root_in_one_step():
    state = widgets.hull_march_explorer().update(polynomial="the pitfall: a linear f", step=0)
    assert state["event"] == "root" and state["crossing"] == pytest.approx(7 / 12, abs=1e-15)


def test_the_march_readout_keeps_its_columns_apart():
    explorer = widgets.hull_march_explorer()
    text = explorer.describe(explorer.update(polynomial="Figure 9.1 (course quartic)", step=3))
    assert text.count("padding") >= 4 * 5  # header and rows: every cell padded
    assert "<th style='padding:1px 10px;text-align:right'>event</th>" in text


def test_stepping_to_the_control_polygon_jumps_the_root_of_the_cubic():
    explorer = widgets.hull_march_explorer()
    explorer.update(polynomial="<1, -1, 2, -3>: hull against polygon", rule="control polygon (wrong)")
    polygon = explorer.update(step=explorer.controls["step"].max)  # the end of the march
    assert [round(s.start, 6) for s in polygon["steps"][:3]] == [0.0, round(1 / 6, 6), 0.337778]
    np.testing.assert_allclose(polygon["roots"], [0.8])  # the wrong "root", past the true one
    assert "polygon" in explorer.ax.get_title()
    explorer.update(rule="convex hull")
    hull = explorer.update(step=explorer.controls["step"].max)
    np.testing.assert_allclose(hull["roots"], hull_march([1.0, -1.0, 2.0, -3.0]), atol=1e-12)
    assert "0.596013393" in explorer.describe(hull)


def test_the_march_explorer_takes_a_polynomial_of_ones_own():
    explorer = widgets.hull_march_explorer([0.5, -1.0, 1.0])
    assert explorer.values["polynomial"] == "your polynomial"
    state = explorer.update(step=explorer.controls["step"].max)
    np.testing.assert_allclose(state["roots"], hull_march([0.5, -1.0, 1.0]), atol=1e-12)
    with pytest.raises(ValueError, match="^coeffs"):
        widgets.hull_march_explorer([[1.0, 2.0]])


# ---------------------------------------------------------------- conditioning


def test_the_conditioning_explorer_measures_the_claim():
    explorer = widgets.conditioning_explorer()
    example = notes_example("09.conditioning")
    state = explorer.update(degree=int(example.inputs["degree"]))
    assert state["ratio"] > example.results["error_ratio_at_least"]
    bernstein, _, exact = wilkinson_polynomial(state["degree"])
    np.testing.assert_array_equal(state["found"]["bernstein_roots (Bernstein form)"], bernstein_roots(bernstein))
    np.testing.assert_allclose(state["exact"], exact)
    eta = 2.0**-53
    for name, errors in state["errors"].items():  # every error within a small multiple of its bound η K(r)
        assert np.all(errors <= 50 * eta * state["condition"][name])
    assert np.all(state["condition"]["bernstein_roots (Bernstein form)"]
                  <= state["condition"]["numpy.roots (power form)"])  # Farouki and Rajan
    low = explorer.update(degree=3)
    assert low["exact"].shape == (3,) and all(e.max() < 1e-13 for e in low["errors"].values())
    assert len(explorer.largest["numpy.roots (power form)"]) == 24


def test_root_errors_match_each_exact_root_with_its_nearest_computed_one():
    errors = widgets.root_errors([0.1 + 0.01j, 0.52, 0.9], [0.1, 0.5, 0.9])
    np.testing.assert_allclose(errors, [0.01, 0.02, 0.0], atol=1e-15)
    assert np.all(np.isinf(widgets.root_errors([], [0.5])))


# ---------------------------------------------------------------- line ∩ rational curve


def test_the_default_line_is_the_notes_lmin():
    example = notes_example("09.line_curve")
    explorer = widgets.line_curve_explorer()
    state = explorer.update(angle=float(np.degrees(np.arctan2(0.8, -0.6))), offset=4.0)
    np.testing.assert_allclose(state["ts"], example.results["roots"][:1], atol=1e-12)
    np.testing.assert_allclose(state["values"], -example.results["values"][0] / 10, atol=1e-12)  # Lmin / -10


def test_the_intersections_lie_on_the_line_and_the_curve():
    explorer = widgets.line_curve_explorer()
    for angle, offset, weight in [(30.0, 8.0, 2.0), (100.0, 5.0, 0.2), (160.0, -2.0, 8.0)]:
        state = explorer.update(angle=angle, offset=offset, weight=weight)
        a, b, c = state["line"]
        assert state["weights"][2] == weight
        np.testing.assert_allclose(state["points"] @ [a, b] + c, 0, atol=1e-9)
        if len(state["ts"]):
            np.testing.assert_allclose(state["points"], evaluate(explorer.points, state["ts"], state["weights"]))
        np.testing.assert_allclose(state["values"], to_homogeneous(explorer.points, state["weights"]) @ state["line"])


def test_a_line_that_misses_the_curve_finds_nothing():
    state = widgets.line_curve_explorer().update(angle=90.0, offset=15.0)  # y = 15, above the quartic
    assert state["ts"].shape == (0,) and state["points"].shape == (0, 2) and state["hull"] is None


def test_a_heavier_weight_pulls_the_intersection():
    explorer = widgets.line_curve_explorer()
    light = explorer.update(weight=0.5)["ts"]
    heavy = explorer.update(weight=8.0)["ts"]
    assert len(light) == len(heavy) == 1 and heavy[0] > light[0]


# ---------------------------------------------------------------- the figures


def test_plot_explicit_draws_curve_polygon_and_hull():
    ax = plot_explicit(_axes(), [1.0, -2.0, 3.0], interval=(2, 4), label="f")
    assert len(ax.patches) == 1 and ax.get_xlabel() == "t"
    xs = np.concatenate([line.get_xdata() for line in ax.lines[1:]])
    assert xs.min() == pytest.approx(2) and xs.max() == pytest.approx(4)
    assert len(plot_explicit(_axes(), [2.0, 2.0], hull=True).patches) == 0  # a flat polygon has no hull to shade
    with pytest.raises(TypeError, match="^ax"):
        plot_explicit(None, [1.0, 2.0])


def test_march_and_derivative_panels_are_labelled():
    steps = hull_march_steps(MARCHING.inputs["coeffs"])
    ax = plot_march_step(_axes(), steps, 2, MARCHING.inputs["coeffs"])
    assert any("t_{3}" in text.get_text() for text in ax.texts)
    coeffs = [-1.0, 2.0, -2.0, 1.0]
    look = bcom_steps(coeffs)[0]
    title = plot_derivative_look(_axes(), look, coeffs).get_title()
    assert f"V = {look.variations}" in title and "split at the roots of f′" in title
    monotone = next(s for s in bcom_steps(coeffs) if s.action == "monotone piece")
    title = plot_derivative_look(_axes(), monotone, coeffs).get_title()
    assert "cut at the roots of" in title and "monotone piece" not in title  # the cut, not V, makes it monotone
    assert len(mark_roots(_axes(), [0.2, 0.4]).lines) == 1


def test_error_plots_are_logarithmic():
    exact = np.array([0.25, 0.5, 0.75])
    ax = plot_root_errors(_axes(), exact, {"a": exact + 1e-9, "b": np.array([0.25, 0.5 + 1e-3j, 0.75])})
    assert ax.get_yscale() == "log" and len(ax.lines) == 2
    ax = plot_conditioning(_axes(), [2, 3, 4], {"a": [1e-16, 1e-15, 1e-14]}, highlight=3)
    assert ax.get_yscale() == "log" and ax.get_xlabel() == "degree n"

"""cagd_course.widgets, chapter 10: the interpolation explorers and their figures, driven without a browser."""

from types import SimpleNamespace

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.text import Text  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import interpolation as figures  # noqa: E402
from cagd_ref import interpolation as ip  # noqa: E402
from cagd_ref.bezier import de_casteljau  # noqa: E402

NEVILLE = notes_example("10.neville")
FLATTENING = notes_example("10.flattening")


# ---------------------------------------------------------------- the interpolation playground


def test_the_playground_starts_with_the_notes_cubic():
    explorer = widgets.interpolation_explorer(draggable=False)
    state = explorer.state
    example = notes_example("10.cubic_bernstein")
    np.testing.assert_allclose(state["ts"], example.inputs["ts"])
    np.testing.assert_allclose(state["bezier"], example.results["control_points"], atol=1e-12)
    np.testing.assert_allclose(ip.lagrange_eval(state["ts"], state["points"], state["ts"]), state["points"], atol=1e-12)
    assert state["min_basis"] < 0 and "no convex combination" in explorer.readout.value
    assert np.allclose(de_casteljau(state["bezier"], state["grid"]), state["curve"])


@pytest.mark.parametrize("mode", ["uniform", "chord length", "centripetal", "Chebyshev"])
def test_the_playground_parameter_choices(mode):
    explorer = widgets.interpolation_explorer(draggable=False)
    state = explorer.update(parameters=mode)
    points = state["points"]
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    expected = {
        "uniform": np.linspace(0, 1, 4),
        "chord length": np.concatenate([[0], np.cumsum(steps)]),
        "centripetal": np.concatenate([[0], np.cumsum(np.sqrt(steps))]),  # square roots of the chords
        "Chebyshev": ip.chebyshev_nodes(0.0, 1.0, 4),
    }[mode]
    cumulative = mode in ("chord length", "centripetal")
    np.testing.assert_allclose(state["ts"], expected / expected[-1] if cumulative else expected)
    np.testing.assert_allclose(ip.lagrange_eval(state["ts"], points, state["ts"]), points, atol=1e-12)


@pytest.mark.parametrize("values", [{}, {"parameters": "uniform", "highlight": 1}, {"t1": 0.1, "t2": 0.2}])
def test_the_playground_legend_sits_above_the_basis_functions(values):
    explorer = widgets.interpolation_explorer(draggable=False)
    state = explorer.update(**values)
    lower = explorer.lower
    box = lower.get_legend().get_window_extent().transformed(lower.transAxes.inverted())
    low, high = lower.get_ylim()
    peak = (state["basis"].max() - low) / (high - low)  # the highest peak, as a fraction of the axes
    assert peak < box.y0


def test_coinciding_parameters_are_refused_and_rolled_back():
    explorer = widgets.interpolation_explorer(draggable=False)
    with pytest.raises(ValueError, match="^t1..t2: ts: the nodes must be distinct"):
        explorer.update(t1=0.5, t2=0.5)
    assert (explorer.values["t1"], explorer.values["t2"]) == (0.25, 0.75)


def test_dragging_a_node_moves_its_parameter():
    explorer = widgets.interpolation_explorer(draggable=False)
    assert explorer.pick_node(0.26) == 1 and explorer.pick_node(0.5) is None
    assert explorer.pick_node(0.0) is None  # the ends stay where they are
    state = explorer.move_node(2, 0.6)
    assert state["ts"].tolist() == [0.0, 0.25, 0.6, 1.0]
    explorer.update(parameters="uniform")
    state = explorer.move_node(1, 0.1)  # the uniform nodes are copied into the sliders first
    assert explorer.values["parameters"] == "sliders"
    np.testing.assert_allclose(state["ts"], [0.0, 0.1, 2 / 3, 1.0])
    with pytest.raises(ValueError, match="index"):
        explorer.move_node(0, 0.5)


def test_mouse_events_reach_the_right_panel():
    explorer = widgets.interpolation_explorer(draggable=False)
    lower, upper = explorer.lower_axes(), explorer.ax
    explorer.on_press(SimpleNamespace(inaxes=lower, xdata=0.74, ydata=0.0))
    explorer.on_motion(SimpleNamespace(inaxes=lower, xdata=0.55, ydata=0.2))
    explorer.on_release(SimpleNamespace(inaxes=lower, xdata=0.55, ydata=0.2))
    assert explorer.values["t2"] == pytest.approx(0.55)
    explorer.on_press(SimpleNamespace(inaxes=upper, xdata=2.05, ydata=2.0))  # grabs the data point (2, 2)
    explorer.on_motion(SimpleNamespace(inaxes=upper, xdata=3.0, ydata=1.5))
    explorer.on_release(SimpleNamespace(inaxes=upper, xdata=3.0, ydata=1.5))
    np.testing.assert_allclose(explorer.state["points"][1], [3.0, 1.5])
    explorer.on_motion(SimpleNamespace(inaxes=upper, xdata=0.0, ydata=0.0))  # released: nothing follows
    np.testing.assert_allclose(explorer.state["points"][1], [3.0, 1.5])


def test_the_playground_takes_other_point_counts():
    points = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0], [4.0, 0.0]])
    explorer = widgets.interpolation_explorer(points, draggable=False)
    assert [name for name in explorer.controls if name.startswith("t")] == ["t1", "t2", "t3"]
    np.testing.assert_allclose(explorer.state["ts"], np.linspace(0, 1, 5))
    assert explorer.update(highlight=2)["highlight"] == 2


# ---------------------------------------------------------------- Runge's phenomenon


def test_chebyshev_nodes_reach_the_optimum_and_beat_uniform_nodes():
    explorer = widgets.runge_explorer()
    for count in (3, 9, 15):
        state = explorer.update(count=count, spacing="Chebyshev")
        assert state["omega_max"] == pytest.approx(state["optimum"], rel=1e-10)
        assert state["omega_max_uniform"] > state["omega_max_chebyshev"]
        assert len(state["nodes"]) == count


def test_runges_function_diverges_at_uniform_nodes_and_converges_at_chebyshev_nodes():
    explorer = widgets.runge_explorer()
    uniform = [explorer.update(count=n, spacing="uniform")["error"] for n in (5, 11, 21)]
    chebyshev = [explorer.update(count=n, spacing="Chebyshev")["error"] for n in (5, 11, 21)]
    assert uniform[0] < uniform[1] < uniform[2] and uniform[2] > 50
    assert chebyshev[0] > chebyshev[1] > chebyshev[2] and chebyshev[2] < 0.02
    assert explorer.state["lebesgue"] < 3  # Chebyshev's Lebesgue constant grows like log N


@pytest.mark.parametrize("lower", widgets.ch10.LOWER_PANELS)
def test_every_lower_panel_draws(lower):
    explorer = widgets.runge_explorer()
    state = explorer.update(lower=lower, function="exp(x)")
    assert explorer.lower.lines and state["error"] < 1e-8  # exp is interpolated almost exactly by degree 10


# ---------------------------------------------------------------- Neville


def test_neville_explorer_reproduces_the_notes_triangle():
    explorer = widgets.neville_explorer()
    state = explorer.update(tau=2.0, level=3)
    for r in (1, 2, 3):
        np.testing.assert_allclose(state["triangle"][r], NEVILLE.results[f"level_{r}"], atol=1e-12)
    np.testing.assert_allclose(state["row"], notes_example("10.newton_row").results["new_row"], atol=1e-12)
    assert "P<sub>0123</sub> (4.167, 4)" in explorer.readout.value


def test_neville_explorer_steps_level_by_level():
    explorer = widgets.neville_explorer()
    counts = []
    for level in range(4):
        explorer.update(level=level)
        counts.append(len(explorer.ax.lines))
    assert counts[0] < counts[1] < counts[2] < counts[3]
    explorer.update(level=1)
    assert "P<sub>01</sub>" in explorer.readout.value and "P<sub>012</sub>" not in explorer.readout.value


@pytest.mark.parametrize("tau", [-0.5, 0.0, 1.7, 4.0, 4.9])
def test_neville_point_is_the_interpolant_and_newtons_new_row_agrees(tau):
    explorer = widgets.neville_explorer()
    state = explorer.update(tau=tau)
    expected = ip.lagrange_eval(NEVILLE.inputs["ts"], NEVILLE.inputs["points"], tau)
    np.testing.assert_allclose(state["point"], expected, atol=1e-12)
    np.testing.assert_allclose(state["row"][0], expected, atol=1e-12)


# ---------------------------------------------------------------- flattening


def test_flattening_explorer_counts_the_course_cubic():
    explorer = widgets.flattening_explorer()
    for tol, m in zip(FLATTENING.inputs["tolerances"], FLATTENING.results["segments"]):
        state = explorer.update(tol=float(tol))
        assert state["segments"] == m == state["fewest"]  # for this cubic the bound is sharp
        assert state["deviation"] <= state["bound"] <= tol
        assert state["gaps"].max() == pytest.approx(state["deviation"], rel=1e-3)


def test_the_fewest_chords_can_be_fewer_than_the_bound_asks_for():
    # The second differences of this quartic overstate |P''|: the bound is loose, the measurement is not.
    points = [(0.0, 0.0), (1.0, 2.0), (2.0, -2.0), (3.0, 2.0), (4.0, 0.0)]
    state = widgets.flattening_explorer(points).update(tol=0.01)
    assert state["fewest"] < state["segments"]
    assert ip.chord_deviation(points, state["fewest"]) <= 0.01 < ip.chord_deviation(points, state["fewest"] - 1)


# ---------------------------------------------------------------- Hermite


def test_hermite_explorer_defaults_to_the_flattening_cubic_exactly():
    explorer = widgets.hermite_explorer()
    state = explorer.state
    example = notes_example("10.hermite")
    # Exactly, not nearly: the sliders hold the example's tangent components themselves.
    np.testing.assert_array_equal(state["d0"], example.inputs["d0"])
    np.testing.assert_array_equal(state["d1"], example.inputs["d1"])
    np.testing.assert_array_equal(state["bezier"], example.results["bezier"])
    np.testing.assert_allclose(3 * (state["bezier"][1] - state["bezier"][0]), state["d0"])
    np.testing.assert_allclose(state["curve"][[0, -1]], [[0.0, 0.0], [4.0, 0.0]])
    assert "P'(0) = (3, 9), P'(1) = (3, -9)" in explorer.readout.value
    assert "(0, 0) (1, 3) (3, 3) (4, 0)" in explorer.readout.value


def test_hermite_explorer_tangent_of_zero_length():
    state = widgets.hermite_explorer().update(d0x=0.0, d0y=0.0, d1x=0.0, d1y=0.0)
    np.testing.assert_allclose(state["bezier"], [[0, 0], [0, 0], [4, 0], [4, 0]])


def test_hermite_explorer_static_frames_sweep_the_start_tangent_on_whole_and_half_numbers():
    explorer = widgets.hermite_explorer()
    name, frames, start = explorer.static_frames(count=9)
    assert name == "d0y" and frames[start]["label"] == "9.00"
    assert "P'(0) = (3, 9)" in frames[start]["readout"]
    values = [float(frame["label"]) for frame in frames]
    assert all(2 * v == round(2 * v) for v in values)


def test_neville_explorer_keeps_the_labels_of_the_lowest_points_inside_the_frame():
    explorer = widgets.neville_explorer()
    explorer.png()  # draws, so the texts have their places
    ax = explorer.ax
    renderer = ax.figure.canvas.get_renderer()
    frame = ax.get_window_extent(renderer)
    for text in ax.texts:
        box = text.get_window_extent(renderer)
        assert box.y0 > frame.y0 and box.y1 < frame.y1, text.get_text()


# ---------------------------------------------------------------- the figures


@pytest.fixture
def ax():
    return Figure().add_subplot()


def test_labels():
    assert figures.parameter_label(0.25) == "t = 1/4"
    assert figures.parameter_label(0.3171) == "t = 0.317"
    assert figures.parameter_label(2.0, "τ") == "τ = 2"
    assert figures.neville_label(0, 3) == "$P_{0123}$"
    assert figures.neville_label(9, 11) == "$P_{9,10,11}$"


def test_plot_interpolant_passes_through_the_labelled_data(ax):
    example = notes_example("10.cubic_power")
    figures.plot_interpolant(ax, example.inputs["ts"], example.inputs["points"])
    curve, data = ax.lines
    np.testing.assert_allclose(curve.get_xydata()[[0, -1]], example.inputs["points"][[0, -1]])
    np.testing.assert_array_equal(data.get_xydata(), example.inputs["points"])
    assert [t.get_text() for t in ax.texts] == ["t = 0", "t = 1/4", "t = 3/4", "t = 1"]


def test_plot_lagrange_basis_shades_the_negative_part(ax):
    figures.plot_lagrange_basis(ax, [0.0, 0.25, 0.75, 1.0], highlight=1)
    assert len([line for line in ax.lines if line.get_label().startswith("$L_")]) == 4
    assert len(ax.collections) == 1  # the shading of L_1 below zero


def test_plot_node_polynomial_marks_the_maximum(ax):
    nodes = ip.chebyshev_nodes(0.0, 1.0, 9)
    figures.plot_node_polynomial(ax, nodes, 0.0, 1.0)
    levels = sorted(line.get_ydata()[0] for line in ax.lines if line.get_linestyle() == "--")
    assert levels == pytest.approx([-2 / 4**9, 2 / 4**9])


def test_plot_flattening_wants_one_of_tol_and_segments(ax):
    figures.plot_flattening(ax, FLATTENING.inputs["points"], tol=0.1)
    assert len(ax.lines[-1].get_xydata()) == 6  # five chords
    with pytest.raises(ValueError, match="tol, segments"):
        figures.plot_flattening(ax, FLATTENING.inputs["points"])


def test_plot_hermite_needs_planar_data(ax):
    figures.plot_hermite(ax, [0.0, 0.0], [4.0, 0.0], [3.0, 9.0], [3.0, -9.0])
    assert len(ax.patches) == 2  # the two tangent arrows
    with pytest.raises(ValueError, match="planar"):
        figures.plot_hermite(ax, [0.0], [1.0], [1.0], [1.0])


def test_neville_explorer_keeps_the_top_label_clear_of_the_level_below():
    explorer = widgets.neville_explorer()  # τ = 2: P_123, P_0123 and P_012 lie side by side at y = 4
    explorer.png()
    renderer = explorer.ax.figure.canvas.get_renderer()
    boxes = {text.get_text(): Text.get_window_extent(text, renderer) for text in explorer.ax.texts}
    top = boxes.pop("$P_{0123}$")
    for name in ("$P_{123}$", "$P_{012}$"):
        below = boxes[name]
        assert max(below.x0 - top.x1, top.x0 - below.x1, below.y0 - top.y1, top.y0 - below.y1) > 20, name

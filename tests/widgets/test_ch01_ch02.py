"""The explorers of chapters 1 and 2 driven without a browser; what every explorer must do is in test_common.py."""

import matplotlib

matplotlib.use("Agg")

import importlib.util
from types import SimpleNamespace

import ipywidgets
import numpy as np
import pytest

from cagd_course import widgets
from cagd_ref.bezier import curvature, de_casteljau, elevate, evaluate, subdivide
from cagd_ref.continuity import Continuity
from cagd_ref.geometry import rotate_about_axis

CUBIC = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 3.0], [5.0, 1.0]])


def test_update_keeps_omitted_controls_and_rejects_unknown_or_bad_values():
    explorer = widgets.rotation_explorer()
    explorer.update(angle=30.0)
    explorer.update(axis_y=0.5)
    assert explorer.values["angle"] == 30.0
    with pytest.raises(TypeError, match="speed"):
        explorer.update(speed=3)
    with pytest.raises(ValueError, match="angle"):
        explorer.update(axis_x=0.7, angle=500.0)
    assert explorer.values["angle"] == 30.0 and explorer.values["axis_x"] == 0.0
    with pytest.raises(TypeError, match="angle"):
        explorer.update(angle="fast")


def test_integer_controls_reject_fractions():
    explorer = widgets.subdivision_explorer()
    with pytest.raises(TypeError, match="depth"):
        explorer.update(depth=2.5)
    assert explorer.update(depth=2.0)["polygons"].shape[0] == 4


def test_slider_error_is_shown_not_raised():
    explorer = widgets.rotation_explorer()
    with pytest.raises(ValueError, match="axis"):
        explorer.update(axis_x=0.0, axis_y=0.0, axis_z=0.0)
    assert explorer.values["axis_z"] == 1.0  # a rejected update leaves the controls as they were
    explorer.update(axis_x=0.0, axis_y=0.0)
    explorer.controls["axis_z"].value = 0.0
    assert "nonzero" in explorer.readout.value


def test_points_given_to_a_factory_are_not_modified():
    points = CUBIC.copy()
    editor = widgets.control_point_editor(points)
    editor.update(x0=2.0)
    assert np.array_equal(points, CUBIC)


def test_factories_reject_bad_points():
    with pytest.raises(ValueError, match="points"):
        widgets.de_casteljau_explorer(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="index"):
        widgets.rational_weight_explorer(CUBIC, index=7)


# ---------------------------------------------------------------- de Casteljau


@pytest.mark.parametrize("t", [0.0, 0.37, 0.8, 1.0])
def test_de_casteljau_explorer_point_and_halves(t):
    explorer = widgets.de_casteljau_explorer(CUBIC)
    state = explorer.update(t=t)
    assert np.allclose(state["point"], de_casteljau(CUBIC, t))
    s = np.linspace(0, 1, 11)
    assert np.allclose(de_casteljau(state["left"], s), de_casteljau(CUBIC, t * s))
    assert np.allclose(de_casteljau(state["right"], s), de_casteljau(CUBIC, t + (1 - t) * s))


def test_de_casteljau_explorer_extrapolates_only_when_asked():
    with pytest.raises(ValueError, match="t"):
        widgets.de_casteljau_explorer(CUBIC).update(t=1.3)
    explorer = widgets.de_casteljau_explorer(CUBIC, extrapolate=True)
    assert explorer.controls["t"].min == -0.5 and explorer.controls["t"].max == 1.5
    state = explorer.update(t=1.3)
    assert np.allclose(state["point"], de_casteljau(CUBIC, 1.3))
    assert np.allclose(state["left"][-1], state["point"])


def _view(explorer):
    """The drawn limits (x0, x1, y0, y1) after the figure has been rendered (equal aspect applied)."""
    explorer.png()
    return (*explorer.ax.get_xlim(), *explorer.ax.get_ylim())


def test_de_casteljau_explorer_fits_the_view_to_the_triangle():
    explorer = widgets.de_casteljau_explorer(CUBIC, extrapolate=True)
    explorer.update(t=0.5)
    x0, x1, y0, y1 = _view(explorer)
    low, high = CUBIC.min(axis=0), CUBIC.max(axis=0)
    assert x0 < low[0] and high[0] < x1 and y0 < low[1] and high[1] < y1
    # the dotted extension over [-0.5, 1.5] reaches y = -6; the view stays near the polygon
    assert (x1 - x0) < 2 * (high - low).max() and (y1 - y0) < 2 * (high - low).max()
    # extrapolating, the view grows to hold the point P(t) outside the polygon
    state = explorer.update(t=1.5)
    x0, x1, y0, y1 = _view(explorer)
    assert x0 < state["point"][0] < x1 and y0 < state["point"][1] < y1


# ---------------------------------------------------------------- control point editor


def test_editor_sliders_are_the_control_points():
    editor = widgets.control_point_editor(CUBIC)
    assert list(editor.controls) == ["x0", "y0", "x1", "y1", "x2", "y2", "x3", "y3"]
    state = editor.update(x2=4.0, y2=-1.0)
    expected = CUBIC.copy()
    expected[2] = [4.0, -1.0]
    assert np.array_equal(state["points"], expected)
    assert np.allclose(state["curve"], evaluate(expected, np.linspace(0, 1, len(state["curve"]))))


def test_editor_with_weights_draws_the_rational_curve():
    weights = np.array([1.0, 2.0, 0.5, 1.0])
    state = widgets.control_point_editor(CUBIC, weights).update(y1=2.0)
    ts = np.linspace(0, 1, len(state["curve"]))
    assert np.allclose(state["curve"], evaluate(state["points"], ts, weights))


def test_pick_finds_the_nearest_point_within_the_radius():
    editor = widgets.control_point_editor(CUBIC, draggable=False)
    assert editor.pick(2.9, 3.1) == 2
    assert editor.pick(2.0, 3.0, radius=0.1) is None
    assert editor.pick(2.0, 3.0, radius=1.5) in (1, 2)


def test_mouse_drag_moves_only_the_grabbed_point():
    editor = widgets.control_point_editor(CUBIC, draggable=False)

    def event(x, y):
        return SimpleNamespace(inaxes=editor.ax, xdata=x, ydata=y)

    editor.on_press(event(1.05, 2.95))
    editor.on_motion(event(1.5, 1.0))
    editor.on_motion(event(2.0, 0.5))
    editor.on_release(event(2.0, 0.5))
    editor.on_motion(event(4.0, 4.0))  # released: no longer dragging
    expected = CUBIC.copy()
    expected[1] = [2.0, 0.5]
    assert np.allclose(editor.state["points"], expected)
    assert editor.values["x1"] == 2.0 and editor.values["y1"] == 0.5
    # A press far from every point grabs nothing.
    editor.on_press(event(10.0, -10.0))
    editor.on_motion(event(0.0, 0.0))
    assert np.allclose(editor.state["points"], expected)


def test_move_point_is_clamped_to_the_slider_range():
    editor = widgets.control_point_editor(CUBIC, draggable=False)
    state = editor.move_point(0, 1e6, -1e6)
    assert state["points"][0].tolist() == [editor.limits[1], editor.limits[0]]
    with pytest.raises(ValueError, match="index"):
        editor.move_point(4, 0, 0)


@pytest.mark.skipif(importlib.util.find_spec("ipympl") is None, reason="ipympl not installed")
@pytest.mark.filterwarnings("ignore:Passing unrecognized arguments:DeprecationWarning")  # inside ipympl's toolbar
def test_draggable_editor_uses_an_ipympl_canvas_and_leaves_the_backend_alone():
    backend = matplotlib.get_backend()
    editor = widgets.control_point_editor(CUBIC, draggable=True)
    assert type(editor.view).__module__.startswith("ipympl")
    assert matplotlib.get_backend() == backend
    state = editor.move_point(3, 4.0, 2.0)
    assert state["points"][3].tolist() == [4.0, 2.0]
    assert editor.png()[:4] == b"\x89PNG"


# ---------------------------------------------------------------- rational weights


def test_rational_weight_explorer_curve_and_weights():
    explorer = widgets.rational_weight_explorer(CUBIC, index=1)
    state = explorer.update(weight=4.0)
    assert state["weights"].tolist() == [1.0, 4.0, 1.0, 1.0]
    ts = np.linspace(0, 1, len(state["curve"]))
    assert np.allclose(state["curve"], evaluate(CUBIC, ts, state["weights"]))
    assert explorer.update(weight=1.0)["curve"] == pytest.approx(evaluate(CUBIC, ts))


def test_rational_family_is_pulled_towards_the_weighted_point():
    assert widgets.rational_weight_explorer(CUBIC).index == 1  # a middle point by default
    explorer = widgets.rational_weight_explorer(CUBIC, index=2)
    family = explorer.state["family"]
    assert tuple(family) == (0.0, 0.5, 1.0, 2.0, 5.0, 10.0)
    gaps = [np.min(np.linalg.norm(curve - CUBIC[2], axis=1)) for curve in family.values()]
    assert all(a > b for a, b in zip(gaps, gaps[1:]))
    # Weight 0 ignores P2 altogether: the curve is the weighted mix of the other three points.
    k = len(family[0.0]) // 2
    t = k / (len(family[0.0]) - 1)
    b = np.array([(1 - t) ** 3, 3 * t * (1 - t) ** 2, 0.0, t**3])
    assert np.allclose(family[0.0][k], b @ CUBIC / b.sum())


def test_weight_slider_is_logarithmic():
    explorer = widgets.rational_weight_explorer()
    assert isinstance(explorer.controls["weight"], ipywidgets.FloatLogSlider)
    explorer.update(weight=0.01)
    explorer.update(weight=100.0)
    with pytest.raises(ValueError, match="weight"):
        explorer.update(weight=0.0)


# ---------------------------------------------------------------- convergence


def test_degree_elevation_polygon_and_shrinking_distance():
    explorer = widgets.degree_elevation_explorer(CUBIC)
    distances = []
    for steps in range(0, 21):
        state = explorer.update(steps=steps)
        assert np.allclose(state["polygon"], elevate(CUBIC, steps))
        distances.append(state["distance"])
    assert all(a > b for a, b in zip(distances, distances[1:]))
    assert distances[-1] < distances[0] / 3


def test_vertex_distance_is_zero_on_the_curve_and_exact_off_it():
    line = np.array([[0.0, 0.0], [2.0, 0.0]])
    assert widgets.vertex_distance([[0.5, 0.0], [1.7, 0.0]], line) == pytest.approx(0.0, abs=1e-12)
    assert widgets.vertex_distance([[0.5, 0.3], [1.0, -0.2]], line) == pytest.approx(0.3)
    assert widgets.vertex_distance([[3.0, 0.0]], line) == pytest.approx(1.0)


def test_subdivide_all_matches_subdivide_and_the_curve():
    left, right = subdivide(CUBIC, 0.5)
    assert np.allclose(widgets.subdivide_all(CUBIC, 1), [left, right])
    pieces = widgets.subdivide_all(CUBIC, 3)
    assert pieces.shape == (8, 4, 2)
    s = np.linspace(0, 1, 5)
    for i, piece in enumerate(pieces):
        assert np.allclose(de_casteljau(piece, s), de_casteljau(CUBIC, (i + s) / 8))


def test_subdivision_explorer_leaves_room_above_the_top_control_point():
    explorer = widgets.subdivision_explorer(CUBIC)
    explorer.update(depth=1)
    _, _, _, y1 = _view(explorer)
    assert y1 >= CUBIC[:, 1].max() + 0.1 * np.ptp(CUBIC, axis=0).max()


def test_subdivision_explorer_polygon_count_and_shrinking_distance():
    explorer = widgets.subdivision_explorer(CUBIC)
    distances = []
    for depth in range(7):
        state = explorer.update(depth=depth)
        assert state["polygons"].shape == (2**depth, 4, 2)
        distances.append(state["distance"])
    assert all(a > b for a, b in zip(distances, distances[1:]))
    # Midpoint subdivision converges quadratically: each halving divides the gap by about four.
    assert distances[6] < distances[5] / 3


# ---------------------------------------------------------------- curvature comb


def test_comb_teeth_are_proportional_to_curvature():
    explorer = widgets.curvature_comb_explorer(CUBIC)
    state = explorer.update(teeth=25, length=2.0)
    ts = np.linspace(0, 1, 25)
    kappa = curvature(CUBIC, ts)
    assert np.allclose(state["bases"], evaluate(CUBIC, ts))
    lengths = np.linalg.norm(state["tips"] - state["bases"], axis=1)
    assert np.allclose(lengths, 2.0 * kappa / kappa.max())
    assert state["max_curvature"] == pytest.approx(kappa.max())


def test_comb_teeth_point_away_from_the_centre_of_curvature():
    # This cubic bends downwards (turns right), so the centre is below and teeth point up.
    state = widgets.curvature_comb_explorer(CUBIC).update(teeth=9)
    assert np.all(state["tips"][1:-1, 1] > state["bases"][1:-1, 1])


# ---------------------------------------------------------------- continuity


def _c2_q2(explorer):
    """Q2 that makes the default h = 1 joint C2: Q2 - 2Q1 + Q0 = P3 - 2P2 + P1."""
    p, q = explorer.state["p"], explorer.state["q"]
    return 2 * q[1] - q[0] + p[3] - 2 * p[2] + p[1]


def test_continuity_starts_c1_at_a_collinear_equal_length_joint():
    explorer = widgets.continuity_explorer()
    state = explorer.state
    p, q = state["p"], state["q"]
    assert np.allclose(q[0], p[3])
    assert np.allclose(q[1] - q[0], p[3] - p[2])
    assert state["continuity"].parametric == 1
    assert state["text"] == str(state["continuity"])
    assert state["text"].startswith("C1")


def test_continuity_orders_drop_when_the_joint_is_broken():
    explorer = widgets.continuity_explorer()
    q1 = explorer.state["q"][1]
    # A longer interval for Q with the same control points: same tangent direction, slower.
    assert explorer.update(h=2.0)["continuity"] == Continuity(0, 1)
    # Stretching the first leg by h restores C1.
    p = explorer.state["p"]
    stretched = p[3] + 2.0 * (p[3] - p[2])
    assert explorer.update(q1x=stretched[0], q1y=stretched[1])["continuity"].parametric == 1
    # Q1 off the tangent line: only G0 / C0.
    state = explorer.update(h=1.0, q1x=q1[0], q1y=q1[1] + 1.0)
    assert state["continuity"] == Continuity(0, 0)
    assert state["text"] == "C0, G0"


def test_continuity_reaches_c2_and_reparametrising_keeps_g2():
    explorer = widgets.continuity_explorer()
    q2 = _c2_q2(explorer)
    state = explorer.update(q2x=q2[0], q2y=q2[1])
    assert state["continuity"] == Continuity(2, 2)
    assert state["text"] == "C2, G2"
    # The same control points over [1, 3] trace the same curve: still G2, only C0.
    assert explorer.update(h=2.0)["text"] == "C0, G2"


# ---------------------------------------------------------------- rotation


@pytest.mark.parametrize(
    "angle, axis", [(0.0, (0, 0, 1)), (90.0, (0, 0, 1)), (-135.0, (1, 0.5, -0.3)), (45.0, (0.2, -1, 0.4))]
)
def test_rotation_explorer_matches_rotate_about_axis(angle, axis):
    explorer = widgets.rotation_explorer()
    state = explorer.update(angle=angle, axis_x=axis[0], axis_y=axis[1], axis_z=axis[2])
    original = state["original"]
    expected = rotate_about_axis(original, [0, 0, 0], axis, np.radians(angle))
    assert np.allclose(state["point"], expected)
    assert np.allclose(state["matrix"] @ np.append(original, 1.0), np.append(expected, 1.0))
    # The point travels on the circle around C in the plane perpendicular to the axis.
    radius = np.linalg.norm(original - state["center"])
    assert np.allclose(np.linalg.norm(state["circle"] - state["center"], axis=1), radius)
    assert np.allclose((state["circle"] - state["center"]) @ state["axis"], 0.0)
    assert np.allclose(state["arc"][0], original) and np.allclose(state["arc"][-1], state["point"])


def test_rotation_about_z_by_90_degrees_is_a_quarter_turn():
    state = widgets.rotation_explorer().update(angle=90.0, axis_x=0.0, axis_y=0.0, axis_z=1.0)
    x, y, z = state["original"]
    assert np.allclose(state["point"], [-y, x, z])


def test_rotation_explorer_opens_on_the_given_axis_and_angle():
    # The chapter opens it on the notes' example: (5, 7, 3) a quarter turn about (1, 1, 1) + s (2, 1, 2).
    explorer = widgets.rotation_explorer(point=(5, 7, 3), axis_point=(1, 1, 1), axis_direction=(2, 1, 2), angle=90)
    assert explorer.values == {"angle": 90.0, "axis_x": 2.0, "axis_y": 1.0, "axis_z": 2.0}
    assert np.allclose(explorer.state["point"], [5 / 3, 13 / 3, 23 / 3])
    assert np.allclose(explorer.state["center"], [5, 3, 5])
    with pytest.raises(ValueError, match="axis_direction"):
        widgets.rotation_explorer(axis_direction=(0, 0, 0))
    with pytest.raises(ValueError, match="axis_direction"):
        widgets.rotation_explorer(axis_direction=(4, 0, 0))  # beyond the sliders
    with pytest.raises(ValueError, match="angle"):
        widgets.rotation_explorer(angle=270)


# ---------------------------------------------------------------- conics


@pytest.mark.parametrize(
    "coefficients, kind, discriminant",
    [
        (dict(a=1.0, b=0.0, c=1.0, d=0.0, e=0.0, f=-1.0), "ellipse", -4.0),
        (dict(a=1.0, b=0.0, c=0.0, d=0.0, e=-1.0, f=0.0), "parabola", 0.0),
        (dict(a=0.0, b=1.0, c=0.0, d=0.0, e=0.0, f=-1.0), "hyperbola", 1.0),
    ],
)
def test_conic_explorer_classifies(coefficients, kind, discriminant):
    explorer = widgets.conic_explorer()
    state = explorer.update(**coefficients)
    assert state["type"] == kind
    assert state["discriminant"] == pytest.approx(discriminant)
    assert kind in explorer.readout.value
    assert len(explorer.ax.collections) == 1  # the zero set is drawn


def test_conic_explorer_without_quadratic_terms_is_not_a_conic():
    state = widgets.conic_explorer().update(a=0.0, b=0.0, c=0.0, d=1.0, e=1.0, f=0.0)
    assert "not a conic" in state["type"]

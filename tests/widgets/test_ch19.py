"""cagd_course.widgets, chapter 19: the double-point classifier, the pencil parametrization and the silhouette."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from numpy.polynomial import polynomial as P  # noqa: E402

from cagd_course import widgets  # noqa: E402
from cagd_course.book.build import DEFAULT_FRAMES  # noqa: E402
from cagd_course.examples import notes_example  # noqa: E402
from cagd_course.plotting import singular_points as figures  # noqa: E402
from cagd_course.widgets._static import _sweep  # noqa: E402
from cagd_course.widgets.ch19 import CURVES, SILHOUETTES  # noqa: E402
from cagd_ref import algebra  # noqa: E402


@pytest.mark.parametrize("k, kind, lines", [(3.0, "crunode", 2), (0.0, "cusp", 1), (-3.0, "acnode", 0)])
def test_the_classifier_passes_through_the_three_kinds(k, kind, lines):
    state = widgets.double_point_kind_explorer().update(k=k)
    assert state["kind"] == kind and len(state["directions"]) == lines
    assert np.sign(state["discriminant"]) == np.sign(k)


def test_the_classifier_reproduces_figures_19_3_and_19_4():
    explorer = widgets.double_point_kind_explorer()
    for k, name in ((0.0, "19.cusp"), (-3.0, "19.acnode")):
        state = explorer.update(k=k)
        example = notes_example(name)
        assert np.allclose(state["c"], example.inputs["c"])
        assert state["kind"] == example.results["kind"]


@pytest.mark.parametrize("curve", list(CURVES))
def test_every_pencil_point_lies_on_the_curve_and_the_line(curve):
    explorer = widgets.pencil_parametrization_explorer(curve)
    for t in (-2.5, -0.4, 0.3, 1.7):
        state = explorer.update(t=t)
        if state["xy"] is None:
            continue
        assert abs(state["residual"]) < 1e-10
        x0, y0 = state["point"]
        assert state["xy"][1] - y0 == pytest.approx(t * (state["xy"][0] - x0), abs=1e-9)


def test_the_pencil_explorer_starts_on_figure_19_6():
    example = notes_example("19.circle_pencil")
    explorer = widgets.pencil_parametrization_explorer()
    for t, point in zip(example.inputs["t"], example.results["points"]):
        assert np.allclose(explorer.update(t=float(t))["xy"], point)
    assert np.allclose(explorer.state["xyw"], example.results["pencil"])


def test_the_silhouette_roots_are_vertical_tangents_and_the_double_point():
    explorer = widgets.silhouette_explorer()
    state = explorer.state
    example = notes_example("19.silhouette")
    assert np.allclose(state["discriminant"], example.results["discriminant"])
    assert np.allclose(state["roots"], sorted([2.0, *example.results["vertical_tangents"]]), atol=1e-9)
    assert state["multiplicities"] == [1, 2, 1]
    turned = explorer.update(angle=40.0)
    assert len(turned["roots"]) == 3
    for x in turned["roots"]:
        column = P.polyval(x, turned["c"])  # f(x, y) as a polynomial in y has a double root there
        assert len(algebra.poly_gcd(column, P.polyder(column), tol=1e-5)) >= 2
    assert len(explorer.figure.axes) == 2
    assert set(SILHOUETTES) == set(explorer.controls["curve"].options)


def _static_angles(explorer) -> list[float]:
    """The angles of the static figure's frames in the book (its slider swept over DEFAULT_FRAMES values)."""
    return [float(a) for a in _sweep(explorer.controls["angle"], DEFAULT_FRAMES)]


# the turns at which a tangent at the double point is vertical, next to them, and a few others
MORE_ANGLES = [-90.0 + 1e-9, -63.43494882292201, -56.309932474020215, -49.10660535086906, -1.0, 1.0, 13.0, 49.1066,
               77.0, 89.0]


@pytest.mark.parametrize("curve", [name for name, item in SILHOUETTES.items() if item[3] is not None])
def test_every_frame_shows_the_double_point_over_a_double_root_and_nothing_spurious(curve):
    explorer = widgets.silhouette_explorer(curve)
    base, centre, _, double_point, _ = SILHOUETTES[curve]
    angles = _static_angles(explorer)
    assert len(angles) >= 21 and -90.0 in angles and 90.0 in angles
    for angle in angles + MORE_ANGLES:
        state = explorer.compute(angle=angle, curve=curve, view="whole curve")
        phi = np.radians(angle)
        # the double point turned about the centre, computed here on its own: x0 + cos φ (x - x0) - sin φ (y - y0)
        x_double = centre[0] + np.cos(phi) * (double_point[0] - centre[0]) - np.sin(phi) * (double_point[1] - centre[1])
        # exactly 4, as SymPy finds for exact rotations (below); the crunode untouched has degree 3, 576x²(x + 9)
        degree = 3 if curve.startswith("crunode") and angle == 0.0 else 4
        assert len(state["discriminant"]) - 1 == degree, angle
        roots, multiplicities = state["roots"], state["multiplicities"]
        assert sum(multiplicities) <= degree and np.all(np.diff(roots) > 0)
        k = int(np.argmin(np.abs(roots - x_double)))
        assert roots[k] == pytest.approx(x_double, abs=1e-12) and multiplicities[k] >= 2, angle
        for x in roots:  # each a vertical tangent or the double point: f(x, ·) and f_y(x, ·) share a y there
            column = P.polyval(x, state["c"])
            assert len(algebra.poly_gcd(column, P.polyder(column), tol=1e-6)) >= 2, (angle, x)
            # the cubic's vertical tangents stay within |x| < 70; the crunode's third one runs off to infinity as
            # the turn goes to 0 (its resultant's leading coefficient with it), 5831 at 1°
            assert abs(x) < (100.0 if curve == "cubic of §19.5" else 1e4), (angle, x)
        readout = explorer.describe(state)
        assert f"degree {degree};" in readout and "-" not in readout
        assert f"{x_double:.4g}".replace("-", "−") + " (double)" in readout or multiplicities[k] > 2


def _exact_real_roots(curve: str, cos: sp.Rational, sin: sp.Rational) -> tuple[int, list[tuple[float, int]]]:
    """The degree of Res_y(f, f_y) of the curve turned exactly by (cos, sin) about its centre, and its real roots."""
    x, y = sp.symbols("x y")
    base, centre, *_ = SILHOUETTES[curve]
    f = sum(sp.Integer(int(v)) * x**i * y**j for (i, j), v in np.ndenumerate(base))
    cx, cy = (sp.nsimplify(v) for v in centre)
    turned = sp.expand(f.subs({x: cos * (x - cx) + sin * (y - cy) + cx, y: -sin * (x - cx) + cos * (y - cy) + cy},
                              simultaneous=True))
    r = sp.Poly(sp.resultant(turned, sp.diff(turned, y), y), x)
    roots = sp.real_roots(r)
    return r.degree(), [(float(v), roots.count(v)) for v in sorted(set(roots), key=float)]


@pytest.mark.parametrize("curve", ["cubic of §19.5", "crunode x³ + 9x² − 12y² (Fig. 19.2)"])
@pytest.mark.parametrize("cos, sin", [(sp.Rational(4, 5), sp.Rational(3, 5)), (sp.Rational(12, 13), sp.Rational(5, 13)),
                                      (sp.Rational(3, 5), sp.Rational(-4, 5)), (sp.Integer(0), sp.Integer(1))])
def test_the_silhouette_roots_are_the_exact_real_roots(curve, cos, sin):
    degree, exact = _exact_real_roots(curve, cos, sin)
    state = widgets.silhouette_explorer(curve, angle=float(np.degrees(np.arctan2(float(sin), float(cos))))).state
    assert len(state["discriminant"]) - 1 == degree == 4
    assert state["multiplicities"] == [m for _, m in exact]
    assert np.allclose(state["roots"], [v for v, _ in exact], rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("curve", list(SILHOUETTES))
@pytest.mark.parametrize("view", ["whole curve", "zoom on the double point"])
def test_the_silhouette_panels_share_their_x_axis_pixel_for_pixel(curve, view):
    explorer = widgets.silhouette_explorer(curve, angle=24.0, view=view)
    upper, lower = explorer.ax, explorer.lower
    explorer.figure.canvas.draw()
    xs = np.linspace(*upper.get_xlim(), 7)
    columns = [ax.transData.transform(np.column_stack([xs, np.zeros_like(xs) + ax.get_ylim()[0]]))[:, 0]
               for ax in (upper, lower)]
    assert np.allclose(*columns, atol=0.5)  # the dashed line at a root stands at one pixel column in both panels
    assert upper.get_xlim() == pytest.approx(lower.get_xlim())
    assert upper.get_position().x0 == pytest.approx(lower.get_position().x0)
    assert upper.get_position().width == pytest.approx(lower.get_position().width)


def test_the_zoom_follows_the_turned_double_point():
    explorer = widgets.silhouette_explorer("crunode x³ + 9x² − 12y² (Fig. 19.2)", angle=40.0,
                                           view="zoom on the double point")
    state = explorer.state
    assert state["zoom"]
    assert abs(P.polyval2d(*state["double_point"], state["c"])) < 1e-9  # still on the turned curve
    (x0, x1), (y0, y1) = state["box"]
    assert x0 < state["double_point"][0] < x1 and y0 < state["double_point"][1] < y1
    circle = explorer.update(curve="circle of Fig. 19.5")
    assert circle["double_point"] is None and not circle["zoom"]  # nothing to zoom on: the whole circle


def test_the_discriminant_panel_is_on_a_symmetric_log_scale():
    explorer = widgets.silhouette_explorer()
    assert explorer.lower.get_yscale() == "symlog"
    ax = Figure().add_subplot()
    figures.plot_discriminant(ax, notes_example("19.silhouette").results["discriminant"], (-3, 7), scale="linear")
    assert ax.get_yscale() == "linear"
    with pytest.raises(ValueError, match="^scale"):
        figures.plot_discriminant(ax, [1.0, 2.0], (0, 1), scale="log")


def test_fill_equal_keeps_the_box_and_widens_one_side():
    fig = Figure(figsize=(6.0, 3.0))
    ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
    (x0, x1), (y0, y1) = figures.fill_equal(ax, (0.0, 2.0), (0.0, 2.0))  # a wide box: x grows
    assert (y0, y1) == (0.0, 2.0) and x1 - x0 == pytest.approx(4.0) and (x0 + x1) / 2 == pytest.approx(1.0)
    (x0, x1), (y0, y1) = figures.fill_equal(ax, (0.0, 10.0), (0.0, 1.0))  # a flat box: y grows
    assert (x0, x1) == (0.0, 10.0) and y1 - y0 == pytest.approx(5.0)


@pytest.mark.parametrize("name, through", [("cusp x³ − 3y² (Fig. 19.3)", "0 (twice)"),
                                           ("acnode x³ − 3x² − 3y² (Fig. 19.4)", "−1i, 1i")])
def test_the_pencil_explorer_shows_where_cusp_and_acnode_are_reached(name, through):
    explorer = widgets.pencil_parametrization_explorer(name, t=0.5)
    example = notes_example("19.cusp" if "cusp" in name else "19.acnode")
    assert np.allclose(explorer.state["xyw"], example.results["pencil"])
    assert through in explorer.readout.value


def test_figures_check_their_axes_and_break_at_poles():
    ax = Figure().add_subplot()
    figures.plot_parametrization(ax, notes_example("19.cubic_pencil").results["pencil"], (-3, 3))
    xs = ax.lines[0].get_xdata()
    assert np.isnan(xs).any()  # W(t) = 1 + 2t + 3t² + 4t³ changes sign once
    with pytest.raises(TypeError, match="^ax"):
        figures.plot_curve(None, [[0, 1], [1, 0]], (0, 1), (0, 1))
    with pytest.raises(ValueError, match="^c"):
        figures.plot_curve(ax, [1.0, 2.0], (0, 1), (0, 1))


def test_the_readouts_use_the_chapter_s_letters_and_readable_formulas():
    classifier = widgets.double_point_kind_explorer(k=3.0)
    assert "f̂₂(a, b) = 3a² − 3b²" in classifier.readout.value and "g₂" not in classifier.readout.value
    pencil = widgets.pencil_parametrization_explorer()
    assert "x(t) = 2 / (1 + t²),  y(t) = 2t / (1 + t²)" in pencil.readout.value
    assert "the parametrization reaches (x0, y0) itself at t = ∞ only" in pencil.readout.value
    cubic = widgets.pencil_parametrization_explorer("cubic with coefficients 1…7 (§19.5)")
    assert "x(t) = (−5 − 6t − 7t²) / (1 + 2t + 3t² + 4t³)" in cubic.readout.value
    assert "x³ + 2x²y + 3xy² + 4y³ + 5x² + 6xy + 7y² = 0" in cubic.readout.value
    silhouette = widgets.silhouette_explorer()
    assert "Res_y(f, ∂f/∂y)" in silhouette.readout.value and "D(x)" not in silhouette.readout.value
    assert "degree 4; real roots x = −0.1126, 2 (double), 2.631" in silhouette.readout.value
    acnode = widgets.double_point_kind_explorer(k=-4.0)  # B² − 4AC = 12k, with the minus sign, not a hyphen
    assert "B² − 4AC = −48:" in acnode.readout.value and "-" not in acnode.readout.value
    for name in CURVES:  # negative numbers with the minus sign in the pencil's readout too
        readout = widgets.pencil_parametrization_explorer(name, t=-1.5).readout.value
        assert "t = −1.50:" in readout and "-" not in readout


def test_a_curve_s_legend_entry_has_its_line_style():
    ax = Figure().add_subplot()
    figures.plot_curve(ax, [[0.0, -1.0], [0.0, 0.0], [1.0, 0.0]], (-2, 2), (-1, 3), colors="0.5", linewidths=1.0,
                       linestyles=":", label="y = x²")
    (entry,) = [line for line in ax.lines if line.get_label() == "y = x²"]
    assert entry.get_linestyle() == ":" and entry.get_linewidth() == 1.0
    solid = Figure().add_subplot()
    figures.plot_curve(solid, [[0.0, -1.0], [0.0, 0.0], [1.0, 0.0]], (-2, 2), (-1, 3), label="y = x²")
    assert solid.lines[0].get_linestyle() == "-"


def test_the_pencil_explorer_draws_every_t_and_names_the_centre():
    explorer = widgets.pencil_parametrization_explorer()  # the circle: (0, 0) is a simple point, reached at t = ∞
    (curve,) = [line for line in explorer.ax.lines if line.get_label() == "(X(t)/W(t), Y(t)/W(t))"]
    xy = np.column_stack([curve.get_xdata(), curve.get_ydata()])
    xy = xy[np.isfinite(xy).all(axis=1)]
    assert np.linalg.norm(xy, axis=1).min() < 1e-6  # no gap next to the centre
    assert np.linalg.norm(np.diff(xy, axis=0), axis=1).max() < 0.05
    assert "the pencil's centre (x0, y0) = (0, 0), a point of multiplicity n − 1" in explorer.readout.value
    assert "singular point" not in explorer.readout.value


def test_plot_parametrization_over_the_whole_line_matches_the_finite_range():
    rows = notes_example("19.circle_pencil").results["pencil"]
    whole, part = Figure().add_subplot(), Figure().add_subplot()
    figures.plot_parametrization(whole, rows, None, samples=2001)
    figures.plot_parametrization(part, rows, (-3, 3))
    drawn = np.column_stack([whole.lines[0].get_xdata(), whole.lines[0].get_ydata()])
    assert np.allclose((drawn[:, 0] - 1) ** 2 + drawn[:, 1] ** 2, 1)  # every sample on the circle
    assert np.allclose(drawn[0], [0, 0]) and np.allclose(drawn[1000], [2, 0])  # t = ∞ and t = 0
    assert np.allclose((part.lines[0].get_xdata()[0], part.lines[0].get_ydata()[0]), [0.2, -0.6])
    with pytest.raises(ValueError, match="^xyw"):
        figures.plot_parametrization(whole, [[1.0, 0.0], [0.0, 1.0]], None)


@pytest.mark.parametrize("curve", list(SILHOUETTES))
@pytest.mark.parametrize("angle", [-60.0, 0.0, 30.0, 90.0])
def test_the_silhouette_legend_sits_where_the_curve_is_not(curve, angle):
    explorer = widgets.silhouette_explorer(curve, angle=angle)
    ax = explorer.ax
    explorer.figure.canvas.draw()
    box = ax.get_legend().get_window_extent().transformed(ax.transAxes.inverted())
    to_axes = ax.transData + ax.transAxes.inverted()
    vertices = np.concatenate([to_axes.transform(p.vertices) for a in ax.collections for p in a.get_paths()
                               if len(p.vertices)])
    covered = ((vertices[:, 0] > box.x0) & (vertices[:, 0] < box.x1)
               & (vertices[:, 1] > box.y0) & (vertices[:, 1] < box.y1))
    assert covered.mean() < 0.01

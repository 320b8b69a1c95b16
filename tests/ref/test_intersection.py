"""Unit tests of cagd_ref.intersection: lines, substitution, subdivision and Bézier clipping (chapter 7).

Each function is checked against the notes' worked examples (read from
cagd_course/examples/ch07.toml), against properties (the circle through the
circular points, a fat line holds its curve, a clip never cuts away a point of
the curve that lies in the band, the V rule never clips more than the hull),
and against independent peers: exact fractions for the clipping examples,
SymPy resultants and the `bezier` package for the intersections, SciPy's
linear programming for the hull of a clip. `intersect_curves` runs one of two
engines, Bézier clipping on Python floats (`_clipping`, polynomial curves of
low degree) or the batched NumPy search (rational curves, high degrees); both
are checked against each other and against the plain one-pair-at-a-time
stepper of `clip_trace`, and their results against 50-digit Newton solutions
(mpmath) at tol 1e-9, 1e-12 and 1e-14. The `bezier` package's functional suite
is run in test_intersection_suite.py.
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import linprog

from cagd_course.examples import notes_example
from cagd_ref import intersection as x
from cagd_ref.bezier import endpoint_curvature, evaluate, signed_curvature, subdivide
from cagd_ref.polynomials import bernstein_horner, power_to_bernstein

UNIT_CIRCLE = np.array([[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])
OTHER_ALGORITHMS = [x.intersect_by_subdivision, x.intersect_by_intervals, x.intersect_by_implicitization]


def example(name: str):
    return notes_example(f"07.{name}")


def test_every_public_name_is_tested():
    # Each name has at least one test below; keep this list in step with the module.
    tested = {
        "homogeneous_circle_point", "circle_conic", "line_intersection", "project", "implicit_polynomial",
        "curve_implicit_bernstein", "curve_implicit_intersection", "osculating_circle_curvature", "flatness",
        "intersect_by_subdivision", "monotone_breaks", "intersect_by_intervals", "implicit_by_nullspace",
        "intersect_by_implicitization", "fat_line", "perpendicular_fat_line", "clip_range", "clip_curve",
        "homogeneous_fat_line", "explicit_meets", "clip_one_sided", "clip_trace", "search_steps", "curve_piece",
        "intersect_curves", "bezier_clipping", "merge_touching",
    }
    assert set(x.__all__) == tested


# --- §7.1 homogeneous coordinates and parameters ----------------------------------------------------


def test_the_four_quadrant_rules_sweep_the_circle():
    ex = example("circle_parameters")
    for quadrant in ("first", "second", "third", "fourth"):
        T, U = ex.args(f"{quadrant}_T", f"{quadrant}_U")
        np.testing.assert_allclose(x.homogeneous_circle_point(T, U), ex.results[quadrant], atol=1e-15)
    # The rule the notes lost: T = -1, U from 0 to 1 stays in the third quadrant.
    third = x.homogeneous_circle_point(-1.0, np.linspace(0.0, 1.0, 21))
    assert np.all(third <= 1e-15) and np.allclose(np.hypot(*third.T), 1)


def test_homogeneous_parameters_agree_with_the_rational_parameter_and_reject_zero():
    t = np.linspace(-3, 3, 13)
    rational = np.column_stack([(1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)])  # (7.2)
    np.testing.assert_allclose(x.homogeneous_circle_point(t, 1.0), rational, atol=1e-15)
    np.testing.assert_allclose(x.homogeneous_circle_point(2 * t, 2.0), rational, atol=1e-15)  # only T/U matters
    assert x.homogeneous_circle_point(0.5, 1.0).shape == (2,)
    with pytest.raises(ValueError, match="^T, U"):
        x.homogeneous_circle_point(0.0, 0.0)


def test_every_circle_passes_through_the_circular_points():
    rng = np.random.default_rng(71)
    for _ in range(10):
        f = x.circle_conic(rng.uniform(-5, 5, 2), rng.uniform(0.1, 4))
        for X, Y, W in [(1, 1j, 0), (1, -1j, 0)]:
            value = sum(f[i, j] * X**i * Y**j * W ** (2 - i - j) for i in range(3) for j in range(3 - i))
            assert abs(value) < 1e-12
    # ... and through its own points: (xc + r cos θ, yc + r sin θ).
    f = x.circle_conic([1.0, -2.0], 3.0)
    theta = np.linspace(0, 2 * np.pi, 9)
    px, py = 1 + 3 * np.cos(theta), -2 + 3 * np.sin(theta)
    assert np.allclose(sum(f[i, j] * px**i * py**j for i in range(3) for j in range(3)), 0)
    with pytest.raises(ValueError, match="^radius"):
        x.circle_conic([0.0, 0.0], 0.0)


# --- §7.2 lines ------------------------------------------------------------------------------------------


def test_meet_and_parallel_lines_of_the_notes():
    meet, parallel = example("meet"), example("parallel")
    point = x.line_intersection(*meet.args("l1", "l2"))
    np.testing.assert_array_equal(point, meet.results["point"])
    np.testing.assert_array_equal(x.project(point), meet.results["cartesian"])
    at_infinity = x.line_intersection(*parallel.args("l1", "l2"))
    np.testing.assert_array_equal(at_infinity, parallel.results["point"])
    assert at_infinity[2] == 0  # exactly: W = 0 is a point at infinity along (4, -3), the lines' direction
    assert np.dot(at_infinity[:2], parallel.inputs["l1"][:2]) == 0


def test_meet_lies_on_both_lines_and_scaling_does_not_move_it():
    rng = np.random.default_rng(72)
    for _ in range(20):
        l1, l2 = rng.normal(size=3), rng.normal(size=3)
        point = x.line_intersection(l1, l2)
        assert abs(point @ l1) < 1e-12 and abs(point @ l2) < 1e-12
        np.testing.assert_allclose(x.project(x.line_intersection(-3 * l1, 0.5 * l2)), x.project(point))
    np.testing.assert_allclose(x.project(np.array([[2.0, 4.0, 2.0], [-3.0, 3.0, -3.0]])), [[1, 2], [1, -1]])


@pytest.mark.parametrize("l1, l2, message", [
    ([1.0, 2.0, 3.0], [2.0, 4.0, 6.0], "^l1, l2: the lines"),
    ([0.1, 0.2, 0.3], [0.3, 0.6, 0.9], "^l1, l2: the lines"),  # equal up to rounding
    ([0.0, 0.0, 0.0], [1.0, 2.0, 3.0], "^l1"),
    ([1.0, 2.0], [1.0, 2.0, 3.0], "^l1"),
])
def test_coincident_and_malformed_lines_are_rejected(l1, l2, message):
    with pytest.raises(ValueError, match=message):
        x.line_intersection(l1, l2)


def test_the_line_at_infinity_meets_a_line_in_its_point_at_infinity():
    np.testing.assert_array_equal(x.line_intersection([0.0, 0.0, 1.0], [3.0, 4.0, 2.0]), [-4.0, 3.0, 0.0])


def test_project_rejects_points_at_infinity():
    with pytest.raises(ValueError, match="^point: W = 0"):
        x.project([4.0, -3.0, 0.0])
    with pytest.raises(ValueError, match="^point"):
        x.project([1.0, 2.0])


# --- §7.3 parametric and implicit ---------------------------------------------------------------------


def test_polynomial_curve_and_circle_of_the_notes():
    ex = example("circle_curve")
    g = x.implicit_polynomial(*ex.args("f", "x", "y"))
    np.testing.assert_array_equal(g, ex.results["g"])
    roots = np.sort(np.polynomial.polynomial.polyroots(g).real)
    np.testing.assert_allclose(roots, ex.results["roots"], atol=5e-6)
    ts, points = x.curve_implicit_intersection(ex.inputs["f"], ex.inputs["points"])
    np.testing.assert_allclose(ts, ex.results["roots"], atol=5e-6)
    np.testing.assert_allclose(points, ex.results["points"], atol=5e-5)  # the notes print 4 to 6 digits
    assert ts[-1] == 1.0


def test_substitution_in_bernstein_form_keeps_the_end_point_root_exact():
    ex = example("circle_curve")
    g = x.curve_implicit_bernstein(ex.inputs["f"], ex.inputs["points"])
    np.testing.assert_allclose(g, ex.results["bernstein"], atol=1e-15)
    assert g[-1] == 0.0  # g(1) = f(P(1)) computed from the end point itself
    # The trap of the same polynomial converted from the power basis: its g(1) is only zero to rounding.
    assert power_to_bernstein(ex.results["g"])[-1] != 0.0


def test_rational_curve_and_parabola_of_the_notes():
    ex = example("rational_parabola")
    g = x.implicit_polynomial(*ex.args("f", "x", "y", "w"))
    np.testing.assert_allclose(g, ex.results["g"], atol=1e-14)
    roots = np.polynomial.polynomial.polyroots(g)
    real = np.sort(roots[np.abs(roots.imag) < 1e-9].real)
    np.testing.assert_allclose(real, ex.results["real_roots"], atol=1e-10)
    X, Y, W = (np.polynomial.polynomial.polyval(real, ex.inputs[k]) for k in ("x", "y", "w"))
    np.testing.assert_allclose(np.column_stack([X / W, Y / W]), ex.results["points"], atol=1e-9)
    assert len(roots) == 4  # Bézout: 2 · 2, two of them complex


def test_implicit_polynomial_agrees_with_sympy():
    rng = np.random.default_rng(73)
    t = sp.symbols("t")
    for _ in range(8):
        d = int(rng.integers(1, 4))
        f = np.triu(rng.integers(-3, 4, (d + 1, d + 1)))[:, ::-1].astype(float)  # only i + j <= d
        xs, ys, ws = (rng.integers(-3, 4, int(rng.integers(1, 4))).astype(float) for _ in range(3))
        ws[0] = 2.0
        X, Y, W = (sum(int(c) * t**k for k, c in enumerate(a)) for a in (xs, ys, ws))
        i, j = np.nonzero(f)
        total = int((i + j).max())
        expected = sp.Poly(sp.expand(sum(int(f[a, b]) * X**a * Y**b * W ** (total - a - b) for a, b in zip(i, j))), t)
        coefficients = [float(c) for c in reversed(expected.all_coeffs())] if not expected.is_zero else [0.0]
        g = x.implicit_polynomial(f, xs, ys, ws)
        assert len(g) == total * (max(len(xs), len(ys), len(ws)) - 1) + 1
        np.testing.assert_allclose(g[: len(coefficients)], coefficients)
        assert not np.any(g[len(coefficients):])


def test_bernstein_substitution_agrees_with_the_power_form():
    rng = np.random.default_rng(74)
    for _ in range(8):
        n, d = int(rng.integers(1, 5)), int(rng.integers(1, 4))
        points, weights = rng.uniform(-2, 2, (n + 1, 2)), rng.uniform(0.5, 2, n + 1)
        f = np.zeros((d + 1, d + 1))
        for i in range(d + 1):
            f[i, : d + 1 - i] = rng.normal(size=d + 1 - i)
        g = x.curve_implicit_bernstein(f, points, weights)
        ts = np.linspace(0, 1, 9)
        p = evaluate(points, ts, weights)
        direct = sum(f[i, j] * p[:, 0] ** i * p[:, 1] ** j for i in range(d + 1) for j in range(d + 1))
        w = bernstein_horner(weights, ts)
        np.testing.assert_allclose(bernstein_horner(g, ts), direct * w**d, atol=1e-9)


def test_curve_implicit_intersection_of_a_rational_arc_and_a_line():
    quarter, weights = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0]
    diagonal = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0]])  # x - y = 0
    ts, points = x.curve_implicit_intersection(diagonal, quarter, weights)
    np.testing.assert_allclose(ts, [0.5], atol=1e-12)
    np.testing.assert_allclose(points, [[np.sqrt(0.5), np.sqrt(0.5)]], atol=1e-12)
    with pytest.raises(ValueError, match="^f: the curve lies on"):
        x.curve_implicit_intersection(UNIT_CIRCLE, quarter, weights)
    with pytest.raises(ValueError, match="^f: the zero polynomial"):
        x.implicit_polynomial(np.zeros((2, 2)), [0.0, 1.0], [1.0])


def test_osculating_circle_gives_the_curvature():
    ex = example("osculating_curvature")
    kappa = x.osculating_circle_curvature(*ex.args("points", "weights"))
    assert kappa == pytest.approx(ex.results["curvature"], rel=1e-13)
    assert ex.results["curvature"] == pytest.approx(2 * ex.results["w0"] * ex.results["y2"] / ex.results["x1"] ** 2)
    # The circle of radius 1/κ touching the x-axis at P(0) meets the (already placed) curve three times at t = 0.
    power = np.array([[0, 0, 1.5], [4.2, 0, -2.4], [9.6, 9, 6.3], [-8.8, -5, -4.4]])  # X, Y, W of the example
    rho = 1 / kappa
    circle = np.array([[0.0, -2 * rho, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])  # x² + y² - 2ρy
    g = x.implicit_polynomial(circle, power[:, 0], power[:, 1], power[:, 2])
    np.testing.assert_allclose(g[:3], 0, atol=1e-12)
    assert abs(g[3]) > 1e-3


def test_osculating_circle_agrees_with_the_curvature_formulas_of_chapter_2():
    rng = np.random.default_rng(75)
    for _ in range(10):
        n = int(rng.integers(2, 6))
        points, weights = rng.uniform(-3, 3, (n + 1, 2)), rng.uniform(0.3, 3, n + 1)
        kappa = x.osculating_circle_curvature(points, weights)
        assert kappa == pytest.approx(signed_curvature(points, 0.0, weights), rel=1e-9, abs=1e-12)
        assert abs(kappa) == pytest.approx(endpoint_curvature(points, weights), rel=1e-9, abs=1e-12)
    with pytest.raises(ValueError, match="^points: P1 coincides"):
        x.osculating_circle_curvature([(0.0, 0.0), (0.0, 0.0), (1.0, 1.0)])


# --- §7.4-7.6 subdivision, intervals, implicitization --------------------------------------------------


def test_flatness_bounds_the_distance_from_the_chord():
    rng = np.random.default_rng(76)
    ts = np.linspace(0, 1, 401)
    for _ in range(30):
        points = rng.uniform(-5, 5, (int(rng.integers(2, 7)), 2))
        curve = evaluate(points, ts)
        chord = (1 - ts)[:, None] * points[0] + ts[:, None] * points[-1]
        assert np.hypot(*(curve - chord).T).max() <= x.flatness(points) * (1 + 1e-12)
    assert x.flatness([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)]) == 1.0  # tight for a parabola: its vertex is 1 off
    assert x.flatness([(0.0, 0.0), (3.0, 1.0)]) == 0.0


def test_monotone_breaks_cut_the_curve_into_monotone_pieces():
    rng = np.random.default_rng(77)
    for _ in range(10):
        points = rng.uniform(-5, 5, (int(rng.integers(2, 6)), 2))
        breaks = x.monotone_breaks(points)
        assert breaks[0] == 0 and breaks[-1] == 1 and np.all(np.diff(breaks) > 0)
        for a, b in zip(breaks[:-1], breaks[1:]):
            values = evaluate(points, np.linspace(a, b, 50))
            steps = np.diff(values, axis=0)
            # each coordinate only rises or only falls on the piece
            assert np.all(np.all(steps >= -1e-12, axis=0) | np.all(steps <= 1e-12, axis=0))


@pytest.mark.parametrize("method", OTHER_ALGORITHMS)
def test_the_other_algorithms_find_the_five_intersections(method):
    ex = example("five_intersections")
    found = method(*ex.args("p", "q"))
    np.testing.assert_allclose(found, np.column_stack([ex.results["t"], ex.results["u"]]), atol=1e-8)


@pytest.mark.parametrize("method", OTHER_ALGORITHMS)
def test_the_other_algorithms_agree_with_clipping_on_random_cubics(method):
    rng = np.random.default_rng(78)
    for _ in range(12):
        p, q = rng.uniform(-1, 1, (4, 2)), rng.uniform(-1, 1, (4, 2))
        expected = x.intersect_curves(p, q)
        found = method(p, q)
        assert found.shape == expected.shape
        np.testing.assert_allclose(found, expected, atol=1e-7)


def test_implicit_by_nullspace_vanishes_on_the_curve_and_matches_the_resultant():
    rng = np.random.default_rng(79)
    for n in (1, 2, 3):
        points, weights = rng.uniform(-1, 1, (n + 1, 2)), rng.uniform(0.5, 2, n + 1)
        f = x.implicit_by_nullspace(points, weights)
        assert f.shape == (n + 1, n + 1) and np.isclose(np.linalg.norm(f), 1)
        p = evaluate(points, np.linspace(-0.5, 1.5, 21), weights)  # the whole algebraic curve, not just [0, 1]
        values = sum(f[i, j] * p[:, 0] ** i * p[:, 1] ** j for i in range(n + 1) for j in range(n + 1))
        assert np.abs(values).max() < 1e-10
    # A cubic with integer control points: the same equation as the resultant Res_t(x(t) - x, y(t) - y), up to scale.
    cubic = [(0, 0), (1, 3), (3, -1), (4, 2)]
    t, X, Y = sp.symbols("t x y")
    xt, yt = (sum(comb(3, i) * c[k] * (1 - t) ** (3 - i) * t**i for i, c in enumerate(cubic)) for k in (0, 1))
    resultant = sp.Poly(sp.resultant(sp.expand(xt) - X, sp.expand(yt) - Y, t), X, Y)
    exact = np.zeros((4, 4))
    for (i, j), c in resultant.terms():
        exact[i, j] = float(c)
    f = x.implicit_by_nullspace(np.array(cubic, dtype=float))
    np.testing.assert_allclose(f / f[3, 0], exact / exact[3, 0], atol=1e-9)


def test_search_steps_show_clipping_examines_far_fewer_pairs():
    ex = example("five_intersections")
    counts = {m: len(x.search_steps(*ex.args("p", "q"), method=m)) for m in ("subdivision", "intervals", "clipping")}
    assert counts["clipping"] * 10 < counts["subdivision"] < counts["intervals"]
    steps = x.search_steps(*ex.args("p", "q"), method="subdivision")
    assert {s.outcome for s in steps} <= {"rejected", "split", "found"}
    assert steps[0].depth == 0 and steps[0].t_range == (0.0, 1.0) and steps[0].outcome == "split"
    assert sum(s.outcome == "found" for s in x.search_steps(*ex.args("p", "q"), method="clipping")) >= 5
    with pytest.raises(ValueError, match="^method"):
        x.search_steps(*ex.args("p", "q"), method="newton")


# --- §7.7 fat lines ---------------------------------------------------------------------------------------


def test_fat_lines_of_the_notes():
    ex = example("clip_curves")
    line, dmin, dmax = x.fat_line(ex.inputs["q"])
    np.testing.assert_allclose(line, ex.results["line"], atol=1e-15)
    assert (dmin, dmax) == (ex.results["dmin"], ex.results["dmax"])
    np.testing.assert_allclose(ex.inputs["p"] @ line[:2] + line[2], ex.results["distances"], atol=1e-14)
    quartic = example("homogeneous_fat_line")
    line, dmin, dmax = x.fat_line(quartic.inputs["points"])
    np.testing.assert_allclose(line, quartic.results["normalised_line"], atol=1e-15)
    assert dmin == pytest.approx(quartic.results["dmin"]) and dmax == pytest.approx(quartic.results["dmax"])


def test_fat_line_orientation_normalisation_and_the_end_points():
    rng = np.random.default_rng(80)
    for _ in range(20):
        points = rng.uniform(-5, 5, (int(rng.integers(2, 7)), 2))
        line, dmin, dmax = x.fat_line(points)
        assert line[0] ** 2 + line[1] ** 2 == pytest.approx(1)
        assert dmin <= 0 <= dmax
        direction = np.cross(np.append(points[0], 1), np.append(points[-1], 1))
        assert np.dot(direction, line) > 0  # oriented as P0 × Pn
        curve = evaluate(points, np.linspace(0, 1, 101))
        d = curve @ line[:2] + line[2]
        assert np.all((d >= dmin - 1e-12) & (d <= dmax + 1e-12))
        back, bmin, bmax = x.fat_line(points[::-1])  # the other orientation negates and swaps
        np.testing.assert_allclose(back, -line, atol=1e-14)
        assert (bmin, bmax) == pytest.approx((-dmax, -dmin))
    # An arch: the interior points are on one side, but the band still holds the end points on L̄.
    line, dmin, dmax = x.fat_line([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)])
    assert (dmin, dmax) == (0.0, 2.0)
    assert x.fat_line([(1.0, 1.0), (3.0, 2.0)])[1:] == (0.0, 0.0)
    with pytest.raises(ValueError, match="^points: P0 = Pn"):
        x.fat_line([(0.0, 0.0), (1.0, 1.0), (0.0, 0.0)])


def test_perpendicular_fat_line_clips_the_notes_figure_7_8_case():
    ex = example("perpendicular")
    assert x.clip_curve(ex.inputs["p"], *x.fat_line(ex.inputs["q"])) == (0.0, 1.0)
    line, dmin, dmax = x.perpendicular_fat_line(ex.inputs["q"])
    assert np.dot(line[:2], np.subtract(ex.inputs["q"][-1], ex.inputs["q"][0])) > 0
    np.testing.assert_allclose(x.clip_curve(ex.inputs["p"], line, dmin, dmax), ex.results["perpendicular"], atol=1e-15)
    assert dmin <= 0 and dmax >= np.hypot(*(ex.inputs["q"][-1] - ex.inputs["q"][0]))


# --- §7.7.2 clipping ----------------------------------------------------------------------------------


def _exact_hull_band(values, low, high):
    """Reference in exact arithmetic: the extremes of control points in the band and crossings of all segments."""
    n = len(values) - 1
    c = [Fraction(v) for v in values]
    t = [Fraction(i, n) for i in range(n + 1)]
    found = [t[i] for i in range(n + 1) if low <= c[i] <= high]
    for level in (Fraction(low), Fraction(high)):
        for i in range(n + 1):
            for j in range(n + 1):
                if c[i] < level < c[j]:
                    found.append(t[i] + (t[j] - t[i]) * (level - c[i]) / (c[j] - c[i]))
    return (min(found), max(found)) if found else None


def test_first_clip_of_the_notes_exactly():
    ex = example("first_clip")
    clip = x.clip_range(*ex.args("distances", "dmin", "dmax"))
    assert clip == tuple(ex.results["clip"])
    assert _exact_hull_band([-5, -1, 2, 3], -2, 1) == (Fraction(1, 4), Fraction(3, 4))


def test_clip_range_is_the_exact_extent_of_the_hull_in_the_band():
    rng = np.random.default_rng(81)
    for _ in range(60):
        n = int(rng.integers(1, 7))
        c = rng.integers(-6, 7, n + 1).astype(float)
        low = float(rng.integers(-4, 3))
        high = low + float(rng.integers(0, 4))
        expected = _exact_hull_band(c, low, high)
        clip = x.clip_range(c, low, high)
        if expected is None:
            assert clip is None
            continue
        assert clip == pytest.approx((float(expected[0]), float(expected[1])), abs=1e-15)


def test_clip_range_agrees_with_linear_programming_over_the_hull():
    rng = np.random.default_rng(82)
    for _ in range(25):
        n = int(rng.integers(1, 6))
        c = rng.normal(size=n + 1) * 3
        low, high = np.sort(rng.normal(size=2))
        ts = np.arange(n + 1) / n
        # Minimise and maximise t = Σ λ_i t_i over λ >= 0, Σ λ = 1, low <= Σ λ_i c_i <= high.
        bounds = dict(A_ub=np.vstack([c, -c]), b_ub=[high, -low], A_eq=np.ones((1, n + 1)), b_eq=[1])
        lowest, highest = linprog(ts, **bounds), linprog(-ts, **bounds)
        clip = x.clip_range(c, low, high)
        if lowest.status == 2:  # infeasible: the hull misses the band
            assert clip is None
        else:
            assert clip == pytest.approx((lowest.fun, -highest.fun), abs=1e-8)


def test_clip_range_never_cuts_away_the_curve_in_the_band():
    rng = np.random.default_rng(83)
    ts = np.linspace(0, 1, 2001)
    for _ in range(40):
        c = rng.normal(size=int(rng.integers(2, 8))) * 2
        low, high = np.sort(rng.normal(size=2))
        d = bernstein_horner(c, ts)
        inside = ts[(d >= low) & (d <= high)]
        clip = x.clip_range(c, low, high)
        if clip is None:
            assert inside.size == 0
        else:
            assert np.all((inside >= clip[0]) & (inside <= clip[1]))


@pytest.mark.parametrize("coeffs, dmin, dmax, expected", [
    ([-5.0, -6.0, 3.0, 3.0], -2.0, 1.0, (0.25, 23 / 27)),  # the hull, not the polygon (which starts at 13/27)
    ([0.0, 5.0, 5.0, 5.0], -1.0, 1.0, (0.0, 0.2)),  # a control point inside the band counts
    ([-1.0, 1.0, -1.0], 1.0, 2.0, (0.5, 0.5)),  # a vertex touching the band
    ([4.0, 5.0, 3.0], -1.0, 1.0, None),  # all above
    ([-4.0, -5.0, -3.0], -1.0, 1.0, None),  # all below
    ([0.5, -0.5, 0.2], -1.0, 1.0, (0.0, 1.0)),  # all inside
    ([0.5], -1.0, 1.0, (0.0, 1.0)),  # degree 0: a constant over [0, 1]
    ([2.0], -1.0, 1.0, None),
    ([-3.0, 3.0], -1.0, 1.0, (1 / 3, 2 / 3)),
])
def test_clip_range_edge_cases(coeffs, dmin, dmax, expected):
    clip = x.clip_range(coeffs, dmin, dmax)
    assert clip == (None if expected is None else pytest.approx(expected, abs=1e-15))


def test_the_control_polygon_would_clip_away_part_of_the_curve_in_the_band():
    # For [-5, -6, 3, 3] and the band [-2, 1] the polygon first reaches the band at 13/27 ≈ 0.4815,
    # but the curve is already inside at t = 0.46: clipping to the polygon would lose it.
    value = bernstein_horner(np.array([-5.0, -6.0, 3.0, 3.0]), 0.46)
    assert -2 <= value <= 1
    assert x.clip_range([-5.0, -6.0, 3.0, 3.0], -2.0, 1.0)[0] < 0.46


def test_clip_range_rejects_an_empty_band():
    with pytest.raises(ValueError, match="^dmin"):
        x.clip_range([0.0, 1.0], 1.0, -1.0)


def test_clip_curve_polynomial_and_rational():
    ex = example("clip_curves")
    line, dmin, dmax = x.fat_line(ex.inputs["q"])
    assert x.clip_curve(ex.inputs["p"], line, dmin, dmax) == (0.25, 0.75)
    rng = np.random.default_rng(84)
    ts = np.linspace(0, 1, 1001)
    for _ in range(25):
        points = rng.uniform(-3, 3, (int(rng.integers(2, 6)), 2))
        weights = rng.uniform(0.2, 5, len(points))
        line = np.append(rng.normal(size=2), rng.normal())
        low, high = np.sort(rng.normal(size=2))
        d = evaluate(points, ts, weights) @ line[:2] + line[2]
        inside = ts[(d >= low) & (d <= high)]
        clip = x.clip_curve(points, line, low, high, weights)
        if clip is None:
            assert inside.size == 0
        else:
            assert np.all((inside >= clip[0] - 1e-12) & (inside <= clip[1] + 1e-12))


def test_the_misprinted_sign_would_lose_the_rational_intersection():
    ex = example("rational_clip")
    arc, weights, cubic = ex.args("p", "p_weights", "q")
    line, dmin, dmax = x.fat_line(cubic)
    assert x.clip_curve(arc, line, dmin, dmax, weights) == (0.0, 1.0)
    # The notes' "+ dmin": keep where Σ w_i (d_i + dmin) B_i >= 0 instead of Σ w_i (d_i - dmin) B_i >= 0.
    h = np.column_stack([arc * weights[:, None], weights])
    misprinted = x.clip_range(h @ line + dmin * weights, 0.0, np.abs(h @ line).max() + 10)
    np.testing.assert_allclose(misprinted, ex.results["misprinted_first_clip"], atol=1e-12)
    assert not misprinted[0] <= ex.results["intersection"][0] <= misprinted[1]


def test_curve_piece_is_the_same_curve_over_the_sub_interval():
    rng = np.random.default_rng(91)
    for _ in range(10):
        points = rng.uniform(-3, 3, (int(rng.integers(2, 6)), 2))
        weights = rng.uniform(0.2, 4, len(points))
        a, b = np.sort(rng.uniform(size=2))
        s = np.linspace(0, 1, 11)
        piece, piece_weights = x.curve_piece(points, (a, b), weights)
        np.testing.assert_allclose(evaluate(piece, s, piece_weights), evaluate(points, a + (b - a) * s, weights))
        polynomial, none = x.curve_piece(points, (a, b))
        assert none is None
        np.testing.assert_allclose(evaluate(polynomial, s), evaluate(points, a + (b - a) * s))
    np.testing.assert_allclose(x.curve_piece([(0.0, 0.0), (2.0, 2.0)], (0.5, 0.5))[0], [[1.0, 1.0], [1.0, 1.0]])
    with pytest.raises(ValueError, match="^interval"):
        x.curve_piece([(0.0, 0.0), (2.0, 2.0)], (0.5, 1.5))


# --- §7.7.7-7.7.8 rational curves ---------------------------------------------------------------------


def test_homogeneous_fat_line_of_the_notes():
    ex = example("homogeneous_fat_line")
    points, weights = ex.args("points", "weights")
    lmin, lmax = x.homogeneous_fat_line(points, weights)
    np.testing.assert_array_equal(lmin, ex.results["lmin"])
    np.testing.assert_array_equal(lmax, ex.results["lmax"])
    h = np.column_stack([points * weights[:, None], weights])
    np.testing.assert_array_equal(np.cross(h[0], h[-1]), ex.results["base"])
    np.testing.assert_array_equal(h @ lmin, ex.results["lmin_values"])
    np.testing.assert_array_equal(h @ lmax, ex.results["lmax_values"])
    for k, name in enumerate(("l1", "l2", "l3"), start=1):  # the parallel line through P_k
        assert ex.results[name][2] == ex.results["offsets"][k] and ex.results[name] @ h[k] == 0


def test_homogeneous_fat_line_bounds_random_rational_curves():
    rng = np.random.default_rng(85)
    for _ in range(20):
        points = rng.uniform(-4, 4, (int(rng.integers(2, 7)), 2))
        weights = rng.uniform(0.2, 5, len(points))
        lmin, lmax = x.homogeneous_fat_line(points, weights)
        curve = np.column_stack([evaluate(points, np.linspace(0, 1, 201), weights), np.ones(201)])
        assert np.all(curve @ lmin >= -1e-9) and np.all(curve @ lmax >= -1e-9)
    with pytest.raises(ValueError, match="^weights"):
        x.homogeneous_fat_line([(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], [1.0, -1.0, 1.0])


def _exact_meets(values, end):
    """E_i, E_end × E_i and their meets with the axis (0, 1, 0), in fractions."""
    n = len(values) - 1
    points = [(Fraction(i, n), Fraction(v), Fraction(1)) for i, v in enumerate(values)]

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    anchor = points[0] if end == "left" else points[-1]
    others = points[1:] if end == "left" else points[:-1]
    lines = [cross(anchor, e) for e in others]
    return lines, [cross(line, (0, 1, 0)) for line in lines]


@pytest.mark.parametrize("name, end", [("clip_lmin", "left"), ("clip_lmax", "right")])
def test_the_v_rule_examples_of_the_notes_exactly(name, end):
    ex = example(name)
    points, weights, line = ex.args("points", "weights", "line")
    h = np.column_stack([points * weights[:, None], weights])
    values = h @ line
    np.testing.assert_array_equal(values, ex.results["values"])
    lines, meets = _exact_meets([int(v) for v in values], end)
    _, found_lines, found_meets = x.explicit_meets(values, end)
    np.testing.assert_allclose(found_lines, np.array(lines, dtype=float), atol=1e-12)
    np.testing.assert_allclose(found_lines, ex.results["lines"], atol=1e-12)
    np.testing.assert_allclose(found_meets, np.array(meets, dtype=float), atol=1e-12)
    v = [m[0] / m[2] for m in meets]
    np.testing.assert_allclose([float(t) for t in v], ex.results["v"], atol=1e-15)
    clip = x.clip_one_sided(line, points, weights)
    np.testing.assert_allclose(clip, ex.results["clip"], atol=1e-15)
    exact = min(t for t in v if t > 0) if end == "left" else max(t for t in v if t < 1)
    assert exact == (Fraction(20, 167) if end == "left" else Fraction(107, 132))
    assert Fraction(clip[0] if end == "left" else clip[1]).limit_denominator(1000) == exact
    assert x.clip_one_sided(line, points, weights, exact=True) == pytest.approx(clip, abs=1e-15)


def test_both_one_sided_clips_keep_the_part_inside_the_fat_line():
    lmin, lmax = example("clip_lmin"), example("clip_lmax")
    points, weights = lmin.args("points", "weights")
    low = x.clip_one_sided(lmin.inputs["line"], points, weights)
    high = x.clip_one_sided(lmax.inputs["line"], points, weights)
    both = (max(low[0], high[0]), min(low[1], high[1]))
    np.testing.assert_allclose(both, lmax.results["both"], atol=1e-15)
    inside = lmax.results["inside"]  # where the curve really is in the fat line: a sub-range, as it must be
    assert both[0] < inside[0] < inside[1] < both[1]
    for t, line in zip(inside, (lmin.inputs["line"], lmax.inputs["line"])):
        assert abs(np.append(evaluate(points, t, weights), 1.0) @ line) < 1e-9


def test_v_rule_cases_of_figures_7_13_and_7_14():
    gap, cases = example("v_rule_gap"), example("clip_cases")
    values = gap.inputs["values"]
    # clip_one_sided takes a line and points; with the line (0, 1, 0) and points (i, e_i) the heights are e_i.
    points = np.column_stack([np.arange(len(values), dtype=float), values])
    assert np.allclose(x.clip_one_sided([0.0, 1.0, 0.0], points), gap.results["v_rule"])
    assert np.allclose(x.clip_one_sided([0.0, 1.0, 0.0], points, exact=True), gap.results["hull"])
    for name in ("nothing", "both_ends"):
        e = cases.inputs[name]
        pts = np.column_stack([np.arange(len(e), dtype=float), e])
        assert np.allclose(x.clip_one_sided([0.0, 1.0, 0.0], pts), cases.results[name])
    e = cases.inputs["everything"]
    assert x.clip_one_sided([0.0, 1.0, 0.0], np.column_stack([np.arange(len(e), dtype=float), e])) is None


def test_the_v_rule_never_clips_more_than_the_hull_and_is_exact_when_the_steepest_point_is_above():
    rng = np.random.default_rng(86)
    for _ in range(200):
        e = rng.normal(size=int(rng.integers(2, 7)))
        points = np.column_stack([np.arange(len(e), dtype=float), e])
        rule = x.clip_one_sided([0.0, 1.0, 0.0], points)
        hull = x.clip_one_sided([0.0, 1.0, 0.0], points, exact=True)
        if hull is None:
            assert rule is None
            continue
        assert rule[0] <= hull[0] + 1e-15 and rule[1] >= hull[1] - 1e-15
        t = np.arange(len(e)) / (len(e) - 1)
        if e[0] < 0:
            steepest = np.argmax((e[1:] - e[0]) / t[1:]) + 1
            if e[steepest] >= 0:
                assert rule[0] == pytest.approx(hull[0], abs=1e-14)


# --- §7.7.3-7.7.6 iterating and intersecting --------------------------------------------------------


def test_iterating_reproduces_the_notes_and_converges_quadratically():
    ex = example("iterating")
    clips = [s for s in x.clip_trace(*ex.args("p", "q")) if s.kind == "clip"]
    p_ranges = [s.t_range for s in clips if s.curve == "P"][:4]
    q_ranges = [s.u_range for s in clips if s.curve == "Q"][:4]
    np.testing.assert_allclose(p_ranges, ex.results["p_ranges"], atol=5e-9)
    np.testing.assert_allclose(q_ranges, ex.results["q_ranges"], atol=5e-9)
    np.testing.assert_allclose(q_ranges[0], ex.results["second_clip"], atol=0.005)
    # After three clips of each curve, the intersection is known to six digits.
    u = example("clip_curves").results["intersection"][1]
    assert q_ranges[2][1] - q_ranges[2][0] < 1e-6 and q_ranges[2][0] <= u <= q_ranges[2][1]
    widths = np.array([b - a for a, b in q_ranges])
    assert np.all(widths[1:] <= 5 * widths[:-1] ** 2)  # quadratic: each width within a small factor of the square


def test_clip_trace_records_splits_and_explicit_curves():
    ex = example("five_intersections")
    trace = x.clip_trace(*ex.args("p", "q"))
    kinds = {s.kind for s in trace}
    assert {"clip", "split", "found"} <= kinds
    first = trace[0]
    line, dmin, dmax = first.fat_line
    np.testing.assert_allclose(first.values, ex.inputs["p"] @ line[:2] + line[2])
    assert first.local == x.clip_range(first.values, dmin, dmax)
    assert first.perpendicular is None and x.clip_trace(*ex.args("p", "q"), perpendicular=True)[0].perpendicular
    arc = example("rational_clip")
    rational = x.clip_trace(*arc.args("p", "q"), p_weights=arc.inputs["p_weights"])
    assert rational[0].values.shape == (2, 3)  # the two one-sided explicit curves of the rational arc


def test_intersections_of_the_notes_and_the_course_examples():
    ex = example("clip_curves")
    np.testing.assert_allclose(x.intersect_curves(*ex.args("p", "q")), [ex.results["intersection"]], atol=1e-11)
    np.testing.assert_allclose(evaluate(ex.inputs["p"], ex.results["intersection"][0]), ex.results["point"], atol=1e-7)
    five = example("five_intersections")
    found = x.intersect_curves(*five.args("p", "q"))
    np.testing.assert_allclose(found, np.column_stack([five.results["t"], five.results["u"]]), atol=1e-11)
    assert np.count_nonzero(np.all(np.abs(found - 0.5) < 1e-6, axis=1)) == 1  # on the split point, reported once
    rational = example("rational_clip")
    arc, weights, cubic = rational.args("p", "p_weights", "q")
    found = x.intersect_curves(arc, cubic, p_weights=weights)
    np.testing.assert_allclose(found, [rational.results["intersection"]], atol=1e-11)
    point = evaluate(arc, found[0, 0], weights)
    assert np.hypot(*point) == pytest.approx(1, abs=1e-12)
    np.testing.assert_allclose(point, rational.results["point"], atol=1e-7)
    np.testing.assert_allclose(x.intersect_curves(cubic, arc, q_weights=weights), found[:, ::-1], atol=1e-11)


# The plain loop of the chapter's algorithm box: the same intersections, the same first clips as the notes.
PLAIN_CASES = [
    ("clip_curves", None), ("five_intersections", None), ("two_intersections", None), ("perpendicular", None),
    ("rational_clip", "p_weights"),
]


@pytest.mark.parametrize("name, weights", PLAIN_CASES)
def test_the_plain_loop_finds_what_intersect_curves_finds(name, weights):
    ex = example(name)
    options = {} if weights is None else {"p_weights": ex.inputs[weights]}
    plain = x.bezier_clipping(*ex.args("p", "q"), **options)
    np.testing.assert_allclose(plain, x.intersect_curves(*ex.args("p", "q"), **options), atol=1e-8)


def test_the_plain_loop_reproduces_the_notes_clips_and_handles_the_hard_cases():
    ex = example("iterating")
    log = []
    x.bezier_clipping(*ex.args("p", "q"), perpendicular=False, log=log)
    clips = [event for event in log if event[0] in ("clip P", "clip Q")]
    np.testing.assert_allclose([t for _, t, _ in clips[0::2][:4]], ex.results["p_ranges"], atol=5e-9)
    np.testing.assert_allclose([u for _, _, u in clips[1::2][:4]], ex.results["q_ranges"], atol=5e-9)
    cubic = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]
    np.testing.assert_allclose(x.bezier_clipping(cubic, [(4.0, 0.0), (5.0, 3.0), (6.0, -1.0)]), [[1.0, 0.0]], atol=1e-9)
    loop = [(0.0, 0.0), (3.0, 3.0), (-3.0, 3.0), (0.0, 0.0)]
    np.testing.assert_allclose(x.bezier_clipping(loop, [(0.0, 0.0), (1.0, -1.0)]), [[0.0, 0.0], [1.0, 0.0]], atol=1e-9)
    touching = x.bezier_clipping([(0.0, 1.0), (0.25, -1.0), (1.0, 1.0)], [(0.0, 0.0), (1.0, 0.0)])
    np.testing.assert_allclose(touching, x.intersect_curves([(0.0, 1.0), (0.25, -1.0), (1.0, 1.0)],
                                                            [(0.0, 0.0), (1.0, 0.0)]), atol=1e-6)
    with pytest.raises(RuntimeError, match="overlap"):
        x.bezier_clipping(cubic, cubic, max_rounds=200)
    with pytest.raises(ValueError, match="q_weights"):
        x.bezier_clipping(cubic, cubic, q_weights=[1.0, -1.0, 1.0, 1.0])


def test_the_pad_keeps_the_intersection_on_the_split_point():
    # Without widening the fat lines, rounding in the halves clips away (0.5, 0.5) of the S-curves.
    five = example("five_intersections")
    expected = np.column_stack([five.results["t"], five.results["u"]])
    np.testing.assert_allclose(x.bezier_clipping(*five.args("p", "q")), expected, atol=1e-8)
    unpadded = x.bezier_clipping(*five.args("p", "q"), pad=0.0)
    assert len(unpadded) == 4 and not np.any(np.all(np.abs(unpadded - 0.5) < 1e-6, axis=1))


def test_the_plain_loop_passes_every_case_of_the_hidden_suite_of_exercise_7_6():
    # Chapter 7 says so: `bezier_clipping` is the staged recipe of exercise 7.6, and that recipe is enough.
    from pathlib import Path

    from cagd_course.grading.engine import _load_suite_file
    from cagd_course.grading.suite import Raises, expected_value

    suite = Path(__file__).resolve().parents[1] / "hidden" / "ch07.py"
    exercise = next(e for e in _load_suite_file(suite) if e.id == "07.intersect_curves")
    compare = exercise.comparison()
    for case in exercise.cases(np.random.default_rng(0)):
        try:
            received = x.bezier_clipping(*case.args, **case.kwargs)
        except (ValueError, TypeError, RuntimeError) as err:
            received = Raises(type(err).__name__, str(err))
        assert compare(expected_value(exercise, case), received) is None, (case.category, case.args)


def test_merge_touching_joins_chains_of_boxes():
    boxes = [((0.1, 0.2), (0.1, 0.2)), ((0.3, 0.4), (0.3, 0.4)), ((0.2, 0.3), (0.2, 0.3)), ((0.8, 0.8), (0.1, 0.1))]
    np.testing.assert_allclose(x.merge_touching(boxes, gap=0.0), [[0.25, 0.25], [0.8, 0.1]])
    assert x.merge_touching([]).shape == (0, 2)
    with pytest.raises(ValueError, match="boxes"):
        x.merge_touching([((0.1, np.nan), (0.1, 0.2))])


def _resultant_intersections(p, q):
    """All (t, u) in [0, 1]² with P(t) = Q(u), for integer control points: real roots of a SymPy resultant."""
    t, u = sp.symbols("t u")

    def curve(points, s):
        n = len(points) - 1
        return [sp.expand(sum(comb(n, i) * int(c[k]) * (1 - s) ** (n - i) * s**i for i, c in enumerate(points)))
                for k in (0, 1)]

    (xp, yp), (xq, yq) = curve(p, t), curve(q, u)
    resultant = sp.Poly(sp.resultant(xp - xq, yp - yq, u), t)
    found = []
    for root in resultant.real_roots():
        t0 = float(root.evalf(30))
        if not -1e-12 <= t0 <= 1 + 1e-12:
            continue
        for u0 in sp.Poly(xp.subs(t, root) - xq, u).nroots(n=30) if sp.Poly(xq, u).degree() > 0 else []:
            if abs(sp.im(u0)) < 1e-20 and -1e-12 <= float(sp.re(u0)) <= 1 + 1e-12:
                if abs(float((yp.subs(t, root) - yq.subs(u, sp.re(u0))).evalf(30))) < 1e-12:
                    found.append((t0, float(sp.re(u0))))
    found = sorted(set((round(a, 12), round(b, 12)) for a, b in found))
    return np.array(found).reshape(-1, 2)


def test_random_cubic_pairs_agree_with_sympy_resultants():
    rng = np.random.default_rng(87)
    checked = 0
    for _ in range(12):
        p, q = rng.integers(-9, 10, (4, 2)), rng.integers(-9, 10, (4, 2))
        expected = _resultant_intersections(p, q)
        found = x.intersect_curves(p.astype(float), q.astype(float))
        assert found.shape == expected.shape, (p.tolist(), q.tolist())
        np.testing.assert_allclose(found, expected, atol=1e-8)
        checked += len(found)
    assert checked >= 6  # the sample really has intersections


def test_random_pairs_of_mixed_degrees_agree_with_the_bezier_package():
    bezier = pytest.importorskip("bezier")
    rng = np.random.default_rng(88)
    for _ in range(40):
        n, m = rng.integers(1, 6, 2)
        p = rng.uniform(-1, 1, (n + 1, 2)) * rng.uniform(0.1, 50)
        q = rng.uniform(-1, 1, (m + 1, 2)) * rng.uniform(0.1, 50)
        theirs = bezier.Curve(np.asfortranarray(p.T), degree=int(n)).intersect(
            bezier.Curve(np.asfortranarray(q.T), degree=int(m))).T
        theirs = theirs[np.lexsort((theirs[:, 1], theirs[:, 0]))] if len(theirs) else np.zeros((0, 2))
        if len(theirs):  # bezier may report an intersection twice
            keep = np.concatenate([[True], np.abs(np.diff(theirs, axis=0)).max(axis=1) > 1e-7])
            theirs = theirs[keep]
        found = x.intersect_curves(p, q)
        assert found.shape == theirs.shape
        np.testing.assert_allclose(found, theirs, atol=1e-7)


def test_rational_pairs_agree_with_substitution_into_the_circle():
    rng = np.random.default_rng(89)
    arc, weights = np.array([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]), np.array([1.0, np.sqrt(0.5), 1.0])
    for _ in range(15):
        cubic = rng.uniform(-0.2, 1.3, (4, 2))
        found = x.intersect_curves(arc, cubic, p_weights=weights)
        us, points = x.curve_implicit_intersection(UNIT_CIRCLE, cubic)
        on_arc = us[(points[:, 0] >= -1e-12) & (points[:, 1] >= -1e-12)]
        np.testing.assert_allclose(np.sort(found[:, 1]), on_arc, atol=1e-8)
        for t, u in found:
            np.testing.assert_allclose(evaluate(arc, t, weights), evaluate(cubic, u), atol=1e-8)


def test_shared_end_points_come_out_exactly():
    cubic = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]
    assert x.intersect_curves(cubic, [(4.0, 0.0), (5.0, 3.0), (6.0, -1.0)]).tolist() == [[1.0, 0.0]]
    assert x.intersect_curves(cubic, [(4.0, 0.0), (5.0, -2.0), (6.0, 1.0)]).tolist() == [[1.0, 0.0]]  # G1 joint
    assert x.intersect_curves(cubic, [(6.0, 1.0), (5.0, -2.0), (0.0, 0.0)]).tolist() == [[0.0, 1.0]]
    loop = [(0.0, 0.0), (3.0, 3.0), (-3.0, 3.0), (0.0, 0.0)]  # P0 = Pn: no chord for a fat line
    assert x.intersect_curves(loop, [(0.0, 0.0), (1.0, -1.0)]).tolist() == [[0.0, 0.0], [1.0, 0.0]]


def test_lines_and_disjoint_curves():
    assert x.intersect_curves([(0.0, 0.0), (1.0, 1.0)], [(0.0, 1.0), (1.0, 0.0)]).tolist() == [[0.5, 0.5]]
    empty = x.intersect_curves([(0.0, 0.0), (1.0, 0.0)], [(0.0, 1.0), (1.0, 1.0)])  # parallel segments
    assert empty.shape == (0, 2)
    assert x.intersect_curves([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0)], [(10.0, 0.0), (11.0, 1.0)]).shape == (0, 2)


@pytest.mark.parametrize("p, q, expected", [
    ([(0.0, 1.0), (0.5, -1.0), (1.0, 1.0)], [(0.0, 0.0), (1.0, 0.0)], (0.5, 0.5)),  # parabola on its tangent
    ([(-1.0, 1.0), (0.0, -1.0), (1.0, 1.0)], [(-1.0, 2.0), (0.0, -2.0), (1.0, 2.0)], (0.5, 0.5)),  # y = x², y = 2x²
])
def test_a_tangential_intersection_is_reported_once(p, q, expected):
    found = x.intersect_curves(p, q)
    assert found.shape == (1, 2)
    np.testing.assert_allclose(found[0], expected, atol=1e-6)


def test_an_asymmetric_tangency_is_located():
    xs = power_to_bernstein(np.array([0.0, 1.0, 0.4, 0.0]))
    ys = power_to_bernstein(np.array([0.09, -0.6, 1.0, 0.0]))  # (t - 0.3)², touching y = 0 at t = 0.3
    found = x.intersect_curves(np.column_stack([xs, ys]), [(-1.0, 0.0), (3.0, 0.0)])
    np.testing.assert_allclose(found, [[0.3, (0.3 + 0.4 * 0.09 + 1) / 4]], atol=1e-6)


@pytest.mark.parametrize("q", [
    [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)],  # the same curve
    subdivide(subdivide(np.array([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]), 0.3)[1], 0.5)[0],  # a piece
    [(1.0, 0.0), (3.0, 0.0)],  # collinear segments below
])
def test_overlapping_curves_raise_quickly(q):
    p = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)] if len(q) > 2 else [(0.0, 0.0), (2.0, 0.0)]
    with pytest.raises(ValueError, match="^p, q: the curves overlap"):
        x.intersect_curves(p, q)


def test_the_step_cap_stops_the_search():
    with pytest.raises(RuntimeError, match="gave up after 3 clipping rounds"):
        x.intersect_curves(*example("five_intersections").args("p", "q"), max_steps=3)


def test_both_kinds_of_fat_line_find_the_same_intersections():
    rng = np.random.default_rng(90)
    for _ in range(10):
        p, q = rng.uniform(-1, 1, (4, 2)), rng.uniform(-1, 1, (5, 2))
        np.testing.assert_allclose(x.intersect_curves(p, q, perpendicular=False), x.intersect_curves(p, q),
                                   atol=1e-8)


def test_results_are_sorted_and_within_tol():
    five = example("five_intersections")
    coarse = x.intersect_curves(*five.args("p", "q"), tol=1e-4)
    exact = np.column_stack([five.results["t"], five.results["u"]])
    assert np.all(np.abs(coarse - exact) <= 1e-4)
    swapped = x.intersect_curves(*five.args("q", "p"))
    assert np.all(np.diff(swapped[:, 0]) > 0)
    np.testing.assert_allclose(swapped, exact[np.argsort(exact[:, 1])][:, ::-1], atol=1e-11)


def _reference(p, q, t, u, p_weights=None, q_weights=None):
    """(t, u) refined by Newton's method in 50 digits (mpmath) on the exact curves given by the doubles."""
    mp = pytest.importorskip("mpmath").mp
    mp.dps = 50

    def curve(points, weights):
        n = len(points) - 1
        w = [mp.mpf(1)] * (n + 1) if weights is None else [mp.mpf(float(v)) for v in weights]
        rows = [[mp.mpf(float(c)) for c in point] for point in points]

        def value(s):
            basis = [mp.binomial(n, i) * (1 - s) ** (n - i) * s**i * w[i] for i in range(n + 1)]
            total = sum(basis)
            return [sum(b * row[k] for b, row in zip(basis, rows)) / total for k in (0, 1)]
        return value

    fp, fq = curve(p, p_weights), curve(q, q_weights)
    root = mp.findroot(lambda a, b: [fp(a)[k] - fq(b)[k] for k in (0, 1)], (mp.mpf(float(t)), mp.mpf(float(u))))
    return float(root[0]), float(root[1])


@pytest.mark.parametrize("tol", [1e-9, 1e-12, 1e-14])
def test_crossings_are_within_tol_of_50_digit_solutions(tol):
    rng = np.random.default_rng(94)
    checked = 0
    for trial in range(24):
        n, m = rng.integers(1, 6, 2)
        p = rng.uniform(-1, 1, (n + 1, 2)) * 10.0 ** rng.integers(-2, 3) + rng.uniform(-5, 5, 2)
        q = p.mean(axis=0) + rng.uniform(-1, 1, (m + 1, 2)) * np.ptp(p, axis=0).max()
        weights = {}
        if trial % 3 == 2:
            weights = {"p_weights": rng.uniform(0.3, 3, n + 1), "q_weights": rng.uniform(0.3, 3, m + 1)}
        found = x.intersect_curves(p, q, tol=tol, **weights)
        for t, u in found:
            if 0 < t < 1 and 0 < u < 1:
                exact = _reference(p, q, t, u, weights.get("p_weights"), weights.get("q_weights"))
                assert abs(t - exact[0]) <= tol and abs(u - exact[1]) <= tol, (trial, t - exact[0], u - exact[1])
                checked += 1
    assert checked >= 20


def test_at_a_small_tol_crossings_come_to_a_few_units_in_the_last_place():
    # Nearly parallel lines far from the origin (the conditioning of case 51 of the bezier suite, made
    # worse): double-precision Newton alone is off by many units; the compensated last step is not.
    p = np.array([[1000.0, 1000.0], [1001.0, 1001.0]])
    q = np.array([[1000.0 + 2.0**-10, 1000.0 - 2.0**-10], [1001.0 - 2.0**-10, 1001.0 + 2.0**-10]])
    found = x.intersect_curves(p, q, tol=1e-15)
    exact = _reference(p, q, *found[0])
    assert np.all(np.abs(found[0] - exact) <= 2 * np.spacing(np.abs(exact)))
    rational = x.intersect_curves(p, q, tol=1e-15, p_weights=[1.0, 3.0], q_weights=[2.0, 1.0])
    exact = _reference(p, q, *rational[0], [1.0, 3.0], [2.0, 1.0])
    assert np.all(np.abs(rational[0] - exact) <= 4 * np.spacing(np.abs(exact)))


@pytest.mark.parametrize("p, q, expected", [
    ([(0.0, 0.0), (1.0, 0.0), (2.0, 1.0)], [(-1.0, 0.0), (0.0, 0.0)], [[0.0, 1.0]]),  # tangent at a shared end
    ([(0.0, 0.0), (1.0, 0.0), (2.0, 1.0)], [(-1.0, 0.0), (1.0, 0.0)], [[0.0, 0.5]]),  # an end on the tangent
    ([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [(1.0, 0.0), (1.0, 1.5), (-0.5, 1.5)], [[0.0, 0.0]]),  # bezier #43
])
def test_tangent_end_points_come_out_exactly(p, q, expected):
    for tol in (1e-9, 1e-12, 1e-14):
        assert x.intersect_curves(p, q, tol=tol).tolist() == expected


def test_a_tangency_is_refined_on_the_tangency_system_whatever_the_tol():
    # y = x² and y = 2x²: parabolas touching at t = u = 1/2 with different curvatures; and the asymmetric
    # tangency of a cubic on the x-axis at t = 0.3.
    p, q = [(-1.0, 1.0), (0.0, -1.0), (1.0, 1.0)], [(-1.0, 2.0), (0.0, -2.0), (1.0, 2.0)]
    xs = power_to_bernstein(np.array([0.0, 1.0, 0.4, 0.0]))
    ys = power_to_bernstein(np.array([0.09, -0.6, 1.0, 0.0]))
    for tol in (1e-4, 1e-9, 1e-15):
        found = x.intersect_curves(p, q, tol=tol)
        assert found.shape == (1, 2)
        np.testing.assert_allclose(found, [[0.5, 0.5]], atol=1e-15)
        found = x.intersect_curves(np.column_stack([xs, ys]), [(-1.0, 0.0), (3.0, 0.0)], tol=tol)
        assert found.shape == (1, 2)
        np.testing.assert_allclose(found, [[0.3, (0.3 + 0.4 * 0.09 + 1) / 4]], atol=1e-15)


def test_the_two_engines_agree():
    # Polynomial curves are clipped on Python floats; the same curves given unit weights are rational
    # ones and go through the batched NumPy search (and the rational evaluation). Both agree.
    rng = np.random.default_rng(95)
    pairs = [(rng.uniform(-1, 1, (n + 1, 2)), rng.uniform(-1, 1, (m + 1, 2)))
             for n, m in rng.integers(1, 9, (40, 2))]
    pairs += [
        ([(0.0, 1.0), (0.5, -1.0), (1.0, 1.0)], [(0.0, 0.0), (1.0, 0.0)]),  # a tangency
        ([(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)], [(4.0, 0.0), (5.0, -2.0), (6.0, 1.0)]),  # G1 joint
        example("five_intersections").args("p", "q"),
    ]
    scalar = [x.intersect_curves(p, q) for p, q in pairs]
    batched = [x.intersect_curves(p, q, p_weights=np.ones(len(p)), q_weights=np.ones(len(q))) for p, q in pairs]
    for a, b in zip(scalar, batched):
        assert a.shape == b.shape
        np.testing.assert_allclose(a, b, atol=1e-12)
    assert sum(len(a) for a in scalar) >= 30


def _plain_intersections(p, q, tol=1e-9, p_weights=None, q_weights=None, perpendicular=True):
    """The same search one pair of pieces and one clip at a time: the stepper `clip_trace` records."""
    pts_p, pts_q, hp, hq = x._curve_pair(p, q, p_weights, q_weights)
    search = x._Search(hp, hq, (p_weights is not None, q_weights is not None), tol, x.MAX_STEPS, perpendicular)
    return x._merge_boxes(search.run(), tol, pts_p, pts_q, p_weights, q_weights)


def test_the_batched_search_agrees_with_the_plain_stepper():
    # intersect_curves clips all live pairs of pieces at once; the plain search takes them one by one.
    rng = np.random.default_rng(91)
    found = 0
    for trial in range(60):
        n, m = rng.integers(1, 7, 2)
        p, q = rng.uniform(-1, 1, (n + 1, 2)), rng.uniform(-1, 1, (m + 1, 2))
        weights = {}
        if trial % 2:  # every other pair rational, one curve or both
            weights["p_weights"] = rng.uniform(0.2, 3, n + 1)
            if trial % 4 == 3:
                weights["q_weights"] = rng.uniform(0.2, 3, m + 1)
        perpendicular = trial % 3 != 0
        batched = x.intersect_curves(p, q, perpendicular=perpendicular, **weights)
        plain = _plain_intersections(p, q, perpendicular=perpendicular, **weights)
        assert batched.shape == plain.shape, (trial, p.tolist(), q.tolist(), weights)
        np.testing.assert_allclose(batched, plain, atol=1e-9)
        for t, u in batched:
            np.testing.assert_allclose(evaluate(p, t, weights.get("p_weights")),
                                       evaluate(q, u, weights.get("q_weights")), atol=1e-7)
        found += len(batched)
    assert found >= 40
    # The notes' examples, a tangency and shared end points come out of both alike.
    for name in ("clip_curves", "five_intersections"):
        ex = example(name)
        np.testing.assert_allclose(x.intersect_curves(*ex.args("p", "q")), _plain_intersections(*ex.args("p", "q")),
                                   atol=1e-11)
    parabola, tangent = [(0.0, 1.0), (0.5, -1.0), (1.0, 1.0)], [(0.0, 0.0), (1.0, 0.0)]
    np.testing.assert_allclose(x.intersect_curves(parabola, tangent), _plain_intersections(parabola, tangent),
                               atol=1e-7)
    cubic, joined = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)], [(4.0, 0.0), (5.0, -2.0), (6.0, 1.0)]
    assert x.intersect_curves(cubic, joined).tolist() == _plain_intersections(cubic, joined).tolist() == [[1.0, 0.0]]


def test_batched_pieces_are_the_pieces_of_curve_piece():
    rng = np.random.default_rng(92)
    for n in (1, 3, 6):
        h = rng.uniform(-2, 2, (n + 1, 3))
        h[:, 2] = rng.uniform(0.5, 2, n + 1)
        other = rng.uniform(-2, 2, (n + 1, 3))
        lo = np.sort(rng.uniform(0, 1, (2, 2, 5)), axis=0)
        lo[:, :, 0] = [[0.0, 0.0], [1.0, 1.0]]  # the whole curve
        lo[:, :, 1] = [[0.3, 0.7], [0.3, 0.7]]  # a single point
        folded, degree, _ = x._batch_curves(h, other)
        pieces = x._batch_pieces(lo[0], lo[1], folded, degree)
        for k in range(5):
            points, weights = x.curve_piece(h[:, :2] / h[:, 2:], (lo[0, 0, k], lo[1, 0, k]), h[:, 2])
            np.testing.assert_allclose(pieces[0, k, :, :2] / pieces[0, k, :, 2:], points, atol=1e-13)
            np.testing.assert_allclose(pieces[0, k, :, 2], weights, rtol=1e-13)
    # A lower degree is elevated first: the same curve, its pieces those of the elevated control points.
    line, cubic = np.array([[0.0, 0.0, 1.0], [3.0, 3.0, 1.0]]), rng.uniform(-1, 1, (4, 3))
    folded, degree, _ = x._batch_curves(line, cubic)
    piece = x._batch_pieces(np.array([[0.25], [0.0]]), np.array([[0.75], [1.0]]), folded, degree)[0, 0]
    np.testing.assert_allclose(piece[:, :2], [[0.75, 0.75], [1.25, 1.25], [1.75, 1.75], [2.25, 2.25]], atol=1e-15)


def test_batched_clips_agree_with_the_plain_clip():
    # One clip of many pieces at once: the kept ranges of clip_curve / the one-sided clips, to rounding.
    rng = np.random.default_rng(93)
    for n in (2, 3, 5):
        pieces = rng.uniform(-1, 1, (2, 40, n + 1, 3))
        pieces[..., 2] = np.where(rng.uniform(size=(2, 40, 1)) < 0.5, 1.0, rng.uniform(0.3, 3, (2, 40, n + 1)))
        for perpendicular in (False, True):
            sides = x._batch_fat_lines(pieces, 1e-12, perpendicular)[0]
            with np.errstate(divide="ignore", invalid="ignore"):  # segments parallel to a side have no crossing
                lo, hi = x._batch_kept(pieces @ sides[::-1], n)
            for c in range(2):
                for k in range(40):
                    other = pieces[1 - c, k]
                    kept = (0.0, 1.0)
                    for line, low, high in x._bands(other[:, :2] / other[:, 2:], 1e-12, perpendicular):
                        kept = x._common(kept, x._clip_homogeneous(pieces[c, k], line, low, high, True))
                    if kept is None:
                        assert not lo[c, k] <= hi[c, k]
                    else:
                        np.testing.assert_allclose([lo[c, k], hi[c, k]], kept, atol=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    (dict(p=[(0.0, 0.0)], q=[(0.0, 0.0), (1.0, 1.0)]), "^p"),
    (dict(p=[(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], q=[(0.0, 0.0), (1.0, 1.0)]), "^p"),
    (dict(p=[(0.0, 0.0), (1.0, 1.0)], q=[(0.0, 1.0), (1.0, 0.0)], q_weights=[1.0, -1.0]), "^q_weights"),
    (dict(p=[(0.0, 0.0), (1.0, 1.0)], q=[(0.0, 1.0), (1.0, 0.0)], p_weights=[1.0]), "^p_weights"),
    (dict(p=[(0.0, 0.0), (1.0, 1.0)], q=[(0.0, 1.0), (1.0, 0.0)], tol=0.0), "^tol"),
    (dict(p=[(0.0, 0.0), (1.0, 1.0)], q=[(0.0, 1.0), (1.0, 0.0)], tol=1e-16), "^tol: 1e-16 is below 1e-15"),
    (dict(p=[(0.0, 0.0), (1.0, np.nan)], q=[(0.0, 1.0), (1.0, 0.0)]), "^p: expected finite"),
])
def test_bad_input_is_rejected(kwargs, message):
    with pytest.raises(ValueError, match=message):
        x.intersect_curves(**kwargs)

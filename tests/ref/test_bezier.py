"""Unit tests of cagd_ref.bezier: polynomial and rational Bézier curves (chapter 2 of the notes)."""

from __future__ import annotations

from math import comb

import numpy as np
import pytest
from scipy.interpolate import BPoly, BSpline

from cagd_course.examples import notes_example
from cagd_ref import bezier as b
from cagd_ref.polynomials import bernstein_horner, horner, power_to_bernstein

CIRCLE = notes_example("02.quarter_circle")
QUARTER, QUARTER_WEIGHTS = CIRCLE.results["points"], CIRCLE.results["weights"]


def random_curve(seed: int, degree: int = 3, dim: int = 2, rational: bool = False):
    """Control points (degree+1, dim) and, for a rational curve, positive weights in [0.5, 2]."""
    rng = np.random.default_rng(seed)
    points = rng.uniform(-5, 5, size=(degree + 1, dim))
    weights = rng.uniform(0.5, 2.0, size=degree + 1) if rational else None
    return points, weights


def direct_rational(points, weights, t):
    """Σ w_i P_i B_i^n(t) / Σ w_i B_i^n(t) summed term by term from the definition."""
    n = len(points) - 1
    t = np.asarray(t, dtype=float)[:, None]
    basis = [comb(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]
    numerator = sum(w * p * B for w, p, B in zip(weights, points, basis))
    denominator = sum(w * B for w, B in zip(weights, basis))
    return numerator / denominator


def finite_difference(f, t, order, scale=1.0):
    """Derivative of order 1, 2 or 3 of f at t by central differences (error O(h⁴), O(h⁴), O(h²)).

    The step h is chosen per order (times `scale`, the length of the parameter interval) to
    balance truncation against rounding error.
    """
    h = scale * (1e-2 if order < 3 else 1e-3)
    v = {j: f(t + j * h) for j in (-2, -1, 0, 1, 2)}
    if order == 1:
        return (-v[2] + 8 * v[1] - 8 * v[-1] + v[-2]) / (12 * h)
    if order == 2:
        return (-v[2] + 16 * v[1] - 30 * v[0] + 16 * v[-1] - v[-2]) / (12 * h * h)
    return (v[2] - 2 * v[1] + 2 * v[-1] - v[-2]) / (2 * h**3)


def test_every_public_name_is_tested():
    # Each name has at least one test below; keep this list in step with the module.
    tested = {
        "bernstein", "bernstein_matrix", "de_casteljau", "de_casteljau_plain", "de_casteljau_triangle", "subdivide",
        "elevate", "hodograph", "evaluate", "derivative", "curvature", "signed_curvature", "to_homogeneous",
        "from_homogeneous", "endpoint_derivatives", "endpoint_curvature", "circular_arc",
        "reparametrize_weights", "change_interval", "explicit_bezier", "explicit_rational_bezier",
        "difference_bound", "hausdorff_distance", "directed_hausdorff", "extreme_parameters", "bounding_box",
        "arc_length",
    }
    assert set(b.__all__) == tested


# --- Bernstein polynomials (Notes §2.1) --------------------------------------------------


def test_cubic_bernstein_polynomials():
    example = notes_example("02.bernstein_cubic")
    n = int(example.inputs["n"])
    t = np.linspace(-0.5, 1.5, 9)
    expected = [(1 - t) ** 3, 3 * t * (1 - t) ** 2, 3 * t**2 * (1 - t), t**3]
    for i, values in enumerate(expected):
        np.testing.assert_allclose(b.bernstein(i, n, t), values, atol=1e-14)
        assert b.bernstein(i, n, 0.5) == example.results["binomials"][i] / 2**n
    assert isinstance(b.bernstein(1, 3, 0.5), float)
    assert b.bernstein(1, 3, 0.5) == 0.375
    assert b.bernstein(0, 0, 0.3) == 1.0


@pytest.mark.parametrize("n", range(0, 8))
def test_bernstein_properties(n):
    t = np.random.default_rng(n).uniform(0, 1, 50)
    matrix = b.bernstein_matrix(n, t)
    assert matrix.shape == (50, n + 1)
    np.testing.assert_allclose(matrix.sum(axis=1), 1.0, rtol=1e-13)  # partition of unity
    assert np.all(matrix >= 0)  # nonnegative on [0, 1]
    for i in range(n + 1):
        np.testing.assert_allclose(b.bernstein(i, n, t), matrix[:, i], rtol=1e-14)
        np.testing.assert_allclose(b.bernstein(i, n, t), b.bernstein(n - i, n, 1 - t), rtol=1e-12, atol=1e-15)
        # SciPy's Bernstein-form polynomial with the i-th unit coefficient is B_i^n.
        unit = np.eye(n + 1)[:, i][:, None]
        np.testing.assert_allclose(b.bernstein(i, n, t), BPoly(unit, [0, 1])(t), rtol=1e-12, atol=1e-15)
    # Each B_i^n peaks at t = i/n (n >= 1).
    if n:
        grid = np.linspace(0, 1, 1001)
        peaks = grid[np.argmax(b.bernstein_matrix(n, grid), axis=0)]
        np.testing.assert_allclose(peaks, np.arange(n + 1) / n, atol=1e-3)
    # A number t gives the one row (n+1,) of all the polynomials there.
    assert b.bernstein_matrix(n, 0.3).shape == (n + 1,)
    np.testing.assert_allclose(b.bernstein_matrix(n, 0.3), [b.bernstein(i, n, 0.3) for i in range(n + 1)], rtol=1e-14)


# --- de Casteljau, subdivision, elevation (Notes §2.3, §2.4) ------------------------------


@pytest.mark.parametrize("degree, dim", [(0, 2), (1, 1), (2, 2), (3, 2), (3, 3), (5, 4), (8, 2)])
def test_de_casteljau_against_bernstein_sum_and_scipy(degree, dim, bezier_polynomials):
    points, _ = random_curve(degree * 10 + dim, degree, dim)
    t = np.random.default_rng(degree).uniform(-0.2, 1.2, 17)
    values = b.de_casteljau(points, t)
    assert values.shape == (17, dim)
    np.testing.assert_allclose(values, b.bernstein_matrix(degree, t) @ points, atol=1e-11)
    spline = BSpline(np.r_[np.zeros(degree + 1), np.ones(degree + 1)], points, degree)
    np.testing.assert_allclose(values, spline(t), atol=1e-11)
    peer = np.column_stack([poly(t) for poly in bezier_polynomials(points)])
    np.testing.assert_allclose(values, peer, atol=1e-10)
    # A scalar parameter gives one point; endpoint interpolation.
    single = b.de_casteljau(points, 0.3)
    assert single.shape == (dim,)
    np.testing.assert_allclose(single, b.de_casteljau(points, [0.3])[0])
    np.testing.assert_allclose(b.de_casteljau(points, [0.0, 1.0]), points[[0, -1]], atol=1e-14)


def random_parameters(seed: int, k: int = 15) -> np.ndarray:
    """Both ends, a spread of parameters inside [0, 1] and a few outside it (extrapolation)."""
    rng = np.random.default_rng(seed)
    return np.r_[0.0, 1.0, rng.uniform(0, 1, k), rng.uniform(-1.5, -0.1, 3), rng.uniform(1.1, 2.5, 3)]


def test_plain_de_casteljau_is_the_tuned_one(notes_cubic):
    """The teaching form the chapter shows and the block-tuned `de_casteljau` compute the same points."""
    split = notes_example("02.cubic_at_half")
    t = split.inputs["t"]
    np.testing.assert_array_equal(b.de_casteljau_plain(notes_cubic, t), split.results["point"])
    np.testing.assert_array_equal(b.de_casteljau(notes_cubic, t), split.results["point"])
    for seed, (degree, dim) in enumerate([(0, 2), (1, 1), (3, 2), (3, 3), (6, 2), (11, 4)]):
        points, _ = random_curve(seed + 70, degree, dim)
        t = random_parameters(seed)
        plain = b.de_casteljau_plain(points, t)
        assert plain.shape == (len(t), dim)
        np.testing.assert_allclose(plain, b.de_casteljau(points, t), rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(plain[:2], points[[0, -1]], atol=1e-13)   # t = 0 and t = 1: the end points
        for tau in (0.0, 1.0, 0.37, 2.0, -0.5):
            np.testing.assert_allclose(b.de_casteljau_plain(points, tau), b.de_casteljau(points, tau), atol=1e-12)
    # Beyond one block of parameters the tuned form switches to blocks; the results stay the plain ones.
    many = np.linspace(-0.5, 1.5, b.BLOCK + 7)
    np.testing.assert_allclose(b.de_casteljau(notes_cubic, many), b.de_casteljau_plain(notes_cubic, many), atol=1e-12)


def test_de_casteljau_triangle(notes_cubic):
    split = notes_example("02.cubic_at_half")
    levels = b.de_casteljau_triangle(notes_cubic, split.inputs["t"])
    assert [level.shape for level in levels] == [(4, 2), (3, 2), (2, 2), (1, 2)]
    np.testing.assert_array_equal(levels[0], notes_cubic)
    np.testing.assert_allclose(levels[1], split.results["level1"])
    np.testing.assert_allclose(levels[2], split.results["level2"])
    np.testing.assert_allclose(levels[-1][0], split.results["point"])
    np.testing.assert_allclose(levels[-1][0], b.de_casteljau(notes_cubic, 0.5))
    # The last two points span the tangent: n (P^{n-1}_1 - P^{n-1}_0) = P'(t) on [0, 1].
    np.testing.assert_allclose(3 * (levels[-2][1] - levels[-2][0]), b.derivative(notes_cubic, 0.5))


@pytest.mark.parametrize("split", [0.5, 0.25, 0.9, 2.0, -0.5])
@pytest.mark.parametrize("degree, dim", [(1, 2), (3, 2), (4, 3)])
def test_subdivision_reproduces_both_pieces(split, degree, dim):
    points, _ = random_curve(int(abs(split) * 100) + degree, degree, dim)
    left, right = b.subdivide(points, split)
    assert left.shape == right.shape == points.shape
    s = np.linspace(0, 1, 21)
    # Left is P on [0, split], right is P on [split, 1], both reparametrised to [0, 1];
    # for split outside [0, 1] the pieces extend the curve (extrapolation).
    np.testing.assert_allclose(b.de_casteljau(left, s), b.de_casteljau(points, split * s), atol=1e-10)
    np.testing.assert_allclose(b.de_casteljau(right, s), b.de_casteljau(points, split + (1 - split) * s), atol=1e-9)
    np.testing.assert_allclose(left[0], points[0])
    np.testing.assert_allclose(right[-1], points[-1], atol=1e-12)
    np.testing.assert_allclose(left[-1], right[0])


def test_subdivide_defaults_to_the_midpoint(notes_cubic):
    split = notes_example("02.cubic_at_half")
    left, right = b.subdivide(notes_cubic)
    np.testing.assert_allclose(left, split.results["left"])
    np.testing.assert_allclose(right, split.results["right"])


def test_subdivision_beyond_the_curve_notes_figure():
    beyond = notes_example("02.split_beyond")
    points, tau = beyond.args("points", "t")
    levels = b.de_casteljau_triangle(points, tau)
    np.testing.assert_allclose(levels[1], beyond.results["level1"])
    np.testing.assert_allclose(levels[2][0], beyond.results["point"])
    left, right = b.subdivide(points, tau)
    np.testing.assert_allclose(left, beyond.results["left"])
    np.testing.assert_allclose(right, beyond.results["right"])
    s = np.linspace(0, 1, 9)
    np.testing.assert_allclose(b.de_casteljau(left, s), b.de_casteljau(points, tau * s), atol=1e-12)  # over [0, 2]


def test_elevation_notes_formula_for_a_cubic(notes_cubic):
    alpha = notes_example("02.cubic_elevation").results["alpha"]
    p = np.random.default_rng(11).normal(size=(4, 3))
    expected = [p[0], p[0] / 4 + 3 * p[1] / 4, 2 * p[1] / 4 + 2 * p[2] / 4, 3 * p[2] / 4 + p[3] / 4, p[3]]
    np.testing.assert_allclose(b.elevate(p), expected, atol=1e-15)
    padded = np.vstack([p[:1], p]), np.vstack([p, p[-1:]])       # P_(i-1) and P_i, the undefined ends weighted 0
    np.testing.assert_allclose(b.elevate(p), alpha[:, None] * padded[0] + (1 - alpha[:, None]) * padded[1], atol=1e-15)
    np.testing.assert_allclose(b.elevate(notes_cubic), notes_example("02.cubic_elevated").results["elevated"])


@pytest.mark.parametrize("degree, times", [(0, 1), (1, 2), (3, 1), (3, 4), (6, 3)])
def test_elevation_keeps_the_curve(degree, times):
    points, _ = random_curve(degree + times, degree, 3)
    raised = b.elevate(points, times)
    assert raised.shape == (degree + 1 + times, 3)
    t = np.linspace(-0.5, 1.5, 31)
    np.testing.assert_allclose(b.de_casteljau(raised, t), b.de_casteljau(points, t), atol=1e-10)
    step_by_step = points
    for _ in range(times):
        step_by_step = b.elevate(step_by_step)
    np.testing.assert_allclose(raised, step_by_step, atol=1e-14)
    np.testing.assert_array_equal(b.elevate(points, 0), points)


def test_repeated_elevation_converges_to_the_curve():
    points, _ = random_curve(12, 4, 2)

    def polygon_error(times):
        raised = b.elevate(points, times)
        n = len(raised) - 1
        return np.abs(raised - b.de_casteljau(points, np.arange(n + 1) / n)).max()

    e10, e100 = polygon_error(10), polygon_error(100)
    assert e100 < 0.2 * e10  # the polygon approaches the curve like 1/(number of elevations)


# --- hodographs and derivatives (Notes §2.7, §2.9.2) --------------------------------------


def test_hodograph_table_of_the_notes():
    table = notes_example("02.hodograph_table")
    points, interval = table.args("points", "interval")
    t0, t1 = interval
    first = b.hodograph(points, interval)
    second = b.hodograph(first, interval)
    third = b.hodograph(second, interval)
    np.testing.assert_array_equal(first, table.results["first"])
    np.testing.assert_array_equal(second, table.results["second"])
    np.testing.assert_array_equal(third, table.results["third"])
    # Read off the table: P'(1/2) = (6, -24), P''(0) = (48, -72), P''' is constant.
    np.testing.assert_allclose(b.derivative(points, t1, 1, interval=interval), table.results["first_at_end"])
    np.testing.assert_allclose(b.derivative(points, t0, 2, interval=interval), table.results["second_at_start"])
    third_derivative = b.derivative(points, [0.1, 0.3], 3, interval=interval)
    np.testing.assert_allclose(third_derivative, np.tile(table.results["third"], (2, 1)))
    np.testing.assert_allclose(b.derivative(points, 0.2, 4, interval=interval), (0, 0))


def test_hodograph_of_a_constant_is_zero():
    np.testing.assert_array_equal(b.hodograph([[3.0, 4.0]]), [[0.0, 0.0]])


@pytest.mark.parametrize("interval", [(0, 1), (0, 0.5), (-2, 3), (5, 9)])
@pytest.mark.parametrize("degree", [1, 3, 5])
def test_derivatives_against_numpy_polynomials(degree, interval, bezier_polynomials):
    points, _ = random_curve(degree, degree, 2)
    t0, t1 = interval
    t = np.linspace(t0, t1, 13)
    polys = bezier_polynomials(points, interval)
    hodo = b.hodograph(points, interval)
    np.testing.assert_allclose(hodo, degree / (t1 - t0) * np.diff(points, axis=0))
    np.testing.assert_allclose(
        b.evaluate(hodo, t, interval=interval), np.column_stack([p.deriv()(t) for p in polys]), rtol=1e-9, atol=1e-9
    )
    for order in range(0, degree + 2):
        expected = np.column_stack([p.deriv(order)(t) for p in polys])
        got = b.derivative(points, t, order, interval=interval)
        assert got.shape == (13, 2)
        np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-9 * max(1.0, np.abs(expected).max()))
    # The derivative over [t0, t1] is the one over [0, 1] scaled by 1/(t1 - t0) per order.
    s = (t - t0) / (t1 - t0)
    np.testing.assert_allclose(
        b.derivative(points, t, 2, interval=interval), b.derivative(points, s, 2) / (t1 - t0) ** 2,
        rtol=1e-10, atol=1e-9,
    )


@pytest.mark.parametrize("seed", range(4))
def test_polynomial_derivative_against_finite_differences(seed):
    points, _ = random_curve(seed, 4, 3)
    for t in (0.2, 0.5, 0.8):
        for order in (1, 2, 3):
            fd = finite_difference(lambda x: b.evaluate(points, x), t, order)
            np.testing.assert_allclose(b.derivative(points, t, order), fd, rtol=1e-4, atol=1e-4 * np.abs(fd).max())


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("order", [1, 2, 3])
def test_rational_derivative_against_finite_differences(seed, order):
    points, weights = random_curve(seed, 2 + seed % 3, 2 + seed % 2, rational=True)
    interval = (0, 1) if seed % 2 else (1, 3)
    t0, t1 = interval
    for t in t0 + (t1 - t0) * np.array([0.2, 0.5, 0.8]):
        fd = finite_difference(lambda x: b.evaluate(points, x, weights, interval), t, order, t1 - t0)
        got = b.derivative(points, t, order, weights, interval)
        np.testing.assert_allclose(got, fd, atol=2e-4 * np.abs(fd).max() + 1e-8)
    # Equal weights give back the polynomial derivative.
    np.testing.assert_allclose(
        b.derivative(points, [0.1, 0.6], order, np.full(len(points), 3.0)),
        b.derivative(points, [0.1, 0.6], order),
        rtol=1e-10, atol=1e-9,
    )


# --- evaluation, homogeneous coordinates, rational curves (Notes §2.2, §2.9) ---------------


@pytest.mark.parametrize("seed", range(5))
def test_rational_evaluation_matches_the_definition(seed):
    points, weights = random_curve(seed, 1 + seed, 2 + seed % 2, rational=True)
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(b.evaluate(points, t, weights), direct_rational(points, weights, t), atol=1e-12)
    # Scaling all weights does not change the curve.
    np.testing.assert_allclose(b.evaluate(points, t, 7.5 * weights), b.evaluate(points, t, weights), atol=1e-12)
    # The homogeneous curve projects onto the rational one.
    values = b.de_casteljau(b.to_homogeneous(points, weights), t)
    np.testing.assert_allclose(values[:, :-1] / values[:, -1:], b.evaluate(points, t, weights), atol=1e-12)


def test_homogeneous_round_trip():
    points, weights = random_curve(3, 4, 3, rational=True)
    h = b.to_homogeneous(points, weights)
    assert h.shape == (5, 4)
    np.testing.assert_allclose(h[1], weights[1] * np.append(points[1], 1.0))
    back, w = b.from_homogeneous(h)
    np.testing.assert_allclose(back, points, atol=1e-14)
    np.testing.assert_allclose(w, weights)
    # Negative weights are allowed (only zero is a point at infinity).
    h = b.to_homogeneous(points, -weights)
    np.testing.assert_allclose(b.from_homogeneous(h)[0], points, atol=1e-14)


def test_evaluate_over_an_interval_notes_example():
    # P over [0, 1] and Q over [5, 9] with the same control points: P(t) = Q(5 + 4t), Q(s) = P(-5/4 + s/4).
    example = notes_example("02.interval_change")
    p_interval, q_interval = example.args("p_interval", "q_interval")
    (shift, scale), (back_shift, back_scale) = example.results["q_of_p"], example.results["p_of_q"]
    points, weights = random_curve(8, 3, 2, rational=True)
    t = np.linspace(0, 1, 9)
    p = b.evaluate(points, t, weights)
    np.testing.assert_allclose(b.evaluate(points, shift + scale * t, weights, interval=q_interval), p, atol=1e-12)
    q_parameters = b.change_interval(t, p_interval, q_interval)
    np.testing.assert_allclose(b.evaluate(points, q_parameters, weights, q_interval), p, atol=1e-12)
    s = np.linspace(*q_interval, 9)
    np.testing.assert_allclose(b.change_interval(s, q_interval, p_interval), back_shift + back_scale * s)
    assert b.change_interval(0.25, p_interval, q_interval) == 6.0
    on_p = b.de_casteljau(points, back_shift + back_scale * s)
    np.testing.assert_allclose(b.evaluate(points, s, None, q_interval), on_p, atol=1e-12)


def test_reparametrisation_notes_example():
    # P(t) = (t² + t - 1, 2t² - t + 3) with t = 2s + 1 is Q(s) = (4s² + 6s + 1, 8s² + 6s + 4).
    example = notes_example("02.reparametrization")
    p_power, q_power = example.inputs["p_power"], example.results["q_power"]
    p_points, q_points = power_to_bernstein(p_power), power_to_bernstein(q_power)
    s = np.linspace(-1, 2, 13)
    np.testing.assert_allclose(b.evaluate(q_points, s), horner(q_power, s), atol=1e-12)
    shift, scale = example.inputs["shift"], example.inputs["scale"]
    np.testing.assert_allclose(b.evaluate(q_points, s), b.evaluate(p_points, shift + scale * s), atol=1e-12)
    np.testing.assert_allclose(
        b.evaluate(q_points, s), b.evaluate(p_points, b.change_interval(s, (0, 1), (1, 3))), atol=1e-12
    )
    # Q's control points are P's over [1, 3]: split at t = 3 (extrapolating), then at 1/3 of [0, 3].
    over_0_3, _ = b.subdivide(p_points, 3.0)
    _, over_1_3 = b.subdivide(over_0_3, 1 / 3)
    np.testing.assert_allclose(over_1_3, q_points, atol=1e-12)


@pytest.mark.parametrize("b_value", [0.25, 0.5, 2.0, 5.0, -1.0])
def test_reparametrize_weights_keeps_the_curve(b_value):
    points, weights = random_curve(int(abs(b_value) * 8), 3, 2, rational=True)
    new_weights = b.reparametrize_weights(weights, b_value)
    np.testing.assert_allclose(new_weights, weights * b_value ** np.arange(4))
    u = np.linspace(0.05, 0.95, 10)
    t = b_value * u / ((1 - u) + b_value * u)
    denominator = b.bernstein_matrix(3, t) @ weights
    keep = np.abs(denominator) > 1e-3  # for b < 0, t runs outside [0, 1] where w(t) may vanish
    np.testing.assert_allclose(
        b.evaluate(points, u[keep], new_weights), b.evaluate(points, t[keep], weights), rtol=1e-9, atol=1e-9
    )
    np.testing.assert_allclose(b.evaluate(points, [0.0, 1.0], new_weights), points[[0, -1]], atol=1e-12)


def test_negative_reparametrisation_completes_the_quarter_circle():
    example = notes_example("02.negative_weights")
    weights = b.reparametrize_weights(*example.args("weights", "b"))
    np.testing.assert_allclose(weights, example.results["weights"])
    np.testing.assert_allclose(b.evaluate(QUARTER, 0.5, weights), example.results["point_at_half"], atol=1e-15)
    u = np.linspace(0.01, 0.99, 99)
    rest = b.evaluate(QUARTER, u, weights)
    np.testing.assert_allclose(np.linalg.norm(rest, axis=1), 1.0, rtol=1e-12)
    # Every point is off the first-quadrant arc, and the three other quadrants are all reached.
    assert np.all((rest[:, 0] < -1e-9) | (rest[:, 1] < -1e-9))
    quadrants = {(x > 0, y > 0) for x, y in rest if min(abs(x), abs(y)) > 1e-6}
    assert quadrants == {(False, True), (False, False), (True, False)}


# --- curvature (Notes §2.9.3) --------------------------------------------------------------


def test_quarter_circle_has_unit_radius_and_curvature():
    points, weights = b.circular_arc(*CIRCLE.args("center", "radius", "start_angle", "sweep"))
    np.testing.assert_allclose(points, QUARTER, atol=1e-15)
    np.testing.assert_allclose(weights, QUARTER_WEIGHTS, rtol=1e-15)
    cubic = b.circular_arc(*CIRCLE.args("center", "radius", "start_angle", "sweep"), degree=3)
    np.testing.assert_allclose(cubic[1], CIRCLE.results["cubic_weights"], rtol=1e-15)
    t = np.linspace(0, 1, 21)
    np.testing.assert_allclose(np.linalg.norm(b.evaluate(QUARTER, t, QUARTER_WEIGHTS), axis=1), 1.0, rtol=1e-14)
    np.testing.assert_allclose(b.curvature(QUARTER, t, QUARTER_WEIGHTS), CIRCLE.results["curvature"], rtol=1e-12)
    np.testing.assert_allclose(b.signed_curvature(QUARTER, t, QUARTER_WEIGHTS), 1.0, rtol=1e-12)
    assert b.endpoint_curvature(QUARTER, QUARTER_WEIGHTS) == pytest.approx(1.0)
    # Without weights it is a parabola, whose curvature varies.
    kappa = b.curvature(QUARTER, t)
    assert kappa.max() - kappa.min() > 0.5


@pytest.mark.parametrize("seed", range(5))
def test_curvature_matches_the_formula(seed):
    rational = seed % 2 == 1
    points, weights = random_curve(seed, 3, 2, rational)
    t = np.linspace(0.05, 0.95, 7)
    d1, d2 = b.derivative(points, t, 1, weights), b.derivative(points, t, 2, weights)
    signed = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    np.testing.assert_allclose(b.signed_curvature(points, t, weights), signed, rtol=1e-9)
    np.testing.assert_allclose(b.curvature(points, t, weights), np.abs(signed), rtol=1e-9)
    assert isinstance(b.curvature(points, 0.5, weights), float)
    assert b.curvature(points, 0.5, weights) == pytest.approx(abs(signed[3]), rel=1e-9)
    # In 3-D the formula is |P' x P''| / |P'|³.
    points3, weights3 = random_curve(seed + 50, 4, 3, rational)
    d1, d2 = b.derivative(points3, t, 1, weights3), b.derivative(points3, t, 2, weights3)
    expected = np.linalg.norm(np.cross(d1, d2), axis=1) / np.linalg.norm(d1, axis=1) ** 3
    np.testing.assert_allclose(b.curvature(points3, t, weights3), expected, rtol=1e-9)


@pytest.mark.parametrize("seed", range(3))
def test_curvature_is_a_geometric_quantity(seed):
    points, weights = random_curve(seed, 3, 2, rational=True)
    t = np.linspace(0.1, 0.9, 5)
    kappa = b.curvature(points, t, weights)
    # Scaling all weights, changing the parameter interval, reparametrising rationally:
    np.testing.assert_allclose(b.curvature(points, t, 3.0 * weights), kappa, rtol=1e-10)
    s = 5 + 4 * t
    d1 = b.derivative(points, s, 1, weights, (5, 9))
    d2 = b.derivative(points, s, 2, weights, (5, 9))
    over_5_9 = np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    np.testing.assert_allclose(over_5_9, kappa, rtol=1e-9)
    factor = 2.5
    u = t / (factor - factor * t + t)  # inverse of t = b u / ((1 - u) + b u)
    np.testing.assert_allclose(b.curvature(points, u, b.reparametrize_weights(weights, factor)), kappa, rtol=1e-9)
    # Rigid motions keep it, uniform scaling by c divides it by c.
    angle = 0.7
    rotation = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    np.testing.assert_allclose(b.curvature(points @ rotation.T + (3, -1), t, weights), kappa, rtol=1e-9)
    np.testing.assert_allclose(b.curvature(2 * points, t, weights), kappa / 2, rtol=1e-9)


def test_curvature_at_a_cusp_is_infinite_and_of_a_line_is_zero():
    cusp = np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]])
    np.testing.assert_allclose(b.derivative(cusp, 0.5), (0.0, 0.0), atol=1e-15)
    assert b.curvature(cusp, 0.5) == np.inf
    line = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 4.0], [5.0, 10.0]])
    np.testing.assert_allclose(b.curvature(line, np.linspace(0, 1, 5)), 0.0, atol=1e-12)


def test_signed_curvature_sign():
    ccw = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])  # turns left
    assert b.signed_curvature(ccw, 0.5) > 0
    assert b.signed_curvature(ccw[::-1], 0.5) == pytest.approx(-b.signed_curvature(ccw, 0.5))
    mirrored = ccw * (1, -1)
    assert b.signed_curvature(mirrored, 0.5) == pytest.approx(-b.signed_curvature(ccw, 0.5))


# --- endpoint formulas (Notes (2.11)-(2.13)) --------------------------------------------------


def test_endpoint_curvature_notes_example():
    # Weights (1, 2, 4), first leg a = 5 long, P2 at height h = 4 above the line P0 P1: κ(0) = 2/25.
    example = notes_example("02.endpoint_curvature")
    points, weights = example.args("points", "weights")
    leg, diagonal = points[1] - points[0], points[2] - points[0]
    assert np.linalg.norm(leg) == example.results["leg"]
    assert abs(leg[0] * diagonal[1] - leg[1] * diagonal[0]) / np.linalg.norm(leg) == example.results["height"]
    kappa = example.results["curvature"]
    assert b.endpoint_curvature(points, weights) == pytest.approx(kappa, rel=1e-12)
    assert b.curvature(points, 0.0, weights) == pytest.approx(kappa, rel=1e-12)
    # Any other points with the same a and h give the same κ(0): turned, moved, and P2 slid along the leg's line.
    other = np.array([[0.0, 0.0], [3.0, 4.0], [3.0 - 3.2, 4.0 + 2.4]])
    assert b.endpoint_curvature(other, weights) == pytest.approx(kappa, rel=1e-12)


@pytest.mark.parametrize("seed", range(6))
def test_endpoint_formulas_match_the_derivatives(seed):
    rational = seed % 3 != 0
    points, weights = random_curve(seed, 2 + seed % 4, 2 + seed % 2, rational)
    interval = [(0, 1), (2, 2.5), (-3, 4)][seed % 3]
    first, second = b.endpoint_derivatives(points, weights, interval)
    np.testing.assert_allclose(first, b.derivative(points, interval[0], 1, weights, interval), rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(second, b.derivative(points, interval[0], 2, weights, interval), rtol=1e-10, atol=1e-8)
    assert b.endpoint_curvature(points, weights) == pytest.approx(b.curvature(points, 0.0, weights), rel=1e-9)


# --- circular arcs (Notes §2.12) ---------------------------------------------------------------


@pytest.mark.parametrize("degree", [2, 3])
@pytest.mark.parametrize("seed", range(4))
def test_circular_arcs(degree, seed):
    rng = np.random.default_rng(seed)
    center, radius = rng.normal(size=2), rng.uniform(0.5, 3)
    start = rng.uniform(-np.pi, np.pi)
    sweep = rng.choice([-1, 1]) * rng.uniform(0.1, np.pi - 0.1)
    points, weights = b.circular_arc(center, radius, start, sweep, degree)
    assert points.shape == (degree + 1, 2) and weights.shape == (degree + 1,)
    half = np.cos(sweep / 2)
    expected_weights = [1, half, 1] if degree == 2 else [1, (1 + 2 * half) / 3, (1 + 2 * half) / 3, 1]
    np.testing.assert_allclose(weights, expected_weights, rtol=1e-12)
    t = np.linspace(0, 1, 25)
    on_arc = b.evaluate(points, t, weights)
    np.testing.assert_allclose(np.linalg.norm(on_arc - center, axis=1), radius, rtol=1e-12)
    np.testing.assert_allclose(b.curvature(points, t, weights), 1 / radius, rtol=1e-9)
    np.testing.assert_allclose(np.sign(b.signed_curvature(points, t, weights)), np.sign(sweep))
    angles = np.unwrap(np.arctan2(*(on_arc - center).T[::-1]))
    assert angles[0] == pytest.approx(np.angle(np.exp(1j * start)))
    assert angles[-1] - angles[0] == pytest.approx(sweep)
    assert np.all(np.diff(angles) * np.sign(sweep) > 0)  # the arc is swept monotonically
    if degree == 3:
        quadratic = b.circular_arc(center, radius, start, sweep, 2)
        np.testing.assert_allclose(on_arc, b.evaluate(*quadratic[:1], t, quadratic[1]), atol=1e-12)


# --- explicit curves and distances (Notes §2.5, §2.6, §2.15) -------------------------------------


@pytest.mark.parametrize("interval", [(0, 1), (-1, 3)])
@pytest.mark.parametrize("degree", [0, 1, 5])
def test_explicit_bezier_reproduces_the_function(degree, interval):
    coeffs = np.random.default_rng(degree).normal(size=degree + 1)
    points = b.explicit_bezier(coeffs, interval)
    assert points.shape == (max(degree, 1) + 1, 2)
    s = np.linspace(0, 1, 11)
    curve = b.de_casteljau(points, s)
    t0, t1 = interval
    np.testing.assert_allclose(curve[:, 0], t0 + (t1 - t0) * s, atol=1e-13)  # x is the parameter
    np.testing.assert_allclose(curve[:, 1], bernstein_horner(coeffs, s), atol=1e-12)


@pytest.mark.parametrize("degree", [0, 1, 2, 4])
def test_explicit_rational_bezier_reproduces_the_function(degree):
    rng = np.random.default_rng(degree)
    y, w = rng.normal(size=degree + 1), rng.uniform(0.5, 2, degree + 1)
    points, weights = b.explicit_rational_bezier(y, w)
    assert points.shape == (degree + 2, 2) and weights.shape == (degree + 2,)
    t = np.linspace(0, 1, 11)
    curve = b.evaluate(points, t, weights)
    np.testing.assert_allclose(curve[:, 0], t, atol=1e-13)
    np.testing.assert_allclose(curve[:, 1], direct_rational(y[:, None], w, t)[:, 0], atol=1e-12)


def test_difference_bound_bounds_the_distance():
    rng = np.random.default_rng(21)
    t = np.linspace(0, 1, 401)
    for degree_p, degree_q in [(3, 3), (2, 5), (4, 1)]:
        p, q = rng.normal(size=(degree_p + 1, 2)), rng.normal(size=(degree_q + 1, 2))
        bound = b.difference_bound(p, q)
        sampled = np.linalg.norm(b.de_casteljau(p, t) - b.de_casteljau(q, t), axis=1).max()
        assert sampled <= bound + 1e-12
        assert b.difference_bound(q, p) == pytest.approx(bound)
        assert b.hausdorff_distance(p, q, samples=201) <= bound + 1e-12
    # The bound is attained for a translated copy, and vanishes for a degree-raised one.
    p = rng.normal(size=(4, 3))
    assert b.difference_bound(p, p + (0, 3, 4)) == pytest.approx(5.0)
    assert b.difference_bound(p, b.elevate(p, 2)) == pytest.approx(0.0, abs=1e-14)


def test_hausdorff_distance():
    p = np.random.default_rng(2).normal(size=(4, 2))
    assert b.hausdorff_distance(p, p, 201) == pytest.approx(0.0, abs=1e-12)
    # Same point set, different parametrisation: Hausdorff sees no difference, the bound does.
    assert b.hausdorff_distance(p, p[::-1], 201) == pytest.approx(0.0, abs=1e-12)
    assert b.hausdorff_distance(p, b.elevate(p), 201) < 1e-6
    assert b.difference_bound(p, p[::-1]) > 0.1
    # Parallel unit segments one apart; a segment and its first half (one-sided distances differ).
    segment = np.array([[0.0, 0.0], [2.0, 0.0]])
    assert b.hausdorff_distance(segment, segment + (0, 1), 201) == pytest.approx(1.0)
    half = np.array([[0.0, 0.0], [1.0, 0.0]])
    assert b.directed_hausdorff(half, segment, 201) == pytest.approx(0.0, abs=1e-12)
    assert b.directed_hausdorff(segment, half, 201) == pytest.approx(1.0)
    assert b.hausdorff_distance(segment, half, 201) == pytest.approx(1.0)
    assert b.hausdorff_distance(half, segment, 201) == pytest.approx(1.0)  # symmetric
    # A sampled lower bound of the exact value that improves with more samples.
    circle_ish = b.evaluate(QUARTER, np.linspace(0, 1, 3))
    coarse = b.hausdorff_distance(QUARTER, circle_ish, samples=11)
    fine = b.hausdorff_distance(QUARTER, circle_ish, samples=401)
    assert coarse <= fine + 1e-12


# --- bad input (NaN, inf, scalar/array shapes and unmodified inputs are checked in test_contract.py) --------


POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: b.bernstein(3, 2, 0.5), ValueError, "i"),
        (lambda: b.bernstein(-1, 2, 0.5), ValueError, "i"),
        (lambda: b.bernstein(1, 2.0, 0.5), TypeError, "n"),
        (lambda: b.bernstein(True, 2, 0.5), TypeError, "i"),
        (lambda: b.bernstein(1, 2, [[0.5]]), ValueError, "t"),
        (lambda: b.bernstein_matrix("3", 0.5), TypeError, "n"),
        (lambda: b.de_casteljau(np.zeros((0, 2)), 0.5), ValueError, "points"),
        (lambda: b.de_casteljau([1.0, 2.0, 3.0], 0.5), ValueError, "points"),
        (lambda: b.de_casteljau(POINTS, "a"), TypeError, "t"),
        (lambda: b.de_casteljau(POINTS, None), TypeError, "t"),
        (lambda: b.de_casteljau_plain([1.0, 2.0, 3.0], 0.5), ValueError, "points"),
        (lambda: b.de_casteljau_plain(POINTS, [[0.5]]), ValueError, "t"),
        (lambda: b.de_casteljau_triangle(POINTS, [0.1, 0.2]), ValueError, "t"),
        (lambda: b.elevate(POINTS, -1), ValueError, "times"),
        (lambda: b.elevate(POINTS, 1.5), TypeError, "times"),
        (lambda: b.hodograph(POINTS, (1, 0)), ValueError, "interval"),
        (lambda: b.hodograph(POINTS, (1, 1)), ValueError, "interval"),
        (lambda: b.hodograph(POINTS, (0, 1, 2)), ValueError, "interval"),
        (lambda: b.to_homogeneous(POINTS, [1, 0, 1, 1]), ValueError, "weights"),
        (lambda: b.to_homogeneous(POINTS, [1, 1, 1]), ValueError, "weights"),
        (lambda: b.from_homogeneous([[1.0], [2.0]]), ValueError, "homogeneous"),
        (lambda: b.from_homogeneous([[1.0, 0.0], [2.0, 1.0]]), ValueError, "homogeneous"),
        (lambda: b.evaluate(POINTS, 0.5, [1, 0, 1, 1]), ValueError, "weights"),
        (lambda: b.evaluate([[0.0, 0.0], [1.0, 0.0]], 0.5, [1, -1]), ValueError, "t"),
        (lambda: b.evaluate(POINTS, 0.5, None, (2, 1)), ValueError, "interval"),
        (lambda: b.derivative(POINTS, 0.5, -1), ValueError, "order"),
        (lambda: b.derivative(POINTS, 0.5, 1.0), TypeError, "order"),
        (lambda: b.curvature([[0.0], [1.0], [2.0]], 0.5), ValueError, "points"),
        (lambda: b.signed_curvature(np.zeros((3, 3)), 0.5), ValueError, "points"),
        (lambda: b.endpoint_derivatives([[0, 0], [1, 1]]), ValueError, "points"),
        (lambda: b.endpoint_derivatives(POINTS, None, (1, 1)), ValueError, "interval"),
        (lambda: b.endpoint_curvature([[0, 0], [0, 0], [1, 1]]), ValueError, "points"),
        (lambda: b.endpoint_curvature([[0, 0], [1, 0], [1, 1]], [1, 0, 1]), ValueError, "weights"),
        (lambda: b.circular_arc((0, 0), 1, 0, np.pi), ValueError, "sweep"),
        (lambda: b.circular_arc((0, 0), 1, 0, -4.0), ValueError, "sweep"),
        (lambda: b.circular_arc((0, 0), 1, 0, 0), ValueError, "sweep"),
        (lambda: b.circular_arc((0, 0), 0, 0, 1), ValueError, "radius"),
        (lambda: b.circular_arc((0, 0), 1, 0, 1, 4), ValueError, "degree"),
        (lambda: b.circular_arc((0, 0), 1, 0, 1, 2.0), TypeError, "degree"),
        (lambda: b.circular_arc((0, 0, 0), 1, 0, 1), ValueError, "center"),
        (lambda: b.reparametrize_weights([1, 1, 1], 0), ValueError, "b"),
        (lambda: b.reparametrize_weights([], 2), ValueError, "weights"),
        (lambda: b.reparametrize_weights([1, 0, 1], 2), ValueError, "weights"),
        (lambda: b.change_interval(0.5, (1, 0), (0, 1)), ValueError, "old"),
        (lambda: b.change_interval(0.5, (0, 1), (1, 1)), ValueError, "new"),
        (lambda: b.explicit_bezier([[1, 2]]), ValueError, "coeffs"),
        (lambda: b.explicit_bezier([]), ValueError, "coeffs"),
        (lambda: b.explicit_bezier([1, 2], (1, 0)), ValueError, "interval"),
        (lambda: b.explicit_rational_bezier([1, 2], [1, 1, 1]), ValueError, "weights"),
        (lambda: b.explicit_rational_bezier([1, 2], [1, 0]), ValueError, "weights"),
        (lambda: b.explicit_rational_bezier([1, 2], [1, -1]), ValueError, "weights"),
        (lambda: b.difference_bound(POINTS, np.zeros((3, 3))), ValueError, "p, q"),
        (lambda: b.difference_bound(POINTS, []), ValueError, "q"),
        (lambda: b.hausdorff_distance(POINTS, np.zeros((3, 3))), ValueError, "p, q"),
        (lambda: b.hausdorff_distance(POINTS, POINTS, 1), ValueError, "samples"),
        (lambda: b.directed_hausdorff(POINTS, POINTS, 10.0), TypeError, "samples"),
        (lambda: b.extreme_parameters(POINTS, [1, 0, 1, 1]), ValueError, "weights"),
        (lambda: b.bounding_box(POINTS, [1, -1, 1, 1]), ValueError, "weights"),
        (lambda: b.bounding_box([]), ValueError, "points"),
        (lambda: b.arc_length(POINTS, [1, 1, 1]), ValueError, "weights"),
        (lambda: b.arc_length(POINTS, None, 0.0), ValueError, "tol"),
        (lambda: b.arc_length(POINTS, None, 2.0), ValueError, "tol"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


def test_results_are_fresh_arrays():
    # Writing to a result leaves the input alone, even where the result equals (part of) the input.
    points, _ = random_curve(31, 3, 2)
    before = points.copy()
    left, _ = b.subdivide(points, 0.0)
    left[:] = 99
    for value in (b.de_casteljau(points, 0.0), b.de_casteljau_plain(points, 0.0), b.evaluate(points, 0.0)):
        value[:] = 99
    b.de_casteljau_triangle(points, 0.5)[0][:] = 99
    np.testing.assert_array_equal(points, before)


# --- Extreme points, bounding boxes, arc length (the course's own, after Pomax's primer) ---------------


@pytest.mark.parametrize("seed", range(12))
@pytest.mark.parametrize("rational", [False, True])
def test_bounding_box_holds_the_curve_and_touches_it(seed, rational):
    points, weights = random_curve(seed, degree=2 + seed % 5, dim=2 + seed % 2, rational=rational)
    box = b.bounding_box(points, weights)
    samples = b.evaluate(points, np.linspace(0, 1, 20001), weights=weights)
    assert box.shape == (2, points.shape[1])
    assert np.all(samples >= box[0] - 1e-12) and np.all(samples <= box[1] + 1e-12)
    np.testing.assert_allclose(samples.min(axis=0), box[0], atol=1e-7)
    np.testing.assert_allclose(samples.max(axis=0), box[1], atol=1e-7)
    # the convex hull property's box of the control points holds the tight one
    assert np.all(points.min(axis=0) <= box[0] + 1e-12) and np.all(box[1] <= points.max(axis=0) + 1e-12)


def test_extreme_parameters_are_the_ends_and_the_zeros_of_the_hodograph():
    # x' has two roots inside (0, 1), y' one between them
    wide = np.array([[0.5, 0.0], [-1.0, 2.5], [5.0, 3.5], [3.5, 0.0]])
    ts = b.extreme_parameters(wide)
    assert ts[0] == 0 and ts[-1] == 1 and len(ts) == 5 and np.all(np.diff(ts) > 0)
    velocity = b.derivative(wide, ts[1:-1])
    assert np.all(np.isclose(velocity, 0, atol=1e-12).any(axis=1))
    assert abs(b.derivative(wide, ts[2])[1]) < 1e-12 and np.allclose(b.derivative(wide, ts[[1, 3]])[:, 0], 0)
    # a constant coordinate adds nothing; a straight line with uniform speed has no interior extreme
    assert b.extreme_parameters([[0, 1], [1, 1], [2, 1]]).tolist() == [0.0, 1.0]
    # a double root (the straight cubic that stops at t = 1/2) appears once
    straight = [[-1, -1], [1, 1], [-1, -1], [1, 1]]
    np.testing.assert_allclose(b.extreme_parameters(straight), [0, 0.5, 1], atol=1e-7)
    # degree 0: only the ends
    assert b.extreme_parameters([[3.0, 4.0]]).tolist() == [0.0, 1.0]


def test_bounding_boxes_of_circles():
    np.testing.assert_allclose(b.bounding_box(QUARTER, QUARTER_WEIGHTS), [[0, 0], [1, 1]], atol=1e-15)
    ring = [[0, 0], [4, 0], [2, 4], [-2, 4], [-4, 0], [0, 0]]
    np.testing.assert_allclose(b.bounding_box(ring, [5, 1, 1, 1, 1, 5]), [[-1, 0], [1, 2]], atol=1e-12)
    # degree 0: the box of a point
    np.testing.assert_allclose(b.bounding_box([[3.0, 4.0]]), [[3, 4], [3, 4]])


def test_arc_length_of_known_curves():
    assert np.isclose(b.arc_length([[0, 0], [1, 1], [2, 2]]), np.sqrt(8), rtol=1e-14)
    assert np.isclose(b.arc_length(QUARTER, QUARTER_WEIGHTS), np.pi / 2, rtol=1e-13)
    ring = [[0, 0], [4, 0], [2, 4], [-2, 4], [-4, 0], [0, 0]]
    assert np.isclose(b.arc_length(ring, [5, 1, 1, 1, 1, 5]), 2 * np.pi, rtol=1e-13)
    # the parabola y = x², x in [0, 1]: length (2√5 + asinh 2) / 4
    assert np.isclose(b.arc_length([[0, 0], [0.5, 0], [1, 1]]), (2 * np.sqrt(5) + np.arcsinh(2)) / 4, rtol=1e-13)
    # a cusp and a point
    cusp = [[0, 0], [2, 2], [0, 2], [2, 0]]
    fine = b.de_casteljau(cusp, np.linspace(0, 1, 200001))
    assert np.isclose(b.arc_length(cusp), np.linalg.norm(np.diff(fine, axis=0), axis=1).sum(), rtol=1e-9)
    assert b.arc_length([[1.0, 2.0], [1.0, 2.0]]) == 0.0


@pytest.mark.parametrize("seed", range(10))
def test_arc_length_lies_between_chord_and_polygon_and_matches_a_fine_polyline(seed):
    points, _ = random_curve(100 + seed, degree=1 + seed % 6, dim=2 + seed % 2)
    length = b.arc_length(points)
    chord = np.linalg.norm(points[-1] - points[0])
    polygon = np.linalg.norm(np.diff(points, axis=0), axis=1).sum()
    assert chord - 1e-12 <= length <= polygon + 1e-12
    fine = b.de_casteljau(points, np.linspace(0, 1, 100001))
    assert np.isclose(length, np.linalg.norm(np.diff(fine, axis=0), axis=1).sum(), rtol=1e-7)

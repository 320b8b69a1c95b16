"""Unit tests of cagd_ref.interpolation: polynomial interpolation (chapter 10).

Three kinds of checks: the notes' worked examples, read from
cagd_course/examples/ch10.toml and recomputed exactly in fractions by small
independent implementations here; properties (a basis that is one at its node
and zero at the others, the remainder bound, Chebyshev's optimum, the
flattening bound); and peers: scipy.interpolate (BarycentricInterpolator,
lagrange, KroghInterpolator, CubicHermiteSpline), numpy.polynomial
(Vandermonde solves, polyfit, chebpts1) and SymPy.
"""

from __future__ import annotations

import sys
from fractions import Fraction
from math import comb, factorial, prod

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import chebyshev
from numpy.polynomial import polynomial as npoly
from scipy.interpolate import BarycentricInterpolator, CubicHermiteSpline, KroghInterpolator, lagrange

from cagd_course.examples import FOLDER, notes_example
from cagd_ref import bezier, forward_differencing, polynomials
from cagd_ref import interpolation as ip

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

RAW = tomllib.loads((FOLDER / "ch10.toml").read_text(encoding="utf-8"))
POWER = notes_example("10.cubic_power")
NEWTON = notes_example("10.newton")
ROW = notes_example("10.newton_row")
NEVILLE = notes_example("10.neville")
FLATTENING = notes_example("10.flattening")
HERMITE = notes_example("10.hermite")
EVALUATORS = [ip.lagrange_eval, ip.lagrange_eval_plain, ip.neville, ip.neville_plain, ip.barycentric_eval]


def exact(value):
    """The notes' numbers of ch10.toml as Fractions, nested as written ("25/6" -> Fraction(25, 6))."""
    if isinstance(value, list):
        return [exact(v) for v in value]
    return Fraction(value)


def random_data(seed: int, count: int, dim: int = 2):
    """Distinct nodes in random order (not sorted: nothing may assume it) and random points."""
    rng = np.random.default_rng(seed)
    ts = rng.permutation(np.sort(rng.uniform(-2, 3, count)) + np.arange(count) * 0.05)
    return ts, rng.uniform(-5, 5, (count, dim))


def newton_value(ts, coeffs, t):
    """The Newton form summed term by term, Σ c_k Π_{j<k} (t - t_j): the definition, not the nesting."""
    t = np.asarray(t, dtype=float)
    terms = (np.multiply.outer(prod((t - tj for tj in ts[:k]), start=np.ones_like(t)), c) for k, c in enumerate(coeffs))
    return sum(terms)


# --- the notes' examples in exact arithmetic ---------------------------------------------------


def fraction_divided_differences(ts, values):
    """Columns of the divided-difference table, each entry a list of Fractions (one per coordinate)."""
    columns = [values]
    for k in range(1, len(ts)):
        prev = columns[-1]
        columns.append([[(b - a) / (ts[i + k] - ts[i]) for a, b in zip(prev[i], prev[i + 1])]
                        for i in range(len(prev) - 1)])
    return columns


def test_newton_table_of_the_notes_in_fractions():
    data = RAW["newton"]
    ts, points = exact(data["inputs"]["ts"]), exact(data["inputs"]["points"])
    columns = fraction_divided_differences(ts, points)
    assert columns[1] == exact(data["results"]["first_differences"])
    assert columns[2] == exact(data["results"]["second_differences"])
    assert columns[3] == exact(data["results"]["third_differences"])
    coeffs = [column[0] for column in columns]
    assert coeffs == exact(data["results"]["coefficients"])
    tau = Fraction(data["inputs"]["tau"])
    value = [sum(c[axis] * prod(tau - tj for tj in ts[:k]) for k, c in enumerate(coeffs)) for axis in (0, 1)]
    assert value == exact(data["results"]["value"])


def test_divided_differences_reproduce_the_notes_table():
    ts, points = NEWTON.args("ts", "points")
    columns = ip.divided_difference_table(ts, points)
    for k, name in enumerate(["first_differences", "second_differences", "third_differences"], start=1):
        np.testing.assert_allclose(columns[k], NEWTON.results[name], atol=1e-14)
    np.testing.assert_array_equal(columns[0], points)
    np.testing.assert_allclose(ip.divided_differences(ts, points), NEWTON.results["coefficients"], atol=1e-14)


def test_newton_form_gives_the_notes_value_and_expands_to_the_power_form():
    ts, points, tau = NEWTON.args("ts", "points", "tau")
    coeffs = ip.divided_differences(ts, points)
    for evaluate in (ip.newton_eval, ip.lagrange_eval, ip.neville):
        args = (ts, coeffs, tau) if evaluate is ip.newton_eval else (ts, points, tau)
        np.testing.assert_allclose(evaluate(*args), NEWTON.results["value"], atol=1e-13)
    power = ip.newton_to_power(ts, coeffs)
    expanded = np.column_stack([NEWTON.results["x_power"], NEWTON.results["y_power"]])
    np.testing.assert_allclose(power, expanded, atol=1e-13)
    t = sp.Symbol("t")
    pairs = [(int(a), int(b)) for a, b in zip(ts, points[:, 0])]
    assert sp.interpolating_poly(4, t, *zip(*pairs)).subs(t, 2) == sp.Rational(25, 6)  # SymPy, exactly


def test_appending_a_row_reproduces_the_notes_c0_c1_c2():
    data = RAW["newton_row"]
    ts, points = exact(data["inputs"]["ts"]), exact(data["inputs"]["points"])
    bottom = [column[-1] for column in fraction_divided_differences(ts, points)]
    assert bottom == exact(data["results"]["bottom_row"])
    tau, n = Fraction(data["inputs"]["tau"]), len(ts) - 1
    new = [None] * n + [bottom[n]]  # the n-th difference is copied, the rest solved from right to left
    for j in range(n - 1, -1, -1):
        new[j] = [f + (tau - ts[n - j]) * g for f, g in zip(bottom[j], new[j + 1])]
    assert new == exact(data["results"]["new_row"])
    ts_float, points_float = ROW.args("ts", "points")
    row = np.array([column[-1] for column in ip.divided_difference_table(ts_float, points_float)])
    np.testing.assert_allclose(ip.next_table_row(ts_float, row, 2.0), ROW.results["new_row"], atol=1e-13)


def test_marching_row_by_row_follows_the_curve_like_forward_differencing():
    ts, points = random_data(3, 5)
    columns = ip.divided_difference_table(ts, points)
    nodes, row = list(ts), np.array([column[-1] for column in columns])
    coeffs = ip.divided_differences(ts, points)
    for tau in [0.3, -1.25, 2.0, 2.5, 4.0]:  # any parameters, in any order
        row = ip.next_table_row(nodes, row, tau)
        nodes = nodes[1:] + [tau]
        np.testing.assert_allclose(row[0], ip.newton_eval(ts, coeffs, tau), rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(row[-1], coeffs[-1], rtol=1e-9)


def test_neville_levels_of_the_notes_in_fractions_and_floats():
    data = RAW["neville"]
    ts, points, tau = exact(data["inputs"]["ts"]), exact(data["inputs"]["points"]), Fraction(data["inputs"]["tau"])
    level = points
    for r in range(1, len(ts)):
        level = [[((ts[i + r] - tau) * a + (tau - ts[i]) * b) / (ts[i + r] - ts[i])
                  for a, b in zip(level[i], level[i + 1])] for i in range(len(level) - 1)]
        assert level == exact(data["results"][f"level_{r}"])
    triangle = ip.neville_triangle(*NEVILLE.args("ts", "points", "tau"))
    assert [len(level) for level in triangle] == [4, 3, 2, 1]
    for r in (1, 2, 3):
        np.testing.assert_allclose(triangle[r], NEVILLE.results[f"level_{r}"], atol=1e-13)


def test_undetermined_coefficients_of_the_running_cubic():
    data = RAW["cubic_power"]
    ts, points = exact(data["inputs"]["ts"]), exact(data["inputs"]["points"])
    x, y = exact(data["results"]["x_coefficients"]), exact(data["results"]["y_coefficients"])
    for t, (px, py) in zip(ts, points):  # the exact coefficients meet the four conditions
        assert sum(a * t**j for j, a in enumerate(x)) == px and sum(b * t**j for j, b in enumerate(y)) == py
    ts_float, points_float = POWER.args("ts", "points")
    power = ip.power_interpolation(ts_float, points_float)
    stated = np.column_stack([POWER.results["x_coefficients"], POWER.results["y_coefficients"]])
    np.testing.assert_allclose(power, stated, atol=1e-12)
    np.testing.assert_allclose(np.linalg.solve(np.vander(ts_float, increasing=True), points_float), power, atol=1e-12)
    np.testing.assert_allclose(npoly.polyfit(ts_float, points_float, 3), power, atol=1e-9)
    np.testing.assert_allclose(polynomials.horner(power, 0.5), POWER.results["point_at_half"], atol=1e-13)


def test_bernstein_form_of_the_running_cubic():
    example = notes_example("10.cubic_bernstein")
    data = RAW["cubic_bernstein"]
    for t, name in [(Fraction(1, 4), "row_quarter"), (Fraction(3, 4), "row_three_quarters")]:
        assert [comb(3, k) * (1 - t) ** (3 - k) * t**k for k in range(4)] == exact(data["results"][name])
    ts, points = example.args("ts", "points")
    control = ip.bernstein_interpolation(ts, points)
    np.testing.assert_allclose(control, example.results["control_points"], atol=1e-12)
    np.testing.assert_allclose(control, polynomials.power_to_bernstein(ip.power_interpolation(ts, points)), atol=1e-12)
    np.testing.assert_allclose(bezier.de_casteljau(control, ts), points, atol=1e-12)
    # The same curve on another parameter interval: nodes and interval scaled together.
    np.testing.assert_allclose(ip.bernstein_interpolation(2 + 4 * ts, points, interval=(2, 6)), control, atol=1e-12)


def test_lagrange_basis_constants_of_the_notes():
    data = RAW["cubic_lagrange"]
    ts = exact(data["inputs"]["ts"])
    constants = [1 / prod(ti - tj for j, tj in enumerate(ts) if j != i) for i, ti in enumerate(ts)]
    assert constants == exact(data["results"]["basis_constants"])
    example = notes_example("10.cubic_lagrange")
    nodes = example.inputs["ts"]
    t = np.linspace(-0.5, 1.5, 21)
    products = np.array([np.prod([t - nodes[j] for j in range(4) if j != i], axis=0) for i in range(4)]).T
    np.testing.assert_allclose(ip.lagrange_basis(nodes, t), products * example.results["basis_constants"], atol=1e-12)
    # Expanded, the Lagrange form is the power form of §10.1.
    power = ip.power_interpolation(nodes, example.inputs["points"])
    np.testing.assert_allclose(ip.lagrange_eval(nodes, example.inputs["points"], t), polynomials.horner(power, t),
                               atol=1e-11)


# --- Lagrange, Newton and Neville agree with each other and with SciPy --------------------------------------


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("count", [2, 3, 5, 8, 12])
def test_every_form_is_the_same_polynomial_as_scipy_barycentric(seed, count):
    ts, points = random_data(seed, count, dim=1 + seed % 3)
    t = np.linspace(-2.5, 4, 37)
    expected = BarycentricInterpolator(ts, points)(t)
    coeffs = ip.divided_differences(ts, points)
    found = [f(ts, points, t) for f in EVALUATORS] + [
        ip.newton_eval(ts, coeffs, t),
        ip.newton_eval_plain(ts, coeffs, t),
        newton_value(ts, coeffs, t),
    ]
    scale = 1 + np.abs(expected).max()
    for values in found:
        np.testing.assert_allclose(values, expected, atol=1e-9 * scale)


def test_scalar_values_and_scipy_lagrange():
    ts = np.array([0.0, 0.5, 2.0, 3.0])
    values = np.array([1.0, -1.0, 2.0, 0.5])
    polynomial = lagrange(ts, values)
    for f in EVALUATORS:
        assert isinstance(f(ts, values, 1.3), float)
        assert f(ts, values, [1.3, 2.5]).shape == (2,)
        np.testing.assert_allclose(f(ts, values, [1.3, 2.5]), polynomial([1.3, 2.5]), rtol=1e-12)
    coeffs = ip.divided_differences(ts, values)
    assert coeffs.shape == (4,)
    assert isinstance(ip.newton_eval(ts, coeffs, 1.3), float)
    assert isinstance(ip.newton_eval_plain(ts, coeffs, 1.3), float)
    np.testing.assert_allclose(ip.newton_eval(ts, coeffs, 1.3), polynomial(1.3), rtol=1e-12)
    np.testing.assert_allclose(ip.power_interpolation(ts, values), polynomial.coeffs[::-1], rtol=1e-10)


def test_the_basis_is_one_at_its_node_sums_to_one_and_goes_negative():
    ts = notes_example("10.cubic_lagrange").inputs["ts"]
    np.testing.assert_allclose(ip.lagrange_basis(ts, ts), np.eye(4), atol=1e-15)
    t = np.linspace(0, 1, 401)
    basis = ip.lagrange_basis(ts, t)
    np.testing.assert_allclose(basis.sum(axis=1), 1.0, atol=1e-14)
    assert basis.min() < -0.17  # negative weights: no convex hull property
    assert ip.lagrange_basis(ts, 0.5).shape == (4,)
    np.testing.assert_array_equal(ip.lagrange_basis([3.0], [0.0, 7.0]), [[1.0], [1.0]])  # one node: a constant
    for f in EVALUATORS:
        np.testing.assert_array_equal(f([3.0], [[1.0, 2.0]], [0.0, 7.0]), [[1.0, 2.0], [1.0, 2.0]])


def test_the_interpolant_leaves_the_convex_hull_of_its_data():
    # Runge's function at eleven uniform nodes: data in (0, 1], interpolant far outside.
    x = np.linspace(-1, 1, 11)
    p = ip.lagrange_eval(x, 1 / (1 + 25 * x**2), np.linspace(-1, 1, 401))
    assert p.min() < -0.2 and p.max() > 1.9


def test_affine_invariance():
    ts, points = random_data(11, 6)
    matrix, shift = np.array([[2.0, 1.0], [-0.5, 3.0]]), np.array([4.0, -1.0])
    t = np.linspace(-2, 3, 17)
    for f in EVALUATORS:
        np.testing.assert_allclose(f(ts, points @ matrix.T + shift, t), f(ts, points, t) @ matrix.T + shift, atol=1e-9)


def test_the_plain_product_formula_and_the_fast_basis_agree():
    for seed in range(5):
        ts, points = random_data(seed, 3 + 2 * seed, dim=3)
        t = np.concatenate([ts, np.linspace(ts.min() - 1, ts.max() + 1, 23)])
        np.testing.assert_allclose(ip.lagrange_eval(ts, points, t), ip.lagrange_eval_plain(ts, points, t),
                                   rtol=1e-10, atol=1e-10 * np.abs(points).max())


def test_many_parameters_are_evaluated_in_blocks_with_the_same_result():
    ts, points = random_data(5, 6)
    t = np.linspace(-2, 3, 2 * ip.CACHE_NUMBERS + 17)
    coeffs = ip.divided_differences(ts, points)
    for f, data in ((ip.lagrange_eval, points), (ip.neville, points), (ip.newton_eval, coeffs)):
        whole = f(ts, data, t)
        parts = np.vstack([f(ts, data, chunk) for chunk in np.array_split(t, 7)])
        np.testing.assert_array_equal(whole, parts)


def test_high_degree_at_chebyshev_nodes_neither_overflows_nor_underflows():
    nodes = ip.chebyshev_nodes(0.0, 1000.0, 80)
    values = np.cos(nodes / 100)
    t = np.linspace(0, 1000, 301)
    np.testing.assert_allclose(ip.lagrange_eval(nodes, values, t), np.cos(t / 100), atol=1e-10)
    np.testing.assert_allclose(ip.lagrange_basis(nodes, t).sum(axis=1), 1.0, atol=1e-10)


def test_newton_form_ignores_the_last_node_and_allows_repeated_nodes():
    ts, points = random_data(2, 5)
    coeffs = ip.divided_differences(ts, points)
    t = np.linspace(-1, 2, 9)
    moved = ts.copy()
    moved[-1] = 99.0
    np.testing.assert_array_equal(ip.newton_eval(moved, coeffs, t), ip.newton_eval(ts, coeffs, t))
    np.testing.assert_array_equal(ip.newton_eval(ts[:-1], coeffs, t), ip.newton_eval(ts, coeffs, t))
    # Confluent nodes (Hermite data in Newton form): the nesting needs no distinct nodes.
    repeated = np.array([0.0, 0.0, 1.0, 1.0])
    c = np.array([2.0, -1.0, 0.5, 3.0])
    np.testing.assert_allclose(ip.newton_eval(repeated, c, t), newton_value(repeated, c, t), atol=1e-13)
    expanded = ip.newton_to_power(repeated, c)
    np.testing.assert_allclose(npoly.polyval(t, expanded), newton_value(repeated, c, t), atol=1e-13)
    assert ip.newton_eval([], [5.0], [0.0, 1.0]).tolist() == [5.0, 5.0]


def test_divided_differences_of_uniform_data_are_scaled_forward_differences():
    h, ts = 0.5, 1.0 + 0.5 * np.arange(6)
    values = np.random.default_rng(7).uniform(-3, 3, 6)
    table = forward_differencing.forward_difference_table(values)
    expected = [row[0] / (factorial(k) * h**k) for k, row in enumerate(table)]
    np.testing.assert_allclose(ip.divided_differences(ts, values), expected, rtol=1e-12)


def test_divided_differences_are_symmetric_in_the_nodes():
    ts, points = random_data(9, 6)
    order = np.random.default_rng(0).permutation(6)
    shuffled = ip.divided_differences(ts[order], points[order])
    np.testing.assert_allclose(ip.divided_differences(ts, points)[-1], shuffled[-1], rtol=1e-9)


def test_neville_levels_are_the_values_of_the_partial_interpolants():
    ts, points = random_data(4, 6)
    tau = 0.37
    for r, level in enumerate(ip.neville_triangle(ts, points, tau)):
        for i, value in enumerate(level):
            partial = ip.lagrange_eval(ts[i : i + r + 1], points[i : i + r + 1], tau)
            np.testing.assert_allclose(value, partial, atol=1e-10)


def test_newton_to_power_is_the_vandermonde_solution():
    for seed in range(4):
        ts, points = random_data(seed, 2 + seed)
        np.testing.assert_allclose(ip.newton_to_power(ts, ip.divided_differences(ts, points)),
                                   ip.power_interpolation(ts, points), rtol=1e-8, atol=1e-8)


# --- error bounds, Chebyshev nodes, flattening -------------------------------------------------------------


def test_figure_10_5_numbers():
    example = notes_example("10.node_polynomial")
    a, b, count = example.args("a", "b", "count")
    uniform = ip.node_polynomial_max(np.linspace(a, b, count), a, b)
    cheb = ip.node_polynomial_max(ip.chebyshev_nodes(a, b, count), a, b)
    assert round(uniform, 7) == example.results["uniform_max_printed"]
    assert round(cheb, 8) == example.results["chebyshev_max_printed"]
    assert uniform == pytest.approx(example.results["uniform_max"], rel=1e-8)
    assert cheb == pytest.approx(example.results["chebyshev_max"], rel=1e-12)


def test_the_uniform_estimate_of_the_notes_counts_nodes():
    example = notes_example("10.uniform_estimate")
    low, high = example.inputs["counts"].astype(int)
    ratios = [ip.node_polynomial_max(np.linspace(0, 1, n), 0, 1) * 3.0**n for n in range(low, high + 1)]
    assert min(ratios) == pytest.approx(example.results["smallest_ratio"], rel=1e-7)
    assert max(ratios) == pytest.approx(example.results["largest_ratio"], rel=1e-7)
    # Counting n + 1 nodes instead would put the ratio far from one.
    assert max(ip.node_polynomial_max(np.linspace(0, 1, n + 1), 0, 1) * 3.0**n for n in range(low, high + 1)) < 0.4


@pytest.mark.parametrize("a, b, n", [(0.0, 1.0, 9), (-1.0, 1.0, 1), (-1.0, 1.0, 2), (2.0, 7.0, 6), (-3.0, 0.5, 15)])
def test_chebyshev_nodes_are_the_mapped_zeros_and_attain_the_optimum(a, b, n):
    nodes = ip.chebyshev_nodes(a, b, n)
    assert nodes.shape == (n,) and np.all(np.diff(nodes) > 0)
    np.testing.assert_allclose(nodes, a + (b - a) * (chebyshev.chebpts1(n) + 1) / 2, atol=1e-14 * (b - a))
    np.testing.assert_allclose(nodes, np.sort(a + (b - a) * (chebyshev.Chebyshev.basis(n).roots() + 1) / 2), atol=1e-12)
    np.testing.assert_allclose(nodes - a, (b - nodes)[::-1], atol=1e-14 * (b - a))  # symmetric
    assert ip.node_polynomial_max(nodes, a, b) == pytest.approx(2 * ((b - a) / 4) ** n, rel=1e-10)
    # ... which no other node set reaches: the uniform nodes are worse from three nodes on.
    if n >= 3:
        assert ip.node_polynomial_max(np.linspace(a, b, n), a, b) > ip.node_polynomial_max(nodes, a, b)
    np.testing.assert_allclose(ip.chebyshev_nodes(0.0, 1.0, 9), notes_example("10.chebyshev_nine").results["nodes"],
                               atol=5e-9)


def test_node_polynomial_max_is_exact_not_sampled():
    rng = np.random.default_rng(1)
    for _ in range(20):
        nodes = rng.uniform(-1, 2, int(rng.integers(1, 9)))
        a, b = sorted(rng.uniform(-1.5, 2.5, 2))
        x = np.linspace(a, b, 200001)
        sampled = np.abs(ip.node_polynomial(nodes, x)).max()
        found = ip.node_polynomial_max(nodes, a, b)
        assert sampled <= found * (1 + 1e-12) and found == pytest.approx(sampled, rel=1e-6)
    assert ip.node_polynomial_max([0.5, 0.5], 0, 1) == pytest.approx(0.25)  # repeated nodes
    assert ip.node_polynomial(np.array([1.0, 2.0]), 4.0) == 6.0


def test_the_cauchy_remainder_bounds_the_error():
    for count in (2, 4, 7, 10):
        nodes = np.linspace(0, 1, count)
        x = np.linspace(0, 1, 1001)
        error = np.abs(np.exp(x) - ip.lagrange_eval(nodes, np.exp(nodes), x))
        bound = ip.interpolation_error_bound(nodes, np.e, x)  # every derivative of exp is <= e on [0, 1]
        assert np.all(error <= bound + 1e-15)
        assert error.max() > 0.1 * bound.max()  # and it is not wildly pessimistic
    assert isinstance(ip.interpolation_error_bound([0.0, 1.0], 2.0, 0.5), float)
    assert ip.interpolation_error_bound([0.0, 1.0], 2.0, 0.5) == pytest.approx(0.25)  # L δ²/8 with L = 2, δ = 1


def test_linear_segments_for_sin():
    example = notes_example("10.linear_error")
    a, b, bound, tol = example.args("a", "b", "second_derivative_bound", "tol")
    m = ip.linear_segments_needed(a, b, bound, tol)
    assert m == example.results["segments"]

    def chord_error(count):
        u, ends = np.linspace(0, 1, 4001), np.linspace(a, b, count + 1)
        return max(np.abs(np.sin(lo + (hi - lo) * u) - ((1 - u) * np.sin(lo) + u * np.sin(hi))).max()
                   for lo, hi in zip(ends[:-1], ends[1:]))

    assert chord_error(m) == pytest.approx(example.results["measured_error"], rel=1e-5)
    assert chord_error(m) <= tol < chord_error(m - 1)  # the bound is sharp here: fewer chords fail
    assert ip.linear_segments_needed(0.0, 1.0, 0.0, 1e-6) == 1  # a straight line needs one


def test_flattening_the_course_cubic():
    points, tolerances = FLATTENING.args("points", "tolerances")
    np.testing.assert_array_equal(ip.second_derivative_bounds(points), FLATTENING.results["second_derivative_bounds"])
    counts = [ip.bezier_segments_needed(points, tol) for tol in tolerances]
    assert counts == FLATTENING.results["segments"].astype(int).tolist()
    for m, tol, measured in zip(counts, tolerances, FLATTENING.results["measured_deviation"]):
        assert ip.chord_deviation(points, m, samples=4001) == pytest.approx(measured, rel=1e-5)
        assert ip.chord_deviation(points, m) <= tol < ip.chord_deviation(points, m - 1)
        polyline = ip.flatten(points, tol)
        assert polyline.shape == (m + 1, 2)
        np.testing.assert_allclose(polyline[[0, -1]], points[[0, -1]])


def test_chord_gaps_vanish_at_the_chord_ends():
    points = FLATTENING.inputs["points"]
    t, gaps = ip.chord_gaps(points, 4, samples=33)
    assert t.shape == gaps.shape == (4 * 33,)
    np.testing.assert_allclose(gaps[t * 4 == np.round(t * 4)], 0.0, atol=1e-14)
    assert gaps.max() == ip.chord_deviation(points, 4, samples=33)
    mid = np.isclose(t, 0.125)  # the middle of the first chord: the gap of a near-parabolic arc peaks there
    assert gaps[mid][0] == pytest.approx(gaps[:33].max(), rel=0.05)


def test_second_derivative_bounds_hold_and_match_the_second_hodograph():
    rng = np.random.default_rng(4)
    for n in range(2, 7):
        points = rng.uniform(-3, 3, (n + 1, 3))
        bounds = ip.second_derivative_bounds(points)
        second = bezier.hodograph(bezier.hodograph(points))
        np.testing.assert_allclose(bounds, np.abs(second).max(axis=0))
        sampled = np.abs(bezier.derivative(points, np.linspace(0, 1, 201), order=2)).max(axis=0)
        assert np.all(sampled <= bounds + 1e-12)
    np.testing.assert_array_equal(ip.second_derivative_bounds([[1.0, 2.0], [3.0, 5.0]]), [0.0, 0.0])


@pytest.mark.parametrize("seed", range(6))
def test_the_flattening_bound_always_holds(seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-5, 5, (int(rng.integers(2, 7)), int(rng.integers(2, 4))))
    tol = 10 ** rng.uniform(-3, 0)
    m = ip.bezier_segments_needed(points, tol)
    bound = np.linalg.norm(ip.second_derivative_bounds(points)) / (8 * m**2)
    assert ip.chord_deviation(points, m) <= bound <= tol


def test_a_line_needs_one_segment():
    assert ip.bezier_segments_needed([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0], [3.0, 3.0]], 1e-9) == 1
    assert ip.bezier_segments_needed([[0.0, 0.0], [4.0, 1.0]], 1e-9) == 1
    assert ip.bezier_segments_needed([[2.0, 1.0]], 0.1) == 1


# --- Hermite and conditions on derivatives -------------------------------------------------------------------


def test_hermite_example_is_the_flattening_cubic():
    p0, p1, d0, d1 = HERMITE.args("p0", "p1", "d0", "d1")
    np.testing.assert_allclose(ip.hermite_to_bezier(p0, p1, d0, d1), HERMITE.results["bezier"])
    conditions = ip.undetermined_coefficients([0.0, 1.0, 0.0, 1.0], [0, 0, 1, 1], np.array([p0, p1, d0, d1]))
    np.testing.assert_allclose(conditions, HERMITE.results["power_coefficients"], atol=1e-13)
    np.testing.assert_allclose(polynomials.bernstein_to_power(HERMITE.results["bezier"]), conditions, atol=1e-13)


@pytest.mark.parametrize("seed", range(5))
def test_hermite_curve_against_scipy(seed):
    rng = np.random.default_rng(seed)
    d = 1 + seed % 3
    p0, p1, d0, d1 = rng.uniform(-4, 4, (4, d))
    t = np.linspace(0, 1, 23)
    krogh = KroghInterpolator([0.0, 0.0, 1.0, 1.0], [p0, d0, p1, d1])(t)  # repeated nodes carry derivatives
    spline = CubicHermiteSpline([0.0, 1.0], [p0, p1], [d0, d1])(t)
    np.testing.assert_allclose(ip.hermite_eval(p0, p1, d0, d1, t), krogh, atol=1e-12)
    np.testing.assert_allclose(ip.hermite_eval(p0, p1, d0, d1, t), spline, atol=1e-12)
    control = ip.hermite_to_bezier(p0, p1, d0, d1)
    np.testing.assert_allclose(bezier.de_casteljau(control, t), spline, atol=1e-12)
    tangents = bezier.hodograph(control)
    np.testing.assert_allclose(tangents[[0, -1]], [d0, d1], atol=1e-13)


def test_hermite_basis_values_and_slopes_at_the_ends():
    basis = ip.hermite_basis(np.array([0.0, 1.0]))
    np.testing.assert_array_equal(basis, [[1, 0, 0, 0], [0, 1, 0, 0]])
    h = 1e-6
    slopes = (ip.hermite_basis(np.array([h, 1.0])) - ip.hermite_basis(np.array([0.0, 1 - h]))) / h
    np.testing.assert_allclose(slopes, [[0, 0, 1, 0], [0, 0, 0, 1]], atol=1e-5)
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(ip.hermite_basis(t)[:, :2].sum(axis=1), 1.0)
    assert ip.hermite_basis(0.5).shape == (4,)


def test_conditions_on_points_and_slopes():
    ts, points = random_data(1, 5)
    np.testing.assert_allclose(ip.undetermined_coefficients(ts, [0] * 5, points), ip.power_interpolation(ts, points),
                               rtol=1e-9, atol=1e-9)
    # Three slopes and one point: P' is the quadratic through three slopes, so this always works.
    coeffs = ip.undetermined_coefficients([0.2, 0.0, 0.5, 1.0], [0, 1, 1, 1], [1.0, 2.0, -1.0, 0.5])
    derivative = npoly.polyder(coeffs)
    np.testing.assert_allclose(npoly.polyval([0.0, 0.5, 1.0], derivative), [2.0, -1.0, 0.5], atol=1e-12)
    assert npoly.polyval(0.2, coeffs) == pytest.approx(1.0)
    # Second derivatives work too.
    quadratic = ip.undetermined_coefficients([0.0, 0.0, 0.0], [0, 1, 2], [1.0, 2.0, 6.0])
    np.testing.assert_allclose(quadratic, [1.0, 2.0, 3.0])


def test_birkhoff_conditions_can_be_singular():
    example = notes_example("10.birkhoff")
    ts, orders = example.args("ts", "orders")
    null = example.results["null_cubic"]
    rows = [npoly.polyval(t, npoly.polyder(null, int(k))) for t, k in zip(ts, orders)]
    np.testing.assert_allclose(rows, 0.0, atol=1e-15)  # t²(t - 1) meets all four conditions with zero data
    with pytest.raises(ValueError, match="singular"):
        ip.undetermined_coefficients(ts, orders.astype(int), [1.0, 2.0, 0.0, 0.0])
    a, b, c, d, t = sp.symbols("a b c d t")
    monomials = [t**j for j in range(4)]
    matrix = sp.Matrix([[m.subs(t, a) for m in monomials], [m.subs(t, b) for m in monomials],
                        [sp.diff(m, t).subs(t, c) for m in monomials], [sp.diff(m, t).subs(t, d) for m in monomials]])
    expected = (a - b) * (c - d) * (2 * a**2 + 2 * a * b + 2 * b**2 - 3 * (a + b) * (c + d) + 6 * c * d)
    assert sp.expand(matrix.det() - expected) == 0 or sp.expand(matrix.det() + expected) == 0


# --- the plain forms the chapter shows, barycentric interpolation, Hermite data in Newton form, Lebesgue ----------


@pytest.mark.parametrize("seed", range(4))
def test_the_plain_forms_the_chapter_shows_agree_with_the_tuned_ones(seed):
    ts, points = random_data(seed, 2 + 3 * seed, dim=1 + seed % 3)
    t = np.concatenate([ts, np.linspace(ts.min() - 1, ts.max() + 1, 31)])
    scale = 1e-10 * (1 + np.abs(points).max())
    np.testing.assert_allclose(ip.neville_plain(ts, points, t), ip.neville(ts, points, t), atol=scale)
    coeffs = ip.divided_differences(ts, points)
    np.testing.assert_allclose(ip.newton_eval_plain(ts, coeffs, t), ip.newton_eval(ts, coeffs, t), atol=scale)
    np.testing.assert_allclose(ip.newton_eval_plain(ts[:-1], coeffs, t), ip.newton_eval(ts, coeffs, t), atol=scale)
    for f in (ip.neville_plain, ip.lagrange_eval_plain, ip.barycentric_eval):
        assert f(ts, points, 0.25).shape == (points.shape[1],)
        assert f(ts, points[:, 0], [0.25]).shape == (1,)


def test_barycentric_weights_are_the_inverse_node_products_up_to_one_factor():
    ts = np.array([0.0, 1.0, 3.0, 4.0])
    products = np.array([np.prod([ti - tj for tj in ts if tj != ti]) for ti in ts])
    weights = ip.barycentric_weights(ts)
    ratio = weights * products
    np.testing.assert_allclose(ratio, ratio[0], rtol=1e-14)
    assert np.abs(weights).max() == 1.0
    # Chebyshev nodes (zeros): weights proportional to (-1)^i sin((2i+1)π/(2n+2)) (Berrut–Trefethen 2004, (5.3)).
    n = 12
    nodes = ip.chebyshev_nodes(-1.0, 1.0, n + 1)[::-1]  # the formula's decreasing order
    i = np.arange(n + 1)
    expected = (-1.0) ** i * np.sin((2 * i + 1) * np.pi / (2 * n + 2))
    np.testing.assert_allclose(ip.barycentric_weights(nodes), expected / np.abs(expected).max(), atol=1e-13)


def test_barycentric_formula_gives_the_data_at_the_nodes_and_takes_any_weights_scale():
    ts, points = random_data(3, 7)
    np.testing.assert_array_equal(ip.barycentric_eval(ts, points, ts), points)
    t = np.linspace(ts.min(), ts.max(), 41)
    weights = ip.barycentric_weights(ts)
    np.testing.assert_allclose(ip.barycentric_eval(ts, points, t, weights=1e-30 * weights),
                               ip.barycentric_eval(ts, points, t), rtol=1e-12, atol=1e-12)
    with pytest.raises(ValueError, match="weights: expected 7 non-zero weights"):
        ip.barycentric_eval(ts, points, t, weights=np.zeros(7))


def test_newton_in_increasing_order_loses_its_accuracy_where_barycentric_keeps_it():
    # §10.5: cos 3t at 81 Chebyshev nodes of [0, 1]. Increasing order: the coefficients computed
    # from the crowded first nodes carry huge rounding errors; a scrambled order, Lagrange and the
    # barycentric formula stay at rounding level.
    x = ip.chebyshev_nodes(0.0, 1.0, 81)
    t = np.linspace(0, 1, 501)
    f = np.cos(3 * x)
    error = lambda values: np.abs(values - np.cos(3 * t)).max()  # noqa: E731
    assert error(ip.newton_eval(x, ip.divided_differences(x, f), t)) > 1e-3
    order = np.random.default_rng(2017).permutation(81)
    assert error(ip.newton_eval(x[order], ip.divided_differences(x[order], f[order]), t)) < 1e-12
    assert error(ip.barycentric_eval(x, f, t)) < 1e-13
    assert error(ip.lagrange_eval(x, f, t)) < 1e-13


@pytest.mark.parametrize("seed", range(4))
def test_confluent_divided_differences_give_the_hermite_interpolant_of_scipy_krogh(seed):
    rng = np.random.default_rng(seed)
    nodes = np.repeat(np.sort(rng.uniform(-2, 2, 3)) + np.arange(3), rng.integers(1, 4, 3))
    values = rng.uniform(-3, 3, (len(nodes), 2))
    coeffs = ip.confluent_divided_differences(nodes, values)
    t = np.linspace(-3, 5, 23)
    expected = KroghInterpolator(nodes, values)(t)
    np.testing.assert_allclose(ip.newton_eval(nodes, coeffs, t), expected, atol=1e-8 * (1 + np.abs(expected).max()))


def test_confluent_divided_differences_of_the_hermite_example_and_of_distinct_nodes():
    p0, p1, d0, d1 = HERMITE.args("p0", "p1", "d0", "d1")
    coeffs = ip.confluent_divided_differences([0.0, 0.0, 1.0, 1.0], [p0, d0, p1, d1])
    np.testing.assert_array_equal(coeffs, [[0, 0], [3, 9], [1, -9], [-2, 0]])  # the chapter's hand table
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(ip.newton_eval([0.0, 0.0, 1.0, 1.0], coeffs, t), ip.hermite_eval(p0, p1, d0, d1, t))
    ts, points = random_data(4, 6)
    np.testing.assert_allclose(ip.confluent_divided_differences(ts, points), ip.divided_differences(ts, points))
    # e^t at 0 three times: 1, 1, 1/2 (the Taylor coefficients)
    np.testing.assert_allclose(ip.confluent_divided_differences([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]), [1.0, 1.0, 0.5])
    with pytest.raises(ValueError, match="ts: equal nodes must stand next to each other"):
        ip.confluent_divided_differences([0.0, 1.0, 0.0], [1.0, 2.0, 3.0])


def test_lebesgue_function_is_one_at_the_nodes_and_bounds_the_effect_of_data_errors():
    ts = np.linspace(-1, 1, 9)
    np.testing.assert_allclose(ip.lebesgue_function(ts, ts), 1.0, atol=1e-13)
    x = np.linspace(-1, 1, 2001)
    lam = ip.lebesgue_function(ts, x)
    np.testing.assert_allclose(lam, np.abs(ip.lagrange_basis(ts, x)).sum(axis=1))
    signs = np.sign(ip.lagrange_basis(ts, x[np.argmax(lam)]))  # the worst data errors of size one
    assert np.isclose(ip.lagrange_eval(ts, signs, x[np.argmax(lam)]), lam.max())
    # Chebyshev nodes: below (2/π) log(n+1) + 1 (Rivlin); uniform ones: exponential growth.
    for count in (5, 11, 21, 31):
        chebyshev = ip.lebesgue_function(ip.chebyshev_nodes(-1.0, 1.0, count), x).max()
        assert chebyshev <= 2 / np.pi * np.log(count) + 1
    assert ip.lebesgue_function(np.linspace(-1, 1, 21), x).max() > 1e4


# --- bad input -------------------------------------------------------------------------------------------


@pytest.mark.parametrize("call, match", [
    (lambda: ip.lagrange_eval([0.0, 1.0, 1.0], [[0.0], [1.0], [2.0]], 0.5), "ts: the nodes must be distinct"),
    (lambda: ip.neville([0.0, 1.0, 0.0], [[0.0], [1.0], [2.0]], 0.5), "ts: the nodes must be distinct"),
    (lambda: ip.divided_differences([2.0, 2.0], [1.0, 3.0]), "ts: the nodes must be distinct"),
    (lambda: ip.power_interpolation([2.0, 2.0], [1.0, 3.0]), "ts: the nodes must be distinct"),
    (lambda: ip.lagrange_eval([0.0, 1.0], [[0.0], [1.0], [2.0]], 0.5), "points: expected one entry per node"),
    (lambda: ip.divided_differences([0.0, 1.0, 2.0], [1.0, 3.0]), "values: expected one entry per node"),
    (lambda: ip.lagrange_eval([[0.0, 1.0]], [[0.0], [1.0]], 0.5), "ts: expected a 1-D array"),
    (lambda: ip.lagrange_eval([], [], 0.5), "ts: expected a 1-D array"),
    (lambda: ip.neville([0.0, 1.0], [[0.0], [1.0]], [[0.5]]), "t: expected a number or a 1-D array"),
    (lambda: ip.newton_eval([0.0], [1.0, 2.0, 3.0], 0.5), "ts: 3 coefficients need 3 nodes"),
    (lambda: ip.chebyshev_nodes(0.0, 1.0, 0), "n: expected an integer >= 1"),
    (lambda: ip.chebyshev_nodes(1.0, 1.0, 3), "a, b: expected a < b"),
    (lambda: ip.bezier_segments_needed([[0.0, 0.0], [1.0, 1.0]], 0.0), "tol: expected a tolerance > 0"),
    (lambda: ip.linear_segments_needed(0.0, 1.0, -1.0, 0.1), "second_derivative_bound: expected a bound >= 0"),
    (lambda: ip.hermite_to_bezier([0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0], [1.0, 1.0]), "p0, p1, d0, d1: expected"),
    (lambda: ip.undetermined_coefficients([0.0, 1.0], [0, 0.5], [1.0, 2.0]), "orders: expected 2 non-negative"),
    (lambda: ip.undetermined_coefficients([0.0, 1.0], [0, -1], [1.0, 2.0]), "orders: expected 2 non-negative"),
    (lambda: ip.node_polynomial_max([0.0, 1.0], 1.0, 0.0), "a, b: expected a < b"),
    (lambda: ip.neville_plain([0.0, 1.0, 0.0], [[0.0], [1.0], [2.0]], 0.5), "ts: the nodes must be distinct"),
    (lambda: ip.barycentric_eval([0.0, 0.0], [1.0, 2.0], 0.5), "ts: the nodes must be distinct"),
    (lambda: ip.newton_eval_plain([0.0], [1.0, 2.0, 3.0], 0.5), "ts: 3 coefficients need 3 or 2 nodes"),
    (lambda: ip.confluent_divided_differences([0.0, 1.0], [1.0]), "values: expected one entry per node"),
    (lambda: ip.checked_data([0.0, 1.0], [1.0], "values"), "values: expected one entry per node"),
])
def test_bad_input_is_named(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_chebyshev_nodes_count_must_be_an_integer():
    with pytest.raises(TypeError, match="n: expected an integer"):
        ip.chebyshev_nodes(0.0, 1.0, 9.0)  # a whole float is no count either (exercise 10.5 says so)
    assert len(ip.chebyshev_nodes(0.0, 1.0, np.int64(9))) == 9

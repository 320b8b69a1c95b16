"""Unit tests of cagd_ref.forward_differencing: evaluation at equally spaced parameters (chapter 4 of the notes)."""

from __future__ import annotations

from math import comb, factorial

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import polynomial as npoly
from scipy.interpolate import BPoly

from cagd_course.examples import notes_example
from cagd_ref import forward_differencing as fd
from cagd_ref.bezier import de_casteljau
from cagd_ref.polynomials import bernstein_to_power

# The notes' worked example: a cubic with f(1..5) = 1, 2, 4, x, 15 and x = 8;
# the same cubic in power form, (t³ - 3t² + 8t) / 6 (ours); our cubic in pixel units for §4.1.
MISSING = notes_example("04.missing_value")
CUBIC = notes_example("04.cubic_power_form")
RASTER = notes_example("04.raster_cubic")
NOTES_VALUES = MISSING.results["values"].copy()
(NOTES_CUBIC,) = CUBIC.args("coeffs")
(PIXEL_CUBIC,) = RASTER.args("points")


def random_poly(seed: int, degree: int, dim: int | None = None) -> np.ndarray:
    """Ascending power coefficients in [-5, 5], shape (degree+1,) or (degree+1, dim)."""
    shape = (degree + 1,) if dim is None else (degree + 1, dim)
    return np.random.default_rng(seed).uniform(-5, 5, shape)


def polyval(coeffs, t) -> np.ndarray:
    """numpy's Horner evaluation, arranged like cagd_ref: (k,) or (k, d)."""
    return npoly.polyval(np.asarray(t, dtype=float), np.asarray(coeffs, dtype=float), tensor=True).T


def test_every_public_name_is_tested():
    tested = {
        "forward_difference_table", "initial_differences", "power_differences", "forward_difference_steps",
        "forward_difference_eval", "missing_value", "bezier_by_differences", "raster_delta", "pixels_along",
        "rasterize", "find_gaps", "double_step", "halve_step", "adaptive_march", "drift", "float32_drift",
    }
    assert set(fd.__all__) == tested


# --- the difference table ------------------------------------------------------------------


def test_notes_table_of_the_cubic_example():
    rows = fd.forward_difference_table(NOTES_VALUES)
    assert [row.tolist() for row in rows] == [row.tolist() for row in MISSING.results["table"]]
    assert all(isinstance(row, np.ndarray) for row in rows)


def test_table_rule_right_equals_self_plus_below():
    values = polyval(random_poly(1, 4), 0.3 + 0.2 * np.arange(9))
    rows = fd.forward_difference_table(values)
    assert len(rows) == 9
    for upper, lower in zip(rows, rows[1:]):
        np.testing.assert_allclose(upper[1:], upper[:-1] + lower, atol=1e-10)


@pytest.mark.parametrize("degree", range(0, 7))
def test_nth_difference_is_constant_and_the_next_vanishes(degree):
    a = random_poly(degree, degree)
    delta = 0.25
    values = polyval(a, -1.0 + delta * np.arange(degree + 3))
    rows = fd.forward_difference_table(values)
    np.testing.assert_allclose(rows[degree], factorial(degree) * a[-1] * delta**degree, rtol=1e-8)
    np.testing.assert_allclose(rows[degree + 1], 0.0, atol=1e-9)


def test_table_works_column_by_column():
    values = np.column_stack([NOTES_VALUES, np.arange(5.0) ** 2, np.ones(5)])
    rows = fd.forward_difference_table(values)
    assert [row.shape for row in rows] == [(5, 3), (4, 3), (3, 3), (2, 3), (1, 3)]
    for k in range(3):
        for row, single in zip(rows, fd.forward_difference_table(values[:, k])):
            np.testing.assert_array_equal(row[:, k], single)
    np.testing.assert_array_equal(rows[2][:, 1], [2.0, 2.0, 2.0])


def test_table_matches_numpy_diff_of_every_order():
    values = np.random.default_rng(5).uniform(-3, 3, 7)
    rows = fd.forward_difference_table(values)
    for j, row in enumerate(rows):
        np.testing.assert_allclose(row, np.diff(values, n=j), atol=1e-12)


def test_table_of_one_value_and_fresh_rows():
    assert [r.tolist() for r in fd.forward_difference_table([3.5])] == [[3.5]]
    values = np.array(NOTES_VALUES)
    rows = fd.forward_difference_table(values)
    rows[0][0] = 99.0  # the rows are fresh arrays, not views of the input
    assert values[0] == 1.0


@pytest.mark.parametrize("bad, error", [([], ValueError), (np.zeros((2, 2, 2)), ValueError), ("abc", TypeError)])
def test_table_rejects_bad_values(bad, error):
    with pytest.raises(error, match="^values"):
        fd.forward_difference_table(bad)
    with pytest.raises(error, match="^values"):
        fd.initial_differences(bad)


def test_initial_differences_are_the_left_column():
    assert fd.initial_differences(NOTES_VALUES).tolist() == [row[0] for row in MISSING.results["table"]]
    values = np.random.default_rng(2).uniform(size=(4, 2))
    column = fd.initial_differences(values)
    assert column.shape == (4, 2)
    np.testing.assert_array_equal(column, [row[0] for row in fd.forward_difference_table(values)])


# --- starting differences from the power form -----------------------------------------------


def test_power_differences_match_the_notes_formulas_for_degrees_1_to_3():
    a0, a1, a2, a3, d = 0.5, -2.0, 3.0, 1.5, 0.2
    np.testing.assert_allclose(fd.power_differences([a0, a1], 0, d), [a0, a1 * d])
    np.testing.assert_allclose(fd.power_differences([a0, a1, a2], 0, d), [a0, a1 * d + a2 * d**2, 2 * a2 * d**2])
    np.testing.assert_allclose(
        fd.power_differences([a0, a1, a2, a3], 0.0, d),
        [a0, a1 * d + a2 * d**2 + a3 * d**3, 2 * a2 * d**2 + 6 * a3 * d**3, 6 * a3 * d**3],
    )


def test_power_differences_agree_with_sympy_for_any_start():
    t0, delta, t = sp.Rational(3, 4), sp.Rational(-1, 3), sp.symbols("t")
    a = [sp.Rational(k * k - 3, k + 2) for k in range(6)]
    f = sum(c * t**k for k, c in enumerate(a))
    values = [f.subs(t, t0 + k * delta) for k in range(6)]
    column = []
    while values:
        column.append(values[0])
        values = [q - p for p, q in zip(values, values[1:])]
    result = fd.power_differences([float(c) for c in a], float(t0), float(delta))
    np.testing.assert_allclose(result, [float(c) for c in column], rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("degree", range(0, 8))
def test_power_differences_agree_with_differences_of_values(degree):
    a = random_poly(10 + degree, degree, dim=2)
    t0, delta = -0.7, 0.3
    values = polyval(a, t0 + delta * np.arange(degree + 1))
    np.testing.assert_allclose(fd.power_differences(a, t0, delta), fd.initial_differences(values), atol=1e-9)


def test_power_differences_keep_tiny_high_differences_exact():
    # From values of size 1 the third difference 6e-9 would lose half its digits; the formula does not.
    a = np.array([1.0, 1.0, 1.0, 1.0])
    column = fd.power_differences(a, 0.0, 1e-3)
    assert column[3] == pytest.approx(6e-9, rel=1e-15)
    from_values = fd.initial_differences(polyval(a, 1e-3 * np.arange(4)))
    assert abs(from_values[3] / 6e-9 - 1) > 1e-12


def test_power_differences_defaults_and_bad_input():
    a = np.array([1.0, 2.0, 3.0])
    np.testing.assert_allclose(fd.power_differences(a), [1.0, 5.0, 6.0])  # f(0), f(1)-f(0), 2 a2
    with pytest.raises(ValueError, match="^t0"):
        fd.power_differences(a, [0.0, 1.0])
    with pytest.raises(ValueError, match="^coeffs"):
        fd.power_differences(np.zeros((0,)))


# --- marching the differences ---------------------------------------------------------------


def test_steps_continue_the_notes_table():
    values = fd.forward_difference_steps(CUBIC.results["differences"], CUBIC.inputs["count"])
    assert values.tolist() == CUBIC.results["values"].tolist()
    assert values.dtype == np.float64


def test_steps_in_float32_and_column_by_column():
    column = np.array([[0.0, 1.0], [0.1, -1.0], [0.02, 0.5]])
    values = fd.forward_difference_steps(column, 5, dtype=np.float32)
    assert values.dtype == np.float32 and values.shape == (5, 2)
    expected = np.column_stack([fd.forward_difference_steps(column[:, k], 5) for k in range(2)])
    np.testing.assert_allclose(values, expected, rtol=1e-6)


def test_steps_edge_counts_and_bad_input():
    column = np.array([2.0, 3.0])
    assert fd.forward_difference_steps(column, 0).shape == (0,)
    assert fd.forward_difference_steps(column, 1).tolist() == [2.0]
    assert fd.forward_difference_steps([[1.0, 2.0]], 3).tolist() == [[1.0, 2.0]] * 3  # degree 0: constant
    with pytest.raises(ValueError, match="^count"):
        fd.forward_difference_steps(column, -1)
    with pytest.raises(TypeError, match="^count"):
        fd.forward_difference_steps(column, 2.5)
    with pytest.raises(TypeError, match="^dtype"):
        fd.forward_difference_steps(column, 3, dtype=np.int32)
    with pytest.raises(TypeError, match="^dtype"):
        fd.forward_difference_steps(column, 3, dtype="no such type")
    with pytest.raises(ValueError, match="^differences"):
        fd.forward_difference_steps(np.zeros((2, 2, 1)), 3)


# --- forward_difference_eval ------------------------------------------------------------------


def notes_quadratic_loop(a0, a1, a2, delta, k):
    """The notes' improved degree-2 loop, transcribed literally: f += Δ1; Δ1 += Δ2."""
    f, d1, d2 = a0, a1 * delta + a2 * delta**2, 2 * a2 * delta**2
    out = [f]
    for _ in range(k):
        f += d1
        d1 += d2
        out.append(f)
    return out


def notes_cubic_loop(a, delta, k):
    """The notes' degree-3 loop, transcribed literally."""
    a0, a1, a2, a3 = a
    f = a0
    d1 = a1 * delta + a2 * delta**2 + a3 * delta**3
    d2 = 2 * a2 * delta**2 + 6 * a3 * delta**3
    d3 = 6 * a3 * delta**3
    out = [f]
    for _ in range(k):
        f += d1
        d1 += d2
        d2 += d3
        out.append(f)
    return out


def test_eval_repeats_the_notes_loops_for_degrees_1_2_3():
    np.testing.assert_allclose(fd.forward_difference_eval([2.0, 3.0], 0, 0.25, 5), [2.0, 2.75, 3.5, 4.25, 5.0])
    np.testing.assert_allclose(fd.forward_difference_eval([1.0, -2.0, 0.5], 0, 0.1, 21),
                               notes_quadratic_loop(1.0, -2.0, 0.5, 0.1, 20), rtol=1e-13)
    a = [0.5, 1.0, -3.0, 2.0]
    np.testing.assert_allclose(fd.forward_difference_eval(a, 0, 1 / 16, 17), notes_cubic_loop(a, 1 / 16, 16),
                               rtol=1e-13)


def test_eval_of_the_notes_cubic_example():
    values = fd.forward_difference_eval(*CUBIC.args("coeffs", "t0", "delta", "count"))
    np.testing.assert_allclose(values, CUBIC.results["values"], atol=1e-12)
    # The first five are the notes' values, the gap x = 8 filled in.
    np.testing.assert_allclose(values[: len(NOTES_VALUES)], NOTES_VALUES, atol=1e-12)


@pytest.mark.parametrize("degree", range(0, 8))
@pytest.mark.parametrize("dim", [None, 1, 3])
def test_eval_matches_numpy_polyval(degree, dim):
    a = random_poly(100 * degree + (dim or 0), degree, dim)
    t0, delta, count = 0.4, -0.05, 40
    values = fd.forward_difference_eval(a, t0, delta, count)
    expected = polyval(a, t0 + delta * np.arange(count))
    assert values.shape == expected.shape == ((count,) if dim is None else (count, dim))
    np.testing.assert_allclose(values, expected, rtol=1e-10, atol=1e-10)


def test_eval_with_zero_step_and_small_counts():
    a = np.array([1.0, 2.0, 3.0])
    np.testing.assert_allclose(fd.forward_difference_eval(a, 2.0, 0.0, 4), [17.0] * 4)
    assert fd.forward_difference_eval(a, 2.0, 0.5, 0).shape == (0,)
    assert fd.forward_difference_eval(a[:, None], 2.0, 0.5, 0).shape == (0, 1)
    np.testing.assert_allclose(fd.forward_difference_eval(a, -1.0, 0.5, 1), [2.0])


@pytest.mark.parametrize("args, error, name", [
    (([1.0, 2.0], 0.0, 0.1, -1), ValueError, "count"),
    (([1.0, 2.0], 0.0, 0.1, 3.0), TypeError, "count"),
    (([1.0, 2.0], [0.0], 0.1, 3), ValueError, "t0"),
    ((np.zeros((2, 2, 2)), 0.0, 0.1, 3), ValueError, "coeffs"),
    (([], 0.0, 0.1, 3), ValueError, "coeffs"),
])
def test_eval_rejects_bad_input(args, error, name):
    with pytest.raises(error, match=f"^{name}"):
        fd.forward_difference_eval(*args)


# --- the notes' missing value ---------------------------------------------------------------------


def test_missing_value_of_the_notes_example_is_eight():
    values, index = MISSING.args("values", "index")
    assert fd.missing_value(values, index) == MISSING.results["x"]
    values[index] = -123.0  # the placeholder is ignored
    assert fd.missing_value(values, index) == MISSING.results["x"]


@pytest.mark.parametrize("index", range(6))
def test_missing_value_recovers_any_entry_of_a_polynomial(index):
    a = random_poly(index, 4, dim=2)
    values = polyval(a, 0.5 * np.arange(6))
    holed = values.copy()
    holed[index] = 0.0
    found = fd.missing_value(holed, index)
    assert found.shape == (2,)
    np.testing.assert_allclose(found, values[index], atol=1e-9)
    # the answer agrees with a fit through the other five points by numpy
    keep = np.arange(6) != index
    fit = npoly.polyfit(0.5 * np.arange(6)[keep], values[keep], 4)
    np.testing.assert_allclose(found, polyval(fit, 0.5 * index), atol=1e-7)


def test_missing_value_takes_nan_or_inf_as_the_placeholder_but_nowhere_else():
    assert fd.missing_value([1.0, 2.0, 4.0, np.nan, 15.0], 3) == 8.0
    assert fd.missing_value([np.inf, 2.0, 4.0, 8.0, 15.0], 0) == 1.0
    found = fd.missing_value([(1.0, 0.0), (2.0, 1.0), (np.nan, np.nan), (10.0, 9.0)], 2)
    np.testing.assert_allclose(found, [5.0, 4.0])  # two quadratics at t = 0..3: t² + 1 and t²
    with pytest.raises(ValueError, match="^values"):
        fd.missing_value([1.0, np.nan, 4.0, 0.0, 15.0], 3)


def test_missing_value_rejects_bad_input():
    with pytest.raises(ValueError, match="^values"):
        fd.missing_value([1.0], 0)
    with pytest.raises(ValueError, match="^values"):
        fd.missing_value(np.zeros((3, 2, 2)), 0)
    with pytest.raises(TypeError, match="^values"):
        fd.missing_value("1 2 4", 0)
    with pytest.raises(ValueError, match="^index"):
        fd.missing_value([1.0, 2.0, 3.0], 3)
    with pytest.raises(TypeError, match="^index"):
        fd.missing_value([1.0, 2.0, 3.0], 1.0)


# --- Bézier curves, rasterisation ----------------------------------------------------------------


@pytest.mark.parametrize("degree", range(0, 6))
def test_bezier_by_differences_matches_de_casteljau_and_scipy(degree):
    points = np.random.default_rng(degree).uniform(-10, 10, (degree + 1, 2))
    steps = 25
    t = np.linspace(0, 1, steps + 1)
    values = fd.bezier_by_differences(points, steps)
    np.testing.assert_allclose(values, de_casteljau(points, t), atol=1e-10)
    np.testing.assert_allclose(values, BPoly(points[:, None, :], [0, 1])(t), atol=1e-10)


def test_power_coefficients_of_a_bezier_curve_are_scaled_differences_of_its_control_points():
    # P(t) = ((1 - t) I + t E)ⁿ P_0 = (I + t Δ)ⁿ P_0, so a_k = C(n, k) Δᵏ P_0.
    rows = fd.forward_difference_table(PIXEL_CUBIC)
    a = np.array([comb(3, k) * rows[k][0] for k in range(4)])
    np.testing.assert_allclose(a, bernstein_to_power(PIXEL_CUBIC))
    np.testing.assert_allclose(fd.bezier_by_differences(PIXEL_CUBIC, 69), fd.forward_difference_eval(a, 0, 1 / 69, 70))


def test_bezier_by_differences_rejects_bad_input():
    with pytest.raises(ValueError, match="^steps"):
        fd.bezier_by_differences(PIXEL_CUBIC, 0)
    with pytest.raises(ValueError, match="^points"):
        fd.bezier_by_differences([1.0, 2.0], 4)


def test_raster_delta_follows_the_notes_formula():
    # Largest neighbour difference: 23 (in y, twice); n = 3, so n d = 69.
    assert np.abs(np.diff(PIXEL_CUBIC, axis=0)).max() == RASTER.results["largest_step"]
    assert fd.raster_delta(PIXEL_CUBIC) == pytest.approx(RASTER.results["delta"])
    assert 1 / fd.raster_delta(PIXEL_CUBIC) == pytest.approx(RASTER.results["steps"])
    assert fd.raster_delta([[0.0, 0.0], [3.0, -1.0]]) == pytest.approx(1 / 3)
    assert fd.raster_delta([[4.0, 4.0]]) == 1.0  # a single point needs one step
    assert fd.raster_delta([[4.0, 4.0], [4.0, 4.0], [4.2, 4.0]]) == 1.0  # capped at one step


@pytest.mark.parametrize("seed", range(6))
def test_the_raster_step_never_moves_a_coordinate_more_than_one_pixel(seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(0, 60, (int(rng.integers(2, 7)), 2))
    delta = fd.raster_delta(points)
    steps = int(np.ceil(1 / delta))
    curve = fd.bezier_by_differences(points, steps)
    assert np.abs(np.diff(curve, axis=0)).max() <= 1 + 1e-12
    # the hodograph bound is reached or beaten by the true largest speed
    dense = de_casteljau(points, np.linspace(0, 1, 4001))
    assert np.abs(np.diff(dense, axis=0)).max() * 4000 <= 1 / delta + 1e-6
    pixels = fd.rasterize(points)
    assert len(fd.find_gaps(pixels)) == 0
    np.testing.assert_array_equal(pixels[0], np.floor(points[0]))
    np.testing.assert_array_equal(pixels[-1], np.floor(points[-1]))
    assert np.all(np.any(pixels[1:] != pixels[:-1], axis=1))


def test_rasterize_a_line_and_a_too_large_step():
    line = np.array([[0.5, 0.5], [6.5, 0.5]])
    assert fd.rasterize(line).tolist() == [[k, 0] for k in range(7)]
    assert fd.rasterize(line, 0.5).tolist() == [[0, 0], [3, 0], [6, 0]]
    pixels = fd.rasterize(PIXEL_CUBIC, 4 * fd.raster_delta(PIXEL_CUBIC))
    assert len(fd.find_gaps(pixels)) > 0
    assert fd.rasterize(PIXEL_CUBIC).dtype.kind == "i"


def test_rasterize_rejects_bad_input():
    with pytest.raises(ValueError, match="^points"):
        fd.rasterize(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="^delta"):
        fd.rasterize(PIXEL_CUBIC, 0.0)
    with pytest.raises(ValueError, match="^delta"):
        fd.rasterize(PIXEL_CUBIC, 1.5)
    with pytest.raises(ValueError, match="^delta"):
        fd.rasterize(PIXEL_CUBIC, [0.1, 0.2])


def test_pixels_along_floors_and_drops_repeats():
    samples = np.array([[0.2, 0.9], [0.7, 0.95], [1.0, 1.0], [-0.5, 1.999], [-0.5, 2.0]])
    assert fd.pixels_along(samples).tolist() == [[0, 0], [1, 1], [-1, 1], [-1, 2]]
    assert fd.pixels_along([[3.5, 3.5, 3.5]]).tolist() == [[3, 3, 3]]
    with pytest.raises(ValueError, match="^samples"):
        fd.pixels_along([0.5, 1.5])


def test_find_gaps_counts_jumps_of_more_than_one_pixel():
    pixels = [[0, 0], [1, 1], [3, 1], [3, 2], [3, 4], [4, 5]]
    assert fd.find_gaps(pixels).tolist() == [1, 3]
    assert fd.find_gaps([[2, 2]]).tolist() == []
    assert fd.find_gaps([[0, 0], [1, 1], [2, 0]]).tolist() == []
    with pytest.raises(ValueError, match="^pixels"):
        fd.find_gaps([1, 2, 3])


# --- changing the step, adaptive marching ----------------------------------------------------------


@pytest.mark.parametrize("degree", range(0, 8))
@pytest.mark.parametrize("dim", [None, 2])
def test_doubling_and_halving_the_step_give_the_columns_of_the_new_step(degree, dim):
    a = random_poly(degree + 10, degree, dim)
    t0, delta = 0.3, 0.125
    column = fd.power_differences(a, t0, delta)
    np.testing.assert_allclose(fd.double_step(column), fd.power_differences(a, t0, 2 * delta), atol=1e-11)
    np.testing.assert_allclose(fd.halve_step(column), fd.power_differences(a, t0, delta / 2), atol=1e-11)
    np.testing.assert_allclose(fd.halve_step(fd.double_step(column)), column, atol=1e-11)
    assert fd.double_step(column).shape == column.shape


def test_the_cubic_step_maps_of_lien_shantz_and_pratt():
    f, d1, d2, d3 = 5.0, 1.0, 2.0, 3.0
    np.testing.assert_allclose(fd.double_step([f, d1, d2, d3]), [f, 2 * d1 + d2, 4 * d2 + 4 * d3, 8 * d3])
    np.testing.assert_allclose(
        fd.halve_step([f, d1, d2, d3]), [f, d1 / 2 - d2 / 8 + d3 / 16, d2 / 4 - d3 / 8, d3 / 8]
    )
    with pytest.raises(ValueError, match="^differences"):
        fd.halve_step([])


@pytest.mark.parametrize("points", [PIXEL_CUBIC, [[2.0, 2.0], [60.0, 4.0], [62.0, 6.0], [64.0, 40.0]]])
def test_adaptive_march_keeps_every_move_within_the_limit_and_ends_at_t_one(points):
    points = np.asarray(points, dtype=float)
    params, samples = fd.adaptive_march(points)
    assert params[0] == 0.0 and params[-1] == 1.0 and np.all(np.diff(params) > 0)
    assert np.all(np.log2(np.diff(params)) == np.round(np.log2(np.diff(params))))  # steps are powers of two
    np.testing.assert_allclose(samples, de_casteljau(points, params), atol=1e-9)
    assert np.abs(np.diff(samples, axis=0)).max() <= 1 + 1e-9
    assert len(fd.find_gaps(fd.pixels_along(samples))) == 0
    assert len(params) - 1 <= np.ceil(1 / fd.raster_delta(points))
    params, samples = fd.adaptive_march(points, limit=0.25)
    assert np.abs(np.diff(samples, axis=0)).max() <= 0.25 + 1e-9


def test_adaptive_march_saves_steps_where_the_speed_varies():
    uneven = np.array([[2.0, 2.0], [60.0, 4.0], [62.0, 6.0], [64.0, 40.0]])  # fast, slow, fast
    params, _ = fd.adaptive_march(uneven)
    assert len(params) - 1 < 0.8 * (1 / fd.raster_delta(uneven))


def test_adaptive_march_edge_cases_and_bad_input():
    params, samples = fd.adaptive_march([[1.0, 2.0]])
    assert params.tolist() == [0.0, 1.0] and samples.tolist() == [[1.0, 2.0], [1.0, 2.0]]
    params, samples = fd.adaptive_march([[0.0, 0.0], [0.3, 0.2]])
    assert params.tolist() == [0.0, 1.0]
    with pytest.raises(ValueError, match="^limit"):
        fd.adaptive_march(PIXEL_CUBIC, limit=0.0)
    with pytest.raises(ValueError, match="^points"):
        fd.adaptive_march([1.0, 2.0])


# --- drift ----------------------------------------------------------------------------------------


def test_float32_forward_differencing_drifts_while_horner_does_not():
    a = np.array([0.0, 1.0, 2.0, 3.0])
    forward, horner32 = fd.drift(a, 0.0, 1e-3, 5000)
    assert forward.shape == horner32.shape == (5000,)
    assert forward[0] == 0.0 or forward[0] < 1e-6
    assert forward[-1] > 100 * horner32[-1]
    assert forward[-1] > 100 * forward[100]
    # Horner's error stays at the size of the float32 rounding of the values
    values = npoly.polyval(1e-3 * np.arange(5000), a)
    assert np.all(horner32 <= 1e-6 * (1 + np.abs(values)))


def test_float64_drift_is_small_and_horner_is_the_yardstick():
    a = np.array([[0.0, 1.0], [1.0, 0.0], [2.0, -1.0], [3.0, 0.5]])
    forward, horner64 = fd.drift(a, 0.0, 1e-3, 2000, np.float64)
    assert np.all(horner64 == 0.0)
    assert 0 < forward[-1] < 1e-9
    empty = fd.drift(a, 0.0, 1e-3, 0)
    assert empty[0].shape == empty[1].shape == (0,)
    with pytest.raises(TypeError, match="^dtype"):
        fd.drift(a, 0.0, 1e-3, 10, dtype=int)


def test_float32_drift_is_the_float32_march_against_float64_horner():
    a = bernstein_to_power(25 * PIXEL_CUBIC)
    errors = fd.float32_drift(a, 1e-4, 10001)
    assert errors.shape == (10001, 2) and errors.dtype == np.float64
    march = fd.forward_difference_eval(a, 0.0, 1e-4, 10001, np.float32)
    np.testing.assert_array_equal(errors, np.abs(march.astype(float) - polyval(a, 1e-4 * np.arange(10001))))
    np.testing.assert_array_equal(errors.max(axis=1), fd.drift(a, 0.0, 1e-4, 10001, np.float32)[0])
    assert errors[-1].max() > 100 * errors[100].max()  # the drift grows with the number of steps
    assert fd.float32_drift([1.0, 2.0], 0.5, 0).shape == (0,)


def test_float32_drift_rejects_bad_input():
    with pytest.raises(TypeError, match="^count"):
        fd.float32_drift([1.0, 2.0], 0.1, 2.0)
    with pytest.raises(ValueError, match="^count"):
        fd.float32_drift([1.0, 2.0], 0.1, -1)
    with pytest.raises(ValueError, match="^coeffs"):
        fd.float32_drift(np.zeros((2, 2, 2)), 0.1, 3)
    with pytest.raises(ValueError, match="^delta"):
        fd.float32_drift([1.0, 2.0], np.nan, 3)

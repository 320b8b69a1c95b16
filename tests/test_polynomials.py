"""Unit tests of cagd_ref.polynomials: power and Bernstein bases (notes §2.16 and chapter 3)."""

from __future__ import annotations

import numpy as np
import numpy.polynomial.polynomial as npp
import pytest
import sympy as sp
from scipy.interpolate import BPoly

from cagd_ref import polynomials as p
from cagd_ref.bezier import bernstein_matrix, de_casteljau, elevate, evaluate, from_homogeneous, hodograph

# Chapter 3's rational curve: homogeneous (X, Y, W) power coefficients (left column of the
# difference table) and the Bernstein coefficients on its top row.
NOTES_POWER = np.array([[1, 2, 1], [24, 30, 6], [-39, -57, -12], [20, 27, 7]], dtype=float)
NOTES_BERNSTEIN = np.array([[1, 2, 1], [9, 12, 3], [4, 3, 1], [6, 2, 2]], dtype=float)

t_sym = sp.Symbol("t")


def test_every_public_name_is_tested():
    tested = {
        "horner", "bernstein_horner", "difference_table", "bernstein_to_power", "power_to_bernstein",
        "bernstein_multiply", "bernstein_integral", "bernstein_area",
    }
    assert set(p.__all__) == tested


# --- evaluation (Notes ch. 3) -----------------------------------------------------------------


@pytest.mark.parametrize("degree", [0, 1, 2, 5, 12])
def test_horner_against_numpy(degree):
    rng = np.random.default_rng(degree)
    a = rng.normal(size=degree + 1)
    t = rng.uniform(-2, 2, 15)
    np.testing.assert_allclose(p.horner(a, t), npp.polyval(t, a), rtol=1e-12, atol=1e-12)
    value = p.horner(a, 0.7)
    assert isinstance(value, float)
    assert value == pytest.approx(npp.polyval(0.7, a), rel=1e-12)
    assert p.horner(a, 0.0) == a[0]
    # Several polynomials at once, one per column.
    columns = rng.normal(size=(degree + 1, 3))
    values = p.horner(columns, t)
    assert values.shape == (15, 3)
    np.testing.assert_allclose(values, npp.polyval(t, columns).T, rtol=1e-12, atol=1e-12)
    assert p.horner(columns, 0.7).shape == (3,)


def test_horner_small_example():
    # 2 - 3t + t³ at t = 2 is 4; nested: ((1·2 + 0)·2 - 3)·2 + 2.
    assert p.horner([2, -3, 0, 1], 2) == 4.0


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 7, 15])
def test_bernstein_horner_against_de_casteljau_and_scipy(degree):
    rng = np.random.default_rng(100 + degree)
    coeffs = rng.normal(size=degree + 1)
    t = np.r_[0.0, rng.uniform(0, 1, 12), 1.0]
    values = p.bernstein_horner(coeffs, t)
    assert values.shape == (14,)
    np.testing.assert_allclose(values, de_casteljau(coeffs[:, None], t)[:, 0], rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(values, bernstein_matrix(degree, t) @ coeffs, rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(values, BPoly(coeffs[:, None], [0, 1])(t), rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(values[[0, -1]], coeffs[[0, -1]], rtol=1e-14)
    assert isinstance(p.bernstein_horner(coeffs, 0.3), float)
    # In the power basis the same polynomial evaluates identically.
    np.testing.assert_allclose(p.horner(p.bernstein_to_power(coeffs), t), values, rtol=1e-9, atol=1e-9)


def test_bernstein_horner_columns_evaluate_a_curve():
    points = np.random.default_rng(5).normal(size=(5, 3))
    t = np.linspace(-0.5, 1.5, 9)
    np.testing.assert_allclose(p.bernstein_horner(points, t), de_casteljau(points, t), atol=1e-12)
    np.testing.assert_allclose(p.bernstein_horner(points, 0.25), de_casteljau(points, 0.25), atol=1e-12)


# --- basis conversion (Notes (3.1) and the difference table) ------------------------------------


def test_difference_table_of_the_notes_example():
    table = p.difference_table(NOTES_BERNSTEIN)
    assert [row.shape for row in table] == [(4, 3), (3, 3), (2, 3), (1, 3)]
    np.testing.assert_array_equal(table[0], NOTES_BERNSTEIN)
    np.testing.assert_array_equal(table[1], [[8, 10, 2], [-5, -9, -2], [2, -1, 1]])
    np.testing.assert_array_equal(table[2], [[-13, -19, -4], [7, 8, 3]])
    np.testing.assert_array_equal(table[3], [[20, 27, 7]])
    # The left column is the power coefficients divided by C(3, i).
    np.testing.assert_array_equal([row[0] for row in table], NOTES_POWER / np.array([1, 3, 3, 1])[:, None])


def test_notes_rational_conversion_both_ways():
    np.testing.assert_allclose(p.power_to_bernstein(NOTES_POWER), NOTES_BERNSTEIN, atol=1e-12)
    np.testing.assert_array_equal(p.bernstein_to_power(NOTES_BERNSTEIN), NOTES_POWER)
    # As a rational curve: homogeneous rows w (x, y, 1) give points and weights.
    points, weights = from_homogeneous(NOTES_BERNSTEIN)
    np.testing.assert_allclose(points, [[1, 2], [3, 4], [4, 3], [3, 1]])
    np.testing.assert_allclose(weights, [1, 3, 1, 2])
    t = np.linspace(0, 1, 11)
    xyw = p.horner(NOTES_POWER, t)
    np.testing.assert_allclose(evaluate(points, t, weights), xyw[:, :2] / xyw[:, 2:], rtol=1e-12)


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 6])
def test_bernstein_to_power_is_exact_on_integers(degree):
    # SymPy expands Σ b_i C(n, i) (1-t)^(n-i) t^i in exact integer arithmetic.
    b = np.random.default_rng(degree).integers(-20, 21, size=degree + 1)
    expanded = sp.expand(sum(int(bi) * sp.binomial(degree, i) * (1 - t_sym) ** (degree - i) * t_sym**i
                             for i, bi in enumerate(b)))
    exact = [int(expanded.coeff(t_sym, k)) for k in range(degree + 1)]
    np.testing.assert_array_equal(p.bernstein_to_power(b), exact)


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 6])
def test_power_to_bernstein_against_sympy(degree):
    a = np.random.default_rng(10 + degree).integers(-20, 21, size=degree + 1)
    # b_j = Σ_{i<=j} C(j, i) / C(n, i) a_i in exact rationals; SymPy confirms it re-expands to a.
    exact = [sum(sp.Rational(sp.binomial(j, i), sp.binomial(degree, i)) * int(a[i]) for i in range(j + 1))
             for j in range(degree + 1)]
    bernstein_sum = sum(c * sp.binomial(degree, j) * (1 - t_sym) ** (degree - j) * t_sym**j for j, c in enumerate(exact))
    assert sp.expand(bernstein_sum - sum(int(ai) * t_sym**i for i, ai in enumerate(a))) == 0
    np.testing.assert_allclose(p.power_to_bernstein(a), [float(c) for c in exact], rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("degree", [0, 1, 4, 9])
def test_basis_conversion_round_trip(degree):
    rng = np.random.default_rng(degree)
    for coeffs in (rng.normal(size=degree + 1), rng.normal(size=(degree + 1, 3))):
        there = p.power_to_bernstein(coeffs)
        assert there.shape == coeffs.shape
        np.testing.assert_allclose(p.bernstein_to_power(there), coeffs, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(p.power_to_bernstein(p.bernstein_to_power(coeffs)), coeffs, rtol=1e-9, atol=1e-9)
        t = np.linspace(0, 1, 7)
        np.testing.assert_allclose(p.bernstein_horner(there, t), p.horner(coeffs, t), rtol=1e-9, atol=1e-9)


def test_power_basis_monomials():
    # t^k in degree n has Bernstein coefficients C(i, k) / C(n, k) (zero for i < k).
    n = 4
    for k in range(n + 1):
        monomial = np.eye(n + 1)[k]
        expected = [float(sp.binomial(i, k) / sp.binomial(n, k)) for i in range(n + 1)]
        np.testing.assert_allclose(p.power_to_bernstein(monomial), expected, atol=1e-15)


# --- products and integrals (Notes §2.16, ch. 9) --------------------------------------------------


@pytest.mark.parametrize("m, n", [(0, 0), (0, 3), (1, 1), (2, 3), (5, 4)])
def test_bernstein_multiply_agrees_with_the_power_form_product(m, n):
    rng = np.random.default_rng(10 * m + n)
    f, g = rng.normal(size=m + 1), rng.normal(size=n + 1)
    product = p.bernstein_multiply(f, g)
    assert product.shape == (m + n + 1,)
    expected = npp.polymul(p.bernstein_to_power(f), p.bernstein_to_power(g))
    np.testing.assert_allclose(p.bernstein_to_power(product), expected, rtol=1e-9, atol=1e-9)
    t = np.linspace(0, 1, 9)
    np.testing.assert_allclose(p.bernstein_horner(product, t),
                               p.bernstein_horner(f, t) * p.bernstein_horner(g, t), atol=1e-12)
    np.testing.assert_allclose(p.bernstein_multiply(g, f), product, atol=1e-14)
    # Columns multiply column by column.
    fc, gc = rng.normal(size=(m + 1, 2)), rng.normal(size=(n + 1, 2))
    columns = p.bernstein_multiply(fc, gc)
    for k in range(2):
        np.testing.assert_allclose(columns[:, k], p.bernstein_multiply(fc[:, k], gc[:, k]), atol=1e-14)


def test_multiplying_by_one_elevates_the_degree():
    f = np.random.default_rng(3).normal(size=(5, 2))
    np.testing.assert_allclose(p.bernstein_multiply(f, np.ones((2, 2))), elevate(f), atol=1e-14)
    np.testing.assert_allclose(p.bernstein_multiply(f, np.ones((4, 2))), elevate(f, 3), atol=1e-14)


@pytest.mark.parametrize("interval", [(0, 1), (0, 0.5), (-2, 3)])
@pytest.mark.parametrize("degree", [0, 1, 4])
def test_bernstein_integral(degree, interval):
    t0, t1 = interval
    coeffs = np.random.default_rng(degree).normal(size=degree + 1)
    q = p.bernstein_integral(coeffs, interval)
    assert q.shape == (degree + 2,)
    assert q[0] == 0.0  # q(t0) = 0
    # Differentiating back gives p (hodograph with the same interval scale).
    np.testing.assert_allclose(hodograph(q[:, None], interval)[:, 0], coeffs, rtol=1e-12, atol=1e-14)
    # numpy integrates the power form of p in the local variable s = (t - t0)/(t1 - t0).
    s = np.linspace(0, 1, 9)
    antiderivative = npp.polyint(p.bernstein_to_power(coeffs)) * (t1 - t0)
    np.testing.assert_allclose(p.bernstein_horner(q, s), npp.polyval(s, antiderivative), rtol=1e-10, atol=1e-12)
    # The area is the mean coefficient times the interval length.
    assert p.bernstein_area(coeffs, interval) == pytest.approx((t1 - t0) * coeffs.mean(), rel=1e-12)


def test_bernstein_integral_notes_formula_and_columns():
    # q_i = (p_0 + ... + p_{i-1}) / (n + 1) on [0, 1].
    np.testing.assert_allclose(p.bernstein_integral([3, 6, 9]), [0, 1, 3, 6])
    assert p.bernstein_area([3, 6, 9]) == 6.0
    columns = np.array([[1.0, 2.0], [3.0, 4.0]])
    q = p.bernstein_integral(columns, (0, 2))
    np.testing.assert_allclose(q, [[0, 0], [1, 2], [4, 6]])
    np.testing.assert_allclose(p.bernstein_area(columns, (0, 2)), [4, 6])


# --- bad input and no mutation ----------------------------------------------------------------------


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: p.horner([], 0.5), ValueError, "coeffs"),
        (lambda: p.horner(np.zeros((2, 2, 2)), 0.5), ValueError, "coeffs"),
        (lambda: p.horner([1, 2], [[0.5]]), ValueError, "t"),
        (lambda: p.horner([1, 2], np.inf), ValueError, "t"),
        (lambda: p.bernstein_horner([1, np.nan], 0.5), ValueError, "coeffs"),
        (lambda: p.bernstein_horner([1, 2], "x"), TypeError, "t"),
        (lambda: p.difference_table(None), TypeError, "coeffs"),
        (lambda: p.power_to_bernstein("abc"), TypeError, "coeffs"),
        (lambda: p.power_to_bernstein(7.0), ValueError, "coeffs"),
        (lambda: p.bernstein_to_power([]), ValueError, "coeffs"),
        (lambda: p.bernstein_multiply([1, 2], [[1, 2], [3, 4]]), ValueError, "f, g"),
        (lambda: p.bernstein_multiply(np.ones((2, 2)), np.ones((2, 3))), ValueError, "f, g"),
        (lambda: p.bernstein_multiply([], [1]), ValueError, "f"),
        (lambda: p.bernstein_multiply([1], [np.nan]), ValueError, "g"),
        (lambda: p.bernstein_integral([1, 2], (1, 1)), ValueError, "interval"),
        (lambda: p.bernstein_integral([1, 2], (0, np.inf)), ValueError, "interval"),
        (lambda: p.bernstein_area([1, 2], (2, 1)), ValueError, "interval"),
        (lambda: p.bernstein_area([], (0, 1)), ValueError, "coeffs"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


def test_inputs_are_not_modified(unchanged):
    rng = np.random.default_rng(9)
    a, c = rng.normal(size=5), rng.normal(size=(4, 2))
    t = np.linspace(0, 1, 5)
    for func, args in [
        (p.horner, (a, t)), (p.horner, (c, t)), (p.bernstein_horner, (a, t)), (p.bernstein_horner, (c, 0.5)),
        (p.difference_table, (c,)), (p.bernstein_to_power, (c,)), (p.power_to_bernstein, (c,)),
        (p.bernstein_multiply, (c, c)), (p.bernstein_integral, (a, np.array([0.0, 2.0]))), (p.bernstein_area, (c,)),
    ]:
        unchanged(func, *args)
    # The first row of the difference table is a copy, not the caller's array.
    table = p.difference_table(c)
    table[0][:] = 0
    assert np.all(c != 0)

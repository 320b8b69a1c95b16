"""Unit tests of cagd_ref.polynomials: power and Bernstein bases (notes §2.16 and chapter 3)."""

from __future__ import annotations

import warnings
from fractions import Fraction
from math import comb

import numpy as np
import numpy.polynomial.polynomial as npp
import pytest
import sympy as sp
from numpy.polynomial import Polynomial
from scipy.interpolate import BPoly, PPoly

from cagd_course.examples import notes_example
from cagd_ref import polynomials as p
from cagd_ref.bezier import bernstein_matrix, de_casteljau, elevate, evaluate, from_homogeneous, hodograph

# Chapter 3's rational curve: homogeneous (X, Y, W) power coefficients (a_j, whose quotients a_j / C(3, j)
# are the left column of the difference table) and the Bernstein coefficients on its top row.
RATIONAL_CUBIC = notes_example("03.rational_cubic")
NOTES_POWER, NOTES_BERNSTEIN = RATIONAL_CUBIC.inputs["power"], RATIONAL_CUBIC.results["bernstein"]

t_sym = sp.Symbol("t")


def test_every_public_name_is_tested():
    tested = {
        "horner", "horner_with_derivative", "bernstein_horner", "bernstein_horner_plain", "evaluation_cost",
        "difference_table", "substitute_affine", "bernstein_to_power", "power_to_bernstein",
        "power_to_bernstein_interval", "power_to_rational_bezier", "bernstein_multiply", "bernstein_integral",
        "bernstein_area",
    }
    assert set(p.__all__) == tested


# --- affine substitution ------------------------------------------------------------------------


@pytest.mark.parametrize("shift, scale", [(0.0, 1.0), (2.0, 0.5), (-1.5, 3.0)])
def test_substitute_affine_matches_numpy_composition(shift, scale):
    rng = np.random.default_rng(4)
    coeffs = rng.normal(size=(5, 2))
    got = p.substitute_affine(coeffs, shift, scale)
    for column in range(2):
        expected = Polynomial(coeffs[:, column])(Polynomial([shift, scale])).coef
        np.testing.assert_allclose(got[:, column], expected, atol=1e-12)


def test_substitute_affine_reparametrises_the_notes_example():
    example = notes_example("02.reparametrization")
    p_power, shift, scale = example.args("p_power", "shift", "scale")
    np.testing.assert_array_equal(p.substitute_affine(p_power, shift, scale), example.results["q_power"])


def test_substitute_affine_rejects_bad_input():
    with pytest.raises(ValueError, match="shift"):
        p.substitute_affine([1.0, 2.0], [1.0, 2.0], 1.0)


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
    example = notes_example("03.horner_steps")
    coeffs, t = example.args("coeffs", "t")
    assert p.horner(coeffs, t) == example.results["value"]
    assert _horner_by_hand(coeffs, t) == example.results["value"]
    # The h_i are the steps of the nested form, and h_3, h_2, h_1 the quotient of the division by (x - t).
    steps = [coeffs[-1]]
    for coefficient in coeffs[-2::-1]:
        steps.append(t * steps[-1] + coefficient)
    np.testing.assert_array_equal(steps, example.results["steps"])
    quotient, remainder = npp.polydiv(coeffs, [-t, 1.0])
    np.testing.assert_array_equal(quotient, example.results["quotient"])
    np.testing.assert_array_equal(remainder, [example.results["value"]])


@pytest.mark.parametrize("degree", [0, 1, 2, 5, 12])
def test_horner_with_derivative_against_numpy(degree):
    rng = np.random.default_rng(50 + degree)
    a = rng.normal(size=degree + 1)
    t = rng.uniform(-2, 2, 15)
    value, slope = p.horner_with_derivative(a, t)
    assert value.shape == slope.shape == (15,)
    np.testing.assert_allclose(value, npp.polyval(t, a), rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(slope, npp.polyval(t, npp.polyder(a)) if degree else 0 * t, rtol=1e-12, atol=1e-12)
    value, slope = p.horner_with_derivative(a, 0.7)
    assert isinstance(value, float) and isinstance(slope, float)
    assert value == p.horner(a, 0.7)  # the same h_i as Horner's rule alone
    assert p.horner_with_derivative(a, 0.0)[1] == (a[1] if degree else 0.0)  # p'(0) = a_1
    columns = rng.normal(size=(degree + 1, 3))
    value, slope = p.horner_with_derivative(columns, t)
    assert value.shape == slope.shape == (15, 3)
    np.testing.assert_allclose(value, p.horner(columns, t), rtol=1e-12, atol=1e-12)
    if degree:
        np.testing.assert_allclose(slope, npp.polyval(t, npp.polyder(columns)).T, rtol=1e-12, atol=1e-12)
    assert [x.shape for x in p.horner_with_derivative(columns, 0.7)] == [(3,), (3,)]


def test_horner_with_derivative_is_the_quotient_at_t():
    # p(x) = (x - t) q(x) + p(t) with q built from the h_i: p'(t) = q(t). The course example: q = x² + 2x + 1.
    example = notes_example("03.horner_steps")
    coeffs, t = example.args("coeffs", "t")
    value, slope = p.horner_with_derivative(coeffs, t)
    assert value == example.results["value"]
    assert slope == npp.polyval(t, example.results["quotient"]) == 9.0
    # SymPy differentiates the notes' rational cubic exactly, coordinate by coordinate.
    exact = [sp.Poly(list(reversed(column.tolist())), t_sym).diff(t_sym) for column in NOTES_POWER.T]
    for tau in (sp.Rational(-1, 2), sp.Rational(1, 3), sp.Integer(2)):
        _, slopes = p.horner_with_derivative(NOTES_POWER, float(tau))
        np.testing.assert_allclose(slopes, [float(d.eval(tau)) for d in exact], rtol=1e-14)


def test_horner_with_derivative_counts_two_horner_passes():
    counts = {"multiplies": 0, "adds": 0}
    coeffs = [2.0, -3.0, 0.0, 1.0, 0.5]
    h, d = coeffs[-1], 0.0
    tally = Tally(1.5, counts)
    for coefficient in coeffs[-2::-1]:
        d, h = tally * d + h, tally * h + coefficient
    assert (float(h), float(d)) == pytest.approx(p.horner_with_derivative(coeffs, 1.5))
    assert counts == {"multiplies": 2 * 4, "adds": 2 * 4}


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


def test_plain_nested_form_is_the_tuned_one():
    """The teaching form the chapter shows and the block-tuned `bernstein_horner` compute the same values."""
    x_column = NOTES_BERNSTEIN[:, 0]
    at_half = p.horner(NOTES_POWER[:, 0], 0.5)
    assert p.bernstein_horner_plain(x_column, 0.5) == p.bernstein_horner(x_column, 0.5) == at_half
    t = np.r_[0.0, 1.0, np.linspace(0.05, 0.95, 11), -0.75, 1.6]           # both ends, inside, and extrapolated
    np.testing.assert_allclose(p.bernstein_horner_plain(NOTES_BERNSTEIN, t), p.bernstein_horner(NOTES_BERNSTEIN, t),
                               rtol=1e-14, atol=1e-13)
    np.testing.assert_array_equal(p.bernstein_horner_plain(NOTES_BERNSTEIN, [0.0, 1.0]), NOTES_BERNSTEIN[[0, -1]])
    rng = np.random.default_rng(17)
    for degree in (0, 1, 2, 5, 12, 40):
        for coeffs in (rng.normal(size=degree + 1), rng.normal(size=(degree + 1, 3))):
            plain = p.bernstein_horner_plain(coeffs, t)
            assert plain.shape == (len(t),) + coeffs.shape[1:]
            np.testing.assert_allclose(plain, p.bernstein_horner(coeffs, t), rtol=1e-12, atol=1e-12)
            np.testing.assert_allclose(plain, de_casteljau(coeffs.reshape(degree + 1, -1), t).reshape(plain.shape),
                                       rtol=1e-9, atol=1e-9)
            for tau in (0.0, 1.0, 0.3, 2.0):
                np.testing.assert_allclose(p.bernstein_horner_plain(coeffs, tau), p.bernstein_horner(coeffs, tau),
                                           rtol=1e-12, atol=1e-12)
    # Beyond one block of parameters the tuned form works block by block; the values stay the plain ones.
    many = np.linspace(-0.25, 1.25, p.BLOCK + 5)
    np.testing.assert_allclose(p.bernstein_horner(NOTES_BERNSTEIN, many),
                               p.bernstein_horner_plain(NOTES_BERNSTEIN, many), rtol=1e-13, atol=1e-12)
    with pytest.raises(ValueError, match="^coeffs:"):
        p.bernstein_horner_plain(np.ones(p.MAX_BINOMIAL_DEGREE + 2), 0.5)


def test_bernstein_horner_columns_evaluate_a_curve():
    points = np.random.default_rng(5).normal(size=(5, 3))
    t = np.linspace(-0.5, 1.5, 9)
    np.testing.assert_allclose(p.bernstein_horner(points, t), de_casteljau(points, t), atol=1e-12)
    np.testing.assert_allclose(p.bernstein_horner(points, 0.25), de_casteljau(points, 0.25), atol=1e-12)


@pytest.mark.parametrize("interval", [(0, 1), (2, 5), (-1, -0.25)])
def test_bernstein_horner_on_an_interval(interval):
    t0, t1 = interval
    rng = np.random.default_rng(7)
    coeffs = rng.normal(size=(6, 2))
    t = np.linspace(t0 - 0.5, t1 + 0.5, 13)
    values = p.bernstein_horner(coeffs, t, interval)
    np.testing.assert_allclose(values, evaluate(coeffs, t, interval=interval), rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(values, BPoly(coeffs[:, None, :], [t0, t1], extrapolate=True)(t), atol=1e-11)
    np.testing.assert_allclose(p.bernstein_horner(coeffs, [t0, t1], interval), coeffs[[0, -1]], rtol=1e-14)


class Tally:
    """A number that counts the floating-point multiplies and adds done with it (a test-only peer)."""

    def __init__(self, value, counts):
        self.value, self.counts = float(value), counts

    def _counted(self, kind, result):
        self.counts[kind] += 1
        return Tally(result, self.counts)

    def __mul__(self, other):
        return self._counted("multiplies", self.value * float(other))

    __rmul__ = __mul__

    def __truediv__(self, other):
        return self._counted("multiplies", self.value / float(other))

    def __add__(self, other):
        return self._counted("adds", self.value + float(other))

    __radd__ = __add__

    def __sub__(self, other):
        return self._counted("adds", self.value - float(other))

    def __rsub__(self, other):
        return self._counted("adds", float(other) - self.value)

    def __float__(self):
        return self.value


def _horner_by_hand(a, t):
    h = a[-1]
    for coefficient in a[-2::-1]:
        h = t * h + coefficient
    return h


def _de_casteljau_by_hand(b, t):
    level = list(b)
    if len(level) > 1:
        s = 1 - t
        while len(level) > 1:
            level = [s * left + t * right for left, right in zip(level, level[1:])]
    return level[0]


def _bernstein_horner_by_hand(b, t):
    # The nested Bernstein form with c_i = C(n, i) b_i prepared once per polynomial.
    n = len(b) - 1
    c = [comb(n, i) * bi for i, bi in enumerate(b)]
    if n == 0:
        return c[0]
    s = 1 - t
    value, power = c[0] * s, 1
    for ci in c[1:-1]:
        power = power * t
        value = (value + power * ci) * s
    return value + power * t * c[-1]


@pytest.mark.parametrize("degree", [0, 1, 2, 3, 7, 12])
def test_evaluation_cost_counts_what_the_algorithms_do(degree):
    coeffs = list(np.random.default_rng(degree).normal(size=degree + 1))
    costs = p.evaluation_cost(degree)
    for method, by_hand, reference in [
        ("horner", _horner_by_hand, p.horner),
        ("de_casteljau", _de_casteljau_by_hand, p.bernstein_horner),
        ("bernstein_horner", _bernstein_horner_by_hand, p.bernstein_horner),
        ("bernstein_horner", _bernstein_horner_by_hand, p.bernstein_horner_plain),
    ]:
        counts = {"multiplies": 0, "adds": 0}
        value = by_hand(coeffs, Tally(0.3, counts))
        assert float(value) == pytest.approx(reference(coeffs, 0.3), rel=1e-12, abs=1e-12)
        assert costs[method] == (counts["multiplies"], counts["adds"]), method


def test_evaluation_cost_formulas():
    assert p.evaluation_cost(3) == {"horner": (3, 3), "bernstein_horner": (9, 4), "de_casteljau": (12, 7)}
    for n in (1, 5, 40):
        costs = p.evaluation_cost(n)
        assert costs["horner"] == (n, n)
        assert sum(costs["de_casteljau"]) == 3 * n * (n + 1) // 2 + 1           # O(n²)
        assert sum(costs["bernstein_horner"]) == 4 * n + 1                       # O(n)
    # Nested Bernstein evaluation beats de Casteljau from the quadratic on, and never beats Horner.
    for n in range(2, 30):
        costs = {k: sum(v) for k, v in p.evaluation_cost(n).items()}
        assert costs["horner"] < costs["bernstein_horner"] < costs["de_casteljau"]


def _exact_roots_polynomial(roots):
    """Exact power and Bernstein coefficients (Fractions) of the product of (t - r) over the roots."""
    power = [Fraction(1)]
    for r in roots:
        power = [Fraction(0)] + power
        for k in range(len(power) - 1):
            power[k] -= r * power[k + 1]
    n = len(power) - 1
    bernstein = [sum(Fraction(comb(j, i), comb(n, i)) * power[i] for i in range(j + 1)) for j in range(n + 1)]
    return power, bernstein


def test_bernstein_form_is_far_more_accurate_near_roots_in_the_interval():
    # Twelve roots evenly spread in [0, 1]: the power coefficients cancel wildly, the Bernstein ones do not.
    roots = [Fraction(k, 13) for k in range(1, 13)]
    power, bernstein = _exact_roots_polynomial(roots)
    ts = [Fraction(k, 97) for k in range(1, 97)]
    exact = np.array([float(np.prod([t - r for r in roots])) for t in ts])
    t = np.array([float(x) for x in ts])
    in_power = p.horner([float(a) for a in power], t)
    in_bernstein = p.bernstein_horner([float(b) for b in bernstein], t)
    by_triangle = de_casteljau(np.array([[float(b)] for b in bernstein]), t)[:, 0]
    scale = np.abs(exact).max()
    assert np.abs(in_bernstein - exact).max() < 1e-12 * scale
    assert np.abs(by_triangle - exact).max() < 1e-12 * scale
    assert np.abs(in_power - exact).max() > 100 * np.abs(in_bernstein - exact).max()
    # The exact conversion agrees with the floating-point difference table.
    np.testing.assert_allclose(p.power_to_bernstein([float(a) for a in power]), [float(b) for b in bernstein],
                               atol=1e-9 * scale)


def test_bernstein_horner_handles_the_highest_degree_with_finite_binomials():
    n = p.MAX_BINOMIAL_DEGREE
    t = np.array([0.0, 0.3, 0.5, 1.0])
    assert np.allclose(p.bernstein_horner(np.ones(n + 1), t), 1.0)          # partition of unity
    ramp = np.arange(n + 1) / n                                              # the coefficients of t itself
    np.testing.assert_allclose(p.bernstein_horner(ramp, t), t, atol=1e-12)


@pytest.mark.parametrize("evaluate", [p.bernstein_horner, p.bernstein_horner_plain])
def test_bernstein_horner_refuses_scaled_coefficients_that_overflow(evaluate):
    """Every β_i = C(n, i) b_i must fit in a float, not only the binomials: |b_i| C(n, i) < 1.8e308."""
    n = p.MAX_BINOMIAL_DEGREE                                                # C(1029, 514) ≈ 1.43e308
    with warnings.catch_warnings():
        warnings.simplefilter("error")                                       # and no overflow warning either
        for coeffs in (2.0 * np.ones(n + 1), [1.0, 1e308, 1.0], 1000.0 * np.ones(1021), -10.0 * np.ones(1028)):
            with pytest.raises(ValueError, match="^coeffs: C\\(n, i\\) b_i overflows"):
                evaluate(coeffs, 0.5)
        with pytest.raises(ValueError, match="^coeffs:"):
            evaluate(np.column_stack([np.ones(n + 1), 2.0 * np.ones(n + 1)]), [0.25, 0.5])  # one bad column
        assert np.isclose(evaluate(1.25 * np.ones(n + 1), 0.5), 1.25)    # 1.25 C(1029, 514) still fits
        assert np.isclose(evaluate(1000.0 * np.ones(1020), 0.5), 1000.0)  # degree 1019: fits
        assert np.isclose(evaluate(10.0 * np.ones(1027), 0.5), 10.0)      # degree 1026: fits
        assert np.isclose(evaluate([1.0, 8e307, 1.0], 0.5), 4e307)       # C(2, 1) · 8e307 < 1.8e308


# --- basis conversion (Notes (3.1) and the difference table) ------------------------------------


def test_difference_table_of_the_notes_example():
    results = RATIONAL_CUBIC.results
    table = p.difference_table(NOTES_BERNSTEIN)
    assert [row.shape for row in table] == [(4, 3), (3, 3), (2, 3), (1, 3)]
    np.testing.assert_array_equal(table[0], NOTES_BERNSTEIN)
    for j in (1, 2, 3):
        np.testing.assert_array_equal(table[j], results[f"delta{j}"])
    # The left column is the power coefficients divided by C(3, i).
    np.testing.assert_array_equal([row[0] for row in table], results["left_column"])
    np.testing.assert_array_equal(results["left_column"], NOTES_POWER / results["binomials"][:, None])


def test_notes_rational_conversion_both_ways():
    np.testing.assert_allclose(p.power_to_bernstein(NOTES_POWER), NOTES_BERNSTEIN, atol=1e-12)
    np.testing.assert_array_equal(p.bernstein_to_power(NOTES_BERNSTEIN), NOTES_POWER)
    # As a rational curve: homogeneous rows w (x, y, 1) give points and weights.
    points, weights = from_homogeneous(NOTES_BERNSTEIN)
    np.testing.assert_allclose(points, RATIONAL_CUBIC.results["points"])
    np.testing.assert_allclose(weights, RATIONAL_CUBIC.results["weights"])
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
    bernstein_sum = sum(c * sp.binomial(degree, j) * (1 - t_sym) ** (degree - j) * t_sym**j
                        for j, c in enumerate(exact))
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


@pytest.mark.parametrize("degree", [0, 1, 3, 6])
def test_conversions_against_scipy_piecewise_polynomials(degree):
    # SciPy stores power coefficients highest first; on the breakpoints [0, 1] its local variable is t.
    rng = np.random.default_rng(40 + degree)
    a = rng.normal(size=degree + 1)
    as_bernstein = BPoly.from_power_basis(PPoly(a[::-1, None], [0, 1]))
    np.testing.assert_allclose(p.power_to_bernstein(a), as_bernstein.c[:, 0], rtol=1e-12, atol=1e-13)
    b = rng.normal(size=degree + 1)
    as_power = PPoly.from_bernstein_basis(BPoly(b[:, None], [0, 1]))
    np.testing.assert_allclose(p.bernstein_to_power(b), as_power.c[::-1, 0], rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("interval", [(0, 1), (1, 3), (-2, -0.5), (0.25, 4)])
@pytest.mark.parametrize("degree", [0, 1, 4])
def test_conversions_on_an_interval_against_polynomial_composition(degree, interval):
    t0, t1 = interval
    rng = np.random.default_rng(degree)
    b = rng.normal(size=(degree + 1, 2))
    # numpy.polynomial builds Σ b_i C(n, i) (1-u)^(n-i) u^i with u = (t - t0)/(t1 - t0) as a polynomial in t.
    u = Polynomial([-t0 / (t1 - t0), 1 / (t1 - t0)])
    for k in range(2):
        expected = sum(b[i, k] * comb(degree, i) * (1 - u) ** (degree - i) * u**i for i in range(degree + 1))
        coef = np.pad(expected.coef, (0, degree + 1))[: degree + 1]
        np.testing.assert_allclose(p.bernstein_to_power(b, interval)[:, k], coef, rtol=1e-9, atol=1e-9)
    a = rng.normal(size=degree + 1)
    there = p.power_to_bernstein(a, interval)
    t = np.linspace(t0, t1, 9)
    np.testing.assert_allclose(p.bernstein_horner(there, t, interval), npp.polyval(t, a), rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(BPoly(there[:, None], [t0, t1])(t), npp.polyval(t, a), rtol=1e-9, atol=1e-9)
    np.testing.assert_allclose(p.bernstein_to_power(there, interval), a, rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("interval", [(0, 1), (1, 3), (-2, -0.5), (0.25, 4)])
@pytest.mark.parametrize("degree", [0, 1, 4, 7])
def test_power_to_bernstein_interval_is_the_conversion_on_the_interval(degree, interval):
    rng = np.random.default_rng(60 + degree)
    for a in (rng.normal(size=degree + 1), rng.normal(size=(degree + 1, 2))):
        got = p.power_to_bernstein_interval(a, interval)
        assert got.shape == a.shape
        np.testing.assert_allclose(got, p.power_to_bernstein(a, interval), rtol=1e-12, atol=1e-12)
        # SciPy's BPoly on the breakpoints [t0, t1] evaluates the same polynomial.
        t = np.linspace(*interval, 9)
        bpoly = BPoly(got.reshape(degree + 1, 1, -1), list(interval))
        np.testing.assert_allclose(bpoly(t).reshape((9,) + a.shape[1:]), p.horner(a, t), rtol=1e-9, atol=1e-9)


def test_power_to_bernstein_interval_by_blossoms():
    # The Bernstein coefficients over [r, s] of t² are its blossom r², r s, s²; of t³: r³, r²s, r s², s³.
    for r, s in [(1.0, 3.0), (-2.0, 0.5), (0.25, 0.75)]:
        np.testing.assert_allclose(p.power_to_bernstein_interval([0, 0, 1], (r, s)), [r * r, r * s, s * s], rtol=1e-13)
        np.testing.assert_allclose(p.power_to_bernstein_interval([0, 0, 0, 1], (r, s)),
                                   [r**3, r * r * s, r * s * s, s**3], rtol=1e-12, atol=1e-14)


def test_power_to_rational_bezier_reproduces_the_notes_example():
    points, weights = p.power_to_rational_bezier(NOTES_POWER)
    np.testing.assert_allclose(points, RATIONAL_CUBIC.results["points"], atol=1e-12)
    np.testing.assert_allclose(weights, RATIONAL_CUBIC.results["weights"], atol=1e-12)
    # The same curve both ways: the power form divided by W, and the rational Bézier form.
    t = np.linspace(0, 1, 21)
    xyw = p.horner(NOTES_POWER, t)
    np.testing.assert_allclose(evaluate(points, t, weights), xyw[:, :2] / xyw[:, 2:], rtol=1e-12)
    # Lists of tuples work, and a 3-D homogeneous curve (X, Y, Z, W) too.
    space = np.column_stack([NOTES_POWER[:, :2], NOTES_POWER[:, :1], NOTES_POWER[:, 2:]])
    points3, weights3 = p.power_to_rational_bezier(space.tolist())
    np.testing.assert_allclose(points3, np.column_stack([points, points[:, 0]]), atol=1e-12)
    np.testing.assert_allclose(weights3, weights, atol=1e-12)


def test_power_to_rational_bezier_of_random_curves_with_negative_weights():
    rng = np.random.default_rng(8)
    for degree in (1, 2, 5):
        points = rng.normal(size=(degree + 1, 2))
        weights = rng.uniform(0.5, 3, degree + 1) * rng.choice([-1.0, 1.0], degree + 1)
        homogeneous = np.column_stack([points * weights[:, None], weights])
        got_points, got_weights = p.power_to_rational_bezier(p.bernstein_to_power(homogeneous))
        np.testing.assert_allclose(got_points, points, rtol=1e-9, atol=1e-9)
        np.testing.assert_allclose(got_weights, weights, rtol=1e-9, atol=1e-9)


def test_power_to_rational_bezier_refuses_a_point_at_infinity():
    # W = (1 - t)²: Bernstein weights 1, 0, 0.
    with pytest.raises(ValueError, match="^coeffs: a zero weight"):
        p.power_to_rational_bezier([(0, 1), (1, -2), (0, 1)])
    # W = 1 - 3t + 3t² written with rounding: its middle weight is 1 - 3/2 = -1/2; no refusal.
    _, weights = p.power_to_rational_bezier([(0, 1), (1, -3), (0, 3)])
    np.testing.assert_allclose(weights, [1.0, -0.5, 1.0])


def test_interval_conversion_is_exact_on_integer_data():
    # Bernstein coefficients (2, -1, 3) on [1, 3]: SymPy expands with u = (t - 1)/2 in rationals.
    b = [2, -1, 3]
    u = (t_sym - 1) / 2
    expanded = sp.expand(sum(bi * sp.binomial(2, i) * (1 - u) ** (2 - i) * u**i for i, bi in enumerate(b)))
    exact = [expanded.coeff(t_sym, k) for k in range(3)]
    assert exact == [sp.Rational(27, 4), sp.Rational(-13, 2), sp.Rational(7, 4)]
    np.testing.assert_allclose(p.bernstein_to_power(b, (1, 3)), [float(c) for c in exact], rtol=1e-14)
    np.testing.assert_allclose(p.power_to_bernstein([float(c) for c in exact], (1, 3)), b, rtol=1e-13, atol=1e-13)


def test_notes_example_by_numpy_polynomial_composition():
    # Each homogeneous coordinate of the notes' curve, rebuilt from its Bernstein row by numpy.polynomial.
    t = Polynomial([0, 1])
    for k in range(3):
        curve = sum(NOTES_BERNSTEIN[i, k] * comb(3, i) * (1 - t) ** (3 - i) * t**i for i in range(4))
        np.testing.assert_allclose(curve.coef, NOTES_POWER[:, k], atol=1e-12)


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
    example = notes_example("02.integral")
    np.testing.assert_allclose(p.bernstein_integral(example.inputs["coeffs"]), example.results["antiderivative"])
    assert p.bernstein_area(example.inputs["coeffs"]) == example.results["area"]
    columns = np.array([[1.0, 2.0], [3.0, 4.0]])
    q = p.bernstein_integral(columns, (0, 2))
    np.testing.assert_allclose(q, [[0, 0], [1, 2], [4, 6]])
    np.testing.assert_allclose(p.bernstein_area(columns, (0, 2)), [4, 6])


# --- bad input (NaN, inf, scalar/array shapes and unmodified inputs are checked in test_contract.py) --------


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: p.horner([], 0.5), ValueError, "coeffs"),
        (lambda: p.horner(np.zeros((2, 2, 2)), 0.5), ValueError, "coeffs"),
        (lambda: p.horner([1, 2], [[0.5]]), ValueError, "t"),
        (lambda: p.bernstein_horner([1, 2], "x"), TypeError, "t"),
        (lambda: p.bernstein_horner_plain(np.zeros((2, 2, 2)), 0.5), ValueError, "coeffs"),
        (lambda: p.bernstein_horner_plain([1, 2], [[0.5]]), ValueError, "t"),
        (lambda: p.difference_table(None), TypeError, "coeffs"),
        (lambda: p.power_to_bernstein("abc"), TypeError, "coeffs"),
        (lambda: p.power_to_bernstein(7.0), ValueError, "coeffs"),
        (lambda: p.bernstein_to_power([]), ValueError, "coeffs"),
        (lambda: p.bernstein_multiply([1, 2], [[1, 2], [3, 4]]), ValueError, "f, g"),
        (lambda: p.bernstein_multiply(np.ones((2, 2)), np.ones((2, 3))), ValueError, "f, g"),
        (lambda: p.bernstein_multiply([], [1]), ValueError, "f"),
        (lambda: p.bernstein_integral([1, 2], (1, 1)), ValueError, "interval"),
        (lambda: p.bernstein_area([1, 2], (2, 1)), ValueError, "interval"),
        (lambda: p.bernstein_area([], (0, 1)), ValueError, "coeffs"),
        (lambda: p.bernstein_horner([1, 2], 0.5, (1, 0)), ValueError, "interval"),
        (lambda: p.bernstein_to_power([1, 2], (0, 0)), ValueError, "interval"),
        (lambda: p.power_to_bernstein([1, 2], (0, 1, 2)), ValueError, "interval"),
        (lambda: p.power_to_bernstein([1, 2], "ab"), TypeError, "interval"),
        (lambda: p.bernstein_horner(np.ones(1101), 0.5), ValueError, "coeffs"),
        (lambda: p.bernstein_to_power(np.ones(1031)), ValueError, "coeffs"),
        (lambda: p.bernstein_multiply(np.ones(600), np.ones(600)), ValueError, "f, g"),
        (lambda: p.evaluation_cost(-1), ValueError, "degree"),
        (lambda: p.horner_with_derivative([], 0.5), ValueError, "coeffs"),
        (lambda: p.horner_with_derivative([1, 2], [[0.5]]), ValueError, "t"),
        (lambda: p.power_to_bernstein_interval([1, 2], (1, 1)), ValueError, "interval"),
        (lambda: p.power_to_bernstein_interval([1, 2], (0, 1, 2)), ValueError, "interval"),
        (lambda: p.power_to_bernstein_interval(np.zeros((2, 2, 2)), (0, 1)), ValueError, "coeffs"),
        (lambda: p.power_to_rational_bezier([1.0, 2.0, 3.0]), ValueError, "coeffs"),
        (lambda: p.power_to_rational_bezier([[1.0], [2.0]]), ValueError, "coeffs"),
        (lambda: p.power_to_rational_bezier([(1.0, 0.0), (2.0, 0.0)]), ValueError, "coeffs"),
        (lambda: p.power_to_rational_bezier("abc"), TypeError, "coeffs"),
        (lambda: p.evaluation_cost(2.0), TypeError, "degree"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


def test_the_difference_table_copies_its_first_row():
    c = np.random.default_rng(9).normal(size=(4, 2))
    table = p.difference_table(c)
    table[0][:] = 0
    assert np.all(c != 0)

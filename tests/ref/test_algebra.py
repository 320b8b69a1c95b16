"""Unit tests of cagd_ref.algebra: resultants, GCDs, implicitization, inversion and intersection (chapter 17).

The notes' worked examples come from cagd_course/examples/ch17.toml. Every exact
claim is cross-checked with SymPy (`resultant`, `bezout(method='prs')`, `gcd`,
`groebner`, implicitization by elimination on integer data); the curve
functions are checked by properties on seeded random rational curves of degree
2-5 (the implicit equation vanishes on the curve and not off it, inversion
returns the parameter) and against chapter 7's independent algorithms (the
null-space implicitization, Bézier clipping).
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import polynomial as P
from sympy.polys.subresultants_qq_zz import bezout as sympy_bezout
from sympy.polys.subresultants_qq_zz import sylvester

from cagd_course.examples import notes_example
from cagd_ref import algebra as al
from cagd_ref import bezier, geometry, intersection
from cagd_ref.polynomials import bernstein_to_power

t, x, y, z = sp.symbols("t x y z")


def ex(name):
    return notes_example(f"17.{name}")


def sym(coeffs, var=t):
    """An ascending coefficient list as an exact SymPy polynomial."""
    return sum(sp.Rational(Fraction(float(c))) * var**k for k, c in enumerate(coeffs))


def bivariate(expr, degree):
    """A SymPy polynomial in x, y as the array c[i, j] of x^i y^j."""
    c = np.zeros((degree + 1, degree + 1))
    for (i, j), value in sp.Poly(sp.expand(expr), x, y).terms():
        c[i, j] = float(value)
    return c


def normalised(c):
    c = np.asarray(c, dtype=float)
    return c / c.flat[np.argmax(np.abs(c))]


def relative_values(f, pts):
    """|f(x, y)| against Σ |c_ij| max(1, |x|)^i max(1, |y|)^j."""
    big = np.maximum(np.abs(pts), 1.0)
    return np.abs(al.implicit_eval(f, pts)) / P.polyval2d(big[:, 0], big[:, 1], np.abs(f))


def random_curve(rng, n, rational=True):
    points = rng.uniform(-5, 5, (n + 1, 2))
    weights = rng.uniform(0.5, 2.0, n + 1) if rational else None
    return points, weights


def integer_curve(rng, n):
    return rng.integers(-6, 7, (n + 1, 2)).astype(float), rng.integers(1, 4, n + 1).astype(float)


# --- §17.3 resultants -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["root_product", "root_product_common", "linear_no_root", "linear_common",
                                  "cubic_no_root", "cubic_common"])
def test_the_notes_resultants(name):
    e = ex(name)
    assert al.resultant(*e.args("f", "g")) == pytest.approx(e.results["resultant"], abs=1e-9)
    if "f_roots" in e.inputs:
        assert al.root_product(*e.args("f_roots", "g_roots")) == pytest.approx(e.results["resultant"])


def test_the_notes_minus_1611_is_the_bezout_convention_of_the_resultant_1611():
    e = ex("cubic_no_root")
    bezout = al.bezout_matrix(*e.args("f", "g"))
    np.testing.assert_array_equal(bezout, e.results["bezout"])
    assert np.linalg.det(bezout) == pytest.approx(e.results["bezout_determinant"]) == -1611
    assert al.resultant(*e.args("f", "g")) == pytest.approx(e.results["resultant"]) == 1611
    assert not e.errata  # a convention, not an erratum
    assert np.linalg.det(al.bezout_matrix(*ex("root_product").args("f", "g"))) == pytest.approx(-12)


def test_bezout_and_sylvester_are_tied_by_sign_and_leading_coefficient():
    """det Bez(f, g) = (-1)^(n(n-1)/2) a_n^(n-m) Res(f, g) for deg f = n >= m = deg g, as chapter 19 uses it."""
    rng = np.random.default_rng(1719)
    for n in range(1, 7):
        for m in range(0, n + 1):
            f, g = rng.integers(-5, 6, n + 1).astype(float), rng.integers(-5, 6, m + 1).astype(float)
            f[-1], g[-1] = float(rng.choice([-3, -2, 2, 3])), float(rng.choice([-2, -1, 1, 2]))
            exact = sylvester(sym(f), sym(g), t, method=1).det() if m else sp.Integer(int(g[0])) ** n
            expected = (-1) ** (n * (n - 1) // 2) * int(f[-1]) ** (n - m) * exact
            assert np.linalg.det(al.bezout_matrix(f, g)) == pytest.approx(float(expected), rel=1e-9, abs=1e-6)
    # the notes' discriminant of chapter 19: 2t² + 3t - 5 against its derivative 4t + 3
    assert np.linalg.det(al.bezout_matrix([-5.0, 3.0, 2.0], [3.0, 4.0])) == pytest.approx(196)
    assert al.resultant([-5.0, 3.0, 2.0], [3.0, 4.0]) == pytest.approx(-98)


def test_the_proof_of_the_sign_the_row_combination_of_the_sylvester_matrix():
    """[-B1, A1] Syl = [0, J Bez] for equal degrees: the rows of Bez are combinations of the rows of Syl."""
    rng = np.random.default_rng(17)
    for n in range(1, 7):
        f, g = rng.integers(-5, 6, (2, n + 1)).astype(float)
        f[-1], g[-1] = 2.0, -3.0
        s = al.sylvester_matrix(f, g)
        a1, b1 = s[:n, :n], s[n:, :n]
        np.testing.assert_allclose(a1 @ b1, b1 @ a1)  # both upper triangular Toeplitz: they commute
        combined = np.hstack([-b1, a1]) @ s
        np.testing.assert_allclose(combined[:, :n], 0, atol=1e-12)
        np.testing.assert_allclose(combined[:, n:], al.bezout_matrix(f, g)[::-1], atol=1e-9)


def test_the_sylvester_matrix_is_the_map_u_f_plus_v_g():
    rng = np.random.default_rng(3)
    f, g = rng.integers(-5, 6, 4).astype(float), rng.integers(-5, 6, 3).astype(float)
    f[-1], g[-1] = 1.0, 2.0  # n = 3, m = 2
    u, v = rng.integers(-5, 6, 2).astype(float), rng.integers(-5, 6, 3).astype(float)  # deg u < m, deg v < n
    row = np.concatenate([u[::-1], v[::-1]])  # highest power first, as the rows
    combination = P.polyadd(P.polymul(u, f), P.polymul(v, g))
    np.testing.assert_allclose(row @ al.sylvester_matrix(f, g), np.pad(combination, (0, 5 - len(combination)))[::-1])
    # a common factor gives a null vector: u = g / h, v = -f / h
    h = np.array([-4.0, 1.0])
    f2, g2 = P.polymul(h, [1.0, 2.0, 1.0]), P.polymul(h, [3.0, 1.0])
    null = np.concatenate([[1.0, 3.0], [-1.0, -2.0, -1.0]])  # u = t + 3, v = -(t² + 2t + 1), highest first
    np.testing.assert_allclose(null @ al.sylvester_matrix(f2, g2), 0, atol=1e-12)


@pytest.mark.parametrize("name", ["root_product", "root_product_common", "cubic_no_root", "cubic_common",
                                  "gauss_two_roots"])
def test_the_notes_bezout_matrices_entry_for_entry(name):
    e = ex(name)
    np.testing.assert_array_equal(al.bezout_matrix(*e.args("f", "g")), e.results["bezout"])


def test_unequal_degrees_constants_and_trailing_zeros():
    assert al.resultant([-1.0, 0.0, 1.0], [4.0, 2.0]) == pytest.approx(12)
    assert al.resultant([-2.0, 0.0, 2.0], [4.0, 2.0]) == pytest.approx(24)
    assert al.resultant([-1.0, 0.0, 1.0], [-2.0, 2.0]) == pytest.approx(0, abs=1e-12)
    assert al.resultant([3.0], [1.0, 0.0, 1.0]) == 9.0
    assert al.resultant([3.0], [5.0]) == 1.0
    assert al.resultant([12.0, -7.0, 1.0, 0.0], [2.0, -3.0, 1.0]) == pytest.approx(12)
    assert al.sylvester_matrix([12.0, -7.0, 1.0, 0.0], [2.0, 1.0]).shape == (3, 3)
    # Padding the lower degree for Bézout brings in a_n^(n-m): det B = (-1)^(n(n-1)/2) a_n^(n-m) Res.
    assert np.linalg.det(al.bezout_matrix([-2.0, 0.0, 2.0], [4.0, 2.0])) == pytest.approx(-2 * 24)
    assert al.bezout_matrix([3.0], [5.0]).shape == (0, 0)
    with pytest.raises(ValueError, match="^f: the zero polynomial"):
        al.resultant([0.0, 0.0], [1.0, 1.0])
    with pytest.raises(ValueError, match="^g: expected ascending"):
        al.resultant([1.0, 1.0], [[1.0, 1.0]])


def test_the_swap_law_and_the_root_formula_with_leading_coefficients():
    rng = np.random.default_rng(7)
    for m, n in [(1, 2), (3, 3), (3, 4), (2, 5)]:
        fr, gr = rng.uniform(-2, 2, m), rng.uniform(-2, 2, n)
        a, b = rng.uniform(0.5, 3, 2)
        f, g = a * P.polyfromroots(fr), b * P.polyfromroots(gr)
        value = al.resultant(f, g)
        assert value == pytest.approx(al.root_product(fr, gr, a, b), rel=1e-9)
        assert al.resultant(g, f) == pytest.approx((-1) ** (m * n) * value, rel=1e-12)
    # Integer coefficients, complex roots, an integer resultant: t² + 1 and t² + 2t + 3.
    assert al.root_product([1j, -1j], [-1 + 1j * np.sqrt(2), -1 - 1j * np.sqrt(2)]) == pytest.approx(8)
    assert al.resultant([1.0, 0.0, 1.0], [3.0, 2.0, 1.0]) == pytest.approx(8)


def test_resultants_and_bezout_matrices_against_sympy():
    rng = np.random.default_rng(2017)
    for _ in range(40):
        m, n = rng.integers(1, 9, 2)
        f, g = rng.integers(-9, 10, m + 1).astype(float), rng.integers(-9, 10, n + 1).astype(float)
        f[-1], g[-1] = f[-1] or 1.0, g[-1] or 2.0
        exact = float(sp.resultant(sym(f), sym(g), t))
        if m < n and m * n % 2:
            exact = -exact  # SymPy 1.14 returns Res(g, f) here (sympy/sympy#10666); Sylvester's determinant agrees:
        assert exact == float(sylvester(sym(f), sym(g), t, method=1).det())
        assert al.resultant(f, g) == pytest.approx(exact, rel=1e-9, abs=1e-9)
        if m == n:
            theirs = np.array(sympy_bezout(sym(f), sym(g), t, method="prs"), dtype=float)
            ours = al.bezout_matrix(f, g)
            np.testing.assert_array_equal(ours, theirs)
            np.testing.assert_allclose(ours, ours.T)
            assert np.linalg.det(ours) == pytest.approx((-1) ** (n * (n - 1) // 2) * exact, rel=1e-9, abs=1e-6)


def test_the_bezout_rows_are_the_auxiliary_polynomials():
    f, g = ex("cubic_no_root").args("f", "g")
    ts = np.linspace(-2, 2, 9)
    rows = al.bezout_matrix(f, g) @ np.vstack([ts**2, ts, np.ones_like(ts)])
    # h_k = (a_n t^(k-1) + ... + a_(n-k+1)) g - (b_n t^(k-1) + ... + b_(n-k+1)) f.
    for k in range(1, 4):
        hk = P.polymul(f[3 - k + 1:], g) - P.polymul(g[3 - k + 1:], f)
        np.testing.assert_allclose(rows[k - 1], P.polyval(ts, hk), atol=1e-9)


# --- §17.4 the common root -----------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["gauss_no_root", "gauss_common"])
def test_fraction_free_elimination_of_the_notes_matrices(name):
    e = ex(name)
    triangular = al.fraction_free_eliminate(e.inputs["matrix"])
    np.testing.assert_array_equal(triangular, e.results["triangular"])
    assert np.count_nonzero(np.abs(triangular).sum(axis=1)) == e.results["rank"]


def test_the_gauss_erratum_and_the_rank_deficient_case():
    erratum = ex("gauss_no_root").errata["middle_row"]
    assert not np.array_equal(erratum.notes, erratum.correct)
    np.testing.assert_array_equal(al.fraction_free_eliminate(ex("gauss_no_root").inputs["matrix"])[1], erratum.correct)
    e = ex("gauss_two_roots")
    np.testing.assert_array_equal(al.fraction_free_eliminate(e.results["bezout"]), e.results["triangular"])
    assert al.common_root_count(*e.args("f", "g")) == 3 - e.results["rank"] == 2
    assert al.common_root_count(*ex("cubic_common").args("f", "g")) == 1
    assert al.common_root_count(*ex("cubic_no_root").args("f", "g")) == 0


def test_fraction_free_elimination_keeps_integers_and_the_determinant():
    rng = np.random.default_rng(3)
    for n in range(2, 7):
        m = rng.integers(-5, 6, (n, n)).astype(float)
        m[1] = m[0] * 2  # a zero pivot in the second column after one step
        m[[1, n - 1]] = m[[n - 1, 1]]
        reduced = al.fraction_free_eliminate(m)
        np.testing.assert_array_equal(reduced, np.round(reduced))
        assert np.count_nonzero(np.abs(reduced).sum(axis=1)) == sp.Matrix(m.astype(int)).rank()
        full = rng.integers(-5, 6, (n, n)).astype(float)
        assert al.fraction_free_eliminate(full)[-1, -1] == pytest.approx(float(sp.Matrix(full.astype(int)).det()))


def test_cramer_finds_the_common_root():
    e = ex("cramer")
    v = al.cramer_null_vector(e.inputs["rows"])
    np.testing.assert_allclose(v, e.results["null_vector"])
    assert v[0] / v[1] == pytest.approx(e.results["t"]) and v[1] / v[2] == pytest.approx(e.results["t"])
    np.testing.assert_allclose(al.bezout_matrix(*ex("cubic_common").args("f", "g")) @ v, 0, atol=1e-9)
    # Two common roots: the first two rows are dependent and Cramer's vector is zero.
    np.testing.assert_allclose(al.cramer_null_vector(ex("gauss_two_roots").results["bezout"][:2]), 0, atol=1e-12)


@pytest.mark.parametrize("name", ["euclid_no_root", "euclid_common", "euclid_two_roots"])
def test_euclid_steps_reproduce_the_notes_remainders(name):
    e = ex(name)
    steps = al.euclid_steps(*e.args("f", "g"))
    assert len(steps) == len(e.results["quotients"])
    for (_, _, q, r), q_want, r_want in zip(steps, e.results["quotients"], e.results["remainders"]):
        np.testing.assert_allclose(q, q_want, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(r, r_want, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(al.poly_gcd(*e.args("f", "g")), e.results["gcd"], atol=1e-12)


def test_euclid_on_integers():
    e = ex("euclid_integers")
    a, b = e.args("a", "b")
    quotients, remainders = [], []
    while b:
        q, r = divmod(a, b)
        quotients.append(q)
        remainders.append(r)
        a, b = b, r
    assert quotients == e.results["quotients"].tolist() and remainders == e.results["remainders"].tolist()
    assert a == e.results["gcd"]


def test_gcd_rules():
    f, g = ex("cubic_common").args("f", "g")
    np.testing.assert_allclose(al.poly_gcd(2 * f, 3 * g), [-4, 1], atol=1e-12)
    np.testing.assert_allclose(al.poly_gcd(f, [0.0]), f / f[-1])
    np.testing.assert_allclose(al.poly_gcd([-4.0, 1.0], f), [-4, 1], atol=1e-12)    # deg f < deg g
    np.testing.assert_allclose(al.common_roots(f, g), [4.0])
    assert al.common_roots(*ex("cubic_no_root").args("f", "g")).size == 0
    # An exact zero test would miss this GCD: the last remainder is rounding noise, not 0.
    last = al.euclid_steps(f, g)[-1]
    assert last[3].tolist() == [0.0]
    with pytest.raises(ValueError, match="^f, g: both"):
        al.poly_gcd([0.0], [0.0, 0.0])


def test_gcds_against_sympy_on_float_input():
    rng = np.random.default_rng(11)
    for _ in range(30):
        common = rng.integers(-8, 9, int(rng.integers(0, 3))) / 4.0
        f = P.polyfromroots(np.concatenate([common, rng.integers(-8, 9, int(rng.integers(1, 4))) / 4 + 1 / 8]))
        g = P.polyfromroots(np.concatenate([common, rng.integers(-8, 9, int(rng.integers(1, 4))) / 4 + 1 / 16]))
        f, g = f * rng.integers(1, 9) / 4, g * rng.integers(1, 9) / 8   # dyadic: exact in binary and in SymPy
        exact = sp.Poly(sp.gcd(sym(f), sym(g)), t).monic().all_coeffs()[::-1]
        np.testing.assert_allclose(al.poly_gcd(f, g), np.array(exact, dtype=float), atol=1e-8)


# --- §17.2, §17.5, §17.6 implicitization ----------------------------------------------------------------------------


def test_brute_force_examples_by_resultants():
    line, parabola = ex("line"), ex("parabola")
    np.testing.assert_array_equal(al.implicitize_power(*line.args("x", "y")), line.results["implicit"])
    np.testing.assert_array_equal(al.implicitize(line.inputs["points"]), line.results["implicit"])
    np.testing.assert_array_equal(al.implicitize_power(*parabola.args("x", "y")), -parabola.results["implicit"])
    np.testing.assert_array_equal(al.implicitize(parabola.inputs["points"]), -parabola.results["implicit"])
    inv = ex("parabola_inversion")
    for k, key in ((0, "t_from_x"), (1, "t_from_y")):
        coordinate = inv.inputs["xy"[k]]
        roots = P.polyroots(P.polysub(coordinate, [inv.inputs["point"][k]])).round(12)
        assert set(roots) == set(inv.results[key])
    assert al.invert(parabola.inputs["points"], inv.inputs["point"]) == pytest.approx(inv.results["t"])


def test_implicitization_example_1_matrix_and_inversion():
    e = ex("resultant_parabola")
    lines = al.power_bezout_lines(*e.args("x", "y"))
    np.testing.assert_array_equal(lines, e.results["bezout"])
    np.testing.assert_array_equal(al.implicitize_power(*e.args("x", "y")), e.results["implicit"])
    # Row 1: 2 t + (x - y - 3) = 0, so t = (y - x + 3) / 2: -2 at (5, -2).
    assert al.implicit_eval(e.results["inversion_row1"], [5.0, -2.0]) / 2 == e.results["t"]


def test_implicitization_example_2_the_recovered_cubic():
    e = ex("resultant_cubic")
    np.testing.assert_array_equal(al.power_bezout_lines(*e.args("x", "y", "w")), e.results["bezout"])
    f = al.implicitize_power(*e.args("x", "y", "w"))
    np.testing.assert_array_equal(f, e.results["implicit"])
    np.testing.assert_array_equal(al.implicitize(*e.args("points", "weights")), e.results["implicit"])
    # The Bézier form and the power form are one curve.
    h = bezier.to_homogeneous(*e.args("points", "weights"))
    np.testing.assert_allclose(bernstein_to_power(h)[:, 0], e.inputs["x"], atol=1e-12)
    np.testing.assert_allclose(bernstein_to_power(h)[:, 2], np.append(e.inputs["w"], 0), atol=1e-12)
    erratum = e.errata["bezout_23"]
    np.testing.assert_array_equal(e.results["bezout"][1, 2], erratum.correct)
    np.testing.assert_array_equal(e.results["bezout"][2, 1], erratum.correct)
    # The real node: f and its gradient vanish there, reached at two parameters.
    node = e.results["node"]
    assert relative_values(f, node[None, :])[0] < 1e-12
    for tk in e.results["node_parameters"]:
        np.testing.assert_allclose(bezier.evaluate(*e.args("points"), tk, e.inputs["weights"]), node, rtol=1e-9)


def test_implicitization_in_bezier_form_the_l_lines():
    e = ex("bezier_cubic")
    lines = al.l_lines(e.inputs["points"])
    for name in ("l32", "l31", "l30", "l21", "l20", "l10"):
        np.testing.assert_array_equal(lines[int(name[1]), int(name[2])], e.results[name])
    np.testing.assert_array_equal(lines, -lines.transpose(1, 0, 2))
    forms = al.bezout_lines(e.inputs["points"])
    np.testing.assert_array_equal(forms[1, 1], lines[3, 0] + lines[2, 1])
    np.testing.assert_array_equal(forms, forms.transpose(1, 0, 2))
    np.testing.assert_array_equal(al.implicitize(e.inputs["points"]), e.results["implicit"])


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_the_bezout_lines_annihilate_the_bernstein_vector_on_the_curve(n):
    rng = np.random.default_rng(n)
    points, weights = random_curve(rng, n)
    forms = al.bezout_lines(points, weights)
    for tk in (-0.4, 0.3, 1.7):
        p = bezier.evaluate(points, tk, weights)
        matrix = forms @ np.array([p[0], p[1], 1.0])
        vector = tk ** np.arange(n - 1, -1, -1) * (1 - tk) ** np.arange(n)
        np.testing.assert_allclose(matrix @ vector, 0, atol=1e-12 * np.abs(forms).sum() * max(1.0, np.abs(p).max()))


def test_simple_curves():
    circle = al.implicitize([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0])
    np.testing.assert_allclose(circle / circle[2, 0], [[-1, 0, 1], [0, 0, 0], [1, 0, 0]], atol=1e-14)
    f = al.implicitize([(0.0, 0.0), (1.0, 2.0), (3.0, -1.0)])
    assert f.shape == (3, 3) and f[1, 2] == f[2, 1] == f[2, 2] == 0
    assert geometry.conic_type(f[2, 0], f[1, 1], f[0, 2], f[1, 0], f[0, 1], f[0, 0]) == "parabola"
    for weights, kind in (([1.0, 0.5, 1.0], "ellipse"), ([1.0, 3.0, 1.0], "hyperbola")):
        f = al.implicitize([(0.0, 0.0), (1.0, 2.0), (3.0, -1.0)], weights)
        assert geometry.conic_type(f[2, 0], f[1, 1], f[0, 2], f[1, 0], f[0, 1], f[0, 0]) == kind
    # Collinear control points: the line to the n-th power (improper, not an error).
    cube = al.implicitize([(0.0, 0.0), (1.0, 1.0), (3.0, 3.0), (4.0, 4.0)])
    np.testing.assert_allclose(normalised(cube), normalised(bivariate((x - y) ** 3, 3)), atol=1e-12)


def test_a_degree_raised_curve_has_no_implicit_equation_of_that_degree():
    raised = bezier.elevate(np.array([(0.0, 0.0), (1.0, 2.0), (3.0, -1.0)]))
    with pytest.raises(ValueError, match="^points: the implicit equation vanishes"):
        al.implicitize(raised)
    with pytest.raises(ValueError, match="^points: expected planar"):
        al.implicitize([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)])
    with pytest.raises(ValueError, match="^weights: weights must be nonzero"):
        al.implicitize([(0.0, 0.0), (1.0, 1.0)], [1.0, 0.0])


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_the_implicit_equation_vanishes_on_random_rational_curves_and_not_off_them(n):
    rng = np.random.default_rng(100 + n)
    for _ in range(8):
        points, weights = random_curve(rng, n, rational=bool(rng.integers(2)))
        f = al.implicitize(points, weights)
        assert f.shape == (n + 1, n + 1)
        i, j = np.indices(f.shape)
        assert not f[i + j > n].any()
        ts = rng.uniform(-1, 2, 40)
        on = bezier.evaluate(points, ts, weights)
        assert relative_values(f, on).max() < 1e-9
        normal = bezier.derivative(points, ts, 1, weights)[:, ::-1] * [1, -1]
        off = on + 0.05 * normal / np.linalg.norm(normal, axis=1)[:, None]
        assert np.median(relative_values(f, off)) > 1e-6


@pytest.mark.parametrize("n", [2, 3, 4])
def test_implicitization_against_sympy_elimination_on_integer_data(n):
    rng = np.random.default_rng(40 + n)
    for _ in range(3):
        points, weights = integer_curve(rng, n)
        power = bernstein_to_power(bezier.to_homogeneous(points, weights))
        X, Y, W = (sym(np.round(power[:, k], 9)) for k in range(3))
        exact = bivariate(sp.resultant(x * W - X, y * W - Y, t), n)
        f = al.implicitize(points, weights)
        np.testing.assert_allclose(f, (-1) ** (n * (n - 1) // 2) * exact, rtol=1e-12, atol=1e-6)
        np.testing.assert_allclose(al.implicitize_power(*power.T), f, rtol=1e-9, atol=1e-6 * np.abs(f).max())
        np.testing.assert_allclose(normalised(intersection.implicit_by_nullspace(points, weights)), normalised(f),
                                   atol=1e-8)


def test_implicitization_by_groebner_elimination():
    e = ex("resultant_cubic")
    X, Y, W = (sym(c) for c in e.args("x", "y", "w"))
    basis = sp.groebner([x * W - X, y * W - Y, 1 - z * W], z, t, x, y, order="lex")
    eliminated = [g for g in basis.exprs if not g.has(z) and not g.has(t)]
    assert len(eliminated) == 1
    np.testing.assert_allclose(normalised(bivariate(eliminated[0], 3)), normalised(e.results["implicit"]), atol=1e-15)


# --- §17.6, §17.7 inversion ----------------------------------------------------------------------------------------


def test_the_notes_cubic_inversion_by_row_reduction():
    e = ex("bezier_cubic")
    la, lb, c1, c2 = al.cubic_inversion_lines(e.inputs["points"])
    np.testing.assert_allclose(la, e.results["la"], atol=1e-12)
    np.testing.assert_allclose(lb, e.results["lb"], atol=1e-12)
    assert (c1, c2) == pytest.approx((e.results["c1"], e.results["c2"]))
    lines = al.l_lines(e.inputs["points"])
    np.testing.assert_allclose(c1 * lines[3, 2] + c2 * lines[3, 1] + lines[3, 0], 0, atol=1e-12)
    num, den = al.inversion(e.inputs["points"])
    np.testing.assert_allclose(normalised(num), normalised(e.results["inversion_num"]), atol=1e-12)
    np.testing.assert_allclose(num / den[1, 0], np.asarray(e.results["inversion_num"]) / 1, atol=1e-12)
    np.testing.assert_allclose(den / den[1, 0], e.results["inversion_den"], atol=1e-12)


def test_the_rational_cubic_inversion_and_its_weights():
    e = ex("resultant_cubic")
    la, lb, c1, c2 = al.cubic_inversion_lines(*e.args("points", "weights"))
    assert (c1, c2) == pytest.approx((e.results["c1"], e.results["c2"]))
    num, den = al.inversion(*e.args("points", "weights"))
    scale = den[1, 0] / e.results["inversion_den"][1, 0]
    np.testing.assert_allclose(num / scale, e.results["inversion_num"], rtol=1e-10)
    np.testing.assert_allclose(den / scale, e.results["inversion_den"], rtol=1e-10)
    # The row operation's t = l_b / (l_b - l_a) is the same formula up to scale.
    top, bottom = al._as_poly2(lb), al._as_poly2(lb - la)
    np.testing.assert_allclose(normalised(bottom), normalised(den), atol=1e-12)
    np.testing.assert_allclose(top / bottom.flat[np.argmax(np.abs(bottom))],
                               num / den.flat[np.argmax(np.abs(bottom))], atol=1e-12)


def test_the_quadratic_inversion_formulas():
    e = ex("quadratic_inversion")
    forms = al.bezout_lines(e.inputs["points"])
    l21, l20, l10 = forms[0, 0], forms[0, 1], forms[1, 1]
    p = np.append(e.inputs["point"], 1.0)
    np.testing.assert_array_equal(al._as_poly2(l20), e.results["top_num"])
    np.testing.assert_array_equal(al._as_poly2(l20 - l21), e.results["top_den"])
    np.testing.assert_array_equal(al._as_poly2(l10), e.results["bottom_num"])
    np.testing.assert_array_equal(al._as_poly2(l10 - l20), e.results["bottom_den"])
    assert (l20 @ p) / ((l20 - l21) @ p) == e.results["t"] == (l10 @ p) / ((l10 - l20) @ p)
    # Each row fails at one end (0/0 at P2, or at P0); inversion() combines them so den is constant on the curve.
    ts = np.linspace(-1, 2, 13)
    pts = bezier.evaluate(e.inputs["points"], ts)
    num, den = al.inversion(e.inputs["points"])
    np.testing.assert_allclose(al.implicit_eval(den, pts), al.implicit_eval(den, pts[0]), rtol=1e-12)
    np.testing.assert_allclose(al.implicit_eval(num, pts) / al.implicit_eval(den, pts), ts, atol=1e-12)


def test_a_double_point_gives_zero_over_zero():
    e = ex("bezier_cubic")
    num, den = al.inversion(e.inputs["points"])
    point = e.results["double_point"]
    assert al.implicit_eval(num, point) == 0 and al.implicit_eval(den, point) == 0
    for tk in e.results["double_point_parameters"]:
        np.testing.assert_allclose(bezier.evaluate(e.inputs["points"], tk), point, atol=1e-12)
    with pytest.raises(ValueError, match="^xy: .* singular point"):
        al.invert(e.inputs["points"], point)
    with pytest.raises(ValueError, match="^xy: expected a point"):
        al.invert(e.inputs["points"], [1.0, 2.0, 3.0])


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_inversion_returns_the_parameter_on_random_rational_curves(n):
    rng = np.random.default_rng(200 + n)
    for _ in range(8):
        points, weights = random_curve(rng, n, rational=bool(rng.integers(2)))
        ts = np.sort(rng.uniform(-0.5, 1.5, 25))
        pts = bezier.evaluate(points, ts, weights)
        np.testing.assert_allclose(al.invert(points, pts, weights), ts, atol=1e-8)
        num, den = al.inversion(points, weights)
        k = 1 if n <= 3 else n - 2
        assert num.shape == den.shape == (k + 1, k + 1)
        inside = bezier.evaluate(points, np.linspace(0, 1, 11), weights)
        np.testing.assert_allclose(al.implicit_eval(num, inside) / al.implicit_eval(den, inside),
                                   np.linspace(0, 1, 11), atol=1e-7)
        assert al.invert(points, pts[3], weights) == pytest.approx(ts[3], abs=1e-8)


def test_inversion_refuses_a_collinear_quadratic():
    with pytest.raises(ValueError, match="^points: the control points are collinear"):
        al.inversion([(0.0, 0.0), (1.0, 1.0), (3.0, 3.0)])
    with pytest.raises(ValueError, match="^points: P1, P2, P3 are collinear"):
        al.cubic_inversion_lines([(0.0, 1.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)])


# --- §17.8 intersection ---------------------------------------------------------------------------------------------


def test_the_nine_intersections_of_the_notes_table():
    e = ex("intersection")
    p, q, pw, qw = e.args("p", "q", "p_weights", "q_weights")
    g = al.intersection_polynomial(p, q, pw, qw)
    np.testing.assert_allclose(g, e.results["bernstein"], rtol=1e-12)
    hits = al.intersect_implicit(p, q, pw, qw)
    assert hits.shape == (9, 2)
    np.testing.assert_allclose(hits[:, 0], e.results["t1_exact"], atol=1e-9)
    np.testing.assert_allclose(hits[:, 1], e.results["t2_exact"], atol=1e-9)
    np.testing.assert_allclose(hits[:, 0], e.results["t1"], atol=1e-4)
    np.testing.assert_allclose(hits[:, 1], e.results["t2"], atol=2e-4)
    np.testing.assert_allclose(bezier.evaluate(p, hits[:, 0], pw), e.results["points"], atol=1e-4)
    np.testing.assert_allclose(bezier.evaluate(q, hits[:, 1], qw), e.results["points"], atol=1e-4)
    for row, key in ((3, "t1_row4"), (5, "t1_row6")):
        erratum = e.errata[key]
        assert abs(hits[row, 0] - erratum.correct) < 1e-4 < abs(hits[row, 0] - erratum.notes)
    np.testing.assert_allclose(normalised(al.implicitize(q, qw)), normalised(e.results["q_implicit_over_832"]),
                               atol=1e-14)


def test_intersections_agree_with_bezier_clipping():
    rng = np.random.default_rng(5)
    for _ in range(12):
        p, _ = random_curve(rng, int(rng.integers(2, 4)), rational=False)
        q, _ = random_curve(rng, int(rng.integers(2, 4)), rational=False)
        ours = al.intersect_implicit(p, q)
        theirs = intersection.intersect_curves(p, q)
        assert ours.shape == theirs.shape
        np.testing.assert_allclose(ours, theirs, atol=1e-7)


def test_intersection_edge_cases():
    line = [(0.0, 0.0), (1.0, 0.0)]
    assert al.intersect_implicit(line, [(0.0, 1.0), (1.0, 2.0)]).shape == (0, 2)
    # A parabola touching the line y = 0 at u = 1/2: one row, not two.
    tangent = al.intersect_implicit(line, [(0.0, 1.0), (0.5, -1.0), (1.0, 1.0)])
    np.testing.assert_allclose(tangent, [[0.5, 0.5]], atol=1e-6)
    # Through the double point of the loop cubic (t = 0 and t = 2 there; only t = 0 is on the segment).
    cubic = ex("bezier_cubic").inputs["points"]
    hits = al.intersect_implicit(cubic, [(1.0, -1.0), (1.0, 1.0)])
    assert [0.0, 0.5] in np.round(hits, 9).tolist()
    with pytest.raises(ValueError, match="^p, q: the curves lie on one implicit curve"):
        al.intersect_implicit(line, [(0.25, 0.0), (0.75, 0.0)])


# --- §17.9-17.11 --------------------------------------------------------------------------------------------------


def test_surface_degrees_and_term_counts():
    e = ex("surface_degrees")
    assert al.surface_implicit_degree("tensor", (3, 3)) == e.results["bicubic_degree"]
    assert al.term_count(e.results["bicubic_degree"]) == e.results["bicubic_terms"]
    assert e.results["bicubic_degree"] ** 2 == e.results["bicubic_intersection_degree"]
    assert al.surface_implicit_degree("tensor", (1, 1)) == e.results["bilinear_degree"]
    assert al.surface_implicit_degree("triangular", 2) == e.results["triangular_quadratic_degree"]
    assert al.surface_implicit_degree("tensor", (2, 2)) == e.results["biquadratic_degree"]
    with pytest.raises(ValueError, match="^kind"):
        al.surface_implicit_degree("ruled", 2)


def test_the_degree_counts_by_resultants_of_plane_sections():
    rng = np.random.default_rng(9)
    s = sp.Symbol("s")

    def section(degrees):
        return sum(int(rng.integers(-3, 4)) * s**i * t**j for i in range(degrees[0] + 1) for j in range(degrees[1] + 1)
                   if degrees != "tri")

    for m, n in [(1, 1), (2, 2), (1, 2)]:
        first, second = section((m, n)), section((m, n))
        assert sp.degree(sp.resultant(first, second, t), s) == al.surface_implicit_degree("tensor", (m, n))


def test_term_orders_of_the_notes_example():
    e = ex("term_orders")
    pairs = zip(e.inputs["exponents"], e.inputs["coefficients"])
    coefficient = {tuple(int(v) for v in exp): int(c) for exp, c in pairs}
    terms = list(coefficient)
    assert [coefficient[term] for term in al.sort_terms(terms, "lex")] == e.results["lex_xyz"].tolist()
    assert [coefficient[term] for term in al.sort_terms(terms, "grlex")] == e.results["deglex_xyz"].tolist()
    for order, key in (((2, 0, 1), "lex_zxy"), ((1, 2, 0), "lex_yzx")):
        permuted = {tuple(term[k] for k in order): c for term, c in coefficient.items()}
        assert [permuted[term] for term in al.sort_terms(list(permuted), "lex")] == e.results[key].tolist()
    poly = sp.Poly(sum(c * x**a * y**b * z**d for (a, b, d), c in coefficient.items()), x, y, z)
    for order in ("lex", "grlex", "grevlex"):
        assert al.sort_terms(terms, order) == [m for m, _ in poly.terms(order=order)]
    # grevlex differs from grlex on x²z² against xy²z... of equal degree 4.
    assert al.sort_terms([(2, 0, 2), (1, 2, 1)], "grlex") == [(2, 0, 2), (1, 2, 1)]
    assert al.sort_terms([(2, 0, 2), (1, 2, 1)], "grevlex") == [(1, 2, 1), (2, 0, 2)]


@pytest.mark.parametrize("name", ["groebner_linear", "groebner_univariate", "groebner_two_variables"])
def test_the_groebner_examples(name):
    e = ex(name)
    gens = sp.symbols(e.inputs["variables"])
    basis = sp.groebner([sp.sympify(g) for g in e.inputs["generators"]], *gens, order="lex")
    assert [sp.expand(b) for b in basis.exprs] == [sp.expand(sp.sympify(b)) for b in e.results["basis"]]


# --- the plain forms the chapter shows agree with the tuned ones ------------------------------------------------


def test_the_plain_resultant_and_bezout_matrix_agree_with_the_tuned_ones():
    rng = np.random.default_rng(1700)
    for _ in range(40):
        n, m = rng.integers(0, 8, 2)
        f, g = rng.integers(-9, 10, n + 1).astype(float), rng.integers(-9, 10, m + 1).astype(float)
        f[-1], g[-1] = f[-1] or 1.0, g[-1] or 2.0
        assert al.resultant_plain(f, g) == pytest.approx(al.resultant(f, g), rel=1e-9, abs=1e-6)
        np.testing.assert_array_equal(al.bezout_matrix_plain(f, g), al.bezout_matrix(f, g))
    assert al.resultant_plain([3.0], [5.0]) == 1.0
    assert al.bezout_matrix_plain([3.0], [5.0]).shape == (0, 0)
    for name in ("cubic_no_root", "cubic_common", "gauss_two_roots", "root_product"):
        e = ex(name)
        np.testing.assert_array_equal(al.bezout_matrix_plain(*e.args("f", "g")), e.results["bezout"])
    with pytest.raises(ValueError, match="^f: the zero polynomial"):
        al.resultant_plain([0.0], [1.0, 1.0])


def test_the_plain_gcd_agrees_with_poly_gcd():
    rng = np.random.default_rng(1704)
    for name in ("euclid_no_root", "euclid_common", "euclid_two_roots"):
        e = ex(name)
        np.testing.assert_allclose(al.poly_gcd_plain(*e.args("f", "g")), e.results["gcd"])
    for _ in range(30):
        shared = rng.integers(-8, 9, int(rng.integers(0, 3))) / 4
        f = P.polyfromroots(np.concatenate([shared, rng.integers(-8, 9, int(rng.integers(1, 4))) / 8]))
        g = P.polyfromroots(np.concatenate([shared, rng.integers(-8, 9, int(rng.integers(1, 4))) / 8 + 0.0625]))
        f, g = f * rng.uniform(0.5, 3), g * rng.uniform(0.5, 3)
        np.testing.assert_allclose(al.poly_gcd_plain(f, g), al.poly_gcd(f, g), atol=1e-8)
    np.testing.assert_allclose(al.poly_gcd_plain([2.0, 4.0], [0.0]), [0.5, 1.0])
    noisy_f, noisy_g = P.polyfromroots([0.1, 0.3, 2]), P.polyfromroots([0.1, 0.3, -3])
    np.testing.assert_allclose(al.poly_gcd_plain(noisy_f, noisy_g), [0.03, -0.4, 1.0])
    with pytest.raises(ValueError, match="both are the zero polynomial"):
        al.poly_gcd_plain([0.0], [0.0, 0.0])


def test_fraction_free_elimination_leaves_its_input_alone_and_checks_it():
    m = np.array([[7.0, -7.0, 2.0], [-7.0, -5.0, -11.0], [2.0, -11.0, 13.0]])
    copy = m.copy()
    al.fraction_free_eliminate(m)
    np.testing.assert_array_equal(m, copy)
    with pytest.raises(ValueError, match="^matrix: expected a 2-D array"):
        al.fraction_free_eliminate([1.0, 2.0])
    with pytest.raises(ValueError, match="^tol"):
        al.fraction_free_eliminate(m, tol=2.0)


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_the_plain_implicitization_agrees_with_implicitize(n):
    rng = np.random.default_rng(1706 + n)
    for _ in range(4):
        points, weights = random_curve(rng, n, rational=bool(rng.integers(2)))
        ours, tuned = al.implicitize_plain(points, weights), al.implicitize(points, weights)
        np.testing.assert_allclose(ours, tuned, rtol=1e-9, atol=1e-9 * np.abs(tuned).max())
    e = ex("resultant_cubic")
    np.testing.assert_array_equal(al.implicitize_plain(*e.args("points", "weights")), e.results["implicit"])
    np.testing.assert_array_equal(al.implicitize_plain(ex("bezier_cubic").inputs["points"]),
                                  ex("bezier_cubic").results["implicit"])


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_the_plain_inversion_returns_the_parameter(n):
    rng = np.random.default_rng(1707 + n)
    for _ in range(6):
        points, weights = random_curve(rng, n, rational=bool(rng.integers(2)))
        num, den = al.inversion_plain(points, weights)
        k = max(1, n - 2)
        assert num.shape == den.shape == (k + 1, k + 1)
        ts = np.linspace(-0.5, 1.5, 21)
        pts = bezier.evaluate(points, ts, weights)
        bottom = al.implicit_eval(den, pts)
        good = np.abs(bottom) > 1e-3 * np.abs(bottom).max()  # one member of a family may vanish somewhere (n >= 4)
        np.testing.assert_allclose(al.implicit_eval(num, pts[good]) / bottom[good], ts[good], atol=1e-7)
        # invert_plain uses every member of a basis at every point (the power basis costs digits at n = 5)
        np.testing.assert_allclose(al.invert_plain(points, pts, weights), al.invert(points, pts, weights),
                                   atol=1e-8 if n <= 4 else 1e-6)
        nums, dens = al.inversion_plain(points, weights, basis=True)
        assert nums.shape == dens.shape == ({2: 2, 3: 1}.get(n, n - 2), k + 1, k + 1)
        np.testing.assert_allclose(nums[-1], num)
        np.testing.assert_allclose(dens[-1], den)
    if n == 3:  # a cubic's formula is unique up to scale: the notes' (17.20) for Example 2
        e = ex("resultant_cubic")
        num, den = al.inversion_plain(*e.args("points", "weights"))
        np.testing.assert_allclose(num / den[1, 0] * 156, e.results["inversion_num"], atol=1e-8)


def test_the_plain_inversion_refuses_lines_and_double_points():
    with pytest.raises(ValueError, match="^points: a line"):
        al.inversion_plain([(0.0, 0.0), (1.0, 1.0)])
    e = ex("bezier_cubic")
    with pytest.raises(ValueError, match="^xy: every inversion formula has den = 0"):
        al.invert_plain(e.inputs["points"], [e.results["double_point"]])


def test_one_member_of_a_quartic_family_is_zero_over_zero_at_an_ordinary_point():
    """From n = 4 on each single formula also gives 0/0 at n - 3 ordinary points; the whole basis never does."""
    quartic = np.array([(0.0, 0.0), (1.0, 2.0), (3.0, -1.0), (4.0, 2.0), (5.0, 0.0)])
    nums, dens = al.inversion_plain(quartic, basis=True)
    assert nums.shape == (2, 3, 3)
    t0 = 0.6
    point = bezier.evaluate(quartic, t0)
    a, b = (al.implicit_eval(d, point) for d in dens)
    num, den = b * nums[0] - a * nums[1], b * dens[0] - a * dens[1]  # the member whose den vanishes at P(t0)
    scale = np.abs(num).sum() + np.abs(den).sum()
    assert abs(al.implicit_eval(num, point)) < 1e-12 * scale and abs(al.implicit_eval(den, point)) < 1e-12 * scale
    others = bezier.evaluate(quartic, [0.1, 0.3, 0.9, 1.7])  # elsewhere it is a good formula
    np.testing.assert_allclose(al.implicit_eval(num, others) / al.implicit_eval(den, others), [0.1, 0.3, 0.9, 1.7],
                               atol=1e-9)
    assert al.invert_plain(quartic, point) == pytest.approx(t0, abs=1e-10)
    assert al.invert(quartic, point) == pytest.approx(t0, abs=1e-10)


def test_the_plain_intersection_agrees_with_intersect_implicit():
    e = ex("intersection")
    p, q, pw, qw = e.args("p", "q", "p_weights", "q_weights")
    np.testing.assert_allclose(al.intersect_implicit_plain(p, q, pw, qw), al.intersect_implicit(p, q, pw, qw),
                               atol=1e-9)
    rng = np.random.default_rng(1708)
    for _ in range(10):
        p, pw = random_curve(rng, int(rng.integers(1, 4)), rational=bool(rng.integers(2)))
        q, qw = random_curve(rng, int(rng.integers(1, 4)), rational=bool(rng.integers(2)))
        ours, tuned = al.intersect_implicit_plain(p, q, pw, qw), al.intersect_implicit(p, q, pw, qw)
        assert ours.shape == tuned.shape
        np.testing.assert_allclose(ours, tuned, atol=1e-8)
    assert al.intersect_implicit_plain([(0.0, 0.0), (1.0, 0.0)], [(0.0, 1.0), (1.0, 2.0)]).shape == (0, 2)

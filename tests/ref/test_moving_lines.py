"""Unit tests of cagd_ref.moving_lines: pencils, conics, the Bézout matrix of moving lines, double points (chapter 18).

The notes' worked examples (the cubic of Figure 18.11, the quartics of Figures
18.12 and 18.13, the implicit equation (18.87)) and the course's own come from
cagd_course/examples/ch18.toml. Exact claims are checked with SymPy (resultants
and singular points on integer data); the rest by properties on seeded random
rational curves of degree 2-5: moving lines follow the curve, the n×n Bézout
determinant and the resultant of two moving lines agree up to scale, and the
implicit equation vanishes on the curve and not off it.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import moving_lines as ml
from cagd_ref.geometry import conic_type

CUBIC = notes_example("18.cubic")
QUARTIC = notes_example("18.quartic")
TRIPLE = notes_example("18.triple_point")
QUARTIC_IMPLICIT = notes_example("18.quartic_implicit")
TANGENT = notes_example("18.tangent")
TS = np.linspace(-1.5, 2.5, 41)
X, Y, T = sp.symbols("x y t")


def same_up_to_scale(a, b, tol=1e-9):
    """a = s b for one nonzero (complex) number s, to within tol relative to the largest entry."""
    a, b = (np.asarray(v, dtype=complex).ravel() for v in (a, b))
    a, b = a / np.abs(a).max(), b / np.abs(b).max()
    scale = np.vdot(b, a) / np.vdot(b, b)
    return abs(scale) > 0.5 / a.size and np.abs(a - scale * b).max() <= tol


def random_curve(seed: int, degree: int, rational: bool = True):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-3, 3, (degree + 1, 2))
    weights = rng.uniform(0.4, 2.5, degree + 1) if rational else None
    return points, weights


def implicit_values(c, xy):
    """f(x, y) and the sum of the magnitudes of its terms, at points (k, 2)."""
    i, j = np.indices(c.shape)
    x, y = xy[:, 0, None, None], xy[:, 1, None, None]
    return (c * x**i * y**j).sum(axis=(1, 2)), (np.abs(c) * np.abs(x) ** i * np.abs(y) ** j).sum(axis=(1, 2))


def determinant_implicit(points, weights=None):
    """The n×n determinant of the Bézout matrix of moving lines at (x, y, 1): the conventional form (18.78)."""
    rows = ml.bezout_moving_lines(points, weights)
    n = len(rows)
    return ml._determinant([[ml._line_poly(rows[i, j], n + 1) for j in range(n)] for i in range(n)])


def exact_implicit(points):
    """Res_t(x - x(t), y - y(t)) by SymPy, on exact integer data, as an array c[i, j] of x^i y^j."""
    n = len(points) - 1
    basis = [sp.binomial(n, i) * (1 - T) ** (n - i) * T**i for i in range(n + 1)]
    x_t = sp.expand(sum(b * sp.Rational(p[0]) for b, p in zip(basis, points)))
    y_t = sp.expand(sum(b * sp.Rational(p[1]) for b, p in zip(basis, points)))
    poly = sp.Poly(sp.resultant(X - x_t, Y - y_t, T), X, Y)
    c = np.zeros((n + 1, n + 1))
    for (i, j), value in poly.terms():
        c[i, j] = float(value)
    return c


# --- the notes' worked examples ------------------------------------------------------------------------------


@pytest.mark.parametrize("example", [CUBIC, QUARTIC, TRIPLE], ids=["cubic", "quartic", "triple point"])
def test_the_bezout_matrices_of_the_notes(example):
    rows = ml.bezout_moving_lines(*example.args("points"))
    np.testing.assert_array_equal(rows, example.results["bezout"])
    np.testing.assert_array_equal(rows, rows.transpose(1, 0, 2))


def test_the_corrected_entries_of_18_68():
    rows = ml.bezout_moving_lines(*QUARTIC.args("points"))
    for k, name in enumerate(["row0_last", "row1_last"]):
        erratum = QUARTIC.errata[name]
        np.testing.assert_array_equal(rows[k, 3], erratum.correct)
        assert not np.array_equal(rows[k, 3], erratum.notes)


def test_the_cubic_elimination_pencil_and_double_point():
    points = CUBIC.inputs["points"]
    rows = ml.bezout_moving_lines(points)
    np.testing.assert_array_equal(rows[2] + 2 * rows[0] - rows[1], CUBIC.results["eliminated"])  # (18.63)
    assert same_up_to_scale(ml.cubic_pencil(points), CUBIC.results["pencil"])
    pivots, reduced = ml.eliminate_leading(rows)
    assert pivots.shape == (2, 3, 3) and same_up_to_scale(reduced[0], CUBIC.results["pencil"])
    assert same_up_to_scale(ml.cubic_double_point(points), CUBIC.results["double_point"])
    for t in CUBIC.results["double_point_parameters"]:
        np.testing.assert_allclose(bezier.evaluate(points, t), CUBIC.results["double_point"][:2], atol=1e-12)
    # The pencil inverts the curve: t = ℓ0 / (ℓ0 - ℓ1), for the notes' cubic t = y / (3 - x).
    ts = np.array([-2.0, -0.5, 0.0, 0.3, 0.5, 2.0])  # not ±1, where both parameters give the double point
    xy = bezier.evaluate(points, ts)
    np.testing.assert_allclose(xy[:, 1] / (3 - xy[:, 0]), ts)


def test_every_row_of_the_bezout_matrix_follows_the_curve():
    for example in (CUBIC, QUARTIC, TRIPLE):
        points = example.inputs["points"]
        for row in ml.bezout_moving_lines(points):
            np.testing.assert_allclose(ml.incidence(ml.unscaled_to_bernstein(row), points), 0, atol=1e-12)


def test_the_quartic_moving_lines_and_double_points():
    points = QUARTIC.inputs["points"]
    rows = ml.bezout_moving_lines(points)
    eliminated = np.array([rows[2] + 4 * rows[0] - 2 * rows[1], 3 * rows[3] + 3 * rows[0] - rows[1]])
    np.testing.assert_array_equal(eliminated, QUARTIC.results["eliminated"])  # (18.68), rows 2 and 3
    la, lb = QUARTIC.results["la"], QUARTIC.results["lb"]
    np.testing.assert_array_equal(eliminated[:, 1:], [la, lb])
    for line in (la, lb):
        np.testing.assert_allclose(ml.incidence(ml.unscaled_to_bernstein(line), points), 0, atol=1e-12)
    np.testing.assert_allclose(ml._axial_cubic(np.array(la), np.array(lb)), QUARTIC.results["axial_cubic"], atol=1e-9)
    erratum = QUARTIC.errata["axial_cubic"]
    np.testing.assert_allclose(np.array(erratum.correct) / 16, erratum.notes)
    taus, axes = ml.axial_combinations(la, lb)
    np.testing.assert_allclose(taus, QUARTIC.results["taus"], atol=1e-12)
    for axis, expected in zip(axes, QUARTIC.results["double_points"]):
        assert same_up_to_scale(axis, expected)
    found = ml.quartic_double_points(points)
    found = sorted((found / found[:, 2:]).real.round(9).tolist())
    np.testing.assert_allclose(found, sorted(QUARTIC.results["double_points"].tolist()), atol=1e-9)
    # Each double point is reached twice: t² = (3 ∓ √5)/4 for (1, ±√2), t = ±1 for (2, 0).
    for t in (np.sqrt((3 - np.sqrt(5)) / 4), np.sqrt((3 + np.sqrt(5)) / 4), 1.0):
        np.testing.assert_allclose(bezier.evaluate(points, t)[0], bezier.evaluate(points, -t)[0], atol=1e-12)


def test_the_triple_point_quartic():
    points = TRIPLE.inputs["points"]
    rows = ml.bezout_moving_lines(points)
    la, lb = np.array(TRIPLE.results["la"]), np.array(TRIPLE.results["lb"])
    np.testing.assert_array_equal((rows[2] + 4 * rows[0] - 2 * rows[1])[1:], la)  # (18.75)
    np.testing.assert_array_equal((2 * rows[3] + 4 * rows[0] - rows[1])[1:], lb)
    # The two quadratics are multiples of one pencil: their meet vanishes identically.
    np.testing.assert_allclose(ml.product_moving_line(ml.unscaled_to_bernstein(la), ml.unscaled_to_bernstein(lb)), 0,
                               atol=1e-12)
    np.testing.assert_array_equal(4 * la - lb, TRIPLE.results["eliminated"])  # the corrected (18.76)
    erratum = TRIPLE.errata["pencil"]
    np.testing.assert_array_equal(erratum.correct, TRIPLE.results["eliminated"])
    assert np.abs(ml.incidence(ml.unscaled_to_bernstein(erratum.notes), points)).max() > 1  # does not follow
    pencil = TRIPLE.results["pencil"]
    np.testing.assert_allclose(ml.incidence(pencil, points), 0, atol=1e-12)
    assert same_up_to_scale(np.cross(*pencil), TRIPLE.results["triple_point"])
    high, low = ml.two_moving_lines(points)  # the μ-basis: a pencil and a cubic
    assert high.shape == (4, 3) and low.shape == (2, 3)
    assert same_up_to_scale(np.cross(*low), TRIPLE.results["triple_point"])
    with pytest.raises(ValueError, match="^points: the quartic has a triple point"):
        ml.quartic_double_points(points)
    with pytest.raises(ValueError, match="^la, lb: every combination is axial"):
        ml.axial_combinations(la, lb)
    for t in TRIPLE.results["triple_point_parameters"]:
        np.testing.assert_allclose(bezier.evaluate(points, t), TRIPLE.results["triple_point"][:2], atol=1e-12)


@pytest.mark.parametrize("example, implicit", [(CUBIC, CUBIC), (QUARTIC, QUARTIC_IMPLICIT), (TRIPLE, TRIPLE)],
                         ids=["cubic", "quartic", "triple point"])
def test_the_implicit_equations_of_the_notes_curves(example, implicit):
    c = ml.moving_line_implicit(example.inputs["points"])
    assert c.shape == implicit.results["implicit"].shape
    assert same_up_to_scale(c, implicit.results["implicit"])
    assert same_up_to_scale(c, exact_implicit(example.inputs["points"].tolist()))  # SymPy's resultant


def test_the_implicit_equation_18_87_from_two_moving_lines():
    c = ml.moving_lines_implicit(*QUARTIC_IMPLICIT.args("la", "lb"))
    assert same_up_to_scale(c, QUARTIC_IMPLICIT.results["implicit"])
    # (18.86): the rows at (x, y, 1), and their resultant by SymPy.
    la, lb = QUARTIC_IMPLICIT.args("la", "lb")
    forms = [[int(a) * X + int(b) * Y + int(cc) for a, b, cc in rows] for rows in (la, lb)]
    fa, fb = (sum(f * (1 - T) ** (2 - j) * T**j for j, f in enumerate(row)) for row in forms)
    exact = sp.Poly(sp.resultant(sp.expand(fa), sp.expand(fb), T), X, Y)
    target = sp.Poly(Y**4 + 4 * X**3 + 2 * X * Y**2 - 16 * X**2 - 6 * Y**2 + 16 * X, X, Y)
    assert sp.simplify(exact.as_expr() / target.as_expr()).is_number


def test_the_tangent_moving_line_and_scaled_hodograph_of_the_cubic():
    points = TANGENT.inputs["points"]
    np.testing.assert_allclose(ml.tangent_moving_line(points), TANGENT.results["lines"])
    np.testing.assert_allclose(ml.scaled_hodograph(points), TANGENT.results["scaled_hodograph"])
    np.testing.assert_allclose(bezier.hodograph(points), TANGENT.results["hodograph"])
    np.testing.assert_allclose(bezier.elevate(TANGENT.results["hodograph"], 2), TANGENT.results["scaled_hodograph"])


def test_the_course_examples_of_pencils_and_conics():
    example = notes_example("18.two_pencils")
    lines = example.args("l00", "l01", "l10", "l11")
    control = ml.conic_from_pencils(*lines)
    np.testing.assert_allclose(control, example.results["control_points"])
    c = ml.pencils_implicit(*lines)
    assert same_up_to_scale(c, example.results["implicit"])
    assert conic_type(c[2, 0], c[1, 1], c[0, 2], c[1, 0], c[0, 1], c[0, 0]) == example.results["conic_type"]
    line = notes_example("18.parameter_line")
    ends = ml.pencil_parameter_line(*line.args("l0", "l1", "d0"))
    np.testing.assert_allclose(ends, line.results["parameter_line"], atol=1e-15)
    np.testing.assert_allclose(np.linalg.norm(ends[1] - line.results["axis"][:2]), line.results["d1"])
    product = notes_example("18.product_line")
    np.testing.assert_allclose(ml.product_moving_line(*product.args("p", "q")), product.results["lines"])


def test_the_nomogram_reads_the_parameter():
    example = notes_example("18.nomogram")
    points, weights, ts = example.args("points", "weights", "t")
    for t in ts:
        found = ml.nomogram_parameter(points, bezier.evaluate(points, t, weights), weights)
        assert found == pytest.approx(t, abs=1e-12)
    p = bezier.to_homogeneous(points, weights)
    pencils = ml.quadratic_pencils(points, weights)
    assert same_up_to_scale(np.cross(*pencils[0]), p[0]) and same_up_to_scale(np.cross(*pencils[1]), p[2])  # axes
    # The two parameter lines end at Pa and Pb (18.36): the pencils meet them where their lines do.
    pa, pb = example.results["pa"], example.results["pb"]
    assert np.dot(pencils[0, 0], [*pa, 1.0]) == pytest.approx(0, abs=1e-12)
    assert np.dot(pencils[1, 1], [*pb, 1.0]) == pytest.approx(0, abs=1e-12)


# --- properties on random curves -----------------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(12))
def test_the_product_moving_line_is_the_cross_product_of_the_moving_points(seed):
    rng = np.random.default_rng(seed)
    p, q = rng.normal(size=(int(rng.integers(1, 4)), 3)), rng.normal(size=(int(rng.integers(1, 5)), 3))
    lines = ml.product_moving_line(p, q)
    assert lines.shape == (len(p) + len(q) - 1, 3)
    np.testing.assert_allclose(ml.moving_line_eval(lines, TS),
                               np.cross(bezier.de_casteljau(p, TS), bezier.de_casteljau(q, TS)), atol=1e-10)


@pytest.mark.parametrize("seed", range(8))
def test_two_pencils_meet_on_their_conic(seed):
    rng = np.random.default_rng(seed)
    lines = rng.normal(size=(4, 3))
    control = ml.conic_from_pencils(*lines)
    curve = bezier.de_casteljau(control, TS)
    meet = np.cross(ml.moving_line_eval(lines[:2], TS), ml.moving_line_eval(lines[2:], TS))
    np.testing.assert_allclose(curve, meet, atol=1e-12)
    values, sizes = implicit_values(ml.pencils_implicit(*lines), curve[:, :2] / curve[:, 2:])
    assert np.all(np.abs(values) <= 1e-9 * sizes)


@pytest.mark.parametrize("seed", range(6))
def test_a_pencil_follows_its_parameter_line(seed):
    rng = np.random.default_rng(seed)
    axis = rng.uniform(-2, 2, 2)
    l0, l1 = (np.cross([*axis, 1.0], [*rng.uniform(-2, 2, 2), 1.0]) for _ in range(2))
    ends = ml.pencil_parameter_line(l0, l1, 1.5)
    line = bezier.de_casteljau(ends, TS)
    incidence = np.einsum("ij,ij->i", ml.moving_line_eval([l0, l1], TS), np.column_stack([line, np.ones(len(TS))]))
    np.testing.assert_allclose(incidence, 0, atol=1e-10)
    np.testing.assert_allclose(np.linalg.norm(ends - axis, axis=1),
                               [1.5, 1.5 * np.hypot(*l1[:2]) / np.hypot(*l0[:2])])


@pytest.mark.parametrize("seed", range(6))
def test_the_two_pencils_of_a_rational_quadratic_meet_on_it(seed):
    points, weights = random_curve(seed, 2)
    pencils = ml.quadratic_pencils(points, weights)
    meet = np.cross(ml.moving_line_eval(pencils[0], TS), ml.moving_line_eval(pencils[1], TS))
    np.testing.assert_allclose(meet[:, :2] / meet[:, 2:], bezier.evaluate(points, TS, weights), rtol=1e-8, atol=1e-8)
    for t in (0.25, 0.8):
        assert ml.nomogram_parameter(points, bezier.evaluate(points, t, weights), weights) == pytest.approx(t)


@pytest.mark.parametrize("degree", [2, 3, 4, 5])
@pytest.mark.parametrize("seed", range(5))
def test_moving_lines_follow_random_rational_curves(degree, seed):
    points, weights = random_curve(100 * degree + seed, degree, rational=seed % 2 == 0)
    for row in ml.bezout_moving_lines(points, weights):
        coeffs = ml.incidence(ml.unscaled_to_bernstein(row), points, weights)
        assert np.abs(coeffs).max() <= 1e-12 * np.abs(row).max() * np.abs(points).max() * 10
    high, low = ml.two_moving_lines(points, weights)
    assert (len(high) - 1, len(low) - 1) == ((degree + 1) // 2, degree // 2)
    for line in (high, low):
        assert np.abs(ml.incidence(ml.unscaled_to_bernstein(line), points, weights)).max() <= 1e-12
    axis = bezier.to_homogeneous(points[:1], [1.0])[0]
    assert np.abs(ml.incidence(ml.axial_moving_line(axis, points, weights), points, weights)).max() <= 1e-12


@pytest.mark.parametrize("degree", [2, 3, 4, 5])
@pytest.mark.parametrize("seed", range(5))
def test_the_two_moving_line_forms_give_one_implicit_equation(degree, seed):
    points, weights = random_curve(200 * degree + seed, degree, rational=seed % 2 == 1)
    compact = ml.moving_line_implicit(points, weights)
    assert compact.shape == (degree + 1, degree + 1)
    assert same_up_to_scale(compact, determinant_implicit(points, weights), tol=1e-8)
    on = bezier.evaluate(points, TS, weights)
    values, sizes = implicit_values(compact, on)
    assert np.all(np.abs(values) <= 1e-9 * sizes)
    # Off the curve: points at least 5 % of the curve's size away from every sampled point of it (t in [-4, 5]).
    rng = np.random.default_rng(seed)
    dense = bezier.evaluate(points, np.linspace(-4, 5, 4001), weights)
    size = np.ptp(points, axis=0).max()
    off = rng.uniform(points.min(axis=0), points.max(axis=0), (40, 2))
    far = np.array([np.linalg.norm(dense - q, axis=1).min() > 0.05 * size for q in off])
    values, sizes = implicit_values(compact, off[far])
    assert far.sum() >= 10 and np.all(np.abs(values) > 1e-7 * sizes)


def test_moving_line_implicit_agrees_with_chapter_17():
    algebra = pytest.importorskip("cagd_ref.algebra")
    for degree in (2, 3, 4, 5):
        points, weights = random_curve(7 + degree, degree)
        assert same_up_to_scale(ml.moving_line_implicit(points, weights), algebra.implicitize(points, weights), 1e-8)


@pytest.mark.parametrize("seed", range(4))
def test_integer_curves_against_sympy(seed):
    rng = np.random.default_rng(seed)
    for degree in (2, 3, 4, 5):
        points = rng.integers(-4, 5, (degree + 1, 2)).tolist()
        assert same_up_to_scale(ml.moving_line_implicit(points), exact_implicit(points), 1e-9)


CUBICS = {
    "notes' crunode": ([(0, 0), (0, 1), (1, 2), (3, 0)], [3, 0, 1]),
    "chapter 19 crunode": ([(3, 3), (-13, -15), (-13, 15), (3, -3)], [0, 0, 1]),
    "cusp (P0 = P1)": ([(0, 0), (0, 0), (1, 0), (3, 3)], [0, 0, 1]),
    "acnode": ([(3, 0), (3, 1), (4, 2), (6, 6)], [0, 0, 1]),
    "y = x³, at infinity": ([(0, 0), (1 / 3, 0), (2 / 3, 0), (1, 1)], [0, 1, 0]),
}


@pytest.mark.parametrize("name", CUBICS)
def test_the_double_points_of_the_cubics(name):
    points, expected = CUBICS[name]
    found = ml.cubic_double_point(points)
    assert np.linalg.norm(found) == pytest.approx(1) and same_up_to_scale(found, expected, 1e-12)
    assert found[2] >= 0


@pytest.mark.parametrize("seed", range(10))
def test_the_double_point_of_a_random_rational_cubic_is_singular(seed):
    points, weights = random_curve(300 + seed, 3)
    p = ml.cubic_double_point(points, weights)
    c = ml.moving_line_implicit(points, weights)
    i, j = np.indices(c.shape)
    X_, Y_, W_ = p
    # The homogeneous form F(X, Y, W) and its partial derivatives vanish at a double point, finite or not.
    terms = c * X_**i * Y_**j * W_ ** (3 - i - j)
    grads = [(c * i * X_ ** np.maximum(i - 1, 0) * Y_**j * W_ ** (3 - i - j)).sum(),
             (c * j * X_**i * Y_ ** np.maximum(j - 1, 0) * W_ ** (3 - i - j)).sum(),
             (c * (3 - i - j) * X_**i * Y_**j * W_ ** np.maximum(2 - i - j, 0)).sum()]
    assert abs(terms.sum()) <= 1e-9 and np.abs(grads).max() <= 1e-8


def test_the_double_points_of_a_random_quartic_are_singular():
    rng = np.random.default_rng(11)
    points = rng.integers(-4, 5, (5, 2)).tolist()
    c = exact_implicit(points)
    poly = sum(int(c[i, j]) * X**i * Y**j for i in range(5) for j in range(5))
    singular = sp.solve([poly, sp.diff(poly, X), sp.diff(poly, Y)], [X, Y], dict=True)
    found = ml.quartic_double_points(points)
    finite = found[np.abs(found[:, 2]) > 1e-9]
    expected = sorted(complex(s[X]).real for s in singular)
    assert len(singular) == len(finite)
    np.testing.assert_allclose(sorted((finite[:, 0] / finite[:, 2]).real), expected, atol=1e-8)


@pytest.mark.parametrize("degree", [1, 2, 3, 4, 5])
def test_the_tangent_moving_line_touches_the_curve(degree):
    points, weights = random_curve(400 + degree, degree)
    lines = ml.tangent_moving_line(points, weights)
    assert lines.shape == (2 * degree - 1, 3)
    h = bezier.to_homogeneous(points, weights)
    tangent = ml.moving_line_eval(lines, TS)
    curve = bezier.de_casteljau(h, TS)
    velocity = bezier.de_casteljau(bezier.hodograph(h), TS)
    np.testing.assert_allclose(tangent, np.cross(curve, velocity), atol=1e-9)
    hodograph = bezier.de_casteljau(ml.scaled_hodograph(points, weights), TS)
    w = curve[:, 2:]
    np.testing.assert_allclose(hodograph, w**2 * bezier.derivative(points, TS, 1, weights), rtol=1e-9, atol=1e-9)


@pytest.mark.parametrize("seed", range(5))
def test_a_moving_line_touches_its_envelope(seed):
    lines = np.random.default_rng(seed).normal(size=(int(2 + seed % 3), 3))
    points = ml.envelope(lines)
    e = bezier.de_casteljau(points, TS)
    line = ml.moving_line_eval(lines, TS)
    slope = bezier.de_casteljau(bezier.hodograph(lines), TS)
    np.testing.assert_allclose(np.einsum("ij,ij->i", e, line), 0, atol=1e-10)
    np.testing.assert_allclose(np.einsum("ij,ij->i", e, slope), 0, atol=1e-10)


def test_the_degrees_of_the_mu_basis():
    generic = QUARTIC.inputs["points"]
    assert [len(ml.moving_lines_of_degree(generic, d)) for d in range(4)] == [0, 0, 2, 4]
    assert [len(ml.moving_lines_of_degree(TRIPLE.inputs["points"], d)) for d in range(4)] == [0, 1, 2, 4]
    assert [len(ml.moving_lines_of_degree(CUBIC.inputs["points"], d)) for d in range(3)] == [0, 1, 3]


def test_an_axis_on_the_curve_is_a_base_point():
    points = CUBIC.inputs["points"]
    tau = 0.3
    axis = bezier.to_homogeneous([bezier.evaluate(points, tau)], [1.0])[0]
    lines = ml.axial_moving_line(axis, points)
    np.testing.assert_allclose(ml.moving_line_eval(lines, tau), 0, atol=1e-12)


# --- the teaching forms and the mu-basis ---------------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_the_plain_forms_agree_with_the_checked_functions(seed):
    rng = np.random.default_rng(seed)
    p, q = rng.normal(size=(int(1 + seed % 3), 3)), rng.normal(size=(int(1 + (seed + 1) % 4), 3))
    np.testing.assert_allclose(ml.product_moving_line_plain(p, q), ml.product_moving_line(p, q), atol=1e-12)
    points, weights = random_curve(seed, 1 + seed % 5)
    np.testing.assert_allclose(ml.bezout_moving_lines_plain(points, weights), ml.bezout_moving_lines(points, weights),
                               rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ml.tangent_moving_line_plain(points, weights), ml.tangent_moving_line(points, weights),
                               rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ml.bezout_moving_lines_plain(points), ml.bezout_moving_lines(points), atol=1e-12)
    cubic, cubic_weights = random_curve(seed + 100, 3)
    assert same_up_to_scale(ml.cubic_double_point_plain(cubic, cubic_weights),
                            ml.cubic_double_point(cubic, cubic_weights))


@pytest.mark.parametrize("name", ["notes", "crunode", "cusp", "acnode", "at infinity"])
def test_the_plain_double_point_finds_the_same_point(name):
    points = {"notes": CUBIC.inputs["points"], "crunode": [(3, 3), (-13, -15), (-13, 15), (3, -3)],
              "cusp": [(0, 0), (0, 0), (1, 0), (3, 3)], "acnode": [(3, 0), (3, 1), (4, 2), (6, 6)],
              "at infinity": [(0, 0), (1 / 3, 0), (2 / 3, 0), (1, 1)]}[name]
    assert same_up_to_scale(ml.cubic_double_point_plain(points), ml.cubic_double_point(points))


@pytest.mark.parametrize("degree, seed", [(2, 0), (3, 1), (4, 2), (5, 3), (6, 4)])
def test_two_moving_lines_form_a_mu_basis(degree, seed):
    """Cox, Sederberg and Chen (1998): La × Lb is a constant times P(t), and every moving line that follows is
    f La + g Lb, with as many of each degree as the count max(0, m-mu+1) + max(0, m-n+mu+1) says."""
    points, weights = random_curve(seed, degree)
    high, low = (ml.unscaled_to_bernstein(line) for line in ml.two_moving_lines(points, weights))
    mu = len(low) - 1
    assert mu == degree // 2 and len(high) - 1 == degree - mu
    product = ml.product_moving_line(low, high)
    assert same_up_to_scale(product, bezier.to_homogeneous(points, weights))
    for m in range(degree + 1):
        found = ml.moving_lines_of_degree(points, m, weights)
        assert len(found) == max(0, m - mu + 1) + max(0, m - degree + mu + 1)
        for line in found:
            f, g = ml.mu_basis_coefficients(line, low, high)
            assert len(f) == max(m - mu + 1, 0) and len(g) == max(m - degree + mu + 1, 0)


def test_the_triple_point_quartic_has_a_mu_basis_of_degrees_one_and_three():
    points = TRIPLE.inputs["points"]
    high, low = (ml.unscaled_to_bernstein(line) for line in ml.two_moving_lines(points))
    assert (len(low), len(high)) == (2, 4)
    assert same_up_to_scale(ml.product_moving_line(low, high), bezier.to_homogeneous(points, np.ones(5)))
    for row in ml.unscaled_to_bernstein(ml.bezout_moving_lines(points)):
        ml.mu_basis_coefficients(row, low, high)  # every row of the 4×4 matrix is f Lb + g La
    with pytest.raises(ValueError, match="^lines"):
        ml.mu_basis_coefficients([(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)], low, high)


def test_the_axial_condition_of_the_quartic():
    la, lb = QUARTIC.results["la"], QUARTIC.results["lb"]
    np.testing.assert_allclose(ml.axial_condition(la, lb), QUARTIC.results["axial_cubic"], atol=1e-9)
    with pytest.raises(ValueError, match="^la, lb"):
        ml.axial_condition(la, [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0)])


# --- bad input -----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("call, message", [
    (lambda: ml.bezout_moving_lines([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)]), "^points"),
    (lambda: ml.bezout_moving_lines([(0.0, 0.0)]), "^points"),
    (lambda: ml.bezout_moving_lines([(0, 0), (1, 1), (2, 0)], [1.0, 0.0, 1.0]), "^weights"),
    (lambda: ml.cubic_double_point([(0, 0), (1, 1), (2, 0)]), "^points: expected the 4"),
    (lambda: ml.cubic_double_point(bezier.elevate([(0.0, 0.0), (1.0, 2.0), (3.0, 0.0)])), "^points: the curve is not"),
    (lambda: ml.cubic_double_point([(0, 0), (1, 1), (2, 2), (4, 4)]), "^points"),
    (lambda: ml.moving_line_implicit(bezier.elevate(CUBIC.inputs["points"])), "^points: the curve's true degree"),
    (lambda: ml.product_moving_line([(0.0, 0.0)], [(1.0, 0.0, 1.0)]), "^p"),
    (lambda: ml.product_moving_line([(0.0, 0.0, 1.0)], [(0.0, 0.0, 0.0)]), "^q"),
    (lambda: ml.conic_from_pencils([1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 1]), "^l00, l01"),
    (lambda: ml.conic_from_pencils([1, 0, 0], [0, 1, 0], [1, 1, 0], [1, -1, 0]), "^l00, l01, l10, l11"),
    (lambda: ml.pencil_parameter_line([0, 1, 0], [0, 1, 3], 1.0), "^l0, l1: the lines are parallel"),
    (lambda: ml.pencil_parameter_line([0, 1, 0], [1, 1, 0], -1.0), "^d0"),
    (lambda: ml.envelope([(1.0, 0.0, 0.0)]), "^lines"),
    (lambda: ml.two_moving_lines([(0, 0), (1, 1)]), "^points"),
])
def test_bad_input_is_rejected_by_name(call, message):
    with pytest.raises(ValueError, match=message):
        call()

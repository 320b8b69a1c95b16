"""Unit tests of cagd_ref.plane_curves: genus, double points, resultants, intersections, parametrization (chapter 19).

The notes' worked examples come from cagd_course/examples/ch19.toml (the
curves of Figures 19.2-19.7, the circle and hyperbola of §19.3 recovered from
their printed points, the cubic with its double point at (2, 3)). Every exact
claim is checked with SymPy (resultants, discriminants, GCDs, factored tangent
cones, singular points); the rest by properties on seeded random data: a
parametrization lies on its curve, intersections satisfy both equations, a
conic passes through its five points.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import polynomial as P

from cagd_course.examples import notes_example
from cagd_ref import algebra
from cagd_ref import plane_curves as pc

X, Y, T = sp.symbols("x y t")
HYPERBOLA_EXAMPLE = notes_example("19.circle_hyperbola")
GENERAL = notes_example("19.general_cubic")


def poly(c) -> sp.Expr:
    """c[i, j] of xⁱ yʲ (integers, or floats that are integers) as a SymPy polynomial."""
    return sum(sp.Integer(int(round(v))) * X**i * Y**j for (i, j), v in np.ndenumerate(np.asarray(c)) if v)


def coefficients(expr, variable) -> list[float]:
    """Ascending coefficients of a univariate SymPy polynomial."""
    return [float(v) for v in sp.Poly(sp.expand(expr), variable).all_coeffs()[::-1]]


def same_up_to_scale(a, b, tol=1e-9):
    a, b = (np.asarray(v, dtype=float).ravel() for v in (a, b))
    a, b = a / np.abs(a).max(), b / np.abs(b).max()
    return min(np.abs(a - b).max(), np.abs(a + b).max()) <= tol


def rotation(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, s], [-s, c]])


def moved(c, angle, point):
    """The curve c turned by `angle` about the origin and then moved so that the origin goes to `point`."""
    m = rotation(angle)
    return pc.transform_implicit(c, m, -m @ np.asarray(point, dtype=float))


# --- §19.1 genus --------------------------------------------------------------------------------------------------


def test_genus_of_the_notes_curves():
    example = notes_example("19.genus")
    for case, expected in zip(example.inputs["cases"], example.results["genus"]):
        degree, *multiplicities = [int(v) for v in case]
        assert pc.genus(degree, multiplicities) == expected
    assert pc.genus(1) == 0 and pc.genus(5) == 6 and pc.genus(5, (3, 2)) == 2
    assert isinstance(pc.genus(3, np.array([2])), int)


def test_too_many_singular_points_mean_a_reducible_curve():
    circles = notes_example("19.concentric_circles")
    assert sp.factor(poly(circles.inputs["c"])) == (X**2 + Y**2 - 4) * (X**2 + Y**2 - 1)
    with pytest.raises(ValueError, match="^multiplicities.*reducible"):
        pc.genus(4, [2, 2, 2, 2])
    with pytest.raises(ValueError, match="^multiplicities"):
        pc.genus(3, [3])  # a triple point on a cubic: three lines
    with pytest.raises(TypeError, match="^multiplicities"):
        pc.genus(3, [2.0])
    with pytest.raises(ValueError, match="^degree"):
        pc.genus(0)


# --- changes of coordinates ------------------------------------------------------------------------------------------


def test_translation_and_rotation_agree_with_sympy():
    c = GENERAL.inputs["c"]
    assert np.array_equal(pc.translate_implicit(c, 2, 3), GENERAL.results["translated"])
    m = np.array([[3.0, -1.0], [2.0, 5.0]])
    got = pc.transform_implicit(c, m, (1.0, -2.0))
    exact = sp.expand(poly(c).subs({X: 3 * X - Y + 1, Y: 2 * X + 5 * Y - 2}, simultaneous=True))
    assert sp.expand(poly(got) - exact) == 0
    assert got.shape == (4, 4)


def test_homogeneous_parts_and_degree():
    example = notes_example("19.double_point")
    parts = pc.homogeneous_parts(example.inputs["c"])
    assert [len(g) for g in parts] == [1, 2, 3, 4] and pc.implicit_degree(example.inputs["c"]) == 3
    assert np.array_equal(parts[2], example.results["tangent_cone"])


# --- §19.2 double points ---------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["19.double_point", "19.crunode", "19.cusp", "19.acnode", "19.figure_19_7"])
def test_the_notes_double_points_are_classified(name):
    example = notes_example(name)
    c, point = example.inputs["c"], example.inputs["point"]
    assert pc.multiplicity(c, point) == 2
    assert pc.classify_double_point(c, point) == example.results["kind"]
    cone = pc.tangent_cone(c, point)
    m = sp.symbols("m")
    exact = sp.Poly(sum(sp.Integer(int(v)) * m**j for j, v in enumerate(cone)), m)  # g_2(1, m)
    lines = len(set(sp.real_roots(exact))) + (exact.degree() < 2)  # a vertical tangent when the degree drops
    assert lines == {"crunode": 2, "cusp": 1, "acnode": 0}[example.results["kind"]]
    assert len(pc.tangent_directions(c, point)) == {"crunode": 2, "cusp": 1, "acnode": 0}[example.results["kind"]]


def test_the_tangents_of_the_first_example_meet_the_curve_three_times():
    example = notes_example("19.double_point")
    directions = pc.tangent_directions(example.inputs["c"], (0, 0))
    expected = np.array(example.results["tangents"], dtype=float)
    expected /= np.linalg.norm(expected, axis=1, keepdims=True)
    for d in directions:
        assert min(min(np.abs(d - e).max(), np.abs(d + e).max()) for e in expected) < 1e-12
        line = sp.expand(poly(example.inputs["c"]).subs({X: d[0] * T, Y: d[1] * T}))
        assert abs(float(sp.Poly(line, T).coeff_monomial(T**2))) < 1e-12


def test_the_general_cubic_has_a_crunode_at_2_3():
    c = GENERAL.inputs["c"]
    assert pc.classify_double_point(c, GENERAL.results["double_point"]) == "crunode"
    low = sum(sp.Integer(int(GENERAL.results["translated"][i][j])) * X**i * Y**j for i in range(3) for j in range(3)
              if i + j == 2)
    assert sp.factor(low) == (X + 2 * Y) * (2 * X + 3 * Y)


@pytest.mark.parametrize("seed", range(8))
def test_classification_survives_rotation_and_translation(seed):
    rng = np.random.default_rng(seed)
    for name in ("19.crunode", "19.cusp", "19.acnode"):
        example = notes_example(name)
        point = rng.uniform(-3, 3, 2)
        c = moved(example.inputs["c"], rng.uniform(0, 2 * np.pi), point)
        assert pc.classify_double_point(c, point) == example.results["kind"]
        assert pc.classify_double_point(c, point + 1e-13) == example.results["kind"]


def test_classification_rejects_points_that_are_not_double():
    c = GENERAL.inputs["c"]
    with pytest.raises(ValueError, match="^point: not on the curve"):
        pc.classify_double_point(c, (0, 0))
    assert pc.multiplicity(c, (1.0, 0.0)) == 0  # f(1, 0) = 13
    with pytest.raises(ValueError, match="simple point"):
        pc.classify_double_point([[0, 1], [1, 0]], (0, 0))  # the line x + y = 0
    with pytest.raises(ValueError, match="multiplicity 3"):
        pc.classify_double_point([[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0], [1, 0, 0, 0]], (0, 0))  # x³ + y³
    with pytest.raises(ValueError, match="^c"):
        pc.classify_double_point(np.zeros((3, 3)), (0, 0))
    with pytest.raises(ValueError, match="^point"):
        pc.classify_double_point(c, (2, 3, 1))


# --- §19.3 resultants and intersections ------------------------------------------------------------------------------


def test_the_notes_resultants_of_circle_and_hyperbola():
    circle, hyperbola = HYPERBOLA_EXAMPLE.args("circle", "hyperbola")
    rx = pc.curve_resultant(circle, hyperbola, eliminate="x")
    ry = pc.curve_resultant(circle, hyperbola)
    assert np.allclose(rx, HYPERBOLA_EXAMPLE.results["x_resultant"], atol=1e-9)
    assert np.allclose(ry, HYPERBOLA_EXAMPLE.results["y_resultant"], atol=1e-9)
    assert np.allclose(rx, coefficients(sp.resultant(poly(circle), poly(hyperbola), X), Y))
    assert np.allclose(ry, coefficients(sp.resultant(poly(circle), poly(hyperbola), Y), X))
    assert sp.factor(sp.resultant(poly(circle), poly(hyperbola), X)) == Y * (3 * Y - 4) * (4 * Y - 3) * (12 * Y - 5)


def test_the_gcd_pairs_x_with_y():
    circle, hyperbola = HYPERBOLA_EXAMPLE.args("circle", "hyperbola")
    at = [P.polyval(5 / 3, np.asarray(c, dtype=float)) for c in (circle, hyperbola)]
    assert np.allclose(at[0], HYPERBOLA_EXAMPLE.results["circle_at_5_3"])
    assert np.allclose(at[1], HYPERBOLA_EXAMPLE.results["hyperbola_at_5_3"])
    assert np.allclose(algebra.poly_gcd(*at), HYPERBOLA_EXAMPLE.results["gcd_at_5_3"])
    exact = sp.gcd(poly(circle).subs(X, sp.Rational(5, 3)), poly(hyperbola).subs(X, sp.Rational(5, 3)))
    assert sp.expand(exact * 3 / exact.coeff(Y)) == 3 * Y - 4
    erratum = HYPERBOLA_EXAMPLE.errata["substitutions"]
    assert "16/9" in erratum.correct


def test_the_notes_four_intersections():
    circle, hyperbola = HYPERBOLA_EXAMPLE.args("circle", "hyperbola")
    got = pc.implicit_intersections(circle, hyperbola)
    assert np.allclose(got, HYPERBOLA_EXAMPLE.results["points"], atol=1e-12)
    exact = sp.solve([poly(circle), poly(hyperbola)], [X, Y], dict=True)
    assert np.allclose(sorted((float(s[X]), float(s[Y])) for s in exact), got)


@pytest.mark.parametrize(
    "f, g, expected",
    [
        ([[-1, 0, 1], [0, 0, 0], [1, 0, 0]], [[-1, 1], [0, 0]], [[0.0, 1.0]]),  # tangency: x² + y² = 1, y = 1
        ([[-1, 0, 1], [0, 0, 0], [1, 0, 0]], [[-2, 1], [0, 0]], []),  # no real point
        ([[-1, 0, 1], [0, 0, 0], [1, 0, 0]], [[0, 0], [1, 0]], [[0.0, -1.0], [0.0, 1.0]]),  # the line x = 0
        ([[-4, 0, 1], [0, 0, 0], [1, 0, 0]], [[-9, 0, 1], [0, 0, 0], [9, 0, 0]],  # two points on each vertical line
         [[-np.sqrt(5 / 8), -np.sqrt(27 / 8)], [-np.sqrt(5 / 8), np.sqrt(27 / 8)],
          [np.sqrt(5 / 8), -np.sqrt(27 / 8)], [np.sqrt(5 / 8), np.sqrt(27 / 8)]]),
        ([[-1], [1]], [[-2], [1]], []),  # x = 1 and x = 2: both without y
        ([[-1], [1]], [[-2, 1]], [[1.0, 2.0]]),  # x = 1 and y = 2
    ],
)
def test_special_intersections(f, g, expected):
    got = pc.implicit_intersections(f, g)
    assert got.shape == (len(expected), 2)
    assert np.allclose(got, np.array(expected, dtype=float).reshape(-1, 2), atol=1e-9)


def test_a_common_component_is_refused():
    line_times_circle = [[0, 0, 0], [-1, 0, 1], [0, 0, 0], [1, 0, 0]]  # x (x² + y² - 1)
    with pytest.raises(ValueError, match="^f, g: the curves share a component"):
        pc.implicit_intersections(line_times_circle, [[0, 0, 0], [1, 2, 0], [0, 0, 0]])  # x (1 + 2y)
    with pytest.raises(ValueError, match="^g"):
        pc.implicit_intersections(line_times_circle, [[3.0]])


@pytest.mark.parametrize("seed", range(6))
def test_random_intersections_satisfy_both_equations_and_match_sympy(seed):
    rng = np.random.default_rng(seed)
    f = rng.integers(-5, 6, (3, 3)) * np.fliplr(np.triu(np.ones((3, 3))))
    g = rng.integers(-5, 6, (4, 4)) * np.fliplr(np.triu(np.ones((4, 4))))
    got = pc.implicit_intersections(f, g)
    for c in (f, g):
        values = P.polyval2d(got[:, 0], got[:, 1], c) if len(got) else np.zeros(0)
        assert np.all(np.abs(values) <= 1e-9 * (1 + np.abs(got).max(initial=0)) ** 3 * np.abs(c).sum())
    solutions = sp.Poly(sp.resultant(poly(f), poly(g), Y), X)
    real_x = sorted({round(float(r), 8) for r in sp.real_roots(solutions)}) if solutions.degree() > 0 else []
    assert sorted({round(float(x), 8) for x in got[:, 0]}) == real_x


# --- §19.4 discriminants ---------------------------------------------------------------------------------------------


def test_the_quadratic_discriminant_in_three_conventions():
    example = notes_example("19.quadratic_discriminant")
    coeffs = example.inputs["coeffs"]
    assert pc.discriminant(coeffs) == pytest.approx(example.results["resultant"])  # Sylvester: -98
    bezout = algebra.bezout_matrix(coeffs, P.polyder(coeffs))
    assert np.linalg.det(bezout) == pytest.approx(example.results["bezout_determinant"])  # the notes': 196
    p = sum(int(v) * T**k for k, v in enumerate(coeffs))
    assert sp.discriminant(p, T) == example.results["normalised"]  # b² - 4ac = 49
    a, b, c = sp.symbols("a b c")
    exact = sp.resultant(a * T**2 + b * T + c, 2 * a * T + b, T)
    assert sp.factor(exact) == sp.factor(a * (4 * a * c - b**2))
    # The notes' a²(b² - 4ac) is the Bézout determinant: det B = (-1)^(n(n-1)/2) a_n^(n-m) Res with n = 2, m = 1.
    matrix = sp.Matrix([[2 * a**2, a * b], [a * b, b**2 - 2 * a * c]])  # (17.8) for p and p' = 0 t² + 2a t + b
    assert sp.expand(matrix.det() - a**2 * (b**2 - 4 * a * c)) == 0
    assert sp.expand(matrix.det() - (-1) * a * exact) == 0


@pytest.mark.parametrize("n", range(1, 8))
def test_bezout_determinant_of_p_and_its_derivative(n):
    rng = np.random.default_rng(n)
    coeffs = rng.integers(-5, 6, n + 1).astype(float)
    coeffs[-1] = coeffs[-1] or 2.0
    bezout = np.linalg.det(algebra.bezout_matrix(coeffs, P.polyder(coeffs)))
    expected = (-1) ** (n * (n - 1) // 2) * coeffs[-1] * pc.discriminant(coeffs)
    assert bezout == pytest.approx(expected, rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("seed", range(5))
def test_discriminant_matches_sympy(seed):
    rng = np.random.default_rng(seed)
    coeffs = rng.integers(-6, 7, int(rng.integers(2, 7)))
    coeffs[-1] = coeffs[-1] or 1
    p = sum(int(v) * T**k for k, v in enumerate(coeffs))
    n = len(coeffs) - 1
    exact = sp.resultant(p, sp.diff(p, T), T)
    assert pc.discriminant(coeffs) == pytest.approx(float(exact), rel=1e-9, abs=1e-9)
    # SymPy's discriminant is (-1)^(n(n-1)/2) Res(p, p') / a_n.
    assert float(sp.discriminant(p, T)) == pytest.approx((-1) ** (n * (n - 1) // 2) * float(exact) / int(coeffs[-1]))


def test_discriminant_edge_cases():
    assert pc.discriminant([3.0, 2.0]) == 2.0  # Res(p, a1) = a1
    assert pc.discriminant([-5.0, 3.0, 2.0, 0.0]) == pytest.approx(-98.0)  # trailing zeros dropped
    assert abs(pc.discriminant(P.polyfromroots([1.0, 1.0, -2.0]))) < 1e-9
    for bad in ([4.0], [0.0, 0.0], [[1.0, 2.0]]):
        with pytest.raises(ValueError, match="^coeffs"):
            pc.discriminant(bad)


def test_the_silhouette_of_the_general_cubic():
    example = notes_example("19.silhouette")
    d = pc.curve_discriminant(example.inputs["c"])
    f = poly(example.inputs["c"])
    exact = sp.resultant(f, sp.diff(f, Y), Y)
    assert sp.factor(exact) == (X - 2) ** 2 * (27 * X**2 - 68 * X - 8)
    assert np.allclose(d, example.results["discriminant"])
    roots = np.sort(P.polyroots(d).real)
    assert np.allclose(roots[[0, 3]], example.results["vertical_tangents"])
    # At a vertical tangent x = x_v, f(x_v, y) has a double root: f and f_y meet there.
    for xv in example.results["vertical_tangents"]:
        column = P.polyval(xv, np.asarray(example.inputs["c"], dtype=float))
        assert len(algebra.poly_gcd(column, P.polyder(column), tol=1e-6)) == 2


# --- §19.5 singular points and parametrization --------------------------------------------------------------------


def test_the_general_cubic_has_one_singular_point_and_a_trap():
    c = GENERAL.inputs["c"]
    fx, fy = P.polyder(np.asarray(c, dtype=float), axis=0), P.polyder(np.asarray(c, dtype=float), axis=1)
    assert np.array_equal(fx[:3, :3], GENERAL.results["fx"]) and np.array_equal(fy[:3, :3], GENERAL.results["fy"])
    assert np.allclose(pc.curve_resultant(fx, fy), GENERAL.results["y_resultant_of_derivatives"])
    assert np.allclose(pc.curve_resultant(fx, fy, "x"), GENERAL.results["x_resultant_of_derivatives"])
    assert np.allclose(pc.implicit_intersections(fx, fy), GENERAL.results["candidates"])
    assert algebra.implicit_eval(c, GENERAL.results["candidates"][1]) == pytest.approx(-1 / 432)
    assert np.allclose(pc.singular_points(c), [GENERAL.results["double_point"]])
    exact = sp.solve([poly(c), sp.diff(poly(c), X), sp.diff(poly(c), Y)], [X, Y], dict=True)
    assert exact == [{X: 2, Y: 3}]


@pytest.mark.parametrize("name", ["19.circle_pencil", "19.cubic_pencil", "19.figure_19_7", "19.crunode", "19.cusp",
                                  "19.acnode"])
def test_the_notes_parametrizations(name):
    example = notes_example(name)
    got = pc.parametrize_by_pencil(example.inputs["c"], example.inputs["point"])
    assert np.allclose(got, example.results["pencil"])
    if "points" in example.results:
        assert np.allclose(pc.pencil_point(got, example.inputs["t"]), example.results["points"])


def test_the_general_cubic_parametrization_and_its_double_point_parameters():
    got = pc.parametrize_by_pencil(GENERAL.inputs["c"], GENERAL.results["double_point"])
    assert np.allclose(got, GENERAL.results["pencil"])
    xt, yt, wt = (sum(sp.Integer(int(v)) * T**k for k, v in enumerate(row)) for row in got)
    assert sp.simplify(poly(GENERAL.inputs["c"]).subs({X: xt / wt, Y: yt / wt}, simultaneous=True)) == 0
    assert np.allclose(pc.pencil_point(got, GENERAL.results["double_point_parameters"]), [[2, 3], [2, 3]])


def test_the_crunode_pencil_gives_the_notes_bezier_points():
    example = notes_example("19.crunode")
    points, weights = pc.pencil_bezier(example.results["pencil"], example.results["pencil_interval"])
    assert np.allclose(points[::-1], example.inputs["points"]) and np.allclose(weights, 1)
    square = pc.translate_implicit(example.inputs["c"], 0, 0)  # the same curve, as a (4, 4) array
    assert same_up_to_scale(algebra.implicitize(example.inputs["points"]), square)


@pytest.mark.parametrize("seed", range(6))
def test_random_parametrizations_lie_on_their_curves(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(2, 5))
    c = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(n + 1 - i):
            if i + j >= n - 1:
                c[i, j] = rng.integers(-4, 5)
    c[n, 0] = c[n, 0] or 1
    point = rng.uniform(-2, 2, 2)
    curve = pc.translate_implicit(c, -point[0], -point[1])
    xyw = pc.parametrize_by_pencil(curve, point)
    ts = rng.uniform(-3, 3, 9)
    pts = pc.pencil_point(xyw, ts)
    assert np.abs(P.polyval2d(pts[:, 0], pts[:, 1], curve)).max() <= 1e-9 * (1 + np.abs(pts).max()) ** n * 10
    assert np.allclose(pts[:, 1] - point[1], ts * (pts[:, 0] - point[0]))  # on the line of slope t


def test_parametrization_needs_a_point_of_multiplicity_n_minus_1():
    c = GENERAL.inputs["c"]
    with pytest.raises(ValueError, match="^point: it is not on the curve"):
        pc.parametrize_by_pencil(c, (0, 0))
    with pytest.raises(ValueError, match="^point: it has multiplicity 3"):
        pc.parametrize_by_pencil([[0, 0, 0, 1], [0, 0, 0, 0], [0, 0, 0, 0], [1, 0, 0, 0]], (0, 0))
    with pytest.raises(ValueError, match="^c: a line"):
        pc.parametrize_by_pencil([[0, 1], [1, 0]], (0, 0))
    with pytest.raises(ValueError, match="^t: W"):
        pc.pencil_point([[1, 0], [0, 1], [0, 1]], 0.0)  # W(t) = t


# --- §19.6 undetermined coefficients -----------------------------------------------------------------------------


def test_the_conic_through_five_points_of_the_unit_circle():
    example = notes_example("19.conic_five_points")
    assert np.allclose(pc.conic_through_points(example.inputs["points"]), example.results["c"])


@pytest.mark.parametrize("seed", range(6))
def test_random_conics_pass_through_their_points(seed):
    rng = np.random.default_rng(seed)
    pts = rng.uniform(-4, 4, (5, 2))
    c = pc.conic_through_points(pts)
    assert c.shape == (3, 3) and c[1, 2] == c[2, 1] == c[2, 2] == 0 and np.abs(c).max() == 1.0
    assert np.abs(P.polyval2d(pts[:, 0], pts[:, 1], c)).max() < 1e-12
    exact = sp.Matrix([[x * x, x * y, y * y, x, y, 1] for x, y in
                       [(sp.Rational(str(round(p, 6))), sp.Rational(str(round(q, 6)))) for p, q in pts]]).nullspace()
    assert len(exact) == 1


def test_conics_through_the_origin_and_degenerate_sets():
    pts = [(0, 0), (1, 1), (2, 4), (-1, 1), (3, 9)]  # y = x²: through the origin
    assert same_up_to_scale(pc.conic_through_points(pts), [[0, 1, 0], [0, 0, 0], [-1, 0, 0]])
    pair = pc.conic_through_points([(0, 0), (1, 1), (2, 2), (0, 1), (1, 3)])  # three collinear: a pair of lines
    factors = sp.factor_list(sp.nsimplify(sum(v * X**i * Y**j for (i, j), v in np.ndenumerate(pair)), rational=True))
    assert sorted(sp.Poly(f, X, Y).total_degree() for f, _ in factors[1]) == [1, 1]
    for bad in ([(0, 0), (1, 1), (2, 2), (3, 3), (0, 1)], [(0, 0), (0, 0), (1, 2), (3, 1), (5, 0)]):
        with pytest.raises(ValueError, match="^points: they do not fix one conic"):
            pc.conic_through_points(bad)
    with pytest.raises(ValueError, match="^points"):
        pc.conic_through_points([(0, 0), (1, 0), (0, 1), (1, 1)])


def test_the_circle_through_three_points():
    example = notes_example("19.circle_three_points")
    centre, radius = pc.circle_through_points(*example.inputs["points"])
    assert np.allclose(centre, example.results["centre"]) and radius == pytest.approx(example.results["radius"])
    for p in example.inputs["points"]:
        assert np.linalg.norm(p - centre) == pytest.approx(radius)
    with pytest.raises(ValueError, match="^p1, p2, p3"):
        pc.circle_through_points((0, 0), (1, 1), (2, 2))


# --- the course's examples of chapter 19: δ, caveats of resultants, adjoint curves --------------------------------


def test_the_smooth_cubic_meets_a_line_through_one_of_its_points_twice_more_by_a_square_root():
    example = notes_example("19.smooth_cubic")
    c = example.inputs["c"]
    assert pc.singular_points(c).shape == (0, 2) and pc.genus(3) == example.results["genus"]
    assert len(sp.factor_list(poly(c))[1]) == 1  # irreducible, yet an oval and a branch
    along = sp.factor(poly(c).subs(Y, T * X))  # on the line y = t x
    assert along == sp.factor(-X * (X**2 - T**2 * X - 1))
    assert sp.sqrt(T**4 + 4).is_Pow  # no polynomial square root: the two points are not rational in t


def test_the_tacnode_counts_twice_in_the_genus():
    example = notes_example("19.tacnode_quartic")
    c = example.inputs["c"]
    rows = example.inputs["parametrization"]
    xt, yt, wt = (sum(sp.Integer(int(v)) * T**k for k, v in enumerate(row)) for row in rows)
    assert sp.expand(sp.resultant(sp.expand(X * wt - xt), sp.expand(Y * wt - yt), T)) == poly(c)  # rational
    assert np.allclose(pc.tangent_cone(c, (0, 0)), example.results["tangent_cone"])
    assert pc.classify_double_point(c, (0, 0)) == "cusp"  # one double tangent: the test cannot tell a tacnode
    # At infinity: (X, Y, W) -> with Y = 1 the curve is x⁴ - 4x² - w², an acnode.
    assert pc.classify_double_point([[0, 0, -1], [0, 0, 0], [-4, 0, 0], [0, 0, 0], [1, 0, 0]], (0, 0)) == "acnode"
    assert pc.singular_points(c).tolist() == [[0.0, 0.0]]  # no other finite singular point
    tacnode, acnode = example.results["deltas"]
    assert (4 - 1) * (4 - 2) // 2 - tacnode - acnode == example.results["genus"] == 0


def test_real_roots_of_a_resultant_without_real_points():
    circles = notes_example("19.disjoint_circles")
    f, h = circles.args("f", "h")
    assert np.allclose(pc.curve_resultant(f, h), circles.results["y_resultant"])  # (6x - 9)²
    assert pc.implicit_intersections(f, h).shape == (0, 2)
    assert sp.solve([poly(f), poly(h)], [X, Y], dict=True) == [
        {X: sp.Rational(3, 2), Y: -sp.sqrt(5) * sp.I / 2}, {X: sp.Rational(3, 2), Y: sp.sqrt(5) * sp.I / 2}]
    asymptote = notes_example("19.asymptote")
    assert np.allclose(pc.curve_discriminant(asymptote.inputs["c"]), asymptote.results["discriminant"])  # x


def test_the_adjoint_conics_parametrize_the_quartic_with_three_double_points():
    example = notes_example("19.adjoint_quartic")
    c = example.inputs["c"]
    f = poly(c)
    assert np.allclose(pc.singular_points(c), example.inputs["double_points"][[2, 1, 0]])
    conics = [poly(example.results[name]) for name in ("conic_a", "conic_b")]
    for px, py in [(2, 0), (1, sp.sqrt(2)), (1, -sp.sqrt(2)), (0, 0)]:
        assert all(q.subs({X: px, Y: py}) == 0 for q in conics)
    pencil = conics[0] - 2 * T * conics[1]
    assert sp.factor(sp.resultant(f, pencil, Y)) == sp.sympify(example.results["resultant_factors"], {"x": X, "t": T})
    xt = sum(int(v) * T**k for k, v in enumerate(example.results["x"]))
    yt = sum(int(v) * T**k for k, v in enumerate(example.results["y"]))
    assert sp.expand(f.subs({X: xt, Y: yt}, simultaneous=True)) == 0
    assert sp.expand(pencil.subs({X: xt, Y: yt}, simultaneous=True)) == 0
    for ts, point in zip(example.results["double_point_parameters"], example.inputs["double_points"][:2]):
        for value in ts:
            assert np.allclose([P.polyval(value, example.results["x"]), P.polyval(value, example.results["y"])], point)


def test_the_functions_the_chapter_shows_read_without_private_helpers():
    import inspect
    import re

    for function in (pc.classify_double_point, pc.parametrize_by_pencil, pc.conic_through_points):
        body = re.sub(r"#.*", "", inspect.getsource(function).split('"""')[-1])  # the code, without comments
        assert not re.search(r"(?<![\w.])_[a-z]\w*\(", body), function.__name__

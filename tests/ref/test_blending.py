"""Unit tests of cagd_ref.blending: blending functions, the cubic forms and their properties (chapter 5)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import Polynomial
from scipy.interpolate import BPoly, CubicHermiteSpline
from scipy.spatial import ConvexHull

from cagd_course.examples import notes_example
from cagd_ref import blending as bl
from cagd_ref import blending_properties as bp
from cagd_ref.bezier import bernstein, de_casteljau, evaluate, hodograph

T = np.linspace(0, 1, 41)
CUBIC = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]])
RATIONAL = notes_example("05.rational_example")
HISTORICAL = notes_example("05.historical_forms")

# Each set of the chapter with the properties the notes (and the mathematics) give it; the tests below check
# these against the notes' own verdicts (the rational example, and the summary of the three historical forms).
EXPECTED = {
    "bezier": dict(coordinate_independence=True, convex_hull=True, symmetry=True, variation_diminishing=True,
                   linear_independence=True, endpoint_interpolation=True),
    "timmer": dict(coordinate_independence=True, convex_hull=False, symmetry=True, variation_diminishing=False,
                   linear_independence=True, endpoint_interpolation=True),
    "ball": dict(coordinate_independence=True, convex_hull=True, symmetry=True, variation_diminishing=True,
                 linear_independence=True, endpoint_interpolation=True),
    "overhauser": dict(coordinate_independence=True, convex_hull=False, symmetry=True, variation_diminishing=False,
                       linear_independence=True, endpoint_interpolation=False),
    "rational_example": dict(coordinate_independence=True, convex_hull=True, symmetry=False, variation_diminishing=True,
                             linear_independence=True, endpoint_interpolation=True),
}
NUMERIC = {**bl.FORMS, "rational_example": bl.rational_example_basis}


def random_points(seed: int, count: int = 4, dim: int = 2) -> np.ndarray:
    return np.random.default_rng(seed).uniform(-5, 5, size=(count, dim))


def test_every_public_name_is_tested():
    tested = {
        "Verdict", "PROPERTIES", "FORMS", "bezier_basis", "timmer_basis", "ball_basis", "overhauser_basis",
        "rational_example_basis", "blend", "overhauser_point", "conversion_matrix", "to_bezier", "from_bezier",
        "timmer_to_bezier",
        "ball_to_bezier", "overhauser_to_bezier", "line_crossings", "convex_hull", "distance_outside_hull",
        "check_properties", "symbolic_basis", "symbolic_properties", "POWER_COEFFICIENTS", "basis_values",
        "variation_diminishing", "exact_minimum", "catmull_rom_parameters", "catmull_rom_point", "sign_changes",
        "crossing_counts",
    }
    assert set(bl.__all__) | set(bp.__all__) == tested


# --- the blending functions (Notes §5.1-§5.3) --------------------------------------------


def test_timmer_basis_is_the_notes_formula_and_its_derivative():
    values = bl.timmer_basis(T)
    factored = np.column_stack(
        [(1 - T) ** 2 * (1 - 2 * T), 4 * T * (1 - T) ** 2, 4 * T**2 * (1 - T), T**2 * (2 * T - 1)]
    )
    np.testing.assert_allclose(values, factored, atol=1e-14)
    # The notes differentiate the basis: Q'(t) = (-6t²+10t-4) Q0 + (12t²-16t+4) Q1 + (-12t²+8t) Q2 + (6t²-2t) Q3.
    notes_derivative = notes_example("05.timmer_to_bezier").results["derivative"]
    for i, coefficients in enumerate(notes_derivative):
        fitted = Polynomial.fit(T, values[:, i], 3).convert()
        np.testing.assert_allclose(fitted.deriv().coef, coefficients, atol=1e-9)


def test_timmer_passes_through_the_midpoint_of_the_middle_leg():
    midpoint = notes_example("05.timmer_midpoint")
    np.testing.assert_allclose(bl.timmer_basis(midpoint.inputs["t"]), midpoint.results["basis"], atol=1e-15)
    np.testing.assert_allclose(bl.blend(bl.timmer_basis, CUBIC, midpoint.inputs["t"]), (CUBIC[1] + CUBIC[2]) / 2)


def test_ball_basis_is_the_notes_formula():
    factored = np.column_stack([(1 - T) ** 2, 2 * T * (1 - T) ** 2, 2 * T**2 * (1 - T), T**2])
    np.testing.assert_allclose(bl.ball_basis(T), factored, atol=1e-14)
    np.testing.assert_allclose(bl.ball_basis(0.5), [0.25] * 4)


def test_ball_with_equal_middle_points_is_the_quadratic_bezier_curve():
    # The notes: P1 = P2 turns Ball's cubic into the quadratic with control points P0, P1, P3.
    p = np.array([[0.0, 0.0], [2.0, 3.0], [2.0, 3.0], [5.0, 1.0]])
    np.testing.assert_allclose(bl.blend(bl.ball_basis, p, T), de_casteljau(p[[0, 1, 3]], T), atol=1e-13)
    # The notes' formulas: f0 = (1-t)², f3 = t², and the merged middle functions f1 + f2 = 2t(1-t).
    quadratic = notes_example("05.ball_quadratic_case").results
    table = bl.POWER_COEFFICIENTS["ball"]
    np.testing.assert_allclose(table[:, [0, 3]].T, quadratic["end_functions"])
    np.testing.assert_allclose(table[:, 1] + table[:, 2], quadratic["merged_middle"])


def test_overhauser_basis_is_the_uniform_catmull_rom_segment():
    factored = 0.5 * np.column_stack(
        [-T * (1 - T) ** 2, 2 - 5 * T**2 + 3 * T**3, T + 4 * T**2 - 3 * T**3, -(T**2) * (1 - T)]
    )
    np.testing.assert_allclose(bl.overhauser_basis(T), factored, atol=1e-14)
    ends = notes_example("05.overhauser_tangents").results
    np.testing.assert_allclose(bl.overhauser_basis(np.array([0.0, 1.0])), [ends["start"], ends["end"]], atol=1e-15)


def test_overhauser_blends_two_parabolas():
    # Overhauser's construction: the parabola through P0, P1, P2 (at -1, 0, 1) and the one through
    # P1, P2, P3 (at 0, 1, 2), blended linearly over the middle span, is the Catmull-Rom segment.
    p = random_points(3)
    left = np.polynomial.polynomial.polyfit([-1, 0, 1], p[:3], 2)
    right = np.polynomial.polynomial.polyfit([0, 1, 2], p[1:], 2)
    polyval = np.polynomial.polynomial.polyval
    blended = (1 - T)[:, None] * polyval(T, left).T + T[:, None] * polyval(T, right).T
    np.testing.assert_allclose(bl.blend(bl.overhauser_basis, p, T), blended, atol=1e-12)


@pytest.mark.parametrize("degree", [0, 1, 3, 6])
def test_bezier_basis_is_the_bernstein_polynomials(degree):
    values = bl.bezier_basis(T, degree)
    assert values.shape == (len(T), degree + 1)
    for i in range(degree + 1):
        np.testing.assert_allclose(values[:, i], bernstein(i, degree, T))
    assert bl.bezier_basis(0.25).shape == (4,)


def test_rational_example_is_a_rational_quadratic_with_weights_1_1_2():
    values = bl.rational_example_basis(T)
    expected = np.column_stack([T**2 - 2 * T + 1, 2 * T - 2 * T**2, 2 * T**2]) / (T**2 + 1)[:, None]
    np.testing.assert_allclose(values, expected, atol=1e-15)
    p = random_points(7, 3)
    np.testing.assert_allclose(bl.blend(bl.rational_example_basis, p, T), evaluate(p, T, weights=[1, 1, 2]), atol=1e-12)
    # Defined for every real t; the notes' factorisations make the signs visible.
    wide = np.linspace(-3, 3, 13)
    np.testing.assert_allclose(bl.rational_example_basis(wide)[:, 0], (wide - 1) ** 2 / (wide**2 + 1))


def test_rational_example_linear_independence_system_of_the_notes():
    # c0 (t²-2t+1) + c1 (2t-2t²) + c2 (2t²) ≡ 0 gives c0 - 2c1 + 2c2 = 0, -2c0 + 2c1 = 0, c0 = 0.
    system = RATIONAL.results["independence_system"]
    assert np.linalg.matrix_rank(system) == 3
    denominator = Polynomial(RATIONAL.inputs["denominator"])
    numerators = bl.rational_example_basis(T) * denominator(T)[:, None]
    for column, row, notes_numerator in zip(numerators.T, system.T, RATIONAL.inputs["numerators"]):
        np.testing.assert_allclose(Polynomial.fit(T, column, 2).convert().coef, row[::-1], atol=1e-9)
        np.testing.assert_allclose(row[::-1], notes_numerator)
    np.testing.assert_allclose(RATIONAL.inputs["numerators"].sum(axis=0), RATIONAL.results["numerator_sum"])
    np.testing.assert_allclose(bl.rational_example_basis(np.array([0.0, 1.0])),
                               [RATIONAL.results["at_start"], RATIONAL.results["at_end"]], atol=1e-15)


# --- blend and the Overhauser curve -------------------------------------------------------


def test_blend_shapes_and_dimensions():
    p = random_points(1, 4, 3)
    assert bl.blend(bl.timmer_basis, p, 0.2).shape == (3,)
    assert bl.blend(bl.timmer_basis, p, T).shape == (len(T), 3)
    np.testing.assert_allclose(bl.blend(bl.bezier_basis, p, T), de_casteljau(p, T), atol=1e-13)


def test_overhauser_curve_interpolates_and_matches_a_hermite_spline():
    p = random_points(11, 7)
    t = np.linspace(0, 4, 81)
    curve = bl.overhauser_point(p, t)
    assert curve.shape == (81, 2)
    np.testing.assert_allclose(bl.overhauser_point(p, np.arange(5.0)), p[1:6], atol=1e-13)
    # Peer: SciPy's cubic Hermite spline through P1..P5 with the Catmull-Rom tangents (P_i+1 - P_i-1)/2.
    tangents = (p[2:] - p[:-2]) / 2
    peer = CubicHermiteSpline(np.arange(5.0), p[1:6], tangents)
    np.testing.assert_allclose(curve, peer(t), atol=1e-12)
    assert bl.overhauser_point(p, 2.5).shape == (2,)


TANGENTS = notes_example("05.overhauser_tangents").results


def test_overhauser_end_tangents_and_continuity():
    p = random_points(5, 6)
    segments = bl.overhauser_to_bezier(p)
    assert segments.shape == (3, 4, 2)
    for j, segment in enumerate(segments):
        velocity = hodograph(segment)
        # The notes: P'(0) = (P2 - P0)/2 and P'(1) = (P3 - P1)/2 for each segment's four points.
        np.testing.assert_allclose(de_casteljau(velocity, 0.0), TANGENTS["start_tangent"] @ p[j : j + 4], atol=1e-14)
        np.testing.assert_allclose(de_casteljau(velocity, 1.0), TANGENTS["end_tangent"] @ p[j : j + 4], atol=1e-14)
    # C1 at the joints (same point and velocity), but in general not C2.
    for first, second in zip(segments, segments[1:]):
        np.testing.assert_allclose(first[-1], second[0])
        np.testing.assert_allclose(de_casteljau(hodograph(first), 1.0), de_casteljau(hodograph(second), 0.0))
        jump = de_casteljau(hodograph(hodograph(first)), 1.0) - de_casteljau(hodograph(hodograph(second)), 0.0)
        assert np.linalg.norm(jump) > 1e-3


def test_overhauser_segments_trace_the_global_curve():
    p = random_points(8, 6, 3)
    for j, segment in enumerate(bl.overhauser_to_bezier(p)):
        np.testing.assert_allclose(de_casteljau(segment, T), bl.overhauser_point(p, j + T), atol=1e-12)


# --- conversions to Bézier form (Notes §5.1 Example, §5.2, §5.3) -------------------------------


@pytest.mark.parametrize("form", ["bezier", "timmer", "ball", "overhauser"])
@pytest.mark.parametrize("dim", [1, 2, 3])
def test_each_form_equals_its_bezier_conversion(form, dim):
    q = random_points(dim, 4, dim)
    bezier_points = bl.to_bezier(form, q)
    np.testing.assert_allclose(de_casteljau(bezier_points, T), bl.blend(bl.FORMS[form], q, T), atol=1e-12)
    np.testing.assert_allclose(bl.from_bezier(form, bezier_points), q, atol=1e-12)


def test_timmer_conversion_follows_the_notes_example():
    q = random_points(21)
    p = bl.timmer_to_bezier(q)
    np.testing.assert_allclose(p[[0, 3]], q[[0, 3]])
    # The notes' end-derivative conditions 3(P1 - P0) = 4(Q1 - Q0) and 3(P3 - P2) = 4(Q3 - Q2) ...
    np.testing.assert_allclose(3 * (p[1] - p[0]), 4 * (q[1] - q[0]))
    np.testing.assert_allclose(3 * (p[3] - p[2]), 4 * (q[3] - q[2]))
    # ... and their Bézier-to-Timmer form Q1 = (P0 + 3 P1)/4, Q2 = (P3 + 3 P2)/4.
    back = bl.from_bezier("timmer", p)
    np.testing.assert_allclose(back[1], (p[0] + 3 * p[1]) / 4)
    np.testing.assert_allclose(back[2], (p[3] + 3 * p[2]) / 4)
    np.testing.assert_allclose(back, notes_example("05.timmer_to_bezier").results["bezier_to_timmer"] @ p, atol=1e-14)
    arch = notes_example("05.timmer_arch")
    np.testing.assert_allclose(bl.timmer_to_bezier(*arch.args("points")), arch.results["bezier_points"], atol=1e-14)


def test_conversion_matrices_hold_bernstein_coefficients():
    np.testing.assert_array_equal(bl.conversion_matrix("bezier"), np.eye(4))
    conversion = notes_example("05.timmer_to_bezier").results
    np.testing.assert_allclose(bl.conversion_matrix("timmer"), conversion["timmer_to_bezier"], atol=1e-15)
    np.testing.assert_allclose(conversion["timmer_to_bezier"] @ conversion["bezier_to_timmer"], np.eye(4), atol=1e-15)
    for form, basis in bl.FORMS.items():
        # Peer: SciPy's Bernstein-form polynomials with these coefficients are the form's functions.
        np.testing.assert_allclose(BPoly(bl.conversion_matrix(form)[:, None, :], [0, 1])(T), basis(T), atol=1e-14)


def test_ball_conversion_is_corner_cutting():
    q = random_points(4)
    p = bl.ball_to_bezier(q)
    np.testing.assert_allclose(p, [q[0], (q[0] + 2 * q[1]) / 3, (2 * q[2] + q[3]) / 3, q[3]])


def test_overhauser_segment_bezier_points():
    p = random_points(9, 5)
    segments = bl.overhauser_to_bezier(p)
    for j, segment in enumerate(segments):
        expected = [p[j + 1], p[j + 1] + (p[j + 2] - p[j]) / 6, p[j + 2] - (p[j + 3] - p[j + 1]) / 6, p[j + 2]]
        np.testing.assert_allclose(segment, expected)
    np.testing.assert_allclose(segments[0], bl.to_bezier("overhauser", p[:4]))


# --- lines, crossings and hulls -----------------------------------------------------------------


def test_line_crossings_of_a_zigzag():
    zigzag = np.array([[0.0, -1.0], [1.0, 1.0], [2.0, -1.0], [3.0, 1.0]])
    crossings = bp.line_crossings(zigzag, [0.0, 2.0, 0.0])  # the x-axis, unnormalised
    np.testing.assert_allclose(crossings, [[0.5, 0.0], [1.5, 0.0], [2.5, 0.0]])
    assert bp.line_crossings(zigzag, [0.0, 1.0, -5.0]).shape == (0, 2)  # y = 5 misses it


def test_touching_is_not_crossing_but_passing_through_a_vertex_is():
    touch = np.array([[0.0, 1.0], [1.0, 0.0], [2.0, 1.0]])
    assert len(bp.line_crossings(touch, [0, 1, 0])) == 0
    through = np.array([[0.0, 1.0], [1.0, 0.0], [2.0, 0.0], [3.0, -1.0]])
    np.testing.assert_allclose(bp.line_crossings(through, [0, 1, 0]), [[1.0, 0.0]])


def test_sampled_curve_crossings_never_exceed_the_true_roots():
    # Peer: the roots of the polynomial distance y(t) of an explicit Bézier cubic, by numpy.
    rng = np.random.default_rng(0)
    for _ in range(20):
        p = np.column_stack([np.arange(4.0), rng.normal(size=4)])
        samples = de_casteljau(p, np.linspace(0, 1, 400))
        roots = Polynomial.fit(T, de_casteljau(p, T)[:, 1], 3).convert().roots()
        inside = roots[(abs(roots.imag) < 1e-9) & (roots.real > 0) & (roots.real < 1)]
        crossings = bp.line_crossings(samples, [0, 1, 0])
        assert len(crossings) <= len(inside)
        np.testing.assert_allclose(crossings[:, 1], 0.0, atol=1e-12)


def test_convex_hull_matches_scipy():
    rng = np.random.default_rng(4)
    for count in (3, 4, 10, 40):
        pts = rng.normal(size=(count, 2))
        hull = bp.convex_hull(pts)
        peer = pts[ConvexHull(pts).vertices]
        assert {tuple(v) for v in hull} == {tuple(v) for v in peer}
        signed_area = np.sum(hull[:, 0] * np.roll(hull[:, 1], -1) - np.roll(hull[:, 0], -1) * hull[:, 1]) / 2
        assert signed_area == pytest.approx(ConvexHull(pts).volume)  # counter-clockwise


def test_convex_hull_degenerate_cases():
    np.testing.assert_allclose(bp.convex_hull([[0, 0], [1, 1], [2, 2], [0.5, 0.5]]), [[0, 0], [2, 2]])
    np.testing.assert_allclose(bp.convex_hull([[1, 2], [1, 2]]), [[1, 2]])


def test_distance_outside_hull():
    square = [[0, 0], [2, 0], [2, 2], [0, 2], [1, 1]]
    query = [[1, 1], [0, 0], [3, 1], [3, 3], [-1, 1]]
    np.testing.assert_allclose(bp.distance_outside_hull(square, query), [0, 0, 1, np.sqrt(2), 1])
    segment = [[0, 0], [2, 0]]
    np.testing.assert_allclose(bp.distance_outside_hull(segment, [[1, 0], [1, 2]]), [0, 2])


def test_timmer_and_overhauser_leave_the_hull_but_ball_and_bezier_do_not():
    rng = np.random.default_rng(6)
    escapes = {form: 0.0 for form in bl.FORMS}
    for _ in range(30):
        q = rng.uniform(-3, 3, (4, 2))
        for form, basis in bl.FORMS.items():
            escapes[form] = max(escapes[form], bp.distance_outside_hull(q, bl.blend(basis, q, T)).max())
    assert escapes["bezier"] < 1e-12 and escapes["ball"] < 1e-12
    assert escapes["timmer"] > 0.05 and escapes["overhauser"] > 0.05


# --- the property checker (Notes §5) ------------------------------------------------------------


@pytest.mark.parametrize("name", EXPECTED)
def test_check_properties_of_the_chapters_sets(name):
    report = bp.check_properties(NUMERIC[name])
    assert tuple(report) == bp.PROPERTIES
    assert all(isinstance(v, bp.Verdict) and v.reason for v in report.values())
    assert {k: v.holds for k, v in report.items()} == EXPECTED[name]


def test_expected_properties_agree_with_the_notes():
    # The notes decide every property of the rational example except variation diminishing ("not attempted").
    notes = RATIONAL.results["properties"]
    decided = {k: v for k, v in notes.items() if isinstance(v, bool)}
    assert set(notes) == set(bp.PROPERTIES) and set(notes) - set(decided) == {"variation_diminishing"}
    assert {k: EXPECTED["rational_example"][k] for k in decided} == decided
    # ... and of the three historical forms: all coordinate system independent and symmetric, only Ball's in the hull.
    for prop, verdicts in HISTORICAL.results.items():
        assert {form: EXPECTED[form][prop] for form in verdicts} == verdicts


def test_the_notes_variation_diminishing_figure():
    # A line meets the polygon p = 5 times and the curve c = 3 times: c = p - 2j, j = 1.
    figure = notes_example("05.variation_diminishing")
    polygon, line = figure.args("polygon", "line")
    p = len(bp.line_crossings(polygon, line))
    c = len(bp.line_crossings(de_casteljau(polygon, np.linspace(0, 1, 801)), line))
    assert (p, c, (p - c) // 2) == tuple(figure.results[k] for k in ("polygon_crossings", "curve_crossings", "j"))


def test_timmer_violates_variation_diminishing_for_a_flat_polygon():
    # Three points just above the x-axis and one high above: the polygon never meets the axis,
    # but Timmer's f3 < 0 near t = 1/3 drags the curve below it and back.
    q = np.array([[0.0, 0.01], [1.0, 0.01], [2.0, 0.01], [3.0, 1.0]])
    assert len(bp.line_crossings(q, [0, 1, 0])) == 0
    assert len(bp.line_crossings(bl.blend(bl.timmer_basis, q, T), [0, 1, 0])) == 2
    assert len(bp.line_crossings(bl.blend(bl.bezier_basis, q, T), [0, 1, 0])) == 0


def test_check_properties_finds_failures_in_made_up_sets():
    power = lambda t: np.column_stack([np.ones_like(t), t, t**2])  # noqa: E731
    report = bp.check_properties(power)
    assert not report["coordinate_independence"].holds and not report["convex_hull"].holds
    assert "sum to 1" in report["convex_hull"].reason
    assert report["linear_independence"].holds and not report["endpoint_interpolation"].holds
    twins = lambda t: np.column_stack([(1 - t) / 2, (1 - t) / 2, t])  # noqa: E731
    report = bp.check_properties(twins)
    assert report["coordinate_independence"].holds and not report["linear_independence"].holds
    assert "rank 2" in report["linear_independence"].reason


def test_check_properties_on_another_domain():
    stretched = lambda t: bl.bezier_basis((t - 2) / 3, 5)  # noqa: E731
    report = bp.check_properties(stretched, domain=(2, 5), probes=90)
    assert all(v.holds for v in report.values())
    assert not bp.check_properties(stretched, domain=(2, 6), probes=90)["symmetry"].holds


@pytest.mark.parametrize("name", EXPECTED)
def test_the_variation_diminishing_probe_is_the_one_check_properties_runs(name):
    values = NUMERIC[name](np.linspace(0, 1, 257))
    for seed in (0, 5):
        probe = bp.variation_diminishing(values, probes=200, seed=seed)
        assert probe == bp.check_properties(NUMERIC[name], probes=200, seed=seed)["variation_diminishing"]
        assert probe.holds == EXPECTED[name]["variation_diminishing"]


@pytest.mark.parametrize("name", EXPECTED)
def test_exact_minimum_matches_dense_sampling(name):
    t = sp.Symbol("t")
    dense = np.linspace(0, 1, 20001)
    minima = [float(bp.exact_minimum(f, t)) for f in bp.symbolic_basis(name, t)]
    np.testing.assert_allclose(minima, NUMERIC[name](dense).min(axis=0), atol=1e-8)
    # On another domain the minimum moves: (t - 2)² on [0, 1] is smallest at t = 1, on [1, 3] at t = 2.
    assert bp.exact_minimum((t - 2) ** 2, t) == 1 and bp.exact_minimum((t - 2) ** 2, t, domain=(1, 3)) == 0


def test_check_properties_is_reproducible():
    assert bp.check_properties(bl.timmer_basis, seed=3) == bp.check_properties(bl.timmer_basis, seed=3)


# --- exact checks with SymPy ----------------------------------------------------------------------


@pytest.mark.parametrize("name", EXPECTED)
def test_symbolic_basis_agrees_with_the_numerical_one(name):
    t = sp.Symbol("t")
    functions = sp.lambdify(t, bp.symbolic_basis(name, t), "numpy")
    values = np.column_stack([np.broadcast_to(v, T.shape) for v in functions(T)])
    np.testing.assert_allclose(values, NUMERIC[name](T), atol=1e-14)


@pytest.mark.parametrize("name", EXPECTED)
def test_symbolic_properties_agree_with_the_notes(name):
    t = sp.Symbol("t")
    report = bp.symbolic_properties(bp.symbolic_basis(name, t), t)
    expected = dict(EXPECTED[name], variation_diminishing=None)
    assert {k: v.holds for k, v in report.items()} == expected


def test_symbolic_details_of_the_rational_example():
    t = sp.Symbol("t")
    report = bp.symbolic_properties(bp.symbolic_basis("rational_example"), sp.Symbol("t"))
    assert "t**2 + 1" in report["linear_independence"].reason and "rank 3" in report["linear_independence"].reason
    timmer = bp.symbolic_properties(bp.symbolic_basis("timmer", t), t)
    assert "-1/27" in timmer["convex_hull"].reason  # the exact minimum of f0 (and f3)
    dip = -sp.Rational(1, 27)
    assert [bp.exact_minimum(f, t) for f in bp.symbolic_basis("timmer", t)] == [dip, 0, 0, dip]
    # A dependent set and a set on another domain.
    assert not bp.symbolic_properties([1 - t, t, 2 - 2 * t], t)["linear_independence"].holds
    shifted = bp.symbolic_properties([(3 - t) ** 2 / 4, (t - 1) * (3 - t) / 2, (t - 1) ** 2 / 4], t, domain=(1, 3))
    assert all(v.holds for k, v in shifted.items() if k != "variation_diminishing")


# --- Catmull-Rom curves with parameters (the course's extension of Notes §5.3) -------------------------

ROW = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 2.0], [4.0, 0.0], [5.0, 2.0]])
UNEVEN = np.array([[0.0, 0.0], [0.2, 1.0], [0.4, 1.1], [4.0, 1.0], [4.5, 0.0], [6.0, -2.0]])


def neville(ts, points, t):
    """The interpolating polynomial through points (m, d) at ts (m,), at the number t: the textbook recursion."""
    level = [np.asarray(p, float) for p in points]
    for r in range(1, len(ts)):
        level = [((ts[i + r] - t) * level[i] + (t - ts[i]) * level[i + 1]) / (ts[i + r] - ts[i])
                 for i in range(len(level) - 1)]
    return level[0]


def test_catmull_rom_parameters_uniform_centripetal_chord():
    np.testing.assert_allclose(bl.catmull_rom_parameters(ROW, alpha=0), np.arange(6.0))
    chords = np.linalg.norm(np.diff(UNEVEN, axis=0), axis=1)
    np.testing.assert_allclose(bl.catmull_rom_parameters(UNEVEN, alpha=1), np.r_[0, np.cumsum(chords)])
    np.testing.assert_allclose(bl.catmull_rom_parameters(UNEVEN), np.r_[0, np.cumsum(np.sqrt(chords))])
    # Repeated points are fine for uniform parameters, which do not look at the points.
    np.testing.assert_allclose(bl.catmull_rom_parameters([(0, 0), (0, 0), (1, 1)], alpha=0), [0, 1, 2])


def test_catmull_rom_with_uniform_parameters_is_the_overhauser_curve():
    ts = np.linspace(0, 3, 61)
    np.testing.assert_allclose(bl.catmull_rom_point(ROW, np.arange(6.0) - 1, ts), bl.overhauser_point(ROW, ts),
                               atol=1e-13)
    # Any affine change of the parameters gives the same points at the corresponding t.
    np.testing.assert_allclose(bl.catmull_rom_point(ROW, 2.5 * np.arange(6.0) + 7, 2.5 * (ts + 1) + 7),
                               bl.overhauser_point(ROW, ts), atol=1e-12)


@pytest.mark.parametrize("alpha", [0.0, 0.5, 1.0])
def test_catmull_rom_blends_the_two_parabolas_of_each_segment(alpha):
    knots = bl.catmull_rom_parameters(UNEVEN, alpha)
    for j in range(len(UNEVEN) - 3):
        t0, t1, t2, t3 = knots[j : j + 4]
        for t in np.linspace(t1, t2, 7):
            left = neville(knots[j : j + 3], UNEVEN[j : j + 3], t)
            right = neville(knots[j + 1 : j + 4], UNEVEN[j + 1 : j + 4], t)
            expected = ((t2 - t) * left + (t - t1) * right) / (t2 - t1)
            np.testing.assert_allclose(bl.catmull_rom_point(UNEVEN, knots, t), expected, atol=1e-12)


@pytest.mark.parametrize("alpha", [0.0, 0.5, 1.0])
def test_catmull_rom_interpolates_and_is_c1_with_the_parabola_tangent(alpha):
    knots = bl.catmull_rom_parameters(UNEVEN, alpha)
    np.testing.assert_allclose(bl.catmull_rom_point(UNEVEN, knots, knots[1:-1]), UNEVEN[1:-1], atol=1e-12)

    def tangent(i):  # the derivative at t_i of the parabola through points i-1, i, i+1
        d0, d1 = knots[i] - knots[i - 1], knots[i + 1] - knots[i]
        v0, v1 = (UNEVEN[i] - UNEVEN[i - 1]) / d0, (UNEVEN[i + 1] - UNEVEN[i]) / d1
        return (d1 * v0 + d0 * v1) / (d0 + d1)

    for j in range(len(UNEVEN) - 3):  # each segment is a cubic in t: fit it exactly, differentiate at both ends
        t1, t2 = knots[j + 1], knots[j + 2]
        samples = np.linspace(t1, t2, 4)
        values = bl.catmull_rom_point(UNEVEN, knots, samples)
        slopes = [[Polynomial.fit(samples, values[:, x], 3).deriv()(end) for x in (0, 1)] for end in (t1, t2)]
        np.testing.assert_allclose(slopes, [tangent(j + 1), tangent(j + 2)], rtol=1e-8, atol=1e-8)


def test_catmull_rom_shapes_and_the_last_parameter():
    knots = np.array([0.0, 1.0, 3.0, 4.0, 4.5, 6.0])
    assert bl.catmull_rom_point(ROW, knots, 2.0).shape == (2,)
    assert bl.catmull_rom_point(ROW, knots, [2.0]).shape == (1, 2)
    assert bl.catmull_rom_point(ROW, knots, np.array([])).shape == (0, 2)
    np.testing.assert_allclose(bl.catmull_rom_point(ROW, knots, 4.5), ROW[4])  # the very end: last segment
    space = np.column_stack([ROW, np.arange(6.0)])
    np.testing.assert_allclose(bl.catmull_rom_point(space, knots, [1.0, 3.0])[:, 2], [1.0, 2.0])


# --- counting crossings (Notes §5, property 4) -----------------------------------------------------


def test_sign_changes_skip_zeros():
    assert bl.sign_changes([1.0, 0.0, -1.0]) == 1
    assert bl.sign_changes([1.0, 0.0, 0.0, 1.0]) == 0
    assert bl.sign_changes([0.0, -1.0, 2.0, -3.0, 0.0]) == 2
    assert bl.sign_changes([1e-13, -1.0]) == 0
    assert bl.sign_changes([]) == 0


def test_crossing_counts_of_the_notes_figure_and_of_timmers_flat_polygon():
    example = notes_example("05.variation_diminishing")
    polygon, line = example.args("polygon", "line")
    p, c = bl.crossing_counts(bl.bezier_basis(np.linspace(0, 1, 401), degree=5), polygon, line)
    assert (p, c) == (example.results["polygon_crossings"], example.results["curve_crossings"])
    flat = [(0, 0), (1.5, 0), (3, 0), (4, 3)]
    assert bl.crossing_counts(bl.timmer_basis(np.linspace(0, 1, 401)), flat, (0, 1, 0.05)) == (0, 2)
    assert bl.crossing_counts(bl.bezier_basis(np.linspace(0, 1, 401)), flat, (0, 1, 0.05)) == (0, 0)


@pytest.mark.parametrize("seed", range(5))
def test_crossing_counts_agree_with_line_crossings(seed):
    rng = np.random.default_rng(seed)
    polygon = rng.uniform(-3, 3, (5, 2))
    line = np.append(rng.normal(size=2), rng.normal())
    values = bl.bezier_basis(np.linspace(0, 1, 301), degree=4)
    p, c = bl.crossing_counts(values, polygon, line)
    assert p == len(bp.line_crossings(polygon, line)) and c == len(bp.line_crossings(values @ polygon, line))
    assert c <= p and (p - c) % 2 == 0  # the Bézier curve: c = p - 2j


# --- bad input and untouched inputs ---------------------------------------------------------------


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: bl.timmer_basis([[0.1, 0.2]]), ValueError, "t"),
        (lambda: bl.ball_basis("half"), TypeError, "t"),
        (lambda: bl.rational_example_basis([[0.5]]), ValueError, "t"),
        (lambda: bl.bezier_basis(0.5, degree=-1), ValueError, "degree"),
        (lambda: bl.blend("timmer", CUBIC, 0.5), TypeError, "basis"),
        (lambda: bl.blend(bl.timmer_basis, CUBIC[:3], 0.5), ValueError, "points"),
        (lambda: bl.blend(lambda t: np.ones(len(t)), CUBIC, T), ValueError, "basis"),
        (lambda: bl.blend(lambda t: np.full((len(t), 4), np.nan), CUBIC, T), ValueError, "basis"),
        (lambda: bl.overhauser_point(CUBIC[:3], 0.5), ValueError, "points"),
        (lambda: bl.overhauser_point(CUBIC, 1.5), ValueError, "t"),
        (lambda: bl.overhauser_point(CUBIC, [-0.1, 0.5]), ValueError, "t"),
        (lambda: bl.overhauser_point([1.0, 2.0, 3.0, 4.0], 0.5), ValueError, "points"),
        (lambda: bl.to_bezier("hermite", CUBIC), ValueError, "form"),
        (lambda: bl.conversion_matrix("rational_example"), ValueError, "form"),
        (lambda: bl.from_bezier("ball", CUBIC[:3]), ValueError, "points"),
        (lambda: bl.timmer_to_bezier(np.vstack([CUBIC, CUBIC[:1]])), ValueError, "points"),
        (lambda: bl.overhauser_to_bezier(CUBIC[:3]), ValueError, "points"),
        (lambda: bp.line_crossings(CUBIC, [0, 0, 1]), ValueError, "line"),
        (lambda: bp.line_crossings(np.zeros((3, 3)), [0, 1, 0]), ValueError, "polyline"),
        (lambda: bp.convex_hull(np.zeros((3, 3))), ValueError, "points"),
        (lambda: bp.distance_outside_hull(CUBIC, [1.0, 2.0]), ValueError, "query"),
        (lambda: bp.check_properties(bl.timmer_basis, domain=(1, 0)), ValueError, "domain"),
        (lambda: bp.check_properties(bl.timmer_basis, samples=1), ValueError, "samples"),
        (lambda: bp.check_properties(bl.timmer_basis, tol=-1.0), ValueError, "tol"),
        (lambda: bp.check_properties([1, 2]), TypeError, "basis"),
        (lambda: bp.symbolic_basis("hermite"), ValueError, "form"),
        (lambda: bp.symbolic_properties([sp.Symbol("t")], "t"), TypeError, "t"),
        (lambda: bp.symbolic_properties([], sp.Symbol("t")), ValueError, "functions"),
        (lambda: bp.symbolic_properties([sp.sin(sp.Symbol("t"))], sp.Symbol("t")), ValueError, "functions"),
        (lambda: bp.symbolic_properties([1 / (2 * sp.Symbol("t") - 1)], sp.Symbol("t")), ValueError, "functions"),
        (lambda: bp.variation_diminishing(bl.ball_basis(0.5)), ValueError, "values"),
        (lambda: bp.variation_diminishing(bl.ball_basis(T), probes=2), ValueError, "probes"),
        (lambda: bp.exact_minimum(sp.sin(sp.Symbol("t")), sp.Symbol("t")), ValueError, "expression"),
        (lambda: bp.exact_minimum(1 / sp.Symbol("t"), sp.Symbol("t")), ValueError, "expression"),
        (lambda: bp.exact_minimum(sp.Symbol("t"), "t"), TypeError, "t"),
        (lambda: bl.basis_values(bl.ball_basis, [[0.5]]), ValueError, "ts"),
        (lambda: bl.catmull_rom_parameters(CUBIC, alpha=2.0), ValueError, "alpha"),
        (lambda: bl.catmull_rom_parameters(CUBIC, alpha="half"), ValueError, "alpha"),
        (lambda: bl.catmull_rom_parameters([(0, 0), (0, 0), (1, 1)], alpha=0.5), ValueError, "points"),
        (lambda: bl.catmull_rom_point(CUBIC[:3], [0, 1, 2], 1.5), ValueError, "points"),
        (lambda: bl.catmull_rom_point(CUBIC, [0, 1, 2], 1.5), ValueError, "params"),
        (lambda: bl.catmull_rom_point(CUBIC, [0, 1, 1, 2], 1.0), ValueError, "params"),
        (lambda: bl.catmull_rom_point(CUBIC, [0, 2, 1, 3], 1.5), ValueError, "params"),
        (lambda: bl.catmull_rom_point(CUBIC, [0, 1, 2, 3], 2.5), ValueError, "t"),
        (lambda: bl.catmull_rom_point(CUBIC, [0, 1, 2, 3], [[1.5]]), ValueError, "t"),
        (lambda: bl.sign_changes([[1.0, -1.0]]), ValueError, "values"),
        (lambda: bl.crossing_counts(bl.ball_basis(0.5), CUBIC, [0, 1, 0]), ValueError, "values"),
        (lambda: bl.crossing_counts(bl.ball_basis(T), CUBIC[:3], [0, 1, 0]), ValueError, "points"),
        (lambda: bl.crossing_counts(bl.ball_basis(T), np.zeros((4, 3)), [0, 1, 0]), ValueError, "points"),
        (lambda: bl.crossing_counts(bl.ball_basis(T), CUBIC, [0, 0, 1]), ValueError, "line"),
        (lambda: bl.crossing_counts(bl.ball_basis(T), CUBIC, [0, 1]), ValueError, "line"),
        (lambda: bl.crossing_counts(bl.ball_basis(T), CUBIC, "y = 0"), TypeError, "line"),
    ],
)
def test_bad_input_is_rejected_with_the_arguments_name(call, error, name):
    with pytest.raises(error, match=f"^{name}"):
        call()


@pytest.mark.parametrize("form", sorted(bl.POWER_COEFFICIENTS))
def test_power_coefficient_tables_are_the_blending_functions(form):
    ts = np.linspace(0, 1, 7)
    table = bl.POWER_COEFFICIENTS[form]
    expected = np.stack([np.polynomial.polynomial.polyval(ts, table[:, i]) for i in range(4)], axis=1)
    np.testing.assert_allclose(bl.FORMS[form](ts), expected, atol=1e-14)


def test_basis_values_checks_what_a_blending_set_returns():
    ts = np.linspace(0, 1, 3)
    assert bl.basis_values(bl.ball_basis, ts).shape == (3, 4)
    with pytest.raises(TypeError, match="basis"):
        bl.basis_values("ball", ts)
    with pytest.raises(ValueError, match="basis"):
        bl.basis_values(lambda t: np.ones(len(t)), ts)

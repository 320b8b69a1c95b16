"""Unit tests of cagd_ref.bspline: B-spline curves in the notes' knot convention (chapter 6).

Every function is checked three ways: against the worked examples of the notes,
against properties (partition of unity, local support, knot insertion and
Bézier extraction keep the curve, blossoms are symmetric and multi-affine, ...),
and against scipy.interpolate.BSpline on seeded random splines of degrees 1-5
with multiple knots, converted with to_scipy.
"""

from __future__ import annotations

from math import comb

import numpy as np
import pytest
from scipy.interpolate import BSpline, insert

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import bspline as b
from cagd_ref.polynomials import horner, power_to_bernstein

DEGREES = range(1, 6)
SEEDS = range(8)

# The degree-4 Bézier curve of §6.7, over [1, 5].
QUARTIC_EXAMPLE = notes_example("06.quartic_insertion")
QUARTIC, QUARTIC_KNOTS = QUARTIC_EXAMPLE.args("points", "knots")
# The two forms of the de Boor algorithm: tuned for many parameters, and the plain teaching form.
DE_BOOR_FORMS = [pytest.param(b.de_boor, id="de_boor"), pytest.param(b.de_boor_plain, id="de_boor_plain")]


def random_spline(seed: int, n: int, dim: int = 2, zero_chance: float = 0.3):
    """Control points (c, dim) and knots (c+n-1,) with random spacing and some multiple knots (at most n-fold).

    The first and last spans of the domain have positive length, so SciPy (which
    evaluates the end of the domain on its last span, whatever its length) agrees at the ends.
    """
    rng = np.random.default_rng(1000 * n + seed)
    c = int(rng.integers(n + 1, n + 9))
    intervals = rng.uniform(0.2, 2.0, c + n - 2)
    zeros = rng.uniform(size=len(intervals)) < zero_chance
    zeros[[n - 1, c - 2]] = False
    run = 0
    for k in range(len(intervals)):
        # A run of n-1 zero intervals is an n-fold knot, the most allowed.
        run = run + 1 if zeros[k] and run < n - 1 else 0
        intervals[k] = 0.0 if run else intervals[k]
    knots = rng.uniform(-3, 3) + np.concatenate([[0.0], np.cumsum(intervals)])
    return rng.uniform(-5, 5, (c, dim)), knots


def scipy_spline(points, knots) -> BSpline:
    return BSpline(*b.to_scipy(points, knots))


def sample(knots, n, count=41):
    """Parameters across the domain, every knot in it included."""
    a, z = b.domain(knots, n)
    kn = np.asarray(knots)
    return np.unique(np.concatenate([np.linspace(a, z, count), kn[(kn >= a) & (kn <= z)]]))


def random_cases():
    return [(seed, n) for n in DEGREES for seed in SEEDS]


def test_every_public_name_is_tested():
    # Each name has at least one test below; keep this list in step with the module.
    tested = {
        "de_boor", "de_boor_plain", "de_boor_triangle", "insert_knot", "insert_knots", "bezier_segments",
        "bezier_segment_intervals", "blossom", "bezier_blossom", "power_blossom", "bspline_basis",
        "basis_matrix", "greville", "explicit_bspline", "to_scipy", "from_scipy", "degree", "domain",
        "knot_multiplicities", "continuity_at_knots", "hodograph", "derivative", "elevate",
        "polar_values", "elevated_polar_values", "bezier_end_knots", "periodic_closed",
        "circle_approximation", "combine_bezier", "checked_bspline", "checked_knots", "knot_span",
    }
    assert set(b.__all__) == tested


# --- the notes' worked examples --------------------------------------------------------------


def test_knot_insertion_example_degree_four():
    # §6.7: the quartic Bézier curve over [1, 5] is the B-spline with knots [1111 5555]; insert t = 3.
    results = QUARTIC_EXAMPLE.results
    points, knots = b.insert_knot(*QUARTIC_EXAMPLE.args("points", "knots", "t"))
    np.testing.assert_array_equal(knots, results["knots"])
    np.testing.assert_allclose(points, results["points"], atol=1e-14)
    # The new points carry the labels f(1,1,1,3), f(1,1,3,5), f(1,3,5,5), f(3,5,5,5) ...
    labels = results["new_labels"]
    np.testing.assert_allclose(b.polar_values(QUARTIC, QUARTIC_KNOTS, labels), results["points"][1:5], atol=1e-14)
    # ... and replace the points f(1,1,1,5), f(1,1,5,5), f(1,5,5,5), whose coordinates the notes state.
    np.testing.assert_allclose(b.polar_values(QUARTIC, QUARTIC_KNOTS, results["replaced"]), QUARTIC[1:4])
    assert b.degree(QUARTIC, QUARTIC_KNOTS) == 4


def test_extraction_example_knots_one_to_eight():
    # §6.3, Figure 6.2.b: a cubic with knots [1..8]; point i is P(i+1, i+2, i+3), domain [3, 6].
    example = notes_example("06.bezier_extraction")
    knots, found = example.inputs["knots"], example.results
    points = np.random.default_rng(5).uniform(-5, 5, (6, 2))
    p = lambda *args: b.blossom(points, knots, args)  # noqa: E731
    assert b.domain(knots, 3) == tuple(notes_example("06.bspline_polar_labels").results["domain"])
    np.testing.assert_allclose(p(1, 2, 3), points[0])
    np.testing.assert_allclose(p(6, 7, 8), points[5])
    # Since 3 sits at 2/3 of [1, 4], P(2,3,3) = P(1,2,3) + 2/3 (P(2,3,4) - P(1,2,3)) ...
    np.testing.assert_allclose(p(2, 3, 3), points[0] + found["helper_233"] * (points[1] - points[0]))
    # ... and 4 sits at 1/3 of [3, 6], so P(4,4,5) = P(3,4,5) + 1/3 (P(4,5,6) - P(3,4,5)); the notes print 2/3.
    np.testing.assert_allclose(p(4, 4, 5), points[2] + found["helper_445"] * (points[3] - points[2]))
    erratum = example.errata["helper_445"]
    assert erratum.correct == found["helper_445"]
    assert not np.allclose(p(4, 4, 5), points[2] + erratum.notes * (points[3] - points[2]))
    # ... and the Bézier end points are midpoints: P(3,3,3) of P(2,3,3), P(3,3,4); P(4,4,4) of P(3,4,4), P(4,4,5).
    half = found["ends"]
    np.testing.assert_allclose(p(3, 3, 3), (1 - half) * p(2, 3, 3) + half * p(3, 3, 4))
    np.testing.assert_allclose(p(4, 4, 4), (1 - half) * p(3, 4, 4) + half * p(4, 4, 5))
    segments = b.bezier_segments(points, knots)
    np.testing.assert_allclose(segments[0], b.polar_values(points, knots, found["bezier_labels"]))
    # Local control: P(5,6,7) and P(6,7,8) do not act on the segment over [3, 4].
    acting = len(found["acting_labels"])
    np.testing.assert_allclose(b.polar_values(points, knots, found["acting_labels"]), points[:acting])
    moved = points.copy()
    moved[acting:] += 10
    np.testing.assert_allclose(b.bezier_segments(moved, knots)[0], segments[0])
    np.testing.assert_array_equal(b.bezier_segment_intervals(knots, 3), [[3, 4], [4, 5], [5, 6]])


def test_insertion_example_bezier_end_conditions():
    # Figures 6.6.b-6.9: knots [0,0,0,1,3,4,4,4]; inserting 2 replaces P(0,1,3), P(1,3,4) by
    # P(0,1,2), P(1,2,3), P(2,3,4); two more 2s expose P(1,2,2), P(2,2,2), P(2,2,3).
    once, thrice = notes_example("06.knot_insertion"), notes_example("06.de_boor")
    knots, t = once.args("knots", "t")
    np.testing.assert_array_equal(knots, notes_example("06.bezier_end_conditions").inputs["knots"])
    points = np.array([[0.0, 0.0], [1.0, 3.0], [3.0, 4.0], [5.0, 3.5], [7.0, 1.0], [8.0, 0.0]])
    new_points, new_knots = b.insert_knot(points, knots, t)
    np.testing.assert_array_equal(new_knots, once.results["knots"])
    np.testing.assert_array_equal(new_points[[0, 1, 5, 6]], points[[0, 1, 4, 5]])
    np.testing.assert_allclose(new_points, b.polar_values(points, knots, once.results["labels"]))
    kept = [i for i, label in enumerate(notes_example("06.bezier_end_conditions").results["labels"].tolist())
            if label not in once.results["replaced"].tolist()]
    np.testing.assert_array_equal(kept, [0, 1, 4, 5])
    more_points, more_knots = b.insert_knots(new_points, new_knots, [t, t])
    np.testing.assert_array_equal(more_knots, thrice.results["knots"])
    np.testing.assert_allclose(more_points[4], b.de_boor(points, knots, t))
    np.testing.assert_allclose(more_points[3:6], b.polar_values(points, knots, thrice.results["exposed"]))
    # The curve starts and ends at the end control points (Bézier end conditions).
    np.testing.assert_allclose(b.de_boor(points, knots, [0.0, 4.0]), points[[0, -1]])


def test_de_boor_triangle_of_the_notes_example():
    # §6.8: the triangle at t = 2 for the knots [0,0,0,1,3,4,4,4], level by level as polar labels.
    example = notes_example("06.de_boor")
    knots, t = example.args("knots", "t")
    points = np.random.default_rng(9).uniform(-5, 5, (6, 2))
    levels, span = b.de_boor_triangle(points, knots, t)
    assert span == 3
    for r, level in enumerate(levels):
        np.testing.assert_allclose(level, b.polar_values(points, knots, example.results[f"level_{r}"]), atol=1e-12)


def test_the_notes_polar_labels_are_control_points():
    # Figures 6.2.b, 6.6, 6.11 and 6.28: control point i carries the label of knots t_i ... t_(i+n-1).
    rng = np.random.default_rng(12)
    for name in ("bspline_polar_labels", "periodic", "bezier_end_conditions", "figure_6_11", "basis_functions"):
        example = notes_example(f"06.{name}")
        knots, n, labels = example.inputs["knots"], example.inputs["degree"], example.results["labels"]
        points = rng.uniform(-5, 5, (len(labels), 2))
        assert b.degree(points, knots) == n
        for label, point in zip(labels, points):
            np.testing.assert_allclose(b.blossom(points, knots, label), point, atol=1e-12)
    # The periodic example closes up: its domain is one period and the last n points repeat the first n.
    periodic = notes_example("06.periodic")
    knots, found = periodic.inputs["knots"], periodic.results
    assert b.domain(knots, 3) == tuple(found["domain"]) and found["domain"][1] - found["domain"][0] == found["period"]
    np.testing.assert_allclose(found["labels"][-3:] - found["labels"][:3], found["period"])
    loop = rng.uniform(-5, 5, (5, 2))
    points = np.vstack([loop, loop[:3]])
    for order in range(3):
        np.testing.assert_allclose(b.derivative(points, knots, 4.0, order), b.derivative(points, knots, 11.0, order))


def test_the_knot_vector_of_section_6_2():
    # Four cubic segments over [1, 2], [2, 4], [4, 5], [5, 8] need [t1, t2, 1, 2, 4, 5, 8, t8, t9].
    example = notes_example("06.knot_vector")
    n, found = example.inputs["degree"], example.results
    ends = found["end_knots"]
    knots = np.concatenate([found["inner_knots"][0] - np.arange(ends, 0, -1.0), found["inner_knots"],
                            found["inner_knots"][-1] + np.arange(1.0, ends + 1)])
    assert ends == n - 1 and len(knots) == found["knot_count"]
    np.testing.assert_array_equal(b.bezier_segment_intervals(knots, n), example.inputs["segments"])
    # With SciPy's two dummy knots the [1, ..., 8] of Figure 6.2.b has ten knots.
    labels = notes_example("06.bspline_polar_labels")
    t, c, k = b.to_scipy(np.zeros((len(labels.results["labels"]), 2)), labels.inputs["knots"])
    assert len(t) == labels.results["usual_knot_count"] and k == labels.inputs["degree"]


BASIS_EXAMPLE = notes_example("06.basis_functions")


def test_greville_example():
    # §6.14, Figure 6.28: cubic with knots [0,0,0,2,3,4,5,5,5] and 7 control points.
    knots, n = BASIS_EXAMPLE.args("knots", "degree")
    np.testing.assert_allclose(b.greville(knots, n), BASIS_EXAMPLE.results["greville"])
    assert b.domain(knots, n) == tuple(BASIS_EXAMPLE.results["domain"])
    # The figure's explicit B-spline: height 1 at f(0, 2, 3), 0 elsewhere, over the Greville abscissae.
    unit = np.eye(7)[BASIS_EXAMPLE.inputs["index"]]
    figure = b.explicit_bspline(unit, knots)
    np.testing.assert_allclose(figure, np.column_stack([BASIS_EXAMPLE.results["greville"], unit]))
    explicit = b.explicit_bspline([0, 0, 0, 1, 0, 0, 0], knots)
    np.testing.assert_allclose(explicit[:, 0], b.greville(knots, 3))
    t = np.linspace(0, 5, 11)
    np.testing.assert_allclose(b.de_boor(explicit, knots, t)[:, 1], b.bspline_basis(knots, 3, 3, t))


def test_power_blossom_example():
    # §6.11: p(t) = t³ + 6t² + 3t + 1 has the blossom 1 + 3 (t1+t2+t3)/3 + 6 (t1t2+t1t3+t2t3)/3 + t1t2t3
    # and its cubic Bernstein coefficients on [0, 1], the blossom with i ones and 3 - i zeros, are 1, 2, 5, 11.
    example = notes_example("06.power_blossom")
    coeffs, (a, z) = example.args("coeffs", "interval")
    bernstein = [b.power_blossom(coeffs, [a] * (3 - i) + [z] * i) for i in range(4)]
    np.testing.assert_allclose(bernstein, example.results["bernstein"])
    np.testing.assert_allclose(bernstein, power_to_bernstein(coeffs))
    u = np.array([0.3, -1.2, 2.5])
    e = [1.0, u.sum(), u[0] * u[1] + u[0] * u[2] + u[1] * u[2], u.prod()]
    formula = np.dot(example.results["symmetric_weights"], e)
    assert formula == pytest.approx(1 + 3 * u.sum() / 3 + 6 * e[2] / 3 + u.prod())
    assert b.power_blossom(coeffs, u) == pytest.approx(formula)
    # The same polynomial blossomed as a quartic (n = 4 > degree) has one more argument.
    assert b.power_blossom(coeffs, [2.0] * 4) == pytest.approx(horner(coeffs, 2.0))


def test_symmetric_polynomial_formulas():
    # §6.11: p[t1, t2] = c0 + c1 (t1+t2)/2 + c2 t1 t2, and the quartic one with e_i / C(4, i).
    c = np.array([2.0, -1.0, 3.0])
    assert b.power_blossom(c, [0.5, 4.0]) == pytest.approx(2 - 1 * 4.5 / 2 + 3 * 2.0)
    c4 = np.array([1.0, 2.0, -1.0, 0.5, 3.0])
    u = np.array([0.2, 1.5, -0.7, 2.0])
    e = [1, u.sum(), sum(u[i] * u[j] for i in range(4) for j in range(i + 1, 4)),
         sum(np.prod(np.delete(u, k)) for k in range(4)), u.prod()]
    assert b.power_blossom(c4, u) == pytest.approx(sum(c4[i] * e[i] / comb(4, i) for i in range(5)))


def test_bernstein_coefficients_are_blossom_values_on_any_interval():
    # The theorem of §6.11: b_i = p[a, ..., a, b, ..., b] (n - i copies of a) over [a, b].
    coeffs = np.array([1.0, -2.0, 0.5, 1.5])
    a, z = -1.0, 2.5
    bern = np.array([b.power_blossom(coeffs, [a] * (3 - i) + [z] * i) for i in range(4)])
    t = np.linspace(a, z, 9)
    np.testing.assert_allclose(bezier.evaluate(bern[:, None], t, interval=(a, z))[:, 0], horner(coeffs, t))


def test_circle_approximation_error():
    # §6.14.4: a periodic uniform cubic with control points on a regular polygon approximates a circle.
    for count, expected in [(4, 0.014059003190753), (8, 5.761672400659e-4), (12, 1.0473885360e-4)]:
        points, knots, error = b.circle_approximation(count)
        assert error == pytest.approx(expected, rel=1e-9)
        radius = np.linalg.norm(b.de_boor(points, knots, sample(knots, 3, 4001)), axis=1)
        assert radius.max() - 1 == pytest.approx(error, rel=1e-6)
        assert 1 - radius.min() == pytest.approx(error, rel=1e-6)
    # Doubling the number of control points divides the error by about 16 (fourth order).
    ratio = b.circle_approximation(20)[2] / b.circle_approximation(40)[2]
    assert 15 < ratio < 17


# --- evaluation ---------------------------------------------------------------------------


@pytest.mark.parametrize("form", DE_BOOR_FORMS)
@pytest.mark.parametrize("seed, n", random_cases())
def test_de_boor_matches_scipy(form, seed, n):
    points, knots = random_spline(seed, n, dim=int(seed % 3) + 1)
    t = sample(knots, n)
    np.testing.assert_allclose(form(points, knots, t), scipy_spline(points, knots)(t), atol=1e-12)


@pytest.mark.parametrize("seed, n", random_cases())
def test_the_plain_and_the_tuned_de_boor_agree(seed, n):
    points, knots = random_spline(seed, n, dim=3)
    t = np.concatenate([sample(knots, n, 2001), [b.domain(knots, n)[1]]])  # more than one block of parameters
    np.testing.assert_allclose(b.de_boor_plain(points, knots, t), b.de_boor(points, knots, t), atol=1e-12)
    np.testing.assert_allclose(b.de_boor_plain(points, knots, t[7]), b.de_boor(points, knots, t[7]), atol=1e-12)


@pytest.mark.parametrize("form", DE_BOOR_FORMS)
def test_de_boor_of_the_notes_quartic_is_its_bezier_curve(form):
    # A Bézier curve is the B-spline with n-fold end knots.
    t = np.linspace(1, 5, 9)
    np.testing.assert_allclose(form(QUARTIC, QUARTIC_KNOTS, t), bezier.evaluate(QUARTIC, t, interval=(1, 5)))
    # The refined quartic of §6.7 is the same curve.
    refined = QUARTIC_EXAMPLE.results
    np.testing.assert_allclose(form(refined["points"], refined["knots"], t), form(QUARTIC, QUARTIC_KNOTS, t))


@pytest.mark.parametrize("form", DE_BOOR_FORMS)
def test_de_boor_is_continuous_at_an_n_fold_knot(form):
    # At a knot of multiplicity n the curve passes through a control point, approached from either side.
    knots = np.array([0.0, 1, 2, 2, 3, 4])
    points = np.random.default_rng(2).uniform(-1, 1, (5, 2))
    assert b.degree(points, knots) == 2
    np.testing.assert_allclose(form(points, knots, 2.0), points[2])
    np.testing.assert_allclose(form(points, knots, 2 - 1e-12), points[2], atol=1e-10)


def test_de_boor_triangle_levels_are_polar_values():
    points, knots = random_spline(3, 3, zero_chance=0.0)
    t = 0.5 * (knots[2] + knots[3])
    levels, span = b.de_boor_triangle(points, knots, t)
    assert span == 2 and [len(level) for level in levels] == [4, 3, 2, 1]
    np.testing.assert_allclose(levels[0], points[0:4])
    # Level r, point i: r copies of t and the knots t_(r+i) ... t_(2+i) (span j = 2, n = 3).
    for r, level in enumerate(levels):
        labels = [[t] * r + list(knots[r + i : 3 + i]) for i in range(4 - r)]
        np.testing.assert_allclose(level, b.polar_values(points, knots, labels), atol=1e-12)
    np.testing.assert_allclose(levels[-1][0], b.de_boor(points, knots, t))


def test_a_knot_uses_the_span_to_its_right():
    points = np.random.default_rng(4).uniform(-1, 1, (6, 2))
    knots = np.arange(7.0)  # quadratic, domain [1, 5]
    assert b.de_boor_triangle(points, knots, 2.0)[1] == 2
    assert b.de_boor_triangle(points, knots, 1.0)[1] == 1
    assert b.de_boor_triangle(points, knots, 5.0)[1] == 4  # the end of the domain: the last span


@pytest.mark.parametrize("seed, n", random_cases())
def test_derivatives_match_scipy(seed, n):
    points, knots = random_spline(seed, n)
    spline = scipy_spline(points, knots)
    t = sample(knots, n)
    for order in range(n + 2):
        expected = spline(t, nu=order) if order <= n else np.zeros((len(t), 2))
        scale = 1 + np.abs(expected).max()
        np.testing.assert_allclose(b.derivative(points, knots, t, order), expected, atol=1e-9 * scale)


@pytest.mark.parametrize("seed, n", [(s, n) for n in range(2, 6) for s in SEEDS])
def test_hodograph_matches_scipy(seed, n):
    points, knots = random_spline(seed, n, zero_chance=0.0)
    hodo_points, hodo_knots = b.hodograph(points, knots)
    assert len(hodo_points) == len(points) - 1 and b.degree(hodo_points, hodo_knots) == n - 1
    assert b.domain(hodo_knots, n - 1) == b.domain(knots, n)
    t = sample(knots, n)
    np.testing.assert_allclose(b.de_boor(hodo_points, hodo_knots, t), scipy_spline(points, knots)(t, nu=1), atol=1e-9)


def test_hodograph_formula_and_limits():
    # (6.2): H_i = n (P_(i+1) - P_i) / (t_(i+n) - t_i).
    points, knots = random_spline(6, 3, zero_chance=0.0)
    hodo, _ = b.hodograph(points, knots)
    np.testing.assert_allclose(hodo[2], 3 * (points[3] - points[2]) / (knots[5] - knots[2]))
    with pytest.raises(ValueError, match="^knots:"):
        b.hodograph([[0.0], [1.0], [3.0]], [0.0, 1.0, 2.0])  # degree 1
    with pytest.raises(ValueError, match="^knots:"):
        b.hodograph(np.zeros((5, 2)), [0.0, 0, 1, 1, 2, 2])  # a double knot in a quadratic: C0


def test_degree_one_derivative_is_the_slope():
    points = np.array([[0.0, 0.0], [2.0, 1.0], [3.0, 5.0]])
    knots = [0.0, 1.0, 3.0]
    np.testing.assert_allclose(b.derivative(points, knots, [0.5, 1.0, 2.0]), [[2, 1], [0.5, 2], [0.5, 2]])
    np.testing.assert_allclose(b.derivative(points, knots, 3.0, order=2), [0, 0])


# --- knot insertion and Bézier extraction -------------------------------------------------


@pytest.mark.parametrize("seed, n", random_cases())
def test_insert_knot_matches_scipy_insert(seed, n):
    points, knots = random_spline(seed, n)
    spline = scipy_spline(points, knots)
    rng = np.random.default_rng(seed)
    a, z = b.domain(knots, n)
    values, counts = b.knot_multiplicities(knots)
    candidates = [float(rng.uniform(a, z))] + values[(counts < n) & (values >= a) & (values <= z)].tolist()
    for t in candidates:
        new_points, new_knots = b.insert_knot(points, knots, t)
        refined = insert(t, spline)
        np.testing.assert_allclose(new_knots, refined.t[1:-1])
        np.testing.assert_allclose(new_points, refined.c[: len(new_points)], atol=1e-12)
        ts = sample(knots, n)
        np.testing.assert_allclose(b.de_boor(new_points, new_knots, ts), spline(ts), atol=1e-12)


def test_insert_knots_in_any_order():
    points, knots = random_spline(7, 3)
    a, z = b.domain(knots, 3)
    ts = np.linspace(a, z, 5)[1:-1]
    forward = b.insert_knots(points, knots, ts)
    backward = b.insert_knots(points, knots, ts[::-1])
    np.testing.assert_allclose(forward[0], backward[0])
    np.testing.assert_allclose(forward[1], np.sort(np.concatenate([knots, ts])))
    single = b.insert_knots(points, knots, ts[0])
    np.testing.assert_allclose(single[0], b.insert_knot(points, knots, ts[0])[0])


def test_insertion_stops_at_multiplicity_n():
    knots = [0.0, 0, 1, 1, 2, 2]
    points = np.zeros((5, 2))
    with pytest.raises(ValueError, match="^t:"):
        b.insert_knot(points, knots, 1.0)


@pytest.mark.parametrize("seed, n", random_cases())
def test_bezier_segments_reproduce_the_curve(seed, n):
    points, knots = random_spline(seed, n)
    segments = b.bezier_segments(points, knots)
    intervals = b.bezier_segment_intervals(knots, n)
    assert segments.shape == (len(intervals), n + 1, 2)
    np.testing.assert_array_equal(intervals[1:, 0], intervals[:-1, 1])
    assert intervals[0, 0] == b.domain(knots, n)[0] and intervals[-1, 1] == b.domain(knots, n)[1]
    spline = scipy_spline(points, knots)
    for segment, (a, z) in zip(segments, intervals):
        t = np.linspace(a, z, 7)
        np.testing.assert_allclose(bezier.evaluate(segment, t, interval=(a, z)), spline(t), atol=1e-11)


def test_bezier_segment_count_with_simple_knots():
    # §6.4.1: c control points and distinct knots give c - n segments; a B-spline string of m
    # degree-n Bézier curves needs m + n control points.
    points, knots = random_spline(2, 3, zero_chance=0.0)
    assert len(b.bezier_segments(points, knots)) == len(points) - 3


# --- blossoms ------------------------------------------------------------------------------


@pytest.mark.parametrize("seed, n", random_cases())
def test_control_points_are_polar_values(seed, n):
    points, knots = random_spline(seed, n)
    spans = b.bezier_segment_intervals(knots, n)
    for i in range(len(points)):
        label = knots[i : i + n]
        # Only points that act on a segment of positive length are determined by the curve.
        acts = np.any((spans[:, 1] > label.min()) & (spans[:, 0] < label.max())) or label.min() == label.max()
        if acts:
            np.testing.assert_allclose(b.blossom(points, knots, label), points[i], atol=1e-10)


@pytest.mark.parametrize("n", DEGREES)
def test_blossom_symmetric_multiaffine_diagonal(n):
    points, knots = random_spline(11, n, zero_chance=0.0)
    rng = np.random.default_rng(n)
    j = n - 1 + int(rng.integers(0, len(points) - n))
    lo, hi = knots[j], knots[j + 1]
    u = rng.uniform(lo, hi, n)
    value = b.blossom(points, knots, u)
    np.testing.assert_allclose(b.blossom(points, knots, rng.permutation(u)), value)
    # Affine in each argument: f(.., (1-λ) a + λ c, ..) = (1-λ) f(.., a, ..) + λ f(.., c, ..).
    a, c = rng.uniform(lo, hi, 2)
    lam = rng.uniform()
    first, second, mixed = u.copy(), u.copy(), u.copy()
    first[0], second[0], mixed[0] = a, c, (1 - lam) * a + lam * c
    np.testing.assert_allclose(
        b.blossom(points, knots, mixed),
        (1 - lam) * b.blossom(points, knots, first) + lam * b.blossom(points, knots, second),
    )
    t = rng.uniform(lo, hi)
    np.testing.assert_allclose(b.blossom(points, knots, [t] * n), scipy_spline(points, knots)(t))


def test_blossom_rejects_ambiguous_and_outside_arguments():
    points = np.random.default_rng(0).uniform(-5, 5, (6, 2))
    knots = notes_example("06.bspline_polar_labels").inputs["knots"]  # 1, 2, ..., 8
    with pytest.raises(ValueError, match="^args:.*ambiguous"):
        b.blossom(points, knots, [3.5, 4.5, 5.5])  # three segments without a shared knot
    with pytest.raises(ValueError, match="^args:"):
        b.blossom(points, knots, [0.0, 3.0, 4.0])
    with pytest.raises(ValueError, match="^args:"):
        b.blossom(points, knots, [3.0, 4.0])
    # Arguments over two segments that share a knot among them are fine: C2 at a simple knot.
    across = [3.5, 4.0, 4.5]
    np.testing.assert_allclose(b.blossom(points, knots, across), b.polar_values(points, knots, [across])[0])


def test_bezier_blossom_gives_subdivision_points():
    points = np.random.default_rng(1).uniform(-5, 5, (5, 3))
    t = 0.3
    left, right = bezier.subdivide(points, t)
    for i in range(5):
        np.testing.assert_allclose(b.bezier_blossom(points, [0.0] * (4 - i) + [t] * i), left[i])
        np.testing.assert_allclose(b.bezier_blossom(points, [t] * (4 - i) + [1.0] * i), right[i])
    np.testing.assert_allclose(b.bezier_blossom([[2.0, 1.0]], []), [2.0, 1.0])
    # The Bézier blossom and the power blossom agree on one polynomial (the notes' t³ + 6t² + 3t + 1).
    coeffs = notes_example("06.power_blossom").inputs["coeffs"]
    u = [0.2, 0.9, -0.4]
    assert b.bezier_blossom(power_to_bernstein(coeffs)[:, None], u)[0] == pytest.approx(b.power_blossom(coeffs, u))


def test_power_blossom_shapes():
    assert isinstance(b.power_blossom([1.0, 2.0], [3.0]), float)
    np.testing.assert_allclose(b.power_blossom([[1.0, 0.0], [2.0, 1.0]], [3.0, 5.0]), [9.0, 4.0])
    assert b.power_blossom([4.0], []) == 4.0


@pytest.mark.parametrize("seed, n", random_cases())
def test_polar_values_of_refined_labels(seed, n):
    # Knot insertion and elevation are read off the blossom: check polar_values against insert_knot.
    points, knots = random_spline(seed, n)
    a, z = b.domain(knots, n)
    t = 0.37 * a + 0.63 * z
    if np.count_nonzero(knots == t) < n:
        new_points, new_knots = b.insert_knot(points, knots, t)
        labels = new_knots[np.arange(len(new_points))[:, None] + np.arange(n)]
        spans = b.bezier_segment_intervals(new_knots, n)
        acts = [np.any((spans[:, 1] > lab.min()) & (spans[:, 0] < lab.max())) for lab in labels]
        np.testing.assert_allclose(b.polar_values(points, knots, labels)[acts], new_points[acts], atol=1e-10)


# --- basis functions -----------------------------------------------------------------------


@pytest.mark.parametrize("seed, n", random_cases())
def test_basis_matrix_matches_scipy_design_matrix(seed, n):
    points, knots = random_spline(seed, n)
    t_scipy, _, k = b.to_scipy(points, knots)
    t = sample(knots, n)
    matrix = b.basis_matrix(knots, n, t)
    np.testing.assert_allclose(matrix, BSpline.design_matrix(t, t_scipy, k).toarray(), atol=1e-12)
    np.testing.assert_allclose(matrix.sum(axis=1), 1.0)
    assert np.all(matrix >= -1e-15)


@pytest.mark.parametrize("seed, n", random_cases())
def test_basis_functions_match_scipy_basis_elements(seed, n):
    points, knots = random_spline(seed, n)
    t_scipy = b.to_scipy(points, knots)[0]
    t = sample(knots, n)
    for i in range(len(points)):
        values = b.bspline_basis(knots, n, i, t)
        local = t_scipy[i : i + n + 2]
        if local[0] == local[-1]:
            continue
        element = BSpline.basis_element(local, extrapolate=False)(t)
        inside = ~np.isnan(element)
        # basis_element treats its last knot as open; the notes' domain end belongs to the last span.
        inside &= t < local[-1]
        np.testing.assert_allclose(values[inside], element[inside], atol=1e-12)
        # Local support (§6.14): B_i vanishes outside (t_(i-1), t_(i+n)).
        assert np.all(values[(t < local[0]) | (t > local[-1])] == 0)


def test_bspline_basis_scalar_and_the_zero_over_zero_rule():
    knots = BASIS_EXAMPLE.inputs["knots"]
    assert isinstance(b.bspline_basis(knots, 3, 0, 0.0), float)
    assert b.bspline_basis(knots, 3, 0, 0.0) == 1.0
    assert b.bspline_basis(knots, 3, 6, 5.0) == 1.0
    # Triple end knots make denominators vanish in the recurrence; the 0/0 = 0 rule gives finite values.
    matrix = b.basis_matrix(knots, 3, np.linspace(0, 5, 21))
    assert np.all(np.isfinite(matrix))
    np.testing.assert_allclose(matrix.sum(axis=1), 1.0)


def test_greville_abscissae_reproduce_the_parameter():
    for seed, n in random_cases()[::3]:
        _, knots = random_spline(seed, n)
        t = sample(knots, n)
        explicit = b.explicit_bspline(np.zeros(len(knots) - n + 1), knots)
        np.testing.assert_allclose(scipy_spline(explicit, knots)(t)[:, 0], t, atol=1e-12)
        np.testing.assert_allclose(b.greville(knots, n), [np.mean(knots[i : i + n]) for i in range(len(knots) - n + 1)])


# --- conversions and bookkeeping -----------------------------------------------------------


def test_scipy_round_trip():
    points, knots = random_spline(3, 4)
    t, c, k = b.to_scipy(points, knots)
    assert len(t) == len(c) + k + 1 and k == 4
    assert t[0] == knots[0] and t[-1] == knots[-1]
    back_points, back_knots = b.from_scipy(t, c, k)
    np.testing.assert_array_equal(back_points, points)
    np.testing.assert_array_equal(back_knots, knots)
    # Any value of the dummy end knots gives the same curve.
    spline = BSpline(np.concatenate([[t[0] - 7], t[1:-1], [t[-1] + 3]]), c, k)
    ts = sample(knots, 4)
    np.testing.assert_allclose(spline(ts), b.de_boor(points, knots, ts), atol=1e-12)
    scalar_points, _ = b.from_scipy(t, c[:, 0], k)
    assert scalar_points.shape == (len(c), 1)


def test_multiplicities_and_continuity():
    knots = [0.0, 0, 0, 1, 2, 2, 3, 3, 3, 4, 5, 5, 5]
    values, counts = b.knot_multiplicities(knots)
    np.testing.assert_array_equal(values, [0, 1, 2, 3, 4, 5])
    np.testing.assert_array_equal(counts, [3, 1, 2, 3, 1, 3])
    inner, orders = b.continuity_at_knots(knots, 3)
    np.testing.assert_array_equal(inner, [1, 2, 3, 4])
    np.testing.assert_array_equal(orders, [2, 1, 0, 2])
    assert b.domain(knots, 3) == (0.0, 5.0)


@pytest.mark.parametrize("seed, n", random_cases())
def test_continuity_matches_the_derivative_jumps(seed, n):
    points, knots = random_spline(seed, n)
    values, orders = b.continuity_at_knots(knots, n)
    spline = scipy_spline(points, knots)
    for v, r in zip(values, orders):
        h = 1e-7
        for order in range(r + 1):
            left = spline(v - h, nu=order)
            right = b.derivative(points, knots, v, order)
            scale = 1 + np.abs(right).max() + np.abs(b.derivative(points, knots, v, order + 1)).max()
            np.testing.assert_allclose(left, right, atol=1e-5 * scale)


@pytest.mark.parametrize("seed, n", random_cases())
def test_elevate_keeps_the_curve(seed, n):
    points, knots = random_spline(seed, n)
    new_points, new_knots = b.elevate(points, knots)
    assert b.degree(new_points, new_knots) == n + 1
    values, counts = b.knot_multiplicities(knots)
    new_values, new_counts = b.knot_multiplicities(new_knots)
    np.testing.assert_array_equal(new_values, values)
    a, z = b.domain(knots, n)
    in_domain = (values >= a) & (values <= z)
    np.testing.assert_array_equal(new_counts - counts, in_domain)
    # c + m - 1 control points, m the distinct knot values of the domain (its ends included).
    assert len(new_points) == len(points) + np.count_nonzero(in_domain) - 1
    t = sample(knots, n)
    np.testing.assert_allclose(scipy_spline(new_points, new_knots)(t), scipy_spline(points, knots)(t), atol=1e-11)


def test_elevate_counts_and_geomdl():
    # A Bézier curve (m = 2 knot values) gains one point, as in geomdl; each interior simple knot adds one more.
    from geomdl import helpers

    cubic = np.array([[5.0, 5.0], [10.0, 10.0], [20.0, 15.0], [35.0, 15.0]])
    raised, raised_knots = b.elevate(cubic, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
    np.testing.assert_allclose(raised, helpers.degree_elevation(3, cubic.tolist()), atol=1e-12)
    np.testing.assert_array_equal(raised_knots, [0, 0, 0, 0, 1, 1, 1, 1])
    six = np.vstack([cubic, [[45.0, 10.0], [50.0, 5.0]]])
    knots = [0.0, 0.0, 0.0, 0.33, 0.66, 1.0, 1.0, 1.0]  # m = 4 knot values in the domain [0, 1]
    new_points, new_knots = b.elevate(six, knots)
    assert len(new_points) == len(six) + 4 - 1 == len(new_knots) - 4 + 1


def test_elevated_polar_values_of_a_bezier_curve_are_bezier_elevation():
    points = np.random.default_rng(3).uniform(-2, 2, (4, 2))
    knots = [0.0, 0, 0, 1, 1, 1]
    labels = [[0.0] * (4 - i) + [1.0] * i for i in range(5)]
    np.testing.assert_allclose(b.elevated_polar_values(points, knots, labels), bezier.elevate(points))


# --- special knot vectors, closed curves, combining ---------------------------------------------


def test_bezier_end_knots():
    knots = b.bezier_end_knots(6, 3)
    np.testing.assert_array_equal(knots, [0, 0, 0, 1, 2, 3, 3, 3])
    np.testing.assert_array_equal(b.bezier_end_knots(4, 3, 1.0, 5.0), [1, 1, 1, 5, 5, 5])
    points = np.random.default_rng(4).uniform(-3, 3, (6, 2))
    np.testing.assert_allclose(b.de_boor(points, knots, [0.0, 3.0]), points[[0, -1]])
    # End tangents along the first and last legs: P'(0) = n (P1 - P0) / (t_n - t_0).
    np.testing.assert_allclose(b.derivative(points, knots, 0.0), 3 * (points[1] - points[0]) / 1.0)


@pytest.mark.parametrize("n", DEGREES)
def test_periodic_closed_curve_closes_smoothly(n):
    polygon = np.random.default_rng(n).uniform(-3, 3, (7, 2))
    points, knots = b.periodic_closed(polygon, n)
    assert len(points) == 7 + n and b.domain(knots, n) == (n - 1, n + 6)
    for order in range(n):
        start = b.derivative(points, knots, float(n - 1), order)
        end = b.derivative(points, knots, float(n + 6), order)
        np.testing.assert_allclose(start, end, atol=1e-9)


def test_combine_bezier_reassembles_a_spline():
    # §6.12: split a C2 cubic with Bézier end conditions into Bézier curves and join them again.
    points = np.random.default_rng(8).uniform(-4, 4, (7, 2))
    knots = np.array([0.0, 0, 0, 1, 2.5, 3, 4, 4, 4])
    segments = b.bezier_segments(points, knots)
    intervals = b.bezier_segment_intervals(knots, 3)
    joined, joined_knots, continuity = b.combine_bezier(segments, intervals)
    np.testing.assert_array_equal(continuity, [2, 2, 2])
    np.testing.assert_allclose(joined_knots, knots)
    np.testing.assert_allclose(joined, points, atol=1e-12)


@pytest.mark.parametrize("seed, n", random_cases())
def test_combine_bezier_of_random_splines_matches_scipy(seed, n):
    points, knots = random_spline(seed, n, zero_chance=0.0)
    segments, intervals = b.bezier_segments(points, knots), b.bezier_segment_intervals(knots, n)
    joined, joined_knots, continuity = b.combine_bezier(segments, intervals)
    np.testing.assert_array_equal(continuity, n - 1)
    t = sample(knots, n)
    np.testing.assert_allclose(scipy_spline(joined, joined_knots)(t), scipy_spline(points, knots)(t), atol=1e-9)


def test_combine_bezier_detects_c0_c1_c2():
    # Three cubics over [0,1], [1,3], [3,4]: the first joint C1 only, the second C0 only.
    first = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 2.0], [3.0, 1.0]])
    # C1 at t = 1: Q1 = P3 + (h_next / h_prev) (P3 - P2) with interval lengths 2 and 1.
    second = np.array([[3.0, 1.0], [5.0, -1.0], [6.0, 0.0], [7.0, 3.0]])
    third = np.array([[7.0, 3.0], [8.0, 3.0], [9.0, 1.0], [9.0, 0.0]])
    intervals = [[0.0, 1.0], [1.0, 3.0], [3.0, 4.0]]
    points, knots, continuity = b.combine_bezier([first, second, third], intervals)
    np.testing.assert_array_equal(continuity, [1, 0])
    np.testing.assert_array_equal(knots, [0, 0, 0, 1, 1, 3, 3, 3, 4, 4, 4])
    assert len(points) == len(knots) - 2
    for segment, (a, z) in zip([first, second, third], intervals):
        t = np.linspace(a, z, 9)
        expected = bezier.evaluate(segment, t, interval=(a, z))
        np.testing.assert_allclose(b.de_boor(points, knots, t), expected, atol=1e-12)
    with pytest.raises(ValueError, match="^segments:"):
        b.combine_bezier([first, third], [[0.0, 1.0], [1.0, 2.0]])


# --- bad input and purity ------------------------------------------------------------------

POINTS = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [5.0, 1.0]])
KNOTS = np.array([0.0, 0.0, 1.0, 2.0, 3.0, 3.0])  # a quadratic over [0, 3]


@pytest.mark.parametrize(
    "call, error, name",
    [
        (lambda: b.de_boor(POINTS, [0, 0, 2, 1, 3, 3], 1.5), ValueError, "knots"),
        (lambda: b.de_boor(POINTS, [0, 1, 2], 1.5), ValueError, "knots"),
        (lambda: b.de_boor(POINTS, [0, 1, 2, 3], 1.5), ValueError, "knots"),  # degree 0
        (lambda: b.de_boor(POINTS, [0, 1, 1, 1, 2, 3], 1.0), ValueError, "knots"),  # triple knot, quadratic
        (lambda: b.de_boor(POINTS[:3], [0, 1, 1, 2], 1.0), ValueError, "knots"),  # empty domain
        (lambda: b.de_boor(POINTS, KNOTS, -0.5), ValueError, "t"),
        (lambda: b.de_boor(POINTS, KNOTS, 3.5), ValueError, "t"),
        (lambda: b.de_boor(POINTS, KNOTS, [[1.5]]), ValueError, "t"),
        (lambda: b.de_boor([1.0, 2.0, 3.0], [0, 1, 2], 1.0), ValueError, "points"),
        (lambda: b.de_boor(POINTS, "knots", 1.0), TypeError, "knots"),
        (lambda: b.de_boor_triangle(POINTS, KNOTS, [1.2, 1.5]), ValueError, "t"),
        (lambda: b.de_boor_triangle(POINTS, KNOTS, 3.5), ValueError, "t"),
        (lambda: b.insert_knot(POINTS, KNOTS, 3.0), ValueError, "t"),
        (lambda: b.insert_knots(POINTS, KNOTS, [[1.5]]), ValueError, "ts"),
        (lambda: b.bezier_segments(POINTS, [3, 2, 1, 0, 0, 0]), ValueError, "knots"),
        (lambda: b.bezier_segment_intervals(KNOTS, 0), ValueError, "degree"),
        (lambda: b.bezier_segment_intervals(KNOTS, 2.0), TypeError, "degree"),
        (lambda: b.blossom(POINTS, KNOTS, [1.5]), ValueError, "args"),
        (lambda: b.blossom(POINTS, KNOTS, [1.5, 4.0]), ValueError, "args"),
        (lambda: b.bezier_blossom(POINTS, [0.5]), ValueError, "args"),
        (lambda: b.power_blossom([1.0, 2.0, 3.0], [0.5]), ValueError, "args"),
        (lambda: b.power_blossom([[[1.0]]], [0.5]), ValueError, "coeffs"),
        (lambda: b.bspline_basis(KNOTS, 2, 5, 1.5), ValueError, "i"),
        (lambda: b.bspline_basis(KNOTS, 2, -1, 1.5), ValueError, "i"),
        (lambda: b.bspline_basis(KNOTS, 2, 0, 3.5), ValueError, "t"),
        (lambda: b.basis_matrix(KNOTS, 0, 1.5), ValueError, "degree"),
        (lambda: b.greville([0, 1], 3), ValueError, "knots"),
        (lambda: b.explicit_bspline([[1.0, 2.0]], KNOTS), ValueError, "coeffs"),
        (lambda: b.from_scipy([0, 0, 1, 2, 3, 3], [1.0, 2.0, 3.0], 3), ValueError, "t"),
        (lambda: b.from_scipy([0, 0, 0, 0, 1, 1, 1, 1], [1.0, 2.0, 3.0, 4.0], 0), ValueError, "k"),
        (lambda: b.from_scipy([0, 0, 1, 1, 1, 2, 2], [1.0, 2.0, 3.0, 4.0], 2), ValueError, "t"),  # a triple knot
        (lambda: b.derivative(POINTS, KNOTS, 1.5, -1), ValueError, "order"),
        (lambda: b.polar_values(POINTS, KNOTS, [1.0, 2.0, 3.0]), ValueError, "labels"),
        (lambda: b.elevated_polar_values(POINTS, KNOTS, [1.0, 2.0]), ValueError, "labels"),
        (lambda: b.bezier_end_knots(3, 3), ValueError, "count"),
        (lambda: b.bezier_end_knots(5, 3, 2.0, 1.0), ValueError, "end"),
        (lambda: b.periodic_closed(POINTS[:2], 3), ValueError, "points"),
        (lambda: b.circle_approximation(2), ValueError, "count"),
        (lambda: b.combine_bezier(np.zeros((2, 4)), [[0, 1]]), ValueError, "segments"),
        (lambda: b.combine_bezier(np.zeros((2, 4, 2)), [[0, 1], [2, 3]]), ValueError, "intervals"),
        (lambda: b.combine_bezier(np.zeros((2, 4, 2)), [[0, 1]]), ValueError, "intervals"),
        (lambda: b.combine_bezier(np.zeros((1, 4, 2)), [[1, 0]]), ValueError, "intervals"),
    ],
)
def test_bad_input_names_the_argument(call, error, name):
    with pytest.raises(error, match=rf"^{name}:"):
        call()


def test_results_are_fresh_arrays():
    # Writing to a result leaves the input alone (level 0 of the triangle holds the span's control points).
    points, knots = random_spline(5, 3)
    a, _ = b.domain(knots, 3)
    result = b.de_boor_triangle(points, knots, a)[0][0]
    result[:] = 99
    assert not np.any(points == 99)


def test_knot_span_finds_the_span_and_gives_the_last_one_the_right_end():
    knots = [0, 0, 0, 1, 2, 2, 3, 3, 3]  # cubic over [0, 3], the knot 2 doubled
    assert b.knot_span(knots, 3, 0.0) == 2
    np.testing.assert_array_equal(b.knot_span(knots, 3, [0.5, 1.0, 1.999, 2.0, 3.0]), [2, 3, 3, 5, 5])
    with pytest.raises(ValueError, match="t: expected values in the domain"):
        b.knot_span(knots, 3, 3.5)


def test_checked_bspline_gives_fresh_arrays_and_the_degree():
    points, knots = [[0, 0], [1, 2], [2, 0], [3, 1]], [0, 0, 1, 1, 1]
    with pytest.raises(ValueError, match="more than the degree"):
        b.checked_bspline(points, knots)  # degree 2: the knot 1 three times
    pts, kn, n = b.checked_bspline(points, [0, 1, 2, 3])
    assert n == 1 and pts.dtype == float and kn.tolist() == [0, 1, 2, 3]
    assert b.checked_knots([0, 0, 1, 1], 2)[1] == 2

"""Tests of cagd_ref.approximation: the notes' examples, properties of least squares and fairing, peer cross-checks.

The generic contract (NaN/inf rejected by name, inputs untouched) is checked in
test_contract.py from tests/ref/calls/approximation.py. Peers: scipy.interpolate
(make_lsq_spline, make_smoothing_spline, BSpline), numpy.polynomial, numpy.linalg,
scipy.integrate.quad, scipy.optimize and exact fractions (sympy) for the notes' tables.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import Polynomial
from scipy.integrate import quad
from scipy.interpolate import BSpline, make_lsq_spline, make_smoothing_spline
from scipy.optimize import LinearConstraint, minimize

from cagd_course.examples import notes_example
from cagd_ref import approximation as ap
from cagd_ref.bspline import basis_matrix, bezier_end_knots, de_boor, derivative, from_scipy, greville, to_scipy

SEEDS = range(6)


def random_spline_problem(seed, degree=None, dims=2, multiple=True):
    """Random knots (notes' convention, some double knots), samples with parameters in every span."""
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 6)) if degree is None else degree
    c = int(rng.integers(n + 1, n + 9))
    inner = np.sort(rng.uniform(0.1, 0.9, c - n - 1))
    if multiple and n >= 2 and len(inner) >= 2:
        inner[1] = inner[0]
    knots = np.concatenate([np.full(n, 0.0), inner, np.full(n, 1.0)]) * 3.0 - 1.0
    params = np.sort(rng.uniform(-1.0, 2.0, 12 * c))
    params[[0, -1]] = -1.0, 2.0
    points = rng.normal(size=(len(params), dims))
    return points, params, knots, n


def sampled_spline(seed, n=3, c=8):
    rng = np.random.default_rng(seed)
    knots = bezier_end_knots(c, n, 0.0, 1.0)
    knots[n:-n] = np.sort(rng.uniform(0.05, 0.95, c - n - 1))
    control = rng.uniform(-5, 5, (c, 3))
    params = np.sort(rng.uniform(0, 1, 5 * c))
    params[[0, -1]] = 0.0, 1.0
    return control, knots, params, de_boor(control, knots, params)


def test_every_public_name_is_tested():
    tested = {
        "best_constant", "uniform_parameters", "chord_length_parameters", "centripetal_parameters", "fitting_knots",
        "fit_inputs", "checked_params", "schoenberg_whitney", "normal_equations", "least_squares_fit", "fit_error",
        "project_parameters", "parameter_correction", "fairing_matrix", "fairing_matrix_plain", "fairing_energy",
        "faired_fit", "constrained_fit", "fit_within_tolerance", "estimate_frames", "box_faired_fit",
        "box_programme", "spline_curvature",
    }
    assert set(ap.__all__) == tested


# --- 11.1, 11.2: best constants --------------------------------------------------------------------


@pytest.mark.parametrize("name", ["best_constant_l2", "best_constant_linf"])
def test_best_constants_of_the_notes(name):
    example = notes_example(f"11.{name}")
    values, norm = example.args("values", "norm")
    best, error = ap.best_constant(values, norm)
    assert best == example.results["value"] and error == example.results["error"]
    # Exact arithmetic agrees: the mean and its sum of squares, the midrange and its half range.
    g = [Fraction(int(v)) for v in values]
    mean = sum(g) / len(g)
    exact = (mean, sum((mean - v) ** 2 for v in g)) if norm == "l2" else ((max(g) + min(g)) / 2, (max(g) - min(g)) / 2)
    assert (best, error) == tuple(float(x) for x in exact)


def test_the_notes_typo_in_example_2():
    example = notes_example("11.best_constant_linf")
    erratum = example.errata["argument"]
    values = example.inputs["values"]
    assert float(np.max(np.abs(erratum.notes - values))) == example.results["error_at_mean"] == 3
    assert float(np.max(np.abs(erratum.correct - values))) == example.results["error"] == 2.5


def test_best_constants_minimise_their_error():
    rng = np.random.default_rng(3)
    g = rng.normal(size=9)
    for norm, error in [("l2", lambda a: np.sum((a - g) ** 2)), ("linf", lambda a: np.max(np.abs(a - g)))]:
        best, value = ap.best_constant(g, norm)
        assert value == pytest.approx(error(best))
        trial = np.linspace(best - 1, best + 1, 201)
        assert np.all([error(a) >= value - 1e-12 for a in trial])
    assert ap.best_constant([3.0]) == (3.0, 0.0)


@pytest.mark.parametrize("values, norm", [([], "l2"), ([[1.0, 2.0]], "l2"), ([1.0, 2.0], "l1"), ([1.0], "L2")])
def test_best_constant_rejects_bad_input(values, norm):
    with pytest.raises(ValueError, match="^(values|norm)"):
        ap.best_constant(values, norm)


# --- 11.3.1: parameters ----------------------------------------------------------------------------


def test_chord_length_example_exactly():
    example = notes_example("11.chord_length")
    points = example.inputs["points"]
    assert ap.chord_length_parameters(points).tolist() == [0.0, 5 / 11, 1.0]
    np.testing.assert_array_equal(ap.chord_length_parameters(points), example.results["chord"])
    np.testing.assert_array_equal(ap.uniform_parameters(points), example.results["uniform"])


def test_parameters_of_random_polygons():
    rng = np.random.default_rng(8)
    points = rng.normal(size=(20, 3))
    chord = ap.chord_length_parameters(points)
    steps = np.linalg.norm(np.diff(points, axis=0), axis=1)
    np.testing.assert_allclose(np.diff(chord), steps / steps.sum(), rtol=1e-13)
    assert chord[0] == 0 and chord[-1] == 1
    np.testing.assert_allclose(ap.centripetal_parameters(points, 1.0), chord, rtol=1e-14)
    np.testing.assert_allclose(ap.centripetal_parameters(points, 0.0), ap.uniform_parameters(points), atol=1e-15)
    root = np.concatenate([[0], np.cumsum(np.sqrt(steps))])
    np.testing.assert_allclose(ap.centripetal_parameters(points), root / root[-1], rtol=1e-13)
    # The parameters of a polygon do not depend on where it stands or how it is turned or scaled.
    turn = np.linalg.qr(rng.normal(size=(3, 3)))[0]
    np.testing.assert_allclose(ap.chord_length_parameters(3 * points @ turn + 5), chord, atol=1e-14)


def test_repeated_samples_share_a_parameter():
    points = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 2.0]]
    assert ap.chord_length_parameters(points).tolist() == [0.0, 1 / 3, 1 / 3, 1.0]
    assert ap.centripetal_parameters(points, 0.0).tolist() == [0.0, 0.5, 0.5, 1.0]


@pytest.mark.parametrize("function", [ap.chord_length_parameters, ap.uniform_parameters, ap.centripetal_parameters])
def test_parameters_reject_bad_input(function):
    with pytest.raises(ValueError, match="^points"):
        function([[1.0, 2.0]])
    with pytest.raises(ValueError, match="^points"):
        function([1.0, 2.0, 3.0])
    if function is not ap.uniform_parameters:
        with pytest.raises(ValueError, match="^points: every sample is the same point"):
            function([[1.0, 2.0], [1.0, 2.0], [1.0, 2.0]])
    with pytest.raises(ValueError, match="^exponent"):
        ap.centripetal_parameters([[0.0], [1.0]], 1.5)


# --- 11.3.2: knot vectors ----------------------------------------------------------------------------


def test_uniform_fitting_knots_are_bezier_end_knots():
    params = np.linspace(-2, 3, 40)
    np.testing.assert_allclose(ap.fitting_knots(params, 9, 3), bezier_end_knots(9, 3, -2.0, 3.0), atol=1e-15)
    np.testing.assert_allclose(ap.fitting_knots(params[::-1], 4, 3), [-2, -2, -2, 3, 3, 3])


@pytest.mark.parametrize("seed", SEEDS)
def test_averaging_puts_a_parameter_in_every_span(seed):
    rng = np.random.default_rng(seed)
    # Clustered parameters: most samples at one end, the case where uniform knots leave spans empty.
    params = np.sort(np.concatenate([rng.uniform(0, 0.1, 40), rng.uniform(0.1, 1, 8), [0.0, 1.0]]))
    n = int(rng.integers(2, 5))
    c = int(rng.integers(n + 2, 30))
    knots = ap.fitting_knots(params, c, n, "averaging")
    assert len(knots) == c + n - 1 and np.all(np.diff(knots) >= 0)
    spans = np.column_stack([knots[n - 1 : c - 1], knots[n : c]])
    assert all(np.any((params >= a) & (params <= b)) for a, b in spans)
    ap.least_squares_fit(np.column_stack([params, params**2]), params, knots, n)  # nonsingular


def test_clustered_parameters_fail_schoenberg_whitney_with_uniform_knots():
    # The chapter's example: 32 distinct parameters, every basis function has one where it is nonzero, yet
    # N_5, N_6, N_7 share (0.4, 1], which holds only two of them: rank 7 of 8.
    params = np.concatenate([np.linspace(0, 0.3, 30), [0.65, 1.0]])
    knots = ap.fitting_knots(params, 8, 3)
    collocation = basis_matrix(knots, 3, params)
    assert np.all(np.any(collocation > 0, axis=0)) and np.linalg.matrix_rank(collocation) == 7
    chosen = ap.schoenberg_whitney(params, knots, 3)
    assert np.isnan(chosen[6:]).all() and not np.isnan(chosen[:6]).any()
    points = np.column_stack([params, np.sin(params)])
    with pytest.raises(ValueError, match=r"^params: the normal equations are singular: the basis function N_6, "
                                         r"nonzero on \(0\.6, 1\),"):
        ap.least_squares_fit(points, params, knots, 3)
    averaged = ap.fitting_knots(params, 8, 3, "averaging")
    assert not np.isnan(ap.schoenberg_whitney(params, averaged, 3)).any()
    ap.least_squares_fit(points, params, averaged, 3)
    ap.faired_fit(points, params, knots, 3, 1e-6)  # any positive weight pins the rest down


def test_the_singular_message_gives_the_support_open_except_at_clamped_ends():
    # Quadratic, knots [0, 0, 0.5, 1, 1] (c = 4): N_0 lives on [0, 0.5) (it is 1 at the clamped start),
    # N_3 on (0.5, 1] (1 at the clamped end), and nothing at or after 0.5 leaves N_3 without a parameter.
    knots = [0.0, 0.0, 0.5, 1.0, 1.0]
    late = np.array([0.6, 0.7, 0.8, 0.9])
    with pytest.raises(ValueError, match=r"the basis function N_0, nonzero on \[0, 0\.5\),"):
        ap.least_squares_fit(late[:, None], late, knots, 2)
    early = np.array([0.0, 0.1, 0.2, 0.3])
    with pytest.raises(ValueError, match=r"the basis function N_3, nonzero on \(0\.5, 1\],"):
        ap.least_squares_fit(early[:, None], early, knots, 2)
    # Without clamped ends (knots 0, 1, 2, 3, 4, domain [1, 3]) the supports are open at both ends.
    inner = np.array([1.0, 1.2, 1.4, 1.6])
    with pytest.raises(ValueError, match=r"the basis function N_3, nonzero on \(2, 4\),"):
        ap.least_squares_fit(inner[:, None], inner, [0.0, 1.0, 2.0, 3.0, 4.0], 2)


def test_a_knot_span_without_parameters_can_leave_the_fit_unique():
    # Cubic, knots [0, 0, 0, 1, 2, 3, 3, 3]: nothing in (1, 2), yet the condition holds and N has full rank.
    knots = [0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]
    params = np.concatenate([np.linspace(0.05, 0.95, 10), np.linspace(2.05, 2.95, 10)])
    assert not np.isnan(ap.schoenberg_whitney(params, knots, 3)).any()
    collocation = basis_matrix(knots, 3, params)
    assert np.linalg.matrix_rank(collocation) == 6 and np.linalg.cond(collocation.T @ collocation) < 100
    points = np.column_stack([params, np.cos(params)])
    np.testing.assert_allclose(ap.least_squares_fit(points, params, knots, 3),
                               np.linalg.lstsq(collocation, points, rcond=None)[0], atol=1e-10)


@pytest.mark.parametrize("seed", range(40))
def test_schoenberg_whitney_holds_exactly_when_the_collocation_matrix_has_full_rank(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 5))
    c = int(rng.integers(n + 1, n + 7))
    inner = np.sort(rng.choice(np.arange(1, 10), c - n - 1)) / 10  # on a grid: repeated knots happen
    knots = np.concatenate([np.zeros(n), inner, np.ones(n)])
    if np.max(np.unique(knots, return_counts=True)[1][1:-1], initial=0) > n:
        return
    params = rng.choice(np.arange(0, 21) / 20, int(rng.integers(1, 2 * c)))  # gaps, clusters and repeats
    chosen = ap.schoenberg_whitney(params, knots, n)
    full = np.linalg.matrix_rank(basis_matrix(knots, n, params)) == c
    assert full == (not np.isnan(chosen).any())
    picked = chosen[~np.isnan(chosen)]
    assert np.all(np.diff(picked) > 0) and np.all(np.isin(picked, params))
    columns = basis_matrix(knots, n, picked)
    assert np.all(np.diag(columns[:, : len(picked)]) > 0)  # each basis function is nonzero at its parameter


def test_fitting_knots_reject_bad_input():
    with pytest.raises(ValueError, match="^count"):
        ap.fitting_knots(np.linspace(0, 1, 5), 6, 2, "averaging")
    with pytest.raises(ValueError, match="^count"):
        ap.fitting_knots(np.linspace(0, 1, 5), 3, 3)
    with pytest.raises(ValueError, match="^params"):
        ap.fitting_knots([0.5, 0.5, 0.5], 3, 2)
    with pytest.raises(ValueError, match="^method"):
        ap.fitting_knots(np.linspace(0, 1, 5), 3, 2, "chord")


# --- 11.3: least squares -------------------------------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_banded_fit_equals_the_dense_normal_equations_and_lstsq(seed):
    points, params, knots, n = random_spline_problem(seed)
    fit = ap.least_squares_fit(points, params, knots, n)
    gram, rhs = ap.normal_equations(points, params, knots, n)
    np.testing.assert_allclose(gram, gram.T)
    np.testing.assert_allclose(fit, np.linalg.solve(gram, rhs), atol=1e-9)
    collocation = basis_matrix(knots, n, params)
    np.testing.assert_allclose(fit, np.linalg.lstsq(collocation, points, rcond=None)[0], atol=1e-9)
    # The residual is orthogonal to every basis function: the stationarity condition (11.2).
    np.testing.assert_allclose(collocation.T @ (collocation @ fit - points), 0, atol=1e-9)


@pytest.mark.parametrize("seed", SEEDS)
def test_fit_agrees_with_scipy_make_lsq_spline(seed):
    points, params, knots, n = random_spline_problem(seed, dims=1)
    fit = ap.least_squares_fit(points, params, knots, n)
    t, _, k = to_scipy(fit, knots)
    theirs = make_lsq_spline(params, points[:, 0], t, k)
    np.testing.assert_allclose(fit[:, 0], theirs.c, atol=1e-10)
    back, inner = from_scipy(theirs.t, theirs.c, theirs.k)
    np.testing.assert_allclose(inner, knots)
    np.testing.assert_allclose(back, fit, atol=1e-10)


@pytest.mark.parametrize("seed", SEEDS)
def test_fit_reproduces_a_sampled_spline(seed):
    control, knots, params, samples = sampled_spline(seed)
    np.testing.assert_allclose(ap.least_squares_fit(samples, params, knots, 3), control, atol=1e-10)
    assert ap.fit_error(samples, params, control, knots)[1] < 1e-12


def test_polynomial_data_is_reproduced_by_a_bezier_fit():
    # A cubic Bézier fit of samples of a cubic polynomial graph returns its Bernstein coefficients.
    x = np.linspace(0, 1, 9)
    poly = Polynomial([1.0, -2.0, 0.5, 3.0])
    fit = ap.least_squares_fit(np.column_stack([x, poly(x)]), x, [0, 0, 0, 1, 1, 1], 3)
    np.testing.assert_allclose(fit[:, 0], [0, 1 / 3, 2 / 3, 1], atol=1e-14)
    bernstein = [1.0, 1 - 2 / 3, 1 - 4 / 3 + 0.5 / 3, 1 - 2 + 0.5 + 3]
    np.testing.assert_allclose(fit[:, 1], bernstein, atol=1e-13)


def test_fit_at_the_end_of_the_domain_and_in_space():
    control, knots, params, samples = sampled_spline(11, n=2, c=5)
    # Only the end parameters and four interior ones: the right end must count (no half-open span there).
    chosen = [0, 3, 9, 15, 20, len(params) - 1]
    np.testing.assert_allclose(ap.least_squares_fit(samples[chosen], params[chosen], knots, 2), control, atol=1e-9)


@pytest.mark.parametrize("name", ["even_arc", "uneven_arc"])
def test_the_course_arcs_uniform_against_chord_length(name):
    example = notes_example(f"11.{name}")
    points, count, degree = example.args("points", "count", "degree")
    knots = bezier_end_knots(count, degree, 0.0, 1.0)
    for kind, params in [("uniform", ap.uniform_parameters(points)), ("chord", ap.chord_length_parameters(points))]:
        fit = ap.least_squares_fit(points, params, knots, degree)
        lsq, worst = ap.fit_error(points, params, fit, knots)
        assert float(f"{lsq:.3g}") == example.results[f"lsq_{kind}"]
        assert float(f"{worst:.3g}") == example.results[f"max_{kind}"]


def test_fit_rejects_bad_input():
    points, params, knots, n = random_spline_problem(1, degree=3)
    with pytest.raises(ValueError, match="^params: expected one parameter per sample"):
        ap.least_squares_fit(points, params[:-1], knots, n)
    with pytest.raises(ValueError, match="^params: expected values in the domain"):
        ap.least_squares_fit(points, params + 0.5, knots, n)
    with pytest.raises(ValueError, match="^knots"):
        ap.least_squares_fit(points, params, knots[::-1], n)
    with pytest.raises(ValueError, match="^degree"):
        ap.least_squares_fit(points, params, knots, 0)
    with pytest.raises(ValueError, match="^params: the normal equations are singular"):
        ap.least_squares_fit(points[:3], params[:3], knots, n)  # fewer samples than control points
    with pytest.raises(ValueError, match="^params: the normal equations are singular"):
        ap.least_squares_fit(np.ones((20, 2)), np.full(20, 0.3), [0, 0, 0, 1, 1, 1], 3)  # one distinct parameter
    with pytest.raises(ValueError, match="^params: the faired system is singular"):
        ap.faired_fit(np.ones((20, 2)), np.full(20, 0.3), [0, 0, 0, 1, 1, 1], 3, 0.1)  # a line is not pinned down
    with pytest.raises(ValueError, match="^params: expected values in the domain"):
        ap.schoenberg_whitney([0.5, 2.0], [0, 0, 1, 1], 2)


# --- 11.3.3: parameter correction -------------------------------------------------------------------


def test_projected_parameters_are_foot_points_and_never_farther():
    control, knots, params, samples = sampled_spline(3)
    rng = np.random.default_rng(3)
    noisy = samples + 0.05 * rng.normal(size=samples.shape)
    start = np.clip(params + 0.02 * rng.normal(size=params.shape), 0.0, 1.0)
    moved = ap.project_parameters(noisy, start, control, knots, steps=8)
    before = np.linalg.norm(de_boor(control, knots, start) - noisy, axis=1)
    after = np.linalg.norm(de_boor(control, knots, moved) - noisy, axis=1)
    assert np.all(after <= before)
    inner = (moved > 0) & (moved < 1)
    # At an inner foot point the offset is perpendicular to the tangent.
    offset = de_boor(control, knots, moved[inner]) - noisy[inner]
    tangent = derivative(control, knots, moved[inner], 1)
    cosine = np.sum(offset * tangent, axis=1) / (np.linalg.norm(offset, axis=1) * np.linalg.norm(tangent, axis=1))
    assert np.abs(cosine).max() < 1e-6
    # Samples on the curve itself come back to their own parameters.
    np.testing.assert_allclose(ap.project_parameters(samples, start, control, knots, steps=8), params, atol=1e-8)


def test_parameter_correction_never_raises_the_error_and_repairs_uniform_parameters():
    example = notes_example("11.uneven_arc")
    points = example.inputs["points"]
    knots = bezier_end_knots(10, 3, 0.0, 1.0)
    control, params, lsq = ap.parameter_correction(points, ap.uniform_parameters(points), knots, 3, iterations=6)
    assert np.all(np.diff(lsq) <= 1e-12) and lsq[0] == pytest.approx(example.results["lsq_uniform"], rel=1e-2)
    assert lsq[-1] < example.results["lsq_chord"]  # better than chord length without correction
    assert ap.fit_error(points, params, control, knots)[0] == pytest.approx(lsq[-1])
    faired, _, objective = ap.parameter_correction(points, ap.chord_length_parameters(points), knots, 3, 3, 1e-4)
    assert faired.shape == (10, 2) and len(objective) == 4


# --- the plain forms agree with the banded ones ---------------------------------------------------------


@pytest.mark.parametrize("seed", SEEDS)
def test_the_plain_fairing_matrix_equals_the_banded_one(seed):
    _, _, knots, n = random_spline_problem(seed, degree=int(np.random.default_rng(seed).integers(2, 6)))
    plain = ap.fairing_matrix_plain(knots, n)
    np.testing.assert_allclose(plain, ap.fairing_matrix(knots, n), rtol=1e-10, atol=1e-9 * np.abs(plain).max())
    with pytest.raises(ValueError, match="^degree"):
        ap.fairing_matrix_plain([0.0, 0.5, 1.0], 1)


def test_fit_error():
    points = np.array([[0.0, 1.0], [1.0, 1.0], [2.0, -1.0]])
    line = np.array([[0.0, 0.0], [2.0, 0.0]])  # the x-axis as a degree-1 B-spline over [0, 1]
    assert ap.fit_error(points, [0.0, 0.5, 1.0], line, [0.0, 1.0]) == (3.0, 1.0)
    with pytest.raises(ValueError, match="^control_points"):
        ap.fit_error(points, [0.0, 0.5, 1.0], [[0.0], [1.0]], [0.0, 1.0])
    with pytest.raises(ValueError, match="^knots"):
        ap.fit_error(points, [0.0, 0.5, 1.0], line, [0.0])


# --- 11.4: fairing ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", ["fairing_quadratic", "fairing_cubic", "fairing_two_spans"])
def test_fairing_matrices_of_the_course(name):
    example = notes_example(f"11.{name}")
    knots, degree = example.args("knots", "degree")
    np.testing.assert_allclose(ap.fairing_matrix(knots, degree), example.results["matrix"], atol=1e-11)


def test_fairing_matrix_of_one_segment_is_exact():
    # SymPy integrates the products of the Bernstein polynomials' second derivatives exactly.
    s = sp.symbols("s")
    for n in (2, 3, 4, 5):
        second = [sp.diff(sp.binomial(n, i) * s**i * (1 - s) ** (n - i), s, 2) for i in range(n + 1)]
        exact = np.array([[float(sp.integrate(a * b, (s, 0, 1))) for b in second] for a in second])
        np.testing.assert_allclose(ap.fairing_matrix([0.0] * n + [1.0] * n, n), exact, rtol=1e-12, atol=1e-10)


@pytest.mark.parametrize("seed", SEEDS)
def test_fairing_matrix_against_scipy_quad(seed):
    _, _, knots, n = random_spline_problem(seed, degree=int(np.random.default_rng(seed).integers(2, 6)))
    c = len(knots) - n + 1
    matrix = ap.fairing_matrix(knots, n)
    t, _, _ = to_scipy(np.zeros((c, 1)), knots)
    second = [BSpline(t, np.eye(c)[i], n).derivative(2) for i in range(c)]
    breaks = np.unique(knots)

    def integral(f, g):
        return sum(quad(lambda x: f(x) * g(x), a, b)[0] for a, b in zip(breaks, breaks[1:]))

    expected = np.array([[integral(f, g) for g in second] for f in second])
    np.testing.assert_allclose(matrix, expected, rtol=1e-9, atol=1e-9 * np.abs(expected).max())


@pytest.mark.parametrize("seed", SEEDS)
def test_fairing_matrix_properties(seed):
    _, _, knots, n = random_spline_problem(seed, degree=int(np.random.default_rng(seed).integers(2, 6)))
    matrix = ap.fairing_matrix(knots, n)
    scale = np.abs(matrix).max()
    np.testing.assert_allclose(matrix, matrix.T, atol=1e-12 * scale)
    assert np.linalg.eigvalsh(matrix).min() > -1e-10 * scale
    # Straight lines have no bending energy: constants and the Greville abscissae (x = s) are in the null space.
    np.testing.assert_allclose(matrix @ np.ones(len(matrix)), 0, atol=1e-10 * scale)
    np.testing.assert_allclose(matrix @ greville(knots, n), 0, atol=1e-9 * scale)
    i, j = np.indices(matrix.shape)
    assert np.all(matrix[np.abs(i - j) > n] == 0)
    assert np.linalg.matrix_rank(matrix) == len(matrix) - 2


def test_energy_is_the_integral_of_the_squared_second_derivative():
    control, knots, _, _ = sampled_spline(4, n=4, c=9)
    breaks = np.unique(knots)
    expected = sum(quad(lambda s: np.sum(derivative(control, knots, s, 2) ** 2), a, b)[0]
                   for a, b in zip(breaks, breaks[1:]))
    assert ap.fairing_energy(control, knots) == pytest.approx(expected, rel=1e-10)
    matrix = ap.fairing_matrix(knots, 4)
    assert ap.fairing_energy(control, knots) == pytest.approx(np.trace(control.T @ matrix @ control), rel=1e-12)
    first = sum(quad(lambda s: np.sum(derivative(control, knots, s, 1) ** 2), a, b)[0]
                for a, b in zip(breaks, breaks[1:]))
    assert ap.fairing_energy(control, knots, order=1) == pytest.approx(first, rel=1e-10)


def test_zero_length_spans_and_scaling_of_the_parameter():
    # A double knot adds no span of its own; stretching the parameter range by 2 divides the energy by 2³.
    knots = np.array([0, 0, 0, 1, 1, 2, 3, 3, 3.0])
    matrix = ap.fairing_matrix(knots, 3)
    assert np.all(np.isfinite(matrix))
    np.testing.assert_allclose(ap.fairing_matrix(2 * knots, 3), matrix / 8, rtol=1e-12, atol=1e-12)


def test_fairing_needs_degree_two():
    with pytest.raises(ValueError, match="^degree: the derivative of order 2"):
        ap.fairing_matrix([0.0, 1.0, 2.0], 1)
    with pytest.raises(ValueError, match="^degree"):
        ap.faired_fit([[0.0], [1.0]], [0.0, 1.0], [0.0, 1.0], 1, 1.0)
    np.testing.assert_allclose(ap.faired_fit([[0.0], [1.0]], [0.0, 1.0], [0.0, 1.0], 1, 0.0), [[0.0], [1.0]])


@pytest.mark.parametrize("seed", SEEDS)
def test_weight_zero_is_least_squares_and_the_faired_fit_minimises_its_objective(seed):
    points, params, knots, n = random_spline_problem(seed, degree=int(np.random.default_rng(seed).integers(2, 6)))
    np.testing.assert_allclose(ap.faired_fit(points, params, knots, n, 0.0),
                               ap.least_squares_fit(points, params, knots, n), atol=1e-12)
    weight = 10.0 ** np.random.default_rng(seed).uniform(-5, -1)
    fit = ap.faired_fit(points, params, knots, n, weight)

    def objective(ctrl):
        return ap.fit_error(points, params, ctrl, knots)[0] + weight * ap.fairing_energy(ctrl, knots)

    gram, rhs = ap.normal_equations(points, params, knots, n)
    np.testing.assert_allclose(fit, np.linalg.solve(gram + weight * ap.fairing_matrix(knots, n), rhs), atol=1e-8)
    rng = np.random.default_rng(seed + 100)
    best = objective(fit)
    assert all(objective(fit + 1e-3 * rng.normal(size=fit.shape)) > best for _ in range(5))


@pytest.mark.parametrize("lam", [1e-4, 1e-2, 1.0])
def test_faired_fit_with_knots_at_the_data_is_scipys_smoothing_spline(lam):
    rng = np.random.default_rng(5)
    x = np.sort(rng.uniform(0, 3, 25))
    y = np.sin(2 * x) + 0.1 * rng.normal(size=25)
    knots = np.concatenate([[x[0]] * 2, x, [x[-1]] * 2])  # the natural cubic spline lives in this space
    fit = ap.faired_fit(y[:, None], x, knots, 3, lam)
    xs = np.linspace(x[0], x[-1], 200)
    np.testing.assert_allclose(de_boor(fit, knots, xs)[:, 0], make_smoothing_spline(x, y, lam=lam)(xs), atol=1e-9)


def test_large_weights_shrink_the_curve_to_the_least_squares_line():
    example = notes_example("11.uneven_arc")
    points, count, degree = example.args("points", "count", "degree")
    params = ap.chord_length_parameters(points)
    knots = bezier_end_knots(count, degree, 0.0, 1.0)
    line = np.column_stack([Polynomial.fit(params, points[:, k], 1)(np.linspace(0, 1, 50)) for k in range(2)])
    lsq, energy, distance = [], [], []
    for weight in [0.0, 1e-4, 1e-2, 1.0, 1e2, 1e4]:
        fit = ap.faired_fit(points, params, knots, degree, weight)
        lsq.append(ap.fit_error(points, params, fit, knots)[0])
        energy.append(ap.fairing_energy(fit, knots))
        distance.append(np.abs(de_boor(fit, knots, np.linspace(0, 1, 50)) - line).max())
    assert np.all(np.diff(lsq) > 0) and np.all(np.diff(energy) < 0) and np.all(np.diff(distance) < 0)
    assert distance[-1] < 1e-3
    # The curve shrinks: its extent in y (the arc's height) drops from about 2.5 towards the line's.
    heights = [np.ptp(de_boor(ap.faired_fit(points, params, knots, degree, w), knots, np.linspace(0, 1, 50))[:, 1])
               for w in (0.0, 1e-2, 1.0)]
    assert heights[0] > 2.4 and heights[0] > heights[1] > heights[2]


def test_faired_fit_rejects_a_negative_weight():
    points, params, knots, n = random_spline_problem(2, degree=3)
    with pytest.raises(ValueError, match="^weight"):
        ap.faired_fit(points, params, knots, n, -1.0)


# --- 11.4.1: interpolation constraints ---------------------------------------------------------------


@pytest.mark.parametrize("weight", [0.0, 1e-4, 1e-2, 1.0, 100.0])
def test_constrained_fit_interpolates_for_every_weight(weight):
    example = notes_example("11.uneven_arc")
    points, count, degree = example.args("points", "count", "degree")
    params = ap.chord_length_parameters(points)
    knots = bezier_end_knots(count, degree, 0.0, 1.0)
    chosen = [0, 12, 29]
    fit = ap.constrained_fit(points, params, knots, degree, weight, points[chosen], params[chosen])
    np.testing.assert_allclose(de_boor(fit, knots, params[chosen]), points[chosen], atol=1e-10)


@pytest.mark.parametrize("seed", SEEDS)
def test_constrained_fit_against_scipy_minimize(seed):
    points, params, knots, n = random_spline_problem(seed, degree=3, dims=1, multiple=False)
    rng = np.random.default_rng(seed)
    c = len(knots) - n + 1
    target_params = np.sort(rng.choice(params, size=min(3, c), replace=False))
    targets = rng.normal(size=(len(target_params), 1))
    weight = 1e-3
    fit = ap.constrained_fit(points, params, knots, n, weight, targets, target_params)
    gram, rhs = ap.normal_equations(points, params, knots, n)
    hessian = gram + weight * ap.fairing_matrix(knots, n)
    rows = basis_matrix(knots, n, target_params)
    result = minimize(lambda x: x @ hessian @ x - 2 * rhs[:, 0] @ x, np.zeros(c),
                      jac=lambda x: 2 * hessian @ x - 2 * rhs[:, 0], method="trust-constr",
                      hess=lambda x: 2 * hessian,
                      constraints=[LinearConstraint(rows, targets[:, 0], targets[:, 0])],
                      options={"gtol": 1e-12, "xtol": 1e-14, "maxiter": 5000})
    np.testing.assert_allclose(fit[:, 0], result.x, atol=1e-5)
    np.testing.assert_allclose(rows @ fit, targets, atol=1e-9)


def test_constrained_fit_without_samples_in_a_span_and_with_every_point_fixed():
    # Targets alone can pin the curve: c targets of a Bézier curve give back its control points.
    control = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
    knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    u = np.array([0.0, 0.3, 0.7, 1.0])
    fit = ap.constrained_fit(control[:1] + 5.0, [0.5], knots, 3, 0.0, de_boor(control, knots, u), u)
    np.testing.assert_allclose(fit, control, atol=1e-12)


def test_constrained_fit_rejects_bad_input():
    points, params, knots, n = random_spline_problem(3, degree=3)
    c = len(knots) - n + 1
    with pytest.raises(ValueError, match="^targets: .* at most"):
        ap.constrained_fit(points, params, knots, n, 0.1, np.zeros((c + 1, 2)), np.linspace(-1, 2, c + 1))
    with pytest.raises(ValueError, match="^target_params: the constrained system is singular"):
        ap.constrained_fit(points, params, knots, n, 0.1, [[0.0, 0.0], [1.0, 1.0]], [0.5, 0.5])
    with pytest.raises(ValueError, match="^target_params: expected one parameter per target"):
        ap.constrained_fit(points, params, knots, n, 0.1, [[0.0, 0.0]], [0.5, 0.6])
    with pytest.raises(ValueError, match="^target_params: expected values in the domain"):
        ap.constrained_fit(points, params, knots, n, 0.1, [[0.0, 0.0]], [5.0])
    with pytest.raises(ValueError, match="^targets: expected points of dimension 2"):
        ap.constrained_fit(points, params, knots, n, 0.1, [[0.0, 0.0, 0.0]], [0.5])


# --- 11.4.2: within a tolerance ------------------------------------------------------------------------


def test_fit_within_tolerance_meets_it_with_the_weight_of_the_course_example():
    example = notes_example("11.uneven_arc")
    points, count, degree = example.args("points", "count", "degree")
    params = ap.chord_length_parameters(points)
    knots = bezier_end_knots(count, degree, 0.0, 1.0)
    tol = example.results["tolerance"]
    fit, weight = ap.fit_within_tolerance(points, params, knots, degree, tol)
    assert float(f"{weight:.3g}") == example.results["tolerance_weight"]
    assert ap.fit_error(points, params, fit, knots)[0] == pytest.approx(tol, rel=1e-9)
    np.testing.assert_allclose(fit, ap.faired_fit(points, params, knots, degree, weight), atol=1e-12)
    # Any fit of these knots within the tolerance bends at least as much: try the faired fits around it.
    for other in (0.5 * weight, 0.9 * weight):
        candidate = ap.faired_fit(points, params, knots, degree, other)
        assert ap.fairing_energy(candidate, knots) > ap.fairing_energy(fit, knots)


def test_fit_within_tolerance_at_the_extremes():
    points, params, knots, n = random_spline_problem(4, degree=3)
    lowest = ap.fit_error(points, params, ap.least_squares_fit(points, params, knots, n), knots)[0]
    with pytest.raises(ValueError, match="^tol: no B-spline"):
        ap.fit_within_tolerance(points, params, knots, n, 0.9 * lowest)
    line, weight = ap.fit_within_tolerance(points, params, knots, n, 1e6)
    assert weight == np.inf
    assert ap.fairing_energy(line, knots) < 1e-9
    coefficients = [Polynomial.fit(params, points[:, k], 1).convert().coef for k in range(2)]
    expected = np.column_stack([np.polynomial.polynomial.polyval(params, c) for c in coefficients])
    np.testing.assert_allclose(de_boor(line, knots, params), expected, atol=1e-10)


# --- 11.4.2: boxes ----------------------------------------------------------------------------------------


def arc_problem():
    example = notes_example("11.uneven_arc")
    points, count, degree = example.args("points", "count", "degree")
    return points, ap.chord_length_parameters(points), bezier_end_knots(count, degree, 0.0, 1.0), degree


def test_estimate_frames():
    points = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [2.0, -1.0]])
    tangents, normals = ap.estimate_frames(points)
    np.testing.assert_allclose(tangents, [[2**-0.5, 2**-0.5], [1, 0], [5**-0.5, -2 * 5**-0.5], [0, -1]], atol=1e-15)
    np.testing.assert_allclose(np.sum(tangents * normals, axis=1), 0, atol=1e-15)
    np.testing.assert_allclose(tangents[:, 0] * normals[:, 1] - tangents[:, 1] * normals[:, 0], 1)  # on the left
    with pytest.raises(ValueError, match="^points: no tangent at sample 1"):
        ap.estimate_frames([[0.0, 0.0], [1.0, 1.0], [0.0, 0.0]])
    with pytest.raises(ValueError, match="^points: tangent and normal boxes are planar"):
        ap.estimate_frames(np.zeros((3, 3)))


def test_estimate_frames_from_a_first_fit():
    points, params, knots, n = arc_problem()
    fit = ap.least_squares_fit(points, params, knots, n)
    tangents, normals = ap.estimate_frames(points, fit, knots, params)
    speed = derivative(fit, knots, params, 1)
    np.testing.assert_allclose(tangents, speed / np.linalg.norm(speed, axis=1)[:, None], atol=1e-14)
    np.testing.assert_allclose(normals, np.column_stack([-tangents[:, 1], tangents[:, 0]]), atol=0)
    # The notes' estimate Q_(k+1) - Q_(k-1) is poor where neighbours are closer than the noise:
    # at the last sample of the course's uneven arc it is over 45° off the fit's tangent.
    notes_tangents, _ = ap.estimate_frames(points)
    cosines = np.abs(np.sum(notes_tangents * tangents, axis=1))
    assert cosines[-1] < np.cos(np.radians(45)) and np.median(cosines) > np.cos(np.radians(10))
    with pytest.raises(ValueError, match="^params: expected one parameter per sample"):
        ap.estimate_frames(points, fit, knots, params[:-1])
    with pytest.raises(ValueError, match="^control_points: expected a planar curve"):
        ap.estimate_frames(points, np.zeros((len(fit), 3)), knots, params)
    with pytest.raises(ValueError, match="^points: no tangent at sample 0: the curve's tangent vanishes"):
        ap.estimate_frames([[0.0, 0.0], [1.0, 0.0]], [[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]], [0, 0, 1, 1], [0.0, 1.0])


def test_curve_boxes_along_the_fit_bound_the_deviations_in_the_fit_frames():
    points, params, knots, n = arc_problem()
    sizes = np.tile([0.3, 0.1], (len(points), 1))
    fit = ap.box_faired_fit(points, params, knots, n, sizes, frame="fit")
    tangents, normals = ap.estimate_frames(points, ap.least_squares_fit(points, params, knots, n), knots, params)
    offset = de_boor(fit, knots, params) - points
    assert np.abs(np.sum(offset * tangents, axis=1)).max() <= 0.3 * (1 + 1e-6)
    assert np.abs(np.sum(offset * normals, axis=1)).max() <= 0.1 * (1 + 1e-6)
    notes = ap.box_faired_fit(points, params, knots, n, sizes, frame="curve")
    assert ap.fairing_energy(fit, knots) < ap.fairing_energy(notes, knots)


def test_axis_boxes_of_the_course_example():
    points, params, knots, n = arc_problem()
    example = notes_example("11.uneven_arc")
    h = example.results["half_width"]
    fit = ap.box_faired_fit(points, params, knots, n, h)
    deviation = np.abs(de_boor(fit, knots, params) - points)
    assert deviation.max() <= h * (1 + 1e-6)
    assert np.sum(deviation > h * (1 - 1e-6)) >= 2  # some boxes are active
    lsq = ap.least_squares_fit(points, params, knots, n)
    assert round(ap.fairing_energy(lsq, knots)) == example.results["energy_lsq"]
    assert round(ap.fairing_energy(fit, knots)) == example.results["energy_box"]


def test_axis_boxes_against_trust_constr():
    points, params, knots, n = arc_problem()
    fit = ap.box_faired_fit(points, params, knots, n, 0.15)
    rows = basis_matrix(knots, n, params)
    hessian = ap.fairing_matrix(knots, n)
    expected = ap.fairing_energy(fit, knots)
    energy = 0.0
    for k in range(2):
        result = minimize(lambda x: x @ hessian @ x, fit[:, k] + 0.01, jac=lambda x: 2 * hessian @ x,
                          hess=lambda x: 2 * hessian, method="trust-constr",
                          constraints=[LinearConstraint(rows, points[:, k] - 0.15, points[:, k] + 0.15)],
                          options={"gtol": 1e-10, "xtol": 1e-12, "maxiter": 3000})
        energy += result.fun
    assert expected == pytest.approx(energy, rel=1e-5)


def test_curve_boxes_bound_the_tangential_and_normal_deviations():
    points, params, knots, n = arc_problem()
    sizes = np.tile([0.3, 0.08], (len(points), 1))
    fit = ap.box_faired_fit(points, params, knots, n, sizes, frame="curve")
    tangents, normals = ap.estimate_frames(points)
    offset = de_boor(fit, knots, params) - points
    assert np.abs(np.sum(offset * tangents, axis=1)).max() <= 0.3 * (1 + 1e-6)
    assert np.abs(np.sum(offset * normals, axis=1)).max() <= 0.08 * (1 + 1e-6)
    wider = ap.box_faired_fit(points, params, knots, n, 0.08)
    assert ap.fairing_energy(fit, knots) < ap.fairing_energy(ap.least_squares_fit(points, params, knots, n), knots)
    assert wider.shape == fit.shape == (len(knots) - n + 1, 2)


@pytest.mark.parametrize("seed", SEEDS)
def test_box_programme_against_slsqp(seed):
    rng = np.random.default_rng(seed)
    k, m = int(rng.integers(2, 8)), int(rng.integers(3, 15))
    root = rng.normal(size=(k, k))
    hessian = root @ root.T + 0.1 * np.eye(k)
    linear, rows = rng.normal(size=k), rng.normal(size=(m, k))
    centre = rows @ rng.normal(size=k)  # a feasible point exists: the boxes are around its image
    lower, upper = centre - rng.uniform(0.05, 0.5, m), centre + rng.uniform(0.05, 0.5, m)
    x = ap.box_programme(hessian, linear, rows, lower, upper)
    assert np.all(rows @ x >= lower - 1e-9) and np.all(rows @ x <= upper + 1e-9)
    # SLSQP's active set ends on the constraints exactly (trust-constr stops a little inside them).
    result = minimize(lambda z: 0.5 * z @ hessian @ z + linear @ z, np.zeros(k), jac=lambda z: hessian @ z + linear,
                      method="SLSQP", options={"ftol": 1e-15, "maxiter": 1000},
                      constraints=[{"type": "ineq", "fun": lambda z: rows @ z - lower, "jac": lambda z: rows},
                                   {"type": "ineq", "fun": lambda z: upper - rows @ z, "jac": lambda z: -rows}])
    np.testing.assert_allclose(x, result.x, atol=1e-8)
    # Equal bounds are equality constraints; unbounded ones leave the unconstrained minimiser.
    free = ap.box_programme(hessian, linear, rows, np.full(m, -1e9), np.full(m, 1e9))
    np.testing.assert_allclose(free, np.linalg.solve(hessian, -linear), atol=1e-7)


def test_box_programme_reports_infeasible_and_bad_shapes():
    rows = np.array([[1.0], [1.0]])
    with pytest.raises(ValueError, match="^no point meets every constraint"):
        ap.box_programme(np.eye(1), np.zeros(1), rows, [0.0, 2.0], [1.0, 3.0])  # x in [0, 1] and in [2, 3]
    with pytest.raises(ValueError, match="^lower"):
        ap.box_programme(np.eye(1), np.zeros(1), rows, [1.0, 2.0], [0.0, 3.0])
    with pytest.raises(ValueError, match="^rows"):
        ap.box_programme(np.eye(2), np.zeros(1), rows, [0.0, 2.0], [1.0, 3.0])


def test_boxes_reject_bad_input():
    points, params, knots, n = arc_problem()
    with pytest.raises(ValueError, match="^half_width: no point meets every constraint"):
        ap.box_faired_fit(points, params, knots, n, 0.02)
    with pytest.raises(ValueError, match="^half_width: box sizes must be positive"):
        ap.box_faired_fit(points, params, knots, n, 0.0)
    with pytest.raises(ValueError, match="^half_width: expected"):
        ap.box_faired_fit(points, params, knots, n, np.ones((3, 2)))
    with pytest.raises(ValueError, match="^frame"):
        ap.box_faired_fit(points, params, knots, n, 0.1, frame="normal")


# --- curvature ----------------------------------------------------------------------------------------------


def test_curvature_of_a_parabola_and_a_helix_arc():
    # y = x² as a quadratic Bézier curve over [0, 1]: κ(x) = 2 / (1 + 4x²)^(3/2).
    x = np.linspace(0, 1, 7)
    kappa = ap.spline_curvature([[0.0, 0.0], [0.5, 0.0], [1.0, 1.0]], [0.0, 0.0, 1.0, 1.0], x)
    np.testing.assert_allclose(kappa, 2 / (1 + 4 * x**2) ** 1.5, rtol=1e-12)
    assert ap.spline_curvature([[0.0, 0.0], [0.5, 0.0], [1.0, -1.0]], [0.0, 0.0, 1.0, 1.0], 0.0) == -2.0
    spatial = ap.spline_curvature([[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [1.0, 1.0, 0.0]], [0, 0, 1, 1.0], x)
    np.testing.assert_allclose(spatial, kappa, rtol=1e-12)
    with pytest.raises(ValueError, match="^t: the curve stops"):
        ap.spline_curvature([[0.0, 0.0], [0.0, 0.0], [1.0, 1.0]], [0.0, 0.0, 1.0, 1.0], 0.0)


def test_checked_params_name_what_is_wrong():
    np.testing.assert_array_equal(ap.checked_params([0.5, 0.0, 1], [0, 0, 1, 1], 2), [0.5, 0.0, 1.0])
    with pytest.raises(ValueError, match="^params: expected values in the domain"):
        ap.checked_params([0.5, 1.5], [0, 0, 1, 1], 2)
    with pytest.raises(ValueError, match="^params"):
        ap.checked_params([[0.5]], [0, 0, 1, 1], 2)
    with pytest.raises(ValueError, match="^knots"):
        ap.checked_params([0.5], [1, 0, 0, 1], 2)

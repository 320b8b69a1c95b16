"""Unit tests of cagd_ref.hybrid: hybrid curves, closed-form integrals, error bounds, the adaptive area (chapter 20).

The notes' semicircle and the course's examples come from
cagd_course/examples/ch20.toml. Independent peers: SymPy integrates the
polynomial integrands exactly (with exact rational control points),
scipy.integrate.quad integrates y x', ½(x y' - y x') and π y² x' along seeded
random rational curves with positive weights, and dense sampling measures the
distance between a curve and its polynomial approximation.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import hybrid as hy

SEMICIRCLE = notes_example("20.semicircle")
EXAMPLE_1 = notes_example("20.example_1")
QUARTER = notes_example("20.quarter_circle")
TS = np.linspace(0, 1, 11)
INTEGRANDS = {
    "area": lambda p, d: p[1] * d[0],
    "sector": lambda p, d: 0.5 * (p[0] * d[1] - p[1] * d[0]),
    "volume": lambda p, d: np.pi * p[1] ** 2 * d[0],
}


def random_rational(seed: int, degree: int | None = None):
    """Seeded planar control points (r+1, 2) and positive weights (r+1,), weight ratios up to 10."""
    rng = np.random.default_rng(seed)
    r = int(rng.integers(2, 5)) if degree is None else degree
    return rng.uniform(-3, 3, (r + 1, 2)), rng.uniform(0.3, 3.0, r + 1)


def by_quad(points, weights, kind: str) -> float:
    """The integral along the curve by scipy.integrate.quad of the integrand in t (an independent peer)."""
    f = INTEGRANDS[kind]

    def integrand(t):
        return f(bezier.evaluate(points, t, weights), bezier.derivative(points, t, 1, weights))

    value, _ = quad(integrand, 0.0, 1.0, epsabs=1e-12, epsrel=1e-12, limit=200)
    return value


def integral_01(expression, t) -> sp.Rational:
    """The exact integral over [0, 1] of a polynomial in t (through its antiderivative: fast, unlike sp.integrate)."""
    antiderivative = sp.Poly(sp.expand(expression), t).integrate()
    return antiderivative.eval(1) - antiderivative.eval(0)


def exact_integral(points: list[tuple[Fraction, Fraction]], kind: str) -> Fraction:
    """SymPy's exact integral over [0, 1] of a polynomial Bézier curve's integrand, exact control points."""
    t = sp.symbols("t")
    n = len(points) - 1
    basis = [sp.binomial(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]
    x = sum(sp.Rational(p[0]) * b for p, b in zip(points, basis))
    y = sum(sp.Rational(p[1]) * b for p, b in zip(points, basis))
    integrand = {"area": y * sp.diff(x, t), "sector": (x * sp.diff(y, t) - y * sp.diff(x, t)) / 2,
                 "volume": y**2 * sp.diff(x, t), "moment_x": y**2 * sp.diff(x, t) / 2,
                 "moment_y": x * y * sp.diff(x, t)}[kind]
    return integral_01(integrand, t)


def exact_points(seed: int, n: int) -> list[tuple[Fraction, Fraction]]:
    rng = np.random.default_rng(seed)
    return [(Fraction(int(a), 4), Fraction(int(b), 4)) for a, b in rng.integers(-12, 13, (n + 1, 2))]


# --- hybrid curves -------------------------------------------------------------------------------


def test_the_semicircle_as_quadratic_and_quartic_hybrids():
    points, weights = SEMICIRCLE.args("points", "weights")
    res = SEMICIRCLE.results
    for n, name in ((2, "quadratic"), (4, "quartic")):
        h = hy.hybrid_curve(points, weights, n)
        assert h.m == n // 2 and np.isnan(h.fixed[h.m]).all()
        np.testing.assert_allclose(np.delete(h.fixed, h.m, axis=0), res[f"{name}_fixed"], atol=1e-15)
        np.testing.assert_allclose(h.moving, res[f"{name}_moving"], rtol=1e-14)
        np.testing.assert_array_equal(h.weights, weights)
        centre, half = hy.moving_box(h)
        assert np.linalg.norm(half) == pytest.approx(res[f"{name}_delta"], rel=1e-14)
        for piece in bezier.subdivide(bezier.to_homogeneous(points, weights), 0.5):  # Figure 20.2: the box shrinks
            p, w = bezier.from_homogeneous(piece)
            half_box = hy.moving_box(hy.hybrid_curve(p, w, n))[1]
            assert np.linalg.norm(half_box) == pytest.approx(res[f"{name}_delta_half"], rel=1e-12)
        P, bound = hy.polynomial_approximation(points, weights, n)
        np.testing.assert_allclose(P[n // 2], centre)
        assert hy.polynomial_area(P) == pytest.approx(res[f"{name}_area"], rel=1e-14)
        assert bound == pytest.approx(res[f"{name}_bound"], rel=1e-14)
    np.testing.assert_allclose(hy.hybrid_point(hy.hybrid_curve(points, weights, 4), 0.5), res["point_at_half"])


@pytest.mark.parametrize("r", [0, 1, 2, 3, 4])
@pytest.mark.parametrize("n", [2, 3, 4, 5, 6, 8])
def test_the_hybrid_curve_is_the_rational_curve_for_every_split_point(r, n):
    points, weights = random_rational(10 * r + n, degree=r)
    expected = bezier.evaluate(points, TS, weights)
    for m in range(1, n):
        h = hy.hybrid_curve(points, weights, n, m)
        assert h.m == m
        np.testing.assert_allclose(h.fixed[[0, -1]], points[[0, -1]], atol=1e-12)  # it starts at R0, ends at Rr
        got = hy.hybrid_point(h, TS)
        scale = np.abs(np.delete(h.fixed, m, axis=0)).max() + np.abs(h.moving).max()
        np.testing.assert_allclose(got, expected, atol=1e-13 * scale)
        # M(t) is the rational curve of the moving points with the original weights.
        basis = bezier.bernstein_matrix(n, TS)
        fixed_part = np.delete(basis, m, axis=1) @ np.delete(h.fixed, m, axis=0)
        moving = bezier.evaluate(h.moving, TS, weights)
        np.testing.assert_allclose(fixed_part + basis[:, m : m + 1] * moving, expected, atol=1e-13 * scale)


@pytest.mark.parametrize("r, n", [(2, 2), (2, 4), (3, 5), (1, 3)])
def test_a_polynomial_curve_has_a_moving_point_that_stands_still(r, n):
    points = np.random.default_rng(r * n).uniform(-2, 2, (r + 1, 2))
    elevated = bezier.elevate(points, n - r)
    for m in range(1, n):
        h = hy.hybrid_curve(points, np.full(r + 1, 2.5), n, m)
        np.testing.assert_allclose(np.delete(h.fixed, m, axis=0), np.delete(elevated, m, axis=0), atol=1e-13)
        np.testing.assert_allclose(h.moving, np.broadcast_to(elevated[m], h.moving.shape), atol=1e-13)


def test_hybrid_curves_in_three_dimensions():
    points, weights = np.random.default_rng(3).uniform(-1, 1, (4, 3)), np.array([1.0, 2.0, 0.5, 1.5])
    h = hy.hybrid_curve(points, weights, 5, 2)
    np.testing.assert_allclose(hy.hybrid_point(h, TS), bezier.evaluate(points, TS, weights), atol=1e-12)


@pytest.mark.parametrize("call, name", [
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0, 1.0], 1), "degree"),
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0, 1.0], 4, 0), "m"),
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0, 1.0], 4, 4), "m"),
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0, -1.0], 4), "weights"),
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0, 0.0], 4), "weights"),
    (lambda: hy.hybrid_curve([(0.0, 0.0), (1.0, 1.0)], [1.0], 4), "weights"),
    (lambda: hy.hybrid_point(("not", "a hybrid"), 0.5), "hybrid"),
])
def test_bad_hybrid_input_is_refused_by_name(call, name):
    with pytest.raises((ValueError, TypeError), match=rf"^{name}\b"):
        call()


@pytest.mark.parametrize("seed", range(8))
@pytest.mark.parametrize("n", [2, 4, 6])
def test_the_a_priori_bound_holds_and_the_approximation_interpolates_the_ends(seed, n):
    points, weights = random_rational(seed)
    P, bound = hy.polynomial_approximation(points, weights, n)
    ts = np.linspace(0, 1, 2001)
    distance = np.linalg.norm(bezier.evaluate(P, ts) - bezier.evaluate(points, ts, weights), axis=1)
    assert distance.max() <= bound * (1 + 1e-12)
    np.testing.assert_allclose(P[[0, -1]], points[[0, -1]], atol=1e-12)


def test_max_bernstein_is_the_maximum_of_the_basis_function():
    ts = np.linspace(0, 1, 100001)
    for n in range(1, 9):
        for m in range(n + 1):
            assert hy.max_bernstein(n, m) == pytest.approx(bezier.bernstein(m, n, ts).max(), rel=1e-8)
    assert hy.max_bernstein(4, 2) == 6 / 16  # C(n, n/2) / 2^n


# --- closed-form integrals -----------------------------------------------------------------------


def exact_area_matrix(n: int) -> list[list[Fraction]]:
    """A_ij = ∫ B_i^n (B_j^n)' dt with Fractions, by expanding the Bernstein polynomials in the power basis."""
    t = sp.symbols("t")
    basis = [sp.binomial(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]
    return [[integral_01(bi * sp.diff(bj, t), t) for bj in basis] for bi in basis]


def test_the_area_matrices_are_the_exact_tables():
    tables = notes_example("20.area_matrices").results
    for n in (1, 2, 3):
        np.testing.assert_allclose(hy.area_matrix(n), tables[f"n{n}"], rtol=1e-14, atol=1e-16)
    for n in range(1, 7):
        exact = np.array(exact_area_matrix(n), dtype=float)
        np.testing.assert_allclose(hy.area_matrix(n), exact, rtol=1e-13, atol=1e-15)
        A = hy.area_matrix(n)
        expected = np.zeros((n + 1, n + 1))
        expected[0, 0], expected[n, n] = -1, 1
        np.testing.assert_allclose(A + A.T, expected, atol=1e-14)  # ∫ (B_i B_j)' = [B_i B_j] from 0 to 1
    np.testing.assert_array_equal(hy.area_matrix(0), [[0.0]])


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_the_moment_tensor_matches_sympy(n):
    t = sp.symbols("t")
    basis = [sp.binomial(n, i) * (1 - t) ** (n - i) * t**i for i in range(n + 1)]
    T = hy.moment_tensor(n)
    for i in range(n + 1):
        for j in range(n + 1):
            for k in range(n + 1):
                exact = integral_01(basis[i] * basis[j] * sp.diff(basis[k], t), t)
                assert T[i, j, k] == pytest.approx(float(exact), abs=1e-14)


@pytest.mark.parametrize("seed", range(5))
@pytest.mark.parametrize("n", [1, 2, 3, 5])
def test_closed_forms_are_the_exact_integrals(seed, n):
    exact = exact_points(seed, n)
    points = np.array(exact, dtype=float)
    ix, iy = hy.first_moments(points)
    got = {"area": hy.polynomial_area(points), "sector": hy.sector_area(points),
           "volume": hy.revolution_volume(points) / np.pi, "moment_x": ix, "moment_y": iy}
    for kind, value in got.items():
        assert value == pytest.approx(float(exact_integral(exact, kind)), rel=1e-12, abs=1e-12), kind
    for kind in hy.KINDS:  # the independent Bernstein-product form agrees
        direct = {"area": got["area"], "sector": got["sector"], "volume": np.pi * got["volume"]}[kind]
        assert hy.polynomial_integral(points, kind) == pytest.approx(direct, rel=1e-12, abs=1e-12)


def test_the_notes_and_course_examples_of_closed_forms():
    cubic = notes_example("20.cubic_area")
    assert hy.polynomial_area(cubic.inputs["points"]) == pytest.approx(cubic.results["area"], rel=1e-14)
    sector = notes_example("20.parabolic_sector")
    assert hy.sector_area(sector.inputs["points"]) == pytest.approx(sector.results["sector"], rel=1e-14)
    cone = notes_example("20.cone")
    assert hy.revolution_volume(cone.inputs["points"]) == pytest.approx(cone.results["volume"], rel=1e-14)
    assert hy.revolution_volume(cone.inputs["points"][::-1]) == pytest.approx(-cone.results["volume"], rel=1e-14)


def test_the_sector_area_of_a_closed_chain_is_the_enclosed_area_counterclockwise_positive():
    square = np.array([(1.0, 1.0), (3.0, 1.0), (3.0, 2.0), (1.0, 2.0)])
    edges = [square[[i, (i + 1) % 4]] for i in range(4)]
    assert sum(hy.sector_area(e) for e in edges) == pytest.approx(2.0)
    assert sum(hy.sector_area(e[::-1]) for e in edges) == pytest.approx(-2.0)
    # A closed cubic loop against the shoelace formula on a dense polyline.
    loop = np.array([(0.0, 0.0), (4.0, 1.0), (-1.0, 3.0), (0.0, 0.0)])
    dense = bezier.evaluate(loop, np.linspace(0, 1, 20001))
    shoelace = 0.5 * np.sum(dense[:-1, 0] * dense[1:, 1] - dense[1:, 0] * dense[:-1, 1])
    assert hy.sector_area(loop) == pytest.approx(shoelace, rel=1e-7)
    assert hy.sector_area(loop) == pytest.approx(hy.sector_area(loop + [5.0, -2.0]), rel=1e-12)  # closed: no origin


@pytest.mark.parametrize("seed", range(4))
def test_first_moments_and_volumes_against_quad(seed):
    points = np.random.default_rng(seed).uniform(-2, 2, (int(3 + seed), 2))
    ix, iy = hy.first_moments(points)
    x_moment = quad(lambda t: 0.5 * bezier.evaluate(points, t)[1] ** 2 * bezier.derivative(points, t)[0], 0, 1)[0]
    y_moment = quad(lambda t: np.prod(bezier.evaluate(points, t)) * bezier.derivative(points, t)[0], 0, 1)[0]
    assert ix == pytest.approx(x_moment, rel=1e-10, abs=1e-12)
    assert iy == pytest.approx(y_moment, rel=1e-10, abs=1e-12)
    assert hy.revolution_volume(points) == pytest.approx(2 * np.pi * ix, rel=1e-13)


def test_degenerate_curves_and_bad_points():
    assert hy.polynomial_area([(2.0, 3.0)]) == 0.0 and hy.sector_area([(2.0, 3.0)]) == 0.0
    assert hy.polynomial_area([(0.0, 1.0), (2.0, 3.0)]) == pytest.approx(4.0)  # the trapezoid
    for function in (hy.polynomial_area, hy.sector_area, hy.revolution_volume, hy.first_moments):
        with pytest.raises(ValueError, match=r"^points\b"):
            function([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)])
    with pytest.raises(ValueError, match=r"^kind\b"):
        hy.polynomial_integral([(0.0, 0.0), (1.0, 1.0)], "length")


# --- error bounds and the adaptive method ------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("n", [2, 4, 6])
def test_the_error_bounds_hold_against_quad(seed, n):
    points, weights = random_rational(seed + 20)
    bounds = hy.integral_error_bounds(points, weights, n)
    P, _ = hy.polynomial_approximation(points, weights, n)
    for kind in hy.KINDS:
        error = abs(by_quad(points, weights, kind) - hy.polynomial_integral(P, kind))
        assert error <= bounds[kind] + 1e-12, kind


@pytest.mark.parametrize("tol", [1e-3, 1e-6, 1e-9, 1e-12])
def test_the_semicircle_area_is_within_tol_of_pi_over_8_and_reverses_sign(tol):
    points, weights = SEMICIRCLE.args("points", "weights")
    exact = SEMICIRCLE.results["area"]
    result = hy.adaptive_integral(points, weights, tol)
    assert abs(result.value - exact) <= result.bound + 1e-15 and result.bound <= tol
    assert hy.bezier_area(points, weights, tol) == result.value
    assert abs(hy.bezier_area(points[::-1], weights[::-1], tol) + exact) <= tol
    # The quartic hybrid (the notes' choice of figure) gets there too, in the plain recursive form.
    assert abs(hy.adaptive_area_plain(points, weights, tol, degree=4) - exact) <= tol


def test_the_notes_printed_semicircle_digits_are_within_their_tolerances_only():
    points, weights = SEMICIRCLE.args("points", "weights")
    res = SEMICIRCLE.results
    for tol, printed in ((1e-3, res["notes_area_tol_1e3"]), (1e-6, res["notes_area_tol_1e6"])):
        assert abs(printed - res["area"]) <= tol  # the notes' values honour their tolerances ...
        assert abs(hy.bezier_area(points, weights, tol) - res["area"]) <= tol  # ... and so does ours
    volume = hy.adaptive_integral(points, weights, 1e-10, kind="volume").value
    assert volume == pytest.approx(res["volume"], abs=1e-10)  # a ball of radius 1/2


def test_the_quarter_circle_and_example_1():
    points, weights = QUARTER.args("points", "weights")
    assert hy.bezier_area(points, weights, 1e-10) == pytest.approx(QUARTER.results["area"], abs=1e-10)
    sector = hy.adaptive_integral(points, weights, 1e-10, kind="sector").value
    assert sector == pytest.approx(QUARTER.results["sector"], abs=1e-10)
    points, weights = EXAMPLE_1.args("points", "weights")
    for kind in hy.KINDS:
        assert by_quad(points, weights, kind) == pytest.approx(EXAMPLE_1.results[kind], rel=1e-11)
        value = hy.adaptive_integral(points, weights, 1e-8, kind=kind).value
        assert abs(value - EXAMPLE_1.results[kind]) <= 1e-8 + 1e-12 * abs(EXAMPLE_1.results[kind])


@pytest.mark.parametrize("seed", range(10))
@pytest.mark.parametrize("tol", [1e-4, 1e-9])
def test_adaptive_integrals_of_random_rational_curves_against_quad(seed, tol):
    points, weights = random_rational(seed + 40)
    for kind in hy.KINDS:
        result = hy.adaptive_integral(points, weights, tol, kind=kind)
        assert abs(result.value - by_quad(points, weights, kind)) <= result.bound + 1e-11
        assert result.bound <= tol
    assert hy.bezier_area(points, weights, tol) == hy.adaptive_integral(points, weights, tol).value


@pytest.mark.parametrize("seed", range(5))
def test_the_plain_recursive_form_computes_the_same_area(seed):
    points, weights = random_rational(seed + 60)
    for degree in (2, 4, 6):
        batched = hy.adaptive_integral(points, weights, 1e-8, degree=degree).value
        assert hy.adaptive_area_plain(points, weights, 1e-8, degree) == pytest.approx(batched, rel=1e-13, abs=1e-14)


def test_polynomial_curves_and_equal_weights_are_exact_at_once():
    cubic = notes_example("20.cubic_area").inputs["points"]
    result = hy.adaptive_integral(cubic, None, 1e-3)
    assert result == (pytest.approx(0.6, rel=1e-15), 0.0, 1, 1)
    assert hy.bezier_area(cubic, [2.0, 2.0, 2.0, 2.0], 1e-3) == pytest.approx(0.6, rel=1e-15)
    assert hy.bezier_area([(0.0, 1.0), (2.0, 3.0)], [1.0, 5.0]) == pytest.approx(4.0)  # a rational line: its chord
    assert hy.bezier_area([(1.0, 1.0)]) == 0.0


def test_halving_a_piece_shrinks_its_bound_by_about_two_to_the_n_plus_two():
    h = bezier.to_homogeneous(*SEMICIRCLE.args("points", "weights"))[None]
    for n in (2, 4, 6):
        piece, bounds = h, []
        for _ in range(5):
            bounds.append(hy._piece_bounds(piece, n, n // 2, "area")[1][0])
            piece = hy._split(piece)[:1]
        assert np.all(np.log2(np.array(bounds[:-1]) / bounds[1:])[1:] >= n + 1.5)


def test_the_notes_comparison_the_trapezoid_rule_needs_many_more_pieces():
    points, weights = SEMICIRCLE.args("points", "weights")
    exact = SEMICIRCLE.results["area"]
    for tol in (1e-3, 1e-6):
        trapezoids = hy.trapezoid_area(points, weights, tol)
        assert abs(trapezoids.value - exact) <= trapezoids.bound <= tol
        hybrid = hy.adaptive_integral(points, weights, tol)
        assert trapezoids.work > 10 * hybrid.work
        simpson = hy.simpson_area(points, weights, tol)
        assert abs(simpson.value - exact) <= 10 * tol and simpson.work == simpson.pieces + 1


@pytest.mark.parametrize("tol", [0.0, -1e-6, 1e-15])
def test_impossible_tolerances_are_refused(tol):
    points, weights = SEMICIRCLE.args("points", "weights")
    for function in (hy.bezier_area, hy.adaptive_integral, hy.trapezoid_area, hy.simpson_area):
        with pytest.raises(ValueError, match=r"^tol\b"):
            function(points, weights, tol)
    # The floor scales with the curve: 1e-11 is fine for the unit semicircle, not for one a hundred times larger.
    assert abs(hy.bezier_area(points, weights, 1e-11) - SEMICIRCLE.results["area"]) <= 1e-11
    with pytest.raises(ValueError, match=r"^tol\b"):
        hy.bezier_area(100 * points, weights, 1e-11)


def test_bad_curves_are_refused_by_name():
    with pytest.raises(ValueError, match=r"^weights\b"):
        hy.bezier_area([(0.0, 0.0), (1.0, 1.0), (2.0, 0.0)], [1.0, -1.0, 1.0])
    with pytest.raises(ValueError, match=r"^points\b"):
        hy.bezier_area([(0.0, 0.0, 1.0), (1.0, 1.0, 1.0)])
    with pytest.raises(ValueError, match=r"^kind\b"):
        hy.adaptive_integral([(0.0, 0.0), (1.0, 1.0)], kind="moment")

"""Unit tests of cagd_ref.offsets: offset curves, their cusps, PH curves and exact rational offsets (chapter 8).

The course's examples of chapter 8 (the notes print none) come from
cagd_course/examples/ch08.toml. Every function is also checked against an
independent computation: central finite differences for the offset's
derivative, dense sampling with scipy.optimize.brentq and numpy.roots for the
cusps, SymPy for the PH identities and for the implicit degree of the
parabola's offset.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq, minimize_scalar

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import offsets as o
from cagd_ref.bspline import de_boor
from cagd_ref.polynomials import bernstein_horner, bernstein_multiply, bernstein_to_power

ARCH = notes_example("08.arch")
INFLECTION = notes_example("08.inflection")
PH = notes_example("08.ph_cubic")
PH_OFFSET = notes_example("08.ph_offset")
PARABOLA = notes_example("08.parabola")
TS = np.linspace(0, 1, 41)


def random_curve(seed: int, rational: bool = False):
    """A random planar Bézier curve of degree 2-5 (and positive weights), moving at a healthy speed everywhere."""
    rng = np.random.default_rng(seed)
    while True:
        points = rng.uniform(-5, 5, (int(rng.integers(3, 7)), 2))
        weights = rng.uniform(0.3, 3.0, len(points)) if rational else None
        speed = np.linalg.norm(bezier.derivative(points, np.linspace(0, 1, 201), 1, weights), axis=1)
        if speed.min() > 0.05 * speed.max():
            return points, weights


def kappa(points, t, weights=None):
    return bezier.signed_curvature(points, t, weights)


def cusps_by_sampling(points, rho, weights=None, count=20001) -> np.ndarray:
    """Sign changes of 1 + ρκ on a fine grid, each refined by brentq: an independent cusp finder."""
    ts = np.linspace(0, 1, count)
    g = 1 + rho * kappa(points, ts, weights)
    brackets = np.flatnonzero(np.sign(g[:-1]) * np.sign(g[1:]) < 0)
    return np.array([brentq(lambda t: 1 + rho * kappa(points, t, weights), ts[i], ts[i + 1], xtol=1e-15)
                     for i in brackets])


# --- the offset, its normal and its side --------------------------------------------------------


def test_the_arch_example():
    points, t, rho = ARCH.args("points", "t", "rho")
    np.testing.assert_allclose(bezier.evaluate(points, t), ARCH.results["point"])
    np.testing.assert_allclose(o.offset_normal(points, t), ARCH.results["normal"], atol=1e-15)
    np.testing.assert_allclose(o.offset_point(points, t, rho), ARCH.results["offset_point"], atol=1e-15)
    assert kappa(points, t) == pytest.approx(ARCH.results["curvature"], rel=1e-14)
    num, speed2 = o.curvature_polynomials(points)
    # Degree 2n - 3 = 3 in Bernstein form; the arch's symmetry makes the t³ term vanish.
    np.testing.assert_allclose(bernstein_to_power(num), np.append(ARCH.results["cross_power"], 0), atol=1e-12)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("rational", [False, True])
def test_the_offset_is_at_distance_rho_on_the_right(seed, rational):
    points, weights = random_curve(seed, rational)
    q = bezier.evaluate(points, TS, weights)
    first = bezier.derivative(points, TS, 1, weights)
    for rho in (0.7, -1.3):
        step = o.offset_point(points, TS, rho, weights) - q
        np.testing.assert_allclose(np.linalg.norm(step, axis=1), abs(rho), rtol=1e-12)
        np.testing.assert_allclose(np.einsum("ij,ij->i", step, first), 0, atol=1e-9)
        # first × step < 0: the step points to the right of the direction of travel when ρ > 0.
        cross = first[:, 0] * step[:, 1] - first[:, 1] * step[:, 0]
        assert np.all(np.sign(cross) == -np.sign(rho))


def test_offsets_of_a_circle_are_concentric_circles():
    points, weights = bezier.circular_arc([1.0, 2.0], 3.0, 0.2, 2.5)  # counterclockwise: the centre is on the left
    for rho in (0.5, -1.0, 4.0):
        radii = np.linalg.norm(o.offset_point(points, TS, rho, weights) - [1.0, 2.0], axis=1)
        np.testing.assert_allclose(radii, 3.0 + rho, rtol=1e-13)


def test_a_scalar_parameter_gives_a_point_and_the_inputs_stay():
    points = ARCH.inputs["points"]
    single = o.offset_point(points, 0.25, 0.5)
    assert single.shape == (2,)
    np.testing.assert_array_equal(o.offset_point(points, [0.25], 0.5), [single])


def test_where_the_curve_stops_there_is_no_normal():
    stops_at_start = [(0.0, 0.0), (0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]
    with pytest.raises(ValueError, match=r"^t: the curve stops"):
        o.offset_point(stops_at_start, [0.5, 0.0], 1.0)
    cusp = [(0.0, 0.0), (1.0, 1.0), (0.0, 1.0), (1.0, 0.0)]  # a cusp at t = 1/2
    with pytest.raises(ValueError, match=r"^t:"):
        o.offset_normal(cusp, 0.5)
    assert np.all(np.isfinite(o.offset_point(stops_at_start, [0.5, 1.0], 1.0)))


@pytest.mark.parametrize("call", [
    lambda: o.offset_point([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], 0.5, 1.0),
    lambda: o.offset_point([(0.0, 0.0)], 0.5, 1.0),
    lambda: o.offset_point([(0.0, 0.0), (1.0, 1.0)], 0.5, 1.0, weights=[1.0, -1.0]),
    lambda: o.offset_point([(0.0, 0.0), (1.0, 1.0)], 0.5, 1.0, weights=[1.0, 0.0]),
    lambda: o.offset_point([(0.0, 0.0), (1.0, 1.0)], 0.5, [1.0, 2.0]),
    lambda: o.offset_cusps([(2.0, 1.0), (2.0, 1.0), (2.0, 1.0)], 1.0),
])
def test_bad_input_is_refused_by_name(call):
    with pytest.raises(ValueError, match=r"^(points|weights|rho|t)\b"):
        call()


# --- the derivative P' = (1 + ρκ) Q' ----------------------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("rational", [False, True])
def test_the_offset_derivative_matches_central_differences(seed, rational):
    points, weights = random_curve(seed + 10, rational)
    ts = np.linspace(0.05, 0.95, 19)
    h = 1e-6
    for rho in (0.4, -2.0):
        slope = (o.offset_point(points, ts + h, rho, weights) - o.offset_point(points, ts - h, rho, weights)) / (2 * h)
        exact = o.offset_derivative(points, ts, rho, weights)
        np.testing.assert_allclose(exact, slope, atol=2e-6 * (1 + np.abs(exact).max()))
        factor = 1 + rho * kappa(points, ts, weights)
        np.testing.assert_allclose(exact, factor[:, None] * bezier.derivative(points, ts, 1, weights), rtol=1e-12)


def test_between_the_cusps_the_offset_runs_backwards():
    points, rho = ARCH.args("points", "rho_cusps")
    first, second = ARCH.results["cusps"]
    ts = np.linspace(0, 1, 101)
    inner = (ts > first) & (ts < second)
    dots = np.einsum("ij,ij->i", o.offset_derivative(points, ts, rho), bezier.derivative(points, ts))
    assert np.all(dots[inner] < 0) and np.all(dots[~inner] > 0)
    np.testing.assert_allclose(o.offset_derivative(points, ARCH.results["cusps"], rho), 0, atol=1e-9)


def test_the_reverse_offset_gives_the_curve_back_only_where_the_offset_runs_forwards():
    points, rho = ARCH.args("points", "rho_cusps")
    first, second = ARCH.results["cusps"]
    ts = np.array([0.05, 0.15, 0.4, 0.5, 0.7, 0.85, 0.99])
    inner = (ts > first) & (ts < second)
    back = o.reverse_offset(points, ts, rho)
    q = bezier.evaluate(points, ts)
    np.testing.assert_allclose(back[~inner], q[~inner], atol=1e-12)
    np.testing.assert_allclose(back[inner], (q + 2 * rho * o.offset_normal(points, ts))[inner], atol=1e-12)
    np.testing.assert_allclose(o.reverse_offset(points, TS, ARCH.inputs["rho_safe"]), bezier.evaluate(points, TS),
                               atol=1e-12)
    with pytest.raises(ValueError, match=r"^t: the offset has a cusp"):
        o.reverse_offset(points, 0.5, ARCH.results["min_radius"])


# --- cusps ----------------------------------------------------------------------------------------


def test_the_arch_has_cusps_only_inside_and_only_beyond_its_tightest_bend():
    points = ARCH.inputs["points"]
    np.testing.assert_allclose(o.offset_cusps(points, ARCH.inputs["rho_cusps"]), ARCH.results["cusps"], atol=1e-12)
    np.testing.assert_allclose(cusps_by_sampling(points, ARCH.inputs["rho_cusps"]), ARCH.results["cusps"], atol=1e-12)
    assert o.offset_cusps(points, ARCH.inputs["rho_safe"]).shape == (0,)
    assert o.offset_cusps(points, -ARCH.inputs["rho_cusps"]).shape == (0,)  # the outside: no radius makes a cusp
    assert o.offset_cusps(points, 0.0).shape == (0,)
    assert o.cusp_free_interval(points) == (-np.inf, pytest.approx(ARCH.results["min_radius"], rel=1e-14))


def test_a_radius_equal_to_the_tightest_bend_touches_once():
    points = ARCH.inputs["points"]
    touching = o.offset_cusps(points, ARCH.results["min_radius"])
    np.testing.assert_allclose(touching, [ARCH.results["min_radius_t"]], atol=1e-6)
    assert len(o.offset_cusps(points, ARCH.results["min_radius"] * (1 + 1e-6))) == 2
    assert len(o.offset_cusps(points, ARCH.results["min_radius"] * (1 - 1e-6))) == 0


def test_an_inflection_puts_the_cusps_of_each_side_on_its_concave_arc():
    points, rho = INFLECTION.args("points", "rho")
    assert kappa(points, INFLECTION.results["inflection_t"]) == pytest.approx(0, abs=1e-12)
    right, left = o.offset_cusps(points, rho), o.offset_cusps(points, -rho)
    np.testing.assert_allclose(right, INFLECTION.results["cusps"], atol=1e-12)
    np.testing.assert_allclose(left, INFLECTION.results["cusps_left"], atol=1e-12)
    assert np.all(right < 0.5) and np.all(left > 0.5)
    low, high = o.cusp_free_interval(points)
    assert high == pytest.approx(INFLECTION.results["min_radius"], rel=1e-12) and low == pytest.approx(-high)
    bends = o.offset_cusps(points, INFLECTION.results["min_radius"]), o.offset_cusps(points, low)
    np.testing.assert_allclose(np.concatenate(bends), INFLECTION.results["min_radius_t"], atol=1e-6)


@pytest.mark.parametrize("seed", range(40))
def test_cusps_agree_with_dense_sampling_and_brentq(seed):
    points, weights = random_curve(100 + seed, rational=seed % 3 == 0)
    # Radii sampled off the grid of cusps_by_sampling, so that no cusp falls on one of its points.
    radii = 1 / np.abs(kappa(points, np.sqrt(np.linspace(0.001, 0.999, 401)), weights))
    rho = float(np.random.default_rng(seed).choice([-1, 1]) * np.quantile(radii, 0.3))
    found = o.offset_cusps(points, rho, weights)
    np.testing.assert_allclose(found, cusps_by_sampling(points, rho, weights), atol=1e-9)
    np.testing.assert_allclose(1 + rho * kappa(points, found, weights), 0, atol=1e-7)


@pytest.mark.parametrize("seed", range(12))
def test_cusps_agree_with_numpy_roots_of_the_squared_condition(seed):
    """numpy.roots on the power form of speed2³ - ρ² num², the other side's roots dropped by the sign of ρ num."""
    points, _ = random_curve(200 + seed)
    points = points[:4]  # cubics: a degree-12 polynomial, well within what numpy.roots resolves
    radii = 1 / np.abs(kappa(points, np.linspace(0, 1, 401)))
    rho = float(np.quantile(radii, 0.25)) * (-1) ** seed
    num, _ = o.curvature_polynomials(points)
    power = bernstein_to_power(o.cusp_polynomial(points, rho))
    roots = np.roots(power[::-1])
    real = np.sort(roots[np.abs(roots.imag) < 1e-7].real)
    expected = [t for t in real if 0 <= t <= 1 and rho * bernstein_horner(num, t) < 0]
    np.testing.assert_allclose(o.offset_cusps(points, rho), expected, atol=1e-7)


def test_the_squared_polynomial_factors_as_its_two_conditions():
    points, weights = random_curve(7, rational=True)
    rho = -0.8
    num, speed2 = o.curvature_polynomials(points, weights)
    f = bernstein_horner(o.cusp_polynomial(points, rho, weights), TS)
    k = kappa(points, TS, weights)
    np.testing.assert_allclose(bernstein_horner(num, TS) / bernstein_horner(speed2, TS) ** 1.5, k, rtol=1e-12)
    np.testing.assert_allclose(f, bernstein_horner(speed2, TS) ** 3 * (1 - rho * k) * (1 + rho * k),
                               rtol=1e-9, atol=1e-9 * np.abs(f).max())


def test_the_parabola_has_its_cusps_where_the_radius_of_curvature_is_rho():
    """y = x² turns left, κ = 2 / (1 + 4t²)^(3/2): for ρ < -1/2 its cusps are at t = ±√(((−2ρ)^(2/3) − 1)/4)."""
    parabola = [(-2.0, 4.0), (0.0, -4.0), (2.0, 4.0)]  # (t, t²) for t = 4s - 2, s in [0, 1]
    for rho in (-0.6, -0.8, -3.0):
        t = np.sqrt(((-2 * rho) ** (2 / 3) - 1) / 4)
        np.testing.assert_allclose(o.offset_cusps(parabola, rho), (np.array([-t, t]) + 2) / 4, atol=1e-12)
    assert o.cusp_free_interval(parabola) == (pytest.approx(-0.5, rel=1e-13), np.inf)
    assert o.offset_cusps(parabola, -0.5).tolist() == [pytest.approx(0.5, abs=1e-12)]  # 1 + ρκ touches zero


def test_a_circle_offset_to_its_centre_collapses_and_is_refused():
    points, weights = bezier.circular_arc([0.0, 0.0], 2.0, 0.0, 2.0)
    with pytest.raises(ValueError, match=r"^rho: 1 \+ ρκ vanishes identically"):
        o.offset_cusps(points, -2.0, weights)
    assert o.offset_cusps(points, -1.0, weights).shape == (0,)
    np.testing.assert_allclose(o.offset_point(points, TS, -2.0, weights), 0, atol=1e-14)


def test_straight_lines_have_no_cusps_and_no_bends():
    line = [(0.0, 0.0), (1.0, 1.0), (3.0, 3.0)]
    assert o.offset_cusps(line, 5.0).shape == (0,)
    assert o.cusp_free_interval(line) == (-np.inf, np.inf)
    assert o.cusp_free_interval([(0.0, 0.0), (2.0, 1.0)]) == (-np.inf, np.inf)


@pytest.mark.parametrize("seed", range(10))
def test_the_cusp_free_interval_agrees_with_a_refined_search(seed):
    points, weights = random_curve(300 + seed, rational=seed % 2 == 1)
    ts = np.linspace(0, 1, 4001)
    k = kappa(points, ts, weights)

    def extreme(sign):
        i = int(np.argmax(sign * k))
        lo, hi = ts[max(i - 1, 0)], ts[min(i + 1, len(ts) - 1)]
        best = minimize_scalar(lambda t: -sign * kappa(points, t, weights), bounds=(lo, hi), method="bounded",
                               options={"xatol": 1e-12})
        return max(-best.fun, sign * k[i])

    low, high = o.cusp_free_interval(points, weights)
    expected_high = 1 / extreme(-1) if k.min() < 0 else np.inf
    expected_low = -1 / extreme(1) if k.max() > 0 else -np.inf
    assert high == pytest.approx(expected_high, rel=1e-8) and low == pytest.approx(expected_low, rel=1e-8)


# --- Pythagorean-hodograph curves ------------------------------------------------------------------


def test_the_ph_cubic_example():
    p0, u, v = PH.args("p0", "u", "v")
    cubic = o.ph_cubic(p0, u, v)
    np.testing.assert_allclose(cubic, PH.results["points"], atol=1e-15)
    np.testing.assert_allclose(bezier.hodograph(cubic), PH.results["hodograph"], atol=1e-14)
    np.testing.assert_allclose(o.ph_hodograph(u, v), PH.results["hodograph"], atol=1e-15)
    np.testing.assert_allclose(o.ph_speed(cubic), PH.results["sigma"], atol=1e-13)
    speed = np.linalg.norm(bezier.derivative(cubic, TS), axis=1)
    np.testing.assert_allclose(bernstein_horner(o.ph_speed(cubic), TS), speed, rtol=1e-14)


def test_the_ph_identities_hold_exactly():
    """SymPy: (u² - v²)² + (2uv)² = (u² + v²)², and the cubic's control points follow the printed formulas."""
    t = sp.symbols("t")
    u0, u1, v0, v1 = sp.symbols("u0 u1 v0 v1", real=True)
    u, v = u0 * (1 - t) + u1 * t, v0 * (1 - t) + v1 * t
    assert sp.expand((u**2 - v**2) ** 2 + (2 * u * v) ** 2 - (u**2 + v**2) ** 2) == 0
    x_prime, y_prime = sp.expand(u**2 - v**2), sp.expand(2 * u * v)
    p1 = sp.Matrix([u0**2 - v0**2, 2 * u0 * v0]) / 3
    p2 = p1 + sp.Matrix([u0 * u1 - v0 * v1, u0 * v1 + u1 * v0]) / 3
    p3 = p2 + sp.Matrix([u1**2 - v1**2, 2 * u1 * v1]) / 3
    control = [sp.zeros(2, 1), p1, p2, p3]
    curve = sum((sp.binomial(3, i) * (1 - t) ** (3 - i) * t**i * control[i] for i in range(4)), sp.zeros(2, 1))
    assert sp.expand(sp.diff(curve[0], t) - x_prime) == 0 and sp.expand(sp.diff(curve[1], t) - y_prime) == 0
    values = {u0: 0.7, u1: -1.3, v0: 2.1, v1: 0.4}
    numeric = o.ph_cubic((0.0, 0.0), (0.7, -1.3), (2.1, 0.4))
    np.testing.assert_allclose(numeric, [[float(c.subs(values)[k]) for k in range(2)] for c in control], atol=1e-14)


@pytest.mark.parametrize("seed", range(8))
def test_ph_curves_of_any_degree_have_a_polynomial_speed(seed):
    rng = np.random.default_rng(seed)
    m = 1 + seed % 3
    u, v = rng.normal(size=m + 1), rng.normal(size=m + 1)
    curve = o.ph_curve(rng.normal(size=2), u, v)
    assert curve.shape == (2 * m + 2, 2)
    np.testing.assert_allclose(bezier.hodograph(curve), o.ph_hodograph(u, v), atol=1e-13)
    sigma = bernstein_multiply(u, u) + bernstein_multiply(v, v)
    np.testing.assert_allclose(o.ph_speed(curve), sigma, atol=1e-10)
    assert o.is_pythagorean_hodograph(curve) and o.is_pythagorean_hodograph(bezier.elevate(curve))


def test_ordinary_cubics_are_not_ph():
    assert not o.is_pythagorean_hodograph(ARCH.inputs["points"])
    for seed in range(5):
        assert not o.is_pythagorean_hodograph(np.random.default_rng(seed).normal(size=(4, 2)))
    assert o.is_pythagorean_hodograph([(0.0, 0.0), (3.0, 4.0)])  # a line moves at a constant speed
    with pytest.raises(ValueError, match=r"^points: x'² \+ y'² is not the square"):
        o.ph_speed(ARCH.inputs["points"])
    with pytest.raises(ValueError, match=r"^tol"):
        o.is_pythagorean_hodograph(ARCH.inputs["points"], tol=0.0)


def test_the_exact_offset_example():
    points, weights = o.ph_offset(*PH_OFFSET.args("points", "rho"))
    np.testing.assert_allclose(points, PH_OFFSET.results["points"], atol=1e-14)
    np.testing.assert_allclose(weights, PH_OFFSET.results["weights"], atol=1e-14)


@pytest.mark.parametrize("seed", range(8))
def test_the_exact_offset_is_the_offset(seed):
    rng = np.random.default_rng(50 + seed)
    m = 1 + seed % 2  # cubics and quintics
    curve = o.ph_curve(rng.normal(size=2), rng.uniform(0.5, 2, m + 1), rng.uniform(-1, 1, m + 1))
    n = len(curve) - 1
    for rho in (0.3, -1.7):
        points, weights = o.ph_offset(curve, rho)
        assert points.shape == (2 * n, 2) and weights.shape == (2 * n,)
        np.testing.assert_allclose(bezier.evaluate(points, TS, weights), o.offset_point(curve, TS, rho), atol=1e-12)
    elevated_points, elevated_weights = o.ph_offset(bezier.elevate(curve), 0.3)
    np.testing.assert_allclose(bezier.evaluate(elevated_points, TS, elevated_weights), o.offset_point(curve, TS, 0.3),
                               atol=1e-12)


def test_the_exact_offset_of_a_line_is_the_shifted_line():
    points, weights = o.ph_offset([(0.0, 0.0), (3.0, 4.0)], 1.0)
    np.testing.assert_allclose(points, [[0.8, -0.6], [3.8, 3.4]], atol=1e-15)
    np.testing.assert_allclose(weights, [5.0, 5.0])


def test_ph_offsets_refuse_curves_that_stop_or_are_not_ph():
    stopping = o.ph_cubic((0.0, 0.0), (1.0, -1.0), (1.0, -1.0))  # u and v both vanish at t = 1/2
    with pytest.raises(ValueError, match=r"^points: the PH curve stops .* t = 0\.5"):
        o.ph_offset(stopping, 0.1)
    with pytest.raises(ValueError, match=r"^points: x'² \+ y'²"):
        o.ph_offset(ARCH.inputs["points"], 0.1)
    with pytest.raises(ValueError, match=r"^u: a PH cubic"):
        o.ph_cubic((0.0, 0.0), (1.0, 2.0, 3.0), (0.0, 1.0, 2.0))
    with pytest.raises(ValueError, match=r"^u, v"):
        o.ph_hodograph((1.0, 2.0), (0.0, 1.0, 2.0))


# --- the parabola --------------------------------------------------------------------------------------


def test_the_parabola_offset_is_rational_of_degree_six():
    """SymPy: the parametrisation keeps its distance and its normal exactly, has degrees 5, 6, 4 without a common
    factor, and traces a curve whose implicit equation (a resultant) has total degree 6, not the notes' 8."""
    u, rho, x, y = sp.symbols("u rho x y")
    t = (u**2 - 1) / (4 * u)
    big_x = 4 * u * (u**2 - 1) * (u**2 + 4 * rho * u + 1)
    big_y = (u**2 - 1) ** 2 * (u**2 + 1) - 32 * rho * u**3
    big_w = 16 * u**2 * (u**2 + 1)
    assert sp.simplify((big_x / big_w - t) ** 2 + (big_y / big_w - t**2) ** 2 - rho**2) == 0
    assert sp.simplify((big_x / big_w - t) + 2 * t * (big_y / big_w - t**2)) == 0
    assert [sp.degree(p, u) for p in (big_x, big_y, big_w)] == [int(d) for d in PARABOLA.results["degrees"]]
    assert sp.gcd(sp.gcd(big_x, big_y), big_w) == 1
    value = sp.Rational(PARABOLA.inputs["rho"]).limit_denominator()
    implicit = sp.resultant(sp.expand((big_x - x * big_w).subs(rho, value)),
                            sp.expand((big_y - y * big_w).subs(rho, value)), u)
    factors = [f for f, _ in sp.factor_list(implicit)[1] if sp.Poly(f, x, y).total_degree() > 0]
    assert [sp.Poly(f, x, y).total_degree() for f in factors] == [PARABOLA.results["implicit_degree"]]
    assert PARABOLA.errata["rational_degree"].correct == PARABOLA.results["rational_degree"] == 6


@pytest.mark.parametrize("rho, interval", [(0.5, (-1.0, 1.0)), (-0.8, (-1.0, 1.0)), (0.3, (0.2, 2.0)),
                                           (-2.0, (-3.0, -1.0))])
def test_the_parabola_offset_matches_the_offset_of_the_parabola(rho, interval):
    points, weights = o.parabola_offset(rho, interval)
    assert points.shape == (7, 2) and np.all(weights > 0)
    t0, t1 = interval
    u0, u1 = (2 * t + np.sqrt(4 * t * t + 1) for t in interval)
    s = np.linspace(0, 1, 31)
    u = u0 + s * (u1 - u0)
    t = (u * u - 1) / (4 * u)
    parabola = [(t0, t0**2), ((t0 + t1) / 2, t0 * t1), (t1, t1**2)]  # (t, t²) as a quadratic Bézier curve
    np.testing.assert_allclose(bezier.evaluate(points, s, weights), o.offset_point(parabola, (t - t0) / (t1 - t0), rho),
                               atol=1e-12)


# --- the evolute, distances, trimming ---------------------------------------------------------------

POCKET = [(-1.5, 2.25), (0.0, -2.25), (1.5, 2.25)]  # y = x² for -1.5 <= x <= 1.5, turning left (inside: ρ < 0)
HOOK = [(0.0, 0.0), (6.0, 0.0), (4.0, 5.0), (1.0, 0.8)]  # curls back towards its start


def test_the_centre_of_curvature_holds_every_cusp():
    assert o.centre_of_curvature(ARCH.inputs["points"], 0.5) == pytest.approx([2.0, 1.5 - ARCH.results["min_radius"]])
    for seed in range(6):
        points, weights = random_curve(seed, rational=seed % 2 == 1)
        low, high = o.cusp_free_interval(points, weights)
        rho = 1.3 * (high if np.isfinite(high) else low)
        cusps = o.offset_cusps(points, rho, weights)
        np.testing.assert_allclose(o.offset_point(points, cusps, rho, weights),
                                   o.centre_of_curvature(points, cusps, weights), atol=1e-9)
    with pytest.raises(ValueError, match="^t: the curve does not bend"):
        o.centre_of_curvature(INFLECTION.inputs["points"], 0.5)  # κ = 0 at the inflection


@pytest.mark.parametrize("seed", range(6))
def test_the_distance_to_a_curve_agrees_with_a_dense_search(seed):
    points, weights = random_curve(seed, rational=seed % 2 == 1)
    rng = np.random.default_rng(seed)
    queries = rng.uniform(-6, 6, (5, 2))
    dense = bezier.evaluate(points, np.linspace(0, 1, 20001), weights)
    for query, found in zip(queries, o.distance_to_curve(points, queries, weights)):
        gaps = np.linalg.norm(dense - query, axis=1)
        k = int(np.argmin(gaps))
        best = minimize_scalar(lambda t, q=query: np.linalg.norm(bezier.evaluate(points, t, weights) - q),
                               bounds=(max(k - 2, 0) / 20000, min(k + 2, 20000) / 20000), method="bounded",
                               options={"xatol": 1e-13})
        assert found == pytest.approx(min(best.fun, gaps.min()), abs=1e-9)
        assert found <= gaps.min() + 1e-12


def test_points_of_a_cusp_free_convex_offset_are_at_distance_rho_and_the_error_measures_the_gap():
    arch = ARCH.inputs["points"]
    offset = o.offset_point(arch, TS, -0.5)  # outside the arch: every foot point is its own
    np.testing.assert_allclose(o.distance_to_curve(arch, offset), 0.5, atol=1e-12)
    assert np.abs(o.offset_error(arch, -0.5, offset, TS)).max() < 1e-12
    moved = offset + 0.01 * o.offset_normal(arch, TS)  # 0.01 back towards the curve
    np.testing.assert_allclose(o.offset_error(arch, -0.5, moved, TS), 0.01, atol=1e-12)
    assert o.offset_error(arch, 0.3, (2.0, 1.25), 0.5) == pytest.approx(0.05)
    with pytest.raises(ValueError, match="^t: expected one parameter per point"):
        o.offset_error(arch, 0.3, offset[:3], TS[:2])


def test_trimming_cuts_the_swallowtail_at_its_crossing():
    kept = o.trim_offset(POCKET, -0.8)
    assert kept.shape == (2, 2) and kept[0, 0] == 0.0 and kept[1, 1] == 1.0
    inner = o.offset_point(POCKET, [kept[0, 1], kept[1, 0]], -0.8)
    np.testing.assert_allclose(inner[0], inner[1], atol=1e-8)  # both pieces end at the crossing ...
    assert inner[0][0] == pytest.approx(0.0, abs=1e-8)  # ... on the axis of the parabola
    cusps = o.offset_cusps(POCKET, -0.8)
    assert kept[0, 1] < cusps[0] and cusps[1] < kept[1, 0]  # the backward arc is gone with the loop


@pytest.mark.parametrize("points, rho", [(POCKET, -0.8), (HOOK, -0.5), (HOOK, -0.8),
                                         (INFLECTION.inputs["points"], 0.6)])
def test_what_trimming_keeps_is_at_distance_rho_and_what_it_drops_is_closer(points, rho):
    kept = o.trim_offset(points, rho)
    ts = np.linspace(0, 1, 1201)
    inside = np.any((ts[:, None] >= kept[:, 0]) & (ts[:, None] <= kept[:, 1]), axis=1)
    margin = np.min(np.abs(ts[:, None] - kept.ravel()[None, :]), axis=1) > 1e-6  # clear of the cut points
    distance = o.distance_to_curve(points, o.offset_point(points, ts, rho))
    assert np.all(distance[inside] >= abs(rho) * (1 - 1e-9))
    assert np.all(distance[~inside & margin] < abs(rho))


def test_the_convex_side_and_rho_zero_keep_everything():
    assert o.trim_offset(ARCH.inputs["points"], -0.5).tolist() == [[0.0, 1.0]]
    assert o.trim_offset(ARCH.inputs["points"], 0.0).tolist() == [[0.0, 1.0]]
    assert o.trim_offset(ARCH.inputs["points"], 2.5).shape == (0, 2)  # a tool of radius 2.5 fits nowhere in the arch


# --- approximation within a tolerance --------------------------------------------------------------


def test_tiller_hanson_is_exact_for_a_line_and_at_the_ends_of_any_curve():
    line = bezier.elevate(np.array([[0.0, 0.0], [3.0, 4.0]]), 2)  # a cubic that is a line, evenly parametrised
    np.testing.assert_allclose(bezier.evaluate(o.tiller_hanson(line, 1.0), TS), o.offset_point(line, TS, 1.0),
                               atol=1e-12)
    for seed in range(5):
        points, _ = random_curve(seed)
        approx = o.tiller_hanson(points, 0.4)
        np.testing.assert_allclose(approx[[0, -1]], o.offset_point(points, [0.0, 1.0], 0.4), atol=1e-12)
        ends = bezier.derivative(approx, [0.0, 1.0])
        tangents = bezier.derivative(points, [0.0, 1.0])
        assert np.allclose(ends[:, 0] * tangents[:, 1] - ends[:, 1] * tangents[:, 0], 0, atol=1e-9)  # parallel
    with pytest.raises(ValueError, match="^points: a leg"):
        o.tiller_hanson([(0.0, 0.0), (0.0, 0.0), (1.0, 1.0)], 0.5)


@pytest.mark.parametrize("rho", [0.5, -1.0, -2.9])
def test_tiller_hanson_is_exact_for_a_rational_circular_arc_with_its_weights(rho):
    points, weights = bezier.circular_arc([1.0, 2.0], 3.0, 0.2, 2.5)
    moved = o.tiller_hanson(points, rho)
    np.testing.assert_allclose(moved, [1.0, 2.0] + (points - [1.0, 2.0]) * (3.0 + rho) / 3.0, atol=1e-13)
    np.testing.assert_allclose(bezier.evaluate(moved, TS, weights), o.offset_point(points, TS, rho, weights),
                               atol=1e-13)


def test_tiller_hanson_is_not_exact_for_a_cubic_quarter_circle():
    k = 4 / 3 * (np.sqrt(2) - 1)
    quarter = np.array([[1.0, 0.0], [1.0, k], [k, 1.0], [0.0, 1.0]])
    moved = o.tiller_hanson(quarter, 0.25)
    assert o.offset_error(quarter, 0.25, bezier.evaluate(moved, TS), TS).max() > 1e-3


def test_tiller_hanson_error_falls_fourfold_per_halving():
    arch = np.array(ARCH.inputs["points"], dtype=float)
    s = np.linspace(0, 1, 101)
    errors = []
    for depth in (3, 4, 5):
        k, worst, rest = 2**depth, 0.0, arch
        for j in range(k):
            piece, rest = bezier.subdivide(rest, 1 / (k - j)) if j < k - 1 else (rest, None)
            worst = max(worst, o.offset_error(piece, -0.5, bezier.evaluate(o.tiller_hanson(piece, -0.5), s), s).max())
        errors.append(worst)
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 3.5) & (ratios < 4.5))


@pytest.mark.parametrize("points, rho, tol", [(ARCH.inputs["points"], -0.5, 1e-3), (ARCH.inputs["points"], 1.0, 1e-4),
                                              (POCKET, 0.3, 1e-3)])
def test_the_tiller_hanson_offset_keeps_its_tolerance(points, rho, tol):
    breaks, pieces, error = o.tiller_hanson_offset(points, rho, tol)
    assert error <= tol and breaks[0] == 0 and breaks[-1] == 1 and len(pieces) == len(breaks) - 1
    np.testing.assert_allclose(pieces[1:, 0], pieces[:-1, -1], atol=1e-12)  # the pieces meet
    s = np.linspace(0, 1, 401)
    for (a, b), piece in zip(zip(breaks, breaks[1:]), pieces):
        assert o.offset_error(points, rho, bezier.evaluate(piece, s), a + s * (b - a)).max() <= 1.05 * tol
    with pytest.raises(ValueError, match="^tol"):
        o.tiller_hanson_offset(points, rho, 0.0)


@pytest.mark.parametrize("degree", [2, 3, 4])
@pytest.mark.parametrize("tol", [1e-2, 1e-4, 1e-6])
def test_the_fitted_offset_keeps_its_tolerance_on_a_dense_grid(degree, tol):
    arch = ARCH.inputs["points"]
    control, knots, error = o.fit_offset(arch, 1.0, tol, degree=degree)
    assert error <= tol and len(knots) == len(control) + degree - 1
    ts = np.linspace(0, 1, 4001)
    gap = np.linalg.norm(de_boor(control, knots, ts) - o.offset_point(arch, ts, 1.0), axis=1)
    assert gap.max() <= 1.05 * tol


def test_a_fit_runs_through_cusps_and_over_a_part_of_the_curve():
    control, knots, error = o.fit_offset(POCKET, -0.8, 1e-5, interval=(0.2, 0.8))  # two cusps inside
    ts = np.linspace(0.2, 0.8, 2001)
    gap = np.linalg.norm(de_boor(control, knots, ts) - o.offset_point(POCKET, ts, -0.8), axis=1)
    assert knots[0] == 0.2 and knots[-1] == 0.8 and gap.max() <= 1.05e-5
    weights = [1.0, 2.0, 1.0]
    control, knots, error = o.fit_offset(POCKET, 0.5, 1e-6, weights)
    assert error <= 1e-6

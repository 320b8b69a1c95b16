"""Real roots of Bernstein-form polynomials (notes ch. 9): the notes' algorithms, the default, and what builds them.

The worked examples come from cagd_course/examples/ch09.toml (and ch07.toml for the
curves chapter 7 shares); cross-checks use numpy.roots, SciPy's BPoly/PPoly and SymPy.
"""

from fractions import Fraction
from math import comb

import numpy as np
import pytest
import sympy as sp
from numpy.polynomial import polynomial as P
from scipy.interpolate import BPoly, PPoly

from cagd_course.examples import notes_example
from cagd_ref import roots
from cagd_ref.bezier import evaluate, explicit_bezier, subdivide
from cagd_ref.polynomials import bernstein_horner, bernstein_multiply, bernstein_to_power, power_to_bernstein
from cagd_ref.roots import (
    bcom_roots,
    bcom_steps,
    bernstein_from_roots,
    bernstein_roots,
    bernstein_roots_plain,
    deflate,
    hull_crossing,
    hull_march,
    hull_march_plain,
    hull_march_steps,
    line_curve_intersection,
    newton_in_bracket,
    one_root_per_cluster,
    polygon_crossing,
    sign_variations,
    wilkinson_polynomial,
)

T = sp.symbols("t")


def test_public_names_are_all_tested():
    assert set(roots.__all__) == {
        "hull_crossing", "polygon_crossing", "sign_variations", "deflate", "hull_march", "hull_march_plain",
        "hull_march_steps", "bcom_roots",
        "bcom_steps", "bernstein_roots", "bernstein_roots_plain", "bernstein_from_roots",
        "line_curve_intersection", "wilkinson_polynomial",
    }


def exact_roots(coeffs) -> np.ndarray:
    """The real roots in [0, 1] of Σ c_i B_i^n with exact (rational) coefficients, by SymPy."""
    n = len(coeffs) - 1
    c = [sp.Rational(Fraction(x).limit_denominator(10**12)) if isinstance(x, float) else sp.Rational(x) for x in coeffs]
    poly = sp.Poly(sp.expand(sum(ci * sp.binomial(n, i) * T**i * (1 - T) ** (n - i) for i, ci in enumerate(c))), T)
    return np.array([float(r) for r in poly.real_roots() if 0 <= r <= 1])


def scipy_roots(coeffs, interval=(0.0, 1.0)) -> np.ndarray:
    """SciPy's own root finder for a Bernstein polynomial: BPoly -> PPoly.roots on the interval."""
    piece = BPoly(np.asarray(coeffs, dtype=float)[:, None], list(interval))
    return np.unique(PPoly.from_bernstein_basis(piece).roots(extrapolate=False))


def power_roots(coeffs) -> np.ndarray:
    """numpy.roots on the power form, the real ones in [0, 1]."""
    found = np.roots(bernstein_to_power(np.asarray(coeffs, dtype=float))[::-1])
    real = found[np.abs(found.imag) < 1e-7].real
    return np.sort(real[(real >= -1e-12) & (real <= 1 + 1e-12)])


def random_simple(rng, inside=(1, 5), outside=(0, 3), gap=0.02):
    """Bernstein coefficients with well-separated roots in (0, 1) and some outside, and the inside roots."""
    while True:
        inner = np.sort(rng.uniform(0.02, 0.98, int(rng.integers(*inside))))
        if len(inner) < 2 or np.diff(inner).min() > gap:
            break
    outer = rng.uniform(1.2, 3.0, int(rng.integers(*outside))) * rng.choice([-1.0, 1.0])
    leading = rng.uniform(0.5, 5.0) * rng.choice([-1.0, 1.0])
    return bernstein_from_roots(np.concatenate([inner, outer]), leading=leading), inner


# ---------------------------------------------------------------- the hull and the rule of signs (§9.1, §9.2)


def test_hull_crossing_bounds_every_root_and_rejects_one_signed_polygons():
    coeffs = bernstein_from_roots([0.4, 0.6])
    lo, hi = hull_crossing(coeffs)
    assert lo <= 0.4 and hi >= 0.6 and 0 <= lo < hi <= 1
    assert hull_crossing([1.0, 0.5, 2.0]) is None
    assert hull_crossing([0.0]) == (0.0, 1.0) and hull_crossing([1.0]) is None


def test_hull_crossing_of_the_marching_example_starts_at_one_eighth():
    example = notes_example("09.hull_marching")
    lo, _ = hull_crossing(*example.args("coeffs"))
    assert lo == example.results["steps"][0] == 1 / 8


def test_hull_crossing_is_the_exact_hull_not_the_fan_from_the_first_point():
    # The hull edge from (1/2, 0.001) to (1, -1) crosses first; the line from (0, 10) to (1, -1) only at 10/11.
    lo, hi = hull_crossing([10.0, 0.001, -1.0])
    assert lo == pytest.approx(0.5 + 0.5 * 0.001 / 1.001) and hi == pytest.approx(10 / 11)
    assert all(lo <= r <= hi for r in exact_roots([10, Fraction(1, 1000), -1]))


def test_the_polygon_crosses_where_its_legs_do_and_is_no_bound_on_the_roots():
    # <1, -1, 2, -3>: the legs cross at 1/6, 4/9 and 4/5; the one root is 0.596, the hull starts at 1/6.
    coeffs = [1.0, -1.0, 2.0, -3.0]
    assert polygon_crossing(coeffs) == pytest.approx(1 / 6, abs=1e-15)
    assert polygon_crossing([2.0, 1.0, 0.0, -1.0]) == pytest.approx(2 / 3)  # a control point on the axis
    assert polygon_crossing([1.0, 0.5, 2.0]) is None and polygon_crossing([0.0]) == 0.0
    # After two steps to the polygon's crossing the piece on [t2, 1] crosses at 0.8, beyond the root:
    # marching to the polygon would step over it.
    t, piece = 0.0, np.array(coeffs)
    for _ in range(2):
        c = polygon_crossing(piece)
        t, piece = t + (1 - t) * c, explicit_split(piece, c)
    assert t == pytest.approx(0.337777777778, abs=1e-11)
    assert t + (1 - t) * polygon_crossing(piece) == pytest.approx(0.8, abs=1e-14)
    assert t < hull_march(coeffs)[0] < 0.8
    rng = np.random.default_rng(17)
    misses = 0
    for _ in range(100):  # the hull's crossing never passes a root; the polygon's sometimes does
        c = rng.normal(size=int(rng.integers(2, 8)))
        found = bernstein_roots(c)
        if found.size:
            assert hull_crossing(c)[0] <= found[0] + 1e-12
            misses += polygon_crossing(c) > found[0] + 1e-9
    assert misses > 0


def test_the_march_steps_can_follow_the_polygon_to_show_the_jump():
    steps = hull_march_steps([1.0, -1.0, 2.0, -3.0], rule="polygon")
    crossings = [s.crossing for s in steps if s.crossing is not None]
    np.testing.assert_allclose(crossings, [1 / 6, 0.337777777778, 0.8], atol=1e-12)
    assert steps[2].event == "root" and steps[2].root == pytest.approx(0.8)  # the wrong "root": a sign change
    with pytest.raises(ValueError, match="^rule"):
        hull_march_steps([1.0, -1.0], rule="legs")


def explicit_split(coeffs, c):
    """The right part of a split at c (de Casteljau on the coefficients)."""
    from cagd_ref.bezier import subdivide

    return subdivide(np.asarray(coeffs, dtype=float)[:, None], c)[1][:, 0]


def test_sign_variations_bound_the_roots_with_their_parity():
    assert sign_variations([1.0, 1.0, -3.0, -2.0, 4.0]) == 2
    assert sign_variations([1.0, 0.0, 0.0, -1.0]) == 1  # zeros are skipped
    assert sign_variations([0.0, 0.0]) == 0
    rng = np.random.default_rng(11)
    for _ in range(60):
        c = rng.normal(size=int(rng.integers(2, 9)))
        found = len(power_roots(c))
        assert found <= sign_variations(c) and (sign_variations(c) - found) % 2 == 0


# ---------------------------------------------------------------- deflation (9.1)


def test_deflation_notes_example():
    example = notes_example("09.deflation")
    np.testing.assert_allclose(deflate(*example.args("coeffs")), example.results["deflated"], rtol=1e-15)


def test_deflation_removes_the_factor_t_on_random_polynomials():
    rng = np.random.default_rng(4)
    s = np.linspace(0, 1, 23)
    for n in range(1, 10):
        f = np.concatenate([[0.0], rng.normal(size=n)])
        g = deflate(f)
        assert g.shape == (n,)
        np.testing.assert_allclose(bernstein_horner(f, s), s * bernstein_horner(g, s), atol=1e-13)


def test_deflation_accepts_rounding_and_rejects_a_real_value_at_zero():
    np.testing.assert_allclose(deflate([1e-17, 2.0]), [2.0])
    np.testing.assert_allclose(deflate([0.0, 0.0, 0.0]), [0.0, 0.0])  # 0 = t · 0
    with pytest.raises(ValueError, match="^coeffs.*not zero"):
        deflate([0.5, 1.0, 2.0])
    with pytest.raises(ValueError, match="^coeffs.*constant"):
        deflate([0.0])


# ---------------------------------------------------------------- convex hull marching (§9.1)


def test_hull_marching_example_steps_and_roots():
    example = notes_example("09.hull_marching")
    (coeffs,) = example.args("coeffs")
    np.testing.assert_allclose(hull_march(coeffs), example.results["roots"], atol=1e-14)
    steps = hull_march_steps(coeffs)
    crossings = [s.crossing for s in steps if s.crossing is not None]
    np.testing.assert_allclose(crossings[:6], example.results["steps"], atol=1e-12)
    first_root = next(k for k, s in enumerate(steps, start=1) if s.event == "root")
    assert first_root == example.results["k"] == 6
    assert steps[first_root - 1].root == crossings[5]  # the root is t6
    second = [s for s in steps[first_root:] if s.event in ("step", "root")]
    assert len(second) == example.results["second_root_steps"]
    assert steps[-1].event == "end"


def test_march_steps_never_pass_a_root_and_restrict_the_polynomial():
    coeffs = notes_example("09.hull_marching").inputs["coeffs"]
    first, second = notes_example("09.hull_marching").results["roots"]
    s = np.linspace(0, 1, 9)
    for step in hull_march_steps(coeffs):
        assert step.start <= first + 1e-12 or first < step.start <= second + 1e-12
        if step.event == "step" and step.start < first:
            # the step's coefficients are f on [start, 1] (before the first deflation)
            t = step.start + (1 - step.start) * s
            np.testing.assert_allclose(bernstein_horner(step.coeffs, s), bernstein_horner(coeffs, t), atol=1e-12)


def test_the_corrected_pitfall_rule_takes_the_far_end_of_the_step():
    example = notes_example("09.pitfall")
    (coeffs,) = example.args("coeffs")
    # The first step lands on the root 7/12, and de Casteljau gives f there the other sign: with the course's
    # subdivide, (1 - c) a + c b, and with the march's own kernel, a + c (b - a) ...
    (step,) = [s for s in hull_march_steps(coeffs) if s.event == "root"]
    assert step.start == 0.0 and step.crossing == example.results["root"] == pytest.approx(7 / 12, abs=1e-16)
    assert subdivide(coeffs[:, None], step.crossing)[1][0, 0] > 0 > coeffs[0]
    assert coeffs[0] + step.crossing * (coeffs[1] - coeffs[0]) > 0
    # ... so the notes' rule ("take t_i") would return t0 = 0; the root is t1, and both marches say so.
    assert not example.errata  # the notes state a rule, not a value
    for march in (hull_march, hull_march_plain):
        np.testing.assert_allclose(march(coeffs), [example.results["root"]], atol=1e-15)


def _tangent_test(coeffs, r):
    """The chapter's test at a simple root r: (Newton steps from some step on, predicted linear factor)."""
    n = len(coeffs) - 1
    bar = subdivide(np.asarray(coeffs, dtype=float)[:, None], r)[1][:, 0]  # f on [r, 1]
    heights = bar[2:] - np.arange(2, n + 1) * bar[1]  # above the tangent at r
    slopes = bar[1:] / np.arange(1, n + 1)
    steepest = slopes.min() if bar[1] < 0 else slopes.max()
    return bool(np.all(bar[1] * heights < 0)), 1 - bar[1] / steepest


@pytest.mark.parametrize(
    "coeffs, newton",
    [
        (bernstein_from_roots([0.3, 1.5], leading=-1.0), True),  # a quadratic with f'f'' < 0
        ([1.0, 1.0, -3.0, -2.0, 4.0], True),  # the quartic's first root
        ([1.0, -1.0, 2.0, -3.0], False),  # f'f'' > 0: Newton from the left would overshoot
        ([0.65, -0.36, -0.24, 0.72, 0.45, -7.08], False),  # f'f'' < 0, yet a far point beyond the tangent
        ([10.0, -4.0, 2.0, -4.0], False),  # the chapter's question: rho = 1/4
        ([-0.39, 0.48, -0.24, 0.96], False),
    ],
)
def test_the_march_is_newton_exactly_when_the_tangent_at_the_root_supports_the_polygon(coeffs, newton):
    coeffs = np.asarray(coeffs, dtype=float)
    r = bernstein_roots(coeffs)[0]
    predicted, rho = _tangent_test(coeffs, r)
    assert predicted == newton
    d = np.abs(r - np.array([s.start for s in hull_march_steps(coeffs) if s.start < r]))
    d = d[d > 1e-9]
    if newton:
        assert d[-1] / d[-2] < 0.01 and d[-1] / d[-2] ** 2 < 10  # quadratic
    else:
        assert d[-1] / d[-2] == pytest.approx(rho, abs=2e-3)  # linear, with the predicted factor


def test_the_step_follows_the_steepest_edge_from_the_first_point_once_the_first_leg_crosses():
    rng = np.random.default_rng(9)
    for _ in range(200):
        y = rng.normal(size=int(rng.integers(2, 8)))
        if y[0] * y[1] >= 0:
            continue
        n = len(y) - 1
        slopes = (y[1:] - y[0]) / np.arange(1, n + 1)
        m = 1 + (int(np.argmin(slopes)) if y[0] > 0 else int(np.argmax(slopes)))
        assert hull_crossing(y)[0] == pytest.approx((0 - y[0] * m / (y[m] - y[0])) / n, abs=1e-14)
    assert hull_crossing([1.0, 0.1, -0.7])[0] == 0.5625  # the first leg does not cross: the edge P1 P2


@pytest.mark.parametrize(
    "coeffs, expected",
    [
        ([-0.87, 0.51], [0.87 / 1.38]),
        ([0.0, 1.0, -1.0, 0.0], [0.0, 0.5, 1.0]),  # roots at both ends, taken with the mirror deflation first
        ([0.0, 0.0, 1.0], [0.0, 0.0]),  # a double root at t = 0: two deflations
        ([1.0, 0.0, 0.0], [1.0, 1.0]),
        ([1.0, 2.0, 3.0], []),
        ([3.0], []),
        ([1.0, -1.0, 2.0, -3.0], [0.5960133932]),  # the polygon's first crossing (0.8) would skip this root
    ],
)
def test_hull_march_edge_cases(coeffs, expected):
    np.testing.assert_allclose(hull_march(coeffs), expected, atol=1e-10)


def test_hull_march_finds_the_circle_curve_roots_with_the_one_at_t_equal_1():
    example = notes_example("07.circle_curve")
    exact = [Fraction(1), Fraction(-9, 2), Fraction(41, 6), Fraction(-1), Fraction(0)]
    np.testing.assert_allclose(example.results["bernstein"], [float(x) for x in exact])
    found = hull_march(example.results["bernstein"])
    np.testing.assert_allclose(found, exact_roots(exact), atol=1e-12)
    np.testing.assert_allclose(found, example.results["roots"], atol=5e-6)


def test_hull_march_agrees_with_numpy_on_random_simple_roots():
    rng = np.random.default_rng(91)
    for _ in range(40):
        coeffs, inner = random_simple(rng)
        np.testing.assert_allclose(hull_march(coeffs), inner, atol=1e-9)
        np.testing.assert_allclose(hull_march(coeffs), power_roots(coeffs), atol=1e-8)


def test_the_plain_march_is_the_same_algorithm():
    rng = np.random.default_rng(5)
    cases = [random_simple(rng)[0] for _ in range(40)]
    cases += [np.array(c) for c in ([-0.87, 0.51], [0.0, 1.0, -1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0],
                                    [1.0, 2.0, 3.0], [3.0], [1.0, -1.0, 2.0, -3.0], [-1.99, 1.0])]
    cases.append(notes_example("07.circle_curve").results["bernstein"])
    for coeffs in cases:
        np.testing.assert_allclose(hull_march_plain(coeffs), hull_march(coeffs), atol=1e-12)
    example = notes_example("09.from_roots")
    np.testing.assert_allclose(hull_march_plain(example.results["coeffs"], interval=example.inputs["interval"]),
                               example.inputs["roots"], atol=1e-11)
    with pytest.raises(RuntimeError, match="multiple root"):
        hull_march_plain(bernstein_from_roots([0.3, 0.3, 0.7]), max_steps=500)


def test_newton_in_a_bracket_and_one_root_per_cluster():
    coeffs = bernstein_from_roots([0.3, 1.4, -0.5])
    root = newton_in_bracket(coeffs, (0.0, 1.0), (coeffs[0], coeffs[-1]), 1e-12)
    assert root == pytest.approx(0.3, abs=1e-15)
    assert one_root_per_cluster([(0.5, 0.5), (0.2, 0.3), (0.3 + 1e-13, 0.31), (0.9, 1.0)], 1e-12).tolist() == [
        pytest.approx(0.255), 0.5, 1.0]
    assert one_root_per_cluster([], 1e-12).size == 0


def test_hull_march_maps_its_interval():
    example = notes_example("09.from_roots")
    np.testing.assert_allclose(hull_march(example.results["coeffs"], interval=example.inputs["interval"]),
                               example.inputs["roots"], atol=1e-11)


def test_a_double_root_stalls_the_march_with_a_clear_error():
    coeffs = bernstein_from_roots([0.3, 0.3, 0.7])
    with pytest.raises(RuntimeError, match="multiple root"):
        hull_march(coeffs)
    steps = hull_march_steps(coeffs)
    assert steps[-1].event == "stalled" and 0.29 < steps[-1].start < 0.3
    # The crawl is sublinear: the distance to the root after k steps falls roughly like 1/k.
    gaps = np.array([0.3 - s.start for s in steps[1:-1]])
    assert gaps[99] / gaps[399] == pytest.approx(4, rel=0.2)


# ---------------------------------------------------------------- combined subdivision and derivative (§9.2)


def test_derivative_isolation_example():
    example = notes_example("09.derivative_isolation")
    coeffs = bernstein_from_roots(np.concatenate(example.args("roots_inside", "roots_outside")))
    np.testing.assert_allclose(bcom_roots(coeffs), example.results["roots"], atol=1e-13)
    steps = bcom_steps(coeffs)
    assert len(steps) == example.results["looks"] and steps[0].variations == example.results["variations"]
    assert [s.order for s in steps] == [0, 1, 2, 1, 1, 0, 0, 0]
    (inflection,) = steps[2].roots
    assert inflection == pytest.approx(example.results["inflection"], abs=1e-12)
    critical = [s.roots[0] for s in steps[3:5]]
    np.testing.assert_allclose(critical, example.results["critical"], atol=1e-12)
    # f is cut at its critical points: three monotone pieces, one root each
    assert [s.interval for s in steps[5:]] == [(0.0, critical[0]), (critical[0], critical[1]), (critical[1], 1.0)]


def test_bcom_finds_a_double_root_as_accurately_as_the_simple_root_of_the_derivative():
    for pair in ([0.3, 0.3, 0.7], [0.25, 0.25, 0.6, 0.6], [0.5, 0.5, 0.5, 0.2]):
        coeffs = bernstein_from_roots(pair)
        np.testing.assert_allclose(bcom_roots(coeffs), sorted(set(pair)), atol=1e-12)


def test_bcom_agrees_with_the_default_on_random_polynomials():
    rng = np.random.default_rng(17)
    for _ in range(60):
        coeffs = rng.normal(size=int(rng.integers(2, 10)))
        np.testing.assert_allclose(bcom_roots(coeffs), bernstein_roots(coeffs), atol=1e-9)


def test_bcom_maps_its_interval():
    example = notes_example("09.from_roots")
    np.testing.assert_allclose(bcom_roots(example.results["coeffs"], interval=example.inputs["interval"]),
                               example.inputs["roots"], atol=1e-12)
    assert all(2 <= s.interval[0] <= s.interval[1] <= 5 for s in bcom_steps(example.results["coeffs"], (2, 5)))


# ---------------------------------------------------------------- the default, fast and plain


def test_circle_curve_roots_include_the_endpoint():
    example = notes_example("07.circle_curve")
    exact = exact_roots([1, Fraction(-9, 2), Fraction(41, 6), -1, 0])
    for solver in (bernstein_roots, bernstein_roots_plain):
        np.testing.assert_allclose(solver(example.results["bernstein"]), exact, atol=1e-13)


def test_a_root_that_rounding_pushed_outside_the_interval_stays_outside():
    # Through the power basis the last coefficient of E7.5 comes out -7e-15, not 0: the root at t = 1 moves a hair
    # past the end. It is not reported: only exact coefficients (or a wider interval) keep it.
    g = notes_example("07.circle_curve").results["g"]
    coeffs = power_to_bernstein(g)
    assert coeffs[-1] < 0
    assert len(bernstein_roots(coeffs)) == 3
    widened = power_to_bernstein(g, interval=(0, 1.5))
    np.testing.assert_allclose(bernstein_roots(widened, interval=(0, 1.5))[-1], 1.0, atol=1e-13)


@pytest.mark.parametrize("degree", [5, 10, 15, 20])
def test_wilkinson_type_roots_are_found_far_more_accurately_than_from_the_power_form(degree):
    bernstein, power, exact = wilkinson_polynomial(degree)
    ours = np.abs(bernstein_roots(bernstein) - exact).max()
    theirs = np.abs(np.sort_complex(np.roots(power[::-1])) - exact).max()
    assert ours < 1e-9
    if degree == notes_example("09.conditioning").inputs["degree"]:
        assert theirs > notes_example("09.conditioning").results["error_ratio_at_least"] * ours


def test_the_rounded_wilkinson_polynomial_has_its_roots_where_sympy_puts_them():
    bernstein, _, exact = wilkinson_polynomial(7)
    np.testing.assert_allclose(bernstein_roots(bernstein), exact_roots([Fraction(b) for b in bernstein]), atol=1e-14)
    np.testing.assert_allclose(bernstein_roots(bernstein), exact, atol=1e-14)


def _battery():
    """Polynomials of every kind the default must handle, with their roots in [0, 1] (distinct, sorted)."""
    rng = np.random.default_rng(2024)
    cases = []
    for _ in range(30):
        coeffs, inner = random_simple(rng)
        cases.append(pytest.param(coeffs, inner, 1e-10, id=f"simple-{len(cases)}"))
    for rs in ([0.3, 0.3, 0.7], [0.25, 0.25, 0.6, 0.6], [0.5, 0.5, 0.5, 0.5], [0.0, 0.0, 0.5], [1.0, 1.0, 0.2]):
        cases.append(pytest.param(bernstein_from_roots(rs), sorted(set(rs)), 1e-6, id=f"multiple-{rs}"))
    for scale in (1e-200, 1e200):
        cases.append(pytest.param(bernstein_from_roots([0.2, 0.7, 1.5]) * scale, [0.2, 0.7], 1e-12, id=f"{scale:g}"))
    inner = np.sort(rng.uniform(0.05, 0.95, 8))
    wide = bernstein_from_roots(np.concatenate([inner, rng.uniform(2, 3, 92)]))  # degree 100, huge range
    cases.append(pytest.param(wide, inner, 1e-10, id="degree-100"))
    return cases


@pytest.mark.parametrize("coeffs, expected, atol", _battery())
def test_the_fast_and_the_plain_form_find_the_same_roots(coeffs, expected, atol):
    fast, plain = bernstein_roots(coeffs), bernstein_roots_plain(coeffs)
    assert len(fast) == len(plain) == len(expected)
    np.testing.assert_allclose(fast, expected, atol=atol)
    np.testing.assert_allclose(plain, fast, atol=atol)


def test_random_polynomials_agree_with_numpy_and_scipy():
    rng = np.random.default_rng(9)
    for _ in range(80):
        coeffs = rng.normal(size=int(rng.integers(2, 12)))
        found = bernstein_roots(coeffs)
        np.testing.assert_allclose(found, power_roots(coeffs), atol=1e-8)
        np.testing.assert_allclose(found, scipy_roots(coeffs), atol=1e-8)


def test_roots_are_roots_of_the_power_form_too():
    coeffs = np.array([2.0, -3.0, 1.0, 2.0, -1.0])
    found = bernstein_roots(coeffs)
    assert len(found) == 3
    np.testing.assert_allclose(P.polyval(found, bernstein_to_power(coeffs)), 0, atol=1e-14)


def test_interval_maps_the_roots():
    example = notes_example("09.from_roots")
    found = bernstein_roots(example.results["coeffs"], interval=example.inputs["interval"])
    np.testing.assert_allclose(found, example.inputs["roots"], atol=1e-12)
    np.testing.assert_allclose(found, scipy_roots(example.results["coeffs"], example.inputs["interval"]), atol=1e-12)


@pytest.mark.parametrize(
    "coeffs, expected",
    [([1.0, -1.0], [0.5]), ([0.0, 1.0, 2.0], [0.0]), ([2.0, 1.0, 0.0], [1.0]), ([1.0, 2.0, 3.0], []), ([3.0], []),
     ([1.0, -1.0, 1.0], [0.5]), ([1.0, -1.0 - 1e-9, 1.0], [0.5 - 1.25e-10**0.5, 0.5 + 1.25e-10**0.5])],
)
def test_edge_cases(coeffs, expected):
    for solver in (bernstein_roots, bernstein_roots_plain):
        np.testing.assert_allclose(solver(coeffs), expected, atol=1e-6)


def test_a_tangency_comes_back_once_and_a_near_miss_not_at_all():
    touching = bernstein_from_roots([0.4, 0.4])
    assert bernstein_roots(touching) == pytest.approx([0.4], abs=1e-7)
    missing = touching + 1e-6  # lifted clear of the axis: no real root
    assert bernstein_roots(missing).size == 0


@pytest.mark.parametrize(
    "kwargs, match",
    [
        ({"coeffs": [0.0, 0.0]}, "^coeffs.*zero polynomial"),
        ({"coeffs": [[1.0, 2.0]]}, "^coeffs"),
        ({"coeffs": []}, "^coeffs"),
        ({"coeffs": "1, 2"}, "^coeffs"),
        ({"coeffs": [1.0, -1.0], "interval": (1, 0)}, "^interval"),
        ({"coeffs": [1.0, -1.0], "interval": (0, 1, 2)}, "^interval"),
        ({"coeffs": [1.0, -1.0], "tol": 0.0}, "^tol"),
        ({"coeffs": [1.0, -1.0], "tol": 2.0}, "^tol"),
    ],
)
@pytest.mark.parametrize("solver", [bernstein_roots, bernstein_roots_plain, hull_march, hull_march_plain, bcom_roots])
def test_bad_input_is_rejected_with_the_argument_named(solver, kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        solver(**kwargs)


# ---------------------------------------------------------------- products and polynomials from roots (§9.3)


def test_product_notes_example_and_the_power_basis():
    example = notes_example("09.product")
    f, g = example.args("f", "g")
    np.testing.assert_allclose(bernstein_multiply(f, g), example.results["product"], rtol=1e-15)
    power = bernstein_to_power(bernstein_multiply(f, g))  # degree 3, with a cubic term that cancels
    np.testing.assert_allclose(power, np.append(example.results["power"], 0.0), atol=1e-14)
    np.testing.assert_allclose(P.polymul(bernstein_to_power(f), bernstein_to_power(g)), example.results["power"])


def test_the_binomial_recurrence_of_the_notes():
    example = notes_example("09.binomials")
    n = example.inputs["n"]
    row = [1.0]
    for i in range(1, int(n) + 1):
        row.append((n - i + 1) / i * row[-1])
    assert row == example.results["row"].tolist() == [comb(7, i) for i in range(8)]


def test_from_roots_notes_example():
    example = notes_example("09.from_roots")
    rs, interval = example.args("roots", "interval")
    t0, t1 = interval
    np.testing.assert_allclose([[t0 - r, t1 - r] for r in rs], example.results["factors"])
    coeffs = bernstein_from_roots(rs, interval=interval)
    np.testing.assert_allclose(coeffs, example.results["coeffs"], rtol=1e-15)
    np.testing.assert_allclose(explicit_bezier(coeffs, interval)[:, 0], example.results["abscissae"])


def test_from_roots_matches_the_power_basis_product_on_any_interval():
    rng = np.random.default_rng(3)
    for _ in range(20):
        rs = rng.uniform(-3, 3, int(rng.integers(0, 7)))
        t0 = rng.uniform(-2, 1)
        interval = (t0, t0 + rng.uniform(0.5, 3))
        leading = rng.uniform(-4, 4)
        coeffs = bernstein_from_roots(rs, interval=interval, leading=leading)
        assert coeffs.shape == (len(rs) + 1,)
        expected = power_to_bernstein(leading * P.polyfromroots(rs), interval=interval)
        np.testing.assert_allclose(coeffs, expected, atol=1e-9 * max(1.0, np.abs(expected).max()))


def test_from_roots_without_roots_is_the_constant_and_rejects_a_table():
    assert bernstein_from_roots([], leading=2.5).tolist() == [2.5]
    with pytest.raises(ValueError, match="^roots"):
        bernstein_from_roots([[0.1, 0.2]])
    with pytest.raises(ValueError, match="^interval"):
        bernstein_from_roots([0.1], interval=(1, 1))


# ---------------------------------------------------------------- line ∩ rational curve (§9.4)


def _quartic():
    curve = notes_example("07.clip_lmin")
    return curve.inputs["points"], curve.inputs["weights"]


def test_line_curve_notes_example():
    example = notes_example("09.line_curve")
    assert example.inputs["curve"] == "07.clip_lmin"
    points, weights = _quartic()
    for line, root, point in zip(example.inputs["lines"], example.results["roots"], example.results["points"]):
        ts, pts = line_curve_intersection(points, line, weights)
        np.testing.assert_allclose(ts, [root], atol=1e-13)
        np.testing.assert_allclose(pts, [point], atol=1e-8)
    # the values f_i are the heights E_i of chapter 7's clipping example, and the roots its 'inside' interval
    h = np.column_stack([points, np.ones(len(points))]) * weights[:, None]
    np.testing.assert_allclose(h @ example.inputs["lines"].T, example.results["values"].T)
    np.testing.assert_allclose(example.results["roots"], notes_example("07.clip_lmax").results["inside"], atol=1e-12)


def test_line_curve_weights_matter():
    example = notes_example("09.line_curve")
    points, _ = _quartic()
    for line, wrong in zip(example.inputs["lines"], example.results["unweighted_roots"]):
        ts, _ = line_curve_intersection(points, line)
        np.testing.assert_allclose(ts, [wrong], atol=1e-9)


def test_intersections_lie_on_the_line_and_the_curve():
    rng = np.random.default_rng(8)
    for _ in range(20):
        points = rng.uniform(-5, 5, (int(rng.integers(2, 7)), 2))
        weights = rng.uniform(0.3, 3, len(points))
        line = np.array([*rng.normal(size=2), rng.uniform(-1, 1)])
        ts, pts = line_curve_intersection(points, line, weights)
        assert pts.shape == (len(ts), 2) and np.all(np.diff(ts) > 0)
        np.testing.assert_allclose(pts @ line[:2] + line[2], 0, atol=1e-9)
        np.testing.assert_allclose(pts, evaluate(points, ts, weights) if len(ts) else np.empty((0, 2)))


def test_line_curve_special_cases():
    cubic = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]  # symmetric about x = 2, top at y = 1.5
    ts, pts = line_curve_intersection(cubic, (0.0, 1.0, -1.5))  # the tangent at the top: one point
    np.testing.assert_allclose(ts, [0.5], atol=1e-7)
    np.testing.assert_allclose(pts, [[2.0, 1.5]], atol=1e-7)
    ts, pts = line_curve_intersection(cubic, (0.0, 1.0, -2.0))  # above the curve: none
    assert ts.shape == (0,) and pts.shape == (0, 2)
    ts, _ = line_curve_intersection(cubic, (1.0, 0.0, 0.0))  # through the first end point
    np.testing.assert_allclose(ts, [0.0], atol=1e-15)
    ts, _ = line_curve_intersection(cubic, (0.0, 1.0, 0.0))  # the chord: both ends
    np.testing.assert_allclose(ts, [0.0, 1.0], atol=1e-15)


@pytest.mark.parametrize(
    "args, match",
    [
        (([(0.0, 0.0), (1.0, 1.0)], (1.0, -1.0, 0.0)), "^line.*lies on the line"),
        (([(0.0, 0.0), (1.0, 1.0)], (0.0, 0.0, 1.0)), "^line"),
        (([(0.0, 0.0), (1.0, 1.0)], (1.0, 1.0)), "^line"),
        (([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], (1.0, 1.0, 1.0)), "^points"),
        (([(0.0, 0.0), (1.0, 1.0)], (1.0, 1.0, -1.0), [1.0, 0.0]), "^weights"),
        (([(0.0, 0.0), (1.0, 1.0)], (1.0, 1.0, -1.0), [1.0]), "^weights"),
    ],
)
def test_line_curve_bad_input(args, match):
    with pytest.raises(ValueError, match=match):
        line_curve_intersection(*args)


# ---------------------------------------------------------------- the conditioning example


def test_wilkinson_coefficients_are_the_correctly_rounded_exact_ones():
    bernstein, power, exact = wilkinson_polynomial(6)
    rs = [Fraction(k, 7) for k in range(1, 7)]
    poly = sp.Poly(sp.prod([T - sp.Rational(r) for r in rs]), T)
    assert power.tolist() == [float(c) for c in reversed(poly.all_coeffs())]
    np.testing.assert_allclose(bernstein, power_to_bernstein(power), rtol=1e-12)
    assert exact.tolist() == [float(r) for r in rs]
    with pytest.raises(ValueError, match="^degree"):
        wilkinson_polynomial(0)

"""Unit tests of cagd_ref.interval_bezier: interval arithmetic, interval Bézier curves and enclosures (chapter 12).

The notes' Examples 1 and 2, the quarter circle and the course's own examples
come from cagd_course/examples/ch12.toml. Independent peers: mpmath's interval
arithmetic (`mpmath.iv`, outward-rounded) for every operation of `Interval`
and for the boxes of the de Casteljau algorithm; exact rational arithmetic
(`fractions.Fraction`) for containment and tightness on thousands of seeded
random curves; SymPy for the Hermite coefficients; SciPy's Krogh interpolator
for the Hermite interpolant; dense sampling of the true functions for every
enclosure.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import operator
from fractions import Fraction
from math import comb

import numpy as np
import pytest
import sympy as sp
from mpmath import iv
from scipy.interpolate import KroghInterpolator

from cagd_course.examples import notes_example
from cagd_ref import bezier
from cagd_ref import interval_bezier as ib
from cagd_ref.interval_bezier import Interval

ARITHMETIC = notes_example("12.arithmetic")
CUBIC = notes_example("12.cubic")
TS = np.linspace(0, 1, 201)
WIDE_TS = np.linspace(-1.5, 2.5, 161)
OPERATORS = {"+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv}


def random_boxes(rng, n=None, d=2) -> np.ndarray:
    n = int(rng.integers(0, 6)) if n is None else n
    centres = rng.uniform(-3, 3, (n + 1, d))
    return ib.boxes_from_center(centres, rng.uniform(0, 0.5, (n + 1, d)) * (rng.uniform(size=(n + 1, d)) < 0.8))


def interval_of(pair) -> Interval:
    return Interval(*pair)


# ---------------------------------------------------------------- Interval: the notes' identities


def test_the_notes_identities():
    u, v, factor, divisor = (interval_of(ARITHMETIC.inputs[k]) for k in ("u", "v", "factor", "divisor"))
    w = ARITHMETIC.inputs["w"]
    r = ARITHMETIC.results
    assert (u - u) == interval_of(r["u_minus_u"]) and (u - u) != Interval(0.0)
    assert u * factor == interval_of(r["product"])
    assert u / divisor == interval_of(r["quotient"])
    assert u * (v + w) == interval_of(r["u_times_sum"])
    assert u * v + u * w == interval_of(r["sum_of_products"])
    assert (u * v + u * w).contains(u * (v + w)) and u * (v + w) != u * v + u * w
    i = Interval(-1.0, 1.0)
    assert 1 * i + (-1) * i == interval_of(r["alpha_beta"])


def test_u_minus_u_is_its_width_times_the_unit_interval():
    rng = np.random.default_rng(1)
    for lo, width in rng.uniform(-5, 5, (50, 2)):
        u = Interval(lo, lo + abs(width))
        assert u - u == Interval(-u.width, u.width)


def test_addition_and_multiplication_commute_and_associate_and_scalars_distribute():
    rng = np.random.default_rng(2)
    for _ in range(200):
        x, y, z = (Interval(*np.sort(rng.integers(-6, 7, 2)).astype(float)) for _ in range(3))
        alpha = float(rng.integers(-4, 5))
        assert x + y == y + x and x * y == y * x
        assert (x + y) + z == x + (y + z) and (x * y) * z == x * (y * z)
        assert alpha * (x + y) == alpha * x + alpha * y  # (12.5)
        assert (x * y + x * z).contains(x * (y + z))  # subdistributivity


def test_properties_and_the_centred_form():
    u = Interval(1.0, 4.0)
    assert (u.width, u.mid, u.radius) == (3.0, 2.5, 1.5)
    assert Interval.from_center(2.5, 1.5) == u
    assert Interval(3) == Interval(3.0, 3.0) and Interval(3).width == 0.0
    assert 2 in u and 5 not in u and Interval(2, 3) in u and Interval(0, 2) not in u
    assert -u == Interval(-4.0, -1.0) and +u is u
    assert str(u) == "[1, 4]"


def test_numbers_on_either_side_numpy_scalars_included():
    u = Interval(1.0, 2.0)
    assert 2 - u == Interval(0.0, 1.0) and u - 2 == Interval(-1.0, 0.0)
    assert 1 / u == Interval(0.5, 1.0) and u / 2 == Interval(0.5, 1.0)
    assert 3 + u == u + 3 == Interval(4.0, 5.0) and -2 * u == u * -2 == Interval(-4.0, -2.0)
    assert np.float64(2.0) - u == Interval(0.0, 1.0) and np.float64(2.0) * u == Interval(2.0, 4.0)
    with pytest.raises(TypeError):
        u + "1"
    with pytest.raises(TypeError):
        u * [1.0, 2.0]


def test_intervals_are_frozen_values():
    u = Interval(1.0, 2.0)
    with pytest.raises(dataclasses.FrozenInstanceError):
        u.lo = 0.0
    assert hash(u) == hash(Interval(1, 2)) and len({u, Interval(1.0, 2.0)}) == 1
    v = Interval(3.0, 5.0)
    u + v, u - v, u * v, u / v
    assert (u, v) == (Interval(1.0, 2.0), Interval(3.0, 5.0))


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: Interval(2.0, 1.0), "^lo: expected lo <= hi"),
        (lambda: Interval(float("nan"), 1.0), "^lo"),
        (lambda: Interval(0.0, float("inf")), "^hi"),
        (lambda: Interval(1.0, 2.0) / Interval(-1.0, 1.0), "^divisor: .* contains 0"),
        (lambda: Interval(1.0, 2.0) / Interval(0.0, 1.0), "^divisor"),
        (lambda: 1 / Interval(-2.0, 0.0), "^divisor"),
        (lambda: Interval(1.0, 2.0) / 0, "^divisor"),
        (lambda: Interval.from_center(1.0, -0.5), "^error"),
    ],
)
def test_bad_intervals_and_division_by_an_interval_holding_zero(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_lo_must_be_a_number():
    with pytest.raises(TypeError, match="^lo"):
        Interval("1", 2.0)


# ---------------------------------------------------------------- Interval against mpmath.iv


def _iv(x):
    return iv.mpf([x.lo, x.hi]) if isinstance(x, Interval) else iv.mpf(x)


def _operand(rng):
    if rng.uniform() < 0.3:
        return float(rng.uniform(-4, 4))
    lo = float(rng.uniform(-4, 4))
    return Interval(lo, lo + float(rng.exponential(1.5)) * (rng.uniform() < 0.9))


@pytest.mark.parametrize("symbol", list(OPERATORS))
def test_every_operation_agrees_with_mpmath_interval_arithmetic(symbol):
    """mpmath rounds outward, so its result holds ours, and ours widened by one ulp holds its."""
    rng = np.random.default_rng(list(OPERATORS).index(symbol))
    op = OPERATORS[symbol]
    checked = 0
    while checked < 500:
        x, y = _operand(rng), _operand(rng)
        if not isinstance(x, Interval) and not isinstance(y, Interval):
            continue
        if symbol == "/" and (ib._as_interval(y).lo <= 0 <= ib._as_interval(y).hi):
            with pytest.raises(ValueError, match="^divisor"):
                op(x, y)
            continue
        ours, theirs = op(x, y), op(_iv(x), _iv(y))
        assert float(theirs.a) <= ours.lo and ours.hi <= float(theirs.b), (x, symbol, y)
        wide = ours.outward()
        assert wide.lo <= float(theirs.a) and float(theirs.b) <= wide.hi, (x, symbol, y)
        checked += 1


def test_negation_agrees_with_mpmath():
    for lo, hi in [(1.0, 2.0), (-3.0, 0.5), (-2.0, -1.0)]:
        theirs = -iv.mpf([lo, hi])
        assert -Interval(lo, hi) == Interval(float(theirs.a), float(theirs.b))


def test_outward_rounding_holds_the_exact_result_of_each_operation():
    rng = np.random.default_rng(3)
    exact_ops = {"+": operator.add, "-": operator.sub, "*": operator.mul, "/": operator.truediv}
    for _ in range(2000):
        symbol = list(OPERATORS)[int(rng.integers(4))]
        a, b = sorted(rng.uniform(-10, 10, 2))
        c, d = sorted(rng.uniform(0.1, 10, 2) * rng.choice([-1, 1]))
        result = OPERATORS[symbol](Interval(a, b), Interval(c, d)).outward()
        exact = [exact_ops[symbol](Fraction(p), Fraction(q)) for p in (a, b) for q in (c, d)]
        if symbol == "+":
            exact = [Fraction(a) + Fraction(c), Fraction(b) + Fraction(d)]
        elif symbol == "-":
            exact = [Fraction(a) - Fraction(d), Fraction(b) - Fraction(c)]
        assert Fraction(result.lo) <= min(exact) and max(exact) <= Fraction(result.hi)


def test_round_outward_widens_arrays_by_one_ulp():
    lo, hi = ib.round_outward([1.0, -2.0], [1.0, 3.0])
    np.testing.assert_array_equal(lo, [np.nextafter(1.0, 0), np.nextafter(-2.0, -3)])
    np.testing.assert_array_equal(hi, [np.nextafter(1.0, 2), np.nextafter(3.0, 4)])
    with pytest.raises(ValueError, match="^lo"):
        ib.round_outward([2.0], [1.0])
    with pytest.raises(ValueError, match="^hi"):
        ib.round_outward([1.0, 2.0], [3.0])


def test_interval_expression_evaluates_plain_data():
    assert ib.interval_expression(("-", [1, 2], [1, 2])) == (-1.0, 1.0)
    assert ib.interval_expression(("/", 1, [2, 4])) == (0.25, 0.5)
    assert ib.interval_expression(("neg", [1, 3])) == (-3.0, -1.0)
    assert ib.interval_expression(("radius", ("*", [1, 2], [-1, 3]))) == 4.0
    assert ib.interval_expression(("mid", [1, 2])) == 1.5
    assert ib.interval_expression(("frozen", [1, 2])) == "frozen"
    assert ib.interval_expression(2.5) == 2.5
    with pytest.raises(ValueError, match="^divisor"):
        ib.interval_expression(("/", [1, 2], [-1, 1]))


# ---------------------------------------------------------------- boxes, affine maps, de Casteljau


def test_centred_form_round_trip():
    rng = np.random.default_rng(4)
    boxes = random_boxes(rng, 4)
    np.testing.assert_allclose(ib.boxes_from_center(*ib.center_error(boxes)), boxes, atol=1e-15)
    c, e = ib.center_error([[0.0, 2.0], [1.0, 1.0]])
    assert c.tolist() == [1.0, 1.0] and e.tolist() == [1.0, 0.0]


def test_the_affine_map_of_two_intervals_in_all_three_ranges_of_t():
    """(12.25) and Fig. 12.3: the crossing lines bound it outside [0, 1]."""
    a, b, c, d = 0.0, 1.0, 2.0, 4.0
    for t in [-1.5, -0.2, 0.0, 0.3, 1.0, 1.4, 3.0]:
        box = ib.interval_affine([[a, b]], [[c, d]], t)[0]
        if 0 <= t <= 1:
            expected = [(1 - t) * a + t * c, (1 - t) * b + t * d]
        elif t < 0:
            expected = [(1 - t) * a + t * d, (1 - t) * b + t * c]
        else:
            expected = [(1 - t) * b + t * c, (1 - t) * a + t * d]
        np.testing.assert_allclose(box, expected, atol=1e-14)
        theirs = (1 - t) * iv.mpf([a, b]) + t * iv.mpf([c, d])
        assert float(theirs.a) <= box[0] + 1e-14 and box[1] <= float(theirs.b) + 1e-14


def test_the_course_cubic():
    boxes = ib.boxes_from_center(*CUBIC.args("centers", "errors"))
    np.testing.assert_allclose(ib.interval_de_casteljau(boxes, CUBIC.inputs["t"]), CUBIC.results["boxes"], atol=1e-12)
    left, right = ib.interval_subdivide(boxes, 0.5)
    np.testing.assert_allclose(left, CUBIC.results["left"], atol=1e-12)
    np.testing.assert_allclose(right[0], CUBIC.results["boxes"][0], atol=1e-12)


def test_lo_and_hi_run_separately_go_wrong_outside_the_unit_interval():
    """The typical mistake: de Casteljau on lo and on hi separately gives lo > hi at t = 2."""
    boxes = ib.boxes_from_center(*CUBIC.args("centers", "errors"))
    lo, hi = bezier.de_casteljau(boxes[..., 0], 2.0), bezier.de_casteljau(boxes[..., 1], 2.0)
    np.testing.assert_allclose(lo, [2.1, -10.5], atol=1e-12)
    np.testing.assert_allclose(hi, [1.9, -13.5], atol=1e-12)
    np.testing.assert_allclose(ib.interval_de_casteljau(boxes, 0.5)[:, 0], bezier.de_casteljau(boxes[..., 0], 0.5))


@pytest.mark.parametrize("seed", range(6))
def test_fast_plain_triangle_and_mpmath_give_the_same_boxes(seed):
    rng = np.random.default_rng(seed)
    boxes = random_boxes(rng, d=int(rng.integers(1, 4)))
    fast = ib.interval_de_casteljau(boxes, WIDE_TS)
    np.testing.assert_allclose(ib.interval_de_casteljau_plain(boxes, WIDE_TS), fast, rtol=1e-12, atol=1e-12)
    for t in (-0.75, 0.4, 1.6):
        last = ib.interval_de_casteljau_triangle(boxes, t)[-1][0]
        np.testing.assert_allclose(last, ib.interval_de_casteljau(boxes, t), rtol=1e-12, atol=1e-12)
        for j in range(boxes.shape[1]):
            level = [iv.mpf(list(box)) for box in boxes[:, j]]
            while len(level) > 1:
                level = [(1 - iv.mpf(t)) * p + iv.mpf(t) * q for p, q in zip(level[:-1], level[1:])]
            ours = ib.interval_de_casteljau(boxes, t)[j]
            np.testing.assert_allclose(ours, [float(level[0].a), float(level[0].b)], rtol=1e-12, atol=1e-12)


def test_centres_are_de_casteljau_and_scalar_polynomials_are_accepted():
    rng = np.random.default_rng(7)
    boxes = random_boxes(rng, 5, d=1)
    np.testing.assert_allclose(ib.interval_de_casteljau(boxes, TS).mean(axis=2),
                               bezier.de_casteljau(ib.center_error(boxes)[0], TS), atol=1e-12)
    scalar = boxes[:, 0]
    np.testing.assert_allclose(ib.interval_de_casteljau(scalar, WIDE_TS),
                               ib.interval_de_casteljau(boxes, WIDE_TS)[:, 0])
    assert ib.interval_de_casteljau(scalar, 0.3).shape == (2,)


def _exact_bernstein(n: int, t: Fraction) -> list[Fraction]:
    return [comb(n, k) * (1 - t) ** (n - k) * t**k for k in range(n + 1)]


def test_containment_and_tightness_in_exact_arithmetic():
    """Thousands of seeded cases: every member curve lies in [P](t), and some corner curve reaches each end."""
    rng = np.random.default_rng(12)
    for _ in range(2500):
        n = int(rng.integers(0, 5))
        boxes = random_boxes(rng, n, d=1)[:, 0]
        t = float(rng.choice([rng.uniform(0, 1), rng.uniform(-2, 0), rng.uniform(1, 3)]))
        basis = _exact_bernstein(n, Fraction(t))
        lo, hi = ib.interval_de_casteljau(boxes, t)
        # The exact range over the boxes: each B_k(t) picks the end of box k that makes the sum smallest or largest.
        ends = [(Fraction(a), Fraction(b)) for a, b in boxes]
        exact_lo = sum(min(b * a0, b * a1) for b, (a0, a1) in zip(basis, ends))
        exact_hi = sum(max(b * a0, b * a1) for b, (a0, a1) in zip(basis, ends))
        scale = 1 + sum(abs(b) for b in basis) * max(abs(x) for pair in ends for x in pair)
        assert abs(Fraction(lo) - exact_lo) <= 1e-13 * scale and abs(Fraction(hi) - exact_hi) <= 1e-13 * scale
        member = [a0 + Fraction(float(rng.uniform())) * (a1 - a0) for a0, a1 in ends]
        value = sum(b * p for b, p in zip(basis, member))
        assert exact_lo <= value <= exact_hi


def test_the_box_is_the_range_over_all_corner_curves():
    """Brute force: a cubic in the plane has 2^8 corner curves, and their extremes are the box's ends."""
    boxes = ib.boxes_from_center(*CUBIC.args("centers", "errors"))
    for t in (0.0, 0.3, 0.5, 1.0, -0.5, 1.7, 2.0):
        rows = np.arange(4)
        values = np.array([
            bezier.de_casteljau(np.column_stack([boxes[rows, 0, list(xs)], boxes[rows, 1, list(ys)]]), t)
            for xs in itertools.product((0, 1), repeat=4) for ys in itertools.product((0, 1), repeat=4)
        ])
        box = ib.interval_de_casteljau(boxes, t)
        np.testing.assert_allclose(box[:, 0], values.min(axis=0), atol=1e-12)
        np.testing.assert_allclose(box[:, 1], values.max(axis=0), atol=1e-12)


def test_monte_carlo_member_curves_stay_inside():
    rng = np.random.default_rng(8)
    for _ in range(20):
        boxes = random_boxes(rng, d=2)
        box = ib.interval_de_casteljau(boxes, WIDE_TS)
        for _ in range(10):
            member = boxes[..., 0] + rng.uniform(size=boxes.shape[:2]) * (boxes[..., 1] - boxes[..., 0])
            values = bezier.de_casteljau(member, WIDE_TS)
            scale = 1e-12 * (1 + np.abs(box).max())
            assert np.all(box[..., 0] - scale <= values) and np.all(values <= box[..., 1] + scale)


# ---------------------------------------------------------------- the error curve


def test_error_curve_inside_is_the_bezier_curve_of_the_errors_and_outside_uses_abs_bernstein():
    rng = np.random.default_rng(9)
    errors = rng.uniform(0, 1, (5, 2))
    np.testing.assert_allclose(ib.error_curve(errors, TS), bezier.de_casteljau(errors, TS), atol=1e-14)
    for t in (-1.3, -0.2, 1.1, 2.5):
        expected = sum(errors[k] * abs(bezier.bernstein(k, 4, t)) for k in range(5))
        np.testing.assert_allclose(ib.error_curve(errors, t), expected, rtol=1e-12)
        signed = (-1.0) ** (np.arange(5) + (4 if t > 1 else 0))
        np.testing.assert_allclose(ib.error_curve(errors, t), bezier.de_casteljau(signed[:, None] * errors, t),
                                   rtol=1e-12)
    assert isinstance(ib.error_curve([1.0, 2.0], 0.5), float)
    with pytest.raises(ValueError, match="^errors: expected non-negative"):
        ib.error_curve([[0.1, -0.1]], 0.5)


def test_the_error_grows_like_t_to_the_n_outside():
    for t in (2.0, 3.0, -1.0, -4.0):
        assert ib.error_curve(np.ones(4), t) == pytest.approx((abs(1 - t) + abs(t)) ** 3)


# ---------------------------------------------------------------- subdivision, ballooning, elevation


@pytest.mark.parametrize("seed", range(4))
def test_subdividing_inside_the_unit_interval_does_not_balloon(seed):
    rng = np.random.default_rng(seed)
    boxes = random_boxes(rng, 4)
    tau = float(rng.uniform(0.1, 0.9))
    left, right = ib.interval_subdivide(boxes, tau)
    np.testing.assert_allclose(ib.interval_de_casteljau(left, TS), ib.interval_de_casteljau(boxes, tau * TS),
                               atol=1e-12)
    np.testing.assert_allclose(ib.interval_de_casteljau(right, TS),
                               ib.interval_de_casteljau(boxes, tau + (1 - tau) * TS), atol=1e-12)
    np.testing.assert_allclose(left[-1], right[0])
    centres, _ = ib.center_error(left)
    np.testing.assert_allclose(centres, bezier.subdivide(ib.center_error(boxes)[0], tau)[0], atol=1e-12)


def test_subdividing_outside_the_unit_interval_inflates():
    example = notes_example("12.ballooning")
    unit = ib.boxes_from_center(np.zeros((4, 1)), np.ones((4, 1)))
    for tau, suffix in zip(example.inputs["tau"], ("2", "3")):
        left, _ = ib.interval_subdivide(unit, tau)
        errors = ib.center_error(left)[1][:, 0]
        np.testing.assert_allclose(errors, example.results[f"left_errors_{suffix}"])
        assert ib.error_curve(errors, 1 / tau) == pytest.approx(example.results[f"at_one_{suffix}"])
        assert ib.error_curve(np.ones(4), 1.0) == 1.0


def test_elevation_keeps_the_boxes_on_the_unit_interval():
    rng = np.random.default_rng(10)
    boxes = random_boxes(rng, 3)
    raised = ib.interval_elevate(boxes, 2)
    assert raised.shape == (6, 2, 2)
    np.testing.assert_allclose(ib.interval_de_casteljau(raised, TS), ib.interval_de_casteljau(boxes, TS), atol=1e-12)


def test_width_is_the_mean_coefficient_width_and_the_integral():
    example = notes_example("12.width")
    coeffs = example.inputs["coeffs"]
    assert ib.interval_polynomial_width(coeffs) == pytest.approx(example.results["width"])
    band = ib.interval_de_casteljau(coeffs, np.linspace(0, 1, 20001))
    assert np.trapezoid(band[:, 1] - band[:, 0], dx=1 / 20000) == pytest.approx(example.results["width"], rel=1e-8)


# ---------------------------------------------------------------- the envelope


def test_envelope_pieces_split_at_tangencies_and_bound_the_swept_region():
    """Each chosen corner point lies on the boundary: outside every other box [P](s), up to sampling."""
    example = notes_example("12.envelope")
    boxes = ib.boxes_from_center(*example.args("centers", "errors"))
    pieces = ib.envelope_pieces(boxes)
    assert pieces == [(0.0, 1.0, tuple(example.results["pair"]))]
    dense = ib.interval_de_casteljau(boxes, np.linspace(0, 1, 4001))
    corners = ib.corner_curves(boxes)
    for name in example.results["pair"]:
        for point in bezier.de_casteljau(corners[name], np.linspace(0.02, 0.98, 49)):
            depth = np.minimum(point - dense[:, :, 0], dense[:, :, 1] - point).min(axis=1)
            assert depth.max() < 3e-3  # not deep inside any box: it is on the region's boundary


def test_envelope_pieces_of_an_arch():
    arch = ib.boxes_from_center([(0, 0), (1, 2), (3, 2), (4, 0)], np.full((4, 2), 0.1))
    assert ib.envelope_pieces(arch) == [(0.0, 0.5, ("TL", "BR")), (0.5, 1.0, ("TR", "BL"))]
    with pytest.raises(ValueError, match="^boxes: the envelope"):
        ib.envelope_pieces(np.zeros((3, 3, 2)))


# ---------------------------------------------------------------- Lagrange and Hermite enclosures


def _band(coeffs, ts=TS):
    return ib.interval_de_casteljau(coeffs, ts)


def test_lagrange_interval_of_exp():
    example = notes_example("12.lagrange_exp")
    nodes, bound = example.args("nodes", "bound")
    coeffs = ib.lagrange_interval(nodes, np.exp(nodes), bound)
    np.testing.assert_allclose(coeffs[:, 0], example.results["lo"], atol=1e-7)
    np.testing.assert_allclose(coeffs[:, 1], example.results["hi"], atol=1e-7)
    assert ib.interval_polynomial_width(coeffs) == pytest.approx((math.e - 1) / 72)
    from cagd_ref.roots import bernstein_from_roots

    np.testing.assert_allclose(bernstein_from_roots(nodes) / 6, example.results["omega"], atol=1e-15)
    band = _band(coeffs)
    assert np.all(band[:, 0] <= np.exp(TS) + 1e-14) and np.all(np.exp(TS) <= band[:, 1] + 1e-14)


def test_lagrange_interval_on_another_interval_and_for_curves():
    nodes = np.array([1.0, 1.7, 2.5, 3.0])
    f = np.sin
    coeffs = ib.lagrange_interval(nodes, np.column_stack([f(nodes), np.cos(nodes)]), [[-1, 1], [-1, 1]], (1.0, 3.0))
    assert coeffs.shape == (5, 2, 2)
    s = np.linspace(1, 3, 101)
    band = ib.interval_de_casteljau(coeffs, (s - 1) / 2)
    truth = np.column_stack([f(s), np.cos(s)])
    assert np.all(band[..., 0] <= truth + 1e-14) and np.all(truth <= band[..., 1] + 1e-14)
    with pytest.raises(ValueError, match="^nodes"):
        ib.lagrange_interval([0.0, 0.0], [1.0, 1.0], [0.0, 1.0])


def test_hermite_bezier_against_scipy_krogh_and_chapter_10():
    from cagd_ref.interpolation import hermite_to_bezier

    rng = np.random.default_rng(11)
    for m in range(1, 5):
        d0, d1 = rng.uniform(-3, 3, m), rng.uniform(-3, 3, m)
        coeffs = ib.hermite_bezier(d0, d1)
        krogh = KroghInterpolator([0.0] * m + [1.0] * m, np.concatenate([d0, d1]))
        np.testing.assert_allclose(bezier.de_casteljau(coeffs[:, None], TS)[:, 0], krogh(TS), atol=1e-9)
    p0, p1, v0, v1 = rng.uniform(-2, 2, (4, 2))
    np.testing.assert_allclose(ib.hermite_bezier([p0, v0], [p1, v1]), hermite_to_bezier(p0, p1, v0, v1), atol=1e-14)


def test_notes_example_1_exp_and_example_2_sine():
    for name, f in (("hermite_exp", np.exp), ("hermite_sin", lambda t: np.sin(np.pi * t / 2))):
        example = notes_example(f"12.{name}")
        coeffs = ib.hermite_interval(*example.args("derivs0", "derivs1", "bound"))
        np.testing.assert_allclose(coeffs[:, 0], example.results["lo"], atol=1e-14)
        np.testing.assert_allclose(coeffs[:, 1], example.results["hi"], atol=1e-14)
        np.testing.assert_allclose(coeffs[2], example.results["middle_approx"], atol=5e-5)
        assert ib.interval_polynomial_width(coeffs) == pytest.approx(example.results["width"], rel=1e-12)
        band = _band(coeffs)
        assert np.all(band[:, 0] <= f(TS) + 1e-14) and np.all(f(TS) <= band[:, 1] + 1e-14)
    band = _band(ib.hermite_interval(*notes_example("12.hermite_exp").args("derivs0", "derivs1", "bound")))
    assert np.max((band[:, 1] - band[:, 0]) / np.exp(TS)) < notes_example("12.hermite_exp").results["max_relative_band"]


def test_the_hermite_coefficients_exactly_with_sympy():
    """(12.63) symbolically, for arbitrary data: only the middle coefficient carries [f⁽⁴⁾]/144."""
    t, f0, f1, g0, g1, lo, hi = sp.symbols("t f0 f1 g0 g1 lo hi")
    cubic = [f0, f0 + g0 / 3, f1 - g1 / 3, f1]
    quartic = [sum(cubic[j] * sp.binomial(3, j) * (1 - t) ** (3 - j) * t**j for j in range(4))]
    bern4 = [sp.binomial(4, k) * (1 - t) ** (4 - k) * t**k for k in range(5)]
    expected = [f0, f0 + g0 / 4, (f0 + f1) / 2 + (g0 - g1) / 6, f1 - g1 / 4, f1]
    assert sp.expand(quartic[0] - sum(c * b for c, b in zip(expected, bern4))) == 0
    assert sp.expand(t**2 * (t - 1) ** 2 / 24 - bern4[2] / 144) == 0
    values = dict(f0=0.3, f1=-1.2, g0=2.0, g1=0.5)
    coeffs = ib.hermite_interval([values["f0"], values["g0"]], [values["f1"], values["g1"]], [-2.0, 5.0])
    centre = [float(c.subs(values)) for c in expected]
    np.testing.assert_allclose(coeffs[:, 0], np.array(centre) + np.array([0, 0, -2 / 144, 0, 0]), atol=1e-15)
    np.testing.assert_allclose(coeffs[:, 1], np.array(centre) + np.array([0, 0, 5 / 144, 0, 0]), atol=1e-15)


def test_linear_and_quintic_hermite_of_exp_and_the_middle_widths():
    for name in ("hermite_linear_exp", "hermite_quintic_exp"):
        example = notes_example(f"12.{name}")
        coeffs = ib.hermite_interval(*example.args("derivs0", "derivs1", "bound"))
        np.testing.assert_allclose(coeffs[:, 0], example.results["lo"], atol=1e-7)
        np.testing.assert_allclose(coeffs[:, 1], example.results["hi"], atol=1e-7)
        band = _band(coeffs)
        assert np.all(band[:, 0] <= np.exp(TS) + 1e-14) and np.all(np.exp(TS) <= band[:, 1] + 1e-14)
    example = notes_example("12.middle_width")
    for n, denominator in zip(example.inputs["n"].astype(int), example.results["denominators"]):
        m = (n + 1) // 2
        coeffs = ib.hermite_interval(np.zeros(m), np.zeros(m), [0.0, 1.0])
        assert 1 / (coeffs[m, 1] - coeffs[m, 0]) == pytest.approx(denominator)
        assert denominator == (math.factorial(n + 1) // math.factorial(m)) ** 2
        widths = coeffs[:, 1] - coeffs[:, 0]
        assert np.count_nonzero(widths) == 1


def test_a_polynomial_of_degree_2m_is_enclosed_exactly_and_rescaling_to_an_interval():
    # f = t⁴ - 2t³: f⁽⁴⁾ = 24 exactly, so the enclosure is the quartic itself.
    coeffs = ib.hermite_interval([0.0, 0.0], [-1.0, -2.0], [24.0, 24.0])
    np.testing.assert_allclose(coeffs[:, 0], coeffs[:, 1])
    np.testing.assert_allclose(bezier.de_casteljau(coeffs[:, :1], TS)[:, 0], TS**4 - 2 * TS**3, atol=1e-14)
    # eᵗ on [1, 2]: derivatives with respect to t, the result in the Bernstein basis of [1, 2].
    a, b = 1.0, 2.0
    coeffs = ib.hermite_interval([math.e, math.e], [math.e**2, math.e**2], [math.e, math.e**2], (a, b))
    band = _band(coeffs)
    truth = np.exp(a + TS)
    assert np.all(band[:, 0] <= truth + 1e-13) and np.all(truth <= band[:, 1] + 1e-13)


def test_the_quarter_circle():
    example = notes_example("12.quarter_circle")
    boxes = ib.hermite_interval(*example.args("derivs0", "derivs1", "bound"))
    np.testing.assert_allclose(boxes, example.results["boxes"], atol=1e-15)
    np.testing.assert_allclose(boxes[2, 0], example.results["middle_approx"], atol=5e-5)
    centres, errors = ib.center_error(boxes)
    assert centres[2, 0] == pytest.approx(example.results["center"])
    assert centres[2, 0] != pytest.approx(example.errata["center"].notes, abs=1e-5)
    # (12.79): the largest error is at t = 1/2, C(4, 2) e_2 / 2⁴ per coordinate.
    largest = ib.error_curve(errors, TS).max(axis=0)
    np.testing.assert_allclose(largest, example.results["max_error_exact"], rtol=1e-12)
    assert round(float(largest[0]), 4) == example.results["max_error"]
    band = ib.interval_de_casteljau(boxes, TS)
    circle = np.column_stack([np.cos(np.pi * TS / 2), np.sin(np.pi * TS / 2)])
    assert np.all(band[..., 0] <= circle + 1e-14) and np.all(circle <= band[..., 1] + 1e-14)
    # The centre quartic follows the arc-length parametrisation to about two digits.
    assert np.abs(bezier.de_casteljau(centres, TS) - circle).max() < 5e-3


# ---------------------------------------------------------------- derivative bounds and degree reduction


def test_derivative_bounds_of_the_course_quintic():
    example = notes_example("12.derivative_bounds")
    coeffs, r = example.args("coeffs", "r")
    np.testing.assert_allclose(ib.derivative_bounds(coeffs, r), example.results["bound"])
    np.testing.assert_allclose(ib.derivative_bounds(np.column_stack([coeffs, -coeffs]), r),
                               [example.results["bound"], -example.results["bound"][::-1]])


@pytest.mark.parametrize("seed", range(5))
def test_derivative_bounds_hold_every_sampled_derivative(seed):
    rng = np.random.default_rng(seed)
    coeffs = rng.uniform(-3, 3, int(rng.integers(1, 8)))
    n = len(coeffs) - 1
    for r in range(n + 3):
        lo, hi = ib.derivative_bounds(coeffs, r)
        column = coeffs[:, None]
        values = (bezier.derivative(column, TS, r) if r else bezier.de_casteljau(column, TS))[:, 0]
        assert np.all(lo - 1e-9 <= values) and np.all(values <= hi + 1e-9)
        if r > n:
            assert (lo, hi) == (0.0, 0.0)
        if r == n:  # the n-th derivative is constant: the bound is exact
            assert lo == pytest.approx(hi)


def test_degree_reduction_of_the_course_quintic():
    example = notes_example("12.derivative_bounds")
    coeffs = example.inputs["coeffs"]
    (piece,) = ib.interval_degree_reduce(coeffs)
    np.testing.assert_allclose(piece[:, 0], example.results["lo"], atol=1e-12)
    np.testing.assert_allclose(piece[:, 1], example.results["hi"], atol=1e-12)
    assert ib.interval_polynomial_width(piece) == pytest.approx(example.results["width"])
    halves = ib.interval_degree_reduce(coeffs, depth=1)
    assert [ib.interval_polynomial_width(h) for h in halves] == pytest.approx([example.results["half_width"]] * 2)


@pytest.mark.parametrize("seed", range(4))
def test_degree_reduction_encloses_the_curve_and_shrinks_with_depth(seed):
    rng = np.random.default_rng(seed)
    points = rng.uniform(-3, 3, (int(rng.integers(6, 9)), 2))
    widths = []
    for depth in range(4):
        pieces = ib.interval_degree_reduce(points, depth)
        assert pieces.shape == (2**depth, 5, 2, 2)
        for i, piece in enumerate(pieces):
            s = (i + TS) / 2**depth
            band = ib.interval_de_casteljau(piece, TS)
            truth = bezier.de_casteljau(points, s)
            assert np.all(band[..., 0] <= truth + 1e-11) and np.all(truth <= band[..., 1] + 1e-11)
        widths.append(np.mean([ib.interval_polynomial_width(p) for p in pieces]))
    ratios = np.array(widths[:-1]) / np.array(widths[1:])
    assert np.all(ratios[1:] > 16)  # about 2⁵ per halving once the pieces are small


def test_higher_degree_enclosures_and_bad_degrees():
    points = np.random.default_rng(5).uniform(-1, 1, (9, 1))
    assert ib.interval_degree_reduce(points, 1, degree=6).shape == (2, 7, 1, 2)
    assert ib.interval_degree_reduce(points[:, 0], 0, degree=2).shape == (1, 3, 2)
    with pytest.raises(ValueError, match="^degree"):
        ib.interval_degree_reduce(points, 0, degree=3)


# ---------------------------------------------------------------- bad input


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda: ib.interval_de_casteljau([[[1.0, 0.0]]], 0.5), "^boxes: lo > hi"),
        (lambda: ib.interval_de_casteljau([[1.0, 2.0, 3.0]], 0.5), "^boxes: expected"),
        (lambda: ib.interval_de_casteljau(np.zeros((2, 2, 3)), 0.5), "^boxes: expected"),
        (lambda: ib.interval_de_casteljau(np.zeros((2, 1, 2)), [[0.5]]), "^t"),
        (lambda: ib.boxes_from_center([[0.0, 0.0]], [[0.1]]), "^errors: expected the shape"),
        (lambda: ib.boxes_from_center([[0.0]], [[-0.1]]), "^errors: expected non-negative"),
        (lambda: ib.interval_affine([[0.0, 1.0]], [[0.0, 1.0], [0.0, 1.0]], 0.5), "^box1"),
        (lambda: ib.interval_subdivide(np.zeros((2, 1, 2)), [0.5, 0.6]), "^t"),
        (lambda: ib.hermite_interval([1.0, 1.0], [1.0], [0.0, 1.0]), "^derivs1"),
        (lambda: ib.hermite_interval([1.0], [1.0], [1.0, 0.0]), "^bound: expected lo <= hi"),
        (lambda: ib.hermite_interval([[1.0, 0.0]], [[1.0, 0.0]], [0.0, 1.0]), "^bound: expected"),
        (lambda: ib.derivative_bounds([1.0, 2.0], -1), "^r"),
        (lambda: ib.derivative_bounds([1.0, 2.0], 1.5), "^r"),
    ],
)
def test_bad_input_is_reported_by_name(call, message):
    with pytest.raises((ValueError, TypeError), match=message):
        call()


def test_the_exercise_notebook_and_the_recorded_mistakes_ship_the_evaluator_unchanged():
    """The grader of 12.Interval calls `interval_expression` on the student's class: every copy is the reference's."""
    import inspect
    from pathlib import Path

    import nbformat

    root = Path(__file__).resolve().parents[2]
    source = inspect.getsource(ib.interval_expression).rstrip()
    notebook = nbformat.read(root / "exercises/12-interval-bezier-curves.ipynb", as_version=4)
    shipped = [cell.source for cell in notebook.cells if cell.source.startswith("def interval_expression")]
    assert shipped == [source]
    mistakes = sorted((root / "tests/hidden/mistakes/ch12").glob("interval_expression__*.py"))
    assert len(mistakes) >= 2
    for path in mistakes:
        assert source in path.read_text(encoding="utf-8"), path.name

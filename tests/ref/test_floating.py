"""Unit tests of cagd_ref.floating: the notes' toy format, rounding, and guaranteed boxes for de Casteljau (ch. 13).

The notes' numbers come from cagd_course/examples/ch13.toml. Independent
peers: exact `fractions.Fraction` arithmetic for every value a box must hold
(thousands of seeded cases, in float32 and float64 arithmetic), NumPy's own
float16/float32/float64 rounding and `numpy.nextafter`, `struct` for IEEE bit
patterns, and mpmath's interval arithmetic for an independent enclosure.
"""

from __future__ import annotations

import struct
from fractions import Fraction

import mpmath
import numpy as np
import pytest

from cagd_course.examples import notes_example
from cagd_ref import bezier, polynomials
from cagd_ref import floating as fp

SEVEN = notes_example("13.decode_seven_sixteenths")
NINE = notes_example("13.decode_minus_nine_and_a_half")
THIRD = notes_example("13.one_third")
FIGURE = notes_example("13.figure_13_1")
WIDENING = notes_example("13.widening")
AFFINE = notes_example("13.rounded_affine_map")
QUARTER = notes_example("13.quarter_box")
ROUNDING = notes_example("13.rounding")
IEEE = notes_example("13.ieee_contrast")
F32, F64 = 2.0**-24, 2.0**-53


def exact_de_casteljau(points, t) -> list[Fraction]:
    """The curve point at t in exact rational arithmetic, one Fraction per coordinate."""
    t = Fraction(float(t))
    level = [[Fraction(float(x)) for x in row] for row in np.atleast_2d(points)]
    while len(level) > 1:
        level = [[(1 - t) * a + t * b for a, b in zip(p, q)] for p, q in zip(level[:-1], level[1:])]
    return level[0]


# --- the toy format ---------------------------------------------------------------------------


@pytest.mark.parametrize("example", [SEVEN, NINE], ids=["7/16", "-9.5"])
def test_the_notes_strings_decode_to_their_values(example):
    assert fp.decode_float(example.inputs["bits"]) == example.results["value"]
    assert fp._decoded(example.inputs["bits"]) == Fraction(example.results["value"])
    fraction, exponent = np.frexp(example.results["value"])
    assert (abs(fraction), exponent) == (example.results["fraction"], example.results["exponent"])


def test_the_notes_strings_carry_nine_exponent_bits_and_encode_back():
    for example in (SEVEN, NINE):
        bits = example.inputs["bits"]
        assert [len(field) for field in bits.split("|")] == [1, 9, 23]  # the erratum: 33 bits
        assert fp.encode_float(example.results["value"], exponent_bits=9) == bits
        encoded = example.results["encoded"]
        assert fp.encode_float(example.results["value"]) == encoded and len(encoded) - 2 == 32
        assert fp.decode_float(encoded) == example.results["value"]
    assert "bit_count" in SEVEN.errata


def test_the_neighbours_of_one_third():
    lower, upper = (fp.decode_float(THIRD.results[k]) for k in ("lower_bits", "upper_bits"))
    assert (lower, upper) == (THIRD.results["lower"], THIRD.results["upper"])
    assert fp.neighbours(1 / 3, THIRD.inputs["fraction_bits"]) == (lower, upper)
    assert upper - lower == THIRD.results["spacing"]
    third = Fraction(1, 3)
    assert third - Fraction(lower) == Fraction(1, 3 * 2**24) and Fraction(upper) - third == Fraction(2, 3 * 2**24)
    assert fp.round_to_bits(1 / 3, 23) == THIRD.results["rounded"] == lower
    assert fp.encode_float(1 / 3) == THIRD.results["lower_bits"].replace("|100000001|", "|10000001|")


def test_decoding_follows_the_separators_and_the_formula():
    assert fp.decode_float("0|01|1") == 1.0  # f = 1/2, e = 1
    assert fp.decode_float("1|11|1") == -0.25  # f = 1/2, e = -1
    assert fp.decode_float("0|0000|0101") == 5 / 16  # an unnormalised fraction decodes by the formula
    assert fp.decode_float("0|0101|1") == 16.0  # e = 5
    assert fp.decode_float("0|00|1") == 0.5
    zero = fp.decode_float("1|00|000")
    assert zero == 0 and np.signbit(zero)
    rng = np.random.default_rng(13)
    for _ in range(200):
        width, d = int(rng.integers(3, 11)), int(rng.integers(1, 40))
        limit = 2 ** (width - 1) - 1
        x = float(rng.choice([-1, 1]) * rng.uniform(0.5, 1) * 2.0 ** rng.integers(-limit + 1, limit))
        bits = fp.encode_float(x, width, d)
        assert fp.decode_float(bits) == fp.round_to_bits(x, d)
        assert bits[bits.rindex("|") + 1] == "1"  # normalised: f_1 = 1


def test_ieee_bits_are_not_the_notes_format():
    for value, pattern in zip(IEEE.inputs["values"], IEEE.results["ieee_bits"]):
        raw = format(struct.unpack(">I", struct.pack(">f", value))[0], "032b")
        assert f"{raw[0]}|{raw[1:9]}|{raw[9:]}" == pattern
        assert fp.encode_float(value) != pattern  # bias and hidden bit differ
    assert Fraction(float(np.float32(1 / 3))) == Fraction(IEEE.results["float32_one_third"])
    assert float(np.float32(1 / 3)) not in fp.neighbours(1 / 3, 23)  # 24 bits: a neighbour of its own
    assert fp.encode_float(7 / 16) == IEEE.results["ieee_read_as_notes"]
    assert np.frombuffer(struct.pack(">I", int("0" + "10000001" + "111" + "0" * 20, 2)), ">f4")[0] == 7.5


@pytest.mark.parametrize("bits", ["0|1000000011110", "0|1|1", "0|10|", "2|10|1", "00|10|1", "0 |10|1", "0|10|1|1", ""])
def test_malformed_strings_are_refused(bits):
    with pytest.raises(ValueError, match="^bits"):
        fp.decode_float(bits)


def test_decoding_refuses_what_a_float64_cannot_hold():
    with pytest.raises(TypeError, match="^bits"):
        fp.decode_float(0.5)
    with pytest.raises(ValueError, match="^bits"):
        fp.decode_float("0|011111111111|1")  # 2^2046
    with pytest.raises(ValueError, match="^bits"):
        fp.decode_float("0|01|" + "1" * 60)  # 60 significant bits
    with pytest.raises(ValueError, match="^x"):
        fp.encode_float(2.0**200)  # beyond a 7-bit exponent magnitude
    assert fp.encode_float(0.0) == "0|00000000|" + "0" * 23
    assert fp.encode_float(0.99999999) == "0|00000001|1" + "0" * 22  # rounds up to f = 1: renormalised


# --- rounding -----------------------------------------------------------------------------------


def test_the_rounding_examples():
    for x, d, want in zip(ROUNDING.inputs["x"], ROUNDING.inputs["d"], ROUNDING.results["rounded"]):
        assert fp.round_to_bits(x, int(d)) == want
    assert fp.round_to_bits(0.1, 24) == float(np.float32(0.1))
    np.testing.assert_array_equal(fp.round_to_bits(ROUNDING.inputs["x"][:3], 4), [0.34375, 0.6875, 0.3125])


@pytest.mark.parametrize("kind, d", [(np.float16, 11), (np.float32, 24), (np.float64, 53)])
def test_rounding_agrees_with_numpy_where_the_formats_agree(kind, d):
    rng = np.random.default_rng(d)
    info = np.finfo(kind)
    exponents = rng.uniform(np.log2(float(info.tiny)) + 1, np.log2(float(info.max)) - 1, 20000)
    x = rng.choice([-1, 1], 20000) * 2.0**exponents * rng.uniform(1, 2, 20000)
    x = np.concatenate([x, np.float64(kind(x[:500])) * (1 + 2.0 ** -(d + 1))])  # ties of the d-bit grid
    x = x[np.abs(x) < float(info.max) / 2]
    np.testing.assert_array_equal(fp.round_to_bits(x, d), x.astype(kind).astype(float))
    assert fp.machine_unit(d) == float(info.eps) / 2


def test_rounding_is_relative_and_within_the_machine_unit():
    rng = np.random.default_rng(7)
    x = rng.standard_normal(5000) * 10.0 ** rng.integers(-30, 30, 5000)
    for d in (1, 2, 5, 12, 30):
        rounded = fp.round_to_bits(x, d)
        assert np.all(np.abs(rounded - x) <= fp.machine_unit(d) * np.abs(x))
        _, e = np.frexp(rounded[rounded != 0])
        scaled = np.ldexp(rounded[rounded != 0], d - e)  # the significand as an integer of d bits
        np.testing.assert_array_equal(np.rint(scaled), scaled)
    assert fp.round_to_bits(0.0, 3) == 0.0 and fp.round_to_bits(-0.0, 3) == 0.0
    assert fp.round_to_bits(np.ones((2, 3)) / 3, 2).shape == (2, 3)
    with pytest.raises(ValueError, match="^x"):
        fp.round_to_bits(1.7e308, 2)
    with pytest.raises(ValueError, match="^d"):
        fp.round_to_bits(1.0, 0)
    with pytest.raises(TypeError, match="^d"):
        fp.round_to_bits(1.0, 2.0)


def test_neighbours_agree_with_nextafter():
    rng = np.random.default_rng(3)
    for x in rng.standard_normal(300) * 10.0 ** rng.integers(-20, 20, 300):
        assert fp.neighbours(x, 53) == (np.nextafter(x, -np.inf), np.nextafter(x, np.inf))
        single = np.float32(x)
        low, high = fp.neighbours(float(single), 24)
        down, up = (float(np.nextafter(single, np.float32(side))) for side in (-np.inf, np.inf))
        assert (low, high) == (down, up)
        low, high = fp.neighbours(x, 24)  # x itself is (almost surely) not a float32: the bracket
        assert low < x < high and fp.round_to_bits(x, 24) in (low, high)
    assert fp.neighbours(0.5, 4) == (0.46875, 0.5625) and fp.neighbours(-0.5, 4) == (-0.5625, -0.46875)
    with pytest.raises(ValueError, match="^x"):
        fp.neighbours(0.0, 4)


def test_the_interval_of_a_float_holds_exactly_what_rounds_to_it():
    assert fp.float_interval(THIRD.results["lower"], 23) == tuple(THIRD.results["interval"])
    assert not fp.float_interval(THIRD.results["upper"], 23)[0] <= 1 / 3
    rng = np.random.default_rng(5)
    for _ in range(300):
        d = int(rng.integers(2, 30))
        b = fp.round_to_bits(rng.standard_normal() * 2.0 ** rng.integers(-40, 40), d)
        if rng.uniform() < 0.3:
            b = float(np.copysign(2.0 ** rng.integers(-10, 10), b))  # a power of two
        low, high = fp.float_interval(b, d, exact=True)
        below, above = fp.neighbours(b, d)
        assert (low, high) == ((below + b) / 2, (b + above) / 2)  # the midpoints to the neighbours
        eps = fp.machine_unit(d + 8) * abs(b)
        inside = np.array([low + eps, high - eps, b])
        assert np.all(fp.round_to_bits(inside, d) == b)
        assert fp.round_to_bits(low - eps, d) != b and fp.round_to_bits(high + eps, d) != b
        symmetric = fp.float_interval(b, d)
        assert symmetric[0] <= low and high <= symmetric[1] and symmetric[1] - b == b - symmetric[0]
        assert b - fp.machine_unit(d) * abs(b) <= symmetric[0] and symmetric[1] <= b + fp.machine_unit(d) * abs(b)
    assert fp.float_interval(0.0, 5) == (0.0, 0.0)
    with pytest.raises(ValueError, match="^b"):
        fp.float_interval(0.3, 4)
    with pytest.raises(ValueError, match="^d"):
        fp.float_interval(0.5, 52)


# --- roundoff of affine maps -------------------------------------------------------------------


def test_the_widening_examples():
    p0, p1 = WIDENING.inputs["p0"], WIDENING.inputs["p1"]
    got = [fp.affine_roundoff(p0, p1, t, 1.0) for t in WIDENING.inputs["ts"]]
    assert got == WIDENING.results["widening_over_eta"].tolist()
    np.testing.assert_array_equal(fp.affine_roundoff(p0, p1, WIDENING.inputs["ts"], 1.0), got)
    vector = fp.affine_roundoff(*WIDENING.args("vector_p0", "vector_p1", "vector_t"), 1.0)
    np.testing.assert_array_equal(vector, WIDENING.results["vector_widening_over_eta"])


def test_the_notes_three_branches_are_one_formula():
    rng = np.random.default_rng(2)
    p0, p1, t = rng.uniform(-5, 5, 200), rng.uniform(-5, 5, 200), rng.uniform(-3, 4, 200)
    exact = p0 * (1 - t) + p1 * t
    branches = np.select(
        [t < 0, t <= 1],
        [np.abs(p0) * (1 - t) - np.abs(p1) * t, np.abs(p0) * (1 - t) + np.abs(p1) * t],
        np.abs(p0) * (t - 1) + np.abs(p1) * t,
    ) + np.abs(exact)
    got = np.array([fp.affine_roundoff(a, b, tk, 1.0) for a, b, tk in zip(p0, p1, t)])
    np.testing.assert_allclose(got, branches, rtol=1e-14)


def _float32_affine(p0, p1, t):
    """fl((1 - t) p0 + t p1) computed the ordinary way in numpy.float32: 1 - t rounded too."""
    p0, p1, t = np.float32(p0), np.float32(p1), np.float32(t)
    return (np.float32(1) - t) * p0 + t * p1


def test_13_7_is_first_order_and_our_widening_holds_when_1_minus_t_is_rounded():
    rng = np.random.default_rng(17)
    p0, p1 = (fp.round_to_bits(rng.uniform(-8, 8, 4000), 24) for _ in range(2))
    t = fp.round_to_bits(rng.uniform(-1, 2, 4000), 24)
    computed = _float32_affine(p0, p1, t).astype(float)
    error = np.array([abs(Fraction(c) - ((1 - Fraction(tk)) * Fraction(a) + Fraction(tk) * Fraction(b)))
                      for c, a, b, tk in zip(computed, p0, p1, t)])
    notes = np.array([Fraction(fp.affine_roundoff(a, b, tk, F32)) for a, b, tk in zip(p0, p1, t)])
    assert np.any(error > notes)  # (13.7) assumes an exact 1 - t
    centre, radius = fp.rounded_affine_map(p0, np.zeros(4000), p1, np.zeros(4000), t[0], F32)
    for a, b, tk, c in zip(p0[:50], p1[:50], t[:50], computed[:50]):
        box_centre, box_radius = fp.rounded_affine_map(a, 0.0, b, 0.0, tk, F32)
        assert box_centre == c  # the same arithmetic as numpy.float32
        exact = (1 - Fraction(tk)) * Fraction(a) + Fraction(tk) * Fraction(b)
        assert abs(Fraction(c) - exact) <= Fraction(box_radius)
    assert centre.shape == radius.shape == (4000,)


def test_the_rounded_affine_map_example():
    c0, e0, c1, e1, t, eta = AFFINE.args("c0", "e0", "c1", "e1", "t", "eta")
    centre, radius = fp.rounded_affine_map(c0, e0, c1, e1, t, eta)
    assert centre == AFFINE.results["centre"]
    widening = (radius - AFFINE.results["exact_radius"]) / eta
    assert widening == pytest.approx(AFFINE.results["widening_over_eta"], rel=1e-6)
    box = notes_example("13.figure_13_2")
    eta5 = fp.machine_unit(int(box.inputs["bits"]))
    centre, radius = fp.rounded_affine_map(*box.args("c0", "e0", "c1", "e1", "t"), eta5)
    np.testing.assert_array_equal(centre, box.results["centre"])
    widening = fp.affine_roundoff(box.inputs["c0"], box.inputs["c1"], 0.5, eta5 / (1 - eta5))
    np.testing.assert_allclose(radius, box.results["exact_radius"] + widening, rtol=1e-14)  # 1 - t exact


# --- rounded de Casteljau ------------------------------------------------------------------------


def test_the_quarter_box_is_27_8_eta():
    points, t, eta = QUARTER.args("points", "t", "eta")
    centre, radius = fp.rounded_de_casteljau(points, t, eta)
    np.testing.assert_array_equal(centre, QUARTER.results["centre"])
    assert radius[0] / eta == pytest.approx(QUARTER.results["radius_over_eta"], rel=1e-6)
    assert FIGURE.results["absolute_sum"] == QUARTER.results["radius_over_eta"]
    level = points[:, 0]
    for want in QUARTER.results["level_radii_over_eta"]:  # the radii level by level, from the boxes of each round
        got = [fp.rounded_de_casteljau(level[k : k + len(level) - len(want) + 1, None], t, eta)[1][0] / eta
               for k in range(len(want))]
        assert got == pytest.approx(want, rel=1e-6)


@pytest.mark.parametrize("d", [24, 53, 11, 4])
def test_the_box_holds_the_exact_value(d):
    """Seeded random curves, degrees 1-8, parameters inside and outside [0, 1]: the exact point is in the box."""
    rng = np.random.default_rng(d)
    eta = fp.machine_unit(d)
    for trial in range(400):
        n, dim = int(rng.integers(1, 9)), int(rng.integers(1, 3))
        points = rng.uniform(-10, 10, (n + 1, dim)) * 10.0 ** rng.integers(-3, 4)
        if trial % 3 == 0:
            points = fp.round_to_bits(points, d)  # representable points: the arithmetic alone
        radii = rng.uniform(0, 1e-3, points.shape) if trial % 4 == 0 else None
        t = fp.round_to_bits(rng.uniform(-0.5, 1.5, 4) if trial % 5 == 0 else rng.uniform(0, 1, 4), d)
        centre, radius = fp.rounded_de_casteljau(points, t, eta, radii)
        for k, tk in enumerate(t):
            moved = points if radii is None else points + radii * rng.choice([-1, 1], points.shape)
            for j, value in enumerate(exact_de_casteljau(moved, tk)):
                assert abs(value - Fraction(centre[k, j])) <= Fraction(radius[k, j]), (trial, k, j)


def test_float32_centres_are_numpy_float32_de_casteljau_bit_for_bit():
    coeffs = FIGURE.inputs["coeffs"]
    t = (np.float32(0.25) + np.float32(2.5e-7) * np.arange(-200, 201, dtype=np.float32)).astype(np.float32)
    level = np.tile(coeffs.astype(np.float32), (len(t), 1))
    s = np.float32(1) - t
    while level.shape[1] > 1:
        level = s[:, None] * level[:, :-1] + t[:, None] * level[:, 1:]
    centre, radius = fp.rounded_de_casteljau(coeffs[:, None], t.astype(float), F32)
    np.testing.assert_array_equal(centre[:, 0], level[:, 0].astype(float))
    np.testing.assert_array_equal(fp.evaluate_in_precision(coeffs, t.astype(float), 24), level[:, 0].astype(float))
    exact = (1 - 4 * t.astype(float)) ** 3
    assert np.all(np.abs(centre[:, 0] - exact) <= radius[:, 0])
    assert np.abs(centre[:, 0]).max() > 1e3 * np.abs(exact).max()  # the chaotic band
    assert radius[:, 0].max() < fp.error_bound(coeffs, 0.25, F32)


def test_with_exact_points_at_float64_it_is_the_interval_de_casteljau_of_chapter_12():
    interval_bezier = pytest.importorskip("cagd_ref.interval_bezier")
    rng = np.random.default_rng(12)
    centres = fp.round_to_bits(rng.uniform(-3, 3, (5, 2)), 20)
    radii = rng.uniform(0.01, 0.1, (5, 2))
    t = np.array([0.25, 0.5, -0.5, 1.5])
    boxes = np.stack([centres - radii, centres + radii], axis=-1)
    enclosure = interval_bezier.interval_de_casteljau(boxes, t)
    centre, radius = fp.rounded_de_casteljau(centres, t, F64, radii)
    np.testing.assert_allclose(centre - radius, enclosure[..., 0], atol=1e-12)
    np.testing.assert_allclose(centre + radius, enclosure[..., 1], atol=1e-12)


def test_mpmath_interval_arithmetic_agrees_in_size():
    """mpmath's outward-rounded intervals at 24 bits: an independent enclosure of the same order as ours."""
    t = fp.round_to_bits(0.2500123, 24)
    coeffs = FIGURE.inputs["coeffs"]
    iv = mpmath.iv
    old = iv.prec
    try:
        iv.prec = 24
        tt = iv.mpf(t)
        level = [iv.mpf(c) for c in coeffs]
        while len(level) > 1:
            level = [(1 - tt) * a + tt * b for a, b in zip(level[:-1], level[1:])]
        low, high = float(level[0].a), float(level[0].b)
    finally:
        iv.prec = old
    centre, radius = fp.rounded_de_casteljau(coeffs[:, None], t, F32)
    exact = float((1 - 4 * Fraction(t)) ** 3)
    assert low <= exact <= high and abs(exact - centre[0]) <= radius[0]
    assert 0.3 < 2 * radius[0] / (high - low) < 3


def test_bad_arithmetic_and_parameters_are_refused():
    cubic = QUARTER.inputs["points"]
    with pytest.raises(ValueError, match="^eta"):
        fp.rounded_de_casteljau(cubic, 0.25, 1e-7)  # not a power of two
    with pytest.raises(ValueError, match="^eta"):
        fp.rounded_de_casteljau(cubic, 0.25, 2.0**-30)  # double rounding in float64
    with pytest.raises(ValueError, match="^t"):
        fp.rounded_de_casteljau(cubic, 0.1, F32)  # 0.1 is not a float32
    with pytest.raises(ValueError, match="^radii"):
        fp.rounded_de_casteljau(cubic, 0.25, F32, -np.ones((4, 1)))
    with pytest.raises(ValueError, match="^e1"):
        fp.rounded_affine_map(1.0, 0.0, 2.0, -1.0, 0.5, F32)
    with pytest.raises(ValueError, match="^p1"):
        fp.affine_roundoff([1.0, 2.0], [1.0], 0.5, F32)
    with pytest.raises(ValueError, match="^eta"):
        fp.affine_roundoff(1.0, 2.0, 0.5, -F32)


# --- the band of Figure 13.1 -----------------------------------------------------------------


def test_the_cubic_of_figure_13_1():
    coeffs = FIGURE.inputs["coeffs"]
    np.testing.assert_allclose(bezier.explicit_bezier(coeffs), FIGURE.results["points"], atol=1e-15)
    np.testing.assert_array_equal(polynomials.bernstein_to_power(coeffs), FIGURE.results["power"])
    t = np.linspace(0, 1, 11)
    np.testing.assert_allclose(polynomials.bernstein_horner(coeffs, t), (1 - 4 * t) ** 3, atol=1e-13)
    assert fp.error_bound(coeffs, 0.25, 1.0) == 3 * 3 * FIGURE.results["absolute_sum"]


@pytest.mark.parametrize("method", fp.METHODS)
@pytest.mark.parametrize("bits", [24, 53])
def test_every_method_is_exactly_zero_at_a_quarter_and_noisy_next_to_it(method, bits):
    coeffs = FIGURE.inputs["coeffs"]
    assert fp.evaluate_in_precision(coeffs, FIGURE.inputs["t"], bits, method) == FIGURE.results["value_at_root"]
    half = FIGURE.inputs["window"] / 2 if bits == 24 else 5e-7
    t = fp.round_to_bits(0.25 + np.linspace(-half, half, 401), bits)
    t = t[t != 0.25]
    values = fp.evaluate_in_precision(coeffs, t, bits, method)
    exact = np.array([float((1 - 4 * Fraction(tk)) ** 3) for tk in t])
    signs = np.count_nonzero(np.diff(np.sign(values)))
    assert signs > 50 and np.all(np.diff(np.sign(exact)) <= 0)  # chaotic, while the exact curve falls monotonically
    assert np.abs(values - exact).max() <= fp.error_bound(coeffs, t, fp.machine_unit(bits)).max()
    scale = FIGURE.inputs["value_scale"] if bits == 24 else 1e-15
    assert scale / 10 < np.abs(values).max() < 10 * scale


def test_simulated_precision_is_native_float32_for_horner_too():
    coeffs = FIGURE.inputs["coeffs"]
    t = fp.round_to_bits(np.random.default_rng(1).uniform(0, 1, 300), 24)
    power = polynomials.bernstein_to_power(coeffs).astype(np.float32)
    value = np.full(len(t), power[-1], dtype=np.float32)
    for a in power[-2::-1]:
        value = value * t.astype(np.float32) + a
    np.testing.assert_array_equal(fp.evaluate_in_precision(coeffs, t, 24, "horner"), value.astype(float))
    np.testing.assert_array_equal(fp.evaluate_in_precision(coeffs, t, 53, "bernstein_horner"),
                                  polynomials.bernstein_horner_plain(coeffs, t))
    with pytest.raises(ValueError, match="^method"):
        fp.evaluate_in_precision(coeffs, 0.5, 24, "power")
    with pytest.raises(ValueError, match="^bits"):
        fp.evaluate_in_precision(coeffs, 0.5, 40)
    with pytest.raises(ValueError, match="^t"):
        fp.error_bound(coeffs, 1.5, F32)

"""Hidden grading suite of chapter 13: the notes' binary format, rounding, and guaranteed boxes for de Casteljau.

Fixed cases are the notes' examples (cagd_course/examples/ch13.toml): the two
decoded strings, the neighbours of 1/3, the cubic (1 - 4t)³ of Figure 13.1
whose box at t = 1/4 has the radius (27/8)η, and the course's own widening
examples. Edge cases probe field widths other than the notes', unnormalised
fractions and signed zeros, ties of the rounding, powers of two (where the
neighbour towards 0 is closer), parameters outside [0, 1], coarse arithmetic
(d = 2 to 8 bits, where the η² terms count) and boxes around the control
points. Random cases come from the generator the grader passes in; the
parameters and points of d-bit arithmetic are drawn as d-bit numbers.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import floating

EXAMPLE = "notes examples"
EDGE = "edge cases"
TIES = "ties and powers of two"
SHAPES = "scalar vs array t"
FLOAT32 = "float32 arithmetic"
FLOAT64 = "float64 arithmetic"
COARSE = "coarse arithmetic"
BOXES = "boxes around the points"
RANDOM = "random"
BAD = "bad input"

SEVEN = notes_example("13.decode_seven_sixteenths")
NINE = notes_example("13.decode_minus_nine_and_a_half")
THIRD = notes_example("13.one_third")
FIGURE = notes_example("13.figure_13_1")
WIDENING = notes_example("13.widening")
QUARTER = notes_example("13.quarter_box")
ROUNDING = notes_example("13.rounding")
F32, F64 = 2.0**-24, 2.0**-53
CUBIC = QUARTER.inputs["points"].tolist()


# --- 13.decode_float ----------------------------------------------------------------------------


def decode_float_cases(rng):
    cases = [Case(EXAMPLE, (SEVEN.inputs["bits"],), visible=True), Case(EXAMPLE, (NINE.inputs["bits"],), visible=True),
             Case(EXAMPLE, (THIRD.results["lower_bits"],), visible=True),
             Case(EXAMPLE, (THIRD.results["upper_bits"],), visible=True),
             Case(EXAMPLE, (SEVEN.results["encoded"],), visible=True),  # the 32-bit layout of the text
             Case(EDGE, ("0|01|1",), visible=True),  # the shortest fields: 1/2 x 2^1
             Case(EDGE, ("1|11|1",), visible=True),  # -1/2 x 2^-1
             Case(EDGE, ("0|0000|0101",), visible=True),  # an unnormalised fraction: 5/16
             Case(EDGE, ("0|00101|1000",), visible=True),  # e = 5
             Case(EDGE, ("0|1111|11111",), visible=True),  # e = -7
             Case(EDGE, ("0|000|0000",), visible=True),  # zero
             Case(EDGE, ("0|0000000000001|1",), visible=True),  # a long exponent field
             Case(EDGE, ("1|10000010|" + "1" * 52,), visible=True)]  # 52 fraction bits
    for _ in range(20):
        width, d = int(rng.integers(3, 12)), int(rng.integers(1, 53))
        limit = 2 ** (width - 1) - 1
        x = float(rng.choice([-1, 1]) * rng.uniform(0.5, 1) * 2.0 ** rng.integers(-limit + 1, limit))
        cases.append(Case(RANDOM, (floating.encode_float(x, width, d),)))
    for bad in ("0|1000000011110", "0|1|1", "0|10|", "2|10|1", "00|10|1", "0 |10|1", "0|10|1|1", "", "0|1x|1"):
        cases.append(Case(BAD, (bad,)))
    cases.append(Case(BAD, (0.4375,)))
    return cases


# --- 13.round_to_bits ---------------------------------------------------------------------------


def round_to_bits_cases(rng):
    xs, ds = ROUNDING.inputs["x"], ROUNDING.inputs["d"].astype(int)
    cases = [Case(EXAMPLE, (float(x), int(d)), visible=True) for x, d in zip(xs, ds)]
    cases += [
        Case(EXAMPLE, (xs, 4), visible=True),  # an array
        Case(TIES, ([0.53125, 0.59375, -0.53125, -0.59375], 4), visible=True),
        Case(TIES, ([2.5, 3.5, 4.5, 5.5], 2), visible=True),
        Case(TIES, ([1.0, 0.5, 2.0**-40, -(2.0**30)], 3), visible=True),  # powers of two round to themselves
        Case(EDGE, ([0.0, -0.0, 1e-300, -3e-300], 5), visible=True),
        Case(EDGE, ([0.99, 1.99, 123456.789], 1), visible=True),  # one bit: powers of two only
        Case(EDGE, ([[1 / 3, 2 / 3], [1e10 / 3, -1e-10 / 3]], 7), visible=True),  # any shape
        Case(EDGE, ([0.1, np.pi, 1e20 / 7], 53), visible=True),  # float64 itself: unchanged
        Case(EDGE, ([0.1, np.pi], 60), visible=True),
    ]
    for _ in range(16):
        d = int(rng.choice([11, 24, int(rng.integers(1, 53))]))
        x = rng.standard_normal(int(rng.integers(1, 30))) * 10.0 ** rng.integers(-30, 30)
        cases.append(Case(RANDOM, (x, d)))
    cases += [Case(BAD, (1.0, 0)), Case(BAD, (1.0, -3)), Case(BAD, (1.0, 2.5)), Case(BAD, ("0.5", 4))]
    return cases


# --- 13.float_interval --------------------------------------------------------------------------


def float_interval_cases(rng):
    lower, upper = THIRD.results["lower"], THIRD.results["upper"]
    cases = [
        Case(EXAMPLE, (lower, 23), visible=True),
        Case(EXAMPLE, (upper, 23), visible=True),
        Case(EXAMPLE, (lower, 23), {"exact": True}, visible=True),
        Case(EDGE, (0.75, 2), visible=True),
        Case(EDGE, (-9.5, 5), visible=True),
        Case(EDGE, (0.0, 10), visible=True),
        Case(EDGE, (float(np.float32(0.1)), 24), visible=True),
        Case(EDGE, (3.0, 2), {"exact": True}, visible=True),  # not a power of two: the same both ways
        Case(TIES, (0.5, 4), visible=True),
        Case(TIES, (0.5, 4), {"exact": True}, visible=True),  # the neighbour below is closer
        Case(TIES, (-8.0, 3), {"exact": True}, visible=True),
        Case(TIES, (2.0**-30, 20), {"exact": True}, visible=True),
        Case(TIES, (1.0, 50), {"exact": True}, visible=True),
    ]
    for k in range(16):
        d = int(rng.integers(1, 40))
        b = floating.round_to_bits(rng.standard_normal() * 2.0 ** rng.integers(-60, 60), d)
        if k % 4 == 0:
            b = float(np.copysign(2.0 ** rng.integers(-20, 20), b))
        cases.append(Case(RANDOM, (b, d), {"exact": bool(k % 2)}))
    cases += [Case(BAD, (0.3, 4)), Case(BAD, (1 / 3, 23)), Case(BAD, (0.5, 0)), Case(BAD, (0.5, 60)),
              Case(BAD, ([0.5, 0.25], 4))]
    return cases


# --- 13.affine_roundoff -------------------------------------------------------------------------


def affine_roundoff_cases(rng):
    p0, p1 = WIDENING.inputs["p0"], WIDENING.inputs["p1"]
    v0, v1 = WIDENING.inputs["vector_p0"].tolist(), WIDENING.inputs["vector_p1"].tolist()
    cases = [Case(EXAMPLE, (float(p0), float(p1), float(t), F32), visible=True) for t in WIDENING.inputs["ts"]]
    cases += [
        Case(EXAMPLE, (v0, v1, WIDENING.inputs["vector_t"], F32), visible=True),
        Case(EDGE, (2.0, -3.0, 0.0, F32), visible=True),
        Case(EDGE, (2.0, -3.0, 1.0, F32), visible=True),
        Case(EDGE, (v0, v1, [-0.5, 0.0, 0.5, 1.0, 2.0], F32), visible=True),
        Case(EDGE, ([1.0, -3.0, 9.0], [-3.0, 9.0, -27.0], 0.25, F64), visible=True),  # three coordinates
        Case(EDGE, (4.0, 4.0, -2.0, 0.001), visible=True),  # equal centres
        Case(EDGE, (1.0, -1.0, 0.5, 0.1), visible=True),  # the exact result 0
        Case(EDGE, (3.0, 5.0, 0.7, 0.0), visible=True),  # eta = 0: no widening
        Case(SHAPES, (v0, v1, np.array([0.3]), F32)),
        Case(SHAPES, (2.0, -3.0, np.array([0.3, 1.7]), F32)),
    ]
    for _ in range(14):
        dim = int(rng.integers(1, 4))
        a, b = rng.uniform(-10, 10, dim), rng.uniform(-10, 10, dim)
        t = float(rng.uniform(-2, 3)) if rng.uniform() < 0.5 else rng.uniform(-2, 3, int(rng.integers(2, 6)))
        cases.append(Case(RANDOM, (a, b, t, float(rng.choice([F32, F64, 2.0**-8])))))
    cases += [Case(BAD, ([1.0, 2.0], [1.0], 0.5, F32)), Case(BAD, (1.0, 2.0, 0.5, -F32)),
              Case(BAD, (1.0, 2.0, [[0.5]], F32)), Case(BAD, ([[1.0]], [[2.0]], 0.5, F32))]
    return cases


# --- 13.rounded_de_casteljau --------------------------------------------------------------------


def same_box(expected, received) -> str | None:
    """The same d-bit centre (the prescribed order of operations gives it bit for bit) and radius to 1e-9."""
    if not isinstance(received, (tuple, list)) or len(received) != 2 or not isinstance(expected, tuple):
        return close()(expected, received)
    problem = close(1e-15, 0.0)(expected[0], received[0])
    if problem:
        return f"centre: {problem}"
    problem = close(1e-9, 1e-300)(expected[1], received[1])
    return f"radius: {problem}" if problem else None


def _d_bit(rng, d, shape, low=-10.0, high=10.0):
    return floating.round_to_bits(rng.uniform(low, high, shape), d)


def rounded_de_casteljau_cases(rng):
    quarter = float(QUARTER.inputs["t"])
    near = floating.round_to_bits(0.25 + np.linspace(-5e-5, 5e-5, 9), 24)
    curve = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]]
    cases = [
        Case(EXAMPLE, (CUBIC, quarter, F32), visible=True),  # (27/8) η
        Case(EXAMPLE, (CUBIC, near, F32), visible=True),  # the band of Figure 13.1
        Case(EXAMPLE, (CUBIC, floating.round_to_bits(near, 53), F64), visible=True),
        Case(FLOAT32, (curve, [0.0, 0.375, 0.5, 1.0], F32), visible=True),
        Case(FLOAT32, ([[0.1, 0.2], [0.3, -0.7], [1.1, 0.4]], 0.3125, F32), visible=True),  # points rounded first
        Case(FLOAT32, (curve, [-0.5, 1.5, 2.0], F32), visible=True),  # extrapolation
        Case(FLOAT64, ([[0.1], [0.2], [0.3]], [0.1, 0.7], F64), visible=True),
        Case(EDGE, ([[2.0, -1.0]], [0.0, 0.5], F32), visible=True),  # degree 0: the point and its rounding
        Case(EDGE, ([[1.0], [3.0]], [0.0, 1.0], F32), visible=True),
        Case(COARSE, (CUBIC, [0.25, 0.375, 0.3125], 2.0**-4), visible=True),  # the η² terms count
        Case(COARSE, ([[0.3, 1.7], [2.2, -0.9], [1.3, 0.6]], 0.625, 2.0**-3), visible=True),
        Case(BOXES, (curve, [0.25, 0.75], F32), {"radii": [[0.1, 0.0], [0.0, 0.2], [0.05, 0.05], [0.0, 0.0]]},
             visible=True),
        Case(BOXES, ([[1.0], [2.0], [4.0]], -1.0, 2.0**-6), {"radii": [[0.5], [0.25], [0.125]]}, visible=True),
        Case(SHAPES, (curve, np.array([0.5]), F32)),
        Case(SHAPES, (curve, np.array(0.5), F32)),
    ]
    for k in range(14):
        d = [24, 53, int(rng.integers(3, 16))][k % 3]
        n, dim = int(rng.integers(1, 7)), int(rng.integers(1, 4))
        points = rng.uniform(-10, 10, (n + 1, dim)) if k % 2 else _d_bit(rng, d, (n + 1, dim))
        t = _d_bit(rng, d, int(rng.integers(1, 6)), -0.5 if k % 4 == 0 else 0.0, 1.0)
        kwargs = {"radii": rng.uniform(0, 0.01, (n + 1, dim))} if k % 5 == 0 else {}
        cases.append(Case(RANDOM, (points, t, 2.0**-d), kwargs))
    cases += [
        Case(BAD, (CUBIC, 0.25, 1e-7)),  # not 2^-d
        Case(BAD, (CUBIC, 0.25, 2.0**-40)),  # beyond the simulated range
        Case(BAD, (CUBIC, 0.1, F32)),  # 0.1 is not a float32
        Case(BAD, (CUBIC, [[0.25]], F32)),
        Case(BAD, ([1.0, 2.0], 0.25, F32)),  # not (n+1, d)
        Case(BAD, (CUBIC, 0.25, F32), {"radii": [[-1.0], [0.0], [0.0], [0.0]]}),
        Case(BAD, (CUBIC, 0.25, F32), {"radii": [[0.0], [0.0]]}),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="13.decode_float",
        reference=floating.decode_float,
        cases=decode_float_cases,
        compare=exact(),
        hint="Split at '|': one sign bit, then the exponent (its first bit the sign, the rest its magnitude, most "
        "significant first), then f_1 f_2 ... worth 1/2, 1/4, ...; b = (-1)^s f 2^e. No bias, no hidden bit.",
        rules={
            EDGE: "decode any fraction by the formula (`0|0000|0101` is $5/16$, and an all-zero fraction is 0).",
            BAD: "Raise a `TypeError` if `bits` is not a string, and a `ValueError` unless it has exactly three "
                "fields, each non-empty and made of `0` and `1` only (no spaces), with a sign field of exactly one "
                "bit and an exponent field of at least two bits (its sign and one magnitude bit).",
        },
    ),
    Exercise(
        id="13.round_to_bits",
        reference=floating.round_to_bits,
        cases=round_to_bits_cases,
        compare=exact(),
        hint="Write x = f 2^e with 1/2 <= |f| < 1 (numpy.frexp), round f 2^d to an integer with ties to even "
        "(numpy.rint) and scale back by 2^(e-d) (numpy.ldexp). Rounding is relative to x's own exponent.",
        rules={
            TIES: "to nearest with ties to even",
            EDGE: "Zero gives zero; very small and very large floats (1e-300, 1e20) must work.",
            BAD: "Raise a `TypeError` if `d` is not an integer (`2.5`) or `x` is not numbers (a string), and a "
                "`ValueError` if $d<1$.",
        },
    ),
    Exercise(
        id="13.float_interval",
        reference=floating.float_interval,
        cases=float_interval_cases,
        compare=exact(),
        hint="With b = f 2^e, 1/2 <= |f| < 1, the neighbours are 2^(e-d) away, so b ± 2^(e-d-1); with exact=True "
        "and |f| = 1/2 the neighbour towards 0 is only 2^(e-d-1) away, so that side is 2^(e-d-2).",
        rules={
            EDGE: "return this symmetric interval by default.",
            TIES: "At a power of two ($|f|=\\tfrac12$) the neighbour **towards zero** has the smaller exponent "
                "$e-1$ and is only $2^{e-d-1}$ away.",
            BAD: "Raise a `ValueError` if `b` is not a single number, if `b` has more than $d$ significant bits (it "
                "is not a $d$-bit number: `float_interval(0.3, 4)`), or if `d` is not an integer with $1\\le d\\le "
                "50$.",
        },
    ),
    Exercise(
        id="13.affine_roundoff",
        reference=floating.affine_roundoff,
        cases=affine_roundoff_cases,
        compare=close(1e-12, 1e-300),
        hint="η(|1-t||p0| + |t||p1| + |(1-t)p0 + t p1|), with absolute values per coordinate: the notes' three "
        "cases of (13.7) are this one formula.",
        rules={
            EDGE: "`eta`: a number $\\ge0$ (0 gives no widening).",
            SHAPES: "`t`: any real number, giving the shape of `p0` (a float for numbers), or a 1-D array of k "
                "numbers, giving `(k,)` for numbers and `(k, dim)` for vectors.",
            BAD: "Raise a `ValueError` if `p0` and `p1` have different shapes or more than one dimension, if `t` "
                "has two or more dimensions, or if `eta` is negative.",
        },
    ),
    Exercise(
        id="13.rounded_de_casteljau",
        reference=floating.rounded_de_casteljau,
        cases=rounded_de_casteljau_cases,
        compare=same_box,
        hint="Round the points to d bits and start the radii at |P - fl(P)| (+ radii). Each step: s = fl(1 - t), "
        "c = fl(fl(s a) + fl(t b)), radius |1-t| ea + |t| eb + γ(w|1-t||a| + |t||b| + |c|), γ = η/(1-η), "
        "w = 1 when s is exactly 1 - t, else 2.",
        rules={
            FLOAT32: "$d=-\\log_2\\eta$ must be an integer with $2\\le d\\le25$ (simulated: every result rounded "
                "with your `round_to_bits(·, d)`)",
            FLOAT64: "or $d=53$ (ordinary floats, where rounding changes nothing).",
            EDGE: "`points`: shape `(n+1, dim)`, any $n\\ge0$ and `dim` ≥ 1",
            COARSE: "$d=-\\log_2\\eta$ must be an integer with $2\\le d\\le25$",
            BOXES: "(plus `radii[k]` when `radii` is given: boxes around the points, as in chapter 12)",
            SHAPES: "`t`: a number, giving `(centre (dim,), radius (dim,))`, or a 1-D array of k numbers, giving "
                "`((k, dim), (k, dim))`",
            BAD: "Raise a `ValueError` if `eta` is not $2^{-d}$ with $2\\le d\\le25$ or $d=53$, if a parameter has "
                "more than $d$ significant bits (for instance `0.1` with $\\eta=2^{-24}$), if `t` has two or more "
                "dimensions, if `points` is not of shape `(n+1, dim)`, or if `radii` has another shape or a "
                "negative entry.",
        },
    ),
]

"""Hidden grading suite of chapter 3: evaluating polynomials and converting between bases.

Fixed cases reuse the notes' rational cubic (cagd_course/examples/ch03.toml), given
by its homogeneous (X, Y, W) coefficients in both bases (NOTES_POWER and
NOTES_BERNSTEIN, one coordinate per column) and by single columns of it. Edge
cases probe degree 0 and 1, t at 0 and 1 and outside [0, 1], a scalar t against
an array of them, and coefficient columns; random cases come from the generator
the grader passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import polynomials

NOTES = "notes example"
COURSE = "course example"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
COLUMNS = "several polynomials (columns)"
RANDOM = "random"
BAD = "bad input"

# As lists of tuples and lists: students must accept those as well as arrays.
_RATIONAL = notes_example("03.rational_cubic")
NOTES_POWER = [tuple(row) for row in _RATIONAL.inputs["power"].tolist()]
NOTES_BERNSTEIN = [tuple(row) for row in _RATIONAL.results["bernstein"].tolist()]
NOTES_X_POWER = _RATIONAL.inputs["power"][:, 0].tolist()
NOTES_X_BERNSTEIN = _RATIONAL.results["bernstein"][:, 0].tolist()
NOTES_W_BERNSTEIN = _RATIONAL.results["weights"].tolist()
_STEPS = notes_example("03.horner_steps")
CUBIC = _STEPS.inputs["coeffs"].tolist()  # 2 - 3t + t³, the course's example of Horner's steps


def _coefficients(rng, low_degree=0, high_degree=8):
    """Random coefficients: (n+1,) most of the time, sometimes (n+1, d) columns."""
    n = int(rng.integers(low_degree, high_degree + 1))
    if rng.uniform() < 0.3:
        return rng.uniform(-10, 10, (n + 1, int(rng.integers(1, 4))))
    return rng.uniform(-10, 10, n + 1)


def _ts(rng, low=0.0, high=1.0):
    """One number (about a third of the time) or a sorted 1-D array of up to 7 values."""
    if rng.uniform() < 0.35:
        return float(rng.uniform(low, high))
    return np.sort(rng.uniform(low, high, int(rng.integers(1, 8))))


def _interval(rng):
    """A random parameter interval (t0, t1): t0 in [-2, 2], length in [0.25, 2]."""
    t0 = float(rng.uniform(-2.0, 2.0))
    return (t0, t0 + float(rng.uniform(0.25, 2.0)))


def _bad_coefficient_cases(*extra):
    return [
        Case(BAD, ([], *extra)),
        Case(BAD, (np.zeros((2, 2, 2)), *extra)),
        Case(BAD, ([1.0, float("inf"), 2.0], *extra)),
    ]


# --- 03.horner ------------------------------------------------------------------


def horner_cases(rng):
    cases = [
        Case(NOTES, (NOTES_X_POWER, 0.5), visible=True),
        Case(NOTES, (NOTES_POWER, [0.0, 0.5, 1.0]), visible=True),  # X, Y, W of the rational cubic
        Case(EDGE, (CUBIC, float(_STEPS.inputs["t"])), visible=True),  # ((1·2 + 0)·2 - 3)·2 + 2 = 4
        Case(EDGE, (CUBIC, -1.5), visible=True),
        Case(EDGE, ([7.0], 3.0), visible=True),  # degree 0: a constant
        Case(EDGE, ([1.0, -2.0], [0.0, 0.5, 4.0]), visible=True),
        Case(EDGE, (CUBIC, 0.0), visible=True),  # the constant term
        Case(EDGE, ([0.0, 0.0, 0.0, 5.0], 1.0), visible=True),
        Case(SHAPES, (CUBIC, np.array([0.5]))),
        Case(SHAPES, (CUBIC, np.array(0.5))),
        Case(SHAPES, ([7.0], [0.0, 1.0, 2.0])),
        Case(COLUMNS, ([(1.0, 0.0), (0.0, 1.0)], 0.25)),
        Case(COLUMNS, ([[3.0], [1.0], [2.0]], [0.0, 1.0])),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_coefficients(rng), _ts(rng, -2.0, 2.0))))
    cases += _bad_coefficient_cases(0.5)
    cases.append(Case(BAD, (CUBIC, [[0.1, 0.2]])))
    return cases


# --- 03.horner_with_derivative ----------------------------------------------------


def horner_with_derivative_cases(rng):
    cases = [
        Case(COURSE, (CUBIC, float(_STEPS.inputs["t"])), visible=True),  # (4, 9): p'(2) = q(2) = 2² + 2·2 + 1
        Case(NOTES, (NOTES_X_POWER, 0.5), visible=True),
        Case(NOTES, (NOTES_POWER, [0.0, 0.5, 1.0]), visible=True),  # X, Y, W and their derivatives
        Case(EDGE, ([7.0], 3.0), visible=True),  # degree 0: the constant, slope 0
        Case(EDGE, ([7.0], [0.0, 1.0]), visible=True),
        Case(EDGE, ([1.0, -2.0], [0.0, 0.5, 4.0]), visible=True),  # a line: slope -2 everywhere
        Case(EDGE, (CUBIC, 0.0), visible=True),  # (a_0, a_1)
        Case(EDGE, (CUBIC, -1.5), visible=True),
        Case(EDGE, ([0.0, 0.0, 0.0, 5.0], 1.0), visible=True),  # (5, 15)
        Case(SHAPES, (CUBIC, np.array([0.5]))),
        Case(SHAPES, (CUBIC, np.array(0.5))),
        Case(COLUMNS, ([(1.0, 0.0), (0.0, 1.0)], 0.25)),
        Case(COLUMNS, ([[3.0], [1.0], [2.0]], [0.0, 1.0])),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_coefficients(rng), _ts(rng, -2.0, 2.0))))
    cases += _bad_coefficient_cases(0.5)
    cases.append(Case(BAD, (CUBIC, [[0.1, 0.2]])))
    return cases


# --- 03.bernstein_horner --------------------------------------------------------


def bernstein_horner_cases(rng):
    cases = [
        Case(NOTES, (NOTES_X_BERNSTEIN, 0.5), visible=True),
        Case(NOTES, (NOTES_BERNSTEIN, [0.0, 0.25, 0.5, 1.0]), visible=True),
        Case(NOTES, (NOTES_W_BERNSTEIN, [0.1, 0.9]), visible=True),
        Case(EDGE, ([4.0], 0.3), visible=True),  # degree 0: a constant
        Case(EDGE, ([1.0, 5.0], 0.25), visible=True),  # degree 1: a straight line
        Case(EDGE, ([2.0, -1.0, 3.0], 0.0), visible=True),
        Case(EDGE, ([2.0, -1.0, 3.0], 1.0), visible=True),
        Case(EDGE, ([2.0, -1.0, 3.0], 1.5), visible=True),  # outside [0, 1] the polynomial still has a value
        Case(EDGE, ([1.0, 1.0, 1.0, 1.0, 1.0], [0.2, 0.7]), visible=True),  # partition of unity
        Case(SHAPES, (NOTES_X_BERNSTEIN, np.array([0.5]))),
        Case(SHAPES, (NOTES_X_BERNSTEIN, np.array(0.5))),
        Case(SHAPES, ([4.0], [0.0, 0.5, 1.0])),
        Case(COLUMNS, ([(0.0, 0.0), (1.0, 2.0), (3.0, 0.0)], 0.5)),
        Case(COLUMNS, ([[1.0], [5.0], [2.0]], [0.0, 1.0])),
    ]
    for _ in range(14):
        low, high = (-0.5, 1.5) if rng.uniform() < 0.2 else (0.0, 1.0)
        cases.append(Case(RANDOM, (_coefficients(rng, 0, 12), _ts(rng, low, high))))
    cases += _bad_coefficient_cases(0.5)
    cases.append(Case(BAD, (NOTES_X_BERNSTEIN, [[0.1, 0.2]])))
    cases.append(Case(BAD, (np.ones(1031), 0.5)))  # degree 1030: the binomial coefficients overflow
    cases.append(Case(BAD, (2.0 * np.ones(1030), 0.5)))  # degree 1029: 2 C(1029, 514) overflows
    cases.append(Case(BAD, ([1.0, 1e308, 1.0], 0.5)))  # degree 2: C(2, 1) 1e308 overflows
    return cases


# --- 03.power_to_bernstein / 03.bernstein_to_power ------------------------------


def power_to_bernstein_cases(rng):
    cases = [
        Case(NOTES, (NOTES_POWER,), visible=True),  # the notes' table, run backwards
        Case(NOTES, (NOTES_X_POWER,), visible=True),
        Case(EDGE, ([5.0],), visible=True),  # degree 0
        Case(EDGE, ([1.0, 2.0],), visible=True),  # 1 + 2t: b = (1, 3)
        Case(EDGE, ([0.0, 0.0, 1.0],), visible=True),  # t²: b = (0, 0, 1)
        Case(EDGE, ([0.0, 1.0, 0.0, 0.0],), visible=True),  # t written as a cubic: b = (0, 1/3, 2/3, 1)
        Case(EDGE, ([1.0, -3.0, 3.0, -1.0],), visible=True),  # (1 - t)³: b = (1, 0, 0, 0)
        Case(COLUMNS, ([(1.0, 0.0), (0.0, 1.0)],)),
        Case(COLUMNS, ([[2.0], [-1.0], [4.0]],)),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_coefficients(rng),)))
    return cases + _bad_coefficient_cases()


def bernstein_to_power_cases(rng):
    cases = [
        Case(NOTES, (NOTES_BERNSTEIN,), visible=True),  # scale the table's left column by C(3, i)
        Case(NOTES, (NOTES_X_BERNSTEIN,), visible=True),
        Case(EDGE, ([5.0],), visible=True),  # degree 0
        Case(EDGE, ([1.0, 3.0],), visible=True),  # the line from 1 to 3: 1 + 2t
        Case(EDGE, ([0.0, 0.0, 1.0],), visible=True),  # B_2^2 = t²
        Case(EDGE, ([0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0],), visible=True),  # equally spaced: t itself
        Case(EDGE, ([2.0, 2.0, 2.0, 2.0, 2.0],), visible=True),  # a constant in degree 4
        Case(COLUMNS, ([(1.0, 0.0), (0.0, 1.0)],)),
        Case(COLUMNS, ([[2.0], [-1.0], [4.0]],)),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_coefficients(rng),)))
    return cases + _bad_coefficient_cases()


# --- 03.power_to_bernstein_interval ---------------------------------------------


def power_to_bernstein_interval_cases(rng):
    cases = [
        Case(NOTES, (NOTES_POWER, (0.0, 1.0)), visible=True),  # on [0, 1]: the notes' table
        Case(COURSE, ([0.0, 0.0, 1.0], (1.0, 3.0)), visible=True),  # t² over [1, 3]: (1, 3, 9)
        Case(EDGE, ([0.0, 1.0], (2.0, 5.0)), visible=True),  # the line t: (t0, t1)
        Case(EDGE, ([0.0, 0.0, 1.0], (-2.0, 0.5)), visible=True),  # t²: (4, -1, 0.25)
        Case(EDGE, ([0.0, 0.0, 1.0], (0.0, 4.0)), visible=True),  # t0 = 0: only a scale
        Case(EDGE, ([5.0], (-1.0, 4.0)), visible=True),  # a constant keeps its coefficient
        Case(EDGE, ([1.0, 2.0], (-3.0, -1.0)), visible=True),  # 1 + 2t from -5 to -1
        Case(COLUMNS, (NOTES_POWER, (0.0, 0.5))),  # the first half of the notes' rational cubic
        Case(COLUMNS, ([(1.0, 0.0), (0.0, 1.0)], (1.0, 2.0))),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_coefficients(rng, 0, 6), _interval(rng))))
    cases += _bad_coefficient_cases((0.0, 1.0))
    cases += [
        Case(BAD, ([1.0, 2.0], (1.0, 1.0))),
        Case(BAD, ([1.0, 2.0], (3.0, 1.0))),
        Case(BAD, ([1.0, 2.0], (0.0, 1.0, 2.0))),
        Case(BAD, ([1.0, 2.0], (0.0, float("nan")))),
    ]
    return cases


# --- 03.power_to_rational_bezier --------------------------------------------------


def _rational_power_form(rng):
    """The homogeneous power coefficients (n+1, d+1) of a random rational curve with weights |w| >= 0.5."""
    n, d = int(rng.integers(1, 6)), int(rng.integers(2, 4))
    points = rng.uniform(-5, 5, (n + 1, d))
    weights = rng.uniform(0.5, 3.0, n + 1)
    if rng.uniform() < 0.3:
        weights *= rng.choice([-1.0, 1.0], n + 1)  # negative weights are allowed
    homogeneous = np.column_stack([points * weights[:, None], weights])
    return polynomials.bernstein_to_power(homogeneous)


def power_to_rational_bezier_cases(rng):
    polynomial = [(0.0, 0.0, 1.0), (3.0, 6.0, 0.0), (3.0, -10.5, 0.0), (-2.0, 5.0, 0.0)]  # W = 1
    cases = [
        Case(NOTES, (NOTES_POWER,), visible=True),  # points (1,2), (3,4), (4,3), (3,1), weights 1, 3, 1, 2
        Case(NOTES, (_RATIONAL.inputs["power"],), visible=True),  # the same, as an array
        Case(EDGE, (polynomial,), visible=True),  # a polynomial cubic: weights 1, 1, 1, 1
        Case(EDGE, ([(2.0, 4.0, 2.0)],), visible=True),  # degree 0: the point (1, 2), weight 2
        Case(EDGE, ([(0.0, 0.0, 1.0), (1.0, 3.0, 1.0)],), visible=True),  # a line, weights 1 and 2
        Case(EDGE, ([(0.0, 1.0), (1.0, -3.0), (0.0, 3.0)],), visible=True),  # W = 1 - 3t + 3t²: weights 1, -1/2, 1
        Case(COLUMNS, ([(1.0, 2.0, 1.0, 1.0), (3.0, 3.0, 0.0, 1.0)],)),  # a space curve (X, Y, Z, W)
        Case(COLUMNS, ([(5.0, 1.0), (1.0, 1.0)],)),  # d = 1: X and W
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_rational_power_form(rng),)))
    cases += [
        Case(BAD, ([],)),
        Case(BAD, ([1.0, 2.0, 3.0],)),  # one dimension: no W column
        Case(BAD, ([[1.0], [2.0]],)),  # one column only
        Case(BAD, (np.zeros((2, 2, 2)),)),
        Case(BAD, ([(1.0, float("nan")), (2.0, 1.0)],)),
        Case(BAD, ([(0.0, 1.0), (1.0, -2.0), (0.0, 1.0)],)),  # W = (1 - t)²: weights 1, 0, 0
        Case(BAD, ([(1.0, 0.0), (2.0, 0.0)],)),  # W = 0
    ]
    return cases


SHAPE_RULE = (
    "A number t gives a float (or shape (d,) for (n+1, d) coefficients); a 1-D array of k values gives (k,) or (k, d)."
)

EXERCISES = [
    Exercise(
        id="03.horner",
        reference=polynomials.horner,
        cases=horner_cases,
        compare=close(1e-9, 1e-9),
        hint="Coefficients are ascending (a0 first), so start from the last one: h = a_n, then h = h·t + a_i for "
        "i = n-1 down to 0. " + SHAPE_RULE,
        rules={
            EDGE: "Any real `t` is allowed, and a degree-0 polynomial is the constant $a_0$.",
            SHAPES: "`t` is either a number (a 0-d array counts as one), and then a float (or shape `(d,)` for "
                "columns) comes back, or a 1-D array (or list) of k numbers, and then shape `(k,)` (or `(k, d)`) "
                "comes back, even when k = 1.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)` (one polynomial per column)",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs`, NaN or infinite coefficients, or "
                "a two-dimensional `t`.",
        },
    ),
    Exercise(
        id="03.horner_with_derivative",
        reference=polynomials.horner_with_derivative,
        cases=horner_with_derivative_cases,
        compare=close(1e-9, 1e-9),
        hint="Run two recurrences side by side, from h = a_n and h' = 0: first h' = h'·t + h (with the h of this "
        "step), then h = h·t + a_i, for i = n-1 down to 0; return the tuple (h, h'). A number t gives two floats "
        "(or two (d,) arrays for (n+1, d) coefficients); a 1-D array of k values gives two (k,) or (k, d) arrays.",
        rules={
            EDGE: "Any real `t` is allowed. A degree-0 polynomial is the constant $a_0$, with derivative 0.",
            SHAPES: "`t` is either a number (a 0-d array counts as one), and then two floats (or two arrays of "
                "shape `(d,)` for columns) come back, or a 1-D array (or list) of k numbers, and then two arrays "
                "of shape `(k,)` (or `(k, d)`) come back, even when k = 1.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)` (one polynomial per column)",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs`, NaN or infinite coefficients, or "
                "a two-dimensional `t`.",
        },
    ),
    Exercise(
        id="03.bernstein_horner",
        reference=polynomials.bernstein_horner,
        cases=bernstein_horner_cases,
        compare=close(1e-9, 1e-9),
        hint="With β_i = C(n, i) b_i (C(n, i) = C(n, i-1)(n-i+1)/i): start from v = β_0, then for i = 1..n "
        "update tⁱ = tⁱ⁻¹·t and set v = v·(1 - t) + β_i tⁱ. A degree-0 polynomial is its constant. " + SHAPE_RULE,
        rules={
            EDGE: "Values outside $[0,1]$ are allowed: the formula extends the polynomial.",
            SHAPES: "`t`: a number (a 0-d array counts as one) gives a float (or shape `(d,)` for columns), a 1-D "
                "array (or list) of k numbers gives shape `(k,)` (or `(k, d)`), even when k = 1.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)`, $n\\ge0$. A degree-0 polynomial is the constant $b_0$.",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs`, NaN or infinite coefficients, a "
                "two-dimensional `t`, a degree $n$ above 1029 (more than 1030 coefficients), and any coefficient "
                "whose $\\beta_i = \\binom ni b_i$ overflows a float, that is $|b_i|\\binom ni$ larger than the "
                "largest double (about $1.8\\cdot 10^{308}$). Beyond degree 1029 the binomial coefficients overflow "
                "on their own; at degree 1029 a coefficient of 2 is already too large (section 3.2 of the "
                "chapter). Refuse such input instead of returning infinities or NaN.",
        },
    ),
    Exercise(
        id="03.power_to_bernstein",
        reference=polynomials.power_to_bernstein,
        cases=power_to_bernstein_cases,
        compare=close(1e-9, 1e-9),
        hint="Divide a_j by C(n, j) and put the results in the left column of the difference table; then fill "
        "the table from the left (each entry = its left neighbour + the entry below that neighbour) and read "
        "the top row. Check: 1 + 2t gives (1, 3).",
        rules={
            EDGE: "Check by hand: $1+2t$ is the line from 1 to 3, so it gives $(1, 3)$; $t$ as a cubic gives "
                "$(0,\\tfrac13,\\tfrac23,1)$.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)` (convert every column); returns the same shape.",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs` and for NaN or infinite "
                "coefficients.",
        },
    ),
    Exercise(
        id="03.bernstein_to_power",
        reference=polynomials.bernstein_to_power,
        cases=bernstein_to_power_cases,
        compare=close(1e-9, 1e-9),
        hint="Put the b_i in the top row, form the forward differences row by row, take the first entry of each "
        "row (Δʲ b_0, the left column) and multiply it by C(n, j). Check: (1, 3) gives 1 + 2t.",
        rules={
            EDGE: "Degree 0 is allowed (a constant).",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)`; returns the same shape.",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs` and for NaN or infinite "
                "coefficients.",
        },
    ),
    Exercise(
        id="03.power_to_bernstein_interval",
        reference=polynomials.power_to_bernstein_interval,
        cases=power_to_bernstein_interval_cases,
        compare=close(1e-9, 1e-9),
        hint="First rewrite p in the local parameter: g(s) = p(t0 + (t1 - t0) s), by Horner's rule with polynomials "
        "(start with g = a_n, then g = g·(t0 + (t1 - t0) s) + a_i); then convert g on [0, 1] as in exercise 3.4. "
        "Check: t over [2, 5] gives (2, 5).",
        rules={
            EDGE: "Check by hand: over $[t_0, t_1]$ a constant keeps its coefficient, the line $t$ has the "
                "coefficients $(t_0, t_1)$ and $t^2$ has $(t_0^2, t_0t_1, t_1^2)$.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)` (convert every column); returns the same shape.",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs`, NaN or infinite numbers, and an "
                "`interval` that is not two numbers $t_0 < t_1$.",
        },
    ),
    Exercise(
        id="03.power_to_rational_bezier",
        reference=polynomials.power_to_rational_bezier,
        cases=power_to_rational_bezier_cases,
        compare=close(1e-9, 1e-9),
        hint="Convert every column, W included, to the Bernstein basis first (exercise 3.4): the rows are the "
        "homogeneous control points w_i (P_i, 1). Only then divide each row by its last entry, the weight w_i.",
        rules={
            EDGE: "When $W = 1$ the curve is polynomial: all weights are 1 and the points are the Bernstein "
                "coefficients of the other columns. Negative weights are allowed.",
            COLUMNS: "Returns the tuple `(points, weights)` with shapes `(n+1, d)` and `(n+1,)`.",
            BAD: "Raise a `ValueError` when `coeffs` is empty, not two-dimensional, has fewer than two columns or "
                "holds NaN or infinite numbers, and when a weight is zero up to rounding "
                r"($|w_i| \le 10^{-12} \max_j |w_j|$): that control point would lie at infinity.",
        },
    ),
]

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
        id="03.bernstein_horner",
        reference=polynomials.bernstein_horner,
        cases=bernstein_horner_cases,
        compare=close(1e-9, 1e-9),
        hint="With s = 1 - t: start from b_0 C(n,0) s, then for i = 1..n-1 update tⁱ and C(n, i) = C(n, i-1)(n-i+1)/i, "
        "add C(n, i) tⁱ b_i and multiply by s; finally add tⁿ b_n. A degree-0 polynomial is its constant. "
        + SHAPE_RULE,
        rules={
            EDGE: "Values outside $[0,1]$ are allowed: the formula extends the polynomial.",
            SHAPES: "`t`: a number (a 0-d array counts as one) gives a float (or shape `(d,)` for columns), a 1-D "
                "array (or list) of k numbers gives shape `(k,)` (or `(k, d)`), even when k = 1.",
            COLUMNS: "shape `(n+1,)` or `(n+1, d)`, $n\\ge0$. A degree-0 polynomial is the constant $b_0$.",
            BAD: "Raise a `ValueError` for an empty or three-dimensional `coeffs`, NaN or infinite coefficients, a "
                "two-dimensional `t`, and a degree $n$ above 1029 (more than 1030 coefficients): beyond it the "
                "binomial coefficients $\\binom ni$ overflow a float (the chapter's accuracy section), so refuse "
                "such input instead of returning infinities or NaN.",
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
]

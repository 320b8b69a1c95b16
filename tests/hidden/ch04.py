"""Hidden grading suite of chapter 4: forward differencing.

Fixed cases reuse the notes' worked example (the cubic with values 1, 2, 4, 8, 15
at t = 1..5, read from cagd_course/examples/ch04.toml with the course's own
examples around it: that cubic in power form, a degree-four table) and the
notes' loops of degree 1, 2 and 3 on numbers of our own; edge cases probe a
single value, degree 0, zero and negative steps, count 0 and 1, and several
polynomials at once as the columns of an (n+1, d) array; random cases come from
the generator the grader passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import forward_differencing

NOTES = "notes example"
EDGE = "edge cases"
ACCURACY = "accuracy"
RANDOM = "random"
BAD = "bad input"

CURVE = [(0.0, 1.0), (1.0, 0.0), (2.0, -1.0), (3.0, 0.5)]  # x(t) and y(t) of a cubic curve, power form
SEXTIC = [1.0, -2.0, 3.0, -4.0, 5.0, -1.0, 2.0]  # stepped 300 times by 0.005 it shows where the start comes from


def _shape(rng):
    """(n+1,) or (n+1, d) for a random degree 0..6 and, half the time, d = 1..3 columns."""
    n = int(rng.integers(0, 7))
    return (n + 1,) if rng.uniform() < 0.5 else (n + 1, int(rng.integers(1, 4)))


def rows_close(rtol: float, atol: float):
    """Compare a difference table row by row: a list (or tuple) of rows, each with the expected shape."""
    numbers = close(rtol, atol)

    def compare(expected, received):
        if not isinstance(expected, list) or isinstance(received, Raises):  # an error expected or raised
            return numbers(expected if isinstance(expected, Raises) else tuple(expected), received)
        if not isinstance(received, (list, tuple)):
            return f"expected a list of {len(expected)} rows, got {type(received).__name__}"
        if len(received) != len(expected):
            return f"expected a list of {len(expected)} rows (Δ⁰ ... Δⁿ), got {len(received)}"
        for j, (row, got) in enumerate(zip(expected, received)):
            problem = numbers(row, got)
            if problem:
                return f"row {j}: {problem}"
        return None

    return compare


# --- 04.forward_difference_table -------------------------------------------------------


def table_cases(rng):
    cases = [
        # The notes' cubic at t = 1..5 with the missing 8 filled in; t⁴ at 0..4, our stand-in for the
        # notes' degree-four table; the cubic continued to t = 7.
        Case(NOTES, (notes_example("04.missing_value").results["values"].copy(),), visible=True),
        Case(NOTES, notes_example("04.quartic_table").args("values"), visible=True),
        Case(NOTES, (notes_example("04.cubic_power_form").results["values"].copy(),), visible=True),
        Case(EDGE, ([3.5],), visible=True),  # one value: a table of one row
        Case(EDGE, ([2.0, -5.0],), visible=True),
        Case(EDGE, ([4.0, 4.0, 4.0],), visible=True),
        Case(EDGE, ([(1.0, 0.0), (2.0, 1.0), (4.0, 4.0), (8.0, 9.0)],), visible=True),  # two polynomials
        Case(EDGE, ([(1.0, 2.0, 3.0), (0.5, 0.0, -1.0), (0.25, -2.0, 1.0)],), visible=True),
        Case(EDGE, ([(7.0, -7.0)],), visible=True),
        Case(EDGE, (np.array([3, 1, 4, 1, 5]),), visible=True),  # integers in, floats out
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (rng.uniform(-10, 10, _shape(rng)),)))
    cases += [
        Case(BAD, ([],)),
        Case(BAD, (np.zeros((2, 2, 2)),)),
        Case(BAD, ([1.0, float("nan"), 4.0],)),
        Case(BAD, ([(1.0, 2.0), (float("inf"), 0.0)],)),
    ]
    return cases


# --- 04.forward_difference_eval --------------------------------------------------------


def eval_cases(rng):
    cases = [
        # The notes' cubic in power form from t0 = 1: 1, 2, 4, 8, 15, 26, 42; then the notes' loops of
        # degree 1, 2 and 3 on coefficients of our own.
        Case(NOTES, notes_example("04.cubic_power_form").args("coeffs", "t0", "delta", "count"), visible=True),
        Case(NOTES, ([2.0, 3.0], 0.0, 0.25, 5), visible=True),  # degree 1: one addition per step
        Case(NOTES, ([1.0, -2.0, 0.5], 0.0, 0.1, 11), visible=True),  # degree 2
        Case(NOTES, ([0.5, 1.0, -3.0, 2.0], 0.0, 1 / 16, 17), visible=True),  # degree 3
        Case(EDGE, ([7.0], 0.3, 0.1, 4), visible=True),  # degree 0: a constant
        Case(EDGE, ([1.0, 2.0, 3.0], 2.0, 0.5, 0), visible=True),  # no values at all
        Case(EDGE, ([1.0, 2.0, 3.0], -1.0, 0.5, 1), visible=True),
        Case(EDGE, ([1.0, 2.0, 3.0], 2.0, 0.0, 3), visible=True),  # δ = 0 repeats f(t0)
        Case(EDGE, ([1.0, 2.0, 3.0, -1.0], 0.5, -0.25, 9), visible=True),  # stepping backwards
        Case(EDGE, (CURVE, 0.25, 0.125, 6), visible=True),  # a planar cubic curve
        Case(EDGE, (CURVE, 0.0, 0.1, 0), visible=True),
        Case(EDGE, ([[1.0], [0.0], [2.0]], -0.5, 0.25, 5), visible=True),  # one column stays a column
        Case(EDGE, ([1.0, -1.0, 0.5, 0.25, -0.125, 0.1, 0.05], -1.0, 0.05, 60), visible=True),
        # Differences of values lose about half their digits here and the loop amplifies the loss by C(k, 6):
        # started from the table of f(t0 + i δ) the last values miss 1e-6 by a factor of about 300.
        Case(ACCURACY, (SEXTIC, -0.5, 0.005, 301), visible=True),
        Case(ACCURACY, (np.column_stack([SEXTIC, SEXTIC[::-1]]), -0.5, 0.005, 301)),
    ]
    for _ in range(16):
        coeffs = rng.uniform(-5, 5, _shape(rng))
        step = float(rng.uniform(0.02, 0.3)) * float(rng.choice([-1, 1]))
        cases.append(Case(RANDOM, (coeffs, float(rng.uniform(-1, 1)), step, int(rng.integers(1, 31)))))
    cases += [
        Case(BAD, ([1.0, 2.0], 0.0, 0.1, -1)),
        Case(BAD, ([1.0, 2.0], 0.0, 0.1, 2.5)),
        Case(BAD, ([], 0.0, 0.1, 3)),
        Case(BAD, (np.zeros((2, 2, 2)), 0.0, 0.1, 3)),
        Case(BAD, ([1.0, float("inf")], 0.0, 0.1, 3)),
        Case(BAD, ([1.0, 2.0], float("nan"), 0.1, 3)),
        Case(BAD, ([1.0, 2.0], 0.0, float("inf"), 3)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="04.forward_difference_table",
        reference=forward_differencing.forward_difference_table,
        cases=table_cases,
        compare=rows_close(1e-9, 1e-9),
        hint="Return a list of n+1 rows: row 0 is the values, row j holds next-minus-previous of row j-1, and the "
        "last row is a single number. For an (n+1, d) array take the differences down the rows (axis 0), "
        "not across the coordinates.",
        rules={
            EDGE: "`values`: shape `(n+1,)` or `(n+1, d)` with $n\\ge0$. For `(n+1, d)` every column is differenced "
                "on its own: the differences go down the rows, never across the coordinates.",
            BAD: "Raise a `ValueError` for an empty array, one with three or more dimensions, or NaN or infinite "
                "values.",
        },
    ),
    Exercise(
        id="04.forward_difference_eval",
        reference=forward_differencing.forward_difference_eval,
        cases=eval_cases,
        compare=close(1e-6, 1e-6),
        hint="Start from f(t0), Δ¹(t0), ..., Δⁿ(t0) in closed form: re-expand f about t0, q_k = b_k δᵏ, then "
        "Δʲ = j! Σ_k S(k, j) q_k (a table of differences of values loses digits). Each step records f, then "
        "updates f += Δ¹, Δ¹ += Δ², ... using the old value below each one. "
        "Return exactly `count` values; an (n+1,) input gives (count,), an (n+1, d) input gives (count, d).",
        rules={
            EDGE: "`t0`, `delta`: numbers; `delta` may be negative (stepping backwards) or zero.",
            ACCURACY: "The values must be right to within $10^{-6}$ (relative or absolute). The tests include a "
                "polynomial of degree 6 stepped 300 times with $\\delta=0.005$: started from differences of "
                "values, the loop misses this tolerance by a factor of about 300; started from the closed form, it "
                "meets it easily.",
            BAD: "Raise a `TypeError` if `count` is not an integer and a `ValueError` if it is negative, if "
                "`coeffs` is empty or has three or more dimensions, or if `coeffs`, `t0` or `delta` hold NaN or "
                "infinity.",
        },
    ),
]

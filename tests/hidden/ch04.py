"""Hidden grading suite of chapter 4: forward differencing.

Fixed cases reuse the notes' worked example (the cubic with values 1, 2, 4, 8, 15
at t = 1..5, read from cagd_course/examples/ch04.toml with the course's own
examples around it: that cubic in power form, a degree-four table, the cubic in
pixel units of §4.1) and the notes' loops of degree 1, 2 and 3 on numbers of our
own; edge cases probe a single value, degree 0, zero and negative steps, count 0
and 1, legs that run left or down, and several polynomials at once as the
columns of an (n+1, d) array; random cases come from the generator the grader
passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import forward_differencing

NOTES = "notes example"
COURSE = "course example"
EDGE = "edge cases"
ACCURACY = "accuracy"
RANDOM = "random"
BAD = "bad input"

CURVE = [(0.0, 1.0), (1.0, 0.0), (2.0, -1.0), (3.0, 0.5)]  # x(t) and y(t) of a cubic curve, power form
(PIXEL_CUBIC,) = notes_example("04.raster_cubic").args("points")  # the course's cubic in pixel units, §4.1
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


# --- 04.bezier_by_differences -------------------------------------------------------------


def bezier_cases(rng):
    cases = [
        # The course's cubic in pixel units at the chapter's 69 steps and at 8; a cubic of chapter 2.
        Case(COURSE, (PIXEL_CUBIC.copy(), 69), visible=True),
        Case(COURSE, (PIXEL_CUBIC.copy(), 8), visible=True),
        Case(COURSE, ([(0.0, 0.0), (1.0, 3.0), (4.0, 3.5), (5.0, 0.5)], 10), visible=True),
        Case(EDGE, ([(3.0, -1.0)], 4), visible=True),  # degree 0: the point, steps + 1 times
        Case(EDGE, ([(0.0, 0.0), (6.0, 3.0)], 3), visible=True),  # a line: equally spaced points
        Case(EDGE, (PIXEL_CUBIC.copy(), 1), visible=True),  # one step: the two end points
        Case(EDGE, ([(0.0, 0.0, 0.0), (1.0, 2.0, 0.0), (2.0, 2.0, 3.0), (4.0, 0.0, 1.0), (5.0, 1.0, 1.0)], 7),
             visible=True),  # a quartic in space
        Case(EDGE, ([[1.0], [4.0], [-2.0]], 5), visible=True),  # one coordinate stays a column
        Case(EDGE, (np.array([[0, 0], [2, 5], [7, 1]]), 6), visible=True),  # integers in, floats out
        # Degree 6 in 400 steps: started from differences of values, the march misses 1e-8 by far.
        Case(ACCURACY, ([(0.0, 0.0), (9.0, -8.0), (-7.0, 10.0), (10.0, 9.0), (-9.0, -10.0), (8.0, 7.0),
                         (1.0, 1.0)], 400), visible=True),
    ]
    for _ in range(14):
        n = int(rng.integers(0, 7))
        points = rng.uniform(-10, 10, (n + 1, int(rng.integers(1, 4))))
        cases.append(Case(RANDOM, (points, int(rng.integers(1, 61)))))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0], 4)),
        Case(BAD, (np.zeros((2, 2, 2)), 4)),
        Case(BAD, (np.zeros((0, 2)), 4)),
        Case(BAD, ([(0.0, 0.0), (float("nan"), 1.0)], 4)),
        Case(BAD, (PIXEL_CUBIC.copy(), 0)),
        Case(BAD, (PIXEL_CUBIC.copy(), -3)),
        Case(BAD, (PIXEL_CUBIC.copy(), 2.5)),
    ]
    return cases


# --- 04.missing_value ---------------------------------------------------------------------


def missing_cases(rng):
    notes_values, index = notes_example("04.missing_value").args("values", "index")
    with_nan = notes_values.copy()
    with_nan[index] = float("nan")
    cases = [
        Case(NOTES, (notes_values, index), visible=True),  # 1, 2, 4, x, 15: x = 8
        Case(NOTES, (with_nan, index), visible=True),  # the same with NaN standing for x
        Case(EDGE, ([0.0, 1.0, 16.0, 81.0, 256.0, -1.0], 5), visible=True),  # the last value: t⁴ at 5 is 625
        Case(EDGE, ([99.0, 1.0, 16.0, 81.0, 256.0, 625.0], 0), visible=True),  # the first value: 0
        Case(EDGE, ([5.0, 0.0], 1), visible=True),  # two values: a constant
        Case(EDGE, ([(1.0, 0.0), (2.0, 1.0), (0.0, 0.0), (10.0, 9.0)], 2), visible=True),  # t² + 1 and t²
        Case(EDGE, (np.array([3, 5, 7, 0]), 3), visible=True),  # integers in, a float out: 9
        Case(EDGE, ([1.0, float("inf"), 3.0], 1), visible=True),  # the placeholder may be anything
    ]
    for _ in range(14):
        n = int(rng.integers(1, 7))
        columns = () if rng.uniform() < 0.5 else (int(rng.integers(1, 4)),)
        coeffs = rng.uniform(-5, 5, (n,) + columns)  # degree n - 1, so n + 1 values determine one gap
        ts = float(rng.uniform(-1, 1)) + float(rng.uniform(0.1, 1.0)) * np.arange(n + 1)
        values = np.polynomial.polynomial.polyval(ts, coeffs, tensor=True).T
        hole = int(rng.integers(0, n + 1))
        values[hole] = float("nan") if rng.uniform() < 0.3 else rng.uniform(-100, 100)
        cases.append(Case(RANDOM, (values, hole)))
    cases += [
        Case(BAD, ([4.0], 0)),
        Case(BAD, ([1.0, 2.0, 3.0], 3)),
        Case(BAD, ([1.0, 2.0, 3.0], -1)),
        Case(BAD, ([1.0, 2.0, 3.0], 1.0)),
        Case(BAD, ([1.0, float("nan"), 3.0, 0.0], 3)),
        Case(BAD, (np.zeros((3, 2, 2)), 0)),
    ]
    return cases


# --- 04.raster_delta ----------------------------------------------------------------------


def raster_cases(rng):
    cases = [
        Case(COURSE, (PIXEL_CUBIC.copy(),), visible=True),  # n d = 3 · 23: δ = 1/69
        Case(EDGE, ([(40.0, 30.0), (35.0, 31.0), (34.0, 27.0)],), visible=True),  # legs run left and down: 1/10
        Case(EDGE, ([(0.0, 0.0), (3.0, -1.0)],), visible=True),  # a line: 1/3
        Case(EDGE, ([(0.5, 0.5), (7.25, 2.0), (9.0, 9.5), (10.0, 3.0)],), visible=True),  # n d = 22.5: 1/22.5
        Case(EDGE, ([(0.0, 0.0, 0.0), (2.0, 5.0, -8.0), (4.0, 4.0, 0.0)],), visible=True),  # voxels: 1/16
        Case(EDGE, ([(3.0, 3.0)],), visible=True),  # one point: 1
        Case(EDGE, ([(4.0, 4.0), (4.0, 4.0), (4.2, 4.1)],), visible=True),  # n d = 0.4 < 1: 1
        Case(EDGE, ([(4.0, 4.0), (4.0, 4.0)],), visible=True),  # n d = 0: 1
        Case(EDGE, (np.array([[0, 0], [5, 12], [9, 0]]),), visible=True),  # integers: 1/24
    ]
    for _ in range(12):
        n = int(rng.integers(1, 7))
        cases.append(Case(RANDOM, (rng.uniform(0, 200, (n + 1, int(rng.integers(2, 4)))),)))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0],)),
        Case(BAD, (np.zeros((0, 2)),)),
        Case(BAD, (np.zeros((2, 2, 2)),)),
        Case(BAD, ([(0.0, 0.0), (float("inf"), 1.0)],)),
    ]
    return cases


# --- 04.float32_drift ---------------------------------------------------------------------

# x(t) and y(t) of the course's cubic in pixel units (the control points (2, 3), (10, 26), (30, 28), (37, 5)),
# and of the same cubic 25 times larger, the chapter's drift experiment.
PIXEL_POWER = [(2.0, 3.0), (24.0, 69.0), (36.0, -63.0), (-25.0, -4.0)]
SCREEN_POWER = [(50.0, 75.0), (600.0, 1725.0), (900.0, -1575.0), (-625.0, -100.0)]


def drift_cases(rng):
    cases = [
        Case(COURSE, ([2.0, 24.0, 36.0, -25.0], 1e-3, 1001), visible=True),
        Case(COURSE, (PIXEL_POWER, 1e-3, 1001), visible=True),
        Case(COURSE, (SCREEN_POWER, 1e-4, 10001), visible=True),
        Case(EDGE, ([0.1], 0.01, 5), visible=True),  # a constant: only the rounding of 0.1 to float32
        Case(EDGE, ([0.0, 1.0], 0.1, 11), visible=True),  # a line, and 0.1 is no float32 either
        Case(EDGE, ([1.0, -2.0, 0.5], 0.01, 0), visible=True),  # no values
        Case(EDGE, ([1.0, -2.0, 0.5], 0.01, 1), visible=True),
        Case(EDGE, ([[1.0], [3.0], [-2.0]], 0.002, 400), visible=True),  # one column stays a column
        Case(EDGE, ([1.0, 3.0, -2.0, 1.5], -0.003, 500), visible=True),  # stepping backwards
        Case(EDGE, ([1.0, 3.0, -2.0, 1.5], 0.0, 4), visible=True),  # δ = 0
    ]
    for _ in range(12):
        n = int(rng.integers(1, 5))
        columns = () if rng.uniform() < 0.5 else (int(rng.integers(1, 3)),)
        coeffs = rng.uniform(-100, 100, (n + 1,) + columns)
        count = int(rng.integers(100, 3001))
        cases.append(Case(RANDOM, (coeffs, 1.0 / count, count + 1)))
    cases += [
        Case(BAD, ([1.0, 2.0], 0.1, -1)),
        Case(BAD, ([1.0, 2.0], 0.1, 2.5)),
        Case(BAD, ([], 0.1, 3)),
        Case(BAD, (np.zeros((2, 2, 2)), 0.1, 3)),
        Case(BAD, ([1.0, float("nan")], 0.1, 3)),
        Case(BAD, ([1.0, 2.0], float("inf"), 3)),
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
        hint="Start from f(t0), Δ¹(t0), ..., Δⁿ(t0) in closed form: re-expand f about t0, q_k = c_k δᵏ, then "
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
    Exercise(
        id="04.bezier_by_differences",
        reference=forward_differencing.bezier_by_differences,
        cases=bezier_cases,
        compare=close(1e-8, 1e-8),
        hint="Power coefficients first: a_k = C(n, k) Δᵏ P_0, with Δᵏ P_0 the first entry of row k of the "
        "difference table of the control points (down the rows, axis 0). Then march them from t0 = 0 with "
        "δ = 1/steps for steps + 1 values, started from the closed form (exercise 4.2).",
        rules={
            EDGE: "`points`: shape `(n+1, d)`, any degree $n\\ge0$ and any number of coordinates (a degree-0 "
                "curve is its one point, repeated). Return shape `(steps+1, d)`: row $i$ is "
                "$\\mathbf P(i/\\text{steps})$, from $\\mathbf P_0$ to $\\mathbf P_n$.",
            ACCURACY: "The points must be right to within $10^{-8}$ (relative or absolute). The tests include a "
                "curve of degree 6 in 400 steps: started from differences of values, the march misses this "
                "tolerance by far; started from the closed form, it meets it easily.",
            BAD: "Raise a `ValueError` if `points` is not two-dimensional, has no rows or holds NaN or "
                "infinity, or if `steps` is less than 1, and a `TypeError` if `steps` is not an integer.",
        },
    ),
    Exercise(
        id="04.missing_value",
        reference=forward_differencing.missing_value,
        cases=missing_cases,
        compare=close(1e-8, 1e-8),
        hint="Δⁿ f_0 = Σ_i (-1)ⁿ⁻ⁱ C(n, i) f_i vanishes for a polynomial of degree n - 1: move the known terms to "
        "one side and divide by the coefficient of the unknown one. Indices count from 0.",
        rules={
            EDGE: "`values`: shape `(n+1,)` or `(n+1, d)` with $n\\ge1$: the values $f_0,\\dots,f_n$ at equally "
                "spaced parameters, of a polynomial of degree at most $n-1$, one polynomial per column. `index` "
                "counts from 0; whatever stands at `values[index]` is ignored (it may be NaN or infinity). Return "
                "a float, or an array of shape `(d,)`.",
            BAD: "Raise a `ValueError` if there are fewer than two values, if `values` has three or more "
                "dimensions or holds NaN or infinity anywhere but at `index`, or if `index` is not between 0 "
                "and $n$; a `TypeError` if `index` is not an integer.",
        },
    ),
    Exercise(
        id="04.raster_delta",
        reference=forward_differencing.raster_delta,
        cases=raster_cases,
        compare=close(1e-12, 1e-15),
        hint="d is the largest absolute coordinate change along a leg, max over i and over the coordinates of "
        "|P_i - P_(i-1)|, not the length of a leg; then δ = 1/(n d), but never more than 1.",
        rules={
            EDGE: "`points`: shape `(n+1, 2)` in pixel units, or `(n+1, 3)` for voxels (the same formula). A leg "
                "that runs left or down counts as much as one that runs right or up. Return $\\delta=1$ when "
                "$n\\,d\\le1$ (one step already moves less than a pixel), which includes a single point and "
                "coincident points.",
            BAD: "Raise a `ValueError` if `points` is not two-dimensional, has no rows, or holds NaN or infinity.",
        },
    ),
    Exercise(
        id="04.float32_drift",
        reference=forward_differencing.float32_drift,
        cases=drift_cases,
        compare=close(1e-6, 1e-9),
        hint="Compute the closed-form start in float64 (exercise 4.2), round it once with .astype(np.float32), "
        "march a float32 array (every addition in float32), and subtract Horner's rule in float64 at i·δ. Return "
        "the absolute errors as float64, one per value (and per column).",
        rules={
            EDGE: "`coeffs`: shape `(n+1,)` or `(n+1, d)`; return shape `(count,)` or `(count, d)`, "
                "and an empty array of that shape for `count = 0`. `delta` may be negative or zero.",
            BAD: "Raise a `TypeError` if `count` is not an integer and a `ValueError` if it is negative, if "
                "`coeffs` is empty or has three or more dimensions, or if `coeffs` or `delta` hold NaN or "
                "infinity.",
        },
    ),
]

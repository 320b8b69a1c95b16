"""Hidden grading suite of chapter 11: best constants, chord-length parameters, least squares and fairing.

Knots follow the notes' convention (c + n - 1 knots for c control points of
degree n, domain [t_(n-1), t_(c-1)]). The notes' own numbers are the two best
constants of §11.1 (read from cagd_course/examples/ch11.toml, with the
corrected e(4.5) = 2.5); the fitting cases use the course's arcs from the
same file, Bézier fits of polynomial data whose answers are known, sampled
B-splines that a fit must give back, knot vectors with double knots and
parameters at both ends of the domain. The normal equations are singular exactly
when the parameters fail the Schoenberg-Whitney condition: the chapter's clustered
example (32 distinct parameters, rank 7 of 8) must be rejected, and its example of
an empty knot span with the condition met must be fitted. Random cases come from
the generator the grader passes in and are built so that every knot span holds
several samples (the normal equations are well conditioned).
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import approximation
from cagd_ref.bspline import bezier_end_knots, de_boor

NOTES = "notes example"
COURSE = "course examples"
EDGE = "edge cases"
RANDOM = "random"
BAD = "bad input"

L2 = notes_example("11.best_constant_l2")
LINF = notes_example("11.best_constant_linf")
CHORD = notes_example("11.chord_length")
EVEN = notes_example("11.even_arc")
UNEVEN = notes_example("11.uneven_arc")
ARC_KNOTS = bezier_end_knots(10, 3, 0.0, 1.0)
X5 = np.linspace(0.0, 1.0, 5)
PARABOLA = np.column_stack([X5, X5**2])  # y = x², a quadratic Bézier curve with control points (0,0), (½,0), (1,1)
X7 = np.linspace(0.0, 1.0, 7)
CUBIC_DATA = np.column_stack([X7, X7**3 - X7])
DOUBLE = np.array([0.0, 0.0, 0.0, 1.0, 1.0, 2.5, 4.0, 4.0, 4.0])  # cubic, a double knot at 1 (C1 there)
# Nothing in (0.3, 1): with 8 uniform cubic knots N_5 and N_6 have no parameter at all (singular).
EMPTY_SPAN_PARAMS = np.concatenate([np.linspace(0.0, 0.3, 12), [1.0]])
# The chapter's Schoenberg-Whitney examples (§11.3.2). An empty span (1, 2) with the condition met:
GAP_KNOTS = np.array([0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0])
GAP_PARAMS = np.concatenate([np.linspace(0.05, 0.95, 10), np.linspace(2.05, 2.95, 10)])
# Clustered parameters: 32 distinct ones, every N_j nonzero at one, but rank 7 of 8 with uniform knots.
CLUSTERED = np.concatenate([np.linspace(0.0, 0.3, 30), [0.65, 1.0]])
CLUSTERED_KNOTS = approximation.fitting_knots(CLUSTERED, 8, 3)
GAP_RULE = "A knot span without parameters is allowed"
CLUSTERED_RULE = ("the chapter's clustered example (30 parameters in $[0,0.3]$, two more at 0.65 and 1, cubic, 8 "
                  "control points, uniform knots)")


def _arc(example, parametrization=approximation.chord_length_parameters):
    points = example.inputs["points"]
    return points, parametrization(points)


def _random_problem(rng, degrees=(1, 5), dims=(1, 2, 3), double_knots=True):
    """Random points, params (several in every span, both ends of the domain), knots, degree."""
    n = int(rng.integers(degrees[0], degrees[1] + 1))
    c = int(rng.integers(n + 1, n + 8))
    breaks = np.cumsum(np.concatenate([[float(rng.uniform(-2, 2))], rng.uniform(0.3, 1.5, c - n)]))
    inner = breaks[1:-1]
    if double_knots and n >= 2 and len(inner) >= 2 and rng.uniform() < 0.4:
        inner = np.sort(np.concatenate([inner, inner[:1]]))[: c - n - 1]
    knots = np.concatenate([np.full(n, breaks[0]), inner, np.full(n, breaks[-1])])
    per_span = int(rng.integers(n + 1, n + 5))
    params = np.concatenate([rng.uniform(a, b, per_span) for a, b in zip(breaks[:-1], breaks[1:])])
    params = np.concatenate([params, breaks[[0, -1]]])
    if rng.uniform() < 0.5:
        params = np.sort(params)
    else:
        rng.shuffle(params)
    d = int(rng.choice(dims))
    return rng.uniform(-5, 5, (len(params), d)), params, knots, n


def _sampled_spline(rng, n=3, c=7):
    """Samples of a known B-spline (control points (c, 3)): a least-squares fit must give it back."""
    knots = bezier_end_knots(c, n, 0.0, 1.0)
    control = rng.uniform(-5, 5, (c, 3))
    params = np.sort(np.concatenate([rng.uniform(0, 1, 4 * c), [0.0, 1.0]]))
    return de_boor(control, knots, params), params, knots, n


# --- 11.best_constant ---------------------------------------------------------------------------


def best_constant_cases(rng):
    values = L2.inputs["values"]
    cases = [
        Case(NOTES, (values,), visible=True),  # the default norm is L2
        Case(NOTES, (values, "l2"), visible=True),
        Case(NOTES, (values, "linf"), visible=True),
        Case(NOTES, (values,), {"norm": "linf"}, visible=True),
        Case(EDGE, ([3.5], "l2"), visible=True),
        Case(EDGE, ([3.5], "linf"), visible=True),
        Case(EDGE, ([1.0, 2.0, 10.0, 11.0], "l2"), visible=True),  # mean 6, median 6: but the next is skewed
        Case(EDGE, ([0.0, 0.0, 0.0, 9.0], "l2"), visible=True),  # mean 2.25, median 0
        Case(EDGE, ([0.0, 0.0, 0.0, 9.0], "linf"), visible=True),
        Case(EDGE, ([-4.0, -1.0, -2.5], "linf"), visible=True),
        Case(EDGE, (np.array([2, 3, 3, 5, 7]), "l2"), visible=True),  # integers
        Case(EDGE, ([7.0, 7.0, 7.0], "linf"), visible=True),
    ]
    for _ in range(12):
        g = rng.normal(0, 3, int(rng.integers(1, 12)))
        cases.append(Case(RANDOM, (g, str(rng.choice(["l2", "linf"])))))
    cases += [
        Case(BAD, ([], "l2")),
        Case(BAD, ([[1.0, 2.0], [3.0, 4.0]], "l2")),
        Case(BAD, (values, "l1")),
        Case(BAD, (values, "max")),
    ]
    return cases


# --- 11.chord_length_parameters ---------------------------------------------------------------------


def chord_length_parameters_cases(rng):
    cases = [
        Case(COURSE, (CHORD.inputs["points"],), visible=True),
        Case(COURSE, (EVEN.inputs["points"],), visible=True),
        Case(COURSE, (UNEVEN.inputs["points"],), visible=True),
        Case(EDGE, ([[0.0, 0.0], [3.0, 4.0]],), visible=True),  # two samples: 0 and 1
        Case(EDGE, ([[1.0], [4.0], [2.0], [2.0]],), visible=True),  # 1-D samples, a repeated one
        Case(EDGE, ([[0.0, 0.0], [1.0, 0.0], [1.0, 0.0], [1.0, 2.0]],), visible=True),
        Case(EDGE, ([[0.0, 0.0, 0.0], [1.0, 2.0, 2.0], [1.0, 2.0, 5.0]],), visible=True),  # 3-D: chords 3 and 3
        Case(EDGE, ([(0, 0), (3, 4), (3, 10)],), visible=True),  # integer tuples
    ]
    for _ in range(10):
        cases.append(Case(RANDOM, (rng.normal(size=(int(rng.integers(2, 30)), int(rng.integers(1, 4)))),)))
    cases += [
        Case(BAD, ([[1.0, 2.0]],)),  # one sample
        Case(BAD, ([[1.0, 2.0], [1.0, 2.0], [1.0, 2.0]],)),  # no length
        Case(BAD, ([1.0, 2.0, 3.0],)),  # not (M, d)
    ]
    return cases


# --- 11.least_squares_fit ---------------------------------------------------------------------------


def least_squares_fit_cases(rng):
    even, even_params = _arc(EVEN)
    uneven, uneven_params = _arc(UNEVEN)
    sampled = _sampled_spline(np.random.default_rng(11))
    cases = [
        Case(COURSE, (PARABOLA, X5, [0.0, 0.0, 1.0, 1.0], 2), visible=True),  # gives back (0,0), (½,0), (1,1)
        Case(COURSE, (even, even_params, ARC_KNOTS, 3), visible=True),
        Case(COURSE, (uneven, uneven_params, ARC_KNOTS, 3), visible=True),
        Case(COURSE, (uneven, approximation.uniform_parameters(uneven), ARC_KNOTS, 3), visible=True),
        Case(EDGE, sampled, visible=True),  # samples of a known cubic: its control points come back
        Case(EDGE, (CUBIC_DATA, X7, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 3), visible=True),
        Case(EDGE, (CUBIC_DATA[:, 1:], X7, [0.0, 0.5, 1.0], 1), visible=True),  # degree 1, scalar data
        Case(EDGE, (np.column_stack([np.linspace(0, 4, 21), np.sin(np.linspace(0, 4, 21))]),
                    np.linspace(0, 4, 21), DOUBLE, 3), visible=True),  # a double knot
        Case(EDGE, (CUBIC_DATA[::-1], X7[::-1], [0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 3), visible=True),  # unsorted
        Case(EDGE, (PARABOLA[[0, 2, 4]], X5[[0, 2, 4]], [0.0, 0.0, 1.0, 1.0], 2), visible=True),  # as many as c
        Case(EDGE, (np.column_stack([GAP_PARAMS, np.cos(GAP_PARAMS)]), GAP_PARAMS, GAP_KNOTS, 3), visible=True,
             rule=GAP_RULE),  # nothing in (1, 2), yet full rank
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, _random_problem(rng)))
    cases += [
        Case(BAD, (PARABOLA, X5[:4], [0.0, 0.0, 1.0, 1.0], 2)),  # one parameter short
        Case(BAD, (PARABOLA, X5 + 0.5, [0.0, 0.0, 1.0, 1.0], 2)),  # outside the domain
        Case(BAD, (PARABOLA, X5, [0.0, 1.0, 0.0, 1.0], 2)),  # decreasing knots
        Case(BAD, (PARABOLA, X5, [0.0, 0.0, 1.0, 1.0], 0)),
        Case(BAD, (PARABOLA[:2], X5[:2], [0.0, 0.0, 1.0, 1.0], 2)),  # fewer samples than control points
        Case(BAD, (np.column_stack([EMPTY_SPAN_PARAMS, EMPTY_SPAN_PARAMS**2]), EMPTY_SPAN_PARAMS,
                   bezier_end_knots(8, 3, 0.0, 1.0), 3)),  # N_5, N_6 without a parameter: singular
        Case(BAD, (np.column_stack([CLUSTERED, np.sin(4 * CLUSTERED)]), CLUSTERED, CLUSTERED_KNOTS, 3),
             rule=CLUSTERED_RULE),  # rank 7 of 8; np.linalg.solve does not notice
    ]
    return cases


# --- 11.fairing_matrix ----------------------------------------------------------------------------


def fairing_matrix_cases(rng):
    cases = [Case(COURSE, notes_example(f"11.{name}").args("knots", "degree"), visible=True)
             for name in ("fairing_quadratic", "fairing_cubic", "fairing_two_spans")]
    cases += [
        Case(EDGE, ([0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], 4), visible=True),  # one quartic Bézier segment
        Case(EDGE, ([0.0] * 5 + [1.0] * 5, 5), visible=True),  # degree 5: needs four Gauss points per span
        Case(EDGE, ([2.0, 2.0, 2.0, 5.0, 5.0, 5.0], 3), visible=True),  # a span of length 3, not at 0
        Case(EDGE, (np.arange(1.0, 9.0), 3), visible=True),  # knots 1..8: the domain is [3, 6] only
        Case(EDGE, (DOUBLE, 3), visible=True),  # a double knot
        Case(EDGE, ([0.0, 0.0, 1.0, 1.0, 3.0, 3.0], 2), visible=True),  # a double knot in a quadratic (C0)
        Case(EDGE, ([0.0, 1.0, 2.5, 3.0, 4.0, 6.0], 2), visible=True),  # non-uniform, knots outside the domain
    ]
    for _ in range(12):
        _, _, knots, n = _random_problem(rng, degrees=(2, 5))
        cases.append(Case(RANDOM, (knots, n)))
    cases += [
        Case(BAD, ([0.0, 1.0, 2.0], 1)),  # degree 1: no second derivative to fair
        Case(BAD, ([0.0, 0.0, 2.0, 1.0, 3.0, 3.0], 2)),  # decreasing knots
        Case(BAD, ([0.0, 0.0, 0.0, 1.0, 1.0], 3)),  # too few knots for a cubic
        Case(BAD, ([0.0, 0.0, 1.0, 1.0], 0)),
    ]
    return cases


# --- 11.faired_fit ------------------------------------------------------------------------------------


def faired_fit_cases(rng):
    uneven, params = _arc(UNEVEN)
    x = np.sort(np.random.default_rng(5).uniform(0, 3, 15))
    smooth = (np.sin(2 * x) + 0.1 * np.random.default_rng(6).normal(size=15))[:, None]
    data_knots = np.concatenate([[x[0]] * 2, x, [x[-1]] * 2])  # knots at the data: a smoothing spline
    cases = [
        Case(COURSE, (PARABOLA[:, 1:], X5, [0.0, 0.0, 1.0, 1.0], 2, 1.0), visible=True),
        Case(COURSE, (PARABOLA, X5, [0.0, 0.0, 1.0, 1.0], 2, 0.0), visible=True),  # weight 0: least squares
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 1e-4), visible=True),
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 1e-2), visible=True),
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 1.0), visible=True),  # shrunk towards a line
        Case(EDGE, (smooth, x, data_knots, 3, 0.01), visible=True),
        Case(EDGE, (CUBIC_DATA, X7 * 4, DOUBLE, 3, 0.5), visible=True),  # a double knot, domain [0, 4]
        Case(EDGE, (np.column_stack([EMPTY_SPAN_PARAMS, EMPTY_SPAN_PARAMS**2]), EMPTY_SPAN_PARAMS,
                    bezier_end_knots(8, 3, 0.0, 1.0), 3, 1e-6), visible=True),  # singular without fairing
        Case(EDGE, (CUBIC_DATA, X7, [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], 4, 1e-3), visible=True),
    ]
    for _ in range(12):
        points, params_, knots, n = _random_problem(rng, degrees=(2, 5))
        cases.append(Case(RANDOM, (points, params_, knots, n, float(10.0 ** rng.uniform(-4, 0)))))
    cases += [
        Case(BAD, (PARABOLA, X5, [0.0, 0.0, 1.0, 1.0], 2, -1.0)),  # a negative weight
        Case(BAD, (PARABOLA, X5, [0.0, 0.5, 1.0], 1, 1.0)),  # degree 1 with a positive weight
        Case(BAD, (PARABOLA, X5 * 2, [0.0, 0.0, 1.0, 1.0], 2, 1.0)),  # outside the domain
        Case(BAD, (PARABOLA, X5[1:], [0.0, 0.0, 1.0, 1.0], 2, 1.0)),
    ]
    return cases


# --- 11.constrained_fit ---------------------------------------------------------------------------


def constrained_fit_cases(rng):
    uneven, params = _arc(UNEVEN)
    ends = [0, 14, 29]
    cubic_knots = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
    cases = [
        Case(COURSE, (CUBIC_DATA, X7, cubic_knots, 3, 0.0, [[0.5, 0.5]], [0.5]), visible=True),
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 0.0, uneven[ends], params[ends]), visible=True),
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 1e-2, uneven[ends], params[ends]), visible=True),
        Case(COURSE, (uneven, params, ARC_KNOTS, 3, 1.0, uneven[ends], params[ends]), visible=True),
        Case(EDGE, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, [[0.0, 0.0], [1.0, 1.0]], [0.0, 1.0]), visible=True),
        Case(EDGE, (CUBIC_DATA, X7, cubic_knots, 3, 0.0, CUBIC_DATA[[0, 2, 4, 6]], X7[[0, 2, 4, 6]]),
             visible=True),  # as many targets as control points: the interpolating cubic
        Case(EDGE, (CUBIC_DATA, X7 * 4, DOUBLE, 3, 0.5, [[1.0, 2.0]], [2.0]), visible=True),
        Case(EDGE, (CUBIC_DATA[:, 1:], X7, [0.0, 0.5, 1.0], 1, 0.0, [[3.0]], [0.25]), visible=True),  # degree 1
    ]
    for _ in range(12):
        points, params_, knots, n = _random_problem(rng, degrees=(2, 4), double_knots=False)
        count = int(rng.integers(1, min(4, len(knots) - n + 1) + 1))
        a, b = knots[n - 1], knots[len(knots) - n]
        target_params = np.sort(rng.uniform(a, b, count))
        targets = rng.uniform(-5, 5, (count, points.shape[1]))
        cases.append(Case(RANDOM, (points, params_, knots, n, float(10.0 ** rng.uniform(-4, -1)), targets,
                                   target_params)))
    cases += [
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, np.zeros((5, 2)), np.linspace(0, 1, 5))),  # I > c
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, np.zeros((0, 2)), np.zeros(0))),  # no targets, I = 0
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, [[0.0, 0.0], [1.0, 1.0]], [0.5, 0.5])),  # repeated
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, [[0.0, 0.0]], [1.5])),  # outside the domain
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, [[0.0, 0.0]], [0.2, 0.4])),  # lengths differ
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, 0.1, [[0.0, 0.0, 0.0]], [0.5])),  # dimension differs
        Case(BAD, (CUBIC_DATA, X7, cubic_knots, 3, -0.1, [[0.0, 0.0]], [0.5])),  # a negative weight
    ]
    return cases


EXERCISES = [
    Exercise(
        id="11.best_constant",
        reference=approximation.best_constant,
        cases=best_constant_cases,
        compare=close(1e-9, 1e-9),
        hint="Return a tuple (A, e(A)). L2: A is the mean and e(A) = Σ (A - g)², the sum (not the mean) of the "
        "squares. linf: A = (max + min) / 2 and e(A) = max |A - g| = (max - min) / 2.",
        rules={
            EDGE: "`values`: a 1-D list or array of at least one number.",
            BAD: "Raise a `ValueError` if `values` is empty or not one-dimensional, or `norm` is anything other "
                "than `\"l2\"` or `\"linf\"` (the names are case-sensitive).",
        },
    ),
    Exercise(
        id="11.chord_length_parameters",
        reference=approximation.chord_length_parameters,
        cases=chord_length_parameters_cases,
        compare=close(1e-12, 1e-12),
        hint="One parameter per sample: τ_0 = 0, then the running sum of the chord lengths ‖Q_i - Q_(i-1)‖ "
        "(not squared), divided by the total so the last is 1. Reject fewer than two samples and a polygon "
        "of total length 0 with a ValueError.",
        rules={
            EDGE: "Two equal neighbours get equal parameters (a chord of length 0 adds nothing).",
            BAD: "Raise a `ValueError` if `points` is not two-dimensional, has fewer than two samples, or all "
                "samples are the same point (the polygon has no length to divide by).",
        },
    ),
    Exercise(
        id="11.least_squares_fit",
        reference=approximation.least_squares_fit,
        cases=least_squares_fit_cases,
        compare=close(1e-8, 1e-8),
        hint="c = len(knots) - degree + 1 control points. Build N[k, j] = N_j(τ_k) (shape (M, c), with the last "
        "span closed so that τ = t_(c-1) counts), then solve (NᵀN) P = NᵀQ for all coordinates at once. "
        "A singular system must become a ValueError, and np.linalg.solve does not always notice one: test the "
        "Schoenberg-Whitney condition or the rank of N. An empty knot span alone is not singular.",
        rules={
            EDGE: "`params`: `(M,)`, one per sample, in any order, each inside the domain $[t_{n-1},t_{c-1}]$ (both "
                "ends allowed, see the note on the end of the domain above)",
            BAD: "Raise a `ValueError` if `params` and `points` differ in length, a parameter lies outside the "
                "domain, the knots decrease, `degree` is below 1 or there are fewer than $2n$ knots, and when the "
                "normal equations are singular",
        },
    ),
    Exercise(
        id="11.fairing_matrix",
        reference=approximation.fairing_matrix,
        cases=fairing_matrix_cases,
        compare=close(1e-8, 1e-8),
        hint="Integrate N_i''(t) N_j''(t) span by span over the domain [t_(n-1), t_(c-1)] only, skipping spans "
        "of length zero. Gauss-Legendre with n - 1 points on [a, b] is exact: nodes (a + b)/2 + (b - a)/2 x_q, "
        "weights (b - a)/2 w_q. Degree 1 has no second derivative: raise a ValueError.",
        rules={
            EDGE: "Return a symmetric array of shape `(c, c)`, compared to within a relative $10^{-8}$.",
            BAD: "Raise a `ValueError` if `degree` is below 2 (a degree-1 spline has no second derivative to fair), "
                "the knots decrease, or there are fewer than $2n$ knots.",
        },
    ),
    Exercise(
        id="11.faired_fit",
        reference=approximation.faired_fit,
        cases=faired_fit_cases,
        compare=close(1e-7, 1e-8),
        hint="Solve (NᵀN + λ M_fair) P = NᵀQ (λ = weight), with M_fair from your fairing_matrix. λ = 0 is the "
        "least-squares fit; a negative weight, or a positive one with degree 1, is a ValueError.",
        rules={
            EDGE: "With `weight = 0` the answer is the least-squares fit; as the weight grows the curve is pulled "
                "towards a straight line.",
            BAD: "Raise a `ValueError` if `params` and `points` differ in length, a parameter lies outside the "
                "domain, the knots decrease, `degree` is below 1 or there are fewer than $2n$ knots, for a "
                "negative weight, for a positive weight with `degree` 1 (there is nothing to fair), and when the "
                "system is singular.",
        },
    ),
    Exercise(
        id="11.constrained_fit",
        reference=approximation.constrained_fit,
        cases=constrained_fit_cases,
        compare=close(1e-7, 1e-7),
        hint="Solve [[NᵀN + λ M_fair, Cᵀ], [C, 0]] [P; μ] = [NᵀQ; R] with C[i, j] = N_j(v_i) (I × c) and "
        "return P only (the first c rows). The targets are met exactly, not approximately: no large penalty "
        "weights. No targets, more targets than control points, or a singular system, is a ValueError.",
        rules={
            EDGE: "The curve must pass through the targets exactly, so treating them as samples with a large weight "
                "is not good enough.",
            BAD: "Raise a `ValueError` for the bad inputs of exercise 11.5 (samples and parameters of different "
                "lengths, a parameter outside the domain, bad knots or degree, a negative weight, a positive "
                "weight with `degree` 1), if there are no targets or more targets than control points, `targets` and "
                "`target_params` differ in length, the targets have another dimension than the samples, a target "
                "parameter lies outside the domain, or the block system is singular",
        },
    ),
]

"""Hidden grading suite of chapter 5: Timmer's and Ball's blending functions, Overhauser curves and
the conversion of Timmer's cubic to Bézier form.

Fixed cases reuse the notes' facts (Timmer's curve through the midpoint of P1 P2 at t = 1/2, the
end-derivative conversion of the notes' example, the Overhauser tangents (P2 - P0)/2); edge cases
probe t at 0, 1 and outside [0, 1], the last parameter of an Overhauser curve, its joints,
coincident and collinear points and 1-D / 3-D points; random cases come from the grader's generator.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import blending

NOTES = "notes example"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
RANDOM = "random"
BAD = "bad input"

ARCH = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.5), (4.0, 0.5)]
WAVE = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0), (3.0, 2.0), (4.0, 0.0), (5.0, 2.0)]
SPACE = [(0.0, 0.0, 0.0), (1.0, 2.0, 0.5), (3.0, -1.0, 2.0), (4.0, 1.0, -1.0), (2.0, 2.0, 2.0)]
MIDPOINT = notes_example("05.timmer_midpoint")  # t = 1/2: Timmer's curve passes through the midpoint of P1 P2
TIMMER_ARCH = notes_example("05.timmer_arch")  # a course example of the Timmer-to-Bézier conversion


def _ts(rng, low=0.0, high=1.0):
    if rng.uniform() < 0.3:
        return float(rng.uniform(low, high))
    return np.sort(rng.uniform(low, high, int(rng.integers(1, 8))))


def _points(rng, low_count, high_count):
    count = int(rng.integers(low_count, high_count + 1))
    return rng.uniform(-10, 10, (count, int(rng.integers(1, 4))))


# --- 05.timmer_basis / 05.ball_basis -----------------------------------------


def _basis_cases(rng):
    cases = [
        Case(NOTES, MIDPOINT.args("t"), visible=True),
        Case(NOTES, ([0.0, 0.25, 0.5, 0.75, 1.0],), visible=True),
        Case(EDGE, (0.0,), visible=True),
        Case(EDGE, (1.0,), visible=True),
        Case(EDGE, (1 / 3,), visible=True),
        Case(EDGE, ([-0.5, 1.5],), visible=True),  # outside [0, 1] the polynomials still apply
        Case(SHAPES, (np.array([0.5]),)),
        Case(SHAPES, (np.array(0.25),)),
        Case(SHAPES, (np.linspace(0, 1, 9),)),
        Case(SHAPES, ([],)),
    ]
    cases += [Case(RANDOM, (_ts(rng),)) for _ in range(12)]
    cases += [Case(BAD, ([[0.1, 0.2]],)), Case(BAD, ("half",)), Case(BAD, (float("nan"),))]
    cases.append(Case(BAD, ([0.5, float("inf")],)))
    return cases


# --- 05.overhauser_point -----------------------------------------------------


def overhauser_point_cases(rng):
    cases = [
        Case(NOTES, (ARCH, 0.5), visible=True),  # (-P0 + 9 P1 + 9 P2 - P3) / 16
        Case(NOTES, (ARCH, [0.0, 1.0]), visible=True),  # from P1 to P2
        Case(NOTES, (WAVE, [0.0, 1.0, 2.0, 3.0]), visible=True),  # through P1 .. P4
        Case(EDGE, (WAVE, 3.0), visible=True),  # the very last parameter belongs to the last segment
        Case(EDGE, (WAVE, [0.999, 1.0, 1.001]), visible=True),  # across a joint
        Case(EDGE, (WAVE, 2.25), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0), (4.0, 4.0)], [0.0, 0.5, 1.5, 2.0]), visible=True),
        Case(EDGE, ([(1.0, 1.0)] * 4, 0.3), visible=True),
        Case(EDGE, ([(0.0, 0.0), (0.0, 0.0), (2.0, 1.0), (2.0, 1.0)], 0.5), visible=True),
        Case(EDGE, ([[0.0], [1.0], [5.0], [2.0], [3.0]], [0.25, 1.75]), visible=True),
        Case(EDGE, (SPACE, [0.0, 0.6, 2.0]), visible=True),
        Case(SHAPES, (ARCH, np.array([0.5]))),
        Case(SHAPES, (ARCH, np.array(0.5))),
        Case(SHAPES, (WAVE, np.linspace(0, 3, 13))),
    ]
    for _ in range(14):
        pts = _points(rng, 4, 9)
        cases.append(Case(RANDOM, (pts, _ts(rng, 0.0, len(pts) - 3))))
    cases += [
        Case(BAD, (ARCH[:3], 0.5)),
        Case(BAD, (ARCH, 1.5)),
        Case(BAD, (WAVE, -0.1)),
        Case(BAD, ([0.0, 1.0, 2.0, 3.0], 0.5)),
        Case(BAD, ([(0.0, 0.0), (1.0, float("nan")), (3.0, 2.5), (4.0, 0.5)], 0.5)),
        Case(BAD, (ARCH, [0.5, float("inf")])),
    ]
    return cases


# --- 05.timmer_to_bezier -----------------------------------------------------


def timmer_to_bezier_cases(rng):
    notes_cubic = notes_example("02.hodograph_table").inputs["points"]
    cases = [
        Case(NOTES, TIMMER_ARCH.args("points"), visible=True),
        # Q1 = (P0 + 3 P1)/4, Q2 = (P3 + 3 P2)/4 of the notes' example, for the cubic of chapter 2.
        Case(NOTES, (blending.from_bezier("timmer", notes_cubic),), visible=True),
        Case(EDGE, ([(1.0, 2.0)] * 4,), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0)],), visible=True),
        Case(EDGE, ([[0.0], [1.0], [5.0], [2.0]],), visible=True),
        Case(EDGE, (SPACE[:4],), visible=True),
        Case(EDGE, ([(0, 0), (3, 6), (6, 6), (9, 0)],), visible=True),  # integers in, floats out
        Case(EDGE, (ARCH,), visible=True),
    ]
    cases += [Case(RANDOM, (rng.uniform(-10, 10, (4, int(rng.integers(1, 4)))),)) for _ in range(14)]
    cases += [
        Case(BAD, (ARCH[:3],)),
        Case(BAD, (ARCH + [(5.0, 5.0)],)),
        Case(BAD, ([0.0, 1.0, 2.0, 3.0],)),
        Case(BAD, ([(0.0, 0.0), (1.0, 2.0), (float("inf"), 2.5), (4.0, 0.5)],)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="05.timmer_basis",
        reference=blending.timmer_basis,
        cases=_basis_cases,
        compare=close(1e-9, 1e-12),
        hint="f0 = (1-t)²(1-2t), f1 = 4t(1-t)², f2 = 4t²(1-t), f3 = t²(2t-1): the middle factor is 4, not Bézier's 3. "
        "A number t gives shape (4,), k values give (k, 4) with one row per t (stack columns, not rows).",
        rules={
            EDGE: "Values of `t` outside $[0,1]$ are allowed",
            SHAPES: "A 0-d array counts as a number, and an empty list gives shape `(0, 4)`.",
            BAD: "Raise a `ValueError` for a `t` with two or more dimensions or with NaN or infinite values, and a "
                "`TypeError` for a `t` that is not numbers (a string, say).",
        },
    ),
    Exercise(
        id="05.ball_basis",
        reference=blending.ball_basis,
        cases=_basis_cases,
        compare=close(1e-9, 1e-12),
        hint="f0 = (1-t)², f1 = 2t(1-t)², f2 = 2t²(1-t), f3 = t²: the end functions are quadratic, the middle ones "
        "carry a factor 2. A number t gives shape (4,), k values give (k, 4), one row per t.",
        rules={
            EDGE: "Values of `t` outside $[0,1]$ are allowed",
            SHAPES: "A 0-d array counts as a number, and an empty list gives shape `(0, 4)`.",
            BAD: "Raise a `ValueError` for a `t` with two or more dimensions or with NaN or infinite values, and a "
                "`TypeError` for a `t` that is not numbers (a string, say).",
        },
    ),
    Exercise(
        id="05.overhauser_point",
        reference=blending.overhauser_point,
        cases=overhauser_point_cases,
        compare=close(1e-9, 1e-9),
        hint="Segment j = floor(t) uses points j..j+3 with u = t - j and runs from points[j+1] to points[j+2]; at "
        "t = c-3 use the last segment with u = 1. The end tangents are half the chords: (P2 - P0)/2 and (P3 - P1)/2.",
        rules={
            EDGE: "except that $t=c-3$ (the very end) belongs to the last segment with $u=1$",
            SHAPES: "`t`: a number (return one point, shape `(d,)`) or a 1-D array of k numbers (return `(k, d)`); "
                "different values may fall in different segments.",
            BAD: "Raise a `ValueError` for fewer than 4 points, `points` that are not two-dimensional, NaN or "
                "infinite coordinates or parameters, or any `t` outside $[0, c-3]$.",
        },
    ),
    Exercise(
        id="05.timmer_to_bezier",
        reference=blending.timmer_to_bezier,
        cases=timmer_to_bezier_cases,
        compare=close(1e-9, 1e-9),
        hint="Match the ends and the end derivatives: Q'(0) = 4(Q1 - Q0) must equal 3(P1 - P0), so P1 = (4 Q1 - Q0)/3, "
        "and likewise P2 = (4 Q2 - Q3)/3; P0 = Q0 and P3 = Q3. Exactly four points of any dimension.",
        rules={
            EDGE: "`points`: shape `(4, d)`, any dimension $d\\ge1$. Return shape `(4, d)`.",
            BAD: "Raise a `ValueError` unless there are exactly four points in a two-dimensional array, and for NaN "
                "or infinite coordinates.",
        },
    ),
]

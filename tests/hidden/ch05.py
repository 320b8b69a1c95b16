"""Hidden grading suite of chapter 5: Timmer's and Ball's blending functions, Overhauser curves, the
conversion of Timmer's cubic to Bézier form, Catmull-Rom curves with parameters and the crossing counts
that test variation diminishing.

Fixed cases reuse the notes' facts (Timmer's curve through the midpoint of P1 P2 at t = 1/2, the
end-derivative conversion of the notes' example, the Overhauser tangents (P2 - P0)/2); edge cases
probe t at 0, 1 and outside [0, 1], the last parameter of an Overhauser curve, its joints,
coincident and collinear points and 1-D / 3-D points, vertices on the line (touching or crossing);
random cases come from the grader's generator.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import blending

NOTES = "notes example"
COURSE = "course examples"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
RANDOM = "random"
BAD = "bad input"

ARCH = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.5), (4.0, 0.5)]
WAVE = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0), (3.0, 2.0), (4.0, 0.0), (5.0, 2.0)]
SPACE = [(0.0, 0.0, 0.0), (1.0, 2.0, 0.5), (3.0, -1.0, 2.0), (4.0, 1.0, -1.0), (2.0, 2.0, 2.0)]
MIDPOINT = notes_example("05.timmer_midpoint")  # t = 1/2: Timmer's curve passes through the midpoint of P1 P2
TIMMER_ARCH = notes_example("05.timmer_arch")  # a course example of the Timmer-to-Bézier conversion
FIGURE_5_1 = notes_example("05.variation_diminishing")  # the line meets the polygon 5 times, the curve 3 times
UNEVEN = [(0.0, 0.0), (0.2, 1.0), (0.4, 1.1), (4.0, 1.0), (4.5, 0.0), (6.0, -2.0)]  # spacing from 0.2 to 3.6
FLAT = [(0.0, 0.0), (1.5, 0.0), (3.0, 0.0), (4.0, 3.0)]  # three points on the x-axis, Timmer's curve dips below


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


# --- 05.catmull_rom_point ----------------------------------------------------


def _increasing(rng, count):
    return np.cumsum(np.r_[rng.uniform(-3, 3), rng.uniform(0.1, 3.0, count - 1)])


def catmull_rom_point_cases(rng):
    chord = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(np.array(UNEVEN), axis=0), axis=1))]
    centripetal = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(np.array(UNEVEN), axis=0), axis=1) ** 0.5)]
    cases = [
        Case(COURSE, (WAVE, [-1.0, 0.0, 1.0, 2.0, 3.0, 4.0], [0.0, 1.5, 3.0]), visible=True),  # uniform: Overhauser
        Case(COURSE, (ARCH, [0.0, 1.0, 3.0, 4.0], [1.0, 2.0, 3.0]), visible=True),
        Case(COURSE, (UNEVEN, chord, np.linspace(chord[1], chord[-2], 9)), visible=True),
        Case(COURSE, (UNEVEN, centripetal, np.linspace(centripetal[1], centripetal[-2], 9)), visible=True),
        Case(EDGE, (UNEVEN, chord, chord[-2]), visible=True),  # the very end belongs to the last segment
        Case(EDGE, (UNEVEN, chord, chord[1]), visible=True),
        Case(EDGE, (UNEVEN, chord, [chord[2] - 1e-9, chord[2], chord[2] + 1e-9]), visible=True),  # across a joint
        Case(EDGE, (WAVE, [-10.0, -7.5, -7.0, -1.0, 0.0, 20.0], [-7.5, -7.2, -4.0, -0.5, 0.0]), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (2.0, 0.0), (2.0, 0.0)], [0.0, 1.0, 2.0, 3.0], 1.5)),
        Case(EDGE, ([[0.0], [1.0], [5.0], [2.0], [3.0]], [0.0, 0.5, 2.0, 2.5, 4.0], [0.5, 1.25, 2.5])),
        Case(EDGE, (SPACE, [0.0, 1.0, 1.5, 4.0, 5.0], [1.0, 1.2, 3.0, 4.0])),
        Case(SHAPES, (ARCH, [0.0, 1.0, 3.0, 4.0], np.array([2.0]))),
        Case(SHAPES, (ARCH, [0.0, 1.0, 3.0, 4.0], np.array(2.0))),
        Case(SHAPES, (ARCH, [0.0, 1.0, 3.0, 4.0], np.array([]))),
    ]
    for _ in range(14):
        pts = _points(rng, 4, 8)
        knots = _increasing(rng, len(pts))
        cases.append(Case(RANDOM, (pts, knots, _ts(rng, knots[1], knots[-2]))))
    cases += [
        Case(BAD, (ARCH[:3], [0.0, 1.0, 2.0], 1.5)),
        Case(BAD, (ARCH, [0.0, 1.0, 2.0], 1.5)),
        Case(BAD, (ARCH, [0.0, 1.0, 1.0, 2.0], 1.0)),
        Case(BAD, (ARCH, [0.0, 2.0, 1.0, 3.0], 1.5)),
        Case(BAD, (ARCH, [0.0, 1.0, 2.0, 3.0], 2.5)),
        Case(BAD, (ARCH, [0.0, 1.0, 2.0, 3.0], [1.5, 0.5])),
        Case(BAD, ([0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 2.0, 3.0], 1.5)),
        Case(BAD, (ARCH, [0.0, 1.0, float("nan"), 3.0], 1.5)),
        Case(BAD, (ARCH, [0.0, 1.0, 2.0, 3.0], float("inf"))),
    ]
    return cases


# --- 05.crossing_counts ------------------------------------------------------


def crossing_counts_cases(rng):
    zigzag, axis = FIGURE_5_1.args("polygon", "line")
    samples = np.linspace(0, 1, 401)
    cases = [
        Case(NOTES, (blending.bezier_basis(samples, degree=5), zigzag, axis), visible=True),
        Case(COURSE, (blending.timmer_basis(samples), FLAT, [0.0, 1.0, 0.05]), visible=True),
        Case(COURSE, (blending.ball_basis(samples), FLAT, [0.0, 1.0, 0.05]), visible=True),
        # A vertex on the line between two vertices on one side touches; between opposite sides it crosses.
        Case(EDGE, (blending.bezier_basis(samples, degree=2), [(0.0, 1.0), (1.0, 0.0), (2.0, 1.0)], [0.0, 1.0, 0.0]),
             visible=True),
        Case(EDGE, (blending.bezier_basis(samples, degree=2), [(0.0, 1.0), (1.0, 0.0), (2.0, -1.0)], [0.0, 1.0, 0.0]),
             visible=True),
        Case(EDGE, (blending.timmer_basis(samples), [(0.0, 1.0), (1.0, 0.0), (2.0, 0.0), (3.0, -1.0)],
                    [0.0, 1.0, 0.0]), visible=True),  # two vertices on the line, the curve's middle on it too
        Case(EDGE, (blending.ball_basis(samples), ARCH, [1.0, 0.0, 0.0])),  # through the first point only
        Case(EDGE, (blending.overhauser_basis(samples), ARCH, [1.0, -1.0, 0.5])),
        Case(EDGE, (blending.overhauser_basis(samples), ARCH, [1000.0, -1000.0, 500.0])),  # the same line, scaled
        Case(EDGE, (blending.ball_basis([0.5]), ARCH, [0.0, 1.0, -1.0])),  # one sample: no curve crossing
        Case(EDGE, (blending.bezier_basis(samples), ARCH, [0.0, 1.0, 5.0])),  # everything on one side
        Case(EDGE, ([[1.0]] * 5, [(3.0, 4.0)], [1.0, 1.0, 1.0])),  # one control point
    ]
    for _ in range(14):
        form = str(rng.choice(["bezier", "timmer", "ball", "overhauser"]))
        polygon = rng.uniform(-3, 3, (4, 2))
        angle = rng.uniform(0, np.pi)
        normal = np.array([-np.sin(angle), np.cos(angle)])
        line = np.append(normal, -normal @ polygon.mean(axis=0) + rng.uniform(-1, 1))
        ts = np.linspace(0, 1, int(rng.integers(50, 400)))
        cases.append(Case(RANDOM, (blending.FORMS[form](ts), polygon, line)))
    cases += [
        Case(BAD, (blending.ball_basis(0.5), ARCH, [0.0, 1.0, 0.0])),
        Case(BAD, (blending.ball_basis(samples), ARCH[:3], [0.0, 1.0, 0.0])),
        Case(BAD, (blending.ball_basis(samples), SPACE[:4], [0.0, 1.0, 0.0])),
        Case(BAD, (blending.ball_basis(samples), ARCH, [0.0, 0.0, 1.0])),
        Case(BAD, (blending.ball_basis(samples), ARCH, [0.0, 1.0])),
        Case(BAD, (blending.ball_basis(samples), ARCH, [0.0, float("nan"), 1.0])),
        Case(BAD, (np.full((5, 4), np.nan), ARCH, [0.0, 1.0, 0.0])),
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
        "t = L-3 use the last segment with u = 1. The end tangents are half the chords: (P2 - P0)/2 and (P3 - P1)/2.",
        rules={
            EDGE: "except that $t=L-3$ (the very end) belongs to the last segment with $u=1$",
            SHAPES: "`t`: a number (return one point, shape `(d,)`) or a 1-D array of k numbers (return `(k, d)`); "
                "different values may fall in different segments.",
            BAD: "Raise a `ValueError` for fewer than 4 points, `points` that are not two-dimensional, NaN or "
                "infinite coordinates or parameters, or any `t` outside $[0, L-3]$.",
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
    Exercise(
        id="05.catmull_rom_point",
        reference=blending.catmull_rom_point,
        cases=catmull_rom_point_cases,
        compare=close(1e-9, 1e-9),
        hint="Segment j (t_j+1 <= t <= t_j+2) uses points j..j+3 at their own parameters: the parabola through "
        "points j..j+2 and the parabola through j+1..j+3 (Neville: interpolate linearly twice), blended with the "
        "weight (t - t_j+1)/(t_j+2 - t_j+1). With params 0, 1, 2, ... the curve must be the Overhauser curve.",
        rules={
            EDGE: "`t` may be any value in $[t_1, t_{L-2}]$, both ends included; $t=t_{L-2}$ belongs to the last "
                "segment.",
            SHAPES: "`t`: a number (return one point, shape `(d,)`) or a 1-D array of k numbers (return `(k, d)`); "
                "a 0-d array counts as a number.",
            BAD: "Raise a `ValueError` for fewer than 4 points, `points` that are not two-dimensional, `params` "
                "whose length is not the number of points or that do not strictly increase, NaN or infinite "
                "values, or any `t` outside $[t_1, t_{L-2}]$.",
        },
    ),
    Exercise(
        id="05.crossing_counts",
        reference=blending.crossing_counts,
        cases=crossing_counts_cases,
        compare=exact(),
        hint="Heights h_i = a x_i + b y_i + h of the control points and of the curve points values @ points; drop "
        "the heights within 1e-12 of zero, then count where the sign of one height differs from the next. "
        "Return (p, c): the polygon first.",
        rules={
            EDGE: "A height with $|\\ell|\\le 10^{-12}$ counts as zero and is skipped, so a vertex on the line "
                "between two vertices on the same side is no crossing.",
            BAD: "Raise a `ValueError` if `values` is not two-dimensional, if `points` is not of shape `(n+1, 2)` "
                "with one point per column of `values`, if `line` is not three numbers with $(a, b)\\ne(0, 0)$, "
                "or for NaN or infinite values.",
        },
    ),
]

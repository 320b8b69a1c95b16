"""Hidden grading suite of chapter 1: vectors, triangles, rotations and conics.

Every exercise mixes the worked examples of the notes (read from
cagd_course/examples/ch01.toml), hand-picked edge cases, a few inputs that must
be rejected, and random cases drawn from the generator the grader passes in (so
a given seed always yields the same cases). The notes work no conic example, so
the conic suite starts from the standard ones.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import geometry

NOTES = "notes example"
CONICS = "standard conics"
EDGE = "edge cases"
MANY = "several points"
RANDOM = "random"
BAD = "bad input"


def _vec(rng, d, scale=5.0):
    return rng.uniform(-scale, scale, d)


# --- 01.projection -----------------------------------------------------------


def projection_cases(rng):
    example = notes_example("01.projection")
    p, q = example.args("p", "q")
    cases = [
        Case(NOTES, (p, q), visible=True),
        Case(NOTES, (p, example.results["projection"]), visible=True),  # onto the answer: the same answer
        # Parallel, perpendicular, 2-D, a negative multiple, a zero p.
        Case(EDGE, ((2, 4, 6), (1, 2, 3)), visible=True),
        Case(EDGE, ((1, 0, 0), (0, 5, 0)), visible=True),
        Case(EDGE, ((4, 1), (2, 0)), visible=True),
        Case(EDGE, ((1, 1), (-3, -3)), visible=True),
        Case(EDGE, ((0, 0, 0), (1, 2, 3)), visible=True),
        Case(EDGE, (np.array([2.5]), np.array([-0.5])), visible=True),
    ]
    for _ in range(10):
        d = int(rng.integers(2, 6))
        cases.append(Case(RANDOM, (_vec(rng, d), _vec(rng, d))))
    cases += [
        Case(BAD, ((1, 2, 3), (0, 0, 0))),
        Case(BAD, ((1, 2, 3), (1, 2))),
        Case(BAD, ([[1, 2, 3]], [[1, 0, 0]])),
    ]
    return cases


# --- 01.triangle_area --------------------------------------------------------


def triangle_area_cases(rng):
    cases = [
        Case(NOTES, notes_example("01.triangle_area").args("p1", "p2", "p3"), visible=True),
        Case(EDGE, ((0, 0), (4, 0), (0, 3)), visible=True),
        Case(EDGE, ((0, 0), (0, 3), (4, 0)), visible=True),  # clockwise: area stays positive
        Case(EDGE, ((1, 1, 1), (2, 2, 2), (5, 5, 5)), visible=True),  # collinear
        Case(EDGE, ((1, 2), (1, 2), (3, 4)), visible=True),  # two vertices coincide
        Case(EDGE, ((0, 0, 7), (2, 0, 7), (0, 2, 7)), visible=True),
    ]
    for _ in range(6):
        cases.append(Case(RANDOM, tuple(_vec(rng, 2) for _ in range(3))))
    for _ in range(6):
        cases.append(Case(RANDOM, tuple(_vec(rng, 3) for _ in range(3))))
    cases += [
        Case(BAD, ((0, 0), (1, 0, 0), (0, 1, 0))),
        Case(BAD, ((0, 0, 0, 0), (1, 0, 0, 0), (0, 1, 0, 0))),
    ]
    return cases


# --- 01.rotate_about_axis ----------------------------------------------------


def rotate_about_axis_cases(rng):
    example = notes_example("01.rotation")
    point, axis_point, direction, angle = example.args("point", "axis_point", "axis_direction", "angle")
    notes = (point, axis_point, direction)
    cases = [
        Case(NOTES, notes + (angle,), visible=True),
        Case(NOTES, (point, axis_point, example.results["n"], angle), visible=True),  # the notes' unit axis n
        Case(EDGE, notes + (-angle,), visible=True),  # negative angle turns the other way
        Case(EDGE, notes + (0.0,), visible=True),
        Case(EDGE, notes + (2 * np.pi,), visible=True),
        Case(EDGE, notes + (np.pi,), visible=True),
        Case(EDGE, (axis_point + direction, axis_point, direction, 1.0), visible=True),  # point on the axis
        Case(EDGE, ((1, 0, 0), (0, 0, 0), (0, 0, 10), np.pi / 3), visible=True),
        Case(EDGE, ((1, 0, 0), (0, 0, 0), (0, 0, -1), np.pi / 3), visible=True),
        Case(MANY, (np.array([point, axis_point, np.zeros(3)]), axis_point, direction, angle)),
        Case(MANY, (_vec(rng, (6, 3)), _vec(rng, 3), _vec(rng, 3), 0.7)),
        Case(MANY, (_vec(rng, (1, 3)), (0, 0, 0), (1, 1, 1), -2.0)),
    ]
    for _ in range(10):
        angle = float(rng.uniform(-2 * np.pi, 2 * np.pi))
        cases.append(Case(RANDOM, (_vec(rng, 3), _vec(rng, 3), _vec(rng, 3), angle)))
    cases += [
        Case(BAD, (point, axis_point, np.zeros(3), 1.0)),
        Case(BAD, (point[:2], axis_point[:2], direction[:2], 1.0)),
        Case(BAD, (point, axis_point, direction[:2], 1.0)),
    ]
    return cases


# --- 01.rotation_matrix ------------------------------------------------------


def rotation_matrix_cases(rng):
    example = notes_example("01.rotation")
    axis_point, direction, angle = example.args("axis_point", "axis_direction", "angle")
    cases = [
        Case(NOTES, (axis_point, direction, angle), visible=True),
        Case(NOTES, (axis_point, example.results["n"], angle), visible=True),
        Case(EDGE, ((0, 0, 0), (0, 0, 1), np.pi / 2), visible=True),
        Case(EDGE, ((0, 0, 0), (0, 0, 1), -np.pi / 2), visible=True),
        Case(EDGE, ((1, 2, 3), (1, 0, 0), 0.0), visible=True),
        Case(EDGE, ((1, 2, 3), (0, -4, 0), np.pi), visible=True),
        Case(EDGE, ((-2, 0, 5), (1, 1, 0), 2.5), visible=True),
    ]
    for _ in range(10):
        angle = float(rng.uniform(-2 * np.pi, 2 * np.pi))
        cases.append(Case(RANDOM, (_vec(rng, 3), _vec(rng, 3), angle)))
    cases += [
        Case(BAD, (axis_point, np.zeros(3), 1.0)),
        Case(BAD, (axis_point[:2], direction, 1.0)),
    ]
    return cases


# --- 01.conic_type -----------------------------------------------------------


def conic_type_cases(rng):
    cases = [
        Case(CONICS, (1, 0, 1, 0, 0, -1), visible=True),  # unit circle
        Case(CONICS, (0, 1, 0, 0, 0, -1), visible=True),  # xy = 1
        Case(CONICS, (1, 0, 0, 0, -1, 0), visible=True),  # y = x²
        Case(CONICS, (1, 0, -1, 0, 0, -1), visible=True),  # x² - y² = 1
        Case(CONICS, (4, 0, 9, 0, 0, -36), visible=True),  # an ellipse with axes 3 and 2
        # b² = 4ac exactly, with nonzero cross terms, and the sign of the linear terms irrelevant.
        Case(EDGE, (1, 2, 1, 3, -1, 0), visible=True),
        Case(EDGE, (1, -4, 4, 0, 1, 0), visible=True),
        Case(EDGE, (-2, 4, -2, 1, 1, 1), visible=True),
        Case(EDGE, (0, 0, 3, 1, 0, 0), visible=True),
        # b² = 4ac up to rounding: 0.6² - 4·0.1·0.9 is -5.6e-17 in floating point.
        Case(EDGE, (0.1, 0.6, 0.9, 0, 0, -1), visible=True),
        Case(EDGE, (-1, 0, -1, 0, 0, 1), visible=True),  # an ellipse with negated coefficients
        Case(EDGE, (1, 1.5, 1, 0, 0, -1), visible=True),
        Case(EDGE, (1, 2.5, 1, 0, 0, -1), visible=True),
    ]
    for _ in range(12):
        a, b, c, d, e, f = (int(v) for v in rng.integers(-9, 10, 6))
        if a == b == c == 0:
            a = 1
        cases.append(Case(RANDOM, (a, b, c, d, e, f)))
    for _ in range(6):
        # A parabola on purpose: b = 2 sqrt(a c) with a c > 0 and integers.
        r, s = (int(v) for v in rng.integers(1, 6, 2))
        sign = int(rng.choice([-1, 1]))
        cases.append(Case(RANDOM, (sign * r * r, 2 * r * s * int(rng.choice([-1, 1])), sign * s * s, 1, 2, 3)))
    for _ in range(6):
        a, b, c, d, e, f = (float(v) for v in rng.uniform(-3, 3, 6))
        cases.append(Case(RANDOM, (a, b, c, d, e, f)))
    cases += [
        Case(BAD, (0, 0, 0, 1, 1, 1)),
        Case(BAD, (0, 0, 0, 0, 0, 0)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="01.projection",
        reference=geometry.projection,
        cases=projection_cases,
        compare=close(1e-9, 1e-9),
        hint="The result is a vector along q, scaled by (p·q)/(q·q): divide by q·q, not by |q|. "
        "Reject a zero q and vectors of different lengths with a ValueError.",
        rules={
            EDGE: "`p`, `q`: vectors of the same length d (any d >= 1), as arrays, lists or tuples.",
            BAD: "Raise a `ValueError` when `q` is the zero vector (there is no direction to project on) or when "
                "`p` and `q` are not two vectors of the same length.",
        },
    ),
    Exercise(
        id="01.triangle_area",
        reference=geometry.triangle_area,
        cases=triangle_area_cases,
        compare=close(1e-9, 1e-9),
        hint="Take the cross product of two edge vectors that start at the same vertex, e.g. "
        "(p2 - p1) × (p3 - p1), and halve its length. For 2-D points pad with z = 0; an area is never negative.",
        rules={
            EDGE: "Returns a float, never negative (the order of the vertices does not matter). Degenerate "
                "triangles (collinear or repeated vertices) have area 0.",
            BAD: "Raise a `ValueError` when the points do not all have the same dimension, or when it is not 2 or 3.",
        },
    ),
    Exercise(
        id="01.rotate_about_axis",
        reference=geometry.rotate_about_axis,
        cases=rotate_about_axis_cases,
        compare=close(1e-9, 1e-9),
        hint="Normalise the axis direction first, the angle is in radians, and v = n × u (not u × n). "
        "A (k, 3) array of points must give a (k, 3) array back.",
        rules={
            EDGE: "`angle` is in **radians**; a positive angle turns counterclockwise when the axis direction "
                "points at you (right-hand rule), a negative one the other way.",
            MANY: "`point`: one 3-D point of shape `(3,)`, or k points as an array of shape `(k, 3)`; the result "
                "has the same shape as `point`.",
            BAD: "Raise a `ValueError` for a zero axis direction or for vectors that are not 3-D.",
        },
    ),
    Exercise(
        id="01.rotation_matrix",
        reference=geometry.rotation_matrix,
        cases=rotation_matrix_cases,
        compare=close(1e-9, 1e-9),
        hint="Normalise the axis direction. The upper-left 3x3 block rotates about an axis through the origin; "
        "the last column must then move the axis back so that the axis point B stays fixed: T = B - R B.",
        rules={
            EDGE: "Same conventions as exercise 1.3: radians, any nonzero axis length",
            BAD: "`ValueError` for a zero axis direction or vectors that are not 3-D.",
        },
    ),
    Exercise(
        id="01.conic_type",
        reference=geometry.conic_type,
        cases=conic_type_cases,
        compare=exact(),
        hint="Only a, b, c matter: the sign of b² - 4ac (negative: ellipse, zero: parabola, positive: hyperbola). "
        "Treat |b² - 4ac| <= 1e-12 * max(|a|, |b|, |c|)² as zero, and reject a = b = c = 0.",
        rules={
            CONICS: "Return one of the three strings exactly as written.",
            EDGE: "Degenerate conics (a pair of lines, a single point, no real points at all) are still classified "
                "by the sign alone.",
            BAD: "Raise a `ValueError` when $a=b=c=0$ (the equation is then linear, not a conic).",
        },
    ),
]

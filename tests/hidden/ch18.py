"""Hidden grading suite of chapter 18: moving lines, conics from pencils, the Bézout matrix, double points.

Fixed cases come from cagd_course/examples/ch18.toml: the notes' cubic of
Figure 18.11 (its matrix (18.62) and double point (3, 0)), the quartics of
Figures 18.12 and 18.13 (the corrected matrix (18.67) and (18.74)), the
implicit equations of §18.4.6, and the course's examples of §18.2, §18.3 and
§18.5. Edge cases: lines and conics, a cusp (P0 = P1), an acnode, a double
point at infinity, negative weights, moving points of degree 0. Random cases
come from the generator the grader passes in. Moving lines given by a formula
are compared entry by entry; double points and implicit equations, defined
only up to a common factor, after normalising.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, same_up_to_scale
from cagd_ref import bezier, moving_lines

NOTES = "notes examples"
COURSE = "course examples"
EDGE = "edge cases"
RATIONAL = "rational curves"
RANDOM = "random"
BAD = "bad input"

CUBIC = notes_example("18.cubic")
QUARTIC = notes_example("18.quartic")
TRIPLE = notes_example("18.triple_point")
QUARTIC_IMPLICIT = notes_example("18.quartic_implicit")
TWO_PENCILS = notes_example("18.two_pencils")
PRODUCT = notes_example("18.product_line")
TANGENT = notes_example("18.tangent")

CUBIC_POINTS = CUBIC.inputs["points"].tolist()
QUARTIC_POINTS = QUARTIC.inputs["points"].tolist()
TRIPLE_POINTS = TRIPLE.inputs["points"].tolist()
CRUNODE = [(3.0, 3.0), (-13.0, -15.0), (-13.0, 15.0), (3.0, -3.0)]  # x³ + 9x² - 12y², chapter 19
CUSP = [(0.0, 0.0), (0.0, 0.0), (1.0, 0.0), (3.0, 3.0)]  # P0 = P1: a cusp at the origin
ACNODE = [(3.0, 0.0), (3.0, 1.0), (4.0, 2.0), (6.0, 6.0)]  # x³ - 3x² - 3y²: the origin at t = ±i
AT_INFINITY = [(0.0, 0.0), (1 / 3, 0.0), (2 / 3, 0.0), (1.0, 1.0)]  # y = x³: its cusp is the point (0, 1, 0)
CONIC = [(0.0, 0.0), (1.0, 2.0), (3.0, 0.0)]
COLLINEAR = [(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (4.0, 4.0)]
RAISED_CONIC = bezier.elevate(np.array(CONIC)).tolist()
WEIGHTS = [1.0, 2.0, 0.5, 1.5]
PENCIL_0 = [v.tolist() for v in TWO_PENCILS.args("l00", "l01")]
PENCIL_1 = [v.tolist() for v in TWO_PENCILS.args("l10", "l11")]


def _curve(rng, low=2, high=5):
    n = int(rng.integers(low, high + 1))
    points = np.round(rng.uniform(-4, 4, (n + 1, 2)), 3)
    weights = np.round(rng.uniform(0.4, 2.5, n + 1), 3) if rng.uniform() < 0.5 else None
    return points, weights


def _with_weights(points, weights):
    return (points,) if weights is None else (points, weights)


# --- 18.product_moving_line ----------------------------------------------------------------------------------


def product_moving_line_cases(rng):
    p, q = PRODUCT.args("p", "q")
    cases = [
        Case(COURSE, (p.tolist(), q.tolist()), visible=True),
        Case(COURSE, (q.tolist(), p.tolist()), visible=True),  # the other order: every line negated
        Case(COURSE, (PENCIL_0, PENCIL_1), visible=True),  # the two pencils of the course's circle
        Case(EDGE, ([(1.0, 2.0, 1.0)], [(0.0, 0.0, 1.0), (1.0, 1.0, 1.0)]), visible=True),  # a fixed point: degree 1
        Case(EDGE, ([(1.0, 2.0, 1.0)], [(3.0, -1.0, 2.0)]), visible=True),  # two fixed points: one line
        Case(EDGE, ([(0.0, 0.0, 1.0), (1.0, 0.0, 1.0)], [(2.0, 0.0, 1.0), (3.0, 0.0, 1.0)]), visible=True),
        Case(EDGE, ([(1.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(0.0, 1.0, 0.0), (-1.0, 0.0, 1.0)]), visible=True),
    ]
    for _ in range(16):
        m, n = int(rng.integers(0, 4)), int(rng.integers(0, 5))
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, (m + 1, 3)), rng.uniform(-3, 3, (n + 1, 3)))))
    cases += [
        Case(BAD, ([(0.0, 0.0), (1.0, 0.0)], q.tolist())),  # pairs, not triples
        Case(BAD, (p.tolist(), [1.0, 2.0, 3.0])),  # one triple must still be a (1, 3) array
        Case(BAD, (np.zeros((0, 3)), q.tolist())),
        Case(BAD, (p.tolist(), [(0.0, 0.0, 0.0), (0.0, 0.0, 0.0)])),  # no point at all
    ]
    return cases


# --- 18.conic_from_pencils ------------------------------------------------------------------------------------


def _pencils(rng):
    return tuple(rng.uniform(-3, 3, 3) for _ in range(4))


def conic_from_pencils_cases(rng):
    lines = [v.tolist() for v in TWO_PENCILS.args("l00", "l01", "l10", "l11")]
    cases = [
        Case(COURSE, tuple(lines), visible=True),
        Case(COURSE, (lines[2], lines[3], lines[0], lines[1]), visible=True),  # the pencils swapped: P negated
        Case(COURSE, ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 1.0]), visible=True),
        Case(EDGE, ([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, -2.0], [1.0, -1.0, 0.0]), visible=True),
        Case(EDGE, ([1.0, 0.0, -1.0], [0.0, 1.0, -1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]), visible=True),
        Case(EDGE, ([0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0]), visible=True),  # at infinity
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, _pencils(rng)))
    cases += [
        Case(BAD, ([1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, -2.0])),  # l01 = 2 l00
        Case(BAD, ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 2.0], [0.0, -2.0, -4.0])),  # l11 ∥ l10
        Case(BAD, ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [1.0, -1.0, 0.0])),  # one axis: (0, 0)
        Case(BAD, ([1.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, -2.0])),
        Case(BAD, ([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, -2.0])),
    ]
    return cases


# --- 18.bezout_moving_lines -----------------------------------------------------------------------------------


def bezout_moving_lines_cases(rng):
    cases = [
        Case(NOTES, (CUBIC_POINTS,), visible=True),
        Case(NOTES, (QUARTIC_POINTS,), visible=True),
        Case(NOTES, (TRIPLE_POINTS,), visible=True),
        Case(EDGE, ([(0.0, 0.0), (2.0, 1.0)],), visible=True),  # a line: the 1×1 matrix P0 × P1
        Case(EDGE, (CONIC,), visible=True),
        Case(EDGE, (CUSP,), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 3.0), (2.0, -1.0), (4.0, 2.0), (5.0, 0.0), (6.0, 3.0)],), visible=True),
        Case(RATIONAL, (CUBIC_POINTS, WEIGHTS), visible=True),
        Case(RATIONAL, (CONIC, [1.0, -0.5, 2.0]), visible=True),
        Case(RATIONAL, (CUBIC_POINTS,), {"weights": [1.0, 1.0, 1.0, 1.0]}, visible=True),
    ]
    for _ in range(16):
        cases.append(Case(RANDOM, _with_weights(*_curve(rng, 1, 6))))
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),
        Case(BAD, ([(1.0, 2.0)],)),
        Case(BAD, (CUBIC_POINTS, [1.0, 0.0, 1.0, 1.0])),
        Case(BAD, (CUBIC_POINTS, [1.0, 1.0, 1.0])),
    ]
    return cases


# --- 18.cubic_double_point ------------------------------------------------------------------------------------


def _cubic(rng):
    points, weights = _curve(rng, 3, 3)
    return _with_weights(points, weights)


def cubic_double_point_cases(rng):
    cases = [
        Case(NOTES, (CUBIC_POINTS,), visible=True),
        Case(EDGE, (CRUNODE,), visible=True),  # parameters in [0, 1]
        Case(EDGE, (CUSP,), visible=True),
        Case(EDGE, (ACNODE,), visible=True),
        Case(EDGE, (AT_INFINITY,), visible=True),
        Case(EDGE, ([(3.0, 0.0), (1.0, 2.0), (0.0, 1.0), (0.0, 0.0)],), visible=True),  # the notes' cubic reversed
        Case(EDGE, ([(1.0, 0.0), (1.0, 1.0), (2.0, 2.0), (4.0, 1.0)],), visible=True),
        Case(RATIONAL, (CUBIC_POINTS, WEIGHTS), visible=True),
        Case(RATIONAL, (CRUNODE, [1.0, -1.0, 2.0, 1.0]), visible=True),  # a negative weight
        Case(RATIONAL, (CUBIC_POINTS,), {"weights": [2.0, 2.0, 2.0, 2.0]}, visible=True),
    ]
    for _ in range(16):
        cases.append(Case(RANDOM, _cubic(rng)))
    cases += [
        Case(BAD, (CONIC,)),  # not a cubic
        Case(BAD, (QUARTIC_POINTS,)),
        Case(BAD, (COLLINEAR,)),  # a line: the leading lines have rank 1 (a 2-D null space), the rows rank 3
        Case(BAD, ([(0.0, 0.0), (0.0, 0.0), (0.0, 0.0), (3.0, 1.0)],)),  # P0 = P1 = P2: a line again
        Case(BAD, (RAISED_CONIC,)),  # a conic written as a cubic
        Case(BAD, (CUBIC_POINTS, [1.0, 0.0, 1.0, 1.0])),
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0), (2.0, 0.0, 1.0), (3.0, 1.0, 0.0)],)),
    ]
    return cases


# --- 18.moving_line_implicit ----------------------------------------------------------------------------------


def moving_line_implicit_cases(rng):
    cases = [
        Case(NOTES, (CUBIC_POINTS,), visible=True),
        Case(NOTES, (QUARTIC_POINTS,), visible=True),
        Case(NOTES, (TRIPLE_POINTS,), visible=True),
        Case(EDGE, ([(0.0, 1.0), (2.0, 3.0)],), visible=True),  # a line
        Case(EDGE, (CONIC,), visible=True),
        Case(EDGE, (CRUNODE,), visible=True),
        Case(EDGE, (CUSP,), visible=True),
        Case(EDGE, (AT_INFINITY,), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 3.0), (2.0, -1.0), (4.0, 2.0), (5.0, 0.0), (6.0, 3.0)],), visible=True),
        Case(RATIONAL, ([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0]), visible=True),  # a circle
        Case(RATIONAL, (CUBIC_POINTS, WEIGHTS), visible=True),
        Case(RATIONAL, (QUARTIC_POINTS, [1.0, 2.0, -1.0, 0.5, 1.0]), visible=True),
    ]
    for _ in range(16):
        cases.append(Case(RANDOM, _with_weights(*_curve(rng, 2, 5))))
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),
        Case(BAD, ([(1.0, 2.0)],)),
        Case(BAD, (CONIC, [1.0, 0.0, 1.0])),
        Case(BAD, (RAISED_CONIC,)),  # the determinant vanishes identically
    ]
    return cases


# --- 18.tangent_moving_line -----------------------------------------------------------------------------------


def tangent_moving_line_cases(rng):
    cases = [
        Case(COURSE, (TANGENT.inputs["points"].tolist(),), visible=True),
        Case(EDGE, ([(0.0, 0.0), (2.0, 1.0)],), visible=True),  # a line: one control line, 1 · P0 × P1
        Case(EDGE, (CONIC,), visible=True),
        Case(EDGE, (CUSP,), visible=True),
        Case(EDGE, (QUARTIC_POINTS,), visible=True),
        Case(RATIONAL, ([(1.0, 0.0), (1.0, 1.0), (0.0, 1.0)], [1.0, np.sqrt(0.5), 1.0]), visible=True),
        Case(RATIONAL, (CUBIC_POINTS, WEIGHTS), visible=True),
        Case(RATIONAL, (CUBIC_POINTS,), {"weights": [1.0, 1.0, 1.0, 1.0]}, visible=True),
    ]
    for _ in range(16):
        cases.append(Case(RANDOM, _with_weights(*_curve(rng, 1, 5))))
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),
        Case(BAD, ([(1.0, 2.0)],)),
        Case(BAD, (CUBIC_POINTS, [1.0, 1.0, 0.0, 1.0])),
        Case(BAD, (CUBIC_POINTS, [1.0, 1.0])),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="18.product_moving_line",
        reference=moving_lines.product_moving_line,
        cases=product_moving_line_cases,
        compare=close(1e-9, 1e-9),
        hint="L_k = Σ_{i+j=k} C(m,i) C(n,j) P_i × Q_j / C(m+n,k), k = 0..m+n, in the order P × Q. Check that "
        "Σ B_k^(m+n)(t) L_k equals P(t) × Q(t) at a few t.",
        rules={
            EDGE: "Degree 0 ($m=0$ or $n=0$, a fixed point) is allowed.",
            BAD: "Raise a ValueError if p or q is not a 2-D array with 3 columns and at least one row, or has all "
                "entries zero (that is no point and no line).",
        },
    ),
    Exercise(
        id="18.conic_from_pencils",
        reference=moving_lines.conic_from_pencils,
        cases=conic_from_pencils_cases,
        compare=close(1e-9, 1e-9),
        hint="P0 = l00 × l10, P1 = (l00 × l11 + l01 × l10) / 2, P2 = l01 × l11, homogeneous (X, Y, W): the "
        "product of the pencils (1-t) l00 + t l01 and (1-t) l10 + t l11.",
        rules={
            EDGE: "a $W=0$ (a control point at infinity) is a valid answer.",
            BAD: "Raise a ValueError if a line is not 3 numbers or is $(0,0,0)$; if a pencil is a single line",
        },
    ),
    Exercise(
        id="18.bezout_moving_lines",
        reference=moving_lines.bezout_moving_lines,
        cases=bezout_moving_lines_cases,
        compare=close(1e-9, 1e-9),
        hint="L_ij = Σ C(n,k) C(n,i+j+1-k) P_k × P_(i+j+1-k) over k = 0..min(i, j), leaving out i+j+1-k > n, "
        "with homogeneous P_k = w_k (x_k, y_k, 1) and the smaller index first in the cross product.",
        rules={
            EDGE: "For a line ($n=1$) it is the single entry $\\mathbf P_0\\times\\mathbf P_1$.",
            RATIONAL: "`weights`: `None` (a polynomial curve) or `n+1` nonzero numbers, negative ones allowed; a "
                "rational curve is handled through its homogeneous points $w_i(x_i,y_i,1)$.",
            BAD: "Raise a `ValueError` if `points` is not of shape `(n+1, 2)` with $n\\ge1$, or if a weight is zero "
                "or their number is not `n+1`.",
        },
    ),
    Exercise(
        id="18.cubic_double_point",
        reference=moving_lines.cubic_double_point,
        cases=cubic_double_point_cases,
        compare=same_up_to_scale(1e-7),
        hint="Combine the three rows of the 3×3 matrix so that the leading line vanishes (a null vector of the "
        "3×3 matrix of leading lines), drop that zero entry: the pencil left has the double point as its axis, "
        "the cross product of its two lines. Keep it homogeneous: it may be at infinity.",
        rules={
            EDGE: "the double point may be at infinity ($W=0$), as for $y=x^3$.",
            RATIONAL: "`weights`: `None` (a polynomial curve) or 4 nonzero numbers, negative ones allowed; a "
                "rational curve is handled through its homogeneous points $w_i(x_i,y_i,1)$.",
            BAD: "Raise a ValueError unless points has shape (4, 2) and weights is None or 4 nonzero numbers, and "
                "when the curve is not a true cubic",
        },
    ),
    Exercise(
        id="18.moving_line_implicit",
        reference=moving_lines.moving_line_implicit,
        cases=moving_line_implicit_cases,
        compare=same_up_to_scale(1e-7),
        hint="c[i, j] is the coefficient of x^i y^j, shape (n+1, n+1). The resultant of two moving lines, or the "
        "determinant of the n×n matrix of moving lines at (x, y, 1), gives it; scale does not matter.",
        rules={
            EDGE: "For $n=1$ return the line: c[0, 0] = c, c[1, 0] = a, c[0, 1] = b.",
            RATIONAL: "`weights`: `None` (a polynomial curve) or `n+1` nonzero numbers, negative ones allowed; a "
                "rational curve is handled through its homogeneous points $w_i(x_i,y_i,1)$.",
            BAD: "Raise a ValueError if points is not of shape (n+1, 2) with $n\\ge1$, if a weight is zero or their "
                "number is not n+1, and when the equation vanishes identically",
        },
    ),
    Exercise(
        id="18.tangent_moving_line",
        reference=moving_lines.tangent_moving_line,
        cases=tangent_moving_line_cases,
        compare=close(1e-9, 1e-9),
        hint="P × P' = n P_0^(n-1) × P_1^(n-1), the degree-(n-1) curves of P_0..P_(n-1) and P_1..P_n "
        "(homogeneous): the product formula of 18.product_moving_line, times n. It has 2n - 1 control lines, not 2n.",
        rules={
            EDGE: "exactly $n$ times the product's control lines (not rescaled)",
            RATIONAL: "Use the homogeneous points $w_i(x_i,y_i,1)$: for a rational curve the Cartesian points give "
                "another line.",
            BAD: "Raise a `ValueError` if `points` is not of shape `(n+1, 2)` with $n\\ge1$, or if a weight is zero "
                "or their number is not `n+1`.",
        },
    ),
]

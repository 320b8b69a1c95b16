"""Hidden grading suite of chapter 9: roots of polynomials in Bernstein form, and what builds them.

Fixed cases reuse the worked examples kept in cagd_course/examples/ch09.toml
(the product <1, 2><3, 4, 5>, the roots 2.5, 3, 4.75 on [2, 5], the deflation
of <0, 1, -1, 2>, the hull-marching quartic, the linear polynomial that trips
the notes' sign rule, the line ∩ rational quartic) and ch07.toml (E7.5 in
Bernstein form, with its root at t = 1; the rational quartic of §7.7.8). Edge
cases probe roots at the ends of the interval, constants, roots outside the
interval, columns of coefficients and Wilkinson-type roots, where a detour
through the power basis loses its accuracy; random cases come from the
generator the grader passes in. Roots inside the interval are simple except
at its ends.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import polynomials, roots

NOTES = "notes example"
EDGE = "edge cases"
ENDS = "roots at the ends"
COLUMNS = "columns of coefficients"
WILKINSON = "Wilkinson-type roots"
RANDOM = "random"
BAD = "bad input"

PRODUCT = notes_example("09.product")
FROM_ROOTS = notes_example("09.from_roots")
DEFLATION = notes_example("09.deflation")
MARCHING = notes_example("09.hull_marching")
PITFALL = notes_example("09.pitfall")
LINE_CURVE = notes_example("09.line_curve")
CIRCLE_CURVE = notes_example("07.circle_curve").results["bernstein"]  # E7.5: roots 0.0612, 0.2815, 0.9073, 1
QUARTIC = notes_example(LINE_CURVE.inputs["curve"])  # the rational quartic of §7.7.8


def _separated(rng, count, low=0.03, high=0.97, gap=0.04):
    """`count` sorted numbers in [low, high], at least `gap` apart."""
    while True:
        values = np.sort(rng.uniform(low, high, count))
        if count < 2 or np.diff(values).min() > gap:
            return values


def _polynomial(rng, inside=(1, 5), outside=(0, 3)):
    """Bernstein coefficients on [0, 1] of a polynomial with well-separated simple roots, some outside [0, 1]."""
    inner = _separated(rng, int(rng.integers(*inside)))
    outer = rng.uniform(1.3, 3.0, int(rng.integers(*outside))) * rng.choice([-1.0, 1.0])
    leading = float(rng.uniform(0.5, 4.0) * rng.choice([-1.0, 1.0]))
    return roots.bernstein_from_roots(np.concatenate([inner, outer]), leading=leading)


# --- 09.bernstein_multiply -------------------------------------------------------------------------------


def bernstein_multiply_cases(rng):
    cases = [
        Case(NOTES, PRODUCT.args("f", "g"), visible=True),
        Case(NOTES, PRODUCT.args("g", "f"), visible=True),  # the product commutes
        Case(EDGE, ([2.0], [1.0, -1.0, 3.0]), visible=True),  # a constant factor scales the coefficients
        Case(EDGE, ([1.0, 4.0, 2.0], [-0.5]), visible=True),
        Case(EDGE, ([3.0], [4.0]), visible=True),
        Case(EDGE, ([0.0, 1.0], [1.0, 0.0]), visible=True),  # t (1 - t) = <0, 1/2, 0>
        Case(EDGE, ([1.0, 1.0, 1.0, 1.0], [2.0, 2.0]), visible=True),  # 1 · 2 in any degree
        Case(COLUMNS, ([[1.0, 0.0], [2.0, 1.0]], [[3.0, 1.0], [4.0, 1.0], [5.0, 1.0]]), visible=True),
        Case(COLUMNS, ([[1.0, 2.0, 3.0]], [[0.0, 1.0, 2.0], [1.0, 1.0, 1.0]]), visible=True),
    ]
    for _ in range(12):
        m, n = (int(k) for k in rng.integers(0, 7, 2))
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, m + 1), rng.uniform(-3, 3, n + 1))))
    for _ in range(4):
        m, n, d = int(rng.integers(0, 5)), int(rng.integers(0, 5)), int(rng.integers(1, 4))
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, (m + 1, d)), rng.uniform(-3, 3, (n + 1, d)))))
    cases += [
        Case(BAD, ([[1.0, 2.0], [3.0, 4.0]], [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])),  # different column counts
        Case(BAD, ([1.0, 2.0], [[1.0, 2.0], [3.0, 4.0]])),  # one vector, one table
        Case(BAD, ([], [1.0, 2.0])),
        Case(BAD, ([1.0, 2.0], np.ones((2, 2, 2)))),
    ]
    return cases


# --- 09.bernstein_from_roots ------------------------------------------------------------------------------


def bernstein_from_roots_cases(rng):
    cases = [
        Case(NOTES, FROM_ROOTS.args("roots", "interval"), visible=True),
        Case(NOTES, (FROM_ROOTS.inputs["roots"],), {"interval": (2.0, 5.0), "leading": -2.0}, visible=True),
        Case(EDGE, ([0.25, 0.75],), visible=True),  # on [0, 1]: <-1/4, 3/4><-3/4, 1/4>
        Case(EDGE, ([],), {"leading": 2.5}, visible=True),  # no roots: the constant
        Case(EDGE, ([1.5, -2.0],), visible=True),  # roots outside the interval
        Case(EDGE, ([0.4, 0.4, 0.4],), visible=True),  # a triple root
        Case(EDGE, ([0.0, 1.0],), {"interval": (-1.0, 1.0)}, visible=True),
        Case(EDGE, ([3.0],), {"interval": (2.0, 4.0), "leading": 0.5}, visible=True),
    ]
    for _ in range(14):
        t0 = float(rng.uniform(-2, 1))
        interval = (t0, t0 + float(rng.uniform(0.5, 3)))
        rs = rng.uniform(-3, 3, int(rng.integers(0, 7)))
        cases.append(Case(RANDOM, (rs,), {"interval": interval, "leading": float(rng.uniform(-4, 4))}))
    cases += [
        Case(BAD, ([[0.2, 0.4]],)),  # a table of roots
        Case(BAD, ([0.2],), {"interval": (1.0, 0.0)}),
        Case(BAD, ([0.2],), {"interval": (0.0, 1.0, 2.0)}),
    ]
    return cases


# --- 09.deflate ------------------------------------------------------------------------------------------------


def deflate_cases(rng):
    cases = [
        Case(NOTES, DEFLATION.args("coeffs"), visible=True),
        Case(EDGE, ([0.0, 2.5],), visible=True),  # degree 1: <0, a> = t · a
        Case(EDGE, ([0.0, 0.0, 0.0],), visible=True),  # 0 = t · 0
        Case(EDGE, ([0.0, 0.0, 1.0],), visible=True),  # t² = t · t: g = <0, 1>, still divisible by t
        Case(EDGE, ([1e-17, 1.0, 1.0],), visible=True),  # y_0 zero to rounding is accepted
        Case(EDGE, ([0.0, -1.0, 2.0, -3.0, 4.0, -5.0, 6.0, -7.0],), visible=True),
    ]
    for _ in range(12):
        n = int(rng.integers(1, 9))
        cases.append(Case(RANDOM, (np.concatenate([[0.0], rng.uniform(-5, 5, n)]),)))
    cases += [
        Case(BAD, ([0.5, 1.0, 2.0],)),  # f(0) = 0.5: t does not divide f
        Case(BAD, ([1e-6, 1.0],)),
        Case(BAD, ([0.0],)),  # a constant
        Case(BAD, ([[0.0, 1.0], [1.0, 2.0]],)),
        Case(BAD, ([],)),
    ]
    return cases


# --- 09.hull_march -----------------------------------------------------------------------------------------------


def _marchable(rng):
    """A random polynomial whose march converges in a modest number of steps per root (the march is linear)."""
    while True:
        coeffs = _polynomial(rng)
        steps = roots.hull_march_steps(coeffs, max_steps=1500)
        if steps[-1].event == "end":
            return coeffs


def hull_march_cases(rng):
    cases = [
        Case(NOTES, MARCHING.args("coeffs"), visible=True),
        Case(NOTES, PITFALL.args("coeffs"), visible=True),  # the first step lands on the root
        Case(NOTES, (CIRCLE_CURVE,), visible=True),
        Case(NOTES, (FROM_ROOTS.results["coeffs"],), {"interval": tuple(FROM_ROOTS.inputs["interval"])}, visible=True),
        Case(EDGE, ([-0.87, 0.51],), visible=True),
        Case(EDGE, ([1.0, -1.0, 2.0, -3.0],), visible=True),  # a march to the polygon jumps the root 0.596 (to 0.8)
        Case(EDGE, ([1.0, 2.0, 3.0],), visible=True),  # no root
        Case(EDGE, ([3.0],), visible=True),  # a constant
        Case(EDGE, ([2.0, -1.0, -1.0, 2.0],), {"interval": (-1.0, 1.0)}, visible=True),
        Case(ENDS, ([0.0, 1.0, -1.0, 0.0],), visible=True),  # roots at 0, 1/2 and 1
        Case(ENDS, ([0.0, 0.0, 1.0],), visible=True),  # t² : the root 0 twice
        Case(ENDS, ([1.0, 0.0, 0.0],), visible=True),  # (1 - t)²: the root 1 twice
        Case(ENDS, ([0.0, -2.0, 1.0, 3.0],), visible=True),
        Case(ENDS, ([-1.0, 2.0, 0.0],), {"interval": (3.0, 5.0)}, visible=True),
    ]
    for _ in range(16):
        cases.append(Case(RANDOM, (_marchable(rng),)))
    for _ in range(4):
        t0 = float(rng.uniform(-3, 3))
        cases.append(Case(RANDOM, (_marchable(rng),), {"interval": (t0, t0 + float(rng.uniform(0.5, 4)))}))
    cases += [
        Case(BAD, ([0.0, 0.0, 0.0],)),  # the zero polynomial
        Case(BAD, ([1.0, -1.0],), {"interval": (1.0, 0.0)}),
        Case(BAD, ([1.0, -1.0],), {"tol": 0.0}),
        Case(BAD, ([[1.0, -1.0]],)),
    ]
    return cases


# --- 09.bernstein_roots ----------------------------------------------------------------------------------------------


def bernstein_roots_cases(rng):
    cases = [
        Case(NOTES, (CIRCLE_CURVE,), visible=True),
        Case(NOTES, MARCHING.args("coeffs"), visible=True),
        Case(NOTES, (FROM_ROOTS.results["coeffs"],), {"interval": tuple(FROM_ROOTS.inputs["interval"])}, visible=True),
        Case(EDGE, ([1.0, -1.0],), visible=True),
        Case(EDGE, ([1.0, 2.0, 3.0],), visible=True),
        Case(EDGE, ([-3.0],), visible=True),
        Case(EDGE, ([1.0, -1.0, 2.0, -3.0],), {"tol": 1e-10}, visible=True),
        Case(EDGE, ([2.0, -1.0, -1.0, 2.0],), {"interval": (-1.0, 1.0)}, visible=True),
        Case(ENDS, ([0.0, 1.0, 2.0],), visible=True),
        Case(ENDS, ([2.0, 1.0, 0.0],), visible=True),
        Case(ENDS, ([0.0, 1.0, -1.0, 0.0],), visible=True),
        Case(ENDS, ([0.0, 0.0, 1.0],), visible=True),  # a double root at 0 is one root
    ]
    for degree in (10, 15, 20):
        bernstein, _, _ = roots.wilkinson_polynomial(degree)
        cases.append(Case(WILKINSON, (bernstein,), visible=True))
    bernstein, _, _ = roots.wilkinson_polynomial(12)
    cases.append(Case(WILKINSON, (bernstein,), {"interval": (1.0, 3.0)}, visible=True))
    for _ in range(16):
        cases.append(Case(RANDOM, (_polynomial(rng, inside=(0, 7)),)))
    for _ in range(4):
        t0 = float(rng.uniform(-3, 3))
        cases.append(Case(RANDOM, (_polynomial(rng),), {"interval": (t0, t0 + float(rng.uniform(0.5, 4)))}))
    cases += [
        Case(BAD, ([0.0, 0.0, 0.0],)),
        Case(BAD, ([1.0, -1.0],), {"interval": (2.0, 2.0)}),
        Case(BAD, ([1.0, -1.0],), {"tol": 1.5}),
        Case(BAD, ([[1.0], [-1.0]],)),
    ]
    return cases


# --- 09.line_curve_intersection ------------------------------------------------------------------------------------


def line_curve_intersection_cases(rng):
    points, weights = QUARTIC.args("points", "weights")
    lmin, lmax = LINE_CURVE.inputs["lines"]
    cubic = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.0), (4.0, 0.0)]
    cases = [
        Case(NOTES, (points, lmin), {"weights": weights}, visible=True),
        Case(NOTES, (points, lmax), {"weights": weights}, visible=True),
        Case(NOTES, (points, lmin), visible=True),  # the same control points without weights
        Case(EDGE, (cubic, (0.0, 1.0, -1.0)), visible=True),  # two crossings
        Case(EDGE, (cubic, (0.0, 1.0, -2.0)), visible=True),  # above the curve: none
        Case(EDGE, (cubic, (1.0, 0.0, 0.0)), visible=True),  # through the first end point
        Case(EDGE, (cubic, (0.0, 1.0, 0.0)), visible=True),  # the chord: both end points
        Case(EDGE, (cubic, (1.0, -1.0, 0.5)), {"weights": [1.0, 2.0, 0.5, 1.0]}, visible=True),
        Case(EDGE, ([(0.0, 0.0), (2.0, 2.0)], (1.0, 1.0, -2.0)), visible=True),  # a segment
    ]
    for _ in range(14):
        n = int(rng.integers(1, 6))
        pts = rng.uniform(-5, 5, (n + 1, 2))
        w = rng.uniform(0.3, 3.0, n + 1) if rng.uniform() < 0.6 else None
        centre = pts.mean(axis=0)
        normal = rng.normal(size=2)
        line = (float(normal[0]), float(normal[1]), float(-normal @ centre + rng.uniform(-1, 1)))
        cases.append(Case(RANDOM, (pts, line), {"weights": w}))
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], (1.0, 1.0, 1.0))),  # points in space
        Case(BAD, (cubic, (0.0, 0.0, 1.0))),  # not a line
        Case(BAD, (cubic, (1.0, 1.0))),
        Case(BAD, (cubic, (0.0, 1.0, -1.0)), {"weights": [1.0, 0.0, 1.0, 1.0]}),
        Case(BAD, (cubic, (0.0, 1.0, -1.0)), {"weights": [1.0, 1.0]}),
        Case(BAD, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0)], (1.0, -1.0, 0.0))),  # the curve lies on the line
    ]
    return cases


EXERCISES = [
    Exercise(
        id="09.bernstein_multiply",
        reference=polynomials.bernstein_multiply,
        cases=bernstein_multiply_cases,
        compare=close(1e-10, 1e-12),
        hint="h_k = Σ_(i+j=k) C(m, i) C(n, j) f_i g_j / C(m+n, k), k = 0 .. m+n: scale f and g by their binomials, "
        "convolve, divide by C(m+n, k). Tables (m+1, d) and (n+1, d) multiply column by column.",
        rules={
            EDGE: "`f`: shape `(m+1,)`, `g`: shape `(n+1,)`, any degrees $m,n\\ge0$: return shape `(m+n+1,)`.",
            COLUMNS: "Tables of coefficients multiply column by column",
            BAD: "Raise a `ValueError` when one argument is a vector and the other a table, when two tables have "
                "different numbers of columns, and for empty or three-dimensional arrays.",
        },
    ),
    Exercise(
        id="09.bernstein_from_roots",
        reference=roots.bernstein_from_roots,
        cases=bernstein_from_roots_cases,
        compare=close(1e-9, 1e-9),
        hint="On [a, b] the factor t - r has the Bernstein coefficients <a - r, b - r>: start from <leading> "
        "and multiply by one factor after another with the product formula (exercise 9.1).",
        rules={
            EDGE: "`roots`: shape `(k,)`, any real numbers (inside the interval or not, repeated or not); `k = 0` "
                "is allowed and gives the constant `[leading]`.",
            BAD: "Raise a `ValueError` when `roots` is not one-dimensional or `interval` is not a pair $(a,b)$ "
                "with $a<b$.",
        },
    ),
    Exercise(
        id="09.deflate",
        reference=roots.deflate,
        cases=deflate_cases,
        compare=close(1e-12, 1e-12),
        hint="g_i = n y_(i+1) / (i + 1) for i = 0 .. n-1 (n = degree of f), after checking |y_0| <= 1e-12 max|y|; "
        "a constant has nothing to deflate.",
        rules={
            EDGE: "$y_0$ counts as zero when $|y_0|\\le10^{-12}\\max_i|y_i|$ (zero to rounding; it is then simply "
                "dropped).",
            BAD: "Otherwise $t$ does not divide $f$: raise a `ValueError`. Also raise one for a constant (`n = 0`) "
                "and for input that is not one-dimensional.",
        },
    ),
    Exercise(
        id="09.hull_march",
        reference=roots.hull_march,
        cases=hull_march_cases,
        compare=close(0.0, 1e-9),
        hint="Divide out roots at the right end first (y_n = 0: g_i = n y_i / (n - i)). Then from t_0 = 0: if y_0 "
        "is zero to rounding, record t_k and deflate; else c = the leftmost crossing of the hull of (i/n, y_i) with "
        "the axis (all pairs of points on opposite sides, not just neighbours), t_(k+1) = t_k + (1 - t_k) c, split "
        "at c and keep the right part; a step <= tol, a value zero to rounding or a sign change is a root at "
        "t_(k+1) (deflate it). Map the roots from [0, 1] to [a, b] at the end.",
        rules={
            EDGE: "The tests use polynomials whose roots inside the interval are simple and well separated",
            ENDS: "one per deflation, so a double root at an end comes back twice.",
            BAD: "Raise a `ValueError` for coefficients that are not a non-empty one-dimensional array, for the "
                "zero polynomial (all coefficients 0), for an interval without $a<b$ and for `tol` outside "
                "$(0,1)$.",
        },
    ),
    Exercise(
        id="09.bernstein_roots",
        reference=roots.bernstein_roots,
        cases=bernstein_roots_cases,
        compare=close(0.0, 1e-8),
        hint="Stay in the Bernstein basis (Wilkinson-type roots defeat the power basis): subdivide, drop pieces "
        "whose coefficients all have one sign, refine pieces with one sign change by bisection or Newton, and "
        "return each root once, sorted, mapped to the interval.",
        rules={
            EDGE: "Return the roots as a sorted array `(k,)`, possibly empty, **each root once**",
            ENDS: "a coefficient $y_0=0$ or $y_n=0$ is a root at $a$ or $b$ (even when the other half of the "
                "search finds it too, and even when it is a double root, as for $\\langle0,0,1\\rangle$).",
            WILKINSON: "the tests include the Wilkinson-type polynomial",
            BAD: "Raise a `ValueError` for coefficients that are not a non-empty one-dimensional array, for the "
                "zero polynomial, for an interval without $a<b$ and for `tol` outside $(0,1)$.",
        },
    ),
    Exercise(
        id="09.line_curve_intersection",
        reference=roots.line_curve_intersection,
        cases=line_curve_intersection_cases,
        compare=close(1e-9, 1e-9),
        hint="f_i = w_i (a x_i + b y_i + c), the line dotted with the homogeneous control point; its roots in "
        "[0, 1] are the parameters, and the points are the (rational) curve evaluated there: (ts (k,), pts (k, 2)).",
        rules={
            EDGE: "with no intersection shapes `(0,)` and `(0, 2)`.",
            BAD: "Raise a `ValueError` for points that are not planar `(n+1, 2)`, a line that is not three numbers "
                "or has $a=b=0$, weights of the wrong length or with a zero, and a curve that lies on the line "
                "($f\\equiv0$).",
        },
    ),
]

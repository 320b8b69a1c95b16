"""Hidden grading suite of chapter 2: Bernstein polynomials and Bézier curves.

Fixed cases take the worked examples from cagd_course/examples/ch02.toml (the
cubic of the notes' hodograph table, the quarter circle, the curvature formula
at an end point, the quadratic split at τ = 2); edge cases probe degree 0 and 1,
coincident control points, t at the ends and outside [0, 1], and a scalar t
against an array of them; the random cases come from the generator the grader
passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import bezier, polynomials

NOTES = "notes example"
COURSE = "course example"
EDGE = "edge cases"
SHAPES = "scalar vs array t"
RANDOM = "random"
BAD = "bad input"

# The notes' examples, as lists of tuples: students must accept those as well as arrays.
TABLE = notes_example("02.hodograph_table")
CUBIC = [tuple(point) for point in TABLE.inputs["points"].tolist()]  # the cubic of the hodograph table
TABLE_INTERVAL = tuple(TABLE.inputs["interval"].tolist())  # it lives on [0, 1/2]
CIRCLE = notes_example("02.quarter_circle")
QUARTER = [tuple(point) for point in CIRCLE.results["points"].tolist()]  # a quarter of the unit circle ...
QUARTER_W = CIRCLE.results["weights"].tolist()  # ... with weights (1, 1/√2, 1)
ENDPOINT = notes_example("02.endpoint_curvature")  # κ(0) = 2/25 by (2.13)
BEYOND = notes_example("02.split_beyond")  # a quadratic split at τ = 2
RATIONAL = notes_example("03.rational_cubic")  # chapter 3's rational cubic, points and weights
SPACE = [(0.0, 0.0, 0.0), (1.0, 2.0, 0.5), (3.0, -1.0, 2.0), (4.0, 1.0, -1.0)]


def _points(rng, low_degree=1, high_degree=7, dims=(1, 2, 3)):
    n = int(rng.integers(low_degree, high_degree + 1))
    d = int(rng.choice(dims))
    return rng.uniform(-10, 10, (n + 1, d))


def _ts(rng, k=None, low=0.0, high=1.0):
    k = int(rng.integers(1, 8)) if k is None else k
    return np.sort(rng.uniform(low, high, k))


def _weights(rng, count):
    return rng.uniform(0.2, 5.0, count)


# --- 02.bernstein ------------------------------------------------------------


def bernstein_cases(rng):
    cases = [
        Case(NOTES, (1, 3, 0.5), visible=True),  # 3 t (1-t)² at 1/2, the notes' B_1^3
        Case(NOTES, (2, 3, 0.25), visible=True),
        Case(NOTES, (0, 3, [0.0, 0.25, 0.5, 0.75, 1.0]), visible=True),
        Case(EDGE, (0, 0, 0.3), visible=True),  # the only degree-0 polynomial is 1
        Case(EDGE, (0, 4, 0.0), visible=True),
        Case(EDGE, (4, 4, 0.0), visible=True),
        Case(EDGE, (0, 4, 1.0), visible=True),
        Case(EDGE, (4, 4, 1.0), visible=True),
        Case(EDGE, (1, 1, 2.0), visible=True),  # outside [0, 1] the formula still applies
        Case(EDGE, (2, 5, -0.5), visible=True),
        Case(SHAPES, (2, 4, np.array([0.5]))),
        Case(SHAPES, (2, 4, np.array(0.5))),
        Case(SHAPES, (3, 6, np.linspace(0, 1, 9))),
        Case(SHAPES, (0, 0, np.linspace(0, 1, 3))),
        Case(SHAPES, (1, 2, [])),
    ]
    for _ in range(12):
        n = int(rng.integers(0, 11))
        i = int(rng.integers(0, n + 1))
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (i, n, t)))
    cases += [
        Case(BAD, (4, 3, 0.5)),
        Case(BAD, (-1, 3, 0.5)),
        Case(BAD, (1, 3, [[0.1, 0.2]])),
    ]
    return cases


# --- 02.de_casteljau ---------------------------------------------------------


def de_casteljau_cases(rng):
    cases = [
        Case(NOTES, (CUBIC, 0.5), visible=True),
        Case(NOTES, (CUBIC, [0.0, 0.25, 0.5, 0.75, 1.0]), visible=True),
        Case(EDGE, ([(3.0, -1.0)], 0.7), visible=True),  # degree 0: a single point
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)], 0.25), visible=True),
        Case(EDGE, (CUBIC, 0.0), visible=True),
        Case(EDGE, (CUBIC, 1.0), visible=True),
        Case(EDGE, (CUBIC, 2.0), visible=True),  # extrapolation beyond t = 1
        Case(EDGE, (CUBIC, -0.5), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)], 0.3), visible=True),
        Case(EDGE, ([(0.0, 0.0), (0.0, 0.0), (3.0, 3.0), (3.0, 3.0)], 0.5), visible=True),
        Case(EDGE, (SPACE, 0.4), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0]], 0.5), visible=True),
        Case(SHAPES, (CUBIC, np.array([0.5]))),
        Case(SHAPES, (CUBIC, np.array(0.5))),
        Case(SHAPES, ([(3.0, -1.0)], [0.0, 0.5, 1.0])),
        Case(SHAPES, (SPACE, np.linspace(-0.5, 1.5, 5))),
    ]
    for _ in range(14):
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (_points(rng), t)))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0], 0.5)),
        Case(BAD, (CUBIC, [[0.1, 0.2]])),
    ]
    return cases


# --- 02.subdivide ------------------------------------------------------------


def subdivide_cases(rng):
    cases = [
        Case(NOTES, (CUBIC, 0.5), visible=True),
        Case(NOTES, (BEYOND.inputs["points"].tolist(), float(BEYOND.inputs["t"])), visible=True),  # τ = 2
        Case(EDGE, (CUBIC, 0.0), visible=True),
        Case(EDGE, (CUBIC, 1.0), visible=True),
        Case(EDGE, (CUBIC, -1.0), visible=True),
        Case(EDGE, ([(3.0, -1.0)], 0.4), visible=True),
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)], 0.25), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (2.0, 0.0), (2.0, 0.0)], 0.3), visible=True),
        Case(EDGE, (SPACE, 0.6), visible=True),
        Case(EDGE, ([[0.0], [1.0], [5.0], [2.0], [3.0]], 0.3), visible=True),
    ]
    for _ in range(14):
        low, high = (-0.5, 1.5) if rng.uniform() < 0.25 else (0.0, 1.0)
        cases.append(Case(RANDOM, (_points(rng), float(rng.uniform(low, high)))))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0], 0.5)),
        Case(BAD, (CUBIC, [0.2, 0.5])),
    ]
    return cases


# --- 02.elevate --------------------------------------------------------------


def elevate_cases(rng):
    cases = [
        Case(NOTES, (CUBIC,), visible=True),  # P*_1 = P0/4 + 3 P1/4, ...
        Case(EDGE, ([(0.0, 0.0), (0.0, 4.0), (4.0, 4.0), (4.0, 0.0)],), visible=True),
        Case(EDGE, ([(3.0, -1.0)],), visible=True),  # degree 0 -> a segment with equal ends
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)],), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (1.0, 1.0)],), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0]],), visible=True),
        Case(EDGE, (SPACE,), visible=True),
        Case(EDGE, (bezier.elevate(CUBIC),), visible=True),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (_points(rng),)))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0],)),
        Case(BAD, (np.zeros((0, 2)),)),
    ]
    return cases


# --- 02.hodograph ------------------------------------------------------------


def hodograph_cases(rng):
    cases = [
        # The table of §2.7, row by row: the curve lives on [0, 1/2].
        Case(NOTES, (CUBIC, TABLE_INTERVAL), visible=True),
        Case(NOTES, (TABLE.results["first"].tolist(), TABLE_INTERVAL), visible=True),
        Case(NOTES, (TABLE.results["second"].tolist(), TABLE_INTERVAL), visible=True),
        Case(NOTES, (CUBIC,), visible=True),
        Case(EDGE, (CUBIC, (0, 1)), visible=True),
        Case(EDGE, ([(3.0, -1.0)],), visible=True),  # degree 0: the zero curve, one zero point
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)], (1, 3)), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (2.0, 0.0)],), visible=True),
        Case(EDGE, (SPACE, (-1, 1)), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0]], (5, 9)), visible=True),
    ]
    for _ in range(14):
        t0 = float(rng.uniform(-3, 3))
        t1 = t0 + float(rng.uniform(0.1, 4))
        args = (_points(rng),) if rng.uniform() < 0.3 else (_points(rng), (t0, t1))
        cases.append(Case(RANDOM, args))
    cases += [
        Case(BAD, ([1.0, 2.0, 3.0],)),
        Case(BAD, (CUBIC, (1, 0))),
        Case(BAD, (CUBIC, (0.5, 0.5))),
    ]
    return cases


# --- 02.to_homogeneous / 02.from_homogeneous ---------------------------------


def to_homogeneous_cases(rng):
    cases = [
        Case(NOTES, (QUARTER, QUARTER_W), visible=True),
        Case(NOTES, (ENDPOINT.inputs["points"].tolist(), ENDPOINT.inputs["weights"].tolist()), visible=True),
        Case(NOTES, (RATIONAL.results["points"].tolist(), RATIONAL.results["weights"].tolist()), visible=True),
        Case(EDGE, ([(3.0, -1.0)], [2.0]), visible=True),
        Case(EDGE, (CUBIC, [1.0, 1.0, 1.0, 1.0]), visible=True),
        Case(EDGE, ([[1.0], [5.0], [2.0]], [0.5, 1.0, 3.0]), visible=True),
        Case(EDGE, (SPACE, [1.0, -1.0, 1.0, -1.0]), visible=True),  # negative weights are allowed
    ]
    for _ in range(12):
        pts = _points(rng, 0)
        cases.append(Case(RANDOM, (pts, _weights(rng, len(pts)))))
    cases += [
        Case(BAD, (CUBIC, [1.0, 0.0, 1.0, 1.0])),
        Case(BAD, (CUBIC, [1.0, 1.0, 1.0])),
        Case(BAD, ([1.0, 2.0, 3.0], [1.0, 1.0, 1.0])),
    ]
    return cases


def from_homogeneous_cases(rng):
    cases = [
        Case(NOTES, (bezier.to_homogeneous(QUARTER, QUARTER_W),), visible=True),
        Case(NOTES, (bezier.to_homogeneous(*ENDPOINT.args("points", "weights")).tolist(),), visible=True),
        Case(NOTES, (RATIONAL.results["bernstein"].tolist(),), visible=True),  # the top row of chapter 3's table
        Case(EDGE, ([(6.0, -2.0, 2.0)],), visible=True),
        Case(EDGE, ([(2.0, 1.0, 1.0), (4.0, 5.0, 1.0)],), visible=True),
        Case(EDGE, ([(1.0, 2.0), (5.0, 0.5)],), visible=True),  # 1-D points
        Case(EDGE, ([(1.0, 2.0, 3.0, -1.0), (2.0, 0.0, 1.0, 0.5)],), visible=True),
    ]
    for _ in range(12):
        pts = _points(rng, 0)
        cases.append(Case(RANDOM, (bezier.to_homogeneous(pts, _weights(rng, len(pts))),)))
    cases += [
        Case(BAD, ([(1.0, 2.0, 0.0), (2.0, 3.0, 1.0)],)),
        Case(BAD, ([1.0, 2.0, 1.0],)),
        Case(BAD, ([(1.0,), (2.0,)],)),
    ]
    return cases


# --- 02.evaluate -------------------------------------------------------------


def evaluate_cases(rng):
    cases = [
        Case(NOTES, (CUBIC, 0.5), visible=True),
        Case(NOTES, (QUARTER, 0.5, QUARTER_W), visible=True),  # (√2/2, √2/2)
        Case(NOTES, (QUARTER, [0.0, 0.25, 0.5, 0.75, 1.0]), {"weights": QUARTER_W}, visible=True),
        Case(EDGE, ([(3.0, -1.0)], 0.7), visible=True),
        Case(EDGE, ([(3.0, -1.0)], 0.7, [2.5]), visible=True),
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)], 0.25, [1.0, 3.0]), visible=True),
        Case(EDGE, (CUBIC, 0.0, [1.0, 2.0, 3.0, 4.0]), visible=True),
        Case(EDGE, (CUBIC, 1.0, [1.0, 2.0, 3.0, 4.0]), visible=True),
        Case(EDGE, (CUBIC, 0.3, [2.0, 2.0, 2.0, 2.0]), visible=True),  # equal weights: the polynomial curve
        Case(EDGE, (CUBIC, 0.3), {"weights": None}, visible=True),
        Case(EDGE, (CUBIC, 1.5), visible=True),
        Case(EDGE, (SPACE, 0.4, [1.0, 0.5, 2.0, 1.0]), visible=True),
        Case(EDGE, ([(1.0, 1.0), (1.0, 1.0), (2.0, 0.0)], 0.5, [1.0, 3.0, 1.0]), visible=True),
        Case(SHAPES, (CUBIC, np.array([0.5]))),
        Case(SHAPES, (CUBIC, np.array([0.5]), [1.0, 2.0, 3.0, 4.0])),
        Case(SHAPES, (QUARTER, np.array(0.25), QUARTER_W)),
        Case(SHAPES, ([(3.0, -1.0)], [0.0, 0.5, 1.0], [4.0])),
    ]
    for _ in range(8):
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (_points(rng), t)))
    for _ in range(10):
        pts = _points(rng)
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (pts, t, _weights(rng, len(pts)))))
    cases += [
        Case(BAD, (CUBIC, 0.5, [1.0, 0.0, 1.0, 1.0])),
        Case(BAD, (CUBIC, 0.5, [1.0, 1.0, 1.0])),
        Case(BAD, ([1.0, 2.0, 3.0], 0.5)),
    ]
    return cases


# --- 02.curvature ------------------------------------------------------------


def curvature_cases(rng):
    cases = [
        Case(NOTES, (QUARTER, 0.5, QUARTER_W), visible=True),  # a unit circle: curvature 1
        Case(NOTES, (QUARTER, [0.0, 0.3, 1.0]), {"weights": QUARTER_W}, visible=True),
        # The end-point formula (2.13) with w = (1, 2, 4), a = 5, h = 4 gives 2/25.
        Case(NOTES, (ENDPOINT.inputs["points"].tolist(), 0.0, ENDPOINT.inputs["weights"].tolist()), visible=True),
        Case(EDGE, ([(0.0, 0.0), (4.0, 2.0)], 0.3), visible=True),  # a line: curvature 0
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (5.0, 5.0)], 0.6), visible=True),
        Case(EDGE, ([(3.0, 0.0), (3.0, 3.0), (0.0, 3.0)], 0.5, [1.0, np.sqrt(0.5), 1.0]), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)], [0.0, 0.5, 1.0]), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, -2.0), (2.0, 0.0)], [0.0, 0.5, 1.0]), visible=True),  # turns the other way
        Case(EDGE, (CUBIC, 1.0), visible=True),
        Case(EDGE, (SPACE, 0.4), visible=True),
        Case(EDGE, (SPACE, 0.4, [1.0, 3.0, 0.5, 2.0]), visible=True),
        Case(SHAPES, (CUBIC, np.array([0.5]))),
        Case(SHAPES, (CUBIC, np.array(0.5))),
        Case(SHAPES, (QUARTER, np.linspace(0, 1, 4), QUARTER_W)),
    ]
    for _ in range(8):
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (_points(rng, 2, 6, (2, 3)), t)))
    for _ in range(8):
        pts = _points(rng, 2, 6, (2, 3))
        t = float(rng.uniform(0, 1)) if rng.uniform() < 0.3 else _ts(rng)
        cases.append(Case(RANDOM, (pts, t, _weights(rng, len(pts)))))
    cases += [
        Case(BAD, ([[0.0], [1.0], [3.0]], 0.5)),
        Case(BAD, (QUARTER, 0.5, [1.0, 0.0, 1.0])),
    ]
    return cases


# --- 02.bernstein_integral ---------------------------------------------------


def bernstein_integral_cases(rng):
    cases = [
        # The last coefficient is the area under the explicit curve: the mean of the p_i. (The notes give
        # only the formulas (2.17)-(2.20); these are the course's.)
        Case(COURSE, (notes_example("02.integral").inputs["coeffs"].tolist(),), visible=True),
        Case(COURSE, ([1.0, 2.0, 3.0],), visible=True),
        Case(COURSE, ([0.0, 3.0, -1.0, 2.0, 5.0, 0.5],), visible=True),
        Case(EDGE, ([4.0],), visible=True),  # a constant integrates to a line
        Case(EDGE, ([0.0, 0.0, 0.0],), visible=True),
        Case(EDGE, ([2.0, -2.0],), visible=True),
        Case(EDGE, ([(1.0, 0.0), (1.0, 2.0), (0.0, 4.0)],), visible=True),  # two polynomials at once
        Case(EDGE, (np.array([7]),), visible=True),
    ]
    for _ in range(10):
        n = int(rng.integers(0, 8))
        cases.append(Case(RANDOM, (rng.uniform(-10, 10, n + 1),)))
    for _ in range(4):
        cases.append(Case(RANDOM, (_points(rng, 0),)))
    cases += [
        Case(BAD, ([],)),
        Case(BAD, (np.zeros((2, 2, 2)),)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="02.bernstein",
        reference=bezier.bernstein,
        cases=bernstein_cases,
        compare=close(1e-9, 1e-12),
        hint="B_i^n(t) = C(n, i) (1-t)^(n-i) t^i: the power of t is i. A number t gives a float, a 1-D array "
        "of k values gives shape (k,); reject i < 0 or i > n with a ValueError.",
        rules={
            EDGE: "Values of `t` outside $[0,1]$ are allowed: just evaluate the formula.",
            SHAPES: "`t`: a number (return a float) or a 1-D array/list of k numbers (return an array of shape "
                "`(k,)`)",
            BAD: "`i`, `n`: integers with $0\\le i\\le n$; raise a `ValueError` otherwise (e.g. `i > n` or `i < 0`).",
        },
    ),
    Exercise(
        id="02.de_casteljau",
        reference=bezier.de_casteljau,
        cases=de_casteljau_cases,
        compare=close(1e-9, 1e-9),
        hint="A degree-n curve needs exactly n rounds of (1-t) P_i + t P_{i+1}. A number t gives shape (d,), "
        "an array of k values (even k = 1) gives (k, d); t outside [0, 1] works the same way.",
        rules={
            EDGE: "`points`: shape `(n+1, d)`, any degree $n\\ge0$ and dimension $d\\ge1$. A degree-0 \"curve\" is "
                "its one point.",
            SHAPES: "`t` is either a number, and then one point of shape `(d,)` comes back, or a 1-D array (or "
                "list) of k numbers, and then an array of shape `(k, d)` comes back, even when k = 1.",
            BAD: "Raise a `ValueError` when `points` is not two-dimensional or `t` has two or more dimensions.",
        },
    ),
    Exercise(
        id="02.subdivide",
        reference=bezier.subdivide,
        cases=subdivide_cases,
        compare=close(1e-9, 1e-9),
        hint="The left half is the first point of every level of the triangle, P_0^0, P_0^1, ..., P_0^n; the right "
        "half is the last point of every level, starting from the bottom: P_0^n, P_1^{n-1}, ..., P_n^0.",
        rules={
            EDGE: "`t` outside $[0,1]$ works too",
            BAD: "Raise a `ValueError` when `points` is not two-dimensional or `t` is not a single number.",
        },
    ),
    Exercise(
        id="02.elevate",
        reference=bezier.elevate,
        cases=elevate_cases,
        compare=close(1e-9, 1e-9),
        hint="Degree n -> n+1 gives n+2 points P*_i = α_i P_{i-1} + (1-α_i) P_i with α_i = i/(n+1), "
        "keeping both end points; a degree-0 curve becomes two copies of its point.",
        rules={
            EDGE: "`points`: shape `(n+1, d)` with $n\\ge0$; returns shape `(n+2, d)`. A degree-0 curve becomes two "
                "copies of its point.",
            BAD: "Raise a `ValueError` when `points` is not two-dimensional or has no rows.",
        },
    ),
    Exercise(
        id="02.hodograph",
        reference=bezier.hodograph,
        cases=hodograph_cases,
        compare=close(1e-9, 1e-9),
        hint="D_i = n/(t1 - t0) (P_{i+1} - P_i): the factor uses the degree n and the length of the interval. "
        "A degree-0 curve has one zero control point as its hodograph.",
        rules={
            EDGE: "A degree-0 curve (one point) is constant, so its derivative is the zero curve: return **one zero "
                "point**, shape `(1, d)`.",
            BAD: "`interval`: a pair `(t0, t1)` with `t0 < t1`; raise a `ValueError` otherwise, and when `points` "
                "is not two-dimensional.",
        },
    ),
    Exercise(
        id="02.to_homogeneous",
        reference=bezier.to_homogeneous,
        cases=to_homogeneous_cases,
        compare=close(1e-12, 1e-12),
        hint="Each row becomes w_i (x_i, ..., 1): multiply the coordinates by the weight and append the weight. "
        "Build a new array rather than scaling the caller's points in place; reject zero weights.",
        rules={
            EDGE: "`points`: shape `(n+1, d)`; `weights`: shape `(n+1,)`. Returns shape `(n+1, d+1)`: row $i$ is "
                "the point times $w_i$ followed by $w_i$.",
            BAD: "Weights may be negative, but not zero; raise a `ValueError` for a zero weight, for a wrong number "
                "of weights, or for `points` that are not two-dimensional.",
        },
    ),
    Exercise(
        id="02.from_homogeneous",
        reference=bezier.from_homogeneous,
        cases=from_homogeneous_cases,
        compare=close(1e-12, 1e-12),
        hint="The weight is the last column; divide the other columns by it and return (points, weights) "
        "with weights of shape (n+1,). A zero weight is a point at infinity: raise a ValueError.",
        rules={
            EDGE: "`homogeneous`: shape `(n+1, d+1)` with $d\\ge1$. Returns the tuple `(points, weights)` with "
                "shapes `(n+1, d)` and `(n+1,)`.",
            BAD: "A zero weight would be a point at infinity: raise a `ValueError` then, and also when the array is "
                "not two-dimensional or has fewer than two columns.",
        },
    ),
    Exercise(
        id="02.evaluate",
        reference=bezier.evaluate,
        cases=evaluate_cases,
        compare=close(1e-9, 1e-9),
        hint="With weights, run de Casteljau on the homogeneous points w_i (P_i, 1) and divide by the last "
        "coordinate at each t; without weights it is plain de Casteljau. Keep the scalar/array shape rule.",
        rules={
            EDGE: "`points`: shape `(n+1, d)`; `weights`: `None` or shape `(n+1,)` with no zero entry.",
            SHAPES: "`t` is either a number, and then one point of shape `(d,)` comes back, or a 1-D array (or "
                "list) of k numbers, and then an array of shape `(k, d)` comes back, even when k = 1.",
            BAD: "Raise a `ValueError` for a zero weight, a wrong number of weights, or `points` that are not "
                "two-dimensional.",
        },
    ),
    Exercise(
        id="02.curvature",
        reference=bezier.curvature,
        cases=curvature_cases,
        compare=close(1e-7, 1e-7),
        hint="κ = |P' × P''| / |P'|³ (the cube of the speed). For a rational curve differentiate P = X / w with "
        "the quotient rule, or use P' = (X' - w' P)/w and P'' = (X'' - 2 w' P' - w'' P)/w. Curvature is never "
        "negative.",
        rules={
            EDGE: "The curvature is never negative.",
            SHAPES: "`t`: a number (return a float) or a 1-D array of k numbers (return shape `(k,)`).",
            BAD: "Raise a `ValueError` for 1-D points (shape `(n+1, 1)`) and for a zero weight.",
        },
    ),
    Exercise(
        id="02.bernstein_integral",
        reference=polynomials.bernstein_integral,
        cases=bernstein_integral_cases,
        compare=close(1e-9, 1e-12),
        hint="The result has one more coefficient than the input: q_0 = 0 and q_i = (p_0 + ... + p_{i-1})/(n+1), "
        "where n is the degree of p (so divide by the number of input coefficients).",
        rules={
            EDGE: "`coeffs`: shape `(n+1,)`, or `(n+1, d)` for d polynomials at once (one per column). Returns "
                "shape `(n+2,)` or `(n+2, d)`.",
            BAD: "Raise a `ValueError` for an empty array or one with more than two dimensions.",
        },
    ),
]

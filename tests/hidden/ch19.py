"""Hidden grading suite of chapter 19: genus, double points, discriminants, intersections, parametrization, conics.

Fixed cases come from cagd_course/examples/ch19.toml: the notes' double points
(Figures 19.2-19.4 and the cubic of §19.2), the circle and hyperbola of
Figure 19.5 (recovered from their printed points), the quadratic
discriminant (in Sylvester's convention), the pencil parametrizations of Figures 19.6-19.7 and
of the cubic with its double point at (2, 3), and the course's conics. Edge
cases: tangencies, points sharing an x, curves without y, rotated and moved
curves (rounding in every coefficient), degree-1 polynomials, conics through
the origin. Random cases come from the generator the grader passes in.
Parametrizations and conics, defined up to a common factor, are compared after
normalising.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact, same_up_to_scale
from cagd_ref import plane_curves

NOTES = "notes examples"
COURSE = "course examples"
EDGE = "edge cases"
MOVED = "moved curves"
RANDOM = "random"
BAD = "bad input"

NODE = notes_example("19.double_point")
CRUNODE = notes_example("19.crunode")
CUSP = notes_example("19.cusp")
ACNODE = notes_example("19.acnode")
HYPERBOLA = notes_example("19.circle_hyperbola")
QUADRATIC = notes_example("19.quadratic_discriminant")
CIRCLE = notes_example("19.circle_pencil")
CUBIC = notes_example("19.cubic_pencil")
FIGURE = notes_example("19.figure_19_7")
GENERAL = notes_example("19.general_cubic")
FIVE = notes_example("19.conic_five_points")


def _c(example, name="c"):
    return example.inputs[name].tolist()


def _moved(c, angle, point):
    """The curve c turned by `angle` about the origin, then moved so that the origin goes to `point`."""
    cos, sin = np.cos(angle), np.sin(angle)
    m = np.array([[cos, sin], [-sin, cos]])
    return plane_curves.transform_implicit(c, m, -m @ np.asarray(point, dtype=float))


def _homogeneous_random(rng, degrees, low=-4, high=4) -> np.ndarray:
    """Integer coefficients on the homogeneous parts of the given degrees only, in an (n+1, n+1) array."""
    n = max(degrees)
    c = np.zeros((n + 1, n + 1))
    for i in range(n + 1):
        for j in range(n + 1 - i):
            if i + j in degrees:
                c[i, j] = rng.integers(low, high + 1)
    if not np.any([c[n - j, j] for j in range(n + 1)]):
        c[n, 0] = 1.0
    return c


# --- 19.genus -----------------------------------------------------------------------------------------------------

def genus_cases(rng):
    cases = [Case(NOTES, (3, [2]), visible=True), Case(NOTES, (3,), visible=True), Case(NOTES, (4, [2, 2, 2])),
             Case(NOTES, (4, [3]), visible=True), Case(NOTES, (2, [])),
             Case(EDGE, (1,)), Case(EDGE, (2,)), Case(EDGE, (5, [])), Case(EDGE, (5, (3, 2))),
             Case(EDGE, (6, [5]), rule="a triple point takes 3, a point of multiplicity r takes r(r-1)/2"),
             Case(EDGE, (5, [4])), Case(EDGE, (7, [3, 3, 2, 2]))]
    for _ in range(10):
        n = int(rng.integers(3, 9))
        rs, budget = [], (n - 1) * (n - 2) // 2
        while rng.uniform() < 0.7:
            r = int(rng.integers(2, n))
            if r * (r - 1) // 2 > budget:
                break
            rs.append(r)
            budget -= r * (r - 1) // 2
        cases.append(Case(RANDOM, (n, rs)))
    cases += [
        Case(BAD, (4, [2, 2, 2, 2])),  # the two concentric circles: -1
        Case(BAD, (3, [2, 2])),
        Case(BAD, (5, [4, 2, 2]), rule="raise a ValueError if the multiplicities take more than (n-1)(n-2)/2 "
             "from the genus"),
        Case(BAD, (0,), rule="a degree below 1"),
        Case(BAD, (3, [3]), rule="a multiplicity outside 2..n-1"),
        Case(BAD, (4, [1]), rule="a multiplicity outside 2..n-1"),
        Case(BAD, (3.0, [2]), rule="a TypeError if the degree or a multiplicity is not an integer"),
        Case(BAD, (4, [2.5]), rule="a TypeError if the degree or a multiplicity is not an integer"),
    ]
    return cases


# --- 19.classify_double_point ---------------------------------------------------------------------------------------


def classify_cases(rng):
    cases = [
        Case(NOTES, (_c(NODE), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(CRUNODE), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(CUSP), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(ACNODE), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(GENERAL), [2.0, 3.0]), visible=True),
        Case(NOTES, (_c(FIGURE), [0.0, 0.0])),
        Case(NOTES, (_c(CUBIC), [0.0, 0.0])),
        Case(EDGE, ([[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]], [0.0, 0.0]),
             rule="the pair of lines x y = 0 has a crunode"),
        Case(EDGE, ([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]], [0.0, 0.0]),
             rule="a tacnode is reported as a cusp"),  # y² - x⁴: two parabolas touching
        Case(EDGE, (_c(GENERAL), [2.0 + 1e-13, 3.0 - 1e-13]),
             rule="A point given with a rounding error of about 1e-13 is still the double point"),
    ]
    for example in (CRUNODE, CUSP, ACNODE, NODE):
        for _ in range(3):
            point = np.round(rng.uniform(-3, 3, 2), 3)
            cases.append(Case(MOVED, (_moved(example.inputs["c"], rng.uniform(0, 2 * np.pi), point), point)))
    for _ in range(8):
        c = _homogeneous_random(rng, (2, 3))
        if abs(c[1, 1] ** 2 - 4 * c[2, 0] * c[0, 2]) < 1 or not np.any(c[2 - np.arange(3), np.arange(3)]):
            continue
        point = np.round(rng.uniform(-2, 2, 2), 2)
        cases.append(Case(RANDOM, (plane_curves.translate_implicit(c, -point[0], -point[1]), point)))
    cases += [
        Case(BAD, (_c(GENERAL), [0.0, 0.0]), rule="a point that is not on the curve"),
        Case(BAD, ([[0.0, 1.0], [1.0, 0.0]], [0.0, 0.0]), rule="a simple point"),
        Case(BAD, (_c(GENERAL), [1.0, 1.0]), rule="a point that is not on the curve"),
        Case(BAD, ([[0, 0, 0, 1.0], [0, 0, 0, 0], [0, 0, 0, 0], [1.0, 0, 0, 0]], [0.0, 0.0]),
             rule="a point of multiplicity 3 or more"),
        Case(BAD, (np.zeros((3, 3)), [0.0, 0.0]), rule="c is not a 2-D array or is the zero polynomial"),
        Case(BAD, ([1.0, 2.0, 3.0], [0.0, 0.0]), rule="c is not a 2-D array or is the zero polynomial"),
        Case(BAD, (_c(CUSP), [0.0, 0.0, 0.0]), rule="point is not 2 numbers"),
    ]
    return cases


# --- 19.discriminant ------------------------------------------------------------------------------------------------


def discriminant_cases(rng):
    cases = [
        Case(NOTES, (QUADRATIC.inputs["coeffs"].tolist(),), visible=True),
        Case(NOTES, ([1.0, 0.0, 1.0],), visible=True),  # t² + 1: a(4ac - b²) = 4
        Case(NOTES, ([4.0, -4.0, 1.0],), visible=True),  # (t - 2)²
        Case(EDGE, ([3.0, 2.0],), visible=True, rule="A polynomial of degree 1 gives its leading coefficient"),
        Case(EDGE, ([-5.0, 3.0, 2.0, 0.0, 0.0],), visible=True, rule="Trailing zeros do not count"),
        Case(EDGE, ([-2.0, 3.0, 0.0, -1.0],), rule="a repeated root gives 0"),
        Case(EDGE, ([0.0, 0.0, 0.0, 1.0],), rule="a repeated root gives 0"),
        Case(EDGE, ([1.0, 0.0, 0.0, 0.0, 1.0],), rule="Trailing zeros do not count"),
        Case(EDGE, ([0.5, -1.5, 0.25, 2.0],), rule="Trailing zeros do not count"),
    ]
    for _ in range(12):
        n = int(rng.integers(2, 7))
        coeffs = rng.integers(-6, 7, n + 1).astype(float)
        coeffs[-1] = coeffs[-1] or 3.0
        cases.append(Case(RANDOM, (coeffs,)))
    cases += [
        Case(BAD, ([4.0],)),
        Case(BAD, ([0.0, 0.0, 0.0],)),
        Case(BAD, ([2.0, 0.0],)),
        Case(BAD, ([[1.0, 2.0], [3.0, 4.0]],)),
        Case(BAD, ([],)),
    ]
    return cases


# --- 19.implicit_intersections --------------------------------------------------------------------------------------

UNIT = [[-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]  # x² + y² - 1


def _conic_through(rng, points) -> np.ndarray:
    """A random conic through the given points (fewer than five): the others random."""
    extra = rng.uniform(-3, 3, (5 - len(points), 2))
    return plane_curves.conic_through_points(np.vstack([points, extra]))


def _well_conditioned(f, g) -> bool:
    try:
        pts = plane_curves.implicit_intersections(f, g)
    except ValueError:
        return False
    if len(pts) >= 2 and np.min(np.diff(pts[:, 0])) < 1e-2:
        return False
    for x, y in pts:
        grads = []
        for c in (f, g):
            c = np.asarray(c, dtype=float)
            fx = np.polynomial.polynomial.polyval2d(x, y, np.polynomial.polynomial.polyder(c, axis=0))
            fy = np.polynomial.polynomial.polyval2d(x, y, np.polynomial.polynomial.polyder(c, axis=1))
            grads.append(np.array([fx, fy]) / (np.hypot(fx, fy) + 1e-300))
        if abs(grads[0][0] * grads[1][1] - grads[0][1] * grads[1][0]) < 0.05:
            return False
    # Nearly real complex pairs (near tangencies) make the count fragile: keep only clear cases.
    r = plane_curves.curve_resultant(f, g)
    roots = np.polynomial.polynomial.polyroots(r) if len(r) > 1 else np.zeros(0)
    return not np.any((np.abs(roots.imag) > 1e-9) & (np.abs(roots.imag) < 5e-2 * (1 + np.abs(roots))))


def intersection_cases(rng):
    circle, hyperbola = HYPERBOLA.args("circle", "hyperbola")
    cases = [
        Case(NOTES, (circle.tolist(), hyperbola.tolist()), visible=True),
        Case(NOTES, (hyperbola.tolist(), circle.tolist()), visible=True),
        Case(EDGE, (UNIT, [[-0.5, 1.0], [-1.0, 0.0]]), visible=True, rule="points where both polynomials vanish"),
        Case(EDGE, (UNIT, [[-1.0, 1.0], [0.0, 0.0]]), visible=True, rule="A tangency is one point"),
        Case(EDGE, (UNIT, [[-2.0, 1.0], [0.0, 0.0]]), visible=True, rule="return an array of shape (0, 2)"),
        Case(EDGE, (UNIT, [[0.0, 0.0], [1.0, 0.0]]), rule="points on one vertical line are all found"),
        Case(EDGE, ([[-4.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
                    [[-9.0, 0.0, 1.0], [0.0, 0.0, 0.0], [9.0, 0.0, 0.0]]),
             rule="points on one vertical line are all found"),
        Case(EDGE, ([[-1.0], [1.0]], [[-2.0], [1.0]]), rule="return an array of shape (0, 2)"),
        Case(EDGE, ([[-1.0], [1.0]], [[-2.0, 1.0]]), rule="A polynomial may lack x or y"),
        Case(EDGE, ([[0.0, -1.0], [0.0, 0.0], [1.0, 0.0]], [[0.0, 1.0]]),  # y = x² and y = 0
             rule="A tangency is one point"),
        Case(EDGE, (_c(GENERAL), [[-3.0, 1.0], [0.0, 0.0]]), rule="points on one vertical line are all found"),
        Case(EDGE, (_c(CRUNODE), [[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]]),
             rule="points where both polynomials vanish"),
    ]
    made = 0
    while made < 10:
        kind = made % 3
        if kind == 0:  # two conics through two chosen points
            shared = np.round(rng.uniform(-2, 2, (2, 2)), 2)
            f, g = _conic_through(rng, shared), _conic_through(rng, shared)
        elif kind == 1:  # a cubic and a line with integer coefficients
            f = _homogeneous_random(rng, (0, 1, 2, 3), -5, 5)
            g = _homogeneous_random(rng, (0, 1), -5, 5)
        else:  # a conic and a cubic
            f = _homogeneous_random(rng, (0, 1, 2), -5, 5)
            g = _homogeneous_random(rng, (0, 1, 2, 3), -5, 5)
        if _well_conditioned(f, g):
            cases.append(Case(RANDOM, (f, g)))
            made += 1
    cases += [
        Case(BAD, ([[0.0, 0.0, 0.0], [-1.0, 0.0, 1.0], [0.0, 0.0, 0.0], [1.0, 0.0, 0.0]],
                   [[0.0, 0.0, 0.0], [1.0, 2.0, 0.0], [0.0, 0.0, 0.0]]), rule="share a component"),
        Case(BAD, (UNIT, [[-2.0, 0.0, 2.0], [0.0, 0.0, 0.0], [2.0, 0.0, 0.0]]), rule="share a component"),
        Case(BAD, (UNIT, [[3.0]]), rule="a constant or the zero polynomial"),
        Case(BAD, (UNIT, np.zeros((2, 2))), rule="a constant or the zero polynomial"),
        Case(BAD, ([1.0, 2.0], UNIT), rule="not a 2-D array"),
    ]
    return cases


# --- 19.parametrize_by_pencil ---------------------------------------------------------------------------------------


def pencil_cases(rng):
    cases = [
        Case(NOTES, (_c(CIRCLE), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(CUBIC), [0.0, 0.0]), visible=True),
        Case(NOTES, (_c(GENERAL), [2.0, 3.0]), visible=True),
        Case(NOTES, (_c(FIGURE), [0.0, 0.0])),
        Case(NOTES, (_c(CRUNODE), [0.0, 0.0])),
        Case(NOTES, (_c(CUSP), [0.0, 0.0])),
        Case(NOTES, (_c(ACNODE), [0.0, 0.0])),
        Case(EDGE, (UNIT, [1.0, 0.0]), rule="any point of a conic"),
        Case(EDGE, (UNIT, [0.6, -0.8]), rule="any point of a conic"),
        Case(EDGE, ([[0.0, -1.0], [0.0, 0.0], [1.0, 0.0]], [2.0, 4.0]), rule="any point of a conic"),  # y = x²
        Case(EDGE, ([[0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 1.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]],
                    [0.0, 0.0]), rule="W(t) may have a lower degree than n"),  # x y² + x² + y²: W = t²
        Case(EDGE, ([[0.0, 0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 0.0, 0.0], [0.0, 0.0, -1.0, 0.0, 0.0],
                     [1.0, 0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0, 0.0]], [0.0, 0.0]),
             rule="a triple point of a quartic"),
        Case(EDGE, (_c(GENERAL), [2.0 + 1e-13, 3.0]), rule="within 1e-9 times the largest coefficient"),
    ]
    for _ in range(4):
        point = np.round(rng.uniform(-3, 3, 2), 2)
        example = (CRUNODE, CUSP, ACNODE, FIGURE)[int(rng.integers(4))]
        cases.append(Case(MOVED, (_moved(example.inputs["c"], rng.uniform(0, 2 * np.pi), point), point)))
    for degrees in ((1, 2), (2, 3), (2, 3), (3, 4), (1, 2), (2, 3)):
        c = _homogeneous_random(rng, degrees)
        point = np.round(rng.uniform(-2, 2, 2), 2)
        cases.append(Case(RANDOM, (plane_curves.translate_implicit(c, -point[0], -point[1]), point)))
    cases += [
        Case(BAD, (_c(GENERAL), [0.0, 0.0]), rule="a point of any other multiplicity"),
        Case(BAD, (_c(GENERAL), [1.0, 0.0]), rule="a point of any other multiplicity"),
        Case(BAD, ([[0.0, 0.0, 0.0, 1.0], [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]],
                   [0.0, 0.0]), rule="multiplicity n"),
        Case(BAD, ([[0.0, 1.0], [1.0, 0.0]], [0.0, 0.0]), rule="degree below 2"),
        Case(BAD, (np.zeros((3, 3)), [0.0, 0.0]), rule="c is not a 2-D array or is the zero polynomial"),
        Case(BAD, (_c(CIRCLE), [0.0]), rule="point is not 2 numbers"),
    ]
    return cases


# --- 19.conic_through_points ----------------------------------------------------------------------------------------


def conic_cases(rng):
    cases = [
        Case(COURSE, (FIVE.inputs["points"].tolist(),), visible=True),
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 4.0), (-1.0, 1.0), (3.0, 9.0)],), visible=True,
             rule="conics through the origin"),
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (-1.0, -1.0), (2.0, 0.5), (0.5, 2.0)],), rule="conics through the origin"),
        Case(EDGE, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (0.0, 1.0), (1.0, 3.0)],), visible=True,
             rule="Three of the points may be collinear"),
        Case(EDGE, ([(1.0, 0.0), (2.0, 0.0), (3.0, 0.0), (0.0, 1.0), (0.0, 2.0)],),
             rule="Three of the points may be collinear"),
        Case(EDGE, ([(3.0, 0.0), (0.0, 2.0), (-3.0, 0.0), (0.0, -2.0), (1.5, np.sqrt(3.0))],),
             rule="an ellipse, a parabola or a hyperbola"),
        Case(EDGE, ([(1.0, 1.0), (2.0, 0.5), (-1.0, -1.0), (4.0, 0.25), (-2.0, -0.5)],),
             rule="an ellipse, a parabola or a hyperbola"),
    ]
    made = 0
    while made < 10:
        pts = np.round(rng.uniform(-5, 5, (5, 2)), 3)
        x, y = pts.T
        m = np.column_stack([x * x, x * y, y * y, x, y, np.ones(5)])
        s = np.linalg.svd(m / np.linalg.norm(m, axis=0), compute_uv=False)
        if s[-1] > 1e-3 * s[0]:
            cases.append(Case(RANDOM, (pts,)))
            made += 1
    cases += [
        Case(BAD, ([(0.0, 0.0), (1.0, 1.0), (2.0, 2.0), (3.0, 3.0), (0.0, 1.0)],), rule="four of them lie on one line"),
        Case(BAD, ([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0), (4.0, 0.0)],), rule="four of them lie on one line"),
        Case(BAD, ([(0.0, 0.0), (0.0, 0.0), (1.0, 2.0), (3.0, 1.0), (5.0, 0.0)],), rule="two of them coincide"),
        Case(BAD, ([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)],), rule="points is not of shape (5, 2)"),
        Case(BAD, ([(0.0, 0.0, 1.0)] * 5,), rule="points is not of shape (5, 2)"),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="19.genus",
        reference=plane_curves.genus,
        cases=genus_cases,
        compare=exact(),
        hint="g = (n-1)(n-2)/2 - Σ r(r-1)/2: a double point takes 1, a triple point 3. A negative result means the "
        "curve is reducible: raise a ValueError instead of returning it.",
        rules={EDGE: "Lines and conics have genus 0", BAD: "a ValueError"},
    ),
    Exercise(
        id="19.classify_double_point",
        reference=plane_curves.classify_double_point,
        cases=classify_cases,
        compare=exact(),
        hint="Move the point to the origin first (substitute x + x0, y + y0), then read the quadratic part "
        "A x² + B xy + C y²: B² - 4AC > 0 crunode, = 0 cusp, < 0 acnode, with the relative tolerances of the "
        "statement.",
        rules={MOVED: "The test must work wherever the point is and however the curve is turned",
               EDGE: "the pair of lines x y = 0 has a crunode", BAD: "raise a ValueError"},
    ),
    Exercise(
        id="19.discriminant",
        reference=plane_curves.discriminant,
        cases=discriminant_cases,
        compare=close(1e-8, 1e-8),
        hint="Build the Sylvester matrix of p (degree n) and p' (degree n-1), size 2n-1, after dropping trailing "
        "zeros; its determinant is Res(p, p'). For a t² + b t + c it is a (4ac - b²): not b² - 4ac (SymPy's "
        "normalised discriminant) and not a²(b² - 4ac) (the notes' Bézout determinant).",
        rules={EDGE: "Trailing zeros do not count", BAD: "Raise a ValueError if the degree is below 1"},
    ),
    Exercise(
        id="19.implicit_intersections",
        reference=plane_curves.implicit_intersections,
        cases=intersection_cases,
        compare=close(1e-7, 1e-7),
        hint="Res_y(f, g) is a polynomial in x whose real roots are the x of the intersections; for each root x_k "
        "the y are the real roots of gcd(f(x_k, y), g(x_k, y)). Keep only points where both f and g vanish, each "
        "once, sorted by x then y.",
        rules={EDGE: "points where both polynomials vanish", BAD: "raise a ValueError"},
    ),
    Exercise(
        id="19.parametrize_by_pencil",
        reference=plane_curves.parametrize_by_pencil,
        cases=pencil_cases,
        compare=same_up_to_scale(1e-7),
        hint="Translate the point to the origin, split into the parts f_(n-1) and f_n, and return "
        "X = x0 W - f_(n-1)(1, t), Y = y0 W - t f_(n-1)(1, t), W = f_n(1, t) as rows of ascending coefficients, "
        "each of length n+1.",
        rules={MOVED: "The test must work wherever the point is and however the curve is turned",
               EDGE: "a point of multiplicity n - 1", BAD: "raise a ValueError"},
    ),
    Exercise(
        id="19.conic_through_points",
        reference=plane_curves.conic_through_points,
        cases=conic_cases,
        compare=same_up_to_scale(1e-7),
        hint="Each point gives a row (x², xy, y², x, y, 1); the conic's six coefficients are the null vector of "
        "the 5×6 matrix (SVD). Do not fix c00 = 1: conics through the origin have c00 = 0. Put c20, c11, c02, c10, "
        "c01, c00 into c[2, 0], c[1, 1], c[0, 2], c[1, 0], c[0, 1], c[0, 0].",
        rules={EDGE: "an ellipse, a parabola or a hyperbola", BAD: "raise a ValueError"},
    ),
]

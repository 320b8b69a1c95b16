"""Hidden grading suite of chapter 17: resultants, Bézout matrices, GCDs, implicitization, inversion, intersection.

Fixed cases reuse the notes' worked examples, read from
cagd_course/examples/ch17.toml: the resultants 12, 0, 5, 0, 1611 (the notes'
-1611 is Bézout's sign), the Bézout matrices of the cubic pairs, Euclid on the
three pairs, the parabola of §17.2, the recovered rational cubic of §17.5, the
loop cubic with its double point of §17.6 and the nine intersections of §17.8.
Edge cases probe unequal degrees, constants, trailing zeros, the swap law, the
zero polynomial, degree-raised curves, double points and parameters outside
[0, 1]; the random cases come from the generator the grader passes in.
Implicit equations are compared after scaling both by the entry where the
reference's equation is largest.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import algebra, bezier
from cagd_ref.roots import bernstein_roots

NOTES = "notes example"
EDGE = "edge cases"
RATIONAL = "rational curves"
SHAPES = "one point vs many"
RANDOM = "random"
BAD = "bad input"


def ex(name):
    return notes_example(f"17.{name}")


def _pair(name):
    return tuple(a.tolist() for a in ex(name).args("f", "g"))


PAIRS = ["root_product", "root_product_common", "linear_no_root", "linear_common", "cubic_no_root", "cubic_common",
         "gauss_two_roots"]
PARABOLA = ex("parabola").inputs["points"].tolist()
LINE = ex("line").inputs["points"].tolist()
RCUBIC, RWEIGHTS = (a.tolist() for a in ex("resultant_cubic").args("points", "weights"))
LOOP = ex("bezier_cubic").inputs["points"].tolist()
CIRCLE, CIRCLE_WEIGHTS = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], [1.0, float(np.sqrt(0.5)), 1.0]
OTHER, OTHER_WEIGHTS = (a.tolist() for a in ex("intersection").args("q", "q_weights"))


def _integer_poly(rng, degree):
    c = rng.integers(-9, 10, degree + 1).astype(float)
    c[-1] = c[-1] or float(rng.choice([-1, 1]) * rng.integers(1, 10))
    return c


def _dyadic_poly(rng, roots):
    """A polynomial with the given roots times a dyadic factor: exact in binary."""
    return np.polynomial.polynomial.polyfromroots(roots) * float(rng.integers(1, 9)) / 4


def _curve(rng, low=2, high=4, rational=None):
    n = int(rng.integers(low, high + 1))
    points = rng.uniform(-5, 5, (n + 1, 2))
    weighted = rng.uniform() < 0.5 if rational is None else rational
    return points, (rng.uniform(0.5, 2.0, n + 1) if weighted else None)


def _args(points, weights, *rest):
    return (points, *rest) if weights is None else (points, *rest, weights)


# --- 17.resultant -------------------------------------------------------------------------------------------------


def resultant_cases(rng):
    cases = [Case(NOTES, _pair(name), visible=True) for name in PAIRS]
    cases += [
        Case(EDGE, ([-1.0, 0.0, 1.0], [4.0, 2.0]), visible=True),  # unequal degrees: Res(t² - 1, 2t + 4) = 12
        Case(EDGE, ([-2.0, 0.0, 2.0], [4.0, 2.0]), visible=True),  # 24, not the padded Bézout ±48
        Case(EDGE, ([4.0, 2.0], [-1.0, 0.0, 1.0]), visible=True),  # swapped: (-1)^(2·1) = +12
        Case(EDGE, ([3.0, 1.0], [1.0, 0.0, 0.0, 1.0]), visible=True),  # mn odd: Res(t + 3, t³ + 1) = -26
        Case(EDGE, ([1.0, 0.0, 0.0, 1.0], [3.0, 1.0]), visible=True),  # ... and swapped, +26
        Case(EDGE, ([3.0], [1.0, 0.0, 1.0]), visible=True),  # a constant: 3² = 9
        Case(EDGE, ([3.0], [5.0]), visible=True),  # two constants: 1
        Case(EDGE, ([12.0, -7.0, 1.0, 0.0], [4.0, -6.0, 2.0]), visible=True),  # trailing zero: a quadratic, 48
        Case(EDGE, ([2.0, 1.0], [1.0, 0.0, 3.0, 0.0, 0.0]), visible=True),  # Res(t + 2, 3t² + 1) = 13
        Case(EDGE, ([1.0, 0.0, 1.0], [3.0, 2.0, 1.0]), visible=True),  # complex roots, integer resultant 8
    ]
    for _ in range(16):
        m, n = (int(d) for d in rng.integers(1, 8, 2))
        cases.append(Case(RANDOM, (_integer_poly(rng, m), _integer_poly(rng, n))))
    for _ in range(6):  # real coefficients with a common root: zero
        root = float(rng.integers(-8, 9)) / 4
        cases.append(Case(RANDOM, (_dyadic_poly(rng, [root, float(rng.integers(-8, 9)) / 8 + 1 / 16]),
                                   _dyadic_poly(rng, [root, 0.3125, -1.5]))))
    cases += [
        Case(BAD, ([0.0, 0.0], [1.0, 1.0])),  # the zero polynomial
        Case(BAD, ([1.0, 2.0], [[1.0, 2.0]])),
        Case(BAD, ([], [1.0, 2.0])),
        Case(BAD, ([1.0, float("nan")], [1.0, 2.0])),
    ]
    return cases


# --- 17.bezout_matrix -----------------------------------------------------------------------------------------------


def bezout_matrix_cases(rng):
    cases = [Case(NOTES, _pair(name), visible=True) for name in PAIRS]
    cases += [
        Case(EDGE, ([-2.0, 0.0, 2.0], [4.0, 2.0]), visible=True),  # g padded to degree 2
        Case(EDGE, ([4.0, 2.0], [-2.0, 0.0, 2.0]), visible=True),  # f padded
        Case(EDGE, ([1.0, 2.0, 3.0, 4.0, 5.0], [2.0, -1.0, 0.0, 1.0, -3.0]), visible=True),  # degree 4
        Case(EDGE, ([1.0, 3.0, -2.0, 1.0, 0.0], [4.0, -1.0, 3.0, 2.0]), visible=True),  # trailing zero
        Case(EDGE, ([2.0], [1.0, 1.0]), visible=True),  # degree 1 against a constant: [[2]]
    ]
    for _ in range(14):
        n = int(rng.integers(1, 7))
        m = n if rng.uniform() < 0.7 else int(rng.integers(0, n))
        pair = (_integer_poly(rng, n), _integer_poly(rng, m))
        cases.append(Case(RANDOM, pair if rng.uniform() < 0.5 else pair[::-1]))
    cases += [
        Case(BAD, ([0.0], [1.0, 1.0])),
        Case(BAD, ([[1.0, 2.0]], [1.0, 1.0])),
        Case(BAD, ([1.0, float("inf")], [1.0, 1.0])),
    ]
    return cases


# --- 17.poly_gcd ---------------------------------------------------------------------------------------------------


def poly_gcd_cases(rng):
    cases = [Case(NOTES, tuple(a.tolist() for a in ex(name).args("f", "g")), visible=True)
             for name in ("euclid_no_root", "euclid_common", "euclid_two_roots")]
    f, g = _pair("cubic_common")
    cases += [
        Case(NOTES, (f, g), visible=True),
        Case(EDGE, ([2 * c for c in f], [3 * c for c in g]), visible=True),  # scaling changes nothing
        Case(EDGE, ([-4.0, 1.0], f), visible=True),  # deg f < deg g
        Case(EDGE, (f, [0.0]), visible=True),  # gcd(f, 0): f made monic
        Case(EDGE, ([0.0, 0.0], [6.0, -5.0, 1.0]), visible=True),
        Case(EDGE, ([2.0], [6.0, -5.0, 1.0]), visible=True),  # a nonzero constant: 1
        Case(EDGE, ([6.0, -5.0, 1.0], [12.0, -10.0, 2.0]), visible=True),  # proportional: the whole polynomial
        Case(EDGE, (np.polynomial.polynomial.polyfromroots([0.5, 0.5, 2.0]).tolist(),
                    np.polynomial.polynomial.polyfromroots([0.5, 0.5, -1.0]).tolist()), visible=True),  # double root
    ]
    for _ in range(18):
        common = (rng.integers(-8, 9, int(rng.integers(0, 4))) / 4).tolist()
        f = _dyadic_poly(rng, common + (rng.integers(-8, 9, int(rng.integers(1, 3))) / 4 + 1 / 8).tolist())
        g = _dyadic_poly(rng, common + (rng.integers(-8, 9, int(rng.integers(1, 3))) / 4 + 1 / 16).tolist())
        cases.append(Case(RANDOM, (f, g) if rng.uniform() < 0.5 else (g, f)))
    cases += [
        Case(BAD, ([0.0], [0.0, 0.0])),  # both zero: no GCD
        Case(BAD, ([[1.0, 2.0]], [1.0, 1.0])),
        Case(BAD, ([1.0, float("nan")], [1.0, 1.0])),
    ]
    return cases


# --- 17.implicitize --------------------------------------------------------------------------------------------------


def same_implicit(expected, received) -> str | None:
    """The same (n+1, n+1) array up to one nonzero factor: both divided by their entry where expected is largest."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    try:
        got = np.asarray(received, dtype=float)
    except (TypeError, ValueError):
        return f"expected an array of shape {expected.shape}, got {type(received).__name__}"
    if got.shape != expected.shape:
        return f"expected shape {expected.shape} (c[i, j] of x^i y^j), got shape {got.shape}"
    index = np.unravel_index(int(np.argmax(np.abs(expected))), expected.shape)
    if not np.isfinite(got).all() or got[index] == 0:
        return f"expected a nonzero coefficient at {tuple(int(i) for i in index)} (x^i y^j), got {got[index]}"
    problem = close(1e-8, 1e-8)(expected / expected[index], got / got[index])
    return f"after scaling both by the coefficient at {tuple(int(i) for i in index)}: {problem}" if problem else None


def implicitize_cases(rng):
    cases = [
        Case(NOTES, (LINE,), visible=True),
        Case(NOTES, (PARABOLA,), visible=True),
        Case(NOTES, (RCUBIC, RWEIGHTS), visible=True),
        Case(NOTES, (LOOP,), visible=True),
        Case(RATIONAL, (CIRCLE, CIRCLE_WEIGHTS), visible=True),
        Case(RATIONAL, (OTHER, OTHER_WEIGHTS), visible=True),
        Case(RATIONAL, (LOOP, [1.0, -2.0, 0.5, 1.0]), visible=True),  # a negative weight is fine
        Case(RATIONAL, (PARABOLA,), {"weights": [1.0, 1.0, 1.0]}, visible=True),
        Case(EDGE, ([[0.0, 0.0], [1.0, 3.0], [4.0, 1.0], [2.0, -2.0], [5.0, 5.0]],), visible=True),  # a quartic
        Case(EDGE, ([[0.0, 0.0], [1.0, 1.0], [3.0, 3.0]],), visible=True),  # collinear: the line squared
    ]
    for _ in range(14):
        points, weights = _curve(rng, 2, 5)
        cases.append(Case(RANDOM, _args(points, weights)))
    for _ in range(4):
        points = rng.integers(-6, 7, (int(rng.integers(3, 5)), 2)).astype(float)
        cases.append(Case(RANDOM, (points, rng.integers(1, 4, len(points)).astype(float))))
    cases += [
        Case(BAD, (bezier.elevate(np.array(PARABOLA)).tolist(),)),  # degree-raised: the determinant vanishes
        Case(BAD, ([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]],)),
        Case(BAD, ([[1.0, 2.0]],)),
        Case(BAD, (PARABOLA, [1.0, 0.0, 1.0])),
        Case(BAD, (PARABOLA, [1.0, 1.0])),
    ]
    return cases


# --- 17.invert -----------------------------------------------------------------------------------------------------


def _on(points, weights, ts):
    return bezier.evaluate(points, ts, weights)


def invert_cases(rng):
    ts = np.array([-0.5, 0.0, 0.2, 0.5, 0.9, 1.0, 1.4])
    loop_ts = np.array([-0.5, 0.3, 0.5, 1.0, 1.5, 2.5])  # away from t = 0 and t = 2, the double point
    cases = [
        Case(NOTES, (PARABOLA, [5.0, -2.0]), visible=True),  # t = -2
        Case(NOTES, (LOOP, bezier.evaluate(LOOP, 0.5).tolist()), visible=True),
        Case(NOTES, (LOOP, _on(LOOP, None, loop_ts)), visible=True),
        Case(NOTES, (RCUBIC, _on(RCUBIC, RWEIGHTS, ts), RWEIGHTS), visible=True),
        Case(NOTES, (LINE, _on(LINE, None, ts)), visible=True),
        Case(RATIONAL, (CIRCLE, _on(CIRCLE, CIRCLE_WEIGHTS, ts), CIRCLE_WEIGHTS), visible=True),
        Case(RATIONAL, ([[0.0, 0.0], [2.0, 1.0]], _on([[0.0, 0.0], [2.0, 1.0]], [1.0, 0.5], ts), [1.0, 0.5]),
             visible=True),  # a rational line: not the chord's fraction
        Case(RATIONAL, (OTHER, _on(OTHER, OTHER_WEIGHTS, ts), OTHER_WEIGHTS), visible=True),
        Case(EDGE, (PARABOLA, _on(PARABOLA, None, [0.0, 1.0])), visible=True),  # both ends
        Case(EDGE, (LOOP, _on(LOOP, None, [1.0])), visible=True),
        Case(SHAPES, (LOOP, _on(LOOP, None, 0.25))),
        Case(SHAPES, (LOOP, _on(LOOP, None, [0.25]))),
    ]
    for _ in range(14):
        points, weights = _curve(rng, 1, 3)
        cases.append(Case(RANDOM, _args(points, weights, _on(points, weights, np.sort(rng.uniform(-0.3, 1.3, 6))))))
    for _ in range(4):
        points, weights = _curve(rng, 4, 4)
        cases.append(Case(RANDOM, _args(points, weights, _on(points, weights, np.sort(rng.uniform(0.05, 0.95, 4))))))
    cases += [
        Case(BAD, (LOOP, [1.0, 0.0])),  # the double point: t = 0 and t = 2
        Case(BAD, (LOOP, [1.0, 0.0, 1.0])),
        Case(BAD, (LOOP, [[[1.0, 0.0]]])),
        Case(BAD, ([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], [0.5, 0.5, 0.5])),
        Case(BAD, (PARABOLA, [5.0, -2.0], [1.0, 0.0, 1.0])),
    ]
    return cases


# --- 17.intersect_implicit ---------------------------------------------------------------------------------------


def _clear_pair(p, q, pw, qw) -> bool:
    """A pair whose intersections are transversal and away from the ends: the answer does not hang on rounding."""
    g = algebra.intersection_polynomial(p, q, pw, qw)
    if np.abs(g[[0, -1]]).min() <= 1e-6 * np.abs(g).max():
        return False
    us = bernstein_roots(g)
    if us.size == 0:
        return True
    try:
        ts = algebra.invert(p, bezier.evaluate(q, us, qw), pw)
    except ValueError:
        return False
    if np.min(np.abs(np.concatenate([ts, ts - 1, us, us - 1]))) < 0.01:
        return False
    for t, u in zip(ts, us):
        a, b = bezier.derivative(p, t, 1, pw), bezier.derivative(q, u, 1, qw)
        if abs(a[0] * b[1] - a[1] * b[0]) < 0.05 * np.linalg.norm(a) * np.linalg.norm(b):
            return False
    return True


def intersect_implicit_cases(rng):
    e = ex("intersection")
    cases = [
        Case(NOTES, tuple(a.tolist() for a in e.args("p", "q", "p_weights", "q_weights")), visible=True),
        Case(NOTES, (e.inputs["q"].tolist(), e.inputs["p"].tolist(), e.inputs["q_weights"].tolist(),
                     e.inputs["p_weights"].tolist()), visible=True),  # the other way round: (u, t) re-sorted
        Case(EDGE, ([[0.0, 0.0], [1.0, 1.0]], [[0.0, 1.0], [1.0, 0.0]]), visible=True),  # two lines
        Case(EDGE, ([[0.0, 0.0], [1.0, 0.0]], [[0.0, 1.0], [1.0, 2.0]]), visible=True),  # disjoint: (0, 2)
        Case(EDGE, ([[0.0, 0.0], [1.0, 0.0]], [[0.0, 1.0], [0.5, -1.0], [1.0, 1.0]]), visible=True),  # tangent
        Case(EDGE, ([[0.0, 0.0], [1.0, 0.0]], [[0.25, 1.0], [0.5, -3.0], [0.75, 1.0]]), visible=True),
        Case(EDGE, ([[0.0, -1.0], [2.0, 3.0], [4.0, -1.0]], [[0.0, 2.0], [6.0, 0.0]]), visible=True),
        Case(EDGE, (LOOP, [[3.0, -1.0], [3.0, 4.0]]), visible=True),
        Case(EDGE, (LOOP, [[0.0, 2.0], [6.0, 2.0]]), visible=True),  # P meets it at t in [0, 1] and beyond
        Case(RATIONAL, (CIRCLE, [[0.0, 0.0], [2.0, 2.0]], CIRCLE_WEIGHTS), visible=True),
        Case(RATIONAL, ([[0.0, 0.0], [2.0, 2.0]], CIRCLE, None, CIRCLE_WEIGHTS), visible=True),  # rational Q
    ]
    drawn = 0
    while drawn < 14:
        p, pw = _curve(rng, 1, 3)
        q, qw = _curve(rng, 1, 3)
        q = q[rng.permutation(len(q))] * 0.8  # criss-cross P's box, so that most pairs meet
        if _clear_pair(p, q, pw, qw) and (drawn < 2 or algebra.intersect_implicit(p, q, pw, qw).size):
            cases.append(Case(RANDOM, (p, q, pw, qw)))
            drawn += 1
    cases += [
        Case(BAD, ([[0.0, 0.0], [1.0, 0.0]], [[0.25, 0.0], [0.75, 0.0]])),  # on one line: infinitely many
        Case(BAD, ([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]], LINE)),
        Case(BAD, (LINE, [[1.0, 2.0]])),
        Case(BAD, (LOOP, OTHER, [1.0, 0.0, 1.0, 1.0])),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="17.resultant",
        reference=algebra.resultant,
        cases=resultant_cases,
        compare=close(1e-8, 1e-8),
        hint="Build the Sylvester matrix: m = deg g rows of f's coefficients from the highest power down, each "
        "shifted one column right, then n = deg f rows of g's; its determinant is Res(f, g). Drop trailing zeros "
        "first; a constant c gives c^(deg of the other).",
        rules={
            EDGE: "A constant counts as degree 0: $\\operatorname{Res}(c, g)=c^{\\deg g}$, $\\operatorname{Res}(f, "
                "c)=c^{\\deg f}$, and two constants give 1.",
            BAD: "Raise a `ValueError` for the zero polynomial (all coefficients zero), an empty array, an array "
                "that is not 1-D, or NaN/infinite coefficients.",
        },
    ),
    Exercise(
        id="17.bezout_matrix",
        reference=algebra.bezout_matrix,
        cases=bezout_matrix_cases,
        compare=close(1e-9, 1e-9),
        hint="With brackets (a_k b_m) = a_k b_m - a_m b_k, entry (r, c) is L_{i,j} with i = n-1-r, j = n-1-c: "
        "the sum of (a_k b_m) over m <= min(i, j), k = i + j + 1 - m <= n. Pad the lower degree with zeros.",
        rules={
            EDGE: "`f`, `g`: ascending coefficients; trailing zeros dropped first. The result has shape `(n, n)` "
                "(`(0, 0)` for two constants) and is symmetric.",
            BAD: "Raise a `ValueError` for the zero polynomial, arrays that are not 1-D, or NaN/infinite "
                "coefficients.",
        },
    ),
    Exercise(
        id="17.poly_gcd",
        reference=algebra.poly_gcd,
        cases=poly_gcd_cases,
        compare=close(1e-8, 1e-8),
        hint="Divide, keep divisor and remainder, repeat until the remainder is zero; in floating point a "
        "remainder coefficient below 1e-9 times the largest coefficient of that step counts as zero. Return the "
        "last nonzero remainder divided by its leading coefficient.",
        rules={
            EDGE: "No common root: return `[1.0]`. One argument the zero polynomial: the GCD is the other one, made "
                "monic. Scaling $f$ or $g$ by a constant changes nothing.",
            BAD: "Raise a `ValueError` if both are the zero polynomial, for arrays that are not 1-D and for "
                "NaN/infinity.",
        },
    ),
    Exercise(
        id="17.implicitize",
        reference=algebra.implicitize,
        cases=implicitize_cases,
        compare=same_implicit,
        hint="l_ij = C(n,i) C(n,j) (H_i × H_j) with H_i = w_i (x_i, y_i, 1) is the line a x + b y + c; the "
        "matrix entry L_{i,j} sums l_km over m <= min(i, j), k = i + j + 1 - m <= n, and f = det L, expanded "
        "as a polynomial (a determinant of linear forms). Entry c[i, j] multiplies x^i y^j.",
        rules={
            RATIONAL: "Weights may be negative (not zero).",
            EDGE: "Collinear control points give a power of the line; that is fine.",
            BAD: "Raise a `ValueError` for points that are not `(n+1, 2)` with $n\\ge1$, for a zero weight or the "
                "wrong number of weights, for NaN/infinity, and when the determinant vanishes identically",
        },
    ),
    Exercise(
        id="17.invert",
        reference=algebra.invert,
        cases=invert_cases,
        compare=close(1e-8, 1e-8),
        hint="For a quadratic t = (l20 - l10) / (2 l20 - l21 - l10), 0/0 nowhere on a conic (l20 / (l20 - l21) "
        "and l10 / (l10 - l20) each fail at one end); for a cubic the row operation of (17.13) gives "
        "t = l_b / (l_b - l_a); for n >= 4 a basis of the linear-algebra family, at each point the member with "
        "the largest den (one member alone is also 0/0 at n - 3 ordinary points). Any degree: t is the common "
        "real root of X(t) - x W(t) and Y(t) - y W(t), the root of their GCD. 0/0 for every formula (two roots) "
        "is a double point: ValueError.",
        rules={
            RATIONAL: "The tests give points $\\mathbf P(t)$ for $t$ anywhere in $[-0.5, 2.5]$, not only in "
                "$[0,1]$, on curves of degree 1 to 4.",
            EDGE: "The tests give points $\\mathbf P(t)$ for $t$ anywhere in $[-0.5, 2.5]$, not only in $[0,1]$",
            SHAPES: "`xy`: a point of shape `(2,)`, giving a float, or `k` points `(k, 2)`, giving an array `(k,)`.",
            BAD: "Raise a `ValueError` for `points` not of shape `(n+1, 2)`, a zero weight, `xy` of another shape, "
                "NaN/infinity.",
        },
    ),
    Exercise(
        id="17.intersect_implicit",
        reference=algebra.intersect_implicit,
        cases=intersect_implicit_cases,
        compare=close(1e-7, 1e-7),
        hint="Substitute Q's homogeneous coordinates into P's implicit equation, homogenised: "
        "Σ c_ij X^i Y^j W^(m-i-j) (rational Q needs the W powers). Keep the roots u in [0, 1], invert Q(u) on "
        "P and keep t in [0, 1]; one row per intersection, rows (t, u) sorted by t.",
        rules={
            EDGE: "A tangency (a double root of $g$) is **one** row.",
            RATIONAL: "points that are not `(n+1, 2)` with $n\\ge1$, a zero weight or the wrong number of weights",
            BAD: "Raise a `ValueError` when $g$ vanishes identically (the curves lie on one implicit curve: "
                "infinitely many common points), and for bad points or weights as in exercise 17.4: points that "
                "are not `(n+1, 2)` with $n\\ge1$, a zero weight or the wrong number of weights, NaN/infinity.",
        },
    ),
]

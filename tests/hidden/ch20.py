"""Hidden grading suite of chapter 20: hybrid curves, the area matrix, sector areas, volumes, the adaptive area.

Fixed cases: the notes' semicircle (Fig. 20.6, weights 3, 1, 1, 3, area π/8),
the course's completion of Example 1 (Fig. 20.5), the polynomial cubic with
area 3/5, the quarter circle (∫ y dx = -π/4), a cone, closed chains. Edge
cases: every split point m of a hybrid, degree-0 and degree-1 curves, equal
weights (a polynomial curve in disguise), reversed curves, curves below the
axis and loops. Random cases come from the generator the grader passes in:
rational curves with positive weights (ratios up to 10), polynomial curves.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import bezier, hybrid

NOTES = "notes examples"
COURSE = "course examples"
EDGE = "edge cases"
RANDOM = "random"
BAD = "bad input"

SEMICIRCLE = notes_example("20.semicircle")
EXAMPLE_1 = notes_example("20.example_1")
QUARTER = notes_example("20.quarter_circle")
CUBIC = notes_example("20.cubic_area").inputs["points"].tolist()
HALF = SEMICIRCLE.inputs["points"].tolist()
HALF_WEIGHTS = SEMICIRCLE.inputs["weights"].tolist()
EXAMPLE_POINTS = EXAMPLE_1.inputs["points"].tolist()
EXAMPLE_WEIGHTS = EXAMPLE_1.inputs["weights"].tolist()
QUARTER_POINTS = QUARTER.inputs["points"].tolist()
QUARTER_WEIGHTS = QUARTER.inputs["weights"].tolist()
LOOP = [(0.0, 0.0), (4.0, 1.0), (-1.0, 3.0), (0.0, 0.0)]  # a closed cubic, counterclockwise
BELOW = [(0.0, -1.0), (1.0, -3.0), (2.0, -2.0), (4.0, -0.5)]  # x increasing under the axis: negative area
ARC_POINTS, ARC_WEIGHTS = (a.tolist() for a in bezier.circular_arc([1.0, 2.0], 1.5, 0.3, 2.0))


def _rational(rng, low=1, high=4):
    r = int(rng.integers(low, high + 1))
    return rng.uniform(-3, 3, (r + 1, 2)), rng.uniform(0.3, 3.0, r + 1)


def _polynomial(rng, low=0, high=6):
    return rng.uniform(-3, 3, (int(rng.integers(low, high + 1)) + 1, 2))


# --- 20.hybrid_curve ---------------------------------------------------------------------------------


def same_hybrid(expected, received) -> str | None:
    """(fixed, moving, weights, m) as the reference, the moving row of `fixed` ignored, within 1e-9 of the scale."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    if not isinstance(received, (tuple, list)) or len(received) != 4:
        return "expected a tuple (fixed, moving, weights, m)"
    fixed, moving, weights, m = expected
    try:
        got_m = int(received[3])
    except (TypeError, ValueError):
        return f"m: expected an integer, got {received[3]!r}"[:200]
    if got_m != m or received[3] != m:
        return f"m: expected {m}, got {received[3]!r}"[:200]
    scale = 1.0 + np.abs(np.delete(fixed, m, axis=0)).max() + np.abs(moving).max()
    try:
        got_fixed = np.array(received[0], dtype=float)
    except (TypeError, ValueError):
        return "fixed: expected numbers"
    if got_fixed.shape != fixed.shape:
        return f"fixed: expected shape {fixed.shape}, got shape {got_fixed.shape}"
    problem = close(1e-9, 1e-10 * scale)(np.delete(fixed, m, axis=0), np.delete(got_fixed, m, axis=0))
    if problem:
        return f"fixed points (row m = {m} is not compared): {problem}"
    for name, want, got in (("moving", moving, received[1]), ("weights", weights, received[2])):
        problem = close(1e-9, 1e-10 * scale)(want, got)
        if problem:
            return f"{name}: {problem}"
    return None


def hybrid_curve_cases(rng):
    cases = [
        Case(NOTES, (HALF, HALF_WEIGHTS, 2), visible=True),
        Case(NOTES, (HALF, HALF_WEIGHTS, 4), visible=True),
        Case(NOTES, (HALF, HALF_WEIGHTS, 6), visible=True),
        Case(NOTES, (HALF, HALF_WEIGHTS, 8), visible=True),
        Case(COURSE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 4), visible=True),
        Case(COURSE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 3), visible=True),  # odd n: m = 1
        Case(EDGE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 3, 2), visible=True),
        Case(EDGE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 5), {"m": 1}, visible=True),
        Case(EDGE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 5, 4), visible=True),
        Case(EDGE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 2), visible=True),  # n < r
        Case(EDGE, (QUARTER_POINTS, QUARTER_WEIGHTS, 2), visible=True),  # r = n = 2
        Case(EDGE, (QUARTER_POINTS, QUARTER_WEIGHTS, 7, 3), visible=True),
        Case(EDGE, (CUBIC, [1.0, 1.0, 1.0, 1.0], 4), visible=True),  # polynomial: M stands still
        Case(EDGE, ([(0.0, 1.0), (2.0, 3.0)], [1.0, 4.0], 3), visible=True),  # r = 1
        Case(EDGE, ([(2.0, -1.0)], [2.0], 4), visible=True),  # r = 0: a point
        Case(EDGE, ([(0.0, 0.0, 1.0), (1.0, 2.0, 0.0), (3.0, 1.0, 2.0)], [1.0, 0.5, 2.0], 4), visible=True),  # 3-D
    ]
    for _ in range(20):
        points, weights = _rational(rng)
        n = int(rng.integers(2, 9))
        m = int(rng.integers(1, n))
        cases.append(Case(RANDOM, (points, weights, n, m) if rng.uniform() < 0.7 else (points, weights, n)))
    cases += [
        Case(BAD, (HALF, HALF_WEIGHTS, 1)),  # no inner control point to move
        Case(BAD, (HALF, HALF_WEIGHTS, 4, 0)),  # m must be inner
        Case(BAD, (HALF, HALF_WEIGHTS, 4, 4)),
        Case(BAD, (HALF, [3.0, -1.0, 1.0, 3.0], 4)),  # a negative weight
        Case(BAD, (HALF, [3.0, 0.0, 1.0, 3.0], 4)),  # a zero weight
        Case(BAD, (HALF, [3.0, 1.0, 1.0], 4)),  # one weight per point
        Case(BAD, ([0.0, 1.0, 2.0], [1.0, 1.0, 1.0], 4)),  # points must be (r+1, d)
    ]
    return cases


# --- 20.area_matrix -----------------------------------------------------------------------------------


def area_matrix_cases(rng):
    cases = [Case(COURSE, (n,), visible=True) for n in (1, 2, 3)]
    cases += [Case(EDGE, (n,), visible=True) for n in (0, 4, 5)]
    cases += [Case(RANDOM, (int(n),)) for n in rng.choice(np.arange(6, 21), 10, replace=False)]
    cases += [Case(BAD, (-1,)), Case(BAD, (2.5,)), Case(BAD, ("3",))]
    return cases


# --- 20.sector_area -----------------------------------------------------------------------------------


def _approximations():
    return [hybrid.polynomial_approximation(HALF, HALF_WEIGHTS, n)[0].tolist() for n in (2, 4)]


def sector_area_cases(rng):
    parabola = notes_example("20.parabolic_sector").inputs["points"].tolist()
    cases = [
        Case(COURSE, (parabola,), visible=True),
        Case(COURSE, (parabola[::-1],), visible=True),  # clockwise: negative
        Case(COURSE, ([(1.0, 0.0), (0.0, 1.0)],), visible=True),  # a segment: the triangle with the origin
        Case(COURSE, (LOOP,), visible=True),  # closed: the area it encloses
        Case(COURSE, (CUBIC,), visible=True),
        Case(EDGE, ([(2.0, 3.0)],), visible=True),  # one point: nothing swept
        Case(EDGE, ([(1.0, 1.0), (2.0, 2.0)],), visible=True),  # through the origin's ray: zero
        Case(EDGE, (BELOW,), visible=True),
    ]
    cases += [Case(EDGE, (p,), visible=True) for p in _approximations()]
    cases += [Case(RANDOM, (_polynomial(rng, 1),)) for _ in range(14)]
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),  # planar curves only
        Case(BAD, ([0.0, 1.0, 2.0],)),
        Case(BAD, (np.zeros((0, 2)),)),
    ]
    return cases


# --- 20.revolution_volume -------------------------------------------------------------------------------


def revolution_volume_cases(rng):
    cone = notes_example("20.cone").inputs["points"].tolist()
    cases = [
        Case(COURSE, (cone,), visible=True),
        Case(COURSE, (cone[::-1],), visible=True),  # x decreasing: negative
        Case(COURSE, ([(0.0, 1.0), (2.0, 1.0)],), visible=True),  # a cylinder: π r² h
        Case(COURSE, (CUBIC,), visible=True),
        Case(EDGE, (BELOW,), visible=True),  # under the axis: still positive (y²)
        Case(EDGE, ([(2.0, 3.0)],), visible=True),
        Case(EDGE, ([(1.0, 0.0), (1.0, 2.0)],), visible=True),  # no dx: no volume
        Case(EDGE, (LOOP,), visible=True),
    ]
    cases += [Case(EDGE, (p,), visible=True) for p in _approximations()]
    cases += [Case(RANDOM, (_polynomial(rng, 1),)) for _ in range(14)]
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)],)),
        Case(BAD, ([0.0, 1.0, 2.0],)),
    ]
    return cases


# --- 20.bezier_area ----------------------------------------------------------------------------------------


def within_tolerance(expected, received) -> str | None:
    """Within tol of the exact area: the reference's value is within its bound of it, so |got - ref| <= tol + bound."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    if isinstance(received, (bool, str, bytes)) or received is None:
        return f"expected a number, got {type(received).__name__}"
    try:
        got = float(np.asarray(received, dtype=float))
    except (TypeError, ValueError):
        return f"expected a single number, got {type(received).__name__}"
    if not np.isfinite(got):
        return f"expected a finite area, got {got}"
    allowed = expected.tol + expected.bound + 1e-12 * (1 + abs(expected))
    if abs(got - expected) > allowed:
        return f"expected an area within {expected.tol:g} of {float(expected):.12g}, got {got:.12g}"
    return None


def bezier_area_cases(rng):
    cases = [Case(NOTES, (HALF, HALF_WEIGHTS, tol), visible=True) for tol in (1e-3, 1e-6, 1e-9)]
    cases += [
        Case(NOTES, (HALF[::-1], HALF_WEIGHTS[::-1]), {"tol": 1e-9}, visible=True),  # reversed: -π/8
        Case(COURSE, (CUBIC,), visible=True),  # polynomial: 3/5 exactly
        Case(COURSE, (QUARTER_POINTS, QUARTER_WEIGHTS), {"tol": 1e-10}, visible=True),  # -π/4
        Case(COURSE, (EXAMPLE_POINTS, EXAMPLE_WEIGHTS, 1e-6), visible=True),
        Case(EDGE, (CUBIC, [2.0, 2.0, 2.0, 2.0], 1e-9), visible=True),  # equal weights: a polynomial curve
        Case(EDGE, (HALF, [6.0, 2.0, 2.0, 6.0], 1e-9), visible=True),  # scaled weights: the same semicircle
        Case(EDGE, ([(0.0, 1.0), (2.0, 3.0)], [1.0, 5.0], 1e-9), visible=True),  # a rational line
        Case(EDGE, ([(2.0, 3.0)],), visible=True),  # a point
        Case(EDGE, (BELOW, [1.0, 2.0, 0.5, 1.0], 1e-8), visible=True),
        Case(EDGE, (LOOP, [1.0, 3.0, 0.4, 1.0], 1e-8), visible=True),  # closed: minus the enclosed area
        Case(EDGE, (ARC_POINTS, ARC_WEIGHTS, 1e-9), visible=True),
        Case(EDGE, (HALF, HALF_WEIGHTS, 1e-12), visible=True),  # near what doubles can guarantee
    ]
    for _ in range(16):
        points, weights = _rational(rng, 2, 4)
        tol = float(rng.choice([1e-4, 1e-7, 1e-10]))
        cases.append(Case(RANDOM, (points, weights, tol)))
    cases += [Case(RANDOM, (_polynomial(rng, 1, 5),)) for _ in range(3)]
    cases += [
        Case(BAD, (HALF, HALF_WEIGHTS, 0.0)),
        Case(BAD, (HALF, HALF_WEIGHTS, -1e-6)),
        Case(BAD, (HALF, HALF_WEIGHTS, 1e-15)),  # below 1e-13 · max|coordinate|²: not guaranteed
        Case(BAD, ((100 * np.array(HALF)).tolist(), HALF_WEIGHTS, 1e-10)),  # the floor grows with the curve
        Case(BAD, (HALF, [3.0, -1.0, 1.0, 3.0], 1e-6)),
        Case(BAD, (HALF, [3.0, 1.0, 1.0], 1e-6)),
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], None, 1e-6)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="20.hybrid_curve",
        reference=hybrid.hybrid_curve,
        cases=hybrid_curve_cases,
        compare=same_hybrid,
        hint="Multiply H(t) = R(t) by the weight function and compare the coefficients of (1-t)^(n+r-k) t^k: "
        "k < m gives P_0..P_(m-1) (20.4) upwards from P_0 = R_0, k > m + r gives P_n..P_(m+1) (20.5) downwards "
        "from P_n = R_r, k = m..m+r gives M_0..M_r (20.6), skipping j = i. Keep the weights w_j in every sum.",
        rules={
            EDGE: "`degree`: an integer $n\\ge2$; `m`: an integer with $0<m<n$, or `None` for $m=\\lfloor "
                "n/2\\rfloor$.",
            BAD: "Raise a ValueError (or TypeError) if degree $<2$, if m is not between $1$ and $n-1$, if a weight "
                "is zero or negative or their number is not r+1, or if points is not a 2-D array.",
        },
    ),
    Exercise(
        id="20.area_matrix",
        reference=hybrid.area_matrix,
        cases=area_matrix_cases,
        compare=close(1e-12, 1e-14),
        hint="A_ij = ∫ B_i^n (B_j^n)' dt = n ∫ B_i^n (B_(j-1)^(n-1) - B_j^(n-1)) dt, with B_(-1)^(n-1) = "
        "B_n^(n-1) = 0 and ∫ B_a^p B_b^q = C(p,a) C(q,b) / (C(p+q,a+b) (p+q+1)). Check: A + Aᵀ = diag(-1, 0, ..., 1).",
        rules={
            EDGE: "`n = 0` (a constant curve, $x'=0$) gives `[[0.0]]`; `n = 1` is the trapezoid.",
            BAD: "Raise a ValueError for a negative n and a TypeError (or ValueError) when n is not an integer.",
        },
    ),
    Exercise(
        id="20.sector_area",
        reference=hybrid.sector_area,
        cases=sector_area_cases,
        compare=close(1e-10, 1e-12),
        hint="½∫(x dy - y dx) = Σ_{i<j} A_ij (x_i y_j - x_j y_i) with A the area matrix; counterclockwise about "
        "the origin is positive. One point sweeps nothing.",
        rules={
            EDGE: "(a single point sweeps nothing: 0.0)",
            BAD: "Raise a ValueError if points is not of shape (n+1, 2) with at least one point.",
        },
    ),
    Exercise(
        id="20.revolution_volume",
        reference=hybrid.revolution_volume,
        cases=revolution_volume_cases,
        compare=close(1e-10, 1e-12),
        hint="π∫ y² dx = 2π Ix with Ix = ½ Σ T_ijk y_i y_j x_k, T_ijk = ∫ B_i^n B_j^n (B_k^n)' dt: or multiply the "
        "Bernstein polynomials y·y·x' and take the mean of the product's coefficients.",
        rules={
            EDGE: "positive where $x$ increases (even below the axis, as $y^2\\ge0$), negative where it decreases.",
            BAD: "Raise a ValueError if points is not of shape (n+1, 2).",
        },
    ),
    Exercise(
        id="20.bezier_area",
        reference=hybrid.bezier_area,
        cases=bezier_area_cases,
        compare=within_tolerance,
        hint="Polynomial curves (weights None or all equal): the closed form yᵀ A x. Rational ones: split at "
        "t = 1/2 on the homogeneous control points until each piece's error bound (20.27) is at most tol times "
        "its parameter length, then add the pieces' polynomial areas. Refuse tol <= 0 and tol below "
        "1e-13 · max|coordinate|².",
        rules={
            EDGE: "`points`: shape `(r+1, 2)`, $r\\ge0$ (a single point has area `0.0`); `weights`: `None` or `r+1` "
                "positive numbers.",
            BAD: "Raise a ValueError if tol is not positive, or if it is smaller than $10^{-13}\\cdot s^2$ with $s$ "
                "the largest absolute coordinate of the control points (double precision cannot guarantee it), if "
                "a weight is zero or negative or their number is not r+1, or if points is not of shape (r+1, 2).",
        },
    ),
]

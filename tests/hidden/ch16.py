"""Hidden grading suite of chapter 16: points and tangents on rational Bézier patches in O(n²).

The notes state only operation counts, so the fixed cases are the course's examples
(cagd_course/examples/ch16.toml): the rational cubic in space with weights 1, 2, 1/2, 1, the
quarter circle, the rational patch of degree (2, 1) and the biquadratic torus patch, all checked
exactly. Edge cases probe degree 1, polynomial input (no weights), parameters at 0, 1/2 and 1 and
just below 1 (where the unswitched pseudo-power form breaks down), high degrees, negative weights,
patches with m ≠ n (so that swapping the directions shows) and planar points. Random cases come
from the generator the grader passes in, with positive weights.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import surfaces

EXAMPLE = "course examples"
EDGE = "edge cases"
POLYNOMIAL = "polynomial input"
NEAR_ONE = "near t = 1"
SHAPES = "scalar vs array parameters"
RANDOM = "random"
BAD = "bad input"

CUBIC = notes_example("16.rational_cubic")
CIRCLE = notes_example("16.quarter_circle")
PATCH = notes_example("16.rational_patch")
TORUS = notes_example("16.torus")

CUBIC_POINTS, CUBIC_WEIGHTS = (a.tolist() for a in CUBIC.args("points", "weights"))
CIRCLE_POINTS, CIRCLE_WEIGHTS = (a.tolist() for a in CIRCLE.args("points", "weights"))
PATCH_POINTS, PATCH_WEIGHTS = (a.tolist() for a in PATCH.args("points", "weights"))
TORUS_POINTS, TORUS_WEIGHTS = (a.tolist() for a in TORUS.args("points", "weights"))
LINE = [(0.0, 1.0), (3.0, 5.0)]
PLANAR_QUARTIC = [(0.0, 0.0), (1.0, 3.0), (3.0, -1.0), (5.0, 2.0), (6.0, 0.0)]
SADDLE = [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]]
TS = np.linspace(0.0, 1.0, 9)


def _curve(rng, low=1, high=7, rational=True):
    n = int(rng.integers(low, high + 1))
    d = int(rng.choice([2, 3]))
    points = rng.uniform(-4, 4, (n + 1, d))
    return points, (rng.uniform(0.4, 2.5, n + 1) if rational else None)


def _patch(rng, rational=True, low=1, high=5):
    m, n = (int(v) for v in rng.integers(low, high + 1, 2))
    points = rng.uniform(-3, 3, (m + 1, n + 1, 3))
    return points, (rng.uniform(0.4, 2.5, (m + 1, n + 1)) if rational else None)


def _with_weights(args, weights):
    return args if weights is None else args + (weights,)


# --- 16.split_qr ---------------------------------------------------------------------------------------


def split_qr_cases(rng):
    cases = [
        Case(EXAMPLE, (CUBIC_POINTS, CUBIC_WEIGHTS), visible=True),
        Case(EXAMPLE, (CIRCLE_POINTS, CIRCLE_WEIGHTS), visible=True),
        Case(POLYNOMIAL, (CUBIC_POINTS,), visible=True),  # weights None: every weight is 1
        Case(POLYNOMIAL, (LINE,), visible=True),  # degree 1: Q and R are single points
        Case(EDGE, (LINE, [2.0, 0.5]), visible=True),
        Case(EDGE, (CUBIC_POINTS, [1.0, -2.0, 0.5, 1.0]), visible=True),  # a negative weight is allowed
        Case(EDGE, ([(1.0,), (2.0,), (4.0,)], [1.0, 3.0, 1.0]), visible=True),  # points on a line, d = 1
        Case(EDGE, (PLANAR_QUARTIC, [1.0, 2.0, 3.0, 2.0, 1.0]), visible=True),
    ]
    for _ in range(10):
        points, weights = _curve(rng, rational=rng.uniform() < 0.7)
        cases.append(Case(RANDOM, _with_weights((points,), weights)))
    cases += [
        Case(BAD, ([(1.0, 2.0)],)),  # degree 0: no Q and R
        Case(BAD, (CUBIC_POINTS, [1.0, 0.0, 1.0, 1.0])),  # a zero weight
        Case(BAD, (CUBIC_POINTS, [1.0, 2.0, 1.0])),  # one weight per point
        Case(BAD, ([1.0, 2.0, 3.0],)),  # not (n+1, d)
    ]
    return cases


# --- 16.curve_point_derivative ---------------------------------------------------------------------------


def curve_point_derivative_cases(rng):
    cases = [
        Case(EXAMPLE, (CUBIC_POINTS, CUBIC.inputs["ts"], CUBIC_WEIGHTS), visible=True),
        Case(EXAMPLE, (CIRCLE_POINTS, CIRCLE.inputs["ts"], CIRCLE_WEIGHTS), visible=True),
        Case(EXAMPLE, (CUBIC_POINTS, 0.25, CUBIC_WEIGHTS), visible=True),
        Case(POLYNOMIAL, (CUBIC_POINTS, TS), visible=True),
        Case(POLYNOMIAL, (LINE, [0.0, 0.5, 1.0]), visible=True),  # degree 1: p' = P1 - P0
        Case(POLYNOMIAL, (PLANAR_QUARTIC, TS), visible=True),
        Case(EDGE, (CUBIC_POINTS, [0.0, 1.0], CUBIC_WEIGHTS), visible=True),  # the ends: n (w1/w0)(P1 - P0), ...
        Case(EDGE, (CUBIC_POINTS, [0.5 - 1e-12, 0.5, 0.5 + 1e-12], CUBIC_WEIGHTS), visible=True),  # across 1/2
        Case(NEAR_ONE, (CUBIC_POINTS, [1 - 1e-9, 1 - 1e-13, 1.0], CUBIC_WEIGHTS), visible=True),
        Case(EDGE, (CUBIC_POINTS, [-0.5, 1.5], CUBIC_WEIGHTS), visible=True),  # beyond [0, 1]
        Case(EDGE, (PLANAR_QUARTIC, TS, [1.0, 3.0, 0.5, 2.0, 1.0]), visible=True),
        Case(SHAPES, (CUBIC_POINTS, np.array([0.3]), CUBIC_WEIGHTS)),
        Case(SHAPES, (CUBIC_POINTS, np.array(0.3), CUBIC_WEIGHTS)),
    ]
    for _ in range(14):
        points, weights = _curve(rng, high=10, rational=rng.uniform() < 0.7)
        ts = float(rng.uniform()) if rng.uniform() < 0.3 else np.sort(rng.uniform(0, 1, int(rng.integers(2, 8))))
        cases.append(Case(RANDOM, _with_weights((points, ts), weights)))
    cases += [
        Case(BAD, (CUBIC_POINTS, 0.5, [1.0, 0.0, 1.0, 1.0])),
        Case(BAD, (CUBIC_POINTS, 0.5, [1.0, 1.0])),
        Case(BAD, (LINE, 0.5, [1.0, -1.0])),  # the weight 1 - 2t vanishes at t = 1/2: a point at infinity
        Case(BAD, (CUBIC_POINTS, [[0.5]])),
    ]
    return cases


# --- 16.pseudo_horner ------------------------------------------------------------------------------------


def pseudo_horner_cases(rng):
    cubic = [1.0, 9.0, 4.0, 6.0]
    powers = (2.0 ** np.arange(41)).tolist()  # (1 + t)^40
    cases = [
        Case(EXAMPLE, (cubic, 0.5), visible=True),
        Case(EXAMPLE, (cubic, TS), visible=True),  # both forms: below and above 1/2
        Case(EXAMPLE, ([1.0, 2.0, 4.0, 8.0], [0.0, 0.25, 1.0]), visible=True),
        Case(EDGE, (cubic, [0.0, 1.0]), visible=True),  # the end coefficients exactly
        Case(EDGE, ([3.0], [0.0, 0.4, 1.0]), visible=True),  # degree 0: a constant
        Case(EDGE, ([2.0, -1.0], TS), visible=True),
        Case(EDGE, (cubic, [-1.0, -0.25, 1.25, 2.0]), visible=True),  # any real t
        Case(NEAR_ONE, (cubic, [1 - 1e-12, 1 - 1e-15, 1.0]), visible=True),
        Case(NEAR_ONE, (powers, [0.5, 1 - 1e-4, 1 - 1e-8, 1.0]), visible=True),  # u^40 would overflow
        Case(SHAPES, (CUBIC_POINTS, 0.3), visible=True),  # columns: (d,) for a number
        Case(SHAPES, (CUBIC_POINTS, TS), visible=True),  # ... and (k, d) for k values
        Case(SHAPES, (cubic, np.array([0.7]))),
        Case(SHAPES, (cubic, np.array(0.7))),
    ]
    for _ in range(14):
        degree = int(rng.integers(1, 16))
        shape = (degree + 1,) if rng.uniform() < 0.5 else (degree + 1, int(rng.integers(1, 4)))
        ts = float(rng.uniform()) if rng.uniform() < 0.3 else np.sort(rng.uniform(0, 1, int(rng.integers(2, 12))))
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, shape), ts)))
    cases += [
        Case(BAD, ([[[1.0]]], 0.5)),
        Case(BAD, ([], 0.5)),
        Case(BAD, (cubic, [[0.5]])),
    ]
    return cases


# --- 16.sub_patches ---------------------------------------------------------------------------------------


def sub_patches_cases(rng):
    bicubic = rng.uniform(-2, 2, (4, 4, 3))
    cases = [
        Case(EXAMPLE, (PATCH_POINTS, PATCH_WEIGHTS), visible=True),  # degree (2, 1): m ≠ n
        Case(EXAMPLE, (TORUS_POINTS, TORUS_WEIGHTS), visible=True),
        Case(POLYNOMIAL, (PATCH_POINTS,), visible=True),
        Case(POLYNOMIAL, (SADDLE,), visible=True),  # degree (1, 1): four single points
        Case(EDGE, (np.transpose(PATCH_POINTS, (1, 0, 2)), np.transpose(PATCH_WEIGHTS)), visible=True),  # (1, 2)
        Case(EDGE, (rng.uniform(-2, 2, (3, 5, 2)), rng.uniform(0.5, 2, (3, 5))), visible=True),  # planar, (2, 4)
        Case(EDGE, (bicubic, -np.ones((4, 4))), visible=True),  # negative weights
    ]
    for _ in range(10):
        points, weights = _patch(rng, rational=rng.uniform() < 0.7)
        cases.append(Case(RANDOM, _with_weights((points,), weights)))
    cases += [
        Case(BAD, ([[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0)]],)),  # degree 0 in s: no sub-patches
        Case(BAD, (PATCH_POINTS, [[1.0, 1.0], [2.0, 0.0], [1.0, 1.0]])),
        Case(BAD, (PATCH_POINTS, [1.0, 2.0, 1.0])),
        Case(BAD, (CUBIC_POINTS,)),  # a curve, not a net
    ]
    return cases


# --- 16.patch_point_tangents ------------------------------------------------------------------------------


def patch_point_tangents_cases(rng):
    corners = ([0.0, 1.0, 0.0, 1.0, 0.5], [0.0, 0.0, 1.0, 1.0, 0.5])
    cases = [
        Case(EXAMPLE, (PATCH_POINTS, PATCH.inputs["s"], PATCH.inputs["t"], PATCH_WEIGHTS), visible=True),
        Case(EXAMPLE, (PATCH_POINTS, 0.5, 0.5, PATCH_WEIGHTS), visible=True),
        Case(EXAMPLE, (TORUS_POINTS, TORUS.inputs["s"], TORUS.inputs["t"], TORUS_WEIGHTS), visible=True),
        Case(EDGE, (PATCH_POINTS, *corners, PATCH_WEIGHTS), visible=True),  # corners: s or t = 0 or 1
        Case(EDGE, (np.transpose(PATCH_POINTS, (1, 0, 2)), [0.25, 0.75], [0.75, 0.25], np.transpose(PATCH_WEIGHTS)),
             visible=True),  # degree (1, 2)
        Case(POLYNOMIAL, (SADDLE, TS, TS[::-1]), visible=True),
        Case(POLYNOMIAL, (PATCH_POINTS, [0.2, 0.7], [0.9, 0.4]), visible=True),
        Case(NEAR_ONE, (TORUS_POINTS, [1 - 1e-12, 1.0, 0.3], [0.4, 1 - 1e-12, 1.0], TORUS_WEIGHTS), visible=True),
        Case(SHAPES, (PATCH_POINTS, TS, 0.3, PATCH_WEIGHTS), visible=True),  # t a number, s an array: 9 pairs
        Case(SHAPES, (PATCH_POINTS, 0.3, 0.6, PATCH_WEIGHTS)),
        Case(SHAPES, (PATCH_POINTS, np.array([0.3]), np.array([0.6]), PATCH_WEIGHTS)),
    ]
    for _ in range(14):
        points, weights = _patch(rng, rational=rng.uniform() < 0.75)
        k = int(rng.integers(1, 8))
        cases.append(Case(RANDOM, _with_weights((points, rng.uniform(0, 1, k), rng.uniform(0, 1, k)), weights)))
    cases += [
        Case(BAD, (PATCH_POINTS, 0.5, 0.5, [[1.0, 1.0], [2.0, 0.0], [1.0, 1.0]])),
        Case(BAD, (PATCH_POINTS, [0.1, 0.2], [0.1, 0.2, 0.3])),  # s and t do not broadcast
        Case(BAD, (SADDLE, 0.5, 0.5, [[1.0, 1.0], [-1.0, -1.0]])),  # the weight vanishes at (1/2, 1/2)
        Case(BAD, (CUBIC_POINTS, 0.5, 0.5)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="16.split_qr",
        reference=surfaces.split_qr,
        cases=split_qr_cases,
        compare=close(1e-12, 1e-12),
        hint="Lift every control point to w_i (P_i, 1) first; Q is the first n of them, R the last n.",
        rules={
            POLYNOMIAL: "for `weights=None` that column holds ones.",
            EDGE: "`weights`: `None` (every weight 1) or `n+1` nonzero numbers (negative ones are allowed).",
            BAD: "Raise a `ValueError` if `points` is not of shape `(n+1, d)` with $n\\ge1$ (a single point has no "
                "$\\mathbf Q$ and $\\mathbf R$), if a weight is zero, or if the number of weights is not `n+1`.",
        },
    ),
    Exercise(
        id="16.curve_point_derivative",
        reference=surfaces.curve_point_derivative,
        cases=curve_point_derivative_cases,
        compare=close(1e-9, 1e-9),
        hint="p = Π((1 - t) Q + t R) and p' = n Q_w R_w / P_w² (Π(R) - Π(Q)): the direction r - q, and a "
        "length that depends on the weights of Q, R and P at t. Evaluate Q and R in a form that works at t = 1.",
        rules={
            POLYNOMIAL: "`weights`: `None` or `n+1` nonzero numbers.",
            EDGE: "The tests use $t$ in $[-\\tfrac12, \\tfrac32]$, including $t=0$, $t=\\tfrac12$, $t=1$ and "
                "$t=1-10^{-13}$",
            NEAR_ONE: "evaluate $\\mathbf Q$ and $\\mathbf R$ by a method that works there",
            SHAPES: "`t`: a number, giving two arrays of shape `(d,)`, or a 1-D array of k numbers, giving two "
                "arrays `(k, d)`.",
            BAD: "Raise a `ValueError` if `points` is not `(n+1, d)`, if a weight is zero or their number is wrong, "
                "if `t` has two or more dimensions, and where $P_w(t)=0$",
        },
    ),
    Exercise(
        id="16.pseudo_horner",
        reference=surfaces.pseudo_horner,
        cases=pseudo_horner_cases,
        compare=close(1e-10, 1e-12),
        hint="For t < 1/2: (1 - t)^N Σ C(N, i) c_i u^i with u = t / (1 - t). For t >= 1/2: t^N Σ C(N, i) c_(N-i) u^i "
        "with u = (1 - t) / t. Choose the form parameter by parameter.",
        rules={
            EDGE: "`t`: a number or a 1-D array of k numbers, any real values.",
            NEAR_ONE: "The tests include $t=1$, $t=1-10^{-15}$, and degree 40 at $t=1-10^{-8}$: every result must "
                "be finite and right to within a relative $10^{-10}$ (or an absolute $10^{-12}$).",
            SHAPES: "For `(N+1,)` coefficients return a float for a number and shape `(k,)` for an array; for "
                "`(N+1, d)` return `(d,)` and `(k, d)`.",
            BAD: "Raise a `ValueError` if `coeffs` is empty or has more than two dimensions, or if `t` has two or "
                "more dimensions.",
        },
    ),
    Exercise(
        id="16.sub_patches",
        reference=surfaces.sub_patches,
        cases=sub_patches_cases,
        compare=close(1e-12, 1e-12),
        hint="Work on the homogeneous net H[i, j] = w_ij (P_ij, 1), shape (m+1, n+1, d+1); P^kl is H[k:k+m, l:l+n], "
        "k along s (the first index), l along t.",
        rules={
            POLYNOMIAL: "ones for `weights=None`",
            EDGE: "`points`: shape `(m+1, n+1, d)` with $m\\ge1$ and $n\\ge1$; `weights`: `None` or shape `(m+1, "
                "n+1)`, nonzero (negative allowed).",
            BAD: "Raise a `ValueError` if `points` does not have three dimensions, if $m=0$ or $n=0$ (no "
                "sub-patches), if a weight is zero, or if `weights` does not have the shape `(m+1, n+1)`.",
        },
    ),
    Exercise(
        id="16.patch_point_tangents",
        reference=surfaces.patch_point_tangents,
        cases=patch_point_tangents_cases,
        compare=close(1e-9, 1e-9),
        hint="Blend the four sub-patch values in t to get A (from P^00, P^01) and B (from P^10, P^11), the Q and R "
        "of the s-iso-curve: p_s = m A_w B_w / P_w² (Π(B) - Π(A)). Blend in s for p_t, with n. Never take the tangents "
        "from the four points Π(S^kl) themselves.",
        rules={
            EDGE: "`points`: shape `(m+1, n+1, d)` with $m, n\\ge1$; `weights`: `None` or `(m+1, n+1)`, nonzero.",
            POLYNOMIAL: "`weights`: `None` or `(m+1, n+1)`, nonzero.",
            NEAR_ONE: "The tests use $s, t$ in $[0, 1]$, including 0, 1 and $1-10^{-12}$.",
            SHAPES: "`s`, `t`: numbers, or 1-D arrays that broadcast together (equal lengths, or one of them a "
                "number): two numbers give three arrays of shape `(d,)`, k pairs three arrays `(k, d)`.",
            BAD: "Raise a `ValueError` if `points` does not have three dimensions, if a weight is zero or `weights` "
                "has the wrong shape, if `s` and `t` do not broadcast together, and where $P_w(s,t)=0$.",
        },
    ),
]

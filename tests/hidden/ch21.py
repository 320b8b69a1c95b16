"""Hidden grading suite of chapter 21: bilinear, birational and projective maps of quadrilaterals.

The fixed cases are the notes' examples (cagd_course/examples/ch21.toml): the
quad of Figure 21.1 with E = (8, 4) and its two bilinear pre-images, w01 = 5/3
with the single pre-image (2/5, 2/3), the concave quad of Figure 21.4a
(w11 = -4.2), the twisted quad of Figure 21.4b (w10 w01 = 16), the collinear
quad of Figure 21.3a (w11 = 0, As = Q01, At = Q10) and the projective weights
2 : 5 : 6 : 9. Edge cases probe trapezoids with either pair of edges parallel,
parallelograms (both axes at infinity), points without a real pre-image, the
fold, corners. Random quads (convex, non-convex, twisted) come from the
generator the grader passes in, kept away from near-degenerate shapes.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import quad_maps

EXAMPLE = "notes examples"
EDGE = "edge cases"
RANDOM = "random"
BAD = "bad input"

BILINEAR = notes_example("21.bilinear")
BIRATIONAL = notes_example("21.birational")
CONCAVE = notes_example("21.concave")
TWISTED = notes_example("21.twisted")
COLLINEAR = notes_example("21.collinear")

QUAD = BILINEAR.inputs["quad"].tolist()
CONCAVE_QUAD = CONCAVE.inputs["quad"].tolist()
TWISTED_QUAD = TWISTED.inputs["quad"].tolist()
COLLINEAR_QUAD = COLLINEAR.inputs["quad"].tolist()
W53 = BIRATIONAL.inputs["weights"].tolist()
UNIT = [[1.0, 1.0], [1.0, 1.0]]
PARALLELOGRAM = [[[0.0, 0.0], [1.0, 2.0]], [[3.0, 0.0], [4.0, 2.0]]]
TRAPEZOID_T = [[[0.0, 0.0], [1.0, 2.0]], [[4.0, 0.0], [3.0, 2.0]]]  # edges t = 0 and t = 1 parallel
TRAPEZOID_S = [[[0.0, 0.0], [0.0, 1.0]], [[2.0, 0.0], [2.0, 3.0]]]  # edges s = 0 and s = 1 parallel
COINCIDING = [[[0.0, 0.0], [0.0, 0.0]], [[2.0, 0.0], [1.0, 1.0]]]
ON_A_LINE = [[[0.0, 0.0], [1.0, 1.0]], [[2.0, 2.0], [3.0, 3.0]]]


def _quad(rng, kind: str) -> list:
    """A random quad [[P00, P01], [P10, P11]]: convex, nonconvex (one concave corner) or twisted; not degenerate."""
    wanted = {"convex": 0, "nonconvex": 1, "twisted": 2}[kind]
    while True:
        corners = rng.uniform(-5, 5, (4, 2))
        quad = np.array([[corners[0], corners[2]], [corners[1], corners[3]]])
        c = quad_maps.corner_determinants(quad)
        if np.abs(c).min() > 3.0 and int((c < 0).sum()) == wanted:
            return quad.tolist()


def _weights(rng, quad) -> list:
    """Random nonzero w00, w10, w01 (either sign) and the w11 that makes them birational."""
    w = rng.uniform(0.3, 3.0, (2, 2)) * rng.choice([-1.0, 1.0], (2, 2))
    w[1, 1] = quad_maps.birational_weight(quad, w)
    return w.tolist()


# --- 21.bilinear_inverse --------------------------------------------------------------------------------


def bilinear_inverse_cases(rng):
    cases = [
        Case(EXAMPLE, (QUAD, BILINEAR.inputs["point"].tolist()), visible=True),  # (1/3, 3/4) and (2, 2)
        Case(EXAMPLE, (QUAD, [6.0, 2.0]), visible=True),  # (1/3, 3/8) and (5/2, 2)
        Case(EXAMPLE, (QUAD, [12.0, 4.0]), visible=True),  # the corner P11, and another pre-image
        Case(EDGE, (QUAD, [20.0, 5.0]), visible=True),  # f(x, y) < 0: no real pre-image
        Case(EDGE, (QUAD, [36.0, 0.0]), visible=True),  # f = 0: the two pre-images meet, reported once
        Case(EDGE, (QUAD, [0.0, 0.0]), visible=True),
        Case(EDGE, (PARALLELOGRAM, [2.0, 1.0]), visible=True),  # an affine map: one pre-image
        Case(EDGE, (PARALLELOGRAM, [-3.0, 7.0]), visible=True),
        Case(EDGE, (TRAPEZOID_T, [2.0, 1.0]), visible=True),  # a linear equation in s
        Case(EDGE, (TRAPEZOID_T, [5.0, 4.0]), visible=True),  # no pre-image: the line through the vertex
        Case(EDGE, (TRAPEZOID_S, [1.0, 1.0]), visible=True),  # a linear equation in t
        Case(EDGE, (TRAPEZOID_S, [0.5, 2.5]), visible=True),
        Case(EDGE, (CONCAVE_QUAD, [7.0, 3.0]), visible=True),
        Case(EDGE, (TWISTED_QUAD, [5.0, 2.0]), visible=True),
    ]
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(6):
            quad = _quad(rng, kind)
            s, t = rng.uniform(-0.5, 1.5, 2)
            point = quad_maps.quad_map(quad, s, t)
            cases.append(Case(RANDOM, (quad, point.tolist())))
    cases += [
        Case(BAD, (TRAPEZOID_T, [2.0, 4.0])),  # the vertex of the pencil: infinitely many pre-images
        Case(BAD, (COINCIDING, [1.0, 1.0])),
        Case(BAD, (ON_A_LINE, [1.0, 1.0])),
        Case(BAD, ([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], [0.5, 0.5])),  # (4, 2), not (2, 2, 2)
        Case(BAD, (QUAD, [8.0, 4.0, 1.0])),
        Case(BAD, (QUAD, [[8.0, 4.0]])),
    ]
    return cases


# --- 21.pencil_axes -------------------------------------------------------------------------------------


def same_points_up_to_scale(expected, received) -> str | None:
    """Two homogeneous triples, each a nonzero multiple (either sign) of the expected one."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    if not isinstance(received, (tuple, list)) or len(received) != 2:
        return "expected a tuple (As, At) of two homogeneous triples"
    for name, want, got in zip(("As", "At"), expected, received):
        try:
            got = np.asarray(got, dtype=float)
        except (TypeError, ValueError):
            return f"{name}: expected three numbers"
        if got.shape != (3,) or not np.all(np.isfinite(got)):
            return f"{name}: expected three finite numbers (X, Y, W), got {np.asarray(got).tolist()}"
        if not np.any(got):
            return f"{name}: got (0, 0, 0), which is no point"
        gap = np.linalg.norm(np.cross(want / np.linalg.norm(want), got / np.linalg.norm(got)))
        if gap > 1e-9:
            shown = want / (want[2] if abs(want[2]) > 1e-12 else np.abs(want).max())
            return f"{name}: expected a multiple of {np.round(shown, 6).tolist()}, got {np.round(got, 6).tolist()}"
    return None


def pencil_axes_cases(rng):
    cases = [
        Case(EXAMPLE, (QUAD,), visible=True),  # As = (12, 9), At = (20, 0)
        Case(EXAMPLE, (CONCAVE_QUAD,), visible=True),  # As = (48/13, 36/13), At = (5, 0)
        Case(EXAMPLE, (TWISTED_QUAD,), visible=True),
        Case(EXAMPLE, (COLLINEAR_QUAD,), visible=True),  # As = Q01, At = Q10
        Case(EDGE, (PARALLELOGRAM,), visible=True),  # both at infinity
        Case(EDGE, (TRAPEZOID_T,), visible=True),  # At at infinity
        Case(EDGE, (TRAPEZOID_S,), visible=True),  # As at infinity
        Case(EDGE, ([[[0.0, 0.0], [0.0, 1.0]], [[1.0, 0.0], [1.0, 1.0]]],), visible=True),  # the unit square
    ]
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(5):
            cases.append(Case(RANDOM, (_quad(rng, kind),)))
    cases += [
        Case(BAD, (COINCIDING,)),
        Case(BAD, (ON_A_LINE,)),
        Case(BAD, ([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],)),
    ]
    return cases


# --- 21.birational_weight --------------------------------------------------------------------------------


def birational_weight_cases(rng):
    w10 = float(TWISTED.results["w10_with_unit_others"])
    cases = [
        Case(EXAMPLE, (QUAD, W53), visible=True),  # w01 = 5/3 keeps w11 = 1
        Case(EXAMPLE, (QUAD, UNIT), visible=True),  # 3/5: the same ratio
        Case(EXAMPLE, (CONCAVE_QUAD, UNIT), visible=True),  # -4.2
        Case(EXAMPLE, (TWISTED_QUAD, [[1.0, 1.0], [w10, 1.0]]), visible=True),  # w10 = 16: w11 = 1
        Case(EXAMPLE, (TWISTED_QUAD, TWISTED.inputs["weights"].tolist()), visible=True),  # w10 = w01 = 4
        Case(EXAMPLE, (TWISTED_QUAD, UNIT), visible=True),  # 1/16
        Case(EXAMPLE, (COLLINEAR_QUAD, UNIT), visible=True),  # 0
        Case(EDGE, (QUAD, [[1.0, 5.0 / 3.0], [1.0, 123.0]]), visible=True),  # weights[1][1] is ignored
        Case(EDGE, (QUAD, [[2.0, -1.0], [0.5, 1.0]]), visible=True),
        Case(EDGE, (PARALLELOGRAM, UNIT), visible=True),  # all four determinants equal: 1
        Case(EDGE, (TRAPEZOID_T, [[1.0, 2.0], [3.0, 1.0]]), visible=True),
        Case(EDGE, ([[[0.0, 0.0], [0.0, 1.0]], [[1.0, 0.0], [3.0, 3.0]]], UNIT), visible=True),
    ]
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(5):
            quad = _quad(rng, kind)
            cases.append(Case(RANDOM, (quad, _weights(rng, quad))))
    cases += [
        Case(BAD, (QUAD, [[0.0, 1.0], [1.0, 1.0]])),  # w00 = 0
        Case(BAD, (QUAD, [[1.0, 0.0], [1.0, 1.0]])),  # w01 = 0
        Case(BAD, ([[[0.0, 0.0], [0.0, 2.0]], [[1.0, 0.0], [2.0, 0.0]]], UNIT)),  # Q00, Q10, Q11 collinear
        Case(BAD, (COINCIDING, UNIT)),
        Case(BAD, (QUAD, [1.0, 1.0, 1.0])),
        Case(BAD, (QUAD, [[1.0, 1.0, 1.0], [1.0, 1.0, 1.0]])),
    ]
    return cases


# --- 21.birational_inverse --------------------------------------------------------------------------------


def _grid(quad, weights, rng, count=8) -> list:
    """Images of random parameters in [-0.25, 1.25]², away from the map's line at infinity."""
    h = quad_maps.homogeneous_quad(quad, weights)
    points = []
    while len(points) < count:
        s, t = rng.uniform(-0.25, 1.25, 2)
        w = h[0, 0, 2] * (1 - s) * (1 - t) + h[1, 0, 2] * s * (1 - t) + h[0, 1, 2] * (1 - s) * t + h[1, 1, 2] * s * t
        if abs(w) > 0.1 * np.abs(h[:, :, 2]).max():
            points.append(quad_maps.quad_map(quad, s, t, weights).tolist())
    return points


def birational_inverse_cases(rng):
    concave = CONCAVE.inputs["weights"].copy()
    concave[1, 1] = CONCAVE.results["w11"]
    collinear = COLLINEAR.inputs["weights"].copy()
    collinear[1, 1] = 0.0
    collinear_points = quad_maps.quad_map(COLLINEAR_QUAD, *COLLINEAR.inputs["parameters"].T, collinear).tolist()
    twisted = TWISTED.inputs["weights"].tolist()
    trapezoid = [[1.0, 2.0], [3.0, quad_maps.birational_weight(TRAPEZOID_T, [[1.0, 2.0], [3.0, 1.0]])]]
    cases = [
        Case(EXAMPLE, (QUAD, W53, BIRATIONAL.inputs["point"].tolist()), visible=True),  # (2/5, 2/3)
        Case(EXAMPLE, (QUAD, W53, [[8.0, 4.0], [12.0, 2.0], [6.0, 1.0], [0.0, 0.0]]), visible=True),
        Case(EXAMPLE, (CONCAVE_QUAD, concave.tolist(), [[4.0, 1.0], [7.0, 3.0], [2.0, 1.2]]), visible=True),
        Case(EXAMPLE, (TWISTED_QUAD, twisted, [[5.0, 2.0], [7.0, 1.0], [4.0, 5.5]]), visible=True),
        Case(EXAMPLE, (TWISTED_QUAD, TWISTED.results["negative_weights"].tolist(), [[5.0, 2.0], [7.0, 1.0]]),
             visible=True),
        Case(EXAMPLE, (COLLINEAR_QUAD, collinear.tolist(), collinear_points), visible=True),  # (21.8) is 0/0 here
        Case(EDGE, (PARALLELOGRAM, UNIT, [[2.0, 1.0], [-1.0, 3.0]]), visible=True),  # both axes at infinity
        Case(EDGE, (TRAPEZOID_T, trapezoid, [[2.0, 1.0], [1.0, 0.5]]), visible=True),  # At at infinity
        Case(EDGE, (QUAD, W53, [[0.0, 0.0], [12.0, 0.0], [8.0, 6.0], [12.0, 4.0]]), visible=True),  # the corners
        Case(EDGE, (QUAD, [[2.0, 10.0 / 3.0], [2.0, 2.0]], [[8.0, 4.0]]), visible=True),  # all weights doubled
    ]
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(5):
            quad = _quad(rng, kind)
            weights = _weights(rng, quad)
            cases.append(Case(RANDOM, (quad, weights, _grid(quad, weights, rng))))
    cases += [
        Case(BAD, (QUAD, UNIT, [8.0, 4.0])),  # not birational
        Case(BAD, (TWISTED_QUAD, [[1.0, -2.0], [-2.0, 1.0]], [5.0, 2.0])),  # the notes' -2: not birational
        Case(BAD, (QUAD, W53, [12.0, 9.0])),  # the axis As: s is 0/0
        Case(BAD, (QUAD, W53, [[1.0, 2.0, 3.0]])),
        Case(BAD, (COINCIDING, UNIT, [1.0, 1.0])),
        Case(BAD, (QUAD, [1.0, 1.0, 1.0, 1.0], [8.0, 4.0])),
    ]
    return cases


# --- 21.projective_weights -----------------------------------------------------------------------------------


def projective_weights_cases(rng):
    cases = [
        Case(EXAMPLE, (QUAD,), visible=True),  # 2 : 5 : 6 : 9
        Case(EXAMPLE, (CONCAVE_QUAD,), visible=True),  # a negative weight at the concave corner's opposite
        Case(EXAMPLE, (TWISTED_QUAD,), visible=True),  # two negative determinants
        Case(EDGE, (PARALLELOGRAM,), visible=True),  # affine: all ones
        Case(EDGE, (TRAPEZOID_T,), visible=True),
        Case(EDGE, ([[[1.0, 1.0], [1.0, 2.0]], [[2.0, 1.0], [2.0, 2.0]]],), visible=True),
        Case(EDGE, ([[[0.0, 0.0], [-1.0, 4.0]], [[5.0, 1.0], [2.0, 2.0]]],), visible=True),
    ]
    for kind in ("convex", "nonconvex", "twisted"):
        for _ in range(5):
            cases.append(Case(RANDOM, (_quad(rng, kind),)))
    cases += [
        Case(BAD, (COLLINEAR_QUAD,)),  # Q10, Q11, Q01 collinear: no projective map
        Case(BAD, (COINCIDING,)),
        Case(BAD, (ON_A_LINE,)),
        Case(BAD, ([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="21.bilinear_inverse",
        reference=quad_maps.bilinear_inverse,
        cases=bilinear_inverse_cases,
        compare=close(1e-9, 1e-9),
        hint="With e = P10 - P00, f = P01 - P00, g = P00 - P10 - P01 + P11, h = X - P00: "
        "(e×g) s² + (e×f - h×g) s - h×f = 0, then t from s (or, when the edges s = 0 and s = 1 are parallel, "
        "the same with the roles of s and t exchanged). Every real root counts, sorted by s; a trapezoid's "
        "equation is linear.",
        rules={
            EDGE: "Every real pre-image counts: $s$ and $t$ are not restricted to $[0,1]$.",
            BAD: "Raise a ValueError for a bad quad (see the conventions), if point does not have shape (2,), and "
                "if the point has infinitely many pre-images",
        },
    ),
    Exercise(
        id="21.pencil_axes",
        reference=quad_maps.pencil_axes,
        cases=pencil_axes_cases,
        compare=same_points_up_to_scale,
        hint="As = (Q00 × Q01) × (Q10 × Q11): the meet of the edges s = 0 and s = 1; At = (Q00 × Q10) × (Q01 × Q11), "
        "with Qij = (xij, yij, 1). Keep the homogeneous triples: parallel edges meet at infinity (W = 0).",
        rules={
            EDGE: "where edges are parallel the axis is at infinity, $W=0$",
            BAD: "Raise a ValueError for a bad quad (see the conventions).",
        },
    ),
    Exercise(
        id="21.birational_weight",
        reference=quad_maps.birational_weight,
        cases=birational_weight_cases,
        compare=close(1e-9, 1e-12),
        hint="w00 w11 C10 C01 = w10 w01 C00 C11 with the signed corner determinants C00 = |Q01 Q00 Q10|, "
        "C10 = |Q00 Q10 Q11|, C11 = |Q10 Q11 Q01|, C01 = |Q11 Q01 Q00|: keep their signs (a concave corner "
        "gives a negative weight).",
        rules={
            EDGE: "**Keep the signs** of the determinants",
            BAD: "Raise a ValueError for a bad quad, if weights does not have shape (2, 2), if $w_{00}$, $w_{10}$ "
                "or $w_{01}$ is zero, and if no $w_{11}$ can satisfy the condition",
        },
    ),
    Exercise(
        id="21.birational_inverse",
        reference=quad_maps.birational_inverse,
        cases=birational_inverse_cases,
        compare=close(1e-9, 1e-9),
        hint="s = |As Q̃01 P| / (|As Q̃01 P| - |As Q̃11 P|) or, when that is 0/0, |As Q̃00 P| / (|As Q̃00 P| - "
        "|As Q̃10 P|), with the weighted Q̃ij = wij Qij and the homogeneous axis As; t the same with At, "
        "Q̃10, Q̃11 (or Q̃00, Q̃01).",
        rules={
            EDGE: "(zeros allowed: the collinear case has $w_{11}=0$)",
            BAD: "Raise a ValueError for a bad quad; if weights does not have shape (2, 2) or is all zeros; if the "
                "weights are not birational",
        },
    ),
    Exercise(
        id="21.projective_weights",
        reference=quad_maps.projective_weights,
        cases=projective_weights_cases,
        compare=close(1e-9, 1e-12),
        hint="w00 : w10 : w01 : w11 = |Q10 Q01 Q11| : |Q00 Q01 Q11| : |Q00 Q11 Q10| : |Q00 Q01 Q10| (signed "
        "determinants of the other three corners), divided by the first so that w00 = 1.",
        rules={
            EDGE: "Keep the signs (a non-convex or twisted quad has negative weights).",
            BAD: "Raise a ValueError for a bad quad and when three corners are collinear",
        },
    ),
]

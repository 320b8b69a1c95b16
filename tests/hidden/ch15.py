"""Hidden grading suite of chapter 15: tensor-product surfaces, NURBS and T-splines."""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import surfaces

# --- tensor-product patches, normals, corner curvatures, tessellation -------------------------------------
#
# Fixed cases: the degree (3, 2) patch of Figs. 15.1-15.4 (m ≠ n and s ≠ t, so swapped directions show), the
# torus patch of chapter 16 and a rational cylinder (rational cases at interior points, where ignoring the
# weights turns the normal), the notes' tessellation example (150 × 130), the cases the notes leave open
# (ruled, bilinear, planar), and course surfaces with known curvature (paraboloid, saddle, cylinder).
# Random cases come from the generator the grader passes in.

EXAMPLE = "course examples"
NOTES = "notes examples"
RATIONAL = "rational patches"
POLYNOMIAL = "polynomial input"
EDGE = "edge cases"
CORNERS = "corners"
SHAPES = "scalar vs array parameters"
DEGREES = "unequal degrees"
SIGNS = "orientation and signs"
CASES = "special cases of the bound"
NORMS = "vector norms"
RANDOM = "random"
BAD = "bad input"

FIG = notes_example("15.patch")
TESS = notes_example("15.tessellation")
SPECIAL = notes_example("15.special_tessellations")
CURV = notes_example("15.corner_curvatures")
TORUS = notes_example("16.torus")

FIG_NET = [[[float(i), 1.5 * j, float(FIG.inputs["z"][i, j])] for j in range(3)] for i in range(4)]
FIG_WEIGHTS = [[1.0, 2.0, 1.0], [0.5, 1.0, 3.0], [2.0, 1.0, 1.0], [1.0, 0.5, 1.0]]
TORUS_NET, TORUS_WEIGHTS = (a.tolist() for a in TORUS.args("points", "weights"))
CYLINDER, CYLINDER_WEIGHTS = (a.tolist() for a in CURV.args("cylinder", "cylinder_weights"))
TESS_NET = [[[float(i), float(j), float(TESS.inputs["z"][i, j])] for j in range(4)] for i in range(4)]
SADDLE = [[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0), (1.0, 1.0, 1.0)]]
TS = np.linspace(0.0, 1.0, 7)


def _lattice(z, dx=1.0, dy=1.0):
    z = np.asarray(z, dtype=float)
    i, j = np.meshgrid(np.arange(z.shape[0]), np.arange(z.shape[1]), indexing="ij")
    return np.stack([dx * i, dy * j, z], axis=2).tolist()


PARABOLOID = _lattice(CURV.inputs["paraboloid_z"], 0.5, 0.5)
SADDLE_2 = _lattice(CURV.inputs["saddle_z"], 0.5, 0.5)


def _with_weights(args, weights):
    return args if weights is None else args + (weights,)


def _random_patch(rng, low=1, high=5, rational=True, d=3):
    m, n = (int(v) for v in rng.integers(low, high + 1, 2))
    points = rng.uniform(-3, 3, (m + 1, n + 1, d))
    return points, (rng.uniform(0.4, 2.5, (m + 1, n + 1)) if rational else None)


def _graph_patch(rng, m, n, rational):
    """A net over a perturbed lattice with random heights: a well-shaped corner."""
    i, j = np.meshgrid(np.arange(m + 1), np.arange(n + 1), indexing="ij")
    xy = np.stack([i + rng.uniform(-0.2, 0.2, i.shape), j + rng.uniform(-0.2, 0.2, j.shape)], axis=2)
    points = np.concatenate([xy, rng.uniform(-1.5, 1.5, (m + 1, n + 1, 1))], axis=2)
    return points, (rng.uniform(0.5, 2.0, (m + 1, n + 1)) if rational else None)


# Rules: sentences of the statements in exercises/15-tensor-product-surfaces.ipynb, word for word.
PATCH_POINT_RULES = {
    BAD: "Raise a ValueError for a net that is not (m+1, n+1, d), for weights of the wrong shape or with a zero, "
    "for s and t that do not broadcast, and where the weight of the patch is zero.",
    SHAPES: "Two numbers give an array of shape (d,); k pairs give an array of shape (k, d).",
    RATIONAL: "A rational patch is the projection of the homogeneous patch.",
    EDGE: "A degree of 0 in either direction is allowed, and s, t may lie outside [0, 1].",
    DEGREES: "The first index of points runs along s, the second along t.",
    POLYNOMIAL: "With weights=None every weight is 1.",
    CORNERS: "The patch passes through its four corner control points.",
}
PATCH_NORMAL_RULES = {
    BAD: "Raise a ValueError for a net that is not (m+1, n+1, 3), for bad weights, for s and t that do not "
    "broadcast, and where P_s × P_t is the zero vector.",
    SHAPES: "Two numbers give an array of shape (3,); k pairs give an array of shape (k, 3).",
    RATIONAL: "For a rational patch the weights matter at every point, not only at the corners.",
    CORNERS: "The normal must also be right at s = 1 and t = 1.",
    SIGNS: "The normal is P_s × P_t divided by its length, never P_t × P_s.",
    DEGREES: "The first index of points runs along s, the second along t.",
    POLYNOMIAL: "With weights=None every weight is 1.",
}
CURVATURE_RULES = {
    BAD: "Raise a ValueError for a net that is not (p+1, q+1, 3) with p, q >= 1, for bad weights, and when "
    "P00, P10, P01 are collinear.",
    DEGREES: "The factor (p-1)/p belongs to h20 and the factor (q-1)/q to h02.",
    SIGNS: "Heights are signed: positive on the side of a × b.",
    RATIONAL: "Weights enter through the formulas above; weights=None means all weights 1.",
    POLYNOMIAL: "Weights enter through the formulas above; weights=None means all weights 1.",
}
TESSELLATION_RULES = {
    BAD: "Raise a ValueError for a net that is not (m+1, n+1, d) and for a tolerance that is not a positive number.",
    CASES: "Treat a bound as zero only when it is exactly 0.",
    NORMS: "Use Euclidean lengths of the difference vectors, all coordinates together.",
    EDGE: "Neither step may exceed 1.",
}


# --- 15.patch_point ---------------------------------------------------------------------------------------


def patch_point_cases(rng):
    cases = [
        Case(EXAMPLE, (FIG_NET, 0.2, 0.7), visible=True),
        Case(EXAMPLE, (FIG_NET, FIG.inputs["iso_values"], 0.4), visible=True),
        Case(RATIONAL, (FIG_NET, [0.3, 0.8], [0.6, 0.1], FIG_WEIGHTS), visible=True),
        Case(RATIONAL, (TORUS_NET, TORUS.inputs["s"], TORUS.inputs["t"], TORUS_WEIGHTS), visible=True),
        Case(RATIONAL, (CYLINDER, TS, TS[::-1], CYLINDER_WEIGHTS)),
        Case(RATIONAL, (SADDLE, 0.5, 0.5, [[1.0, -0.5], [2.0, 1.0]])),  # a negative weight, still a point
        Case(POLYNOMIAL, (SADDLE, 0.5, 0.25), visible=True),
        Case(DEGREES, (np.transpose(FIG_NET, (1, 0, 2)), 0.7, 0.2), visible=True),  # degree (2, 3)
        Case(DEGREES, (rng.uniform(-2, 2, (2, 6, 3)), [0.1, 0.9], [0.3, 0.3])),  # (1, 5)
        Case(CORNERS, (FIG_NET, [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0], FIG_WEIGHTS)),
        Case(EDGE, ([[(1.0, 2.0), (3.0, 1.0), (4.0, 4.0)]], [0.0, 0.5, 1.0], 0.25), visible=True),  # degree (0, 2)
        Case(EDGE, (FIG_NET, [-0.5, 1.5], [1.25, -0.25])),  # beyond [0, 1]
        Case(EDGE, (rng.uniform(-2, 2, (4, 3, 5)), 0.3, 0.6)),  # d = 5
        Case(SHAPES, (FIG_NET, TS, 0.3, FIG_WEIGHTS), visible=True),  # t a number: broadcast to every s
        Case(SHAPES, (FIG_NET, 0.3, TS)),
        Case(SHAPES, (FIG_NET, np.array([0.3]), np.array([0.6]))),
        Case(SHAPES, (FIG_NET, np.array(0.3), 0.6)),
    ]
    for _ in range(14):
        points, weights = _random_patch(rng, low=0, rational=rng.uniform() < 0.6, d=int(rng.choice([2, 3])))
        k = int(rng.integers(1, 7))
        cases.append(Case(RANDOM, _with_weights((points, rng.uniform(0, 1, k), rng.uniform(0, 1, k)), weights)))
    cases += [
        Case(BAD, ([(0.0, 0.0), (1.0, 1.0)], 0.5, 0.5)),  # a curve, not a net
        Case(BAD, (FIG_NET, 0.5, 0.5, [[1.0, 1.0, 1.0]] * 3)),  # weights of the wrong shape
        Case(BAD, (FIG_NET, 0.5, 0.5, [[1.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [1.0, 1.0, 1.0]])),
        Case(BAD, (FIG_NET, [0.1, 0.2], [0.1, 0.2, 0.3])),  # s and t do not broadcast
        Case(BAD, (SADDLE, 0.5, 0.5, [[1.0, 1.0], [-1.0, -1.0]])),  # the weight vanishes at (1/2, 1/2)
    ]
    return cases


# --- 15.patch_normal --------------------------------------------------------------------------------------


def patch_normal_cases(rng):
    bent = _graph_patch(np.random.default_rng(151), 3, 2, True)
    cases = [
        Case(EXAMPLE, (TORUS_NET, TORUS.inputs["s"], TORUS.inputs["t"], TORUS_WEIGHTS), visible=True),
        Case(EXAMPLE, (FIG_NET, 0.2, 0.7), visible=True),
        Case(POLYNOMIAL, (SADDLE, TS, TS[::-1]), visible=True),
        Case(RATIONAL, (FIG_NET, [0.3, 0.55, 0.8], [0.6, 0.45, 0.1], FIG_WEIGHTS), visible=True),
        Case(RATIONAL, (bent[0], [0.25, 0.5, 0.7], [0.4, 0.5, 0.65], bent[1])),
        Case(RATIONAL, (CYLINDER, [0.3, 0.6], [0.5, 0.2], CYLINDER_WEIGHTS)),
        Case(CORNERS, (FIG_NET, [0.0, 1.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0], FIG_WEIGHTS), visible=True),
        Case(CORNERS, (TORUS_NET, [1.0, 1.0, 0.4], [0.3, 1.0, 1.0], TORUS_WEIGHTS)),
        Case(SIGNS, (np.asarray(FIG_NET)[::-1], [0.2, 0.9], [0.7, 0.4])),  # s reversed: the normal turns over
        Case(DEGREES, (np.transpose(FIG_NET, (1, 0, 2)), 0.7, 0.2, np.transpose(FIG_WEIGHTS))),
        Case(SHAPES, (FIG_NET, TS, 0.3, FIG_WEIGHTS), visible=True),
        Case(SHAPES, (FIG_NET, np.array([0.3]), np.array([0.6]))),
        Case(SHAPES, (FIG_NET, 0.3, 0.6, FIG_WEIGHTS)),
    ]
    for _ in range(14):
        m, n = (int(v) for v in rng.integers(1, 5, 2))
        points, weights = _graph_patch(rng, m, n, rational=rng.uniform() < 0.7)
        k = int(rng.integers(1, 7))
        s, t = rng.uniform(0, 1, k), rng.uniform(0, 1, k)
        cases.append(Case(RANDOM, _with_weights((points, s, t), weights)))
    collapsed = np.array(FIG_NET)
    collapsed[1, 0] = collapsed[0, 0]  # P10 = P00: P_s = 0 at the corner (0, 0)
    cases += [
        Case(BAD, (np.asarray(FIG_NET)[..., :2], 0.5, 0.5)),  # a patch in the plane has no normal
        Case(BAD, (collapsed, 0.0, 0.0)),
        Case(BAD, (FIG_NET, 0.5, 0.5, [[1.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [1.0, 1.0, 1.0]])),
        Case(BAD, (FIG_NET, [0.1, 0.2], [0.1, 0.2, 0.3])),
    ]
    return cases


# --- 15.corner_curvatures ---------------------------------------------------------------------------------


def corner_curvatures_cases(rng):
    cases = [
        Case(EXAMPLE, (PARABOLOID,), visible=True),
        Case(EXAMPLE, (SADDLE_2,), visible=True),
        Case(EXAMPLE, (CYLINDER, CYLINDER_WEIGHTS), visible=True),
        Case(POLYNOMIAL, (SADDLE,), visible=True),  # degree (1, 1): only h11 counts
        Case(DEGREES, (FIG_NET,), visible=True),  # degree (3, 2)
        Case(DEGREES, (np.transpose(FIG_NET, (1, 0, 2)),)),  # degree (2, 3)
        Case(DEGREES, (_graph_patch(np.random.default_rng(152), 1, 3, False)[0],)),  # (1, 3): no h20 term
        Case(DEGREES, (_graph_patch(np.random.default_rng(153), 4, 2, False)[0],)),
        Case(SIGNS, (np.transpose(PARABOLOID, (1, 0, 2)),)),  # a × b points down: the mean curvature is -1
        Case(SIGNS, ((np.asarray(FIG_NET) * [1.0, 1.0, -1.0]).tolist(),)),  # negative heights
        Case(RATIONAL, (FIG_NET, FIG_WEIGHTS), visible=True),
        Case(RATIONAL, (np.transpose(FIG_NET, (1, 0, 2)), np.transpose(FIG_WEIGHTS))),
    ]
    for _ in range(14):
        m, n = (int(v) for v in rng.integers(1, 5, 2))
        points, weights = _graph_patch(rng, m, n, rational=rng.uniform() < 0.7)
        cases.append(Case(RANDOM, _with_weights((points,), weights)))
    line = np.array(PARABOLOID)
    line[0, 1] = 2 * line[1, 0]  # P01 on the line through P00 and P10
    cases += [
        Case(BAD, (line,)),
        Case(BAD, (np.asarray(PARABOLOID)[..., :2],)),
        Case(BAD, ([[(0.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 2.0, 1.0)]],)),  # degree 0 in s
        Case(BAD, (PARABOLOID, [[1.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0]])),
        Case(BAD, (PARABOLOID, [[1.0, 1.0], [1.0, 1.0]])),
    ]
    return cases


# --- 15.tessellation_steps --------------------------------------------------------------------------------


def tessellation_steps_cases(rng):
    tol = float(SPECIAL.inputs["tol"])
    ruled = SPECIAL.inputs["ruled"].tolist()
    wavy = _lattice(TESS.inputs["z"])
    skewed = np.array(wavy)
    skewed[..., 0] += np.array([[0, 0, 0, 0], [0, 1, 0, 0], [0, 0, 2, 0], [1, 0, 0, 0]])  # x no longer linear
    cases = [
        Case(NOTES, (TESS_NET, float(TESS.inputs["tol"])), visible=True),
        Case(NOTES, (TESS_NET, 0.01), visible=True),
        Case(NOTES, (np.transpose(TESS_NET, (1, 0, 2)), 0.001)),
        Case(CASES, (ruled, tol), visible=True),  # M1 = 0
        Case(CASES, (np.transpose(ruled, (1, 0, 2)), tol)),  # M3 = 0
        Case(CASES, (SPECIAL.inputs["bilinear"].tolist(), tol), visible=True),  # M1 = M3 = 0
        Case(CASES, (SPECIAL.inputs["plane"].tolist(), tol), visible=True),  # all zero: one cell
        Case(CASES, ([[(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (2.0, 1.0, 0.0)]], tol)),  # degree (0, 2)
        Case(NORMS, (skewed, 0.001)),
        Case(NORMS, ((np.asarray(TESS_NET)[..., [2, 0, 1]]).tolist(), 0.002)),  # the heights in x
        Case(NORMS, (rng.uniform(-1, 1, (3, 4, 5)), 0.01)),  # d = 5
        Case(EDGE, (TESS_NET, 100.0)),  # a loose tolerance: one cell
        Case(EDGE, (SADDLE, 0.3)),  # 4 tol / M2 > 1
    ]
    for _ in range(14):
        points, _ = _random_patch(rng, low=1, high=5, rational=False, d=int(rng.choice([2, 3])))
        cases.append(Case(RANDOM, (points, float(10 ** rng.uniform(-4, -1)))))
    cases += [
        Case(BAD, (TESS_NET, 0.0)),
        Case(BAD, (TESS_NET, -0.001)),
        Case(BAD, ([(0.0, 0.0), (1.0, 1.0)], 0.01)),
        Case(BAD, (TESS_NET, [0.001, 0.002])),
    ]
    return cases


SURFACE_EXERCISES = [
    Exercise(
        id="15.patch_point",
        reference=surfaces.patch_point,
        cases=patch_point_cases,
        compare=close(1e-9, 1e-9),
        hint="Lift to H_ij = w_ij (P_ij, 1), evaluate Σ_i Σ_j H_ij B_i^m(s) B_j^n(t) with m = points.shape[0] - 1 "
        "along s and n = points.shape[1] - 1 along t, then divide by the last coordinate.",
        rules=PATCH_POINT_RULES,
    ),
    Exercise(
        id="15.patch_normal",
        reference=surfaces.patch_normal,
        cases=patch_normal_cases,
        compare=close(1e-9, 1e-9),
        hint="Subdivide the homogeneous net so that (s, t) becomes a corner, or differentiate the rational patch "
        "by the quotient rule; the normal is P_s × P_t over its length, with P_s along the first index.",
        rules=PATCH_NORMAL_RULES,
    ),
    Exercise(
        id="15.corner_curvatures",
        reference=surfaces.corner_curvatures,
        cases=corner_curvatures_cases,
        compare=close(1e-9, 1e-9),
        hint="a = P10 - P00, b = P01 - P00, n = a × b / |a × b|, h_ij = (P_ij - P00)·n (signed). The factor "
        "(p-1)/p uses the degree of the first index and goes with h20.",
        rules=CURVATURE_RULES,
    ),
    Exercise(
        id="15.tessellation_steps",
        reference=surfaces.tessellation_steps,
        cases=tessellation_steps_cases,
        compare=exact(),
        hint="M1 = m(m-1) max |second difference in i|, M2 = mn max |mixed difference|, M3 = n(n-1) max |second "
        "difference in j|; k = sqrt(M3/M1), δt = sqrt(8 tol / (M1 k² + 2 M2 k + M3)), δs = k δt, then ceilings.",
        rules=TESSELLATION_RULES,
    ),
]

# --- T-splines ---------------------------------------------------------------------------------------------

TSPLINE_EXERCISES = []

EXERCISES = SURFACE_EXERCISES + TSPLINE_EXERCISES

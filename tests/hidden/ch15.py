"""Hidden grading suite of chapter 15: tensor-product surfaces, NURBS and T-splines."""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close, exact
from cagd_ref import surfaces, tsplines

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
#
# Fixed cases: the notes' numerical example (Fig. 15.17, all 28 control points, the blending functions at
# (3, 4)), the Rule-1 examples of Fig. 15.15 and the mesh of Fig. 15.20 before and after local refinement
# (the same surface). The meshes are the plain dicts of the statement, built by `tsplines.tmesh`. Random
# cases are grids with integer knot intervals from which interior vertices were taken out, each leaving a
# gap in its row or in its column (two T-junctions), with a unit or a random frame.

T_EXAMPLE = "notes examples"
T_COURSE = "course examples"
T_JUNCTIONS = "T-junctions on the ray"
T_FRAME = "frame knots"
T_RATIONAL = "rational"
T_SHAPES = "scalar vs array parameters"
T_DOMAIN = "domain boundary"
T_RANDOM = "random"
T_BAD = "bad input"

TMESH = notes_example("15.tmesh")
RULE1 = notes_example("15.rule1")
REFINEMENT = notes_example("15.refinement")


def _plain_mesh(mesh) -> dict:
    """A T-mesh dict of plain lists (integer edges), as a student builds it."""
    plain = {"vertices": np.asarray(mesh["vertices"], dtype=float).tolist(),
             "edges": np.asarray(mesh["edges"]).astype(int).tolist()}
    if mesh.get("frame") is not None:
        plain["frame"] = np.asarray(mesh["frame"], dtype=float).tolist()
    return plain


E2_MESH = _plain_mesh(TMESH.inputs["mesh"])
E2_POINTS = np.column_stack([TMESH.inputs["mesh"]["vertices"], TMESH.inputs["heights"]]).tolist()
E3_MESH = _plain_mesh(RULE1.inputs["mesh"])
E4_MESH = _plain_mesh(REFINEMENT.inputs["mesh"])
E4_POINTS = [[s, t, (s - 3.0) * (t - 4.0) / 8.0] for s, t in E4_MESH["vertices"]]
E2_UNFRAMED = {"vertices": E2_MESH["vertices"], "edges": E2_MESH["edges"]}
E2_FRAMED = dict(E2_MESH, frame=[[-3.0, -0.5, 8.5, 12.0], [-1.5, -1.0, 7.25, 9.0]])


def _refined_e4():
    mesh, points, weights, _ = tsplines.local_refinement(
        E4_MESH, E4_POINTS, REFINEMENT.inputs["new_vertices"], REFINEMENT.inputs["new_edges"].astype(int))
    return _plain_mesh(mesh), points.tolist(), weights.tolist()


def _random_tmesh(rng, framed=None):
    """A grid with integer knot intervals, some interior vertices removed (each opens its row or its column)."""
    count_s, count_t = (int(v) for v in rng.integers(4, 8, 2))
    s_lines = np.cumsum(np.r_[0, rng.integers(1, 4, count_s - 1)]).astype(float)
    t_lines = np.cumsum(np.r_[0, rng.integers(1, 4, count_t - 1)]).astype(float)
    gaps = {}
    for i in range(1, count_s - 1):
        for j in range(1, count_t - 1):
            if rng.uniform() < 0.3:
                gaps[(s_lines[i], t_lines[j])] = "row" if rng.uniform() < 0.5 else "column"
    vertices = [(s, t) for t in t_lines for s in s_lines if (s, t) not in gaps]
    index = {v: k for k, v in enumerate(vertices)}
    edges = []
    for axis, lines, others in ((1, t_lines, s_lines), (0, s_lines, t_lines)):
        kind = "row" if axis == 1 else "column"
        for value in lines:
            on_line = [(o, value) if axis == 1 else (value, o) for o in others]
            present = [p for p in on_line if p in index]
            for a, b in zip(present[:-1], present[1:]):
                between = [p for p in on_line if p in gaps and a[1 - axis] < p[1 - axis] < b[1 - axis]]
                if not any(gaps[p] == kind for p in between):
                    edges.append([index[a], index[b]])
    frame = None
    use_frame = rng.uniform() < 0.5 if framed is None else framed
    if use_frame:
        frame = [[s_lines[0] - 2.5, s_lines[0] - 0.5, s_lines[-1] + 1.5, s_lines[-1] + 4.0],
                 [t_lines[0] - 1.5, t_lines[0] - 0.25, t_lines[-1] + 0.5, t_lines[-1] + 3.0]]
    return _plain_mesh(tsplines.tmesh(vertices, edges, frame))


# Rules: sentences of the statements of exercises 15.infer_knot_vectors and 15.tspline_point, word for word.
MESH_RULE = ("Raise a ValueError (or a TypeError) if mesh is not a dict with the keys \"vertices\" and \"edges\" "
             "(and optionally \"frame\"), if vertices is not of shape (V, 2), or if an edge joins two vertices that "
             "share neither s nor t.")
INFER_RULES = {
    T_JUNCTIONS: "An edge that merely ends on the ray (a T-junction lying on it) is met.",
    T_FRAME: "A ray that leaves the mesh takes the frame knots of that side.",
    T_BAD: MESH_RULE + " Raise a ValueError if vertex is not an index 0 <= vertex < V (a TypeError if it is not "
    "an integer).",
}
POINT_RULES = {
    T_RATIONAL: "The weight multiplies once: H_i = w_i (P_i, 1) in the numerator and w_i in the denominator.",
    T_SHAPES: "Two numbers give an array of shape (d,); k pairs give an array of shape (k, d).",
    T_DOMAIN: "The domain is the box of the vertices, its boundary included.",
    T_BAD: "Raise a ValueError if points does not have one row per vertex, if weights is not None and not V "
    "nonzero numbers, if s and t do not broadcast, or if a pair (s, t) lies outside the domain.",
}


# --- 15.infer_knot_vectors --------------------------------------------------------------------------------


def infer_knot_vectors_cases(rng):
    refined, _, _ = _refined_e4()
    # Ten of the 28 vertices of Fig. 15.17: the four the notes evaluate, corners, T-junctions and the middle.
    cases = [Case(T_EXAMPLE, (E2_MESH, i), visible=i in (10, 15, 0, 27)) for i in (0, 2, 4, 6, 10, 13, 15, 20, 24, 27)]
    cases += [Case(T_EXAMPLE, (E3_MESH, int(v)), visible=True) for v in RULE1.inputs["vertices"]]
    cases += [Case(T_COURSE, (E4_MESH, i)) for i in range(0, 37, 6)]
    cases += [Case(T_COURSE, (refined, i)) for i in (37, 38, 16)]
    cases += [
        Case(T_JUNCTIONS, (E2_MESH, 10), visible=True),  # P10: no vertex to its left on t = 3, yet s = 1 and 0
        Case(T_JUNCTIONS, (E2_MESH, 2)),  # P2 = (7, 0): up, the rows t = 1 and t = 3
        Case(T_JUNCTIONS, (E2_MESH, 21)),  # (4, 6): the column s = 4 ends at (4, 5)
        Case(T_JUNCTIONS, (E2_MESH, 13)),
        Case(T_JUNCTIONS, (E3_MESH, 33)),  # (10, 4): the row t = 5 starts at s = 10
        Case(T_FRAME, (E2_FRAMED, 0), visible=True),
        Case(T_FRAME, (E2_FRAMED, 27)),
        Case(T_FRAME, (E2_FRAMED, 9)),
        Case(T_FRAME, (E2_UNFRAMED, 3), visible=True),  # no frame: unit intervals beyond the mesh
        Case(T_FRAME, ({"vertices": [[0.0, 0.0]], "edges": []}, 0), visible=True),  # one vertex: only the frame
        Case(T_FRAME, ({"vertices": [[0.0, 0.0], [2.0, 0.0]], "edges": [[0, 1]],
                        "frame": [[-1.0, -0.5, 3.0, 5.0], [-2.0, -1.0, 1.0, 4.0]]}, 1)),
    ]
    for _ in range(6):
        mesh = _random_tmesh(rng)
        for vertex in rng.choice(len(mesh["vertices"]), 2, replace=False):
            cases.append(Case(T_RANDOM, (mesh, int(vertex))))
    cases += [
        Case(T_BAD, ([[0.0, 0.0]], 0)),  # not a dict
        Case(T_BAD, ({"vertices": [[0.0, 0.0], [1.0, 0.0]]}, 0)),  # no edges
        Case(T_BAD, ({"vertices": [[0.0, 0.0, 0.0]], "edges": []}, 0)),
        Case(T_BAD, ({"vertices": [[0.0, 0.0], [1.0, 1.0]], "edges": [[0, 1]]}, 0)),  # a slanted edge
        Case(T_BAD, (E2_MESH, 28)),
        Case(T_BAD, (E2_MESH, -1)),
        Case(T_BAD, (E2_MESH, 2.5)),
    ]
    return cases


# --- 15.tspline_point -------------------------------------------------------------------------------------


def tspline_point_cases(rng):
    refined, refined_points, refined_weights = _refined_e4()
    s_grid, t_grid = (a.ravel().tolist() for a in np.meshgrid(np.linspace(0.5, 7.5, 6), np.linspace(0.5, 6.5, 5)))
    e2_weights = np.random.default_rng(154).uniform(0.5, 2.0, 28).tolist()
    e4_s, e4_t = (a.ravel().tolist() for a in np.meshgrid(np.linspace(0, 8, 7), np.linspace(0.5, 7.5, 6)))
    cases = [
        Case(T_EXAMPLE, (E2_MESH, E2_POINTS, 3.0, 4.0), visible=True),
        Case(T_EXAMPLE, (E2_MESH, E2_POINTS, s_grid, t_grid), visible=True),
        Case(T_EXAMPLE, (E2_FRAMED, E2_POINTS, [3.0, 1.5, 6.0], [4.0, 2.0, 5.5])),
        Case(T_COURSE, (E4_MESH, E4_POINTS, e4_s, e4_t), visible=True),
        Case(T_COURSE, (refined, refined_points, e4_s, e4_t, refined_weights), visible=True),  # the same surface
        Case(T_RATIONAL, (E2_MESH, E2_POINTS, 3.0, 4.0, e2_weights), visible=True),
        Case(T_RATIONAL, (E2_MESH, E2_POINTS, s_grid, t_grid, e2_weights)),
        Case(T_RATIONAL, (E2_MESH, E2_POINTS, [2.0, 6.0], [2.0, 6.0], [1.0, -0.25] * 14)),  # negative weights
        Case(T_SHAPES, (E2_MESH, E2_POINTS, [3.0], [4.0])),
        Case(T_SHAPES, (E2_MESH, E2_POINTS, [1.0, 3.0, 5.0], 4.0), visible=True),
        Case(T_SHAPES, (E2_MESH, [p[:2] for p in E2_POINTS], 2.5, [1.0, 3.5])),  # d = 2
        Case(T_SHAPES, (E2_MESH, [[p[2]] for p in E2_POINTS], 3.0, 4.0)),  # d = 1
        Case(T_DOMAIN, (E2_MESH, E2_POINTS, [0.0, 8.0, 0.0, 8.0, 4.0], [0.0, 0.0, 7.0, 7.0, 7.0]), visible=True),
        Case(T_DOMAIN, (E4_MESH, E4_POINTS, [0.0, 8.0, 4.0], [4.0, 8.0, 0.0])),
    ]
    for _ in range(12):
        mesh = _random_tmesh(rng)
        (s_min, t_min), (s_max, t_max) = np.min(mesh["vertices"], axis=0), np.max(mesh["vertices"], axis=0)
        count = len(mesh["vertices"])
        k = int(rng.integers(1, 8))
        points = rng.uniform(-2, 2, (count, 3)).tolist()
        s, t = rng.uniform(s_min, s_max, k).tolist(), rng.uniform(t_min, t_max, k).tolist()
        weights = rng.uniform(0.4, 2.5, count).tolist() if rng.uniform() < 0.6 else None
        cases.append(Case(T_RANDOM, (mesh, points, s, t) + ((weights,) if weights else ())))
    cases += [
        Case(T_BAD, (E2_MESH, E2_POINTS[:27], 3.0, 4.0)),
        Case(T_BAD, (E2_MESH, E2_POINTS, 3.0, 4.0, [1.0] * 27)),
        Case(T_BAD, (E2_MESH, E2_POINTS, 3.0, 4.0, [0.0] + [1.0] * 27)),
        Case(T_BAD, (E2_MESH, E2_POINTS, [1.0, 2.0], [1.0, 2.0, 3.0])),
        Case(T_BAD, (E2_MESH, E2_POINTS, 8.5, 4.0)),  # beyond s_max = 8
        Case(T_BAD, (E2_MESH, E2_POINTS, [3.0, 3.0], [4.0, -0.1])),
    ]
    return cases


TSPLINE_EXERCISES = [
    Exercise(
        id="15.infer_knot_vectors",
        reference=tsplines.infer_knot_vectors,
        cases=infer_knot_vectors_cases,
        compare=close(1e-12, 1e-12),
        hint="Going right from (s_i, t_i), collect the s values of the vertical edges whose closed t-range contains "
        "t_i and whose s is greater than s_i, sorted; append the two frame knots; take the first two. Likewise left "
        "(then reverse), up and down with the horizontal edges.",
        rules=INFER_RULES,
    ),
    Exercise(
        id="15.tspline_point",
        reference=tsplines.tspline_point,
        cases=tspline_point_cases,
        compare=close(1e-9, 1e-9),
        hint="Every control point has its own knot vectors (your infer_knot_vectors); B_i = N[s_i](s) N[t_i](t). "
        "Sum w_i P_i B_i and w_i B_i separately and divide: the B_i do not sum to 1 on a T-mesh.",
        rules=POINT_RULES,
    ),
]

EXERCISES = SURFACE_EXERCISES + TSPLINE_EXERCISES

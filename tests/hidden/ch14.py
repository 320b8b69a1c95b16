"""Hidden grading suite of chapter 14: free-form deformation.

The notes' figures lost their lattices, so the fixed cases are the notes'
surviving numbers on the course's lattices (cagd_course/examples/ch14.toml):
Figure 14.3's point at s = .6, t = .7 of the box (1, -2)-(5, 1); example A,
the 3 x 3 identity lattice of (0, 0)-(3, 2) with its centre moved (and
weighted); example B, the m = 3, n = 2 lattice of Figures 14.6-14.9 with the
lines s = .6 and t = .3. Edge cases probe boxes away from the origin, m ≠ n
(a swapped degree or axis shows only there), points on the boundary (inside:
the box is closed) and outside it (unchanged), single points and empty
arrays, every edge and order of freezing. Random cases come from the generator
the grader passes in.
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import ffd as reference

NOTES = "notes example"
COURSE = "course examples"
EDGE = "edge cases"
RATIONAL = "weights"
OUTSIDE = "outside and on the box"
SHAPES = "shapes"
RANDOM = "random"
BAD = "bad input"

LOCAL = notes_example("14.local_coordinates")
IDENTITY = notes_example("14.identity")
EXAMPLE_A = notes_example("14.example_a")
EXAMPLE_B = notes_example("14.example_b")
FAR_BOX = LOCAL.inputs["box"].tolist()  # (1, -2)-(5, 1): not anchored at the origin
BOX = EXAMPLE_A.inputs["box"].tolist()  # (0, 0)-(3, 2)
BAD_BOXES = [
    [0.0, 0.0, 3.0, 2.0],  # a flat 4-tuple
    [[3.0, 2.0], [0.0, 0.0]],  # the corners swapped
    [[0.0, 1.0], [3.0, 1.0]],  # no height
    [[0.0, 0.0], [3.0, 2.0], [4.0, 4.0]],
]


def _built(example) -> np.ndarray:
    box, m, n = example.args("box", "m", "n")
    lattice = reference.identity_lattice(box, int(m), int(n))
    moved = np.atleast_2d(example.inputs["moved"]).astype(int)
    lattice[tuple(moved.T)] = example.inputs["to"]
    return lattice


LATTICE_A = _built(EXAMPLE_A)
LATTICE_B = _built(EXAMPLE_B)
HEAVY_B = np.ones((4, 3))
HEAVY_B[tuple(EXAMPLE_B.inputs["heavy"].astype(int))] = EXAMPLE_B.inputs["heavy_weight"]
HEAVY_A = np.ones((3, 3))
HEAVY_A[1, 1] = EXAMPLE_A.inputs["weight"]


def _box(rng) -> list:
    low = rng.uniform(-5, 5, 2)
    return [low.tolist(), (low + rng.uniform(0.5, 6, 2)).tolist()]


def _lattice(rng, box, low=1, high=5, rational=None):
    """A random lattice over `box` (the identity, displaced) and weights (None or positive)."""
    m, n = (int(k) for k in rng.integers(low, high + 1, 2))
    box = np.array(box)
    lattice = reference.identity_lattice(box, m, n) + rng.normal(0, 0.2, (m + 1, n + 1, 2)) * (box[1] - box[0])
    weighted = rng.uniform() < 0.5 if rational is None else rational
    return lattice, (rng.uniform(0.3, 3.0, (m + 1, n + 1)) if weighted else None)


def _points(rng, box, count, spill=0.25):
    """Points over the box and a little beyond it (a quarter of them fall outside, on average)."""
    box = np.array(box)
    return box[0] + rng.uniform(-spill, 1 + spill, (count, 2)) * (box[1] - box[0])


def _on_the_boundary(box) -> np.ndarray:
    (x0, y0), (x1, y1) = box
    return np.array([[x0, y0], [x1, y1], [x0, y1], [x1, y0], [(x0 + x1) / 2, y0], [x1, (y0 + y1) / 2]])


# --- 14.ffd_parameters ---------------------------------------------------------------------------


def ffd_parameters_cases(rng):
    box, point = (a.tolist() for a in LOCAL.args("box", "point"))
    cases = [
        Case(NOTES, (point, box), visible=True),
        Case(NOTES, ([point, [1.0, -2.0], [5.0, 1.0]], box), visible=True),
        Case(EDGE, (_on_the_boundary(FAR_BOX), FAR_BOX), visible=True),
        Case(EDGE, ([[0.0, 2.5], [6.0, -3.0], [-1.0, 4.0]], FAR_BOX), visible=True),  # outside: beyond [0, 1]
        Case(EDGE, ([[1.5, 1.0], [2.25, 0.5]], BOX), visible=True),
        Case(EDGE, ([[-3.0, -7.5]], [[-4.0, -8.0], [-2.0, -7.0]]), visible=True),  # a box left of and below 0
        Case(SHAPES, ([0.0, 0.0], FAR_BOX)),
        Case(SHAPES, (np.zeros((0, 2)), FAR_BOX)),
    ]
    for _ in range(12):
        random_box = _box(rng)
        cases.append(Case(RANDOM, (_points(rng, random_box, int(rng.integers(1, 20))), random_box)))
    cases += [Case(BAD, (point, bad)) for bad in BAD_BOXES]
    cases += [Case(BAD, ([[1.0, 2.0, 3.0]], box)), Case(BAD, ([1.0, 2.0, 3.0], box))]
    return cases


# --- 14.identity_lattice -------------------------------------------------------------------------


def identity_lattice_cases(rng):
    box, m, n = IDENTITY.args("box", "m", "n")
    cases = [
        Case(NOTES, (box.tolist(), int(m), int(n)), visible=True),
        Case(NOTES, (BOX, 2, 2), visible=True),
        Case(EDGE, (FAR_BOX, 2, 5), visible=True),  # m ≠ n: swapped degrees or axes show
        Case(EDGE, (FAR_BOX, 1, 1), visible=True),
        Case(EDGE, (FAR_BOX, 4, 1), visible=True),
        Case(EDGE, ([[-1.0, -1.0], [1.0, 1.0]], 6, 3), visible=True),
    ]
    for _ in range(10):
        cases.append(Case(RANDOM, (_box(rng), int(rng.integers(1, 7)), int(rng.integers(1, 7)))))
    cases += [Case(BAD, (bad, 2, 2)) for bad in BAD_BOXES[:3]]
    cases += [Case(BAD, (BOX, 0, 2)), Case(BAD, (BOX, 2, -1)), Case(BAD, (BOX, 2.5, 2))]
    return cases


# --- 14.ffd --------------------------------------------------------------------------------------


def ffd_cases(rng):
    points = EXAMPLE_A.inputs["points"]
    s, t = EXAMPLE_B.args("s", "t")
    crossing = (np.array(BOX[0]) + np.array([s, t]) * (np.array(BOX[1]) - np.array(BOX[0]))).tolist()
    identity = reference.identity_lattice(FAR_BOX, 3, 2)
    inside = _points(rng, FAR_BOX, 12, spill=0.0)
    cases = [
        Case(COURSE, (points, LATTICE_A, BOX), visible=True),
        Case(COURSE, (points[:3], LATTICE_A, BOX, HEAVY_A), visible=True),
        Case(COURSE, (crossing, LATTICE_B, BOX), visible=True),
        Case(COURSE, (crossing, LATTICE_B, BOX), {"weights": HEAVY_B}, visible=True),
        Case(EDGE, (_points(rng, BOX, 15, spill=0.0), LATTICE_B, BOX), visible=True),  # m = 3 ≠ n = 2
        Case(EDGE, (inside, identity, FAR_BOX), visible=True),  # the identity
        Case(EDGE, (inside, identity, FAR_BOX, np.full((4, 3), 2.5)), visible=True),  # equal weights: still
        Case(EDGE, (inside, identity, FAR_BOX, HEAVY_B), visible=True),  # one weight differs: it moves
        Case(OUTSIDE, (notes_example("14.outside").inputs["points"], LATTICE_A, BOX), visible=True),
        Case(OUTSIDE, (_on_the_boundary(BOX), LATTICE_B, BOX), visible=True),  # the box is closed
        Case(OUTSIDE, ([[1.5, 2.0], [1.5, 2.0 + 1e-9], [3.0 + 1e-9, 1.0]], LATTICE_B + 0.3, BOX), visible=True),
        Case(SHAPES, ([1.0, 1.0], LATTICE_B, BOX)),
        Case(SHAPES, ([[1.0, 1.0]], LATTICE_B, BOX)),
        Case(SHAPES, (np.zeros((0, 2)), LATTICE_B, BOX)),
    ]
    for _ in range(16):
        box = _box(rng)
        lattice, weights = _lattice(rng, box)
        args = (_points(rng, box, int(rng.integers(1, 30))), lattice, box) + (() if weights is None else (weights,))
        cases.append(Case(RANDOM, args))
    cases += [Case(BAD, (points, LATTICE_A, bad)) for bad in BAD_BOXES[:3]]
    cases += [
        Case(BAD, (points, LATTICE_A[:, :1], BOX)),  # n = 0
        Case(BAD, (points, LATTICE_A.reshape(9, 2), BOX)),
        Case(BAD, (points, np.zeros((3, 3, 3)), BOX)),
        Case(BAD, (points, LATTICE_A, BOX, np.ones((3, 2)))),
        Case(BAD, (points, LATTICE_A, BOX, [[1.0, 1.0, 1.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0]])),
        Case(BAD, (points, LATTICE_A, BOX, [[1.0, 1.0, 1.0], [1.0, -2.0, 1.0], [1.0, 1.0, 1.0]])),
        Case(BAD, ([[1.0, 1.0, 1.0]], LATTICE_A, BOX)),
    ]
    return cases


# --- 14.isoline_image ----------------------------------------------------------------------------


def isoline_image_cases(rng):
    s, t = EXAMPLE_B.args("s", "t")
    cases = [
        Case(NOTES, (LATTICE_B, s), visible=True),
        Case(NOTES, (LATTICE_B, t, "t"), visible=True),
        Case(NOTES, (LATTICE_B, s, "s", HEAVY_B), visible=True),
        Case(NOTES, (LATTICE_B, t), {"direction": "t", "weights": HEAVY_B}, visible=True),
        Case(EDGE, (LATTICE_B, 0.0), visible=True),  # the left column itself
        Case(EDGE, (LATTICE_B, 1.0, "t"), visible=True),  # the top row itself
        Case(EDGE, (LATTICE_A, 0.5, "s", HEAVY_A), visible=True),
        Case(EDGE, (reference.identity_lattice(FAR_BOX, 2, 5), 0.25, "t"), visible=True),
        Case(SHAPES, (LATTICE_B, [s, t, 1.0])),
        Case(SHAPES, (LATTICE_B, np.array([t]), "t")),
        Case(SHAPES, (LATTICE_B, np.zeros(0), "t")),
    ]
    for _ in range(14):
        lattice, weights = _lattice(rng, _box(rng))
        value = float(rng.uniform()) if rng.uniform() < 0.7 else rng.uniform(0, 1, 3)
        cases.append(Case(RANDOM, (lattice, value, str(rng.choice(["s", "t"])), weights)))
    cases += [
        Case(BAD, (LATTICE_B, 1.5)),
        Case(BAD, (LATTICE_B, -0.1, "t")),
        Case(BAD, (LATTICE_B, 0.5, "x")),
        Case(BAD, (LATTICE_B, 0.5, "s", np.zeros((4, 3)))),
        Case(BAD, (LATTICE_B, 0.5, "s", np.ones((3, 4)))),
        Case(BAD, (LATTICE_B[:1], 0.5)),
    ]
    return cases


# --- 14.freeze -----------------------------------------------------------------------------------


def freeze_cases(rng):
    bent = LATTICE_B + [0.2, 0.3]  # every point displaced, so that freezing shows everywhere
    cases = [
        Case(COURSE, (bent, BOX, "bottom", 0), visible=True),
        Case(COURSE, (bent, BOX, "bottom", 1), visible=True),
        Case(COURSE, (bent, BOX, "bottom", 2), visible=True),  # every row: the identity
        Case(COURSE, (bent, BOX, "top", 1, HEAVY_B), visible=True),
        Case(COURSE, (bent, BOX, "left", 1), visible=True),
        Case(COURSE, (bent, BOX, "right", 2, HEAVY_B), visible=True),
        Case(EDGE, (bent, BOX, "right", 3), visible=True),
        Case(RATIONAL, (bent, BOX, "bottom", 1, HEAVY_B * 2.0), visible=True),  # frozen weights become 1
        Case(RATIONAL, (LATTICE_A + 0.1, BOX, "top", 0), {"weights": HEAVY_A}, visible=True),
    ]
    for _ in range(14):
        box = _box(rng)
        lattice, weights = _lattice(rng, box)
        edge = str(rng.choice(reference.EDGES))
        count = lattice.shape[1] - 1 if edge in ("bottom", "top") else lattice.shape[0] - 1
        cases.append(Case(RANDOM, (lattice, box, edge, int(rng.integers(0, count + 1)), weights)))
    cases += [
        Case(BAD, (bent, BOX, "middle", 0)),
        Case(BAD, (bent, BOX, "bottom", 3)),  # n = 2: at most 3 rows, order <= 2
        Case(BAD, (bent, BOX, "left", 4)),
        Case(BAD, (bent, BOX, "bottom", -1)),
        Case(BAD, (bent, BOX, "bottom", 1.5)),
        Case(BAD, (bent, BAD_BOXES[1], "bottom", 1)),
        Case(BAD, (bent, BOX, "bottom", 1, np.zeros((4, 3)))),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="14.ffd_parameters",
        reference=reference.ffd_parameters,
        cases=ffd_parameters_cases,
        compare=close(1e-12, 1e-12),
        hint="s = (x - xmin)/(xmax - xmin) and t = (y - ymin)/(ymax - ymin), with box = [[xmin, ymin], [xmax, ymax]]: "
        "subtract the lower corner, divide by the box's width and height (not by xmax). One point (2,) gives (2,).",
        rules={
            EDGE: "Points outside the box are allowed: they get values outside $[0, 1]$.",
            SHAPES: "`points`: shape `(k, 2)`, giving shape `(k, 2)` (also for k = 0 and k = 1), or a single point "
                "of shape `(2,)`, giving `(2,)`.",
            BAD: "Raise a `ValueError` for a box that breaks the conventions and for points of any other shape "
                "(three coordinates, for instance).",
        },
    ),
    Exercise(
        id="14.identity_lattice",
        reference=reference.identity_lattice,
        cases=identity_lattice_cases,
        compare=close(1e-12, 1e-12),
        hint="lattice[i, j] = (xmin + i/m (xmax - xmin), ymin + j/n (ymax - ymin)) for i = 0..m, j = 0..n: shape "
        "(m+1, n+1, 2), the first index along x.",
        rules={
            EDGE: "Return an array of shape `(m+1, n+1, 2)` with `lattice[i, j]` $=\\mathbf P_{ij}$ (the first "
                "index along $x$).",
            BAD: "Raise a `ValueError` (or `TypeError`) when `m` or `n` is not an integer $\\ge1$ (0, -1, 2.5) and "
                "for a bad box.",
        },
    ),
    Exercise(
        id="14.ffd",
        reference=reference.ffd,
        cases=ffd_cases,
        compare=close(1e-9, 1e-9),
        hint="For each point inside the closed box: (s, t), then (X, Y, W) = Σ_i Σ_j B_i^m(s) B_j^n(t) w_ij (x_ij, "
        "y_ij, 1) with m = lattice.shape[0] - 1 along s and n = lattice.shape[1] - 1 along t, and the point "
        "(X/W, Y/W). Points outside are returned as they are; do not modify the input.",
        rules={
            EDGE: "`lattice`, `box`, `weights` as in the conventions; `weights=None` means all weights 1.",
            OUTSIDE: "**Points outside the box are returned unchanged.** The box is *closed*: a point on its "
                "boundary ($s$ or $t$ equal to 0 or 1) is inside and is deformed.",
            SHAPES: "`points`: `(k, 2)` giving `(k, 2)` (also for k = 0), or one point `(2,)` giving `(2,)`.",
            BAD: "Raise a `ValueError` for a lattice that is not `(m+1, n+1, 2)` with $m,n\\ge1$, for weights of "
                "the wrong shape or with a zero or negative entry, for points of the wrong shape and for a bad box.",
        },
    ),
    Exercise(
        id="14.isoline_image",
        reference=reference.isoline_image,
        cases=isoline_image_cases,
        compare=close(1e-9, 1e-9),
        hint="direction 's': H_j = Σ_i B_i^m(value) w_ij (x_ij, y_ij, 1) for each row j (a point on the row's degree-m "
        "curve, in homogeneous coordinates); return (H_j's (X/W, Y/W), H_j's W): n+1 of each. Direction 't': the "
        "same along the columns, V_i = Σ_j B_j^n(value) w_ij (x_ij, y_ij, 1).",
        rules={
            EDGE: "`weights=None` means all weights 1 (and then the returned weights are all 1).",
            SHAPES: "`value`: a number in $[0, 1]$, or a 1-D array of k such numbers, giving shapes `(k, n+1, 2)` "
                "and `(k, n+1)` (also for k = 0 and k = 1).",
            BAD: "Raise a `ValueError` for a value outside $[0, 1]$ (that line misses the box), for a direction "
                "other than `\"s\"` and `\"t\"`, and for a bad lattice or bad weights as in exercise 14.3.",
        },
    ),
    Exercise(
        id="14.freeze",
        reference=reference.freeze,
        cases=freeze_cases,
        compare=close(1e-12, 1e-12),
        hint="order k resets k+1 rows (C⁰: 1 row): 'bottom' rows j = 0..k, 'top' j = n-k..n, 'left' columns "
        "i = 0..k, 'right' i = m-k..m, to their identity-lattice positions and their weights to 1; return new "
        "arrays (lattice, weights), with weights all ones when none were given.",
        rules={
            EDGE: "freezing every row gives back the identity lattice.",
            RATIONAL: "The frozen weights must be 1",
            BAD: "Raise a `ValueError` for an unknown edge, for an order out of range (negative, or more rows than "
                "the lattice has; a non-integer may raise a `TypeError`), and for a bad lattice, box or weights.",
        },
    ),
]

"""Hidden grading suite of chapter 8: offset curves, their cusps, PH cubics and exact rational offsets.

The notes print no numbers in this chapter, so the fixed cases are the course's
examples (cagd_course/examples/ch08.toml): the arch [(0,0), (1,2), (3,2), (4,0)]
whose tightest bend has radius 27/16 at t = 1/2, the S-curve with an inflection,
the PH cubic with u = (2, 1), v = (0, 1) and its exact offset at ρ = 1/4. Edge
cases probe the ends of the curve, lines, parabolas, circles (rational), a
radius equal to the tightest bend (1 + ρκ touches zero), a cusp at an end,
degree-raised and quintic PH curves. Random cases come from the generator the
grader passes in, drawn away from the ill-conditioned places (curves that almost
stop, radii at which two cusps are about to merge).
"""

from __future__ import annotations

import numpy as np

from cagd_course.examples import notes_example
from cagd_course.grading.suite import Case, Exercise, Raises, close
from cagd_ref import bezier, offsets

EXAMPLE = "course examples"
EDGE = "edge cases"
RATIONAL = "rational curves"
SHAPES = "scalar vs array t"
RANDOM = "random"
BAD = "bad input"

ARCH = notes_example("08.arch")
INFLECTION = notes_example("08.inflection")
PH = notes_example("08.ph_cubic")
PH_OFFSET = notes_example("08.ph_offset")

ARCH_POINTS = ARCH.inputs["points"].tolist()
S_CURVE = INFLECTION.inputs["points"].tolist()
PH_POINTS = PH.results["points"].tolist()
LINE = [(0.0, 0.0), (3.0, 4.0)]
PARABOLA = [(-2.0, 4.0), (0.0, -4.0), (2.0, 4.0)]  # (t, t²) for t in [-2, 2]: κ = 2 / (1 + 4t²)^(3/2) > 0
HALF_PARABOLA = [(0.0, 0.0), (0.5, 0.0), (1.0, 1.0)]  # its vertex at t = 0, where the bend is tightest
QUARTIC = [(0.0, 0.0), (1.0, 3.0), (3.0, -1.0), (5.0, 2.0), (6.0, 0.0)]
STOPS_AT_START = [(0.0, 0.0), (0.0, 0.0), (1.0, 1.0), (2.0, 0.0)]  # Q'(0) = 0
ARC_POINTS, ARC_WEIGHTS = (a.tolist() for a in bezier.circular_arc([1.0, 1.0], 2.0, 0.0, 2.0))  # counterclockwise
RATIONAL_WEIGHTS = [1.0, 2.0, 0.5, 1.0]
TS = np.linspace(0.0, 1.0, 9)


def _curve(rng, low=1, high=5, rational=None):
    """Random planar control points (n+1, 2) and weights (None or positive), moving at a healthy speed everywhere."""
    while True:
        n = int(rng.integers(low, high + 1))
        points = rng.uniform(-5, 5, (n + 1, 2))
        weighted = rng.uniform() < 0.35 if rational is None else rational
        weights = rng.uniform(0.4, 2.5, n + 1) if weighted else None
        speed = np.linalg.norm(bezier.derivative(points, np.linspace(0, 1, 101), 1, weights), axis=1)
        if speed.min() > 0.1 * speed.max():
            return points, weights


def _parameters(rng):
    return float(rng.uniform()) if rng.uniform() < 0.3 else np.sort(rng.uniform(0, 1, int(rng.integers(2, 8))))


# --- 08.offset_point ------------------------------------------------------------------------------


def _offset_cases(rng):
    """Cases (points, t, rho[, weights]) shared by offset_point and offset_derivative."""
    cases = [
        Case(EXAMPLE, (ARCH_POINTS, ARCH.inputs["t"], ARCH.inputs["rho"]), visible=True),
        Case(EXAMPLE, (ARCH_POINTS, TS, -1.0), visible=True),  # on the left: outside the arch
        Case(EXAMPLE, (ARCH_POINTS, TS, ARCH.inputs["rho_cusps"]), visible=True),  # beyond the tightest bend
        Case(EXAMPLE, (S_CURVE, TS, 0.6), visible=True),
        Case(EXAMPLE, (PH_POINTS, TS, 0.25), visible=True),
        Case(EDGE, (ARCH_POINTS, [0.0, 1.0], 0.75), visible=True),  # the two ends
        Case(EDGE, (LINE, TS, 1.0), visible=True),  # degree 1: a constant normal
        Case(EDGE, (PARABOLA, TS, -0.4), visible=True),
        Case(EDGE, (QUARTIC, TS, 0.5), visible=True),
        Case(EDGE, (STOPS_AT_START, [0.25, 0.5, 1.0], 0.5), visible=True),  # stops at t = 0 only
        Case(EDGE, (ARCH_POINTS, TS, 0.0), visible=True),  # ρ = 0: the curve itself
        Case(RATIONAL, (ARC_POINTS, TS, -0.5, ARC_WEIGHTS), visible=True),  # a circle: concentric circles
        Case(RATIONAL, (ARCH_POINTS, TS, 0.8, RATIONAL_WEIGHTS), visible=True),
        Case(RATIONAL, (ARCH_POINTS, TS, -0.8), {"weights": [1.0, 1.0, 1.0, 1.0]}, visible=True),
        Case(SHAPES, (ARCH_POINTS, np.array([0.3]), 0.5)),
        Case(SHAPES, (ARCH_POINTS, np.array(0.3), 0.5)),
        Case(SHAPES, (ARCH_POINTS, 0.3, 0.5)),
    ]
    for _ in range(14):
        points, weights = _curve(rng)
        rho = float(rng.uniform(-3, 3))
        args = (points, _parameters(rng), rho) + (() if weights is None else (weights,))
        cases.append(Case(RANDOM, args))
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], 0.5, 1.0)),  # offsets are planar
        Case(BAD, ([(1.0, 2.0)], 0.5, 1.0)),  # a single point
        Case(BAD, (STOPS_AT_START, [0.0, 0.5], 1.0)),  # Q'(0) = 0: no normal
        Case(BAD, (STOPS_AT_START, [0.0, 0.5], 1.0, [1.0, 2.0, 0.5, 1.0])),  # rational: Q'(0) = 0 too
        Case(BAD, (ARCH_POINTS, 0.5, 1.0, [1.0, 0.0, 1.0, 1.0])),  # a zero weight
        Case(BAD, (ARCH_POINTS, 0.5, 1.0, [1.0, -2.0, 1.0, 1.0])),  # a negative weight
        Case(BAD, (ARCH_POINTS, 0.5, 1.0, [1.0, 1.0, 1.0])),  # one weight per point
        Case(BAD, (ARCH_POINTS, [[0.5]], 1.0)),
    ]
    return cases


def offset_point_cases(rng):
    return _offset_cases(rng)


# --- 08.offset_derivative --------------------------------------------------------------------------


def offset_derivative_cases(rng):
    at_cusps = Case(EDGE, (ARCH_POINTS, ARCH.results["cusps"], ARCH.inputs["rho_cusps"]), visible=True)  # P' = 0
    return _offset_cases(rng) + [at_cusps]


# --- 08.offset_cusps -------------------------------------------------------------------------------

MERGE = 1e-6


def _merged(values) -> np.ndarray:
    """Sorted parameters, those closer than MERGE replaced by their mean."""
    groups: list[list[float]] = []
    for t in np.sort(values):
        if groups and t - groups[-1][-1] <= MERGE:
            groups[-1].append(float(t))
        else:
            groups.append([float(t)])
    return np.array([sum(g) / len(g) for g in groups])


def same_cusps(expected, received) -> str | None:
    """The same parameters to within 1e-6, after merging parameters closer than 1e-6 on both sides."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    try:
        got = np.asarray(received, dtype=float)
    except (TypeError, ValueError):
        return f"expected a 1-D array of parameters, got {type(received).__name__}"
    if got.ndim != 1:
        return f"expected a 1-D array of parameters, got shape {got.shape}"
    if not np.all(np.isfinite(got)):
        return "got NaN or infinity among the parameters"
    if np.any(np.diff(got) < 0):
        return f"the parameters must be sorted, got {np.round(got, 6).tolist()}"
    want, got = _merged(expected), _merged(got)
    if len(want) != len(got):
        return f"expected {len(want)} cusp(s) at t = {np.round(want, 6).tolist()}, got {np.round(got, 6).tolist()}"
    return close(0.0, MERGE)(want, got)


def _clear_cusps(points, rho, weights) -> bool:
    """True when the cusps are well conditioned: apart from each other and from the ends, and no bend almost touches.

    A local minimum of |1 + ρκ| close to zero must be the crossing at a cusp;
    anywhere else a tiny change of ρ would add or remove two cusps.
    """
    cusps = offsets.offset_cusps(points, rho, weights)
    if np.diff(np.concatenate([[0.0], cusps, [1.0]])).min() < 2e-3:
        return False
    ts = np.linspace(0, 1, 2001)
    g = np.abs(1 + rho * bezier.signed_curvature(points, ts, weights))
    minima = np.flatnonzero((g[1:-1] < g[:-2]) & (g[1:-1] < g[2:])) + 1
    small = ts[minima[g[minima] < 5e-3]]
    return all(cusps.size and np.abs(cusps - t).min() < 2e-3 for t in small)


def offset_cusps_cases(rng):
    min_radius = ARCH.results["min_radius"]
    cases = [
        Case(EXAMPLE, (ARCH_POINTS, ARCH.inputs["rho_cusps"]), visible=True),
        Case(EXAMPLE, (ARCH_POINTS, ARCH.inputs["rho_safe"]), visible=True),  # below the tightest bend: none
        Case(EXAMPLE, (ARCH_POINTS, -ARCH.inputs["rho_cusps"]), visible=True),  # the convex side: never
        Case(EXAMPLE, (S_CURVE, INFLECTION.inputs["rho"]), visible=True),
        Case(EXAMPLE, (S_CURVE, -INFLECTION.inputs["rho"]), visible=True),
        Case(EDGE, (ARCH_POINTS, min_radius), visible=True),  # 1 + ρκ touches zero at t = 1/2
        Case(EDGE, (S_CURVE, INFLECTION.results["min_radius"]), visible=True),  # ... and here at t = 0.190655
        Case(EDGE, (S_CURVE, -INFLECTION.results["min_radius"]), visible=True),  # ... and at t = 0.809345
        Case(EDGE, (ARCH_POINTS, 2.0 * min_radius), visible=True),
        Case(EDGE, (ARCH_POINTS, 0.0), visible=True),
        Case(EDGE, (PARABOLA, -0.8), visible=True),
        Case(EDGE, (PARABOLA, -0.5), visible=True),  # touches at the vertex
        Case(EDGE, (HALF_PARABOLA, -0.5), visible=True),  # a cusp at the end t = 0
        Case(EDGE, (LINE, 3.0), visible=True),
        Case(EDGE, (QUARTIC, 0.4), visible=True),
        Case(EDGE, (QUARTIC, -0.4), visible=True),
        Case(RATIONAL, (ARC_POINTS, -1.0, ARC_WEIGHTS), visible=True),  # a circle: concentric circles, no cusps
        Case(RATIONAL, (ARC_POINTS, 3.0, ARC_WEIGHTS), visible=True),
        Case(RATIONAL, (ARCH_POINTS, 0.8, RATIONAL_WEIGHTS), visible=True),
        Case(RATIONAL, (ARCH_POINTS, 2.5), {"weights": [1.0, 1.0, 1.0, 1.0]}, visible=True),
    ]
    drawn = 0
    while drawn < 16:
        points, weights = _curve(rng, low=2, high=4)
        radii = 1 / np.abs(bezier.signed_curvature(points, np.linspace(0.01, 0.99, 99), weights))
        rho = float(rng.choice([-1.0, 1.0]) * np.quantile(radii, rng.uniform(0.05, 0.6)) * rng.uniform(0.9, 1.1))
        if _clear_cusps(points, rho, weights):
            cases.append(Case(RANDOM, (points, rho) + (() if weights is None else (weights,))))
            drawn += 1
    cases += [
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0), (2.0, 0.0, 1.0)], 1.0)),
        Case(BAD, ([(1.0, 2.0)], 1.0)),
        Case(BAD, ([(1.0, 2.0), (1.0, 2.0), (1.0, 2.0)], 1.0)),  # a single point, drawn three times
        Case(BAD, (ARC_POINTS, -2.0, ARC_WEIGHTS)),  # a circle offset to its centre: 1 + ρκ ≡ 0
        Case(BAD, (ARCH_POINTS, 1.0, [1.0, -1.0, 1.0, 1.0])),
        Case(BAD, (ARCH_POINTS, 1.0, [0.0, 1.0, 1.0, 1.0])),
    ]
    return cases


# --- 08.ph_cubic ------------------------------------------------------------------------------------


def ph_cubic_cases(rng):
    p0, u, v = (a.tolist() for a in PH.args("p0", "u", "v"))
    cases = [
        Case(EXAMPLE, (p0, u, v), visible=True),
        Case(EXAMPLE, ([1.0, -2.0], u, v), visible=True),  # the same shape, moved
        Case(EDGE, ([0.0, 0.0], [1.0, 1.0], [0.0, 0.0]), visible=True),  # v = 0: a line along x
        Case(EDGE, ([0.0, 0.0], [0.0, 0.0], [1.0, 1.0]), visible=True),  # u = 0: a line, backwards along x
        Case(EDGE, ([0.5, 0.5], [1.0, -1.0], [1.0, -1.0]), visible=True),  # u = v: stops at t = 1/2
        Case(EDGE, ([0.0, 0.0], [-1.5, 0.5], [2.0, -0.5]), visible=True),
        Case(EDGE, ([3.0, 1.0], [0.0, 2.0], [1.0, 0.0]), visible=True),
    ]
    for _ in range(14):
        cases.append(Case(RANDOM, (rng.uniform(-3, 3, 2), rng.uniform(-2, 2, 2), rng.uniform(-2, 2, 2))))
    cases += [
        Case(BAD, (p0, [2.0, 1.0, 0.0], [0.0, 1.0, 2.0])),  # quadratic u, v: not a cubic
        Case(BAD, (p0, [2.0, 1.0], [0.0])),
        Case(BAD, ([0.0, 0.0, 0.0], u, v)),
        Case(BAD, (p0, [[2.0, 1.0]], [[0.0, 1.0]])),
    ]
    return cases


# --- 08.ph_offset -------------------------------------------------------------------------------------


def same_rational_curve(expected, received) -> str | None:
    """The same points, and weights equal up to one common nonzero factor (both describe the same curve)."""
    if isinstance(expected, Raises):
        return close()(expected, received)
    if not isinstance(received, (tuple, list)) or len(received) != 2:
        return "expected a tuple (points, weights)"
    points, weights = expected
    problem = close(1e-9, 1e-9)(points, received[0])
    if problem:
        return f"points: {problem}"
    try:
        got = np.asarray(received[1], dtype=float)
    except (TypeError, ValueError):
        return "weights: expected numbers"
    if got.shape != weights.shape:
        return f"weights: expected shape {weights.shape}, got shape {got.shape}"
    if got[0] == 0 or not np.all(np.isfinite(got)):
        return "weights: expected finite weights with a nonzero first one"
    problem = close(1e-9, 1e-12)(weights / weights[0], got / got[0])
    return f"weights (divided by the first one): {problem}" if problem else None


def _ph(rng, m):
    return offsets.ph_curve(rng.uniform(-3, 3, 2), rng.uniform(0.5, 2.0, m + 1) * rng.choice([-1, 1]),
                            rng.uniform(-1.5, 1.5, m + 1))


def ph_offset_cases(rng):
    quintic = offsets.ph_curve([0.0, 0.0], [1.0, 2.0, 1.5], [0.5, -0.5, 1.0])
    cases = [
        Case(EXAMPLE, (PH_OFFSET.inputs["points"].tolist(), PH_OFFSET.inputs["rho"]), visible=True),
        Case(EXAMPLE, (PH_POINTS, -0.7), visible=True),
        Case(EXAMPLE, (PH_POINTS, 3.0), visible=True),  # beyond the tightest bend: still exact
        Case(EDGE, (LINE, 1.0), visible=True),  # degree 1: constant speed, the offset is a shifted line
        Case(EDGE, (bezier.elevate(np.array(PH_POINTS)).tolist(), 0.25), visible=True),  # degree raised to 4
        Case(EDGE, (quintic.tolist(), 0.4), visible=True),
        Case(EDGE, (offsets.ph_cubic([0.0, 0.0], [0.0, 2.0], [1.0, 0.0]).tolist(), -0.3), visible=True),
        Case(EDGE, (PH_POINTS, 0.0), visible=True),
    ]
    for _ in range(12):
        cases.append(Case(RANDOM, (_ph(rng, int(rng.integers(1, 3))), float(rng.uniform(-2, 2)))))
    stopping = offsets.ph_cubic([0.0, 0.0], [1.0, -1.0], [1.0, -1.0])
    cases += [
        Case(BAD, (ARCH_POINTS, 0.5)),  # not PH
        Case(BAD, ([(1.0, 1.0), (1.0, 3.0), (2.0, 4.0)], 0.5)),  # nor is a parabola: x'² + y'² has no square root
        Case(BAD, (stopping.tolist(), 0.5)),  # σ = 0 at t = 1/2
        Case(BAD, ([(0.0, 0.0, 0.0), (1.0, 1.0, 1.0)], 0.5)),
        Case(BAD, ([(1.0, 1.0)], 0.5)),
    ]
    return cases


EXERCISES = [
    Exercise(
        id="08.offset_point",
        reference=offsets.offset_point,
        cases=offset_point_cases,
        compare=close(1e-9, 1e-9),
        hint="P(t) = Q(t) + ρ (y'(t), -x'(t)) / |Q'(t)|: the unit normal on the right of the direction of travel. "
        "For a rational curve differentiate Q = X / w by the quotient rule, Q' = (X' - w' Q) / w. Raise a "
        "ValueError where Q'(t) = 0.",
        rules={
            EDGE: "`rho`: a number of either sign; `rho = 0` gives the curve itself.",
            RATIONAL: "`weights`: `None` or `n+1` positive numbers.",
            SHAPES: "`t`: a number, giving shape `(2,)`, or a 1-D array of k numbers, giving `(k, 2)`",
            BAD: "Raise a `ValueError` if the points are not of shape `(n+1, 2)` with $n\\ge1$ (a 3-D curve, a "
                "single point), if a weight is zero or negative or their number is not `n+1`, if `t` has two or "
                "more dimensions, and if $\\mathbf Q'(t)=0$ at a requested parameter",
        },
    ),
    Exercise(
        id="08.offset_derivative",
        reference=offsets.offset_derivative,
        cases=offset_derivative_cases,
        compare=close(1e-9, 1e-9),
        hint="P'(t) = (1 + ρκ(t)) Q'(t) with the signed curvature κ = (x'y'' - y'x'') / |Q'|³ (positive turning "
        "left). Between the cusps 1 + ρκ < 0 and the offset runs backwards.",
        rules={
            EDGE: "$\\kappa$ is **signed**.",
            RATIONAL: "`weights` `None` or `n+1` positive numbers",
            SHAPES: "`t` a number, giving shape `(2,)`, or a 1-D array of k numbers, giving `(k, 2)`",
            BAD: "Raise a `ValueError` if the points are not of shape `(n+1, 2)` with $n\\ge1$ (a 3-D curve, a "
                "single point), if a weight is zero or negative or their number is not `n+1`, if `t` has two or "
                "more dimensions, and if $\\mathbf Q'(t)=0$ at a requested parameter",
        },
    ),
    Exercise(
        id="08.offset_cusps",
        reference=offsets.offset_cusps,
        cases=offset_cusps_cases,
        compare=same_cusps,
        hint="1 + ρκ = 0 on the offset's side only (ρκ < 0): squaring |Q'|³ = -ρ (x'y'' - y'x'') gives a "
        "polynomial whose roots also include the other side's, where ρ (x'y'' - y'x'') > 0: drop those. Where "
        "1 + ρκ only touches zero (a double root), report it once; ends count.",
        rules={
            EDGE: "The ends count: $t=0$ or $t=1$ is a cusp when $1+\\rho\\kappa$ vanishes there.",
            RATIONAL: "Rational curves (`weights`) use the derivatives of the conventions above; a circular arc's "
                "offsets are concentric arcs.",
            BAD: "Raise a `ValueError` for points not of shape `(n+1, 2)` with $n\\ge1$, for a weight that is zero "
                "or negative (or a wrong number of weights), for a curve whose control points all coincide, and "
                "when $1+\\rho\\kappa$ vanishes **identically**",
        },
    ),
    Exercise(
        id="08.ph_cubic",
        reference=offsets.ph_cubic,
        cases=ph_cubic_cases,
        compare=close(1e-12, 1e-12),
        hint="P1 = P0 + (u0² - v0², 2u0v0)/3, P2 = P1 + (u0u1 - v0v1, u0v1 + u1v0)/3, "
        "P3 = P2 + (u1² - v1², 2u1v1)/3: the hodograph's Bernstein coefficients, integrated.",
        rules={
            EDGE: "`p0`, `u`, `v`: two numbers each. Return shape `(4, 2)`, right to within $10^{-12}$.",
            BAD: "Raise a `ValueError` if `p0`, `u` or `v` is not a 1-D array of two numbers.",
        },
    ),
    Exercise(
        id="08.ph_offset",
        reference=offsets.ph_offset,
        cases=ph_offset_cases,
        compare=same_rational_curve,
        hint="With σ the polynomial whose square is x'² + y'² (degree n-1), the offset is the rational curve "
        "(σQ + ρ(y', -x'), σ) of degree 2n-1: multiply σ by Q, raise ρ(y', -x') and σ to degree 2n-1; the "
        "weights are σ's raised coefficients and the points the numerator divided by them.",
        rules={
            EDGE: "Degree-raised PH curves are PH curves too (a PH cubic raised to degree 4 gives 8 points), and so "
                "is a line ($n=1$: its offset is the shifted line).",
            BAD: "Raise a `ValueError` for points not of shape `(n+1, 2)` with $n\\ge1$, for a curve that is not PH "
                "(the arch; a parabola), and for a PH curve that stops somewhere in $[0,1]$ ($u$ and $v$ with a "
                "common root).",
        },
    ),
]

"""Intersections of 100 seeded random pairs of Bézier curves: Bézier clipping against the `bezier` package.

`cagd_ref.intersection.intersect_curves` is the course's Bézier-clipping
intersector (notes §7.7) in NumPy: every round clips all live pairs of pieces
of one call at once, in arrays; the `bezier` package (D. Hermes) intersects
with compiled Fortran (bounding-box subdivision, then Newton's method). Each
case times one pass over all 100 pairs of a degree, the same pairs for both,
the peer's `Curve` objects built outside the clock. The agreement is checked
pair by pair: the same number of intersections, and the largest difference of
a parameter t or u (the peer may report an intersection twice; repeats closer
than 1e-7 are dropped before comparing). `bezier` has no rational curves: 100
random rational cubic pairs are checked against intersection by
implicitization (`intersect_by_implicitization`, §7.4), an independent
algorithm of the same module.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.intersection import intersect_by_implicitization, intersect_curves

from . import peers
from .common import Case, Plan, compare, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Curve intersection"
ABOUT = ("100 seeded random pairs of planar Bézier curves per degree, intersected by Bézier clipping "
         "(`intersect_curves`, NumPy, all live pairs of pieces of a call clipped at once) and by the `bezier` "
         "package's compiled `Curve.intersect`; agreement pair by pair (the same number of intersections, the "
         "largest parameter difference). 100 random rational cubic pairs, which `bezier` cannot intersect, against "
         "implicitization (`intersect_by_implicitization`).")
TIME_FACTOR = 3
AGREEMENT = 1e-9

CLIPPING = "cagd_ref intersect_curves"
BEZIER_INTERSECT = "bezier Curve.intersect"
IMPLICITIZATION = "cagd_ref intersect_by_implicitization"
PAIRS = 100
DEGREES = (3, 5)
SEED = 7_2017


def random_pairs(degree: int, count: int = PAIRS, seed: int = SEED) -> list[tuple[np.ndarray, np.ndarray]]:
    """`count` pairs of planar Bézier curves of one degree, control points uniform in [-1, 1]²."""
    rng = np.random.default_rng([seed, degree])
    return [(rng.uniform(-1, 1, (degree + 1, 2)), rng.uniform(-1, 1, (degree + 1, 2))) for _ in range(count)]


def random_rational_pairs(degree: int = 3, count: int = PAIRS, seed: int = SEED):
    """`count` rational pairs (points, weights, points, weights): points in [-1, 1]², weights in [0.5, 2]."""
    rng = np.random.default_rng([seed, degree, 1])
    return [(rng.uniform(-1, 1, (degree + 1, 2)), rng.uniform(0.5, 2, degree + 1),
             rng.uniform(-1, 1, (degree + 1, 2)), rng.uniform(0.5, 2, degree + 1)) for _ in range(count)]


def _sorted_unique(found: np.ndarray) -> np.ndarray:
    """(k, 2) parameters sorted by t, then u, with repeats closer than 1e-7 dropped."""
    if not len(found):
        return np.zeros((0, 2))
    found = found[np.lexsort((found[:, 1], found[:, 0]))]
    keep = np.concatenate([[True], np.abs(np.diff(found, axis=0)).max(axis=1) > 1e-7])
    return found[keep]


def agreement(ours: list[np.ndarray], theirs: list[np.ndarray]) -> tuple[int, float]:
    """(pairs whose intersection counts differ, largest parameter difference over the pairs that agree)."""
    mismatched, worst = 0, 0.0
    for a, b in zip(ours, theirs):
        b = _sorted_unique(np.asarray(b, dtype=float))
        if a.shape != b.shape:
            mismatched += 1
        elif len(a):
            worst = max(worst, float(np.abs(a - b).max()))
    return mismatched, worst


def intersection_cases(plan: Plan) -> list[Case]:
    cases = []
    for degree in DEGREES:
        pairs = random_pairs(degree)
        candidates = {CLIPPING: lambda: [intersect_curves(p, q) for p, q in pairs]}
        if peers.available("bezier"):
            import bezier

            curves = [tuple(bezier.Curve(np.asfortranarray(c.T), degree=degree, copy=True) for c in pair)
                      for pair in pairs]
            candidates[BEZIER_INTERSECT] = lambda: [a.intersect(b).T for a, b in curves]
        timings = compare(candidates, plan)
        case = Case("intersection", {"degree": degree, "pairs": PAIRS})
        ours = timings[CLIPPING].output
        record(case, CLIPPING, timings[CLIPPING])
        case.extra["intersections"] = sum(len(found) for found in ours)
        if BEZIER_INTERSECT in timings:
            mismatched, worst = agreement(ours, timings[BEZIER_INTERSECT].output)
            entry = record(case, BEZIER_INTERSECT, timings[BEZIER_INTERSECT], timings[CLIPPING].seconds, worst)
            entry.note = f"{mismatched} pair(s) with a different count" if mismatched else ""
            case.extra["mismatched pairs"] = mismatched
        else:
            record(case, BEZIER_INTERSECT, None, note="bezier not installed")
        progress(f"[intersection] degree {degree}, {PAIRS} pairs, {case.extra['intersections']} intersections: "
                 f"{_summary(case)}")
        cases.append(case)
    cases.append(_rational_case(plan))
    return cases


def _rational_case(plan: Plan, degree: int = 3) -> Case:
    pairs = random_rational_pairs(degree)
    timings = compare({
        CLIPPING: lambda: [intersect_curves(p, q, p_weights=pw, q_weights=qw) for p, pw, q, qw in pairs],
        IMPLICITIZATION: lambda: [intersect_by_implicitization(p, q, pw, qw) for p, pw, q, qw in pairs],
    }, plan)
    case = Case("rational intersection", {"degree": degree, "pairs": PAIRS, "weights": "0.5-2"})
    ours = timings[CLIPPING].output
    record(case, CLIPPING, timings[CLIPPING])
    mismatched, worst = agreement(ours, timings[IMPLICITIZATION].output)
    entry = record(case, IMPLICITIZATION, timings[IMPLICITIZATION], timings[CLIPPING].seconds, worst)
    entry.note = f"{mismatched} pair(s) with a different count" if mismatched else ""
    case.extra["intersections"] = sum(len(found) for found in ours)
    case.extra["mismatched pairs"] = mismatched
    progress(f"[intersection] rational degree {degree}, {PAIRS} pairs, {case.extra['intersections']} intersections: "
             f"{_summary(case)}")
    return case


cases = intersection_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    target = (f"`intersect_curves` within {TIME_FACTOR}× of `bezier`'s `Curve.intersect` on {PAIRS} random cubic "
              f"pairs, the same intersections to {AGREEMENT:g}")
    verdicts = [_rational_verdict(found)]
    case = next((c for c in found if c.section == "intersection" and c.params["degree"] == 3
                 and c.get(BEZIER_INTERSECT) and c.get(BEZIER_INTERSECT).seconds), None)
    if case is None:
        return [Verdict(target, "—", None, "bezier not installed" if found else "")] + verdicts
    ratio = case.get(CLIPPING).seconds / case.get(BEZIER_INTERSECT).seconds
    agrees = case.extra.get("mismatched pairs", 0) == 0 and case.get(BEZIER_INTERSECT).difference <= AGREEMENT
    detail = ("the clipping is batched over the live pairs of pieces, but a random cubic pair needs about 5 rounds "
              "with only 1-2 pairs of pieces alive: each round is some 60 small NumPy operations (50-70 µs however "
              "few pieces), the peer spends about 30 µs on a whole pair in compiled Fortran"
              if ratio > TIME_FACTOR else "")
    return [Verdict(target, f"{ratio:.1f}× the time, largest difference {case.get(BEZIER_INTERSECT).difference:.1e}",
                    ratio <= TIME_FACTOR and agrees, detail)] + verdicts


def _rational_verdict(found: list[Case]) -> Verdict:
    target = (f"`intersect_curves` on {PAIRS} random rational cubic pairs: the same intersections as "
              f"implicitization to {AGREEMENT:g}")
    case = next((c for c in found if c.section == "rational intersection"), None)
    if case is None:
        return Verdict(target, "—", None, "")
    other = case.get(IMPLICITIZATION)
    agrees = case.extra["mismatched pairs"] == 0 and other.difference <= AGREEMENT
    slower = other.seconds / case.get(CLIPPING).seconds
    return Verdict(target, f"{case.extra['mismatched pairs']} pair(s) differ, largest difference "
                   f"{other.difference:.1e}; implicitization {slower:.1f}× the time", agrees, "")

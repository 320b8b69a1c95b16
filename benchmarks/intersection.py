"""Intersections of planar Bézier curves: `intersect_curves` against the `bezier` package, in time and in being right.

`cagd_ref.intersection.intersect_curves` is the course's Bézier-clipping
intersector (notes §7.7) in pure Python and NumPy: polynomial curves are
clipped on Python floats and finished by Newton's method once two pieces can
cross only once; rational curves are clipped in NumPy, every live pair of
pieces of a call at once. The `bezier` package
(D. Hermes) intersects with compiled Fortran (bounding-box subdivision, then
Newton's method). Each timing case is one pass over 100 seeded random pairs of
a degree, the same pairs for both, the peer's `Curve` objects built outside
the clock. The agreement is checked pair by pair: the same number of
intersections, and the largest difference of a parameter t or u (the peer may
report an intersection twice; repeats closer than 1e-7 are dropped before
comparing). `bezier` has no rational curves: 100 random rational cubic pairs
are checked against intersection by implicitization
(`intersect_by_implicitization`, §7.4), an independent algorithm of the same
module. Last, both run the 53 cases of the `bezier` package's own functional
suite (tests/ref/data/bezier/, Apache-2.0): how many each gets right, against
the exact parameters of the suite.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.intersection import intersect_by_implicitization, intersect_curves

from . import peers
from .common import ROOT, Case, Plan, compare, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Curve intersection"
ABOUT = ("100 seeded random pairs of planar Bézier curves per degree, intersected by Bézier clipping "
         "(`intersect_curves`: pure Python for polynomial curves, finished by Newton's method) and "
         "by the `bezier` package's compiled `Curve.intersect`; agreement pair by pair (the same number of "
         "intersections, the largest parameter difference). 100 random rational cubic pairs, which `bezier` "
         "cannot intersect, against implicitization (`intersect_by_implicitization`). The 53 cases of the "
         "`bezier` package's functional suite, run by both: cases right (the suite's number of intersections, "
         "each within 1e-9 of the suite's exact parameters, 1e-7 for a contact of equal curvature; for "
         "`intersect_curves` the overlap of case 20 refused with a ValueError, as documented). Most of "
         "`intersect_curves`' time on the suite goes to cases 42 and 45, two curves touching with equal "
         "curvature, where clipping has to cut the curves into hundreds of pieces before they look flat "
         "(`bezier` gives up on both), and to the overlap check of case 20.")
TIME_FACTOR = 3
AGREEMENT = 1e-9

CLIPPING = "cagd_ref intersect_curves"
BEZIER_INTERSECT = "bezier Curve.intersect"
IMPLICITIZATION = "cagd_ref intersect_by_implicitization"
PAIRS = 100
DEGREES = (3, 5)
SEED = 7_2017
# The bezier package's functional suite (copied with its licence, see the README there).
SUITE = ROOT / "tests" / "ref" / "data" / "bezier"
SUITE_TOL = 1e-9  # a case is right when every parameter is within this of the suite's exact one
CONTACTS = {42: 1e-7, 45: 1e-7}  # tangent with equal curvature: the docstring promises about 1e-7
OVERLAP_CASE = 20  # curves that share a piece: `intersect_curves` raises a ValueError, as documented


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
    cases.append(_suite_case(plan))
    return cases


def suite_number(value) -> float:
    """A number of the suite's files: an integer, a fraction "p/q" or a C99 hex float."""
    if isinstance(value, int):
        return float(value)
    if value.lstrip("-").startswith("0x"):
        return float.fromhex(value)
    numerator, denominator = value.split("/")
    return int(numerator) / int(denominator)


def suite_cases() -> list[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
    """The suite's cases as (id, p (n+1, 2), q (m+1, 2), expected (k, 2) sorted by t)."""
    import json

    curves = json.loads((SUITE / "curves.json").read_text(encoding="utf-8"))
    found = []
    for entry in json.loads((SUITE / "curve_intersections.json").read_text(encoding="utf-8")):
        p, q = (np.array([[suite_number(v) for v in row] for row in curves[entry[key]]["control_points"]]).T
                for key in ("curve1", "curve2"))
        expected = np.array([[suite_number(v) for v in entry[key]] for key in ("curve1_params", "curve2_params")],
                            dtype=float).reshape(2, -1).T
        found.append((entry["id"], p, q, expected[np.lexsort((expected[:, 1], expected[:, 0]))]))
    return found


def _suite_right(case_id: int, expected: np.ndarray, outcome, refuses_overlap: bool) -> tuple[bool, float]:
    """(right, largest parameter error) of one library's outcome (an array (k, 2) or the exception it raised)."""
    if isinstance(outcome, Exception):
        return refuses_overlap and case_id == OVERLAP_CASE and isinstance(outcome, ValueError), 0.0
    found = _sorted_unique(np.asarray(outcome, dtype=float))
    if found.shape != expected.shape:
        return False, 0.0
    error = float(np.abs(found - expected).max(initial=0.0))
    return error <= CONTACTS.get(case_id, SUITE_TOL), error


def _suite_case(plan: Plan) -> Case:
    cases = suite_cases()

    def ours():
        outcomes = []
        for _, p, q, _ in cases:
            try:
                outcomes.append(intersect_curves(p, q))
            except ValueError as err:
                outcomes.append(err)
        return outcomes

    candidates = {CLIPPING: ours}
    if peers.available("bezier"):
        import bezier

        curves = [tuple(bezier.Curve(np.asfortranarray(c.T), degree=len(c) - 1, copy=True) for c in (p, q))
                  for _, p, q, _ in cases]

        def theirs():
            outcomes = []
            for a, b in curves:
                try:
                    outcomes.append(a.intersect(b).T)
                except Exception as err:  # the package raises NotImplementedError on cases it cannot do
                    outcomes.append(err)
            return outcomes

        candidates[BEZIER_INTERSECT] = theirs
    timings = compare(candidates, plan)
    case = Case("bezier functional suite", {"cases": len(cases)})
    record(case, CLIPPING, timings[CLIPPING])
    for name, label in ((CLIPPING, "ours"), (BEZIER_INTERSECT, "bezier")):
        if name not in timings:
            continue
        if name != CLIPPING:
            record(case, name, timings[name], timings[CLIPPING].seconds)
        judged = [_suite_right(case_id, expected, outcome, name == CLIPPING)
                  for (case_id, _, _, expected), outcome in zip(cases, timings[name].output)]
        case.extra[f"right ({label})"] = sum(right for right, _ in judged)
        wrong = [case_id for (case_id, *_), (right, _) in zip(cases, judged) if not right]
        case.extra[f"wrong ({label})"] = ", ".join(map(str, wrong)) or "none"
        case.extra[f"largest error ({label})"] = max(
            (error for (case_id, *_), (right, error) in zip(cases, judged) if right and case_id not in CONTACTS),
            default=0.0)
    if BEZIER_INTERSECT not in timings:
        record(case, BEZIER_INTERSECT, None, note="bezier not installed")
    progress(f"[intersection] bezier functional suite, {len(cases)} cases: {case.extra['right (ours)']} right "
             f"(wrong: {case.extra['wrong (ours)']}); {_summary(case)}")
    return case


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
    verdicts = [_rational_verdict(found), _suite_verdict(found)]
    case = next((c for c in found if c.section == "intersection" and c.params["degree"] == 3
                 and c.get(BEZIER_INTERSECT) and c.get(BEZIER_INTERSECT).seconds), None)
    if case is None:
        return [Verdict(target, "—", None, "bezier not installed" if found else "")] + verdicts
    ratio = case.get(CLIPPING).seconds / case.get(BEZIER_INTERSECT).seconds
    agrees = case.extra.get("mismatched pairs", 0) == 0 and case.get(BEZIER_INTERSECT).difference <= AGREEMENT
    detail = ("a random cubic pair takes about 6 clips and 3 Newton steps on Python floats; each clip costs a "
              "few µs of interpreted arithmetic, the peer spends about 30 µs on a whole pair in compiled Fortran"
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


def _suite_verdict(found: list[Case]) -> Verdict:
    target = ("`intersect_curves` right on every case of the `bezier` package's functional suite (the overlap of "
              "case 20 refused as documented)")
    case = next((c for c in found if c.section == "bezier functional suite"), None)
    if case is None:
        return Verdict(target, "—", None, "")
    total = case.params["cases"]
    measured = f"{case.extra['right (ours)']} of {total} right, largest error {case.extra['largest error (ours)']:.1e}"
    detail = ""
    if "right (bezier)" in case.extra:
        detail = (f"`bezier`'s own `Curve.intersect`: {case.extra['right (bezier)']} of {total} "
                  f"(wrong: {case.extra['wrong (bezier)']})")
    return Verdict(target, measured, case.extra["right (ours)"] == total, detail)

"""Knot insertion and Bézier extraction of B-splines: ours against SciPy and geomdl.

One cubic (by default) B-spline per size, with uniform interior knots and
Bézier end conditions on [0, 1]. Insertion adds one knot at u = 0.618...,
which is no existing knot, and returns the new control points. Extraction
returns the Bézier control points of every segment: SciPy has no routine for
it, so its column raises every interior knot to multiplicity n with
`BSpline.insert_knot`, the way a SciPy user would.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bspline import bezier_end_knots, bezier_segments, insert_knot, to_scipy

from . import peers
from .common import Candidate, Case, Plan, compare, max_difference, progress, record
from .evaluation import SEED, _summary
from .targets import Verdict

INSERTED = (5**0.5 - 1) / 2

INSERT = "cagd_ref insert_knot"
EXTRACT = "cagd_ref bezier_segments"
SCIPY_INSERT = "SciPy insert_knot"
SCIPY_EXTRACT = "SciPy insert_knot, repeated"
GEOMDL_INSERT = "geomdl insert_knot"
GEOMDL_EXTRACT = "geomdl decompose_curve"
TIME_FACTOR = 2  # the target: within 2x of SciPy at every size measured


def knot_cases(plan: Plan) -> list[Case]:
    rng = np.random.default_rng(SEED + 2)
    n = plan.knot_degree
    cases = []
    for count in plan.knot_counts:
        points = rng.uniform(-1, 1, size=(count, 2))
        knots = bezier_end_knots(count, n, 0.0, 1.0)
        full_knots, _, _ = to_scipy(points, knots)
        scipy = peers.scipy_bspline(points, full_knots, n) if peers.available("scipy") else None
        geomdl = peers.geomdl_curve(points, full_knots, n) if peers.available("geomdl") else None
        operations = {
            "insertion": (
                INSERT,
                lambda: insert_knot(points, knots, INSERTED)[0],
                SCIPY_INSERT,
                lambda: peers.scipy_insert(scipy, INSERTED),
                GEOMDL_INSERT,
                Candidate(lambda copy: peers.geomdl_insert(copy, INSERTED), lambda: peers.fresh_copy(geomdl)),
            ),
            "extraction": (
                EXTRACT,
                lambda: bezier_segments(points, knots),
                SCIPY_EXTRACT,
                lambda: peers.scipy_bezier_segments(scipy),
                GEOMDL_EXTRACT,
                lambda: peers.geomdl_bezier_segments(geomdl),
            ),
        }
        for operation, (ours, run, scipy_name, scipy_run, geomdl_name, geomdl_run) in operations.items():
            candidates = {ours: run}
            if scipy is not None:
                candidates[scipy_name] = scipy_run
            if geomdl is not None:
                candidates[geomdl_name] = geomdl_run
            timings = compare(candidates, plan)
            case = Case("knots", {"operation": operation, "degree": n, "control points": count})
            reference = timings[ours].output
            for method, timing in timings.items():
                record(case, method, timing, timings[ours].seconds, max_difference(reference, timing.output))
            for method, peer in ((scipy_name, "scipy"), (geomdl_name, "geomdl")):
                if case.get(method) is None:
                    record(case, method, None, note=f"{peer} not installed")
            progress(f"[knots] {operation}, degree {n}, {count} control points: {_summary(case)}")
            cases.append(case)
    return cases


def verdicts(found: list[Case]) -> list[Verdict]:
    """Insertion and extraction each within TIME_FACTOR x SciPy's time, at the worst size measured."""
    judged = []
    for operation, ours, scipy in (("insertion", INSERT, SCIPY_INSERT), ("extraction", EXTRACT, SCIPY_EXTRACT)):
        target = f"knot {operation} within {TIME_FACTOR}× of SciPy at every size measured"
        ratios = [(case, case.get(ours).seconds / case.get(scipy).seconds) for case in found
                  if case.params["operation"] == operation and case.get(scipy) and case.get(scipy).seconds]
        if not ratios:
            judged.append(Verdict(target, "—", None, "SciPy not measured"))
            continue
        case, worst = max(ratios, key=lambda item: item[1])
        judged.append(Verdict(target, f"{worst:.2f}× at worst", worst <= TIME_FACTOR,
                              f"worst at {case.params['control points']} control points"))
    return judged

"""Evaluating curves at many parameters: Bézier curves and B-splines, ours against the peers.

Every case evaluates a random planar curve (seeded) at k evenly spaced
parameters covering its whole domain, the way a curve is sampled for drawing
or tessellation. geomdl, pure Python, runs on an evenly spaced subset of the
same parameters when k is above the plan's `geomdl_max_points`, and its time
is then scaled linearly to k and marked as extrapolated.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bezier import de_casteljau, evaluate
from cagd_ref.bspline import bezier_end_knots, de_boor, to_scipy

from . import peers
from .common import Candidate, Case, Plan, compare, format_count, format_seconds, max_difference, progress, record

SEED = 20240601


def _geomdl_subset(t: np.ndarray, plan: Plan) -> np.ndarray:
    """Indices of the parameters geomdl is run on: all of them, or an evenly spaced subset."""
    if len(t) <= plan.geomdl_max_points:
        return np.arange(len(t))
    return np.unique(np.round(np.linspace(0, len(t) - 1, plan.geomdl_max_points)).astype(int))


def _record_all(case: Case, timings: dict, subject: str, ours: np.ndarray, subset: np.ndarray | None = None,
                subset_method: str | None = None) -> None:
    """Turn the timings of one case into measurements; the subset method is compared and scaled on its subset."""
    base = timings[subject].seconds
    for method, timing in timings.items():
        if method == subset_method and len(subset) < len(ours):
            record(case, method, timing, base, max_difference(ours[subset], timing.output),
                   extrapolated_from=len(subset), scale=len(ours) / len(subset))
        else:
            record(case, method, timing, base, max_difference(ours, timing.output))


def _summary(case: Case) -> str:
    parts = []
    for m in case.measurements:
        if m.seconds is None:
            continue
        ratio = "" if m.ratio is None or m.method == case.measurements[0].method else f" (×{m.ratio:.2g})"
        extra = " extrapolated" if m.extrapolated_from else ""
        parts.append(f"{m.method} {format_seconds(m.seconds)}{ratio}{extra}")
    return "; ".join(parts)


# --- Bézier curves ------------------------------------------------------------------------

BEZIER_EVALUATE = "cagd_ref evaluate"
BEZIER_DE_CASTELJAU = "cagd_ref de_casteljau"
BEZIER_PACKAGE = "bezier evaluate_multi"
BEZIER_GEOMDL = "geomdl evaluate_list"
BEZIER_MATRIX = "NumPy Bernstein matrix"


def bezier_cases(plan: Plan) -> list[Case]:
    rng = np.random.default_rng(SEED)
    cases = []
    for n in plan.bezier_degrees:
        points = rng.uniform(-1, 1, size=(n + 1, 2))
        package = peers.bezier_package_evaluator(points) if peers.available("bezier") else None
        geomdl = peers.geomdl_bezier_evaluator(points) if peers.available("geomdl") else None
        for k in plan.bezier_sizes:
            t = np.linspace(0, 1, k)
            subset = _geomdl_subset(t, plan)
            t_geomdl = t[subset]
            candidates = {
                BEZIER_EVALUATE: lambda: evaluate(points, t),
                BEZIER_DE_CASTELJAU: lambda: de_casteljau(points, t),
                BEZIER_MATRIX: lambda: peers.bernstein_matrix_baseline(points, t),
            }
            if package:
                candidates[BEZIER_PACKAGE] = lambda: package(t)
            if geomdl:
                candidates[BEZIER_GEOMDL] = lambda: geomdl(t_geomdl)
            timings = compare(candidates, plan)
            case = Case("bezier", {"degree": n, "values": k})
            _record_all(case, timings, BEZIER_EVALUATE, timings[BEZIER_EVALUATE].output, subset, BEZIER_GEOMDL)
            for method, peer in ((BEZIER_PACKAGE, "bezier"), (BEZIER_GEOMDL, "geomdl")):
                if case.get(method) is None:
                    record(case, method, None, note=f"{peer} not installed")
            progress(f"[bezier] degree {n}, {format_count(k)} values: {_summary(case)}")
            cases.append(case)
    return cases


# --- B-splines ----------------------------------------------------------------------------

DE_BOOR = "cagd_ref de_boor"
SCIPY_BSPLINE = "SciPy BSpline"
GEOMDL_BSPLINE = "geomdl evaluate_list"


def bspline_cases(plan: Plan) -> list[Case]:
    rng = np.random.default_rng(SEED + 1)
    cases = []
    for n in plan.bspline_degrees:
        for count in plan.bspline_counts:
            points = rng.uniform(-1, 1, size=(count, 2))
            # Uniform interior knots on [0, 1] with Bézier end conditions (notes' convention, c + n - 1 knots).
            knots = bezier_end_knots(count, n, 0.0, 1.0)
            full_knots, _, _ = to_scipy(points, knots)
            scipy = peers.scipy_bspline(points, full_knots, n) if peers.available("scipy") else None
            geomdl = (peers.geomdl_evaluator(peers.geomdl_curve(points, full_knots, n))
                      if peers.available("geomdl") else None)
            for k in plan.bspline_sizes:
                t = np.linspace(0, 1, k)
                subset = _geomdl_subset(t, plan)
                t_geomdl = t[subset]
                candidates = {DE_BOOR: lambda: de_boor(points, knots, t)}
                if scipy is not None:
                    candidates[SCIPY_BSPLINE] = Candidate(lambda: scipy(t))
                if geomdl is not None:
                    candidates[GEOMDL_BSPLINE] = lambda: geomdl(t_geomdl)
                timings = compare(candidates, plan)
                case = Case("bspline", {"degree": n, "control points": count, "values": k})
                _record_all(case, timings, DE_BOOR, timings[DE_BOOR].output, subset, GEOMDL_BSPLINE)
                for method, peer in ((SCIPY_BSPLINE, "scipy"), (GEOMDL_BSPLINE, "geomdl")):
                    if case.get(method) is None:
                        record(case, method, None, note=f"{peer} not installed")
                progress(f"[bspline] degree {n}, {count} control points, {format_count(k)} values: {_summary(case)}")
                cases.append(case)
    return cases

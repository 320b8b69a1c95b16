"""Least-squares B-spline fitting: ours against SciPy's `make_lsq_spline`.

Noisy planar samples of a smooth curve at sorted random parameters on
[0, 1] (the first at 0 and the last at 1), fitted by a cubic with uniform
interior knots and Bézier end conditions: 10^3 to 10^5 samples, 10 to 200
control points. Both solve the same normal equations in band form; SciPy
gets the knots converted with `to_scipy` and the samples as one (M, 2) array,
and its coefficients are compared with our control points.

The plan of `benchmarks.common` has no sizes for this section yet: a plan
with `fit_samples`/`fit_counts` fields uses them, the full plan the sizes
above, any other plan (quick, the tests' tiny one) two small sizes.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.approximation import least_squares_fit
from cagd_ref.bspline import bezier_end_knots, to_scipy

from .common import Case, Plan, compare, max_difference, progress, record
from .evaluation import SEED, _summary
from .targets import Verdict

TITLE = "Least-squares B-spline fitting"
ABOUT = ("Noisy planar samples at sorted random parameters, fitted by a cubic B-spline with uniform interior knots "
         "and Bézier end conditions: `least_squares_fit` (banded normal equations) against SciPy's "
         "`make_lsq_spline` with the knots converted, coefficients compared.")

FIT = "cagd_ref least_squares_fit"
SCIPY_FIT = "SciPy make_lsq_spline"
DEGREE = 3
FULL_SAMPLES, FULL_COUNTS = (10**3, 10**4, 10**5), (10, 50, 200)
QUICK_SAMPLES, QUICK_COUNTS = (10**3, 10**4), (10, 50)
# The targets: within this factor of SciPy's time, and this close to its coefficients.
TIME_FACTOR, AGREEMENT = 3.0, 1e-9


def fit_sizes(plan: Plan) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """(sample counts, control point counts) of a plan."""
    if hasattr(plan, "fit_samples"):
        return plan.fit_samples, plan.fit_counts
    return (FULL_SAMPLES, FULL_COUNTS) if plan.name == "full" else (QUICK_SAMPLES, QUICK_COUNTS)


def samples(count: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """(points (count, 2), params (count,)): a wave with noise at sorted random parameters spanning [0, 1]."""
    params = np.sort(rng.uniform(0.0, 1.0, count))
    params[0], params[-1] = 0.0, 1.0
    curve = np.column_stack([np.cos(3 * params), np.sin(5 * params) + params])
    return curve + 0.01 * rng.normal(size=curve.shape), params


def fit_cases(plan: Plan) -> list[Case]:
    from scipy.interpolate import make_lsq_spline

    rng = np.random.default_rng(SEED + 3)
    sample_counts, control_counts = fit_sizes(plan)
    cases = []
    for m in sample_counts:
        points, params = samples(m, rng)
        for count in control_counts:
            knots = bezier_end_knots(count, DEGREE, 0.0, 1.0)
            full_knots, _, _ = to_scipy(np.zeros((count, 1)), knots)
            timings = compare(
                {
                    FIT: lambda: least_squares_fit(points, params, knots, DEGREE),
                    SCIPY_FIT: lambda: make_lsq_spline(params, points, full_knots, DEGREE).c,
                },
                plan,
            )
            case = Case("fitting", {"degree": DEGREE, "samples": m, "control points": count})
            ours = timings[FIT]
            for method, timing in timings.items():
                record(case, method, timing, ours.seconds, max_difference(ours.output, timing.output))
            progress(f"[fitting] {m} samples, {count} control points: {_summary(case)}")
            cases.append(case)
    return cases


def worst_case(cases: list[Case]) -> tuple[Case, float, float] | None:
    """The case where we are slowest relative to SciPy: (case, our time / SciPy's, largest coefficient difference)."""
    measured = [(c, c.get(FIT).seconds / c.get(SCIPY_FIT).seconds) for c in cases
                if c.get(SCIPY_FIT) and c.get(SCIPY_FIT).seconds]
    if not measured:
        return None
    case, ratio = max(measured, key=lambda item: item[1])
    difference = max(c.get(SCIPY_FIT).difference for c, _ in measured)
    return case, ratio, difference


cases = fit_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    target = f"`least_squares_fit` within {TIME_FACTOR}× of SciPy's `make_lsq_spline`, agreeing to {AGREEMENT:g}"
    worst = worst_case(found)
    if worst is None:
        return [Verdict(target, "—", None)]
    case, ratio, difference = worst
    detail = f"worst case {case.params}"
    return [Verdict(target, f"{ratio:.2f}× at worst, difference {difference:.1e}",
                    ratio <= TIME_FACTOR and difference <= AGREEMENT, detail)]

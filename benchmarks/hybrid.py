"""The area under rational cubics: the hybrid method of chapter 20 against scipy.integrate.quad and Simpson's rule.

The notes claim (§20.4) that integrating polynomial approximations built from
hybrid curves beats numerical quadrature. Measured here on the notes'
semicircle and on seeded random rational cubics (positive weights, ratios up
to 10), at tolerances 1e-3 to 1e-12: `bezier_area` (a guaranteed bound),
`scipy.integrate.quad` of y(t) x'(t) asked for the same absolute tolerance
(adaptive Gauss-Kronrod, an error estimate without a guarantee) and the
composite Simpson rule of `simpson_area` (the notes' heuristic of comparing k
and 2k intervals). Each method's true error is measured against the hybrid
method run at 1e-13 (cross-checked with quad at 1e-14 when the section starts).

Work is counted in each method's own unit: pieces examined (one hybrid
conversion, one bound and one closed form each) for ours, integrand
evaluations for quad and Simpson; the times are the fair comparison. The
integrand for quad is a scalar function on precomputed power coefficients
(`area_integrand`), as a SciPy user would write it; Simpson evaluates the
curve with `cagd_ref.bezier` at all its parameters at once.

The plan of `benchmarks.common` has no field for this section: a plan with
`hybrid_tolerances` uses it, the full plan the tolerances above, any other
plan (quick, the tests' tiny one) three of them.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bezier import to_homogeneous
from cagd_ref.hybrid import adaptive_integral, bezier_area, simpson_area
from cagd_ref.polynomials import bernstein_to_power

from .common import Case, Plan, compare, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Areas under rational curves"
ABOUT = ("The notes' semicircle and seeded random rational cubics at tolerances 1e-3 to 1e-12: `bezier_area` (hybrid "
         "pieces with a proved bound) against `scipy.integrate.quad` (Gauss-Kronrod, an estimate) and the composite "
         "Simpson rule; the difference column is each method's true error, the notes count pieces or evaluations.")

HYBRID = "cagd_ref bezier_area"
QUAD = "scipy.integrate.quad"
SIMPSON = "cagd_ref simpson_area"
FULL_TOLERANCES = (1e-3, 1e-6, 1e-9, 1e-12)
QUICK_TOLERANCES = (1e-3, 1e-6, 1e-9)
CURVES = 4  # random rational cubics besides the semicircle


def hybrid_tolerances(plan: Plan) -> tuple[float, ...]:
    if hasattr(plan, "hybrid_tolerances"):
        return plan.hybrid_tolerances
    return FULL_TOLERANCES if plan.name == "full" else QUICK_TOLERANCES


def test_curves() -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The notes' semicircle and seeded random rational cubics with positive weights."""
    curves = {"semicircle": (np.array([[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]]), np.array([3.0, 1, 1, 3]))}
    rng = np.random.default_rng(20)
    for k in range(CURVES):
        curves[f"random cubic {k + 1}"] = (rng.uniform(-3, 3, (4, 2)), rng.uniform(0.3, 3.0, 4))
    return curves


def area_integrand(points, weights):
    """y(t) x'(t) of the rational curve as a fast scalar function: Horner on power coefficients of X, Y, W.

    x = X/W gives y x' = Y (X' W - X W') / W³. Built once per curve (set-up, not timed), so that quad is
    charged for its evaluations and not for our input checks.
    """
    X, Y, W = (np.poly1d(c[::-1]) for c in bernstein_to_power(to_homogeneous(points, weights)).T)
    dX, dW = X.deriv(), W.deriv()

    def integrand(t: float) -> float:
        w = W(t)
        return Y(t) * (dX(t) * w - X(t) * dW(t)) / w**3

    return integrand


def quad_area(integrand, tol: float) -> tuple[float, int]:
    """∫ y x' dt by scipy.integrate.quad to the absolute tolerance tol: (value, integrand evaluations)."""
    from scipy.integrate import quad

    value, _, info = quad(integrand, 0.0, 1.0, epsabs=tol, epsrel=0.0, limit=500, full_output=True)[:3]
    return value, int(info["neval"])


def hybrid_cases(plan: Plan) -> list[Case]:
    cases = []
    for name, (points, weights) in test_curves().items():
        exact = adaptive_integral(points, weights, 1e-13 * max(1.0, np.abs(points).max() ** 2)).value
        integrand = area_integrand(points, weights)
        check, _ = quad_area(integrand, 1e-14)
        for tol in hybrid_tolerances(plan):
            timings = compare(
                {
                    HYBRID: lambda: bezier_area(points, weights, tol),
                    QUAD: lambda: quad_area(integrand, tol),
                    SIMPSON: lambda: simpson_area(points, weights, tol),
                },
                plan,
            )
            case = Case("hybrid", {"curve": name, "tol": tol})
            values = {HYBRID: timings[HYBRID].output, QUAD: timings[QUAD].output[0],
                      SIMPSON: timings[SIMPSON].output.value}
            work = {HYBRID: adaptive_integral(points, weights, tol).work, QUAD: timings[QUAD].output[1],
                    SIMPSON: timings[SIMPSON].output.work}
            for method, timing in timings.items():
                entry = record(case, method, timing, timings[HYBRID].seconds, abs(values[method] - exact))
                entry.note = f"{work[method]} {'pieces' if method == HYBRID else 'evaluations'}"
                if entry.difference > tol:
                    entry.note += f", missed tol by ×{entry.difference / tol:.1f}"
            case.extra.update({"work": work, "quad check": abs(check - exact)})
            progress(f"[hybrid] {name}, tol {tol:.0e}: {_summary(case)}; errors "
                     + ", ".join(f"{m.method} {m.difference:.1e} ({m.note})" for m in case.measurements))
            cases.append(case)
    return cases


def fastest_within_tolerance(cases: list[Case], tol: float) -> dict[str, float]:
    """Median time over the curves at one tolerance, per method, counting only results within tol."""
    chosen = [c for c in cases if c.params["tol"] == tol]
    times: dict[str, list[float]] = {}
    for case in chosen:
        for m in case.measurements:
            if m.seconds is not None and m.difference is not None and m.difference <= tol:
                times.setdefault(m.method, []).append(m.seconds)
    return {method: float(np.median(values)) for method, values in times.items()}


cases = hybrid_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    """The guarantee is the target; the time against quad is reported, not required (the notes' claim, measured)."""
    target = "`bezier_area` within its tolerance on every curve and tolerance (time against `quad` reported)"
    if not found:
        return [Verdict(target, "—", None)]
    misses = [c for c in found if c.get(HYBRID).difference > c.params["tol"]]
    tol = min(c.params["tol"] for c in found)
    medians = fastest_within_tolerance(found, tol)
    ratio = medians[HYBRID] / medians[QUAD] if HYBRID in medians and QUAD in medians else float("nan")
    return [Verdict(target, f"{len(misses)} of {len(found)} cases outside tol; at tol {tol:g} "
                            f"{ratio:.1f}× the time of quad", not misses,
                    "quad reaches far more accuracy than asked for; only the hybrid bound is a guarantee")]

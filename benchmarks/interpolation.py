"""Evaluating an interpolating polynomial at many parameters: Newton, Lagrange and Neville against SciPy.

Planar data at the n+1 Chebyshev nodes of [0, 1] (degrees 3, 10 and 20),
evaluated at 10^6 evenly spaced parameters (10^4 in the quick plan). Ours:
`newton_eval` (nested form, the coefficients from `divided_differences`),
`lagrange_eval` (the basis by running products) and `neville` (the
O(n²) triangle); the peer is SciPy's `BarycentricInterpolator`. As everywhere
in the benchmarks, building a peer's object is set-up and not timed; so is our
divided-difference table, the Newton form's counterpart of that object. Every
result is compared with SciPy's.

The plan of `benchmarks.common` has no sizes for this section yet: a plan
with `interpolation_degrees`/`interpolation_sizes` fields uses them, the full
plan the sizes above, any other plan (quick, the tests' tiny one) small ones.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.interpolation import chebyshev_nodes, divided_differences, lagrange_eval, neville, newton_eval

from .common import Case, Plan, compare, max_difference, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Polynomial interpolation"
ABOUT = ("Planar data at the Chebyshev nodes of [0, 1], evaluated at evenly spaced parameters by the notes' "
         "algorithms (`newton_eval`, `lagrange_eval`, `neville`) and by SciPy's `BarycentricInterpolator`; the "
         "ratios are to `newton_eval`.")
TIME_FACTOR = 2
AGREEMENT = 1e-12

NEWTON = "cagd_ref newton_eval"
LAGRANGE = "cagd_ref lagrange_eval"
NEVILLE = "cagd_ref neville"
BARYCENTRIC = "SciPy BarycentricInterpolator"
FULL_DEGREES, FULL_SIZES = (3, 10, 20), (10**6,)
QUICK_DEGREES, QUICK_SIZES = (3, 10), (10**4,)


def interpolation_sizes(plan: Plan) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """(degrees, numbers of parameters) of a plan."""
    if hasattr(plan, "interpolation_degrees"):
        return plan.interpolation_degrees, plan.interpolation_sizes
    return (FULL_DEGREES, FULL_SIZES) if plan.name == "full" else (QUICK_DEGREES, QUICK_SIZES)


def data(n: int) -> tuple[np.ndarray, np.ndarray]:
    """(nodes (n+1,), points (n+1, 2)): a smooth planar curve sampled at the Chebyshev nodes of [0, 1]."""
    nodes = chebyshev_nodes(0.0, 1.0, n + 1)
    return nodes, np.column_stack([np.cos(3 * nodes), np.sin(5 * nodes) + nodes])


def interpolation_cases(plan: Plan) -> list[Case]:
    from scipy.interpolate import BarycentricInterpolator

    degrees, sizes = interpolation_sizes(plan)
    cases = []
    for size in sizes:
        t = np.linspace(0.0, 1.0, size)
        for n in degrees:
            nodes, points = data(n)
            coeffs = divided_differences(nodes, points)
            peer = BarycentricInterpolator(nodes, points)
            timings = compare(
                {
                    NEWTON: lambda: newton_eval(nodes, coeffs, t),
                    LAGRANGE: lambda: lagrange_eval(nodes, points, t),
                    NEVILLE: lambda: neville(nodes, points, t),
                    BARYCENTRIC: lambda: peer(t),
                },
                plan,
            )
            case = Case("interpolation", {"degree": n, "values": size})
            reference = timings[BARYCENTRIC].output
            for method, timing in timings.items():
                record(case, method, timing, timings[NEWTON].seconds, max_difference(timing.output, reference))
            progress(f"[interpolation] degree {n}, {size} values: {_summary(case)}")
            cases.append(case)
    return cases


def slowest_against_scipy(cases: list[Case], method: str = NEWTON) -> tuple[Case, float, float] | None:
    """The case where `method` is slowest relative to SciPy: (case, its time / SciPy's, largest difference)."""
    measured = [(c, c.get(method).seconds / c.get(BARYCENTRIC).seconds) for c in cases
                if c.get(method) and c.get(BARYCENTRIC) and c.get(BARYCENTRIC).seconds]
    if not measured:
        return None
    case, ratio = max(measured, key=lambda item: item[1])
    return case, ratio, max(c.get(method).difference for c, _ in measured)


cases = interpolation_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    result = []
    for method in (NEWTON, LAGRANGE):
        target = f"`{method.split()[-1]}` within {TIME_FACTOR}× of SciPy's `BarycentricInterpolator`, agreeing to " \
                 f"{AGREEMENT:g}"
        worst = slowest_against_scipy(found, method)
        if worst is None:
            result.append(Verdict(target, "—", None))
            continue
        case, ratio, difference = worst
        detail = f"worst case degree {case.params['degree']} at {case.params['values']} values"
        result.append(Verdict(target, f"{ratio:.2f}× at worst, difference {difference:.1e}",
                              ratio <= TIME_FACTOR and difference <= AGREEMENT, detail))
    return result

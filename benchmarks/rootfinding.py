"""Roots of Wilkinson-type polynomials: the Bernstein-form root finder against power-form eigenvalue solvers.

The polynomial of degree n has the n roots k/(n+1), k = 1..n, spread evenly
inside (0, 1): Wilkinson's classic example of ill conditioning, squeezed into
the unit interval, the kind of test behind the conditioning result the notes
cite in chapter 9 ([FR87]). `cagd_ref.roots.wilkinson_polynomial` computes its
coefficients exactly, with fractions, in both bases and only then rounds them to
doubles: each solver starts from the correctly rounded coefficients of its own
basis, so the errors measure how well conditioned each representation is
(together with the solver), which is the notes' claim. numpy.roots takes
descending power coefficients, Polynomial.roots ascending ones; both return all
n complex roots.

The error of a solver is the largest distance from an exact root to the
computed root matched with it (roots sorted by real part, complex distance);
a solver that returns fewer roots is charged with the nearest one found.
Each case also records the time ratio bernstein_roots / numpy.roots next to
the error ratio numpy.roots / bernstein_roots: the issue's target at degree 20
is a time ratio of at most 10 with an error ratio of at least 10^6.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.roots import bernstein_roots, wilkinson_polynomial

from .common import Case, Plan, compare, progress, record
from .evaluation import _summary

BERNSTEIN = "cagd_ref bernstein_roots"
NUMPY_ROOTS = "numpy.roots (power form)"
POLYNOMIAL_ROOTS = "Polynomial.roots (power form)"


def wilkinson(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ascending power coefficients, Bernstein coefficients on [0, 1], exact roots) of Π (t - k/(n+1))."""
    bernstein, power, roots = wilkinson_polynomial(n)
    return power, bernstein, roots


def root_error(found, exact: np.ndarray) -> float:
    """Largest distance between an exact root and its computed partner; see the module docstring."""
    found = np.asarray(found, dtype=complex)
    if found.size == 0:
        return float("inf")
    found = found[np.argsort(found.real, kind="stable")]
    if len(found) == len(exact):
        return float(np.max(np.abs(found - exact)))
    return float(max(np.min(np.abs(found - r)) for r in exact))


def root_cases(plan: Plan) -> list[Case]:
    cases = []
    for n in plan.root_degrees:
        power, bernstein, exact = wilkinson(n)
        descending = power[::-1].copy()
        timings = compare(
            {
                BERNSTEIN: lambda: bernstein_roots(bernstein),
                NUMPY_ROOTS: lambda: np.roots(descending),
                POLYNOMIAL_ROOTS: lambda: np.polynomial.Polynomial(power).roots(),
            },
            plan,
        )
        case = Case("roots", {"degree": n})
        for method, timing in timings.items():
            entry = record(case, method, timing, timings[BERNSTEIN].seconds)
            entry.difference = root_error(timing.output, exact)
            if method == BERNSTEIN and len(timing.output) != n:
                entry.note = f"found {len(timing.output)} of {n} roots"
        errors = {m.method: m.difference for m in case.measurements}
        case.extra["error ratio"] = errors[NUMPY_ROOTS] / max(errors[BERNSTEIN], np.finfo(float).tiny)
        case.extra["time ratio"] = timings[BERNSTEIN].seconds / timings[NUMPY_ROOTS].seconds
        progress(
            f"[roots] degree {n}: {_summary(case)}; largest root error "
            + ", ".join(f"{m} {e:.1e}" for m, e in errors.items())
            + f"; bernstein_roots / numpy.roots time {case.extra['time ratio']:.1f}×"
        )
        cases.append(case)
    return cases

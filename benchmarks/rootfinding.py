"""Roots of Wilkinson-type polynomials: Bernstein-form clipping against power-form eigenvalue solvers.

The polynomial of degree n has the n roots k/(n+1), k = 1..n, spread evenly
inside (0, 1): Wilkinson's classic example of ill conditioning, squeezed into
the unit interval, the kind of test behind the conditioning result the notes
cite in chapter 9 ([FR87]). Its coefficients are computed exactly, with fractions, in both bases and
only then rounded to doubles: each solver starts from the correctly rounded
coefficients of its own basis, so the errors measure how well conditioned
each representation is (together with the solver), which is the notes'
claim. numpy.roots takes descending power coefficients,
Polynomial.roots ascending ones; both return all n complex roots.

The error of a solver is the largest distance from an exact root to the
computed root matched with it (roots sorted by real part, complex distance);
a solver that returns fewer roots is charged with the nearest one found.
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

import numpy as np

from cagd_ref.roots import bernstein_roots

from .common import Case, Plan, compare, progress, record
from .evaluation import _summary

BERNSTEIN = "cagd_ref bernstein_roots"
NUMPY_ROOTS = "numpy.roots (power form)"
POLYNOMIAL_ROOTS = "Polynomial.roots (power form)"


def wilkinson(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(ascending power coefficients, Bernstein coefficients on [0, 1], exact roots) of Π (t - k/(n+1))."""
    roots = [Fraction(k, n + 1) for k in range(1, n + 1)]
    power = [Fraction(1)]
    for r in roots:  # multiply by (t - r)
        power = [(power[j - 1] if j > 0 else 0) - r * (power[j] if j < len(power) else 0) for j in range(len(power) + 1)]
    # b_i = Σ_{j<=i} C(i, j) / C(n, j) a_j converts ascending power coefficients to the Bernstein basis.
    bernstein = [sum(Fraction(comb(i, j), comb(n, j)) * power[j] for j in range(i + 1)) for i in range(n + 1)]
    return _rounded(power), _rounded(bernstein), _rounded(roots)


def _rounded(values: list[Fraction]) -> np.ndarray:
    """Each exact value rounded once to the nearest double."""
    return np.array([float(v) for v in values])


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
        progress(f"[roots] degree {n}: {_summary(case)}; largest root error "
                 + ", ".join(f"{m} {e:.1e}" for m, e in errors.items()))
        cases.append(case)
    return cases

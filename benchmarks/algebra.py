"""Implicitization and resultants (chapter 17): `cagd_ref.algebra` against SymPy's exact elimination.

Implicitization: rational Bézier curves of degree 2-6 with small integer
control points and weights (seeded). Ours is `implicitize` (the Bézout matrix
of lines l_ij and its determinant expanded as a polynomial, in floating
point); the peer is SymPy's exact `resultant(x W(t) - X(t), y W(t) - Y(t), t)`
on the same curve in power form, its expansion into a coefficient array
included in its time. The two equations are compared after dividing each by
its largest coefficient (they agree up to the sign (-1)^(n(n-1)/2)); the
target is agreement to 1e-9 relative and at most 100 ms at degree 6.

Resultants: random integer polynomials f, g of equal degree 5-20 (coefficients
in [-9, 9], seeded). Ours is `resultant` (Sylvester's determinant by LU in
double precision), the peer SymPy's exact `resultant` of the two `Poly`
objects (built as set-up); SymPy's cache is emptied before every timed call
(outside the clock), so that repeating a call does not time a look-up. The case records the relative error of ours
against the exact value (with SymPy's sign corrected where its known swap
applies, sympy/sympy#10666; equal degrees never trigger it) and the time ratio.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from cagd_ref.algebra import implicitize, resultant
from cagd_ref.bezier import to_homogeneous
from cagd_ref.polynomials import bernstein_to_power

from .common import Candidate, Case, Plan, compare, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Implicitization and resultants"
ABOUT = ("Rational Bézier curves of degree 2-6 implicitized by `implicitize` and by SymPy's exact resultant of "
         "x W - X and y W - Y; resultants of random integer polynomials of degree 5-20 by `resultant` "
         "(floating-point Sylvester determinant) and by SymPy. Ratios are SymPy's time over ours.")
IMPLICITIZE = "cagd_ref implicitize"
SYMPY_IMPLICIT = "SymPy resultant (exact)"
RESULTANT = "cagd_ref resultant"
SYMPY_RESULTANT = "SymPy resultant of Poly (exact)"
AGREEMENT = 1e-9
DEGREE_6_LIMIT = 0.1  # seconds
FULL_CURVE_DEGREES, FULL_POLY_DEGREES = (2, 3, 4, 5, 6), (5, 10, 15, 20)
QUICK_CURVE_DEGREES, QUICK_POLY_DEGREES = (2, 4, 6), (5, 20)


def algebra_sizes(plan: Plan) -> tuple[tuple[int, ...], tuple[int, ...]]:
    """(curve degrees, polynomial degrees) of a plan."""
    if hasattr(plan, "algebra_curve_degrees"):
        return plan.algebra_curve_degrees, plan.algebra_poly_degrees
    return (FULL_CURVE_DEGREES, FULL_POLY_DEGREES) if plan.name == "full" else (QUICK_CURVE_DEGREES,
                                                                               QUICK_POLY_DEGREES)


def curve(n: int, seed: int = 17) -> tuple[np.ndarray, np.ndarray]:
    """Integer control points (n+1, 2) in [-6, 6] and weights in 1..3 of a rational curve of degree n."""
    rng = np.random.default_rng(seed + n)
    return rng.integers(-6, 7, (n + 1, 2)).astype(float), rng.integers(1, 4, n + 1).astype(float)


def _sympy_implicit(points: np.ndarray, weights: np.ndarray):
    """A function computing the exact implicit equation with SymPy, as an (n+1, n+1) float array."""
    import sympy as sp

    t, x, y = sp.symbols("t x y")
    power = bernstein_to_power(to_homogeneous(points, weights))
    X, Y, W = (sum(sp.Rational(Fraction(float(c))) * t**k for k, c in enumerate(np.round(power[:, j], 9)))
               for j in range(3))
    n = len(points) - 1

    def run():
        exact = sp.Poly(sp.resultant(x * W - X, y * W - Y, t), x, y)
        c = np.zeros((n + 1, n + 1))
        for (i, j), value in exact.terms():
            c[i, j] = float(value)
        return c

    return run


def _fresh_cache() -> None:
    """Empty SymPy's cache (outside the clock): repeating one call would otherwise time a cache look-up."""
    from sympy.core.cache import clear_cache

    clear_cache()


def _normalised(c) -> np.ndarray:
    c = np.asarray(c, dtype=float)
    return c / c.flat[np.argmax(np.abs(c))]


def implicit_cases(plan: Plan) -> list[Case]:
    degrees, _ = algebra_sizes(plan)
    cases = []
    for n in degrees:
        points, weights = curve(n)
        exact = _sympy_implicit(points, weights)
        timings = compare({IMPLICITIZE: lambda: implicitize(points, weights),
                           SYMPY_IMPLICIT: Candidate(lambda _: exact(), setup=_fresh_cache)}, plan)
        case = Case("implicitize", {"degree": n})
        ours, theirs = (_normalised(timings[m].output) for m in (IMPLICITIZE, SYMPY_IMPLICIT))
        for method, timing in timings.items():
            entry = record(case, method, timing, timings[IMPLICITIZE].seconds)
            if method != IMPLICITIZE:
                entry.difference = float(np.abs(ours - theirs).max())
        case.extra["speed-up"] = timings[SYMPY_IMPLICIT].seconds / timings[IMPLICITIZE].seconds
        progress(f"[algebra] implicitize degree {n}: {_summary(case)}; "
                 f"speed-up {case.extra['speed-up']:.0f}×, difference {case.get(SYMPY_IMPLICIT).difference:.1e}")
        cases.append(case)
    return cases


def resultant_cases(plan: Plan) -> list[Case]:
    import sympy as sp

    _, degrees = algebra_sizes(plan)
    t = sp.Symbol("t")
    rng = np.random.default_rng(2017)
    cases = []
    for n in degrees:
        f, g = (rng.integers(-9, 10, n + 1).astype(float) for _ in range(2))
        f[-1], g[-1] = f[-1] or 1.0, g[-1] or 1.0
        pf, pg = (sp.Poly([int(c) for c in reversed(c)], t) for c in (f, g))
        timings = compare({RESULTANT: lambda: resultant(f, g),
                           SYMPY_RESULTANT: Candidate(lambda _: pf.resultant(pg), setup=_fresh_cache)}, plan)
        exact = int(timings[SYMPY_RESULTANT].output)
        case = Case("resultant", {"degree": n})
        for method, timing in timings.items():
            record(case, method, timing, timings[RESULTANT].seconds)
        case.extra["relative error"] = abs(timings[RESULTANT].output - exact) / max(abs(exact), 1)
        case.extra["time ratio"] = timings[SYMPY_RESULTANT].seconds / timings[RESULTANT].seconds
        progress(f"[algebra] resultant degree {n}: {_summary(case)}; relative error "
                 f"{case.extra['relative error']:.1e}, SymPy / ours {case.extra['time ratio']:.1f}×")
        cases.append(case)
    return cases


def cases(plan: Plan) -> list[Case]:
    return implicit_cases(plan) + resultant_cases(plan)


def verdicts(found: list[Case]) -> list[Verdict]:
    implicit = [c for c in found if c.section == "implicitize"]
    results = [c for c in found if c.section == "resultant"]
    verdict = []
    target = f"`implicitize` agrees with SymPy's exact resultant to {AGREEMENT:g} (relative, after normalising)"
    if implicit:
        worst = max(c.get(SYMPY_IMPLICIT).difference for c in implicit)
        slowest = min(c.extra["speed-up"] for c in implicit)
        verdict.append(Verdict(target, f"difference {worst:.1e} at worst, speed-up {slowest:.0f}× at least",
                               worst <= AGREEMENT, f"degrees {', '.join(str(c.params['degree']) for c in implicit)}"))
    else:
        verdict.append(Verdict(target, "—", None))
    target = f"`implicitize` at degree 6 within {DEGREE_6_LIMIT * 1e3:.0f} ms"
    six = [c for c in implicit if c.params["degree"] == 6]
    if six:
        seconds = six[0].get(IMPLICITIZE).seconds
        verdict.append(Verdict(target, f"{seconds * 1e3:.2f} ms", seconds <= DEGREE_6_LIMIT))
    else:
        verdict.append(Verdict(target, "—", None))
    target = "`resultant` of integer polynomials of degree 5-20 against SymPy's exact value"
    if results:
        worst = max(c.extra["relative error"] for c in results)
        ratios = ", ".join(f"{c.params['degree']}: {c.extra['time ratio']:.1f}×" for c in results)
        verdict.append(Verdict(target, f"relative error {worst:.1e} at worst; SymPy / ours {ratios}", worst <= 1e-9))
    else:
        verdict.append(Verdict(target, "—", None))
    return verdict

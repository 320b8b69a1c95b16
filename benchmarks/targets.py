"""The issue's targets, judged on one run's measurements.

A target whose cases were not measured (a peer not installed, a section
skipped) gets no verdict rather than a guessed one. A quick run has no
10^6-value cases: its targets are judged at the largest size it measured,
and the table says so.
"""

from __future__ import annotations

from dataclasses import dataclass

from .common import Case, format_count, format_seconds
from .evaluation import BEZIER_EVALUATE, BEZIER_PACKAGE, DE_BOOR, GEOMDL_BSPLINE, SCIPY_BSPLINE
from .health import CHAPTER_LIMIT, WIDGET_LIMIT
from .rootfinding import BERNSTEIN, NUMPY_ROOTS


@dataclass
class Verdict:
    target: str
    measured: str
    met: bool | None  # None: not measured
    detail: str = ""

    @property
    def label(self) -> str:
        return {True: "met", False: "**missed**", None: "not measured"}[self.met]


def _largest(cases: list[Case], key: str) -> list[Case]:
    if not cases:
        return []
    size = max(c.params[key] for c in cases)
    return [c for c in cases if c.params[key] == size]


def _at(size: int, wanted: int = 10**6) -> str:
    return "" if size == wanted else f" (judged at {format_count(size)} values: this run has no {format_count(wanted)})"


def bspline_vs_scipy(cases: list[Case]) -> Verdict:
    target = "B-spline evaluation within 3× of SciPy's `BSpline` at 10^6 values"
    ratios = [(c, c.get(DE_BOOR).seconds / c.get(SCIPY_BSPLINE).seconds) for c in _largest(cases, "values")
              if c.get(SCIPY_BSPLINE) and c.get(SCIPY_BSPLINE).seconds]
    if not ratios:
        return Verdict(target, "—", None)
    case, worst = max(ratios, key=lambda item: item[1])
    detail = (f"worst case degree {case.params['degree']}, {case.params['control points']} control points"
              f"{_at(case.params['values'])}")
    return Verdict(target, f"`de_boor` / SciPy = {worst:.2f}× at worst", worst <= 3, detail)


def bspline_vs_geomdl(cases: list[Case]) -> Verdict:
    target = "B-spline evaluation at least 10× faster than geomdl"
    ratios = [(c, c.get(GEOMDL_BSPLINE).seconds / c.get(DE_BOOR).seconds) for c in cases
              if c.get(GEOMDL_BSPLINE) and c.get(GEOMDL_BSPLINE).seconds]
    if not ratios:
        return Verdict(target, "—", None, "geomdl not installed")
    case, worst = min(ratios, key=lambda item: item[1])
    extrapolated = " (geomdl extrapolated)" if case.get(GEOMDL_BSPLINE).extrapolated_from else ""
    detail = (f"smallest margin: degree {case.params['degree']}, {case.params['control points']} control points, "
              f"{format_count(case.params['values'])} values{extrapolated}")
    return Verdict(target, f"geomdl / `de_boor` = {worst:.0f}× at least", worst >= 10, detail)


def bezier_vs_package(cases: list[Case]) -> Verdict:
    target = "Bézier `evaluate` at least as fast as `bezier`'s `evaluate_multi`, degree ≤ 5, 10^6 values"
    chosen = [c for c in _largest(cases, "values") if c.params["degree"] <= 5 and c.get(BEZIER_PACKAGE)
              and c.get(BEZIER_PACKAGE).seconds]
    if not chosen:
        return Verdict(target, "—", None, "the bezier package is not installed")
    ratios = {c.params["degree"]: c.get(BEZIER_EVALUATE).seconds / c.get(BEZIER_PACKAGE).seconds for c in chosen}
    worst_degree = max(ratios, key=ratios.get)
    measured = ", ".join(f"degree {n}: {r:.2f}×" for n, r in sorted(ratios.items()))
    return Verdict(target, f"`evaluate` / `bezier` = {measured}", ratios[worst_degree] <= 1,
                   f"{_at(chosen[0].params['values']).strip(' ()')}")


def roots_accuracy(cases: list[Case]) -> Verdict:
    target = "Bernstein root errors at least 100× smaller than `numpy.roots` on the power form, degree 20"
    if not cases:
        return Verdict(target, "—", None)
    by_degree = {c.params["degree"]: c for c in cases}
    degree = 20 if 20 in by_degree else max(by_degree)
    case = by_degree[degree]
    ratio = case.extra["error ratio"]
    detail = (f"largest root error {case.get(BERNSTEIN).difference:.1e} (Bernstein) against "
              f"{case.get(NUMPY_ROOTS).difference:.1e} (numpy.roots)"
              + ("" if degree == 20 else f"; judged at degree {degree}, this run has no degree 20"))
    return Verdict(target, f"error ratio {ratio:.1e}", ratio >= 100, detail)


def widgets_latency(widgets) -> Verdict:
    target = "every widget update under 100 ms (median)"
    measured = [w for w in widgets if not w.error]
    if not measured:
        return Verdict(target, "—", None)
    slow = [w for w in measured if w.update >= WIDGET_LIMIT]
    worst = max(measured, key=lambda w: w.update)
    broken = [w.factory for w in widgets if w.error]
    detail = (f"{len(slow)} of {len(measured)} explorers at or above 100 ms; slowest `{worst.factory}`"
              + (f"; failed to run: {', '.join(broken)}" if broken else ""))
    return Verdict(target, f"slowest {format_seconds(worst.update)}", not slow and not broken, detail)


def chapters_time(chapters) -> Verdict:
    target = "every chapter executes in under 30 s"
    if not chapters:
        return Verdict(target, "—", None)
    worst = max(chapters, key=lambda c: c.seconds)
    failed = [c.notebook for c in chapters if c.error]
    detail = f"slowest {worst.notebook}" + (f"; failed: {', '.join(failed)}" if failed else "")
    return Verdict(target, f"slowest {worst.seconds:.1f} s", worst.seconds < CHAPTER_LIMIT and not failed, detail)


def roots_speed(cases: list[Case]) -> Verdict:
    target = ("`bernstein_roots` within 10× of `numpy.roots` at degree 20 (Wilkinson-type roots), "
              "its errors at least 10^6 times smaller")
    case = {c.params["degree"]: c for c in cases}.get(20)
    if case is None:
        return Verdict(target, "—", None, "this run has no degree 20" if cases else "")
    time_ratio, error_ratio = case.extra["time ratio"], case.extra["error ratio"]
    return Verdict(target, f"{time_ratio:.1f}× the time, errors {error_ratio:.1e}× smaller",
                   time_ratio <= 10 and error_ratio >= 1e6)


def verdicts(results: dict) -> list[Verdict]:
    from .knots import verdicts as knots_vs_scipy
    from .topics import TOPICS, topic

    found = [
        bspline_vs_scipy(results.get("bspline", [])),
        bspline_vs_geomdl(results.get("bspline", [])),
        bezier_vs_package(results.get("bezier", [])),
        *knots_vs_scipy(results.get("knots", [])),
        roots_accuracy(results.get("roots", [])),
        roots_speed(results.get("roots", [])),
    ]
    for section in TOPICS:
        found += topic(section).verdicts(results.get(section, []))
    return found + [widgets_latency(results.get("widgets", [])), chapters_time(results.get("chapters", []))]


def verdict_line(found: list[Verdict]) -> str:
    judged = [v for v in found if v.met is not None]
    met = sum(v.met for v in judged)
    missed = [v.target for v in judged if not v.met]
    line = f"{met} of {len(judged)} targets met"
    if len(judged) < len(found):
        line += f" ({len(found) - len(judged)} not measured)"
    if missed:
        line += "; missed: " + "; ".join(missed)
    return line

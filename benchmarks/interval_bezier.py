"""Interval Bézier curves: the cost of interval evaluation, and how tight the degree-reduction enclosures are.

Speed. `interval_de_casteljau` on k parameter values (spread over [-0.5, 1.5],
so all three of its branches run) against `cagd_ref.bezier.de_casteljau` on
the boxes' centres alone: the interval version evaluates the centres and the
signed errors with the same de Casteljau kernel, so it costs about twice the
plain evaluation; the issue's target is at most 5× at 10^6 values.

Quality. A random planar curve of degree 7 is enclosed by quartic interval
pieces (`interval_degree_reduce`) after 0, 1, 2, ... halvings. For each depth
the case records the guaranteed bound, the largest half-width of the boxes
[P](t) over t in [0, 1] (per coordinate, the worse one), the true largest
deviation of the pieces' centre curves from the curve, and their ratio
(bound / true, always at least 1: how pessimistic the guarantee is). The width
should fall by about 2^5 per halving (the fifth derivative sets the error).
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bezier import de_casteljau
from cagd_ref.interval_bezier import boxes_from_center, center_error, interval_de_casteljau, interval_degree_reduce

from .common import Case, Plan, compare, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Interval Bézier curves"
ABOUT = ("Speed: `interval_de_casteljau` on boxes of a random planar curve at parameters spread over [-0.5, 1.5], "
         "against `de_casteljau` on the centres alone. Quality: a degree-7 curve enclosed by quartic interval "
         "pieces after 0 to 5 halvings; bound, true deviation, their ratio and the shrink per halving.")
TIME_FACTOR = 5

INTERVAL = "cagd_ref interval_de_casteljau"
CENTRES = "cagd_ref de_casteljau (centres)"
DEPTHS = (0, 1, 2, 3, 4, 5)
SAMPLES = 257  # parameters per piece at which bound and deviation are measured


def _boxes(degree: int, seed: int = 12) -> np.ndarray:
    rng = np.random.default_rng(seed)
    return boxes_from_center(rng.uniform(-1, 1, (degree + 1, 2)), rng.uniform(0, 0.05, (degree + 1, 2)))


def speed_cases(plan: Plan) -> list[Case]:
    cases = []
    for degree in plan.bezier_degrees:
        boxes = _boxes(degree)
        centres = center_error(boxes)[0]
        for size in plan.bezier_sizes:
            ts = np.linspace(-0.5, 1.5, size)
            timings = compare(
                {INTERVAL: lambda: interval_de_casteljau(boxes, ts), CENTRES: lambda: de_casteljau(centres, ts)}, plan
            )
            case = Case("interval evaluation", {"degree": degree, "values": size})
            for method, timing in timings.items():
                record(case, method, timing, timings[INTERVAL].seconds)
            middle = timings[INTERVAL].output.mean(axis=2)
            case.get(CENTRES).difference = float(np.abs(middle - timings[CENTRES].output).max())
            case.extra["time ratio"] = timings[INTERVAL].seconds / timings[CENTRES].seconds
            progress(f"[interval] degree {degree}, {size} values: {_summary(case)}; "
                     f"interval / centres {case.extra['time ratio']:.2f}×")
            cases.append(case)
    return cases


def enclosure_quality(points: np.ndarray, depth: int) -> dict[str, float]:
    """The guaranteed bound, the true deviation of the centre curves and their ratio, after `depth` halvings."""
    pieces = interval_degree_reduce(points, depth)
    s = np.linspace(0, 1, SAMPLES)
    bound = deviation = 0.0
    for i, piece in enumerate(pieces):
        box = interval_de_casteljau(piece, s)
        centre, radius = box.mean(axis=2), 0.5 * (box[..., 1] - box[..., 0])
        truth = de_casteljau(points, (i + s) / len(pieces))
        bound = max(bound, float(radius.max()))
        deviation = max(deviation, float(np.abs(truth - centre).max()))
    return {"bound": bound, "deviation": deviation, "ratio": bound / deviation if deviation else float("inf")}


def quality_cases(plan: Plan) -> list[Case]:
    points = np.random.default_rng(7).uniform(-1, 1, (8, 2))
    cases, previous = [], None
    for depth in DEPTHS:
        case = Case("interval enclosure", {"depth": depth, "pieces": 2**depth})
        case.extra.update(enclosure_quality(points, depth))
        if previous:
            case.extra["shrink"] = previous / case.extra["bound"]
        previous = case.extra["bound"]
        progress(f"[interval] depth {depth}: bound {case.extra['bound']:.3e}, true {case.extra['deviation']:.3e}, "
                 f"bound / true {case.extra['ratio']:.2f}" + (f", shrink {case.extra['shrink']:.1f}×" if depth else ""))
        cases.append(case)
    return cases


def interval_cases(plan: Plan) -> list[Case]:
    return speed_cases(plan) + quality_cases(plan)


if __name__ == "__main__":
    from .common import quick_plan

    interval_cases(quick_plan())


cases = interval_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    target = f"`interval_de_casteljau` within {TIME_FACTOR}× of `de_casteljau` on the centres at 10^6 values"
    speed = [c for c in found if c.section == "interval evaluation"]
    if not speed:
        return [Verdict(target, "—", None)]
    size = max(c.params["values"] for c in speed)
    worst = max((c for c in speed if c.params["values"] == size), key=lambda c: c.extra["time ratio"])
    detail = f"worst at degree {worst.params['degree']}" + ("" if size == 10**6 else f", judged at {size} values")
    return [Verdict(target, f"{worst.extra['time ratio']:.2f}× at worst", worst.extra["time ratio"] <= TIME_FACTOR,
                    detail)]

"""Tensor-product Bézier patches: `patch_point` against SciPy and geomdl, and chapter 16's O(n²) tangents.

Two sections.

- "patch points": `cagd_ref.surfaces.patch_point` on a regular grid of (s, t) pairs (10^3 × 10^3 in the
  full plan) of a polynomial bicubic and a degree-(5, 5) patch, against `scipy.interpolate.NdBSpline`
  (the patch as a B-spline patch with Bézier end knots, evaluated at the same pairs) and geomdl's
  `BSpline.Surface.evaluate_list` (pure Python: run on an evenly spaced subset of the pairs and scaled
  linearly, marked as extrapolated). The issue's targets: within 3× of NdBSpline, at least 10× faster
  than geomdl.
- "point and tangents": `patch_point_tangents` (four sub-patches in pseudo-power form, 16(mn - 1)
  multiplies per point) against `de_casteljau_point_tangents` (tensor de Casteljau down to the same
  2 × 2 net, O(n³)) on rational patches of degree (n, n), n = 3..10. Each case records the measured
  speed-up next to the ratio of the operation counts the notes predict
  (`surfaces.point_tangent_cost`: multiplies plus adds of de Casteljau over those of the sub-patches).

Building the peers' objects (an NdBSpline, a geomdl surface, the parameter lists geomdl wants) is set-up
and is not timed; our functions check their inputs on every call, and that is timed.
The plan of `benchmarks.common` has no fields for this section: the full plan uses the sizes above,
any other plan (quick, the tests' tiny one) a 10^2 × 10^2 grid and 10^4 pairs.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bspline import bezier_end_knots, to_scipy
from cagd_ref.surfaces import de_casteljau_point_tangents, patch_point, patch_point_tangents, point_tangent_cost

from . import peers
from .common import Case, Plan, compare, max_difference, progress, record
from .evaluation import _geomdl_subset, _summary
from .targets import Verdict

TITLE = "Surface patches"
ABOUT = ("`patch_point` on a grid of a bicubic and of a degree-(5, 5) patch against SciPy's `NdBSpline` (the same "
         "patch through the knot converters) and geomdl; `patch_point_tangents` (chapter 16's sub-patches) against "
         "point and tangents by de Casteljau, the measured speed-up next to the ratio the operation count predicts.")
SCIPY_FACTOR, GEOMDL_FACTOR = 3, 10

OURS = "cagd_ref patch_point"
SCIPY = "scipy NdBSpline"
GEOMDL = "geomdl evaluate_list"
SUB_PATCHES = "cagd_ref patch_point_tangents"
DE_CASTELJAU = "cagd_ref de_casteljau_point_tangents"
POINT_DEGREES = (3, 5)
TANGENT_DEGREES = (3, 4, 5, 6, 8, 10)
SEED = 16


def _sizes(plan: Plan) -> tuple[int, int]:
    """(grid side, number of pairs for the tangents)."""
    return (1000, 10**5) if plan.name == "full" else (100, 10**4)


def _grid(side: int) -> tuple[np.ndarray, np.ndarray]:
    values = np.linspace(0.0, 1.0, side)
    s, t = np.meshgrid(values, values, indexing="ij")
    return s.ravel(), t.ravel()


def _scipy_patch(net: np.ndarray):
    from scipy.interpolate import NdBSpline

    m, n = net.shape[0] - 1, net.shape[1] - 1
    knots_s = to_scipy(net[:, 0], bezier_end_knots(m + 1, m, 0.0, 1.0))[0]
    knots_t = to_scipy(net[0], bezier_end_knots(n + 1, n, 0.0, 1.0))[0]
    return NdBSpline((knots_s, knots_t), net, (m, n))


def _geomdl_patch(net: np.ndarray):
    from geomdl import BSpline

    m, n = net.shape[0] - 1, net.shape[1] - 1
    surface = BSpline.Surface()
    surface.degree_u, surface.degree_v = m, n
    surface.ctrlpts_size_u, surface.ctrlpts_size_v = m + 1, n + 1
    surface.ctrlpts = net.reshape(-1, net.shape[2]).tolist()
    surface.knotvector_u = [0.0] * (m + 1) + [1.0] * (m + 1)
    surface.knotvector_v = [0.0] * (n + 1) + [1.0] * (n + 1)
    return surface


def point_cases(plan: Plan) -> list[Case]:
    side, _ = _sizes(plan)
    s, t = _grid(side)
    pairs = np.column_stack([s, t])
    rng = np.random.default_rng(SEED)
    cases = []
    for degree in POINT_DEGREES:
        net = rng.uniform(-1, 1, (degree + 1, degree + 1, 3))
        candidates = {OURS: lambda: patch_point(net, s, t)}
        if peers.available("scipy"):
            spline = _scipy_patch(net)
            candidates[SCIPY] = lambda: spline(pairs)
        subset = _geomdl_subset(s, plan)
        if peers.available("geomdl"):
            surface, listed = _geomdl_patch(net), pairs[subset].tolist()
            candidates[GEOMDL] = lambda: np.array(surface.evaluate_list(listed))
        timings = compare(candidates, plan)
        case = Case("patch points", {"degree": f"({degree}, {degree})", "pairs": len(s)})
        ours = timings[OURS].output
        record(case, OURS, timings[OURS], timings[OURS].seconds, 0.0)
        for method, peer in ((SCIPY, "scipy"), (GEOMDL, "geomdl")):
            timing = timings.get(method)
            if timing is None:
                record(case, method, None, note=f"{peer} not installed")
            elif method == GEOMDL and len(subset) < len(s):
                record(case, method, timing, timings[OURS].seconds, max_difference(ours[subset], timing.output),
                       extrapolated_from=len(subset), scale=len(s) / len(subset))
            else:
                record(case, method, timing, timings[OURS].seconds, max_difference(ours, timing.output))
        progress(f"[patch points] degree ({degree}, {degree}), {side} × {side} grid: {_summary(case)}")
        cases.append(case)
    return cases


def tangent_cases(plan: Plan) -> list[Case]:
    _, count = _sizes(plan)
    rng = np.random.default_rng(SEED + 1)
    s, t = rng.uniform(0, 1, (2, count))
    cases = []
    for degree in TANGENT_DEGREES:
        net = rng.uniform(-1, 1, (degree + 1, degree + 1, 3))
        weights = rng.uniform(0.5, 2.0, (degree + 1, degree + 1))
        timings = compare({SUB_PATCHES: lambda: patch_point_tangents(net, s, t, weights),
                           DE_CASTELJAU: lambda: de_casteljau_point_tangents(net, s, t, weights)}, plan)
        case = Case("point and tangents", {"degree": f"({degree}, {degree})", "pairs": count})
        ours = timings[SUB_PATCHES].output
        for method, timing in timings.items():
            difference = max(max_difference(a, b) for a, b in zip(ours, timing.output))
            record(case, method, timing, timings[SUB_PATCHES].seconds, difference)
        costs = point_tangent_cost(degree, degree)
        case.extra["counted ratio"] = sum(costs["de_casteljau"]) / sum(costs["sub_patches"])
        case.extra["measured speed-up"] = timings[DE_CASTELJAU].seconds / timings[SUB_PATCHES].seconds
        progress(f"[point and tangents] degree ({degree}, {degree}), {count} pairs: {_summary(case)}; "
                 f"speed-up {case.extra['measured speed-up']:.2f}× measured, "
                 f"{case.extra['counted ratio']:.2f}× by the operation count")
        cases.append(case)
    return cases


def surface_cases(plan: Plan) -> list[Case]:
    """Both sections of this benchmark, points then tangents."""
    return point_cases(plan) + tangent_cases(plan)


cases = surface_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    points = [c for c in found if c.section == "patch points"]
    result = []
    for peer, target, judge in (
        (SCIPY, f"`patch_point` within {SCIPY_FACTOR}× of SciPy's `NdBSpline`", lambda r: r <= SCIPY_FACTOR),
        (GEOMDL, f"`patch_point` at least {GEOMDL_FACTOR}× faster than geomdl", lambda r: 1 / r >= GEOMDL_FACTOR),
    ):
        ratios = [c.get(OURS).seconds / c.get(peer).seconds for c in points if c.get(peer) and c.get(peer).seconds]
        if not ratios:
            result.append(Verdict(target, "—", None))
            continue
        worst = max(ratios) if peer == SCIPY else min(ratios)
        result.append(Verdict(target, f"{worst:.2f}× the peer's time at worst", judge(worst)))
    return result

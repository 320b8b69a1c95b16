"""Free-form deformation of many points: `cagd_ref.ffd.ffd` against evaluating point by point and against peers.

The issue's targets (chapter 14): `ffd` on 10^6 points with a degree-(3, 3)
lattice is vectorised and at least 10× faster than calling it once per point,
and the lattice editor deforms a 10^5-point outline in well under a second.

The lattice is the identity of the box (0, 0)-(3, 2) with seeded random
displacements and weights in [0.5, 2]; the points are seeded and uniform over a
region a little larger than the box, so that about a fifth of them lie outside
and must come back unchanged. Peers, on the same inputs: the tensor-product
Bernstein sum written directly with `np.einsum` (the formula with nothing else:
no input checks, no outside test, which `ffd` must then do too), and SciPy's
`NdBSpline` with clamped knots on the homogeneous lattice. The point-by-point
loop is timed on its first `LOOP_POINTS` points and scaled linearly, as
`record` notes. The explorer's case times one `update` of a `LatticeEditor`
whose word outline holds about 10^5 points (deforming it, the grid and the
circle, drawing and rendering the PNG).

The plan of `benchmarks.common` has no field for this section: a plan with
`ffd_sizes` uses it, the full plan 10^6 points and the others 10^5.
"""

from __future__ import annotations

import numpy as np

from cagd_ref.bezier import bernstein_matrix
from cagd_ref.ffd import ffd, identity_lattice

from .common import Case, Plan, compare, format_seconds, max_difference, progress, record
from .evaluation import _summary
from .targets import Verdict

TITLE = "Free-form deformation"
ABOUT = ("`ffd` with a rational degree-(3, 3) lattice on random points in and around the box, against an einsum "
         "tensor sum, SciPy's `NdBSpline` on the homogeneous lattice, and `ffd` called once per point (timed on "
         "2000 points, scaled); and one update of the lattice editor deforming a word outline of about 10^5 points.")
LOOP_FACTOR, EXPLORER_SECONDS = 10, 1.0

FFD = "cagd_ref ffd"
LOOP = "cagd_ref ffd, one point per call"
EINSUM = "np.einsum tensor sum (peer)"
SCIPY = "scipy NdBSpline (peer)"
EXPLORER = "lattice_editor update"
DEGREES = (3, 3)
BOX = np.array([[0.0, 0.0], [3.0, 2.0]])
LOOP_POINTS = 2000
OUTLINE_POINTS = 10**5
FULL_SIZES = (10**6,)
QUICK_SIZES = (10**5,)


def ffd_sizes(plan: Plan) -> tuple[int, ...]:
    if hasattr(plan, "ffd_sizes"):
        return plan.ffd_sizes
    return FULL_SIZES if plan.name == "full" else QUICK_SIZES


def test_lattice(seed: int = 14) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    m, n = DEGREES
    lattice = identity_lattice(BOX, m, n) + rng.normal(0, 0.15, (m + 1, n + 1, 2))
    return lattice, rng.uniform(0.5, 2.0, (m + 1, n + 1))


def test_points(count: int, seed: int = 15) -> np.ndarray:
    return np.random.default_rng(seed).uniform(BOX[0] - 0.2, BOX[1] + 0.2, (count, 2))


def einsum_ffd(points: np.ndarray, homogeneous: np.ndarray) -> np.ndarray:
    """The formula (14.2) with einsum: local coordinates, Bernstein matrices, one tensor contraction, projection."""
    st = (points - BOX[0]) / (BOX[1] - BOX[0])
    inside = np.all((st >= 0) & (st <= 1), axis=1)
    m, n = homogeneous.shape[0] - 1, homogeneous.shape[1] - 1
    h = np.einsum("ki,kj,ijd->kd", bernstein_matrix(m, st[inside, 0]), bernstein_matrix(n, st[inside, 1]), homogeneous)
    out = points.copy()
    out[inside] = h[:, :2] / h[:, 2:]
    return out


def scipy_ffd(points: np.ndarray, spline) -> np.ndarray:
    st = (points - BOX[0]) / (BOX[1] - BOX[0])
    inside = np.all((st >= 0) & (st <= 1), axis=1)
    h = spline(st[inside])
    out = points.copy()
    out[inside] = h[:, :2] / h[:, 2:]
    return out


def _scipy_spline(homogeneous: np.ndarray):
    try:
        from scipy.interpolate import NdBSpline
    except ImportError:
        return None
    m, n = homogeneous.shape[0] - 1, homogeneous.shape[1] - 1
    knots = (np.r_[[0.0] * (m + 1), [1.0] * (m + 1)], np.r_[[0.0] * (n + 1), [1.0] * (n + 1)])
    return NdBSpline(knots, homogeneous, (m, n))


def one_by_one(points: np.ndarray, lattice, weights) -> np.ndarray:
    return np.array([ffd(point, lattice, BOX, weights) for point in points])


def ffd_cases(plan: Plan) -> list[Case]:
    lattice, weights = test_lattice()
    homogeneous = np.concatenate([lattice * weights[..., None], weights[..., None]], axis=2)
    spline = _scipy_spline(homogeneous)
    cases = []
    for size in ffd_sizes(plan):
        points = test_points(size)
        few = points[:LOOP_POINTS]
        candidates = {FFD: lambda: ffd(points, lattice, BOX, weights),
                      EINSUM: lambda: einsum_ffd(points, homogeneous)}
        if spline is not None:
            candidates[SCIPY] = lambda: scipy_ffd(points, spline)
        timings = compare(candidates, plan)
        loop = compare({LOOP: lambda: one_by_one(few, lattice, weights)}, plan)[LOOP]
        ours = timings[FFD]
        case = Case("ffd", {"degree": DEGREES, "points": size})
        for method, timing in timings.items():
            record(case, method, timing, ours.seconds, max_difference(timing.output, ours.output))
        if spline is None:
            record(case, SCIPY, None)
        record(case, LOOP, loop, ours.seconds, max_difference(loop.output, ours.output[:LOOP_POINTS]),
               extrapolated_from=LOOP_POINTS, scale=size / LOOP_POINTS)
        moved = np.any(ours.output != points, axis=1)
        case.extra["outside unchanged"] = bool(np.all(ours.output[~moved] == points[~moved]))
        case.extra["speed-up over the loop"] = case.get(LOOP).seconds / ours.seconds
        progress(f"[ffd] {size} points, degree {DEGREES}: {_summary(case)}; "
                 f"{case.extra['speed-up over the loop']:.0f}× faster than one point per call")
        cases.append(case)
    cases.append(explorer_case(plan))
    return cases


def explorer_case(plan: Plan) -> Case:
    """One update of the lattice editor with a word outline of about OUTLINE_POINTS points."""
    import matplotlib

    matplotlib.use("Agg")
    from cagd_course.widgets.ch14 import LatticeEditor

    # About 75 curved segments in "CAGD": this many samples each gives ~10^5 outline points.
    editor = LatticeEditor(word="CAGD", draggable=False, glyph_samples=OUTLINE_POINTS // 44)
    outline = int(np.isfinite(editor.shapes["word"][:, 0]).sum())
    heights = iter(np.linspace(1.2, 1.9, 10_000))
    timing = compare({EXPLORER: lambda: editor.update(y=float(next(heights)))}, plan)[EXPLORER]
    case = Case("ffd explorer", {"outline points": outline})
    record(case, EXPLORER, timing, timing.seconds, note=f"{outline} outline points, drawn and rendered")
    progress(f"[ffd] lattice editor, {outline}-point outline: one update in {timing.seconds * 1000:.0f} ms")
    return case


cases = ffd_cases


def verdicts(found: list[Case]) -> list[Verdict]:
    result = []
    target = f"`ffd` at 10^6 points at least {LOOP_FACTOR}× faster than one point per call"
    speed = [c for c in found if c.section == "ffd"]
    if speed:
        case = max(speed, key=lambda c: c.params["points"])
        speed_up = case.extra["speed-up over the loop"]
        at = "" if case.params["points"] == 10**6 else f"judged at {case.params['points']} points"
        result.append(Verdict(target, f"{speed_up:.0f}× faster", speed_up >= LOOP_FACTOR, at))
    else:
        result.append(Verdict(target, "—", None))
    target = f"a deformed 10^5-point outline redrawn by the lattice editor in under {EXPLORER_SECONDS:g} s"
    editor = next((c.get(EXPLORER) for c in found if c.get(EXPLORER)), None)
    if editor is None or editor.seconds is None:
        result.append(Verdict(target, "—", None))
    else:
        result.append(Verdict(target, format_seconds(editor.seconds), editor.seconds < EXPLORER_SECONDS))
    return result

"""What every benchmark section shares: the plan of sizes, fair timing, result records, progress lines.

Timing rules, the same for every library:

- inputs are built once, before any clock starts, and every library gets the
  same arrays; building a peer's own objects (a `bezier.Curve`, a SciPy
  `BSpline`, a geomdl curve) is set-up and is not timed, while our functions
  check their inputs on every call and that is timed;
- a first call per candidate warms caches up and gives the output that is
  checked against ours; it also sets how many calls make up one sample, so
  that fast functions are timed over at least `min_sample` seconds;
- samples of all candidates are taken in turns (A B C A B C ...), so a burst
  of load from other work on the machine hits all of them alike, and the best
  sample per call is reported (the least disturbed one, as `timeit` advises);
- slow candidates get fewer samples, within `budget` seconds each; the table
  says how many.
"""

from __future__ import annotations

import gc
import math
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
RESULTS = Path(__file__).resolve().parent / "results"


@dataclass(frozen=True)
class Plan:
    """Sizes and repetitions of one benchmark run (see `full_plan`, `quick_plan`)."""

    name: str
    bezier_degrees: tuple[int, ...]
    bezier_sizes: tuple[int, ...]
    bspline_degrees: tuple[int, ...]
    bspline_counts: tuple[int, ...]
    bspline_sizes: tuple[int, ...]
    geomdl_max_points: int  # geomdl is pure Python: beyond this many values its time is extrapolated
    knot_counts: tuple[int, ...]
    knot_degree: int
    root_degrees: tuple[int, ...]
    repeats: int  # samples per candidate, at most
    min_sample: float  # seconds; fast calls are repeated until one sample lasts this long
    budget: float  # seconds one candidate may spend on its samples
    chapters: tuple[Path, ...] | None  # notebooks to execute; None: every chapter of book.toml
    widgets: tuple[str, ...] | None  # explorer factories to drive; None: all of them
    widget_updates: int
    grade_runs: int  # gradings of the one submission (0: skip)


def full_plan() -> Plan:
    """The sizes of the issue: about five minutes on an idle 2-core machine."""
    return Plan(
        name="full",
        bezier_degrees=(3, 5, 10),
        bezier_sizes=(10**3, 10**6),
        bspline_degrees=(2, 3, 4, 5),
        bspline_counts=(10, 100, 1000),
        bspline_sizes=(10**3, 10**6),
        geomdl_max_points=10**4,
        knot_counts=(10, 100, 1000),
        knot_degree=3,
        root_degrees=(5, 10, 15, 20, 25),
        repeats=7,
        min_sample=0.05,
        budget=6.0,
        chapters=None,
        widgets=None,
        widget_updates=11,
        grade_runs=3,
    )


def quick_plan() -> Plan:
    """A smoke run of every section on small sizes and one chapter, in well under a minute."""
    return Plan(
        name="quick",
        bezier_degrees=(3, 5),
        bezier_sizes=(10**3, 10**5),
        bspline_degrees=(2, 3),
        bspline_counts=(10, 100),
        bspline_sizes=(10**3, 10**5),
        geomdl_max_points=10**3,
        knot_counts=(10, 100),
        knot_degree=3,
        root_degrees=(5, 10, 20),
        repeats=3,
        min_sample=0.01,
        budget=0.5,
        chapters=(ROOT / "chapters" / "01-introduction.ipynb",),
        widgets=None,
        widget_updates=3,
        grade_runs=1,
    )


# --- timing -------------------------------------------------------------------------------


@dataclass(frozen=True)
class Candidate:
    """One thing to time. `run()` is called as is; with `setup`, each call gets `run(setup())`
    and the set-up (e.g. a fresh copy of an object the call modifies) stays outside the clock."""

    run: Callable
    setup: Callable | None = None


@dataclass(frozen=True)
class Timing:
    seconds: float  # best time of one call
    samples: int  # timed samples the best was taken from
    output: object  # what the first call returned


def _sample(candidate: Candidate, calls: int) -> tuple[float, object]:
    """Seconds per call over `calls` calls, and the last output; garbage collection paused, as timeit does."""
    argument = candidate.setup() if candidate.setup else None
    enabled = gc.isenabled()
    gc.disable()
    try:
        start = time.perf_counter()
        for _ in range(calls):
            output = candidate.run(argument) if candidate.setup else candidate.run()
        seconds = (time.perf_counter() - start) / calls
    finally:
        if enabled:
            gc.enable()
    return seconds, output


def compare(candidates: dict[str, Candidate | Callable], plan: Plan) -> dict[str, Timing]:
    """Time every candidate on the same inputs, interleaved; best seconds per call for each."""
    candidates = {k: c if isinstance(c, Candidate) else Candidate(c) for k, c in candidates.items()}
    best, outputs, calls, wanted, taken = {}, {}, {}, {}, {}
    for name, candidate in candidates.items():
        gc.collect()
        seconds, outputs[name] = _sample(candidate, 1)
        # A candidate with per-call set-up is timed one call per sample.
        calls[name] = 1 if candidate.setup else max(1, min(10_000, math.ceil(plan.min_sample / max(seconds, 1e-9))))
        per_sample = seconds * calls[name]
        wanted[name] = max(1, min(plan.repeats, int(plan.budget / max(per_sample, 1e-9))))
        best[name], taken[name] = seconds, 1
        if calls[name] > 1:  # the first call alone was too short to count as a sample
            taken[name] = 0
            best[name] = math.inf
    for _ in range(max(wanted.values())):
        for name, candidate in candidates.items():
            if taken[name] < wanted[name]:
                seconds, _ = _sample(candidate, calls[name])
                best[name] = min(best[name], seconds)
                taken[name] += 1
    return {name: Timing(best[name], taken[name], outputs[name]) for name in candidates}


def max_difference(ours, theirs) -> float:
    """Largest absolute difference between two arrays of the same shape (inf if the shapes differ)."""
    a, b = np.asarray(ours, dtype=float), np.asarray(theirs, dtype=float)
    if a.shape != b.shape:
        return math.inf
    return float(np.max(np.abs(a - b))) if a.size else 0.0


# --- records ------------------------------------------------------------------------------


@dataclass
class Measurement:
    """One library's result in one case: its time, how it compares, and whether it agrees with ours."""

    method: str
    seconds: float | None  # None: not measured (the library is not installed)
    ratio: float | None = None  # seconds / seconds of the case's cagd_ref method
    difference: float | None = None  # max |output - ours|
    samples: int = 0
    extrapolated_from: int | None = None  # measured on this many values and scaled linearly
    note: str = ""


@dataclass
class Case:
    """One benchmark case (e.g. degree 3 at 10^6 values) with the measurements of every method."""

    section: str
    params: dict
    measurements: list[Measurement] = field(default_factory=list)
    extra: dict = field(default_factory=dict)  # section-specific numbers, such as root errors

    def get(self, method: str) -> Measurement | None:
        return next((m for m in self.measurements if m.method == method), None)


def record(case: Case, method: str, timing: Timing | None, subject_seconds: float | None = None,
           difference: float | None = None, extrapolated_from: int | None = None, scale: float = 1.0,
           note: str = "") -> Measurement:
    """Add a measurement to `case`; `scale` > 1 turns a time measured on fewer values into the extrapolated one."""
    if timing is None:
        entry = Measurement(method, None, note=note or "not installed")
    else:
        seconds = timing.seconds * scale
        ratio = seconds / subject_seconds if subject_seconds else None
        entry = Measurement(method, seconds, ratio, difference, timing.samples, extrapolated_from, note)
    case.measurements.append(entry)
    return entry


# --- output -------------------------------------------------------------------------------


def progress(message: str) -> None:
    """One line of progress on stderr, so that stdout stays free for the final summary."""
    print(message, file=sys.stderr, flush=True)


def format_seconds(seconds: float | None) -> str:
    if seconds is None or not math.isfinite(seconds):
        return "—"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if seconds >= scale or unit == "µs":
            value = seconds / scale
            return f"{value:.3g} {unit}" if value >= 1 else f"{value:.2g} {unit}"
    raise AssertionError("unreachable")


def format_count(count: int) -> str:
    """10^6 rather than 1000000 for exact powers of ten, plain digits otherwise."""
    exponent = round(math.log10(count)) if count > 0 else 0
    return f"10^{exponent}" if count == 10**exponent and exponent >= 3 else str(count)

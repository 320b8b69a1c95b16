"""Course health: how long a chapter takes to run, a slider to respond, a submission to be graded.

- Chapters are executed the way `cagd book` executes them (nbclient, a fresh
  kernel each, in the chapter's folder); the time includes starting the kernel,
  because a reader waits for that too.
- Every explorer of `cagd_course.widgets` is built with its defaults and then
  one of its sliders is moved back and forth by a small step, through
  `update(**controls)` exactly as the slider's observer does. The median over
  the moves is reported, and next to it the median time of `compute` alone,
  the part that runs `cagd_ref`, and of `png()`, which renders the figure
  and encodes it as the PNG the widget shows; the rest of an update is
  making the figure's artists and the readout.
- Grading runs `cagd grade`'s code path (`grade_class`) on the complete
  chapter 1-2 solution of the test fixtures, against every exercise of the
  course, in its sandboxed worker process.
"""

from __future__ import annotations

import csv
import re
import shutil
import statistics
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from .common import ROOT, Plan, progress

EXERCISE_COLUMN = re.compile(r"^\d\d\.\w+$")

CHAPTER_LIMIT = 30.0  # seconds
WIDGET_LIMIT = 0.100  # seconds
SUBMISSION = ROOT / "tests" / "grading" / "fixtures" / "submissions" / "complete.ipynb"


@dataclass
class ChapterTiming:
    notebook: str
    seconds: float
    error: str = ""


@dataclass
class WidgetTiming:
    factory: str
    control: str
    build: float  # seconds to construct the explorer (including its first drawing)
    update: float  # median seconds of update(control=...)
    compute: float  # median seconds of compute(**values) alone
    render: float  # median seconds of png(): rendering the figure with Agg and encoding the PNG
    updates: int
    error: str = ""


@dataclass
class GradingTiming:
    seconds: float  # median over the runs
    runs: int
    score: str
    exercises: int


# --- chapters -----------------------------------------------------------------------------


def chapter_notebooks(plan: Plan) -> list[Path]:
    if plan.chapters is not None:
        return list(plan.chapters)
    from cagd_course.manifest import load_course

    return [chapter.notebook for chapter in load_course(ROOT).chapters]


def time_chapter(path: Path, timeout: int = 600) -> ChapterTiming:
    import nbformat
    from nbclient import NotebookClient

    notebook = nbformat.read(path, as_version=4)
    client = NotebookClient(notebook, timeout=timeout, kernel_name="python3",
                            resources={"metadata": {"path": str(path.parent)}})
    start = time.perf_counter()
    try:
        client.execute()
        error = ""
    except Exception as err:  # a failing chapter is reported, and the benchmark goes on
        error = f"{type(err).__name__}: {str(err).strip().splitlines()[-1] if str(err).strip() else ''}"[:200]
    return ChapterTiming(path.name, time.perf_counter() - start, error)


def chapter_timings(plan: Plan) -> list[ChapterTiming]:
    results = []
    for path in chapter_notebooks(plan):
        result = time_chapter(path)
        progress(
            f"[chapters] {result.notebook}: {result.seconds:.1f} s"
            + (f" FAILED {result.error}" if result.error else "")
        )
        results.append(result)
    return results


# --- widgets ------------------------------------------------------------------------------


def explorer_factories() -> list[str]:
    """Names of the functions in `cagd_course.widgets` that build an explorer."""
    from cagd_course import widgets

    return [
        name
        for name in widgets.__all__
        if name.endswith(("_explorer", "_editor"))
        and callable(getattr(widgets, name))
        and not isinstance(getattr(widgets, name), type)
    ]


def _nudges(explorer) -> list[tuple[str, object, object]]:
    """(control, nearby value, original value) for each slider, in the explorer's order.

    A step of 1 for integer sliders and 1 % of the range otherwise, downwards
    when upwards would leave the range.
    """
    import ipywidgets

    found = []
    for name, control in explorer.controls.items():
        if isinstance(control, ipywidgets.FloatLogSlider):
            value = control.value
            high = control.base**control.max
            step = value * (control.base ** ((control.max - control.min) / 100) - 1)
        elif isinstance(control, (ipywidgets.FloatSlider, ipywidgets.IntSlider)):
            value, high = control.value, control.max
            step = 1 if isinstance(control, ipywidgets.IntSlider) else (control.max - control.min) / 100
        else:
            continue
        found.append((name, value + step if value + step <= high else value - step, value))
    return found


def time_widget(factory: str, updates: int) -> WidgetTiming:
    from cagd_course import widgets

    start = time.perf_counter()
    explorer = getattr(widgets, factory)()
    build = time.perf_counter() - start
    # The first slider whose small move the explorer accepts (some moves break a constraint, e.g. knot order).
    for control, nearby, original in _nudges(explorer):
        try:
            explorer.update(**{control: nearby})
            explorer.update(**{control: original})
            break
        except (ValueError, TypeError):
            continue
    else:
        control, nearby, original = "", None, None
    update_times, compute_times, render_times = [], [], []
    for i in range(updates):
        values = {control: nearby if i % 2 == 0 else original} if control else {}
        start = time.perf_counter()
        explorer.update(**values)
        update_times.append(time.perf_counter() - start)
        start = time.perf_counter()
        explorer.compute(**explorer.values)
        compute_times.append(time.perf_counter() - start)
        start = time.perf_counter()
        explorer.png()
        render_times.append(time.perf_counter() - start)
    return WidgetTiming(
        factory,
        control or "(no slider)",
        build,
        statistics.median(update_times),
        statistics.median(compute_times),
        statistics.median(render_times),
        updates,
    )


def widget_timings(plan: Plan) -> list[WidgetTiming]:
    import matplotlib

    matplotlib.use("Agg")  # no display: the explorers draw into their own Agg canvases anyway
    results = []
    for factory in plan.widgets if plan.widgets is not None else explorer_factories():
        try:
            result = time_widget(factory, plan.widget_updates)
        except Exception as err:  # a broken explorer is reported, and the benchmark goes on
            nan = float("nan")
            result = WidgetTiming(factory, "", 0.0, nan, nan, nan, 0, f"{type(err).__name__}: {err}"[:200])
        progress(
            f"[widgets] {factory}: update {result.update * 1e3:.1f} ms median (compute "
            f"{result.compute * 1e3:.2f} ms, PNG {result.render * 1e3:.1f} ms)"
            + (f" FAILED {result.error}" if result.error else "")
        )
        results.append(result)
    return results


# --- grading ------------------------------------------------------------------------------


def grading_timing(plan: Plan) -> GradingTiming | None:
    if plan.grade_runs < 1:
        return None
    from cagd_course.grading.classroom import grade_class
    from cagd_course.grading.runner import Limits

    times, row = [], None
    for _ in range(plan.grade_runs):
        folder = Path(tempfile.mkdtemp(prefix="cagd-bench-submission-"))
        out = Path(tempfile.mkdtemp(prefix="cagd-bench-graded-"))
        try:
            shutil.copy(SUBMISSION, folder / "ada.ipynb")
            start = time.perf_counter()
            # A known-good fixture: timing it needs no confinement, where the machine cannot offer it. It answers
            # chapters 1 and 2 in one notebook; a class hands in one per chapter, so it is graded on chapter 2.
            grade_class([folder], out, jobs=1, limits=Limits(), progress=False, chapters=[2], allow_unconfined=True)
            times.append(time.perf_counter() - start)
            with (out / "gradebook.csv").open(encoding="utf-8", newline="") as handle:
                row = next(line for line in csv.DictReader(handle) if line["student"] == "ada")
        finally:
            shutil.rmtree(folder, ignore_errors=True)
            shutil.rmtree(out, ignore_errors=True)
    graded = sum(1 for column in row if EXERCISE_COLUMN.match(column))
    result = GradingTiming(statistics.median(times), len(times), f"{row['score']} / {row['max_score']}", graded)
    progress(f"[grading] one submission: {result.seconds:.2f} s median of {result.runs} (score {result.score})")
    return result

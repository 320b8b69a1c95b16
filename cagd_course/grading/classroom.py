"""`cagd grade`: grade a whole class of notebooks into a gradebook, feedback pages and Gradescope JSON.

Every submission gets exactly one gradebook row whatever it does. Files are
written atomically (temporary file, then rename), the gradebook after every
submission, so an interrupted run loses nothing and resumes where it stopped.
"""

from __future__ import annotations

import csv
import io
import json
import os
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import dataclass
from pathlib import Path

from tqdm import tqdm

from ..manifest import load_course
from .engine import grade_statements, load_exercises, prepare, submission_seed
from .extract import SubmissionError, extract_notebook
from .report import feedback_html, gradescope_results, status_of
from .runner import Limits

__all__ = ["GradeRow", "collect_submissions", "grade_class", "read_gradebook", "GRADEBOOK"]

GRADEBOOK = "gradebook.csv"


@dataclass(frozen=True)
class GradeRow:
    submission: str
    score: float
    max_score: float
    status: str
    exercises: dict[str, float]
    seed: int
    seconds: dict[str, float] | None = None
    sandbox: str = ""

    def as_csv(self, exercise_ids: list[str]) -> list[str]:
        return [self.submission, _number(self.score), _number(self.max_score), self.status] + [
            _number(self.exercises.get(eid, 0.0)) for eid in exercise_ids
        ] + [str(self.seed)]


def _number(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".") if value else "0"


def collect_submissions(paths: list[Path]) -> dict[str, Path]:
    """Notebooks named by the paths (files, or folders of .ipynb files), keyed by submission name (the stem)."""
    found: dict[str, Path] = {}
    for path in map(Path, paths):
        if path.is_dir():
            files = sorted(p for p in path.glob("*.ipynb") if p.is_file())
        elif path.is_file():
            files = [path]
        else:
            raise FileNotFoundError(f"no such file or folder: {path}")
        for file in files:
            if file.stem in found and found[file.stem] != file.resolve():
                raise ValueError(f"two submissions are named {file.stem!r}: {found[file.stem]} and {file}")
            found[file.stem] = file.resolve()
    return dict(sorted(found.items()))


def atomic_write(path: Path, text: str) -> None:
    """Write a file so that readers see the old or the new content, never half of it."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def read_gradebook(path: Path) -> dict[str, list[str]]:
    """Rows of an existing gradebook by submission name (empty if there is none)."""
    if not path.is_file():
        return {}
    with path.open(encoding="utf-8", newline="") as handle:
        rows = list(csv.reader(handle))
    return {row[0]: row for row in rows[1:] if row}


def _gradebook_text(header: list[str], rows: dict[str, list[str]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(header)
    for name in sorted(rows):
        writer.writerow(rows[name])
    return buffer.getvalue()


def grade_one(name: str, path: Path, exercises, base_seed: int, limits: Limits, out: Path) -> GradeRow:
    """Grade one notebook and write its feedback page and results.json; return its gradebook row."""
    seed = submission_seed(base_seed, name)
    # Cases and reference answers exist before any of the submission's code runs.
    prepared = prepare(exercises, seed)
    max_score = round(sum(points for _, points in exercises.values()), 4)
    try:
        submission = extract_notebook(path)
    except SubmissionError as err:
        notes = [f"{err.status}: {err.detail}"]
        row = GradeRow(name, 0.0, max_score, err.status, {}, seed)
        _write_feedback(out / name, name, [], 0.0, max_score, notes)
        return row
    outcome = grade_statements(submission.statements, prepared, limits)
    notes = submission.skipped + outcome.run.load_problems
    problems = ["output truncated"] if outcome.run.output_truncated else []
    if not submission.defined_names() & {exercise.function for exercise, _ in exercises.values()}:
        problems.append("none of the exercise functions is defined")
    status = status_of(outcome.exercises, problems)
    _write_feedback(out / name, name, outcome.exercises, outcome.score, outcome.max_score, notes)
    return GradeRow(
        name,
        outcome.score,
        outcome.max_score,
        status,
        {r.id: r.score for r in outcome.exercises},
        seed,
        {r.id: r.seconds for r in outcome.exercises},
        outcome.run.sandbox,
    )


def _write_feedback(folder: Path, name: str, results, score: float, max_score: float, notes: list[str]) -> None:
    atomic_write(folder / "feedback.html", feedback_html(name, results, score, max_score, notes))
    atomic_write(folder / "results.json", json.dumps(gradescope_results(results, score, notes), indent=2) + "\n")


@dataclass
class ClassSummary:
    graded: int
    skipped: int
    failed_to_run: int
    mean_score: float
    max_score: float
    slowest_exercise: str
    seconds: float
    unconfined: str = ""

    def __str__(self) -> str:
        text = (
            f"graded {self.graded} submission(s) (skipped {self.skipped} already graded) in {self.seconds:.1f} s; "
            f"{self.failed_to_run} did not run cleanly; mean score {self.mean_score:.2f} / {self.max_score:g}"
            + (f"; slowest exercise {self.slowest_exercise}" if self.slowest_exercise else "")
        )
        if self.unconfined:
            text += (
                f"\nWARNING: graded code could write files as your user ({self.unconfined}); "
                "grade in a container or VM."
            )
        return text


def grade_class(
    paths,
    out,
    jobs: int = 1,
    limits: Limits = Limits(),
    seed: int = 0,
    force: bool = False,
    progress: bool = True,
    chapters: list[int] | None = None,
) -> ClassSummary:
    """Grade every submission under `paths` into `out` (on the exercises of `chapters`, default all).

    Submissions already in the gradebook are skipped unless `force`.
    """
    started = time.monotonic()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    submissions = collect_submissions(paths)
    course = load_course()
    exercises = load_exercises(course, _chapter_ids(course, chapters))
    ids = list(exercises)
    header = ["submission", "score", "max_score", "status"] + ids + ["seed"]
    gradebook = out / GRADEBOOK
    rows = {} if force else {k: v for k, v in read_gradebook(gradebook).items() if k in submissions}
    todo = {name: path for name, path in submissions.items() if name not in rows}
    new_rows: list[GradeRow] = []
    with (
        ThreadPoolExecutor(max_workers=max(1, jobs)) as pool,
        tqdm(total=len(todo), desc="grading", unit="submission", disable=None if progress else True) as bar,
    ):
        futures = {
            pool.submit(grade_one, name, path, exercises, seed, limits, out): name for name, path in todo.items()
        }
        for future in as_completed(futures):
            row = future.result()
            new_rows.append(row)
            rows[row.submission] = row.as_csv(ids)
            atomic_write(gradebook, _gradebook_text(header, rows))
            bar.update()
    if not todo:
        atomic_write(gradebook, _gradebook_text(header, rows))
    return _summary(new_rows, len(submissions) - len(todo), sum(p for _, p in exercises.values()), started)


def _chapter_ids(course, chapters: list[int] | None) -> list[str] | None:
    if not chapters:
        return None
    known = {c.number for c in course.chapters}
    unknown = sorted(set(chapters) - known)
    if unknown:
        raise ValueError(f"no chapter {unknown} in book.toml (chapters: {sorted(known)})")
    return [eid for c in course.chapters if c.number in chapters for eid in c.exercise_points]


def _summary(rows: list[GradeRow], skipped: int, max_score: float, started: float) -> ClassSummary:
    failed = sum(1 for r in rows if r.status != "ok")
    mean = sum(r.score for r in rows) / len(rows) if rows else 0.0
    totals: dict[str, float] = {}
    for row in rows:
        for exercise_id, seconds in (row.seconds or {}).items():
            totals[exercise_id] = totals.get(exercise_id, 0.0) + seconds
    slowest = max(totals, key=totals.get, default="")
    label = f"{slowest} ({totals[slowest] / len(rows):.2f} s per submission)" if slowest else ""
    unconfined = next((r.sandbox for r in rows if r.sandbox and "landlock ABI" not in r.sandbox), "")
    return ClassSummary(len(rows), skipped, failed, mean, max_score, label, time.monotonic() - started, unconfined)

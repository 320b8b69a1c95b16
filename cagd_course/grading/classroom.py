"""`cagd grade`: grade a whole class of notebooks into a gradebook, feedback pages and Gradescope JSON.

Every submission gets exactly one gradebook row whatever it does, with the
confinement its code ran under. Files are written atomically (temporary file,
then rename), the gradebook after every submission, so an interrupted run
loses nothing and resumes where it stopped. With ``jobs`` > 1 the submissions
are graded by that many grading processes, each with its own zygote: the
grader's side (drawing cases, computing the reference's answers, comparing)
costs as much CPU as running the submission, and one process holds one core.
Grading refuses to start where graded code cannot be confined, unless the
instructor allows it and is told exactly what that means.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import json
import os
import selectors
import subprocess
import sys
import tempfile
import time
import traceback
from dataclasses import dataclass
from pathlib import Path

from tqdm import tqdm

from ..manifest import load_course
from . import runner, sandbox
from .engine import grade_statements, load_exercises, prepare, submission_seed
from .extract import SubmissionError, extract_notebook
from .report import feedback_html, gradescope_results, status_of
from .runner import Limits

__all__ = ["GradeRow", "UnconfinedError", "collect_submissions", "grade_class", "read_gradebook", "GRADEBOOK"]

GRADEBOOK = "gradebook.csv"


class UnconfinedError(RuntimeError):
    """Graded code cannot be confined on this machine, and grading it unconfined was not allowed."""


@dataclass(frozen=True)
class GradeRow:
    """One gradebook line; `sandbox` is the confinement the submission's code ran under ("" if none ran)."""

    submission: str
    score: float
    max_score: float
    status: str
    exercises: dict[str, float]
    seed: int
    seconds: dict[str, float] | None = None
    sandbox: str = ""
    confined: bool | None = None

    def as_csv(self, exercise_ids: list[str]) -> list[str]:
        return [self.submission, _number(self.score), _number(self.max_score), self.status] + [
            _number(self.exercises.get(eid, 0.0)) for eid in exercise_ids
        ] + [str(self.seed), self.sandbox]


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


def grade_one(
    name: str, path: Path, exercises, base_seed: int, limits: Limits, out: Path, require_confinement: bool = True
) -> GradeRow:
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
    outcome = grade_statements(submission.statements, prepared, limits, require_confinement=require_confinement)
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
        outcome.run.confined,
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
    confinement: str = ""
    unconfined: str = ""

    def __str__(self) -> str:
        text = (
            f"graded {self.graded} submission(s) (skipped {self.skipped} already graded) in {self.seconds:.1f} s; "
            f"{self.failed_to_run} did not run cleanly; mean score {self.mean_score:.2f} / {self.max_score:g}"
            + (f"; slowest exercise {self.slowest_exercise}" if self.slowest_exercise else "")
        )
        if self.confinement:
            text += f"\nconfinement: {self.confinement}"
        if self.unconfined:
            text += f"\nWARNING: {self.unconfined}"
        return text


def _unconfined_text(probe: runner.RunResult, allowed: bool) -> str:
    """What graded code can do here, for the refusal or for the warning after an allowed unconfined run."""
    lead = (
        "graded unconfined (--allow-unconfined)" if allowed else "refusing to grade: graded code cannot be confined"
    )
    lines = [f"{lead}: {probe.sandbox or 'no confinement'}.", "Unconfined, a submission can"]
    lines += [f"  - {risk};" for risk in sandbox.risks(probe.gaps)]
    lines.append(
        "Grade on Linux 5.13 or later with Landlock and user namespaces enabled (a VM, or a container that allows "
        "them)" + ("." if allowed else ", or pass --allow-unconfined if you trust every submission.")
    )
    return "\n".join(lines)


class _GradingProcess:
    """A separate grading process of a `jobs` run: one submission at a time, rows back as JSON lines.

    A fresh interpreter rather than a fork or a multiprocessing pool: it inherits no thread, no
    zygote and nothing of the caller's main module, and a submission cannot reach it anyway.
    """

    def __init__(self, config: dict):
        code = "import sys, json; sys.path[:0] = json.loads(sys.argv[1]); " + (
            "from cagd_course.grading.classroom import _serve_grading; _serve_grading()"
        )
        self.proc = subprocess.Popen(
            [sys.executable, "-c", code, json.dumps(sys.path)],
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            text=True,
            # Ctrl-C reaches the grading run, which stops these; they would only print tracebacks.
            start_new_session=True,
        )
        self.send(config)

    def send(self, message: dict) -> None:
        self.proc.stdin.write(json.dumps(message) + "\n")
        self.proc.stdin.flush()

    def receive(self) -> GradeRow:
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"a grading process ended unexpectedly (exit code {self.proc.wait()})")
        message = json.loads(line)
        if "error" in message:
            raise RuntimeError(f"a grading process failed:\n{message['error']}")
        return GradeRow(**message["row"])

    def close(self) -> None:
        try:
            self.proc.stdin.close()
            self.proc.wait(timeout=runner.REAP_SECONDS + 5)
        except (OSError, subprocess.TimeoutExpired):
            self.proc.kill()
            self.proc.wait()
        self.proc.stdout.close()


def _serve_grading() -> None:
    """The loop of a grading process: a configuration line, then one submission per line until EOF."""
    channel = os.fdopen(os.dup(1), "w")
    os.dup2(2, 1)  # prints of the grading code must not corrupt the channel
    config = json.loads(sys.stdin.readline())
    runner.set_owner(config["owner"])
    exercises = load_exercises(load_course(), config["ids"])
    limits = Limits(**config["limits"])
    try:
        for line in sys.stdin:
            task = json.loads(line)
            try:
                row = grade_one(
                    task["name"], Path(task["path"]), exercises, config["seed"], limits, Path(config["out"]),
                    config["require"],
                )
                message = {"row": dataclasses.asdict(row)}
            except Exception:  # noqa: BLE001 - reported to the grading run, which stops
                message = {"error": traceback.format_exc()}
            channel.write(json.dumps(message) + "\n")
            channel.flush()
    finally:
        runner.shutdown()


def _graded_rows(todo: dict[str, Path], exercises, ids, seed: int, limits: Limits, out: Path, require: bool, jobs: int):
    """Grade `todo`, yielding each row as it is ready: in this process, or in `jobs` grading processes."""
    if jobs <= 1 or len(todo) <= 1:
        for name, path in todo.items():
            yield grade_one(name, path, exercises, seed, limits, out, require)
        return
    config = {
        "ids": ids,
        "owner": os.getpid(),
        "limits": dataclasses.asdict(limits),
        "seed": seed,
        "out": str(Path(out).resolve()),
        "require": require,
    }
    waiting = [{"name": name, "path": str(path)} for name, path in todo.items()][::-1]
    processes = [_GradingProcess(config) for _ in range(min(jobs, len(todo)))]
    selector = selectors.DefaultSelector()
    try:
        for process in processes:
            process.send(waiting.pop())
            selector.register(process.proc.stdout, selectors.EVENT_READ, process)
        busy = len(processes)
        while busy:
            for key, _ in selector.select():
                process = key.data
                yield process.receive()
                if waiting:
                    process.send(waiting.pop())
                else:
                    selector.unregister(key.fileobj)
                    busy -= 1
    finally:
        selector.close()
        for process in processes:
            process.close()


def grade_class(
    paths,
    out,
    jobs: int = 1,
    limits: Limits = Limits(),
    seed: int = 0,
    force: bool = False,
    progress: bool = True,
    chapters: list[int] | None = None,
    allow_unconfined: bool = False,
) -> ClassSummary:
    """Grade every submission under `paths` into `out` (on the exercises of `chapters`, default all).

    Submissions already in the gradebook are skipped unless `force`. Raises `UnconfinedError`
    before grading anyone where graded code cannot be confined, unless `allow_unconfined`.
    """
    started = time.monotonic()
    out = Path(out)
    submissions = collect_submissions(paths)
    course = load_course()
    ids = _chapter_ids(course, chapters)
    exercises = load_exercises(course, ids)
    try:
        probe = runner.probe(limits)
        if not probe.confined and not allow_unconfined:
            raise UnconfinedError(_unconfined_text(probe, allowed=False))
        out.mkdir(parents=True, exist_ok=True)
        exercise_ids = list(exercises)
        header = ["submission", "score", "max_score", "status"] + exercise_ids + ["seed", "confinement"]
        gradebook = out / GRADEBOOK
        rows = {} if force else {k: v for k, v in read_gradebook(gradebook).items() if k in submissions}
        todo = {name: path for name, path in submissions.items() if name not in rows}
        new_rows: list[GradeRow] = []
        bar = tqdm(total=len(todo), desc="grading", unit="submission", disable=None if progress else True)
        with bar:
            for row in _graded_rows(todo, exercises, ids, seed, limits, out, not allow_unconfined, jobs):
                new_rows.append(row)
                rows[row.submission] = row.as_csv(exercise_ids)
                atomic_write(gradebook, _gradebook_text(header, rows))
                bar.update()
        if not todo:
            atomic_write(gradebook, _gradebook_text(header, rows))
    finally:
        runner.shutdown()
    summary = _summary(new_rows, len(submissions) - len(todo), sum(p for _, p in exercises.values()), started)
    summary.confinement = probe.sandbox
    if not probe.confined:
        summary.unconfined = _unconfined_text(probe, allowed=True)
    elif any(row.confined is False for row in new_rows):
        fate = "ran unconfined" if allow_unconfined else "were not graded"
        summary.unconfined = f"some submissions could not be confined and {fate}; see the confinement column"
    return summary


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
    return ClassSummary(len(rows), skipped, failed, mean, max_score, label, time.monotonic() - started)

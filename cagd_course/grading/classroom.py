"""`cagd grade`: grade a class's notebooks, each on its own chapter, into the semester's gradebook.

Submissions come in nbgrader's folder-per-student layout or as an LMS bulk download (see
`layouts`); each notebook is graded on the exercises of its chapter only, and its record,
feedback page and Gradescope JSON go to ``GRADES/<submission>/chNN/``; the student's pages for
the whole semester to ``GRADES/<submission>/feedback.html`` and ``results.json``. Each record is
written as soon as its notebook is graded; the gradebook (`gradebook`) is rebuilt from the records
during the run at a cost proportional to the class (`_Gradebook`) and at its end, so an
interrupted run loses nothing and resumes where it stopped: a notebook already graded, unchanged,
is skipped unless ``force``. With ``jobs`` > 1 the submissions are graded by that many grading processes, each with
its own zygote: the grader's side (drawing cases, computing the reference's answers, comparing)
costs as much CPU as running the submission, and one process holds one core. Grading refuses to
start where graded code cannot be confined, unless the instructor allows it and is told exactly
what that means. At the end the class report (`class_report`) is written.
"""

from __future__ import annotations

import dataclasses
import hashlib
import html
import json
import os
import re
import selectors
import subprocess
import sys
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

from tqdm import tqdm

from ..manifest import load_course
from . import runner, sandbox
from .engine import grade_statements, load_exercises, prepare, submission_seed
from .extract import SubmissionError, extract_notebook
from .gradebook import (
    GRADEBOOK,
    UNASSIGNED,
    atomic_write,
    chapter_folder,
    exclusive,
    gradebook_text,
    load_records,
    read_gradebook,
    unassigned_text,
    write_record,
)
from .layouts import Found, find_submissions
from .report import feedback_html, gradescope_results, status_of
from .runner import Limits
from .similarity import function_fingerprints

__all__ = ["ClassSummary", "UnconfinedError", "grade_class", "grade_one", "read_gradebook", "GRADEBOOK"]


class UnconfinedError(RuntimeError):
    """Graded code cannot be confined on this machine, and grading it unconfined was not allowed."""


def _digest(path: Path) -> str:
    try:
        return hashlib.sha256(Path(path).read_bytes()).hexdigest()
    except OSError:
        return ""


def _task(found: Found) -> dict:
    return {
        "path": str(found.path),
        "submission": found.submission,
        "student": found.student,
        "lms_id": found.lms_id,
        "late": found.late,
        "original": found.original,
        "chapter": found.chapter,
        "how": found.how,
        "notes": list(found.notes),
        "sha256": _digest(found.path),
    }


def _categories(result) -> dict[str, list]:
    """Per category of cases: [passed, in all, visible] (names only: never the inputs)."""
    return {
        category: [sum(c.passed for c in cases), len(cases), bool(cases[0].visible)]
        for category, cases in result.categories().items()
    }


def grade_one(
    task: dict, exercises, base_seed: int, limits: Limits, out: Path, require_confinement: bool = True
) -> dict:
    """Grade one notebook on its chapter's `exercises`; write its feedback and results.json; return its record."""
    name, chapter = task["submission"], task["chapter"]
    seed = submission_seed(base_seed, name if chapter is None else f"{name}/ch{chapter:02d}")
    # Cases and reference answers exist before any of the submission's code runs.
    prepared = prepare(exercises, seed)
    max_score = round(sum(points for _, points in exercises.values()), 4)
    record = {
        **{k: task[k] for k in ("submission", "student", "lms_id", "late", "original", "chapter", "how", "sha256")},
        "file": task["path"],
        "seed": seed,
        "max_score": max_score,
        "score": 0.0,
        "exercises": {},
        "fingerprints": {},
        "sandbox": "",
        "confined": None,
        "graded": time.strftime("%Y-%m-%d %H:%M:%S"),
    }
    folder = chapter_folder(out, name, chapter)
    title = f"{task['student']}, chapter {chapter}"
    try:
        submission = extract_notebook(task["path"])
    except SubmissionError as err:
        notes = task["notes"] + [f"{err.status}: {err.detail}"]
        _write_feedback(folder, title, [], 0.0, max_score, notes)
        return {**record, "status": err.status, "notes": notes}
    outcome = grade_statements(submission.statements, prepared, limits, require_confinement=require_confinement)
    notes = task["notes"] + submission.skipped + outcome.run.load_problems
    problems = ["output truncated"] if outcome.run.output_truncated else []
    functions = {exercise.function: eid for eid, (exercise, _) in exercises.items()}
    if not submission.defined_names() & set(functions):
        problems.append("none of the exercise functions is defined")
    _write_feedback(folder, title, outcome.exercises, outcome.score, outcome.max_score, notes)
    record.update(
        score=outcome.score,
        max_score=outcome.max_score,
        status=status_of(outcome.exercises, problems),
        notes=notes,
        sandbox=outcome.run.sandbox,
        confined=outcome.run.confined,
        fingerprints=function_fingerprints(submission.statements, functions),
        exercises={
            r.id: {
                "score": r.score,
                "points": r.points,
                "seconds": round(r.seconds, 4),
                "stopped": r.stopped,
                "categories": _categories(r),
            }
            for r in outcome.exercises
        },
    )
    return record


def _write_feedback(folder: Path, title: str, results, score: float, max_score: float, notes: list[str]) -> None:
    atomic_write(folder / "feedback.html", feedback_html(title, results, score, max_score, notes))
    atomic_write(folder / "results.json", json.dumps(gradescope_results(results, score, notes), indent=2) + "\n")


_BODY = re.compile(r"<body>(.*)</body>", re.S)
_STYLE = re.compile(r"<style>(.*?)</style>", re.S)


def write_student_pages(out: Path, submission: str, records: list[dict]) -> None:
    """The student's semester: every graded chapter's feedback on one page, and one results.json of them all."""
    records = sorted(records, key=lambda r: r["chapter"])
    sections, tests, outputs, style = [], [], [], ""
    for record in records:
        folder = chapter_folder(out, submission, record["chapter"])
        try:
            page = (folder / "feedback.html").read_text(encoding="utf-8")
            results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        body = _BODY.search(page)
        style = style or (_STYLE.search(page).group(1) if _STYLE.search(page) else "")
        sections.append(f"<section id='ch{record['chapter']:02d}'>{body.group(1) if body else ''}</section>")
        tests += results.get("tests", [])
        if results.get("output"):
            outputs.append(f"chapter {record['chapter']}: {results['output']}")
    total = round(sum(float(r["score"]) for r in records), 4)
    name = html.escape(records[0]["student"]) if records else html.escape(submission)
    index = "".join(
        f"<li><a href='#ch{r['chapter']:02d}'>chapter {r['chapter']}</a>: {float(r['score']):g} / "
        f"{float(r['max_score']):g}</li>" for r in records
    )
    page = (
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>Feedback: {name}</title><style>{style}section{{border-top:2px solid #ddd;margin-top:2rem}}"
        f"</style></head><body><h1>Feedback for {name}</h1><p>Chapters graded so far:</p><ul>{index}</ul>"
        + "\n".join(sections) + "</body></html>\n"
    )
    atomic_write(Path(out) / submission / "feedback.html", page)
    combined = {"score": total, "output": "\n".join(outputs), "tests": tests}
    atomic_write(Path(out) / submission / "results.json", json.dumps(combined, indent=2) + "\n")


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
    by_chapter: dict = field(default_factory=dict)  # chapter -> (graded, mean, max)
    unassigned: list = field(default_factory=list)  # rows of unassigned.csv
    other_chapters: int = 0
    report: str = ""

    def __str__(self) -> str:
        if len(self.by_chapter) > 1:
            means = "mean score by chapter: " + ", ".join(
                f"{ch}: {mean:.2f} / {top:g} ({n})" for ch, (n, mean, top) in sorted(self.by_chapter.items())
            )
        else:
            means = f"mean score {self.mean_score:.2f} / {self.max_score:g}"
        text = (
            f"graded {self.graded} submission(s) (skipped {self.skipped} already graded) in {self.seconds:.1f} s; "
            f"{self.failed_to_run} did not run cleanly; {means}"
            + (f"; slowest exercise {self.slowest_exercise}" if self.slowest_exercise else "")
        )
        if self.other_chapters:
            text += f"\nleft out {self.other_chapters} notebook(s) of other chapters (--chapter)"
        if self.unassigned:
            text += f"\nnot graded: {len(self.unassigned)} notebook(s) (see {UNASSIGNED}):"
            text += "".join(f"\n  {row['file']}: {row['reason']}" for row in self.unassigned[:20])
            if len(self.unassigned) > 20:
                text += f"\n  ... and {len(self.unassigned) - 20} more"
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


class _Exercises:
    """The hidden suites of each chapter, loaded when first needed (a broken chapter stops only its own notebooks)."""

    def __init__(self, course):
        self.course = course
        self.loaded: dict[int, object] = {}

    def __call__(self, chapter: int):
        if chapter not in self.loaded:
            ids = next((list(c.exercise_points) for c in self.course.chapters if c.number == chapter), [])
            try:
                if not ids:
                    raise KeyError(f"book.toml lists no graded exercise for chapter {chapter}")
                self.loaded[chapter] = load_exercises(self.course, ids)
            except Exception as err:  # noqa: BLE001 - a broken suite is reported for its own notebooks
                self.loaded[chapter] = err
        return self.loaded[chapter]


class _GradingProcess:
    """A separate grading process of a `jobs` run: one submission at a time, records back as JSON lines.

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

    def receive(self) -> dict:
        line = self.proc.stdout.readline()
        if not line:
            raise RuntimeError(f"a grading process ended unexpectedly (exit code {self.proc.wait()})")
        message = json.loads(line)
        if "error" in message:
            raise RuntimeError(f"a grading process failed:\n{message['error']}")
        return message["record"]

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
    suites = _Exercises(load_course())
    limits = Limits(**config["limits"])
    try:
        for line in sys.stdin:
            task = json.loads(line)
            try:
                record = grade_one(
                    task, suites(task["chapter"]), config["seed"], limits, Path(config["out"]), config["require"]
                )
                message = {"record": record}
            except Exception:  # noqa: BLE001 - reported to the grading run, which stops
                message = {"error": traceback.format_exc()}
            channel.write(json.dumps(message) + "\n")
            channel.flush()
    finally:
        runner.shutdown()


def _graded(todo: list[dict], suites: _Exercises, seed: int, limits: Limits, out: Path, require: bool, jobs: int):
    """Grade `todo`, yielding each record as it is ready: in this process, or in `jobs` grading processes."""
    if jobs <= 1 or len(todo) <= 1:
        for task in todo:
            yield grade_one(task, suites(task["chapter"]), seed, limits, out, require)
        return
    config = {
        "owner": os.getpid(),
        "limits": dataclasses.asdict(limits),
        "seed": seed,
        "out": str(Path(out).resolve()),
        "require": require,
    }
    waiting = list(todo)[::-1]
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


# What a run keeps of each record in memory (the gradebook, the students' pages and the summary need no more;
# the class report reads the records from disk): a class of 10,000 then holds a few objects per exercise each.
_KEPT = ("submission", "student", "lms_id", "late", "chapter", "seed", "score", "max_score", "status", "sandbox",
         "confined", "sha256")


def _slim(record: dict) -> dict:
    slim = {key: record.get(key) for key in _KEPT if key in record}
    slim["exercises"] = {eid: {"score": r.get("score", 0.0), "points": r.get("points", 0.0),
                               "seconds": r.get("seconds", 0.0)} for eid, r in record.get("exercises", {}).items()}
    return slim


class _Gradebook:
    """Writes GRADES/gradebook.csv from the records during a run, at a cost proportional to the class.

    A rebuild reads every record, so rebuilding after each submission would cost the square of the
    class. The gradebook is rewritten when the grading done since the last rewrite has taken at
    least `SHARE` times as long as that rewrite did (and at least `EVERY` seconds), so rewriting
    adds at most about 1/SHARE to the run's time, and always at the end. The records are the
    truth: an interrupted run leaves a gradebook that may lag behind them, which the next run
    rebuilds.
    """

    SHARE = 20.0
    EVERY = 2.0

    def __init__(self, path: Path, records: dict, course):
        self.path, self.records, self.course = path, records, course
        self.cost = 0.0
        self.since = time.monotonic()
        self.pending = False

    def changed(self) -> None:
        self.pending = True
        if time.monotonic() - self.since >= max(self.SHARE * self.cost, self.EVERY):
            self.write()

    def write(self) -> None:
        started = time.monotonic()
        atomic_write(self.path, gradebook_text(self.records, self.course))
        self.since = time.monotonic()
        self.cost = self.since - started
        self.pending = False


def _check_chapters(course, chapters: list[int] | None) -> None:
    if not chapters:
        return
    known = {c.number for c in course.chapters}
    unknown = sorted(set(chapters) - known)
    if unknown:
        raise ValueError(f"no chapter {unknown} in book.toml (chapters: {sorted(known)})")


def _plan(found: list[Found], chapters, students, suites: _Exercises):
    """Split the notebooks into those to grade (one per student and chapter) and those reported instead."""
    unassigned, other = [], 0
    groups: dict[tuple[str, int], list[Found]] = {}
    for item in found:
        if students and item.submission not in students and item.student not in students:
            continue
        if item.chapter is None:
            unassigned.append({"submission": item.submission, "file": str(item.path), "reason": item.problem})
            continue
        if chapters and item.chapter not in chapters:
            other += 1
            continue
        groups.setdefault((item.submission, item.chapter), []).append(item)
    tasks = []
    for (submission, chapter), items in sorted(groups.items()):
        clear = [i for i in items if not i.unclear]
        if clear and len(clear) < len(items):
            # --chapter names the chapter of unclear notebooks only where the student has no clear one.
            for item in items:
                if item.unclear:
                    unassigned.append({"submission": submission, "file": str(item.path), "reason": item.unclear})
            items = clear
        if len(items) > 1:
            names = ", ".join(sorted(str(i.path) for i in items))
            for item in items:
                unassigned.append({"submission": submission, "file": str(item.path),
                                   "reason": f"{len(items)} notebooks of this student for chapter {chapter}: {names}"})
            continue
        suite = suites(chapter)
        if isinstance(suite, Exception):
            unassigned.append({"submission": submission, "file": str(items[0].path),
                               "reason": f"chapter {chapter} cannot be graded: {suite}"})
            continue
        tasks.append(_task(items[0]))
    return tasks, unassigned, other


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
    students: list[str] | None = None,
    report: bool = True,
) -> ClassSummary:
    """Grade every notebook under `paths` on its own chapter into the grades folder `out`.

    chapters: grade only these chapters (a single one also decides notebooks whose chapter is
    unclear); students: only these students (submission keys or names). Notebooks already graded
    and unchanged are skipped unless `force`. Raises `UnconfinedError` before grading anyone where
    graded code cannot be confined, unless `allow_unconfined`.
    """
    started = time.monotonic()
    out = Path(out)
    course = load_course()
    _check_chapters(course, chapters)
    found = find_submissions(paths, course, chapters)
    suites = _Exercises(course)
    tasks, unassigned, other = _plan(found, chapters, set(students or ()), suites)
    try:
        probe = runner.probe(limits)
        if not probe.confined and not allow_unconfined:
            raise UnconfinedError(_unconfined_text(probe, allowed=False))
        with exclusive(out):
            records = {key: _slim(record) for key, record in load_records(out).items()}
            todo = [
                t for t in tasks
                if force or records.get((t["submission"], t["chapter"]), {}).get("sha256") != t["sha256"]
                or not t["sha256"]
            ]
            new: list[dict] = []
            atomic_write(out / UNASSIGNED, unassigned_text(unassigned))
            # Each student's chapters, so that writing a student's pages costs their chapters, not the class.
            chapters_of: dict[str, dict[int, dict]] = {}
            for (submission, chapter), record in records.items():
                chapters_of.setdefault(submission, {})[chapter] = record
            gradebook = _Gradebook(out / GRADEBOOK, records, course)
            bar = tqdm(total=len(todo), desc="grading", unit="notebook", disable=None if progress else True)
            with bar:
                for record in _graded(todo, suites, seed, limits, out, not allow_unconfined, jobs):
                    write_record(out, record)
                    record = _slim(record)
                    records[(record["submission"], record["chapter"])] = record
                    new.append(record)
                    mine = chapters_of.setdefault(record["submission"], {})
                    mine[record["chapter"]] = record
                    write_student_pages(out, record["submission"], list(mine.values()))
                    gradebook.changed()
                    bar.set_postfix_str(f"{record['student']} ch{record['chapter']:02d}", refresh=False)
                    bar.update()
            gradebook.write()
            written = ""
            if report:
                from .class_report import write_report

                try:
                    written = str(write_report(out, course))
                except Exception as err:  # noqa: BLE001 - the grades are written; the report is told apart
                    written = f"(the class report could not be written: {err})"
    finally:
        runner.shutdown()
    summary = _summary(new, len(tasks) - len(todo), started)
    summary.unassigned, summary.other_chapters, summary.report = unassigned, other, written
    summary.confinement = probe.sandbox
    if not probe.confined:
        summary.unconfined = _unconfined_text(probe, allowed=True)
    elif any(r["confined"] is False for r in new):
        fate = "ran unconfined" if allow_unconfined else "were not graded"
        summary.unconfined = f"some submissions could not be confined and {fate}; see the confinement column"
    return summary


def _summary(records: list[dict], skipped: int, started: float) -> ClassSummary:
    failed = sum(1 for r in records if r["status"] != "ok")
    by_chapter: dict[int, list[dict]] = {}
    for record in records:
        by_chapter.setdefault(record["chapter"], []).append(record)
    chapters = {
        ch: (len(rs), sum(float(r["score"]) for r in rs) / len(rs), max(float(r["max_score"]) for r in rs))
        for ch, rs in by_chapter.items()
    }
    mean = sum(float(r["score"]) for r in records) / len(records) if records else 0.0
    top = max((float(r["max_score"]) for r in records), default=0.0)
    totals: dict[str, float] = {}
    for record in records:
        for exercise_id, result in record["exercises"].items():
            totals[exercise_id] = totals.get(exercise_id, 0.0) + result["seconds"]
    slowest = max(totals, key=totals.get, default="")
    count = sum(1 for r in records if slowest in r["exercises"]) if slowest else 0
    label = f"{slowest} ({totals[slowest] / count:.2f} s per submission)" if slowest else ""
    seconds = time.monotonic() - started
    return ClassSummary(len(records), skipped, failed, mean, top, label, seconds, by_chapter=chapters)

"""Hidden suites in, scores out: prepare cases and expected values, run a submission, compare.

Everything that decides a grade happens here, in the grader's process:
suites are loaded and expected values computed from the reference before
any student code runs, and the values a worker sends back are compared
against them with the exercise's comparison.
"""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import inspect
import json
from collections import OrderedDict
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..manifest import Course, load_course
from .runner import Limits, RunResult, Task, run_tasks
from .suite import Case, Exercise, Mismatch, Raises, expected_value
from .worker import Unsupported, decode, encode

__all__ = [
    "CaseResult",
    "ExerciseResult",
    "Prepared",
    "load_exercises",
    "prepare",
    "grade_statements",
    "submission_seed",
]


def submission_seed(base_seed: int, name: str) -> int:
    """The seed of a submission's random cases: fixed by the run's seed and the submission's name."""
    digest = hashlib.sha256(f"{base_seed}:{name}".encode()).hexdigest()
    return int(digest[:12], 16)


def _load_suite_file(path: Path) -> list[Exercise]:
    spec = importlib.util.spec_from_file_location(f"cagd_hidden_{path.stem}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return list(module.EXERCISES)


def load_exercises(course: Course | None = None, ids: list[str] | None = None) -> dict[str, tuple[Exercise, float]]:
    """Every exercise of the course (or just `ids`) with its points, from the hidden suites in book.toml order."""
    course = course or load_course()
    listed = course.exercise_points()
    unknown = [i for i in ids or () if i not in listed]
    if unknown:
        raise KeyError(f"unknown exercise id(s) {unknown}; `cagd list` shows them")
    wanted = list(listed) if ids is None else list(ids)
    found: dict[str, tuple[Exercise, float]] = {}
    for chapter in course.chapters:
        mine = [eid for eid in wanted if eid in chapter.exercise_points]
        if not mine:
            continue
        if chapter.hidden is None or not chapter.hidden.is_file():
            raise FileNotFoundError(f"chapter {chapter.number}: hidden suite {chapter.hidden} is missing")
        by_id = {exercise.id: exercise for exercise in _load_suite_file(chapter.hidden)}
        for exercise_id in mine:
            if exercise_id not in by_id:
                raise KeyError(f"{chapter.hidden} has no exercise {exercise_id!r} listed in book.toml")
            found[exercise_id] = (by_id[exercise_id], float(listed[exercise_id]))
    return {eid: found[eid] for eid in wanted}


@dataclass
class Prepared:
    """An exercise ready to grade: its cases, their encoded form and the reference's answers."""

    exercise: Exercise
    points: float
    cases: list[Case]
    expected: list
    encoded: list[dict]
    sent: list[str] = field(default_factory=list)  # the encoded cases as JSON text, as the worker gets them

    def task(self) -> Task:
        text = "[" + ",".join(self.sent) + "]" if self.sent else ""
        return Task(self.exercise.id, self.exercise.function, self.encoded, text)


# The reference's answers by exercise and input as sent: the fixed cases (the notes' examples, edge
# cases, bad input) recur in every submission, and a class would otherwise recompute them each time.
_ANSWERS: OrderedDict = OrderedDict()
ANSWERS_KEPT = 50_000


def _answer(exercise: Exercise, case: Case, sent: str):
    key = (exercise.id, exercise.reference, sent)
    if key in _ANSWERS:
        _ANSWERS.move_to_end(key)
        return _ANSWERS[key]
    value = _ANSWERS[key] = expected_value(exercise, case)
    if len(_ANSWERS) > ANSWERS_KEPT:
        _ANSWERS.popitem(last=False)
    return value


def prepare(exercises: dict[str, tuple[Exercise, float]], seed: int) -> list[Prepared]:
    """Draw each exercise's cases from `seed` and compute the expected values with the reference."""
    prepared = []
    for exercise_id, (exercise, points) in exercises.items():
        # Each exercise gets its own stream so adding cases to one does not reshuffle another.
        rng = np.random.default_rng([seed, int(hashlib.sha256(exercise_id.encode()).hexdigest()[:8], 16)])
        cases = exercise.cases(rng)
        encoded = [{"args": encode(list(case.args)), "kwargs": encode(dict(case.kwargs))} for case in cases]
        sent = [json.dumps(e) for e in encoded]
        expected = [_answer(exercise, case, text) for case, text in zip(cases, sent)]
        prepared.append(Prepared(exercise, points, cases, expected, encoded, sent))
    return prepared


@dataclass
class CaseResult:
    """One case's verdict; `kind` names the failure (see `suite.Mismatch`), `rule` the statement's rule it tests."""

    category: str
    visible: bool
    passed: bool
    message: str = ""
    case: Case | None = None
    expected: object = None
    received: object = None
    kind: str = ""
    rule: str = ""


@dataclass
class ExerciseResult:
    id: str
    points: float
    score: float
    cases: list[CaseResult]
    stopped: str = ""
    hint: str = ""
    seconds: float = 0.0
    # The comparison's (rtol, atol), quoted when a value misses it narrowly.
    tolerance: tuple[float, float] | None = None

    def categories(self) -> dict[str, list[CaseResult]]:
        grouped: dict[str, list[CaseResult]] = {}
        for result in self.cases:
            grouped.setdefault(result.category, []).append(result)
        return grouped

    @property
    def passed(self) -> bool:
        return all(result.passed for result in self.cases) and bool(self.cases)


def _received(event: dict):
    if "raised" in event:
        record = event["raised"]
        return Raises(str(record.get("type")), str(record.get("message")))
    return decode(event.get("value"))


@functools.lru_cache(maxsize=256)
def _parameter_names(function) -> tuple[str, ...]:
    """The positional parameters of the exercise's reference: the names the statement gives them."""
    try:
        parameters = inspect.signature(function).parameters.values()
    except (TypeError, ValueError):
        return ()
    return tuple(p.name for p in parameters if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD))


def _mutation(exercise: Exercise, case: Case, sent: list, event: dict) -> str:
    """A message if the student's function changed one of its inputs in place (`sent`: the inputs as encoded)."""
    if "args_after" not in event or event["args_after"] == sent:
        return ""  # the worker leaves the inputs out when they came back as they were sent
    after = decode(event.get("args_after"))
    if not isinstance(after, list) or len(after) != len(case.args):
        return ""
    names = _parameter_names(exercise.reference)
    for position, (before, now) in enumerate(zip(case.args, after)):
        if isinstance(before, (np.ndarray, list)) and not isinstance(now, Unsupported):
            try:
                same = np.array_equal(np.asarray(before, dtype=float), np.asarray(now, dtype=float), equal_nan=True)
            except (TypeError, ValueError):
                same = False
            if not same:
                name = f"`{names[position]}`" if position < len(names) else f"number {position + 1}"
                return Mismatch(
                    f"the function changed its argument {name} in place (inputs must be left unchanged)", "mutation"
                )
    return ""


def _judge(prepared: Prepared, index: int, event: dict | None, stopped: str, compare) -> CaseResult:
    case = prepared.cases[index]
    expected = prepared.expected[index]
    rule = prepared.exercise.rule_for(case)
    base = dict(category=case.category, visible=case.visible, case=case, expected=expected, rule=rule)
    if event is None:
        return CaseResult(passed=False, message=stopped or "not run", kind="stopped", **base)
    if "missing" in event:
        return CaseResult(passed=False, message=str(event["missing"]), kind="missing", **base)
    received = _received(event)
    try:
        problem = compare(expected, received)
    except Exception as err:  # noqa: BLE001 - a suite that cannot read an answer fails that case, not the run
        problem = Mismatch(f"the answer could not be compared ({type(err).__name__}: {err})"[:300], "type")
    if problem is None:
        problem = _mutation(prepared.exercise, case, prepared.encoded[index]["args"], event)
    kind = getattr(problem, "kind", "value") if problem else ""
    return CaseResult(passed=not problem, message=str(problem or ""), received=received, kind=kind, **base)


def _tolerance(exercise: Exercise) -> tuple[float, float] | None:
    compare = exercise.comparison()
    rtol, atol = getattr(compare, "rtol", None), getattr(compare, "atol", None)
    return (float(rtol), float(atol)) if rtol is not None and atol is not None else None


def score(cases: list[CaseResult], points: float) -> float:
    """Points times the mean, over categories, of the fraction of cases passed."""
    if not cases:
        return 0.0
    grouped: dict[str, list[bool]] = {}
    for result in cases:
        grouped.setdefault(result.category, []).append(result.passed)
    fraction = sum(sum(flags) / len(flags) for flags in grouped.values()) / len(grouped)
    return round(points * fraction, 4)


@dataclass
class GradeRun:
    """The outcome of running one submission on prepared exercises."""

    exercises: list[ExerciseResult]
    run: RunResult
    notes: list[str] = field(default_factory=list)

    @property
    def score(self) -> float:
        return round(sum(e.score for e in self.exercises), 4)

    @property
    def max_score(self) -> float:
        return round(sum(e.points for e in self.exercises), 4)


def grade_statements(
    statements: list[dict],
    prepared: list[Prepared],
    limits: Limits = Limits(),
    allow_reference: bool = False,
    require_confinement: bool = False,
) -> GradeRun:
    """Run the submission's statements in a worker on every prepared exercise and score the answers.

    With `require_confinement` nothing runs where graded code cannot be confined (every exercise
    scores 0, "not graded").
    """
    run = run_tasks(statements, [p.task() for p in prepared], limits, allow_reference, require_confinement)
    results = []
    for item in prepared:
        events = run.events.get(item.exercise.id, [])
        stopped = run.stopped.get(item.exercise.id, "")
        compare = item.exercise.comparison()
        cases = [
            _judge(item, index, events[index] if index < len(events) else None, stopped, compare)
            for index in range(len(item.cases))
        ]
        results.append(
            ExerciseResult(
                id=item.exercise.id,
                points=item.points,
                score=score(cases, item.points),
                cases=cases,
                stopped=stopped,
                hint=item.exercise.hint,
                seconds=float(run.seconds.get(item.exercise.id, 0.0)),
                tolerance=_tolerance(item.exercise),
            )
        )
    return GradeRun(results, run)

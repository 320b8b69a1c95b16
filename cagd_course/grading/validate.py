"""`cagd validate`: prove every hidden suite right before it grades anyone.

For each exercise: the reference must score 100%, the untouched stub of the
shipped exercise notebook 0%, and every recorded wrong implementation
(``tests/hidden/mistakes/chNN/<function>__<mistake>.py``) less than 100%.
All three run through the same isolated worker as a student's submission.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from tqdm import tqdm

from ..manifest import Course, load_course
from .engine import grade_statements, load_exercises, prepare
from .extract import extract_notebook, extract_source
from .runner import Limits

__all__ = ["Verdict", "validate", "mistake_files"]

MINIMUM_MISTAKES = 2


@dataclass
class Verdict:
    exercise: str
    points: float
    reference: float = 0.0
    stub: float = 0.0
    mistakes: dict[str, float] = field(default_factory=dict)

    @property
    def problems(self) -> list[str]:
        found = []
        if self.reference != self.points:
            found.append(f"reference scores {self.reference:g}/{self.points:g}, not full marks")
        if self.stub != 0:
            found.append(f"untouched stub scores {self.stub:g}, not 0")
        if len(self.mistakes) < MINIMUM_MISTAKES:
            found.append(f"only {len(self.mistakes)} recorded mistake(s), at least {MINIMUM_MISTAKES} needed")
        found += [f"mistake {name!r} gets full marks" for name, s in self.mistakes.items() if s >= self.points]
        return found


def mistake_files(hidden_suite: Path) -> dict[str, list[Path]]:
    """Recorded wrong implementations next to a suite, by function name."""
    folder = hidden_suite.parent / "mistakes" / hidden_suite.stem
    found: dict[str, list[Path]] = {}
    for path in sorted(folder.glob("*__*.py")):
        found.setdefault(path.stem.split("__", 1)[0], []).append(path)
    return found


def validate(
    course: Course | None = None, seed: int = 0, ids: list[str] | None = None, progress: bool = True
) -> list[Verdict]:
    """Grade the reference, the shipped stubs and the recorded mistakes of every exercise."""
    course = course or load_course()
    exercises = load_exercises(course, ids)
    prepared = {p.exercise.id: p for p in prepare(exercises, seed)}
    verdicts = {eid: Verdict(eid, points) for eid, (_, points) in exercises.items()}
    limits = Limits(exercise_seconds=20, submission_seconds=300)
    jobs = []
    for chapter in course.chapters:
        mine = [prepared[eid] for eid in chapter.exercise_points if eid in prepared]
        if not mine:
            continue
        jobs.append(("reference", mine, _reference_statements(mine), None))
        jobs.append(("stub", mine, extract_notebook(chapter.exercises).statements, None))
        mistakes = mistake_files(chapter.hidden)
        for item in mine:
            for path in mistakes.get(item.exercise.function, []):
                statements = extract_source([path.read_text(encoding="utf-8")]).statements
                jobs.append(("mistake", [item], statements, path.stem.split("__", 1)[1]))
    for kind, items, statements, label in tqdm(
        jobs, desc="validating suites", unit="run", disable=None if progress else True
    ):
        outcome = grade_statements(statements, items, limits, allow_reference=kind == "reference")
        for result in outcome.exercises:
            verdict = verdicts[result.id]
            if kind == "mistake":
                verdict.mistakes[label] = result.score
            else:
                setattr(verdict, kind, result.score)
    return list(verdicts.values())


def _reference_statements(items) -> list[dict]:
    return [
        {
            "source": (
                f"from {p.exercise.reference.__module__} import {p.exercise.reference.__name__} "
                f"as {p.exercise.function}"
            ),
            "where": "reference",
        }
        for p in items
    ]


def format_verdicts(verdicts: list[Verdict]) -> str:
    """A plain-text table: one line per exercise, then the problems found."""
    lines = [f"{'exercise':28} {'points':>6} {'reference':>9} {'stub':>5}  mistakes (score)"]
    for v in verdicts:
        mistakes = ", ".join(f"{name} {score:g}" for name, score in v.mistakes.items())
        mark = "ok " if not v.problems else "BAD"
        lines.append(f"{mark} {v.exercise:24} {v.points:6g} {v.reference:9g} {v.stub:5g}  {mistakes}")
    problems = [f"{v.exercise}: {p}" for v in verdicts for p in v.problems]
    lines.append("")
    lines.append("All suites valid." if not problems else "Problems:\n  " + "\n  ".join(problems))
    return "\n".join(lines)

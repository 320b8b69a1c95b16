"""Every rule a hidden suite checks is written in the statement of its exercise.

The statement is the student's whole specification. So every case of a hidden suite whose category
does not explain itself (the notes' and the course's examples, random cases) names the rule of the
statement it tests (`Case.rule`, or `Exercise.rules` for its whole category), and that rule must be
found, word for word, in the statement of that very exercise: the markdown cells from the
exercise's heading down to its check cell, found by the stub's ``def name(`` (or ``class name``) and
by ``check("NN.name", ...)``. Whitespace and markdown emphasis (``**``, ``*``, backticks) do not
count; a sentence in the notebook's introduction or in another exercise's statement does not
count either. Chapters whose suite or exercise notebook does not exist yet are skipped.
"""

from __future__ import annotations

import re

import nbformat
import numpy as np
import pytest

from cagd_course.grading.engine import _load_suite_file
from cagd_course.grading.suite import Case, Exercise
from cagd_course.manifest import load_course

# Categories that explain themselves: worked examples of the notes or the course, and random cases.
SELF_EXPLAINING = frozenset(
    {"notes example", "notes examples", "course example", "course examples", "random"}
)
SEED = 0  # the fixed cases do not depend on it; the random ones are allowed without a rule


def normalise(text: str) -> str:
    """Text with markdown emphasis and code marks dropped and every run of whitespace one space."""
    text = re.sub(r"[*`]", "", text)
    return re.sub(r"\s+", " ", text).strip()


def statement(cells, exercise_id: str) -> str:
    """The markdown of exercise `exercise_id`: its heading cell down to its check cell.

    Raises LookupError when the notebook has no check cell for the exercise or no stub before it.
    """
    name = exercise_id.split(".", 1)[1]
    check = re.compile(r"""\bcheck\(\s*["']""" + re.escape(exercise_id) + r"""["']""")
    stub = re.compile(rf"^(?:def|class)\s+{re.escape(name)}\b", re.M)
    at_check = next((i for i, c in enumerate(cells) if c.cell_type == "code" and check.search(c.source)), None)
    if at_check is None:
        raise LookupError(f"no cell calls check({exercise_id!r}, ...)")
    at_stub = next(
        (i for i in range(at_check - 1, -1, -1) if cells[i].cell_type == "code" and stub.search(cells[i].source)),
        None,
    )
    if at_stub is None:
        raise LookupError(f"no stub `def {name}(` before the check cell of {exercise_id}")
    start = at_stub
    while start > 0 and not (cells[start].cell_type == "markdown" and cells[start].source.lstrip().startswith("#")):
        start -= 1
    return "\n\n".join(c.source for c in cells[start:at_check] if c.cell_type == "markdown")


def problems(exercise: Exercise, cells) -> list[str]:
    """What the statement of `exercise` in the notebook `cells` does not say of the rules its suite checks."""
    try:
        text = normalise(statement(cells, exercise.id))
    except LookupError as err:
        return [str(err)]
    found: dict[tuple[str, str], str] = {}
    cases: list[Case] = exercise.cases(np.random.default_rng(SEED))
    for number, case in enumerate(cases):
        if case.category in SELF_EXPLAINING:
            continue
        rule = exercise.rule_for(case)
        if not rule.strip():
            message = f"category {case.category!r} has no rule (first: case {number}, {repr(case.args)[:80]})"
        elif normalise(rule) not in text:
            message = f"category {case.category!r}: the rule {rule!r} is not in the statement"
        else:
            continue
        found.setdefault((case.category, rule.strip()), message)
    return list(found.values())


def _exercises():
    course = load_course()
    for chapter in course.chapters:
        if chapter.hidden is None or chapter.exercises is None:
            continue
        if not (chapter.hidden.is_file() and chapter.exercises.is_file()):
            continue
        listed = chapter.exercise_points
        for exercise in _load_suite_file(chapter.hidden):
            if exercise.id in listed:
                yield pytest.param(exercise, chapter.exercises, id=exercise.id)


@pytest.mark.parametrize(("exercise", "notebook"), list(_exercises()))
def test_every_rule_the_suite_checks_is_in_the_statement(exercise, notebook):
    cells = nbformat.read(notebook, as_version=4).cells
    found = problems(exercise, cells)
    assert not found, f"{exercise.id} ({notebook.name}):\n  " + "\n  ".join(found)


# --- the check itself can fail ------------------------------------------------------------


def _notebook(*cells):
    made = []
    for kind, source in cells:
        made.append(nbformat.v4.new_markdown_cell(source) if kind == "md" else nbformat.v4.new_code_cell(source))
    return made


CELLS = _notebook(
    ("md", "# Exercises\n\n* Bad input must be rejected with a `ValueError`."),
    ("md", "## Exercise 1.1: a\n\nWrite `a(x)`.\n\n* Raise a `ValueError` if `x` is **negative**."),
    ("code", "def a(x):\n    raise NotImplementedError"),
    ("md", "**Examples:** `a(1)` gives 1.\n\nThe tests include   x = 0."),
    ("code", 'check("01.a", a)'),
    ("md", "## Exercise 1.2: b\n\n* Raise a `ValueError` if `x` is zero."),
    ("code", "def b(x):\n    raise NotImplementedError"),
    ("code", 'check("01.b", b)'),
)


def _synthetic(exercise_id="01.a", rules=None, rule="", category="bad input"):
    def cases(rng):
        return [
            Case("notes example", (1.0,), visible=True),
            Case("random", (float(rng.uniform()),)),
            Case(category, (-1.0,), rule=rule),
        ]

    return Exercise(id=exercise_id, reference=abs, cases=cases, rules=rules or {})


@pytest.mark.parametrize(
    ("exercise", "wanted"),
    [
        pytest.param(_synthetic(), "has no rule", id="no rule"),
        pytest.param(_synthetic(rules={"bad input": "   "}), "has no rule", id="blank rule"),
        pytest.param(_synthetic(rule="Raise a ValueError if x is positive."), "not in the statement", id="other words"),
        pytest.param(_synthetic(rule="Raise a ValueError if x is zero."), "not in the statement", id="other exercise"),
        pytest.param(
            _synthetic(rule="Bad input must be rejected with a ValueError."), "not in the statement", id="introduction"
        ),
        pytest.param(_synthetic(category="edge cases"), "'edge cases' has no rule", id="edge cases need one too"),
        pytest.param(_synthetic("01.c", rules={"bad input": "x"}), "no cell calls check", id="no check cell"),
    ],
)
def test_a_rule_missing_from_its_statement_is_reported(exercise, wanted):
    found = problems(exercise, CELLS)
    assert found and wanted in found[0], found


@pytest.mark.parametrize(
    "exercise",
    [
        pytest.param(_synthetic(rules={"bad input": "Raise a ValueError if x is negative."}), id="category rule"),
        pytest.param(_synthetic(rule="if x is negative"), id="a phrase of it"),
        pytest.param(_synthetic(category="edge cases", rule="The tests include x = 0."), id="examples cell, spaces"),
        pytest.param(_synthetic("01.b", rule="Raise a ValueError if x is zero."), id="last exercise"),
    ],
)
def test_a_rule_written_in_its_own_statement_is_found(exercise):
    assert problems(exercise, CELLS) == []


def test_the_course_has_statements_to_check():
    assert len(list(_exercises())) >= 90

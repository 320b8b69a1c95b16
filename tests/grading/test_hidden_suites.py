"""The hidden suites are right: `cagd validate` passes, and their cases are reproducible."""

import numpy as np
import pytest

from cagd_course.cli import main
from cagd_course.grading.engine import load_exercises, prepare
from cagd_course.grading.validate import format_verdicts, validate

EXERCISES = load_exercises()


def test_validate_proves_every_suite():
    verdicts = validate(progress=False)
    problems = [p for v in verdicts for p in v.problems]
    assert not problems, format_verdicts(verdicts)
    assert {v.exercise for v in verdicts} == set(EXERCISES)


def test_cagd_validate_command_reports_success_for_one_exercise(capsys):
    assert main(["validate", "--exercise", "02.de_casteljau"]) == 0
    assert "All suites valid." in capsys.readouterr().out


@pytest.mark.parametrize("exercise_id", list(EXERCISES))
def test_cases_are_reproducible_and_random_cases_follow_the_seed(exercise_id):
    subset = {exercise_id: EXERCISES[exercise_id]}
    first, again, other = (prepare(subset, seed)[0] for seed in (3, 3, 4))
    assert first.encoded == again.encoded
    assert 10 <= len(first.cases) <= 60
    visible = {c.category for c in first.cases if c.visible}
    assert visible, "students need at least one category whose failures they can see"
    randoms = [i for i, c in enumerate(first.cases) if c.category == "random"]
    if randoms:
        assert any(first.encoded[i] != other.encoded[i] for i in randoms)


def test_bad_input_categories_really_are_rejected_by_the_reference():
    from cagd_course.grading.suite import Raises

    for item in prepare(EXERCISES, 0):
        for case, expected in zip(item.cases, item.expected):
            assert (case.category == "bad input") == isinstance(expected, Raises), (item.exercise.id, case)
            assert not isinstance(expected, np.ndarray) or np.isfinite(expected).all()

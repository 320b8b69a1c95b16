"""Feedback a student can act on: the rejected input and the rule it breaks, named parameters, hints by failure."""

import numpy as np
import pytest

from cagd_course.grading.engine import grade_statements, prepare
from cagd_course.grading.extract import extract_source
from cagd_course.grading.report import check_text, failure_hint, feedback_html, gradescope_results
from cagd_course.grading.runner import Limits
from cagd_course.grading.suite import Case, Exercise, close
from cagd_ref import geometry

FAST = Limits(exercise_seconds=3, submission_seconds=20)
ZERO_Q = "q must not be the zero vector"
SAME_LENGTH = "p and q must have the same length"
ALGORITHM_HINT = "The result is a vector along q, scaled by (p·q)/(q·q)."


def _cases(rng):
    return [
        Case("worked example", ((3.0, 1.0, 2.0), (1.0, 1.0, 0.0)), visible=True),
        Case("zero q", ((1.0, 2.0, 3.0), (0.0, 0.0, 0.0)), visible=True, rule=ZERO_Q),
        Case("lengths", ((1.0, 2.0), (1.0, 2.0, 3.0))),
    ]


EXERCISE = Exercise(
    "01.projection",
    geometry.projection,
    _cases,
    compare=close(1e-9, 1e-9),
    hint=ALGORITHM_HINT,
    rules={"lengths": SAME_LENGTH},
)
CORRECT = """
import numpy as np

def projection(p, q):
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    if p.shape != q.shape:
        raise ValueError("p, q: expected vectors of the same length")
    if not q.any():
        raise ValueError("q: expected a nonzero vector")
    return p @ q / (q @ q) * q
"""
ZERO_CHECK = '    if not q.any():\n        raise ValueError("q: expected a nonzero vector")\n'
LENGTH_CHECK = '        raise ValueError("p, q: expected vectors of the same length")\n'


def _result(source: str):
    statements = extract_source([source]).statements
    outcome = grade_statements(statements, prepare({EXERCISE.id: (EXERCISE, 3.0)}, 0), FAST)
    return outcome.exercises[0]


def _failing(result, category):
    return next(c for c in result.cases if c.category == category)


def test_a_correct_solution_passes_every_group():
    assert _result(CORRECT).score == 3.0


def test_an_accepted_bad_input_shows_the_call_the_rule_and_a_validation_hint():
    result = _result(CORRECT.replace(ZERO_CHECK, ""))
    failing = _failing(result, "zero q")
    assert failing.kind == "accepted_bad_input"
    text = check_text(result)
    # The input the function should have rejected, the reference's reason, what came back, the statement's rule.
    assert "call:     projection((1.0, 2.0, 3.0), (0.0, 0.0, 0.0))" in text
    assert "expected: a ValueError or TypeError (the reference raises ValueError: 'q:" in text
    assert "received: array([nan, nan, nan])" in text
    assert f"rule:     {ZERO_Q}" in text
    hint = failure_hint(result, failing)
    assert "check the inputs" in hint and ZERO_Q in hint and ALGORITHM_HINT not in hint


def test_a_hidden_bad_input_shows_its_rule_but_not_its_input():
    # Truncating to the shorter vector instead of rejecting the pair.
    trimmed = "        n = min(p.size, q.size)\n        p, q = p[:n], q[:n]\n"
    result = _result(CORRECT.replace(LENGTH_CHECK, trimmed))
    failing = _failing(result, "lengths")
    assert not failing.passed and not failing.visible
    html = feedback_html("ann", [result], result.score, result.points, [])
    assert SAME_LENGTH in html and "call:" not in html
    assert "raise a ValueError" in html  # the hint speaks of validation


def test_a_crash_on_bad_input_is_told_apart_from_a_missing_check():
    result = _result(CORRECT.replace(ZERO_CHECK, "    if not q.any():\n        1 / 0\n"))
    failing = _failing(result, "zero q")
    assert failing.kind == "wrong_error" and "ZeroDivisionError" in failure_hint(result, failing)


def test_a_wrong_shape_gets_a_shape_hint_not_the_algorithm():
    result = _result(CORRECT.replace("return p @ q / (q @ q) * q", "return (p @ q / (q @ q) * q)[None, :]"))
    failing = _failing(result, "worked example")
    assert failing.kind == "shape" and "expected shape (3,)" in failing.message
    hint = failure_hint(result, failing)
    assert "shape" in hint and ALGORITHM_HINT not in hint


def test_a_near_miss_quotes_the_tolerance():
    # A relative error of 1e-7, as from a rounded constant: far beyond 1e-9, far below a wrong formula.
    result = _result(CORRECT.replace("return p @ q / (q @ q) * q", "return p @ q / (q @ q) * q * (1 + 1e-7)"))
    failing = _failing(result, "worked example")
    assert failing.kind == "tolerance" and "outside the tolerance" in failing.message
    assert "rtol 1e-09, atol 1e-09" in failure_hint(result, failing)


def test_a_wrong_value_gets_the_exercises_own_hint():
    result = _result(CORRECT.replace("p @ q / (q @ q) * q", "p @ q / np.sqrt(q @ q) * q"))
    failing = _failing(result, "worked example")
    assert failing.kind == "value" and failure_hint(result, failing) == ALGORITHM_HINT
    assert f"Hint: {ALGORITHM_HINT}" in check_text(result)
    output = next(t for t in gradescope_results([result], result.score, [])["tests"])["output"]
    assert f"Hint: {ALGORITHM_HINT}" in output


def test_a_missing_function_is_named():
    result = _result("def projektion(p, q):\n    return q")
    failing = result.cases[0]
    assert failing.kind == "missing" and "named projection" in failure_hint(result, failing)


def test_a_refused_operation_explains_the_confinement():
    result = _result("import os\ndef projection(p, q):\n    os.fork()\n    return q")
    failing = result.cases[0]
    assert failing.kind == "raised" and "PermissionError" in failing.message
    assert "runs confined" in failure_hint(result, failing)


def test_a_case_rule_overrides_the_category_rule():
    exercise = Exercise("01.projection", geometry.projection, _cases, rules={"zero q": "category rule"})
    cases = _cases(np.random.default_rng(0))
    assert exercise.rule_for(cases[1]) == ZERO_Q and exercise.rule_for(cases[2]) == ""
    assert exercise.rule_for(Case("zero q", ())) == "category rule"


@pytest.mark.parametrize(
    "expected, received, kind",
    [
        (np.ones(2), np.array([1.0, 1.0 + 1e-8]), "tolerance"),
        (np.ones(2), np.array([1.0, 1.5]), "value"),
        (np.array([np.inf, 1.0]), np.array([np.inf, 2.0]), "value"),
        (np.ones(2), None, "type"),
    ],
)
def test_comparisons_classify_what_went_wrong(expected, received, kind):
    assert close()(expected, received).kind == kind


def test_the_worst_entry_is_one_that_fails():
    # An infinity matching an infinity is not the entry to report.
    message = close()(np.array([np.inf, 1.0]), np.array([np.inf, 2.0]))
    assert "(entry (1,))" in message and "expected 1.0, got 2.0" in message

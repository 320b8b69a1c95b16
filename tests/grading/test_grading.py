"""The grading engine: extraction, the isolated worker, comparisons, scoring and the self-check."""

import json
import math
import sys

import numpy as np
import pytest

from cagd_course.grading.engine import CaseResult, grade_statements, prepare, score, submission_seed
from cagd_course.grading.extract import SubmissionError, extract_notebook, extract_source
from cagd_course.grading.report import check_text, failure_hint
from cagd_course.grading.runner import Limits
from cagd_course.grading.suite import Case, Exercise, Raises, close, exact
from cagd_course.grading.worker import Unsupported, decode, encode
from cagd_ref import bezier

FAST = Limits(exercise_seconds=3, submission_seconds=20, memory_mb=1024)


def _casteljau_cases(rng):
    points = rng.normal(size=(4, 2))
    return [
        Case("notes example", ([[0, 0], [1, 2], [3, 2]], 0.3), visible=True),
        Case("array t", (points, np.linspace(0, 1, 5))),
        Case("bad input", ([1.0, 2.0, 3.0], 0.5)),
    ]


EXERCISES = {
    "02.de_casteljau": (Exercise("02.de_casteljau", bezier.de_casteljau, _casteljau_cases, hint="interpolate"), 3.0),
    "02.elevate": (
        Exercise(
            "02.elevate", bezier.elevate, lambda rng: [Case("cubic", (np.array([[0.0, 0], [1, 2], [3, 2], [4, 0]]),))]
        ),
        2.0,
    ),
}

GOOD = """
import numpy as np

def de_casteljau(points, t):
    p = np.array(points, dtype=float)
    if p.ndim != 2:
        raise ValueError("points must be (n+1, d)")
    ts = np.atleast_1d(np.asarray(t, dtype=float))[:, None, None]
    level = np.broadcast_to(p, (ts.shape[0],) + p.shape)
    while level.shape[1] > 1:
        level = (1 - ts) * level[:, :-1] + ts * level[:, 1:]
    return level[0, 0] if np.ndim(t) == 0 else level[:, 0]

def elevate(points):
    p = np.array(points, dtype=float)
    n = len(p) - 1
    a = (np.arange(n + 2) / (n + 1))[:, None]
    return a * np.vstack([p[:1], p]) + (1 - a) * np.vstack([p, p[-1:]])
"""


def _grade(source, exercises=EXERCISES, seed=1, limits=FAST):
    return grade_statements(extract_source([source]).statements, prepare(exercises, seed), limits)


def test_extraction_keeps_top_level_defs_and_imports_wherever_they_stand():
    cells = [
        "print('hi')\nx = 3",
        "%matplotlib inline\nimport numpy as np\ndef f(a):\n    return a\nf(2)",
        "def broken(:\n    pass",
        "from cagd_ref.bezier import de_casteljau\n@staticmethod\ndef g():\n    pass",
        "def f(a):\n    return 2 * a",
    ]
    submission = extract_source(cells)
    sources = [s["source"] for s in submission.statements]
    assert sources == [
        "import numpy as np",
        "def f(a):\n    return a",
        "@staticmethod\ndef g():\n    pass",
        "def f(a):\n    return 2 * a",
    ]
    assert len(submission.skipped) == 2
    assert "does not parse" in submission.skipped[0] and "cagd_ref" in submission.skipped[1]


def test_the_notebooks_own_course_imports_are_dropped_without_a_note():
    cells = [
        "from cagd_course import check\nfrom cagd_course.examples import notes_example",
        "from cagd_course.plotting import plot_bezier\nimport cagd_course.widgets",
        "def f(a):\n    return a",
    ]
    submission = extract_source(cells)
    assert [s["source"] for s in submission.statements] == ["def f(a):\n    return a"]
    # Only the imports a student added get a note: they will not be there when the function is graded.
    assert len(submission.skipped) == 2 and all("cagd_course" in note for note in submission.skipped)


@pytest.mark.parametrize(
    "content, status",
    [
        (b"{not json", "invalid notebook (not valid JSON)"),
        (b'{"cells": 3}', "invalid notebook (no list of cells)"),
        (json.dumps({"cells": [{"cell_type": "markdown", "source": "hi"}]}).encode(), "no code"),
        (json.dumps({"cells": [{"cell_type": "code", "source": ["x = 1\n", "print(x)"]}]}).encode(), "nothing defined"),
    ],
)
def test_unreadable_notebooks_are_reported_with_a_plain_status(tmp_path, content, status):
    path = tmp_path / "sub.ipynb"
    path.write_bytes(content)
    with pytest.raises(SubmissionError) as info:
        extract_notebook(path)
    assert info.value.status == status


def test_codec_round_trips_arrays_tuples_and_special_floats():
    value = (
        np.arange(6.0).reshape(2, 3),
        [1, "a", None, float("nan")],
        {"k": np.float64(2.5)},
        np.array([True, False]),
    )
    back = decode(json.loads(json.dumps(encode(value))))
    assert isinstance(back, tuple) and np.array_equal(back[0], value[0]) and back[0].shape == (2, 3)
    assert back[1][:3] == [1, "a", None] and np.isnan(back[1][3])
    assert back[2] == {"k": 2.5} and back[3].dtype == bool
    assert isinstance(decode(encode(object())), Unsupported)


def test_a_correct_submission_gets_full_marks():
    outcome = _grade(GOOD)
    assert outcome.score == outcome.max_score == 5.0
    assert all(r.passed for r in outcome.exercises)


def test_the_reference_itself_passes_in_a_trusted_worker():
    statements = [{"source": "from cagd_ref.bezier import de_casteljau, elevate", "where": "reference"}]
    outcome = grade_statements(statements, prepare(EXERCISES, 0), FAST, allow_reference=True)
    assert outcome.score == 5.0


@pytest.mark.parametrize(
    "source",
    [
        "from cagd_ref.bezier import de_casteljau",
        "import importlib\n"
        "def de_casteljau(p, t):\n    return importlib.import_module('cagd_ref.bezier').de_casteljau(p, t)",
        "def de_casteljau(p, t):\n    return __import__('cagd_ref.bezier', fromlist=['x']).de_casteljau(p, t)",
        # The grader's own package is as far out of reach: it could read the suites or call the reference.
        "import importlib\n"
        "def de_casteljau(p, t):\n"
        "    engine = importlib.import_module('cagd_course.grading.engine')\n"
        "    return engine.load_exercises()['02.de_casteljau'][0].reference(p, t)",
    ],
)
def test_the_reference_cannot_be_imported_by_graded_code(source):
    outcome = _grade(source, {"02.de_casteljau": EXERCISES["02.de_casteljau"]})
    assert outcome.score == 0


def test_a_stub_scores_zero_and_the_check_says_to_write_it():
    outcome = _grade("def de_casteljau(points, t):\n    raise NotImplementedError('write me')")
    assert outcome.score == 0
    text = check_text(outcome.exercises[0])
    assert "Not written yet" in text and "0 / 3 points" in text


def test_wrong_values_show_the_first_failing_visible_case():
    source = GOOD.replace(
        "(1 - ts) * level[:, :-1] + ts * level[:, 1:]", "ts * level[:, :-1] + (1 - ts) * level[:, 1:]"
    )
    result = _grade(source).exercises[0]
    text = check_text(result)
    assert "[FAIL] notes example" in text and "expected:" in text and "received:" in text
    assert 0 < result.score < 3


def test_an_endless_loop_is_stopped_and_the_next_exercise_still_runs():
    source = GOOD.replace(
        "def de_casteljau(points, t):\n", "def de_casteljau(points, t):\n    while True:\n        pass\n", 1
    )
    outcome = _grade(source)
    first, second = outcome.exercises
    assert first.score == 0 and first.stopped.startswith("timed out")
    assert second.score == second.points


def test_a_hard_exit_costs_only_the_exercise_it_happens_in():
    source = GOOD.replace(
        "    p = np.array(points, dtype=float)\n    n = len(p) - 1", "    import os\n    os._exit(7)", 1
    )
    outcome = _grade(source)
    first, second = outcome.exercises
    assert first.score == 3 and second.score == 0
    assert second.stopped == "the process exited with code 7 before finishing"


def test_modifying_an_input_in_place_fails_the_case():
    source = GOOD.replace(
        "    p = np.array(points, dtype=float)\n    n = len(p) - 1",
        "    p = np.array(points, dtype=float)\n    points[1, 1] = 99\n    n = len(p) - 1",
        1,
    )
    result = _grade(source).exercises[1]
    # Named as the statement names it (the reference's parameter), not by its position.
    assert result.score == 0 and "changed its argument `points` in place" in result.cases[0].message
    assert result.cases[0].kind == "mutation" and "copy" in failure_hint(result, result.cases[0])


def test_a_comparison_that_cannot_read_an_answer_fails_the_case_not_the_run():
    def fragile(expected, received):
        return None if received == [1.0] else f"got {tuple(received)}"  # breaks on a number

    exercises = {
        "02.bernstein": (
            Exercise("02.bernstein", lambda: [1.0], lambda rng: [Case("one", ())], compare=fragile),
            1.0,
        )
    }
    result = _grade("def bernstein():\n    return 2.0\n", exercises).exercises[0]
    assert result.score == 0 and "could not be compared" in result.cases[0].message


def test_bad_input_cases_demand_a_value_or_type_error():
    compare = close()
    assert compare(Raises("ValueError", "x"), Raises("TypeError", "y")) is None
    assert "NotImplementedError" in compare(Raises("ValueError", "x"), Raises("NotImplementedError", ""))
    assert "returned" in compare(Raises("ValueError", "x"), np.zeros(2))


@pytest.mark.parametrize(
    "expected, received, fragment",
    [
        (np.zeros((2, 3)), np.zeros((3, 2)), "expected shape (2, 3)"),
        (np.ones(3), [1.0, 1.0, float("nan")], "NaN"),
        (np.ones(3), None, "got NoneType"),
        ((np.ones(2), np.ones(2)), np.ones(2), "tuple of 2"),
        (np.ones(2), np.array([1.0, 1.5]), "expected 1.0, got 1.5"),
    ],
)
def test_comparison_messages_say_what_is_wrong(expected, received, fragment):
    assert fragment in close()(expected, received)


def test_lists_are_accepted_where_arrays_are_expected_and_strings_compare_exactly():
    assert close()(np.array([[1.0, 2.0]]), [[1.0, 2.0]]) is None
    assert exact()("ellipse", "ellipse") is None and exact()("ellipse", "Ellipse")


def test_score_is_the_mean_over_categories_of_the_fraction_passed():
    cases = [CaseResult("a", False, True), CaseResult("a", False, False), CaseResult("b", False, True)]
    assert score(cases, 4.0) == pytest.approx(4.0 * (0.5 + 1.0) / 2)


def test_seeds_depend_on_the_run_seed_and_the_submission_name_only():
    assert submission_seed(0, "ann") == submission_seed(0, "ann")
    assert len({submission_seed(0, "ann"), submission_seed(1, "ann"), submission_seed(0, "bob")}) == 3


def test_the_worker_reports_its_confinement():
    outcome = _grade(GOOD)
    assert "landlock ABI" in outcome.run.sandbox, outcome.run.sandbox
    assert outcome.run.confined and outcome.run.gaps == []


def test_the_worker_path_keeps_the_environment_and_drops_checkouts(tmp_path, monkeypatch):
    from cagd_course.grading import runner

    environment = tmp_path / "venv"
    site = environment / "lib" / "site-packages"
    checkout = tmp_path / "checkout"
    other = tmp_path / "other"
    for folder in (site / "cagd_ref", site / "numpy", checkout / "cagd_ref", checkout / "tests", other):
        folder.mkdir(parents=True)
    (checkout / "book.toml").write_text("", encoding="utf-8")
    monkeypatch.setattr(sys, "prefix", str(environment))
    monkeypatch.setattr(sys, "path", [str(site), str(checkout), str(checkout / "tests"), str(other)])
    monkeypatch.setattr(runner, "_package_home", lambda name: site)
    monkeypatch.setenv("CAGD_COURSE", str(checkout))
    # A normal install lives in the environment (the worker refuses its imports by name); the checkout goes.
    assert runner._allowed_path(allow_reference=False) == [str(site), str(other)]


def test_numpy_scalars_travel_like_floats_nan_included():
    for value in (np.float64(1.5), np.float64("nan"), np.float64("-inf"), np.float32(0.25)):
        back = decode(json.loads(json.dumps(encode(value))))
        assert isinstance(back, float)
        assert back == float(value) or (math.isnan(back) and math.isnan(value))


def test_a_dataclass_in_a_submission_is_built_with_its_annotations():
    source = (
        "from dataclasses import dataclass\n"
        "@dataclass(frozen=True)\n"
        "class Pair:\n    a: float\n    b: float\n"
        "def de_casteljau(points, t):\n"
        "    import numpy as np\n"
        "    levels = np.asarray(points, float)\n"
        "    ts = np.atleast_1d(np.asarray(t, float))[:, None, None]\n"
        "    P = np.broadcast_to(levels, (len(ts),) + levels.shape).copy()\n"
        "    while P.shape[1] > 1:\n"
        "        P = (1 - ts) * P[:, :-1] + ts * P[:, 1:]\n"
        "    Pair(1.0, 2.0)\n"
        "    return P[0, 0] if np.ndim(t) == 0 else P[:, 0]\n"
    )
    outcome = _grade(source, {"02.de_casteljau": EXERCISES["02.de_casteljau"]})
    assert not outcome.run.load_problems
    assert outcome.score > 0

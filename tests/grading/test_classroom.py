"""`cagd grade` on a small class: gradebook rows, feedback, results.json, resuming and stability."""

import csv
import json
import shutil
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits

ROOT = Path(__file__).resolve().parents[2]
SUBMISSIONS = Path(__file__).parent / "fixtures" / "submissions"
LIMITS = Limits(exercise_seconds=5, submission_seconds=60)


@pytest.fixture(scope="module")
def class_folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("class")
    shutil.copy(SUBMISSIONS / "complete.ipynb", folder / "ada.ipynb")
    shutil.copy(ROOT / "exercises" / "02-bezier-curves.ipynb", folder / "bob.ipynb")
    text = (SUBMISSIONS / "complete.ipynb").read_text()
    (folder / "cy.ipynb").write_text(
        text.replace("(1 - t) * levels[-1][:-1] + t * levels[-1][1:]", "t * levels[-1][:-1] + (1 - t) * levels[-1][1:]")
    )
    (folder / "dee.ipynb").write_text("{ this is not json")
    return folder


@pytest.fixture(scope="module")
def graded(class_folder, tmp_path_factory):
    out = tmp_path_factory.mktemp("graded")
    grade_class([class_folder], out, jobs=2, limits=LIMITS, seed=5, progress=False, chapters=[2])
    return out


def _rows(out):
    with (out / "gradebook.csv").open() as handle:
        return list(csv.DictReader(handle))


def test_every_submission_gets_one_row(graded):
    rows = {r["submission"]: r for r in _rows(graded)}
    assert sorted(rows) == ["ada", "bob", "cy", "dee"]
    assert rows["ada"]["score"] == rows["ada"]["max_score"] == "21" and rows["ada"]["status"] == "ok"
    assert rows["bob"]["score"] == "0" and rows["bob"]["status"] == "ok"
    assert 0 < float(rows["cy"]["score"]) < 21 and float(rows["cy"]["02.subdivide"]) < 3
    assert rows["dee"]["score"] == "0" and rows["dee"]["status"] == "invalid notebook (not valid JSON)"


def test_header_lists_the_exercises_of_the_graded_chapter_the_seed_and_the_confinement(graded):
    header = (graded / "gradebook.csv").read_text().splitlines()[0].split(",")
    assert header[:4] == ["submission", "score", "max_score", "status"] and header[-2:] == ["seed", "confinement"]
    assert all(h.startswith("02.") for h in header[4:-2]) and len(header) == 16
    rows = {r["submission"]: r for r in _rows(graded)}
    assert "landlock ABI" in rows["ada"]["confinement"] and rows["dee"]["confinement"] == ""


def test_feedback_and_gradescope_results_are_written(graded):
    results = json.loads((graded / "cy" / "results.json").read_text())
    assert {"score", "tests"} <= results.keys()
    assert all({"name", "score", "max_score", "output", "visibility"} <= t.keys() for t in results["tests"])
    subdivide = next(t for t in results["tests"] if t["name"] == "02.subdivide")
    assert subdivide["score"] < subdivide["max_score"] and "expected" in subdivide["output"]
    page = (graded / "cy" / "feedback.html").read_text()
    assert "02.subdivide" in page and "Hint:" in page
    assert "not valid JSON" in (graded / "dee" / "feedback.html").read_text()


def test_regrading_with_the_same_seed_gives_identical_gradebooks(class_folder, graded, tmp_path):
    grade_class([class_folder], tmp_path, jobs=1, limits=LIMITS, seed=5, progress=False, chapters=[2])
    assert (tmp_path / "gradebook.csv").read_bytes() == (graded / "gradebook.csv").read_bytes()


def test_an_interrupted_run_resumes_and_force_regrades(class_folder, tmp_path):
    out = tmp_path / "out"
    first = grade_class([class_folder / "ada.ipynb"], out, limits=LIMITS, progress=False, chapters=[1])
    again = grade_class([class_folder], out, limits=LIMITS, progress=False, chapters=[1])
    assert (first.graded, again.graded, again.skipped) == (1, 3, 1)
    forced = grade_class([class_folder], out, limits=LIMITS, progress=False, chapters=[1], force=True)
    assert forced.graded == 4 and len(_rows(out)) == 4


def test_command_line_grading_prints_a_summary_with_the_confinement(class_folder, tmp_path, capsys):
    assert main(["grade", str(class_folder / "ada.ipynb"), "--out", str(tmp_path), "--chapter", "1"]) == 0
    out = capsys.readouterr().out
    assert "graded 1 submission" in out and "mean score 10.00 / 10" in out
    assert "\nconfinement: " in out and "WARNING" not in out


def test_duplicate_submission_names_are_refused(class_folder, tmp_path):
    other = tmp_path / "other"
    other.mkdir()
    shutil.copy(class_folder / "ada.ipynb", other / "ada.ipynb")
    with pytest.raises(ValueError, match="two submissions are named 'ada'"):
        grade_class([class_folder, other], tmp_path / "out", progress=False)

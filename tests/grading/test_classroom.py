"""`cagd grade` over a semester: both layouts, each notebook on its own chapter, one gradebook that grows.

A small class hands in one notebook per chapter, in nbgrader's folder-per-student layout and as a Canvas
bulk download; the tests grade it as an instructor would, in several runs, and read the gradebook, the
per-student feedback and the summary.
"""

import csv
import importlib.util
import json
import shutil
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits

HERE = Path(__file__).parent
spec = importlib.util.spec_from_file_location("semester", HERE / "fixtures" / "semester.py")
semester = importlib.util.module_from_spec(spec)
spec.loader.exec_module(semester)

LIMITS = Limits(exercise_seconds=5, submission_seconds=60)
SUBDIVIDE_RIGHT = "(1 - t) * levels[-1][:-1] + t * levels[-1][1:]"
SUBDIVIDE_WRONG = "t * levels[-1][:-1] + (1 - t) * levels[-1][1:]"


def _rows(out):
    with (out / "gradebook.csv").open() as handle:
        return {row["submission"]: row for row in csv.DictReader(handle)}


@pytest.fixture(scope="module")
def nbgrader(tmp_path_factory):
    """SUBMISSIONS/<student>/<NN-slug>.ipynb: ada solves 1 and 2, bob 1 (stamped, any name) and hands in the stub of 2,
    cy a wrong subdivision, dee hands in one notebook holding two chapters and one that is not JSON."""
    root = tmp_path_factory.mktemp("nbgrader")
    semester.write(root / "ada" / "01-introduction.ipynb", semester.chapter_notebook(1))
    semester.write(root / "ada" / "02-bezier-curves.ipynb", semester.chapter_notebook(2))
    semester.write(root / "ada" / ".ipynb_checkpoints" / "02-bezier-curves-checkpoint.ipynb", "{")
    semester.write(root / "bob" / "my homework.ipynb", semester.chapter_notebook(1, stamped=True))
    semester.write(root / "bob" / "02-bezier-curves.ipynb", semester.stub_notebook(2))
    semester.write(root / "cy" / "ch2" / "submission.ipynb",
                   semester.broken(semester.chapter_notebook(2), SUBDIVIDE_RIGHT, SUBDIVIDE_WRONG))
    semester.write(root / "dee" / "everything.ipynb", semester.COMPLETE)
    semester.write(root / "dee" / "01-introduction.ipynb", "{ this is not json")
    return root


@pytest.fixture(scope="module")
def graded(nbgrader, tmp_path_factory):
    out = tmp_path_factory.mktemp("grades")
    summary = grade_class([nbgrader], out, jobs=2, limits=LIMITS, seed=5, progress=False)
    return out, summary


def test_each_notebook_is_graded_on_its_own_chapter_only(graded):
    out, summary = graded
    rows = _rows(out)
    assert sorted(rows) == ["ada", "bob", "cy", "dee"]
    ada, bob, cy = rows["ada"], rows["bob"], rows["cy"]
    assert (ada["ch01 total"], ada["ch01 max"], ada["ch02 total"], ada["ch02 max"]) == ("10", "10", "21", "21")
    assert (ada["score"], ada["max_score"], ada["status"]) == ("31", "31", "ok")
    assert (bob["ch01 total"], bob["ch02 total"], bob["ch02 status"]) == ("10", "0", "ok")
    assert cy["ch01 total"] == "" and cy["01.projection"] == ""  # handed in nothing for chapter 1: blank, not 0
    assert 0 < float(cy["ch02 total"]) < 21 and float(cy["02.subdivide"]) < 3
    assert summary.graded == 6 and summary.by_chapter[1][0] == 3 and summary.by_chapter[2][0] == 3


def test_an_unreadable_notebook_of_a_known_chapter_gets_its_row_and_an_ambiguous_one_is_reported(graded):
    out, summary = graded
    dee = _rows(out)["dee"]
    assert (dee["ch01 total"], dee["ch01 status"]) == ("0", "invalid notebook (not valid JSON)")
    assert dee["ch02 total"] == ""
    reported = {Path(u["file"]).name: u["reason"] for u in summary.unassigned}
    assert list(reported) == ["everything.ipynb"] and "several chapters (1, 2)" in reported["everything.ipynb"]
    with (out / "unassigned.csv").open() as handle:
        assert [Path(r["file"]).name for r in csv.DictReader(handle)] == ["everything.ipynb"]
    assert "not graded: 1 notebook(s)" in str(summary) and "everything.ipynb" in str(summary)


def test_the_header_has_a_total_per_chapter_and_a_column_per_exercise_graded(graded):
    out, _ = graded
    header = (out / "gradebook.csv").read_text().splitlines()[0].split(",")
    assert header[:6] == ["submission", "score", "max_score", "status", "student", "id"]
    assert header[-1] == "confinement"
    assert header[6:11] == ["ch01 total", "ch01 max", "ch01 status", "ch01 late", "ch01 seed"]
    assert header[11:16] == ["01.projection", "01.triangle_area", "01.rotate_about_axis", "01.rotation_matrix",
                             "01.conic_type"]
    assert header[16] == "ch02 total" and sum(h.startswith("02.") for h in header) == 10
    assert not any(h.startswith("03.") for h in header)  # no chapter 3 graded yet: no columns for it
    assert "landlock ABI" in _rows(out)["ada"]["confinement"]


def test_feedback_and_results_are_written_per_student_and_chapter_and_for_the_semester(graded):
    out, _ = graded
    results = json.loads((out / "cy" / "ch02" / "results.json").read_text())
    subdivide = next(t for t in results["tests"] if t["name"] == "02.subdivide")
    assert subdivide["score"] < subdivide["max_score"] and "expected" in subdivide["output"]
    assert "Hint:" in (out / "cy" / "ch02" / "feedback.html").read_text()
    semester_results = json.loads((out / "ada" / "results.json").read_text())
    assert semester_results["score"] == 31 and len(semester_results["tests"]) == 15
    page = (out / "ada" / "feedback.html").read_text()
    assert "chapter 1</a>: 10 / 10" in page and "chapter 2</a>: 21 / 21" in page and "02.subdivide" in page
    assert "not valid JSON" in (out / "dee" / "feedback.html").read_text()
    record = json.loads((out / "bob" / "ch01" / "record.json").read_text())
    assert (record["chapter"], record["how"]) == (1, "metadata")


def test_regrading_with_the_same_seed_gives_identical_gradebooks(nbgrader, graded, tmp_path):
    out, _ = graded
    grade_class([nbgrader], tmp_path, jobs=1, limits=LIMITS, seed=5, progress=False, report=False)
    assert (tmp_path / "gradebook.csv").read_bytes() == (out / "gradebook.csv").read_bytes()


def test_a_later_chapter_adds_its_columns_and_keeps_the_others(nbgrader, tmp_path):
    out = tmp_path / "grades"
    first = grade_class([nbgrader], out, limits=LIMITS, seed=5, progress=False, chapters=[1], report=False)
    assert first.other_chapters == 3 and (first.graded, first.failed_to_run) == (3, 1)  # dee's is not JSON
    assert "left out 3 notebook(s) of other chapters" in str(first)
    # dee handed in a notebook of chapter 1: --chapter 1 does not make the unclear one a second.
    assert [Path(u["file"]).name for u in first.unassigned] == ["everything.ipynb"]
    before = _rows(out)
    assert not any(k.startswith("02.") for k in before["ada"])
    second = grade_class([nbgrader], out, limits=LIMITS, seed=5, progress=False, chapters=[2], report=False)
    assert second.graded == 4 and second.skipped == 0 and not second.unassigned  # dee's unclear one is chapter 2
    after = _rows(out)
    for name, row in before.items():
        assert {k: after[name][k] for k in row if k.startswith(("01.", "ch01"))} == \
            {k: v for k, v in row.items() if k.startswith(("01.", "ch01"))}
    assert after["ada"]["ch02 total"] == "21" and after["ada"]["score"] == "31"
    third = grade_class([nbgrader], out, limits=LIMITS, seed=5, progress=False, report=False)
    assert (third.graded, third.skipped) == (0, 6)


def test_regrading_one_students_chapter_changes_only_those_cells(nbgrader, graded, tmp_path):
    out = tmp_path / "grades"
    shutil.copytree(graded[0], out)
    before = (out / "gradebook.csv").read_text().splitlines()
    regraded = grade_class([nbgrader], out, limits=LIMITS, seed=6, progress=False, chapters=[2], students=["cy"],
                           force=True)
    assert regraded.graded == 1
    after = (out / "gradebook.csv").read_text().splitlines()
    header = before[0].split(",")
    changed = {
        (row_after.split(",")[0], header[i])
        for row_before, row_after in zip(before, after)
        for i, (a, b) in enumerate(zip(next(csv.reader([row_before])), next(csv.reader([row_after]))))
        if a != b
    }
    assert changed and {name for name, _ in changed} == {"cy"}
    assert {column for _, column in changed} <= {"score", "ch02 total", "ch02 seed"} | {h for h in header
                                                                                          if h.startswith("02.")}


def test_an_interrupted_run_resumes_and_force_regrades(nbgrader, tmp_path):
    out = tmp_path / "out"
    first = grade_class([nbgrader / "ada"], out, limits=LIMITS, progress=False, report=False)
    (out / "gradebook.csv").unlink()  # as if the run stopped after writing a record
    again = grade_class([nbgrader], out, limits=LIMITS, progress=False, report=False)
    assert (first.graded, again.graded, again.skipped) == (2, 4, 2)
    assert len(_rows(out)) == 4
    forced = grade_class([nbgrader], out, limits=LIMITS, progress=False, force=True, report=False)
    assert forced.graded == 6 and len(_rows(out)) == 4


def test_a_changed_notebook_is_graded_again_without_force(nbgrader, tmp_path):
    folder = tmp_path / "class"
    shutil.copytree(nbgrader / "cy", folder / "cy")
    out = tmp_path / "out"
    grade_class([folder], out, limits=LIMITS, progress=False, report=False)
    semester.write(folder / "cy" / "ch2" / "submission.ipynb", semester.chapter_notebook(2))
    again = grade_class([folder], out, limits=LIMITS, progress=False, report=False)
    assert again.graded == 1 and _rows(out)["cy"]["ch02 total"] == "21"


@pytest.fixture(scope="module")
def canvas(tmp_path_factory):
    """A Canvas bulk download: <name>_<userid>_<submissionid>_<original>, LATE after the name when late."""
    root = tmp_path_factory.mktemp("canvas")
    semester.write(root / "doejane_1234_99001_01-introduction.ipynb", semester.chapter_notebook(1))
    semester.write(root / "roefred_LATE_4321_99002_01-introduction-1.ipynb", semester.chapter_notebook(1))
    semester.write(root / "roefred_4321_99003_homework.ipynb", semester.chapter_notebook(2, stamped=True))
    semester.write(root / "zed.ipynb", semester.chapter_notebook(1, stamped=True))
    return root


def test_a_canvas_download_is_graded_with_ids_and_late_markers(canvas, tmp_path):
    out = tmp_path / "grades"
    summary = grade_class([canvas], out, limits=LIMITS, progress=False, report=False)
    assert summary.graded == 4 and not summary.unassigned
    rows = _rows(out)
    assert sorted(rows) == ["doejane_1234", "roefred_4321", "zed"]
    jane, fred, zed = rows["doejane_1234"], rows["roefred_4321"], rows["zed"]
    assert (jane["student"], jane["id"], jane["ch01 late"], jane["ch01 total"]) == ("doejane", "1234", "", "10")
    assert (fred["id"], fred["ch01 late"], fred["ch02 late"], fred["score"]) == ("4321", "LATE", "", "31")
    assert (zed["student"], zed["id"], zed["ch01 total"]) == ("zed", "", "10")


def test_two_notebooks_of_one_student_for_one_chapter_are_reported_not_guessed(tmp_path):
    folder = tmp_path / "class"
    semester.write(folder / "ada" / "01-introduction.ipynb", semester.chapter_notebook(1))
    semester.write(folder / "ada" / "01-introduction (1).ipynb", semester.stub_notebook(1))
    summary = grade_class([folder], tmp_path / "out", limits=LIMITS, progress=False, report=False)
    assert summary.graded == 0 and len(summary.unassigned) == 2
    assert all("2 notebooks of this student for chapter 1" in u["reason"] for u in summary.unassigned)


def test_a_single_chapter_option_decides_a_notebook_whose_chapter_is_unclear(tmp_path):
    folder = tmp_path / "class"
    semester.write(folder / "ann.ipynb", semester.COMPLETE)
    summary = grade_class([folder], tmp_path / "out", limits=LIMITS, progress=False, chapters=[1], report=False)
    row = _rows(tmp_path / "out")["ann"]
    assert summary.graded == 1 and (row["score"], row["max_score"], row["status"]) == ("10", "10", "ok")
    record = json.loads((tmp_path / "out" / "ann" / "ch01" / "record.json").read_text())
    assert record["how"] == "--chapter"


def test_command_line_grading_prints_a_summary_with_the_confinement(nbgrader, tmp_path, capsys):
    assert main(["grade", str(nbgrader / "ada"), "--out", str(tmp_path), "--chapter", "1"]) == 0
    out = capsys.readouterr().out
    assert "graded 1 submission" in out and "mean score 10.00 / 10" in out
    assert "\nconfinement: " in out and "WARNING" not in out and "report.html" in out
    assert (tmp_path / "report.html").is_file()


def test_grade_help_explains_the_layouts(capsys):
    with pytest.raises(SystemExit):
        main(["grade", "--help"])
    text = capsys.readouterr().out
    assert "nbgrader" in text and "Canvas" in text and "--student" in text and "metadata.cagd.chapter" in text

"""Whose notebook is it, and which chapter does it answer: the layouts, the chapter's sources, the stamp."""

import json
import shutil
from pathlib import Path

import nbformat
import pytest

from cagd_course.cli import main
from cagd_course.grading.layouts import CANVAS, chapter_candidates, find_submissions, stamp_exercise_notebooks
from cagd_course.manifest import load_course

COURSE = load_course()


def _notebook(path: Path, chapter=None, title="") -> Path:
    notebook = {"cells": [{"cell_type": "markdown", "id": "c0", "metadata": {}, "source": title}], "metadata": {},
                "nbformat": 4, "nbformat_minor": 5}
    if chapter is not None:
        notebook["metadata"]["cagd"] = {"chapter": chapter}
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(notebook))
    return path


def test_canvas_file_names_give_name_user_id_late_and_original_name():
    match = CANVAS.match("smithjohn_LATE_123456_7890123_03-polynomial-evaluation-1.ipynb")
    assert match.group("name", "late", "userid", "subid", "original") == (
        "smithjohn", "LATE", "123456", "7890123", "03-polynomial-evaluation-1.ipynb")
    assert CANVAS.match("smithjohn_123456_7890123_hw.ipynb").group("late") is None
    assert CANVAS.match("ada.ipynb") is None and CANVAS.match("02-bezier-curves.ipynb") is None


@pytest.mark.parametrize("name, chapters", [
    ("03-polynomial-evaluation.ipynb", {3}),
    ("03-polynomial-evaluation (1).ipynb", {3}),
    ("Copy of 03-polynomial-evaluation.ipynb", {3}),
    ("ch3.ipynb", {3}),
    ("chapter_12_work.ipynb", {12}),
    ("7-intersections.ipynb", {7}),
    ("homework.ipynb", set()),
    ("research3.ipynb", set()),
])
def test_file_names_point_to_chapters(name, chapters):
    assert chapter_candidates([name], COURSE) == chapters


def test_metadata_wins_then_the_file_name_then_the_title_and_unclear_ones_are_reported(tmp_path):
    root = tmp_path / "class"
    _notebook(root / "ann" / "02-bezier-curves.ipynb", chapter=3)  # metadata says 3: it is 3
    _notebook(root / "ann" / "work.ipynb", title="# Exercises: chapter 4, forward differencing")
    _notebook(root / "bo" / "ch02" / "submission.ipynb")  # nbgrader's <student>/<assignment>/ tree
    _notebook(root / "bo" / "notes.ipynb")
    _notebook(root / "bo" / "ch1-ch2.ipynb")
    _notebook(root / "cy" / "x.ipynb", chapter=99)
    (root / "cy" / ".ipynb_checkpoints").mkdir(parents=True)
    _notebook(root / "cy" / ".ipynb_checkpoints" / "x-checkpoint.ipynb", chapter=1)
    found = {(f.submission, f.path.name): f for f in find_submissions([root], COURSE)}
    assert len(found) == 6
    stamped = found["ann", "02-bezier-curves.ipynb"]
    assert (stamped.chapter, stamped.how) == (3, "metadata") and "metadata to 3" in stamped.notes[0]
    assert (found["ann", "work.ipynb"].chapter, found["ann", "work.ipynb"].how) == (4, "title cell")
    assert (found["bo", "submission.ipynb"].chapter, found["bo", "submission.ipynb"].how) == (2, "file name")
    assert found["bo", "notes.ipynb"].chapter is None and "names a chapter" in found["bo", "notes.ipynb"].problem
    assert found["bo", "ch1-ch2.ipynb"].chapter is None and "several chapters" in found["bo", "ch1-ch2.ipynb"].problem
    assert found["cy", "x.ipynb"].chapter is None and "99" in found["cy", "x.ipynb"].problem


def test_flat_files_belong_to_the_canvas_user_the_file_or_the_folder_of_a_course_named_notebook(tmp_path):
    _notebook(tmp_path / "doejane_77_88_01-introduction.ipynb")
    _notebook(tmp_path / "ann.ipynb", chapter=1)
    _notebook(tmp_path / "ada" / "02-bezier-curves.ipynb")
    found = find_submissions([tmp_path / "doejane_77_88_01-introduction.ipynb", tmp_path / "ann.ipynb",
                              tmp_path / "ada" / "02-bezier-curves.ipynb"], COURSE)
    assert [(f.submission, f.student, f.lms_id, f.chapter) for f in found] == [
        ("doejane_77", "doejane", "77", 1), ("ann", "ann", "", 1), ("ada", "ada", "", 2)]


def test_a_missing_path_is_a_clear_error(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file or folder"):
        find_submissions([tmp_path / "nowhere"], COURSE)


def test_stamping_writes_the_chapter_and_nothing_else(tmp_path):
    shutil.copy(COURSE.root / "book.toml", tmp_path / "book.toml")
    copies = {}
    for chapter in COURSE.chapters:
        if chapter.exercises is not None and chapter.exercises.is_file():
            target = tmp_path / chapter.exercises.relative_to(COURSE.root)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(chapter.exercises, target)
            copies[target] = chapter.number
    course = load_course(tmp_path)
    assert set(stamp_exercise_notebooks(course, check=True)) >= {p for p in copies
                                                                 if "cagd" not in json.loads(p.read_text())["metadata"]}
    stamp_exercise_notebooks(course)
    assert stamp_exercise_notebooks(course, check=True) == []
    for path, number in copies.items():
        stamped = nbformat.read(path, as_version=4)
        original = nbformat.read(COURSE.root / path.relative_to(tmp_path), as_version=4)
        assert stamped.metadata["cagd"]["chapter"] == number
        assert [c.source for c in stamped.cells] == [c.source for c in original.cells]
        assert path.read_text().endswith("}\n")
    assert stamp_exercise_notebooks(course) == []  # a second stamp changes nothing


def test_every_exercise_notebook_carries_its_chapter_in_its_metadata():
    # The course writes it with `cagd stamp`; the grader finds a notebook's chapter from it, whatever its name.
    assert stamp_exercise_notebooks(COURSE, check=True) == [], "run `cagd stamp`"


def test_the_stamp_command_checks_without_changing(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("CAGD_COURSE", "")  # whatever `cagd --course` sets is undone after the test
    (tmp_path / "book.toml").write_text('[book]\ntitle = "t"\n[[chapters]]\nnumber = 1\ntitle = "one"\n'
                                        'notebook = "chapters/01-a.ipynb"\nexercises = "exercises/01-a.ipynb"\n')
    _notebook(tmp_path / "exercises" / "01-a.ipynb")
    assert main(["--course", str(tmp_path), "stamp", "--check"]) == 1
    assert "lacks metadata.cagd.chapter: exercises/01-a.ipynb" in capsys.readouterr().out
    assert main(["--course", str(tmp_path), "stamp"]) == 0
    assert main(["--course", str(tmp_path), "stamp", "--check"]) == 0

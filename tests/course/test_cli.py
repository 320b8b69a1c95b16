"""The `cagd` command line: help, list, check and book."""

import subprocess
import sys
from pathlib import Path

import pytest

from cagd_course.cli import main
from cagd_course.manifest import load_course

ROOT = Path(__file__).resolve().parents[2]
SOLUTION = ROOT / "tests" / "grading" / "fixtures" / "submissions" / "complete.ipynb"


def test_help_lists_every_subcommand():
    result = subprocess.run(
        [sys.executable, "-m", "cagd_course.cli", "--help"], capture_output=True, text=True, check=True
    )
    for command in ("list", "check", "validate", "grade", "book"):
        assert command in result.stdout


def test_list_prints_chapters_and_exercise_ids(capsys):
    assert main(["list"]) == 0
    out = capsys.readouterr().out
    assert "02.de_casteljau" in out and "chapters/02-bezier-curves.ipynb" in out


def test_list_notebooks_gives_every_listed_notebook(capsys):
    assert main(["list", "--notebooks"]) == 0
    listed = capsys.readouterr().out.split()
    course = load_course()
    expected = [str(p.relative_to(course.root)) for c in course.chapters for p in (c.notebook, c.exercises) if p]
    assert listed == expected


def test_check_grades_a_notebook_on_the_exercises_it_defines(capsys):
    assert main(["check", str(SOLUTION), "--exercise", "01.projection", "--exercise", "02.elevate"]) == 0
    out = capsys.readouterr().out
    assert "01.projection: 1 / 1 points" in out and "02.elevate: 2 / 2 points" in out and "Total: 3 / 3" in out


def test_check_of_an_unreadable_notebook_says_why(tmp_path, capsys):
    broken = tmp_path / "broken.ipynb"
    broken.write_text("{")
    assert main(["check", str(broken)]) == 2
    assert "not valid JSON" in capsys.readouterr().err


def test_unknown_exercise_is_a_clear_error(capsys):
    assert main(["validate", "--exercise", "09.nothing"]) == 2
    assert "unknown exercise" in capsys.readouterr().err


@pytest.mark.parametrize("argv", [["grade", "--out", "x"], ["book", "--chapter", "one"]])
def test_bad_arguments_exit_with_usage(argv):
    with pytest.raises(SystemExit) as info:
        main(argv)
    assert info.value.code == 2


# The book (`cagd book`) is tested in test_book.py, on a course of its own, and in a browser in tests/browser/.


@pytest.fixture
def unnamed_course(monkeypatch):
    """No CAGD_COURSE during the test, and whatever `cagd --course` sets in it is undone afterwards."""
    monkeypatch.setenv("CAGD_COURSE", "")
    monkeypatch.delenv("CAGD_COURSE")


def test_the_course_folder_is_found_from_anywhere_inside_it_or_named(tmp_path, monkeypatch, capsys, unnamed_course):
    monkeypatch.chdir(ROOT / "exercises")
    assert main(["list"]) == 0
    assert "02.de_casteljau" in capsys.readouterr().out
    # A folder of its own: --course names it (and the run's child processes inherit it).
    (tmp_path / "book.toml").write_text('[book]\ntitle = "A tiny course"\n', encoding="utf-8")
    monkeypatch.chdir(ROOT.parent)
    assert main(["--course", str(tmp_path), "list"]) == 0
    assert capsys.readouterr().out.strip() == "A tiny course"


def test_a_missing_course_folder_is_a_clear_error(tmp_path, capsys, unnamed_course):
    assert main(["--course", str(tmp_path / "nowhere"), "list"]) == 2
    assert "book.toml" in capsys.readouterr().err

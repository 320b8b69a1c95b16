"""book.toml, the files it names and the two dependency lists agree with each other."""

import importlib
import re
import sys
from pathlib import Path

import pytest

from cagd_course.grading.engine import load_exercises
from cagd_course.manifest import load_course

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
COURSE = load_course(ROOT)


def test_every_listed_file_exists():
    for chapter in COURSE.chapters:
        assert chapter.notebook.is_file(), chapter.notebook
        assert chapter.exercises is None or chapter.exercises.is_file(), chapter.exercises
        assert chapter.hidden is None or chapter.hidden.is_file(), chapter.hidden


@pytest.mark.parametrize("module", sorted({m for c in COURSE.chapters for m in c.modules}))
def test_every_listed_module_imports(module):
    assert importlib.import_module(module).__all__


def test_exercise_ids_name_their_chapter_and_a_reference_function():
    for chapter in COURSE.chapters:
        for exercise_id, points in chapter.exercise_points.items():
            number, function = exercise_id.split(".", 1)
            assert int(number) == chapter.number and points > 0
            assert any(hasattr(importlib.import_module(m), function) for m in chapter.modules), exercise_id


def test_hidden_suites_cover_exactly_the_listed_exercises():
    loaded = load_exercises(COURSE)
    assert list(loaded) == list(COURSE.exercise_points())
    for exercise_id, (exercise, _) in loaded.items():
        assert exercise.reference.__name__ == exercise.function, exercise_id


def test_at_least_ten_exercises_in_chapters_one_and_two():
    assert len([e for e in COURSE.exercise_points() if e[:2] in ("01", "02")]) >= 10


def _conda_dependencies() -> list[str]:
    text = (ROOT / "environment.yml").read_text()
    # Conda packages and the entries of its `pip:` subsection; "pip" itself is the installer, not a dependency.
    found = re.findall(r"^\s+-\s+(\S+)", text.split("dependencies:", 1)[1], flags=re.M)
    return [entry for entry in found if entry not in ("pip", "pip:")]


def _name(requirement: str) -> str:
    return re.split(r"[<>=!;\s\[]", requirement, maxsplit=1)[0].lower().replace("_", "-")


def test_environment_yml_and_pyproject_name_the_same_dependencies():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    required = project["dependencies"] + [r for extra in project["optional-dependencies"].values() for r in extra]
    # Back-ports needed only on older Pythons (markers) have no conda counterpart.
    pip_names = {_name(r) for r in required if "python_version" not in r}
    conda_names = {_name(r) for r in _conda_dependencies()} - {"python"}
    assert pip_names == conda_names


def test_lower_bounds_match_between_the_two_files():
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    required = project["dependencies"] + [r for extra in project["optional-dependencies"].values() for r in extra]
    pip_bounds = {_name(r): r.split(">=")[1] for r in required if ">=" in r and "python_version" not in r}
    conda = dict(r.split(">=") for r in _conda_dependencies() if ">=" in r)
    conda.pop("python", None)
    assert pip_bounds == conda


def test_the_readme_lists_every_chapter():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for chapter in COURSE.chapters:
        assert f"| {chapter.number}. {chapter.title} |" in readme, f"README: add chapter {chapter.number}"
        assert f"`{chapter.notebook.relative_to(ROOT)}`" in readme

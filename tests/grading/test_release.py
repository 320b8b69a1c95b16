"""`cagd release`: what a class's students get holds no reference code of a graded function and no hidden answer,
and its self-check works offline, without the course, on the notebooks as they are."""

import ast
import contextlib
import importlib.util
import inspect
import io
import json
import subprocess
import sys
from pathlib import Path

import numpy
import pytest

from cagd_course.cli import main
from cagd_course.grading.engine import load_exercises
from cagd_course.grading.release import TAG, leaks, load_released, release
from cagd_course.manifest import load_course

HERE = Path(__file__).parent
spec = importlib.util.spec_from_file_location("semester", HERE / "fixtures" / "semester.py")
semester = importlib.util.module_from_spec(spec)
spec.loader.exec_module(semester)
COURSE = load_course()


def _loadable(chapter):
    try:
        return load_exercises(COURSE, list(chapter.exercise_points))
    except Exception:  # noqa: BLE001 - a chapter being written right now
        return None


SUITES = {c.number: s for c in COURSE.chapters if (s := _loadable(c)) is not None}


@pytest.fixture(scope="module")
def released(tmp_path_factory):
    out = tmp_path_factory.mktemp("release") / "class"
    # Without outputs (executing every chapter takes minutes): test_release_outputs executes one.
    made = release(out, progress=False, execute=False)
    return out, made


def test_the_release_holds_the_notebooks_and_a_self_check_but_not_the_course(released):
    out, made = released
    # (Other chapters are being written while this runs: compare with what the release found, and the course.)
    exercises = {p.name for p in (out / "exercises").glob("*.ipynb")}
    assert exercises == {p.name for p in made.exercises} and len(exercises) >= 19
    assert exercises <= {c.exercises.name for c in COURSE.chapters if c.exercises}
    chapters = {p.name for p in (out / "chapters").glob("*.ipynb")}
    assert chapters == {p.name for p in made.chapters} <= {c.notebook.name for c in COURSE.chapters}
    package = out / "exercises" / "cagd_course"
    assert {p.name for p in package.iterdir()} >= {"__init__.py", "check.py", "_support.py", "_checks", "cases",
                                                    "examples"}
    assert not list(out.rglob("cagd_ref")) and not list(out.rglob("hidden"))
    assert all(p.parent.name == "_checks" for p in out.rglob("ch[0-9][0-9].py"))  # comparisons only, no suite
    assert set(made.checked) == {eid for s in SUITES.values() for eid in s}
    for path in package.rglob("*.py"):
        tree = ast.parse(path.read_text())
        imported = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
        imported |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.module and not n.level}
        assert not {m for m in imported if m.split(".")[0] in ("cagd_ref", "cagd_course", "tests")}, path


def test_no_reference_source_and_no_hidden_case_is_in_the_release(released):
    out, _ = released
    assert leaks(out, COURSE) == []
    for path in (out / "chapters").glob("*.ipynb"):
        cells = json.loads(path.read_text())["cells"]
        assert not [c for c in cells if TAG in c.get("metadata", {}).get("tags", [])]
        assert not [c for c in cells if c["cell_type"] == "code" and "show_source(" in "".join(c["source"])
                    and "def show_source" not in "".join(c["source"])]
    released_names = {p.name for p in released[1].chapters}
    tagged = sum(TAG in c.get("metadata", {}).get("tags", []) for ch in COURSE.chapters
                 if ch.notebook.name in released_names for c in json.loads(ch.notebook.read_text())["cells"])
    assert tagged > 0 and released[1].dropped_cells == tagged
    for data in (out / "exercises" / "cagd_course" / "cases").glob("*.json"):
        for exercise in json.loads(data.read_text())["exercises"].values():
            hidden = {c for c, info in exercise["categories"].items() if not info["visible"]}
            assert hidden and not {case["category"] for case in exercise["cases"]} & hidden


def test_the_leak_detector_finds_a_reference_function_and_a_hidden_case(released, tmp_path):
    import shutil

    from cagd_course.grading.engine import prepare
    from cagd_course.grading.release import CHECK_SEED

    out = tmp_path / "copy"
    shutil.copytree(released[0], out)
    import cagd_ref.polynomials as polynomials

    (out / "exercises" / "helpers.py").write_text(inspect.getsource(polynomials.power_to_bernstein))
    hidden = next(text for p in prepare(SUITES[3], CHECK_SEED) for case, text in zip(p.cases, p.sent)
                  if not case.visible and case.category == "random")
    (out / "notes.md").write_text(f"found it: {hidden}\n")
    found = leaks(out, COURSE)
    assert any("helpers.py: power_to_bernstein is the reference implementation of 03.power_to_bernstein" in f
               for f in found)
    assert any(f.startswith("notes.md: holds") for f in found)


def test_the_released_check_passes_the_reference_and_fails_a_mistake(released):
    checker = load_released(released[0], "cagd_released_test")
    for eid, (exercise, _) in ((e, v) for s in SUITES.values() for e, v in s.items()):
        text = io.StringIO()
        with contextlib.redirect_stdout(text):
            checker.check(eid, exercise.reference)
        assert "All visible cases pass." in text.getvalue(), text.getvalue()
    import runpy

    mistakes = COURSE.root / "tests" / "hidden" / "mistakes" / "ch03"
    mistake = runpy.run_path(str(mistakes / "horner__descending_order.py"))
    text = io.StringIO()
    with contextlib.redirect_stdout(text):
        checker.check("03.horner", mistake["horner"])
    report = text.getvalue()
    assert "[FAIL] notes example" in report and "expected: 5.75" in report and "Hint:" in report
    assert "[hidden] random: " in report and "checked when your work is graded" in report


def _run_notebook(notebook: Path, folder: Path) -> subprocess.CompletedProcess:
    """Run a notebook's code cells top to bottom in a Python that has NumPy but not the course on its path."""
    site = str(Path(numpy.__file__).resolve().parents[1])
    program = (
        "import sys, json, importlib.util\n"
        f"sys.path[:0] = [{str(folder)!r}]; sys.path.append({site!r})\n"
        "assert importlib.util.find_spec('cagd_ref') is None, 'the reference is reachable'\n"
        "import cagd_course\n"
        f"assert cagd_course.__file__.startswith({str(folder)!r}), cagd_course.__file__\n"
        f"cells = json.load(open({str(notebook)!r}))['cells']\n"
        "namespace = {'__name__': '__main__', 'display': print}\n"
        "for cell in cells:\n"
        "    if cell['cell_type'] == 'code':\n"
        "        exec(compile(''.join(cell['source']), 'cell', 'exec'), namespace)\n"
        "assert not [m for m in sys.modules if m.split('.')[0] in ('cagd_ref', 'tests')]\n"
    )
    return subprocess.run([sys.executable, "-I", "-S", "-c", program], capture_output=True, text=True,
                          cwd=folder, timeout=120)


def _cells(path: Path) -> list[dict]:
    return json.loads(path.read_text())["cells"]


def test_a_correct_notebook_self_checks_green_without_the_course(released):
    folder = released[0] / "exercises"
    notebook = semester.write(folder / "student-01.ipynb", semester.chapter_notebook(1))
    try:
        result = _run_notebook(notebook, folder)
    finally:
        notebook.unlink()
    assert result.returncode == 0, result.stderr
    assert result.stdout.count("All visible cases pass.") == 5 and "[FAIL]" not in result.stdout
    assert "checked when your work is graded" in result.stdout


def test_the_released_exercise_notebooks_run_unchanged_and_report_what_is_not_written(released):
    folder = released[0] / "exercises"
    result = _run_notebook(folder / "03-polynomial-evaluation.ipynb", folder)
    assert result.returncode == 0, result.stderr
    checks = sum("check(" in "".join(c["source"]) for c in _cells(folder / "03-polynomial-evaluation.ipynb")
                 if c["cell_type"] == "code")
    assert checks >= 4 and result.stdout.count("Not written yet") == checks


def test_the_release_command_refuses_a_folder_that_is_not_empty(released, capsys):
    assert main(["release", str(released[0])]) == 2
    assert "not empty" in capsys.readouterr().err


def test_release_help_says_what_is_left_out(capsys):
    with pytest.raises(SystemExit):
        main(["release", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "no reference" in text and "--book" in text

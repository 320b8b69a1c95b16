"""`cagd release` as a class meets it: chapters that read without a kernel, the live mode, the book, the README.

One release of chapter 1 (executing all 21 chapters takes minutes) with --live and --book, through a
private execution cache: the released chapter carries its executed outputs, the book is built from it
without executing the chapter again, and with the shipped runtime the chapter runs without the course.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest

from cagd_course.cli import main
from cagd_course.grading.release import TAG, WIDGET_VIEW, leaks, release
from cagd_course.manifest import load_course

COURSE = load_course()
CHAPTER = next(c for c in COURSE.chapters if c.number == 1)


@pytest.fixture(scope="module")
def live(tmp_path_factory):
    work = tmp_path_factory.mktemp("execution-cache")
    out = tmp_path_factory.mktemp("release") / "class"
    made = release(out, [1], book=True, live=True, progress=False, work=work)
    return out, made, work


def _cells(out: Path):
    return nbformat.read(out / "chapters" / CHAPTER.notebook.name, as_version=4).cells


def test_the_released_chapter_carries_its_figures_and_the_frames_of_its_explorers(live):
    out, made, _ = live
    assert made.executed == [1] and not made.problems
    cells = _cells(out)
    nbformat.validate(nbformat.read(out / "chapters" / CHAPTER.notebook.name, as_version=4))
    code = [c for c in cells if c.cell_type == "code"]
    assert not [c for c in code if TAG in c.metadata.get("tags", [])]
    figures = [c for c in code if "figure" in c.metadata.get("tags", [])]
    assert figures and all(any("image/png" in o.get("data", {}) for o in c.outputs) for c in figures)
    explorers = [c for c in code if "explorer" in c.metadata.get("tags", [])]
    assert explorers
    for cell in explorers:
        html = "".join("".join(o["data"].get("text/html", "")) for o in cell.outputs if "data" in o)
        assert "cagd-static-explorer" in html and "data:image/png;base64," in html
    # Without the kernel that made them, live widget views would show an error instead of the figure.
    assert not [o for c in code for o in c.outputs if WIDGET_VIEW in o.get("data", {})]
    counts = [c.execution_count for c in code if c.execution_count is not None]
    assert counts == list(range(1, len(counts) + 1))
    assert all(o.execution_count == c.execution_count for c in code for o in c.outputs
               if o.output_type == "execute_result")
    checks = [c for c in code if "check" in c.metadata.get("tags", [])]
    assert checks and all(c.outputs for c in checks)  # the verdicts are there to read


def test_the_outputs_hold_no_hidden_case_and_no_reference_listing(live, tmp_path):
    out, _, _ = live
    assert leaks(out, COURSE, runtime=True) == []
    plain = tmp_path / "without-runtime"
    shutil.copytree(out, plain, ignore=shutil.ignore_patterns("cagd_ref", "book"))
    shutil.rmtree(plain / "chapters" / "cagd_course")
    assert leaks(plain, COURSE) == []  # the outputs keep the promise of a release without the runtime
    text = (out / "chapters" / CHAPTER.notebook.name).read_text()
    assert "def rotate_about_axis" not in text and "def projection" not in text


def test_the_book_is_built_from_the_released_notebooks_without_executing_them_again(live):
    out, made, _ = live
    assert made.book == out / "book" and (out / "book" / "index.html").is_file()
    chapter = [p for p in made.book_pages if p.kind == "chapter"]
    assert [p.chapter for p in chapter] == [1] and not chapter[0].error
    assert not chapter[0].executed, "the release's book executed the chapter a second time"
    page = (out / "book" / CHAPTER.notebook.relative_to(COURSE.root).with_suffix(".html")).read_text()
    assert page.count("<img") >= 5 and "cagd-static-explorer" in page
    assert "Reference implementation of" not in page


def test_a_second_release_reuses_the_execution_cache(live, tmp_path):
    _, _, work = live
    again = release(tmp_path / "again", [1], progress=False, work=work)
    assert again.executed == [1] and not again.live
    assert not (tmp_path / "again" / "chapters" / "cagd_ref").exists()
    readme = (tmp_path / "again" / "README.md").read_text()
    assert "keeps the course's promise" in readme and "do not run here" in readme and "live" not in readme.lower()


def test_live_the_chapter_runs_with_the_shipped_runtime_and_without_the_course(live, tmp_path):
    out, _, _ = live
    chapters = out / "chapters"
    assert (chapters / "cagd_ref" / "geometry.py").is_file() and (chapters / "cagd_course" / "widgets").is_dir()
    assert not (chapters / "cagd_course" / "grading").exists() and not (chapters / "cagd_course" / "cli.py").exists()
    notebook = nbformat.read(chapters / CHAPTER.notebook.name, as_version=4)
    probe = nbformat.v4.new_code_cell(
        "import sys\n"
        "mine = {m.__name__: getattr(m, '__file__', '') for n, m in list(sys.modules.items())\n"
        "        if n.split('.')[0] in ('cagd_ref', 'cagd_course')}\n"
        f"assert mine and all(f.startswith({str(chapters)!r}) for f in mine.values() if f), mine\n"
        "print('runtime ok', len(mine))"
    )
    notebook.cells.append(probe)
    copy = chapters / "probe-run.ipynb"
    nbformat.write(notebook, copy)
    env = {k: v for k, v in os.environ.items() if k not in ("CAGD_COURSE", "PYTHONPATH")}
    program = (
        "import nbformat, sys\nfrom nbclient import NotebookClient\n"
        f"nb = nbformat.read({str(copy)!r}, as_version=4)\n"
        f"NotebookClient(nb, timeout=300, resources={{'metadata': {{'path': {str(chapters)!r}}}}}).execute()\n"
        "print(''.join(o.get('text', '') for o in nb.cells[-1].outputs))\n"
    )
    try:
        done = subprocess.run([sys.executable, "-c", program], cwd=tmp_path, env=env, capture_output=True,
                              text=True, timeout=600)
    finally:
        copy.unlink()
    assert done.returncode == 0, done.stderr[-3000:]
    assert "runtime ok" in done.stdout


def test_the_live_readme_says_what_it_ships_and_what_protects_grading(live):
    out, _, _ = live
    readme = (out / "README.md").read_text()
    assert "live" in readme and "chapters/cagd_ref" in readme and "reference implementation" in readme
    assert "does not hold in this mode" in readme and "class report flags" in readme
    assert "visible* cases" in readme and "hidden groups" in readme and "book/index.html" in readme
    requirements = (out / "requirements.txt").read_text().splitlines()
    assert {r.split(">")[0].split("=")[0] for r in requirements} >= {"numpy", "matplotlib", "ipywidgets", "scipy"}


def test_release_help_names_the_modes(capsys):
    with pytest.raises(SystemExit):
        main(["release", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--live" in text and "--book" in text and "--no-outputs" in text and "executed outputs" in text


def test_the_exercise_notebooks_say_what_check_does_in_each_place():
    for chapter in COURSE.chapters:
        if chapter.exercises is None or not chapter.exercises.is_file():
            continue
        cells = json.loads(chapter.exercises.read_text())["cells"]
        text = next("".join(c["source"]) for c in cells if "## How this works" in "".join(c["source"]))
        assert "In the course's repository" in text and "In a class release" in text, chapter.exercises.name
        assert "runs the hidden tests on your function in a separate" not in text

"""`cagd release OUT`: what the students of a class get, with no reference code and no hidden answers.

The release holds

* ``exercises/NN-slug.ipynb``, the exercise notebooks as they are, and next to them a small
  ``cagd_course`` package holding only ``check`` and ``examples``: the notebooks' own lines
  ``from cagd_course import check`` and ``from cagd_course.examples import notes_example`` work
  unchanged (Jupyter starts a notebook's kernel in its folder, which is first on the import path),
  and a notebook a student hands in is exactly the course's, so the grader treats its imports as it
  always does. That ``check`` runs the visible cases, whose inputs and expected answers are bundled
  as JSON (``cagd_course/cases/chNN.json``), with the grader's own comparisons, generated from the
  suites (``cagd_course/_checks/chNN.py``); hidden groups are named, with "checked when your work is
  graded". Nothing imports `cagd_ref` or the hidden suites.
* ``chapters/NN-slug.ipynb``, the chapter notebooks without the cells tagged ``reference-source``
  (those display reference implementations of graded functions), each with its executed outputs
  (figures, tables, the static frames of its explorers; live widget views left out), so that it
  reads without a kernel. The outputs come from the book's execution cache
  (`book.build.execute_notebooks`): a chapter `cagd book` executed is not run again. With
  ``book=True`` also ``book/``, the HTML book built from exactly those notebooks and executions.
* with ``live=True``, ``chapters/cagd_ref`` and ``chapters/cagd_course`` (the course's figures and
  explorers, without the grader): what the chapters run, so that every chapter and explorer runs in
  the students' Jupyter. That is the reference implementation: this mode gives up the promise
  below, and the README of the release says so.
* ``README.md`` (which mode, what ``check`` does here) and ``requirements.txt``.

`leaks` looks for what must not be there (in a live release: anything but the shipped runtime); the
release refuses to finish when it finds any.
"""

from __future__ import annotations

import ast
import builtins
import importlib.util
import json
import os
import re
import shutil
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

from ..manifest import COURSE_ENV, load_course
from . import suite as suite_module
from . import worker as worker_module
from .check import CHECK_SEED
from .engine import load_exercises, prepare
from .report import _HINTS
from .suite import Raises
from .worker import encode

__all__ = ["Release", "release", "leaks", "load_released", "TAG", "drop_tagged"]

TAG = "reference-source"
SHOWS_SOURCE = re.compile(r"(?:show_source|getsource)\(")
_DIGITS = re.compile(r"-?\d+\.\d{3,}")
# Images and other binary data stored as base64 (figures in notebook outputs): no case is hidden in them.
_BASE64 = re.compile(r"[A-Za-z0-9+/=\\\n]{400,}")
PACKAGE = "cagd_course"
SUITE_NAMES = ("INPUT_ERRORS", "NEAR_MISS", "Raises", "Mismatch", "_describe", "close", "exact", "_compare",
               "_compare_numbers", "_short", "_unit", "same_up_to_scale")
CODEC_NAMES = ("MAX_ARRAY_SIZE", "MAX_DEPTH", "Unsupported", "encode", "_encode_array", "_PLAIN", "decode")
# What a suite's comparisons may import: whatever is not the course (the reference, the grader, the suites).
FORBIDDEN_IMPORTS = ("cagd_ref", "cagd_course", "tests")


@dataclass
class Release:
    out: Path
    exercises: list[Path] = field(default_factory=list)
    chapters: list[Path] = field(default_factory=list)
    checked: list[str] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)
    dropped_cells: int = 0
    book: Path | None = None
    executed: list[int] = field(default_factory=list)  # chapters whose notebooks carry their outputs
    live: bool = False
    book_pages: list = field(default_factory=list)  # the book's pages (book.BuiltPage), with --book


def _top_level(path: Path, names: tuple[str, ...]) -> str:
    """The source of the named top-level definitions of a module, in the module's order."""
    text = path.read_text(encoding="utf-8")
    pieces = []
    for node in ast.parse(text).body:
        targets = [node.name] if isinstance(node, (ast.FunctionDef, ast.ClassDef)) else [
            t.id for t in getattr(node, "targets", []) if isinstance(t, ast.Name)
        ]
        if set(targets) & set(names):
            start = min([node.lineno] + [d.lineno for d in getattr(node, "decorator_list", [])])
            pieces.append("\n".join(text.splitlines()[start - 1 : node.end_lineno]))
    return "\n\n\n".join(pieces)


def support_source() -> str:
    """The release's ``_support.py``: the grader's value codec and comparisons, taken from their modules."""
    return (
        '"""The grader\'s value codec and comparisons, copied by `cagd release` from the course\'s grader."""\n\n'
        "from __future__ import annotations\n\nimport math\nimport sys\nfrom dataclasses import dataclass\n\n"
        "import numpy as np\n\n\n"
        + _top_level(Path(worker_module.__file__), CODEC_NAMES)
        + "\n\n\n"
        + _top_level(Path(suite_module.__file__), SUITE_NAMES)
        + "\n"
    )


class NotShippable(Exception):
    """A comparison that needs the course (the reference or the grader) to run."""


def _free_names(node: ast.AST) -> set[str]:
    loaded, bound = set(), set()
    for n in ast.walk(node):
        if isinstance(n, ast.Name):
            (loaded if isinstance(n.ctx, ast.Load) else bound).add(n.id)
        elif isinstance(n, ast.arg):
            bound.add(n.arg)
        elif isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)) and n is not node:
            bound.add(n.name)
    return loaded - bound


def comparisons_source(suite_path: Path, ids: list[str]) -> tuple[str, dict[str, str]]:
    """The release's ``_checks/chNN.py`` for a suite: its comparisons and what they need, nothing else.

    Returns the source and, per exercise whose comparison needs the course, why it is left out.
    """
    text = suite_path.read_text(encoding="utf-8")
    tree = ast.parse(text)
    defs: dict[str, ast.stmt] = {}
    imports: dict[str, tuple[ast.stmt, str]] = {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            defs[node.name] = node
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            for target in node.targets if isinstance(node, ast.Assign) else [node.target]:
                if isinstance(target, ast.Name):
                    defs[target.id] = node
        elif isinstance(node, ast.ImportFrom):
            for alias in node.names:
                imports[alias.asname or alias.name] = (node, node.module or "")
        elif isinstance(node, ast.Import):
            for alias in node.names:
                imports[alias.asname or alias.name.partition(".")[0]] = (node, alias.name)
    compares: dict[str, str] = {}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Exercise":
            keywords = {k.arg: k.value for k in node.keywords}
            ident = keywords.get("id")
            if isinstance(ident, ast.Constant) and ident.value in ids:
                compare = keywords.get("compare")
                compares[ident.value] = ast.get_source_segment(text, compare) if compare is not None else "close()"
    provided = set(SUITE_NAMES)
    needed: set[str] = set()
    lines_import: set[str] = set()
    excluded: dict[str, str] = {}

    def visit(name: str, trail: set[str]) -> None:
        if name in provided or name in trail or hasattr(builtins, name):
            return
        if name in imports:
            node, module = imports[name]
            if module.partition(".")[0] in FORBIDDEN_IMPORTS:
                raise NotShippable(f"it uses {name} from {module}")
            trail.add(name)
            return
        if name in defs:
            trail.add(name)
            for free in _free_names(defs[name]):
                visit(free, trail)

    for eid in ids:
        expression = compares.get(eid, "close()")
        trail: set[str] = set()
        try:
            for name in _free_names(ast.parse(expression, mode="eval")):
                visit(name, trail)
        except NotShippable as why:
            excluded[eid] = str(why)
            continue
        needed |= trail
    for name in needed & set(imports):
        node, module = imports[name]
        alias = next(a for a in node.names if (a.asname or a.name.partition(".")[0]) == name or a.asname == name
                     or a.name == name)
        if isinstance(node, ast.ImportFrom):
            lines_import.add(f"from {module} import {alias.name}" + (f" as {alias.asname}" if alias.asname else ""))
        else:
            lines_import.add(f"import {alias.name}" + (f" as {alias.asname}" if alias.asname else ""))
    body = []
    for node in tree.body:
        names = set()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names = {node.name}
        elif isinstance(node, (ast.Assign, ast.AnnAssign)):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names = {t.id for t in targets if isinstance(t, ast.Name)}
        if names & (needed - set(imports)):
            start = min([node.lineno] + [d.lineno for d in getattr(node, "decorator_list", [])])
            body.append("\n".join(text.splitlines()[start - 1 : node.end_lineno]))
    table = "".join(f"    {eid!r}: {compares.get(eid, 'close()')},\n" for eid in ids if eid not in excluded)
    table += "".join(f"    {eid!r}: None,  # {why}: checked when graded\n" for eid, why in excluded.items())
    source = (
        f'"""Comparisons of the exercises of {suite_path.stem}, taken by `cagd release` from its hidden suite."""\n\n'
        "from __future__ import annotations\n\n"
        + "".join(f"{line}\n" for line in sorted(lines_import))
        + f"\nfrom .._support import {', '.join(sorted(n for n in SUITE_NAMES if not n.startswith('_')))}  # noqa\n"
        + ("\n\n" + "\n\n\n".join(body) + "\n" if body else "")
        + "\n\nCOMPARE = {\n" + table + "}\n"
    )
    return source, excluded


def _encode_expected(value):
    if isinstance(value, Raises):
        return {"__raises__": [value.name, value.message]}
    if isinstance(value, float) and type(value) is not float and getattr(value, "__dict__", None):
        return {"__number__": float(value), "attrs": {k: encode(v) for k, v in vars(value).items()}}
    return encode(value)


def _tolerance(exercise) -> list[float] | None:
    compare = exercise.comparison()
    rtol, atol = getattr(compare, "rtol", None), getattr(compare, "atol", None)
    return [float(rtol), float(atol)] if rtol is not None and atol is not None else None


def cases_data(exercises: dict, seed: int = CHECK_SEED) -> dict:
    """The visible cases of `exercises` with the reference's answers, and the names and sizes of hidden groups."""
    data = {"seed": seed, "hints": dict(_HINTS), "exercises": {}}
    for prepared in prepare(exercises, seed):
        exercise = prepared.exercise
        categories: dict[str, dict] = {}
        cases = []
        for case, sent, expected in zip(prepared.cases, prepared.encoded, prepared.expected):
            entry = categories.setdefault(case.category, {"visible": False, "cases": 0})
            if case.visible:
                entry["visible"] = True
                cases.append({"category": case.category, "args": sent["args"], "kwargs": sent["kwargs"],
                              "expected": _encode_expected(expected), "rule": exercise.rule_for(case)})
            else:
                entry["cases"] += 1
        # A group with visible cases reports its hidden ones too: only groups with no visible case stay named.
        data["exercises"][exercise.id] = {
            "function": exercise.function,
            "points": prepared.points,
            "hint": exercise.hint,
            "tolerance": _tolerance(exercise),
            "categories": categories,
            "cases": cases,
        }
    return data


def drop_tagged(notebook_path: Path, target: Path) -> int:
    """Copy a notebook without its cells tagged `reference-source` (and without outputs); return how many went."""
    import nbformat

    notebook = nbformat.read(notebook_path, as_version=4)
    kept = [c for c in notebook.cells if TAG not in c.get("metadata", {}).get("tags", [])]
    dropped = len(notebook.cells) - len(kept)
    for cell in kept:
        if cell.cell_type == "code":
            cell.outputs, cell.execution_count = [], None
    notebook.cells = kept
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(nbformat.writes(notebook) + "\n", encoding="utf-8")
    return dropped


README = """# Class release: {title}

Written by `cagd release` ({mode}). Set up once: `pip install -r requirements.txt`, then `jupyter lab`.

## Chapters

`chapters/` holds the chapter notebooks{executed}{book}

{promise}

## Exercises

Work in `exercises/`: each notebook states its exercises, gives a stub to replace and a check cell; run
its cells from the top. What `check("NN.name", name)` does here: it runs the *visible* cases of that
exercise on your function, in the notebook's own process, and compares your answers with the course's
answers shipped with this release (`exercises/cagd_course/cases/`). The hidden groups of cases are only
named: they run when your work is graded, in a separate, confined process that cannot see this folder,
so all visible cases passing does not yet mean full marks. (In the course's own repository the same
`check` runs every case, hidden ones included, in a separate process.) Hand in the notebook itself,
without renaming the functions.
"""

EXECUTED = (
    ", executed: their figures, tables and the static frames of each explorer's main slider are stored in them, "
    "so they read in JupyterLab, on a JupyterHub, on nbviewer and on GitHub without running anything"
)
NOT_EXECUTED = " (written without outputs: run `cagd release` without `--no-outputs` to store them)"
PROMISE = (
    "This release keeps the course's promise: it holds no reference implementation of a graded function and no "
    "hidden test case (`cagd release` checked every file before it finished). So the chapters' code cells, which "
    "call the reference implementation, do not run here: read their stored outputs."
)
LIVE = (
    "This is a **live** release: `chapters/cagd_ref` is the course's reference implementation (every algorithm of "
    "the course, the graded exercises' included) and `chapters/cagd_course` its figures and explorers, so that "
    "every chapter and every explorer runs in your Jupyter (run the cells from the top; every control is live). "
    "The promise that a release holds no reference code does not hold in this mode: the reference solutions of "
    "the exercises can be read here. What protects grading: handed-in code is graded without the reference (it "
    "can neither import nor read it), the hidden test cases are not in this release, and the class report flags "
    "graded functions that are the reference implementation's code once names and formatting are ignored."
)
# What students install: for the exercises and reading the chapters, and, live, for running the chapters.
REQUIREMENTS = ("numpy", "jupyterlab", "jupyterlab-myst")
LIVE_REQUIREMENTS = ("numpy", "scipy", "sympy", "matplotlib", "ipywidgets", "ipykernel", "pillow", "jupyterlab",
                     "jupyterlab-myst")
# Parts of cagd_course a live release's chapters do not run: the grader, the book builder, the command.
NOT_RUNTIME = ("grading", "book", "cli.py", "__pycache__")
RUNTIME_INIT = (
    '"""The course\'s figures and explorers, shipped by `cagd release --live` so the chapters run (no grader)."""'
    '\n\n__version__ = "{version}"\n'
)
# The MIME type of a live widget's view: without the kernel that made it, it shows nothing (or an error).
WIDGET_VIEW = "application/vnd.jupyter.widget-view+json"


def _package(target: Path, course) -> None:
    import cagd_course.examples as examples

    target.mkdir(parents=True, exist_ok=True)
    (target / "__init__.py").write_text(
        '"""The self-check of the released exercise notebooks (`check`) and the notes\' worked examples '
        '(`examples`)."""\n\nfrom .check import check\n\n__all__ = ["check"]\n',
        encoding="utf-8",
    )
    shutil.copyfile(Path(__file__).with_name("released_check.py"), target / "check.py")
    (target / "_support.py").write_text(support_source(), encoding="utf-8")
    (target / "_checks").mkdir(exist_ok=True)
    (target / "_checks" / "__init__.py").write_text('"""Each chapter\'s comparisons."""\n', encoding="utf-8")
    (target / "cases").mkdir(exist_ok=True)
    folder = Path(examples.__file__).parent
    (target / "examples").mkdir(exist_ok=True)
    shutil.copyfile(folder / "__init__.py", target / "examples" / "__init__.py")
    for toml in sorted(folder.glob("*.toml")):
        shutil.copyfile(toml, target / "examples" / toml.name)


def release(out: Path | str, chapters: list[int] | None = None, book: bool = False, force: bool = False,
            progress: bool = True, live: bool = False, execute: bool = True, work: Path | str | None = None,
            timeout: int = 300) -> Release:
    """Write the class release into `out` (which must be new or empty unless `force`).

    execute: store each chapter's executed outputs in its released notebook, from the book's execution
    cache (`work`, default the book's `_build/.book`: chapters `cagd book` executed are not run again);
    live: ship the runtime the chapters need (the reference among it) beside them; book: build the
    HTML book from the released notebooks, from the same executions.
    """
    out = Path(out)
    course = load_course()
    if out.exists() and any(out.iterdir()):
        if not force:
            raise FileExistsError(f"{out} is not empty: choose a new folder, or pass --force to replace it")
        shutil.rmtree(out)
    if out.resolve().is_relative_to(course.root.resolve()):
        raise ValueError(f"{out} lies inside the course folder; write the release outside it")
    selected = [c for c in course.chapters if chapters is None or c.number in chapters]
    result = Release(out)
    package = out / "exercises" / PACKAGE
    _package(package, course)
    for chapter in selected:
        if chapter.exercises is not None and chapter.exercises.is_file():
            target = out / "exercises" / chapter.exercises.name
            result.dropped_cells += drop_tagged(chapter.exercises, target)
            result.exercises.append(target)
            ids = list(chapter.exercise_points)
            try:
                exercises = load_exercises(course, ids)
            except Exception as err:  # noqa: BLE001 - named in the problems; the rest of the release goes on
                result.problems.append(f"chapter {chapter.number}: no self-check data ({err})")
                continue
            source, excluded = comparisons_source(chapter.hidden, ids)
            for eid, why in excluded.items():
                result.problems.append(f"{eid}: its comparison is not shipped ({why}); checked when graded")
            tag = f"ch{chapter.number:02d}"
            (package / "_checks" / f"{tag}.py").write_text(source, encoding="utf-8")
            data = cases_data(exercises)
            (package / "cases" / f"{tag}.json").write_text(json.dumps(data, allow_nan=True) + "\n", encoding="utf-8")
            result.checked += ids
        elif chapter.exercises is not None:
            result.problems.append(f"chapter {chapter.number}: {chapter.exercises.name} is missing")
        if chapter.notebook.is_file():
            target = out / "chapters" / chapter.notebook.name
            result.dropped_cells += drop_tagged(chapter.notebook, target)
            result.chapters.append(target)
        else:
            result.problems.append(f"chapter {chapter.number}: {chapter.notebook.name} is missing")
    executed: dict[int, object] = {}
    if execute:
        executed = _store_outputs(out, course, [c for c in selected if c.notebook.is_file()], work, timeout,
                                  progress, result)
    if live:
        _runtime(out / "chapters")
        result.live = True
    (out / "requirements.txt").write_text(_requirements(course, LIVE_REQUIREMENTS if live else REQUIREMENTS),
                                          encoding="utf-8")
    if book:
        result.book, result.book_pages = _build_book(out, course, selected, progress, executed, timeout)
    mode = "live: with the runtime the chapters need, the reference implementation among it" if live else \
        "no reference implementation, no hidden case"
    (out / "README.md").write_text(
        README.format(
            title=course.title,
            mode=mode,
            executed=EXECUTED if result.executed else NOT_EXECUTED,
            book="; `book/index.html` is the HTML book built from them." if book else ".",
            promise=LIVE if live else PROMISE,
        ),
        encoding="utf-8",
    )
    found = leaks(out, course, runtime=live)
    if found:
        shutil.rmtree(out)
        listed = "\n  ".join(found)
        raise RuntimeError(f"the release would give away what it must not; nothing was written:\n  {listed}")
    return result


def _build_book(out: Path, course, selected, progress: bool, executed: dict, timeout: int) -> tuple[Path, list]:
    """The HTML book of the released chapters: built from a copy of the course holding the released notebooks.

    The executions behind the released notebooks' outputs are recorded in the copy's cache first, so
    the book shows the same outputs and no chapter is executed again.
    """
    from ..book import build_book
    from ..book.build import execute_notebooks

    stage = Path(tempfile.mkdtemp(prefix="cagd-release-book-"))
    try:
        shutil.copyfile(course.root / "book.toml", stage / "book.toml")
        for chapter in selected:
            for path, folder in ((chapter.notebook, "chapters"), (chapter.exercises, "exercises")):
                if path is not None and path.is_file():
                    (stage / path.relative_to(course.root)).parent.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(out / folder / path.name, stage / path.relative_to(course.root))
        previous = os.environ.get(COURSE_ENV)
        os.environ[COURSE_ENV] = str(stage)
        try:
            staged = {c.number: stage / c.notebook.relative_to(course.root) for c in selected if c.number in executed}
            if staged:
                execute_notebooks(staged, stage / "_build", timeout, progress,
                                  outputs={n: executed[n] for n in staged})
            pages = build_book(out / "book", [c.number for c in selected], timeout, progress=progress,
                               work=stage / "_build")
        finally:
            if previous is None:
                os.environ.pop(COURSE_ENV, None)
            else:
                os.environ[COURSE_ENV] = previous
        failed = [p.error for p in pages if p.error]
        if failed:
            raise RuntimeError("the book of the release did not build:\n" + "\n".join(failed))
        return out / "book", pages
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def _only_displays(cells) -> bool:
    """True when every one of `cells` is expressions only (displays): dropping them changes no later cell."""
    for cell in cells:
        try:
            body = ast.parse(cell.source).body
        except SyntaxError:
            return False
        if not all(isinstance(node, ast.Expr) for node in body):
            return False
    return True


def _released_outputs(cell_outputs: list) -> list:
    """A cell's outputs as a release stores them: without live widget views, which need the kernel that made them."""
    kept = []
    for output in cell_outputs:
        data = output.get("data")
        if isinstance(data, dict) and WIDGET_VIEW in data:
            output = dict(output)
            output["data"] = {k: v for k, v in data.items() if k != WIDGET_VIEW}
            if not output["data"]:
                continue
        kept.append(output)
    return kept


def _attach(target: Path, code_outputs: list, language: dict | None) -> object:
    """Give the released notebook `target` the outputs of its code cells, in order; return it (with outputs)."""
    import nbformat

    notebook = nbformat.read(target, as_version=4)
    code = [c for c in notebook.cells if c.cell_type == "code"]
    if len(code) != len(code_outputs):
        raise ValueError(f"{target.name}: {len(code)} code cells, {len(code_outputs)} executed")
    for count, (cell, ran) in enumerate(zip(code, code_outputs), start=1):
        if cell.source != ran.source:
            raise ValueError(f"{target.name}: code cell {count} is not the one executed")
        cell.execution_count = count if ran.get("execution_count") is not None else None
        cell.outputs = [nbformat.from_dict(o) for o in _released_outputs(ran.get("outputs", []))]
        for output in cell.outputs:
            if output.output_type == "execute_result":
                output.execution_count = cell.execution_count
    notebook.metadata.pop("widgets", None)
    if language:
        notebook.metadata["language_info"] = language
    target.write_text(nbformat.writes(notebook) + "\n", encoding="utf-8")
    return notebook


def _store_outputs(out: Path, course, selected, work, timeout: int, progress: bool, result: Release) -> dict:
    """Store each released chapter's executed outputs in it; return the released notebooks with outputs, by chapter.

    The chapters are executed as the book executes them, through its cache (`book.build.execute_notebooks`):
    a chapter the book has executed is not run again. A released chapter lacks only display cells of
    reference listings, so its outputs are the chapter's, those cells' left out; one whose dropped cells
    could change later ones is executed as released.
    """
    import nbformat

    from ..book.build import execute_notebooks

    full = execute_notebooks({c.number: c.notebook for c in selected}, work, timeout, progress)
    done, again = {}, []
    for chapter in selected:
        executed, error = full[chapter.number]
        if executed is None:
            result.problems.append(f"chapter {chapter.number}: not executed, released without outputs ({error})")
            continue
        cells = [c for c in nbformat.read(chapter.notebook, as_version=4).cells if c.cell_type == "code"]
        dropped = [c for c in cells if TAG in c.metadata.get("tags", [])]
        if not _only_displays(dropped):
            again.append(chapter)
            continue
        kept = [ran for cell, ran in zip(cells, executed.cells) if TAG not in cell.metadata.get("tags", [])]
        target = out / "chapters" / chapter.notebook.name
        done[chapter.number] = _attach(target, kept, executed.metadata.get("language_info"))
    if again:
        rerun = execute_notebooks({c.number: out / "chapters" / c.notebook.name for c in again}, work, timeout,
                                  progress)
        for chapter in again:
            executed, error = rerun[chapter.number]
            if executed is None:
                result.problems.append(f"chapter {chapter.number}: not executed, released without outputs ({error})")
                continue
            target = out / "chapters" / chapter.notebook.name
            done[chapter.number] = _attach(target, list(executed.cells), executed.metadata.get("language_info"))
    result.executed = sorted(done)
    return done


def _runtime(target: Path) -> None:
    """What the chapters run, beside them: `cagd_ref` and `cagd_course` without the grader, the book and the command."""
    import cagd_course
    import cagd_ref

    ignore = shutil.ignore_patterns("__pycache__", "*.pyc")
    shutil.copytree(Path(cagd_ref.__file__).parent, target / "cagd_ref", ignore=ignore)
    source = Path(cagd_course.__file__).parent
    shutil.copytree(source, target / PACKAGE, ignore=lambda folder, names: [
        n for n in names if n in ("__pycache__",) or n.endswith(".pyc")
        or (Path(folder) == source and n in NOT_RUNTIME)])
    (target / PACKAGE / "__init__.py").write_text(RUNTIME_INIT.format(version=cagd_course.__version__),
                                                  encoding="utf-8")


def _requirements(course, names: tuple[str, ...]) -> str:
    from .autograder import _normalise, _requirement_specs

    specs = _requirement_specs(course)
    return "".join(specs.get(_normalise(name), name) + "\n" for name in names)


def _code_cells(path: Path) -> list[str]:
    try:
        cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    except (OSError, ValueError, KeyError):
        return []
    return ["".join(c.get("source", "")) for c in cells if c.get("cell_type") == "code"]


def _definitions(source: str):
    try:
        tree = ast.parse(source)
    except SyntaxError:
        return
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            yield node


def leaks(out: Path, course=None, runtime: bool = False) -> list[str]:
    """What in `out` must not be in a release: reference code of a graded function, hidden suites, hidden answers.

    Checks every Python file and notebook code cell for a function whose normalised syntax tree is a
    graded function's reference implementation (except one the course's own exercise notebook gives
    students), for `cagd_ref` and the suites' files, for cells that show reference source, and for the
    inputs and answers of hidden cases (as the grader encodes them) in any file, a notebook's outputs
    included (images and other long base64 data left aside). With `runtime` (a live release) the
    runtime beside the chapters, `chapters/cagd_ref` and `chapters/cagd_course`, is the reference by
    design: it is checked for hidden cases only.
    """
    from .similarity import fingerprint, source_fingerprint

    course = course or load_course()
    out = Path(out)
    found = []
    files = [p for p in out.rglob("*") if p.is_file()]
    shipped = {("chapters", "cagd_ref"), ("chapters", PACKAGE)} if runtime else set()
    for path in files:
        relative = path.relative_to(out)
        if tuple(relative.parts[:2]) in shipped:
            continue
        if "cagd_ref" in relative.parts or relative.parts[:2] == ("tests", "hidden"):
            found.append(f"{relative}: part of the reference or of the hidden suites")
    given: set[str] = set()  # what the course's exercise notebooks themselves give students
    for chapter in course.chapters:
        if chapter.exercises is not None and chapter.exercises.is_file():
            for cell in _code_cells(chapter.exercises):
                given |= {fingerprint(n)[0] for n in _definitions(cell)}
    references: dict[str, str] = {}
    hidden_texts: set[str] = set()
    visible: set[str] = set()
    for chapter in course.chapters:
        try:
            exercises = load_exercises(course, list(chapter.exercise_points))
        except Exception:  # noqa: BLE001 - a chapter whose suite does not load shipped no data either
            continue
        for eid, (exercise, _) in exercises.items():
            printed = source_fingerprint(exercise.reference)
            if printed is not None and printed[0] not in given:
                references[printed[0]] = eid
        for prepared in prepare(exercises, CHECK_SEED):
            for case, text, expected in zip(prepared.cases, prepared.sent, prepared.expected):
                # Values telling enough to be recognised: three numbers with digits after the point, at least.
                telling = {t for t in (text, json.dumps(_encode_expected(expected))) if len(_DIGITS.findall(t)) >= 3}
                (visible if case.visible else hidden_texts).update(telling)
    hidden_texts -= visible
    for path in files:
        in_runtime = tuple(path.relative_to(out).parts[:2]) in shipped
        sources = [] if in_runtime else _code_cells(path) if path.suffix == ".ipynb" else \
            [path.read_text(encoding="utf-8")] if path.suffix == ".py" else []
        for source in sources:
            for node in _definitions(source):
                eid = references.get(fingerprint(node)[0])
                if eid is not None:
                    found.append(f"{path.relative_to(out)}: {node.name} is the reference implementation of {eid}")
            if path.suffix == ".ipynb" and SHOWS_SOURCE.search(source) and not re.search(r"^\s*def show_source",
                                                                                           source, re.M):
                found.append(f"{path.relative_to(out)}: a cell shows source code ({source.strip()[:60]!r})")
        if path.suffix in (".json", ".py", ".ipynb", ".md", ".toml", ".html", ".txt"):
            text = _BASE64.sub("", path.read_text(encoding="utf-8", errors="replace"))
            hits = [t for t in hidden_texts if t in text]
            if hits:
                found.append(f"{path.relative_to(out)}: holds {len(hits)} hidden case(s) or answer(s)")
    return found


def load_released(out: Path | str, name: str = "cagd_released"):
    """Import a release's ``cagd_course`` package under another name (for tests, beside the real course)."""
    folder = Path(out) / "exercises" / PACKAGE
    spec = importlib.util.spec_from_file_location(
        name, folder / "__init__.py", submodule_search_locations=[str(folder)]
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module

"""Build the book: stage the notebooks of book.toml, execute what changed, run Sphinx, report per chapter.

The work folder (`_build/.book` in the course folder) keeps what makes the
second build fast: the jupyter-cache of executed notebooks (a chapter runs
again only when its code cells change, or when the course's own code does),
Sphinx's doctrees, and the staged sources (`src/`: the generated landing page
and links to the notebook folders).
"""

from __future__ import annotations

import hashlib
import multiprocessing
import os
import re
import shutil
import sys
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import nbformat
from tqdm import tqdm

from ..figure_check import INLINE_BACKEND
from ..manifest import COURSE_ENV, Chapter, Course, load_course
from ..widgets._static import STATIC_FRAMES_ENV

__all__ = ["BuiltPage", "BookError", "build_book", "DEFAULT_FRAMES", "CONF_DIR"]

CONF_DIR = Path(__file__).resolve().parent
WORK = Path("_build") / ".book"
# The course's notation table: the book's front matter (one symbol, one meaning in every chapter).
NOTATION = CONF_DIR / "notation.md"
DEFAULT_FRAMES = 21
FINGERPRINT = "fingerprint.txt"


class BookError(RuntimeError):
    """The book could not be built (Sphinx failed); the message says why."""


@dataclass(frozen=True)
class BuiltPage:
    """One page of the book: a chapter (executed) or an exercise notebook (shown as shipped)."""

    chapter: int
    title: str
    file: str
    seconds: float = 0.0
    error: str = ""
    executed: bool = False
    kind: str = "chapter"

    @property
    def state(self) -> str:
        if self.error:
            return f"FAILED: {self.error}"
        if self.kind != "chapter":
            return "shown as shipped (not executed)"
        if self.executed:
            return f"executed in {self.seconds:.1f} s"
        return f"from the cache (executed in {self.seconds:.1f} s)"


# ---------------------------------------------------------------- staging


def _docname(course: Course, notebook: Path) -> str:
    return notebook.relative_to(course.root).with_suffix("").as_posix()


def _first_sentence(notebook: Path) -> str:
    """The first sentence of a notebook's opening paragraph (after its title): its line on the landing page."""
    cells = nbformat.read(notebook, as_version=4).cells
    text = next((c.source for c in cells if c.cell_type == "markdown"), "")
    paragraphs = [p for p in re.split(r"\n\s*\n", text) if p.strip() and not p.lstrip().startswith("#")]
    if not paragraphs:
        return ""
    paragraph = " ".join(paragraphs[0].split())
    # A sentence ends at . ! ? before a capital, except after an initial ("T. W. Sederberg").
    return re.split(r"(?<=[.!?])(?<!\b[A-Z]\.)\s+(?=[A-Z(])", paragraph, maxsplit=1)[0]


def _landing_page(course: Course, chapters: list[Chapter]) -> str:
    lines = [f"# {course.title}", ""]
    if course.subtitle:
        lines += [f"*{course.subtitle}*", ""]
    lines += [
        "A course on the mathematics of curves for computer aided design, one chapter per chapter of the notes. "
        "Each chapter is a notebook that explains an idea, computes it with the course's reference code "
        "(`cagd_ref`), draws it and lets you play with it; each has an exercise notebook in which you write the "
        "algorithms yourself and hidden tests check them.",
        "",
        "## How to use this book",
        "",
        "**Reading.** Every chapter was executed for this book: prose, formulas, the reference code and its "
        "figures. The main slider of each explorer works on the page (its frames were computed when the book "
        "was built; the play button runs through them). The search box finds any term, the sidebar leads "
        "through the course, and the download button of every page gives its notebook.",
        "",
        "**Studying.** In the course folder, `./course lab` opens the notebooks in JupyterLab, where every "
        "control of every explorer is live and you can change the code. After a chapter, open its exercise "
        "notebook, replace each stub by your own function and run its self-check cell; "
        "`./course cagd check exercises/<notebook>` checks a whole notebook.",
        "",
        "**Notation.** One symbol has one meaning in the whole course; the [notation](notation.md) page lists "
        "them.",
        "",
        "**Teaching.** `./course cagd validate` proves the hidden suites (reference 100 %, stub 0 %, recorded "
        "mistakes below 100 %), `./course cagd grade submissions/ --out graded/` grades a class into a gradebook, "
        "feedback pages and Gradescope-style results, and `./course build --pdf` prints this book.",
        "",
        "## Chapters",
        "",
    ]
    for chapter in chapters:
        # A bullet, not a numbered item: Markdown renumbers lists, and the course may skip chapters.
        line = f"- **{chapter.number}. [{chapter.title}]({chapter.notebook.relative_to(course.root).as_posix()})**"
        sentence = _first_sentence(chapter.notebook)
        if sentence:
            line += f": {sentence}"
        if chapter.exercises is not None:
            count = len(chapter.exercise_points)
            noun = "exercise" if count == 1 else "exercises"
            line += f" [{count} {noun}]({chapter.exercises.relative_to(course.root).as_posix()})."
        lines.append(line)
    lines.append("")
    for caption, docs in (
        ("Front matter", [NOTATION.stem]),
        ("Chapters", [_docname(course, c.notebook) for c in chapters]),
        ("Exercises", [_docname(course, c.exercises) for c in chapters if c.exercises is not None]),
    ):
        if docs:
            lines += ["```{toctree}", ":hidden:", f":caption: {caption}", "", *docs, "```", ""]
    return "\n".join(lines)


def _write_if_changed(path: Path, text: str) -> None:
    """Write `text` unless the file holds it already (Sphinx reads a page again when its file changes)."""
    if not path.is_file() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


# role -> (MyST-NB tags, the toggle's label) of a chapter's code cell in the book (cagd_course.notebook.ROLES)
BOOK_FORM = {
    "setup": (["remove-cell"], ""),
    "check": (["hide-input"], "Show the check"),
    "figure": (["hide-input"], "Show the code of this figure"),
    # The output of a reference-source cell is the listing: the input goes, the listing is folded.
    "reference-source": (["remove-input", "hide-output"], "Reference implementation"),
}


def _listing_label(source: str, exercises: dict[str, str]) -> str:
    """The toggle of a reference listing: what it shows and, for a graded function, which exercise to try first.

    exercises: function name -> exercise id of the chapter ("de_casteljau" -> "02.de_casteljau").
    """
    names = [name.rsplit(".", 1)[-1] for name in re.findall(r"show_source\(\s*([\w.]+)", source)]
    label = "Reference implementation" + (f" of {', '.join(names)}" if names else "")
    # A listing of a graded function's plain teaching form (`hull_march_plain`) guards the same exercise.
    graded = [exercises[key] for key in (name.removesuffix("_plain") for name in names) if key in exercises]
    if graded:
        label += f": try exercise {', '.join(graded)} first"
    return label


def _book_form(notebook: nbformat.NotebookNode, exercises: dict[str, str] | None = None) -> nbformat.NotebookNode:
    """The notebook as the book shows it: each code cell's role becomes MyST-NB's tags and toggle label."""
    for cell in notebook.cells:
        if cell.cell_type != "code":
            continue
        tags = cell.metadata.get("tags", [])
        role = next((tag for tag in tags if tag in BOOK_FORM), None)
        if role is None:
            continue
        extra, label = BOOK_FORM[role]
        cell.metadata["tags"] = [*tags, *(tag for tag in extra if tag not in tags)]
        if label:
            if role == "reference-source":
                label, hide = _listing_label(cell.source, exercises or {}), "Hide the listing"
            else:
                hide = "Hide the code"
            cell.metadata["mystnb"] = {"code_prompt_show": label, "code_prompt_hide": hide}
    return notebook


def _stage(course: Course, chapters: list[Chapter], src: Path) -> None:
    """The Sphinx source folder: the landing page and copies of the notebooks, at their places in the course.

    Copies rather than links, so that links between notebooks resolve inside the
    source folder; chapters are copied in their book form (`_book_form`). A copy
    is rewritten only when it changed, and notebooks no longer in the book go.
    """
    src.mkdir(parents=True, exist_ok=True)
    wanted = {}
    for path in (p for c in chapters for p in (c.notebook, c.exercises) if p is not None):
        wanted[src / path.relative_to(course.root)] = path
    # A chapter's graded functions, by name: their listings say which exercise to try first.
    exercises = {c.notebook: {e.split(".", 1)[1]: e for e in c.exercise_points} for c in chapters}
    for stale in set(src.rglob("*.ipynb")) - set(wanted):
        stale.unlink()
    for copy, original in wanted.items():
        copy.parent.mkdir(parents=True, exist_ok=True)
        if original in exercises:
            text = nbformat.writes(_book_form(nbformat.read(original, as_version=4), exercises[original]))
            _write_if_changed(copy, text)
        elif not copy.is_file() or copy.read_bytes() != original.read_bytes():
            shutil.copyfile(original, copy)
    _write_if_changed(src / "index.md", _landing_page(course, chapters))
    _write_if_changed(src / NOTATION.name, NOTATION.read_text(encoding="utf-8"))


def _pages(course: Course, chapters: list[Chapter], failures: dict[int, str]) -> dict:
    """docname -> what the extension's "run it yourself" box says about that page."""
    pages = {}
    for chapter in chapters:
        doc = _docname(course, chapter.notebook)
        exercises = _docname(course, chapter.exercises) if chapter.exercises is not None else ""
        pages[doc] = {
            "kind": "chapter",
            "notebook": chapter.notebook.relative_to(course.root).as_posix(),
            "partner": exercises,
            "partner_title": f"the exercises of chapter {chapter.number}",
            "failure": failures.get(chapter.number, ""),
        }
        if exercises:
            pages[exercises] = {
                "kind": "exercises",
                "notebook": chapter.exercises.relative_to(course.root).as_posix(),
                "partner": doc,
                "partner_title": f"chapter {chapter.number}, {chapter.title}",
            }
    return pages


# ---------------------------------------------------------------- execution


def _fingerprint() -> str:
    """A digest of the code the chapters run: cagd_ref, and cagd_course (the examples' data included) except
    the builder and the grader, which no chapter runs."""
    import cagd_course
    import cagd_ref

    course = Path(cagd_course.__file__).parent
    skipped = (CONF_DIR, course / "grading")
    digest = hashlib.sha256()
    for package in (Path(cagd_ref.__file__).parent, course):
        for path in sorted(package.rglob("*")):
            if path.suffix in (".py", ".toml") and not any(folder in path.parents for folder in skipped):
                digest.update(path.relative_to(package.parent).as_posix().encode())
                digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def _open_cache(folder: Path, fingerprint: str):
    """The jupyter-cache of executed chapters, emptied when the course's code changed since it was filled."""
    from jupyter_cache import get_cache

    stamp = folder / FINGERPRINT
    if folder.exists() and (not stamp.is_file() or stamp.read_text().strip() != fingerprint):
        shutil.rmtree(folder)
    folder.mkdir(parents=True, exist_ok=True)
    stamp.write_text(fingerprint + "\n")
    return get_cache(str(folder))


@dataclass(frozen=True)
class _Run:
    seconds: float
    executed: bool
    error: str = ""


def _failure(traceback: str, notebook: Path) -> str:
    """Which cell of `notebook` raised what, from jupyter-cache's traceback of a failed execution."""
    text = re.sub(r"\x1b\[[0-9;]*m", "", traceback or "")  # the kernel colours its tracebacks
    cell = ""
    match = re.search(r"\n-{10,}\n(.*?)\n-{10,}\n", text, flags=re.S)
    if match:
        source = match.group(1).strip()
        cells = nbformat.read(notebook, as_version=4).cells
        index = next((i for i, c in enumerate(cells) if c.cell_type == "code" and c.source.strip() == source), None)
        first = source.splitlines()[0] if source else ""
        cell = f"cell {index + 1} ({first!r})" if index is not None else f"the cell starting {first!r}"
    errors = re.findall(r"^(\w+(?:Error|Exception|Interrupt|Exit)\b.*)$", text, flags=re.M)
    timed_out = "CellTimeoutError" in text or "timed out" in text
    what = "timed out" if timed_out and not errors else (f"raised {errors[-1]}" if errors else "failed")
    return f"{cell or 'a cell'} {what}"


def _execute_all(cache, notebooks: dict[int, Path], timeout: int, progress: bool) -> dict[int, _Run]:
    """Execute (one per core) the chapters the cache does not hold, in their own folders; seconds and errors.

    The cache matches notebooks by their code, so the staged copies Sphinx reads find these executions.
    """
    from jupyter_cache.executors.basic import ExecutionWorkerLocalMProc, ProcessData

    records = {number: cache.add_nb_to_project(str(path)) for number, path in notebooks.items()}
    todo = {r.pk for r in cache.list_unexecuted(filter_pks=[r.pk for r in records.values()])}
    jobs = [ProcessData(r.pk, r.uri, cache, timeout, False) for r in records.values() if r.pk in todo]
    outcome: dict[str, int] = {}
    if jobs:
        workers = max(1, min(len(jobs), os.cpu_count() or 1))
        # Fresh interpreters (not forks of a process that may run threads), with the environment set for the kernels.
        with multiprocessing.get_context("spawn").Pool(workers) as pool:
            results = pool.imap_unordered(ExecutionWorkerLocalMProc(), jobs)
            shown = None if progress else True  # tqdm: None shows the bar on a terminal only
            for status, uri in tqdm(results, total=len(jobs), desc="executing chapters", unit="chapter", disable=shown):
                outcome[uri] = status
    runs = {}
    for number, record in records.items():
        if record.pk in todo and outcome.get(record.uri) != 0:
            traceback = cache.get_project_record(record.pk).traceback or "the executor failed"
            runs[number] = _Run(0.0, True, _failure(traceback, notebooks[number]))
            continue
        cached = cache.match_cache_notebook(nbformat.read(notebooks[number], as_version=4))
        runs[number] = _Run(float(cached.data.get("execution_seconds") or 0.0), record.pk in todo)
    return runs


def _drew_no_figure(notebook: nbformat.NotebookNode) -> bool:
    """True when the notebook has `figure` cells and none of them has an image among its outputs.

    That is what an execution under a non-inline matplotlib backend leaves (e.g. MPLBACKEND=Agg inherited
    from a server's environment): `plt.show()` draws nothing, and the cache would keep the empty outputs.
    """
    figures = [c for c in notebook.cells if c.cell_type == "code" and "figure" in c.metadata.get("tags", [])]
    has_image = any(
        key.startswith("image/") for c in figures for out in c.get("outputs", []) for key in out.get("data", {})
    )
    return bool(figures) and not has_image


def _forget_figureless(cache, notebooks: dict[int, Path]) -> None:
    """Remove from the cache the executions of chapters that lost their figures, so they run again."""
    for path in notebooks.values():
        try:
            record = cache.match_cache_notebook(nbformat.read(path, as_version=4))
        except KeyError:
            continue
        if _drew_no_figure(cache.get_cache_bundle(record.pk).nb):
            cache.remove_cache(record.pk)


@contextmanager
def _environment(**values: str):
    """Set environment variables for the run (the kernels inherit them), then put back what was there."""
    saved = {key: os.environ.get(key) for key in values}
    os.environ.update(values)
    try:
        yield
    finally:
        for key, value in saved.items():
            if value is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = value


# ---------------------------------------------------------------- Sphinx


def run_sphinx(src: Path, out: Path, doctrees: Path, overrides: dict, builder: str = "html") -> None:
    """Run Sphinx with the book's configuration; raise BookError if it fails."""
    from sphinx.application import Sphinx
    from sphinx.util.docutils import docutils_namespace, patch_docutils

    with patch_docutils(str(CONF_DIR)), docutils_namespace():
        app = Sphinx(
            str(src), str(CONF_DIR), str(out), str(doctrees), builder,
            confoverrides=overrides, status=None, warning=sys.stderr, freshenv=False,
        )  # fmt: skip
        app.build()
    if app.statuscode:
        raise BookError(f"Sphinx failed to build the book (status {app.statuscode}); see the messages above")


def build_book(
    out: Path | str | None = None,
    chapters: list[int] | None = None,
    timeout: int = 300,
    progress: bool = True,
    frames: int = DEFAULT_FRAMES,
    work: Path | str | None = None,
) -> list[BuiltPage]:
    """Execute the chapters of book.toml (all, or the numbers given) and write the book into `out`.

    out: the HTML folder (default `_build/html` in the course folder); work:
    the cache and Sphinx's state (default `_build/.book`); timeout: seconds
    per cell; frames: frames of each explorer's static figure. A chapter that
    fails to execute is reported with its cell (`BuiltPage.error`) and shown
    without outputs; the other pages are built all the same.
    """
    course = load_course()
    selected = [c for c in course.chapters if chapters is None or c.number in chapters]
    if chapters is not None:
        unknown = sorted(set(chapters) - {c.number for c in course.chapters})
        if unknown:
            raise ValueError(f"--chapter: no chapter {', '.join(map(str, unknown))} in book.toml")
    missing = [
        f"chapter {chapter.number}: book.toml names {path.relative_to(course.root)}, which does not exist"
        for chapter in selected
        for path in (chapter.notebook, chapter.exercises)
        if path is not None and not path.is_file()
    ]
    if missing:
        raise FileNotFoundError("; ".join(missing))
    out = Path(out) if out is not None else course.root / "_build" / "html"
    work = Path(work) if work is not None else course.root / WORK
    src = work / "src"
    _stage(course, selected, src)
    fingerprint = _fingerprint()
    # The staged copies (book form) are what Sphinx reads, so they are what the cache must hold.
    notebooks = {c.number: src / c.notebook.relative_to(course.root) for c in selected}
    # The kernels draw inline whatever backend the environment names (MPLBACKEND=Agg would draw nothing).
    environment = {COURSE_ENV: str(course.root), STATIC_FRAMES_ENV: str(frames), "MPLBACKEND": INLINE_BACKEND}
    with _environment(**environment):
        cache = _open_cache(work / "jupyter_cache", fingerprint)
        _forget_figureless(cache, notebooks)
        runs = _execute_all(cache, notebooks, timeout, progress)
        failures = {n: run.error for n, run in runs.items() if run.error}
        rel = {c.number: c.notebook.relative_to(course.root).as_posix() for c in selected}
        exercises = [c.exercises.relative_to(course.root).as_posix() for c in selected if c.exercises is not None]
        overrides = {
            "project": course.title,
            "html_title": course.title,
            "include_patterns": ["index.md", NOTATION.name, *rel.values(), *exercises],
            # Exercise notebooks are shown as shipped (their stubs raise); a failed chapter is not run twice.
            "nb_execution_excludepatterns": [*exercises, *(rel[n] for n in failures)],
            "nb_execution_cache_path": str(work / "jupyter_cache"),
            "nb_execution_timeout": int(timeout),
            "cagd_pages": _pages(course, selected, failures),
            "cagd_fingerprint": fingerprint,
            "cagd_output_folder": str(work / "jupyter_execute"),
        }
        run_sphinx(src, out, work / "doctrees", overrides)
    pages = []
    for chapter in selected:
        run, notebook = runs[chapter.number], rel[chapter.number]
        error = f"chapter {chapter.number} ({notebook}): {run.error}" if run.error else ""
        html = Path(notebook).with_suffix(".html").as_posix()
        pages.append(BuiltPage(chapter.number, chapter.title, html, run.seconds, error, run.executed))
        if chapter.exercises is not None:
            html = chapter.exercises.relative_to(course.root).with_suffix(".html").as_posix()
            pages.append(BuiltPage(chapter.number, f"Exercises: {chapter.title}", html, kind="exercises"))
    return pages


def execute_notebooks(
    notebooks: dict[int, Path],
    work: Path | str | None = None,
    timeout: int = 300,
    progress: bool = True,
    frames: int = DEFAULT_FRAMES,
    outputs: dict[int, nbformat.NotebookNode] | None = None,
) -> dict[int, tuple[nbformat.NotebookNode | None, str]]:
    """Chapter notebooks executed as `build_book` executes them, through its execution cache (for `cagd release`).

    notebooks: chapter number -> a chapter notebook of book.toml, or a copy of one (a class release's). Each is
    staged in its book form under `work/executed/chapters` (the book's own sources are left alone) and executed,
    one per core, unless the cache `work/jupyter_cache` holds its execution; the default `work` is the book's
    (`_build/.book`), so what `cagd book` executed is not executed again. outputs: for some chapters, an executed
    notebook with the same code cells whose outputs are recorded in the cache as that notebook's execution
    instead of running it, so a later `build_book` with this `work` finds them. Returns, per chapter, the
    executed code cells (the cache's notebook, book form) and "", or None and which cell failed.
    """
    from jupyter_cache.base import CacheBundleIn

    course = load_course()
    work = Path(work) if work is not None else course.root / WORK
    graded = {c.number: {e.split(".", 1)[1]: e for e in c.exercise_points} for c in course.chapters}
    staged = {}
    for number, path in notebooks.items():
        copy = work / "executed" / "chapters" / Path(path).name
        copy.parent.mkdir(parents=True, exist_ok=True)
        form = _book_form(nbformat.read(path, as_version=4), graded.get(number, {}))
        _write_if_changed(copy, nbformat.writes(form))
        staged[number] = copy
    environment = {COURSE_ENV: str(course.root), STATIC_FRAMES_ENV: str(frames), "MPLBACKEND": INLINE_BACKEND}
    with _environment(**environment):
        cache = _open_cache(work / "jupyter_cache", _fingerprint())
        for number, executed in (outputs or {}).items():
            notebook = nbformat.read(staged[number], as_version=4)
            code = [c for c in notebook.cells if c.cell_type == "code"]
            done = [c for c in executed.cells if c.cell_type == "code"]
            if len(code) != len(done) or any(a.source != b.source for a, b in zip(code, done)):
                raise ValueError(f"outputs of chapter {number}: its code cells are not those of {staged[number]}")
            for cell, ran in zip(code, done):
                cell.outputs, cell.execution_count = ran.get("outputs", []), ran.get("execution_count")
            bundle = CacheBundleIn(notebook, str(staged[number]), data={"execution_seconds": 0.0})
            cache.cache_notebook_bundle(bundle, check_validity=False, overwrite=True)
        _forget_figureless(cache, staged)
        runs = _execute_all(cache, staged, timeout, progress)
    found: dict[int, tuple[nbformat.NotebookNode | None, str]] = {}
    for number, path in staged.items():
        if runs[number].error:
            found[number] = (None, f"chapter {number} ({Path(notebooks[number]).name}): {runs[number].error}")
            continue
        record = cache.match_cache_notebook(nbformat.read(path, as_version=4))
        found[number] = (cache.get_cache_bundle(record.pk).nb, "")
    return found

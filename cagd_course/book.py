"""`cagd book`: execute every chapter of book.toml and write a static HTML book.

Chapters are executed with nbclient (widget state stored, so sliders and their
pictures show in the HTML) and converted with nbconvert; exercise notebooks
are converted as shipped. The table of contents comes from book.toml. A
chapter that fails does not stop the others: its page says what went wrong
and the build reports failure at the end.
"""

from __future__ import annotations

import html
import time
from dataclasses import dataclass
from pathlib import Path

import nbformat
from nbclient import NotebookClient
from nbclient.exceptions import CellExecutionError
from nbconvert import HTMLExporter
from tqdm import tqdm

from .manifest import Chapter, Course, load_course

__all__ = ["BuiltPage", "build_book"]


@dataclass(frozen=True)
class BuiltPage:
    chapter: int
    title: str
    file: str
    seconds: float
    error: str = ""


def _execute(path: Path, timeout: int) -> tuple[nbformat.NotebookNode, float]:
    notebook = nbformat.read(path, as_version=4)
    started = time.monotonic()
    client = NotebookClient(
        notebook,
        timeout=timeout,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
        store_widget_state=True,
    )
    client.execute()
    return notebook, time.monotonic() - started


def _write_html(notebook, target: Path, exporter: HTMLExporter) -> None:
    body, _ = exporter.from_notebook_node(notebook)
    target.write_text(body, encoding="utf-8")


def _build_chapter(chapter: Chapter, out: Path, exporter: HTMLExporter, timeout: int) -> list[BuiltPage]:
    pages = []
    file = f"{chapter.slug}.html"
    try:
        notebook, seconds = _execute(chapter.notebook, timeout)
        _write_html(notebook, out / file, exporter)
        pages.append(BuiltPage(chapter.number, chapter.title, file, seconds))
    except (CellExecutionError, OSError, TimeoutError, RuntimeError) as err:
        message = str(err)
        (out / file).write_text(f"<pre>{html.escape(message)}</pre>", encoding="utf-8")
        pages.append(
            BuiltPage(chapter.number, chapter.title, file, 0.0, message.splitlines()[0] if message else "failed")
        )
    if chapter.exercises is not None:
        exercise_file = f"exercises-{chapter.slug}.html"
        _write_html(nbformat.read(chapter.exercises, as_version=4), out / exercise_file, exporter)
        pages.append(BuiltPage(chapter.number, f"Exercises: {chapter.title}", exercise_file, 0.0))
    return pages


def _index(course: Course, pages: list[BuiltPage]) -> str:
    esc = html.escape
    items = "\n".join(
        f"<li><a href='{esc(p.file)}'>{p.chapter}. {esc(p.title)}</a>"
        + (f" <span class='error'>(failed: {esc(p.error)})</span>" if p.error else "")
        + "</li>"
        for p in pages
    )
    return (
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>"
        f"<title>{esc(course.title)}</title>"
        "<style>body{font-family:system-ui,sans-serif;max-width:50rem;margin:2rem auto;line-height:1.5}"
        ".error{color:#c0392b}</style></head><body>"
        f"<h1>{esc(course.title)}</h1><p>{esc(course.subtitle)}</p>"
        f"<h2>Contents</h2><ol style='list-style:none;padding-left:0'>{items}</ol></body></html>\n"
    )


def build_book(
    out: Path | str = "_build/html", chapters: list[int] | None = None, timeout: int = 300, progress: bool = True
) -> list[BuiltPage]:
    """Execute and convert the chapters (all, or the numbers given) into `out`, with an index page."""
    course = load_course()
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    selected = [c for c in course.chapters if chapters is None or c.number in chapters]
    exporter = HTMLExporter(template_name="lab")
    pages: list[BuiltPage] = []
    for chapter in tqdm(selected, desc="building the book", unit="chapter", disable=None if progress else True):
        pages.extend(_build_chapter(chapter, out, exporter, timeout))
    (out / "index.html").write_text(_index(course, pages), encoding="utf-8")
    return pages

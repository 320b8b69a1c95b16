"""The course manifest `book.toml`: chapters, notebooks, modules and graded exercises.

The course folder (the one holding `book.toml`) is found at run time, so the
package works from an editable or a normal install: `cagd --course DIR` (or the
environment variable CAGD_COURSE) names it; otherwise the working directory and
its parents are searched, then the checkout this package was installed from.
"""

from __future__ import annotations

import os
import sys
from dataclasses import dataclass
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["Chapter", "Course", "load_course", "find_course_root", "COURSE_ENV"]

MANIFEST = "book.toml"
# Set by `cagd --course DIR`; child processes (notebook kernels of the book build) inherit it.
COURSE_ENV = "CAGD_COURSE"


@dataclass(frozen=True)
class Chapter:
    number: int
    title: str
    notebook: Path
    exercises: Path | None
    hidden: Path | None
    modules: tuple[str, ...]
    exercise_points: dict

    @property
    def slug(self) -> str:
        return self.notebook.stem


@dataclass(frozen=True)
class Course:
    title: str
    subtitle: str
    root: Path
    chapters: tuple[Chapter, ...]

    def exercise_points(self) -> dict[str, float]:
        """Every exercise id of the course, in manifest order, with its points."""
        return {eid: pts for ch in self.chapters for eid, pts in ch.exercise_points.items()}

    def chapter_of(self, exercise_id: str) -> Chapter:
        for chapter in self.chapters:
            if exercise_id in chapter.exercise_points:
                return chapter
        raise KeyError(f"unknown exercise {exercise_id!r}; `cagd list` shows the exercise ids")


def find_course_root(start: Path | str | None = None) -> Path:
    """The course folder: $CAGD_COURSE, else the first of `start` (default: the working directory) and
    its parents that holds book.toml, else the checkout this package lives in."""
    named = os.environ.get(COURSE_ENV)
    if named:
        return Path(named).resolve()
    here = Path(start if start is not None else Path.cwd()).resolve()
    for folder in (here, *here.parents):
        if (folder / MANIFEST).is_file():
            return folder
    checkout = Path(__file__).resolve().parent.parent
    if (checkout / MANIFEST).is_file():
        return checkout
    raise FileNotFoundError(
        f"no {MANIFEST} in {here} or its parents: run cagd inside the course folder or pass --course DIR"
    )


def load_course(root: Path | str | None = None) -> Course:
    """Read `book.toml` under `root` (default: `find_course_root()`)."""
    root = Path(root).resolve() if root is not None else find_course_root()
    manifest = root / MANIFEST
    if not manifest.is_file():
        raise FileNotFoundError(f"no {MANIFEST} in {root}: pass the course folder (the one holding {MANIFEST})")
    data = tomllib.loads(manifest.read_text(encoding="utf-8"))
    chapters = []
    for entry in data.get("chapters", []):
        optional = {key: root / entry[key] if key in entry else None for key in ("exercises", "hidden")}
        chapters.append(
            Chapter(
                number=int(entry["number"]),
                title=entry["title"],
                notebook=root / entry["notebook"],
                modules=tuple(entry.get("modules", ())),
                exercise_points=dict(entry.get("exercise_points", {})),
                **optional,
            )
        )
    book = data.get("book", {})
    return Course(book.get("title", "CAGD"), book.get("subtitle", ""), root, tuple(chapters))

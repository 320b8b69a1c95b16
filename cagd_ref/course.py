"""The course manifest `book.toml`: chapters, notebooks, modules and graded exercises."""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["Chapter", "Course", "load_course", "COURSE_ROOT"]

# The course is used from its source checkout (README: editable install), so the
# manifest sits one level above the package.
COURSE_ROOT = Path(__file__).resolve().parent.parent


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


def load_course(root: Path | str | None = None) -> Course:
    """Read `book.toml` under `root` (default: the checkout this package lives in)."""
    root = Path(root) if root is not None else COURSE_ROOT
    manifest = root / "book.toml"
    if not manifest.is_file():
        raise FileNotFoundError(f"no book.toml in {root}: run cagd from the course checkout")
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

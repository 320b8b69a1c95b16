"""Which student handed in which chapter: the folder layouts of nbgrader and of LMS bulk downloads.

Two layouts are understood, and may be mixed:

* a folder per student, as nbgrader collects them: ``SUBMISSIONS/<student>/<NN-slug>.ipynb``, or
  ``SUBMISSIONS/<student>/<assignment>/<notebook>.ipynb`` (nbgrader's ``submitted/`` tree);
* flat files, as an LMS bulk download gives them: Canvas names each file
  ``<name>_<userid>_<submissionid>_<original name>`` (``<name>_LATE_<userid>_...`` when late); any
  other flat file is one student's: the folder's holding it when the file has the course's name
  (``ada/02-bezier-curves.ipynb`` given alone), else named after the file.

Each notebook is graded on its own chapter only. The chapter comes from the metadata the course
writes into every exercise notebook (``metadata.cagd.chapter``, see `stamp_exercise_notebooks`),
else from the file name (and the folders between the student's folder and the file), else from
the notebook's title cell ("Exercises: chapter N"). A notebook whose chapter stays unclear is
reported, never guessed; only an explicit single ``--chapter N`` decides it.
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..manifest import Course

__all__ = [
    "Found",
    "find_submissions",
    "chapter_candidates",
    "stamp_exercise_notebooks",
    "METADATA_KEY",
]

METADATA_KEY = "cagd"
# <name>_<userid>_<submissionid>_<original name>, with LATE after the name for late work (Canvas).
CANVAS = re.compile(r"^(?P<name>[^_/]+?)_(?:(?P<late>LATE)_)?(?P<userid>\d+)_(?P<subid>\d+)_(?P<original>.+)$")
_TITLE = re.compile(r"Exercises:\s*chapter\s+(\d{1,2})\b", re.I)
_LEADING = re.compile(r"^(?:ch(?:apter)?[\s_-]*)?0*(\d{1,2})(?=$|[\s_.-])", re.I)
_ANYWHERE = re.compile(r"(?:^|[^a-z])ch(?:apter)?[\s_-]*0*(\d{1,2})(?!\d)", re.I)


@dataclass
class Found:
    """One notebook found under the submission paths, with whose it is and which chapter it answers.

    `submission` is the key the student's files are kept under in the grades folder (unique per
    student); `student` the name shown, `lms_id` the LMS's user id (Canvas), `chapter` None when
    unclear, then `problem` says why; `how` says where the chapter came from.
    """

    path: Path
    submission: str
    student: str
    lms_id: str = ""
    late: bool = False
    original: str = ""
    chapter: int | None = None
    how: str = ""
    problem: str = ""
    notes: list[str] = field(default_factory=list)
    unclear: str = ""  # why the chapter was unclear, when --chapter decided it


def _safe(name: str) -> str:
    """A folder name for a student key: no separators, no leading dot."""
    cleaned = re.sub(r"[^\w.@+-]+", "-", name.strip()).strip(".-")
    return cleaned or "student"


def _slugs(course: Course) -> dict[str, int]:
    return {c.exercises.stem.lower(): c.number for c in course.chapters if c.exercises is not None}


def chapter_candidates(names: list[str], course: Course) -> set[int]:
    """Chapters the given names (a file name, folder names) point to, by slug or by a leading number."""
    slugs = _slugs(course)
    found: set[int] = set()
    for name in names:
        low = Path(name).stem.lower() if name.lower().endswith(".ipynb") else name.lower()
        by_slug = {number for slug, number in slugs.items() if slug in low}
        if by_slug:
            found |= by_slug
            continue
        match = _LEADING.match(low)
        if match:
            found.add(int(match.group(1)))
        found |= {int(m) for m in _ANYWHERE.findall(low)}
    return found


def _read_notebook(path: Path) -> dict | None:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return None
    return data if isinstance(data, dict) else None


def _metadata_chapter(notebook: dict | None):
    if notebook is None:
        return None
    meta = notebook.get("metadata")
    entry = meta.get(METADATA_KEY) if isinstance(meta, dict) else None
    return entry.get("chapter") if isinstance(entry, dict) else None


def _title_chapters(notebook: dict | None) -> set[int]:
    if notebook is None or not isinstance(notebook.get("cells"), list):
        return set()
    found = set()
    for cell in notebook["cells"]:
        if isinstance(cell, dict) and cell.get("cell_type") == "markdown":
            source = cell.get("source", "")
            text = "".join(source) if isinstance(source, list) else str(source)
            for line in text.splitlines():
                if line.lstrip().startswith("#"):
                    found |= {int(n) for n in _TITLE.findall(line)}
    return found


def _resolve(found: Found, hints: list[str], course: Course, forced: int | None) -> None:
    known = {c.number for c in course.chapters}
    notebook = _read_notebook(found.path)
    stamped = _metadata_chapter(notebook)
    by_name = chapter_candidates(hints, course) & known
    if stamped is not None:
        if isinstance(stamped, int) and not isinstance(stamped, bool) and stamped in known:
            found.chapter, found.how = stamped, "metadata"
            if by_name and stamped not in by_name:
                found.notes.append(f"the file name points to chapter {sorted(by_name)}, its metadata to {stamped}")
            return
        found.problem = f"its metadata names chapter {stamped!r}, which is not a chapter of book.toml"
    elif len(by_name) == 1:
        found.chapter, found.how = next(iter(by_name)), "file name"
        return
    elif by_name:
        found.problem = f"its name points to several chapters ({', '.join(map(str, sorted(by_name)))})"
    else:
        titles = _title_chapters(notebook) & known
        if len(titles) == 1:
            found.chapter, found.how = next(iter(titles)), "title cell"
            return
        if titles:
            found.problem = f"it holds the exercises of several chapters ({', '.join(map(str, sorted(titles)))})"
        elif notebook is None:
            found.problem = "it is not a readable notebook and its name names no chapter"
        else:
            found.problem = "neither its metadata, its name nor its title names a chapter"
    if forced is not None:
        found.chapter, found.how = forced, "--chapter"
        found.notes.append(f"chapter {forced} taken from --chapter: {found.problem}")
        found.unclear, found.problem = found.problem, ""


def _notebooks_below(folder: Path) -> list[Path]:
    """The .ipynb files under `folder`, leaving out hidden folders (.ipynb_checkpoints and the like)."""
    return sorted(
        p for p in folder.rglob("*.ipynb")
        if p.is_file() and not any(part.startswith(".") for part in p.relative_to(folder).parts)
    )


def _flat(path: Path, course: Course) -> tuple[Found, list[str]]:
    """A notebook on its own: a Canvas download's, one named after the course's notebook (then the folder
    holding it is the student's, as when one student's folder is graded), or one named after its student."""
    match = CANVAS.match(path.name)
    if match:
        name, userid = match.group("name"), match.group("userid")
        found = Found(
            path.resolve(), _safe(f"{name}_{userid}"), name, userid, bool(match.group("late")), match.group("original")
        )
        return found, [match.group("original")]
    if chapter_candidates([path.name], course):
        folder = path.resolve().parent.name
        return Found(path.resolve(), _safe(folder), folder, original=path.name), [path.name]
    return Found(path.resolve(), _safe(path.stem), path.stem, original=path.name), [path.name]


def find_submissions(paths, course: Course, chapters: list[int] | None = None) -> list[Found]:
    """Every notebook under `paths` (files, folders of either layout) with its student and chapter.

    A single entry in `chapters` decides the chapter of notebooks whose own is unclear.
    """
    forced = chapters[0] if chapters and len(chapters) == 1 else None
    entries: list[tuple[Found, list[str]]] = []
    for path in map(Path, paths):
        if path.is_file():
            entries.append(_flat(path, course))
        elif path.is_dir():
            for file in _notebooks_below(path):
                parts = file.relative_to(path).parts
                if len(parts) == 1:
                    entries.append(_flat(file, course))
                else:
                    student = parts[0]
                    found = Found(file.resolve(), _safe(student), student, original=file.name)
                    entries.append((found, list(parts[1:])))
        else:
            raise FileNotFoundError(f"no such file or folder: {path}")
    seen: dict[Path, Found] = {}
    for found, hints in entries:
        if found.path in seen:
            continue
        _resolve(found, hints, course, forced)
        seen[found.path] = found
    return list(seen.values())


def stamp_exercise_notebooks(course: Course, check: bool = False) -> list[Path]:
    """Write ``metadata.cagd.chapter`` into every exercise notebook of book.toml; return those changed.

    With `check`, change nothing and return the notebooks that lack it (or carry a wrong one).
    Notebooks are rewritten the way nbformat stores them (the course keeps them without outputs).
    """
    import nbformat

    changed = []
    for chapter in course.chapters:
        path = chapter.exercises
        if path is None or not path.is_file():
            continue
        notebook = nbformat.read(path, as_version=4)
        entry = notebook.metadata.get(METADATA_KEY, {})
        if isinstance(entry, dict) and entry.get("chapter") == chapter.number:
            continue
        changed.append(path)
        if check:
            continue
        notebook.metadata[METADATA_KEY] = {**(entry if isinstance(entry, dict) else {}), "chapter": chapter.number}
        text = nbformat.writes(notebook) + "\n"
        temporary = path.with_name(f".{path.name}.stamp")
        temporary.write_text(text, encoding="utf-8")
        temporary.replace(path)
    return changed

"""The semester's gradebook: one record per student and chapter, and the CSV views made from them.

Grading writes one record per graded notebook, ``GRADES/<submission>/chNN/record.json``, next to
that notebook's feedback; the records are the truth. ``GRADES/gradebook.csv`` (one row per
student, a column per exercise graded so far, a total per chapter and overall) is rebuilt from
them (in time proportional to the records: `gradebook_text` makes one pass), so grading chapter 4
later adds its columns and keeps the others, and re-grading one student's chapter changes only
that student's cells. Every file is written atomically (temporary file, then rename); a run
interrupted between a record and the gradebook leaves a gradebook the next run rebuilds. One
grading run at a time holds ``GRADES/.lock``.

Columns: ``submission`` (the student's key, also their folder in GRADES), ``score`` and
``max_score`` (overall, of the chapters graded so far), ``status``, ``student``, ``id`` (the LMS
user id), then per chapter ``chNN total``, ``chNN max``, ``chNN status``, ``chNN late``,
``chNN seed`` and its exercises, and last ``confinement``. Cells of a chapter a student has not
handed in are blank.
"""

from __future__ import annotations

import csv
import fcntl
import io
import json
import os
import tempfile
from contextlib import contextmanager
from pathlib import Path

__all__ = [
    "GRADEBOOK",
    "atomic_write",
    "chapter_folder",
    "exclusive",
    "gradebook_header",
    "gradebook_text",
    "load_records",
    "number",
    "read_gradebook",
    "read_unassigned",
    "write_record",
    "UNASSIGNED",
]

GRADEBOOK = "gradebook.csv"
UNASSIGNED = "unassigned.csv"
RECORD = "record.json"


def atomic_write(path: Path, text: str) -> None:
    """Write a file so that readers see the old or the new content, never half of it."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


@contextmanager
def exclusive(out: Path):
    """Hold the grades folder for one run; a second run at the same time is refused with a clear error."""
    out.mkdir(parents=True, exist_ok=True)
    handle = open(out / ".lock", "w")
    try:
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise RuntimeError(f"another grading run is writing {out}; wait for it to finish") from None
        yield
    finally:
        handle.close()


def number(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".") if value else "0"


def chapter_folder(out: Path, submission: str, chapter: int) -> Path:
    return Path(out) / submission / f"ch{chapter:02d}"


def write_record(out: Path, record: dict) -> None:
    folder = chapter_folder(out, record["submission"], record["chapter"])
    atomic_write(folder / RECORD, json.dumps(record, indent=1, sort_keys=True) + "\n")


def load_records(out: Path) -> dict[tuple[str, int], dict]:
    """Every record under the grades folder, by (submission, chapter)."""
    records = {}
    for path in sorted(Path(out).glob(f"*/ch[0-9][0-9]/{RECORD}")):
        try:
            record = json.loads(path.read_text(encoding="utf-8"))
            records[(record["submission"], int(record["chapter"]))] = record
        except (OSError, ValueError, KeyError, TypeError):
            continue  # a stray or damaged file: that chapter is graded again
    return records


def _chapter_order(records, course) -> list[int]:
    graded = {chapter for _, chapter in records}
    listed = [c.number for c in course.chapters if c.number in graded]
    return listed + sorted(graded - set(listed))


def _exercise_ids(records, course) -> dict[int, list[str]]:
    """Per graded chapter, the exercise ids graded so far: book.toml's order, then any others sorted (one pass)."""
    seen: dict[int, set[str]] = {}
    for (_, chapter), record in records.items():
        seen.setdefault(chapter, set()).update(record["exercises"])
    ids = {}
    for chapter, found in seen.items():
        listed = next((list(c.exercise_points) for c in course.chapters if c.number == chapter), [])
        ids[chapter] = [eid for eid in listed if eid in found] + sorted(found - set(listed))
    return ids


def gradebook_header(records, course, ids: dict[int, list[str]] | None = None) -> list[str]:
    ids = _exercise_ids(records, course) if ids is None else ids
    header = ["submission", "score", "max_score", "status", "student", "id"]
    for chapter in _chapter_order(records, course):
        tag = f"ch{chapter:02d}"
        header += [f"{tag} total", f"{tag} max", f"{tag} status", f"{tag} late", f"{tag} seed"]
        header += ids[chapter]
    return header + ["confinement"]


def _overall_status(mine: list[dict]) -> str:
    parts = []
    for record in mine:
        if record["status"] == "ok":
            continue
        prefix = f"{record['chapter']:02d}."
        own = record["status"].startswith(prefix) and len(mine) > 1 or len(mine) == 1
        parts.append(record["status"] if own else f"chapter {record['chapter']}: {record['status']}")
    return "; ".join(parts) if parts else "ok"


def gradebook_text(records: dict[tuple[str, int], dict], course) -> str:
    """The wide gradebook: one row per student, sorted by submission key; blank cells where nothing was handed in."""
    chapters = _chapter_order(records, course)
    position = {chapter: i for i, chapter in enumerate(chapters)}
    ids_of = _exercise_ids(records, course)
    maxima = {}
    for (_, chapter), record in records.items():
        maxima[chapter] = max(maxima.get(chapter, 0.0), float(record["max_score"]))
    by_student: dict[str, list[dict]] = {}
    for (submission, _), record in sorted(records.items()):
        by_student.setdefault(submission, []).append(record)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(gradebook_header(records, course, ids_of))
    for submission, mine in sorted(by_student.items()):
        mine.sort(key=lambda r: position[r["chapter"]])
        first = mine[0]
        total = round(sum(float(r["score"]) for r in mine), 4)
        row = [submission, number(total), number(round(sum(maxima.values()), 4)), _overall_status(mine),
               first["student"], first.get("lms_id", "")]
        have = {r["chapter"]: r for r in mine}
        for chapter in chapters:
            ids = ids_of[chapter]
            record = have.get(chapter)
            if record is None:
                row += ["", number(maxima[chapter]), "", "", ""] + [""] * len(ids)
                continue
            row += [number(float(record["score"])), number(float(record["max_score"])), record["status"],
                    "LATE" if record.get("late") else "", str(record["seed"])]
            row += [number(float(record["exercises"][eid]["score"])) if eid in record["exercises"] else ""
                    for eid in ids]
        sandboxes = list(dict.fromkeys(r.get("sandbox", "") for r in mine if r.get("sandbox")))
        row.append(" | ".join(sandboxes))
        writer.writerow(row)
    return buffer.getvalue()


def read_gradebook(path: Path) -> dict[str, list[str]]:
    """Rows of an existing gradebook by submission key (its first column; then score, max_score, status)."""
    path = Path(path)
    if not path.is_file():
        return {}
    with path.open(encoding="utf-8", newline="") as handle:
        rows = list(csv.reader(handle))
    return {row[0]: row for row in rows[1:] if row}


def read_unassigned(out: Path) -> list[dict]:
    path = Path(out) / UNASSIGNED
    if not path.is_file():
        return []
    with path.open(encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


def unassigned_text(rows: list[dict]) -> str:
    buffer = io.StringIO()
    writer = csv.DictWriter(buffer, ["submission", "file", "reason"], lineterminator="\n")
    writer.writeheader()
    for row in sorted(rows, key=lambda r: (r["submission"], r["file"])):
        writer.writerow(row)
    return buffer.getvalue()

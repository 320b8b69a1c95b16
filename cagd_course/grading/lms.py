"""Grades out to a learning-management system: Canvas's gradebook import, and a plain long CSV.

Canvas imports a CSV whose first columns are Student, ID, SIS User ID, SIS Login ID and Section,
followed by one column per assignment, and whose second row may give each assignment's points
possible. A column named like an existing assignment, "Title (assignment id)", updates it; any
other name makes a new assignment. Students are matched by Canvas's user ID, which the file names
of a Canvas bulk download carry; for the folder-per-student layout, give a roster (Canvas's own
gradebook export) and students are matched by ID, SIS Login ID, SIS User ID or name.
"""

from __future__ import annotations

import csv
import io
import re
from pathlib import Path

from .gradebook import atomic_write, load_records

__all__ = ["CANVAS_COLUMNS", "canvas_csv", "long_csv", "export"]

CANVAS_COLUMNS = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"]
POINTS_ROW = "    Points Possible"


def _number(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".") if value else "0"


def _key(text: str) -> str:
    return re.sub(r"[^a-z0-9]", "", text.lower())


def _read_roster(path: Path) -> tuple[list[dict], list[str]]:
    with Path(path).open(encoding="utf-8-sig", newline="") as handle:
        reader = csv.DictReader(handle)
        rows = [r for r in reader if r.get("Student", "").strip() and "Points Possible" not in r.get("Student", "")]
        missing = [c for c in CANVAS_COLUMNS[:2] if c not in (reader.fieldnames or [])]
        if missing:
            raise ValueError(f"{path}: a Canvas gradebook export has the columns {CANVAS_COLUMNS}; missing {missing}")
        return rows, list(reader.fieldnames or [])


def _match(record: dict, roster: list[dict]) -> dict | None:
    for row in roster:
        if record.get("lms_id") and row.get("ID", "").strip() == record["lms_id"]:
            return row
    for column in ("SIS Login ID", "SIS User ID"):
        for row in roster:
            if row.get(column, "").strip() and row[column].strip() in (record["submission"], record["student"]):
                return row
    wanted = _key(record["student"])
    names = [row for row in roster if wanted in (_key(row["Student"]), _key(" ".join(row["Student"].split(",")[::-1])))]
    return names[0] if len(names) == 1 else None


def _assignment_names(course, chapters: list[int], roster_columns: list[str]) -> dict[int, str]:
    """Column name per chapter: an existing Canvas assignment "Chapter N..." ("... (id)") if the roster has one."""
    titles = {c.number: c.title for c in course.chapters}
    names = {}
    for chapter in chapters:
        own = f"Chapter {chapter}: {titles.get(chapter, 'exercises')}"
        existing = [c for c in roster_columns if re.match(rf"^(?:chapter|ch)\s*0*{chapter}\b", c.strip(), re.I)]
        names[chapter] = existing[0] if len(existing) == 1 else own
    return names


def canvas_csv(out: Path, course, roster: Path | None = None) -> tuple[str, list[str]]:
    """The Canvas import CSV of the grades folder, and the students it could not match to the roster."""
    records = load_records(out)
    order = {c.number: i for i, c in enumerate(course.chapters)}
    chapters = sorted({ch for _, ch in records}, key=lambda c: order.get(c, 100 + c))
    roster_rows, roster_columns = _read_roster(roster) if roster else ([], [])
    names = _assignment_names(course, chapters, roster_columns)
    maxima = {ch: max(float(r["max_score"]) for (_, c), r in records.items() if c == ch) for ch in chapters}
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(CANVAS_COLUMNS + [names[ch] for ch in chapters])
    writer.writerow([POINTS_ROW, "", "", "", ""] + [_number(maxima[ch]) for ch in chapters])
    unmatched = []
    by_student: dict[str, dict[int, dict]] = {}
    for (submission, chapter), record in records.items():
        by_student.setdefault(submission, {})[chapter] = record
    for submission, mine in sorted(by_student.items()):
        first = next(iter(mine.values()))
        row = _match(first, roster_rows) if roster_rows else None
        if roster_rows and row is None:
            unmatched.append(submission)
        ident = [row.get(c, "") for c in CANVAS_COLUMNS] if row else [first["student"], first.get("lms_id", ""), "",
                                                                        "" if first.get("lms_id") else submission, ""]
        writer.writerow(ident + [_number(float(mine[ch]["score"])) if ch in mine else "" for ch in chapters])
    return buffer.getvalue(), unmatched


def long_csv(out: Path, course) -> str:
    """One line per student, chapter and exercise: student, chapter, exercise, score, max, status."""
    records = load_records(out)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["student", "chapter", "exercise", "score", "max", "status"])
    ids = {c.number: list(c.exercise_points) for c in course.chapters}
    for (submission, chapter), record in sorted(records.items()):
        listed = ids.get(chapter, [])
        exercises = [e for e in listed if e in record["exercises"]] + sorted(set(record["exercises"]) - set(listed))
        if not exercises:  # nothing ran (an unreadable notebook): one line per exercise of the chapter, scored 0
            exercises = listed
        for eid in exercises:
            result = record["exercises"].get(eid)
            status = record["status"] if result is None else (result.get("stopped") or "ok")
            points = result["points"] if result else course.exercise_points().get(eid, 0)
            writer.writerow([submission, chapter, eid, _number(float(result["score"]) if result else 0.0),
                             _number(float(points)), status])
    return buffer.getvalue()


def export(out: Path, course, canvas: Path | None = None, long: Path | None = None, roster: Path | None = None):
    """Write the requested files; return (files written, students the roster did not know)."""
    out = Path(out)
    if not any(out.glob("*/ch[0-9][0-9]/record.json")):
        raise FileNotFoundError(f"{out} holds no graded notebooks: grade with `cagd grade SUBMISSIONS --out {out}`")
    written, unmatched = [], []
    if canvas is not None:
        text, unmatched = canvas_csv(out, course, roster)
        atomic_write(Path(canvas), text)
        written.append(Path(canvas))
    if long is not None:
        atomic_write(Path(long), long_csv(out, course))
        written.append(Path(long))
    return written, unmatched

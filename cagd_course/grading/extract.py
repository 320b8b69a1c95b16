"""From a submitted notebook to the statements that are graded: top-level imports and definitions.

A student's notebook is full of experiments, prints and calls to `check`. Only
the top-level ``def``/``class`` statements and imports of its code cells are
kept, in cell order, wherever they stand; a later definition replaces an
earlier one, as it would when the cells run top to bottom. Cells that do not
parse (work in progress, IPython magics) are skipped line by line where
possible, and every skipped piece is reported back to the student.
"""

from __future__ import annotations

import ast
import json
from dataclasses import dataclass, field
from pathlib import Path

from .worker import PACKAGES

__all__ = ["Submission", "SubmissionError", "extract_notebook", "extract_source"]

KEPT = (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Import, ast.ImportFrom)


class SubmissionError(Exception):
    """The notebook itself cannot be read (not JSON, not a notebook, no code)."""

    def __init__(self, status: str, detail: str):
        super().__init__(f"{status}: {detail}")
        self.status = status
        self.detail = detail


@dataclass
class Submission:
    """The graded part of a submission: top-level statements, each with where it stands in the notebook."""

    statements: list[dict]
    skipped: list[str] = field(default_factory=list)

    def defined_names(self) -> set[str]:
        names = set()
        for statement in self.statements:
            for node in ast.parse(statement["source"]).body:
                if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                    names.add(node.name)
        return names


def _course_package(node: ast.stmt) -> str | None:
    """The course package (cagd_ref or cagd_course) an import statement reaches for, if any."""
    if isinstance(node, ast.ImportFrom):
        names = [node.module or ""] if not node.level else []
    elif isinstance(node, ast.Import):
        names = [alias.name for alias in node.names]
    else:
        return None
    return next((name.partition(".")[0] for name in names if name.partition(".")[0] in PACKAGES), None)


# What the exercise notebooks themselves import from the course: the self-check and the notes' examples.
NOTEBOOK_IMPORTS = {"cagd_course": {"check"}, "cagd_course.examples": {"notes_example", "notes_examples"}}


def _is_notebook_import(node: ast.stmt) -> bool:
    """An import the exercise notebooks make themselves (dropped without a note, like every course import)."""
    return isinstance(node, ast.ImportFrom) and {a.name for a in node.names} <= NOTEBOOK_IMPORTS.get(node.module, set())


def _without_magics(source: str) -> str:
    # IPython magics and shell escapes are not Python; blank them so line numbers stay right.
    return "\n".join("" if line.lstrip().startswith(("%", "!")) else line for line in source.splitlines())


def extract_source(cells: list[str]) -> Submission:
    """Keep top-level imports and definitions of each code cell's source, in order."""
    statements, skipped = [], []
    for number, source in enumerate(cells, start=1):
        text = _without_magics(source)
        try:
            tree = ast.parse(text)
        except SyntaxError as err:
            skipped.append(f"code cell {number} does not parse (line {err.lineno}: {err.msg}); it was ignored")
            continue
        lines = text.splitlines()
        for node in tree.body:
            if not isinstance(node, KEPT):
                continue
            package = _course_package(node)
            if package is not None:
                if not _is_notebook_import(node):
                    skipped.append(f"code cell {number}: importing {package} is not allowed in graded code; ignored")
                continue
            start = min([node.lineno] + [d.lineno for d in getattr(node, "decorator_list", [])])
            body = "\n".join(lines[start - 1 : node.end_lineno])
            statements.append({"source": body, "where": f"code cell {number}, line {start}"})
    return Submission(statements, skipped)


def extract_notebook(path: Path | str) -> Submission:
    """Read a .ipynb file and keep its graded statements; raise SubmissionError if it is unreadable."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except OSError as err:
        raise SubmissionError("unreadable file", str(err)) from None
    try:
        notebook = json.loads(raw.decode("utf-8"))
    except (UnicodeDecodeError, json.JSONDecodeError) as err:
        raise SubmissionError("invalid notebook (not valid JSON)", str(err)[:200]) from None
    if not isinstance(notebook, dict) or not isinstance(notebook.get("cells"), list):
        raise SubmissionError("invalid notebook (no list of cells)", "the file is JSON but not a Jupyter notebook")
    cells = []
    for cell in notebook["cells"]:
        if isinstance(cell, dict) and cell.get("cell_type") == "code":
            source = cell.get("source", "")
            cells.append("".join(source) if isinstance(source, list) else str(source))
    if not any(source.strip() for source in cells):
        raise SubmissionError("no code", "the notebook has no code cells with content")
    submission = extract_source(cells)
    if not submission.statements:
        raise SubmissionError("nothing defined", "no top-level def or import was found in the code cells")
    return submission

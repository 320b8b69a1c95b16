"""Root of the test session: every figure the chapter notebooks draw under nbval is checked for legibility.

The kernels nbval starts inherit IPYTHONDIR, whose start-up file makes each kernel check the figures it
displays (`cagd_course.figure_check`) into a report file; after each cell of a chapter notebook, the
findings that cell produced fail it, naming the notebook, the cell and the colliding strings. A chapter cell
that writes to stderr (a warning, a log line: the book would show it) fails too.
(A conftest under tests/ would not see the notebooks in chapters/.)
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

import pytest

from cagd_course.figure_check import REPORT_ENV, checking_environment, read_report

_FOLDER = Path(tempfile.mkdtemp(prefix="cagd-figure-check-"))
REPORT = _FOLDER / "report.jsonl"
# Only what the kernels need: the pytest process itself keeps its own matplotlib backend.
_environment = checking_environment(_FOLDER / "ipython", REPORT)
for _name in ("IPYTHONDIR", REPORT_ENV):
    os.environ[_name] = _environment[_name]


def _is_chapter_cell(item) -> bool:
    path = Path(str(getattr(item, "path", "")))
    return path.suffix == ".ipynb" and path.parent.name == "chapters"


@pytest.hookimpl(wrapper=True)
def pytest_runtest_call(item):
    if not _is_chapter_cell(item):
        return (yield)
    seen = len(read_report(REPORT))
    result = yield
    where = f"{Path(str(item.path)).name} {item.name}"
    findings = [finding for record in read_report(REPORT)[seen:] for finding in record["findings"]]
    if findings:
        raise AssertionError(f"{where}: figures a reader cannot read\n- " + "\n- ".join(findings))
    # The book shows a cell's stderr: a chapter prints no warning or log line a reader would have to skip.
    stderr = "".join(out.get("text", "") for out in item.test_outputs or [] if out.get("name") == "stderr")
    if stderr.strip():
        raise AssertionError(f"{where}: writes to stderr, which the book would show:\n{stderr.strip()[:600]}")
    return result

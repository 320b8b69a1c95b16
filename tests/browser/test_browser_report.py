"""The class report as an instructor opens it: `GRADES/report.html` from file://, with no network, in Chromium."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

from cagd_course.book.browser import keep_inside
from cagd_course.grading.classroom import grade_class
from cagd_course.grading.runner import Limits

expect = pytest.importorskip("playwright.sync_api").expect
FIXTURES = Path(__file__).resolve().parents[1] / "grading" / "fixtures"
spec = importlib.util.spec_from_file_location("semester", FIXTURES / "semester.py")
semester = importlib.util.module_from_spec(spec)
spec.loader.exec_module(semester)


@pytest.fixture(scope="module")
def grades(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("class")
    semester.write(root / "ada" / "01-introduction.ipynb", semester.chapter_notebook(1))
    semester.write(root / "ada" / "02-bezier-curves.ipynb", semester.chapter_notebook(2))
    semester.write(root / "bob" / "01-introduction.ipynb", semester.chapter_notebook(1))  # a copy of ada's
    semester.write(root / "cy" / "01-introduction.ipynb", semester.stub_notebook(1))
    semester.write(root / "cy" / "02-bezier-curves.ipynb", "{ not json")
    out = tmp_path_factory.mktemp("grades")
    grade_class([root], out, limits=Limits(exercise_seconds=5, submission_seconds=60), progress=False)
    return out


def test_the_class_report_opens_offline_with_every_section(page, grades, artefacts):
    outside = keep_inside(page, grades)
    page.goto((grades / "report.html").as_uri())
    expect(page.locator("h1")).to_contain_text("Class report")
    for heading in ("Scores", "Hidden case categories failed most often", "Slowest exercises",
                    "Notebooks that did not run cleanly", "Graded functions with the same code"):
        expect(page.get_by_role("heading", name=heading)).to_be_visible()
    # A histogram per chapter and per exercise, drawn (bars with a size) and labelled.
    assert page.locator("figure.histogram[data-kind='chapter']").count() == 2
    assert page.locator("figure.histogram[data-kind='exercise']").count() == 15
    box = page.locator("figure.histogram[data-key='1'] svg").bounding_box()
    assert box["width"] > 200 and box["height"] > 100
    expect(page.locator("table.unclean")).to_contain_text("invalid notebook (not valid JSON)")
    expect(page.locator("table.similar")).to_contain_text("bob")
    page.screenshot(path=str(artefacts / "class-report.png"), full_page=True)
    assert outside == [] and page.errors == []

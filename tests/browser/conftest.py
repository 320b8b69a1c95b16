"""Browser tests: the built book opened from file://, and the course in JupyterLab, both in headless Chromium.

Playwright drives the system's Chromium (`apt-get install chromium`; `./course test` installs it where it can).
Without Chromium or playwright the tests skip and say how to enable them, except in CI (CI set), where they must
run and fail instead.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from cagd_course.book.browser import HOW_TO_GET_IT, chromium_executable, launch

ROOT = Path(__file__).resolve().parents[2]
# Screenshots the tests take, for a person (or CI's artefacts) to look at.
ARTEFACTS = Path(os.environ.get("CAGD_TEST_ARTEFACTS", ROOT / "_build" / "test-artefacts"))


def _unavailable(reason: str):
    if os.environ.get("CI"):
        pytest.fail(f"{reason}: CI must run the browser tests (.ci/run installs Chromium through ./course test)")
    pytest.skip(f"{reason}; to run the browser tests, {HOW_TO_GET_IT}")


@pytest.fixture(scope="session")
def browser():
    """Headless Chromium for the session."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _unavailable("the Python package playwright is not installed")
    if chromium_executable() is None:
        _unavailable("no Chromium found")
    with sync_playwright() as playwright:
        chromium = launch(playwright)
        yield chromium
        chromium.close()


@pytest.fixture
def page(browser):
    """A fresh page (own context: no cookies, storage or routes shared between tests) that collects its errors."""
    context = browser.new_context(viewport={"width": 1280, "height": 900})
    page = context.new_page()
    page.errors = []
    page.on("pageerror", lambda error: page.errors.append(str(error)))
    yield page
    context.close()


@pytest.fixture(scope="session")
def artefacts() -> Path:
    ARTEFACTS.mkdir(parents=True, exist_ok=True)
    return ARTEFACTS

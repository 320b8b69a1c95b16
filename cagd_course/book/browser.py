"""Headless Chromium for the book (its PDF and the browser tests): where it is, how it starts, what it may load.

Playwright drives the system's Chromium (Debian's `chromium` package), since
`playwright install` cannot download browsers everywhere: CAGD_CHROMIUM names
the executable, else `chromium`, `chromium-browser` or `google-chrome` on the
PATH.
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from urllib.parse import unquote, urlparse

__all__ = [
    "CHROMIUM_ENV",
    "LAUNCH_ARGS",
    "BrowserMissing",
    "chromium_executable",
    "launch",
    "keep_inside",
    "wait_until_typeset",
]

CHROMIUM_ENV = "CAGD_CHROMIUM"
LAUNCH_ARGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)
HOW_TO_GET_IT = (
    "install Chromium (Debian/Ubuntu: `sudo apt-get install chromium`) or name an executable in "
    f"{CHROMIUM_ENV}, and the Python package playwright (the course's test extra has it)"
)


class BrowserMissing(RuntimeError):
    """No Chromium or no playwright here; the message says how to get them."""


def chromium_executable() -> str | None:
    """The Chromium to drive: $CAGD_CHROMIUM, else the first Chromium or Chrome on the PATH, else None."""
    named = os.environ.get(CHROMIUM_ENV)
    if named:
        return named if Path(named).is_file() else None
    for name in ("chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(name)
        if found:
            return found
    return None


def launch(playwright):
    """Start headless Chromium through a running `sync_playwright()`; BrowserMissing if there is none."""
    executable = chromium_executable()
    if executable is None:
        raise BrowserMissing(f"no Chromium found: {HOW_TO_GET_IT}")
    return playwright.chromium.launch(executable_path=executable, args=list(LAUNCH_ARGS), headless=True)


def _inside(url: str, folder: Path) -> bool:
    parsed = urlparse(url)
    if parsed.scheme in ("data", "blob", "about"):
        return True
    if parsed.scheme != "file":
        return False
    return Path(unquote(parsed.path)).resolve().is_relative_to(folder)


def keep_inside(page, folder: Path | str) -> list[str]:
    """Block every request of `page` (or a browser context) that leaves `folder`; return the list it records them in.

    Only file:// URLs inside the folder (and data:, blob:, about: URLs) load.
    """
    folder = Path(folder).resolve()
    outside: list[str] = []

    def handle(route) -> None:
        url = route.request.url
        if _inside(url, folder):
            route.continue_()
        else:
            outside.append(url)
            route.abort()

    page.route("**/*", handle)
    return outside


def wait_until_typeset(page, timeout_ms: float = 60_000) -> None:
    """Wait until MathJax (on pages that load it) has typeset the page and the web fonts have loaded."""
    page.wait_for_function(
        "() => !window.MathJax || (window.MathJax.startup && window.MathJax.startup.promise)", timeout=timeout_ms
    )
    page.evaluate("() => window.MathJax ? window.MathJax.startup.promise.then(() => true) : true")
    page.evaluate("() => document.fonts.ready.then(() => true)")

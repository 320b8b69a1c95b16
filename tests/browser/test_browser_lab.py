"""Chapter 2 in JupyterLab, as a student uses it: run every cell, move a slider with the keyboard, drag a point.

A JupyterLab server is started for the test on 127.0.0.1 (a free port, a random token) in a folder of its own
holding a copy of the chapter, so nothing the test does reaches the course's notebooks; it is always stopped.
"""

from __future__ import annotations

import json
import os
import re
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import nbformat
import numpy as np
import pytest

from cagd_course.manifest import load_course

expect = pytest.importorskip("playwright.sync_api").expect

COURSE = load_course(Path(__file__).resolve().parents[2])
CHAPTER_2 = next(c for c in COURSE.chapters if c.number == 2)

# JupyterLab settings for the test: every cell in the page (no windowing, so all outputs can be inspected) and
# no news or update checks (nothing leaves the machine).
SETTINGS = {
    "@jupyterlab/notebook-extension/tracker": {"windowingMode": "none"},
    "@jupyterlab/apputils-extension/notification": {"fetchNews": "false", "checkForUpdates": False},
}
# Every code cell whose input shows has its execution count (collapsed cells show no prompt).
ALL_RUN = """() => {
  const prompts = [...document.querySelectorAll(".jp-CodeCell")]
    .filter(cell => !cell.querySelector(".jp-InputPlaceholder"))
    .map(cell => cell.querySelector(".jp-InputPrompt").textContent.trim());
  return prompts.length > 0 && prompts.every(p => /^\\[\\d+\\]:$/.test(p));
}"""


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def _wait_until_up(url: str, process: subprocess.Popen, log: Path, seconds: float = 90) -> None:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if process.poll() is not None:
            pytest.fail(f"JupyterLab exited with {process.returncode}:\n{log.read_text()[-3000:]}")
        try:
            with urllib.request.urlopen(url, timeout=2) as response:
                if response.status == 200:
                    return
        except OSError:
            time.sleep(0.5)
    pytest.fail(f"JupyterLab did not answer within {seconds} s:\n{log.read_text()[-3000:]}")


def _stop(process: subprocess.Popen) -> None:
    """Stop the server (it shuts its kernels down on SIGTERM), then anything left of its process group."""
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            pass
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    process.wait(timeout=10)


@pytest.fixture(scope="module")
def lab(tmp_path_factory, browser):
    """A JupyterLab server on a free port of 127.0.0.1 with a token: (base URL, token). Stopped afterwards."""
    home = tmp_path_factory.mktemp("lab")
    root = home / "root"
    (root / "chapters").mkdir(parents=True)
    shutil.copy(CHAPTER_2.notebook, root / "chapters" / CHAPTER_2.notebook.name)
    for plugin, values in SETTINGS.items():
        path = home / "settings" / f"{plugin}.jupyterlab-settings"
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values))
    port, token = _free_port(), secrets.token_hex(16)
    env = dict(
        os.environ,
        CAGD_COURSE=str(COURSE.root),
        JUPYTER_CONFIG_DIR=str(home / "config"),
        JUPYTER_RUNTIME_DIR=str(home / "runtime"),
        JUPYTERLAB_SETTINGS_DIR=str(home / "settings"),
        JUPYTERLAB_WORKSPACES_DIR=str(home / "workspaces"),
    )
    log = home / "server.log"
    command = [
        sys.executable, "-m", "jupyterlab", "--no-browser",
        "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={port}", "--ServerApp.port_retries=0",
        f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={root}",
        # CI and containers run as root; the server refuses that unless told.
        "--ServerApp.allow_root=True",
    ]  # fmt: skip
    with open(log, "w") as output:
        process = subprocess.Popen(command, env=env, stdout=output, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        base = f"http://127.0.0.1:{port}"
        _wait_until_up(f"{base}/api/status?token={token}", process, log)
        yield base, token
    finally:
        _stop(process)


def _cell(page, text: str):
    """The code cell whose source contains `text`."""
    return page.locator(".jp-CodeCell").filter(has=page.locator(".jp-InputArea", has_text=text)).first


def _slider_value(cell, name: str) -> float:
    label = cell.page.locator("label", has_text=re.compile(f"^{re.escape(name)}$"))
    slider = cell.locator(".widget-slider").filter(has=label).first
    # The readout, not the handle's aria-valuenow: ipywidgets leaves that at the value it was drawn with.
    return float(slider.locator(".widget-readout").inner_text())


def _eventually(check, page, seconds: float = 15) -> bool:
    """Whether `check()` becomes true within `seconds` (the kernel answers each move asynchronously)."""
    deadline = time.monotonic() + seconds
    while not check():
        if time.monotonic() > deadline:
            return False
        page.wait_for_timeout(100)
    return True


def _canvas_point(cell, points: np.ndarray, index: int) -> tuple[float, float]:
    """Where control point `index` is drawn on the editor's canvas, in page pixels.

    The editor lays its axes out in fixed figure fractions, so the same editor drawn here (Agg, no kernel) has
    the same transform as the one in the browser.
    """
    from cagd_course.widgets import control_point_editor

    twin = control_point_editor(points=points, draggable=False)
    twin.figure.canvas.draw()
    x, y = twin.ax.transData.transform(points[index])
    width, height = twin.figure.bbox.width, twin.figure.bbox.height
    box = cell.locator(".jupyter-matplotlib-canvas-div canvas").first.bounding_box()
    return box["x"] + x * box["width"] / width, box["y"] + (height - y) * box["height"] / height


def test_chapter_2_runs_in_jupyterlab_and_its_explorers_respond(lab, browser, artefacts):
    base, token = lab
    context = browser.new_context(viewport={"width": 1400, "height": 1000})
    outside = []

    def only_the_server(route):
        if route.request.url.startswith((base, "data:", "blob:")):
            route.continue_()
        else:
            outside.append(route.request.url)
            route.abort()

    context.route("**/*", only_the_server)
    page = context.new_page()
    try:
        page.goto(f"{base}/lab/tree/chapters/{CHAPTER_2.notebook.name}?token={token}")
        page.wait_for_selector(".jp-Notebook .jp-CodeCell", timeout=60_000)
        # The kernel is up (the status bar says so) before the notebook is run.
        expect(page.locator("#jp-main-statusbar")).to_contain_text("Idle", timeout=60_000)
        page.locator(".jp-Notebook .jp-Cell").first.click()
        page.locator("#jp-MainMenu").get_by_role("menuitem", name="Run", exact=True).click()
        page.locator("li[data-command='runmenu:run-all']").click()
        try:
            page.wait_for_function(ALL_RUN, timeout=240_000)
        finally:
            page.screenshot(path=artefacts / "lab-chapter-02.png")
        stderr = page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']")
        errors = [text for text in stderr.all_inner_texts() if "Error" in text or "Traceback" in text]
        assert errors == []

        # The reading form: setup, check, figure and reference cells are collapsed to their first line, and the
        # chapter's algorithm boxes, definitions and questions are rendered by jupyterlab-myst, not shown as source.
        hidden = [c for c in nbformat.read(CHAPTER_2.notebook, as_version=4).cells if c.cell_type == "code"
                  and c.metadata.get("jupyter", {}).get("source_hidden")]
        expect(page.locator(".jp-InputPlaceholder")).to_have_count(len(hidden))
        for kind in ("Algorithm", "Definition", "Theorem", "Exercise"):
            expect(page.locator(f".jp-MarkdownCell a[title='Link to this {kind}']").first).to_be_attached()

        # The de Casteljau explorer: the keyboard moves its t slider, the figure and the readout follow.
        explorer = _cell(page, "de_casteljau_explorer(")
        explorer.scroll_into_view_if_needed()
        image, readout = explorer.locator("img.widget-image"), explorer.locator(".widget-html-content")
        expect(image).to_have_count(1)
        before, readout_before = image.get_attribute("src"), readout.inner_text()
        t_before = _slider_value(explorer, "t")
        explorer.locator(".noUi-handle").first.focus()
        for _ in range(5):
            page.keyboard.press("ArrowRight")
        expect(readout).not_to_have_text(readout_before)
        expect(image).not_to_have_attribute("src", before)
        t_after = round(t_before + 0.05, 2)
        assert _eventually(lambda: _slider_value(explorer, "t") == pytest.approx(t_after), page), (
            f"t = {_slider_value(explorer, 't')} after five steps right from {t_before}"
        )
        expect(readout).to_contain_text(f"P({t_after:.2f})")

        # The control point editor with ipympl: dragging P0 with the mouse moves the curve and its sliders.
        editor = _cell(page, "control_point_editor(")
        editor.scroll_into_view_if_needed()
        canvas = editor.locator(".jupyter-matplotlib-canvas-div")
        expect(canvas).to_have_count(1)
        count = editor.locator(".widget-slider").count() // 2
        points = np.array([[_slider_value(editor, f"x{i}"), _slider_value(editor, f"y{i}")] for i in range(count)])
        picture = canvas.screenshot()
        x, y = _canvas_point(editor, points, 0)
        page.mouse.move(x, y)
        page.mouse.down()
        page.mouse.move(x + 60, y - 40, steps=8)
        page.mouse.up()
        assert _eventually(lambda: _slider_value(editor, "x0") > points[0, 0], page)
        assert _eventually(lambda: _slider_value(editor, "y0") > points[0, 1], page)
        assert _eventually(lambda: canvas.screenshot() != picture, page)
        page.screenshot(path=artefacts / "lab-chapter-02.png")
        assert outside == []
    finally:
        context.close()

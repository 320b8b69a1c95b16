"""The static figure of an explorer, for pages without a kernel: its main slider swept over precomputed frames.

The book build sets CAGD_STATIC_FRAMES to N in the kernels it starts; every
explorer displayed there then adds to its output a self-contained HTML figure:
N frames of the main control's range, a range input and a play button driven by
a few lines of JavaScript, the readout of each frame. JupyterLab keeps showing the
live widget from the same output.
"""

from __future__ import annotations

import base64
import html
import io
import json
import os

import ipywidgets as widgets
import numpy as np
from PIL import Image

__all__ = ["STATIC_FRAMES_ENV", "frame_count", "frames", "html_figure"]

# Set by the book build: how many frames the static figure of every displayed explorer precomputes.
STATIC_FRAMES_ENV = "CAGD_STATIC_FRAMES"
# Palette size of the static frames: line drawings keep their look and shrink to a quarter.
FRAME_COLORS = 128


def frame_count() -> int:
    """The number of static frames asked for through CAGD_STATIC_FRAMES (0: none, the default)."""
    try:
        return max(int(os.environ.get(STATIC_FRAMES_ENV, "0")), 0)
    except ValueError:
        return 0


def _compact_png(png: bytes) -> bytes:
    """The PNG re-encoded with a small palette: a frame of a line drawing in about a quarter of the bytes."""
    image = Image.open(io.BytesIO(png)).convert("RGBA")
    buffer = io.BytesIO()
    image.quantize(colors=FRAME_COLORS, method=Image.Quantize.FASTOCTREE).save(buffer, format="PNG")
    return buffer.getvalue()


def _sweep(control, count: int) -> list:
    """About `count` values spread over a control's range (a slider's [min, max], a choice's options)."""
    value = control.value
    if isinstance(control, (widgets.Checkbox, widgets.ToggleButton)):
        return [False, True]
    if hasattr(control, "options"):
        return [option[1] if isinstance(option, tuple) else option for option in control.options]
    low, high = control.min, control.max
    if isinstance(control, widgets.FloatLogSlider):
        values = control.base ** np.linspace(low, high, count)
    elif isinstance(control, widgets.IntSlider):
        values = np.unique(np.round(np.linspace(low, high, count)).astype(int)).tolist()
    else:
        step = control.step or (high - low) / (count - 1)
        snapped = low + np.round((np.linspace(low, high, count) - low) / step) * step
        # Rounded, so that a snapped value equal to the current one is the same number.
        values = np.unique(np.round(np.clip(snapped, low, high), 12))
    # The frame the page shows first is the one the explorer was built with.
    return sorted({*(type(value)(v) for v in values), value})


def _label(control, value) -> str:
    """A value as the control's readout shows it."""
    if hasattr(control, "options"):
        for option in control.options:
            if isinstance(option, tuple) and option[1] == value:
                return str(option[0])
        return str(value)
    if isinstance(value, float) and getattr(control, "readout_format", ""):
        try:
            return format(value, control.readout_format)
        except ValueError:
            pass
    return f"{value:g}" if isinstance(value, float) else str(value)


_STATIC_SCRIPT = """(function () {
  var root = document.currentScript.parentElement;
  var data = JSON.parse(root.querySelector(".cagd-sx-data").textContent);
  var img = root.querySelector(".cagd-sx-frame"), range = root.querySelector("input[type=range]");
  var out = root.querySelector("output"), readout = root.querySelector(".cagd-sx-readout");
  var play = root.querySelector(".cagd-sx-play"), timer = null;
  function show(i) {
    img.src = "data:image/png;base64," + data.frames[i];
    img.alt = data.alts[i];
    out.textContent = data.labels[i];
    readout.innerHTML = data.readouts[i];
    range.value = i;
  }
  function stop() { clearInterval(timer); timer = null; play.textContent = "\u25B6"; play.title = "Play"; }
  range.addEventListener("input", function () { stop(); show(+range.value); });
  play.addEventListener("click", function () {
    if (timer) { stop(); return; }
    var i = +range.value >= data.frames.length - 1 ? -1 : +range.value;
    play.textContent = "\u25A0"; play.title = "Pause";
    timer = setInterval(function () { i += 1; if (i >= data.frames.length) { stop(); } else { show(i); } }, 150);
  });
})();"""

_STATIC_STYLE = (
    "<style>.cagd-static-explorer{display:flex;flex-wrap:wrap;gap:1em;align-items:flex-start;margin:.5em 0}"
    ".cagd-static-explorer img{max-width:100%;height:auto}"
    ".cagd-sx-panel{flex:1;min-width:16em}"
    ".cagd-sx-controls{display:flex;align-items:center;gap:.5em;margin-bottom:.5em}"
    ".cagd-sx-controls input{width:12em}"
    ".cagd-sx-play{min-width:2.2em;cursor:pointer}"
    ".cagd-sx-note{font-size:85%;opacity:.75}"
    "@media print{.cagd-sx-controls,.cagd-sx-note{display:none}}</style>"
)


def frames(explorer, count: int = 21) -> tuple[str, list[dict], int]:
    """Sweep the main control over about `count` values: (its name, frames, index of the current value).

    Each frame is {"label", "png" (palette PNG bytes), "readout" (HTML), "alt" (the frame's title)}.
    Values the explorer rejects are left out; afterwards every control has
    its value again and the figure shows what it showed before.
    """
    name = explorer.main_control()
    control = explorer.controls[name]
    saved = explorer.values
    frames, start = [], 0
    try:
        for value in _sweep(control, max(int(count), 2)):
            try:
                explorer.update(**{name: value})
            except (ValueError, TypeError):
                continue
            if value == saved[name]:
                start = len(frames)
            png = _compact_png(explorer.view.value if isinstance(explorer.view, widgets.Image) else explorer.png())
            frames.append(
                {"label": _label(control, value), "png": png, "readout": explorer.readout.value,
                 "alt": explorer.ax.get_title()}
            )
    finally:
        explorer.update(**saved)
    return name, frames, start


def html_figure(explorer, count: int = 21) -> str:
    """A self-contained HTML figure: the frames of `frames`, a slider over them and a play button."""
    name, swept, start = frames(explorer, count)
    if not swept:  # the explorer rejected every value of the sweep: the picture alone
        return f"<img alt='' src='data:image/png;base64,{base64.b64encode(explorer.png()).decode('ascii')}'>"
    control = explorer.controls[name]
    description = control.description or name
    data = {
        "labels": [f["label"] for f in swept],
        "readouts": [f["readout"] for f in swept],
        # The picture's text alternative follows the frame (its title says what the frame shows).
        "alts": [f.get("alt") or description for f in swept],
        "frames": [base64.b64encode(f["png"]).decode("ascii") for f in swept],
    }
    # Inside a <script> element only "</" could end it early.
    payload = json.dumps(data).replace("</", "<\\/")
    others = ", ".join(
        f"{html.escape(c.description or n)} = {html.escape(_label(c, c.value))}"
        for n, c in explorer.controls.items()
        if n != name
    )
    note = f"{len(swept)} precomputed frames of {html.escape(description)}" + (
        f", with {others}; in a running notebook every control is live."
        if others
        else "; in a running notebook the explorer is live."
    )
    first = swept[start]
    esc = html.escape
    return (
        f"<div class='cagd-static-explorer'>{_STATIC_STYLE}"
        f"<img class='cagd-sx-frame' alt='{esc(explorer.ax.get_title() or description)}' "
        f"src='data:image/png;base64,{data['frames'][start]}'>"
        "<div class='cagd-sx-panel'><div class='cagd-sx-controls'>"
        "<button type='button' class='cagd-sx-play' title='Play'>&#9654;</button>"
        f"<label>{esc(description)} <input type='range' min='0' max='{len(swept) - 1}' step='1' "
        f"value='{start}' aria-label='{esc(description)}'></label>"
        f"<output>{esc(first['label'])}</output></div>"
        f"<div class='cagd-sx-readout'>{first['readout']}</div>"
        f"<p class='cagd-sx-note'>{note}</p></div>"
        f"<script type='application/json' class='cagd-sx-data'>{payload}</script>"
        f"<script>{_STATIC_SCRIPT}</script></div>"
    )

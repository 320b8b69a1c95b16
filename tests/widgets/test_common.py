"""What every explorer of `cagd_course.widgets` must do, whatever its chapter: one sample update each.

Chapter-specific behaviour is tested in the test_chNN.py files next to this one.
"""

import importlib.util
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import ipywidgets  # noqa: E402
import pytest  # noqa: E402

from cagd_course import widgets  # noqa: E402


# Factory -> (a sample update, keys its state must have).
def _samples() -> dict:
    """Factory -> (a sample update, keys its state must have), merged from the samples_chNN.py files here."""
    merged = {}
    for path in sorted(Path(__file__).with_name("samples_ch01.py").parent.glob("samples_ch*.py")):
        spec = importlib.util.spec_from_file_location(f"explorer_{path.stem}", path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        assert not set(module.SAMPLES) & set(merged), f"{path.name} repeats an explorer"
        merged.update(module.SAMPLES)
    return merged


# One samples_chNN.py per chapter, so a new chapter adds its explorers without touching this file.
FACTORIES = _samples()


def test_every_exported_explorer_is_covered_here():
    factories = {name for name in widgets.__all__ if name.endswith(("_explorer", "_editor"))}
    assert factories == set(FACTORIES)


@pytest.mark.parametrize("name", FACTORIES)
def test_every_explorer_updates_redraws_and_displays(name):
    values, keys = FACTORIES[name]
    explorer = getattr(widgets, name)()
    before = explorer.view.value
    assert before[:8] == b"\x89PNG\r\n\x1a\n"
    state = explorer.update(**values)
    assert keys <= set(state)
    assert explorer.state is state
    assert explorer.view.value != before
    for key, value in values.items():
        assert explorer.values[key] == (value if isinstance(value, str) else pytest.approx(value))
    assert isinstance(explorer.widget, ipywidgets.Box)
    bundle = explorer._repr_mimebundle_()
    assert "application/vnd.jupyter.widget-view+json" in bundle
    assert bundle["image/png"][:4] == b"\x89PNG"
    assert explorer.ax.get_title()


@pytest.mark.parametrize("name", FACTORIES)
def test_redrawing_replaces_the_old_drawing(name):
    explorer = getattr(widgets, name)()
    axes = explorer.figure.axes

    def counts():
        return [(len(ax.lines), len(ax.collections), len(ax.texts), len(ax.patches), len(ax.images)) for ax in axes]

    explorer.update()
    first = counts()
    explorer.update()
    assert counts() == first
    assert len(explorer.figure.axes) == len(axes)


@pytest.mark.parametrize("name", FACTORIES)
def test_moving_a_control_calls_update(name):
    values, _ = FACTORIES[name]
    explorer = getattr(widgets, name)()
    control, value = next(iter(values.items()))
    before_png, before_state = explorer.view.value, explorer.state
    explorer.controls[control].value = value
    assert explorer.state is not before_state
    assert explorer.view.value != before_png

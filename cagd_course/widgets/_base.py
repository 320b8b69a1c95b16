"""The machinery every explorer shares: controls -> compute -> draw -> PNG, and dragging support.

Every explorer follows one pattern, implemented once in `Explorer`: a dict of
named ipywidgets controls; `update(**values)` sets controls, recomputes
(`compute`, pure NumPy on the `cagd_ref` functions), redraws (`draw`, with
`cagd_course.plotting`) and returns a dict of what is shown. Sliders call
`update` through an observer; notebooks and tests call it directly, so every
explorer works without a browser. The figure is a `matplotlib.figure.Figure`
(no pyplot, so nothing is displayed twice) rendered to PNG by the Agg canvas
into an `ipywidgets.Image`, or shown as an ipympl canvas when points can be
dragged with the mouse.

A static page has no kernel, so a widget cannot change its picture there. When
the environment variable CAGD_STATIC_FRAMES holds a number N (the book build
sets it for the kernels it starts), the display bundle also carries a
self-contained HTML figure: the main slider swept over N precomputed frames,
with a slider and a play button that work in any browser. The book chooses
that representation and JupyterLab the live widget, from the same output.
"""

from __future__ import annotations

import html
import io
from importlib.util import find_spec

import ipywidgets as widgets
import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.transforms import Bbox
from traitlets import TraitError

from cagd_ref._validation import as_points

from ..figure_check import report_findings
from ..plotting import hide_from_legend
from . import _static

__all__ = ["Explorer"]


DEFAULT_CUBIC = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]])
FAMILY_WEIGHTS = (0.0, 0.5, 1.0, 2.0, 5.0, 10.0)
CURVE_SAMPLES = 200
SLIDER_LAYOUT = widgets.Layout(width="300px")


def _slider(kind, description: str, **options):
    """A slider in the course's layout that reports every move, not just the release."""
    return kind(description=description, continuous_update=True, layout=SLIDER_LAYOUT, **options)


def _control_points(points, default: np.ndarray, min_count: int = 2) -> np.ndarray:
    """Planar control points (n+1, 2) given to a factory, or a copy of the default."""
    pts = as_points(default if points is None else points, min_count=min_count)
    if pts.shape[1] != 2:
        raise ValueError(f"points: the explorers draw planar curves, expected shape (n+1, 2), got {pts.shape}")
    return pts


def _ipympl_manager(figure: Figure):
    """An ipympl figure manager (whose canvas is a widget) for `figure`, leaving matplotlib's backend alone.

    Importing ipympl switches the global backend to itself, which would turn
    every later pyplot figure of the notebook into a widget; the previous
    setting (read raw, so an unresolved automatic choice stays automatic) is
    put back.
    """
    previous = dict.__getitem__(matplotlib.rcParams, "backend")
    from ipympl.backend_nbagg import new_figure_manager_given_figure

    if isinstance(previous, str):
        matplotlib.use(previous)
    else:
        dict.__setitem__(matplotlib.rcParams, "backend", previous)
    return new_figure_manager_given_figure(id(figure), figure)


def _swatch(color: str) -> str:
    """A small coloured square in HTML for a readout's colour key (matplotlib colour names such as 'C3')."""
    return f"<span style='color:{matplotlib.colors.to_hex(color)}'>&#9632;</span>"


def _fmt(vector) -> str:
    return "(" + ", ".join(f"{v:.4g}" for v in np.ravel(vector)) + ")"


def bare_axes(ax) -> None:
    """Drop ticks and axis labels: a polygon's coordinates say little, and tick labels cost most in a redraw."""
    ax.set(xticks=[], yticks=[], xlabel="", ylabel="")


class TwoPanels:
    """Mixin: a second axes (self.lower) under the explorer's main one, cleared with it on every redraw."""

    figsize = (6.5, 6.4)

    def lower_axes(self):
        if getattr(self, "lower", None) is None:
            # Room on both sides for the end tick labels: the explorer's PNG is the whole canvas, nothing beyond it.
            self.ax.set_position([0.09, 0.40, 0.86, 0.52])
            self.lower = self.figure.add_axes([0.09, 0.07, 0.86, 0.25])
        return self.lower

    def _clear(self) -> None:
        super()._clear()
        if getattr(self, "lower", None) is not None:
            # Explorer._clear empties self.ax; point it at the lower axes for a moment to reuse that logic.
            main, self.ax = self.ax, self.lower
            try:
                super()._clear()
            finally:
                self.ax = main


class Explorer:
    """Shared machinery: named controls -> `compute` -> `draw` -> PNG (or ipympl canvas) plus a text readout.

    Subclasses set up their controls, then call `Explorer.__init__`, and
    implement `compute(**values) -> dict` and `draw(ax, state)`; `describe`
    turns the state into the readout's HTML.
    """

    figsize = (6.0, 4.5)
    dpi = 100
    # The control the static figure sweeps; None means the first slider (else the first control).
    static_control: str | None = None
    # True where `describe` gives the colour key (a legend redrawn on every move would cost more than the rest of
    # the update): the drawn series then carry no legend labels, so the figure promises no legend it lacks.
    key_in_readout = False

    def __init__(self, controls: dict, projection: str | None = None, interactive_canvas: bool = False):
        self.controls = dict(controls)
        # A fixed layout: constrained layout would measure every label on each redraw, tripling its cost.
        self.figure = Figure(figsize=self.figsize, dpi=self.dpi)
        self.figure.subplots_adjust(left=0.1, right=0.97, bottom=0.1, top=0.88)
        if interactive_canvas:
            self.canvas = _ipympl_manager(self.figure).canvas
            self.canvas.header_visible = False
            self.canvas.footer_visible = False
            self.view = self.canvas
        else:
            self.canvas = FigureCanvasAgg(self.figure)
            self.view = widgets.Image(format="png")
        self.ax = self.figure.add_subplot(projection=projection)
        self.readout = widgets.HTML()
        self._syncing = False
        for control in self.controls.values():
            control.observe(self._on_control, names="value")
        panel = widgets.VBox(list(self.controls.values()) + [self.readout])
        self.widget = widgets.HBox([self.view, panel])
        self.state: dict = {}
        self.update()

    # The notebook shows the explorer as its widget; the PNG rides along for static renderers, and for the
    # book (CAGD_STATIC_FRAMES set) an HTML figure whose main slider works without a kernel.
    def _repr_mimebundle_(self, **kwargs):
        bundle = self.widget._repr_mimebundle_(**kwargs)
        bundle = dict(bundle[0] if isinstance(bundle, tuple) else bundle)
        bundle["image/png"] = self.png()
        # Under the notebook tests, the explorer's figure is checked for legibility like every other figure.
        report_findings(self.figure, tight=False)
        frames = _static.frame_count()
        if frames:
            bundle["text/html"] = self.static_html(frames)
        return bundle

    def main_control(self) -> str:
        """The name of the control the static figure sweeps: `static_control`, else the first slider."""
        if self.static_control is not None:
            return self.static_control
        sliders = [name for name, control in self.controls.items() if hasattr(control, "min")]
        return (sliders or list(self.controls))[0]

    def static_frames(self, count: int = 21) -> tuple[str, list[dict], int]:
        """Sweep the main control over about `count` values: (its name, frames, index of the current value)."""
        return _static.frames(self, count)

    def static_html(self, count: int = 21) -> str:
        """A self-contained HTML figure of the main control's sweep, with a slider and a play button."""
        return _static.html_figure(self, count)

    @property
    def values(self) -> dict:
        """Current value of every control, by name."""
        return {name: control.value for name, control in self.controls.items()}

    def update(self, **values) -> dict:
        """Set the named controls (others keep their value), recompute, redraw; return what is shown.

        If the new values are rejected (ValueError/TypeError naming the
        control), the controls go back to what they were.
        """
        previous = self.values
        try:
            self._set_controls(values)
            state = self.compute(**self.values)
        except (ValueError, TypeError):
            self._set_controls(previous)
            raise
        self._clear()
        self.draw(self.ax, state)
        if self.key_in_readout:
            for ax in self.figure.axes:
                hide_from_legend(ax)
        self.readout.value = self.describe(state)
        self._render()
        self.state = state
        return state

    def _set_controls(self, values: dict) -> None:
        unknown = sorted(set(values) - set(self.controls))
        if unknown:
            raise TypeError(
                f"{', '.join(unknown)}: not a control of this explorer; controls are {sorted(self.controls)}"
            )
        self._syncing = True
        try:
            for name, value in values.items():
                self._set_one(name, self.controls[name], value)
        finally:
            self._syncing = False

    @staticmethod
    def _set_one(name: str, control, value) -> None:
        low, high = getattr(control, "min", None), getattr(control, "max", None)
        if isinstance(control, widgets.FloatLogSlider):
            low, high = control.base**low, control.base**high
        if low is not None and not isinstance(value, bool) and isinstance(value, (int, float, np.number)):
            # Sliders would silently clamp (and integer ones truncate); a caller's bad value is an error instead.
            if isinstance(control, widgets.IntSlider) and not float(value).is_integer():
                raise TypeError(f"{name}: expected an integer, got {value}")
            if not low <= value <= high:
                raise ValueError(f"{name}: expected a value in [{low:g}, {high:g}], got {value}")
        try:
            control.value = value
        except TraitError as err:
            raise TypeError(f"{name}: {err}") from None

    def _clear(self) -> None:
        """Empty the axes for the next drawing.

        The axis objects stay (`Axes.clear` would rebuild every tick, a third
        of a redraw); only what was drawn goes, and the limits forget the old
        data. 3-D explorers set their limits themselves on every draw.
        """
        ax = self.ax
        for artist in [*ax.lines, *ax.collections, *ax.patches, *ax.texts, *ax.artists, *ax.images]:
            artist.remove()
        if ax.get_legend() is not None:
            ax.get_legend().remove()
        ax.set_title("")
        ax.dataLim.set_points(Bbox.null().get_points())
        ax.ignore_existing_data_limits = True
        ax.set_autoscale_on(True)

    def _on_control(self, change) -> None:
        if self._syncing:
            return
        try:
            self.update()
        except ValueError as err:
            # From a slider there is no caller to raise to: show the problem instead.
            self.readout.value = f"<b style='color:#b00'>{html.escape(str(err))}</b>"

    def _render(self) -> None:
        if isinstance(self.view, widgets.Image):
            self.view.value = self.png()
        else:
            self.canvas.draw_idle()

    def png(self) -> bytes:
        """The current figure as PNG bytes."""
        buffer = io.BytesIO()
        # Light compression: at the default level, encoding costs as much as drawing.
        self.figure.canvas.print_png(buffer, pil_kwargs={"compress_level": 1})
        return buffer.getvalue()

    def compute(self, **values) -> dict:
        raise NotImplementedError

    def draw(self, ax, state: dict) -> None:
        raise NotImplementedError

    def describe(self, state: dict) -> str:
        return ""


def _want_ipympl() -> bool:
    """Drag by default only inside a running kernel with ipympl installed, where a canvas can be shown."""
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and hasattr(shell, "kernel") and find_spec("ipympl") is not None



"""Interactive explorers for the chapter notebooks: sliders drive a figure and a readout.

Every explorer follows one pattern, implemented once in `_base.Explorer`: a dict
of named ipywidgets controls; `update(**values)` sets controls, recomputes
(`compute`, pure NumPy on the `cagd_ref` functions), redraws (`draw`, with
`cagd_course.plotting`) and returns a dict of what is shown. Sliders call `update`
through an observer; notebooks and tests call it directly, so every explorer
works without a browser.

The explorers of chapter NN live in the submodule `chNN`; everything they export
is available here, e.g. ``cagd_course.widgets.de_casteljau_explorer``.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._base import Explorer

__all__ = ["Explorer"]

for _module in sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name.startswith("ch")):
    _chapter = importlib.import_module(f"{__name__}.{_module}")
    globals().update({name: getattr(_chapter, name) for name in _chapter.__all__})
    __all__ += list(_chapter.__all__)

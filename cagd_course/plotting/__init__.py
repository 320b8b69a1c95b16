"""Static figures of the course, one module per family of figures.

`curves` (Bézier curves: control polygons, de Casteljau triangles, curvature
combs), `bsplines` (B-splines with polar and knot-interval labels), `algebraic`
(implicit curves), `vectors` (arrows). Every function draws into the matplotlib
Axes `ax` it is given and returns that same Axes, so calls chain and several
drawings share one picture. Planar drawings switch on an equal aspect ratio
(circles look round) and label the axes x and y unless the caller already did.
Extra keyword arguments (`**style`) go to the underlying matplotlib call and
override the defaults. Everything is importable from here too.
"""

from __future__ import annotations

from . import algebraic, bsplines, curves, vectors
from .algebraic import *  # noqa: F401,F403
from .bsplines import *  # noqa: F401,F403
from .curves import *  # noqa: F401,F403
from .vectors import *  # noqa: F401,F403

__all__ = curves.__all__ + bsplines.__all__ + algebraic.__all__ + vectors.__all__

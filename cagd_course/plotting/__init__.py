"""Static figures of the course, one module per family of figures.

Curves: `curves` (Bézier curves: control polygons, de Casteljau triangles,
curvature combs), `bsplines` (B-splines with polar and knot-interval labels),
`vectors` (arrows), `algebraic` (implicit curves). Later chapters' families:
`clipping` (fat lines and Bézier clipping, ch. 7), `offsets` (ch. 8), `roots`
(explicit curves, hulls and conditioning, ch. 9), `interpolation` (ch. 10),
`fitting` (ch. 11), `intervals` (interval Bézier curves, ch. 12), `rounding`
(floating-point bands, ch. 13), `deformation` (FFD lattices, ch. 14), `surfaces`
(patches in 3-D, ch. 15-16), `implicit_curves` (sign regions and intersection
polynomials, ch. 17), `pencils` (pencils of lines, ch. 18), `singular_points` (singular points,
pencil parametrizations and silhouettes, ch. 19), `hybrid` (ch. 20),
`quads` (maps of quadrilaterals, ch. 21).

Every function draws into the matplotlib Axes `ax` it is given and returns that
same Axes, so calls chain and several drawings share one picture. Planar
drawings switch on an equal aspect ratio (circles look round) and label the
axes x and y unless the caller already did. Extra keyword arguments (`**style`)
go to the underlying matplotlib call and override the defaults. The first four
families are importable from here too (``cagd_course.plotting.plot_bezier``), as is
`hide_from_legend` (a panel whose series an earlier legend names);
the others by their module (``from cagd_course.plotting.clipping import
plot_fat_line``), since some share names for different drawings (`plot_line`
draws a clipped line in `clipping` and a line across a fixed view in `pencils`).
"""

from __future__ import annotations

from . import algebraic, bsplines, curves, vectors
from ._style import hide_from_legend
from .algebraic import *  # noqa: F401,F403
from .bsplines import *  # noqa: F401,F403
from .curves import *  # noqa: F401,F403
from .vectors import *  # noqa: F401,F403

__all__ = [*curves.__all__, *bsplines.__all__, *algebraic.__all__, *vectors.__all__, "hide_from_legend"]

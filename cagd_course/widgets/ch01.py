"""Explorers of chapter 1 of the notes: rotation about an arbitrary axis, and the conic classifier."""

from __future__ import annotations

import html

import ipywidgets as widgets
import numpy as np
from matplotlib.ticker import MaxNLocator

from cagd_ref._validation import as_scalar, as_vector
from cagd_ref.geometry import conic_discriminant, conic_type, rotate_about_axis, rotation_matrix

from ..plotting.algebraic import plot_implicit
from ..plotting.vectors import plot_vector
from ._base import Explorer, _fmt, _slider, _swatch

__all__ = ["rotation_explorer", "conic_explorer", "RotationExplorer", "ConicExplorer"]

# ---------------------------------------------------------------- chapter 1


ROTATED_POINT = np.array([1.5, 0.0, 0.5])
AXIS_POINT = np.array([0.0, 0.0, 0.0])
AXIS_DIRECTION = np.array([0.0, 0.3, 1.0])
ANGLE = 60.0


class RotationExplorer(Explorer):
    """A point P rotated about an axis through B, in 3-D, with the circle it moves on. Notes §1.3."""

    def __init__(self, point=ROTATED_POINT, axis_point=AXIS_POINT, axis_direction=AXIS_DIRECTION, angle=ANGLE):
        self.point = as_vector(point, "point", dim=3)
        self.axis_point = as_vector(axis_point, "axis_point", dim=3)
        direction = as_vector(axis_direction, "axis_direction", dim=3)
        if not np.any(direction) or np.abs(direction).max() > 3:
            raise ValueError(
                f"axis_direction: expected a nonzero vector with entries in [-3, 3], got {direction.tolist()}"
            )
        angle = as_scalar(angle, "angle")
        if not -180 <= angle <= 180:
            raise ValueError(f"angle: expected degrees in [-180, 180], got {angle}")
        controls = {
            "angle": _slider(widgets.FloatSlider, "angle (°)", min=-180.0, max=180.0, step=1.0, value=angle),
            **{
                f"axis_{name}": _slider(
                    widgets.FloatSlider, f"axis {name}", min=-3.0, max=3.0, step=0.05, value=float(value)
                )
                for name, value in zip("xyz", direction)
            },
        }
        super().__init__(controls, projection="3d")

    def compute(self, angle: float, axis_x: float, axis_y: float, axis_z: float) -> dict:
        direction = np.array([axis_x, axis_y, axis_z])
        if not np.any(direction):
            raise ValueError("axis_x, axis_y, axis_z: the axis direction must be a nonzero vector")
        theta = np.radians(angle)
        n = direction / np.linalg.norm(direction)
        center = self.axis_point + ((self.point - self.axis_point) @ n) * n
        u, v = self.point - center, np.cross(n, self.point - center)
        sweep = np.linspace(0, 2 * np.pi, 121)[:, None]
        travelled = np.linspace(0, theta, 61)[:, None]
        return {
            "angle": angle,
            "original": self.point.copy(),
            "point": rotate_about_axis(self.point, self.axis_point, direction, theta),
            "matrix": rotation_matrix(self.axis_point, direction, theta),
            "axis": n,
            "center": center,
            "circle": center + np.cos(sweep) * u + np.sin(sweep) * v,
            "arc": center + np.cos(travelled) * u + np.sin(travelled) * v,
        }

    def draw(self, ax, state: dict) -> None:
        n, c = state["axis"], state["center"]
        radius = max(np.linalg.norm(state["original"] - c), 1.0)
        reach = 1.5 * radius + np.linalg.norm(c - self.axis_point)
        axis_ends = np.array([self.axis_point - reach * n, self.axis_point + reach * n])
        # no legend labels: the colour key is in `describe`, a legend would double the drawing time
        ax.plot(*axis_ends.T, color="0.3", linewidth=1)
        plot_vector(ax, self.axis_point, n, label="$\\mathbf{n}$", color="0.2")
        ax.plot(*state["circle"].T, color="C0", linewidth=1)
        ax.plot(*state["arc"].T, color="C3", linewidth=2.5)
        ax.plot(*np.array([c, state["original"]]).T, ":", color="0.5")
        ax.plot(*np.array([c, state["point"]]).T, ":", color="0.5")
        ax.scatter(*state["original"], color="C1", s=40)
        ax.scatter(*state["point"], color="C3", s=40)
        ax.scatter(*c, color="0.4", s=15)
        ax.scatter(*self.axis_point, color="k", marker="s", s=20)
        low, high = c - 1.3 * radius, c + 1.3 * radius
        ax.set(xlim=(low[0], high[0]), ylim=(low[1], high[1]), zlim=(low[2], high[2]))
        ax.set_box_aspect((1, 1, 1))
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        ax.set_title(f"Rotating P by {state['angle']:.0f}° about an axis", fontsize=10)
        # Three ticks per axis: 3-D tick labels are most of the drawing time.
        for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
            axis.set_major_locator(MaxNLocator(3))

    def describe(self, state: dict) -> str:
        # The colour key lives here rather than in a legend, which would double the drawing time.
        return (
            f"P* = {_fmt(state['point'])}<br>axis n = {_fmt(state['axis'])}<br>"
            f"{_swatch('C1')} P &nbsp; {_swatch('C3')} P* and the arc of θ = {state['angle']:.0f}° &nbsp; "
            f"{_swatch('C0')} circle of rotation &nbsp; {_swatch('0.4')} its centre C &nbsp; {_swatch('0.3')} the axis "
            f"through B (square)"
        )


def rotation_explorer(
    point=ROTATED_POINT, axis_point=AXIS_POINT, axis_direction=AXIS_DIRECTION, angle=ANGLE
) -> RotationExplorer:
    """Controls `angle` (degrees) and `axis_x, axis_y, axis_z`: `point` (default (1.5, 0, 0.5)) rotated about
    the axis through `axis_point` (default the origin). Notes §1.3.

    `axis_direction` (default (0, 0.3, 1), entries in [-3, 3]) and `angle` (default 60, in [-180, 180]) are
    the sliders' starting values.

    `update` returns {"point" (3,), "matrix" (4, 4), "original", "axis" (unit),
    "center", "circle" (121, 3), "arc" (61, 3) from P to P*}; matrix @ (P, 1) gives (point, 1).
    """
    return RotationExplorer(point, axis_point, axis_direction, angle)


class ConicExplorer(Explorer):
    """The conic a x² + b xy + c y² + d x + e y + f = 0, drawn and classified by b² - 4ac. Notes §1.6."""

    box = (-3.0, 3.0)

    def __init__(self):
        defaults = {"a": 1.0, "b": 0.0, "c": 1.0, "d": 0.0, "e": 0.0, "f": -1.0}
        controls = {
            name: _slider(widgets.FloatSlider, name, min=-5.0, max=5.0, step=0.1, value=value)
            for name, value in defaults.items()
        }
        super().__init__(controls)

    def compute(self, a: float, b: float, c: float, d: float, e: float, f: float) -> dict:
        coefficients = (a, b, c, d, e, f)
        kind = conic_type(*coefficients) if (a, b, c) != (0, 0, 0) else "not a conic (no quadratic terms)"
        return {"type": kind, "discriminant": conic_discriminant(a, b, c), "coefficients": coefficients}

    def draw(self, ax, state: dict) -> None:
        a, b, c, d, e, f = state["coefficients"]
        def conic(x, y):
            return a * x * x + b * x * y + c * y * y + d * x + e * y + f

        plot_implicit(ax, conic, self.box, self.box, label=state["type"])
        ax.axhline(0, color="0.85", linewidth=0.8, zorder=0)
        ax.axvline(0, color="0.85", linewidth=0.8, zorder=0)
        ax.set_title(f"${_conic_equation(state['coefficients'])}$\n"
                     f"$b^2-4ac$ = {state['discriminant']:.3g}: {state['type']}", fontsize=10)
        ax.legend(fontsize=8, loc="upper right")

    def describe(self, state: dict) -> str:
        return f"b² − 4ac = {state['discriminant']:.4g} → <b>{html.escape(state['type'])}</b>"


def _conic_equation(coefficients) -> str:
    """Mathtext for a x² + b xy + c y² + d x + e y + f = 0, leaving out zero terms and unit factors."""
    terms = []
    for value, monomial in zip(coefficients, ("x^2", "xy", "y^2", "x", "y", "")):
        if value == 0:
            continue
        sign = "-" if value < 0 else "+"
        size = "" if abs(value) == 1 and monomial else f"{abs(value):g}"
        terms.append(f"{sign} {size}{monomial}")
    if not terms:
        return "0 = 0"
    # The first term keeps a minus sign, without a space, and drops a plus.
    first = terms[0].replace("+ ", "").replace("- ", "-")
    return " ".join([first, *terms[1:]]) + " = 0"


def conic_explorer() -> ConicExplorer:
    """Sliders `a, b, c, d, e, f` for a x² + b xy + c y² + d x + e y + f = 0, default the unit circle. Notes §1.6.

    `update` returns {"type" ('ellipse'/'parabola'/'hyperbola'), "discriminant"
    (b² - 4ac), "coefficients"}; an empty picture means no real points in view.
    """
    return ConicExplorer()

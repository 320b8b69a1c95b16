"""What every explorer of `cagd_course.widgets` must do, whatever its chapter: one sample update each.

Chapter-specific behaviour is tested in the test_chNN.py files next to this one.
"""

import matplotlib

matplotlib.use("Agg")

import ipywidgets  # noqa: E402
import pytest  # noqa: E402

from cagd_course import widgets  # noqa: E402

# Factory -> (a sample update, keys its state must have).
FACTORIES = {
    "rotation_explorer": ({"angle": 45.0, "axis_x": 1.0}, {"point", "matrix"}),
    "conic_explorer": ({"b": 3.0}, {"type", "discriminant"}),
    "de_casteljau_explorer": ({"t": 0.3}, {"point", "left", "right"}),
    "control_point_editor": ({"x1": 1.5}, {"points", "curve"}),
    "rational_weight_explorer": ({"weight": 3.0}, {"weights", "curve"}),
    "degree_elevation_explorer": ({"steps": 4}, {"polygon", "distance"}),
    "subdivision_explorer": ({"depth": 3}, {"polygons", "distance"}),
    "curvature_comb_explorer": ({"teeth": 20, "length": 2.0}, {"bases", "tips", "max_curvature"}),
    "continuity_explorer": ({"h": 2.0}, {"continuity", "text"}),
    "basis_conversion_explorer": ({"b1": 4.5}, {"bernstein", "power", "table", "text"}),
    "evaluation_cost_explorer": ({"degree": 7}, {"degree", "costs", "totals"}),
    "raster_explorer": ({"delta": 0.1}, {"pixels", "gaps", "gap_count", "bound", "steps"}),
    "drift_explorer": ({"steps": 300, "precision": "float64"}, {"forward_error", "horner_error", "final_forward"}),
    "blending_forms_explorer": ({"x1": 1.5}, {"points", "curves", "midpoints", "bezier_points", "hull_escape"}),
    "variation_diminishing_explorer": (
        {"angle": 30.0},
        {"line", "p", "c", "holds", "polygon_crossings", "curve_crossings"},
    ),
    "knot_vector_editor": ({"u2": 2.5}, {"knots", "continuity", "segments", "basis"}),
    "de_boor_explorer": ({"t": 3.3}, {"point", "levels", "span", "labels"}),
    "knot_insertion_explorer": ({"t": 2.6}, {"points", "knots", "new", "deviation"}),
    "knot_interval_explorer": ({"fraction": 0.5}, {"points", "intervals", "construction", "deviation"}),
    "local_control_explorer": ({"dx": 1.0}, {"points", "segments", "changed", "support"}),
}


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

"""Sample updates of the chapter 19 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "double_point_kind_explorer": ({"k": -2.0}, {"c", "tangent_cone", "discriminant", "kind", "directions"}),
    "pencil_parametrization_explorer": ({"t": 1.0}, {"c", "point", "xyw", "xy", "residual"}),
    "silhouette_explorer": ({"angle": 30.0, "view": "zoom on the double point"},
                            {"c", "discriminant", "roots", "double_point", "zoom"}),
}

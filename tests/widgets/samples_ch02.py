"""Sample updates of the chapter 2 explorers for test_common.py: factory -> (one update, keys its state must have)."""

SAMPLES = {
    "de_casteljau_explorer": ({"t": 0.3}, {"point", "left", "right"}),
    "control_point_editor": ({"x1": 1.5}, {"points", "curve"}),
    "rational_weight_explorer": ({"weight": 3.0}, {"weights", "curve"}),
    "degree_elevation_explorer": ({"steps": 4}, {"polygon", "distance"}),
    "subdivision_explorer": ({"depth": 3}, {"polygons", "distance"}),
    "curvature_comb_explorer": ({"teeth": 20, "length": 2.0}, {"bases", "tips", "max_curvature"}),
    "continuity_explorer": ({"h": 2.0}, {"continuity", "text"}),
}

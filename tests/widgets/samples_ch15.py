"""Sample updates of the chapter 15 explorers (tensor-product patches) for test_common.py."""

SAMPLES = {
    "patch_editor": ({"dz": 1.5}, {"points", "moved", "centre", "normals"}),
    "iso_curve_explorer": ({"c": 0.7}, {"wires", "beads", "bead_weights", "gap"}),
    "tessellation_explorer": ({"log_tol": -2.0}, {"bounds", "n_s", "n_t", "triangles", "error", "bound"}),
    "curvature_explorer": ({"h11": 0.3}, {"gaussian", "mean", "gaussian_forms", "mean_forms", "principal"}),
}

"""Valid calls of cagd_ref.offsets for the contract test (planar curves; rational ones with positive weights)."""

from . import Call

ARCH = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]
WEIGHTS = [1.0, 2.0, 0.5, 1.0]
PH_CUBIC = [[0.0, 0.0], [4.0 / 3.0, 0.0], [2.0, 2.0 / 3.0], [2.0, 4.0 / 3.0]]  # u = (2, 1), v = (0, 1)

CALLS = {
    "offset_normal": [Call((ARCH, 0.3), parameter="t"), Call((ARCH, 0.3), dict(weights=WEIGHTS), parameter="t")],
    "offset_point": [Call((ARCH, 0.3, 0.5), parameter="t"), Call((ARCH, 0.3, -0.5, WEIGHTS), parameter="t")],
    "offset_derivative": [Call((ARCH, 0.3, 2.5), parameter="t"), Call((ARCH, 0.7, 0.5, WEIGHTS), parameter="t")],
    "reverse_offset": [Call((ARCH, 0.3, 1.0), parameter="t"), Call((ARCH, 0.3, 1.0, WEIGHTS), parameter="t")],
    "curvature_polynomials": [Call((ARCH,)), Call((ARCH, WEIGHTS))],
    "cusp_polynomial": [Call((ARCH, 2.5)), Call((ARCH, 2.5, WEIGHTS))],
    "offset_cusps": [Call((ARCH, 2.5)), Call((ARCH, 0.8, WEIGHTS))],
    "cusp_free_interval": [Call((ARCH,)), Call((ARCH, WEIGHTS))],
    "ph_hodograph": Call(([2.0, 1.0], [0.0, 1.0])),
    "ph_curve": Call(([1.0, 2.0], [2.0, 1.0, 0.5], [0.0, 1.0, 1.5])),
    "ph_cubic": Call(([0.0, 0.0], [2.0, 1.0], [0.0, 1.0])),
    "ph_speed": Call((PH_CUBIC,)),
    "is_pythagorean_hodograph": Call((PH_CUBIC,), dict(tol=1e-9)),
    "ph_offset": Call((PH_CUBIC, 0.25)),
    "parabola_offset": Call((0.5,), dict(interval=[-1.0, 1.0])),
}
CALLS.update({
    "centre_of_curvature": [Call((ARCH, 0.3), parameter="t"), Call((ARCH, 0.3, WEIGHTS), parameter="t")],
    "distance_to_curve": [Call((ARCH, [2.0, 1.0])), Call((ARCH, [[2.0, 1.0], [0.5, -1.0]], WEIGHTS))],
    "offset_error": [Call((ARCH, 0.3, [2.0, 1.25], 0.5), parameter="t"),
                     Call((ARCH, 0.3, [2.0, 1.25], 0.5, WEIGHTS), parameter="t")],
    "trim_offset": [Call((ARCH, -0.5)), Call((ARCH, 1.0, WEIGHTS), dict(samples=50))],
    "tiller_hanson": Call((ARCH, 0.5)),
    "tiller_hanson_offset": Call((ARCH, -0.5, 1e-2)),
    "fit_offset": [Call((ARCH, -0.5, 1e-3)), Call((ARCH, 0.5, 1e-3, WEIGHTS), dict(interval=[0.2, 0.8], degree=2))],
})

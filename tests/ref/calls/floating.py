"""Valid calls of cagd_ref.floating for the contract test (float32 arithmetic, η = 2^-24, and the notes' strings)."""

from . import Call

ETA32 = 2.0**-24
CUBIC = [[1.0], [-3.0], [9.0], [-27.0]]  # (1 - 4t)³, Figure 13.1
CURVE = [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]]

CALLS = {
    "machine_unit": Call((24,)),
    "decode_float": Call(("0|100000001|11100000000000000000000",)),
    "encode_float": Call((0.4375,), dict(exponent_bits=8, fraction_bits=23)),
    "round_to_bits": [Call((0.3, 4)), Call(([0.1, -9.3], 24))],
    "neighbours": Call((0.3333, 23)),
    "float_interval": [Call((0.5, 4)), Call((0.5, 4), dict(exact=True))],
    "affine_roundoff": [Call((2.0, -3.0, 0.5, ETA32)), Call(([1.0, -2.0], [3.0, 4.0], 0.25, ETA32), parameter="t")],
    "rounded_affine_map": [
        Call((2.0, 0.1, -3.0, 0.2, -0.5, ETA32)),
        Call(([1.0, 1.0], [0.3, 0.2], [4.0, 3.0], [0.2, 0.4], 0.5, ETA32), parameter="t"),
    ],
    "rounded_de_casteljau": [
        Call((CUBIC, 0.25, ETA32), parameter="t"),
        Call((CURVE, 0.375, 2.0**-53), dict(radii=[[0.1, 0.1]] * 4), parameter="t"),
    ],
    "evaluate_in_precision": Call(([1.0, -3.0, 9.0, -27.0], 0.2500123, 24), dict(method="horner"), parameter="t"),
    "exact_value": Call(([1.0, -3.0, 9.0, -27.0], 0.2500123), parameter="t"),
    "error_bound": Call(([1.0, -3.0, 9.0, -27.0], 0.25, ETA32), parameter="t"),
}

"""Valid calls of cagd_ref.roots for the contract test."""

from . import Call

QUARTIC = [1.0, 1.0, -3.0, -2.0, 4.0]  # the hull-marching example of ch09.toml: roots 0.2547, 0.7660
POINTS = [[0.0, 10.0], [0.0, 12.0], [5.0, 10.0], [8.0, 7.0], [11.0, 1.0]]  # the rational quartic of §7.7.8

CALLS = {
    "hull_crossing": Call((QUARTIC,)),
    "sign_variations": Call((QUARTIC,)),
    "deflate": Call(([0.0, 1.0, -1.0, 2.0],)),
    "hull_march": Call((QUARTIC,), dict(interval=(0.0, 2.0), tol=1e-10)),
    "hull_march_steps": Call((QUARTIC,), dict(interval=(0.0, 2.0), tol=1e-10, max_steps=50)),
    "bcom_roots": Call((QUARTIC,), dict(interval=(0.0, 2.0), tol=1e-10)),
    "bcom_steps": Call((QUARTIC,), dict(interval=(0.0, 2.0), tol=1e-10)),
    "bernstein_roots": Call((QUARTIC,), dict(interval=(1.0, 3.0), tol=1e-10)),
    "bernstein_roots_plain": Call((QUARTIC,), dict(interval=(1.0, 3.0), tol=1e-10)),
    "bernstein_from_roots": Call(([2.5, 3.0, 4.75],), dict(interval=(2.0, 5.0), leading=2.0)),
    "line_curve_intersection": Call((POINTS, [6.0, -8.0, 40.0]), dict(weights=[1.0, 1.0, 2.0, 3.0, 3.0])),
    "wilkinson_polynomial": Call((6,)),
    "hull_march_plain": Call((QUARTIC,), dict(interval=(0.0, 2.0), tol=1e-10)),
    "polygon_crossing": Call(([1.0, -1.0, 2.0, -3.0],)),
}

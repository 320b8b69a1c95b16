"""Measures only the last coordinate (the height z) of the differences, as if x and y were a flat lattice."""
import math

import numpy as np


def _net(points, tol):
    P = np.array(points, dtype=float)
    if P.ndim != 3 or not np.all(np.isfinite(P)):
        raise ValueError("points: expected shape (m+1, n+1, d)")
    tol = np.array(tol, dtype=float)
    if tol.ndim != 0 or not np.isfinite(tol) or tol <= 0:
        raise ValueError("tol: expected a positive number")
    return P, float(tol)


def _biggest(d, norm=lambda v: np.linalg.norm(v, axis=-1)):
    return float(norm(d).max()) if d.size else 0.0


def _steps(M1, M2, M3, tol, k_of=lambda M1, M3: math.sqrt(M3 / M1)):
    if M1 == 0 and M2 == 0 and M3 == 0:
        ds, dt = 1.0, 1.0
    elif M1 == 0:
        ds, dt = 1.0, 8 * tol / (math.sqrt(M2 * M2 + 8 * tol * M3) + M2)
    elif M3 == 0:
        ds, dt = 8 * tol / (math.sqrt(M2 * M2 + 8 * tol * M1) + M2), 1.0
    else:
        k = k_of(M1, M3)
        dt = math.sqrt(8 * tol / (M1 * k * k + 2 * M2 * k + M3))
        ds = k * dt
    return math.ceil(1 / min(ds, 1.0)), math.ceil(1 / min(dt, 1.0))


def tessellation_steps(points, tol):
    P, tol = _net(points, tol)
    m, n = P.shape[0] - 1, P.shape[1] - 1

    def z(v):
        return np.abs(v[..., -1])

    M1 = m * (m - 1) * _biggest(np.diff(P, 2, axis=0), z)
    M2 = m * n * _biggest(np.diff(np.diff(P, axis=0), axis=1), z)
    M3 = n * (n - 1) * _biggest(np.diff(P, 2, axis=1), z)
    return _steps(M1, M2, M3, tol)

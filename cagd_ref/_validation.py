"""Input checking shared by every module: clear errors instead of NumPy surprises.

Every public function of `cagd_ref` turns its array arguments into fresh float
arrays through these helpers, so inputs are never modified in place and bad
input is reported with the argument's name, what was expected and what came.
"""

from __future__ import annotations

import math
import numbers

import numpy as np


def _describe(value) -> str:
    if isinstance(value, np.ndarray):
        return f"an array of shape {value.shape}"
    return f"{type(value).__name__} {value!r}"[:120]


def as_float_array(value, name: str) -> np.ndarray:
    """A fresh float copy of `value`, rejecting non-numbers, NaN and infinities."""
    if value is None or isinstance(value, (str, bytes, dict, set)):
        raise TypeError(f"{name}: expected numbers, got {_describe(value)}")
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError) as err:
        raise TypeError(f"{name}: expected numbers, got {_describe(value)} ({err})") from None
    if not np.isfinite(array).all():
        raise ValueError(f"{name}: expected finite numbers, got NaN or infinity in {_describe(value)}")
    return array


def as_points(points, name: str = "points", min_count: int = 1) -> np.ndarray:
    """Control points as a float array of shape (n+1, d): one row per point."""
    array = as_float_array(points, name)
    if array.ndim != 2:
        raise ValueError(
            f"{name}: expected an array of shape (n+1, d), one row per point, got shape {array.shape}"
        )
    if array.shape[0] < min_count or array.shape[1] < 1:
        raise ValueError(
            f"{name}: expected at least {min_count} point(s) with at least one coordinate, "
            f"got shape {array.shape}"
        )
    return array


def as_coefficients(coeffs, name: str = "coeffs") -> np.ndarray:
    """Polynomial coefficients of shape (n+1,) or (n+1, d), at least one."""
    array = as_float_array(coeffs, name)
    if array.ndim not in (1, 2) or array.shape[0] == 0:
        raise ValueError(
            f"{name}: expected coefficients of shape (n+1,) or (n+1, d) with n >= 0, got shape {array.shape}"
        )
    return array


def as_parameter(t, name: str = "t") -> tuple[np.ndarray, bool]:
    """Parameter values as a 1-D float array, and whether a single scalar came in."""
    array = as_float_array(t, name)
    if array.ndim == 0:
        return array.reshape(1), True
    if array.ndim != 1:
        raise ValueError(f"{name}: expected a number or a 1-D array of numbers, got shape {array.shape}")
    return array, False


def as_vector(value, name: str, dim: int | None = None) -> np.ndarray:
    """A single point or vector of shape (d,), optionally of a required dimension."""
    array = as_float_array(value, name)
    if array.ndim != 1 or array.shape[0] == 0 or (dim is not None and array.shape[0] != dim):
        wanted = f"({dim},)" if dim is not None else "(d,)"
        raise ValueError(f"{name}: expected a vector of shape {wanted}, got shape {array.shape}")
    return array


def as_line(value, name: str) -> np.ndarray:
    """A homogeneous line (a, b, c) of a x + b y + c w = 0, shape (3,); (0, 0, 0) is none."""
    line = as_vector(value, name, dim=3)
    if not np.any(line):
        raise ValueError(f"{name}: (0, 0, 0) is not a line")
    return line


def as_weights(weights, count: int, name: str = "weights") -> np.ndarray:
    """Weights of shape (count,), all nonzero (a zero weight is a point at infinity)."""
    array = as_float_array(weights, name)
    if array.shape != (count,):
        raise ValueError(f"{name}: expected {count} weights (one per control point), got shape {array.shape}")
    if np.any(array == 0):
        raise ValueError(f"{name}: weights must be nonzero, got {array.tolist()}")
    return array


def as_positive_weights(weights, count: int, requirement: str, name: str = "weights") -> np.ndarray:
    """Weights of shape (count,), all positive; `requirement` is the error's reason, e.g. "offsets need positive
    weights (no pole on the curve)"."""
    array = as_weights(weights, count, name)
    if np.any(array < 0):
        raise ValueError(f"{name}: {requirement}, got {array.tolist()}")
    return array


def as_interval(interval, name: str = "interval") -> tuple[float, float]:
    """A parameter interval (t0, t1) with t0 < t1."""
    array = as_float_array(interval, name)
    if array.shape != (2,) or not array[0] < array[1]:
        raise ValueError(f"{name}: expected (t0, t1) with t0 < t1, got {_describe(interval)}")
    return float(array[0]), float(array[1])


def as_count(value, name: str, minimum: int = 0) -> int:
    """A non-negative integer such as a degree or an index."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TypeError(f"{name}: expected an integer, got {_describe(value)}")
    if value < minimum:
        raise ValueError(f"{name}: expected an integer >= {minimum}, got {value}")
    return int(value)


def as_scalar(value, name: str) -> float:
    """One finite real number."""
    if type(value) in (float, int):  # the common case, without an array round trip
        number = float(value)
        if not math.isfinite(number):
            raise ValueError(f"{name}: expected finite numbers, got NaN or infinity in {_describe(value)}")
        return number
    array = as_float_array(value, name)
    if array.ndim != 0:
        raise ValueError(f"{name}: expected a single number, got shape {array.shape}")
    return float(array)


def as_tolerance(tol, name: str = "tol", below_one: bool = False) -> float:
    """A tolerance: a finite number > 0 (and < 1 where it is relative, `below_one`)."""
    value = as_scalar(tol, name)
    if below_one and not 0 < value < 1:
        raise ValueError(f"{name}: expected a number in (0, 1), got {value}")
    if value <= 0:
        raise ValueError(f"{name}: expected a tolerance > 0, got {value}")
    return value

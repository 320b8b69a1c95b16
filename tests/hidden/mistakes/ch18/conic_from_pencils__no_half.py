"""Forgets the 1/2 of the middle control point: P1 = l00 × l11 + l01 × l10."""
import numpy as np


def _lines(*lines):
    out = [np.array(v, dtype=float) for v in lines]
    for v in out:
        if v.shape != (3,) or not np.all(np.isfinite(v)) or not np.any(v):
            raise ValueError("l00: expected a line (a, b, c)")
    l00, l01, l10, l11 = out
    first, second = np.cross(l00, l01), np.cross(l10, l11)
    if np.linalg.norm(first) <= 1e-10 * np.linalg.norm(l00) * np.linalg.norm(l01):
        raise ValueError("l00, l01: one line")
    if np.linalg.norm(second) <= 1e-10 * np.linalg.norm(l10) * np.linalg.norm(l11):
        raise ValueError("l10, l11: one line")
    if np.linalg.norm(np.cross(first, second)) <= 1e-10 * np.linalg.norm(first) * np.linalg.norm(second):
        raise ValueError("l00, l01, l10, l11: one axis")
    return out


def conic_from_pencils(l00, l01, l10, l11):
    l00, l01, l10, l11 = _lines(l00, l01, l10, l11)
    return np.array([np.cross(l00, l10), np.cross(l00, l11) + np.cross(l01, l10), np.cross(l01, l11)])

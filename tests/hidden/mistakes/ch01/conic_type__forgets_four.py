"""Drops the factor 4 and tests the sign of b² - ac."""


def conic_type(a, b, c, d, e, f):
    if a == 0 and b == 0 and c == 0:
        raise ValueError("a, b and c cannot all be zero")
    disc = b * b - a * c
    if abs(disc) <= 1e-12 * max(abs(a), abs(b), abs(c)) ** 2:
        return "parabola"
    return "hyperbola" if disc > 0 else "ellipse"

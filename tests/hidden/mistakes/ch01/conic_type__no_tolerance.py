"""Tests the discriminant with == 0, so a parabola whose b² - 4ac rounds to -5e-17 is called an ellipse."""


def conic_type(a, b, c, d, e, f):
    if a == 0 and b == 0 and c == 0:
        raise ValueError("a, b and c cannot all be zero")
    disc = b ** 2 - 4 * a * c
    if disc == 0:
        return "parabola"
    elif disc > 0:
        return "hyperbola"
    return "ellipse"

"""Mixes up the two signs: calls a positive discriminant an ellipse and a negative one a hyperbola."""


def conic_type(a, b, c, d, e, f):
    if a == 0 and b == 0 and c == 0:
        raise ValueError("a, b and c cannot all be zero")
    disc = b * b - 4 * a * c
    if abs(disc) <= 1e-12 * max(abs(a), abs(b), abs(c)) ** 2:
        return "parabola"
    return "ellipse" if disc > 0 else "hyperbola"

"""Uses b² + 4ac as the discriminant instead of b² - 4ac."""


def conic_type(a, b, c, d, e, f):
    if a == 0 and b == 0 and c == 0:
        raise ValueError("a, b and c cannot all be zero")
    disc = b * b + 4 * a * c
    scale = max(abs(a), abs(b), abs(c)) ** 2
    if abs(disc) <= 1e-12 * scale:
        return "parabola"
    return "hyperbola" if disc > 0 else "ellipse"

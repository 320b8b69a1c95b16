"""Returns a negative genus instead of rejecting a reducible curve."""

def _check(degree, multiplicities):
    if isinstance(degree, bool) or not isinstance(degree, int):
        raise TypeError("degree: expected an integer")
    if degree < 1:
        raise ValueError("degree: expected n >= 1")
    rs = list(multiplicities)
    for r in rs:
        if isinstance(r, float) and r != r:
            raise ValueError("multiplicities: NaN")
        if isinstance(r, bool) or not isinstance(r, int):
            raise TypeError("multiplicities: expected integers")
        if not 2 <= r <= degree - 1:
            raise ValueError("multiplicities: expected 2 <= r <= n-1")
    return rs


def genus(degree, multiplicities=()):
    rs = _check(degree, multiplicities)
    return (degree - 1) * (degree - 2) // 2 - sum(r * (r - 1) // 2 for r in rs)

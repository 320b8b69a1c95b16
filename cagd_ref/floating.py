"""Floating-point numbers, rounding, and boxes that provably hold the exact value of de Casteljau: chapter 13.

A binary floating-point number is b = ±f·2^e with a fraction f of d bits,
normalised to [1/2, 1) in the notes' format (`decode_float`, `encode_float`).
Rounding a real x to d significant bits, to nearest with ties to even
(`round_to_bits`), moves it by at most η|x|, where η = 2^-d is the machine
unit (`machine_unit`); and a float stands for the interval of reals that
round to it (`float_interval`), between the midpoints to its two neighbours
(`neighbours`).

Every operation of d-bit arithmetic obeys the rounding model
fl(x ∗ y) = (x ∗ y)(1 + δ) with |δ| ≤ η. Applied to the affine map
(1 - t) p0 + t p1 it widens the exact result by ε(t) = η(|1-t||p0| + |t||p1|
+ |(1-t)p0 + t p1|), the notes' (13.7) after Farouki and Rajan
(`affine_roundoff`), a first-order bound that takes t and 1 - t as exact.
`rounded_affine_map` and `rounded_de_casteljau` run the arithmetic itself in
d bits (simulated in float64) and carry a centre and a radius per coordinate
through every step with a bound that also covers the rounding of 1 - t and
the η² terms, so that the box centre ± radius provably holds the exact value.
`evaluate_in_precision` evaluates a polynomial three ways in d-bit
arithmetic (the chaotic band of the notes' Figure 13.1) and `error_bound` is
the a-priori size of that band.

Simulated arithmetic: d-bit numbers are float64 numbers with at most d
significant bits; each operation is done in float64 and rounded to d bits.
For d <= 25 the float64 result is exact or too close to a d-bit number to
round differently, so this is correctly rounded d-bit arithmetic (with the
exponent range of float64: no underflow or overflow is modelled); d = 53 is
float64 itself. Bounds assume that nothing underflows or overflows.
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

import numpy as np

from ._validation import as_count, as_float_array, as_parameter, as_points, as_scalar, as_vector
from .bezier import bernstein_matrix
from .polynomials import bernstein_to_power

__all__ = [
    "machine_unit",
    "decode_float",
    "encode_float",
    "round_to_bits",
    "neighbours",
    "float_interval",
    "affine_roundoff",
    "rounded_affine_map",
    "rounded_de_casteljau",
    "evaluate_in_precision",
    "exact_value",
    "error_bound",
]

FLOAT64_BITS = 53
# Up to this many bits, float64 operations on d-bit numbers followed by one rounding to d bits are correctly rounded.
MAX_SIMULATED_BITS = 25
METHODS = ("de_casteljau", "horner", "bernstein_horner")
# A radius is a sum of non-negative float64 terms, each step rounding at most ten times by 2^-53:
# one factor (1 + 2^-49) per step rounds the step's radius up (barring underflow).
_RADIUS_UP = 1.0 + 2.0**-49


# --- bits and rounding ------------------------------------------------------------------------


def _bits(d, name: str = "d", minimum: int = 1) -> int:
    return as_count(d, name, minimum)


def machine_unit(d: int) -> float:
    """The machine unit η = 2^-d of d-bit rounding to nearest (13.4): |fl(x) - x| <= η|x|. Notes §13.

    d: the number of significant bits, >= 1 (24 for IEEE single with its
    hidden bit, 53 for double; NumPy's `finfo(...).eps` is 2η).

    >>> from cagd_ref.floating import machine_unit
    >>> machine_unit(24) == 2.0**-24
    True
    """
    return 2.0 ** -_bits(d)


def _round(x: np.ndarray, d: int) -> np.ndarray:
    """x rounded to d significant bits, to nearest with ties to even (no checks; d <= 53 changes nothing above)."""
    if d >= FLOAT64_BITS:
        return x
    fraction, exponent = np.frexp(x)  # x = fraction 2^exponent, |fraction| in [1/2, 1)
    return np.ldexp(np.rint(np.ldexp(fraction, d)), exponent - d)  # rint: to nearest, ties to even


def round_to_bits(x, d: int):
    """x rounded to d significant bits, to nearest with ties to even: fl(x) in d-bit arithmetic. Notes §13.

    x: a number -> float, or an array of any shape -> an array of that shape.
    d: the number of significant bits, >= 1; from 53 on float64 is returned
    unchanged. With x = f 2^e, 1/2 <= |f| < 1, the result is rint(f 2^d) 2^(e-d):
    rounding is relative to the exponent of x, so |round_to_bits(x, d) - x| <= 2^-d |x|.
    For d = 24 and d = 11 this is what numpy.float32 and numpy.float16 do (in
    their normal ranges); it knows no exponent limits.

    >>> from cagd_ref.floating import round_to_bits
    >>> round_to_bits(1 / 3, 23) == 5592405 / 2**24          # the notes' lower neighbour of 1/3
    True
    >>> print(round_to_bits(0.3, 4), round_to_bits(-9.3, 4))
    0.3125 -9.0
    >>> round_to_bits([0.53125, 0.59375], 4).tolist()        # ties go to the even neighbour
    [0.5, 0.625]
    """
    values = as_float_array(x, "x")
    bits = _bits(d)
    with np.errstate(over="ignore"):
        rounded = _round(values, bits)
    if not np.all(np.isfinite(rounded)):
        raise ValueError(f"x: rounding to {bits} bits overflows the float64 range")
    return float(rounded) if rounded.ndim == 0 else rounded


def neighbours(x, d: int) -> tuple[float, float]:
    """The d-bit numbers next to x: the largest below it and the smallest above it. Notes §13.

    x: a number (representable or not); d: 1 <= d <= 53. For d = 53 these
    are numpy.nextafter(x, -inf) and numpy.nextafter(x, inf). With an
    unlimited exponent there is no d-bit number next to 0, so x = 0 is refused.

    >>> from cagd_ref.floating import neighbours
    >>> low, high = neighbours(1 / 3, 23)     # the notes' two neighbours of 1/3
    >>> low * 2**24, high * 2**23
    (5592405.0, 2796203.0)
    """
    value = as_scalar(x, "x")
    bits = _bits(d)
    if bits > FLOAT64_BITS:
        raise ValueError(f"d: float64 holds at most {FLOAT64_BITS} significant bits, got {bits}")
    if value == 0:
        raise ValueError("x: with an unlimited exponent no d-bit number is next to 0")
    rounded = float(_round(np.float64(value), bits))
    magnitude = abs(rounded)
    fraction, exponent = np.frexp(magnitude)
    up = np.ldexp(1.0, int(exponent) - bits)  # the spacing above |rounded|
    down = up / 2 if fraction == 0.5 else up  # below a power of two the spacing halves
    if value < 0:
        up, down = down, up
    low = rounded - down if rounded >= value else rounded
    high = rounded + up if rounded <= value else rounded
    return float(low), float(high)


def float_interval(b, d: int, exact: bool = False) -> tuple[float, float]:
    """The interval [lo, hi] of the reals that round to the d-bit number b (the notes' lost 13.3). Notes §13.

    b: a number with at most d significant bits (a ValueError otherwise: round
    it first); d: 1 <= d <= 50 (so that the ends are float64 numbers). With
    b = f 2^e, 1/2 <= |f| < 1, the neighbours of b are 2^(e-d) away, and the
    reals closer to b than to them form b ± 2^(e-d-1) (the default). At a
    power of two the neighbour towards 0 is only half as far (a smaller
    exponent): `exact=True` gives that interval, 2^(e-d-2) on that side. The
    ends are the ties, which round to b only when b is the even neighbour.
    Only 0 rounds to 0 (no exponent limit), so b = 0 gives (0.0, 0.0).
    Either way the interval lies in b ± η|b|, η = 2^-d.

    >>> from cagd_ref.floating import float_interval
    >>> low, high = float_interval(5592405 / 2**24, 23)          # the lower neighbour of 1/3 ...
    >>> low * 2**25, high * 2**25, low <= 1 / 3 <= high          # ... is the one that 1/3 rounds to
    (11184809.0, 11184811.0, True)
    >>> float_interval(0.5, 4), float_interval(0.5, 4, exact=True)
    ((0.46875, 0.53125), (0.484375, 0.53125))
    """
    value = as_scalar(b, "b")
    bits = _bits(d)
    if bits > 50:
        raise ValueError(f"d: expected at most 50 bits (so that the ends are float64 numbers), got {bits}")
    if float(_round(np.float64(value), bits)) != value:
        raise ValueError(f"b: {value!r} has more than {bits} significant bits; round it first (round_to_bits)")
    if value == 0:
        return 0.0, 0.0
    fraction, exponent = np.frexp(abs(value))
    half = float(np.ldexp(1.0, int(exponent) - bits - 1))  # half the spacing to the neighbours
    below = half / 2 if exact and fraction == 0.5 else half  # towards 0 from a power of two
    if value < 0:
        return value - half, value + below
    return value - below, value + half


# --- the notes' toy format --------------------------------------------------------------------


def _fields(bits) -> tuple[str, str, str]:
    if not isinstance(bits, str):
        raise TypeError(f"bits: expected a string 's|exponent|fraction' of 0s and 1s, got {type(bits).__name__}")
    fields = bits.split("|")
    if len(fields) != 3 or any(set(field) - {"0", "1"} or not field for field in fields):
        raise ValueError(f"bits: expected 's|exponent|fraction', three non-empty fields of 0s and 1s, got {bits!r}")
    sign, exponent, fraction = fields
    if len(sign) != 1 or len(exponent) < 2:
        raise ValueError(
            f"bits: expected one sign bit and an exponent of a sign bit and at least one magnitude bit, got {bits!r}"
        )
    return sign, exponent, fraction


def _decoded(bits: str) -> Fraction:
    """The exact value (-1)^s f 2^e of a string of the notes' format (13.2)."""
    sign, exponent, fraction = _fields(bits)
    e = int(exponent[1:], 2) * (-1 if exponent[0] == "1" else 1)  # sign-magnitude, the most significant bit first
    f = Fraction(int(fraction, 2), 2 ** len(fraction))  # f_1 is worth 1/2, f_d is worth 2^-d
    return (-1 if sign == "1" else 1) * f * Fraction(2) ** e


def decode_float(bits: str) -> float:
    """The value b = (-1)^s f 2^e of a number in the notes' binary format, (13.2). Notes §13.

    bits: 's|e_s e_k ... e_0|f_1 f_2 ... f_d', three fields of 0s and 1s
    separated by '|' and read with the widths they have: one sign bit s; an
    exponent in sign-magnitude form, its sign bit e_s and then its magnitude
    bits, the most significant first (e = (-1)^e_s Σ e_j 2^j); the fraction bits
    f = Σ f_i 2^-i (f_1 is worth 1/2). Unlike IEEE 754 there is no exponent
    bias and no hidden leading 1: a normalised fraction has f_1 = 1. Any
    fraction decodes by the formula; a ValueError when the value is not
    exactly a float64 (more than 53 significant bits, or out of range).

    >>> from cagd_ref.floating import decode_float
    >>> decode_float("0|100000001|11100000000000000000000")      # .111 x 2^-1 = 7/16
    0.4375
    >>> decode_float("1|000000100|10011000000000000000000")      # -.10011 x 2^4 = -9 1/2
    -9.5
    """
    exact = _decoded(bits)
    try:
        value = float(exact)
    except OverflowError:
        raise ValueError(f"bits: {bits!r} is too large for a float64") from None
    if Fraction(value) != exact:
        raise ValueError(f"bits: the value of {bits!r} is not exactly a float64 (too many bits, or too small)")
    return -0.0 if exact == 0 and bits[0] == "1" else value


def encode_float(x, exponent_bits: int = 8, fraction_bits: int = 23) -> str:
    """The string 's|exponent|fraction' of x in the notes' format, rounded to nearest, ties to even. Notes §13.

    x: a number; exponent_bits: the width of the exponent field, its sign bit
    included (>= 2; the notes' 32-bit layout has 8, so exponents up to ±127);
    fraction_bits: d >= 1 (23 in the notes). The fraction is normalised to
    [1/2, 1) (f_1 = 1); zero is all zeros. A ValueError when the rounded x
    needs an exponent beyond the field. (The notes' printed examples carry a
    9-bit exponent field: `decode_float` reads them as printed.)

    >>> from cagd_ref.floating import encode_float
    >>> encode_float(7 / 16)
    '0|10000001|11100000000000000000000'
    >>> encode_float(-9.5, exponent_bits=9)
    '1|000000100|10011000000000000000000'
    """
    value = as_scalar(x, "x")
    width = _bits(exponent_bits, "exponent_bits", 2)
    d = _bits(fraction_bits, "fraction_bits")
    if value == 0:
        return f"0|{'0' * width}|{'0' * d}"
    exact = Fraction(value)
    magnitude = abs(exact)
    e = magnitude.numerator.bit_length() - magnitude.denominator.bit_length()
    if magnitude >= Fraction(2) ** e:  # make 2^(e-1) <= |x| < 2^e, so that f = |x| 2^-e is in [1/2, 1)
        e += 1
    scaled = magnitude / Fraction(2) ** e * 2**d
    digits = round(scaled)  # Python rounds a Fraction to nearest, ties to even
    if digits == 2**d:  # rounded up to f = 1: renormalise
        digits, e = 2 ** (d - 1), e + 1
    limit = 2 ** (width - 1) - 1
    if abs(e) > limit:
        raise ValueError(f"x: {value!r} needs the exponent {e}; a {width}-bit exponent field holds -{limit}..{limit}")
    exponent = ("1" if e < 0 else "0") + format(abs(e), f"0{width - 1}b")
    return f"{'1' if value < 0 else '0'}|{exponent}|{format(digits, f'0{d}b')}"


# --- roundoff of affine maps -------------------------------------------------------------------


def _eta(eta, name: str = "eta") -> float:
    value = as_scalar(eta, name)
    if value < 0:
        raise ValueError(f"{name}: expected a machine unit >= 0, got {value}")
    return value


def _pair(p0, p1, names: tuple[str, str] = ("p0", "p1")) -> tuple[np.ndarray, np.ndarray]:
    a, b = as_float_array(p0, names[0]), as_float_array(p1, names[1])
    if a.ndim > 1 or a.size == 0:
        raise ValueError(f"{names[0]}: expected a number or a vector (d,), got shape {a.shape}")
    if b.shape != a.shape:
        raise ValueError(f"{names[1]}: expected the shape of {names[0]}, {a.shape}, got shape {b.shape}")
    return a, b


def affine_roundoff(p0, p1, t, eta):
    """The widening ε(t) = η(|1-t||p0| + |t||p1| + |(1-t)p0 + t p1|) of an affine map done in floating point, (13.7).

    Notes §13, after Farouki and Rajan (eq. 26). p0, p1: numbers or vectors
    (d,) of the same shape (the centres of the two boxes; every |.| is taken
    per coordinate, so the widening is a box too); t: any real number ->
    the shape of p0, or a 1-D array of k values -> (k,) or (k, d); eta: the
    machine unit η >= 0. The notes' three cases t < 0, 0 <= t <= 1 and t > 1
    are this one formula with |1 - t| and |t| written out. It is a
    first-order bound that takes t and 1 - t as exact numbers (see
    `rounded_affine_map` for one that holds when 1 - t is rounded too).

    >>> from cagd_ref.floating import affine_roundoff
    >>> eta = 2.0**-24
    >>> [affine_roundoff(2.0, -3.0, t, eta) / eta for t in (0.5, -0.5, 2.0)]
    [3.0, 9.0, 16.0]
    >>> (affine_roundoff([1.0, -2.0], [3.0, 4.0], 0.25, eta) / eta).tolist()
    [3.0, 3.0]

    Ref: R. T. Farouki and V. T. Rajan, CAGD 4(3), 1987, 191-216 (numerical condition of the Bernstein
    form; their eq. 26 is the widening).
    """
    a, b = _pair(p0, p1)
    ts, scalar = as_parameter(t)
    unit = _eta(eta)
    tt = ts.reshape((-1,) + (1,) * a.ndim)
    widening = unit * (np.abs(1 - tt) * np.abs(a) + np.abs(tt) * np.abs(b) + np.abs((1 - tt) * a + tt * b))
    if scalar:
        return float(widening[0]) if a.ndim == 0 else widening[0]
    return widening


def _simulated(d: int, name: str) -> int:
    if not (2 <= d <= MAX_SIMULATED_BITS or d == FLOAT64_BITS):
        raise ValueError(f"{name}: expected d-bit arithmetic with 2 <= d <= {MAX_SIMULATED_BITS} (simulated) "
                         f"or d = 53 (float64), got d = {d}")
    return d


def _arithmetic_bits(eta) -> int:
    """The d of a machine unit η = 2^-d whose arithmetic can be simulated exactly: 2 <= d <= 25, or 53."""
    unit = as_scalar(eta, "eta")
    fraction, exponent = np.frexp(unit)
    if fraction != 0.5:
        raise ValueError(f"eta: expected the machine unit 2**-d of d-bit arithmetic, got {unit!r}")
    return _simulated(1 - int(exponent), "eta")


def _d_bit_parameters(t, d: int) -> tuple[np.ndarray, bool]:
    ts, scalar = as_parameter(t)
    if np.any(_round(ts, d) != ts):
        bad = ts[_round(ts, d) != ts][0]
        raise ValueError(f"t: the parameters of {d}-bit arithmetic have at most {d} significant bits, got {bad!r} "
                         f"(round them first: round_to_bits(t, {d}))")
    return ts, scalar


def _complement(t, d: int) -> tuple[np.ndarray, np.ndarray]:
    """s = fl(1 - t) in d-bit arithmetic, and whether s is 1 - t exactly (TwoSum recovers the float64 error)."""
    x = 1 - t
    z = x - 1
    error = (1 - (x - z)) + (-t - z)  # 1 - t = x + error exactly (Knuth's TwoSum)
    s = _round(x, d)
    return s, (s == x) & (error == 0)


def _rounded_step(a, ea, b, eb, t, d: int, gamma: float) -> tuple[np.ndarray, np.ndarray]:
    """One rounded interpolation of boxes a ± ea and b ± eb at t: the d-bit centre and a radius that covers it.

    With s = fl(1 - t) and c = fl(fl(s a) + fl(t b)) the rounding model gives
    |c - ((1-t)a + t b)| <= (2η + η²)|1-t||a| + η|t||b| + η|c|/(1-η), which
    γ(2|1-t||a| + |t||b| + |c|), γ = η/(1-η), bounds; when s is 1 - t exactly
    the first term is γ|1-t||a|, as in (13.7). The boxes add |1-t| ea + |t| eb
    (12.25). The radius is rounded up (`_RADIUS_UP`).
    """
    s, exact = _complement(t, d)
    centre = _round(_round(s * a, d) + _round(t * b, d), d)
    u, v = np.abs(1 - t), np.abs(t)
    widening = gamma * (np.where(exact, 1.0, 2.0) * u * np.abs(a) + v * np.abs(b) + np.abs(centre))
    return centre, (u * ea + v * eb + widening) * _RADIUS_UP


def _representation(points: np.ndarray, d: int) -> tuple[np.ndarray, np.ndarray]:
    """The d-bit points and their exact rounding errors |P - fl(P)| (the first source of error)."""
    rounded = _round(points, d)
    return rounded, np.abs(points - rounded)  # exact in float64: P and fl(P) are within a factor 2 (Sterbenz)


def rounded_affine_map(c0, e0, c1, e1, t, eta) -> tuple[np.ndarray, np.ndarray]:
    """The box (1-t)[P0] + t[P1] computed in d-bit arithmetic, η = 2^-d, with a radius that covers the rounding.

    Notes §13 (Figure 13.2). [P0] = c0 ± e0 and [P1] = c1 ± e1 per
    coordinate: c0, c1 numbers or vectors (d,), e0, e1 >= 0 of the same
    shape; t: a number -> (centre, radius) of that shape, or k values -> (k, d)
    (or (k,)); t is used as given (1 - t and the products are rounded) and
    must have at most d significant bits; eta: 2^-d, 2 <= d <= 25 or d = 53.
    The centres are rounded to d bits first (their errors join the radius).
    Every real point (1-t)p0 + t p1 with p0 in [P0] and p1 in [P1] lies in
    centre ± radius: (12.25) plus a widening that is (13.7) with its
    |1-t||p0| term doubled (1 - t is rounded too) and η replaced by η/(1-η).

    >>> from cagd_ref.floating import rounded_affine_map
    >>> centre, radius = rounded_affine_map(2.0, 0.1, -3.0, 0.2, -0.5, 2.0**-24)
    >>> float(centre), round(float((radius - 0.25) / 2.0**-24), 3)   # 1.5·0.1 + 0.5·0.2, widened by 9η
    (4.5, 9.0)
    """
    a, b = _pair(c0, c1, ("c0", "c1"))
    ea, eb = (as_float_array(e, name) for e, name in ((e0, "e0"), (e1, "e1")))
    for e, name in ((ea, "e0"), (eb, "e1")):
        if e.shape != a.shape or np.any(e < 0):
            raise ValueError(f"{name}: expected radii >= 0 of the shape of c0, {a.shape}, got {e.tolist()}")
    d = _arithmetic_bits(eta)
    ts, scalar = _d_bit_parameters(t, d)
    gamma = float(eta) / (1 - float(eta))
    (a, ra), (b, rb) = _representation(a, d), _representation(b, d)
    tt = ts.reshape((-1,) + (1,) * a.ndim)
    centre, radius = _rounded_step(a, ea + ra, b, eb + rb, tt, d, gamma)
    if scalar:
        return (float(centre[0]), float(radius[0])) if a.ndim == 0 else (centre[0], radius[0])
    return centre, radius


def rounded_de_casteljau(points, t, eta, radii=None) -> tuple[np.ndarray, np.ndarray]:
    """De Casteljau in d-bit arithmetic (η = 2^-d) with a box centre ± radius that provably holds the exact value.

    Notes §13. points: (n+1, dim) float64 control points, rounded to d bits
    first (the first source of error: their exact rounding errors start the
    radii); radii: None or (n+1, dim) >= 0, boxes around the points (an
    interval Bézier curve, chapter 12); t: a number -> (centre (dim,),
    radius (dim,)), or k values -> ((k, dim), (k, dim)); any real t with at
    most d significant bits; eta: 2^-d with 2 <= d <= 25 (simulated) or
    d = 53 (float64). Each round replaces neighbouring boxes by
    `rounded_affine_map` of them (the second source of error: the
    arithmetic). Every curve whose control points lie in the boxes passes at
    t, computed exactly, through centre ± radius, barring underflow.

    >>> from cagd_ref.floating import rounded_de_casteljau
    >>> eta = 2.0**-24
    >>> centre, radius = rounded_de_casteljau([[1.0], [-3.0], [9.0], [-27.0]], 0.25, eta)  # (1 - 4t)³
    >>> float(centre[0]), round(float(radius[0] / eta), 6)    # 1 - t = 3/4 is exact: (27/8) η
    (0.0, 3.375)
    """
    pts = as_points(points)
    d = _arithmetic_bits(eta)
    ts, scalar = _d_bit_parameters(t, d)
    boxes = np.zeros_like(pts) if radii is None else as_float_array(radii, "radii")
    if boxes.shape != pts.shape or np.any(boxes < 0):
        raise ValueError(f"radii: expected radii >= 0 of the shape of points, {pts.shape}, got shape {boxes.shape}")
    gamma = float(eta) / (1 - float(eta))
    centres, errors = _representation(pts, d)
    tau = ts[:, None, None]  # one copy of the polygon per parameter, (k, n+1, dim)
    centre = np.broadcast_to(centres, (len(ts),) + pts.shape)
    radius = np.broadcast_to(errors + boxes, centre.shape)
    while centre.shape[1] > 1:
        centre, radius = _rounded_step(centre[:, :-1], radius[:, :-1], centre[:, 1:], radius[:, 1:], tau, d, gamma)
    centre, radius = centre[:, 0].copy(), radius[:, 0].copy()
    return (centre[0], radius[0]) if scalar else (centre, radius)


# --- the chaotic band of Figure 13.1 ----------------------------------------------------------


def _de_casteljau_rounded(c: np.ndarray, t: np.ndarray, d: int) -> np.ndarray:
    s = _complement(t, d)[0][:, None]
    level = np.broadcast_to(c, (len(t), len(c)))
    while level.shape[1] > 1:
        level = _round(_round(s * level[:, :-1], d) + _round(t[:, None] * level[:, 1:], d), d)
    return level[:, 0]


def _horner_rounded(a: np.ndarray, t: np.ndarray, d: int) -> np.ndarray:
    value = np.full(len(t), a[-1])
    for coefficient in a[-2::-1]:
        value = _round(_round(value * t, d) + coefficient, d)
    return value


def _bernstein_horner_rounded(c: np.ndarray, t: np.ndarray, d: int) -> np.ndarray:
    """(((c0 s + c1 t) s + c2 t²) s + ...) s + cn tⁿ, c_i = fl(C(n, i) b_i), in the order of chapter 3."""
    n = len(c) - 1
    if n == 0:
        return np.full(len(t), c[0])
    s = _complement(t, d)[0]
    value, power = _round(c[0] * s, d), np.ones_like(t)
    for coefficient in c[1:-1]:
        power = _round(power * t, d)
        value = _round(_round(value + _round(coefficient * power, d), d) * s, d)
    return _round(value + _round(c[-1] * _round(power * t, d), d), d)


def evaluate_in_precision(coeffs, t, bits: int, method: str = "de_casteljau"):
    """Σ b_i B_i^n(t) evaluated in `bits`-bit arithmetic, rounding after every operation (Figure 13.1). Notes §13.

    coeffs: Bernstein coefficients (n+1,) on [0, 1]; t: a number -> float, or
    k values -> (k,), each first rounded to `bits` bits; bits: 2..25, or 53
    (float64); method: "de_casteljau" (the triangle, notes §2.3), "horner"
    (Horner's rule on the power form from `bernstein_to_power`, notes §3.1) or
    "bernstein_horner" (the nested Bernstein form, notes §3.2). The
    coefficients, converted in float64, are rounded to `bits` bits once.
    With bits = 24 the de Casteljau values are those of numpy.float32.

    >>> from cagd_ref.floating import evaluate_in_precision
    >>> cubic = [1.0, -3.0, 9.0, -27.0]                    # (1 - 4t)³, a triple root at t = 1/4
    >>> [evaluate_in_precision(cubic, 0.25, 24, m) for m in ("de_casteljau", "horner", "bernstein_horner")]
    [0.0, 0.0, 0.0]
    >>> print(evaluate_in_precision(cubic, 0.2500123, 24), evaluate_in_precision(cubic, 0.2500123, 53))
    -3.725429920109491e-08 -1.1902609668504655e-13
    """
    b = as_vector(coeffs, "coeffs")
    d = _simulated(as_count(bits, "bits"), "bits")
    if method not in METHODS:
        raise ValueError(f"method: expected one of {METHODS}, got {method!r}")
    ts, scalar = as_parameter(t)
    tau = _round(ts, d)
    if method == "de_casteljau":
        values = _de_casteljau_rounded(_round(b, d), tau, d)
    elif method == "horner":
        values = _horner_rounded(_round(bernstein_to_power(b), d), tau, d)
    else:
        n = len(b) - 1
        values = _bernstein_horner_rounded(_round(b * [comb(n, i) for i in range(n + 1)], d), tau, d)
    return float(values[0]) if scalar else values


def exact_value(coeffs, t):
    """Σ b_i B_i^n(t) computed exactly in rational arithmetic and rounded once to float64: the truth to compare with.

    Notes §13. coeffs: Bernstein coefficients (n+1,); t: a number -> float, or
    k values -> (k,). Slow on purpose (fractions.Fraction, one parameter at
    a time): it is the independent yardstick of the chapter's measurements.

    >>> from cagd_ref.floating import exact_value
    >>> exact_value([1.0, -3.0, 9.0, -27.0], 0.2500123)       # (1 - 4t)³ = (-4.92e-5)³
    -1.1909548800059918e-13
    """
    b = as_vector(coeffs, "coeffs")
    ts, scalar = as_parameter(t)
    coefficients = [Fraction(float(c)) for c in b]
    values = np.empty(len(ts))
    for k, tk in enumerate(ts):  # exact arithmetic has no vector form
        tau = Fraction(float(tk))
        level = coefficients
        while len(level) > 1:
            level = [(1 - tau) * x + tau * y for x, y in zip(level[:-1], level[1:])]
        values[k] = float(level[0])
    return float(values[0]) if scalar else values


def error_bound(coeffs, t, eta):
    """The a-priori bound 3nη Σ|b_i| B_i^n(t) on the rounding error of d-bit de Casteljau, to first order in η.

    Notes §13. coeffs: Bernstein coefficients (n+1,) of degree n; t: a number
    -> float, k values -> (k,), in [0, 1]; eta: the machine unit η >= 0.
    Each of the n rounds adds at most 3η times the absolute-value curve
    Σ|b_i| B_i^n(t) to the radius of `rounded_de_casteljau`: the band of
    Figure 13.1 is that wide wherever the curve is small against Σ|b_i| B_i^n.

    >>> from cagd_ref.floating import error_bound
    >>> error_bound([1.0, -3.0, 9.0, -27.0], 0.25, 1.0) == 9 * 27 / 8    # Σ|b_i|B_i = (1 + 2t)³
    True
    """
    b = as_vector(coeffs, "coeffs")
    ts, scalar = as_parameter(t)
    unit = _eta(eta)
    if np.any((ts < 0) | (ts > 1)):
        raise ValueError(f"t: the a-priori bound holds for 0 <= t <= 1, got {ts[(ts < 0) | (ts > 1)][0]!r}")
    values = 3 * (len(b) - 1) * unit * (bernstein_matrix(len(b) - 1, ts) @ np.abs(b))
    return float(values[0]) if scalar else values

"""Reads the fields as IEEE 754: a biased exponent and a hidden leading 1."""
from fractions import Fraction


def decode_float(bits):
    if not isinstance(bits, str):
        raise TypeError("bits must be a string")
    parts = bits.split("|")
    if len(parts) != 3 or len(parts[0]) != 1 or len(parts[1]) < 2 or not parts[2]:
        raise ValueError("bits: expected s|exponent|fraction")
    if any(set(p) - set("01") for p in parts):
        raise ValueError("bits: only 0 and 1")
    sign, exponent, fraction = parts
    bias = 2 ** (len(exponent) - 1) - 1
    e = int(exponent, 2) - bias
    f = 1 + Fraction(int(fraction, 2), 2 ** len(fraction))
    value = f * Fraction(2) ** e
    return float(-value if sign == "1" else value)

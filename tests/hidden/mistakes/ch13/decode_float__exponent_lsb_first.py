"""Reads the exponent magnitude with its least significant bit first."""
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
    e = int(exponent[1:][::-1], 2) * (-1 if exponent[0] == "1" else 1)
    f = Fraction(int(fraction, 2), 2 ** len(fraction))
    value = f * Fraction(2) ** e
    return float(-value if sign == "1" else value)

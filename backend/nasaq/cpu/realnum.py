"""IEEE 754 single precision for REAL instructions, and the status bits of a REAL result.

ACCU1 holds the 32-bit pattern; arithmetic runs in Python floats (doubles) and rounds to single
once, which gives the same result as single-precision hardware for + - * / and SQRT.
Status of a result (S7 manual): NaN → CC1 CC0 OV OS = 1 1 1 1; +inf 1 0 1 1; -inf 0 1 1 1;
denormal (underflow) 0 0 1 1; zero 0 0 0 -; positive 1 0 0 -; negative 0 1 0 -.
Every NaN a REAL instruction produces is 16#FFFF_FFFF, as on the S7 CPUs.
"""

from __future__ import annotations

import math
import struct

_F = struct.Struct(">f")
_U = struct.Struct(">I")
_D = struct.Struct(">d")  # LREAL (S7-1200/1500): an IEEE 754 double
_Q = struct.Struct(">Q")
NAN_BITS = 0xFFFFFFFF  # an S7 CPU delivers every NaN result as 16#FFFF_FFFF
MIN_NORMAL = 1.1754943508222875e-38


def to_float(bits: int) -> float:
    value: float = _F.unpack(_U.pack(bits & 0xFFFFFFFF))[0]
    return value


def to_bits(value: float) -> int:
    if value != value:
        return NAN_BITS
    try:
        bits: int = _U.unpack(_F.pack(value))[0]
    except OverflowError:
        return 0x7F800000 if value > 0 else 0xFF800000
    return bits


def float_of(bits: int, size: int) -> float:
    """The REAL (``size`` 4) or LREAL (8) with the bit pattern ``bits``."""
    if size == 4:
        return to_float(bits)
    value: float = _D.unpack(_Q.pack(bits & 0xFFFFFFFFFFFFFFFF))[0]
    return value


def bits_of(value: float, size: int) -> int:
    """The bit pattern of ``value`` as a REAL (``size`` 4: rounded to single, NaN as the CPU
    gives it, beyond the range infinity) or an LREAL (8)."""
    if size == 4:
        return to_bits(value)
    bits: int = _Q.unpack(_D.pack(value))[0]
    return bits


def ieee(op: str, x: float, y: float) -> float:
    """``x op y`` (``+ - * /``) in doubles, a division by zero as IEEE 754 has it (±infinity,
    NaN for 0/0)."""
    try:
        if op == "+":
            return x + y
        if op == "-":
            return x - y
        if op == "*":
            return x * y
        if y == 0.0:
            if x == 0.0 or x != x:
                return math.nan
            return math.copysign(math.inf, x) * math.copysign(1.0, y)
        return x / y
    except OverflowError:
        return math.inf


def status(bits: int) -> tuple[int, int, int, int]:
    """(CC1, CC0, OV, sets_OS) of a REAL result pattern."""
    exponent = (bits >> 23) & 0xFF
    negative = bits >> 31
    if exponent == 0xFF:
        if bits & 0x7FFFFF:
            return 1, 1, 1, 1
        return (0, 1, 1, 1) if negative else (1, 0, 1, 1)
    if exponent == 0:
        if bits & 0x7FFFFF:
            return 0, 0, 1, 1
        return 0, 0, 0, 0
    return (0, 1, 0, 0) if negative else (1, 0, 0, 0)


def result(value: float, os: int) -> tuple[int, int, int, int, int]:
    """(ACCU1, CC1, CC0, OV, OS) after a REAL instruction produced ``value``. A result too small
    for a normalised REAL is an underflow even when it rounds to zero."""
    bits = to_bits(value)
    cc1, cc0, ov, sets_os = status(bits)
    if not bits & 0x7FFFFFFF and value != 0.0:
        ov = sets_os = 1
    return bits, cc1, cc0, ov, os | sets_os


def arith(op: str, a2: int, a1: int, os: int) -> tuple[int, int, int, int, int]:
    return result(ieee(op, to_float(a2), to_float(a1)), os)


def _function(name: str, x: float) -> float:
    if x != x:
        return math.nan
    try:
        if name == "SQR":
            return x * x
        if name == "SQRT":
            return math.sqrt(x) if x >= 0 else math.nan
        if name == "EXP":
            return math.exp(x) if x < 1000 else math.inf
        if name == "LN":
            return math.log(x) if x > 0 else math.nan
        if name in ("SIN", "COS", "TAN"):
            if math.isinf(x):
                return math.nan
            return {"SIN": math.sin, "COS": math.cos, "TAN": math.tan}[name](x)
        if name in ("ASIN", "ACOS"):
            if not -1.0 <= x <= 1.0:
                return math.nan
            return math.asin(x) if name == "ASIN" else math.acos(x)
        return math.atan(x)
    except (OverflowError, ValueError):
        return math.nan


def function(name: str, a1: int, os: int) -> tuple[int, int, int, int, int]:
    return result(_function(name, to_float(a1)), os)


def compare(a2: int, a1: int, relation: str, os: int) -> tuple[int, int, int, int, int]:
    """(RLO, CC1, CC0, OV, OS) of a REAL comparison of ACCU2 with ACCU1."""
    x, y = to_float(a2), to_float(a1)
    if x != x or y != y:
        return 0, 1, 1, 1, 1
    holds = {
        "==": x == y,
        "!=": x != y,
        ">": x > y,
        "<": x < y,
        ">=": x >= y,
        "<=": x <= y,
    }[relation]
    return int(holds), int(x > y), int(x < y), 0, os


def rounded(mode: str, a1: int, os: int) -> tuple[int, int, int]:
    """RND RND+ RND- TRUNC: (ACCU1, OV, OS); out of DINT range keeps ACCU1 and sets OV OS."""
    x = to_float(a1)
    if x != x or math.isinf(x):
        return a1, 1, 1
    if mode == "RND":
        value = round(x)  # halves go to the even neighbour, as on the CPU
    elif mode == "RND+":
        value = math.ceil(x)
    elif mode == "RND-":
        value = math.floor(x)
    else:
        value = math.trunc(x)
    if not -0x80000000 <= value <= 0x7FFFFFFF:
        return a1, 1, 1
    return value & 0xFFFFFFFF, 0, os


def from_dint(a1: int) -> int:
    return to_bits(float((a1 ^ 0x80000000) - 0x80000000))

"""Bit patterns of elementary S7 types as the values a monitor shows (JSON-friendly).

A 64-bit integer (LINT, ULINT, LWORD, LTIME in nanoseconds) whose magnitude is above 2**53 - 1
is sent as its decimal digits in a string: a browser reads JSON numbers as doubles and would
round it. Smaller ones stay numbers, so trends and inline values take them as they are.
"""

from __future__ import annotations

import math
import struct

from nasaq.ir import types as ir_types

Value = bool | int | float | str | None

# The types a monitor shows as one value: those that fit an accumulator (and the TOD alias).
ELEMENTARY_BITS = (
    {name: ir_types.ELEMENTARY_BITS[name] for name in ir_types.ACCU_TYPES}
    | {
        alias: ir_types.ELEMENTARY_BITS[name]
        for alias, name in ir_types.TYPE_ALIASES.items()
        if name in ir_types.ACCU_TYPES
    }
    | dict.fromkeys(ir_types.LONG_TYPES, 64)
)
SAFE_INTEGER = 2**53 - 1  # the largest integer a JSON reader in a browser keeps exact
_S5_BASES = (10, 100, 1000, 10000)


def signed(pattern: int, bits: int) -> int:
    return pattern - (1 << bits) if pattern >> (bits - 1) & 1 else pattern


def real(pattern: int) -> float | str:
    value: float = struct.unpack(">f", (pattern & 0xFFFFFFFF).to_bytes(4, "big"))[0]
    return _shown_float(value)


def long_real(pattern: int) -> float | str:
    value: float = struct.unpack(">d", (pattern & 0xFFFF_FFFF_FFFF_FFFF).to_bytes(8, "big"))[0]
    return _shown_float(value)


def exact(number: int) -> int | str:
    """``number`` as JSON keeps it exact in a browser: a number, or its digits above 2**53."""
    return number if -SAFE_INTEGER <= number <= SAFE_INTEGER else str(number)


def _shown_float(value: float) -> float | str:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "+Inf" if value > 0 else "-Inf"
    return value


def s5time_ms(pattern: int) -> int:
    digits = pattern & 0xFFF
    count = (digits >> 8 & 15) * 100 + (digits >> 4 & 15) * 10 + (digits & 15)
    return count * _S5_BASES[pattern >> 12 & 3]


def decode(type_name: str, pattern: int | None) -> Value:
    """``pattern`` (unsigned, of the type's width) read as ``type_name``; None stays None."""
    if pattern is None:
        return None
    if type_name == "BOOL":
        return bool(pattern & 1)
    if type_name == "INT":
        return signed(pattern, 16)
    if type_name == "SINT":  # (USINT, UINT, UDINT are the unsigned pattern itself)
        return signed(pattern, 8)
    if type_name in ("DINT", "TIME"):
        return signed(pattern, 32)
    if type_name == "REAL":
        return real(pattern)
    if type_name == "CHAR":
        return chr(pattern & 0xFF)
    if type_name == "WCHAR":
        return chr(pattern & 0xFFFF)
    if type_name in ("LINT", "LTIME"):
        return exact(signed(pattern, 64))
    if type_name in ("ULINT", "LWORD"):
        return exact(pattern)
    if type_name == "LREAL":
        return long_real(pattern)
    if type_name == "S5TIME":
        return s5time_ms(pattern)
    return pattern

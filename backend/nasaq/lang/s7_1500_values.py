"""Values of the S7-1200/1500 64-bit types as bytes, shared by the compilers (constants) and
the CPU (the library FCs that compute with them, ``nasaq.cpu.long_library``).

In a standard (non-optimized) block every one is 8 bytes, big-endian like the classic types:
LINT and LTIME two's complement (LTIME counts nanoseconds), ULINT and LWORD unsigned, LREAL an
IEEE 754 double. ``LTIME#1D2H3M4S5MS6US7NS`` takes the units D, H, M, S, MS, US, NS (each
at most once, in that order, the first may have a fraction), as TIA Portal writes them.
"""

from __future__ import annotations

import re
import struct

from nasaq.lang.stl.constants import ConstantError, duration_ms

LINT_RANGE = (-(2**63), 2**63 - 1)
ULINT_MAX = 2**64 - 1
_DOUBLE = struct.Struct(">d")
_SIGNED = frozenset({"LINT", "LTIME"})
_UNIT_NS = {
    "d": 86_400 * 10**9,
    "h": 3_600 * 10**9,
    "m": 60 * 10**9,
    "s": 10**9,
    "ms": 10**6,
    "us": 10**3,
    "ns": 1,
}
_NUMBER = r"(\d+(?:\.\d+)?)"
_LTIME = re.compile(
    rf"^(?:{_NUMBER}D)?(?:{_NUMBER}H)?(?:{_NUMBER}M(?!S))?(?:{_NUMBER}S)?(?:{_NUMBER}MS)?"
    rf"(?:{_NUMBER}US)?(?:{_NUMBER}NS)?$"
)


def ltime_ns(body: str, text: str) -> int:
    """The nanoseconds of an ``LTIME#`` body; ConstantError (STL107/STL214) when it is none or
    out of range."""
    clean = body.replace("_", "").upper()
    negative = clean.startswith("-")
    clean = clean.lstrip("+-")
    match = _LTIME.match(clean) if clean else None
    if match is None or not any(match.groups()):
        raise ConstantError("STL107", text=text, reason="a duration is written like 1D2H3M4S5MS")
    total = 0
    for unit, amount in zip(_UNIT_NS, match.groups(), strict=True):
        if amount is not None:
            whole, _, fraction = amount.partition(".")
            total += int(whole) * _UNIT_NS[unit]
            if fraction:
                total += int(fraction) * _UNIT_NS[unit] // 10 ** len(fraction)
    ns = -total if negative else total
    low, high = LINT_RANGE
    if not low <= ns <= high:
        raise ConstantError("STL214", text=text, type="LTIME", hint="")
    return ns


def encode(type_name: str, value: int | float) -> bytes:
    """The 8 bytes of ``value`` as a ``type_name`` (integers wrap to 64 bits)."""
    if type_name == "LREAL":
        return _DOUBLE.pack(float(value))
    return (int(value) & ULINT_MAX).to_bytes(8, "big")


def decode(type_name: str, data: bytes) -> int | float:
    """The value of the 8 bytes ``data`` as a ``type_name``."""
    if type_name == "LREAL":
        return float(_DOUBLE.unpack(data)[0])
    return int.from_bytes(data, "big", signed=type_name in _SIGNED)


_INTEGER_LIMITS = {
    "SINT": (-(2**7), 2**7 - 1),
    "USINT": (0, 2**8 - 1),
    "UINT": (0, 2**16 - 1),
    "UDINT": (0, 2**32 - 1),
    "LINT": LINT_RANGE,
    "ULINT": (0, ULINT_MAX),
    "LWORD": (0, ULINT_MAX),
    "LTIME": LINT_RANGE,
}
_SIZES = {"SINT": 1, "USINT": 1, "UINT": 2, "UDINT": 4}
_FLOAT_PREFIXES = frozenset({"REAL", "LREAL"})


def initial_bytes(type_name: str, kind: str, text: str) -> bytes | None:
    """The bytes of an initial value written ``text`` (an STL value token of ``kind``: NUMBER,
    REAL or TYPED such as ``L#5``, ``DW#16#FF``, ``LINT#-5``, ``LREAL#1.5``, ``LTIME#2S``) for
    an S7-1200/1500 type; None when it is not one or does not fit. An integer for an LTIME is
    nanoseconds; a ``T#`` duration is converted."""
    value: int | float
    try:
        if kind == "REAL" or (
            kind == "TYPED" and text.partition("#")[0].upper() in _FLOAT_PREFIXES
        ):
            if type_name != "LREAL":
                return None
            value = float(text.partition("#")[2] if "#" in text else text)
            return encode("LREAL", value)
        if kind == "NUMBER":
            value = int(text)
        elif kind == "TYPED":
            value = _typed_integer(type_name, text)
        else:
            return None
    except (ValueError, ConstantError):
        return None
    if type_name == "LREAL":
        return encode("LREAL", value)
    low, high = _INTEGER_LIMITS[type_name]
    if type_name == "LWORD" and value < 0:
        value &= ULINT_MAX
    if not low <= value <= high:
        return None
    size = _SIZES.get(type_name, 8)
    return (value & ((1 << 8 * size) - 1)).to_bytes(size, "big")


def _typed_integer(type_name: str, text: str) -> int:
    prefix, _, body = text.partition("#")
    upper = prefix.upper()
    if upper in ("LT", "LTIME"):
        return ltime_ns(body, text)
    if upper in ("T", "TIME"):
        if type_name != "LTIME":
            raise ValueError(text)
        return duration_ms(body, text) * 1_000_000
    base_text, _, digits = body.rpartition("#")
    if upper in ("2", "8", "16"):
        base_text, digits = upper, body
    clean = digits.replace("_", "")
    return int(clean, int(base_text)) if base_text else int(clean)

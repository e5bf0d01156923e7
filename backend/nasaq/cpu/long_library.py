"""The bodies of the hidden library FCs of the S7-1200/1500 types (``nasaq.lang.long_library``):
Python functions over the references to the actual parameters, as ``nasaq.cpu.iec_library``'s
(a reference is ``(buffer, byte, bit)`` of the actual's first byte; RET_VAL's is where the
result goes). They return BR, which the caller sees as ENO.

Semantics (S7-1200/1500; where the manuals leave it open, the choice is marked *Nasaq*):
- LINT/ULINT/UDINT arithmetic wraps around in two's complement (64/32 bits), BR stays 1, as the
  S7-1500's SCL does with the overflow check off (*Nasaq*: ENO is not cleared on an overflow).
  ``/`` and ``DIV`` truncate toward zero, ``MOD`` has the sign of the dividend. A division by
  zero gives 0 and BR = 0.
- LREAL is an IEEE 754 double: a division by zero gives ±infinity (NaN for 0/0) and BR = 0.
- LTIME is a LINT of nanoseconds: + and - of two LTIMEs, * and / by an integer, wrapping.
- LWORD: AND, OR, XOR, NOT on 64 bits.
- Comparisons: the values (LREAL NaN is unequal to everything); BR = 1.
- Conversions (TIA Portal's names): integer to integer keeps the value; out of the target's
  range it keeps the low bits and BR = 0. REAL/LREAL to an integer rounds to the nearest (a
  half to the even neighbour, as RND); NaN, infinity or out of range give BR = 0 (and the low
  bits of the rounded value, 0 for NaN/infinity). Integer to REAL/LREAL rounds to the nearest
  representable value; LREAL_TO_REAL beyond the REAL range gives ±infinity and BR = 0.
  Bit strings and integers convert by their bit pattern (a signed value sign-extended, then
  cut to the target's width); a bit string and REAL/LREAL by the floating value's bit pattern
  (zero-filled or cut). LTIME_TO_TIME truncates to milliseconds (BR = 0 beyond TIME's range),
  TIME_TO_LTIME multiplies by 10^6; LTIME and LINT (and DINT, LREAL) convert by the number of
  nanoseconds.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from nasaq.cpu.errors import CpuError
from nasaq.cpu.realnum import bits_of, float_of, ieee
from nasaq.lang.long_library import ARITHMETIC, COMPARE, OPERATION_TYPES
from nasaq.lang.s7_1500_types import CONVERSIONS, INTEGER_RANGES

Ref = tuple[Any, int, int]
Body = Callable[[list[Ref]], int]

# type name -> (bytes, signed, kind): kind "i" integer or bit string, "f" REAL/LREAL
_FORMS: dict[str, tuple[int, bool, str]] = {
    "SINT": (1, True, "i"),
    "USINT": (1, False, "i"),
    "BYTE": (1, False, "i"),
    "INT": (2, True, "i"),
    "UINT": (2, False, "i"),
    "WORD": (2, False, "i"),
    "DINT": (4, True, "i"),
    "UDINT": (4, False, "i"),
    "DWORD": (4, False, "i"),
    "TIME": (4, True, "i"),
    "REAL": (4, True, "f"),
    "LINT": (8, True, "i"),
    "ULINT": (8, False, "i"),
    "LWORD": (8, False, "i"),
    "LTIME": (8, True, "i"),
    "LREAL": (8, True, "f"),
}
_BITS = frozenset({"BYTE", "WORD", "DWORD", "LWORD"})
_SIGNS = {"ADD": "+", "SUB": "-", "MUL": "*", "DIV": "/"}
_NS_PER_MS = 1_000_000


def _get(ref: Ref, kind: str) -> int | float:
    size, signed, form = _FORMS[kind]
    buf, byte, _bit = ref
    if buf is None or byte < 0 or byte + size > len(buf):
        raise CpuError("SIM503", address=f"byte {byte} (parameter)")
    value = int.from_bytes(buf[byte : byte + size], "big", signed=signed and form == "i")
    return float_of(value, size) if form == "f" else value


def _set(ref: Ref, kind: str, value: int | float) -> None:
    size, _signed, form = _FORMS[kind]
    buf, byte, _bit = ref
    if buf is None or byte < 0 or byte + size > len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    bits = bits_of(value, size) if form == "f" else int(value) & ((1 << 8 * size) - 1)
    buf[byte : byte + size] = bits.to_bytes(size, "big")


def _set_bool(ref: Ref, value: bool) -> None:
    buf, byte, bit = ref
    if buf is None or not 0 <= byte < len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    if value:
        buf[byte] |= 1 << bit
    else:
        buf[byte] &= ~(1 << bit) & 0xFF


def _wrap(kind: str, value: int) -> int:
    """``value`` cut to the width of ``kind`` (two's complement for the signed ones)."""
    size, signed, _form = _FORMS[kind]
    bits = 8 * size
    value &= (1 << bits) - 1
    if signed and value >> (bits - 1):
        value -= 1 << bits
    return value


def _truncated(left: int, right: int) -> tuple[int, int]:
    """S7's integer division: the quotient toward zero, the remainder with the dividend's sign."""
    quotient = abs(left) // abs(right)
    if (left < 0) != (right < 0):
        quotient = -quotient
    return quotient, left - quotient * right


# -- arithmetic -----------------------------------------------------------------------------------


def _integer(op: str, kind: str, right_kind: str | None = None) -> Body:
    other = right_kind or kind

    def body(p: list[Ref]) -> int:
        a, b = int(_get(p[0], kind)), int(_get(p[1], other))
        ok = 1
        if op == "ADD":
            value = a + b
        elif op == "SUB":
            value = a - b
        elif op == "MUL":
            value = a * b
        elif b == 0:
            value, ok = 0, 0
        else:
            quotient, remainder = _truncated(a, b)
            value = quotient if op == "DIV" else remainder
        _set(p[2], kind, _wrap(kind, value))
        return ok

    return body


def _real(op: str) -> Body:
    def body(p: list[Ref]) -> int:
        value = ieee(_SIGNS[op], float(_get(p[0], "LREAL")), float(_get(p[1], "LREAL")))
        _set(p[2], "LREAL", value)
        return int(math.isfinite(value))

    return body


def _negate(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        value = _get(p[0], kind)
        _set(p[1], kind, -value if kind == "LREAL" else _wrap(kind, -int(value)))
        return 1

    return body


def _bitwise(op: str) -> Body:
    def body(p: list[Ref]) -> int:
        a = int(_get(p[0], "LWORD"))
        if op == "NOT":
            _set(p[1], "LWORD", ~a)
            return 1
        b = int(_get(p[1], "LWORD"))
        _set(p[2], "LWORD", a & b if op == "AND" else a | b if op == "OR" else a ^ b)
        return 1

    return body


_TESTS: dict[str, Callable[[Any, Any], bool]] = {
    "EQ": lambda a, b: a == b,
    "NE": lambda a, b: a != b,
    "LT": lambda a, b: a < b,
    "LE": lambda a, b: a <= b,
    "GT": lambda a, b: a > b,
    "GE": lambda a, b: a >= b,
}


def _compare(op: str, kind: str) -> Body:
    test = _TESTS[op]

    def body(p: list[Ref]) -> int:
        _set_bool(p[2], test(_get(p[0], kind), _get(p[1], kind)))
        return 1

    return body


# -- conversions ----------------------------------------------------------------------------------


def _fits(kind: str, value: int) -> bool:
    low, high = INTEGER_RANGES.get(kind, (0, (1 << 8 * _FORMS[kind][0]) - 1))
    return low <= value <= high


def _to_float(kind: str, value: float) -> tuple[float, int]:
    if kind == "REAL":
        single = float_of(bits_of(value, 4), 4)
        return single, 0 if math.isinf(single) and not math.isinf(value) else 1
    return float(value), 1


def _pattern(kind: str, value: int | float) -> int:
    """The bits of ``value`` (a float's IEEE pattern, a signed value sign-extended)."""
    size, _signed, form = _FORMS[kind]
    return bits_of(value, size) if form == "f" else int(value)


def _convert(source: str, target: str) -> Body:
    form_in = _FORMS[source][2]
    size_out, _, form_out = _FORMS[target]

    def body(p: list[Ref]) -> int:
        value = _get(p[0], source)
        ok = 1
        if source == "LTIME" and target == "TIME":
            quotient, _rest = _truncated(int(value), _NS_PER_MS)
            result: int | float = _wrap("TIME", quotient)
            ok = int(result == quotient)
        elif source == "TIME" and target == "LTIME":
            result = int(value) * _NS_PER_MS
        elif source in _BITS or target in _BITS:
            if form_out == "f":  # a bit string's pattern as a REAL/LREAL
                bits = _pattern(source, value) & ((1 << 8 * size_out) - 1)
                result = float_of(bits, size_out)
            else:
                result = _wrap(target, _pattern(source, value))
        elif form_out == "f":
            result, ok = _to_float(target, float(value))
        elif form_in == "f":
            number = float(value)
            if not math.isfinite(number):
                result, ok = 0, 0
            else:
                whole = round(number)  # a half to the even neighbour
                ok = int(_fits(target, whole))
                result = _wrap(target, whole)
        else:
            whole = int(value)
            ok = int(_fits(target, whole))
            result = _wrap(target, whole)
        _set(p[1], target, result)
        return ok

    return body


def _bodies() -> dict[str, Body]:
    found: dict[str, Body] = {}
    for kind in ("LINT", "ULINT"):
        for op in ARITHMETIC:
            found[f"{op}_{kind}"] = _integer(op, kind)
    for op in ("DIV", "MOD"):  # + - * of UDINTs are the accumulators'
        found[f"{op}_UDINT"] = _integer(op, "UDINT")
    for op in ARITHMETIC[:4]:
        found[f"{op}_LREAL"] = _real(op)
    for kind in ("LINT", "LREAL", "LTIME"):
        found[f"NEG_{kind}"] = _negate(kind)
    for op in ("ADD", "SUB"):
        found[f"{op}_LTIME"] = _integer(op, "LTIME")
    for op in ("MUL", "DIV"):
        found[f"{op}_LTIME"] = _integer(op, "LTIME", "LINT")
    for op in ("AND", "OR", "XOR", "NOT"):
        found[f"{op}_LWORD"] = _bitwise(op)
    for kind in OPERATION_TYPES:
        for op in COMPARE.values():
            found[f"{op}_{kind}"] = _compare(op, kind)
    for name in CONVERSIONS:
        source, _, target = name.partition("_TO_")
        found[name] = _convert(source, target)
    from nasaq.cpu.long_functions import bodies  # SQRT_LREAL, MIN_LINT ... (imports this one)

    found.update(bodies())
    return found


BODIES: dict[str, Body] = _bodies()

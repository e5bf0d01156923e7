"""The S7-1200/1500 values a watch table reads and writes beside the classic ones.

LINT, ULINT, LWORD, LTIME and LREAL take 8 bytes, more than one CPU access (at most a
doubleword): they are read and written as two doublewords, the high one first (big-endian as
every standard block). SINT ... UDINT and WCHAR fit one access; what they add is the values a
user may type for them. ``STRING[n]`` and ``WSTRING[n]`` are read as TIA Portal shows them:
the current characters (a length above the maximum is cut to the maximum). A written string
keeps the declared maximum in its header.

What a user may type (as TIA Portal's "Modify value" takes it): a plain number, a based number
(``16#FF``, ``2#1010``), a typed constant of any integer type (``LINT#-5``, ``UINT#16#FFFF``);
for an LTIME ``LT#1D2H3M4S5MS6US7NS`` (also ``LTIME#``, or a ``T#`` duration, or a plain
number of nanoseconds); for an LREAL a number (``1.5``, ``-2.5E+300``, ``LREAL#1.5``, ``NaN``,
``Inf``); for a WCHAR one character; for a string its characters, quoted or not.
Encoding functions return the pattern or, when the text does not fit, the :class:`Phrase` that
says why (``nasaq.monitor.targets`` raises it as MON606).
"""

from __future__ import annotations

import math
import re
import struct

from nasaq.cpu import Cpu
from nasaq.diagnostics.phrases import Phrase, phrase
from nasaq.ir import Direct, Width
from nasaq.lang.s7_1500_values import ltime_ns
from nasaq.lang.stl.constants import ConstantError, duration_ms

Typed = bool | int | float | str | None

LINT_LIMITS = (-(2**63), 2**63 - 1)
_ALLOWED = {
    "SINT": ((-128, 127), phrase("range", low="-128", high="127")),
    "USINT": ((0, 255), phrase("range", low="0", high="255")),
    "UINT": ((0, 2**16 - 1), phrase("range", low="0", high="65535")),
    "UDINT": ((0, 2**32 - 1), phrase("range", low="0", high="4294967295")),
    "LINT": (
        LINT_LIMITS,
        phrase("range", low="-9223372036854775808", high="9223372036854775807"),
    ),
    "ULINT": ((0, 2**64 - 1), phrase("range", low="0", high="18446744073709551615")),
    # a negative LWORD is stored as its two's complement, as a negative WORD is
    "LWORD": (
        (-(2**63), 2**64 - 1),
        phrase("range", low="-9223372036854775808", high="16#FFFF_FFFF_FFFF_FFFF"),
    ),
    "LTIME": (
        LINT_LIMITS,
        phrase(
            "range",
            low="LT#-106751D23H47M16S854MS775US808NS",
            high="LT#106751D23H47M16S854MS775US807NS",
        ),
    ),
    "WCHAR": ((0, 0xFFFF), phrase("range", low="WCHAR#16#0000", high="WCHAR#16#FFFF")),
}
EXAMPLES = {
    "SINT": "-5",
    "USINT": "200",
    "UINT": "60000",
    "UDINT": "4000000000",
    "LINT": "-40000000000",
    "ULINT": "16#FFFF_FFFF_FFFF",
    "LWORD": "16#0123_4567_89AB_CDEF",
    "LTIME": "LT#1D2H3M4S5MS6US7NS",
    "LREAL": "1.5",
    "WCHAR": "'A'",
}
WIDE_TYPES = frozenset(EXAMPLES)
_INTEGER_PREFIXES = frozenset(
    {"SINT", "USINT", "INT", "UINT", "DINT", "UDINT", "LINT", "ULINT"}
    | {"B", "BYTE", "W", "WORD", "DW", "DWORD", "LW", "LWORD", "L"}
)
_DIGITS = {2: "01", 8: "01234567", 10: "0123456789", 16: "0123456789ABCDEF"}
_SPECIAL = {"NAN": math.nan, "INF": math.inf, "+INF": math.inf, "-INF": -math.inf}
_DOUBLE = struct.Struct(">d")
_STRING = re.compile(r"^(W?)STRING\[(\d+)\]$")
_LREAL_MAX = "1.7976931348623157E+308"


# -- reading and writing in the CPU -----------------------------------------------------------


def _at(direct: Direct, byte: int, width: Width) -> Direct:
    return Direct(direct.area, width, direct.byte + byte, 0, direct.db)


def read_long(cpu: Cpu, direct: Direct) -> int:
    """The 8 bytes at ``direct`` as one unsigned pattern."""
    return cpu.read(_at(direct, 0, Width.DWORD)) << 32 | cpu.read(_at(direct, 4, Width.DWORD))


def write_long(cpu: Cpu, direct: Direct, pattern: int) -> None:
    cpu.write(_at(direct, 4, Width.DWORD), pattern & 0xFFFFFFFF)  # the far end first: a
    cpu.write(_at(direct, 0, Width.DWORD), pattern >> 32 & 0xFFFFFFFF)  # short DB fails early


def string_shape(kind: str) -> tuple[bool, int]:
    """(wide, maximum length) of ``STRING[n]`` / ``WSTRING[n]`` (uppercase, no spaces)."""
    match = _STRING.match(kind)
    assert match is not None, kind
    return bool(match[1]), int(match[2])


def read_string(cpu: Cpu, direct: Direct, kind: str) -> str:
    wide, maximum = string_shape(kind)
    unit = Width.WORD if wide else Width.BYTE
    size = 2 if wide else 1
    length = min(cpu.read(_at(direct, size, unit)), maximum)
    start = 2 * size
    return "".join(chr(cpu.read(_at(direct, start + k * size, unit))) for k in range(length))


def write_string(cpu: Cpu, direct: Direct, kind: str, text: str) -> None:
    wide, maximum = string_shape(kind)
    unit = Width.WORD if wide else Width.BYTE
    size = 2 if wide else 1
    start = 2 * size
    cpu.read(_at(direct, start + maximum * size - 1, Width.BYTE))  # (a short DB fails first)
    cpu.write(_at(direct, 0, unit), maximum)
    cpu.write(_at(direct, size, unit), len(text))
    for k, char in enumerate(text):
        cpu.write(_at(direct, start + k * size, unit), ord(char))


def string_value(kind: str, value: Typed) -> str | Phrase:
    """The characters to store in a ``STRING[n]``/``WSTRING[n]``, or why they do not fit."""
    wide, maximum = string_shape(kind)
    if value is None:
        return phrase("value_needed", type=kind, example="'Nasaq'")
    text = value if isinstance(value, str) else str(value)
    if len(text) >= 2 and text[0] == text[-1] == "'":
        text = text[1:-1].replace("''", "'")
    if len(text) > maximum:
        return phrase(
            "value_not_fit",
            value=repr(text),
            type=kind,
            allowed=phrase("text_too_long", max_length=maximum),
        )
    limit = 0xFFFF if wide else 0xFF
    if any(ord(char) > limit for char in text):
        allowed = (
            phrase("range", low="WCHAR#16#0000", high="WCHAR#16#FFFF")
            if wide
            else phrase("char_range")
        )
        return phrase("value_not_fit", value=repr(text), type=kind, allowed=allowed)
    return text


# -- what a user types -------------------------------------------------------------------------


def encode(kind: str, value: Typed) -> int | Phrase:
    """The unsigned pattern (of the type's width) storing ``value`` as ``kind`` (one of
    :data:`WIDE_TYPES`), or the phrase saying why it cannot."""
    example = EXAMPLES[kind]
    if value is None:
        return phrase("value_needed", type=kind, example=example)
    if kind == "LREAL":
        return _encode_lreal(value)
    number = _whole(kind, value)
    if isinstance(number, Phrase):
        return number
    (low, high), allowed = _ALLOWED[kind]
    if not low <= number <= high:
        return phrase("value_not_fit", value=_shown(value), type=kind, allowed=allowed)
    bits = 16 if kind == "WCHAR" else {"SINT": 8, "USINT": 8, "UINT": 16, "UDINT": 32}.get(kind, 64)
    return number & ((1 << bits) - 1)


def _shown(value: bool | int | float | str) -> str:
    return value.strip() if isinstance(value, str) else str(value)


def _encode_lreal(value: bool | int | float | str) -> int | Phrase:
    if isinstance(value, bool):
        return phrase("not_of_type", value=str(value), type="LREAL", example="1.5")
    if isinstance(value, str):
        text = value.strip()
        prefix, sharp, body = text.partition("#")
        if sharp and prefix.upper() in ("LREAL", "REAL"):
            text = body
        number = _SPECIAL.get(text.upper())
        if number is None:
            try:
                number = float(text.replace("_", ""))
            except ValueError:
                return phrase("not_of_type", value=repr(value.strip()), type="LREAL", example="1.5")
            if math.isinf(number):
                allowed = phrase(
                    "range", low="-1.7976931348623157E+308", high="1.7976931348623157E+308"
                )
                return phrase("value_not_fit", value=text, type="LREAL", allowed=allowed)
    else:
        number = float(value)
    return int.from_bytes(_DOUBLE.pack(number), "big")


def _whole(kind: str, value: bool | int | float | str) -> int | Phrase:
    example = EXAMPLES[kind]
    if isinstance(value, bool):
        return phrase("not_of_type", value=str(value), type=kind, example=example)
    if isinstance(value, int):
        return value
    if isinstance(value, float):
        if not value.is_integer():
            return phrase("not_whole", value=str(value), type=kind, allowed=_ALLOWED[kind][1])
        return int(value)
    text = value.strip()
    if kind == "WCHAR" and (char := _char(text)) is not None:
        return ord(char)
    number = _integer_text(kind, text)
    if number is None:
        return phrase("not_of_type", value=repr(text), type=kind, example=example)
    return number


def _char(text: str) -> str | None:
    if len(text) == 1:
        return text
    if len(text) == 3 and text[0] == text[2] and text[0] in "'\"":
        return text[1]
    return None


def _integer_text(kind: str, text: str) -> int | None:
    """A whole number written as TIA Portal writes constants; None when it is none. For an LTIME
    the number is nanoseconds."""
    negative = text.startswith("-")
    body = text.lstrip("+-") if text[:1] in "+-" else text
    prefix, sharp, rest = body.partition("#")
    upper = prefix.upper()
    if sharp and kind == "LTIME" and upper in ("LT", "LTIME", "T", "TIME"):
        try:
            ns = ltime_ns(rest, text) if upper in ("LT", "LTIME") else duration_ms(rest, text)
        except ConstantError:
            return None
        ns = ns if upper in ("LT", "LTIME") else ns * 1_000_000
        return -ns if negative else ns
    if sharp and upper in _INTEGER_PREFIXES:
        body = rest
        negative = negative != body.startswith("-")
        body = body.lstrip("+-")
        prefix, sharp, rest = body.partition("#")
    base = 10
    if sharp:
        if prefix not in ("2", "8", "16"):
            return None
        base, body = int(prefix), rest
    digits = body.replace("_", "").upper()
    if not digits or any(char not in _DIGITS[base] for char in digits):
        return None
    number = int(digits, base)
    return -number if negative else number

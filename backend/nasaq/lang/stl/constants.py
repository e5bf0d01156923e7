"""Every STL constant format → ``ir.Constant`` with the exact 32-bit pattern ``L`` puts in ACCU1
(``DT#`` excepted: 64 bits that only a parameter or a DB value holds).

Rules (STEP 7 / S7-300/400, cross-checked with awlsim's behaviour):
- decimal: INT, -32768..32767, as a 16-bit immediate: ACCU1-H becomes 0, so ``L -1`` then
  ``T MD 0`` stores 16#0000FFFF, the classic reason to write ``L#-1`` (larger values need ``L#``);
- ``L#``: DINT; ``B#16#`` ``W#16#`` ``DW#16#`` (also base 2 and 8) and bare ``16#``/``2#``/``8#``
  (WORD up to 16#FFFF, DWORD above); ``_`` separators are allowed in digits;
- ``B#(a, b)`` / ``B#(a, b, c, d)``: the bytes packed big-endian (first byte highest);
- ``P#byte.bit`` area-internal pointer ``byte << 3 | bit``; with an area (``P#M10.0``) the area
  code sits in bits 24..31: P(eripheral) 80, I 81, Q 82, M 83, DB 84, DI 85, L 86, V 87;
- ``C#n``: BCD 0..999; ``S5T#``: BCD value with the smallest time base that holds it
  (10 ms, 100 ms, 1 s, 10 s → base code 0..3 in bits 12..13; finer parts are truncated), at
  most 2H46M30S; ``T#``: milliseconds as DINT (``T#-1S``); ``D#``: days since 1990-01-01;
  ``TOD#``: milliseconds since midnight; ``DT#``: the 8 BCD bytes S7 stores (as a 64-bit
  pattern: a DATE_AND_TIME is an actual parameter or a DB value, never an accumulator value);
- reals: IEEE 754 single precision; ``'A'`` .. ``'ABCD'``: characters right-aligned, one byte
  each (``'AB'`` is 16#4142); a longer ``'...'`` (up to 254 characters) is a STRING constant,
  only ever the actual value of a STRING parameter.
"""

from __future__ import annotations

import datetime
import math
import re
import struct
from typing import Any

from nasaq.ir import Constant, ConstType

MASK32 = 0xFFFFFFFF
POINTER_AREAS = {
    "P": 0x80,
    "PI": 0x80,
    "PE": 0x80,
    "PQ": 0x80,
    "PA": 0x80,
    "I": 0x81,
    "E": 0x81,
    "Q": 0x82,
    "A": 0x82,
    "M": 0x83,
    "DB": 0x84,
    "DBX": 0x84,
    "DI": 0x85,
    "DIX": 0x85,
    "L": 0x86,
    "V": 0x87,
}
_DURATION = re.compile(
    r"^(?:(?P<d>\d+(?:\.\d+)?)D)?(?:(?P<h>\d+(?:\.\d+)?)H)?(?:(?P<m>\d+(?:\.\d+)?)M(?!S))?"
    r"(?:(?P<s>\d+(?:\.\d+)?)S)?(?:(?P<ms>\d+(?:\.\d+)?)MS)?$"
)
_UNIT_MS = {"d": 86_400_000, "h": 3_600_000, "m": 60_000, "s": 1000, "ms": 1}
_POINTER = re.compile(
    r"^(?:DB\s*(?P<db>\d+)\s*\.\s*)?(?P<area>[A-Za-z]+)?\s*(?P<byte>\d+)\.(?P<bit>\d+)"
    r"(?:\s+(?P<type>[A-Za-z_]+)\s+(?P<count>\d+))?$"
)
EPOCH = datetime.date(1990, 1, 1)
# Constants that are actual parameters only (a DT# or a string of more than 4 characters).
NOT_LOADABLE = {
    ConstType.DATE_AND_TIME: "a DATE_AND_TIME (8 bytes) cannot be loaded into the accumulator",
    ConstType.STRING: "a character constant has at most 4 characters",
}


class ConstantError(ValueError):
    """A malformed (``STL107``) or out-of-range (``STL214``) constant."""

    def __init__(self, code: str, **params: Any) -> None:
        super().__init__(code)
        self.code = code
        self.params = params


def _bad(text: str, reason: str) -> ConstantError:
    return ConstantError("STL107", text=text, reason=reason)


def _range(text: str, type_name: str, hint: str = "") -> ConstantError:
    return ConstantError("STL214", text=text, type=type_name, hint=hint)


def bcd(value: int) -> int:
    result = 0
    for shift, digit in enumerate(reversed(str(value))):
        result |= int(digit) << (4 * shift)
    return result


def real_pattern(value: float) -> int:
    """IEEE 754 single bits; raises OverflowError when the value does not fit."""
    if math.isfinite(value) and abs(value) > 3.4028235677973366e38:
        raise OverflowError(value)
    result: int = struct.unpack(">I", struct.pack(">f", value))[0]
    return result


def parse_int(digits: str, base: int, text: str) -> int:
    clean = digits.replace("_", "")
    if not clean:
        raise _bad(text, "digits are missing")
    if base == 10 and clean.isdigit() and len(clean.lstrip("0")) > 40:  # past every S7 type
        clean = "1" + "0" * 40
    try:
        return int(clean, base)
    except ValueError:
        raise _bad(text, f"not a base-{base} number") from None


def decimal_int(text: str) -> Constant:
    # Python converts at most 4,300 digits; anything past 10 is out of range anyway.
    value = int(text) if len(text.lstrip("+-0")) <= 20 else 1 << 70
    if not -32768 <= value <= 32767:
        raise _range(text, "INT", hint="; write L#" + text.lstrip("+") + " for a DINT")
    return Constant(ConstType.INT, value & 0xFFFF, value, text)  # a 16-bit immediate


def real(text: str) -> Constant:
    value = float(text)
    try:
        pattern = real_pattern(value)
    except OverflowError:
        raise _range(text, "REAL") from None
    return Constant(ConstType.REAL, pattern, value, text)


def chars(text: str, raw: str) -> Constant:
    """``raw`` is the unescaped content of the quotes. Up to 4 characters it is a CHAR constant
    (what ``L 'AB'`` loads); a longer one can only be a STRING parameter's actual value."""
    if len(raw) > 254:
        raise _range(text, "STRING", hint=" (at most 254 characters)")
    pattern = 0
    for char in raw:
        if ord(char) > 0xFF:
            raise _bad(text, f"{char!r} is not a one-byte character")
        pattern = (pattern << 8) | ord(char)
    if len(raw) > 4:
        return Constant(ConstType.STRING, pattern, len(raw), text)
    return Constant(ConstType.CHAR, pattern, pattern, text)


_SIGNED = re.compile(r"[+-]?\d+")


def byte_list(text: str) -> Constant:
    parts = [part.strip() for part in text[text.index("(") + 1 : -1].split(",")]
    if not all(_SIGNED.fullmatch(part) for part in parts):
        raise _bad(text, "B#( ) takes 2 or 4 bytes")
    # A part of more than 3 digits is out of a byte's range; int() refuses 4,300 anyway.
    values = [int(part) if len(part) <= 6 else 256 for part in parts]
    if len(values) not in (2, 4):
        raise _bad(text, "B#( ) takes 2 or 4 bytes")
    pattern = 0
    for value in values:
        if not 0 <= value <= 255:
            raise _range(text, "BYTE")
        pattern = (pattern << 8) | value
    return Constant(ConstType.BYTES, pattern, pattern, text)


def duration_ms(body: str, text: str) -> int:
    clean = body.replace("_", "").upper()
    negative = clean.startswith("-")
    clean = clean.lstrip("+-")
    match = _DURATION.match(clean)
    if not clean or match is None or not any(match.groupdict().values()):
        raise _bad(text, "a duration is written like 1H2M3S4MS")
    total = 0.0
    for unit, amount in match.groupdict().items():
        if amount is not None:
            total += float(amount) * _UNIT_MS[unit]
    if not total < _DURATION_CAP:  # 9999...D or an infinite float: out of every time range
        total = _DURATION_CAP  # the caller's range check refuses it with the type's range
    ms = round(total)
    return -ms if negative else ms


_DURATION_CAP = float(2**62)  # ms; above LTIME's range too


def s5time(body: str, text: str) -> Constant:
    ms = duration_ms(body, text)
    if ms < 0 or ms > 9_990_000:
        raise _range(text, "S5TIME", hint=" (0 to 2H46M30S)")
    for code, base in enumerate((10, 100, 1000, 10_000)):
        if ms // base <= 999:
            return Constant(ConstType.S5TIME, (code << 12) | bcd(ms // base), ms, text)
    raise _range(text, "S5TIME")  # pragma: no cover - excluded by the range check


def time(body: str, text: str) -> Constant:
    ms = duration_ms(body, text)
    if not -(2**31) <= ms < 2**31:  # T#-24D_20H_31M_23S_648MS is the least TIME, -2^31 ms
        raise _range(text, "TIME")
    return Constant(ConstType.TIME, ms & MASK32, ms, text)


def date_days(body: str, text: str) -> int:
    try:
        year, month, day = (_field(part) for part in body.split("-"))
        days = (datetime.date(year, month, day) - EPOCH).days
    except (ValueError, OverflowError):
        raise _bad(text, "a date is written like 1990-1-31") from None
    if not 0 <= days <= 65378:
        raise _range(text, "DATE", hint=" (1990-1-1 to 2168-12-31)")
    return days


def tod_ms(body: str, text: str) -> int:
    match = re.match(r"^(\d+):(\d+)(?::(\d+)(?:\.(\d{1,3}))?)?$", body)
    if match is None:
        raise _bad(text, "a time of day is written like 13:30:00.000")
    hours, minutes = _field(match[1]), _field(match[2])
    seconds = _field(match[3] or "0")
    millis = int((match[4] or "0").ljust(3, "0"))
    if hours > 23 or minutes > 59 or seconds > 59:
        raise _range(text, "TIME_OF_DAY")
    return ((hours * 60 + minutes) * 60 + seconds) * 1000 + millis


def _field(digits: str) -> int:
    """A date or time field; one of more than 9 digits is out of every range and stands as
    10**9 (Python converts at most 4,300 digits, datetime none past 32 bits)."""
    return int(digits) if len(digits.lstrip("0")) <= 9 else 10**9


def date_and_time_bytes(body: str, text: str) -> bytes:
    """``DT#1990-1-1-0:0:0.0`` as the 8 BCD bytes S7 stores (year..second, ms, weekday)."""
    match = re.match(r"^(\d+)-(\d+)-(\d+)-(.*)$", body)
    if match is None:
        raise _bad(text, "a date and time is written like 1990-1-1-13:30:00.000")
    year, month, day = _field(match[1]), _field(match[2]), _field(match[3])
    try:
        date = datetime.date(year, month, day)
    except (ValueError, OverflowError):
        raise _bad(text, "not a date") from None
    if not 1990 <= year <= 2089:
        raise _range(text, "DATE_AND_TIME", hint=" (1990 to 2089)")
    ms = tod_ms(match[4], text)
    seconds, millis = divmod(ms, 1000)
    minutes, seconds = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    weekday = date.isoweekday() % 7 + 1  # 1 = Sunday
    return bytes(
        [
            bcd(year % 100),
            bcd(month),
            bcd(day),
            bcd(hours),
            bcd(minutes),
            bcd(seconds),
            bcd(millis // 10),
            (bcd(millis % 10) << 4) | weekday,
        ]
    )


def pointer(text: str) -> Constant:
    """``P#M10.0``, ``P#10.0``, ``P#DB5.DBX 2.0 BYTE 4`` (an ANY pointer: only as a parameter;
    the pattern is then its area pointer part)."""
    body = text[2:].strip()
    match = _POINTER.match(body)
    if match is None:
        raise _bad(text, "a pointer is written like P#M10.0 or P#10.0")
    if len(match["byte"].lstrip("0")) > 9 or len(match["bit"]) > 9:  # before int(): 4,300 digits
        raise _range(text, "POINTER")
    byte, bit = int(match["byte"]), int(match["bit"])
    if bit > 7:
        raise _bad(text, "the bit number must be 0 to 7")
    if byte > 65535:
        raise _range(text, "POINTER")
    area = 0
    if match["area"] is not None:
        code = POINTER_AREAS.get(match["area"].upper())
        if code is None:
            raise _bad(text, f"{match['area']} is not a memory area")
        area = code
    if match["db"] is not None:
        area = POINTER_AREAS["DB"]
    pattern = (area << 24) | (byte << 3) | bit
    return Constant(ConstType.POINTER, pattern, (byte << 3) | bit, text)


# TIA Portal's notation of a constant by its type name (``INT#5``, ``DINT#-7``, ``WORD#16#FF``,
# ``UDINT#16#FFFF``, ``REAL#1.5``): the value STEP 7's own notation gives (``L 5``, ``L L#-7``,
# ``L W#16#FF``, ``L DW#16#FFFF``, ``L 1.5``). A value in base notation is the bit pattern.
# type -> (what the pattern is, lowest and highest value in decimal, width in bits)
IEC_TYPED: dict[str, tuple[ConstType, int, int, int]] = {
    "INT": (ConstType.INT, -(2**15), 2**15 - 1, 16),
    "DINT": (ConstType.DINT, -(2**31), 2**31 - 1, 32),
    "BYTE": (ConstType.BYTE, 0, 2**8 - 1, 8),
    "WORD": (ConstType.WORD, 0, 2**16 - 1, 16),
    "DWORD": (ConstType.DWORD, 0, 2**32 - 1, 32),
    # the S7-1200/1500 ones (``S7_1500_TYPED``: STL500 under S7-300/400)
    "SINT": (ConstType.INT, -(2**7), 2**7 - 1, 8),
    "USINT": (ConstType.BYTE, 0, 2**8 - 1, 8),
    "UINT": (ConstType.WORD, 0, 2**16 - 1, 16),
    "UDINT": (ConstType.DWORD, 0, 2**32 - 1, 32),
}
# 64 bits, more than an accumulator holds: STL603 (STL500 first under S7-300/400)
WIDE_TYPED = frozenset({"LINT", "ULINT", "LWORD", "LREAL", "LTIME"})
S7_1500_TYPED = frozenset({"SINT", "USINT", "UINT", "UDINT"}) | WIDE_TYPED


def typed_prefix(text: str) -> str:
    """The type name before the first ``#`` of a typed constant, in capitals."""
    return text.partition("#")[0].upper()


def _iec_typed(prefix: str, body: str, text: str) -> Constant:
    kind, low, high, bits = IEC_TYPED[prefix]
    base_text, sign, digits = body.partition("#")
    if sign:
        if base_text not in ("2", "8", "16"):
            raise _bad(text, f"write {prefix}#16#... with base 2, 8 or 16")
        pattern = parse_int(digits, int(base_text), text)
        if pattern >> bits:
            raise _range(text, prefix)
        value = pattern - (1 << bits) if low < 0 and pattern >> (bits - 1) else pattern
    else:
        value = parse_int(body, 10, text)
        if not low <= value <= high:
            raise _range(text, prefix)
    width = 16 if kind is ConstType.INT else 32  # INT and SINT load as a 16-bit immediate
    return Constant(kind, value & ((1 << width) - 1), value, text)


def typed(text: str) -> Constant:
    prefix, _, body = text.partition("#")
    prefix = prefix.upper()
    if prefix in IEC_TYPED:
        return _iec_typed(prefix, body, text)
    if prefix == "REAL":
        number = real(body)
        return Constant(number.type, number.pattern, number.value, text)
    if prefix in WIDE_TYPED:
        raise ConstantError("STL603", text=text, type=prefix)
    if prefix == "L":
        value = parse_int(body, 10, text)
        if not -(2**31) <= value < 2**31:
            raise _range(text, "DINT")
        return Constant(ConstType.DINT, value & MASK32, value, text)
    if prefix in ("B", "W", "DW"):
        base_text, _, digits = body.partition("#")
        if not digits or base_text not in ("2", "8", "16"):
            raise _bad(text, f"write {prefix}#16#... with base 2, 8 or 16")
        value = parse_int(digits, int(base_text), text)
        kind, limit = {
            "B": (ConstType.BYTE, 0xFF),
            "W": (ConstType.WORD, 0xFFFF),
            "DW": (ConstType.DWORD, MASK32),
        }[prefix]
        if value > limit:
            raise _range(text, kind.value)
        return Constant(kind, value, value, text)
    if prefix in ("2", "8", "16"):
        value = parse_int(body, int(prefix), text)
        if value > MASK32:
            raise _range(text, "DWORD")
        kind = ConstType.WORD if value <= 0xFFFF else ConstType.DWORD
        return Constant(kind, value, value, text)
    if prefix == "C":
        value = parse_int(body, 10, text)
        if not 0 <= value <= 999:
            raise _range(text, "COUNTER", hint=" (0 to 999)")
        return Constant(ConstType.COUNTER, bcd(value), value, text)
    if prefix in ("S5T", "S5TIME"):
        return s5time(body, text)
    if prefix in ("T", "TIME"):
        return time(body, text)
    if prefix in ("D", "DATE"):
        days = date_days(body, text)
        return Constant(ConstType.DATE, days, days, text)
    if prefix in ("TOD", "TIME_OF_DAY"):
        ms = tod_ms(body, text)
        return Constant(ConstType.TOD, ms, ms, text)
    if prefix in ("DT", "DATE_AND_TIME"):
        pattern = int.from_bytes(date_and_time_bytes(body, text), "big")
        return Constant(ConstType.DATE_AND_TIME, pattern, pattern, text)
    raise _bad(text, f"{prefix}# is not a constant prefix")


def parse_literal(kind: str, text: str, raw_chars: str | None = None) -> Constant:
    """The constant for a literal token (``kind`` NUMBER, REAL, TYPED, BYTES, POINTER, CHARS)."""
    if kind == "NUMBER":
        return decimal_int(text)
    if kind == "REAL":
        return real(text)
    if kind == "TYPED":
        return typed(text)
    if kind == "BYTES":
        return byte_list(text)
    if kind == "POINTER":
        return pointer(text)
    if kind == "CHARS":
        return chars(text, raw_chars if raw_chars is not None else text[1:-1])
    raise _bad(text, "not a constant")


BOOLEANS = {"TRUE": 1, "FALSE": 0}


def boolean(text: str) -> Constant:
    value = BOOLEANS[text.upper()]
    return Constant(ConstType.BOOL, value, value, text)


# awlsim test constants (``__CNST_PI`` ...): REAL bit patterns
TEST_CONSTANTS = {
    "__CNST_PI": real_pattern(math.pi),
    "__CNST_E": real_pattern(math.e),
    "__CNST_PINF": 0x7F800000,
    "__CNST_NINF": 0xFF800000,
    "__CNST_PNAN": 0x7FFFFFFF,
    "__CNST_NNAN": 0xFFFFFFFF,
}

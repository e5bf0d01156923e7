"""The IEC functions of STEP 7's Standard Library (``nasaq.lang.iec_library``) as FCs whose body
is Python: STRING functions, conversions to and from STRING, DATE_AND_TIME arithmetic and
comparisons.

A library block is an FC of the program (the compiler adds it, see ``nasaq.lang.iec_library``)
with ``FAMILY : IEC``, its IEC name and no code; ``compiled`` gives the CPU a body for it, which
runs through the ordinary FC call (``nasaq.cpu.calls``): the parameters arrive as references
``(buffer, byte, bit)`` to the actuals, a STRING or DATE_AND_TIME one to its first byte, RET_VAL
to where the result goes. The body returns BR, which the caller sees as the FC's ENO.

STRINGs: byte 0 the maximum length, byte 1 the current length, then the characters. A function
reads ``min(current, maximum)`` characters of its inputs and writes at most the maximum length
of RET_VAL's actual (its byte 0, never changed), then the current length. The WSTRING versions
(``LEN_WSTRING``, ``EQ_WSTRING`` ...; S7-1200/1500) run the same bodies on WORD lengths and
UTF-16 code units (``_Texts``); ``WSTRING_TO_STRING`` writes ``?`` for a character beyond
Latin-1 and gives BR = 0 (*Nasaq*).

Behaviour (System Software for S7-300/400, System and Standard Functions, "IEC Functions"; where
the manual says nothing, the choice is marked *Nasaq*):

- LEN: the current length. FIND: the position of the first IN2 in IN1, 0 when there is none
  (*Nasaq*: also for an empty IN2). The comparisons (EQ_STRNG ... NE_STRNG) compare the
  character codes, the first different character decides, a string that is the start of a
  longer one is the smaller. No errors (BR = 1).
- CONCAT, INSERT, REPLACE: a result longer than RET_VAL's maximum length is cut to it and
  BR = 0 (the manual); *Nasaq*: so are LEFT, RIGHT, MID, DELETE (the manual does not say what
  they do with a RET_VAL that is too short).
- LEFT/RIGHT: the first/last L characters; L greater than the length gives the whole input,
  L = 0 an empty string; L < 0 gives an empty string and BR = 0.
- MID: L characters from position P (1 = the first); past the end, the rest from P. P outside
  the string (P < 1 or P > length), L <= 0 or P <= 0: an empty string and BR = 0.
- INSERT: IN2 after the P-th character of IN1; P = 0 before it, P past the end after it;
  P < 0: an empty string and BR = 0.
- DELETE: L characters from position P removed; L = 0, P = 0 or P past the end give IN
  unchanged; P + L past the end deletes to the end; L < 0 or P < 0: an empty string, BR = 0.
- REPLACE: L characters of IN1 from position P replaced by IN2; L = 0 gives IN1; P = 0 or 1
  replaces from the first character; P past the end appends IN2; L < 0 or P < 0: an empty
  string and BR = 0.
- I_STRNG, DI_STRNG: the number with its sign (``+205``, ``-3``, ``+0``). R_STRNG: 14
  characters ``±v.nnnnnnnE±xx``. If RET_VAL's maximum length is too short for the text, or the
  REAL is not a valid number (NaN, infinity), nothing is written and BR = 0.
- STRNG_I, STRNG_DI: an optional sign, then digits only; a length of 0 or above 6 (STRNG_DI: 11)
  or another character: nothing is written and BR = 0; a value outside INT (DINT) is limited to
  the range and BR = 0.
- STRNG_R: the first 14 characters must read ``±v.nnnnnnnE±xx``; a shorter string or another
  form: nothing is written and BR = 0; a value beyond the REAL range is limited to the largest
  (smallest normalised) REAL and BR = 0.
- DATE_AND_TIME (8 BCD bytes: year 90-99 = 1990-1999, 00-89 = 2000-2089, month, day, hour,
  minute, second, three digits of milliseconds, weekday 1 = Sunday in the last half byte):
  AD_DT_TM/SB_DT_TM add/subtract a TIME; a result outside 1990-01-01-00:00:00.000 ...
  2089-12-31-23:59:59.999 is limited to that range and BR = 0. SB_DT_DT gives T1 - T2 as a
  TIME, limited to the TIME range (BR = 0). D_TOD_DT joins a DATE and a TIME_OF_DAY, DT_DATE,
  DT_TOD take them apart, DT_DAY reads the weekday half byte. Results carry the weekday of
  their date. Inputs are not checked (the manual): BCD digits are read as they are.
  The comparisons (EQ_DT ... NE_DT) compare the points in time; the weekday does not count.
"""

from __future__ import annotations

import datetime
import functools
import re
import struct
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from nasaq.cpu.character_arrays import BODIES as REACHING
from nasaq.cpu.errors import CpuError
from nasaq.cpu.long_library import BODIES as LONG_BODIES
from nasaq.cpu.text_instructions import bodies as text_bodies
from nasaq.ir import Block, BlockKind
from nasaq.lang.iec_library import FAMILY, FUNCTIONS, WIDE
from nasaq.lang.number_text import TIME_CONVERSIONS
from nasaq.lang.s7_1500_types import INTEGER_RANGES

if TYPE_CHECKING:
    from nasaq.cpu.codegen.compiler import Compiled
    from nasaq.cpu.machine import Machine
    from nasaq.cpu.memory import Memory

Ref = tuple[Any, int, int]
Body = Callable[[list[Ref]], int]  # the parameter references in interface order -> BR

INT_RANGE = (-(2**15), 2**15 - 1)
DINT_RANGE = (-(2**31), 2**31 - 1)
REAL_MAX = 3.4028234663852886e38
REAL_MIN = 1.1754943508222875e-38  # the smallest normalised REAL
_F = struct.Struct(">f")
_REAL_TEXT = re.compile(rb"[+-][0-9]\.[0-9]{7}E[+-][0-9]{2}")
_DIGITS = re.compile(rb"[+-]?[0-9]+")

# -- reading and writing the actual parameters ----------------------------------------------------


def _bytes(ref: Ref, count: int) -> bytes:
    buf, byte, _bit = ref
    if buf is None or byte < 0 or byte + count > len(buf):
        raise CpuError("SIM503", address=f"byte {byte} (parameter)")
    return bytes(buf[byte : byte + count])


def _put(ref: Ref, data: bytes) -> None:
    buf, byte, _bit = ref
    if buf is None or byte < 0 or byte + len(data) > len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    buf[byte : byte + len(data)] = data


def _text(ref: Ref) -> bytes:
    """The characters of a STRING: ``min(current, maximum)`` of them."""
    maximum, length = _bytes(ref, 2)
    count = min(maximum, length)
    return _bytes(ref, 2 + count)[2:]


def _room(ref: Ref) -> int:
    return _bytes(ref, 1)[0]


def _put_text(ref: Ref, text: bytes) -> int:
    """RET_VAL := ``text``, cut to its maximum length (BR 0 then); byte 0 stays."""
    room = _room(ref)
    count = min(room, len(text))
    _put((ref[0], ref[1] + 1, 0), bytes((count,)) + text[:count])
    return 1 if count == len(text) else 0


def _int(ref: Ref) -> int:
    return int.from_bytes(_bytes(ref, 2), "big", signed=True)


def _dint(ref: Ref) -> int:
    return int.from_bytes(_bytes(ref, 4), "big", signed=True)


def _real(ref: Ref) -> float:
    value: float = _F.unpack(_bytes(ref, 4))[0]
    return value


def _put_int(ref: Ref, value: int, width: int = 2) -> None:
    _put(ref, (value & ((1 << 8 * width) - 1)).to_bytes(width, "big"))


def _put_bool(ref: Ref, value: bool) -> None:
    buf, byte, bit = ref
    if buf is None or not 0 <= byte < len(buf):
        raise CpuError("SIM504", address=f"byte {byte} (parameter)")
    if value:
        buf[byte] |= 1 << bit
    else:
        buf[byte] &= ~(1 << bit) & 0xFF


# -- STRING functions -----------------------------------------------------------------------------


class _Texts:
    """Reads and writes the STRINGs (``width`` 1) or WSTRINGs (``width`` 2: WORD lengths,
    UTF-16 code units) of a function's parameters as Python text, one character a code unit,
    so that one body serves both."""

    def __init__(self, width: int) -> None:
        self.width = width

    def text(self, ref: Ref) -> str:
        if self.width == 1:
            return _text(ref).decode("latin-1")
        header = _bytes(ref, 4)
        count = min(int.from_bytes(header[:2], "big"), int.from_bytes(header[2:], "big"))
        units = _bytes(ref, 4 + 2 * count)[4:]
        return "".join(chr(int.from_bytes(units[i : i + 2], "big")) for i in range(0, 2 * count, 2))

    def put(self, ref: Ref, text: str) -> int:
        """RET_VAL := ``text``, cut to its maximum length (BR 0 then); the maximum stays."""
        if self.width == 1:
            return _put_text(ref, text.encode("latin-1"))
        room = int.from_bytes(_bytes(ref, 2), "big")
        count = min(room, len(text))
        units = b"".join(ord(char).to_bytes(2, "big") for char in text[:count])
        _put((ref[0], ref[1] + 2, 0), count.to_bytes(2, "big") + units)
        return 1 if count == len(text) else 0


_NARROW, _WIDE = _Texts(1), _Texts(2)


def _len(t: _Texts, p: list[Ref]) -> int:
    _put_int(p[1], len(t.text(p[0])))
    return 1


def _find(t: _Texts, p: list[Ref]) -> int:
    text, wanted = t.text(p[0]), t.text(p[1])
    _put_int(p[2], text.find(wanted) + 1 if wanted else 0)
    return 1


def _concat(t: _Texts, p: list[Ref]) -> int:
    return t.put(p[2], t.text(p[0]) + t.text(p[1]))


def _left(t: _Texts, p: list[Ref]) -> int:
    text, count = t.text(p[0]), _int(p[1])
    if count < 0:
        t.put(p[2], "")
        return 0
    return t.put(p[2], text[:count])


def _right(t: _Texts, p: list[Ref]) -> int:
    text, count = t.text(p[0]), _int(p[1])
    if count < 0:
        t.put(p[2], "")
        return 0
    return t.put(p[2], text[max(len(text) - count, 0) :] if count else "")


def _mid(t: _Texts, p: list[Ref]) -> int:
    text, count, position = t.text(p[0]), _int(p[1]), _int(p[2])
    if count <= 0 or not 1 <= position <= len(text):
        t.put(p[3], "")
        return 0
    return t.put(p[3], text[position - 1 : position - 1 + count])


def _insert(t: _Texts, p: list[Ref]) -> int:
    first, second, position = t.text(p[0]), t.text(p[1]), _int(p[2])
    if position < 0:
        t.put(p[3], "")
        return 0
    return t.put(p[3], first[:position] + second + first[position:])


def _delete(t: _Texts, p: list[Ref]) -> int:
    text, count, position = t.text(p[0]), _int(p[1]), _int(p[2])
    if count < 0 or position < 0:
        t.put(p[3], "")
        return 0
    if count == 0 or position == 0 or position > len(text):
        return t.put(p[3], text)
    return t.put(p[3], text[: position - 1] + text[position - 1 + count :])


def _replace(t: _Texts, p: list[Ref]) -> int:
    first, second, count, position = t.text(p[0]), t.text(p[1]), _int(p[2]), _int(p[3])
    if count < 0 or position < 0:
        t.put(p[4], "")
        return 0
    if count == 0:
        return t.put(p[4], first)
    start = max(position, 1) - 1
    if start >= len(first):
        return t.put(p[4], first + second)
    return t.put(p[4], first[:start] + second + first[start + count :])


def _compare(t: _Texts, test: Callable[[str, str], bool]) -> Body:
    def body(p: list[Ref]) -> int:
        _put_bool(p[2], test(t.text(p[0]), t.text(p[1])))
        return 1

    return body


_STRING_BODIES: dict[str, Callable[[_Texts, list[Ref]], int]] = {
    "LEN": _len,
    "FIND": _find,
    "CONCAT": _concat,
    "LEFT": _left,
    "RIGHT": _right,
    "MID": _mid,
    "INSERT": _insert,
    "DELETE": _delete,
    "REPLACE": _replace,
}


def _to_wide(p: list[Ref]) -> int:
    return _WIDE.put(p[1], _NARROW.text(p[0]))


def _to_narrow(p: list[Ref]) -> int:
    """*Nasaq*: a character beyond latin-1 becomes ``?`` and BR = 0."""
    text = _WIDE.text(p[0])
    narrow = "".join(char if ord(char) < 256 else "?" for char in text)
    done = _NARROW.put(p[1], narrow)
    return done if narrow == text else 0


def _string_bodies(t: _Texts, names: dict[str, str]) -> dict[str, Body]:
    """The STRING functions and comparisons for one character width, under ``names``."""
    found: dict[str, Body] = {
        names[name]: functools.partial(body, t) for name, body in _STRING_BODIES.items()
    }
    for op in ("EQ", "NE", "GT", "GE", "LT", "LE"):
        found[names[f"{op}_STRNG"]] = _compare(t, _ordered(op))
    return found


# -- conversions ----------------------------------------------------------------------------------


def _number_text(value: int, ret: Ref) -> int:
    text = f"{value:+d}".encode()
    if len(text) > _room(ret):
        return 0  # RET_VAL too short: no conversion
    _put_text(ret, text)
    return 1


def _i_strng(p: list[Ref]) -> int:
    return _number_text(_int(p[0]), p[1])


def _di_strng(p: list[Ref]) -> int:
    return _number_text(_dint(p[0]), p[1])


def _r_strng(p: list[Ref]) -> int:
    value = _real(p[0])
    if value != value or value in (float("inf"), float("-inf")) or _room(p[1]) < 14:
        return 0
    _put_text(p[1], f"{value:+.7E}".encode())
    return 1


# TIA Portal's INT_TO_STRING ... (``nasaq.lang.number_text``) as its help's table "Explicit
# conversion of INT" says for SCL: no blanks inserted, the number preceded by its sign ("+42",
# "-42"; S_CONV/VAL_STRG in LAD/FBD pad and leave the "+" out). A REAL has its 14 characters.
_FIELDS = {"SINT": (1, 4), "USINT": (1, 4), "INT": (2, 6), "UINT": (2, 6), "DINT": (4, 11)}
_FIELDS |= {"UDINT": (4, 11), "LINT": (8, 21), "ULINT": (8, 21)}  # (bytes, characters)
_TIA_NUMBER = re.compile(rb"\s*([+-]?[0-9]+)")
_TIA_REAL = re.compile(rb"\s*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)")


def _tia_text(kind: str) -> Body:
    size, _characters = _FIELDS[kind]
    signed = not kind.startswith("U")

    def body(p: list[Ref]) -> int:
        value = int.from_bytes(_bytes(p[0], size), "big", signed=signed)
        return _put_text(p[1], f"{value:+d}".encode())

    return body


def _tia_real_text(p: list[Ref]) -> int:
    value = _real(p[0])
    if value != value or value in (float("inf"), float("-inf")):
        return 0
    return _put_text(p[1], f"{value:>+14.6E}".encode())


def _rest_blank(p: list[Ref], end: int) -> bool:
    return not _text(p[0])[end:].strip()


def _tia_number(limits: tuple[int, int], width: int) -> Body:
    def body(p: list[Ref]) -> int:
        found = _TIA_NUMBER.match(_text(p[0]))  # up to the first character of no number
        value = int(found[1]) if found else 0
        limited = min(max(value, limits[0]), limits[1])
        _put(p[1], limited.to_bytes(width, "big", signed=limits[0] < 0))
        return int(found is not None and _rest_blank(p, found.end()) and limited == value)

    return body


def _tia_real(p: list[Ref]) -> int:
    text = _text(p[0])
    found = _TIA_REAL.match(text)
    value = float(found[1]) if found else 0.0
    limited = min(max(value, -REAL_MAX), REAL_MAX)
    _put(p[1], _F.pack(limited))
    return int(found is not None and _rest_blank(p, found.end()) and limited == value)


_TIME_FORMS = {  # (bytes, signed, range)
    "TIME": (4, True, DINT_RANGE),
    "TIME_OF_DAY": (4, False, (0, 86_399_999)),
    "UDINT": (4, False, (0, 2**32 - 1)),
    "INT": (2, True, INT_RANGE),
    "UINT": (2, False, (0, 2**16 - 1)),
    "LINT": (8, True, (-(2**63), 2**63 - 1)),
    "ULINT": (8, False, (0, 2**64 - 1)),
}


def _tia_time(source: str, target: str) -> Body:
    """A TIME's milliseconds to or from a number: outside the target's range, its low bits and
    BR = 0 (as ``DINT_TO_INT``)."""
    size_in, signed_in, _ = _TIME_FORMS[source]
    size_out, _signed, (low, high) = _TIME_FORMS[target]
    mask = (1 << 8 * size_out) - 1

    def body(p: list[Ref]) -> int:
        value = int.from_bytes(_bytes(p[0], size_in), "big", signed=signed_in)
        _put(p[1], (value & mask).to_bytes(size_out, "big"))
        return int(low <= value <= high)

    return body


def _whole_number(p: list[Ref], longest: int, limits: tuple[int, int], width: int) -> int:
    text = _text(p[0])
    if not 0 < len(text) <= longest or _DIGITS.fullmatch(text) is None:
        return 0
    value = int(text)
    low, high = limits
    limited = min(max(value, low), high)
    _put_int(p[1], limited, width)
    return 1 if limited == value else 0


def _strng_i(p: list[Ref]) -> int:
    return _whole_number(p, 6, INT_RANGE, 2)


def _strng_di(p: list[Ref]) -> int:
    return _whole_number(p, 11, DINT_RANGE, 4)


def _strng_r(p: list[Ref]) -> int:
    text = _text(p[0])
    if len(text) < 14 or _REAL_TEXT.fullmatch(text[:14]) is None:
        return 0
    value = float(text[:14])
    size = abs(value)
    result = 1
    if size > REAL_MAX:
        value, result = (REAL_MAX if value > 0 else -REAL_MAX), 0
    elif 0 < size < REAL_MIN:
        value, result = (REAL_MIN if value > 0 else -REAL_MIN), 0
    _put(p[1], _F.pack(value))
    return result


# -- DATE_AND_TIME --------------------------------------------------------------------------------

MS_PER_DAY = 86_400_000
_EPOCH = datetime.date(1990, 1, 1)
_LAST = (datetime.date(2089, 12, 31) - _EPOCH).days * MS_PER_DAY + MS_PER_DAY - 1


def _bcd(byte: int) -> int:
    return (byte >> 4) * 10 + (byte & 0x0F)


def _to_bcd(value: int) -> int:
    return (value // 10 % 10) << 4 | value % 10


def _days(year: int, month: int, day: int) -> int:
    """Days from 1990-01-01 (any month and day numbers: they count on, as the digits say)."""
    year += (month - 1) // 12
    month = (month - 1) % 12 + 1
    year -= month <= 2
    era, rest = divmod(year, 400)
    march = (month + 9) % 12
    of_era = rest * 365 + rest // 4 - rest // 100 + (153 * march + 2) // 5 + day - 1
    return era * 146097 + of_era - 719468 - 7305  # 7305: days from 1970-01-01 to 1990-01-01


def dt_ms(data: bytes) -> int:
    """Milliseconds from 1990-01-01-00:00:00.000 to the DATE_AND_TIME ``data`` (8 bytes)."""
    short = _bcd(data[0])
    year = 1900 + short if short >= 90 else 2000 + short
    days = _days(year, _bcd(data[1]), _bcd(data[2]))
    seconds = (_bcd(data[3]) * 60 + _bcd(data[4])) * 60 + _bcd(data[5])
    millis = _bcd(data[6]) * 10 + (data[7] >> 4)
    return days * MS_PER_DAY + seconds * 1000 + millis


def dt_bytes(ms: int) -> bytes:
    """The DATE_AND_TIME of ``ms`` milliseconds after 1990-01-01-00:00:00.000 (in range)."""
    days, rest = divmod(ms, MS_PER_DAY)
    date = _EPOCH + datetime.timedelta(days=days)
    seconds, millis = divmod(rest, 1000)
    minutes, seconds = divmod(seconds, 60)
    hours, minutes = divmod(minutes, 60)
    weekday = date.isoweekday() % 7 + 1  # 1 = Sunday
    return bytes(
        (
            _to_bcd(date.year % 100),
            _to_bcd(date.month),
            _to_bcd(date.day),
            _to_bcd(hours),
            _to_bcd(minutes),
            _to_bcd(seconds),
            _to_bcd(millis // 10),
            _to_bcd(millis % 10) << 4 | weekday,
        )
    )


def _put_dt(ref: Ref, ms: int) -> int:
    limited = min(max(ms, 0), _LAST)
    _put(ref, dt_bytes(limited))
    return 1 if limited == ms else 0


def _ad_dt_tm(p: list[Ref]) -> int:
    return _put_dt(p[2], dt_ms(_bytes(p[0], 8)) + _dint(p[1]))


def _sb_dt_tm(p: list[Ref]) -> int:
    return _put_dt(p[2], dt_ms(_bytes(p[0], 8)) - _dint(p[1]))


def _sb_dt_dt(p: list[Ref]) -> int:
    difference = dt_ms(_bytes(p[0], 8)) - dt_ms(_bytes(p[1], 8))
    low, high = DINT_RANGE
    limited = min(max(difference, low), high)
    _put_int(p[2], limited, 4)
    return 1 if limited == difference else 0


def _d_tod_dt(p: list[Ref]) -> int:
    date = int.from_bytes(_bytes(p[0], 2), "big")
    tod = int.from_bytes(_bytes(p[1], 4), "big")
    _put(p[2], dt_bytes(date * MS_PER_DAY + tod))  # not checked: a year past 2089 wraps round
    return 1


def _dt_date(p: list[Ref]) -> int:
    _put_int(p[1], dt_ms(_bytes(p[0], 8)) // MS_PER_DAY)
    return 1


def _dt_day(p: list[Ref]) -> int:
    _put_int(p[1], _bytes(p[0], 8)[7] & 0x0F)
    return 1


def _dt_tod(p: list[Ref]) -> int:
    _put_int(p[1], dt_ms(_bytes(p[0], 8)) % MS_PER_DAY, 4)
    return 1


def _dt_compare(test: Callable[[int, int], bool]) -> Body:
    def body(p: list[Ref]) -> int:
        _put_bool(p[2], test(dt_ms(_bytes(p[0], 8)), dt_ms(_bytes(p[1], 8))))
        return 1

    return body


def _ordered(op: str) -> Callable[[Any, Any], bool]:
    return {
        "EQ": lambda a, b: a == b,
        "NE": lambda a, b: a != b,
        "GT": lambda a, b: a > b,
        "GE": lambda a, b: a >= b,
        "LT": lambda a, b: a < b,
        "LE": lambda a, b: a <= b,
    }[op]


_SAME = {name: name for name in WIDE}
BODIES: dict[str, Body] = {
    **_string_bodies(_NARROW, _SAME),
    **_string_bodies(_WIDE, WIDE),  # WSTRING: LEN_WSTRING, EQ_WSTRING ...
    "STRING_TO_WSTRING": _to_wide,
    "WSTRING_TO_STRING": _to_narrow,
    "I_STRNG": _i_strng,
    "DI_STRNG": _di_strng,
    "R_STRNG": _r_strng,
    "STRNG_I": _strng_i,
    "STRNG_DI": _strng_di,
    "STRNG_R": _strng_r,
    **{f"{kind}_TO_STRING": _tia_text(kind) for kind in _FIELDS},
    "REAL_TO_STRING": _tia_real_text,
    **{
        f"STRING_TO_{kind}": _tia_number(INTEGER_RANGES[kind], size)
        for kind, (size, _) in _FIELDS.items()
    },
    "STRING_TO_REAL": _tia_real,
    **{name: _tia_time(*kinds) for name, kinds in TIME_CONVERSIONS.items()},
    "AD_DT_TM": _ad_dt_tm,
    "SB_DT_TM": _sb_dt_tm,
    "SB_DT_DT": _sb_dt_dt,
    "D_TOD_DT": _d_tod_dt,
    "DT_DATE": _dt_date,
    "DT_DAY": _dt_day,
    "DT_TOD": _dt_tod,
    **{f"{op}_DT": _dt_compare(_ordered(op)) for op in ("EQ", "NE", "GT", "GE", "LT", "LE")},
}
BODIES.update(LONG_BODIES)  # the S7-1200/1500 types' hidden FCs (``nasaq.cpu.long_library``)
BODIES.update(text_bodies(BODIES))  # INT_TO_WSTRING, VAL_STRG ... (``nasaq.cpu.text_instructions``)
# ATH, Strg_TO_Chars ... reach their VARIANTs through the memory (``nasaq.cpu.character_arrays``)
assert BODIES.keys() | REACHING.keys() == FUNCTIONS.keys()


def library_name(block: Block) -> str | None:
    """The IEC name of a library block (an FC with FAMILY IEC, an IEC name and no code)."""
    if block.kind is not BlockKind.FC or block.code:
        return None
    if block.attributes.get("FAMILY", "").upper() != FAMILY:
        return None
    name = (block.attributes.get("NAME") or block.name).upper()
    return name if name in BODIES or name in REACHING else None


def compiled(block: Block, memory: Memory) -> Compiled | None:
    """The library FC ``block`` with its Python body; None when it is no library block.
    ``memory``: the CPU's, for the bodies that follow an ANY (``REACHING``)."""
    name = library_name(block)
    if name is None:
        return None
    from nasaq.cpu.codegen.compiler import Compiled  # codegen imports the call module

    slots = [v.name for v in block.interface if v.section in ("IN", "OUT", "IN_OUT", "RETURN")]
    reaching = REACHING.get(name)
    if reaching is not None:

        def run(m: Machine, callee_frame: bytearray, frame: bytearray, params: list[Ref]) -> None:
            m.br = reaching(params, memory, frame)  # (``frame``: the caller's, the V area)

    else:
        body = BODIES[name]

        def run(m: Machine, callee_frame: bytearray, frame: bytearray, params: list[Ref]) -> None:
            m.br = body(params)

    label = f"<FC {block.number} {name}>"
    return Compiled(block, run, 0, slots, [], [], {}, label, "", {})

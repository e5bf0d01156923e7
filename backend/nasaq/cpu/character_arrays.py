"""The bodies of ATH, HTA, Strg_TO_Chars and Chars_TO_Strg (``nasaq.lang.character_arrays``):
Python over the references to the actual parameters, as ``nasaq.cpu.iec_library``'s, plus the
CPU's memory, since their VARIANT/ANY parameters point at data a reference does not reach: the
body reads the 10-byte ANY the call built (``nasaq.cpu.pointers``) and resolves its DB, I, Q, M
or V (the caller's local data) pointer. Each returns BR (the caller's ENO).

Behaviour (S7-1200 System Manual, "String and character"; STEP 7 TI-S7 Converting Blocks;
*Nasaq* where they are silent):

- ATH: N characters of IN become N hexadecimal digits, two to a byte of OUT, in the order read;
  an odd N leaves the last byte's low digit 0. ``0``-``9``, ``A``-``F`` and ``a``-``f`` are
  digits; any other character gives the digit 0 and RET_VAL 16#0007, the rest is still
  converted (the manual's example). HTA: N bytes of IN become 2N characters ``0``-``9``,
  ``A``-``F`` in OUT, the high digit first. RET_VAL 16#8101/16#8301: IN/OUT points nowhere (a
  DB that does not exist, past its end); 16#8182: IN is shorter than N (*Nasaq*: also N < 0);
  16#8382: OUT is shorter than the result. On an error OUT is unchanged; ENO = (RET_VAL = 0).
  IN and OUT are taken as their bytes whatever their type (an ARRAY OF INT, a DWORD).
- Strg_TO_Chars: the current characters of Strg into Chars from element pChars (element 0 is
  the first of the array, which TIA requires to start at 0), Cnt = the number written. More
  characters than the array holds from pChars: what fits is written, ENO = 0 (the manual's
  "more character bytes than allowed"). *Nasaq*: pChars outside the array, or Chars no array
  of CHAR/BYTE (WSTRING: of WCHAR, two bytes each), writes nothing, Cnt = 0, ENO = 0.
- Chars_TO_Strg: Cnt elements of Chars from element pChars (Cnt = 0: to the array's end) into
  Strg, whose maximum length stays; a NUL character ends the text, and ENO = 0 then (the
  manual's ENO table); more characters than Strg holds: Strg gets what fits, ENO = 0.
  *Nasaq*: Cnt past the array's end copies to its end with ENO = 0; pChars outside the array or
  Chars of another type: Strg unchanged, ENO = 0.

A STRING given to IN or OUT of ATH/HTA is its bytes, header included (*Nasaq*: the ANY of a
STRING names its bytes; TIA reads its characters).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from nasaq.cpu.long_library import Ref
from nasaq.cpu.text_instructions import _bytes, _put, _put_text, _text
from nasaq.ir import Area
from nasaq.lang.character_arrays import TO_CHARS, TO_TEXT, WIDE_SUFFIX

if TYPE_CHECKING:
    from nasaq.cpu.memory import Memory

Body = Callable[[list[Ref], "Memory", bytearray], int]  # refs, memory, caller's frame -> BR

# bytes per element of an ANY's type code (``nasaq.cpu.pointers.ANY_TYPES``)
_SIZES = {2: 1, 3: 1, 4: 2, 5: 2, 6: 4, 7: 4, 8: 4, 9: 2, 10: 4, 11: 4, 12: 2, 14: 8, 19: 1}
_GLOBAL = {1: Area.I, 2: Area.Q, 3: Area.M}
_BYTE, _CHAR, _WORD = 2, 3, 4
_DIGITS = "0123456789ABCDEF"
_OK, _BAD_CHARACTER = 0x0000, 0x0007
_IN_POINTER, _IN_SHORT, _OUT_POINTER, _OUT_SHORT = 0x8101, 0x8182, 0x8301, 0x8382


def reach(ref: Ref, memory: Memory, frame: bytearray) -> tuple[bytearray, int, int, int] | None:
    """(buffer, first byte, length in bytes, type code) of the data the ANY at ``ref`` points
    to; None when it points nowhere (no ANY, a DB that does not exist, past the area's end)."""
    raw = _bytes(ref, 10)
    if raw[0] != 0x10:
        return None
    code, count = raw[1], int.from_bytes(raw[2:4], "big")
    db, pointer = int.from_bytes(raw[4:6], "big"), int.from_bytes(raw[6:10], "big")
    area, bits = (pointer >> 24) & 7, pointer & 0x7FFFF
    length = (count + 7) // 8 if code == 1 else count * _SIZES.get(code, 1)
    buf: bytearray | None
    if area == 4:
        buf = memory.dbs.get(db)
    elif area in _GLOBAL:
        buf = memory.area(_GLOBAL[area])
    elif area == 7:
        buf = frame
    else:
        buf = None
    byte = bits >> 3
    if buf is None or bits & 7 or byte + length > len(buf):
        return None
    return buf, byte, length, code


def _int(ref: Ref) -> int:
    return int.from_bytes(_bytes(ref, 2), "big", signed=True)


def _ret(ref: Ref, code: int) -> int:
    _put(ref, code.to_bytes(2, "big"))
    return 1 if code == _OK else 0


def _operands(
    p: list[Ref], memory: Memory, frame: bytearray, out_bytes: Callable[[int], int]
) -> tuple[int, bytearray, int, bytearray, int] | int:
    """ATH/HTA's N, IN and OUT: (N, IN's buffer and first byte, OUT's), or the RET_VAL error
    already written: a pointer that reaches nothing, N beyond IN, OUT shorter than
    ``out_bytes(N)``."""
    n, source, target = _int(p[1]), reach(p[0], memory, frame), reach(p[2], memory, frame)
    if source is None:
        return _ret(p[3], _IN_POINTER)
    if target is None:
        return _ret(p[3], _OUT_POINTER)
    buf, start, length, _code = source
    if not 0 <= n <= length:
        return _ret(p[3], _IN_SHORT)
    out, at, room, _code = target
    if room < out_bytes(n):
        return _ret(p[3], _OUT_SHORT)
    return n, buf, start, out, at


def _ath(p: list[Ref], memory: Memory, frame: bytearray) -> int:
    operands = _operands(p, memory, frame, lambda n: (n + 1) // 2)
    if isinstance(operands, int):
        return operands
    n, buf, start, out, at = operands
    code, digits = _OK, []
    for char in buf[start : start + n].decode("latin-1").upper():
        if char in _DIGITS:
            digits.append(_DIGITS.index(char))
        else:
            digits.append(0)
            code = _BAD_CHARACTER
    if len(digits) % 2:
        digits.append(0)
    packed = bytes(high << 4 | low for high, low in zip(digits[::2], digits[1::2], strict=True))
    out[at : at + len(packed)] = packed
    return _ret(p[3], code)


def _hta(p: list[Ref], memory: Memory, frame: bytearray) -> int:
    operands = _operands(p, memory, frame, lambda n: 2 * n)
    if isinstance(operands, int):
        return operands
    n, buf, start, out, at = operands
    text = "".join(f"{value:02X}" for value in buf[start : start + n])
    out[at : at + 2 * n] = text.encode("ascii")
    return _ret(p[3], _OK)


def _elements(
    ref: Ref, memory: Memory, frame: bytearray, width: int
) -> tuple[bytearray, int, int] | None:
    """(buffer, first byte, element count) of a character array of ``width`` bytes an element:
    CHAR or BYTE (width 1), WCHAR (2: its ANY names bytes, or WORDs)."""
    found = reach(ref, memory, frame)
    if found is None:
        return None
    buf, byte, length, code = found
    allowed = (_CHAR, _BYTE) if width == 1 else (_BYTE, _WORD)
    if code not in allowed:
        return None
    return buf, byte, length // width


def _dint(ref: Ref) -> int:
    return int.from_bytes(_bytes(ref, 4), "big", signed=True)


def _to_chars(width: int) -> Body:
    def body(p: list[Ref], memory: Memory, frame: bytearray) -> int:
        text, start = _text(p[0], width), _dint(p[1])
        array = _elements(p[3], memory, frame, width)
        if array is None or not 0 <= start < array[2]:
            _put(p[2], bytes(2))
            return 0
        buf, byte, count = array
        fit = min(len(text), count - start)
        data = b"".join(ord(char).to_bytes(width, "big") for char in text[:fit])
        at = byte + start * width
        buf[at : at + len(data)] = data
        _put(p[2], fit.to_bytes(2, "big"))
        return 1 if fit == len(text) else 0

    return body


def _to_text(width: int) -> Body:
    def body(p: list[Ref], memory: Memory, frame: bytearray) -> int:
        array = _elements(p[0], memory, frame, width)
        start, wanted = _dint(p[1]), int.from_bytes(_bytes(p[2], 2), "big")
        if array is None or not 0 <= start < array[2]:
            return 0
        buf, byte, count = array
        end = count if wanted == 0 else start + wanted
        done = 1
        if end > count:
            end, done = count, 0
        data = buf[byte + start * width : byte + end * width]
        units = [int.from_bytes(data[i : i + width], "big") for i in range(0, len(data), width)]
        if 0 in units:  # a NUL ends the text (ENO = 0: the manual)
            units, done = units[: units.index(0)], 0
        return _put_text(p[3], "".join(map(chr, units)), width) & done

    return body


BODIES: dict[str, Body] = {
    "ATH": _ath,
    "HTA": _hta,
    TO_CHARS: _to_chars(1),
    TO_TEXT: _to_text(1),
    TO_CHARS + WIDE_SUFFIX: _to_chars(2),
    TO_TEXT + WIDE_SUFFIX: _to_text(2),
}

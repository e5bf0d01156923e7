"""The bodies of TIA Portal's text instructions (``nasaq.lang.text_instructions``) and of the
number conversions with WSTRING (``nasaq.lang.number_text``): Python over the references to
the actual parameters, as ``nasaq.cpu.iec_library``'s; each returns BR (the caller's ENO).

``INT_TO_WSTRING`` ... write the text ``INT_TO_STRING`` writes, as UTF-16 code units;
``WSTRING_TO_INT`` ... read a WSTRING as ``STRING_TO_INT`` reads a STRING (a character beyond
Latin-1 ends the number).

VAL_STRG (S7-1200 System Manual, "String and character"; *Nasaq* where it is silent):
- FORMAT bit 0 r: the decimal point is ``,`` (1) or ``.`` (0); bit 1 f: exponential notation
  (1) or fixed point (0); bit 2 s: a ``+`` before positive values too (1) or only ``-`` (0).
  Other bits set (FORMAT 8 or more): OUT unchanged, ENO = 0.
- Fixed point: ``<sign><digits without leading zeros>.<PREC digits>``, rounded to PREC digits;
  an integer's PREC places the decimal point (123 with PREC 1 is ``12.3``); PREC 0 writes no
  decimal point (*Nasaq*: the manual's form with no fraction). Exponential (REAL and LREAL):
  ``<sign><digit>.<PREC digits>E<sign><exponent without leading zeros>``. A REAL keeps at most 7
  fractional digits (the manual's largest precision; *Nasaq*: LREAL 15).
- The text goes right-justified into SIZE characters of OUT from character P (1 = the first),
  blanks before it. SIZE 0: the text as long as it is. A P past OUT's current length fills the
  gap with blanks; OUT's current length becomes at least P - 1 + SIZE.
- *Nasaq*: a text longer than SIZE, a field past OUT's maximum length, P = 0, NaN or infinity:
  OUT unchanged, ENO = 0 (the manual: on an error "OUT is unchanged").

STRG_VAL (the same manual):
- Reading starts at character P of IN (1 = the first); leading blanks are skipped; it stops at
  the end of IN or at the first character that is not ``+ - . , e E`` or a digit. With ``.``
  as the decimal point (FORMAT bit 0 = 0) a ``,`` before it is a thousands separator and
  ignored, and the other way round. Bit 1 (exponential) allows an exponent (*Nasaq*: fixed
  point reads one too, as a real CPU does not forbid it). FORMAT 4 or more: ENO = 0.
- P is set to the character after the number (*Nasaq*: the manual's "offset of the next
  character"). No number there (or P outside IN): OUT unchanged, P unchanged, ENO = 0.
- A value beyond OUT's range: OUT unchanged, ENO = 0 (*Nasaq*); a REAL/integer target gets the
  value rounded to the nearest (ties to even, as ROUND).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping

from nasaq.cpu.errors import CpuError
from nasaq.cpu.long_library import Ref, _get, _set
from nasaq.lang.number_text import CHARACTER_CONVERSIONS, WIDE_NUMBERS
from nasaq.lang.s7_1500_types import INTEGER_RANGES
from nasaq.lang.text_instructions import NUMBERS

Body = Callable[[list[Ref]], int]
_FLOATS = frozenset({"REAL", "LREAL"})
_MOST_DIGITS = {"REAL": 7, "LREAL": 15}
_REAL_MAX = 3.4028234663852886e38

# -- texts ----------------------------------------------------------------------------------------


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


def _text(ref: Ref, width: int = 1) -> str:
    """A STRING's (``width`` 1) or WSTRING's (2) characters, ``min(current, maximum)``."""
    header = _bytes(ref, 2 * width)
    room, length = int.from_bytes(header[:width], "big"), int.from_bytes(header[width:], "big")
    count = min(room, length)
    data = _bytes(ref, 2 * width + width * count)[2 * width :]
    return "".join(
        chr(int.from_bytes(data[i : i + width], "big")) for i in range(0, len(data), width)
    )


def _room(ref: Ref, width: int = 1) -> int:
    return int.from_bytes(_bytes(ref, width), "big")


def _put_text(ref: Ref, text: str, width: int = 1) -> int:
    """The text into the STRING/WSTRING, cut to its maximum length (BR 0 then)."""
    count = min(_room(ref, width), len(text))
    data = b"".join(ord(c).to_bytes(width, "big") for c in text[:count])
    _put((ref[0], ref[1] + width, 0), count.to_bytes(width, "big") + data)
    return 1 if count == len(text) else 0


# -- the number conversions with WSTRING ----------------------------------------------------------


def _scratch() -> Ref:
    """A STRING[254] of this call only (its header says 254, empty)."""
    buf = bytearray(256)
    buf[0] = 254
    return (buf, 0, 0)


def _to_wide(narrow: Body) -> Body:
    """``X_TO_WSTRING``: ``X_TO_STRING``'s text, widened into RET_VAL."""

    def body(p: list[Ref]) -> int:
        text = _scratch()
        done = narrow([p[0], text])
        if not done and _bytes(text, 2)[1] == 0:
            return 0  # nothing written (NaN ...): RET_VAL unchanged, as the STRING version
        return _put_text(p[1], _text(text), 2) & done

    return body


def _from_wide(narrow: Body) -> Body:
    """``WSTRING_TO_X``: the WSTRING read as ``STRING_TO_X`` reads a STRING (a character
    beyond Latin-1 is no character of a number)."""

    def body(p: list[Ref]) -> int:
        text = _scratch()
        wide = _text(p[0], 2)[:254]
        _put_text(text, "".join(c if ord(c) < 256 else "\x00" for c in wide))
        return narrow([text, p[1]])

    return body


def bodies(narrow: Mapping[str, Body]) -> dict[str, Body]:
    """The bodies of this module, given the STRING conversions' (``nasaq.cpu.iec_library``,
    which merges them)."""
    found: dict[str, Body] = {}
    for name in WIDE_NUMBERS:
        base = narrow[name.replace("WSTRING", "STRING")]
        found[name] = _to_wide(base) if name.endswith("_TO_WSTRING") else _from_wide(base)
    found.update({name: _character(*kinds) for name, kinds in CHARACTER_CONVERSIONS.items()})
    found.update({f"VAL_STRG_{kind}": _val_strg(kind) for kind in NUMBERS})
    found.update({f"STRG_VAL_{kind}": _strg_val(kind) for kind in NUMBERS})
    return found


_WIDTHS = {"CHAR": 1, "STRING": 1, "WCHAR": 2, "WSTRING": 2}


def _character(source: str, target: str) -> Body:
    """One character between the two widths: a text's first character (an empty text gives
    code 0 and BR = 0), a character as a text of one; a code beyond Latin-1 into a CHAR or
    STRING is ``?`` and BR = 0 (*Nasaq*, as WSTRING_TO_STRING)."""
    width_in, width_out = _WIDTHS[source], _WIDTHS[target]

    def body(p: list[Ref]) -> int:
        if source.endswith("STRING"):
            text = _text(p[0], width_in)[:1]
        else:
            text = chr(int.from_bytes(_bytes(p[0], width_in), "big"))
        done = int(bool(text))
        if width_out == 1 and text and ord(text) > 255:
            text, done = "?", 0
        if target.endswith("STRING"):
            return _put_text(p[1], text, width_out) & done
        _put(p[1], (ord(text) if text else 0).to_bytes(width_out, "big"))
        return done

    return body


def _word(ref: Ref) -> int:
    return int.from_bytes(_bytes(ref, 2), "big")


def _byte(ref: Ref) -> int:
    return _bytes(ref, 1)[0]


# -- VAL_STRG -------------------------------------------------------------------------------------


def _fixed(value: int | float, kind: str, prec: int) -> str | None:
    """The digits of ``value`` with ``prec`` fractional digits, without a sign."""
    if kind in _FLOATS:
        if prec > _MOST_DIGITS[kind]:
            return None
        text = f"{abs(value):.{prec}f}"
    else:
        digits = str(abs(int(value))).rjust(prec + 1, "0")
        text = f"{digits[: len(digits) - prec]}.{digits[len(digits) - prec :]}" if prec else digits
    return text


def _exponential(value: float, kind: str, prec: int) -> str | None:
    if prec > _MOST_DIGITS[kind]:
        return None
    mantissa, _, exponent = f"{abs(value):.{prec}E}".partition("E")
    power = int(exponent)
    return f"{mantissa}E{'-' if power < 0 else '+'}{abs(power)}"


def _val_strg(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        value = _get(p[0], kind)
        size, prec, form, start = _byte(p[1]), _byte(p[2]), _word(p[3]), _word(p[4])
        out = p[5]
        if form > 7 or start == 0:
            return 0
        if isinstance(value, float) and not math.isfinite(value):
            return 0
        exponential = bool(form & 2)
        if exponential and kind in _FLOATS:
            digits = _exponential(float(value), kind, prec)
        else:
            digits = _fixed(value, kind, prec)
        if digits is None:
            return 0
        if form & 1:
            digits = digits.replace(".", ",")
        negative = value < 0 and digits.strip("0.,E+") != ""
        sign = "-" if negative else ("+" if form & 4 else "")
        text = sign + digits
        width = size or len(text)
        if len(text) > width:
            return 0
        current = _text(out)
        room = _bytes(out, 1)[0]
        end = start - 1 + width
        if end > room:
            return 0
        padded = current.ljust(start - 1)
        result = padded[: start - 1] + text.rjust(width) + padded[end:]
        _put_text(out, result)
        return 1

    return body


# -- STRG_VAL -------------------------------------------------------------------------------------

_NUMBER_CHARS = re.compile(r"[ ]*([-+.,eE0-9]*)")


def _parsed(chars: str, comma: bool) -> tuple[float | int, bool] | None:
    """The number in ``chars`` (only number characters) and whether it has a fraction or
    exponent; None when it is no number."""
    point, separator = (",", ".") if comma else (".", ",")
    whole, has_point, fraction = chars.partition(point)
    whole = whole.replace(separator, "")
    text = whole + ("." + fraction if has_point else "")
    if not re.fullmatch(r"[-+]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][-+]?[0-9]+)?", text):
        return None
    is_real = bool(has_point) or "e" in text.lower()
    return (float(text) if is_real else int(text)), is_real


def _strg_val(kind: str) -> Body:
    def body(p: list[Ref]) -> int:
        text, form, start = _text(p[0]), _word(p[1]), _word(p[3])
        if form > 3 or not 1 <= start <= len(text):
            return 0
        found = _NUMBER_CHARS.match(text, start - 1)
        assert found is not None  # (the pattern matches the empty text)
        chars = found[1]
        if not form & 2:  # fixed point: no exponent (the number ends before an E)
            chars = re.split("[eE]", chars, maxsplit=1)[0]
        parsed = _parsed(chars, bool(form & 1))
        if parsed is None:
            return 0
        value, _is_real = parsed
        if kind not in _FLOATS:
            value = round(value)
            low, high = INTEGER_RANGES[kind]
            if not low <= value <= high:
                return 0
        elif kind == "REAL" and abs(value) > _REAL_MAX:
            return 0
        _set(p[2], kind, value)
        _put(p[3], (found.start(1) + len(chars) + 1).to_bytes(2, "big"))
        return 1

    return body

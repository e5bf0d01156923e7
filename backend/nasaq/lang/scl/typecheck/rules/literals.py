"""Rule: constants. A typed constant must be valid for its prefix (``SCL219``) and in the range
of its type (``SCL218``): ``INT#40000``, ``BYTE#16#1FF``, ``T#25d``, ``D#1989-12-31``. Untyped
constants get a type that adapts to where they are used (``types.IntConst`` ...). STEP 7's
``L#2000`` is a DINT under every profile."""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING

from nasaq.lang import s7_1500_values
from nasaq.lang.profiles import is_s7_1500, needs_s7_1500
from nasaq.lang.scl import ast
from nasaq.lang.scl.typecheck.types import (
    BIT_LIMITS,
    RANGES,
    BitsConst,
    CharsConst,
    IntConst,
    TimeConst,
    Type,
)
from nasaq.lang.stl import constants
from nasaq.lang.stl.build import unquote_chars
from nasaq.lang.stl.constants import ConstantError
from nasaq.lang.types import Elementary, StringType
from nasaq.lang.wide_text import wide_text

if TYPE_CHECKING:
    from nasaq.lang.scl.typecheck.context import Context

BOOL = Elementary("BOOL")
REAL = Elementary("REAL")
_INTEGER_PREFIXES = {"INT": "INT", "DINT": "DINT", "L": "DINT"}  # L#2000: STEP 7's DINT
_INTEGER_PREFIXES |= {name: name for name in ("SINT", "USINT", "UINT", "UDINT", "LINT", "ULINT")}
_BIT_PREFIXES = {
    "LW": "LWORD",
    "LWORD": "LWORD",
    "B": "BYTE",
    "BYTE": "BYTE",
    "W": "WORD",
    "WORD": "WORD",
    "DW": "DWORD",
    "DWORD": "DWORD",
}


def literal(ctx: Context, node: ast.Literal) -> Type:
    if node.kind == "BOOL":
        return BOOL
    if node.kind == "REAL":
        return REAL
    if node.kind == "INTEGER":
        return _integer(node.text)
    if node.kind == "STRING":
        return CharsConst(_length(node.text[1:-1]))
    prefix, _, body = node.text.partition("#")
    if prefix.upper() == "STRING" and body.startswith("'"):  # TIA's STRING#'text'
        return CharsConst(_length(body[1:-1]))
    wide = wide_text(prefix)
    if wide is not None:  # WSTRING#'..', WCHAR#'.' (issue 20, the functions part)
        if not is_s7_1500(ctx.index.profile):
            return ctx.report("SCL500", node.loc, what=node.text, profile=ctx.index.profile)
        body = node.text.partition("#")[2]
        units = len(unquote_chars(body).encode("utf-16-be", errors="surrogatepass")) // 2
        if wide == "WCHAR":
            if units != 1:
                return ctx.report("SCL218", node.loc, text=node.text, type="WCHAR", hint="")
            return Elementary("WCHAR")
        return StringType(units, wide=True)
    try:
        found = _typed(node.text)
    except ConstantError as error:
        params = dict(error.params)
        if error.code == "STL214":
            return ctx.report("SCL218", node.loc, **params)
        return ctx.report("SCL219", node.loc, text=params["text"], reason=params["reason"])
    if type(found) is Elementary and needs_s7_1500(found.name, ctx.index.profile):
        return ctx.report("SCL500", node.loc, what=node.text, profile=ctx.index.profile)
    return found


@lru_cache(maxsize=4096)  # programs repeat the same few numbers
def _integer(text: str) -> IntConst:
    return IntConst(int(text.replace("_", "")))


def _bad(text: str, reason: str) -> ConstantError:
    return ConstantError("STL107", text=text, reason=reason)


def _range(text: str, type_name: str) -> ConstantError:
    return ConstantError("STL214", text=text, type=type_name, hint="")


def _number(body: str, text: str) -> int:
    """``-32768``, ``16#3f_ff``, ``2#1111_0000``: a signed decimal or a based number."""
    base_text, _, digits = body.rpartition("#")
    if base_text:
        if base_text not in ("2", "8", "16"):
            raise _bad(text, "the base must be 2, 8 or 16")
        return constants.parse_int(digits, int(base_text), text)
    sign = -1 if body.startswith("-") else 1
    return sign * constants.parse_int(body.lstrip("+-"), 10, text)


@lru_cache(maxsize=4096)  # a typed constant's type depends on its text only (errors raise)
def _typed(text: str) -> Type:
    prefix, _, body = text.partition("#")
    prefix = prefix.upper()
    if prefix in ("2", "8", "16"):
        return BitsConst(constants.parse_int(body, int(prefix), text))
    if prefix in _INTEGER_PREFIXES:
        name = _INTEGER_PREFIXES[prefix]
        value = _number(body, text)
        low, high = RANGES[name]
        if not low <= value <= high:
            raise _range(text, name)
        return Elementary(name)
    if prefix in _BIT_PREFIXES:
        name = _BIT_PREFIXES[prefix]
        if body.startswith("("):  # B#(1, 2) is a WORD, B#(1, 2, 3, 4) a DWORD
            byte_count = body.count(",") + 1
            constants.byte_list(text)
            return Elementary("WORD" if byte_count == 2 else "DWORD")
        elif body.startswith("'"):
            value = _chars_value(body, text)
        else:
            value = _number(body, text)
        if not 0 <= value <= BIT_LIMITS[name]:
            raise _range(text, name)
        return Elementary(name)
    if prefix == "BOOL":
        if body.upper() not in ("0", "1", "TRUE", "FALSE"):
            raise _bad(text, "a BOOL is 0, 1, TRUE or FALSE")
        return Elementary("BOOL")
    if prefix == "CHAR":
        if not body.startswith("'"):
            value = _number(body, text)
            if not 0 <= value <= 0xFF:
                raise _range(text, "CHAR")
        elif _length(body[1:-1]) != 1:
            raise _bad(text, "a CHAR is one character")
        return Elementary("CHAR")
    if prefix in ("LT", "LTIME"):
        s7_1500_values.ltime_ns(body, text)
        return Elementary("LTIME")
    if prefix in ("REAL", "LREAL"):
        try:
            number = float(body.replace("_", ""))
        except ValueError:
            raise _bad(text, "not a number") from None
        if prefix == "LREAL" and not math.isfinite(number):  # LREAL#1e400
            raise _range(text, "LREAL")
        return Elementary(prefix)
    if prefix in ("T", "TIME"):
        return TimeConst(int(constants.time(body, text).value))
    if prefix in ("S5T", "S5TIME"):
        constants.s5time(body, text)
        return Elementary("S5TIME")
    if prefix in ("D", "DATE"):
        constants.date_days(body, text)
        return Elementary("DATE")
    if prefix in ("TOD", "TIME_OF_DAY"):
        constants.tod_ms(body, text)
        return Elementary("TIME_OF_DAY")
    if prefix in ("DT", "DATE_AND_TIME"):
        year, dash, rest = body.partition("-")
        if len(year) == 2 and year.isdigit() and dash:  # DT#95-01-01-...: 1990..2089
            body = f"{1900 + int(year) if int(year) >= 90 else 2000 + int(year)}-{rest}"
        constants.date_and_time_bytes(body, text)
        return Elementary("DATE_AND_TIME")
    raise _bad(text, f"{prefix}# is not a type prefix")


def _chars_value(body: str, text: str) -> int:
    if _length(body[1:-1]) != 1:
        raise _bad(text, "one character is expected")
    inner = body[1:-1]
    if inner.startswith("$") and len(inner) == 3:
        return int(inner[1:], 16)
    return ord(inner[-1])


def _length(inner: str) -> int:
    """Characters of a quoted text: ``$41`` and ``$$``, ``$'``, ``$L`` ... count as one."""
    count = 0
    position = 0
    while position < len(inner):
        if inner[position] == "$":
            hex_pair = inner[position + 1 : position + 3]
            is_hex = len(hex_pair) == 2 and all(c in "0123456789abcdefABCDEF" for c in hex_pair)
            position += 3 if is_hex else 2
        else:
            position += 1
        count += 1
    return count

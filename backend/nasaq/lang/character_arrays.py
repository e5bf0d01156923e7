"""The instructions that move characters between texts and arrays of bytes: TIA Portal's
``Strg_TO_Chars`` and ``Chars_TO_Strg`` (S7-1200/1500) and ``ATH``/``HTA`` (STEP 7's TI-S7
Converting Blocks FC 94/95, in TIA for every CPU), as hidden library FCs (``nasaq.lang.
iec_library`` lists them; their bodies are Python: ``nasaq.cpu.character_arrays``).

Interfaces (S7-1200 System Manual, "String and character"; STEP 7 Standard Library):
``RET_VAL := ATH(IN : ANY, N : INT, OUT : ANY)`` and ``HTA`` alike (RET_VAL a WORD);
``Strg_TO_Chars(Strg : STRING, pChars : DINT, Cnt => UINT, Chars : VARIANT (in/out))``,
``Chars_TO_Strg(Chars : VARIANT, pChars : DINT, Cnt : UINT, Strg => STRING)``.

**How a body reaches the array.** TIA's VARIANT parameters of these system instructions are
ANY parameters here (STEP 7's own form for ATH/HTA): the SCL call passes the variable and the
STL call builds the 10-byte ANY of its declared type (``nasaq.lang.stl.calls.any_actual``: an
array of CHAR as ``CHAR n``, of anything else as its bytes), so the FC's body gets a reference
to that ANY and resolves its area pointer through the CPU's memory at run time (DB, I, Q, M,
the caller's local data; an FB's own variables as ``P#DI`` plus AR2's offset). The text
parameters are ordinary STRING/WSTRING parameters (a reference to the first byte, as for
VAL_STRG). What an ANY cannot describe is refused in SCL: a constant (``SCL554``) and a
parameter of the caller reached through a pointer (``SCL801``,
``nasaq.lang.scl.typecheck.character_arrays``). A WSTRING picks the ``_WSTRING`` FC, whose
arrays hold WCHARs (two bytes each), as TIA's overload of the instruction does.

Numbers: ATH FC 94 and HTA FC 95 (the Standard Library's); the four text FCs have none on
S7-300/400, Nasaq gives them FC 944-947 (``nasaq/cpu/COMPATIBILITY.md``, "Strings and
conversions").
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from nasaq.lang.types import DataType, Elementary, StringType

if TYPE_CHECKING:
    from nasaq.lang.iec_library import LibraryFunction

TO_CHARS, TO_TEXT = "STRG_TO_CHARS", "CHARS_TO_STRG"
WIDE_SUFFIX = "_WSTRING"
HEX = ("ATH", "HTA")
WIDE_FORMS = frozenset([TO_CHARS, TO_TEXT])
# the text instructions exist in TIA Portal for S7-1200/1500 only (SCL500 under S7-300/400)
S7_1500_ONLY = frozenset([TO_CHARS, TO_TEXT, TO_CHARS + WIDE_SUFFIX, TO_TEXT + WIDE_SUFFIX])
_ANY, _INT, _DINT = Elementary("ANY"), Elementary("INT"), Elementary("DINT")
_UINT, _WORD, _VOID = Elementary("UINT"), Elementary("WORD"), Elementary("VOID")
_TEXT_BASE = 944


def functions() -> list[LibraryFunction]:
    from nasaq.lang.iec_library import LibraryFunction

    made = [
        LibraryFunction(
            name, number, (("IN", _ANY), ("N", _INT)), _WORD, title, (("OUT", "OUT", _ANY),)
        )
        for name, number, title in (
            ("ATH", 94, "ASCII characters to hexadecimal digits"),
            ("HTA", 95, "hexadecimal digits to ASCII characters"),
        )
    ]
    number = _TEXT_BASE
    for wide in (False, True):
        text: DataType = StringType(254, wide=wide)
        suffix = WIDE_SUFFIX if wide else ""
        inputs: tuple[tuple[str, DataType], ...] = (("Strg", text), ("pChars", _DINT))
        others: tuple[tuple[str, str, DataType], ...] = (
            ("OUT", "Cnt", _UINT),
            ("IN_OUT", "Chars", _ANY),
        )
        made.append(
            LibraryFunction(TO_CHARS + suffix, number, inputs, _VOID, "text to characters", others)
        )
        inputs = (("Chars", _ANY), ("pChars", _DINT), ("Cnt", _UINT))
        made.append(
            LibraryFunction(
                TO_TEXT + suffix,
                number + 1,
                inputs,
                _VOID,
                "characters to text",
                (("OUT", "Strg", text),),
            )
        )
        number += 2
    return made


def overload(name: str, kinds: Sequence[str | None]) -> str:
    """``Strg_TO_Chars``/``Chars_TO_Strg`` of a WSTRING call the ``_WSTRING`` FC."""
    upper = name.upper()
    if upper in WIDE_FORMS and "WSTRING" in kinds:
        return upper + WIDE_SUFFIX
    return name

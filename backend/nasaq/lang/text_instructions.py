"""TIA Portal's instructions that put numbers into text and read them back (S7-1200/1500):
``VAL_STRG`` and ``STRG_VAL``, as hidden library FCs (``nasaq.lang.iec_library`` lists them,
their bodies are Python: ``nasaq.cpu.text_instructions``).

TIA overloads both on the number's type (VAL_STRG's ``IN``, STRG_VAL's ``OUT``: SINT, INT,
DINT, USINT, UINT, UDINT, REAL, LREAL); Nasaq has one FC per type, ``VAL_STRG_INT``,
``STRG_VAL_REAL`` ..., and a call of ``VAL_STRG`` calls the one of its argument's type
(``overload``), as ``LEN`` of a WSTRING calls ``LEN_WSTRING``.

Interfaces (S7-1200 System Manual, "String and character"): ``VAL_STRG(IN, SIZE : USINT, PREC
: USINT, FORMAT : WORD, P : UINT, OUT => STRING)``; P is an input (``P := 1``), OUT a
STRING that must hold a valid header before the call. ``STRG_VAL(IN : STRING, FORMAT : WORD,
P : UINT (in/out), OUT => number)``. Neither has a RET_VAL; ENO says whether it worked.

Numbers: no S7-300/400 library has these; Nasaq gives them FC 922-937 (``BASE``), clear of
the other hidden FCs (``nasaq/cpu/COMPATIBILITY.md``, "Strings and conversions").
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

from nasaq.lang import character_arrays
from nasaq.lang.types import DataType, Elementary, StringType

if TYPE_CHECKING:
    from nasaq.lang.iec_library import LibraryFunction

BASE = 922
NUMBERS = ("SINT", "INT", "DINT", "USINT", "UINT", "UDINT", "REAL", "LREAL")
# the generic name -> the formal whose actual's type picks the FC, and its position
OVERLOADS = {"VAL_STRG": ("IN", 0), "STRG_VAL": ("OUT", 3)}
# VAL_STRG and STRG_VAL exist in TIA Portal for S7-1200/1500 only (SCL500 under S7-300/400)
S7_1500_ONLY = (
    frozenset([*OVERLOADS, *(f"{name}_{kind}" for name in OVERLOADS for kind in NUMBERS)])
    | character_arrays.S7_1500_ONLY
)  # and Strg_TO_Chars, Chars_TO_Strg
_WORD, _USINT, _UINT = Elementary("WORD"), Elementary("USINT"), Elementary("UINT")
_TEXT = StringType(254)
_VOID = Elementary("VOID")


def functions() -> list[LibraryFunction]:
    from nasaq.lang.iec_library import LibraryFunction

    made: list[LibraryFunction] = []
    number = BASE
    inputs: tuple[tuple[str, DataType], ...]
    others: tuple[tuple[str, str, DataType], ...]
    for kind in NUMBERS:
        inputs = (("IN", Elementary(kind)), ("SIZE", _USINT), ("PREC", _USINT))
        inputs += (("FORMAT", _WORD), ("P", _UINT))
        others = (("OUT", "OUT", _TEXT),)
        made.append(
            LibraryFunction(f"VAL_STRG_{kind}", number, inputs, _VOID, f"{kind} into text", others)
        )
        number += 1
    for kind in NUMBERS:
        inputs = (("IN", _TEXT), ("FORMAT", _WORD))
        others = (("OUT", "OUT", Elementary(kind)), ("IN_OUT", "P", _UINT))  # (OUTs first)
        made.append(
            LibraryFunction(f"STRG_VAL_{kind}", number, inputs, _VOID, f"text to {kind}", others)
        )
        number += 1
    return made


def overload(name: str, formals: Sequence[str | None], kinds: Sequence[str | None]) -> str:
    """The FC a call of ``name`` calls: ``VAL_STRG_REAL`` for ``VAL_STRG(IN := a REAL ...)``;
    ``name`` itself for every other name. ``formals``: the arguments' formal names in call
    order (None: positional), ``kinds``: their types' names. A deciding argument of another
    type (or none) picks the INT version, whose interface then reports it."""
    upper = name.upper()
    if upper in character_arrays.WIDE_FORMS:  # Strg_TO_Chars of a WSTRING ...
        return character_arrays.overload(upper, kinds)
    deciding = OVERLOADS.get(upper)
    if deciding is None:
        return name
    formal, position = deciding
    for index, (given, kind) in enumerate(zip(formals, kinds, strict=True)):
        if (given or "").upper() == formal or (given is None and index == position):
            return f"{upper}_{kind}" if kind in NUMBERS else f"{upper}_INT"
    return f"{upper}_INT"

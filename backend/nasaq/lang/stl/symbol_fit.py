"""Whether a symbol's data type fits its address, by STEP 7's symbol editor rule.

A bit address (``I 0.0``, ``M 1.0``) takes BOOL; a byte (``MB 2``) BYTE or CHAR; a word
(``MW 10``, ``PIW 256``) WORD, INT, S5TIME or DATE; a double word (``MD 4``) DWORD, DINT, REAL,
TIME or TIME_OF_DAY (TOD); a timer TIMER and a counter COUNTER. A block takes its own kind and
number (``FB 10`` : ``FB 10``); a data block also the FB, SFB or UDT it is an instance of
(``DB 10`` : ``FB 10``), as in STEP 7. An empty or unknown type is not judged here (the symbol
table editor reports an unknown type on its own, API123).
"""

from __future__ import annotations

import re

from nasaq.ir import Width
from nasaq.ir.types import ELEMENTARY_BITS, TYPE_ALIASES
from nasaq.lang.stl.addresses import Parsed

_BY_WIDTH: dict[Width, tuple[str, ...]] = {
    Width.BIT: ("BOOL",),
    Width.BYTE: ("BYTE", "CHAR"),
    Width.WORD: ("WORD", "INT", "S5TIME", "DATE"),
    Width.DWORD: ("DWORD", "DINT", "REAL", "TIME", "TIME_OF_DAY"),
}
_BLOCK_TYPE = re.compile(r"^(OB|FB|FC|SFB|SFC|DB|UDT|VAT)\s*(\d+)$")
_INSTANCE_OF = ("FB", "SFB", "UDT")


def _canonical(type_text: str) -> str:
    upper = " ".join(type_text.upper().split())
    return TYPE_ALIASES.get(upper, upper)


def misfit(parsed: Parsed, type_text: str) -> str | None:
    """None if ``type_text`` fits the address (or is empty or unknown); else the types the
    address takes, as a list to show (``WORD, INT, S5TIME, DATE``)."""
    wanted = _canonical(type_text)
    block = _BLOCK_TYPE.match(wanted)
    if not wanted or (wanted not in ELEMENTARY_BITS and block is None):
        return None
    if parsed.kind == "timer":
        return None if wanted == "TIMER" else "TIMER"
    if parsed.kind == "counter":
        return None if wanted == "COUNTER" else "COUNTER"
    if parsed.kind == "block" and parsed.block is not None:
        own = f"{parsed.block.value} {parsed.number}"
        data_block = parsed.block.value in ("DB", "DI")
        if block is not None:
            kind, number = block[1], int(block[2])
            if (kind, number) == (parsed.block.value, parsed.number):
                return None
            if data_block and kind in _INSTANCE_OF:
                return None
        return f"{own}, FB n, SFB n, UDT n" if data_block else own
    if parsed.width is None:
        return None
    allowed = _BY_WIDTH.get(parsed.width)
    if allowed is None or wanted in allowed:
        return None
    return ", ".join(allowed)

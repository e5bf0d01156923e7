"""Absolute addresses as written (``MW 10``, ``E 0.0``, ``DB5.DBX 2.1``, ``T 3``, ``FB 10``).

Both mnemonic sets share one table: their area letters never collide (German E/A/Z/PE/PA,
international I/Q/C/PI/PQ; M, L, V, DB, DI, T are common), so an area's meaning does not
depend on the file's mnemonics; ``language`` only says which set spelled it.

TIA Portal writes them with a ``%`` (``%I0.0``, ``%MW10``, ``%DB5.DBX2.1``); it is accepted
and means the same.

``SFC -3`` / ``SFB -1``: negative numbers name awlsim's own system blocks (``__SHUTDOWN``,
``__REBOOT``, ``__SFB_NOP`` ...). They parse here (a symbol table may list them); the compiler
accepts them only with test instructions enabled, like ``__ASSERT`` (see ``resolve``/``bind``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache

from nasaq.ir import Area, BlockKind, Width

_AREA_PREFIX: dict[str, tuple[Area, str | None]] = {
    "I": (Area.I, "en"),
    "E": (Area.I, "de"),
    "Q": (Area.Q, "en"),
    "A": (Area.Q, "de"),
    "M": (Area.M, None),
    "L": (Area.L, None),
    "V": (Area.V, None),
    "DB": (Area.DB, None),
    "DI": (Area.DI, None),
    "PI": (Area.PI, "en"),
    "PE": (Area.PI, "de"),
    "PQ": (Area.PQ, "en"),
    "PA": (Area.PQ, "de"),
}
_WIDTHS = {"X": Width.BIT, "B": Width.BYTE, "W": Width.WORD, "D": Width.DWORD}
BLOCK_PREFIXES = {
    "OB": BlockKind.OB,
    "FB": BlockKind.FB,
    "FC": BlockKind.FC,
    "SFB": BlockKind.SFB,
    "SFC": BlockKind.SFC,
    "DB": BlockKind.DB,
    "DI": BlockKind.DI,
    "UDT": BlockKind.UDT,
}
SYSTEM_PREFIXES = frozenset({"SFC", "SFB"})
_SHAPE = re.compile(
    r"^(?:DB\s*(?P<db>\d+)\s*\.\s*)?(?P<prefix>[A-Za-z]+)\s*"
    r"(?P<sign>-\s*)?(?P<number>\d+(?:\.\d+)*)$",
    re.IGNORECASE,  # db20.dbw0 as well as DB20.DBW0 (the lexer's ADDR is case-insensitive too)
)


@dataclass(frozen=True, slots=True)
class Parsed:
    """What an address text means. ``kind`` is "memory", "timer", "counter" or "block"."""

    kind: str
    area: Area | None = None
    width: Width | None = None
    byte: int = 0
    bit: int = 0
    db: int | None = None
    block: BlockKind | None = None
    number: int = 0
    language: str | None = None  # "de" / "en" when only one mnemonic set spells it


class AddressError(ValueError):
    """The text is not a valid address; the message says why."""


def split_area(prefix: str) -> tuple[Area, Width, str | None] | None:
    """``MW`` → (M, WORD); ``DBX`` → (DB, BIT); ``PEW`` → (PI, WORD); bare ``I`` → (I, BIT)."""
    prefix = prefix.upper()
    if prefix in ("DB", "DI"):
        return None
    for length in (2, 1):
        head, tail = prefix[:length], prefix[length:]
        if head in _AREA_PREFIX and (tail == "" or tail in _WIDTHS):
            area, language = _AREA_PREFIX[head]
            if area in (Area.DB, Area.DI) and tail == "":
                return None
            if area in (Area.PI, Area.PQ) and tail in ("", "X"):
                return None  # the peripheral areas have no bit access
            return area, _WIDTHS.get(tail, Width.BIT), language
    return None


def parse_address(text: str) -> Parsed:
    """What ``text`` addresses; ``AddressError`` says why it addresses nothing."""
    found = _parsed(text)
    if isinstance(found, str):
        raise AddressError(found)
    return found


@lru_cache(maxsize=8192)
def _parsed(text: str) -> Parsed | str:
    """The address, or why it is none. Cached, failures too: programs repeat the same
    addresses a lot, and the compilers try many names (``x``, ``WORD_TO_INT``) as addresses."""
    try:
        return _parse(text)
    except AddressError as error:
        return str(error)


def _parse(text: str) -> Parsed:
    if "%" in text:  # TIA Portal's spelling of an absolute address: %I0.0, %DB5.DBW2
        text = text.replace("%", "", 2) if text.lstrip().startswith("%") else text
    match = _SHAPE.match(text.strip())
    if match is None:
        raise AddressError("not an address")
    prefix = match["prefix"].upper()
    numbers = match["number"].split(".")
    # No S7 address has a number of more than 5 digits; a longer one is refused before int()
    # (Python refuses to convert more than 4,300 digits, and nothing needs to).
    if any(len(part.lstrip("0")) > 9 for part in (*numbers, match["db"] or "")):
        raise AddressError("the number is larger than 65535")
    db = int(match["db"]) if match["db"] is not None else None
    if db is not None and db > 65535:
        raise AddressError("the number is larger than 65535")
    if match["sign"] is not None:
        if prefix not in SYSTEM_PREFIXES or db is not None or len(numbers) > 1:
            raise AddressError("an address has no sign")
        return Parsed("block", block=BLOCK_PREFIXES[prefix], number=-int(numbers[0]))
    if prefix in ("T", "C", "Z") or prefix in BLOCK_PREFIXES:
        if db is not None or len(numbers) > 1:
            raise AddressError("a number without bit address is expected")
        number = int(numbers[0])
        if number > 65535:
            raise AddressError("the number is larger than 65535")
        if prefix == "T":
            return Parsed("timer", number=number)
        if prefix in ("C", "Z"):
            return Parsed("counter", number=number, language="de" if prefix == "Z" else "en")
        return Parsed("block", block=BLOCK_PREFIXES[prefix], number=number)
    found = split_area(prefix)
    if found is None:
        raise AddressError(f"{prefix} is not an address area")
    area, width, language = found
    if db is not None and area is not Area.DB:
        raise AddressError("only DBX, DBB, DBW and DBD follow a DB number")
    if width is Width.BIT:
        if len(numbers) != 2:
            raise AddressError("a bit address needs byte.bit")
        bit = int(numbers[1])
        if bit > 7:
            raise AddressError("the bit number must be 0 to 7")
    else:
        if len(numbers) != 1:
            raise AddressError("a byte, word or double word address has no bit number")
        bit = 0
    byte = int(numbers[0])
    if byte > 65535:
        raise AddressError("the byte address is larger than 65535")
    return Parsed("memory", area, width, byte, bit, db, language=language)
